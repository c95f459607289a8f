#!/usr/bin/env python3
"""Parse-speed benchmark: lancer's parser against POV-Ray's parse phase, side by side.

Writes three scenes into a temporary directory, parses each with both programs (best of N
runs) and prints a table with the ratio lancer / POV-Ray (below 1 means lancer is faster).

  include-lib   every standard include file both programs read without error, in an order
                that satisfies their dependencies (worked out at run time, see pick_includes)
  while-grid    a 100x100 #while grid of spheres (10,000 objects)
  macro-tri     a recursive macro building a Sierpinski triangle from 3^9 = 19,683 triangles

POV-Ray's figure is the "Parse Time" line of its statistics (stderr). lancer's is the
"parse X s" line of a 1x1 render, which times reading, lexing and parsing only; the wall
time of `lancer check` (the whole process) is shown next to it.

Usage: parse_bench.py LANCER_BINARY [--runs N] [--keep DIR]
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

INCLUDE_DIR = "/usr/share/povray-3.7/include"
# Files others depend on go first, so the greedy pass below keeps as many as possible.
FIRST = ["colors.inc", "shapes.inc", "textures.inc", "finish.inc", "metals.inc", "golds.inc",
         "glass.inc", "woods.inc", "stones.inc", "math.inc", "functions.inc", "transforms.inc"]

SCENE_TAIL = """
camera { location <0, 2, -6> look_at <0, 0, 0> }
light_source { <10, 10, -10> rgb 1 }
sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } }
"""

WHILE_GRID = """#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <5, 8, -6> look_at <5, 0, 5> }
light_source { <10, 20, -10> rgb 1 }
#declare I = 0;
#while (I < 100)
  #declare J = 0;
  #while (J < 100)
    sphere { <I, 0, J> * 0.1, 0.04 pigment { rgb <I / 100, J / 100, 0.5> } }
    #declare J = J + 1;
  #end
  #declare I = I + 1;
#end
"""

MACRO_TRI = """#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 0.5, -2> look_at <0.5, 0.5, 0> }
light_source { <10, 20, -10> rgb 1 }
// Each level calls itself three times on the corner triangles: 3^9 triangles at depth 9.
#macro Sier(A, B, C, N)
  #if (N = 0)
    triangle { A, B, C }
  #else
    #local AB = (A + B) / 2;
    #local BC = (B + C) / 2;
    #local CA = (C + A) / 2;
    Sier(A, AB, CA, N - 1)
    Sier(AB, B, BC, N - 1)
    Sier(CA, BC, C, N - 1)
  #end
#end
mesh { Sier(<0, 0, 0>, <1, 0, 0>, <0.5, 1, 0>, 9) pigment { rgb 1 } }
"""


def pov_parse_seconds(scene, cwd):
    """POV-Ray's own parse-phase time in seconds, or None when the scene fails to parse."""
    r = subprocess.run(
        ["povray", "-D", "-V", "+W16", "+H16", "-A", "+WT1",
         "+L" + INCLUDE_DIR, "+I" + scene, "+O" + os.devnull],
        cwd=cwd, capture_output=True, text=True)
    m = re.search(r"Parse Time:.*\(([0-9.]+) seconds\)", r.stderr)
    if r.returncode != 0 or not m:
        return None
    return float(m.group(1))


def lancer_parse_seconds(lancer, scene, cwd):
    """lancer's parse time from a 1x1 render's summary line, or None on a parse error."""
    r = subprocess.run(
        [lancer, "+W1", "+H1", "-A", "+L" + INCLUDE_DIR, "+I" + scene,
         "+O" + os.path.join(cwd, "out.png")],
        cwd=cwd, capture_output=True, text=True)
    m = re.search(r"parse ([0-9.]+)s", r.stderr)
    if r.returncode != 0 or not m:
        return None
    return float(m.group(1))


def lancer_check_wall(lancer, scene, cwd):
    t = time.perf_counter()
    r = subprocess.run([lancer, "check", "-q", "--library-path", INCLUDE_DIR, scene],
                       cwd=cwd, capture_output=True)
    return time.perf_counter() - t if r.returncode == 0 else None


def include_scene(names):
    # One pass only: reading the files again in a loop would mostly time the skipping of
    # their include guards (#ifndef (Colors_Inc_Temp) ...), not parsing.
    body = "".join(f'#include "{n}"\n' for n in names)
    return "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n" + body + SCENE_TAIL


def pick_includes(lancer, tmp):
    """Greedy: add each include file in turn, keep it if both programs still parse the whole
    set. Returns (kept, dropped-with-reason)."""
    names = sorted(f for f in os.listdir(INCLUDE_DIR) if f.endswith(".inc"))
    names = [n for n in FIRST if n in names] + [n for n in names if n not in FIRST]
    kept, dropped = [], []
    path = os.path.join(tmp, "probe.pov")
    for n in names:
        with open(path, "w") as f:
            f.write(include_scene(kept + [n]))
        pov = pov_parse_seconds(path, tmp) is not None
        lan = lancer_parse_seconds(lancer, path, tmp) is not None
        if pov and lan:
            kept.append(n)
        else:
            who = "POV-Ray and lancer" if not pov and not lan else ("POV-Ray" if not pov else "lancer")
            dropped.append((n, f"{who} fails"))
    return kept, dropped


def best(f, runs):
    vals = [f() for _ in range(runs)]
    return None if any(v is None for v in vals) else min(vals)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("lancer")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--keep", help="write the scenes here instead of a temporary directory")
    a = ap.parse_args()
    lancer = os.path.abspath(a.lancer)
    tmp = a.keep or tempfile.mkdtemp(prefix="parse_bench.")
    os.makedirs(tmp, exist_ok=True)

    kept, dropped = pick_includes(lancer, tmp)
    print(f"include set ({len(kept)} files): {' '.join(kept)}")
    for n, why in dropped:
        print(f"  left out {n}: {why} (alone or with the files before it)")
    scenes = {
        "include-lib": include_scene(kept),
        "while-grid": WHILE_GRID,
        "macro-tri": MACRO_TRI,
    }
    rows = []
    for name, text in scenes.items():
        path = os.path.join(tmp, name + ".pov")
        with open(path, "w") as f:
            f.write(text)
        pov = best(lambda: pov_parse_seconds(path, tmp), a.runs)
        lan = best(lambda: lancer_parse_seconds(lancer, path, tmp), a.runs)
        wall = best(lambda: lancer_check_wall(lancer, path, tmp), a.runs)
        rows.append((name, pov, lan, wall))

    def fmt(v):
        return "error" if v is None else f"{v:.3f}"

    print(f"\nbest of {a.runs}; seconds; ratio = lancer parse / POV-Ray parse (< 1: lancer faster)")
    print(f"{'scene':<14} {'POV-Ray':>9} {'lancer':>9} {'ratio':>7} {'check wall':>11}")
    for name, pov, lan, wall in rows:
        # POV-Ray prints milliseconds; a 0.000 reading is shown as such, with no ratio.
        ratio = f"{lan / pov:.2f}" if pov and lan is not None else "n/a"
        print(f"{name:<14} {fmt(pov):>9} {fmt(lan):>9} {ratio:>7} {fmt(wall):>11}")
    print(f"\nscenes in {tmp}")


if __name__ == "__main__":
    sys.exit(main())
