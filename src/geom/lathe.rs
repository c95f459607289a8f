//! POV-Ray `lathe`: a 2-D spline of (radius, height) points turned about the y axis.
//!
//! A ray meets the surface traced by piece point (r(s), h(s)) where the ray's height is h(s)
//! and its distance from the axis is |r(s)|. Eliminating the ray parameter t = (h − oy) / dy
//! gives a polynomial in s of degree twice the piece's (six for cubic pieces), whose sign
//! changes on [0, 1] are the crossings. That elimination loses accuracy as the ray turns
//! horizontal (its roots pair up at distance ∝ dy), so nearly horizontal rays take the
//! horizontal solution instead (h(s) = oy, then the circle of radius r(s)) polished by Newton
//! steps on the exact equations.
//!
//! The problem is scaled so the bounding cylinder has radius 1 and the ray origin moved to
//! where the ray enters it, as the torus does, so the coefficients stay of order one.

use crate::geom::spline2d::{
    inside_even_odd, sign_changes, sign_changes_until, Piece, SplineKind, P2,
};
use crate::geom::{Hit, Shape};
use crate::math::{Aabb, DVec3, Ray, EPSILON};

/// Below this |dy| (unit direction) the ray counts as nearly horizontal.
const FLAT: f64 = 1e-3;

#[derive(Clone, Debug)]
pub struct Lathe {
    /// Pieces scaled by `1 / scale`.
    pieces: Vec<Piece>,
    /// Each piece's squared radius polynomial (`mul(x, x)`), the same for every ray.
    r2: Vec<[f64; 7]>,
    scale: f64,
    /// Largest |radius| and the height range, scaled.
    radius: f64,
    y: [f64; 2],
}

/// The pieces of a lathe's profile, or POV-Ray's reason to refuse the points. The profile is
/// not closed automatically.
pub fn profile(kind: SplineKind, p: &[P2]) -> Result<Vec<Piece>, String> {
    let n = p.len();
    let (need, word) = match kind {
        SplineKind::Linear => (2, "two"),
        SplineKind::Quadratic => (3, "three"),
        SplineKind::Cubic => (4, "four"),
        SplineKind::Bezier => (4, "four"),
    };
    if kind == SplineKind::Bezier && !n.is_multiple_of(4) {
        return Err("Lathe with Bezier splines must have four points per segment.".into());
    }
    if n < need {
        return Err(format!(
            "Lathe with {} splines must have at least {word} points.",
            kind.name()
        ));
    }
    Ok(match kind {
        SplineKind::Linear => (1..n).map(|i| Piece::linear(p[i - 1], p[i])).collect(),
        SplineKind::Quadratic => (1..n - 1)
            .map(|i| Piece::quadratic(p[i - 1], p[i], p[i + 1]))
            .collect(),
        SplineKind::Cubic => (1..n - 2)
            .map(|i| Piece::cubic(p[i - 1], p[i], p[i + 1], p[i + 2]))
            .collect(),
        SplineKind::Bezier => (0..n)
            .step_by(4)
            .map(|i| Piece::bezier(p[i], p[i + 1], p[i + 2], p[i + 3]))
            .collect(),
    })
}

/// Products of polynomials in ascending order (degrees up to 3 here).
fn mul(a: &[f64; 4], b: &[f64; 4]) -> [f64; 7] {
    let mut c = [0.0; 7];
    for i in 0..4 {
        for j in 0..4 {
            c[i + j] += a[i] * b[j];
        }
    }
    c
}

impl Lathe {
    pub fn new(pieces: Vec<Piece>) -> Lathe {
        let mut radius: f64 = 0.0;
        let mut y = [f64::INFINITY, f64::NEG_INFINITY];
        for pc in &pieces {
            radius = radius.max(pc.lo[0].abs()).max(pc.hi[0].abs());
            y = [y[0].min(pc.lo[1]), y[1].max(pc.hi[1])];
        }
        let scale = radius.max(y[0].abs()).max(y[1].abs());
        let scale = if scale > 0.0 && scale.is_finite() {
            scale
        } else {
            1.0
        };
        let k = 1.0 / scale;
        let scaled = |q: P2| [q[0] * k, q[1] * k];
        let pieces: Vec<Piece> = pieces
            .iter()
            .map(|pc| Piece {
                x: pc.x.map(|c| c * k),
                y: pc.y.map(|c| c * k),
                p0: scaled(pc.p0),
                p1: scaled(pc.p1),
                lo: scaled(pc.lo),
                hi: scaled(pc.hi),
            })
            .collect();
        Lathe {
            r2: pieces.iter().map(|pc| mul(&pc.x, &pc.x)).collect(),
            pieces,
            scale,
            radius: radius * k,
            y: [y[0] * k, y[1] * k],
        }
    }

    /// Calls `found(t, piece, s)` for each crossing, t in scaled unit-direction units from `o`,
    /// piece by piece until `done()` holds before one (`any_kept`'s stop; `|| false` lists all).
    fn crossings(
        &self,
        o: DVec3,
        u: DVec3,
        t_lo: f64,
        t_hi: f64,
        done: impl Fn() -> bool,
        found: &mut impl FnMut(f64, usize, f64),
    ) {
        let a = u.x * u.x + u.z * u.z;
        let b = o.x * u.x + o.z * u.z;
        let c = o.x * o.x + o.z * o.z;
        let dy = u.y;
        let inv = [1.0 / dy, 1.0 / a];
        for (i, pc) in self.pieces.iter().enumerate() {
            if done() {
                return;
            }
            if !Self::may_cross(pc, o, [a, b, c], dy, inv, t_lo, t_hi) {
                continue;
            }
            if dy.abs() >= FLAT {
                self.sloped(pc, i, o, [a, b, c], dy, None, found);
            } else {
                self.flat(pc, i, o, [a, b, c], dy, found);
            }
        }
    }

    /// Whether the ray's stretch [t_lo, t_hi] passes through the piece's own cylindrical shell
    /// and height band.
    ///
    /// The height band is tried before the shell (its two divisions before a square root and
    /// two more): each bound only raises `lo` or lowers `hi` (`max` and `min` are exact, and
    /// ignore NaN in any order), so a stretch already empty after the band stays empty, and
    /// the answer is the one the whole test gives.
    ///
    /// `inv` is `[1 / dy, 1 / a]`, taken once per ray: the bounds are products by it rather
    /// than four quotients per piece. A product differs from the quotient by at most an ulp of
    /// bounds near the stretch (t of order one in the scaled problem), far inside the 1e-9
    /// margin the stretch is allowed; an infinite reciprocal (`dy` or `a` subnormal) gives
    /// NaN or infinite bounds, which `max` and `min` drop or keep as the quotients would.
    #[allow(clippy::too_many_arguments)]
    fn may_cross(
        pc: &Piece,
        o: DVec3,
        [a, b, c]: [f64; 3],
        dy: f64,
        [inv_dy, inv_a]: [f64; 2],
        t_lo: f64,
        t_hi: f64,
    ) -> bool {
        let r_max = pc.lo[0].abs().max(pc.hi[0].abs());
        let disc = b * b - a * (c - r_max * r_max);
        if disc < 0.0 && c > r_max * r_max {
            return false;
        }
        let (mut lo, mut hi) = (t_lo, t_hi);
        if dy != 0.0 {
            let (y0, y1) = ((pc.lo[1] - o.y) * inv_dy, (pc.hi[1] - o.y) * inv_dy);
            lo = lo.max(y0.min(y1));
            hi = hi.min(y0.max(y1));
            if lo > hi + 1e-9 {
                return false;
            }
        } else if o.y < pc.lo[1] || o.y > pc.hi[1] {
            return false;
        }
        if a > 0.0 {
            let h = disc.max(0.0).sqrt();
            lo = lo.max((-b - h) * inv_a);
            hi = hi.min((-b + h) * inv_a);
        }
        // A degenerate ray leaves NaN bounds: nothing to find.
        !(lo.is_nan() || hi.is_nan() || lo > hi + 1e-9)
    }

    /// `intersect_first` for a ray that is not nearly horizontal: the crossings of a piece
    /// then have `t = (y(s) − oy) / dy` with `y(s)` in the piece's height band, so the band
    /// bounds them below (less a margin far above rounding). Pieces are taken by that bound
    /// and the search stops beyond the best crossing found; a crossing replaces the best
    /// when its `t` is less, or equal and from an earlier piece, which is the default's
    /// choice (the first least `t` in `intersect_all`'s order) to the bit.
    ///
    /// Only crossings `keep` holds for may be the best (`gather_kept`; `intersect_first`
    /// keeps all): it is asked last, of a crossing that would replace the best. Without
    /// `LEAVE` every crossing of a piece taken is refined to the end (no settle test in the
    /// Newton steps; the pieces past the best are still left whole).
    fn first_sloped<const LEAVE: bool>(
        &self,
        (o, u, lo, hi, back): (DVec3, DVec3, f64, f64, f64),
        tmax: f64,
        cand: &mut Vec<Hit>,
        mut keep: impl FnMut(f64) -> bool,
    ) -> Option<Hit> {
        let shift = lo;
        let o = o + u * shift;
        let (t_lo, t_hi) = (0.0, hi - shift);
        let a = u.x * u.x + u.z * u.z;
        let b = o.x * u.x + o.z * u.z;
        let c = o.x * o.x + o.z * o.z;
        let dy = u.y;
        cand.clear();
        let inv = [1.0 / dy, 1.0 / a];
        for (i, pc) in self.pieces.iter().enumerate() {
            if Self::may_cross(pc, o, [a, b, c], dy, inv, t_lo, t_hi) {
                let (y0, y1) = ((pc.lo[1] - o.y) / dy, (pc.hi[1] - o.y) / dy);
                let t = y0.min(y1);
                let floor =
                    t - 1e-9 * (t.abs() + (pc.lo[1].abs() + pc.hi[1].abs() + o.y.abs()) / dy.abs());
                cand.push(Hit::with_part((floor + shift) * back, i as u32));
            }
        }
        cand.sort_unstable_by(|p, q| p.t.total_cmp(&q.t).then(p.part.cmp(&q.part)));
        let mut best: Option<Hit> = None;
        for cd in cand.iter() {
            let (floor, i) = (cd.t, cd.part);
            if best.is_some_and(|h| floor > h.t) || floor >= tmax {
                break;
            }
            let pc = &self.pieces[i as usize];
            // A crossing of this piece is kept only after EPSILON, before `tmax` and before
            // the best (a tie with an earlier piece's cannot win, nor one of this piece's).
            let leave = Leave {
                shift,
                back,
                inv_dy: inv[0],
                after: EPSILON,
                before: tmax,
                past: best.map_or(f64::INFINITY, |h| h.t),
            };
            self.sloped(
                pc,
                i as usize,
                o,
                [a, b, c],
                dy,
                LEAVE.then_some(leave),
                &mut |t, i, s| {
                    let t = (t + shift) * back;
                    if t > EPSILON
                        && t < tmax
                        && best.is_none_or(|h| t < h.t || (t == h.t && (i as u32) < h.part))
                        && keep(t)
                    {
                        best = Some(Hit {
                            t,
                            part: i as u32,
                            uv: [s, 0.0],
                        });
                    }
                },
            );
        }
        best
    }

    #[allow(clippy::too_many_arguments)]
    fn sloped(
        &self,
        pc: &Piece,
        i: usize,
        o: DVec3,
        [a, b, c]: [f64; 3],
        dy: f64,
        leave: Option<Leave>,
        found: &mut impl FnMut(f64, usize, f64),
    ) {
        // dy²(c − r²) + 2 b dy (h − oy) + a (h − oy)², zero where the ray meets the surface.
        let mut hh = pc.y;
        hh[0] -= o.y;
        if pc.is_linear() && hh[0].is_finite() {
            return self.sloped_linear(pc, i, o, [a, b, c], dy, hh[0], leave, found);
        }
        self.sloped_general(pc, i, o, [a, b, c], dy, hh, leave, found);
    }

    /// `sloped` for any piece: `f` over all seven terms. Its own function so that the tests
    /// can hold the straight pieces' path against it; inlined, so `sloped` compiles as one.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    pub(super) fn sloped_general(
        &self,
        pc: &Piece,
        i: usize,
        o: DVec3,
        [a, b, c]: [f64; 3],
        dy: f64,
        hh: [f64; 4],
        leave: Option<Leave>,
        found: &mut impl FnMut(f64, usize, f64),
    ) {
        let (r2, h2) = (&self.r2[i], mul(&hh, &hh));
        let mut f = [0.0; 7];
        for k in 0..7 {
            f[k] = -dy * dy * r2[k] + a * h2[k];
            if k < 4 {
                f[k] += 2.0 * b * dy * hh[k];
            }
        }
        f[0] += dy * dy * c;
        sloped_roots(&f, pc, i, o.y, [a, b, c], dy, leave, found);
    }

    /// `sloped` for a straight piece: `f`'s terms past the square are sums of zero products
    /// (`+0`, or `−0` for the `f` terms, which `sign_changes` trims all the same), so only the
    /// first three are computed, by `mul`'s and the loop's operations in their order. `mul`'s
    /// sums start from `+0`, which only matters for a `−0` product: `h0·h1` keeps its `0.0 +`,
    /// and `h1²` is never `−0`, so adding `h0·0 = ±0` before it and `0·h0` after it (finite
    /// `h0`, checked by the caller) leaves it as it is.
    ///
    /// Only `hh[0]` (`pc.y[0] − oy`) comes from the caller, in a register; the other terms are
    /// read from the piece. The caller's `hh` array was on the stack, just written, and the
    /// paired load of its terms 1 and 2 waited on a failed store forward on every call.
    #[allow(clippy::too_many_arguments)]
    #[inline(never)]
    fn sloped_linear(
        &self,
        pc: &Piece,
        i: usize,
        o: DVec3,
        [a, b, c]: [f64; 3],
        dy: f64,
        h0: f64,
        leave: Option<Leave>,
        found: &mut impl FnMut(f64, usize, f64),
    ) {
        let hh = [h0, pc.y[1], pc.y[2]];
        let r2 = &self.r2[i];
        let h2 = [
            hh[0] * hh[0],
            0.0 + hh[0] * hh[1] + hh[1] * hh[0],
            hh[1] * hh[1],
        ];
        let mut f = [0.0; 3];
        for k in 0..3 {
            f[k] = -dy * dy * r2[k] + a * h2[k];
            f[k] += 2.0 * b * dy * hh[k];
        }
        f[0] += dy * dy * c;
        sloped_roots(&f, pc, i, o.y, [a, b, c], dy, leave, found);
    }

    fn flat(
        &self,
        pc: &Piece,
        i: usize,
        o: DVec3,
        [a, b, c]: [f64; 3],
        dy: f64,
        found: &mut impl FnMut(f64, usize, f64),
    ) {
        if a == 0.0 {
            return;
        }
        let mut hh = pc.y;
        hh[0] -= o.y;
        sign_changes(&hh, 0.0, 1.0, pc.p0[1] - o.y, pc.p1[1] - o.y, |s0| {
            let r = pc.at(s0)[0];
            let disc = b * b - a * (c - r * r);
            if disc < 0.0 {
                return;
            }
            let root = disc.sqrt();
            for t0 in [(-b - root) / a, (-b + root) / a] {
                let (mut s, mut t) = (s0, t0);
                // Newton on h(s) − oy − t dy = 0 and a t² + 2 b t + c − r(s)² = 0.
                for _ in 0..8 {
                    let (q, tan) = (pc.at(s), pc.tangent(s));
                    let e1 = q[1] - o.y - t * dy;
                    let e2 = a * t * t + 2.0 * b * t + c - q[0] * q[0];
                    let (j11, j12) = (tan[1], -dy);
                    let (j21, j22) = (-2.0 * q[0] * tan[0], 2.0 * (a * t + b));
                    let det = j11 * j22 - j12 * j21;
                    if det == 0.0 || !det.is_finite() {
                        break;
                    }
                    let ds = (e1 * j22 - j12 * e2) / det;
                    let dt = (j11 * e2 - j21 * e1) / det;
                    if !(ds.abs() < 0.1 && dt.abs() < 0.5) {
                        // Leaving the neighbourhood: keep the horizontal answer.
                        (s, t) = (s0, t0);
                        break;
                    }
                    s -= ds;
                    t -= dt;
                    if ds.abs() < 1e-15 && dt.abs() < 1e-15 {
                        break;
                    }
                }
                found(t, i, s);
            }
        });
    }

    /// Ray in scaled space with a unit direction, plus the factor from scaled distance back to
    /// ray units, and the part of the ray inside the bounding cylinder.
    fn setup(&self, ray: &Ray) -> Option<(DVec3, DVec3, f64, f64, f64)> {
        let len = ray.dir.length();
        if !(len > 0.0 && len.is_finite()) || self.pieces.is_empty() {
            return None;
        }
        let u = ray.dir / len;
        let o = ray.origin / self.scale;
        let a = u.x * u.x + u.z * u.z;
        let b = o.x * u.x + o.z * u.z;
        let c = o.x * o.x + o.z * o.z - self.radius * self.radius;
        let margin = 1e-9;
        let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
        if a > 0.0 {
            let disc = b * b - a * c;
            if disc < 0.0 {
                return None;
            }
            let h = disc.sqrt();
            lo = (-b - h) / a - margin;
            hi = (-b + h) / a + margin;
        } else if c > 0.0 {
            return None;
        }
        if u.y != 0.0 {
            let (y0, y1) = ((self.y[0] - o.y) / u.y, (self.y[1] - o.y) / u.y);
            lo = lo.max(y0.min(y1) - margin);
            hi = hi.min(y0.max(y1) + margin);
        } else if o.y < self.y[0] || o.y > self.y[1] {
            return None;
        }
        let min_dist = EPSILON * len / self.scale;
        lo = lo.max(min_dist);
        (lo <= hi).then_some((o, u, lo, hi, self.scale / len))
    }

    /// Calls `f` with each crossing `intersect_all` lists, in its order, until `done()` holds
    /// before a piece.
    fn each_hit(&self, ray: &Ray, done: impl Fn() -> bool, mut f: impl FnMut(Hit)) {
        let Some((o, u, lo, hi, back)) = self.setup(ray) else {
            return;
        };
        // Solve from the entry point so the coefficients do not depend on a far origin.
        let shift = lo;
        let o2 = o + u * shift;
        self.crossings(o2, u, 0.0, hi - shift, done, &mut |t, i, s| {
            let t = (t + shift) * back;
            if t > EPSILON {
                f(Hit {
                    t,
                    part: i as u32,
                    uv: [s, 0.0],
                });
            }
        });
    }
}

impl Shape for Lathe {
    fn bounds(&self) -> Aabb {
        if self.pieces.is_empty() {
            return Aabb::EMPTY;
        }
        let (r, k) = (self.radius * self.scale, self.scale);
        Aabb::new(
            DVec3::new(-r, self.y[0] * k, -r),
            DVec3::new(r, self.y[1] * k, r),
        )
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        self.each_hit(ray, || false, |h| out.push(h));
    }

    /// The crossings `intersect_all` lists, in its order, each asked as it is found; the
    /// pieces after the one holding the first kept crossing are not solved (a CSG shadow ray
    /// through a lathe stops at its first kept wall instead of refining every crossing).
    fn any_kept(
        &self,
        ray: &Ray,
        tmax: f64,
        _scratch: &mut Vec<Hit>,
        keep: &mut dyn FnMut(f64) -> bool,
    ) -> bool {
        let kept = std::cell::Cell::new(false);
        self.each_hit(
            ray,
            || kept.get(),
            |h| {
                if !kept.get() && h.t < tmax && keep(h.t) {
                    kept.set(true);
                }
            },
        );
        kept.get()
    }

    fn intersect_first(&self, ray: &Ray, tmax: f64, scratch: &mut Vec<Hit>) -> Option<Hit> {
        let setup = self.setup(ray)?;
        if setup.1.y.abs() >= FLAT {
            return self.first_sloped::<true>(setup, tmax, scratch, |_| true);
        }
        scratch.clear();
        self.intersect_all(ray, scratch);
        scratch
            .iter()
            .filter(|h| h.t > EPSILON && h.t < tmax)
            .min_by(|a, b| a.t.total_cmp(&b.t))
            .copied()
    }

    /// A sloped ray's first kept crossing alone, by `first_sloped`'s search (pieces by their
    /// height band's nearest `t`, none past the best refined to the end): it is the crossing
    /// the listing's order would give first, `intersect_first`'s choice among the kept ones.
    /// A nearly horizontal ray lists every crossing.
    fn gather_kept(
        &self,
        ray: &Ray,
        tmax: f64,
        out: &mut Vec<Hit>,
        scratch: &mut Vec<Hit>,
        keep: &mut dyn FnMut(f64) -> bool,
    ) {
        let Some(setup) = self.setup(ray) else {
            return;
        };
        if setup.1.y.abs() >= FLAT {
            out.extend(self.first_sloped::<false>(setup, tmax, scratch, keep));
        } else {
            self.intersect_all(ray, out);
        }
    }

    fn inside(&self, p: DVec3) -> bool {
        let q = p / self.scale;
        let rho = (q.x * q.x + q.z * q.z).sqrt();
        inside_even_odd(&self.pieces, [rho, q.y], true)
    }

    fn normal(&self, p: DVec3, hit: &Hit) -> DVec3 {
        let Some(pc) = self.pieces.get(hit.part as usize) else {
            return DVec3::Y;
        };
        let s = hit.uv[0];
        let (r, tan) = (pc.at(s)[0], pc.tangent(s));
        // The profile as seen in the half plane of the hit: radius |r|.
        let dr = if r < 0.0 { -tan[0] } else { tan[0] };
        let mut m = [tan[1], -dr];
        let q = p / self.scale;
        let rho = (q.x * q.x + q.z * q.z).sqrt();
        let len = (m[0] * m[0] + m[1] * m[1]).sqrt();
        if len > 0.0 {
            let e = 1e-7 / len;
            if inside_even_odd(&self.pieces, [rho + e * m[0], q.y + e * m[1]], true) {
                m = [-m[0], -m[1]];
            }
        }
        if rho > 0.0 {
            DVec3::new(m[0] * q.x / rho, m[1], m[0] * q.z / rho)
        } else {
            DVec3::new(0.0, m[1].signum(), 0.0)
        }
    }
}

/// The crossings of a sloped piece whose equation in the piece's parameter is `f`: its roots
/// in [0, 1] (the ends' values by the unexpanded form), each with the ray's distance.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn sloped_roots(
    f: &[f64],
    pc: &Piece,
    i: usize,
    oy: f64,
    [a, b, c]: [f64; 3],
    dy: f64,
    leave: Option<Leave>,
    found: &mut impl FnMut(f64, usize, f64),
) {
    let end = |q: P2| {
        let e = q[1] - oy;
        dy * dy * (c - q[0] * q[0]) + 2.0 * b * dy * e + a * e * e
    };
    // A crossing's `t` is linear in the piece's height: bounds of the height over a bracket
    // bound it, widened far above the rounding of the quotient, the shift and the scaling
    // (as `first_sloped`'s floors are).
    let mut found_t = |s: f64| {
        let t = (crate::geom::poly::eval(&pc.y, s) - oy) / dy;
        found(t, i, s);
    };
    // Without a `Leave` (the CSG path) the plain search: no settle check in its Newton steps.
    let Some(k) = leave else {
        return sign_changes(f, 0.0, 1.0, end(pc.p0), end(pc.p1), found_t);
    };
    let settle = |s0: f64, s1: f64| -> Option<()> {
        let (y0, y1) = crate::geom::spline2d::hull_on(&pc.y, s0, s1);
        let (t0, t1) = ((y0 - oy) * k.inv_dy, (y1 - oy) * k.inv_dy);
        let (lo, hi) = (t0.min(t1), t0.max(t1));
        let m = 1e-9
            * (lo.abs() + hi.abs() + k.shift.abs() + (y0.abs() + y1.abs() + oy.abs()) / dy.abs());
        let (lo, hi) = ((lo - m + k.shift) * k.back, (hi + m + k.shift) * k.back);
        (hi <= k.after || lo >= k.before || lo > k.past).then_some(())
    };
    sign_changes_until(f, 0.0, 1.0, end(pc.p0), end(pc.p1), settle, |r| {
        if let Ok(s) = r {
            found_t(s);
        }
    });
}

/// The crossings `first_sloped` cannot keep, for `sloped_roots`: those whose `t`, taken back
/// to the ray's (`(t + shift) · back`), is at or below `after`, at or past `before`, or past
/// `past`. `inv_dy` is `1 / dy`.
#[derive(Clone, Copy)]
pub(super) struct Leave {
    shift: f64,
    back: f64,
    inv_dy: f64,
    after: f64,
    before: f64,
    past: f64,
}

#[cfg(test)]
mod tests;
