#!/usr/bin/env python3
"""Measure POV-Ray 3.7's noise from the `povray` binary and write lancer's noise tables.

POV-Ray's source is AGPL, so lancer does not copy its tables: this script recovers them from
what the binary prints. It writes SDL that evaluates `f_noise_generator(x, y, z, g)` and
`vturbulence(...)` at chosen points into a file with `#write(..., str(v, 0, 20))` (full double
precision), and reads the numbers back. See docs/noise.md for what was found and how.

  scripts/measure_noise.py            # re-measure everything: src/render/noise_data.rs,
                                      # src/render/cells_data.rs, tests/data/noise_probes.txt
  scripts/measure_noise.py --cells    # only the cells/crackle tables
  scripts/measure_noise.py --probes   # only the held-out probe values

Needs `povray` (3.7) and numpy. Takes a few minutes on one core.
"""

import json
import math
import os
import random
import subprocess
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
INC = "/usr/share/povray-3.7/include"
M = 4095  # the lattice hash works on 12-bit coordinates (period 4096 in each axis)


# ---------------------------------------------------------------------------------------------
# talking to povray


def evalpov(exprs, pre=""):
    """Evaluate SDL float expressions in povray's parser; returns the doubles."""
    out_vals = []
    for start in range(0, len(exprs), 200_000):
        chunk = exprs[start : start + 200_000]
        with tempfile.TemporaryDirectory() as d:
            out = os.path.join(d, "o.txt")
            src = os.path.join(d, "s.pov")
            with open(src, "w") as f:
                f.write('#version 3.7;\n#include "functions.inc"\n' + pre)
                f.write(f'#fopen F "{out}" write\n')
                for e in chunk:
                    f.write(f'#write(F, str({e},0,20), "\\n")\n')
                f.write("#fclose F\n")
            r = subprocess.run(
                ["povray", "-D", "-V", "+FN8", "-A", "+W8", "+H8", f"+L{INC}", f"+I{src}",
                 "+O/dev/null"],
                capture_output=True, text=True)
            try:
                vals = [float(x) for x in open(out).read().split()]
            except FileNotFoundError:
                sys.exit("povray failed:\n" + r.stderr[-3000:])
            if len(vals) != len(chunk):
                sys.exit("povray failed:\n" + r.stderr[-3000:])
            out_vals += vals
    return out_vals


def fmt(v):
    return repr(float(v))


def gen(pts, g):
    return evalpov([f"f_noise_generator({fmt(x)},{fmt(y)},{fmt(z)},{g})" for x, y, z in pts])


def vturb(pts, lam=2, omega=0.5, octaves=1):
    ex = [f"vturbulence({lam},{omega},{octaves},<{fmt(x)},{fmt(y)},{fmt(z)}>).{c}"
          for x, y, z in pts for c in "xyz"]
    v = evalpov(ex)
    return [v[3 * i:3 * i + 3] for i in range(len(pts))]


def s_curve(t):
    return t * t * (3 - 2 * t)


# ---------------------------------------------------------------------------------------------
# generators 1 and 2: a lattice of (value, gradient) entries chosen by a 12-bit hash


def measure_entries(rng):
    """At lattice points generator 1 is the entry's value: 256 distinct values; generator 2 is
    an affine map of generator 1's unclipped value."""
    pts = [tuple(rng.randint(-5000, 5000) for _ in range(3)) for _ in range(20000)]
    v1, v2 = gen(pts, 1), gen(pts, 2)
    vals = sorted(set(v1))
    assert len(vals) == 256, len(vals)
    pairs = dict(zip(v1, v2))
    b, a = np.polyfit(list(pairs), list(pairs.values()), 1)
    assert max(abs(a + b * x - y) for x, y in pairs.items()) < 1e-14
    return vals, float(a), float(b), pts, v1


class Labels:
    def __init__(self, vals):
        self.idx = {x: n for n, x in enumerate(vals)}

    def of(self, pts):
        return [self.idx[x] for x in gen(pts, 1)]


def recover_hash(lab, check_pts, check_vals):
    """label(x, y, z) = LAM[P[Q[X] ^ Y] ^ Z] with X = (x + O) & 4095 etc.: three table
    lookups chained by XOR. Recovered from rows of labels along z."""
    lz = lab.of([(0, 0, z) for z in range(4096)])
    l0 = lab.of([(0, y, z) for y in range(4096) for z in range(16)])
    rows_y = [l0[y * 16:(y + 1) * 16] for y in range(4096)]
    lx = lab.of([(x, 0, z) for x in range(4096) for z in range(16)])
    rows_x = [lx[x * 16:(x + 1) * 16] for x in range(4096)]
    full = lab.of([(0, y, z) for y in range(1, 9) for z in range(4096)])
    full_rows = [full[i * 4096:(i + 1) * 4096] for i in range(8)]
    where = {}
    for p, l in enumerate(lz):
        where.setdefault(l, []).append(p)

    def xor_shift(row, o):
        found = []
        for p in where[row[0]]:
            c = ((p + o) & M) ^ o
            if all(lz[((((z + o) & M) ^ c) - o) & M] == row[z] for z in range(len(row))):
                found.append(c)
        return found

    offsets = [o for o in range(4096)
               if all(len(xor_shift(rows_y[y], o)) == 1 for y in range(1, 40))
               and all(len(xor_shift(r, o)) == 1 for r in full_rows)]
    for o in offsets:
        lam = [lz[(w - o) & M] for w in range(4096)]
        p_tab = [0] * 4096
        for y in range(4096):
            p_tab[(y + o) & M] = xor_shift(rows_y[y], o)[0]
        p_inv = {v: u for u, v in enumerate(p_tab)}
        if len(p_inv) != 4096:
            continue
        q_tab = [0] * 4096
        for x in range(4096):
            q_tab[(x + o) & M] = p_inv[xor_shift(rows_x[x], o)[0]] ^ (o & M)

        def label(x, y, z):
            return lam[p_tab[q_tab[(x + o) & M] ^ ((y + o) & M)] ^ ((z + o) & M)]

        if all(label(*p) == lab.idx[v] for p, v in zip(check_pts, check_vals)):
            return o, lam, p_tab, q_tab, label
    sys.exit("no hash offset explains the lattice labels")


def measure_gradients(label, vals, a2, b2):
    """Along a lattice edge, noise = (1-s)(v0 + g0 t) + s(v1 + g1 (t-1)) with s = 3t²-2t³:
    two samples per edge give the entry's gradient component. Generator 2 is not clipped."""
    first = {}
    for x in range(40):
        for y in range(40):
            for z in range(40):
                first.setdefault(label(x, y, z), (x, y, z))
    grads = [[0.0] * 3 for _ in range(256)]
    for ax in range(3):
        qs = []
        for l in range(256):
            for t in (0.25, 0.75):
                p = list(first[l])
                p[ax] += t
                qs.append(tuple(p))
        u = [(v - a2) / b2 for v in gen(qs, 2)]
        for l in range(256):
            c1 = list(first[l])
            c1[ax] += 1
            v0, v1 = vals[l], vals[label(*c1)]
            eq = []
            for k, t in enumerate((0.25, 0.75)):
                s = s_curve(t)
                eq.append((t * (1 - s), -s * (1 - t), u[2 * l + k] - (v0 + s * (v1 - v0))))
            (p, q, r1), (r, w, r2) = eq
            grads[l][ax] = round((r1 * w - q * r2) / (p * w - q * r), 9)
    return grads


def chain_entries(vals, grads):
    """Each entry's gradient is the next three entries' raw values: one array R, where the
    entry at position i has value R[i] (raw, generator 1 = 0.5 + 0.5 R) and gradient
    R[i+1..i+3]. Returns the order of labels in R and R[0..258]."""
    raw = [2 * v - 1 for v in vals]
    at = {round(r, 7): i for i, r in enumerate(raw)}
    succ = {l: at[round(grads[l][0], 7)] for l in range(256) if round(grads[l][0], 7) in at}
    start = [l for l in range(256) if l not in set(succ.values())]
    assert len(start) == 1
    seq = [start[0]]
    while seq[-1] in succ:
        seq.append(succ[seq[-1]])
    assert len(seq) == 256
    for l, n in zip(seq, seq[1:]):
        assert abs(grads[l][1] - grads[n][0]) < 1e-9
    return seq, [raw[l] for l in seq] + grads[seq[-1]]


def corners(pos_of, x, y, z):
    ix, iy, iz = math.floor(x), math.floor(y), math.floor(z)
    fx, fy, fz = x - ix, y - iy, z - iz
    sx, sy, sz = s_curve(fx), s_curve(fy), s_curve(fz)
    for dx in (0, 1):
        for dy in (0, 1):
            for dz in (0, 1):
                w = (sx if dx else 1 - sx) * (sy if dy else 1 - sy) * (sz if dz else 1 - sz)
                yield w, pos_of(ix + dx, iy + dy, iz + dz), (fx - dx, fy - dy, fz - dz)


def component(r, pos_of, p, k):
    t = 0.0
    for w, i, d in corners(pos_of, *p):
        j = i + k
        t += w * (0.5 * r[j] + r[j + 1] * d[0] + r[j + 2] * d[1] + r[j + 3] * d[2])
    return t


def measure_tail(r, pos_of, rng):
    """vturbulence's y and z use the entries 4 and 8 further on: R[259..266], solved by least
    squares from vturbulence near lattice points at the end of the array."""
    hi = [(x, y, z) for x in range(30) for y in range(30) for z in range(30)
          if pos_of(x, y, z) >= 247][:60]
    pts = [tuple(c + rng.uniform(-0.9, 0.9) for c in h) for h in hi for _ in range(4)]
    v = vturb(pts)
    n = 267
    rows, rhs = [], []
    for p, val in zip(pts, v):
        for ci, k in ((1, 4), (2, 8)):
            row = np.zeros(n)
            for w, i, d in corners(pos_of, *p):
                j = i + k
                row[j] += 0.5 * w
                row[j + 1:j + 4] += [w * d[0], w * d[1], w * d[2]]
            rows.append(row)
            rhs.append(val[ci])
    a = np.array(rows)
    b = np.array(rhs) - a[:, :259] @ np.array(r)
    sol, *_ = np.linalg.lstsq(a[:, 259:], b, rcond=None)
    assert np.abs(a[:, 259:] @ sol - b).max() < 1e-12
    return r + [round(float(x), 9) for x in sol]


# ---------------------------------------------------------------------------------------------
# output


def write_rust(path, o, lam_pos, p_tab, q_tab, r, a2, b2):
    def table(name, ty, xs, per=16):
        lines = [f"pub static {name}: [{ty}; {len(xs)}] = ["]
        for i in range(0, len(xs), per):
            lines.append("    " + ", ".join(str(x) for x in xs[i:i + per]) + ",")
        lines.append("];")
        return "\n".join(lines)

    with open(path, "w") as f:
        f.write("//! POV-Ray 3.7's noise tables, measured from the `povray` binary by\n")
        f.write("//! scripts/measure_noise.py (generated: do not edit; see docs/noise.md).\n\n")
        f.write("/// Added to integer lattice coordinates before they are masked to 12 bits.\n")
        f.write(f"pub const HASH_OFFSET: i64 = {o};\n")
        f.write("/// Generator 2 (and f_noise3d) is `GEN2_A + GEN2_B * u`, u generator 1's unclipped value.\n")
        f.write(f"pub const GEN2_A: f64 = {a2!r};\n")
        f.write(f"pub const GEN2_B: f64 = {b2!r};\n\n")
        f.write("/// First hash stage: x (offset, masked) to a 12-bit value.\n")
        f.write(table("HASH_X", "u16", q_tab) + "\n\n")
        f.write("/// Second stage, indexed by HASH_X[x] ^ y.\n")
        f.write(table("HASH_Y", "u16", p_tab) + "\n\n")
        f.write("/// Last stage, indexed by HASH_Y[..] ^ z: the lattice point's position in ENTRY.\n")
        f.write(table("HASH_Z", "u8", lam_pos, 32) + "\n\n")
        f.write("/// Entry i: value ENTRY[i] (raw, in [-1, 1]) and gradient ENTRY[i+1..i+4];\n")
        f.write("/// vturbulence's y and z use the entries 4 and 8 further on.\n")
        f.write(table("ENTRY", "f64", [repr(float(x)) for x in r], 4) + "\n")
    subprocess.run(["rustfmt", "--edition", "2021", path], check=False)


# ---------------------------------------------------------------------------------------------
# cells and crackle: one random point and one value per unit cube, chosen by a 12-bit hash of
# the same three-stage kind (offset 0)


def cells_value(pts):
    pre = "#declare PF = function { pattern { cells } }\n"
    return evalpov([f"PF({x + 0.5!r},{y + 0.5!r},{z + 0.5!r})" for x, y, z in pts], pre)


class CellLabels:
    """`cells` at a cube's centre is its value; equal values, equal hash (and crackle point)."""

    def __init__(self):
        self.idx = {}
        self.vals = []

    def of(self, pts):
        out = []
        for v in cells_value(pts):
            k = round(v, 13)
            if k not in self.idx:
                self.idx[k] = len(self.vals)
                self.vals.append(v)
            out.append(self.idx[k])
        return out


def crackle_d1(pts):
    pre = "#declare PF = function { pattern { crackle form <1,0,0> metric 2 } }\n"
    return evalpov([f"PF({fmt(x)},{fmt(y)},{fmt(z)})" for x, y, z in pts], pre)


def nearest_points(starts, h=0.01):
    """The crackle point nearest to each start: d1² = |p - c|² at seven spots is linear in c."""
    offs = np.array([(0, 0, 0), (h, 0, 0), (0, h, 0), (0, 0, h), (-h, 0, 0), (0, -h, 0),
                     (0, 0, -h)])
    spots = [tuple(np.array(p) + o) for p in starts for o in offs]
    d = np.array(crackle_d1(spots)).reshape(len(starts), 7)
    out = []
    for p, dd in zip(starts, d):
        ps = np.array(p) + offs
        a = 2 * (ps[1:] - ps[0])
        b = (ps[1:] ** 2).sum(1) - ps[0] @ ps[0] - (dd[1:] ** 2 - dd[0] ** 2)
        c, *_ = np.linalg.lstsq(a, b, rcond=None)
        out.append((c, np.abs(np.linalg.norm(ps - c, axis=1) - dd).max()))
    return out


def measure_cells(rng):
    lab = CellLabels()
    pts = [tuple(rng.randint(-5000, 5000) for _ in range(3)) for _ in range(3000)]
    labels = lab.of(pts)

    class Ident:
        idx = {i: i for i in range(4096)}

        def of(self, p):
            return lab.of(p)

    o, lam, p_tab, q_tab, label = recover_hash(Ident(), pts, labels)
    assert len(lab.vals) == 4096, len(lab.vals)
    first = {}
    for x in range(64):
        for y in range(64):
            for z in range(64):
                first.setdefault(label(x, y, z), (x, y, z))
    assert len(first) == 4096
    point = [None] * 4096
    todo = list(range(4096))
    spots = [(a, b, c) for a in (0.5, 0.2, 0.8) for b in (0.5, 0.2, 0.8) for c in (0.5, 0.2, 0.8)]
    for s in spots:
        if not todo:
            break
        starts = [tuple(np.array(first[l]) + s) for l in todo]
        found = nearest_points(starts)
        left = []
        for l, (c, r) in zip(todo, found):
            cell = np.array(first[l])
            if r < 1e-9 and np.all(np.floor(c) == cell):
                point[l] = [float(x) for x in c - cell]
            else:
                left.append(l)
        todo = left
        print(f"crackle points: {4096 - len(todo)} found", file=sys.stderr)
    assert not todo
    return o, lam, p_tab, q_tab, lab.vals, point


# ---------------------------------------------------------------------------------------------
# held-out probes: values povray prints at points none of the fitting above used


PROBE_GROUPS = [
    # (declarations, expression template with {x} {y} {z}, number of points, coordinate range)
    ("", "f_noise_generator({x},{y},{z},1)", 150, 300.0),
    ("", "f_noise_generator({x},{y},{z},2)", 150, 300.0),
    ("", "f_noise3d({x},{y},{z})", 60, 50.0),
    ("", "f_snoise3d({x},{y},{z})", 60, 50.0),
    ("", "vturbulence(2,0.5,1,<{x},{y},{z}>).y", 60, 100.0),
    ("", "vturbulence(2,0.5,6,<{x},{y},{z}>).z", 60, 10.0),
    ("", "vturbulence(2.7,0.6,4,<{x},{y},{z}>).x", 60, 10.0),
    ("", "vturbulence(1.5,0.9,8,<{x},{y},{z}>).y", 60, 10.0),
    ("", "vturbulence(1.3,0.9,20,<{x},{y},{z}>).z", 30, 10.0),
]
PATTERNS = [
    "bozo", "bozo noise_generator 1", "spotted", "bumps", "dents", "dents noise_generator 1",
    "granite", "granite noise_generator 1", "wrinkles", "wrinkles noise_generator 1",
    "agate", "agate agate_turb 0.5", "agate omega 0.7 lambda 3", "agate octaves 3",
    "agate noise_generator 1",
    "bozo turbulence <0.3,0.5,0.7>", "bozo turbulence 0.8 octaves 3 omega 0.7 lambda 2.7",
    "granite turbulence 0.4 noise_generator 1",
    "bozo warp { turbulence 0.5 octaves 4 } scale 0.7",
    "bozo warp { turbulence <1,0.2,0.3> lambda 3 omega 0.3 }",
    "wrinkles warp { turbulence 0.5 } warp { turbulence 0.2 octaves 2 }",
    "wood turbulence 0.05", "wood turbulence <0.05,0.1,0.3> octaves 3 omega 0.7 lambda 2.7",
    "wood turbulence 0.04 noise_generator 1 ramp_wave frequency 3",
    "agate turbulence 0.3", "spotted turbulence 0.3", "dents turbulence 0.3 lambda 2.5",
    "marble turbulence 0.3 warp { turbulence 0.2 }",
    "gradient x turbulence 0.4 noise_generator 3", "bozo turbulence 0.5 octaves 14 lambda 1.3",
    "cells", "crackle", "crackle solid", "crackle metric 1", "crackle metric 3",
    "crackle form <-1,1,0> offset 0.3", "crackle form <0.2,0.5,-0.4>",
    "crackle form <1,0,0> metric 3 offset 0.3", "crackle form <0.2,0.5,-1.4>",
    "crackle solid noise_generator 1", "crackle metric 1 form <1,0,0> offset 0.2",
    "crackle turbulence 0.8 octaves 5 lambda 2.25 omega 0.707 phase 0.97 scale 1.3",
]
# marble: x + t·turbulence; the ramp wave wraps at 1.00001, so its points keep x + t·T in
# [0, 1) away from the wrap
MARBLE = [
    "marble turbulence 0.1 ramp_wave",
    "marble turbulence <0.1,0.5,0.5> octaves 3 omega 0.7 lambda 3 ramp_wave",
    "marble turbulence 0.1 noise_generator 1 ramp_wave",
]


def probe_group(lines, pre, exprs):
    """Appends a probe group: a 'P' line with the declarations `pre`, then each expression
    with the value povray prints for it."""
    vals = evalpov(exprs, pre)
    lines.append("P " + pre.replace("\n", " ").strip())
    lines.extend(f"{e}\t{v!r}" for e, v in zip(exprs, vals))


def probe_points(rng, n, r):
    """n random points in the cube of half-size r, rounded to 6 decimals."""
    return [tuple(round(rng.uniform(-r, r), 6) for _ in range(3)) for _ in range(n)]


def write_probes(path, rng):
    lines = ["# (point, value) pairs printed by povray 3.7 at points not used to fit lancer's",
             "# noise; written by scripts/measure_noise.py. 'P' lines declare; others are",
             "# <expression>\t<value>."]

    def group(pre, exprs):
        probe_group(lines, pre, exprs)

    def pts(n, r):
        return probe_points(rng, n, r)

    for pre, tmpl, n, r in PROBE_GROUPS:
        group(pre, [tmpl.format(x=x, y=y, z=z) for x, y, z in pts(n, r)])
    for pat in PATTERNS:
        pre = f"#declare PF = function {{ pattern {{ {pat} }} }}\n"
        group(pre, [f"PF({x},{y},{z})" for x, y, z in pts(40, 20.0)])
    for pat in MARBLE:
        pre = f"#declare PF = function {{ pattern {{ {pat} }} }}\n"
        p = [(round(rng.uniform(0.3, 0.45), 6), y, z) for _, y, z in pts(40, 20.0)]
        group(pre, [f"PF({x},{y},{z})" for x, y, z in p])
    # keep the generator-3 section scripts/measure_noise3.py appends
    mark = "# --- generator 3 (scripts/measure_noise3.py) ---"
    old = open(path).read() if os.path.exists(path) else ""
    tail = mark + old.split(mark, 1)[1] if mark in old else ""
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n" + tail)


def write_cells_rust(path, o, lam, p_tab, q_tab, vals, points):
    def table(name, ty, xs, per=16):
        lines = [f"pub static {name}: [{ty}; {len(xs)}] = ["]
        for i in range(0, len(xs), per):
            lines.append("    " + ", ".join(str(x) for x in xs[i:i + per]) + ",")
        lines.append("];")
        return "\n".join(lines)

    with open(path, "w") as f:
        f.write("//! The random point (crackle) and value (cells) of each unit cube, as POV-Ray 3.7\n")
        f.write("//! picks them, measured from the `povray` binary by scripts/measure_noise.py\n")
        f.write("//! (generated: do not edit; see docs/noise.md).\n\n")
        f.write("/// Added to a cube's integer coordinates before they are masked to 12 bits.\n")
        f.write(f"pub const CELL_HASH_OFFSET: i64 = {o};\n\n")
        f.write("/// First hash stage: x to a 12-bit value.\n")
        f.write(table("CELL_HASH_X", "u16", q_tab) + "\n\n")
        f.write("/// Second stage, indexed by CELL_HASH_X[x] ^ y.\n")
        f.write(table("CELL_HASH_Y", "u16", p_tab) + "\n\n")
        f.write("/// Last stage, indexed by CELL_HASH_Y[..] ^ z: the cube's entry.\n")
        f.write(table("CELL_HASH_Z", "u16", lam) + "\n\n")
        f.write("/// The `cells` pattern's value of an entry.\n")
        f.write(table("CELL_VALUE", "f64", [repr(float(v)) for v in vals], 4) + "\n\n")
        f.write("/// The crackle point of an entry, relative to the cube's low corner.\n")
        f.write(f"pub static CELL_POINT: [[f64; 3]; {len(points)}] = [\n")
        for p in points:
            f.write("    [" + ", ".join(repr(float(c)) for c in p) + "],\n")
        f.write("];\n")
    subprocess.run(["rustfmt", "--edition", "2021", path], check=False)


def main():
    if sys.argv[1:] == ["--cells"]:
        write_cells_rust(os.path.join(ROOT, "src/render/cells_data.rs"),
                         *measure_cells(random.Random(5)))
        return
    if sys.argv[1:] == ["--probes"]:
        write_probes(os.path.join(ROOT, "tests/data/noise_probes.txt"), random.Random(2024))
        return
    rng = random.Random(1)
    vals, a2, b2, pts, v1 = measure_entries(rng)
    lab = Labels(vals)
    o, lam, p_tab, q_tab, label = recover_hash(lab, pts, v1)
    print(f"hash offset {o:#x}", file=sys.stderr)
    grads = measure_gradients(label, vals, a2, b2)
    seq, r = chain_entries(vals, grads)
    pos = {l: i for i, l in enumerate(seq)}

    def pos_of(x, y, z):
        return pos[label(x, y, z)]

    r = measure_tail(r, pos_of, rng)
    lam_pos = [pos[l] for l in lam]
    # check on points not used above
    test = [tuple(rng.uniform(-1e4, 1e4) for _ in range(3)) for _ in range(500)]
    got = vturb(test)
    err = max(abs(g[c] - component(r, pos_of, p, 4 * c)) for p, g in zip(test, got)
              for c in range(3))
    print(f"vturbulence check: max error {err:.3g}", file=sys.stderr)
    assert err < 1e-12
    write_rust(os.path.join(ROOT, "src/render/noise_data.rs"), o, lam_pos, p_tab, q_tab, r,
               a2, b2)
    write_cells_rust(os.path.join(ROOT, "src/render/cells_data.rs"),
                     *measure_cells(random.Random(5)))
    write_probes(os.path.join(ROOT, "tests/data/noise_probes.txt"), random.Random(2024))
    json.dump({"offset": o, "a2": a2, "b2": b2, "R": r},
              open(os.path.join(ROOT, "scripts/noise_measured.json"), "w"), indent=0)


if __name__ == "__main__":
    main()
