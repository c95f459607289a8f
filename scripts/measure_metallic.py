#!/usr/bin/env python3
"""Measures how POV-Ray 3.7's `metallic` tint fades towards white at glancing angles.

An orthographic camera looks along +z at a unit sphere with pigment rgb <1, 0.2, 0> in front
of a white background. With `finish { ambient 0 diffuse 0 reflection { 1 metallic } }` a pixel
shows the reflection's tint: 1 + (c - 1)(1 - k), so its blue channel is k. With `phong 1
phong_size 1 metallic` under a parallel light from the camera (reflection off) blue over red is
the highlight's k. The angle between the normal and the ray is asin(x) at a pixel x across the
sphere's middle row; two renders (x in [0, 1] and a zoom on [0.99, 1]) cover the angles.
16-bit PPM with File_Gamma 1, so values are linear.

Prints `angle_degrees k_reflection k_highlight` every 0.5 degrees from 0 to 89.5 (linear
interpolation between pixels). RENDERER=target/release/lancer measures lancer the same way.
"""
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from measure_normals import read_ppm  # noqa: E402

SCENE = """#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <X0 + 0.5 * WX, 0, -10> direction z right WX * x up WX * y / 4001 }
background { rgb 1 }
#if (Mode = 0)
sphere { 0, 1 pigment { rgb <1, 0.2, 0> } finish { ambient 0 diffuse 0 reflection { 1 metallic } } }
#else
light_source { <0, 0, -1000> rgb 1 parallel point_at 0 }
sphere { 0, 1 pigment { rgb <1, 0.2, 0> } finish { ambient 0 diffuse 0 phong 1 phong_size 1 metallic } }
#end
"""


def row(mode, x0, wx, n=4001):
    d = tempfile.mkdtemp()
    src = os.path.join(d, "m.pov")
    open(src, "w").write(SCENE)
    out = os.path.join(d, "o.ppm")
    subprocess.run([os.environ.get("RENDERER", "povray"), "-D", "-V", "+FP16", "-A", f"+W{n}", "+H1",
                    f"Declare=Mode={mode}", f"Declare=X0={x0}", f"Declare=WX={wx}", "File_Gamma=1.0",
                    "+I" + src, "+O" + out], check=True, capture_output=True)
    _, _, px = read_ppm(out)
    pts = []
    for i, p in enumerate(px):
        x = x0 + (i + 0.5) * wx / n
        if x >= 1.0 or p[0] <= 0:
            continue
        k = p[2] if mode == 0 else p[2] / p[0]
        pts.append((math.degrees(math.asin(x)), k))
    return pts


def table(mode):
    pts = sorted(row(mode, 0.0, 1.0) + row(mode, 0.99, 0.01))
    out = []
    for a in [i * 0.5 for i in range(180)]:
        for (a0, k0), (a1, k1) in zip(pts, pts[1:]):
            if a0 <= a <= a1:
                out.append(k0 + (k1 - k0) * (a - a0) / (a1 - a0) if a1 > a0 else k0)
                break
        else:
            out.append(pts[0][1] if a < pts[0][0] else float("nan"))
    return out


if __name__ == "__main__":
    refl, high = table(0), table(1)
    for i, (r, h) in enumerate(zip(refl, high)):
        print(f"{i * 0.5:.1f} {r:.6f} {h:.6f}")
