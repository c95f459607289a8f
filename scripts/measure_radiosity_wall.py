#!/usr/bin/env python3
"""The open-box radiosity probe (tests/radiosity/open_box.inc's scene) with one radiosity
setting changed at a time, rendered by povray (+WT1, every option explicit) and by lancer:
the mean 8-bit level of the back wall's lower half, lit only indirectly, on both sides.

Each variant is NAME=ITEMS, where ITEMS replaces or adds items of the radiosity block (the
base block is pretrace_start 0.08 pretrace_end 0.04 count 100 error_bound 0.5 nearest_count 5
recursion_limit 2). An item `@scene:TEXT` instead adds TEXT to the scene after the box.

usage: scripts/measure_radiosity_wall.py [--size 80x60] [--lancer BIN] [--keep DIR] VARIANT...
e.g.   scripts/measure_radiosity_wall.py base= rec1='recursion_limit 1' eb01='error_bound 0.1'
"""

import argparse
import os
import re
import subprocess
import sys
import tempfile

import numpy as np
from PIL import Image

BASE = {
    "pretrace_start": "0.08",
    "pretrace_end": "0.04",
    "count": "100",
    "error_bound": "0.5",
    "nearest_count": "5",
    "recursion_limit": "2",
}

SCENE = """#version 3.7;
global_settings {{
  assumed_gamma 1.0
  radiosity {{
    {rad}
  }}
}}
camera {{ location <0, 1, -1.9> look_at <0, 1, 0> angle 70 }}
light_source {{ <0, 8, 0> rgb 3 }}
#declare Wall = texture {{ pigment {{ rgb 0.8 }} finish {{ diffuse 0.7 ambient 0 }} }}
difference {{
  box {{ <-2.1, -0.1, -2.1>, <2.1, 2.1, 2.1> }}
  box {{ <-2, 0, -2>, <2, 2, 2> }}
  box {{ <-0.4, 1.9, -0.4>, <0.4, 2.2, 0.4> }}
  texture {{ Wall }}
}}
box {{ <-0.8, 0, -0.8>, <0.8, 0.01, 0.8> pigment {{ rgb <1, 0.2, 0.1> }} finish {{ diffuse 0.7 ambient 0 }} }}
sphere {{ <0.8, 0.5, 0.8>, 0.5 texture {{ Wall }} }}
{extra}
"""


def parse_items(text):
    """Radiosity items as (keyword, rest) pairs, e.g. 'count 200 error_bound 0.1'."""
    items = []
    for m in re.finditer(r"([a-z_]+)((?:\s+[-0-9.<>, ]+|\s+(?:on|off))*)", text):
        items.append((m.group(1), m.group(2).strip()))
    return items


def scene_text(spec):
    rad = dict(BASE)
    extra = []
    for part in spec.split(";"):
        part = part.strip()
        if part.startswith("@scene:"):
            extra.append(part[len("@scene:"):])
            continue
        for k, v in parse_items(part):
            if v == "-":
                rad.pop(k, None)
            else:
                rad[k] = v
    body = " ".join(f"{k} {v}" for k, v in rad.items())
    return SCENE.format(rad=body, extra="\n".join(extra))


def wall(path, w, h):
    a = np.asarray(Image.open(path).convert("RGB"), dtype=np.float64)
    # Rows 30..45 and columns 25..55 of 80x60, scaled to the picture's size.
    y0, y1 = h * 30 // 60, h * 45 // 60
    x0, x1 = w * 25 // 80, w * 55 // 80
    return a[y0:y1, x0:x1].reshape(-1, 3).mean(axis=0)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--size", default="80x60")
    ap.add_argument("--lancer", default=os.path.join(os.path.dirname(__file__), "../target/release/lancer"))
    ap.add_argument("--keep")
    ap.add_argument("--no-povray", action="store_true")
    ap.add_argument("variants", nargs="+")
    args = ap.parse_args()
    w, h = map(int, args.size.split("x"))
    tmp = args.keep or tempfile.mkdtemp()
    os.makedirs(tmp, exist_ok=True)
    print(f"| variant | povray R G B | lancer R G B | lancer/povray (R) | povray s | lancer s |")
    print("|---|---|---|---:|---:|---:|")
    for v in args.variants:
        name, _, spec = v.partition("=")
        pov = os.path.join(tmp, f"{name}.pov")
        with open(pov, "w") as f:
            f.write(scene_text(spec))
        common = ["-D", "-V", "+FN8", "-A", f"+W{w}", f"+H{h}", "+WT1", f"+L{tmp}",
                  "+L/usr/share/povray-3.7/include", f"+I{pov}"]
        pp = os.path.join(tmp, f"{name}_pov.png")
        lp = os.path.join(tmp, f"{name}_lancer.png")
        pt = "-"
        if not args.no_povray:
            out = subprocess.run(["povray", *common, f"+O{pp}"], capture_output=True, text=True)
            m = re.findall(r"(?:Radiosity|Trace) Time:.*\(([0-9.]+) seconds\)", out.stderr)
            pt = f"{sum(map(float, m)):.2f}" if m else "?"
        out = subprocess.run([args.lancer, *common, f"+O{lp}"], capture_output=True, text=True)
        m = re.search(r"render ([0-9.]+)s", out.stderr)
        lt = m.group(1) if m else "?"
        lw = wall(lp, w, h)
        if args.no_povray:
            print(f"| {name} | | {lw[0]:.1f} {lw[1]:.1f} {lw[2]:.1f} | | | {lt} |")
            continue
        pw = wall(pp, w, h)
        print(f"| {name} | {pw[0]:.1f} {pw[1]:.1f} {pw[2]:.1f} | {lw[0]:.1f} {lw[1]:.1f} {lw[2]:.1f} "
              f"| {lw[0] / pw[0]:.3f} | {pt} | {lt} |")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
