#!/usr/bin/env bash
# Measures povray's fake caustics (`interior { caustics C }`): a floor lit from straight above
# by a parallel light of 0.1 under a filter-1 surface tilted by THETA, read at 16 bits (linear).
# Prints, per tilt and C, the gain (floor / unshadowed floor) and the exponent p of
# gain = 1 + cos(THETA)^p divided by C; povray gives p/C = 45 (to the 16-bit step), the gain
# is 2 at THETA 0 for any C > 0, and a slab (two crossings) gives the square of one plane's
# gain. src/scene/desc.rs (Interior::caustic_gain) and tests/probes/caustics.pov use this.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
command -v povray >/dev/null || { echo "povray not found: apt-get install povray" >&2; exit 1; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
floor() { # floor THETA C plane|slab
  local obj="plane { y, 1 hollow"
  [ "$3" = slab ] && obj="box { <-5, 0.9, -5>, <5, 1, 5> hollow"
  cat > "$tmp/c.pov" <<POV
#version 3.7; global_settings { assumed_gamma 1.0 }
camera { orthographic location <0,5,0> look_at 0 right 0.2*x up 0.2*z }
light_source { <0,1000,0> rgb 0.1 parallel point_at 0 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
$obj pigment { rgbf <1,1,1,1> } finish { ambient 0 diffuse 0 } interior { caustics $2 } rotate $1*z }
POV
  povray -D -V +FP16 -A +W4 +H4 File_Gamma=1.0 "+I$tmp/c.pov" "+O$tmp/c.ppm" 2>/dev/null
  python3 -c "import sys; sys.path.insert(0, '$here'); from ppm import read; print(read('$tmp/c.ppm')[2][2][0])"
}
base=$(floor 0 0 plane)
echo "theta C kind gain p/C"
for kind in plane slab; do
  for theta in 0 10 20 30; do
    for c in 0.25 0.5 1 2; do
      v=$(floor "$theta" "$c" "$kind")
      python3 -c "
import math
g = $v / $base
one = math.sqrt(g) if '$kind' == 'slab' else g
cos = math.cos(math.radians($theta))
p = math.log(one - 1) / math.log(cos) / $c if $theta > 0 and 1 + 1e-4 < one < 2 - 1e-4 else float('nan')
print('$theta $c $kind %.5f %.3f' % (g, p))"
    done
  done
done
