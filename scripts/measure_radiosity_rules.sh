#!/usr/bin/env bash
# Radiosity rules read off the povray binary (docs/radiosity.md, "Measured rules"), each from a
# probe scene written here and povray's own output: its statistics and the sample file it
# saves with Radiosity_To_File (+RFO: one line per sample: C<depth>, position, packed normal,
# irradiance, reuse radius, nearest hit distance, packed mean light direction).
#
# 1. Reuse bounds per depth: the open box (tests/radiosity/open_box.inc) at recursion_limit 3;
#    each depth's reuse radius over its distance from the camera, min and max.
# 2. Gathering rays and area lights: shadow ray tests of a radiosity render with a point light
#    against the same light as a 4x4 area light, and the same without radiosity.
# 3. Gathering directions: the irradiance povray saves for a floor point under an emitting
#    disc seen within angle theta, against the cosine-weighted share sin^2(theta).
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
here=$(cd "$(dirname "$0")/.." && pwd)
inc=/usr/share/povray-3.7/include
pov() { povray -D -V +FN8 -A +WT1 "+L$tmp" "+L$here/tests/radiosity" "+L$inc" "$@" 2>&1; }

echo "## 1. reuse radius / camera distance by depth (open box, recursion_limit 3, 80x60)"
cat >"$tmp/box3.pov" <<'EOF'
#declare Rad_Recursion = 3;
#include "open_box.inc"
EOF
pov +W80 +H60 "+I$tmp/box3.pov" "+O$tmp/b.png" Radiosity_File_Name="$tmp/b.rca" Radiosity_To_File=on >/dev/null
python3 - "$tmp/b.rca" <<'EOF'
import math, sys
cam = (0, 1, -1.9)
by = {}
for line in open(sys.argv[1]):
    r = line.split("\t")
    d = math.dist(cam, tuple(map(float, r[1:4])))
    by.setdefault(r[0], []).append(float(r[8]) / d)
for k in sorted(by):
    print(f"{k}: {len(by[k])} samples, radius/distance from {min(by[k]):.4f} to {max(by[k]):.4f}")
EOF

echo
echo "## 2. shadow ray tests, a floor and a wall under one light (80x60)"
cat >"$tmp/al.pov" <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1.0
 #if (RAD) radiosity { pretrace_start 0.08 pretrace_end 0.04 count 100 error_bound 0.5 nearest_count 5 recursion_limit 1 } #end
}
camera { location <0, 3, -6> look_at <0, 0, 0> }
light_source { <0, 5, 0> rgb 1 #if (AL) area_light 2*x, 2*z, 4, 4 adaptive 0 #end }
plane { y, 0 pigment { rgb 1 } finish { diffuse 0.7 } }
box { <-3, 0, 3>, <3, 3, 3.1> pigment { rgb 1 } finish { diffuse 0.7 } }
EOF
for r in 0 1; do
  for a in 0 1; do
    t=$(pov +W80 +H60 "+I$tmp/al.pov" "+O$tmp/a.png" Declare=RAD=$r Declare=AL=$a | grep -oE "Shadow Ray Tests: +[0-9]+" | grep -oE "[0-9]+$")
    echo "radiosity $r, area light $a: $t shadow ray tests"
  done
done
echo "(gathering's share: radiosity 1 minus radiosity 0, for the point and for the area light)"

echo
echo "## 3. share of gathering rays within theta of the normal (count 100 and 1600)"
cat >"$tmp/disc.pov" <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1.0
  radiosity { pretrace_start 1 pretrace_end 1 count CNT error_bound 1 nearest_count 1 recursion_limit 1 }
}
camera { orthographic location <0, 10, 0> look_at <0, 0, 0> right x*0.001 up z*0.001 }
plane { y, 0 pigment { rgb 1 } finish { diffuse 1 ambient 0 } }
disc { <0, 1, 0>, y, A no_image pigment { rgb 1 } finish { emission 1 diffuse 0 } }
EOF
for c in 100 1600; do
  for deg in 10 30 50 70 80 85; do
    a=$(python3 -c "import math; print(math.tan(math.radians($deg)))")
    rm -f "$tmp/d.rca"
    pov +W1 +H1 "+I$tmp/disc.pov" "+O$tmp/d.png" Declare=A="$a" Declare=CNT=$c Radiosity_File_Name="$tmp/d.rca" Radiosity_To_File=on >/dev/null
    v=$(head -1 "$tmp/d.rca" | cut -f6)
    echo "count $c, theta $deg: povray $v, cosine-weighted $(python3 -c "import math; print(round(math.sin(math.radians($deg))**2, 4))")"
  done
done
