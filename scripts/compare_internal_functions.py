#!/usr/bin/env python3
"""Compare lancer's internal functions with povray's on random parameter sets.

Usage: compare_internal_functions.py [--seed N] [--count N] [--lancer BIN] [NAME ...]
NAME is one of the functions below (default: all). Each case is written by both binaries
with `#write` of `str(f(...), 0, 15)` (not #debug: povray wraps long console lines); a case differs when the values are further apart than
1e-12 relative. Values beyond 1e70 are skipped: povray's str() cuts long numbers short.
Exit status 1 if any case differs. This is how f_hetero_mf and f_ridge were fitted.
f_ridged_mf is not here: povray keeps the octave weights of its first call for the whole
run (see src/func/internal_noise.rs), so random parameter sets in one run do not compare.
"""
import argparse
import os
import random
import subprocess
import sys
import tempfile

OCTAVES = [-1.5, -1, 0, 0.5, 1, 1.5, 2, 3.7, 6, 9, 12.3]


def u(lo, hi):
    return round(random.uniform(lo, hi), 3)


# Random parameters (after x, y, z) for each function.
PARAMS = {
    "f_hetero_mf": lambda: [u(-0.5, 1.5), u(0.5, 3), random.choice(OCTAVES), u(-1, 2),
                            random.choice([0, 0.5, 1, 1.5, 2, 3, -1]), random.choice([1, 2, 3])],
    "f_ridge": lambda: [u(0.5, 3), random.choice(OCTAVES), u(0, 1.2),
                        random.choice([0, 0.2, 0.5, 0.8, 1, 1.5, -0.5]),
                        random.choice([0, 0.2, 0.5, 1, 2, -1]), random.choice([1, 2, 3])],
}


PARAMS["f_strophoid"] = lambda: [random.choice([1, -0.4, 2.5])] + [u(-1, 1.5) for _ in range(3)]


def sor():
    return [random.choice([0, 1, 0.5, -1, 2]), random.choice([0, 0.4, -0.3]),
            random.choice([0, 30, -60, 90])]


# The 2-d curves: field strength, the curve's parameters, then switch, offset, angle.
for _name, _k in [("f_witch_of_agnesi_2d", 2), ("f_devils_curve_2d", 2),
                  ("f_folium_surface_2d", 2), ("f_kampyle_of_eudoxus_2d", 2),
                  ("f_lemniscate_of_gerono_2d", 2), ("f_strophoid_2d", 3)]:
    PARAMS[_name] = (lambda k: lambda: [random.choice([1, -0.4, 2.5])]
                     + [u(0.3, 1.5) for _ in range(k)] + sor())(_k)


def values(cmd, cwd):
    out = os.path.join(cwd, "values.txt")
    if os.path.exists(out):
        os.remove(out)
    subprocess.run(cmd, capture_output=True, text=True, cwd=cwd)
    if not os.path.exists(out):
        return []
    with open(out) as f:
        return [l[2:].strip() for l in f if l.startswith("V ")]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--seed", type=int, default=7)
    ap.add_argument("--count", type=int, default=200)
    here = os.path.dirname(os.path.abspath(__file__))
    ap.add_argument("--lancer", default=os.path.join(here, "..", "target", "release", "lancer"))
    ap.add_argument("names", nargs="*")
    a = ap.parse_args()
    names = a.names or sorted(PARAMS)
    random.seed(a.seed)
    cases = []
    for k in range(a.count):
        name = names[k % len(names)]
        args = [u(-3, 3) for _ in range(3)] + PARAMS[name]()
        cases.append(f"{name}({','.join(str(v) for v in args)})")
    lines = ['#include "functions.inc"', '#fopen Out "values.txt" write'] + [
        f'#write (Out, "V ", str({c},0,15), "\\n")' for c in cases] + ['#fclose Out']
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "cmp.pov"), "w") as f:
            f.write("\n".join(lines) + "\n")
        pov = values(["povray", "-D", "-V", "+W8", "+H8", "-GR", "-GS", "+GD", "-F",
                      "+L/usr/share/povray-3.7/include", "+Icmp.pov"], d)
        lan = values([a.lancer, "-D", "+W8", "+H8", "-F", "-o", os.path.join(d, "x.png"),
                      "cmp.pov"], d)
    if len(pov) != len(cases) or len(lan) != len(cases):
        sys.exit(f"expected {len(cases)} values, povray gave {len(pov)}, lancer {len(lan)}")
    bad = 0
    for c, p, l in zip(cases, pov, lan):
        try:
            fp, fl = float(p), float(l)
        except ValueError:
            continue
        if fp != fp and fl != fl:
            continue
        if abs(fp) > 1e70:
            continue
        if not abs(fp - fl) <= 1e-12 * max(1.0, abs(fp)):
            bad += 1
            print(f"{c}: povray {p}, lancer {l}")
    print(f"{len(cases)} cases, {bad} differ")
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
