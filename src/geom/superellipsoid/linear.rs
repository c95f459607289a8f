//! The field near a point whose powers are known, to first order, with a proven bound: the
//! refinement's cheapest estimate of a midpoint's value (`refine` asks it before `near`).
//!
//! With `m` and `n` the larger and smaller of |x| and |y|, the field is
//! `F = m^c·(1 + (n/m)^a)^b + |z|^c − 1`. Near a reference point (its powers exact, glibc's
//! bits) each coordinate moves by a relative `d` (`d_m`, `d_n`, `d_z`), and
//! `F ≈ F_r + α_m d_m + α_n d_n + α_z d_z` with `α_m = MG (c − a b w)`, `α_n = MG a b w`,
//! `α_z = c Z` (`MG = m^c (1 + r^a)^b`, `Z = |z|^c`, `w = r^a / (1 + r^a)`, all at the
//! reference). Where every |d| is at most `D <= dmax` the error is below
//! `E0 + E1·D + Q·D²`:
//!
//! * `Q·D²` the second-order remainder. Each power `(1 + d)^k = 1 + k d + ρ` with
//!   `|ρ| <= 2|C(k, 2)| d²` where `(|k| + 1)|d| <= 1/2` (the series' terms then shrink by half
//!   at least from the third on). The ratio's relative move is
//!   `(1 + d_n)/(1 + d_m) − 1 = (d_n − d_m) + ε_r`, `|ε_r| <= 2D²/(1 − D)`; through `r^a`,
//!   `1 + r^a` (`w` times the relative move of `r^a`, at most `β D`) and `^b` this gives
//!   `G/G_r = 1 + b w a (d_n − d_m) + g2` with `|g2| <= D² (|b|(2.01|a| + 8.1|C(a, 2)|) +
//!   2|C(b, 2)| β²)`, and the product `M G` adds the cross terms (`Lin::new`'s `q_mg`).
//! * `E0` the roundings of the two exact evaluations (glibc's `pow` under one unit in the last
//!   place, the ratio, the sums; amplified by `|a|` and `|b|` through `r^a` and `^b`) and of
//!   the model's own sum, generously (four times their first-order size).
//! * `E1·D` the roundings of the coefficients (from rounded powers, with a cancellation in
//!   `α_m`) and of each `d`.
//!
//! The estimate never replaces an exact value the refinement needs (module `near`): it only
//! gives a midpoint's sign where `|F| > bound`, and an interval for the ratio test. Where it
//! cannot (a move beyond `dmax`, a zero coordinate at the reference, a value within the bound)
//! `near`'s series decide as before.

use super::Superellipsoid;
use crate::math::DVec3;

/// The per-shape constants of the bound (exponents only).
#[derive(Clone, Copy, Debug)]
pub(super) struct LinConsts {
    /// Largest relative move of a coordinate the model is used for.
    dmax: f64,
    /// `Q = q_mg·MG + q_z·Z`.
    q_mg: f64,
    q_z: f64,
    /// `E0 = e0_mg·MG + e0_z·Z + e0_1·(1 + |F_r|)`.
    e0_mg: f64,
    e0_z: f64,
    /// `E1 = e1·(MG·(|c| + 2|a b| w) + |c| Z)`.
    e1: f64,
}

/// |C(k, 2)| = |k (k − 1) / 2|.
fn c2(k: f64) -> f64 {
    (k * (k - 1.0) * 0.5).abs()
}

impl LinConsts {
    pub(super) fn new(a: f64, b: f64, c: f64) -> LinConsts {
        let (aa, ba, ca) = (a.abs(), b.abs(), c.abs());
        // β bounds |d_B| / D (the relative move of 1 + r^a) at D <= 1e-3; smaller D give a
        // smaller β, so the conditions below, checked with it, hold for every D up to dmax.
        let beta = 2.0 * aa + (2.01 * aa + 8.1 * c2(a)) * 1e-3;
        let dmax = [
            1e-3,
            // (|a| + 1)·|d_r| <= 1/2 with |d_r| <= 2.01 D
            0.5 / ((aa + 1.0) * 2.01),
            // (|b| + 1)·β D <= 1/2
            0.5 / ((ba + 1.0) * beta.max(1e-300)),
            // (|c| + 1)·D <= 1/2
            0.5 / (ca + 1.0),
        ]
        .into_iter()
        .fold(f64::INFINITY, f64::min);
        let gamma = ba * beta + 2.0 * c2(b) * beta * beta * dmax;
        let q_mg = 2.0 * c2(c)
            + ba * (2.01 * aa + 8.1 * c2(a))
            + 2.0 * c2(b) * beta * beta
            + (ca + 2.0 * c2(c) * dmax) * gamma;
        // Units of 1e-16 per exact evaluation: m^c 2.3, r 1.2 carried by a, r^a 2.3, the sum
        // 1 + r^a 1.2, all carried by b, (·)^b 2.3, the product 1.2, |z|^c 2.3, the two sums
        // 1.2 each; two evaluations, times four.
        let e0_mg = (2.3 + 1.2 + ba * (1.2 * aa + 2.3 + 1.2) + 2.3 + 1.2 + 1.2) * 1e-16 * 8.0;
        let e0_z = (2.3 + 1.2) * 1e-16 * 8.0;
        LinConsts {
            dmax,
            q_mg: q_mg * 1.05,
            q_z: 2.0 * c2(c) * 1.05,
            e0_mg,
            e0_z,
            e1: 1e-14 + (aa + 1.0) * (ba + 1.0) * 1e-15,
        }
    }
}

/// The first-order model at one reference point.
#[derive(Clone, Copy, Debug)]
pub(super) struct Lin {
    m: f64,
    inv_m: f64,
    n: f64,
    inv_n: f64,
    z: f64,
    inv_z: f64,
    v: f64,
    am: f64,
    an: f64,
    az: f64,
    e0: f64,
    e1: f64,
    q: f64,
    dmax: f64,
}

impl Lin {
    /// The model at a point the exact path evaluated: its max/min of |x|, |y| and their
    /// reciprocals, |z|, the powers `mc = m^c`, `ra = r^a`, `g = (1 + ra)^b`, `zc = |z|^c`
    /// and the value `v`.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn new(
        se: &Superellipsoid,
        (m, inv_m): (f64, f64),
        n: f64,
        (z, inv_z): (f64, f64),
        (mc, ra, g, zc): (f64, f64, f64, f64),
        v: f64,
    ) -> Lin {
        let k = &se.lin;
        let (a, b, c) = (se.a.exponent(), se.b.exponent(), se.c.exponent());
        let mg = mc * g;
        let w = ra / (1.0 + ra);
        let abw = a * b * w;
        Lin {
            m,
            inv_m,
            n,
            inv_n: 1.0 / n,
            z,
            inv_z,
            v,
            am: mg * (c - abw),
            an: mg * abw,
            az: c * zc,
            e0: k.e0_mg * mg + k.e0_z * zc + 8e-16 * (1.0 + v.abs()),
            e1: k.e1 * (mg * (c.abs() + 2.0 * abw.abs()) + c.abs() * zc),
            q: k.q_mg * mg + k.q_z * zc,
            dmax: k.dmax,
        }
    }

    /// The field at `p` and a bound on its distance from `value(p)`, when the bound is below
    /// the value's size (so the sign is `value`'s); None otherwise.
    #[inline(always)]
    pub(super) fn at(&self, p: DVec3) -> Option<(f64, f64)> {
        self.bounded(p)
            .filter(|&(v, err)| v.abs() > err && v.abs() < 1e300)
    }

    /// The model's value at `p` and its bound, where `p` is within its reach.
    // Negated comparisons: a NaN must say None.
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    #[inline(always)]
    fn bounded(&self, p: DVec3) -> Option<(f64, f64)> {
        let (x, y, z) = (p.x.abs(), p.y.abs(), p.z.abs());
        let (m, n) = (x.max(y), x.min(y));
        // Each difference is exact (Sterbenz) where its d is within dmax <= 1e-3.
        let dm = (m - self.m) * self.inv_m;
        let dn = (n - self.n) * self.inv_n;
        let dz = (z - self.z) * self.inv_z;
        let big = dm.abs().max(dn.abs()).max(dz.abs());
        if !(dm.abs() <= self.dmax && dn.abs() <= self.dmax && dz.abs() <= self.dmax) {
            return None;
        }
        let v = self.v + (self.am * dm + self.an * dn + self.az * dz);
        let err = self.e0 + big * (self.e1 + big * self.q);
        Some((v, err))
    }
}

#[cfg(test)]
mod tests {
    use super::super::near::tests::{on_surface, rng, SHAPES};
    use super::*;

    /// The model is within its bound of `value`, from references on and off the surface and
    /// relative moves from 1e-15 to past `dmax`; with offsets up to 1e-6 (most of the
    /// refinement's midpoints) it is used and decides most signs.
    #[test]
    fn linear_values_are_within_their_bound() {
        let mut next = rng(0x5851_f42d_4c95_7f2d);
        let (mut used, mut decided, mut worst) = (0, 0, 0.0f64);
        for (e, n) in SHAPES {
            let s = Superellipsoid::new(e, n);
            for i in 0..40_000 {
                let dir = DVec3::new(next(), next(), next()) * 2.0 - DVec3::ONE;
                let p0 = if i % 4 == 0 { dir } else { on_surface(&s, dir) };
                let (_, pw) = s.value_powers(p0);
                let Some(pw) = pw else { continue };
                let lin = pw.lin(&s);
                let step = 10f64.powf(-2.0 - 13.0 * next());
                // Along a line through the reference, as the refinement's midpoints lie.
                let off = (DVec3::new(next(), next(), next()) * 2.0 - DVec3::ONE) * step;
                let p = p0 + off;
                let exact = s.value(p);
                if let Some((v, err)) = lin.bounded(p) {
                    used += 1;
                    let miss = (v - exact).abs();
                    assert!(miss <= err, "{e} {n} {p0} {p}: {v} {exact} {err}");
                    worst = worst.max(miss / err);
                    if lin.at(p).is_some() {
                        assert_eq!(v < 0.0, exact < 0.0);
                        decided += 1;
                    }
                }
            }
        }
        assert!(used > 200_000 && decided > 150_000, "{used} {decided}");
        assert!(worst < 0.5, "{worst}");
    }
}
