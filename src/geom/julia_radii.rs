//! The radii a quaternion julia set is bounded by, for `Julia::new`: those under which an orbit
//! is sure to stay inside for its last iterations (`keep_radii`), the ball every inside point
//! lies in (`inner_radius`; `hyper_inner_radius` for hypercomplex sqr and cube), and the
//! squared norms their comparisons take (`sqrt_threshold`).

use super::KEEP;

/// The radii under which a quaternion orbit is sure to stay inside for `j` more iterations.
///
/// The quaternion norm is multiplicative, so |h^p + c| <= |h|^p + |c|: from |h| <= R_j the
/// next iterate is within R_{j−1} when R_j^p + |c| <= R_{j−1}, and R_0 is the bailout. Each
/// radius is shrunk by 1e-9 (relative) and |c| grown by 1e-12, which covers the iteration's
/// roundings (a few units of 1e-16 of |h|^p + |c|, all below 2 + 8 here) and those of the
/// computed norm the orbit compares (its square root, or the squared norm against
/// `keep_sq`), so the computed iterates stay at or below `bail_sq` and the orbit would have
/// ended `Inside`: leaving those iterations out changes no answer. A radius whose
/// predecessor is within 1e-6 of |c| is not used.
pub(super) fn keep_radii(bailout: f64, c_norm: f64, cube: bool) -> ([f64; KEEP], [f64; KEEP]) {
    let mut keep = [-1.0; KEEP];
    let mut keep_sq = [-1.0; KEEP];
    let c = c_norm * (1.0 + 1e-12);
    let mut prev = bailout * (1.0 - 1e-9);
    for j in 1..KEEP {
        if !(prev.is_finite() && c.is_finite()) || prev - c <= 1e-6 {
            break;
        }
        let room = prev - c;
        let r = if cube { room.cbrt() } else { room.sqrt() } * (1.0 - 1e-9);
        keep[j] = r;
        keep_sq[j] = r * r * (1.0 - 1e-9);
        prev = r;
    }
    (keep, keep_sq)
}

/// The radius of a ball holding every point whose quaternion orbit is called inside after
/// `max_iteration` iterates (h0 and the next `max_iteration − 1`), at most `bailout`.
///
/// The norm is multiplicative, so |h_{k+1}| = |h_k^p + c| >= |h_k|^p − |c|: an iterate within
/// R_{j−1} has a predecessor within R_j = (R_{j−1} + |c|)^(1/p), and the last iterate is within
/// R_0, the bailout. The computed iterates differ from `h^p + c` of their predecessors by a few
/// units of 1e-16 of |h|^p + |c| (and the squared norm compared with `bail_sq` from the norm
/// by as little), so each radius is grown by 1e-9 (relative) and |c| by 1e-12. The lifted point
/// (x, y, z, w) is at least as long as (x, y, z), so a sample whose 3-D point lies outside the
/// last radius is outside.
pub(super) fn inner_radius(bailout: f64, c_norm: f64, cube: bool, max_iteration: u32) -> f64 {
    let c = c_norm * (1.0 + 1e-12);
    let mut rho = bailout * (1.0 + 1e-9);
    for _ in 1..max_iteration {
        let next = (rho + c) * (1.0 + 1e-9);
        let r = if cube { next.cbrt() } else { next.sqrt() } * (1.0 + 1e-9);
        // From here on the radii would grow (a bound the bailout already gives) or are NaN.
        if r >= rho || r.is_nan() {
            break;
        }
        rho = r;
    }
    rho.min(bailout)
}

/// `inner_radius` for a hypercomplex set whose orbit iterates the square (sqr and cube), with
/// parameter halves of norms `c1_norm` and `c2_norm` (`split`).
///
/// The halves z1, z2 of h iterate apart, z ← z² + c_k, and |h|² = (|z1|² + |z2|²)/2 (the
/// orbit compares this `s` with the bailout's square). So |h| > R puts one half beyond R, and
/// once a half is beyond √2·bailout, `s` is beyond the bailout's square. As for quaternions,
/// |z² + c| >= |z|² − |c|: a half beyond R_j = (R_{j−1} + |c|)^(1/2) is beyond R_{j−1} one
/// iterate later, from R_0 = √2·bailout, with the same margins (1e-9 relative a radius, 1e-12
/// on |c|) over the roundings of the split, the iterations and `s`. Before its escape an orbit
/// stays within s <= bailout², so nothing overflows. Each R_j is a radius beyond which the
/// orbit escapes within j iterations; the least of those within `max_iteration − 1` and the
/// bailout (an escape before any iteration) is returned.
pub(super) fn hyper_inner_radius(
    bailout: f64,
    c1_norm: f64,
    c2_norm: f64,
    max_iteration: u32,
) -> f64 {
    let c = c1_norm.max(c2_norm) * (1.0 + 1e-12);
    let mut rho = 2f64.sqrt() * bailout * (1.0 + 1e-9);
    let mut least = bailout;
    for _ in 1..max_iteration {
        let r = ((rho + c) * (1.0 + 1e-9)).sqrt() * (1.0 + 1e-9);
        // From here on the radii would grow, or are NaN.
        if r >= rho || r.is_nan() {
            break;
        }
        rho = r;
        least = least.min(rho);
    }
    least
}

/// The largest non-negative `s` with `s.sqrt() <= b`, found on the bit patterns (ordered as
/// integers for non-negative floats).
pub(super) fn sqrt_threshold(b: f64) -> f64 {
    if b.is_nan() || b < 0.0 {
        return -1.0;
    }
    if b == f64::INFINITY {
        return f64::INFINITY;
    }
    // sqrt(lo) <= b < sqrt(hi) holds throughout.
    let (mut lo, mut hi) = (0u64, f64::INFINITY.to_bits());
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if f64::from_bits(mid).sqrt() <= b {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    f64::from_bits(lo)
}
