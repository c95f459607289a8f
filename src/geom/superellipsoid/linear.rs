//! The field near a point whose powers are known, to first order, with a proven bound: the
//! refinement's cheapest estimate of a midpoint's value (`refine` asks it, carried along its
//! ray as `Line`, before `near`).
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
//!   `G/G_r = 1 + b w a (d_n − d_m) + g2` with `|g2| <= D² (|b|(2.03|a| + 8.25|C(a, 2)|) +
//!   2|C(b, 2)| β²)` (`2/(1 − D) <= 2.03` and `(2.03)² · 2 <= 8.25` for `D <= D_CAP`), and
//!   the product `M G` adds the cross terms (`Lin::new`'s `q_mg`).
//! * `E0` the roundings of the two exact evaluations (glibc's `pow` under one unit in the last
//!   place, the ratio, the sums; amplified by `|a|` and `|b|` through `r^a` and `^b`) and of
//!   the model's own sum, generously (four times their first-order size).
//! * `E1·D` the roundings of the coefficients (from rounded powers, with a cancellation in
//!   `α_m`) and of each `d`.
//!
//! The estimate never replaces an exact value the refinement needs (module `near`): it only
//! gives a midpoint's sign where `|F| > bound`, and an interval for the ratio test. Where it
//! cannot (a move beyond `dmax`, a zero coordinate at the reference, a value within the bound)
//! `near`'s series decide as before. (`Lin::at` itself, the model at an arbitrary point, is
//! asked by the tests only: where `Line` leaves a midpoint, it settled about one in ten for
//! ~60 instructions each, less than the series it spared.)

use super::Superellipsoid;
use crate::math::DVec3;

/// The largest `dmax` of any shape. 1e-2 rather than 1e-3: a bisection run starts with moves
/// of a few 1e-3 from its reference, which the model then left to the series (~255
/// instructions) on ~10 midpoints per crossing (superel2). Every constant below is derived
/// for `D <= D_CAP`; the differences stay exact (Sterbenz) up to a relative move of 1/2.
const D_CAP: f64 = 1e-2;

/// The per-shape constants of the bound (exponents only).
#[derive(Clone, Copy, Debug)]
pub(super) struct LinConsts {
    /// The exponents a, b, c (`Power::exponent`'s values, kept here so the model's build and
    /// `near` read them without a match over `Power`).
    pub(super) a: f64,
    pub(super) b: f64,
    pub(super) c: f64,
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
        // β bounds |d_B| / D (the relative move of 1 + r^a) at D <= D_CAP; smaller D give a
        // smaller β, so the conditions below, checked with it, hold for every D up to dmax.
        let beta = 2.0 * aa + (2.03 * aa + 8.25 * c2(a)) * D_CAP;
        let dmax = [
            D_CAP,
            // (|a| + 1)·|d_r| <= 1/2 with |d_r| <= 2.03 D
            0.5 / ((aa + 1.0) * 2.03),
            // (|b| + 1)·β D <= 1/2
            0.5 / ((ba + 1.0) * beta.max(1e-300)),
            // (|c| + 1)·D <= 1/2
            0.5 / (ca + 1.0),
        ]
        .into_iter()
        .fold(f64::INFINITY, f64::min);
        let gamma = ba * beta + 2.0 * c2(b) * beta * beta * dmax;
        let q_mg = 2.0 * c2(c)
            + ba * (2.03 * aa + 8.25 * c2(a))
            + 2.0 * c2(b) * beta * beta
            + (ca + 2.0 * c2(c) * dmax) * gamma;
        // Units of 1e-16 per exact evaluation: m^c 2.3, r 1.2 carried by a, r^a 2.3, the sum
        // 1 + r^a 1.2, all carried by b, (·)^b 2.3, the product 1.2, |z|^c 2.3, the two sums
        // 1.2 each; two evaluations, times four.
        let e0_mg = (2.3 + 1.2 + ba * (1.2 * aa + 2.3 + 1.2) + 2.3 + 1.2 + 1.2) * 1e-16 * 8.0;
        let e0_z = (2.3 + 1.2) * 1e-16 * 8.0;
        LinConsts {
            a,
            b,
            c,
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
    /// |z| at the reference (only `bounded`, a test check, reads it: `Line` needs the
    /// reciprocal alone).
    #[cfg(test)]
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
    #[inline(always)]
    pub(super) fn new(
        se: &Superellipsoid,
        (m, inv_m): (f64, f64),
        n: f64,
        (z, inv_z): (f64, f64),
        (mc, ra, g, zc): (f64, f64, f64, f64),
        v: f64,
    ) -> Lin {
        // |z| itself is kept for the tests' `bounded` only.
        #[cfg(not(test))]
        let _ = z;
        let k = &se.lin;
        let (a, b, c) = (k.a, k.b, k.c);
        let mg = mc * g;
        let w = ra / (1.0 + ra);
        let abw = a * b * w;
        Lin {
            m,
            inv_m,
            n,
            inv_n: 1.0 / n,
            #[cfg(test)]
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
    /// the value's size (so the sign is `value`'s); None otherwise. The refinement asks
    /// `Line` (this model carried along its ray); the tests check this bound, which `Line`'s
    /// rests on.
    #[cfg(test)]
    pub(super) fn at(&self, p: DVec3) -> Option<(f64, f64)> {
        self.bounded(p)
            .filter(|&(v, err)| v.abs() > err && v.abs() < 1e300)
    }

    /// The model's value at `p` and its bound, where `p` is within its reach.
    // Negated comparisons: a NaN must say None.
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    #[cfg(test)]
    fn bounded(&self, p: DVec3) -> Option<(f64, f64)> {
        let (x, y, z) = (p.x.abs(), p.y.abs(), p.z.abs());
        let (m, n) = (x.max(y), x.min(y));
        // Each difference is exact (Sterbenz) where its d is within dmax <= D_CAP.
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

/// `Lin` carried along the refinement's ray: the field at `o + u·s` as `v + slope·(s − s_r)`
/// from the reference `o + u·s_r`, with a bound in `|s − s_r|` alone. The refinement's
/// bisection runs ask it at ~30 midpoints per crossing, where `Lin::at` needs the point and
/// three relative moves (~75 instructions against ~15).
///
/// Bound: within `reach`, each coordinate keeps its sign and |x| and |y| their order (so `Lin`
/// reads the same coordinates as `m`, `n`, `z`), and every relative move `Lin` computes is
/// within `dmax`, so `|F − v_lin| <= err_lin`. Each fp coordinate of `o + u·s` is within
/// `η/2` of `o + u·s` (two roundings of values at most `|o| + |u|·s_max`), so the computed
/// moves are `(σ u Δ ± η)·inv` to a rounding: `err_lin <= e0 + B (e1 + B q)` with
/// `B = |Δ| U + M` (`U` the largest `|u|·inv`, `M` the largest `η·inv`), and
/// `|v_lin − V| <= H + 2.4e-16 |v_r| + 1.3e-15 S |Δ|` (`H = Σ|α| η inv`, `S = Σ|α u| inv`;
/// the roundings of both sums, of the slope and of `Δ`). The constants below take each
/// factor generously (and 1e-13 for the roundings of the bound's own few operations).
#[derive(Clone, Copy, Debug)]
pub(super) struct Line {
    s: f64,
    v: f64,
    slope: f64,
    /// Largest |s − s_r| the line is used for; negative when it is not used at all.
    reach: f64,
    /// The bound `c0 + |Δ| (c1 + |Δ| c2)`.
    c0: f64,
    c1: f64,
    c2: f64,
}

impl Line {
    /// How far apart two points' fp coordinates can be from `u` times their distance, per
    /// axis, for points `o + u·s` with `0 <= s <= s_max` computed as `o + u * s`: each is
    /// rounded twice, by at most 2^-53 of `|o| + 2|u|·s_max`.
    pub(super) fn eta(o: DVec3, u: DVec3, s_max: f64) -> DVec3 {
        (u.abs() * (2.0 * s_max) + o.abs()) * (f64::EPSILON * 1.01)
    }

    /// The line through the reference `p = o + u·s` (the point `lin` was built at), for a ray
    /// whose points are within `eta` (per axis, absolute) of their exact places, twice over.
    #[inline(always)]
    pub(super) fn new(lin: &Lin, s: f64, p: DVec3, u: DVec3, eta: DVec3) -> Line {
        let off = Line {
            s,
            v: lin.v,
            slope: 0.0,
            reach: -1.0,
            c0: 0.0,
            c1: 0.0,
            c2: 0.0,
        };
        // A zero coordinate (an infinite reciprocal) or NaN: `Lin` itself is never used.
        if !(lin.inv_m < f64::INFINITY && lin.inv_n < f64::INFINITY && lin.inv_z < f64::INFINITY) {
            return off;
        }
        // `u` as the moves of |x|, |y|, |z| (the coordinates' signs put on it), and the axis
        // `Lin::new` took for m = max(|x|, |y|).
        let sign = |p: f64, u: f64| f64::from_bits(u.to_bits() ^ (p.to_bits() & (1 << 63)));
        let (ux, uy, uz) = (sign(p.x, u.x), sign(p.y, u.y), sign(p.z, u.z));
        let ((um, em), (un, en)) = if p.x.abs() >= p.y.abs() {
            ((ux, eta.x), (uy, eta.y))
        } else {
            ((uy, eta.y), (ux, eta.x))
        };
        let (sm, sn, sz) = (um * lin.inv_m, un * lin.inv_n, uz * lin.inv_z);
        let (tm, tn, tz) = (lin.am * sm, lin.an * sn, lin.az * sz);
        let slope = tm + tn + tz;
        let s_sum = tm.abs() + tn.abs() + tz.abs();
        let (um_, un_, uz_) = (sm.abs(), sn.abs(), sz.abs());
        let (em_, en_, ez_) = (em * lin.inv_m, en * lin.inv_n, eta.z * lin.inv_z);
        let h = lin.am.abs() * em_ + lin.an.abs() * en_ + lin.az.abs() * ez_;
        let u_max = fmax(fmax(um_, un_), uz_);
        let m_max = fmax(fmax(em_, en_), ez_);
        let room = lin.dmax * (1.0 - 1e-12) - m_max;
        // |x| and |y| keep their order (equal is as good: the max is the same number).
        let gap = (lin.m - lin.n) * (1.0 - 1e-15) - em - en;
        if !(room > 0.0 && gap > 0.0) {
            return off;
        }
        let (r1, r2) = (room / u_max, gap / (um.abs() + un.abs()));
        let reach = if r1 < r2 { r1 } else { r2 };
        let up = 1.0 + 1e-13;
        let (e1, q) = (lin.e1 * 1.01, lin.q * 1.01);
        Line {
            slope,
            reach: reach * 0.999,
            c0: (lin.e0 * 1.01 + m_max * (e1 + m_max * q) + 1.01 * h + 2e-15 * lin.v.abs()) * up,
            c1: (u_max * (e1 + 2.0 * m_max * q) + 3e-15 * s_sum) * up,
            c2: u_max * u_max * q * up,
            ..off
        }
    }

    /// The field at `o + u·s` and its bound, when the bound settles the sign (as `Lin::at`).
    // Negated comparison: a NaN must say None.
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    #[inline(always)]
    pub(super) fn at(&self, s: f64) -> Option<(f64, f64)> {
        let d = s - self.s;
        let ad = d.abs();
        if !(ad <= self.reach) {
            return None;
        }
        let v = self.v + self.slope * d;
        let err = self.c0 + ad * (self.c1 + ad * self.c2);
        (v.abs() > err && v.abs() < 1e300).then_some((v, err))
    }

    /// Whether `at` would pass its reach and 1e300 tests at every point between `a` and `b`:
    /// it passes them at both. The fp midpoint of two points lies between them, and `d`
    /// and then the line's value are computed by roundings monotone in the point, so their
    /// sizes there are at most the larger of the two ends'.
    #[inline(always)]
    pub(super) fn covers(&self, a: f64, b: f64) -> bool {
        let within = |s: f64| {
            let d = s - self.s;
            d.abs() <= self.reach && (self.v + self.slope * d).abs() < 1e300
        };
        within(a) && within(b)
    }

    /// `at` at a point between two that `covers` accepted: the same answer without the two
    /// tests that always pass there (a bisection run's ~60-instruction step spent 4 on them).
    #[inline(always)]
    pub(super) fn at_between(&self, s: f64) -> Option<(f64, f64)> {
        let d = s - self.s;
        let ad = d.abs();
        let v = self.v + self.slope * d;
        let err = self.c0 + ad * (self.c1 + ad * self.c2);
        (v.abs() > err).then_some((v, err))
    }
}

/// The larger of two numbers without `f64::max`'s NaN handling (a third of the model's build
/// went to it). A NaN can only come from a NaN in `u` or `eta`, and then it also reaches the
/// slope or `c0`, so `at` answers None whatever this returns.
#[inline(always)]
fn fmax(a: f64, b: f64) -> f64 {
    if a > b {
        a
    } else {
        b
    }
}

#[cfg(test)]
mod tests {
    use super::super::near::tests::{on_surface, rng, SHAPES};
    use super::*;

    /// `Line` is within its bound of `value` at points `o + u * s` near a reference on the
    /// same ray (the refinement's midpoints), and settles most signs within 1e-6 of it.
    #[test]
    fn line_values_are_within_their_bound() {
        let mut next = rng(0x2f7a_c3e1_9b54_0d67);
        let (mut used, mut near_used, mut near_asked, mut worst) = (0, 0, 0, 0.0f64);
        for (e, n) in SHAPES {
            let s = Superellipsoid::new(e, n);
            for i in 0..20_000 {
                // A ray from the box's surface region through a point near the surface.
                let target = DVec3::new(next(), next(), next()) * 2.0 - DVec3::ONE;
                let target = if i % 4 == 0 {
                    target
                } else {
                    on_surface(&s, target)
                };
                let o = DVec3::new(next(), next(), next()) * 2.0 - DVec3::ONE;
                let u = (target - o).normalize();
                let s_r = (target - o).length() * (0.9 + 0.2 * next());
                let s_max = 4.0;
                let p_r = o + u * s_r;
                let (_, pw) = s.value_powers(p_r);
                let Some(pw) = pw else { continue };
                let lin = pw.lin(&s);
                let line = Line::new(&lin, s_r, p_r, u, Line::eta(o, u, s_max));
                for _ in 0..4 {
                    let step = 10f64.powf(-2.0 - 14.0 * next());
                    let s1 = (s_r + if next() < 0.5 { step } else { -step }).clamp(0.0, s_max);
                    let exact = s.value(o + u * s1);
                    near_asked += usize::from(step < 1e-6);
                    if let Some((v, err)) = line.at(s1) {
                        used += 1;
                        near_used += usize::from(step < 1e-6);
                        let miss = (v - exact).abs();
                        assert!(miss <= err, "{e} {n} {o} {u} {s_r} {s1}: {v} {exact} {err}");
                        assert_eq!(v < 0.0, exact < 0.0);
                        worst = worst.max(miss / err);
                    }
                }
            }
        }
        assert!(
            used > 100_000 && near_used * 10 > near_asked * 7,
            "{used} {near_used} {near_asked}"
        );
        // The bound keeps a margin (0.50 seen: at |Δ| near 0 the exact evaluations' own
        // roundings are all there is to bound).
        assert!(worst < 0.75, "{worst}");
    }

    /// Where `covers` accepts two ends, `at_between` answers as `at` at every midpoint a
    /// bisection between them can reach (the midpoints of nested brackets).
    #[test]
    fn at_between_is_at_inside_covered_ends() {
        let mut next = rng(0x3c6e_f372_fe94_f82b);
        let (mut covered, mut settled) = (0, 0);
        for (e, n) in SHAPES {
            let s = Superellipsoid::new(e, n);
            for _ in 0..4000 {
                let target = on_surface(&s, DVec3::new(next(), next(), next()) * 2.0 - DVec3::ONE);
                let o = DVec3::new(next(), next(), next()) * 2.0 - DVec3::ONE;
                let u = (target - o).normalize();
                let s_r = (target - o).length();
                let p_r = o + u * s_r;
                let Some(pw) = s.value_powers(p_r).1 else {
                    continue;
                };
                let line = Line::new(&pw.lin(&s), s_r, p_r, u, Line::eta(o, u, 4.0));
                let w = 10f64.powf(-1.0 - 8.0 * next());
                let (mut a, mut b) = (s_r - w * next(), s_r + w * next());
                if !line.covers(a, b) {
                    continue;
                }
                covered += 1;
                for _ in 0..60 {
                    let m = 0.5 * (a + b);
                    let (x, y) = (line.at(m), line.at_between(m));
                    assert_eq!(
                        x.map(|(v, e)| (v.to_bits(), e.to_bits())),
                        y.map(|(v, e)| (v.to_bits(), e.to_bits()))
                    );
                    settled += usize::from(x.is_some());
                    if next() < 0.5 {
                        a = m;
                    } else {
                        b = m;
                    }
                }
            }
        }
        assert!(covered > 10_000 && settled > 100_000, "{covered} {settled}");
    }

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
        // The bound keeps a margin (0.5007 seen since moves up to D_CAP = 1e-2 are in reach;
        // below 0.5 with 1e-3).
        assert!(worst < 0.75, "{worst}");
    }
}
