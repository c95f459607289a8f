#!/usr/bin/env python3
"""Print POV-Ray's internal functions (functions.inc) at chosen points, to fit lancer's.

Usage: measure_internal_functions.py NAME 'P0,P1,..' ['P0,P1,..' ...] [--pts 'x,y,z;x,y,z']
Prints one line per (parameter set, point): params, point, value (15 decimals), as the
installed `povray` binary computes it. The values in src/func/internal*.rs tests came from
this script (default points below).
"""
import os
import subprocess
import sys
import tempfile

DEFAULT_PTS = [
    (1.0, 2.0, 3.0),
    (-0.5, 0.3, 0.2),
    (0.2, -1.5, 0.7),
    (0.0, 0.0, 0.4),
    (0.7, 0.1, -0.3),
    (-1.1, 0.45, -0.6),
]


def measure(name, param_sets, pts):
    lines = ['#include "functions.inc"']
    for ps in param_sets:
        for p in pts:
            args = ",".join(repr(float(v)) for v in list(p) + list(ps))
            lines.append(f'#debug concat("V ", str({name}({args}),0,15), "\\n")')
    with tempfile.TemporaryDirectory() as d:
        scene = os.path.join(d, "m.pov")
        with open(scene, "w") as f:
            f.write("\n".join(lines) + "\n")
        r = subprocess.run(
            ["povray", "-D", "-V", "+W8", "+H8", "-GR", "-GS", "+GD", "-F",
             "+L/usr/share/povray-3.7/include", f"+I{scene}"],
            capture_output=True, text=True, cwd=d)
    vals = [l[2:] for l in r.stderr.splitlines() if l.startswith("V ")]
    if len(vals) != len(param_sets) * len(pts):
        sys.exit(r.stderr[-2000:])
    out, k = [], 0
    for ps in param_sets:
        for p in pts:
            out.append((ps, p, vals[k]))
            k += 1
    return out


def main():
    args = sys.argv[1:]
    pts = DEFAULT_PTS
    if "--pts" in args:
        i = args.index("--pts")
        pts = [tuple(float(v) for v in s.split(",")) for s in args[i + 1].split(";")]
        del args[i:i + 2]
    name, sets = args[0], [[float(v) for v in s.split(",") if v] for s in args[1:]]
    for ps, p, v in measure(name, sets or [[]], pts):
        print(",".join(map(str, ps)), "|", ",".join(map(str, p)), "|", v)


if __name__ == "__main__":
    main()
