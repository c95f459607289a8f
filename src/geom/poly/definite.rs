//! A certificate that a quartic keeps one sign along the whole ray, by a margin far above
//! rounding, so that a ray missing a quartic surface by a clear margin is answered without
//! isolating any root (most rays near a `quartic` miss it, and their isolation polishes a
//! critical point from a bracket reaching Cauchy's bound: twenty Newton steps).
//!
//! The root finders here decide everything from the signs of Horner evaluations: a change of
//! sign between two points, or an exact zero. Where every evaluation in the search interval
//! has the leading coefficient's sign, [`roots_in`](super::roots_in) and its variants find
//! nothing, whatever points they evaluate at; and [`sturm_roots_in`](super::sturm_roots_in)
//! adds a root only where the polynomial is zero to within its rounding error. So the answer
//! "no root" is theirs to the bit.

/// Relative margin, against the size of the terms, that the polynomial's value must keep
/// everywhere: Horner's rounding error on a quartic is below `8 · 2^-53` of that size, and
/// the rounding of the Taylor shift below is of the same order, both far below this.
const MARGIN: f64 = 1e-11;

/// Whether every Horner evaluation of the quartic `c` (ascending, `c[4] != 0`) at a point `x`
/// with `|x| <= reach` is nonzero and has the sign of `c[4]`.
///
/// With `p = ±c` (leading coefficient positive) shifted to `x0 = -p3 / (4 p4)` (where the
/// cubic term nearly vanishes), `p(x0 + s) = Σ a_k s^k`; the Horner error at `x` is below a
/// tiny multiple of `Σ|c_j| |x|^j <= Σ e_k |s|^k`, the same shift of `Σ|c_j| y^j` to `|x0|`.
/// So it suffices that `Q4 u⁴ - B3 u³ + Q2 u² - B1 u + Q0 > 0` for every `u >= 0`, with the
/// even coefficients lowered and the odd ones raised by `MARGIN` of the `e_k` (and the odd
/// ones taken with their worst sign). Splitting `Q2 = X + Y` with `X = B3² / 4Q4`, the
/// quartic part `u²(Q4 u² - B3 u + X)` is never negative and the quadratic `Y u² - B1 u + Q0`
/// is positive when `B1² < 4 Y Q0`.
pub fn surely_definite_quartic(c: &[f64; 5], reach: f64) -> bool {
    // No overflow in any evaluation within reach (Horner's partial sums stay below `T`).
    let t = (((c[4].abs() * reach + c[3].abs()) * reach + c[2].abs()) * reach + c[1].abs()) * reach
        + c[0].abs();
    if !(t * 4.0).is_finite() {
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
    let ax = x0.abs();
    let mut a = p;
    let mut e = p.map(f64::abs);
    for i in 0..4 {
        for j in (i..4).rev() {
            a[j] += x0 * a[j + 1];
            e[j] += ax * e[j + 1];
        }
    }
    // The margins doubled: the rounding of these few operations (below 2^-52 of `e_k`, as
    // `|a_k| <= e_k`) is then covered as well.
    let m = 2.0 * MARGIN;
    let q4 = a[4] - m * e[4];
    let b3 = a[3].abs() + m * e[3];
    let q2 = a[2] - m * e[2];
    let b1 = a[1].abs() + m * e[1];
    let q0 = a[0] - m * e[0];
    // The products and quotients below round by a few ulps; the factors 1 ± 1e-6 cover that
    // (a ray this close to the bound is simply solved).
    const UP: f64 = 1.0 + 1e-6;
    const DOWN: f64 = 1.0 - 1e-6;
    if !(q4 > 0.0 && q2 > 0.0 && q0 > 0.0 && e.iter().all(|v| v.is_finite())) {
        return false;
    }
    let x = b3 * b3 / (4.0 * q4) * UP;
    let y = q2 * DOWN - x;
    y > 0.0 && b1 * b1 * UP < 4.0 * y * q0 * DOWN
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::poly::{roots_in_isolated, sturm_roots_in};
    use crate::geom::test_rng::{from_roots, Lcg};

    /// Where the certificate holds, the root finders find nothing, and every evaluation on a
    /// fine grid within reach has the leading coefficient's sign: random quartics with real
    /// roots, complex pairs near and far from the axis, and values grazing zero.
    #[test]
    fn definite_quartics_have_no_roots() {
        let mut rng = Lcg(41);
        let mut certified = 0;
        for case in 0..60_000 {
            let re = |r: &mut Lcg| r.next() * 20.0 - 5.0;
            // (x - r1)(x - r2)((x - m)² + w²)·k, or two complex pairs, or shifted by a hair.
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
                c = from_roots(&[re(&mut rng), re(&mut rng), re(&mut rng), re(&mut rng)])
                    .try_into()
                    .unwrap();
            }
            if case % 4 == 2 {
                c[0] -= (w1 * w2).powi(2) * (1.0 - 1e-9 * rng.next());
            }
            let k = (rng.next() - 0.5) * 10f64.powi((rng.next() * 12.0) as i32 - 6);
            let c = c.map(|v| v * k);
            let reach = 1e3;
            if !surely_definite_quartic(&c, reach) {
                continue;
            }
            certified += 1;
            assert!(roots_in_isolated(&c, -reach, reach).is_empty(), "{c:?}");
            assert!(sturm_roots_in(&c, -reach, reach).is_empty(), "{c:?}");
            let positive = c[4] > 0.0;
            for i in 0..=400 {
                let x = -30.0 + 0.15 * i as f64 + 1e-3 * rng.next();
                let v = crate::geom::poly::eval(&c, x);
                assert!(v != 0.0 && (v > 0.0) == positive, "{c:?} at {x}: {v}");
            }
        }
        assert!(certified > 4_000, "{certified}");
    }

    #[test]
    fn certifies_clear_cases_only() {
        // (x² + 1)(x² + 4) and its negation hold; a double root, real roots and NaN do not.
        assert!(surely_definite_quartic(&[4.0, 0.0, 5.0, 0.0, 1.0], 1e6));
        assert!(surely_definite_quartic(&[-4.0, 0.0, -5.0, 0.0, -1.0], 1e6));
        let square: [f64; 5] = from_roots(&[1.0, 1.0, 2.0, 2.0]).try_into().unwrap();
        assert!(!surely_definite_quartic(&square, 1e6));
        let real: [f64; 5] = from_roots(&[1.0, 2.0, 3.0, 4.0]).try_into().unwrap();
        assert!(!surely_definite_quartic(&real, 1e6));
        assert!(!surely_definite_quartic(
            &[4.0, 0.0, f64::NAN, 0.0, 1.0],
            1e6
        ));
        assert!(!surely_definite_quartic(&[4.0, 0.0, 5.0, 0.0, 1e300], 1e6));
    }
}
