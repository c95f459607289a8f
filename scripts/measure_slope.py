#!/usr/bin/env python3
"""Measures POV-Ray 3.7's normal-dependent patterns (`slope`, `aoi`) from the binary.

A unit sphere at the origin seen by an orthographic camera from -z, its pigment the pattern
through a black-to-white map (`ambient 1 diffuse 0`, assumed_gamma 1, 16-bit linear PPM), so a
pixel's grey is the pattern value where the surface normal is n = (x, y, -sqrt(1 - x² - y²)).
Prints, for the pixels on the sphere, x y nx ny nz value; RENDERER=lancer measures lancer.

  scripts/measure_slope.py 'slope { y }' [size] [extra SDL after the pigment, e.g. 'rotate 30*z']
"""
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from measure_normals import read_ppm  # noqa: E402

BASE = """#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0,0,-10> direction z right 2.2*x up 2.2*y }
"""


def values(pattern, size=16, extra="", obj="sphere { 0, 1"):
    d = tempfile.mkdtemp()
    f = os.path.join(d, "s.pov")
    o = os.path.join(d, "o.ppm")
    open(f, "w").write(BASE + obj + " pigment { " + pattern +
                       " color_map { [0 rgb 0] [1 rgb 1] } } finish { ambient 1 diffuse 0 } "
                       + extra + " }\n")
    subprocess.run([os.environ.get("RENDERER", "povray"), "-D", "-V", "+FP16", "-A",
                    f"+W{size}", f"+H{size}", "File_Gamma=1.0", "+I" + f, "+O" + o],
                   check=True, capture_output=True)
    w, h, px = read_ppm(o)
    out = []
    for j in range(h):
        for i in range(w):
            x = -1.1 + (i + 0.5) * 2.2 / w
            y = 1.1 - (j + 0.5) * 2.2 / h
            r2 = x * x + y * y
            if r2 < 0.97:
                out.append((x, y, x, y, -(1 - r2) ** 0.5, px[j * w + i][0]))
    return out


if __name__ == "__main__":
    size = int(sys.argv[2]) if len(sys.argv) > 2 else 16
    extra = sys.argv[3] if len(sys.argv) > 3 else ""
    for row in values(sys.argv[1], size, extra):
        print(" ".join(f"{v:+.5f}" for v in row))
