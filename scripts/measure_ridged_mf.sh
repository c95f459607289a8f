#!/usr/bin/env bash
# Prints povray's f_ridged_mf (internal 59) values: at the unit test's points (the first call
# of the run, so its own H and lacunarity weigh the octaves), then a run whose first call has
# H 0, after which H changes nothing in any later call (povray keeps the first call's octave
# weights; see src/func/internal.rs ridged_mf).
set -euo pipefail
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT; cd "$dir"
cat > a.pov <<'EOF'
#declare f_ridged_mf = function { internal(59) }
#declare P = array[4] { <1,2,3>, <-0.5,0.3,0.2>, <0.2,-1.5,0.7>, <0,0,0.4> }
#for (i, 0, 3) #declare V = P[i];
 #debug concat("f_ridged_mf(", vstr(3, V, ",", 0, 1), ", 0.07, 2.2, 7, 0.6, 0.9, 1) = ", str(f_ridged_mf(V.x,V.y,V.z,0.07,2.2,7,0.6,0.9,1),0,15), "\n")
#end
EOF
cat > b.pov <<'EOF'
#declare f_ridged_mf = function { internal(59) }
#declare V = <0.3,0.7,0.2>;
#for (H, 0, 2, 0.5)
 #debug concat("H ", str(H,0,1), ": ", str(f_ridged_mf(V.x,V.y,V.z,H,2,2,1,1,2),0,12), "\n")
#end
EOF
for s in a b; do povray -D -V +W8 +H8 "+I$s.pov" -F 2>&1 | grep -E "^(f_|H )"; done
