//! Algebraic surfaces: POV-Ray's `quadric`, `cubic`, `quartic`, `poly` and `polynomial`, the
//! points where a polynomial in x, y, z is zero (inside where it is negative).
//!
//! A ray substituted into the polynomial gives a polynomial in t, whose real roots are the
//! crossings (found by `poly`'s isolation and polishing). The shapes are unbounded, as in
//! POV-Ray; `clipped_by` gives them bounds.

use crate::geom::poly::{
    first_root_before, low_roots_in, roots_in, roots_in_window, sturm_first_root_in,
    sturm_roots_in, sturm_roots_in_window, surely_definite_quartic, Candidate, MAX_DEGREE,
};
use crate::geom::{Hit, Shape};
use crate::math::{Aabb, DVec3, Ray, EPSILON};

mod expand;
mod lanes;
mod quadric;
use expand::{add_term, along_quartic, powers_unrolled, quartic_term, QuarticTerm};
#[cfg(target_arch = "x86_64")]
pub use lanes::{crossings_lanes, crossings_pair};
pub use lanes::{LaneHits, QuadricLanes, LANES};
use quadric::Diagonal;

/// Highest order accepted (POV-Ray allows 35; the root finder handles this many).
pub const MAX_ORDER: usize = MAX_DEGREE;

/// Far limit of the root search for rays that never leave the surface's reach.
const FAR: f64 = 1e7;

#[derive(Clone, Debug)]
pub struct Algebraic {
    order: usize,
    /// (powers of x, y, z; coefficient), zero coefficients left out.
    terms: Vec<([u8; 3], f64)>,
    sturm: bool,
    /// The diagonal form of a quadric without cross terms, for its certified misses.
    diagonal: Option<Diagonal>,
    /// A cubic's or quartic's terms as their expansions (`expand::quartic_term`), in the
    /// order of `terms`; empty for other orders.
    quartic: Vec<(QuarticTerm, f64)>,
}

/// The terms of an order-`order` polynomial in POV-Ray's coefficient order: powers of x
/// falling, then of y, then of z, each from what the order leaves down to 0 (so a quartic's
/// A1 is x⁴, A5 x²y², A10 x², A21 y⁴, A35 the constant; manual 3.4.5.3.5).
pub fn pov_term_order(order: usize) -> Vec<[u8; 3]> {
    let mut v = Vec::new();
    for i in (0..=order).rev() {
        for j in (0..=order - i).rev() {
            for k in (0..=order - i - j).rev() {
                v.push([i as u8, j as u8, k as u8]);
            }
        }
    }
    v
}

impl Algebraic {
    /// A quadric's square, linear and constant coefficients per axis, when it has no cross
    /// terms.
    fn diagonal_quadric(&self) -> Option<([f64; 3], [f64; 3], f64)> {
        if self.order != 2 {
            return None;
        }
        let (mut sq, mut lin, mut k) = ([0.0f64; 3], [0.0f64; 3], 0.0);
        for ([i, j, l], c) in &self.terms {
            match (*i, *j, *l) {
                (2, 0, 0) => sq[0] = *c,
                (0, 2, 0) => sq[1] = *c,
                (0, 0, 2) => sq[2] = *c,
                (1, 0, 0) => lin[0] = *c,
                (0, 1, 0) => lin[1] = *c,
                (0, 0, 1) => lin[2] = *c,
                (0, 0, 0) => k = *c,
                _ => return None,
            }
        }
        Some((sq, lin, k))
    }

    pub fn new(order: usize, terms: &[([u8; 3], f64)], sturm: bool) -> Algebraic {
        let terms: Vec<([u8; 3], f64)> = terms
            .iter()
            .filter(|(p, c)| {
                *c != 0.0 && c.is_finite() && (p[0] + p[1] + p[2]) as usize <= MAX_ORDER
            })
            .copied()
            .collect();
        let order = terms
            .iter()
            .map(|(p, _)| (p[0] + p[1] + p[2]) as usize)
            .max()
            .unwrap_or(0)
            .max(order.min(MAX_ORDER));
        let mut a = Algebraic {
            order,
            terms,
            sturm,
            diagonal: None,
            quartic: Vec::new(),
        };
        if (3..=4).contains(&a.order) {
            a.quartic = a
                .terms
                .iter()
                .map(|&(p, c)| (quartic_term(p).expect("a term above the order"), c))
                .collect();
        }
        // Each power once, so that the diagonal form holds every term.
        let distinct = (1..a.terms.len()).all(|i| a.terms[..i].iter().all(|t| t.0 != a.terms[i].0));
        a.diagonal = a
            .diagonal_quadric()
            .filter(|_| distinct && !a.sturm)
            .map(|(sq, lin, k)| Diagonal::new(sq, lin, k, &a.terms));
        a
    }

    pub fn value(&self, p: DVec3) -> f64 {
        // A quadric without cross terms: the same sum without the tables and the loop over
        // powers (`Diagonal::value`).
        if let Some(q) = &self.diagonal {
            return q.value(p);
        }
        // Tables as small as the order allows: they live in registers or on the stack.
        match self.order {
            0..=2 => self.value_n::<3>(p),
            3..=4 => self.value_n::<5>(p),
            _ => self.value_n::<{ MAX_ORDER + 1 }>(p),
        }
    }

    /// `value` for orders below `N`.
    #[inline(always)]
    fn value_n<const N: usize>(&self, p: DVec3) -> f64 {
        // Powers from tables filled as `powi` computes them (see `powi_table`): the same
        // values without a library call per factor.
        let (x, y, z) = (
            powi_table::<N>(p.x, self.order),
            powi_table::<N>(p.y, self.order),
            powi_table::<N>(p.z, self.order),
        );
        self.terms
            .iter()
            .map(|([i, j, k], c)| c * x[*i as usize] * y[*j as usize] * z[*k as usize])
            .sum()
    }

    /// Crossings with the ray (its `t`), those outside `window` possibly left out.
    fn crossings(&self, ray: &Ray, window: Option<(f64, f64)>, out: &mut Vec<Hit>) {
        if self.order <= 2 && !self.sturm && window.is_none() {
            if let Some((roots, n, len)) = self.low_order_roots(ray) {
                out.extend(roots[..n].iter().map(|t| Hit::new(t / len)));
            }
            return;
        }
        let mut c = [0.0; MAX_ORDER + 1];
        let Some((hi, len)) = self.along_ray(ray, &mut c) else {
            return;
        };
        if self.surely_misses(&c, EPSILON * len, hi) {
            return;
        }
        let c = &c[..=self.order];
        let roots = match (self.sturm, window) {
            (true, None) => sturm_roots_in(c, EPSILON * len, hi),
            (true, Some((wlo, whi))) => {
                sturm_roots_in_window(c, EPSILON * len, hi, wlo * len, whi * len)
            }
            (false, None) => roots_in(c, EPSILON * len, hi),
            // In units of the unit direction.
            (false, Some((wlo, whi))) => {
                roots_in_window(c, EPSILON * len, hi, wlo * len, whi * len)
            }
        };
        out.extend(roots.iter().map(|t| Hit::new(t / len)));
    }

    /// The polynomial along the ray in units of its unit direction (into `c`), the end of
    /// the search interval and the direction's length; None when there is nothing to solve.
    #[inline(always)]
    fn along_ray(&self, ray: &Ray, c: &mut [f64; MAX_ORDER + 1]) -> Option<(f64, f64)> {
        let (len, lead) = self.along_ray_lead(ray, c)?;
        Some((cauchy(c, lead), len))
    }

    /// The polynomial along the ray in units of its unit direction (into `c`), the
    /// direction's length and the degree (its last nonzero coefficient); None when there is
    /// nothing to solve.
    #[inline(always)]
    fn along_ray_lead(&self, ray: &Ray, c: &mut [f64; MAX_ORDER + 1]) -> Option<(f64, usize)> {
        let len = ray.dir.length();
        if !(len > 0.0 && len.is_finite()) || self.terms.is_empty() {
            return None;
        }
        let u = ray.dir / len;
        self.along(ray.origin, u, c);
        let lead = c[..=self.order]
            .iter()
            .rposition(|v| *v != 0.0)
            .unwrap_or(0);
        (lead != 0).then_some((len, lead))
    }

    /// A quadric's (or a lower-degree) polynomial along the ray, not `sturm`: its roots as
    /// `roots_in` gives them on [EPSILON, Cauchy's bound], the bound computed only when a
    /// root needs it (most rays miss most quadrics of an unbounded scene).
    #[inline(always)]
    fn low_order_roots(&self, ray: &Ray) -> Option<([f64; 2], usize, f64)> {
        if let Some(q) = &self.diagonal {
            if q.surely_misses(ray.origin, ray.dir) {
                return None;
            }
        }
        self.low_order_solved(ray)
    }

    /// `low_order_roots` without the certificate.
    #[inline(always)]
    fn low_order_solved(&self, ray: &Ray) -> Option<([f64; 2], usize, f64)> {
        // `along_ray_lead` on three coefficients: the expansion for orders below 3 is
        // `along_quadric`, whatever `along` would copy it into.
        let len = ray.dir.length();
        if !(len > 0.0 && len.is_finite()) || self.terms.is_empty() {
            return None;
        }
        let u = ray.dir / len;
        let c = match &self.diagonal {
            // The same coefficients, bit for bit, written for the diagonal terms.
            Some(q) => q.along(ray.origin, u),
            None => self.along_quadric(ray.origin, u),
        };
        let lead = c[..=self.order]
            .iter()
            .rposition(|v| *v != 0.0)
            .unwrap_or(0);
        if lead == 0 {
            return None;
        }
        let (roots, n) = low_roots_in(&c[..=lead], EPSILON * len, || cauchy(&c, lead));
        Some((roots, n, len))
    }

    /// A quartic along the ray (`c`, searched over `[lo, hi]`) that keeps one sign by a clear
    /// margin: every root finder would find no root (see `surely_definite_quartic`).
    #[inline(always)]
    fn surely_misses(&self, c: &[f64; MAX_ORDER + 1], lo: f64, hi: f64) -> bool {
        self.order == 4
            && c[4] != 0.0
            && surely_definite_quartic(c.first_chunk::<5>().expect("a quartic"), lo, hi)
    }

    /// `intersect_first`'s walk over `c` (orders 3 and up, not `sturm`) on `[EPSILON·len,
    /// hi]`, stopped unpolished at a piece starting at or past `tmax` (`first_root_before`:
    /// every crossing the walk could still give there is at or past `tmax`, which the
    /// callers drop, and it is kept, `tmax` being above `EPSILON` where any is below it).
    #[inline(always)]
    fn first_walk(
        &self,
        c: &[f64; MAX_ORDER + 1],
        hi: f64,
        len: f64,
        tmax: f64,
        take: impl FnMut(Candidate) -> Option<f64>,
    ) -> Option<f64> {
        // A quartic that `surely_misses` could not settle seldom passes `surely_no_root`
        // either (hyptorus: never in 9,797 rays), which the walk would otherwise ask first.
        let c = &c[..=self.order];
        let shortcut = !(self.order == 4 && c[4] != 0.0);
        first_root_before(c, EPSILON * len, hi, shortcut, |a| a / len >= tmax, take)
    }

    /// `intersect_first`'s `t`. `settle`: a bracket `[a, b]` of the walk with `a / len >
    /// EPSILON` and `b / len < tmax` is answered with `a / len` unpolished, for a caller that
    /// asks only whether there is a crossing (it holds the walk's first kept root, whose `t`
    /// lies in `[a / len, b / len]`: the quotient rounds monotonically).
    #[inline(always)]
    fn first_t(&self, ray: &Ray, tmax: f64, settle: bool) -> Option<f64> {
        if self.order <= 2 && !self.sturm {
            let (roots, n, len) = self.low_order_roots(ray)?;
            return roots[..n]
                .iter()
                .copied()
                .find(|&x| x / len > EPSILON)
                .map(|x| x / len)
                .filter(|&t| t < tmax);
        }
        let mut c = [0.0; MAX_ORDER + 1];
        let (hi, len) = self.along_ray(ray, &mut c)?;
        if self.surely_misses(&c, EPSILON * len, hi) {
            return None;
        }
        let keep = |x: f64| x / len > EPSILON;
        if self.sturm {
            return sturm_first_root_in(&c[..=self.order], EPSILON * len, hi, keep)
                .map(|x| x / len)
                .filter(|&t| t < tmax);
        }
        self.first_walk(&c, hi, len, tmax, |cand| {
            if settle && cand.a / len > EPSILON && cand.b / len < tmax {
                return Some(cand.a);
            }
            let x = cand.root();
            keep(x).then_some(x)
        })
        .map(|x| x / len)
        .filter(|&t| t < tmax)
    }

    /// The polynomial along `origin + t·dir` (ascending coefficients in t).
    fn along(&self, origin: DVec3, dir: DVec3, out: &mut [f64; MAX_ORDER + 1]) {
        // The table of powers is zeroed on every ray: 7 KB at the largest order, most of the
        // time of a quadric's intersection. Low orders use a small one (same arithmetic), and
        // quadrics, cubics and quartics a term-by-term expansion.
        if self.order <= 2 {
            out[..3].copy_from_slice(&self.along_quadric(origin, dir));
        } else if self.order <= 4 {
            let low = out.first_chunk_mut::<5>().expect("room for a quartic");
            along_quartic(&self.quartic, origin, dir, low);
        } else if self.order < 8 {
            *out = self.along_in::<8>(origin, dir);
        } else {
            *out = self.along_in::<{ MAX_ORDER + 1 }>(origin, dir);
        }
    }

    /// Powers of (o + t d) per axis as polynomials in t, up to the shape's order.
    fn powers<const N: usize>(&self, origin: DVec3, dir: DVec3) -> [[[f64; N]; N]; 3] {
        let n = self.order;
        let mut pw = [[[0.0f64; N]; N]; 3];
        for (axis, (o, d)) in [(origin.x, dir.x), (origin.y, dir.y), (origin.z, dir.z)]
            .into_iter()
            .enumerate()
        {
            pw[axis][0][0] = 1.0;
            for e in 1..=n {
                let (prev, cur) = pw[axis].split_at_mut(e);
                let prev = &prev[e - 1];
                let cur = &mut cur[0];
                for k in 0..e {
                    cur[k] += prev[k] * o;
                    cur[k + 1] += prev[k] * d;
                }
            }
        }
        pw
    }

    /// `along_in` for orders up to 2, each term expanded by code made for its powers: the
    /// same products and sums in the same order, so the same bits, without the loads and
    /// stores of index-dependent loops.
    fn along_quadric(&self, origin: DVec3, dir: DVec3) -> [f64; 3] {
        let pw = powers_unrolled::<3>(origin, dir);
        let mut acc = [0.0f64; 3];
        macro_rules! dispatch {
            ($p:expr, $c:expr; $(($i:literal, $j:literal, $k:literal)),*) => {
                match $p {
                    $([$i, $j, $k] => add_term::<3, $i, $j, $k>($c, &pw, &mut acc),)*
                    _ => unreachable!("a term above the order"),
                }
            };
        }
        for (p, c) in &self.terms {
            dispatch!(*p, *c;
                (2, 0, 0), (1, 1, 0), (1, 0, 1), (1, 0, 0), (0, 2, 0), (0, 1, 1), (0, 1, 0),
                (0, 0, 2), (0, 0, 1), (0, 0, 0))
        }
        acc
    }

    /// `along` with room for orders below `N`.
    fn along_in<const N: usize>(&self, origin: DVec3, dir: DVec3) -> [f64; MAX_ORDER + 1] {
        let pw = self.powers::<N>(origin, dir);
        let mut out = [0.0; MAX_ORDER + 1];
        let mut xy = [0.0; MAX_ORDER + 1];
        for ([i, j, k], c) in &self.terms {
            let (i, j, k) = (*i as usize, *j as usize, *k as usize);
            xy[..=i + j].fill(0.0);
            for a in 0..=i {
                for b in 0..=j {
                    xy[a + b] += pw[0][i][a] * pw[1][j][b];
                }
            }
            for a in 0..=i + j {
                if xy[a] == 0.0 {
                    continue;
                }
                for b in 0..=k {
                    out[a + b] += c * xy[a] * pw[2][k][b];
                }
            }
        }
        out
    }
}

/// Cauchy's bound on the roots, `1 + max|c_i / c_lead|` (at most `FAR`), which keeps the
/// search interval finite. The maximum ignores NaN quotients, as `f64::max` does, and does
/// not depend on the order of the quotients.
///
/// One division instead of one per coefficient (they were most of a quadric's hit path):
/// `(v / l).abs()` is `|v| / |l|` bit for bit, and rounding a division by a fixed `|l|` is
/// monotone, so the largest quotient is the largest `|v|` divided once. A NaN quotient comes
/// only from an infinite or NaN `c_lead` (every quotient is then 0 or NaN) or a NaN `c_i`
/// (never the largest `|v|`), so a NaN result stands for 0.
#[inline(always)]
fn cauchy(c: &[f64], lead: usize) -> f64 {
    let mut big = 0.0f64;
    for v in &c[..lead] {
        let a = v.abs();
        if a > big {
            big = a;
        }
    }
    let q = big / c[lead].abs();
    let m = if q > 0.0 { q } else { 0.0 };
    (1.0 + m).min(FAR)
}

/// `cauchy` as a division per coefficient: the reference its unit test compares with.
#[cfg(test)]
fn cauchy_per_coefficient(c: &[f64], lead: usize) -> f64 {
    let mut m = 0.0;
    for v in &c[..lead] {
        let q = (v / c[lead]).abs();
        if q > m {
            m = q;
        }
    }
    (1.0 + m).min(FAR)
}

impl Shape for Algebraic {
    fn bounds(&self) -> Aabb {
        Aabb::INFINITE
    }

    fn as_algebraic(&self) -> Option<&Algebraic> {
        Some(self)
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        self.crossings(ray, None, out)
    }

    fn intersect_all_within(&self, ray: &Ray, lo: f64, hi: f64, out: &mut Vec<Hit>) {
        self.crossings(ray, Some((lo, hi)), out)
    }

    /// The nearest of `intersect_all`'s crossings without polishing the roots beyond it
    /// (`first_root_in`); the `t` are increasing in the roots, so the first root whose `t`
    /// passes `EPSILON` gives the nearest crossing.
    fn intersect_first(&self, ray: &Ray, tmax: f64, _scratch: &mut Vec<Hit>) -> Option<Hit> {
        self.first_t(ray, tmax, false).map(Hit::new)
    }

    /// `intersect_first(..).is_some()`, a root's polish left out where its bracket settles
    /// the answer (`first_t`'s `settle`): shadow rays.
    fn any_hit(&self, ray: &Ray, tmax: f64, _scratch: &mut Vec<Hit>) -> bool {
        self.first_t(ray, tmax, true).is_some()
    }

    fn windowed(&self) -> bool {
        // Sturm's search counts roots over the whole interval, which
        // `sturm_roots_in_window` does without polishing the roots outside the window.
        self.order >= 3
    }

    fn inside(&self, p: DVec3) -> bool {
        self.value(p) < 0.0
    }

    /// A quadric without cross terms, a·x² + b·y² + c·z² + linear + constant with the squared
    /// terms' coefficients >= 0 and no linear term on the axes without one (spheres,
    /// ellipsoids, the axis cylinders of shapes.inc): its solid (negative side) lies within
    /// centre ± sqrt(K / a) on each axis with a square term.
    fn slab_bounds(&self) -> Aabb {
        let Some((sq, lin, k)) = self.diagonal_quadric() else {
            return Aabb::INFINITE;
        };
        if sq.iter().any(|&a| a < 0.0) || (0..3).any(|a| sq[a] == 0.0 && lin[a] != 0.0) {
            return Aabb::INFINITE;
        }
        // sum a(x + l/2a)² <= K
        let big_k = (0..3)
            .filter(|&a| sq[a] > 0.0)
            .map(|a| lin[a] * lin[a] / (4.0 * sq[a]))
            .sum::<f64>()
            - k;
        if big_k.is_nan() || big_k < 0.0 || big_k.is_infinite() {
            return Aabb::INFINITE;
        }
        let (mut lo, mut hi) = (DVec3::NEG_INFINITY, DVec3::INFINITY);
        for a in 0..3 {
            if sq[a] > 0.0 {
                let c = -lin[a] / (2.0 * sq[a]);
                let r = (big_k / sq[a]).sqrt();
                let pad = 1e-6 * (r + c.abs()) + 1e-9;
                lo[a] = c - r - pad;
                hi[a] = c + r + pad;
            }
        }
        Aabb::new(lo, hi)
    }

    /// A quadric without cross terms inside a box: on each axis with a positive square term,
    /// sq·(x - c)² is at most what the other axes' terms leave of -k at their least over the
    /// box (a negative square term's least is at an end of its interval, so it needs that
    /// interval finite; a hyperboloid between two planes).
    fn slab_bounds_within(&self, b: &Aabb) -> Aabb {
        let own = self.slab_bounds().intersection(b);
        let Some((sq, lin, k)) = self.diagonal_quadric() else {
            return own;
        };
        // The least of g(x) = sq·x² + lin·x over [lo, hi], and the size of the terms in it.
        let least = |a: usize| -> f64 {
            let (lo, hi) = (own.min[a], own.max[a]);
            let g = |x: f64| sq[a] * x * x + lin[a] * x;
            if sq[a] > 0.0 {
                let c = -lin[a] / (2.0 * sq[a]);
                g(c.clamp(lo, hi))
            } else if sq[a] == 0.0 && lin[a] == 0.0 {
                0.0
            } else {
                // Concave or linear: the least is at an end (-inf when that end is open).
                g(lo).min(g(hi))
            }
        };
        let mins = [least(0), least(1), least(2)];
        let (mut lo, mut hi) = (own.min, own.max);
        for i in 0..3 {
            if sq[i] <= 0.0 {
                continue;
            }
            let others: f64 = (0..3).filter(|&j| j != i).map(|j| mins[j]).sum();
            let c = -lin[i] / (2.0 * sq[i]);
            let shift = lin[i] * lin[i] / (4.0 * sq[i]);
            // sq·(x - c)² = g(x) + shift <= -k - others + shift
            let q = (-k - others + shift) / sq[i];
            if !q.is_finite() {
                continue;
            }
            // Rounding in the sums above is far below this margin.
            let scale = (k.abs() + mins.iter().map(|m| m.abs()).sum::<f64>() + shift) / sq[i];
            let r = (q.max(0.0) + 1e-9 * scale).sqrt();
            let pad = 1e-6 * (r + c.abs()) + 1e-9;
            lo[i] = lo[i].max(c - r - pad);
            hi[i] = hi[i].min(c + r + pad);
        }
        Aabb::new(lo, hi)
    }

    fn normal(&self, p: DVec3, _hit: &Hit) -> DVec3 {
        // As in `value`: powers from tables the size of the order, not a `powi` call
        // (`__powidf2`) per factor, which was most of a quartic's normal.
        match self.order {
            0..=2 => self.gradient_n::<3>(p),
            3..=4 => self.gradient_n::<5>(p),
            _ => self.gradient_n::<{ MAX_ORDER + 1 }>(p),
        }
    }
}

impl Algebraic {
    /// The gradient for orders below `N`: each term's derivatives as `c·i·x^(i-1)·y^j·z^k`
    /// in that order, the powers from `powi_table` (bit for bit `powi`'s, see there).
    #[inline(always)]
    fn gradient_n<const N: usize>(&self, p: DVec3) -> DVec3 {
        let (x, y, z) = (
            powi_table::<N>(p.x, self.order),
            powi_table::<N>(p.y, self.order),
            powi_table::<N>(p.z, self.order),
        );
        let mut g = DVec3::ZERO;
        for ([i, j, k], c) in &self.terms {
            let (i, j, k) = (*i as usize, *j as usize, *k as usize);
            if i > 0 {
                g.x += c * i as f64 * x[i - 1] * y[j] * z[k];
            }
            if j > 0 {
                g.y += c * j as f64 * x[i] * y[j - 1] * z[k];
            }
            if k > 0 {
                g.z += c * k as f64 * x[i] * y[j] * z[k - 1];
            }
        }
        g
    }

    /// `normal` by `powi` calls: the reference its unit test compares with.
    #[cfg(test)]
    fn gradient_powi(&self, p: DVec3) -> DVec3 {
        let mut g = DVec3::ZERO;
        for ([i, j, k], c) in &self.terms {
            let (i, j, k) = (*i as i32, *j as i32, *k as i32);
            let (x, y, z) = (p.x, p.y, p.z);
            if i > 0 {
                g.x += c * i as f64 * x.powi(i - 1) * y.powi(j) * z.powi(k);
            }
            if j > 0 {
                g.y += c * j as f64 * x.powi(i) * y.powi(j - 1) * z.powi(k);
            }
            if k > 0 {
                g.z += c * k as f64 * x.powi(i) * y.powi(j) * z.powi(k - 1);
            }
        }
        g
    }
}

/// `x.powi(e)` for e in 0..=n, each computed as `powi` does (the compiler's `__powidf2`:
/// square-and-multiply from the lowest bit, starting from 1), so each is bit for bit the value
/// `powi` gives.
#[inline(always)]
fn powi_table<const N: usize>(x: f64, n: usize) -> [f64; N] {
    let mut t = [1.0; N];
    // What the loop below gives for the low powers, written out: x^1 = 1·x, x^2 = 1·(x·x),
    // x^3 = (1·x)·(x·x), x^4 = 1·((x·x)·(x·x)) (and 1·v is v).
    if N <= 5 {
        let x2 = x * x;
        for (e, v) in [x, x2, x * x2, x2 * x2].into_iter().enumerate().take(N - 1) {
            t[e + 1] = v;
        }
        return t;
    }
    for (e, v) in t.iter_mut().enumerate().take(n + 1).skip(1) {
        let (mut a, mut b, mut r) = (x, e, 1.0f64);
        loop {
            if b & 1 != 0 {
                r *= a;
            }
            b >>= 1;
            if b == 0 {
                break;
            }
            a *= a;
        }
        *v = r;
    }
    t
}

#[cfg(test)]
mod tests;
