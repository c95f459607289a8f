#!/usr/bin/env bash
# Measures POV-Ray 3.7's dispersion (render/dispersion.rs): a tiny white dot seen through a
# slab tilted 50 degrees, orthographic camera 100 px a unit. Each of the dispersion_samples
# images is printed with its centre column and colour: the column gives its ior (the slab
# shifts a ray by 2 sin(50° - θt) / cos θt, θt the refracted angle), the colour its share of
# the spectrum. The line scene gives the 10-bin colours (summed over a vertical white line,
# linear light, normalised to add up to 10) that scripts/dispersion_fit.py fits with the 2-
# and 3-bin ones.
# Results with povray 3.7.0.10: ior 1.5, dispersion 1.5, 3 samples: columns 110.5 122.5 138.5
# → iors 1.714 1.502 1.314 = 1.5 · 1.5^(1/3, 0, -1/3); 2 samples: 1.654 1.354 = 1.5 ·
# 1.5^(±1/4); colours in render/dispersion.rs.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
cat > d.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 }
camera { orthographic location <0,0,-10> look_at 0 right 4*x up 3*y }
box { <-3,-3,-1>, <3,3,1> rotate y*50 pigment { rgbf 1 } finish { ambient 0 diffuse 0 } interior { ior 1.5 dispersion 1.5 dispersion_samples N } }
sphere { <0,0,5>, 0.03 pigment { rgb 1 } finish { ambient 0 emission 1 diffuse 0 } }
POV
cat > line.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 }
camera { orthographic location <0,0,-10> look_at 0 right 4*x up 3*y }
box { <-3,-3,-1>, <3,3,1> rotate y*50 pigment { rgbf 1 } finish { ambient 0 diffuse 0 } interior { ior 1.41421356 dispersion 2 dispersion_samples 10 } }
box { <-0.006,-1,5>, <0.006,1,5.01> pigment { rgb 1 } finish { ambient 0 emission 1 diffuse 0 } }
POV
for n in 2 3; do
  sed "s/ N / $n /" d.pov > d$n.pov
  povray -D -V +FN8 -A +W400 +H300 +L. +Id$n.pov +Od$n.png 2>/dev/null
done
povray -D -V +FN8 -A +W800 +H600 +L. +Iline.pov +Oline.png 2>/dev/null
python3 - <<'PY'
import numpy as np
from PIL import Image
def lin(a):
    a = a / 255
    return np.where(a <= 0.04045, a / 12.92, ((a + 0.055) / 1.055) ** 2.4)
def blobs(prof):
    xs = np.nonzero(prof.sum(axis=1) > 0.001)[0]
    groups = []
    for c in xs:
        if groups and c - groups[-1][-1] <= 1:
            groups[-1].append(c)
        else:
            groups.append([c])
    return groups
for n in (2, 3):
    a = np.asarray(Image.open(f"d{n}.png").convert("RGB")).astype(float)
    for g in blobs(lin(a).max(axis=0)):
        print(f"{n} samples: column {(g[0] + g[-1]) / 2}, colour", a[:, g[0]:g[-1] + 1].reshape(-1, 3).max(axis=0))
prof = lin(np.asarray(Image.open("line.png").convert("RGB")).astype(float))[250:350].sum(axis=0)
main = [g for g in blobs(prof) if 150 < np.mean(g) < 450]
sums = [prof[g[0]:g[-1] + 1].sum(axis=0) for g in main]
tot = sum(sums)
for g, s in zip(main, sums):
    print(f"10 samples: column {np.mean(g):.0f}, share", np.round(s / tot * len(main), 2))
PY
