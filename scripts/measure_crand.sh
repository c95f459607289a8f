#!/usr/bin/env bash
# Measures povray's `crand`: a flat plane lit head-on (diffuse 1, pigment 1) rendered at
# 100x100 as linear 16-bit PPM, printing the 10th, 50th and 90th percentile of the red
# channel. tests/crand.rs holds these numbers. One light: uniform over [1-crand, 1]; two lights
# of half strength: the triangular spread of two independent draws.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
command -v povray >/dev/null || { echo "povray not found: apt-get install povray" >&2; exit 1; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
for lights in "light_source { <0,0,-1000> rgb 1 }" \
  "light_source { <0,0,-1000> rgb 0.5 } light_source { <0,1,-1000> rgb 0.5 }"; do
  cat > "$tmp/c.pov" <<POV
#version 3.7; global_settings { assumed_gamma 1.0 }
camera { orthographic location <0,0,-1> look_at 0 right x up y }
$lights
plane { z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 crand 0.5 } }
POV
  povray -D -V +FP16 -A +W100 +H100 File_Gamma=1.0 "+I$tmp/c.pov" "+O$tmp/c.ppm" 2>/dev/null
  python3 - "$tmp/c.ppm" "$lights" "$here" <<'PY'
import sys
sys.path.insert(0, sys.argv[3])
from ppm import read
v = sorted(p[0] for row in read(sys.argv[1]) for p in row)
n = len(v)
print(f"{sys.argv[2]}: p10 {v[n//10]:.4f} median {v[n//2]:.4f} p90 {v[9*n//10]:.4f}")
PY
done
