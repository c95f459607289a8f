#!/usr/bin/env python3
"""Reference SSIM for lancer's image comparison (src/ssim.rs).

Prints scikit-image's SSIM (and PSNR) for pairs of PNG files, with the
parameters that src/ssim.rs reproduces:

    structural_similarity(a, b, gaussian_weights=True, sigma=1.5,
                          use_sample_covariance=False, data_range=1.0,
                          channel_axis=2)

Usage:
    python3 scripts/ssim_check.py A.png B.png [C.png D.png ...]
    python3 scripts/ssim_check.py --rust [--tol 0.005] A.png B.png ...
    python3 scripts/ssim_check.py --rust --lancer target/release/lancer A.png B.png ...
    python3 scripts/ssim_check.py --synthetic
    python3 scripts/ssim_check.py --make-pairs DIR

The verification table in docs/ssim.md is reproduced by

    python3 scripts/ssim_check.py --rust $(python3 scripts/ssim_check.py --make-pairs /tmp/ssim_pairs)

--rust also runs lancer's implementation (through the ignored unit test
ssim::tests::pairs_from_env, in the crate this script belongs to), prints
both numbers and their difference, and exits 1 if any pair differs by more
than --tol; with --lancer BIN it runs `BIN compare A B` (the command users
put in their regression tests) for each pair instead. --markdown prints that table as Markdown for docs/ssim.md.
--synthetic prints the reference numbers for the synthetic pair that the
unit tests in src/ssim.rs check against. --make-pairs renders two POV-Ray
sample scenes into DIR (needs `povray`), derives the test variants from them
with numpy and prints the pairs, one pair a line.

PNGs are decoded by the small decoder below rather than Pillow, for two
reasons: Pillow reads 16-bit RGB PNGs as 8-bit, and src/ssim.rs compares raw
stored values (gAMA/sRGB chunks ignored), which a hand decoder guarantees.

Needs: pip install scikit-image numpy pillow (Pillow only for --make-pairs)
"""

import argparse
import os
import struct
import subprocess
import sys
import zlib

import numpy as np
from skimage.metrics import peak_signal_noise_ratio, structural_similarity

SSIM_ARGS = dict(
    gaussian_weights=True,
    sigma=1.5,
    use_sample_covariance=False,
    data_range=1.0,
    channel_axis=2,
)

CHANNELS = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}  # PNG colour type -> samples per pixel
ADAM7 = [  # (x0, y0, dx, dy)
    (0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4),
    (0, 2, 2, 4), (1, 0, 2, 2), (0, 1, 1, 2),
]


def _unfilter(data, pos, rows, rowbytes, bpp):
    """Undoes PNG scanline filters; returns (rows x rowbytes uint8, new pos)."""
    out = np.zeros((rows, rowbytes), dtype=np.uint8)
    prev = np.zeros(rowbytes, dtype=np.int64)
    for r in range(rows):
        ftype = data[pos]
        line = np.frombuffer(data, dtype=np.uint8, count=rowbytes, offset=pos + 1).astype(np.int64)
        pos += 1 + rowbytes
        if ftype == 0:
            cur = line
        elif ftype == 1:  # Sub: a running sum per byte lane, vectorised
            pad = (-rowbytes) % bpp
            lanes = np.concatenate([line, np.zeros(pad, np.int64)]).reshape(-1, bpp)
            cur = (np.cumsum(lanes, axis=0) % 256).reshape(-1)[:rowbytes]
        elif ftype == 2:
            cur = (line + prev) % 256
        elif ftype in (3, 4):  # Average, Paeth: sequential, done byte by byte
            ln, up, cur = line.tolist(), prev.tolist(), [0] * rowbytes
            for i in range(rowbytes):
                a = cur[i - bpp] if i >= bpp else 0
                b = up[i]
                if ftype == 3:
                    cur[i] = (ln[i] + ((a + b) >> 1)) & 255
                else:
                    c = up[i - bpp] if i >= bpp else 0
                    p = a + b - c
                    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                    pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                    cur[i] = (ln[i] + pred) & 255
            cur = np.array(cur, dtype=np.int64)
        else:
            raise ValueError(f"bad PNG filter type {ftype}")
        out[r] = cur
        prev = cur
    return out, pos


def _samples(raw, width, depth, nch):
    """Unpacks filtered-out bytes of one image (or pass) into integer samples."""
    rows = raw.shape[0]
    if depth == 16:
        s = raw.reshape(rows, -1, 2).astype(np.uint32)
        s = (s[..., 0] << 8) | s[..., 1]
    elif depth == 8:
        s = raw.astype(np.uint32)
    else:
        bits = np.unpackbits(raw, axis=1).reshape(rows, -1, depth)
        weights = 1 << np.arange(depth - 1, -1, -1)
        s = (bits * weights).sum(axis=2).astype(np.uint32)
    return s[:, : width * nch].reshape(rows, width, nch)


def read_png(path):
    """Raw PNG samples as float64 RGB in [0,1], shape (height, width, 3)."""
    with open(path, "rb") as f:
        buf = f.read()
    if buf[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG file")
    pos, idat, palette = 8, [], None
    while pos < len(buf):
        (length,) = struct.unpack(">I", buf[pos : pos + 4])
        ctype = buf[pos + 4 : pos + 8]
        body = buf[pos + 8 : pos + 8 + length]
        pos += 12 + length
        if ctype == b"IHDR":
            width, height, depth, color, _, _, interlace = struct.unpack(">IIBBBBB", body)
        elif ctype == b"PLTE":
            palette = np.frombuffer(body, dtype=np.uint8).reshape(-1, 3)
        elif ctype == b"IDAT":
            idat.append(body)
        elif ctype == b"IEND":
            break
    data = zlib.decompress(b"".join(idat))
    nch = CHANNELS[color]
    bpp = max(1, nch * depth // 8)
    img = np.zeros((height, width, nch), dtype=np.uint32)
    passes = ADAM7 if interlace else [(0, 0, 1, 1)]
    p = 0
    for x0, y0, dx, dy in passes:
        pw = (width - x0 + dx - 1) // dx
        ph = (height - y0 + dy - 1) // dy
        if pw == 0 or ph == 0:
            continue
        raw, p = _unfilter(data, p, ph, (pw * nch * depth + 7) // 8, bpp)
        img[y0::dy, x0::dx] = _samples(raw, pw, depth, nch)
    if color == 3:
        rgb = palette[img[..., 0]].astype(np.float64) / 255.0
    else:
        vals = img.astype(np.float64) / float((1 << depth) - 1)
        rgb = vals[..., :3] if nch >= 3 else np.repeat(vals[..., :1], 3, axis=2)
    return np.ascontiguousarray(rgb)


def reference(pa, pb):
    a, b = read_png(pa), read_png(pb)
    if a.shape != b.shape:
        raise ValueError(f"{pa} and {pb} differ in size: {a.shape} vs {b.shape}")
    with np.errstate(divide="ignore"):  # identical pictures: PSNR is +inf
        psnr = float(peak_signal_noise_ratio(a, b, data_range=1.0))
    return float(structural_similarity(a, b, **SSIM_ARGS)), psnr


POVRAY_SCENES = "/usr/share/povray-3.7/scenes/advanced"
POVRAY_RENDERS = [  # (output, scene, extra options)
    ("biscuit.png", "biscuit.pov", ["+FN8", "-A"]),
    ("biscuit16.png", "biscuit.pov", ["+FN16", "-A"]),
    ("biscuit_rgba.png", "biscuit.pov", ["+FN8", "+UA", "-A"]),
    ("biscuit_aa.png", "biscuit.pov", ["+FN8", "+A0.1"]),
    ("woodbox.png", "woodbox.pov", ["+FN8", "-A"]),
]


def _write_png(path, v, color):
    """Minimal PNG writer for 16-bit samples (Pillow cannot write 16-bit RGB)."""
    h, w = v.shape[:2]
    raw = b"".join(b"\x00" + v[y].astype(">u2").tobytes() for y in range(h))

    def chunk(t, body):
        return struct.pack(">I", len(body)) + t + body + struct.pack(">I", zlib.crc32(t + body))

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 16, color, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def make_pairs(d):
    """Renders and derives the verification pairs of docs/ssim.md; returns them."""
    from PIL import Image
    from scipy.ndimage import gaussian_filter

    os.makedirs(d, exist_ok=True)
    p = lambda name: os.path.join(d, name)  # noqa: E731
    for out, scene, opts in POVRAY_RENDERS:
        cmd = ["povray", "-D", "-V", *opts, "+W320", "+H240",
               "+L/usr/share/povray-3.7/include", f"+I{POVRAY_SCENES}/{scene}", f"+O{p(out)}"]
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

    def save8(arr, name, mode="RGB"):
        Image.fromarray(np.round(np.clip(arr, 0, 1) * 255).astype(np.uint8), mode).save(p(name))

    # The hand decoder must agree exactly with Pillow wherever Pillow is exact.
    for f in ["biscuit.png", "biscuit_aa.png", "woodbox.png", "biscuit_rgba.png"]:
        pil = np.asarray(Image.open(p(f)).convert("RGB"), dtype=np.float64) / 255.0
        assert np.array_equal(read_png(p(f)), pil), f

    rng = np.random.default_rng(20240611)
    a = read_png(p("biscuit.png"))
    save8(a + rng.normal(0, 0.05, a.shape), "biscuit_noise.png")
    save8(gaussian_filter(a, sigma=(1.0, 1.0, 0)), "biscuit_blur.png")
    save8(np.concatenate([a[:, 1:], a[:, -1:]], axis=1), "biscuit_shift.png")  # 1 px left
    save8(a + 0.1, "biscuit_bright.png")
    save8(a * 0.7, "biscuit_dark.png")
    save8(a @ np.array([0.2126, 0.7152, 0.0722]), "biscuit_gray.png", "L")
    Image.open(p("biscuit.png")).quantize(64).save(p("biscuit_pal.png"))
    a16 = read_png(p("biscuit16.png"))
    noisy16 = np.clip(a16 + rng.normal(0, 0.01, a16.shape), 0, 1)
    _write_png(p("biscuit16_noise.png"), np.round(noisy16 * 65535), 2)
    # Small and odd-sized, where the border handling weighs most.
    small = a[100:133, 50:77]
    save8(small, "small.png")
    save8(small + rng.normal(0, 0.1, small.shape), "small_noise.png")

    pairs = [
        ("biscuit.png", "biscuit.png"),
        ("biscuit.png", "biscuit_noise.png"),
        ("biscuit.png", "biscuit_blur.png"),
        ("biscuit.png", "biscuit_shift.png"),
        ("biscuit.png", "biscuit_bright.png"),
        ("biscuit.png", "biscuit_dark.png"),
        ("biscuit.png", "woodbox.png"),
        ("biscuit.png", "biscuit16.png"),
        ("biscuit16.png", "biscuit16_noise.png"),
        ("biscuit.png", "biscuit_aa.png"),
        ("biscuit.png", "biscuit_rgba.png"),
        ("biscuit.png", "biscuit_gray.png"),
        ("biscuit.png", "biscuit_pal.png"),
        ("small.png", "small_noise.png"),
    ]
    return [(p(x), p(y)) for x, y in pairs]


def synthetic(w, h, which):
    """The integer patterns of `synthetic` in src/ssim.rs's tests."""
    y, x, c = np.meshgrid(np.arange(h), np.arange(w), np.arange(3), indexing="ij")
    if which == 0:
        v = (x * 11 + y * 7 + c * 50) % 256
    else:
        v = (x * x + 3 * y + c * 29 + (x * y) % 17) % 256
    # Divided in f32 as Picture::from_rgb8 does, then widened.
    return (v.astype(np.float32) / np.float32(255)).astype(np.float64)


def run_rust(paths):
    """lancer's numbers for the pairs, from the ignored unit test."""
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    env = dict(os.environ, LANCER_SSIM_PAIRS=os.pathsep.join(os.path.abspath(p) for p in paths))
    cmd = ["cargo", "test", "--release", "--lib", "--quiet", "ssim::tests::pairs_from_env",
           "--", "--ignored", "--exact", "--nocapture"]
    out = subprocess.run(cmd, cwd=root, env=env, capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"cargo test failed:\n{out.stdout}\n{out.stderr}")
    rows = [l.split("\t") for l in out.stdout.splitlines() if l.startswith("LANCER_SSIM\t")]
    return [(float(r[1]), float(r[2])) for r in rows]


def run_compare(binary, paths):
    """lancer's numbers for the pairs, from the `lancer compare` command a user runs."""
    res = []
    for a, b in zip(paths[::2], paths[1::2]):
        out = subprocess.run([binary, "compare", a, b], capture_output=True, text=True)
        if out.returncode != 0:
            sys.exit(f"lancer compare {a} {b} failed ({out.returncode}):\n{out.stderr}")
        vals = dict(l.split(" ", 1) for l in out.stdout.splitlines() if " " in l)
        psnr = vals["psnr"].split()[0]
        res.append((float(vals["ssim"]), float("inf") if psnr == "inf" else float(psnr)))
    return res


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("files", nargs="*", help="pairs of PNG files: A B [C D ...]")
    ap.add_argument("--rust", action="store_true", help="also run lancer's SSIM and compare")
    ap.add_argument("--lancer", metavar="BIN",
                    help="with --rust: run `BIN compare A B` instead of the unit test")
    ap.add_argument("--tol", type=float, default=0.005, help="largest allowed |difference|")
    ap.add_argument("--markdown", action="store_true", help="print the --rust table as Markdown")
    ap.add_argument("--synthetic", action="store_true", help="numbers for the unit-test pair")
    ap.add_argument("--make-pairs", metavar="DIR", help="build the docs/ssim.md test pairs in DIR")
    args = ap.parse_args()

    if args.make_pairs:
        for a, b in make_pairs(args.make_pairs):
            print(a, b)
        return
    if args.synthetic:
        a, b = synthetic(24, 20, 0), synthetic(24, 20, 1)
        print(f"ssim {float(structural_similarity(a, b, **SSIM_ARGS))!r}")
        print(f"psnr {float(peak_signal_noise_ratio(a, b, data_range=1.0))!r}")
        return
    if not args.files or len(args.files) % 2:
        ap.error("give an even number of PNG files (pairs)")
    pairs = list(zip(args.files[::2], args.files[1::2]))
    refs = [reference(a, b) for a, b in pairs]
    if not args.rust:
        for (a, b), (s, p) in zip(pairs, refs):
            print(f"{s:.10f}\t{p:.6f}\t{a}\t{b}")
        return

    ours = run_compare(args.lancer, args.files) if args.lancer else run_rust(args.files)
    if len(ours) != len(pairs):
        sys.exit(f"expected {len(pairs)} results from cargo, got {len(ours)}")
    worst = 0.0
    if args.markdown:
        print("| A | B | scikit-image | lancer | difference |")
        print("|---|---|---:|---:|---:|")
    else:
        print(f"{'scikit-image':>14} {'lancer':>14} {'difference':>11}  pair")
    for (a, b), (s, _), (r, _) in zip(pairs, refs, ours):
        d = r - s
        worst = max(worst, abs(d))
        na, nb = os.path.basename(a), os.path.basename(b)
        if args.markdown:
            print(f"| {na} | {nb} | {s:.8f} | {r:.8f} | {d:.1e} |")
        else:
            print(f"{s:14.10f} {r:14.10f} {d:11.2e}  {na} {nb}")
    print(f"\nlargest |difference| {worst:.2e} (tolerance {args.tol})")
    if worst > args.tol:
        sys.exit(1)


if __name__ == "__main__":
    main()
