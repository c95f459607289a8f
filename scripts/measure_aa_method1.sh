#!/usr/bin/env bash
# Measures POV-Ray's anti-aliasing method 1 (+AM1) on probe scenes, beside lancer: povray's
# "Samples" count (sub-sample rays) and the SSIM of the two pictures, without jitter so both
# are deterministic. The facts src/render/aa1.rs is built on (blocks of Render_Block_Size
# refined on their own, with a border row and column; pixels compared by their first sample
# with neighbours as they are, refined or not) come from these runs.
#   scripts/measure_aa_method1.sh [lancer binary]
set -euo pipefail
export LANCER_NO_CONFIG=1
root=$(cd "$(dirname "$0")/.." && pwd)
lancer=${1:-$root/target/release/lancer}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
probe() { # name, black box corners
  cat >"$tmp/$1.pov" <<POV
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0,0,-5> look_at 0 right x*0.32 up y*0.32 }
plane { z, 0 pigment { rgb 1 } finish { ambient 1 diffuse 0 } }
box { $2 pigment { rgb 0 } finish { ambient 1 diffuse 0 } }
POV
}
# A vertical edge in the left quarter of column 16 of 32, and the box's corner at the middle.
probe edge "<-1,-1,-1>, <0.0026,1,-0.1>"
probe corner "<-1,-1,-1>, <0.0026,0,-0.1>"
# Above the picture: the edge in row 0's upper quarter (compared with the row above the block).
probe top "<-1,-1,-1>, <1,0.1575,-0.1>"
# A noisy reflecting floor: thousands of refinements, every rule at once.
cat >"$tmp/water.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,1,-4> look_at <0,0,0> }
light_source { <-5,8,-5> rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.8,0.9,1>] [1 rgb <0.1,0.2,0.6>] } } }
plane { y, 0 pigment { rgb <0.05,0.15,0.2> } finish { reflection 0.5 specular 0.8 roughness 0.01 }
  normal { bumps 0.6 scale 0.05 } }
sphere { <0,0.5,2>, 0.5 pigment { checker rgb 1 rgb <1,0,0> scale 0.2 } }
POV
printf '%-7s %-36s %9s %14s %8s\n' scene options povray lancer ssim
run() { # scene, options...
  local name=$1
  shift
  local pov lan first
  pov=$(cd "$tmp" && povray -D -V +FN8 +A0.3 -J "$@" +WT1 "+I$name.pov" +Opov.png 2>&1 |
    grep -oE "Samples: +[0-9]+" | grep -oE "[0-9]+")
  lan=$(cd "$tmp" && "$lancer" -D +FN8 +A0.3 -J "$@" +WT1 "+I$name.pov" +Olan.png 2>&1 |
    grep -oE "\([0-9]+ camera\)" | grep -oE "[0-9]+")
  printf '%-7s %-36s %9s %14s %8s\n' "$name" "$*" "$pov" "$lan camera" \
    "$("$lancer" compare "$tmp/lan.png" "$tmp/pov.png" | awk '/^ssim/ {print $2}')"
}
for r in 1 2 3 4; do run edge +W32 +H32 +R$r; done
for bs in 16 8 4; do run edge +W32 +H32 +R3 +BS$bs; done
for r in 2 3; do run corner +W32 +H32 +R$r; done
run top +W32 +H32 +R3
run corner +W64 +H64 +R3 +SC10 +EC41 +SR10 +ER45
run water +W160 +H120 +R3
run water +W160 +H120 +R3 +BS8
run water +W160 +H120 +R3 +SC7 +EC99 +SR13 +ER101 +BS6
echo
echo "lancer's camera rays = first pass + border rays outside the picture or window + povray's Samples"
echo "(povray traces every block's border itself; lancer reuses the first pass inside the picture)."
