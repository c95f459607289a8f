#!/usr/bin/env python3
"""Print POV-Ray 3.7's value of `tiling N` at points of the x-z plane, read from the binary.

`tiling` cannot be used in `function { pattern { } }` in 3.7.0, so the value is read as the red
channel of `function { pigment { tiling N color_map { [0 rgb 0] [1 rgb 1] } } }`, which is the
pattern value itself (a linear map over [0, 1]). This is how the tiling rules in
docs/textures.md were measured.

  scripts/measure_tiling.py N --grid X0 X1 Z0 Z1 NX NZ      prints "x z value" on a grid
  scripts/measure_tiling.py N x,z x,z ...                    prints the same at given points

RENDERER=target/release/lancer evaluates the same with lancer.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from measure_pattern import evaluate  # noqa: E402


def values(n, points):
    return evaluate(f"function {{ pigment {{ tiling {n} color_map {{ [0 rgb 0] [1 rgb 1] }} }} }}",
                    "P({x},0,{z}).red", [(x, 0.0, z) for x, z in points])


def main():
    args = sys.argv[1:]
    if len(args) < 2:
        sys.exit(__doc__)
    n = args[0]
    if args[1] == "--grid":
        x0, x1, z0, z1 = map(float, args[2:6])
        nx, nz = int(args[6]), int(args[7])
        pts = [(x0 + (x1 - x0) * i / max(nx - 1, 1), z0 + (z1 - z0) * j / max(nz - 1, 1))
               for j in range(nz) for i in range(nx)]
    else:
        pts = [tuple(float(c) for c in s.split(",")) for s in args[1:]]
    for p, v in zip(pts, values(n, pts)):
        print(f"{p[0]:.9g} {p[1]:.9g} {v:.9f}")


if __name__ == "__main__":
    main()
