#!/usr/bin/env bash
# Measures POV-Ray 3.7's photon rules that render/photons.rs and render/shadow.rs follow:
#  1. which light / object photon settings make a glass sphere's shadow dark (its light then
#     arrives as photons only) - prints the floor's pixels across the shadow;
#  2. photon light through an ior-1 slab against the direct light it replaces (ratio 1);
#  3. the shadow edge of that slab seen from above: the estimate's radius in photon spacings.
# Results with povray 3.7.0.10 are in docs/photons.md.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
pov() { povray -D -V +FN8 -A "+W$2" "+H$3" +L. "+I$1.pov" "+O$1.png" 2>&1 | grep -i "photons stored" || true; }
cat > sphere.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 GLOBAL }
camera { location <0, 4, -5> look_at <0, 0.6, 0> angle 40 }
light_source { <0, 8, 0> rgb 1 LIGHT }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0.05 diffuse 0.7 } }
sphere { <0, 1.2, 0>, 1 pigment { rgbf <1,1,1,1> } finish { ambient 0 diffuse 0 } interior { ior 1.5 } OBJ }
POV
G='photons { spacing 0.02 }'
variant() {
  sed "s/GLOBAL/$2/; s/LIGHT/$3/; s/OBJ/$4/" sphere.pov > "$1.pov"
  pov "$1" 160 120
  python3 - "$1" "$5" <<'PY'
import sys
from PIL import Image
a = Image.open(sys.argv[1] + ".png").convert("RGB")
print(f"{sys.argv[2]:70s}", [a.getpixel((x, 95))[0] for x in range(40, 120, 12)])
PY
}
variant a "" "" "" "no photons"
variant b "$G" "" "photons { target refraction on reflection on }" "target refraction reflection, light without block"
variant c "$G" "" "photons { target refraction on }" "target refraction only"
variant d "$G" "" "photons { target reflection on }" "target reflection only"
variant e "$G" "" "photons { target }" "target without refraction or reflection"
variant f "$G" "" "photons { refraction on }" "refraction without target"
variant g "$G" "photons { reflection off }" "photons { target refraction on }" "light photons { reflection off }"
variant h "$G" "photons { refraction off }" "photons { target refraction on }" "light photons { refraction off }"
variant i "$G" "" "photons { target refraction on } no_shadow" "no_shadow target (pass_through)"
cat > slab.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 GLOBAL }
camera { location <0, 6, -5> look_at <0, 0, 0> angle 50 }
light_source { LIGHT rgb 1 }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0.05 diffuse 0.7 } }
box { BOX pigment { rgbf <1,1,1,1> } finish { ambient 0 diffuse 0 } interior { ior 1 } photons { target refraction on } }
POV
slab() {
  for g in "" "$G"; do
    n=$1$([ -n "$g" ] && echo p || true)
    sed "s/GLOBAL/$g/; s/LIGHT/$2/; s/BOX/$3/" slab.pov > "$n.pov"
    pov "$n" 160 120
  done
  python3 - "$1" "$4" <<'PY'
import sys
import numpy as np
from PIL import Image
def lin(f):
    a = np.asarray(Image.open(f).convert("RGB")).astype(float)[:, :, 0] / 255
    return np.where(a <= 0.04045, a / 12.92, ((a + 0.055) / 1.055) ** 2.4)
r = lin(sys.argv[1] + "p.png") / lin(sys.argv[1] + ".png")
print(f"{sys.argv[2]:40s} photon / direct light, row 60:", np.round(r[60, 56:104:4], 2))
PY
}
slab s1 "<0, 8, 0>" "<-1.5, 1, -1.5>, <1.5, 1.3, 1.5>" "slab 1 above the floor"
slab s2 "<0, 8, 0>" "<-0.5, 5.5, -0.5>, <0.5, 5.6, 0.5>" "slab near the light"
slab s3 "<8, 5, 0>" "<-1.5, 1, -1.5>, <1.5, 1.3, 1.5>" "light at 50 degrees"
for sp in 0.02 0.04; do
  cat > edge$sp.pov <<POV
#version 3.7;
global_settings { assumed_gamma 1 photons { spacing $sp } }
camera { orthographic location <0, 10, 0> look_at <0, 0, 0> right 4*x up 4*y }
light_source { <0, 8, 0> rgb 1 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
box { <-5, 1, -5>, <0, 1.3, 5> pigment { rgbf <1,1,1,1> } finish { ambient 0 diffuse 0 } interior { ior 1 } photons { target refraction on } }
POV
  sed "s/photons { spacing $sp }//" edge$sp.pov > edgen.pov
  pov edge$sp 160 160
  pov edgen 160 160 >/dev/null
  python3 - "$sp" <<'PY'
import sys
import numpy as np
from PIL import Image
def lin(f):
    a = np.asarray(Image.open(f).convert("RGB")).astype(float)[:, :, 0] / 255
    return np.where(a <= 0.04045, a / 12.92, ((a + 0.055) / 1.055) ** 2.4)
r = (lin(f"edge{sys.argv[1]}.png") / lin("edgen.png"))[60:100].mean(axis=0)
print(f"shadow edge (x = 0 at column 80, 0.025 units a column), spacing {sys.argv[1]}:", np.round(r[66:82], 2))
PY
done
