#!/usr/bin/env python3
"""Find POV-Ray's polynomial internal functions (functions.inc) from the povray binary.

A function f(x, y, z, P0, P1..Pk) is taken to be clamp(P0 * Q(x, y, z, P1..Pk), -10, 10)
with Q a polynomial (P0 the manual's field strength). It is measured
(measure_internal_functions.py) at random points and random P1..Pk with a fixed P0; every
monomial up to a total degree is fitted by least squares, the coefficients rounded to small
fractions, and the model is then checked at fresh points over a wider range, with other
field strengths and parameters. Prints per function the largest difference found (relative
to max(1, |value|)) and the Rust rows for src/func/internal_polynomials.rs:
(coefficient, [power of x, y, z, P1, P2, P3]).

Usage: fit_internal_polynomials.py [NAME:DEGREE:RANGE:FIT_P0:K ...]
(FIT_P0 keeps large polynomials inside the clamp while fitting; K extra parameters, drawn
in [0.3, 1.5]). Without arguments, every function lancer takes from this fit.
"""
import math
import random
import sys
from fractions import Fraction

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from measure_internal_functions import measure  # noqa: E402

DEFAULT = [
    "f_bicorn:4:0.7:1:1", "f_crossed_trough:4", "f_cubic_saddle:4", "f_cushion:4",
    "f_devils_curve:4", "f_glob:6", "f_heart:6", "f_hunt_surface:6:0.7:0.0001",
    "f_klein_bottle:6", "f_kummer_surface_v1:4", "f_lemniscate_of_gerono:4", "f_mitre:4",
    "f_nodal_cubic:3", "f_odd:4", "f_pillow:4", "f_piriform:4", "f_quartic_paraboloid:4",
    "f_quartic_saddle:4", "f_steiners_roman:4", "f_torus_gumdrop:6", "f_umbrella:4",
    "f_hyperbolic_torus:4:0.7:1:2", "f_parabolic_torus:4:0.7:1:2", "f_witch_of_agnesi:4:0.7:1:1",
    "f_quartic_cylinder:4:0.7:1:2", "f_folium_surface:4:0.7:1:2", "f_bifolia:6:0.7:1:1",
    "f_strophoid:5:0.7:1:3",
]

# Polynomials whose parameters reach a degree the joint fit would need too many povray runs
# for: their terms were read off per-parameter-set fits (fit with K = 0 at several fixed
# parameter sets and compare the coefficients), and are only checked here.
HAND = {
    # P2² x⁴ − P1² P2² x² − y² − z²
    "f_kampyle_of_eudoxus": (2, [(1, [4, 0, 0, 0, 2]), (-1, [2, 0, 0, 2, 2]), (-1, [0, 2, 0, 0, 0]),
                                 (-1, [0, 0, 2, 0, 0])]),
    # −(x²+y²+z²)² − 2 R² y² + (T − 2) R² (x² + z²) − R⁴ + F²  (R, F, T = P1, P2, P3)
    "f_ovals_of_cassini": (3, [(-1, [4, 0, 0, 0, 0, 0]), (-1, [0, 4, 0, 0, 0, 0]), (-1, [0, 0, 4, 0, 0, 0]),
                               (-2, [2, 2, 0, 0, 0, 0]), (-2, [2, 0, 2, 0, 0, 0]), (-2, [0, 2, 2, 0, 0, 0]),
                               (-2, [0, 2, 0, 2, 0, 0]), (1, [2, 0, 0, 2, 0, 1]), (-2, [2, 0, 0, 2, 0, 0]),
                               (1, [0, 0, 2, 2, 0, 1]), (-2, [0, 0, 2, 2, 0, 0]), (-1, [0, 0, 0, 4, 0, 0]),
                               (1, [0, 0, 0, 0, 2, 0])]),
    # 1 − x⁴ − y⁴ − z⁴ − P1 (x² + y² + z²) − P2 (x²y² + x²z² + y²z²) − P3 xyz
    "f_kummer_surface_v2": (3, [(1, [0, 0, 0, 0, 0, 0]), (-1, [4, 0, 0, 0, 0, 0]), (-1, [0, 4, 0, 0, 0, 0]),
                                (-1, [0, 0, 4, 0, 0, 0]), (-1, [2, 0, 0, 1, 0, 0]), (-1, [0, 2, 0, 1, 0, 0]),
                                (-1, [0, 0, 2, 1, 0, 0]), (-1, [2, 2, 0, 0, 1, 0]), (-1, [2, 0, 2, 0, 1, 0]),
                                (-1, [0, 2, 2, 0, 1, 0]), (-1, [1, 1, 1, 0, 0, 1])]),
    # P1 times a sextic whose odd coefficients are multiples of 2√2 (fits at P1 = 0.5, 1, 2
    # with field strength 0.001, which keeps it inside the clamp).
    "f_boy_surface": (1, [(c * (2 * math.sqrt(2) if r8 else 1), list(m) + [1]) for c, r8, m in [
        (64, 0, (0, 0, 3)), (-288, 0, (0, 0, 4)), (432, 0, (0, 0, 5)), (-216, 0, (0, 0, 6)),
        (-144, 0, (0, 2, 2)), (324, 0, (0, 2, 4)), (216, 1, (0, 3, 2)), (-216, 1, (0, 3, 3)),
        (324, 0, (0, 4, 1)), (-810, 0, (0, 4, 2)), (-729, 0, (0, 6, 0)), (324, 1, (1, 2, 3)),
        (-1458, 1, (1, 4, 1)), (-144, 0, (2, 0, 2)), (324, 0, (2, 0, 4)), (-648, 1, (2, 1, 2)),
        (648, 1, (2, 1, 3)), (648, 0, (2, 2, 1)), (-1620, 0, (2, 2, 2)), (-2187, 0, (2, 4, 0)),
        (-108, 1, (3, 0, 3)), (-972, 1, (3, 2, 1)), (324, 0, (4, 0, 1)), (-810, 0, (4, 0, 2)),
        (-2187, 0, (4, 2, 0)), (486, 1, (5, 0, 1)), (-729, 0, (6, 0, 0))]]),
}


def monomials(deg, nvars):
    if nvars == 0:
        return [()]
    return [(i,) + m for i in range(deg + 1) for m in monomials(deg - i, nvars - 1)]


def row(args, mon):
    v = 1.0
    for a, e in zip(args, mon):
        v *= a**e
    return v


def sample(rng, k, n, seed):
    random.seed(seed)
    return [[round(random.uniform(-rng, rng), 4) for _ in range(3)]
            + [round(random.uniform(0.3, 1.5), 3) for _ in range(k)] for _ in range(n)]


def measure_many(name, p0, args, k):
    if k == 0:
        return np.array([float(v) for _, _, v in measure(name, [[p0]], [tuple(a) for a in args])])
    # One povray run per parameter set would be slow: group points by 10 per set.
    vals = []
    for s in range(0, len(args), 10):
        chunk = args[s:s + 10]
        ps = chunk[0][3:]
        for a in chunk:
            a[3:] = ps
        vals += [float(v) for _, _, v in measure(name, [[p0] + ps], [tuple(a[:3]) for a in chunk])]
    return np.array(vals)


def fit(name, deg, rng, p0, k):
    mons = monomials(deg, 3 + k)
    args = sample(rng, k, 2 * len(mons) + 40, hash(name) & 0xFFFF)
    vals = measure_many(name, p0, args, k) / p0
    keep = np.abs(vals * p0) < 10 - 1e-9
    a = np.array([[row(x, m) for m in mons] for x in args])
    c, *_ = np.linalg.lstsq(a[keep], vals[keep], rcond=None)
    return [(Fraction(v).limit_denominator(1000), m) for m, v in zip(mons, c)
            if Fraction(v).limit_denominator(1000) != 0]


def model(terms, p0, x):
    v = sum(float(f) * row(x, m) for f, m in terms)
    return min(10.0, max(-10.0, p0 * v))


def check(name, terms, k):
    worst = 0.0
    for p0 in (1.0, -0.37, 2.5, 0.001):
        args = sample(2.0, k, 60, 1) + sample(0.6, k, 60, 2)
        vals = measure_many(name, p0, args, k)
        for a, v in zip(args, vals):
            worst = max(worst, abs(model(terms, p0, a) - v) / max(1.0, abs(v)))
    return worst


def print_rows(name, k, worst, terms):
    rows = ", ".join(
        f"({f.numerator}.0 / {f.denominator}.0, {list(m) + [0] * (6 - len(m))})"
        if isinstance(f, Fraction) and f.denominator != 1 and len(str(float(f))) >= 12
        else f"({float(f)!r}, {list(m) + [0] * (6 - len(m))})" for f, m in terms)
    print(f"// {name}: {k} parameter(s), worst {worst:.2e}\n{rows}", flush=True)


def main():
    for name, (k, hand) in HAND.items() if len(sys.argv) < 2 else []:
        terms = [(Fraction(c) if isinstance(c, int) else c, tuple(m[:3 + k])) for c, m in hand]
        print_rows(name, k, check(name, terms, k), terms)
    for spec in sys.argv[1:] or DEFAULT:
        parts = spec.split(":") + [None] * 4
        name, deg = parts[0], int(parts[1] or 6)
        rng, p0, k = float(parts[2] or 0.7), float(parts[3] or 1.0), int(parts[4] or 0)
        terms = fit(name, deg, rng, p0, k)
        print_rows(name, k, check(name, terms, k), terms)


if __name__ == "__main__":
    main()
