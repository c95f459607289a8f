#!/usr/bin/env bash
# Measures POV-Ray 3.7's omnimax camera: which direction it traces through each pixel.
# A sky_sphere whose colour is the ray direction ((d + 1) / 2 in 16-bit linear RGB) is rendered
# by povray; the script reads the directions back and prints
#  1. the angle from the view axis along one picture row (8193 pixels, right = up): an odd
#     quintic in the distance r from the disc's centre (least squares, residual ~2e-5 rad, the
#     16-bit measurement's noise) -> omnimax_theta in src/render/camera.rs;
#  2. for several right/up ratios, the disc's scale and centre (fitted with that angle law),
#     and the dome's lower edge -> omnimax_disc.
# usage: scripts/measure_omnimax.sh   (needs povray, python3 with numpy and scipy)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat > "$tmp/dir.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 }
#declare Up = 1;
camera { omnimax location 0 right x*R up y*Up direction z }
sky_sphere { pigment { average pigment_map {
  [1 function { 0.5 + 0.5*x } color_map { [0 rgb 0] [1 rgb <3,0,0>] }]
  [1 function { 0.5 + 0.5*y } color_map { [0 rgb 0] [1 rgb <0,3,0>] }]
  [1 function { 0.5 + 0.5*z } color_map { [0 rgb 0] [1 rgb <0,0,3>] }]
} } }
POV
pov() { povray -D -V -A +FP16 File_Gamma=1 "+I$tmp/dir.pov" "$@" 2>/dev/null; }
pov +W8193 +H3 Declare=R=1 "+O$tmp/row.ppm"
for r in 0.75 1 1.1 1.2 1.3333333 2 3; do pov +W321 +H241 "Declare=R=$r" "+O$tmp/r$r.ppm"; done
python3 - "$tmp" "$here" <<'PY'
import sys, math, glob
import numpy as np
sys.path.insert(0, sys.argv[2])
from ppm import read_array
from scipy.optimize import least_squares
tmp = sys.argv[1]
def read(fn):
    return read_array(fn) * 2 - 1
def angles(d):
    ok = abs(np.linalg.norm(d, axis=2) - 1) < 0.002
    return ok, np.arctan2(np.hypot(d[..., 0], d[..., 1]), d[..., 2]), np.arctan2(d[..., 1], d[..., 0])
row = read(tmp + '/row.ppm')[1]
W = row.shape[0]; c = W // 2
r = 2 * np.arange(0, c + 1) / W
ok, th, _ = angles(row[None, c:])
r, th = r[ok[0]], th[0][ok[0]]
A = np.stack([r, r**3, r**5], 1)
co = np.linalg.lstsq(A, th, rcond=None)[0]
print('1. angle from the axis: theta(r) = %.8f r %+.8f r^3 %+.8f r^5 (max residual %.1e rad over %d pixels)'
      % (co[0], co[1], co[2], abs(A @ co - th).max(), len(r)))
f = lambda x: x * (co[0] + x * x * (co[1] + x * x * co[2]))
lo, hi = 0.0, 1.0
for _ in range(60):
    m = (lo + hi) / 2
    lo, hi = (m, hi) if f(m) < math.pi / 4 else (lo, m)
print('   theta = 45 deg at r = %.7f; 2/(1+r) = %.7f' % (lo, 2 / (1 + lo)))
print('2. disc x = sx*u, y = sy*(v - v0) (u, v from -1/2 to 1/2, v up); rows below 45 deg cut:')
for fn in sorted(glob.glob(tmp + "/r[0-9]*.ppm")):
    R = float(fn.split('/r')[-1][:-4])
    d = read(fn); H, W = d.shape[:2]
    U = ((np.arange(W) + 0.5) / W - 0.5)[None, :].repeat(H, 0)
    V = (0.5 - (np.arange(H) + 0.5) / H)[:, None].repeat(W, 1)
    ok, th, ph = angles(d)
    sel = ok & (th < 1.5)
    u, v, t = U[sel], V[sel], th[sel]
    res = lambda p: f(np.hypot(p[0] * u, p[1] * (v - p[2]))) - t
    p = least_squares(res, [2, 2, 0]).x
    cut = ok.sum(), (ok & (np.sin(th) * np.sin(ph) + np.cos(th) < -1e-3)).sum()
    print('   right/up %.4f: sx %.5f sy %.5f v0 %+.5f (max residual %.1e); traced pixels %d, of them below the 45 deg edge %d'
          % (R, p[0], p[1], p[2], abs(res(p)).max(), cut[0], cut[1]))
PY
