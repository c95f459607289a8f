#!/usr/bin/env bash
# Prints the image coordinates (u, v) POV-Ray 3.7 reads for image_map map_type $1 (default 5,
# the torus) at a few points: the image is a function image of x (for u) or y (for v), read
# back through a pigment function. Values near 0.5 at a seam are the interpolation between
# its two sides. A function image's y runs from its top row down, so v here is 1 - the file
# image's v. docs/povray-behaviour.md (Patterns) has what was found.
set -euo pipefail
t=${1:-5}
d=$(mktemp -d)
cat > "$d/m.pov" <<POV
#version 3.7;
global_settings { assumed_gamma 1 }
#declare PU = function { pigment { image_map { function 400,400 { x } map_type $t interpolate 2 } } }
#declare PV = function { pigment { image_map { function 400,400 { y } map_type $t interpolate 2 } } }
#fopen F "$d/m.txt" write
#declare Pts = array[8] { <2,0,0>, <0,0,2>, <-2,0,0>, <0,0,-2>, <1.5,0.3,0>, <1.5,-0.3,0>, <0.7,0.2,0>, <1.2,0.4,0.9> }
#for (i,0,7)
#write (F, Pts[i], " u ", PU(Pts[i].x,Pts[i].y,Pts[i].z).red, " v ", PV(Pts[i].x,Pts[i].y,Pts[i].z).red, "\n")
#end
#fclose F
camera{} sphere{0,1 pigment{rgb 1}}
POV
(cd "$d" && povray -D -V +W8 +H8 -A +Im.pov +O/dev/null 2>/dev/null)
cat "$d/m.txt"
rm -rf "$d"
