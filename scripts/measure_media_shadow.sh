#!/usr/bin/env bash
# How POV-Ray 3.7 samples media along shadow rays, and which points of an area light media
# scattering sees.
# 1. A parallel light shines along +y through a box (y 0..1) of absorbing media onto a wall
#    at y = 1.5, seen from between box and wall; the density is a step (y > x), one picture
#    column per position x. Each time the step passes a sample point of the shadow ray the
#    column's optical depth drops by that sample's weight: prints the positions (in the
#    shadow ray's distance from where it enters the box, 1 - x) and weights.
# 2. Scattering media under an area light (4x4, no jitter) half hidden by a wall: prints the
#    in-scattered light across the penumbra (four levels: the light's four columns).
# 3. A box of scattering media whose density steps from 0.05 to 1 at x = 0.6, lit from +x by
#    a light, then by the same light made shadowless: prints the scattered light per column
#    (the shadowed light's thin part is dimmed by the dense part; the shadowless light
#    scatters nothing at all).
# usage: scripts/measure_media_shadow.sh   (needs povray and python3 with numpy)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat > "$tmp/sh.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0.5, 1.2, 0.5> look_at <0.5, 2, 0.5> right -x up z*0.01 }
light_source { <0.5, -1000, 0.5> rgb 1 parallel point_at <0.5, 0, 0.5> }
plane { -y, -1.5 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
box { <0,0,0>, <1,1,1> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow
  interior { media { absorption A method 3 samples S, S intervals 1
    density { function { y > x } } } } }
POV
cat > "$tmp/al.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0.5, -5> look_at <0, 0.5, 0> right x*6 up y*0.06 }
light_source { <0, 10, 0> rgb 1 area_light 4*x, 4*z, 4, 4 }
box { <-10, 5, -10>, <0, 5.1, 10> pigment { rgb 0 } }
box { <-3, 0, -0.5>, <3, 1, 0.5> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow
  interior { media { scattering { 1, 0.5 } method 3 samples 3,3 } } }
background { rgb 0 }
POV
for s in 3 7 15; do
  povray -D -V -A +W400 +H3 +FP16 File_Gamma=1 "Declare=S=$s" "Declare=A=0.5" \
    "+I$tmp/sh.pov" "+O$tmp/sh.ppm" 2>/dev/null
  python3 - "$tmp/sh.ppm" "$s" "$here" <<'PY'
import sys
import numpy as np
sys.path.insert(0, sys.argv[3])
from ppm import read_array
r = read_array(sys.argv[1])[1, :, 0]
od = -np.log(np.maximum(r, 1e-9)) / 0.5
w = len(r)
x = (np.arange(w) + 0.5) / w
drops = [(1 - x[i], od[i-1] - od[i]) for i in range(1, w) if abs(od[i] - od[i-1]) > 1e-4]
drops.append((0.0, od[-1]))
print(f"shadow ray, samples {sys.argv[2]}: optical depth {od[0]:.4f} for density 1; "
      "sample points (distance along the shadow ray from where it enters the box) : weight")
print("   " + " ".join(f"{p:.3f}:{dw:.4f}" for p, dw in sorted(drops)))
PY
done
povray -D -V -A +W300 +H3 +FP16 File_Gamma=1 "+I$tmp/al.pov" "+O$tmp/al.ppm" 2>/dev/null
python3 - "$tmp/al.ppm" "$here" <<'PY'
import sys
sys.path.insert(0, sys.argv[2])
from ppm import read_array
r = read_array(sys.argv[1])[1, :, 0]
print("area light 4x4 over scattering media, x = -3..3 in 300 columns, every 12th:")
print("   " + " ".join(f"{v:.4f}" for v in r[::12]))
PY
cat > "$tmp/ss.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0.5, 0.5, -1> direction z right x up y }
light_source { <100, 0.5, 0.5> rgb 1 #if (SL) shadowless #end }
box { <0, 0, 0>, <1, 1, 1> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow
  interior { media { scattering { 1, 3 extinction 1 } method 3 samples 3, 3
    density { function { select(x - 0.6, 0.05, 1) } } } } }
background { rgb 0 }
POV
for sl in 0 1; do
  povray -D -V -A +W10 +H3 +FP16 File_Gamma=1 "Declare=SL=$sl" "+I$tmp/ss.pov" "+O$tmp/ss.ppm" 2>/dev/null
  python3 - "$tmp/ss.ppm" "$sl" "$here" <<'PY'
import sys
sys.path.insert(0, sys.argv[3])
from ppm import read_array
r = read_array(sys.argv[1])[1, :, 0]
print(f"scattering lit by a {'shadowless ' if sys.argv[2] == '1' else ''}light, x = 0.05..0.95:")
print("   " + " ".join(f"{v:.4f}" for v in r))
PY
done
