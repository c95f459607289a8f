#!/usr/bin/env bash
# Prints POV-Ray's quilted pattern value (a pigment function's red through a black-to-white
# map) along x in [-0.5, 0.5] on the lines (x, 0.1, 0.2), (x, 0, 0), (x, x, 0) and
# (x, 0.3, 0.3), for a few control0/control1 pairs: the data for fitting quilted (not yet
# done; docs/povray-behaviour.md, Normals).
set -euo pipefail
d=$(mktemp -d)
cat > "$d/q.pov" <<POV
#version 3.7;
#declare P = function { pigment { quilted control0 C0 control1 C1 color_map { [0 rgb 0] [1 rgb 1] } } }
#fopen F "$d/q.txt" write
#for (i,0,10)
#local X=-0.5+i/10;
#write (F, X, " ", P(X,0.1,0.2).red, " ", P(X,0,0).red, " ", P(X,X,0).red, " ", P(X,0.3,0.3).red, "\n")
#end
#fclose F
camera{} sphere{0,1 pigment{rgb 1}}
POV
for c in "0 1" "1 1" "0 0" "0.5 0.5"; do
  set -- $c
  (cd "$d" && povray -D -V +W8 +H8 -A Declare=C0="$1" Declare=C1="$2" +Iq.pov +Oq.png 2>/dev/null)
  echo "control0 $1 control1 $2: x (x,.1,.2) (x,0,0) (x,x,0) (x,.3,.3)"
  cat "$d/q.txt"
done
rm -rf "$d"
