#!/usr/bin/env python3
"""Checks the quilted rule of docs/textures.md against the `povray` binary (or RENDERER).

The rule: d = p - floor(p) - 1/2, t = |d|, B(t) = 3(1-t)^2 t c0 + 3(1-t) t^2 c1 + t^3,
V = d (2/sqrt 3) B(t); the pattern value is (|Vx|+|Vy|+|Vz|)/3 and `normal { quilted A }` is
n + A V. Prints the largest difference between the rule and the binary: pattern values at 30
random points for several control pairs (scripts/measure_pattern.py), and perturbed normals on
a 12x12 grid of a plane (scripts/measure_normals.py, 16-bit, so about 1e-5).
"""
import math
import os
import random
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from measure_normals import coords, render  # noqa: E402


def vector(p, c0, c1):
    d = [x - math.floor(x) - 0.5 for x in p]
    t = math.sqrt(sum(x * x for x in d))
    b = 3 * (1 - t) ** 2 * t * c0 + 3 * (1 - t) * t * t * c1 + t ** 3
    return [x * b * 2 / math.sqrt(3) for x in d]


def pattern_values(spec, pts):
    here = os.path.dirname(os.path.abspath(__file__))
    args = ["python3", os.path.join(here, "measure_pattern.py"), spec] + ["%r,%r,%r" % p for p in pts]
    out = subprocess.run(args, capture_output=True, text=True).stdout.split("\n")
    return [float(l.split()[3]) for l in out if l.strip()]


def main():
    random.seed(3)
    pts = [tuple(round(random.uniform(-3, 3), 4) for _ in range(3)) for _ in range(30)]
    for c0, c1 in [(0, 0), (0.3, 0.8), (1, 1), (-0.5, 2)]:
        got = pattern_values(f"quilted control0 {c0} control1 {c1}", pts)
        err = max(abs(g - sum(abs(v) for v in vector(p, c0, c1)) / 3) for p, g in zip(pts, got))
        print(f"value  control0 {c0} control1 {c1}: max difference {err:.2e}")
    w = h = 12
    for a, c0, c1, tz in [(1, 0, 0, 0.3), (0.7, 0.5, 1, 0.8)]:
        spec = f"quilted {a} control0 {c0} control1 {c1} translate <0.1,0.2,{tz}>"
        n = render("plane { -z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } normal { "
                   + spec + " } }\n", w, h)
        err = 0
        for j in range(h):
            for i in range(w):
                x, y = coords(i, j, w, h)
                v = vector((x - 0.1, y - 0.2, -tz), c0, c1)
                m = [a * v[0], a * v[1], -1 + a * v[2]]
                ln = math.sqrt(sum(q * q for q in m))
                pred = (m[0] / ln, m[1] / ln, -m[2] / ln)
                err = max(err, max(abs(p - g) for p, g in zip(pred, n[j * w + i])))
        print(f"normal {spec}: max difference {err:.2e}")


if __name__ == "__main__":
    main()
