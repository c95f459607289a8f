#!/usr/bin/env python3
"""Measures POV-Ray's ten wave sources (ripples, waves) from the binary.

With `global_settings { number_of_waves N }` the ripples/waves pigment is the mean of N
sources' waves, so N*v_N - (N-1)*v_(N-1) (v mapped to [-1, 1]) is source N's own field. On the
plane z = 0 its gradient points away from the source's (x, y); a least-squares fit of those
directions gives x and y, a search then |z|, and a render of the plane z = 0.5 the sign of z.
The ripples field of one source is sin(2*pi*d); the waves field is (0.4/f)*sin(2*pi*f*d) with a
frequency f per source, fitted here. Prints the table render::pattern::WAVE_SOURCES holds.
Pure Python (no numpy); takes about a minute.
"""
import math, os, subprocess, sys, tempfile
sys.path.insert(0, os.path.dirname(__file__))
from measure_normals import read_ppm


def field(n, pat="ripples", w=41, z=0.0, r=2.0):
    d = tempfile.mkdtemp(); f = os.path.join(d, "s.pov"); o = os.path.join(d, "o.ppm")
    open(f, "w").write(f"""#version 3.7;
global_settings {{ assumed_gamma 1.0 number_of_waves {n} }}
camera {{ orthographic location <0,0,-10+{z}> direction z right {2*r}*x up {2*r}*y }}
plane {{ -z, {-z} pigment {{ {pat} color_map {{ [0 rgb 0] [1 rgb 1] }} }} finish {{ ambient 1 diffuse 0 }} }}
""")
    subprocess.run(["povray", "-D", "-V", "+FP16", "-A", f"+W{w}", f"+H{w}", "File_Gamma=1.0",
                    "+I" + f, "+O" + o], check=True, capture_output=True)
    px = read_ppm(o)[2]
    return [((-r + (i + 0.5) * 2 * r / w), (r - (j + 0.5) * 2 * r / w), px[j * w + i][0])
            for j in range(w) for i in range(w)]


def own_fields(pat, w, r, z=0.0):
    prev = None
    for n in range(1, 11):
        f = field(n, pat, w, z, r)
        v = [2 * p[2] - 1 for p in f]
        s = [n * a - (n - 1) * b for a, b in zip(v, prev)] if prev else v
        prev = v
        yield n, f, s


def descend(err, c, step):
    e = err(*c)
    while step > 1e-6:
        better = False
        for d in range(len(c)):
            for sg in (1, -1):
                t = list(c); t[d] += sg * step
                et = err(*t)
                if et < e:
                    c, e, better = t, et, True
        if not better:
            step /= 2
    return c, e


def centres():
    w, r = 61, 3.0
    out = []
    for n, f, s in own_fields("ripples", w, r):
        xs = [p[0] for p in f]; ys = [p[1] for p in f]; h = 2 * r / w
        a = [[0, 0], [0, 0]]; b = [0, 0]
        for j in range(1, w - 1):
            for i in range(1, w - 1):
                k = j * w + i
                gx = (s[k + 1] - s[k - 1]) / (2 * h); gy = (s[k - w] - s[k + w]) / (2 * h)
                row = [gy, -gx]; rhs = xs[k] * gy - ys[k] * gx
                for u in range(2):
                    for v in range(2):
                        a[u][v] += row[u] * row[v]
                    b[u] += row[u] * rhs
        det = a[0][0] * a[1][1] - a[0][1] * a[1][0]
        cx = (b[0] * a[1][1] - a[0][1] * b[1]) / det; cy = (a[0][0] * b[1] - a[1][0] * b[0]) / det
        err = lambda cx, cy, cz: sum((math.sin(2 * math.pi * math.sqrt((x - cx) ** 2 + (y - cy) ** 2 + cz * cz)) - t) ** 2 for x, y, t in zip(xs, ys, s))
        cz = min((err(cx, cy, k / 50), k / 50) for k in range(151))[1]
        c, e = descend(err, [cx, cy, cz], 0.02)
        out.append(c)
        print(f"source {n}: x {c[0]:+.5f} y {c[1]:+.5f} |z| {abs(c[2]):.5f} rms {math.sqrt(e / len(s)):.5f}", flush=True)
    # The sign of z from the plane z = 0.5.
    z = 0.5
    for (n, f, s), c in zip(own_fields("ripples", 41, 2.0, z), out):
        errs = []
        for sg in (1, -1):
            cz = sg * abs(c[2])
            errs.append(sum((math.sin(2 * math.pi * math.sqrt((x - c[0]) ** 2 + (y - c[1]) ** 2 + (z - cz) ** 2)) - t) ** 2 for (x, y, _), t in zip(f, s)))
        c[2] = abs(c[2]) if errs[0] < errs[1] else -abs(c[2])
    return out


def frequencies(cs):
    fr_out = []
    for (n, f, s), c in zip(own_fields("waves", 41, 2.0), cs):
        ds = [math.sqrt((x - c[0]) ** 2 + (y - c[1]) ** 2 + c[2] ** 2) for x, y, _ in f]
        err = lambda fr: sum((0.4 / fr * math.sin(2 * math.pi * fr * d) - t) ** 2 for d, t in zip(ds, s))
        fr = min((err(k / 200), k / 200) for k in range(20, 600))[1]
        (fr,), e = descend(lambda fr: err(fr), [fr], 0.0025)
        fr_out.append(fr)
        print(f"source {n}: waves frequency {fr:.5f} rms {math.sqrt(e / len(s)):.5f}", flush=True)
    return fr_out


if __name__ == "__main__":
    cs = centres()
    fs = frequencies(cs)
    for c, fr in zip(cs, fs):
        print(f"    (DVec3::new({c[0]:.5f}, {c[1]:.5f}, {c[2]:.5f}), {fr:.5f}),")
