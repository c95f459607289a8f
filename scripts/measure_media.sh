#!/usr/bin/env bash
# Measures how povray 3.7 computes media, with probe scenes whose centre pixel is read back
# as a linear value (File_Gamma 1, 16-bit PPM). The facts lancer's media follow
# (src/scene/media.rs, src/render/media.rs) come from these numbers:
#  1. constant media: emission e over depth 1 with absorption a, for `samples` S, equals
#     e/n * sum_{i<n} exp(-a*i/n) with n = S/2 + 1 (at least 2); no `samples` is S = 10;
#  2. scattering phase functions (light at 1000 units, colour 0.1, depth 1): isotropic 1,
#     Mie haze 1.1533*(0.5 + 4.5*((1+c)/2)^8), Mie murky 0.9916*(0.5 + 25*((1+c)/2)^32),
#     Rayleigh 0.79935*(1 + c^2), Henyey-Greenstein (1-g^2)/(1+g^2-2gc)^1.5.
# usage: scripts/measure_media.sh   (needs povray and python3)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
cat > read.py <<PY
import sys
sys.path.insert(0, "$here")
from ppm import read
px = read(sys.argv[1])
print('%.5f' % px[len(px) // 2][len(px[0]) // 2][0])
PY
render() { # scene, declares...
  local s=$1; shift
  povray -D -V +FP16 File_Gamma=1.0 -A +W8 +H8 "$@" "+I$s" +Oo.ppm >/dev/null 2>&1
  python3 read.py o.ppm
}
cat > constant.pov <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0,0,-5> look_at 0 right x up y }
background { rgb 0 }
box { <-1,-1,0>, <1,1,1> hollow pigment { rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { media { emission 0.1 absorption A #ifdef (S) samples S #end } } }
EOF
echo "1. constant media, emission 0.1, depth 1: measured vs e/n*sum exp(-a i/n), n = S/2+1"
for S in 1 3 5 10 20 none; do
  for A in 1 4 16; do
    if [ $S = none ]; then v=$(render constant.pov Declare=A=$A); n=6; else v=$(render constant.pov Declare=A=$A Declare=S=$S); n=$(( (S < 2 ? 2 : S) / 2 + 1 )); fi
    python3 -c "import math; n=$n; a=$A; print('  samples $S absorption $A: povray $v  formula %.5f' % (0.1/n*sum(math.exp(-a*i/n) for i in range(n))))"
  done
done
cat > scatter.pov <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0,0,-5> look_at 0 right x*0.01 up y*0.01 }
background { rgb 0 }
light_source { vnormalize(<LX,0,LZ>)*1000, rgb 1 }
box { <-1,-1,0>, <1,1,1> hollow no_shadow pigment { rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { media { scattering { T, SC #if (T = 5) eccentricity 0.5 #end extinction 0 } } } }
EOF
echo "2. scattering, colour SC, depth 1: the phase value is povray's number / SC"
for T in 1 2 3 4 5; do
  for ang in 0 30 45 90 135 180; do
    read -r x z < <(python3 -c "import math; a=math.radians($ang); print(math.sin(a), math.cos(a))")
    sc=$([ $T = 3 ] && echo 0.01 || echo 0.1)
    v=$(render scatter.pov Declare=T=$T Declare=LX=$x Declare=LZ=$z Declare=SC=$sc)
    python3 -c "print('  type $T, light at $ang deg from straight behind: phase %.4f' % ($v / $sc))"
  done
done
