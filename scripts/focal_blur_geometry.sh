#!/usr/bin/env bash
# Measures POV-Ray 3.7's focal-blur lens (render/focal.rs cites the results): the blur of a
# straight edge and of a tiny bright sphere 10 units away, for several focal points and camera
# vector lengths. Prints each picture's blurred extent in pixels (400x300, no anti-aliasing).
#
# Results with povray 3.7.0.10 (disc radius R in pixels; lens radius r = aperture / 4 predicts
# R = r * |F - D| / D * W / (|right| * F) with D = 10, F = |focal_point - location|):
#   edge, direction z right 1.33x: columns 193..207 (R ~ 7.5; predicted 7.5)
#   edge, right 2.66x: 196..203 (halved: the lens does not grow with right)
#   edge, direction 2z: 186..215 (doubled: nor with direction)
#   bokeh, focal_point <0,0,5>: 170..229 x 120..180 (round, R ~ 30; predicted 30)
#   focal_point <0,0,2.5>: 107..291 (R ~ 92; predicted 90)
#   focal_point <0,0,7.5>: 189..210 (R ~ 11; predicted 10 plus the sphere's own size)
#   focal_point <3,0,5>: 178..221 (R ~ 22; predicted 21.5 with F = |<3,0,5>| = 5.83, but 30
#     with its depth 5: the distance to the focal point counts, not its depth)
#   sphere at <3,0,5>, focal_point <0,0,5>: 378..382, sharp (the zone of sharpness is a plane)
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
render() { povray -D -V +FN8 -A +W400 +H300 +L. "+I$1" "+O$2" 2>/dev/null; }
extent() {
  python3 - "$1" <<'PY'
import sys
from PIL import Image
import numpy as np
a = np.asarray(Image.open(sys.argv[1])).astype(float)[:, :, 0]
ys, xs = np.nonzero((a > 2) & (a < 253)) if (a >= 253).any() else np.nonzero(a > 0)
print(f"columns {xs.min()}..{xs.max()} rows {ys.min()}..{ys.max()}")
PY
}
edge() {
  cat > e.pov <<POV
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location 0 $1 aperture 1 blur_samples 100,400 focal_point <0,0,5> confidence 0.999 variance 1/100000 }
box { <-100,-100,10>, <0,100,11> pigment { rgb 1 } finish { ambient 0 emission 1 diffuse 0 } }
POV
  render e.pov e.png
  echo "edge $1: $(extent e.png)"
}
bokeh() {
  cat > b.pov <<POV
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location 0 direction z right 1.33*x up y aperture 4 blur_samples 300,300 focal_point $1 }
sphere { $2, 0.03 pigment { rgb 1 } finish { ambient 0 emission 1 diffuse 0 } }
POV
  render b.pov b.png
  echo "bokeh focal_point $1, sphere $2: $(extent b.png)"
}
edge "direction z right 1.33*x up y"
edge "direction z right 2.66*x up y"
edge "direction 2*z right 1.33*x up y"
for fp in "<0,0,5>" "<0,0,2.5>" "<0,0,7.5>" "<3,0,5>"; do bokeh "$fp" "<0,0,10>"; done
bokeh "<0,0,5>" "<3,0,5>"
