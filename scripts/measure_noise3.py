#!/usr/bin/env python3
"""Measure POV-Ray 3.7's `noise_generator 3` from the `povray` binary and write lancer's tables.

POV-Ray's source is AGPL, so lancer does not copy it: this script recovers generator 3 from
what the binary prints (`f_noise_generator(x, y, z, 3)` written with `str(v, 0, 20)`, through
measure_noise.py's `evalpov`). See docs/noise.md, "Generator 3", for what was found.

  scripts/measure_noise3.py           # re-measure: src/render/noise3_data.rs and the
                                      # generator-3 probes at the end of
                                      # tests/data/noise_probes.txt
  scripts/measure_noise3.py --probes  # only the held-out probe values

Needs `povray` (3.7) and numpy. Takes about a minute on one core.
"""

import collections
import math
import os
import random
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from measure_noise import ROOT, evalpov, fmt, probe_group, probe_points  # noqa: E402

N = 2048  # generator 3's lattice hash works on 11-bit coordinates
PROBE_MARK = "# --- generator 3 (scripts/measure_noise3.py) ---"


def gen3(pts):
    return evalpov([f"f_noise_generator({fmt(x)},{fmt(y)},{fmt(z)},3)" for x, y, z in pts])


# ---------------------------------------------------------------------------------------------
# where the lattice is: POV-Ray adds a constant C to each coordinate and floors


def lattice_value():
    """Far from the origin the kinks sit at x = k - F for one F; there the value is V0."""
    f0 = 0.0231572136  # rough shift, from kinks of a scan along x (docs/noise.md)
    vals = gen3([(k - f0, 2 * k - f0, 7 - k - f0) for k in range(-3, 4)])
    assert max(vals) - min(vals) < 1e-8, vals
    return vals[0], f0


def boundary(f, lo, hi):
    """The x in [lo, hi] where f(x) changes, to one double step."""
    vlo = f([lo])[0]
    while True:
        xs = [lo + (hi - lo) * i / 500 for i in range(501)]
        vs = f(xs)
        i = next(i for i in range(501) if vs[i] != vlo)
        if xs[i - 1] == lo and xs[i] == hi or hi - lo < 4e-16:
            return xs[i - 1], xs[i]
        lo, hi = xs[i - 1], xs[i]


def measure_shift(v0, f0):
    """x + C is rounded to a multiple of 2^-29 (C is in [2^23, 2^24)): the value is flat at v0
    within half a step either side of a lattice point. The two edges of that flat give the
    lattice point, hence C's fraction, exactly."""
    s = 1 - f0
    f = lambda xs: gen3([(x, s, s) for x in xs])  # noqa: E731
    probe = f([s + d * 1e-9 for d in range(-3, 4)])
    flat = [d for d, v in zip(range(-3, 4), probe) if v == v0]
    _, a = boundary(f, s + (flat[0] - 1) * 1e-9, s + flat[0] * 1e-9)
    b, _ = boundary(f, s + flat[-1] * 1e-9, s + (flat[-1] + 1) * 1e-9)
    step = (b - a) * 2 ** 29
    frac = (1 - (a + b) / 2) * 2 ** 29
    assert abs(step - 1) < 1e-6 and abs(frac - round(frac)) < 1e-6, (step, frac)
    return round(frac)


def measure_integer_part(frac):
    """Below x = 2^23 - C the rounding step halves: bisect for it (C's integer part)."""
    fc = frac / 2 ** 29

    def changes(ks):
        pts = [(k - fc + 0.3 + j * 2 ** -33, 0.3 - fc, 0.3 - fc) for k in ks for j in range(100)]
        v = gen3(pts)
        return [sum(v[i * 100 + j] != v[i * 100 + j - 1] for j in range(1, 100))
                for i in range(len(ks))]

    lo, hi = -5_000_000, -100_000  # step 2^-30 at lo, 2^-29 at hi
    while hi - lo > 1:
        ks = [lo + (hi - lo) * i // 50 for i in range(51)]
        n = changes(ks)
        i = next(i for i in range(51) if n[i] < 9)
        lo, hi = ks[i - 1], ks[i]
    # 2^23 - C lies in (lo - fc + 0.3, hi - fc + 0.3): C = 2^23 - hi
    return 2 ** 23 - hi


# ---------------------------------------------------------------------------------------------
# gradients and the hash


class Lattice:
    def __init__(self, v0, c):
        self.v0, self.c = v0, c
        self.fc = c - math.floor(c)
        self.labels = {}
        self.vecs = []

    def at(self, k):
        """x of lattice coordinate k (floor(x + C) = k + floor(C))."""
        return k - self.fc

    def grads(self, pts):
        """B·gradient at lattice points: along each axis the cell's value is
        (1-s) g0 t + s g1 (t-1), s = 3t² - 2t³; t = 1/4 and 1/2 solve for g0."""
        ex = []
        for p in pts:
            for a in range(3):
                for t in (0.25, 0.5):
                    ex.append(tuple(self.at(p[i]) + (t if i == a else 0) for i in range(3)))
        v = [x - self.v0 for x in gen3(ex)]
        out = []
        for n in range(len(pts)):
            g = []
            for a in range(3):
                f25, f5 = v[6 * n + 2 * a], v[6 * n + 2 * a + 1]
                g.append((f25 - 0.46875 * f5) / 0.09375)
            out.append(g)
        return out

    def label(self, pts, scale):
        out = []
        for g in self.grads(pts):
            key = tuple(round(x / scale, 7) for x in g)
            if key not in self.labels:
                self.labels[key] = len(self.vecs)
                self.vecs.append([x / scale for x in g])
            out.append(self.labels[key])
        return out


def measure_hash(lat, scale):
    """gradient(x, y, z) = GRAD[(P[(P[X] + Y) & 2047] + Z) & 2047], X = floor(x + C) & 2047:
    rows along z are cyclic shifts of the row (0, 0, z), so one label fixes a row's shift;
    the shifts along y give P, those along x give P[P[X]]."""
    lz = lat.label([(0, 0, z) for z in range(N)], scale)
    assert len(set(lz)) == N, "row (0, 0, z) should hold every gradient once"
    inv = {l: z for z, l in enumerate(lz)}

    def shift(pts):
        return [inv[l] for l in lat.label([(x, y, 0) for x, y in pts], scale)]

    s0y = shift([(0, y) for y in range(N)])
    sx0 = shift([(x, 0) for x in range(N)])
    where = collections.defaultdict(list)
    for y, v in enumerate(s0y):
        where[v].append(y)
    # s(x, y) = s0y[(u_x + y) & 2047]; u_x is P[X] up to constants d, c fixed by asking one
    # table P to serve both stages
    u = [where[v] for v in sx0]
    ci = int(math.floor(lat.c)) % N
    best = None
    for d in range(N):
        cnt = collections.Counter((u[k][0] + d - s0y[(k - d) % N]) % N
                                  for k in range(N) if len(u[k]) == 1)
        c, n = cnt.most_common(1)[0]
        if best is None or n > best[0]:
            best = (n, d, c)
    n, d, c = best
    assert n == sum(len(x) == 1 for x in u), best
    perm = [(s0y[(m - ci - d) % N] + c) % N for m in range(N)]
    grad = [lat.vecs[lz[(m - ci - c) % N]] for m in range(N)]
    return perm, grad


# ---------------------------------------------------------------------------------------------
# the model, checked against povray


def model(p, c, v0, scale, perm, grad):
    perm, grad = np.asarray(perm), np.asarray(grad)
    t = np.asarray(p, dtype=float) + c
    i = np.floor(t)
    f = t - i
    i = i.astype(np.int64) & (N - 1)
    s = f * f * (3 - 2 * f)
    tot = 0
    for corner in range(8):
        d = np.array([corner & 1, (corner >> 1) & 1, (corner >> 2) & 1])
        j = (i + d) & (N - 1)
        h = perm[(perm[j[:, 0]] + j[:, 1]) & (N - 1)]
        g = grad[(h + j[:, 2]) & (N - 1)]
        w = np.prod(np.where(d == 1, s, 1 - s), axis=1)
        tot = tot + w * ((f - d) * g).sum(1)
    return np.clip(v0 + scale * tot, 0, 1)


def write_rust(path, c, v0, scale, perm, grad):
    with open(path, "w") as f:
        f.write("//! POV-Ray 3.7's `noise_generator 3` tables, measured from the `povray` binary\n")
        f.write("//! by scripts/measure_noise3.py (generated: do not edit; see docs/noise.md).\n\n")
        f.write("/// Added to each coordinate before the floor: the lattice sits at x = k - frac(C).\n")
        f.write(f"pub const GEN3_SHIFT: f64 = {c!r};\n")
        f.write("/// The value is `GEN3_A + GEN3_B * Σ w g·d`, clipped to [0, 1].\n")
        f.write(f"pub const GEN3_A: f64 = {v0!r};\n")
        f.write(f"pub const GEN3_B: f64 = {scale!r};\n\n")
        f.write("/// The hash table: a lattice point's gradient is\n")
        f.write("/// GEN3_GRAD[(P[(P[X] + Y) & 2047] + Z) & 2047].\n")
        f.write(f"pub static GEN3_PERM: [u16; {N}] = [\n")
        for i in range(0, N, 16):
            f.write("    " + ", ".join(str(x) for x in perm[i:i + 16]) + ",\n")
        f.write("];\n\n")
        f.write("/// The unit gradients.\n")
        f.write("#[rustfmt::skip]\n")
        f.write(f"pub static GEN3_GRAD: [[f64; 3]; {N}] = [\n")
        for i in range(0, N, 2):
            f.write("    " + " ".join("[" + ", ".join(repr(float(x)) for x in g) + "],"
                                      for g in grad[i:i + 2]) + "\n")
        f.write("];\n")
    subprocess.run(["rustfmt", "--edition", "2021", path], check=False)


# ---------------------------------------------------------------------------------------------
# held-out probes


PROBE_GROUPS = [
    ("f_noise_generator({x},{y},{z},3)", 200, 300.0),
    ("f_noise_generator({x},{y},{z},3)", 100, 3.0),
    ("f_noise_generator({x},{y},{z},3)", 50, 3e7),
]
PATTERNS = [
    "bozo noise_generator 3", "spotted noise_generator 3", "bumps noise_generator 3",
    "dents noise_generator 3", "granite noise_generator 3", "wrinkles noise_generator 3",
    "agate noise_generator 3", "agate agate_turb 0.7 octaves 4 noise_generator 3",
    "bozo turbulence 0.6 octaves 3 noise_generator 3",
    "granite warp { turbulence 0.3 } noise_generator 3",
    "wood turbulence 0.05 noise_generator 3",
    "wood turbulence <0.05,0.1,0.3> octaves 3 omega 0.7 lambda 2.7 noise_generator 3",
    "crackle solid noise_generator 3", "spotted scale 0.3 noise_generator 3",
    # agate_turb is single precision for every generator (0.7 is not a float)
    "agate agate_turb 0.7 octaves 4", "agate agate_turb 0.3 noise_generator 1",
]
MARBLE = [
    "marble turbulence 0.1 noise_generator 3 ramp_wave",
    "marble turbulence <0.1,0.5,0.5> octaves 6 omega 0.7 lambda 3 noise_generator 3 ramp_wave",
]


def probe_lines(rng):
    lines = [PROBE_MARK]

    def group(pre, exprs):
        probe_group(lines, pre, exprs)

    def pts(n, r):
        return probe_points(rng, n, r)

    for tmpl, n, r in PROBE_GROUPS:
        group("", [tmpl.format(x=x, y=y, z=z) for x, y, z in pts(n, r)])
    # global_settings { noise_generator 3 } reaches the patterns too
    group("global_settings { noise_generator 3 }\n"
          "#declare PF = function { pattern { granite } }\n",
          [f"PF({x},{y},{z})" for x, y, z in pts(40, 20.0)])
    for pat in PATTERNS:
        pre = f"#declare PF = function {{ pattern {{ {pat} }} }}\n"
        group(pre, [f"PF({x},{y},{z})" for x, y, z in pts(40, 20.0)])
    for pat in MARBLE:
        pre = f"#declare PF = function {{ pattern {{ {pat} }} }}\n"
        p = [(round(rng.uniform(0.3, 0.45), 6), y, z) for _, y, z in pts(40, 20.0)]
        group(pre, [f"PF({x},{y},{z})" for x, y, z in p])
    return lines


def write_probes(path, rng):
    text = open(path).read().split(PROBE_MARK)[0].rstrip("\n")
    with open(path, "w") as f:
        f.write(text + "\n" + "\n".join(probe_lines(rng)) + "\n")


def main():
    probes = os.path.join(ROOT, "tests/data/noise_probes.txt")
    if sys.argv[1:] == ["--probes"]:
        write_probes(probes, random.Random(2025))
        return
    rng = random.Random(3)
    v0, f0 = lattice_value()
    frac = measure_shift(v0, f0)
    c = measure_integer_part(frac) + frac / 2 ** 29
    print(f"lattice value {v0!r}, C = {c!r} (fraction {frac}/2^29)", file=sys.stderr)
    lat = Lattice(v0, c)
    sample = [tuple(rng.randint(-3000, 3000) for _ in range(3)) for _ in range(2000)]
    norms = [math.sqrt(sum(x * x for x in g)) for g in lat.grads(sample)]
    scale = round(float(np.median(norms)), 9)
    assert max(abs(x - scale) for x in norms) < 1e-12, "gradients are of one length"
    print(f"gradient length (output scale) {scale!r}", file=sys.stderr)
    perm, grad = measure_hash(lat, scale)
    test = [tuple(rng.uniform(-r, r) for _ in range(3)) for r in (3.0, 3000.0, 3e7)
            for _ in range(1000)]
    err = np.abs(model(test, c, v0, scale, perm, grad) - np.array(gen3(test))).max()
    print(f"check on {len(test)} points: max error {err:.3g}", file=sys.stderr)
    assert err < 1e-12
    write_rust(os.path.join(ROOT, "src/render/noise3_data.rs"), c, v0, scale, perm, grad)
    write_probes(probes, random.Random(2025))


if __name__ == "__main__":
    main()
