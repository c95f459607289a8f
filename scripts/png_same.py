#!/usr/bin/env python3
"""Whether two PNG files hold the same picture: the same chunks in the same order with the
same contents, except that the compressed image data (IDAT) may differ as long as it
inflates and unfilters to the same rows of samples.

For byte-identity checks across a change of the PNG writer's compression settings (which
change the file's bytes, never its pixels): scripts/identical_check.sh falls back to this when
`cmp` finds the files differ. Standard library only; non-interlaced pictures (lancer writes no
others).

usage: scripts/png_same.py a.png b.png   (exit 0 same, 1 different, 2 unreadable)
"""
import struct
import sys
import zlib


def chunks(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG")
    pos, out = 8, []
    while pos < len(data):
        (n,) = struct.unpack(">I", data[pos : pos + 4])
        kind = data[pos + 4 : pos + 8]
        out.append((kind, data[pos + 8 : pos + 8 + n]))
        pos += 12 + n
    return out


def rows(path):
    """The chunks other than IDAT, and the unfiltered scanlines."""
    cs = chunks(path)
    ihdr = cs[0][1]
    width, height, depth, color, _, _, interlace = struct.unpack(">IIBBBBB", ihdr)
    if interlace:
        raise ValueError(f"{path}: interlaced")
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[color]
    bpp = max(1, channels * depth // 8)
    stride = (width * channels * depth + 7) // 8
    raw = zlib.decompress(b"".join(d for k, d in cs if k == b"IDAT"))
    lines, prev = [], bytearray(stride)
    for y in range(height):
        base = y * (stride + 1)
        f, line = raw[base], bytearray(raw[base + 1 : base + 1 + stride])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[i] = (line[i] + pred) & 255
        lines.append(bytes(line))
        prev = line
    others = [(k, d) for k, d in cs if k != b"IDAT"]
    return others, lines


def main():
    try:
        a, b = rows(sys.argv[1]), rows(sys.argv[2])
    except (OSError, ValueError, zlib.error, IndexError, KeyError, struct.error) as e:
        print(e, file=sys.stderr)
        return 2
    return 0 if a == b else 1


if __name__ == "__main__":
    sys.exit(main())
