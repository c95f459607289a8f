#!/usr/bin/env python3
"""Print POV-Ray 3.7's value of a pattern at chosen points, read from the `povray` binary.

The pattern is evaluated in POV-Ray's parser as `function { pattern { PATTERN } }` and the
values written with full precision; this is how the rules of spiral2, quilted, tiling,
pavement and magnet in docs/povray-behaviour.md were measured.

  scripts/measure_pattern.py 'spiral2 3' 0.3,0.2,0 1,1,0.5 ...
  scripts/measure_pattern.py 'quilted control0 0 control1 1' --line -0.5,0.1,0.2 0.5,0.1,0.2 11

With --line A B N the points are N evenly spaced ones from A to B. Prints "x y z value".
RENDERER=target/release/lancer evaluates the same with lancer.
"""

import os
import subprocess
import sys
import tempfile

INC = "/usr/share/povray-3.7/include"


def evaluate(declaration, expression, points):
    """POV-Ray's value of `expression` (a format string over x, y, z, reading P) at each
    point, with `#declare P = declaration` first; also used by measure_tiling.py."""
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "o.txt")
        src = os.path.join(d, "s.pov")
        with open(src, "w") as f:
            f.write("#version 3.7;\n")
            f.write(f"#declare P = {declaration}\n")
            f.write(f'#fopen F "{out}" write\n')
            for x, y, z in points:
                e = expression.format(x=repr(x), y=repr(y), z=repr(z))
                f.write(f'#write(F, str({e},0,12), "\\n")\n')
            f.write("#fclose F\n")
        r = subprocess.run([os.environ.get("RENDERER", "povray"), "-D", "-V", "+FN8", "-A", "+W8", "+H8", f"+L{INC}",
                            f"+I{src}", "+O/dev/null"], capture_output=True, text=True)
        try:
            return [float(v) for v in open(out).read().split()]
        except FileNotFoundError:
            sys.exit("povray failed:\n" + r.stderr[-3000:])


def values(pattern, points):
    return evaluate(f"function {{ pattern {{ {pattern} }} }}", "P({x},{y},{z})", points)


def main():
    args = sys.argv[1:]
    if not args:
        sys.exit(__doc__)
    pattern = args[0]
    vec = lambda s: tuple(float(c) for c in s.split(","))
    if len(args) >= 2 and args[1] == "--line":
        a, b, n = vec(args[2]), vec(args[3]), int(args[4])
        pts = [tuple(a[k] + (b[k] - a[k]) * i / max(n - 1, 1) for k in range(3)) for i in range(n)]
    else:
        pts = [vec(s) for s in args[1:]]
    for p, v in zip(pts, values(pattern, pts)):
        print(f"{p[0]:.6g} {p[1]:.6g} {p[2]:.6g} {v:.9f}")


if __name__ == "__main__":
    main()
