#!/usr/bin/env bash
# Measures povray's fog turbulence: an orthographic camera at z = -10 looks along +z at a black
# wall 10 away (a row of 64 pixels over x in [-2, 2]) through a white fog of distance 20,
# read at 16 bits (linear). Prints, per case, the fog's effective depth d' = -20 ln(1 - v)
# relative to d (d'/d - 1) at four pixels, beside what the rule in render/fog.rs (stirred)
# predicts with T = marble's turbulence read from povray itself (a `marble ramp_wave
# turbulence 1` pattern function: x + T, wrapped). Rule: d'/d - 1 = -min(turb_depth*T, 1) *
# exp(-d/distance), T at turbulence * (the ray's midpoint); the same factor on ground fog's
# depth. Cases vary the turbulence vector, turb_depth, octaves/omega/lambda, and fog_type.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
command -v povray >/dev/null || { echo "povray not found: apt-get install povray" >&2; exit 1; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
case_() { # case_ TURB DEPTH OCT OMEGA LAMBDA EXTRA
  cat > f.pov <<POV
#version 3.7; global_settings { assumed_gamma 1.0 }
camera { orthographic location <0,0,-10> look_at <0,0,0> right 4*x up 0.0625*y }
plane { -z, 0 pigment { rgb 0 } finish { ambient 0 diffuse 0 } }
fog { distance 20 color rgb 1 turbulence $1 turb_depth $2 octaves $3 omega $4 lambda $5 $6 }
POV
  povray -D -V +FP16 -A +W64 +H1 File_Gamma=1.0 +If.pov +Of.ppm 2>/dev/null
  python3 - "$here" "$@" <<'PY'
import sys, math, subprocess
sys.path.insert(0, sys.argv[1])
from ppm import read
turb, depth, octv, omega, lam = sys.argv[2], float(sys.argv[3]), sys.argv[4], sys.argv[5], sys.argv[6]
t = [float(v) for v in turb.strip('<>').split(',')] if turb.startswith('<') else [float(turb)] * 3
pix = (0, 16, 32, 48)
xs = [-2 + (i + 0.5) * 4 / 64 for i in pix]
lines = ['#version 3.7; global_settings { assumed_gamma 1.0 }',
         '#declare M = function { pattern { marble ramp_wave turbulence <1,1,1> octaves %s omega %s lambda %s } }' % (octv, omega, lam),
         '#fopen F "t.txt" write']
for x in xs:  # the ray's midpoint is (x, 0, -5)
    p = (t[0] * x, 0.0, t[2] * -5.0)
    lines.append('#write(F, str(M(%r,%r,%r),0,12), "\\n")' % p)
lines.append('#fclose F')
open('t.pov', 'w').write('\n'.join(lines))
subprocess.run(['povray', '-D', '-V', '+W1', '+H1', '+It.pov'], capture_output=True)
row = read('f.ppm')[0]
out = []
for k, (x, l) in enumerate(zip(xs, open('t.txt'))):
    v = float(l) - t[0] * x
    meas = -20 * math.log(1 - row[pix[k]][0]) / 10 - 1
    # The pattern value is wrapped into [0, 1): take the T whose prediction is nearest.
    preds = [-min(depth * (v + j * 1.00001), 1) * math.exp(-0.5) for j in range(-3, 4)]
    pred = min(preds, key=lambda p: abs(p - meas))
    out.append('%.5f/%.5f' % (meas, pred))
print(' '.join(sys.argv[2:7]), sys.argv[7] if len(sys.argv) > 7 else '', ' measured/rule:', ' '.join(out))
PY
}
case_ "<0,0,0.5>" 0.5 6 0.5 2 ""
case_ "<0,0,0.5>" 0.25 6 0.5 2 ""
case_ "<0,0,1>" 0.5 6 0.5 2 ""
case_ "<0.5,0.5,0.5>" 0.5 6 0.5 2 ""
case_ "<0.5,0.5,0.5>" 1 6 0.5 2 ""
case_ "<0.5,0.3,0.7>" 0.7 4 0.6 2.5 ""
case_ "<0.5,0.3,0.7>" 0.4 6 0.5 2 "fog_type 2 fog_offset 100 fog_alt 1"
