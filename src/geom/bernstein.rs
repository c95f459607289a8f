//! Bernstein-basis tests on polynomials: whether a polynomial surely keeps one sign on an
//! interval, which lets root finders skip isolating roots where there are none. The Bernstein
//! coefficients of a polynomial on an interval bound it there (the curve lies in their hull),
//! so they settle its sign far more cheaply than isolating its roots.

use crate::geom::poly::eval;

/// Binomial coefficients C(k, i) up to k = 16 (exact integers), built at compile time.
pub const BINOM: [[f64; 17]; 17] = {
    let mut binom = [[0.0f64; 17]; 17];
    let mut k = 0;
    while k < 17 {
        binom[k][0] = 1.0;
        let mut i = 1;
        while i <= k {
            binom[k][i] = binom[k - 1][i - 1] + if i < k { binom[k - 1][i] } else { 0.0 };
            i += 1;
        }
        k += 1;
    }
    binom
};

/// `BINOM[k][i] / BINOM[n][i]` for degrees `n` up to 8, the weights of the change to the
/// Bernstein basis: the same quotients (IEEE division, at compile time) without a division per
/// term at run time.
pub(crate) const TO_BERNSTEIN: [[[f64; 9]; 9]; 9] = {
    let mut w = [[[0.0f64; 9]; 9]; 9];
    let mut n = 0;
    while n < 9 {
        let mut k = 0;
        while k <= n {
            let mut i = 0;
            while i <= k {
                w[n][k][i] = BINOM[k][i] / BINOM[n][i];
                i += 1;
            }
            k += 1;
        }
        n += 1;
    }
    w
};

/// `surely_no_root`'s first questions, shared with its quartic copy: the values at the ends
/// alike in sign and neither zero, the terms' bound `T` and the width finite. Gives whether the
/// polynomial is positive there, the width `hi - lo` and the margin `1e-11·T`.
#[inline(always)]
fn ends_and_margin(c: &[f64], lo: f64, hi: f64) -> Option<(bool, f64, f64)> {
    let (f_lo, f_hi) = (eval(c, lo), eval(c, hi));
    if (f_lo > 0.0) != (f_hi > 0.0) || f_lo == 0.0 || f_hi == 0.0 {
        return None;
    }
    let w = hi - lo;
    let reach = lo.abs() + w;
    let mut t = 0.0;
    let mut pw = 1.0;
    for &cj in c {
        t += cj.abs() * pw;
        pw *= reach;
    }
    (t.is_finite() && w.is_finite()).then_some((f_lo > 0.0, w, 1e-11 * t))
}

/// Whether the polynomial keeps one sign on `[lo, hi]` by a margin far above every rounding
/// error of evaluating it there, so that `isolate` could find no change of sign and no exact
/// zero: its Bernstein coefficients on the interval (whose hull holds the curve) all exceed,
/// in magnitude and with one sign, 1e-11 of `T = Σ|c_j|(|lo| + (hi - lo))^j`. `T` bounds
/// the sum of the magnitudes of the terms in Horner's evaluation at any point of the interval
/// and in the interval's change of variable, whose rounding errors are a few times
/// `degree · 2^-53 · T` (well below 1e-13 T up to degree 8). Most intervals a ray spends near a
/// blob or quartic hold no crossing, and this is far cheaper than isolating the roots.
pub(crate) fn surely_no_root(c: &[f64], lo: f64, hi: f64) -> bool {
    // As in `poly::polish`: a quartic's test (a blob's stretch, a torus's) and a cubic's
    // compiled with the length known, so the shift's and the sums' loops unroll: the same
    // operations in the same order.
    match c.len() {
        5 => surely_no_root_body(<&[f64; 5]>::try_from(c).unwrap(), lo, hi),
        4 => surely_no_root_body(<&[f64; 4]>::try_from(c).unwrap(), lo, hi),
        _ => surely_no_root_body(c, lo, hi),
    }
}

#[inline(always)]
fn surely_no_root_body(c: &[f64], lo: f64, hi: f64) -> bool {
    let n = c.len().saturating_sub(1);
    if !(3..=8).contains(&n) {
        return false;
    }
    let Some((positive, w, margin)) = ends_and_margin(c, lo, hi) else {
        return false;
    };
    // q(u) = p(lo + w u): a Taylor shift to `lo` (repeated synthetic division), then scaling.
    let mut q = [0.0f64; 9];
    q[..=n].copy_from_slice(c);
    for i in 0..n {
        for j in (i..n).rev() {
            q[j] += lo * q[j + 1];
        }
    }
    let mut scale = 1.0;
    for qi in q[..=n].iter_mut() {
        *qi *= scale;
        scale *= w;
    }
    // Bernstein coefficients b_k = Σ_{i ≤ k} C(k, i) / C(n, i) · q_i.
    let w = &TO_BERNSTEIN[n];
    (0..=n).all(|k| {
        let b: f64 = (0..=k).map(|i| w[k][i] * q[i]).sum();
        if positive {
            b > margin
        } else {
            b < -margin
        }
    })
}

/// [`surely_no_root`] for a quartic on `[0, hi]` (a torus's interval, whose variable starts
/// where the ray enters the bounds), written out: the same answer for every input. With
/// `lo = 0` the Taylor shift adds `0·q` terms, which leave each `q_j` as it is (or turn a -0
/// into +0: a zero's sign cannot take a sum across the margin), and every coefficient is
/// finite past the check of `t`; the remaining operations are `surely_no_root`'s, in its
/// order.
#[inline]
pub(crate) fn surely_no_root_quartic_from_zero(c: &[f64; 5], hi: f64) -> bool {
    let Some((positive, w, margin)) = ends_and_margin(c, 0.0, hi) else {
        return false;
    };
    let q0 = c[0];
    let q1 = c[1] * w;
    let w2 = w * w;
    let q2 = c[2] * w2;
    let w3 = w2 * w;
    let q3 = c[3] * w3;
    let q4 = c[4] * (w3 * w);
    let b = &TO_BERNSTEIN[4];
    // `q0` is `1·q0` (the first weight of every row is 1): b_0 = q0 = f(0), whose sign was
    // checked above by the same value.
    let sums = [
        q0,
        b[1][0] * q0 + b[1][1] * q1,
        b[2][0] * q0 + b[2][1] * q1 + b[2][2] * q2,
        b[3][0] * q0 + b[3][1] * q1 + b[3][2] * q2 + b[3][3] * q3,
        b[4][0] * q0 + b[4][1] * q1 + b[4][2] * q2 + b[4][3] * q3 + b[4][4] * q4,
    ];
    if positive {
        sums.iter().all(|&s| s > margin)
    } else {
        sums.iter().all(|&s| s < -margin)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::test_rng::from_roots;

    /// `roots_in` with the shortcut off: the roots `isolate` finds.
    fn roots_in_no_shortcut(c: &[f64], lo: f64, hi: f64) -> Vec<f64> {
        crate::geom::poly::roots_in_isolated(c, lo, hi).to_vec()
    }

    /// The Bernstein shortcut never hides a root `isolate` would find: random polynomials of
    /// degree 3 to 8, many of them grazing zero (a tiny constant shift), on random intervals.
    #[test]
    fn no_root_test_never_hides_a_root() {
        let mut rng = crate::geom::test_rng::Lcg(23);
        let mut skipped = 0;
        for case in 0..100_000 {
            let deg = 3 + case % 6;
            let roots: Vec<f64> = (0..deg).map(|_| rng.next() * 6.0 - 3.0).collect();
            let mut c = from_roots(&roots);
            let k = rng.next();
            c[0] += if case % 2 == 0 {
                k * 1e-12
            } else {
                k * 40.0 - 20.0
            };
            let lo = rng.next() * 8.0 - 4.0;
            let hi = lo + rng.next() * rng.next() * 6.0;
            if surely_no_root(&c, lo, hi) {
                skipped += 1;
                let out = roots_in_no_shortcut(&c, lo, hi);
                assert!(out.is_empty(), "{c:?} {lo} {hi} {out:?}");
            }
        }
        assert!(skipped > 10_000, "{skipped}");
    }

    /// The written-out quartic certificate on [0, hi] answers as `surely_no_root` does:
    /// random quartics (near-double roots among them), tori's own, and special values.
    #[test]
    fn quartic_from_zero_is_surely_no_root() {
        let mut rng = crate::geom::test_rng::Lcg(41);
        let specials = [0.0, -0.0, 1e-300, -1e-300, f64::INFINITY, f64::NAN, 1e300];
        let (mut yes, mut total) = (0, 0);
        for case in 0..200_000 {
            let roots: Vec<f64> = (0..4).map(|_| rng.next() * 4.0 - 1.0).collect();
            let mut c: [f64; 5] = from_roots(&roots).try_into().unwrap();
            let k = rng.next();
            c[0] += match case % 3 {
                0 => k * 1e-12,
                1 => k * 10.0 - 2.0,
                _ => k * k * 100.0,
            };
            let mut hi = rng.next() * rng.next() * 3.0;
            if case % 97 == 0 {
                c[(case / 97) % 5] = specials[(case / 485) % specials.len()];
            }
            if case % 89 == 0 {
                hi = specials[(case / 89) % specials.len()];
            }
            let want = surely_no_root(&c, 0.0, hi);
            assert_eq!(surely_no_root_quartic_from_zero(&c, hi), want, "{c:?} {hi}");
            yes += usize::from(want);
            total += 1;
        }
        assert!(yes > total / 10 && yes < total * 9 / 10, "{yes} of {total}");
    }

    /// The table holds the quotients computed at run time, bit for bit.
    #[test]
    fn weights_are_the_quotients() {
        for n in 0..9 {
            for k in 0..=n {
                for i in 0..=k {
                    let q = std::hint::black_box(BINOM[k][i]) / std::hint::black_box(BINOM[n][i]);
                    assert_eq!(TO_BERNSTEIN[n][k][i].to_bits(), q.to_bits());
                }
            }
        }
    }
}
