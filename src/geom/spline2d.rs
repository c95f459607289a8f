//! The 2-D spline curves that `prism` and `lathe` sweep, and the root finding they share.
//!
//! Every spline piece is stored as two cubics in a parameter s ∈ [0, 1] together with its two
//! end points exactly as written. Measured against povray (orthographic renders of prisms and
//! lathes, compared pixel for pixel with each candidate curve), POV-Ray's pieces are:
//! * linear: the straight line between two points;
//! * quadratic: through P[i] and P[i+1], leaving P[i] with slope (P[i+1] − P[i−1]) / 2;
//! * cubic: Catmull-Rom, slopes (P[i+1] − P[i−1]) / 2 and (P[i+2] − P[i]) / 2;
//! * bezier: the cubic Bézier curve of four points.
//!
//! Crossings are counted with one sign convention (a value of exactly zero counts as positive)
//! and with each end point's value computed from the exact point, the same for both pieces that
//! share it. So a crossing at a shared vertex is found by exactly one of the two pieces, and
//! even-odd counts never double or lose a vertex.

use crate::geom::bernstein::{BINOM, TO_BERNSTEIN};
use crate::geom::poly::{eval, eval_with_derivative, roots_in_into, Roots};

/// A point of a 2-D curve: (x, z) for prisms, (radius, height) for lathes.
pub type P2 = [f64; 2];

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SplineKind {
    Linear,
    Quadratic,
    Cubic,
    Bezier,
}

impl SplineKind {
    pub fn name(self) -> &'static str {
        match self {
            SplineKind::Linear => "linear",
            SplineKind::Quadratic => "quadratic",
            SplineKind::Cubic => "cubic",
            SplineKind::Bezier => "Bezier",
        }
    }
}

/// One piece of a spline: `x(s) = Σ x[i] sⁱ`, `y(s) = Σ y[i] sⁱ` for s in [0, 1].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Piece {
    pub x: [f64; 4],
    pub y: [f64; 4],
    /// The end points as written (the polynomials reproduce them only up to rounding).
    pub p0: P2,
    pub p1: P2,
    /// Bounds of the piece: min x, min y, max x, max y.
    pub lo: P2,
    pub hi: P2,
}

impl Piece {
    fn from_coefficients(x: [f64; 4], y: [f64; 4], p0: P2, p1: P2) -> Piece {
        // The Bézier control points of the same cubic; the curve lies in their hull.
        let hull = |c: [f64; 4]| {
            let b = [
                c[0],
                c[0] + c[1] / 3.0,
                c[0] + (2.0 * c[1] + c[2]) / 3.0,
                c[0] + c[1] + c[2] + c[3],
            ];
            b.iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
                    (lo.min(v), hi.max(v))
                })
        };
        let (xl, xh) = hull(x);
        let (yl, yh) = hull(y);
        Piece {
            x,
            y,
            p0,
            p1,
            lo: [xl.min(p0[0]).min(p1[0]), yl.min(p0[1]).min(p1[1])],
            hi: [xh.max(p0[0]).max(p1[0]), yh.max(p0[1]).max(p1[1])],
        }
    }

    pub fn linear(a: P2, b: P2) -> Piece {
        let c = |i: usize| [a[i], b[i] - a[i], 0.0, 0.0];
        Piece::from_coefficients(c(0), c(1), a, b)
    }

    /// From `a` to `b`, leaving `a` with slope (b − prev) / 2.
    pub fn quadratic(prev: P2, a: P2, b: P2) -> Piece {
        let c = |i: usize| {
            let d = 0.5 * (b[i] - prev[i]);
            [a[i], d, b[i] - a[i] - d, 0.0]
        };
        Piece::from_coefficients(c(0), c(1), a, b)
    }

    /// Catmull-Rom from `a` to `b`.
    pub fn cubic(prev: P2, a: P2, b: P2, next: P2) -> Piece {
        let c = |i: usize| {
            let (d0, d1) = (0.5 * (b[i] - prev[i]), 0.5 * (next[i] - a[i]));
            [
                a[i],
                d0,
                3.0 * (b[i] - a[i]) - 2.0 * d0 - d1,
                2.0 * (a[i] - b[i]) + d0 + d1,
            ]
        };
        Piece::from_coefficients(c(0), c(1), a, b)
    }

    pub fn bezier(a: P2, b: P2, c: P2, d: P2) -> Piece {
        let k = |i: usize| {
            [
                a[i],
                3.0 * (b[i] - a[i]),
                3.0 * (a[i] - 2.0 * b[i] + c[i]),
                d[i] - a[i] + 3.0 * (b[i] - c[i]),
            ]
        };
        Piece::from_coefficients(k(0), k(1), a, d)
    }

    pub fn at(&self, s: f64) -> P2 {
        [eval(&self.x, s), eval(&self.y, s)]
    }

    /// d/ds of the curve.
    pub fn tangent(&self, s: f64) -> P2 {
        [
            eval_with_derivative(&self.x, s).1,
            eval_with_derivative(&self.y, s).1,
        ]
    }

    /// Whether the piece is a straight line (its crossings need no root finding).
    pub fn is_linear(&self) -> bool {
        self.x[2] == 0.0 && self.x[3] == 0.0 && self.y[2] == 0.0 && self.y[3] == 0.0
    }
}

/// Calls `found` with every s in [lo, hi] where the polynomial `c` changes sign, zero counting
/// as positive. `f_lo` and `f_hi` stand for the polynomial's values at the ends: the caller
/// computes them from exact data so that neighbouring pieces agree on them.
pub fn sign_changes(c: &[f64], lo: f64, hi: f64, f_lo: f64, f_hi: f64, mut found: impl FnMut(f64)) {
    sign_changes_until(
        c,
        lo,
        hi,
        f_lo,
        f_hi,
        |_, _| None::<std::convert::Infallible>,
        |r| match r {
            Ok(s) => found(s),
            Err(never) => match never {},
        },
    );
}

/// [`sign_changes`] for callers that may not need a root's last bits: before each of its
/// Newton steps, `settle(a, b)` sees the bracket that holds the root the refinement would
/// return (its iterates never leave it), and a `Some` ends that root's refinement, reported to
/// `found` as `Err`. A root refined to the end is `Ok`, the same bits as `sign_changes`' (the
/// same iterates). Callers answer from bounds of their own functions over the bracket (see
/// [`hull_on`]): most roots a ray's pieces hold are beyond what the caller keeps.
pub fn sign_changes_until<R>(
    c: &[f64],
    lo: f64,
    hi: f64,
    f_lo: f64,
    f_hi: f64,
    settle: impl FnMut(f64, f64) -> Option<R>,
    found: impl FnMut(Result<f64, R>),
) {
    let n = c.iter().rposition(|&v| v != 0.0).map_or(0, |i| i + 1);
    if lo.is_nan() || hi.is_nan() || lo > hi || n > 17 {
        return;
    }
    // The lengths lathes, prisms and sors make, each with its own copy of the body: a
    // constant length lets LLVM unroll the evaluations (the same operations in the same
    // order, so the same roots to the bit).
    let c = &c[..n];
    let (s, f) = (settle, found);
    match n {
        3 => changes_body(<&[f64; 3]>::try_from(c).unwrap(), lo, hi, f_lo, f_hi, s, f),
        4 => changes_body(<&[f64; 4]>::try_from(c).unwrap(), lo, hi, f_lo, f_hi, s, f),
        5 => changes_body(<&[f64; 5]>::try_from(c).unwrap(), lo, hi, f_lo, f_hi, s, f),
        7 => changes_body(<&[f64; 7]>::try_from(c).unwrap(), lo, hi, f_lo, f_hi, s, f),
        _ => changes_body(c, lo, hi, f_lo, f_hi, s, f),
    }
}

#[inline(always)]
fn changes_body<R>(
    c: &[f64],
    lo: f64,
    hi: f64,
    f_lo: f64,
    f_hi: f64,
    mut settle: impl FnMut(f64, f64) -> Option<R>,
    mut found: impl FnMut(Result<f64, R>),
) {
    let n = c.len();
    if n > 2 && lo == 0.0 && hi == 1.0 && no_sign_change(c, f_lo, f_hi) {
        return;
    }
    // Extrema cut [lo, hi] into monotone pieces with at most one sign change each; inflection
    // points where the derivative only touches zero do not break monotonicity.
    let mut d = [0.0; 16];
    for i in 1..n {
        d[i - 1] = c[i] * i as f64;
    }
    let (line_root, mut roots);
    let crit: &[f64] = if n == 3 {
        // `roots_in` of a line, as it computes it: `d[1] = 2 c[2]` is not zero (nor is
        // `c[2]`), so it is the line's one root, kept when in [lo, hi].
        line_root = [-d[0] / d[1]];
        if line_root[0] >= lo && line_root[0] <= hi {
            &line_root
        } else {
            &[]
        }
    } else if n > 2 {
        roots = Roots::new();
        roots_in_into(&d[..n - 1], lo, hi, &mut roots);
        &roots
    } else {
        &[]
    };
    let mut a = lo;
    let mut fa = f_lo;
    let inner = crit.iter().copied().filter(|&x| x > lo && x < hi);
    for (b, fb) in inner
        .map(|x| (x, eval(c, x)))
        .chain(std::iter::once((hi, f_hi)))
    {
        if (fa >= 0.0) != (fb >= 0.0) {
            found(refine_until(c, a, b, fa < 0.0, &mut settle));
        }
        a = b;
        fa = fb;
    }
}

/// Whether the polynomial surely keeps one sign on [0, 1], ends included: its Bernstein
/// coefficients (whose hull holds the curve) all share the sign of both end values. Most
/// pieces a ray passes near have no crossing, and this is far cheaper than isolating roots.
#[inline(always)]
fn no_sign_change(c: &[f64], f_lo: f64, f_hi: f64) -> bool {
    let n = c.len() - 1;
    let positive = f_lo >= 0.0;
    if positive != (f_hi >= 0.0) {
        return false;
    }
    // b_k = Σ_{i ≤ k} C(k, i) / C(n, i) · c_i, the quotients from the table up to degree 8.
    let b = |k: usize| -> f64 {
        if n < TO_BERNSTEIN.len() {
            let w = &TO_BERNSTEIN[n][k];
            (0..=k).map(|i| w[i] * c[i]).sum()
        } else {
            (0..=k).map(|i| BINOM[k][i] / BINOM[n][i] * c[i]).sum()
        }
    };
    (0..=n).all(|k| if positive { b(k) > 0.0 } else { b(k) < 0.0 })
}

/// A root in the bracket `[a, b]` by Newton steps kept inside a shrinking bracket, or
/// `settle`'s answer for a bracket on the way (asked before each step; the iterates and the
/// root returned never leave the bracket it is shown).
#[inline(always)]
fn refine_until<R>(
    c: &[f64],
    mut a: f64,
    mut b: f64,
    neg_at_a: bool,
    mut settle: impl FnMut(f64, f64) -> Option<R>,
) -> Result<f64, R> {
    let mut x = 0.5 * (a + b);
    for _ in 0..100 {
        if let Some(r) = settle(a, b) {
            return Err(r);
        }
        let (f, df) = eval_with_derivative(c, x);
        if f == 0.0 {
            return Ok(x);
        }
        if (f < 0.0) == neg_at_a {
            a = x;
        } else {
            b = x;
        }
        let newton = x - f / df;
        let next = if newton > a && newton < b {
            newton
        } else {
            0.5 * (a + b)
        };
        let tol = 4.0 * f64::EPSILON * next.abs().max(1e-300);
        if (next - x).abs() <= tol || b - a <= tol {
            return Ok(next);
        }
        x = next;
    }
    Ok(x)
}

/// Bounds of the cubic `p` (or a lower degree, zeros on top) over `[a, b]`, `a ≤ b`: the least
/// and greatest of its Bézier control values there, from its values and slopes at the ends.
/// Rounding can put them a few ulps of `Σ |p_i| max(1, |a|, |b|)³` inside the true bounds;
/// callers widen them by far more.
#[inline(always)]
pub fn hull_on(p: &[f64; 4], a: f64, b: f64) -> (f64, f64) {
    let (pa, da) = eval_with_derivative(p, a);
    let (pb, db) = eval_with_derivative(p, b);
    let h3 = (b - a) * (1.0 / 3.0);
    let (c1, c2) = (pa + da * h3, pb - db * h3);
    (pa.min(pb).min(c1.min(c2)), pa.max(pb).max(c1.max(c2)))
}

/// Whether the horizontal half-line from `p` towards +x crosses the pieces an odd number of
/// times: the even-odd rule of prism outlines and polygons. With `radial`, the curve is a
/// lathe's profile and a crossing counts where |x| (the radius) exceeds `p`'s.
pub fn inside_even_odd(pieces: &[Piece], p: P2, radial: bool) -> bool {
    let mut odd = false;
    for pc in pieces {
        if p[1] < pc.lo[1] || p[1] > pc.hi[1] {
            continue;
        }
        let g0 = pc.p0[1] - p[1];
        let g1 = pc.p1[1] - p[1];
        let right_of = |x: f64| if radial { x.abs() > p[0] } else { x > p[0] };
        let all_right = if radial {
            pc.lo[0] > p[0] || -pc.hi[0] > p[0]
        } else {
            pc.lo[0] > p[0]
        };
        if all_right {
            // Only parity matters, and the end points' signs give it.
            odd ^= (g0 >= 0.0) != (g1 >= 0.0);
            continue;
        }
        if !radial && pc.hi[0] <= p[0] {
            continue;
        }
        if pc.is_linear() {
            if (g0 >= 0.0) != (g1 >= 0.0) {
                let s = g0 / (g0 - g1);
                odd ^= right_of(pc.p0[0] + s * (pc.p1[0] - pc.p0[0]));
            }
            continue;
        }
        let mut c = pc.y;
        c[0] -= p[1];
        // A crossing's side is settled once the curve's x over its bracket is wholly on one
        // side of p's (or, radially, of ±p's), by a margin far above the rounding of the hull
        // and of `eval` at the root: the root itself is not needed then.
        let m = 1e-9 * (pc.lo[0].abs().max(pc.hi[0].abs()) + p[0].abs());
        let settle = |a: f64, b: f64| {
            let (lo, hi) = hull_on(&pc.x, a, b);
            let (lo, hi) = (lo - m, hi + m);
            if lo > p[0] || (radial && hi < -p[0]) {
                Some(true)
            } else if hi < p[0] && !(radial && lo <= -p[0]) {
                Some(false)
            } else {
                None
            }
        };
        sign_changes_until(&c, 0.0, 1.0, g0, g1, settle, |r| {
            odd ^= match r {
                Ok(s) => right_of(eval(&pc.x, s)),
                Err(right) => right,
            }
        });
    }
    odd
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pieces_pass_through_their_points() {
        let (a, b, c, d) = ([0.0, 0.0], [1.0, 2.0], [3.0, 1.0], [4.0, 4.0]);
        for p in [
            Piece::linear(b, c),
            Piece::quadratic(a, b, c),
            Piece::cubic(a, b, c, d),
        ] {
            let (s0, s1) = (p.at(0.0), p.at(1.0));
            assert!((s0[0] - b[0]).abs() < 1e-12 && (s0[1] - b[1]).abs() < 1e-12);
            assert!((s1[0] - c[0]).abs() < 1e-12 && (s1[1] - c[1]).abs() < 1e-12);
        }
        let q = Piece::quadratic(a, b, c);
        let t = q.tangent(0.0);
        assert!((t[0] - 1.5).abs() < 1e-12 && (t[1] - 0.5).abs() < 1e-12);
        let z = Piece::bezier(a, b, c, d);
        assert_eq!(z.at(1.0), d);
        let t = z.tangent(0.0);
        assert!((t[0] - 3.0).abs() < 1e-12 && (t[1] - 6.0).abs() < 1e-12);
        // The bounds hold the curve.
        for i in 0..=100 {
            let p = z.at(i as f64 / 100.0);
            assert!(p[0] >= z.lo[0] && p[0] <= z.hi[0] && p[1] >= z.lo[1] && p[1] <= z.hi[1]);
        }
    }

    #[test]
    fn sign_changes_find_each_crossing_once() {
        // (s - 0.25)(s - 0.5)(s - 0.75)
        let c = [-0.09375, 0.6875, -1.5, 1.0];
        let mut v = Vec::new();
        sign_changes(&c, 0.0, 1.0, eval(&c, 0.0), eval(&c, 1.0), |s| v.push(s));
        assert_eq!(v.len(), 3);
        for (got, want) in v.iter().zip([0.25, 0.5, 0.75]) {
            assert!((got - want).abs() < 1e-14);
        }
        // The Bernstein shortcut: no roots in [0, 1] here, two there.
        let far = [2.0, -3.0, 1.5]; // 1.5 s² - 3 s + 2 > 0
        assert!(no_sign_change(&far, 2.0, 0.5));
        let two = [0.2, -1.5, 1.5]; // roots near 0.18 and 0.82
        assert!(!no_sign_change(&two, 0.2, 0.2));
        let mut n = 0;
        sign_changes(&two, 0.0, 1.0, 0.2, 0.2, |_| n += 1);
        assert_eq!(n, 2);
        // A root exactly at an end: counted by the piece where the sign changes, zero positive.
        let c = [0.0, 1.0];
        let mut n = 0;
        sign_changes(&c, 0.0, 1.0, 0.0, 1.0, |_| n += 1);
        assert_eq!(n, 0);
        let c = [-1.0, 1.0];
        sign_changes(&c, 0.0, 1.0, -1.0, 0.0, |_| n += 1);
        assert_eq!(n, 1);
    }

    /// The fixed-length bodies `sign_changes` picks find the roots the slice body finds, bit
    /// for bit: random polynomials of the lengths it specialises (many with roots in [0, 1],
    /// some nearly touching zero), on [0, 1] (the Bernstein shortcut) and on other intervals.
    #[test]
    fn fixed_lengths_match_the_slice_body() {
        let mut rng = crate::geom::test_rng::Lcg(0x51_6e);
        let mut found = 0;
        for case in 0..20_000 {
            let len = [3, 4, 5, 7][case % 4];
            let roots: Vec<f64> = (0..len - 1).map(|_| rng.next() * 1.6 - 0.3).collect();
            let mut c = crate::geom::test_rng::from_roots(&roots);
            c[0] += (rng.next() - 0.5) * if case % 3 == 0 { 1e-9 } else { 0.2 };
            let (lo, hi) = if case % 5 == 0 {
                let lo = rng.next() - 0.2;
                (lo, lo + rng.next())
            } else {
                (0.0, 1.0)
            };
            let (f_lo, f_hi) = (eval(&c, lo), eval(&c, hi));
            let mut fixed = Vec::new();
            sign_changes(&c, lo, hi, f_lo, f_hi, |s| fixed.push(s.to_bits()));
            let mut slice = Vec::new();
            let never = |_, _| None::<()>;
            changes_body(
                std::hint::black_box(&c[..]),
                lo,
                hi,
                f_lo,
                f_hi,
                never,
                |s| slice.push(s.unwrap().to_bits()),
            );
            assert_eq!(fixed, slice, "{c:?} on [{lo}, {hi}]");
            found += fixed.len();
        }
        assert!(found > 10_000, "{found}");
    }

    /// `sign_changes_until` shows `settle` only brackets that hold the root the refinement
    /// returns, and with a `settle` that never answers it finds `sign_changes`' roots to the bit.
    #[test]
    fn settled_brackets_hold_the_root() {
        let mut rng = crate::geom::test_rng::Lcg(0x5e7);
        let mut shown = 0;
        for case in 0..20_000 {
            let len = [3, 4, 5, 7][case % 4];
            let roots: Vec<f64> = (0..len - 1).map(|_| rng.next() * 1.6 - 0.3).collect();
            let mut c = crate::geom::test_rng::from_roots(&roots);
            c[0] += (rng.next() - 0.5) * if case % 3 == 0 { 1e-9 } else { 0.2 };
            let (f_lo, f_hi) = (eval(&c, 0.0), eval(&c, 1.0));
            let mut plain = Vec::new();
            sign_changes(&c, 0.0, 1.0, f_lo, f_hi, |s| plain.push(s));
            let (mut brackets, mut got) = (Vec::new(), Vec::new());
            // Which root the brackets shown belong to: the count found so far.
            let n = std::cell::Cell::new(0);
            let settle = |a: f64, b: f64| {
                brackets.push((a, b, n.get()));
                None::<()>
            };
            sign_changes_until(&c, 0.0, 1.0, f_lo, f_hi, settle, |r| {
                got.push(r.unwrap());
                n.set(n.get() + 1);
            });
            let bits = |v: &[f64]| v.iter().map(|s| s.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&got), bits(&plain), "{c:?}");
            for (a, b, k) in brackets {
                assert!(
                    a <= got[k] && got[k] <= b,
                    "{c:?}: {} not in [{a}, {b}]",
                    got[k]
                );
                shown += 1;
            }
        }
        assert!(shown > 50_000, "{shown}");
    }

    /// The even-odd test as it was before crossings were settled by the hull of x: every
    /// crossing refined, its x compared.
    fn inside_refining_all(pieces: &[Piece], p: P2, radial: bool) -> bool {
        let mut odd = false;
        for pc in pieces {
            if p[1] < pc.lo[1] || p[1] > pc.hi[1] {
                continue;
            }
            let g0 = pc.p0[1] - p[1];
            let g1 = pc.p1[1] - p[1];
            let right_of = |x: f64| if radial { x.abs() > p[0] } else { x > p[0] };
            let all_right = if radial {
                pc.lo[0] > p[0] || -pc.hi[0] > p[0]
            } else {
                pc.lo[0] > p[0]
            };
            if all_right {
                odd ^= (g0 >= 0.0) != (g1 >= 0.0);
                continue;
            }
            if !radial && pc.hi[0] <= p[0] {
                continue;
            }
            if pc.is_linear() {
                if (g0 >= 0.0) != (g1 >= 0.0) {
                    let s = g0 / (g0 - g1);
                    odd ^= right_of(pc.p0[0] + s * (pc.p1[0] - pc.p0[0]));
                }
                continue;
            }
            let mut c = pc.y;
            c[0] -= p[1];
            sign_changes(&c, 0.0, 1.0, g0, g1, |s| odd ^= right_of(eval(&pc.x, s)));
        }
        odd
    }

    /// Random outlines of every kind and points near them (many level with a vertex or on the
    /// curve's x): the settled even-odd test answers as the one that refines every crossing.
    #[test]
    fn settled_even_odd_is_the_refined_one() {
        let mut rng = crate::geom::test_rng::Lcg(0xe0d);
        let mut inside = 0;
        for case in 0..3000 {
            let pts: Vec<P2> = (0..9)
                .map(|_| [rng.next() * 4.0 - 1.0, rng.next() * 4.0 - 2.0])
                .collect();
            let pieces: Vec<Piece> = (0..6)
                .map(|i| {
                    let (a, b, c, d) = (pts[i], pts[i + 1], pts[i + 2], pts[i + 3]);
                    match (case + i) % 4 {
                        0 => Piece::linear(b, c),
                        1 => Piece::quadratic(a, b, c),
                        2 => Piece::cubic(a, b, c, d),
                        _ => Piece::bezier(a, b, c, d),
                    }
                })
                .collect();
            for k in 0..40 {
                let pc = &pieces[k % 6];
                let s = rng.next();
                let mut p = match k % 4 {
                    0 => [rng.next() * 5.0 - 2.0, rng.next() * 5.0 - 2.5],
                    1 => pc.p0,
                    _ => pc.at(s),
                };
                p[0] += (rng.next() - 0.5) * [0.0, 1e-12, 1e-3, 1.0][k % 4];
                for radial in [false, true] {
                    let want = inside_refining_all(&pieces, p, radial);
                    assert_eq!(
                        inside_even_odd(&pieces, p, radial),
                        want,
                        "{pieces:?} {p:?}"
                    );
                    inside += want as u32;
                }
            }
        }
        assert!(inside > 20_000, "{inside}");
    }

    #[test]
    fn even_odd_square_with_hole() {
        let sq = |a: f64, b: f64| {
            let p = [[a, a], [b, a], [b, b], [a, b], [a, a]];
            (0..4)
                .map(|i| Piece::linear(p[i], p[i + 1]))
                .collect::<Vec<_>>()
        };
        let mut pieces = sq(0.0, 4.0);
        pieces.extend(sq(1.0, 3.0));
        assert!(inside_even_odd(&pieces, [0.5, 0.5], false));
        assert!(!inside_even_odd(&pieces, [2.0, 2.0], false));
        assert!(!inside_even_odd(&pieces, [5.0, 2.0], false));
        assert!(inside_even_odd(&pieces, [0.5, 2.0], false));
        // Level with a vertex.
        assert!(inside_even_odd(&pieces, [0.5, 1.0], false));
        assert!(!inside_even_odd(&pieces, [-0.5, 1.0], false));
        // A circle-like cubic outline: the point in the middle is inside.
        let ring = [[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]];
        let cubic: Vec<Piece> = (0..4)
            .map(|i| {
                Piece::cubic(
                    ring[(i + 3) % 4],
                    ring[i],
                    ring[(i + 1) % 4],
                    ring[(i + 2) % 4],
                )
            })
            .collect();
        assert!(inside_even_odd(&cubic, [0.1, 0.2], false));
        assert!(!inside_even_odd(&cubic, [1.1, 0.0], false));
        // Radially (a lathe profile), a ring off the axis: a torus-like solid.
        let q = |k: usize| [ring[k % 4][0] + 2.0, ring[k % 4][1]];
        let off: Vec<Piece> = (0..4)
            .map(|i| Piece::cubic(q(i + 3), q(i), q(i + 1), q(i + 2)))
            .collect();
        assert!(inside_even_odd(&off, [2.5, 0.0], true));
        assert!(!inside_even_odd(&off, [0.5, 0.0], true));
        assert!(!inside_even_odd(&off, [3.5, 0.0], true));
    }
}
