#!/usr/bin/env python3
"""Find POV-Ray's 2-d curve internal functions (functions.inc `*_2d`, `f_strophoid`) from
the povray binary.

Each is taken to be clamp(P0 * Q(X, Y, P1..Pk), -10, 10), Q a polynomial of the curve's
plane, where (X, Y) comes from the "SOR" parameters after P1..Pk (switch, offset, angle):
with the switch off (<= 0) (X, Y) = (x, y) and z is unused (the curve extruded along z);
with it on, r = hypot(x, z) - offset and (X, Y) = (r, y) turned by the angle in degrees
(X = r cos a - y sin a, Y = r sin a + y cos a): a surface of revolution about y. That rule
was measured on f_witch_of_agnesi_2d (80 random cases, switches 0, 0.5, 1, 2, -1).

Q is fitted by least squares with the switch off, then the whole model is checked at fresh
points with random SOR parameters and field strengths. Prints the worst difference
(relative to max(1, |value|)) and the Rust rows (coefficient, [X, Y, 0, P1, P2, P3] powers)
for src/func/internal_polynomials.rs.

Usage: fit_internal_curves.py [NAME:DEGREE:K ...]   (default: every curve lancer takes from it)
"""
import math
import random
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from fit_internal_polynomials import monomials, print_rows, row  # noqa: E402
from fractions import Fraction  # noqa: E402
from measure_internal_functions import measure  # noqa: E402

DEFAULT = ["f_witch_of_agnesi_2d:4:2", "f_devils_curve_2d:4:2", "f_folium_surface_2d:4:2",
           "f_kampyle_of_eudoxus_2d:6:2", "f_lemniscate_of_gerono_2d:6:2", "f_piriform_2d:6:3",
           "f_strophoid_2d:6:3"]


def values(name, p0, cases):
    """povray's values for cases [(x, y, z, [P1..Pk + SOR])], one run per parameter set."""
    out = []
    for x, y, z, ps in cases:
        out.append(((x, y, z), ps))
    vals = []
    for i in range(0, len(out), 1):
        (pt, ps) = out[i]
        vals.append(float(measure(name, [[p0] + ps], [pt])[0][2]))
    return np.array(vals)


def values_grouped(name, p0, pts, ps):
    return np.array([float(v) for _, _, v in measure(name, [[p0] + ps], pts)])


def sor(x, y, z, sw, off, ang):
    if sw <= 0:
        return x, y
    r = math.hypot(x, z) - off
    c, s = math.cos(math.radians(ang)), math.sin(math.radians(ang))
    return r * c - y * s, r * s + y * c


def fit(name, deg, k, rng=1.2, p0=1.0):
    mons = [m for m in monomials(deg, 2 + k)]
    random.seed(hash(name) & 0xFFFF)
    rows, vals = [], []
    sets = max(4, (2 * len(mons) + 40) // 10)
    for _ in range(sets):
        ps = [round(random.uniform(0.3, 1.5), 3) for _ in range(k)]
        pts = [(round(random.uniform(-rng, rng), 4), round(random.uniform(-rng, rng), 4), 0.0)
               for _ in range(10)]
        v = values_grouped(name, p0, pts, ps + [0, 0, 0])
        for (x, y, _), val in zip(pts, v):
            if abs(val) < 10 - 1e-9:
                rows.append([row([x, y] + ps, m) for m in mons])
                vals.append(val / p0)
    c, *_ = np.linalg.lstsq(np.array(rows), np.array(vals), rcond=None)
    terms = []
    for m, v in zip(mons, c):
        f = Fraction(v).limit_denominator(1000)
        if f != 0:
            terms.append((f, (m[0], m[1], 0) + tuple(m[2:])))
    return terms


def model(terms, p0, args):
    v = sum(float(f) * row(args, m) for f, m in terms)
    return min(10.0, max(-10.0, p0 * v))


def check(name, terms, k):
    worst = 0.0
    random.seed(1)
    for p0 in (1.0, -0.37, 2.5, 0.01):
        for _ in range(8):
            ps = [round(random.uniform(0.3, 1.5), 3) for _ in range(k)]
            so = [random.choice([0, 1, 0.5, -1]), random.choice([0, 0.4, -0.3]),
                  random.choice([0, 30, -60])]
            pts = [tuple(round(random.uniform(-2, 2), 4) for _ in range(3)) for _ in range(10)]
            vals = values_grouped(name, p0, pts, ps + so)
            for (x, y, z), v in zip(pts, vals):
                X, Y = sor(x, y, z, *so)
                m = model(terms, p0, [X, Y, 0.0] + ps)
                worst = max(worst, abs(m - v) / max(1.0, abs(v)))
    return worst


def main():
    for spec in sys.argv[1:] or DEFAULT:
        name, deg, k = spec.split(":")
        terms = fit(name, int(deg), int(k))
        print_rows(name, int(k), check(name, terms, int(k)), terms)


if __name__ == "__main__":
    main()
