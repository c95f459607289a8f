//! A certificate that a quartic keeps one sign along the ray's search interval, by a margin above
//! rounding, so that a ray missing a quartic surface by a clear margin is answered without
//! isolating any root (most rays near a `quartic` miss it, and their isolation polishes a
//! critical point from a bracket reaching Cauchy's bound: twenty Newton steps).
//!
//! The root finders here decide everything from the signs of Horner evaluations: a change of
//! sign between two points, or an exact zero. Where every evaluation in the search interval
//! is nonzero and of one sign, [`roots_in`](super::roots_in) and its variants find
//! nothing, whatever points they evaluate at; and [`sturm_roots_in`](super::sturm_roots_in)
//! adds a root only where the polynomial is zero to within its rounding error. So the answer
//! "no root" is theirs to the bit.

use super::eval;
use crate::geom::bernstein::surely_no_root;

/// Relative margin, against the size of the terms, that the polynomial's value must keep
/// everywhere: Horner's rounding error on a quartic is below `8 · 2^-53` of that size, and
/// the rounding of the Taylor shift below is of the same order, both far below this.
const MARGIN: f64 = 1e-11;

/// Whether every Horner evaluation of the quartic `c` (ascending, `c[4] != 0`) at a point of
/// `[lo, hi]` is nonzero and of one sign (that of `c[4]`, unless the interval ends before
/// `x0` below and [`surely_no_root`] alone decides).
///
/// With `p = ±c` (leading coefficient positive) and `x0 = -p3 / (4 p4)`, where the cubic term
/// of the shifted quartic nearly vanishes, the whole axis is tried first (see [`shifted`] and
/// [`positive_for_u_ge_0`], odd terms taken with their worst sign); failing that, and when the
/// interval starts before `x0`, [`surely_no_root`] on `[lo, x0]` and the quartic shifted to
/// `x0` on `s >= 0` (odd terms with their own sign); when it starts after `x0`, the quartic
/// shifted to `lo` on `s >= 0`. Rays that graze a quartic from afar, or have its roots behind
/// them, pass the half-axis tests.
pub fn surely_definite_quartic(c: &[f64; 5], lo: f64, hi: f64) -> bool {
    // No overflow in any evaluation within reach (Horner's partial sums stay below `T`).
    let reach = lo.abs().max(hi.abs());
    let t = (((c[4].abs() * reach + c[3].abs()) * reach + c[2].abs()) * reach + c[1].abs()) * reach
        + c[0].abs();
    if !(t * 4.0).is_finite() || lo > hi {
        return false;
    }
    let p = if c[4] > 0.0 {
        *c
    } else if c[4] < 0.0 {
        c.map(|v| -v)
    } else {
        return false;
    };
    let x0 = -p[3] / (4.0 * p[4]);
    let m = 2.0 * MARGIN;
    let (center, a, e) = if x0 > lo {
        let Some((a, e)) = shifted(&p, x0) else {
            return false;
        };
        let whole = positive_for_u_ge_0(
            a[4] - m * e[4],
            a[3].abs() + m * e[3],
            a[2] - m * e[2],
            a[1].abs() + m * e[1],
            a[0] - m * e[0],
        );
        if whole {
            return true;
        }
        if x0 >= hi {
            return surely_no_root(c, lo, hi)
                || positive_around_a_well(c, lo, x0, [a[0], a[1], a[2]]);
        }
        if !surely_no_root(c, lo, x0) {
            return positive_around_a_well(c, lo, x0, [a[0], a[1], a[2]]);
        }
        (x0, a, e)
    } else {
        let Some((a, e)) = shifted(&p, lo) else {
            return false;
        };
        (lo, a, e)
    };
    debug_assert!(center >= lo);
    // s >= 0 only: an odd term of the right sign only helps, and is dropped. No well's test
    // is asked here: after the Bernstein test on `[lo, x0]` passed the near well's never
    // certified a ray on the quartic scenes (0 of ~64,000 calls over eight of them), and the
    // far well's certifies a few (quarcyl 1,779, steiner 1,859 at 320x240) but fails on most
    // of piriform's (12,232 misses and 7,002 hits ran it in vain: piriform 1.042 by time).
    positive_for_u_ge_0(
        a[4] - m * e[4],
        (m * e[3] - a[3]).max(0.0),
        a[2] - m * e[2],
        (m * e[1] - a[1]).max(0.0),
        a[0] - m * e[0],
    )
}

/// Newton steps on `p'` towards the near well's floor from the guess: enough to centre the
/// expansion of [`positive_around_a_well`] (the place need not be exact: any centre gives
/// a valid answer, a good one a passing one).
const WELL_STEPS: usize = 2;

/// Newton steps towards the far well's floor (or a single well's), whose guess is rougher.
const FAR_STEPS: usize = 3;

/// Whether `p` (`p[4] > 0`) is positive, by the margin, on the whole axis, by an expansion at
/// the floor of one of its wells: at a well's floor the linear term vanishes and the other
/// well shows only as a large cubic term, which [`positive_by_quadratic_factor`] bounds on
/// each half axis. For a ray that misses a quartic with two wells of different depth
/// (objects/quartic/quarcyl: complex roots near 3.5 ± 0.4i and 273 ± 14i), neither the
/// centroid `x0` nor the Bernstein test on `[lo, x0]` separates them.
///
/// The centres: `p` expanded at `x0` (`a`, its cubic term nearly zero) is nearly
/// `a4 s⁴ + a2 s² + ..`, whose wells lie near `s = ±sqrt(-a2 / 2a4)` (both at `x0` when
/// `a2 >= 0`). With two wells the near one is tried first ([`WELL_STEPS`] Newton steps on
/// `p'`), then the far one (or the single well) from `x0 + sqrt(-a2 / 2a4)` ([`FAR_STEPS`]
/// steps): on the quartic scenes most misses the near well
/// leaves are certified there (quarcyl 21,160 of 35,578 walks that found nothing,
/// hyptorus 4,779 of 12,679, steiner 16,042 of 20,151, at 320x240). A value at or below zero
/// at any centre or step means a real root: the answer is then "no" at once (most hits end
/// there, after one evaluation).
///
/// It takes `c` (`c[4] != 0`) and the shifted terms it needs as scalars, and rebuilds `p`:
/// given `&p` and `&a`, the caller wrote `p` to a stack slot and read its coefficients
/// back on every ray's path, most of which never come here (taking them as scalars measured
/// 0.97-0.99 by time on the quartic scenes; the instruction count is unchanged).
#[inline(never)]
fn positive_around_a_well(c: &[f64; 5], lo: f64, x0: f64, [a0, a1, a2]: [f64; 3]) -> bool {
    let p = if c[4] > 0.0 { *c } else { c.map(|v| -v) };
    let a4 = p[4];
    // Positive on the whole axis needs `p(x0) > 0` (`a0`, never certified otherwise on the
    // quartic scenes).
    if !positive(a0) {
        return false;
    }
    let p = &p;
    let d = [p[1], 2.0 * p[2], 3.0 * p[3], 4.0 * p[4]];
    let half = (-a2 / (2.0 * a4)).max(0.0).sqrt();
    // Two wells only where `4a4 s³ + 2a2 s + a1` has three real roots: `-8a2³ > 27a4·a1²`.
    if positive(-8.0 * a2 * a2 * a2 - 27.0 * a4 * a1 * a1) {
        let x = (x0 - half).max(lo);
        match positive_at_well(p, &d, x, WELL_STEPS, x0) {
            Some(true) => return true,
            Some(false) => {}
            None => return false,
        }
    }
    positive_at_well(p, &d, (x0 + half).max(lo), FAR_STEPS, f64::INFINITY) == Some(true)
}

/// From `x`, `steps` Newton steps on `p'` (`d`; each new place at most `cap`), then the
/// expansion there on both half axes: `Some(answer)`, or `None` when a value at or below
/// zero turned up on the way (a real root: no centre can certify). The value's chain runs
/// beside the step's.
#[inline(always)]
fn positive_at_well(
    p: &[f64; 5],
    d: &[f64; 4],
    mut x: f64,
    steps: usize,
    cap: f64,
) -> Option<bool> {
    for _ in 0..steps {
        if !positive(eval(p, x)) {
            return None;
        }
        let f = ((d[3] * x + d[2]) * x + d[1]) * x + d[0];
        let df = (3.0 * d[3] * x + 2.0 * d[2]) * x + d[1];
        if !positive(df) {
            break;
        }
        x = (x - f / df).min(cap);
    }
    if !positive(eval(p, x)) {
        return None;
    }
    let Some((a, e)) = shifted(p, x) else {
        return Some(false);
    };
    let m = 2.0 * MARGIN;
    // Forward (s >= 0) and backward (s = -u, u >= 0: the odd terms change sign), each odd
    // term at its own sign made worse by the margin.
    Some(
        positive_by_quadratic_factor(
            a[4] - m * e[4],
            (m * e[3] - a[3]).max(0.0),
            a[2] - m * e[2],
            (m * e[1] - a[1]).max(0.0),
            a[0] - m * e[0],
        ) && positive_by_quadratic_factor(
            a[4] - m * e[4],
            (m * e[3] + a[3]).max(0.0),
            a[2] - m * e[2],
            (m * e[1] + a[1]).max(0.0),
            a[0] - m * e[0],
        ),
    )
}

/// `v > 0`, false for NaN (a test that fails on NaN).
fn positive(v: f64) -> bool {
    v > 0.0
}

/// Whether `q4 u⁴ - b3 u³ + q2 u² - b1 u + q0 > 0` for every `u >= 0` (`b3, b1 >= 0`), by
/// `q4 u² - b3 u + q2 >= g = q2 - b3² / 4q4` (its least value, at `u = b3 / 2q4 >= 0`): the
/// quartic is at least `g u² - b1 u + q0`, positive when `g, q0 > 0` and `b1² < 4 g q0`.
/// Unlike [`positive_for_u_ge_0`] it pays for the cubic term only at the far well's place,
/// which is what a centre at the near well's floor needs. Each rounded quantity is pushed
/// by 1e-6 of its terms the safe way, far more than its rounding.
fn positive_by_quadratic_factor(q4: f64, b3: f64, q2: f64, b1: f64, q0: f64) -> bool {
    const SLACK: f64 = 1e-6;
    if !(q4 > 0.0 && q0 > 0.0) {
        return false;
    }
    let g = q2 - SLACK * q2.abs() - b3 * b3 / (4.0 * q4) * (1.0 + SLACK);
    g > 0.0 && b1 * b1 * (1.0 + SLACK) < 4.0 * g * q0 * (1.0 - SLACK)
}

/// `p(x0 + s) = Σ a_k s^k` and the same shift of `Σ|p_j| y^j` to `|x0|`, `e`: the Horner
/// error of `c` at `x0 + s` is below a tiny multiple of `Σ e_k |s|^k`, and the rounding of
/// `a_k` below 2^-50 of `e_k` (`|a_k| <= e_k`). `None` when they overflow.
fn shifted(p: &[f64; 5], x0: f64) -> Option<([f64; 5], [f64; 5])> {
    let ax = x0.abs();
    let mut a = *p;
    let mut e = p.map(f64::abs);
    for i in 0..4 {
        for j in (i..4).rev() {
            a[j] += x0 * a[j + 1];
            e[j] += ax * e[j + 1];
        }
    }
    e.iter().all(|v| v.is_finite()).then_some((a, e))
}

/// Whether `q4 u⁴ - b3 u³ + q2 u² - b1 u + q0 > 0` for every `u >= 0` (`b3, b1 >= 0`), by a
/// sum of squares: `u³ <= (ε u⁴ + u² / ε) / 2` with `ε = q4 / b3` leaves at least
/// `r4 u⁴ + r2 u² - b1 u + q0` (`r4 = q4 / 2`, `r2 = q2 - b3² / 2q4`), which is
/// `r4 (u² - w)² + y u² - b1 u + z` with `y = r2 + 2 r4 w`, `z = q0 - r4 w²` for any `w`
/// (the best `w` solves `3 r4 w² + r2 w - q0 = 0`), positive when `y, z > 0` and
/// `b1² < 4 y z`. Each rounded quantity is pushed by 1e-6 of its terms the safe way, far
/// more than its rounding.
fn positive_for_u_ge_0(q4: f64, b3: f64, q2: f64, b1: f64, q0: f64) -> bool {
    const SLACK: f64 = 1e-6;
    if !(q4 > 0.0 && q0 > 0.0) {
        return false;
    }
    let r4 = 0.5 * q4 * (1.0 - SLACK);
    let cubic = b3 * b3 / (2.0 * q4) * (1.0 + SLACK);
    let r2 = q2 - SLACK * q2.abs() - cubic;
    let w = ((r2 * r2 + 12.0 * r4 * q0).sqrt() - r2) / (6.0 * r4);
    let (yw, zw) = (2.0 * r4 * w, r4 * w * w);
    let y = r2 + yw - SLACK * (r2.abs() + yw.abs());
    let z = q0 - zw - SLACK * (q0 + zw);
    y > 0.0 && z > 0.0 && b1 * b1 * (1.0 + SLACK) < 4.0 * y * z * (1.0 - SLACK)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::poly::{eval, roots_in_isolated, sturm_roots_in};
    use crate::geom::test_rng::{from_roots, Lcg};

    /// Where the certificate holds, the root finders find nothing on the interval, and every
    /// evaluation on a fine grid of it has one sign: random quartics
    /// with real roots (some behind the interval's start), complex pairs near and far from
    /// the axis, values grazing zero, on intervals starting anywhere.
    #[test]
    fn definite_quartics_have_no_roots() {
        let mut rng = Lcg(41);
        let mut certified = 0;
        for case in 0..60_000 {
            let re = |r: &mut Lcg| r.next() * 20.0 - 5.0;
            // ((x - m1)² + w1²)((x - m2)² + w2²), or real roots, or shifted by a hair.
            let (m1, m2) = (re(&mut rng), re(&mut rng));
            let w1 = rng.next() * rng.next() * 4.0;
            let w2 = rng.next() * rng.next() * 4.0;
            let pair = |m: f64, w: f64| [m * m + w * w, -2.0 * m, 1.0];
            let (p1, p2) = (pair(m1, w1), pair(m2, w2));
            let mut c = [0.0; 5];
            for i in 0..3 {
                for j in 0..3 {
                    c[i + j] += p1[i] * p2[j];
                }
            }
            if case % 4 == 1 {
                let roots = [re(&mut rng), re(&mut rng), re(&mut rng), re(&mut rng)];
                c = from_roots(&roots).try_into().unwrap();
            }
            if case % 4 == 2 {
                c[0] -= (w1 * w2).powi(2) * (1.0 - 1e-9 * rng.next());
            }
            let k = (rng.next() - 0.5) * 10f64.powi((rng.next() * 12.0) as i32 - 6);
            let c = c.map(|v| v * k);
            let lo = rng.next() * 24.0 - 8.0;
            let hi = lo + 10f64.powf(rng.next() * 6.0 - 2.0);
            if !surely_definite_quartic(&c, lo, hi) {
                continue;
            }
            certified += 1;
            assert!(roots_in_isolated(&c, lo, hi).is_empty(), "{c:?} {lo} {hi}");
            assert!(sturm_roots_in(&c, lo, hi).is_empty(), "{c:?} {lo} {hi}");
            let positive = eval(&c, lo) > 0.0;
            for i in 0..=400 {
                let x = lo + (hi - lo) * (i as f64 + rng.next()) / 401.0;
                let v = eval(&c, x);
                assert!(v != 0.0 && (v > 0.0) == positive, "{c:?} at {x}: {v}");
            }
        }
        assert!(certified > 20_000, "{certified}");
    }

    /// `k` times the quartic with complex root pairs `m1 ± w1 i` and `m2 ± w2 i`, lowest
    /// coefficient first (a product by `k = 1` is exact).
    fn two_wells(m1: f64, w1: f64, m2: f64, w2: f64, k: f64) -> [f64; 5] {
        let (p1, p2) = (
            [m1 * m1 + w1 * w1, -2.0 * m1, 1.0],
            [m2 * m2 + w2 * w2, -2.0 * m2, 1.0],
        );
        let mut c = [0.0; 5];
        for i in 0..3 {
            for j in 0..3 {
                c[i + j] += p1[i] * p2[j] * k;
            }
        }
        c
    }

    /// Two wells of different depth (quarcyl's misses: complex roots near 3.5 ± 0.4i and
    /// 273 ± 14i, the interval from near 0 to Cauchy's bound) are certified by the expansion
    /// at the near well, and every evaluation on a grid has the leading sign; moving the
    /// near pair onto the axis (a double root, then two real roots) is not certified.
    #[test]
    fn two_wells_of_different_depth() {
        let quartic = two_wells;
        let mut rng = Lcg(7);
        let mut certified = 0;
        for case in 0..4000 {
            let m1 = 1.0 + rng.next() * 6.0;
            let w1 = 0.05 + rng.next() * 0.8;
            let m2 = 50.0 + rng.next() * 400.0;
            let w2 = rng.next() * 30.0;
            let k = if case % 2 == 0 { 1e-4 } else { -3.0 };
            let c = quartic(m1, w1, m2, w2, k);
            let hi = 1.0 + c[..4].iter().fold(0.0f64, |b, v| b.max(v.abs())) / c[4].abs();
            let lo = rng.next() * 0.5;
            if !surely_definite_quartic(&c, lo, hi) {
                continue;
            }
            certified += 1;
            assert!(roots_in_isolated(&c, lo, hi).is_empty(), "{c:?} {lo} {hi}");
            let positive = c[4] > 0.0;
            for i in 0..=2000 {
                let x = lo + (m1 + 2.0 - lo) * (i as f64 + rng.next()) / 2001.0;
                let v = eval(&c, x);
                assert!(v != 0.0 && (v > 0.0) == positive, "{c:?} at {x}: {v}");
            }
        }
        assert!(certified > 3000, "{certified}");
        let c = quartic(3.5, 0.4, 273.0, 14.0, 1.0);
        assert!(surely_definite_quartic(&c, 0.01, 1e4));
        assert!(!surely_definite_quartic(
            &quartic(3.5, 0.0, 273.0, 14.0, 1.0),
            0.01,
            1e4
        ));
        let real: [f64; 5] = from_roots(&[3.4, 3.6, 273.0, 274.0]).try_into().unwrap();
        assert!(!surely_definite_quartic(&real, 0.01, 1e4));
    }

    /// The far (or single) well's expansion: random quartics with two wells of any depth and
    /// spacing, or one well (the wells merged), each certified at the far well's centre has
    /// no root on its interval and the leading sign at
    /// every evaluation of a grid over the interval and around both wells; the far well's
    /// centre must certify cases whose near well's does not.
    #[test]
    fn far_and_single_wells_hold() {
        let mut rng = Lcg(1234);
        let (mut certified, mut far_only) = (0, 0);
        for case in 0..20_000 {
            let m1 = rng.next() * 8.0 - 1.0;
            let w1 = 0.01 + rng.next() * rng.next() * 2.0;
            let m2 = if case % 3 == 0 {
                m1 + rng.next() * 0.5
            } else {
                m1 + 10f64.powf(rng.next() * 3.0)
            };
            let w2 = rng.next() * rng.next() * 40.0;
            let mut c = two_wells(m1, w1, m2, w2, 1.0);
            if case % 5 == 4 {
                // Grazing: the near well lowered to (nearly) touch the axis, or through it.
                c[0] -= (w1 * w1) * (m2 - m1).powi(2) * (1.0 - 1e-3 * rng.next());
            }
            let k = (rng.next() - 0.5) * 10f64.powi((rng.next() * 8.0) as i32 - 4);
            let c = c.map(|v| v * k);
            let p = if c[4] > 0.0 { c } else { c.map(|v| -v) };
            let x0 = -p[3] / (4.0 * p[4]);
            let Some((a, _)) = shifted(&p, x0) else {
                continue;
            };
            let lo = rng.next() * 0.5;
            let hi = 1.0 + c[..4].iter().fold(0.0f64, |b, v| b.max(v.abs())) / c[4].abs();
            let d = [p[1], 2.0 * p[2], 3.0 * p[3], 4.0 * p[4]];
            let half = (-a[2] / (2.0 * p[4])).max(0.0).sqrt();
            let far = positive_at_well(&p, &d, (x0 + half).max(lo), FAR_STEPS, f64::INFINITY);
            if far != Some(true) {
                continue;
            }
            certified += 1;
            // The whole test answers yes whenever the far well's centre does.
            assert!(positive_around_a_well(&c, lo, x0, [a[0], a[1], a[2]]));
            let two = -8.0 * a[2] * a[2] * a[2] - 27.0 * p[4] * a[1] * a[1] > 0.0;
            let near =
                two && positive_at_well(&p, &d, (x0 - half).max(lo), WELL_STEPS, x0) == Some(true);
            if !near {
                far_only += 1;
            }
            assert!(roots_in_isolated(&c, lo, hi).is_empty(), "{c:?} {lo} {hi}");
            assert!(sturm_roots_in(&c, lo, hi).is_empty(), "{c:?} {lo} {hi}");
            let positive = c[4] > 0.0;
            for (from, to) in [
                (lo, hi),
                (m1 - 3.0 * w1, m1 + 3.0 * w1),
                (m2 - 3.0 * w2, m2 + 3.0 * w2),
            ] {
                for i in 0..=600 {
                    let x = from + (to - from) * (i as f64 + rng.next()) / 601.0;
                    let v = eval(&c, x);
                    assert!(v != 0.0 && (v > 0.0) == positive, "{c:?} at {x}: {v}");
                }
            }
        }
        assert!(
            certified > 8_000 && far_only > 2_000,
            "{certified} {far_only}"
        );
    }

    #[test]
    fn certifies_clear_cases_only() {
        // (x² + 1)(x² + 4) and its negation hold; a double root, real roots ahead and NaN do
        // not; real roots behind the interval do.
        assert!(surely_definite_quartic(
            &[4.0, 0.0, 5.0, 0.0, 1.0],
            -1e6,
            1e6
        ));
        assert!(surely_definite_quartic(
            &[-4.0, 0.0, -5.0, 0.0, -1.0],
            0.0,
            1e6
        ));
        let square: [f64; 5] = from_roots(&[1.0, 1.0, 2.0, 2.0]).try_into().unwrap();
        assert!(!surely_definite_quartic(&square, 0.0, 1e6));
        let real: [f64; 5] = from_roots(&[1.0, 2.0, 3.0, 4.0]).try_into().unwrap();
        assert!(!surely_definite_quartic(&real, 0.0, 1e6));
        assert!(surely_definite_quartic(&real, 4.5, 1e6));
        assert!(!surely_definite_quartic(&real, 3.5, 1e6));
        let nan = [4.0, 0.0, f64::NAN, 0.0, 1.0];
        assert!(!surely_definite_quartic(&nan, 0.0, 1e6));
        assert!(!surely_definite_quartic(
            &[4.0, 0.0, 5.0, 0.0, 1e300],
            0.0,
            1e6
        ));
    }
}
