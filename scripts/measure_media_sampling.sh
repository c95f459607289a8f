#!/usr/bin/env bash
# Where POV-Ray 3.7's method 3 media samples a stretch, and how it weighs the samples: an
# emission-only box of depth 1 seen along z (orthographic), whose density is a step
# (z > x) moved through it, one picture column per position x. Each time the step passes a
# sample point the column's light drops by that sample's weight, so the drops give the points
# and their weights; with aa_threshold above the light's difference no step is split (the
# base pattern), below it the splits near the edge show (aa_level). A thin gaussian bump
# exp(-(z - x)^2 / (2 W^2)) is also compared for the refinement on smooth densities.
# The box is then made D deep (scale <1, 1, D>) and cut in I intervals: the split test
# compares the neighbouring samples' light times the interval's length D/I with aa_threshold.
# Prints, per setting, the positions where the light changes and the weight lost there.
# usage: scripts/measure_media_sampling.sh   (needs povray and python3 with numpy)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat > "$tmp/st.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0.5, 0.5, -1> direction z right x up y*0.01 }
box { <0,0,0>, <1,1,1> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow
  interior { media { emission E method 3 samples S, S intervals I aa_threshold T aa_level L
    density { function { z > x } } } } scale <1, 1, D> }
background { rgb 0 }
POV
run() { # S T L E [D I]
  povray -D -V -A +W400 +H3 +FP16 File_Gamma=1 "Declare=S=$1" "Declare=T=$2" "Declare=L=$3" \
    "Declare=E=$4" "Declare=D=${5:-1}" "Declare=I=${6:-1}" "+I$tmp/st.pov" "+O$tmp/p.ppm" 2>/dev/null
  python3 - "$here" "$tmp/p.ppm" "$1" "$2" "$3" "$4" "${5:-1}" <<'PY'
import sys
import numpy as np
sys.path.insert(0, sys.argv[1])
from ppm import read_array
a = read_array(sys.argv[2])
w = a.shape[1]
S, T, L, E = sys.argv[3:7]
D = float(sys.argv[7])
row = a[1, :, 0] / float(E) / D
x = (np.arange(w) + 0.5) / w
drops = [(x[i], row[i-1] - row[i]) for i in range(1, w) if abs(row[i] - row[i-1]) > 1e-5]
print(f"samples {S} aa_threshold {T} aa_level {L} emission {E} depth {D:g}: light {row[0]:.4f} at x=0, "
      f"{len(drops)} drops")
print("   at x ~ " + " ".join(f"{p:.3f}:{dw:.4f}" for p, dw in drops[:40]))
PY
}
for s in 3 7 15; do run "$s" 1000 3 0.5; done   # base pattern: points k/(S+3), weights
run 7 0.1 1 0.5      # aa_level 1: no split
run 7 0.1 2 0.5      # one split
run 7 0.1 3 0.5      # the default: two splits
run 7 0.1 3 0.03     # channel sum 0.09 < 0.1: no split
run 7 0.1 3 0.035    # 0.105 > 0.1: split
# Deeper boxes: the test is (summed difference) x depth > aa_threshold, for any samples.
run 7 0.1 3 0.008 4      # 0.096: no split
run 7 0.1 3 0.0087 4     # 0.104: split
run 15 0.1 3 0.008 4
run 15 0.1 3 0.0087 4
run 3 0.1 3 0.0087 4
run 7 0.1 3 0.035 0.25   # 0.026: no split (split at depth 1)
# intervals 2: each half sampled apart (points 0..0.4 and 0.5..0.9), tested with length 0.5
run 7 0.1 3 0.05 1 2     # 0.075: no split
run 7 0.1 3 0.2 1 2      # 0.3: split
