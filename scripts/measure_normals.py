#!/usr/bin/env python3
"""Measures the perturbed normal POV-Ray computes for a `normal { }` block, from the binary.

A white plane facing -z (diffuse 1, ambient 0) under parallel lights: pass 0 has a red light
from +x, green from +y, blue from -z; pass 1 red from -x, green from -y. With assumed_gamma 1
and a 16-bit linear PPM each channel is max(0, n'.L), so n' = (R0-R1, G0-G1, B0) per pixel.
The view covers x, y in [-2, 2] (orthographic). Usage as a module: `normals(spec, w, h)`;
as a script: prints n' along the middle row for the normal body given as argument. RENDERER=lancer
measures lancer the same way.
"""
import os, subprocess, sys, tempfile

BASE = """#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0,0,-10> direction z right 4*x up 4*y }
#if (Pass=0)
light_source { <1000,0,0> color rgb <1,0,0> parallel point_at 0 }
light_source { <0,1000,0> color rgb <0,1,0> parallel point_at 0 }
light_source { <0,0,-1000> color rgb <0,0,1> parallel point_at 0 }
#else
light_source { <-1000,0,0> color rgb <1,0,0> parallel point_at 0 }
light_source { <0,-1000,0> color rgb <0,-1000,0>*0+<0,1,0> parallel point_at 0 }
#end
"""


def read_ppm(path):
    data = open(path, "rb").read()
    parts, pos = [], 0
    while len(parts) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos) + 1
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        parts.append(data[pos:end])
        pos = end
    pos += 1
    w, h, mx = int(parts[1]), int(parts[2]), int(parts[3])
    px = []
    for i in range(w * h):
        o = pos + i * 6
        px.append(tuple(int.from_bytes(data[o + 2 * k:o + 2 * k + 2], "big") / mx for k in range(3)))
    return w, h, px


def render(scene, w, h, extra=()):
    d = tempfile.mkdtemp()
    out = []
    for p in (0, 1):
        f = os.path.join(d, "s.pov")
        open(f, "w").write(BASE + scene)
        o = os.path.join(d, f"o{p}.ppm")
        subprocess.run([os.environ.get("RENDERER", "povray"), "-D", "-V", "+FP16", "-A", f"+W{w}", f"+H{h}", f"Declare=Pass={p}",
                        "File_Gamma=1.0", "+L" + d, "+L/usr/share/povray-3.7/include", *extra,
                        "+I" + f, "+O" + o], check=True, capture_output=True)
        out.append(read_ppm(o)[2])
    return [(a[0] - b[0], a[1] - b[1], a[2]) for a, b in zip(*out)]


def normals(spec, w=16, h=16, obj="plane { -z, 0"):
    scene = obj + " pigment { rgb 1 } finish { ambient 0 diffuse 1 } normal { " + spec + " } }\n"
    return render(scene, w, h)


def coords(i, j, w, h):
    return (-2 + (i + 0.5) * 4 / w, 2 - (j + 0.5) * 4 / h)


if __name__ == "__main__":
    w = int(sys.argv[2]) if len(sys.argv) > 2 else 16
    n = normals(sys.argv[1], w, 1)
    for i, v in enumerate(n):
        x, _ = coords(i, 0, w, 1)
        print(f"x={x:+.4f}  n=({v[0]:+.5f},{v[1]:+.5f},{v[2]:+.5f})")
