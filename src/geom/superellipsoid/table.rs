//! Tabulated powers for the samples' sign test (`Superellipsoid::field`): bounds on `x^c` and
//! `(1 + r^a)^b` for `x`, `r` in [0, 1] without calling `pow`.
//!
//! Both functions increase on [0, 1], so the two table entries around `x` bound the value;
//! that alone is loose for large exponents (`x^20` moves by ~17 % across a step of 1/128 near
//! 0.9). Where the function is convex on the step, the chord bounds it above and the tangent
//! at the step's left end below; where concave, the chord below and the tangent at the right
//! end above. The gap then shrinks with the step squared, and more samples are settled
//! without the exact powers.
//!
//! Convexity: `x^c` is convex for c >= 1 and concave for c <= 1. For `g(r) = (1 + r^a)^b`,
//! `r·g''/g' = (a − 1) + a(b − 1)·w` with `w = r^a / (1 + r^a)`, which increases with r: the
//! sign of `g''` on a step is known when this expression has the same sign at both ends (with
//! a margin over its rounding); the one step holding an inflection keeps the plain bounds.
//!
//! Rigour: the slopes are the derivative shrunk by 1e-9 (a smaller slope keeps either tangent
//! on its side: the left tangent of a convex step and the right one of a concave step), zero
//! where not finite. The bounds' own roundings are relative ones of a few 1e-16 (sums and
//! products of non-negative numbers), except the concave upper bound's subtraction, which adds
//! four units of the right entry. The table entries are `Power::of` (glibc's bits, within one
//! unit of the true power) and the field the caller bounds is computed the same way; the
//! caller's margins (1e-9 against 1) cover these units.

use super::Power;

/// Table steps on [0, 1] (a power of two, so that `x * STEPS`, its floor and their difference
/// are exact).
const STEPS: usize = 128;

/// What is known of a step's curvature.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Bend {
    Convex,
    Concave,
    Unknown,
}

#[derive(Clone, Debug)]
pub(super) struct Table {
    /// The function at `i / STEPS`.
    f: [f64; STEPS + 1],
    /// A lower bound on its derivative there, times the step (so per unit of `t` below).
    slope: [f64; STEPS + 1],
    bend: [Bend; STEPS],
}

impl Table {
    /// `x^c` (`c` the power's exponent).
    pub(super) fn power(c: Power) -> Table {
        let k = c.exponent();
        let bend = if k >= 1.0 {
            Bend::Convex
        } else {
            Bend::Concave
        };
        Table::new(|x| c.of(x), |x| k * x.powf(k - 1.0), |_, _| bend)
    }

    /// `(1 + r^a)^b`.
    pub(super) fn ratio(a: Power, b: Power) -> Table {
        let (ka, kb) = (a.exponent(), b.exponent());
        let e = |r: f64| {
            let ra = r.powf(ka);
            (ka - 1.0) + ka * (kb - 1.0) * (ra / (1.0 + ra))
        };
        let tol = 1e-9 * ((ka - 1.0).abs() + (ka * (kb - 1.0)).abs());
        Table::new(
            |r| b.of(1.0 + a.of(r)),
            |r| ka * kb * r.powf(ka - 1.0) * (1.0 + r.powf(ka)).powf(kb - 1.0),
            |r0, r1| {
                let (e0, e1) = (e(r0), e(r1));
                if e0 > tol && e1 > tol {
                    Bend::Convex
                } else if e0 < -tol && e1 < -tol {
                    Bend::Concave
                } else {
                    Bend::Unknown
                }
            },
        )
    }

    fn new(
        f: impl Fn(f64) -> f64,
        df: impl Fn(f64) -> f64,
        bend: impl Fn(f64, f64) -> Bend,
    ) -> Table {
        let at = |i: usize| i as f64 / STEPS as f64;
        Table {
            f: std::array::from_fn(|i| f(at(i))),
            slope: std::array::from_fn(|i| {
                let s = df(at(i)) / STEPS as f64 * (1.0 - 1e-9);
                if s.is_finite() && s > 0.0 {
                    s
                } else {
                    0.0
                }
            }),
            bend: std::array::from_fn(|i| bend(at(i), at(i + 1))),
        }
    }

    /// Bounds on the function at `x` in `[0, 1]` (None outside, or NaN).
    #[inline]
    pub(super) fn bounds(&self, x: f64) -> Option<(f64, f64)> {
        if x > 1.0 || x.is_nan() {
            return None;
        }
        let xs = x * STEPS as f64;
        let i = xs as usize;
        if i >= STEPS {
            return Some((self.f[STEPS], self.f[STEPS]));
        }
        let t = xs - i as f64;
        let (f0, f1) = (self.f[i], self.f[i + 1]);
        Some(match self.bend[i] {
            Bend::Convex => (f0 + self.slope[i] * t, f0 + (f1 - f0) * t),
            Bend::Concave => (
                f0 + (f1 - f0) * t,
                (f1 - self.slope[i + 1] * (1.0 - t)) + 4.5e-16 * f1,
            ),
            Bend::Unknown => (f0, f1),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The bounds hold the exact powers (as `Power::of` gives them) at many points, and are
    /// much tighter than the two entries around the point.
    #[test]
    fn bounds_hold_the_powers() {
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let (mut gap, mut plain) = (0.0, 0.0);
        for (e, n) in [
            (1.0, 0.1),
            (1.0, 0.5),
            (0.3, 0.3),
            (2.5, 0.2),
            (0.2, 2.5),
            (3.0, 3.0),
            (1.0, 1.0),
            (0.05, 1.7),
            (2.0, 2.0),
            (0.7, 1.3),
        ] {
            let (a, b, c) = (Power::new(2.0 / e), Power::new(e / n), Power::new(2.0 / n));
            let tables = [
                (
                    Table::power(c),
                    Box::new(move |x: f64| c.of(x)) as Box<dyn Fn(f64) -> f64>,
                ),
                (
                    Table::ratio(a, b),
                    Box::new(move |r: f64| b.of(1.0 + a.of(r))),
                ),
            ];
            for (table, f) in &tables {
                for j in 0..20_000 {
                    let x = match j % 4 {
                        0 => next(),
                        1 => next() * 1e-3,
                        2 => 1.0 - next() * 1e-3,
                        _ => (next() * STEPS as f64).floor() / STEPS as f64,
                    };
                    let (lo, hi) = table.bounds(x).unwrap();
                    let v = f(x);
                    let tol = 1e-12 * v.abs();
                    assert!(lo <= v + tol && v <= hi + tol, "{e} {n} {x}: {lo} {v} {hi}");
                    let i = ((x * STEPS as f64) as usize).min(STEPS - 1);
                    gap += hi - lo;
                    plain += table.f[i + 1] - table.f[i];
                }
            }
            assert!(table_bounds_none_outside(&tables[0].0));
        }
        assert!(gap < 0.2 * plain, "{gap} {plain}");
    }

    fn table_bounds_none_outside(t: &Table) -> bool {
        t.bounds(1.0 + 1e-12).is_none() && t.bounds(f64::NAN).is_none()
    }
}
