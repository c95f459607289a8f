//! POV-Ray `torus { major, minor [sturm] }`: in the XZ plane around the y axis, at the origin.
//!
//! The crossings are the real roots of a quartic in the ray parameter. Three things keep them
//! accurate enough that silhouettes show neither speckles nor holes:
//! * the problem is scaled so the bounding sphere has radius 1 and the direction made unit,
//!   so the coefficients are of order 1 whatever the scene units;
//! * the ray origin is first moved to where the ray enters the bounding volume (sphere of
//!   radius major + minor cut by the slab |y| <= minor), and that offset added back to t
//!   afterwards, so the quartic is never evaluated with a far-away origin;
//! * roots are isolated on that short interval and polished, rather than taken from a closed
//!   form (see `poly`). `sturm` adds a Sturm-sequence search for exact tangencies (double
//!   roots without a sign change); it is slower and visually the same.

use crate::geom::bernstein::surely_no_root_quartic_from_zero;
use crate::geom::poly::{
    first_root_with_unchecked, roots_in, roots_in_isolated, sturm_roots_in, Roots,
};
use crate::geom::{Hit, Shape};
use crate::math::{by_coordinates, Aabb, DVec3, Ray, EPSILON};

/// Widening of the bounding interval, in units of the bounding radius, so a root lying
/// exactly where the torus touches its bounds is not lost to the endpoint's rounding.
const MARGIN: f64 = 1e-7;

/// How far inside the hole's cylinder (`rho² < (major - minor)²`, in the unit-scaled
/// variables) both ends of a ray's search interval must lie for `Torus::setup` to call it a
/// miss without solving: `rho² <= (1 - HOLE_SLACK)·(major - minor)²`.
const HOLE_SLACK: f64 = 1e-6;

/// The least lower bound of the quartic on such an interval (`minor · (major - minor)² ·
/// HOLE_SLACK`, see `Torus::new`) for which the hole test is used: far above the rounding of
/// the quartic's coefficients and of its evaluations there (a few 1e-13 in these units).
const HOLE_FLOOR: f64 = 1e-10;

#[derive(Clone, Copy, Debug)]
pub struct Torus {
    major: f64,
    minor: f64,
    sturm: bool,
    /// Non-positive or non-finite minor radius: nothing to hit.
    empty: bool,
    /// `(1 - HOLE_SLACK)·(major - minor)²` in the unit-scaled variables, or -1 where the hole
    /// test is not used (see `Torus::setup`).
    hole2: f64,
    /// `setup`'s constants of the torus, worked out once with the same operations instead of
    /// on every ray (two divisions and three products of its chain): the bounding radius
    /// `major + minor`, the radii in its units, their squares and `4·big²`.
    scale: f64,
    big: f64,
    small: f64,
    big2: f64,
    small2: f64,
    r2: f64,
}

impl Torus {
    /// Radii are taken by magnitude. A zero minor radius gives an empty shape; a zero major
    /// radius gives the sphere the quartic degenerates to. A minor radius larger than the major
    /// one gives POV-Ray's self-intersecting spindle torus (all quartic roots are reported).
    pub fn new(major: f64, minor: f64, sturm: bool) -> Torus {
        let (major, minor) = (major.abs(), minor.abs());
        let empty = !(minor > 0.0 && minor.is_finite() && major.is_finite());
        // Inside the hole, at rho <= h·sqrt(1 - HOLE_SLACK) with h = major - minor (scaled so
        // major + minor = 1), the quartic is ((rho - major)² + y² - minor²)·((rho + major)² +
        // y² - minor²) >= (minor·h·HOLE_SLACK)·h: positive by far more than its rounding
        // wherever that bound clears HOLE_FLOOR. Sturm tori keep their own search.
        let scale = major + minor;
        let (big, small) = (major / scale, minor / scale);
        let h = big - small;
        let hole2 = if !empty && !sturm && h > 0.0 && small * h * h * HOLE_SLACK >= HOLE_FLOOR {
            (1.0 - HOLE_SLACK) * h * h
        } else {
            -1.0
        };
        Torus {
            major,
            minor,
            sturm,
            empty,
            hole2,
            scale,
            big,
            small,
            big2: big * big,
            small2: small * small,
            r2: 4.0 * big * big,
        }
    }

    /// Crossings as t values (ray units), increasing, with t > EPSILON.
    pub fn crossings(&self, ray: &Ray, out: &mut [f64; 4]) -> usize {
        let Some(q) = self.setup(ray) else {
            return 0;
        };
        let roots = match &q.poly {
            // Degenerate to a sphere: the quartic is a perfect square whose double roots the
            // sign-change search would miss.
            Poly::Sphere(c) => roots_in(c, 0.0, q.hi),
            Poly::Quartic(c) if self.sturm => sturm_roots_in(c, 0.0, q.hi),
            // The solvers' own `surely_no_root` shortcut, asked here written out for the
            // quartic on [0, hi] (the same answer), then the solvers without it.
            Poly::Quartic(c) if surely_no_root_quartic_from_zero(c, q.hi) => Roots::new(),
            Poly::Quartic(c) => roots_in_isolated(c, 0.0, q.hi),
        };
        let mut n = 0;
        for &s in roots.iter() {
            let t = q.to_t(s);
            if t > EPSILON && n < 4 {
                out[n] = t;
                n += 1;
            }
        }
        n
    }

    /// The first of `crossings` if it is below `tmax`, the same bits; the others neither
    /// found nor polished (`first_root_with`). A root `s` of the shifted variable lies in its
    /// bracket `[a, b]`, and `to_t` rounds monotonically (`s >= a` gives `t >= to_t(a)`), so a
    /// walk that reaches a bracket starting at or past `tmax`, or an interval starting there,
    /// has nothing below it to find: it stops unpolished (a shadow ray's light, or a nearer
    /// hit, before the torus).
    ///
    /// `settle`: a bracket `[a, b]` with `to_t(a) > EPSILON` and `to_t(b) < tmax` is answered
    /// with `to_t(a)` unpolished, for a caller that asks only whether there is a crossing (it
    /// holds the walk's first kept root, whose `t` lies in `[to_t(a), to_t(b)]`).
    #[inline(always)]
    fn first_below(&self, ray: &Ray, tmax: f64, settle: bool) -> Option<f64> {
        let q = self.setup(ray)?;
        let c = match &q.poly {
            Poly::Quartic(c) if !self.sturm => c,
            _ => {
                let mut t = [0.0; 4];
                let n = self.crossings(ray, &mut t);
                return t[..n].first().copied().filter(|&t| t < tmax);
            }
        };
        if q.to_t(0.0) >= tmax || surely_no_root_quartic_from_zero(c, q.hi) {
            return None;
        }
        let mut past = false;
        let s = first_root_with_unchecked(c, 0.0, q.hi, |cand| {
            if q.to_t(cand.a) >= tmax {
                past = true;
                return Some(cand.a);
            }
            if settle && q.to_t(cand.a) > EPSILON && q.to_t(cand.b) < tmax {
                return Some(cand.a);
            }
            let s = cand.root();
            (q.to_t(s) > EPSILON).then_some(s)
        })?;
        let t = q.to_t(s);
        (!past && t < tmax).then_some(t)
    }

    /// The first of `crossings` below `tmax` that `keep` holds for, asking `keep` of those
    /// before it in order; `None` when the walk does not apply (`sturm`, a sphere's square),
    /// where the caller lists. Roots come nearest first, each polished only when the walk
    /// reaches it (`first_root_with`, the same bits as `roots_in`), with `crossings`' filters
    /// replayed on the way: `Roots::push`'s merge of a root equal to the one before,
    /// `t > EPSILON`, and at most four crossings.
    #[inline(always)]
    fn first_kept(
        &self,
        ray: &Ray,
        tmax: f64,
        keep: &mut dyn FnMut(f64) -> bool,
    ) -> Option<Option<f64>> {
        let Some(q) = self.setup(ray) else {
            return Some(None);
        };
        let c = match &q.poly {
            Poly::Quartic(c) if !self.sturm && surely_no_root_quartic_from_zero(c, q.hi) => {
                return Some(None);
            }
            Poly::Quartic(c) if !self.sturm => c,
            _ => return None,
        };
        let (mut last, mut listed, mut found) = (None, 0, None);
        first_root_with_unchecked(c, 0.0, q.hi, |cand| {
            let s = cand.root();
            if last == Some(s) {
                return None;
            }
            last = Some(s);
            let t = q.to_t(s);
            if t.is_nan() || t <= EPSILON {
                return None;
            }
            // Roots increase, and `t` with them: none after this one is below `tmax`.
            if listed == 4 || t >= tmax {
                return Some(s);
            }
            listed += 1;
            found = keep(t).then_some(t);
            found.map(|_| s)
        });
        Some(found)
    }

    /// The polynomial whose roots in `[0, hi]` are the crossings, in the shifted and scaled
    /// variable of the module's notes; None when the ray misses the bounds.
    #[inline(always)]
    fn setup(&self, ray: &Ray) -> Option<Setup> {
        if self.empty {
            return None;
        }
        // Each coordinate by its own 8-byte load: a transformed ray was just stored as an x-y
        // pair and z, and the y-z pairs LLVM read back could not be forwarded from those two
        // stores (a sixth of this function's samples on sign).
        let (dir, origin) = (by_coordinates(&ray.dir), by_coordinates(&ray.origin));
        let len = dir.length();
        if !(len > 0.0 && len.is_finite()) {
            return None;
        }
        let scale = self.scale;
        let u = dir / len;
        let o = origin / scale;
        let (big, small) = (self.big, self.small);

        // Interval of the ray (unit-scaled distance) inside the bounding sphere and slab.
        let b = o.dot(u);
        let closest = o - u * b;
        let disc = 1.0 - closest.length_squared();
        if disc < -MARGIN {
            return None;
        }
        let half = disc.max(0.0).sqrt();
        let (mut lo, mut hi) = (-b - half, -b + half);
        if u.y != 0.0 {
            let (y0, y1) = ((-small - o.y) / u.y, (small - o.y) / u.y);
            lo = lo.max(y0.min(y1));
            hi = hi.min(y0.max(y1));
        } else if o.y.abs() > small {
            return None;
        }
        // Distances not beyond EPSILON in ray units are self-intersections.
        let min_dist = EPSILON * len / scale;
        lo = (lo - MARGIN).max(min_dist);
        hi += MARGIN;
        // Written to also reject NaN from a non-finite origin.
        if lo.is_nan() || hi.is_nan() || lo > hi {
            return None;
        }

        let shift = lo;
        let p = o + u * shift;
        let span = hi - shift;
        // Both ends of the interval in the hole's cylinder: so is all of it (rho² is convex
        // along a line), where the quartic has no root and the solvers would find none.
        let end = p + u * span;
        if p.x * p.x + p.z * p.z < self.hole2 && end.x * end.x + end.z * end.z < self.hole2 {
            return None;
        }
        let poly = if big == 0.0 {
            let c = p.length_squared() - self.small2;
            Poly::Sphere([c, 2.0 * p.dot(u), 1.0])
        } else {
            let k = p.length_squared() + self.big2 - self.small2;
            let b = p.dot(u);
            let r2 = self.r2;
            Poly::Quartic([
                k * k - r2 * (p.x * p.x + p.z * p.z),
                4.0 * b * k - 2.0 * r2 * (p.x * u.x + p.z * u.z),
                4.0 * b * b + 2.0 * k - r2 * (u.x * u.x + u.z * u.z),
                4.0 * b,
                1.0,
            ])
        };
        Some(Setup {
            poly,
            hi: span,
            shift,
            scale,
            len,
        })
    }
}

/// The polynomial of a ray's crossings: a quartic, or for a zero major radius the sphere's
/// quadratic.
enum Poly {
    Sphere([f64; 3]),
    Quartic([f64; 5]),
}

/// `Torus::setup`'s answer: the polynomial, the end of its interval (the start is 0), and
/// what turns its variable back into the ray's `t`.
struct Setup {
    poly: Poly,
    hi: f64,
    shift: f64,
    scale: f64,
    len: f64,
}

impl Setup {
    /// The ray's `t` of root `s`.
    #[inline(always)]
    fn to_t(&self, s: f64) -> f64 {
        (s + self.shift) * self.scale / self.len
    }
}

impl Shape for Torus {
    fn bounds(&self) -> Aabb {
        if self.empty {
            return Aabb::EMPTY;
        }
        let r = self.major + self.minor;
        Aabb::new(
            DVec3::new(-r, -self.minor, -r),
            DVec3::new(r, self.minor, r),
        )
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        let mut t = [0.0; 4];
        let n = self.crossings(ray, &mut t);
        out.extend(t[..n].iter().map(|&t| Hit::new(t)));
    }

    fn intersect_first(&self, ray: &Ray, tmax: f64, _scratch: &mut Vec<Hit>) -> Option<Hit> {
        self.first_below(ray, tmax, false).map(Hit::new)
    }

    /// `intersect_first(..).is_some()`, a root's polish left out where its bracket settles
    /// the answer (`first_below`'s `settle`): shadow rays.
    fn any_hit(&self, ray: &Ray, tmax: f64, _scratch: &mut Vec<Hit>) -> bool {
        self.first_below(ray, tmax, true).is_some()
    }

    /// The crossings `intersect_all` lists, nearest first, to the first kept (`first_kept`):
    /// a CSG shadow ray whose first kept crossing is the torus's nearest does not polish the
    /// other two or three.
    fn any_kept(
        &self,
        ray: &Ray,
        tmax: f64,
        scratch: &mut Vec<Hit>,
        keep: &mut dyn FnMut(f64) -> bool,
    ) -> bool {
        match self.first_kept(ray, tmax, keep) {
            Some(found) => found.is_some(),
            None => {
                scratch.clear();
                self.intersect_all(ray, scratch);
                scratch.iter().any(|h| h.t < tmax && keep(h.t))
            }
        }
    }

    /// The least kept crossing below `tmax` alone (`first_kept`): the CSG search takes a
    /// member's least kept crossing, so the others cannot change its answer.
    fn gather_kept(
        &self,
        ray: &Ray,
        tmax: f64,
        out: &mut Vec<Hit>,
        _scratch: &mut Vec<Hit>,
        keep: &mut dyn FnMut(f64) -> bool,
    ) {
        match self.first_kept(ray, tmax, keep) {
            Some(found) => out.extend(found.map(Hit::new)),
            None => self.intersect_all(ray, out),
        }
    }

    fn inside(&self, p: DVec3) -> bool {
        if self.empty {
            return false;
        }
        let rho = (p.x * p.x + p.z * p.z).sqrt() - self.major;
        rho * rho + p.y * p.y < self.minor * self.minor
    }

    fn normal(&self, p: DVec3, _hit: &Hit) -> DVec3 {
        // Away from the tube's centre circle; unlike the quartic's gradient this does not
        // vanish or lose digits, and it is the same direction on a regular torus.
        let rho = (p.x * p.x + p.z * p.z).sqrt();
        if rho > 0.0 {
            let f = self.major / rho;
            DVec3::new(p.x * (1.0 - f), p.y, p.z * (1.0 - f))
        } else if p.y != 0.0 {
            DVec3::new(0.0, p.y, 0.0)
        } else {
            DVec3::Y
        }
    }
}

#[cfg(test)]
mod tests;
