"""Read the binary PPM files POV-Ray writes with +FP (8- or 16-bit, comments allowed in the
header), for the measuring scripts: `read(path)` gives the pixels as a list of rows of
(r, g, b) floats in [0, 1] (linear when rendered with File_Gamma=1), `read_array(path)` the
same as an H x W x 3 NumPy array. Used by scripts/measure_*.sh and measure_crand.sh."""

import struct


def _header(d):
    """(width, height, maxval, offset of the pixels) of PPM bytes `d`."""
    pos, vals = 2, []
    while len(vals) < 3:
        while d[pos:pos + 1].isspace():
            pos += 1
        if d[pos:pos + 1] == b'#':
            pos = d.index(b'\n', pos)
            continue
        start = pos
        while not d[pos:pos + 1].isspace():
            pos += 1
        vals.append(int(d[start:pos]))
    return vals[0], vals[1], vals[2], pos + 1


def read(path):
    d = open(path, 'rb').read()
    w, h, mx, off = _header(d)
    size = 2 if mx > 255 else 1
    fmt = '>%dH' % (w * h * 3) if size == 2 else '%dB' % (w * h * 3)
    v = struct.unpack(fmt, d[off:off + w * h * 3 * size])
    return [[tuple(v[(y * w + x) * 3 + c] / mx for c in range(3)) for x in range(w)]
            for y in range(h)]


def read_array(path):
    import numpy as np
    d = open(path, 'rb').read()
    w, h, mx, off = _header(d)
    dt = '>u2' if mx > 255 else 'u1'
    return np.frombuffer(d[off:], dtype=dt)[:w * h * 3].reshape(h, w, 3) / mx
