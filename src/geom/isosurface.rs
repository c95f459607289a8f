//! POV-Ray `isosurface`: where a user function equals the threshold, inside a container box
//! or sphere.
//!
//! The function is known only by evaluation, so crossings are found the way the manual
//! describes POV-Ray's: the stretch of the ray inside the container is split recursively, and
//! a piece is dropped when the function's values at its ends are too far from the threshold
//! for a function whose gradient is at most `max_gradient` to reach it in between. A piece
//! whose ends lie on different sides holds a crossing; pieces are searched nearest first, down
//! to `accuracy`, and the crossing is then polished within that piece. Points where the
//! function is below the threshold are inside. Unless the isosurface is `open`, the
//! container's own surface closes the solid where the function is inside at it.
//!
//! `max_trace` limits how many crossings a ray reports (1 by default: what the first hit needs;
//! CSG wants more, as in POV-Ray); `all_intersections` lifts the limit. The function runs on
//! every render thread at once: `func::Function` evaluates with no shared state.

use std::sync::Arc;

use crate::func::Function;
use crate::geom::{Hit, Shape};
use crate::math::{Aabb, DVec3, Ray, EPSILON};

/// Hit parts: on the function's surface, or on the container's.
const PART_FIELD: u32 = 0;
const PART_CONTAINER: u32 = 1;
/// A ray starting where the function is within reach of the threshold (a shadow, reflected or
/// refracted ray leaving a hit point, which lies up to `accuracy` beyond the root) ignores
/// crossings nearer than this many accuracies: they are the surface it starts on. POV-Ray's
/// own rule is not documented; measured, its shadow rays see such crossings only now and then
/// (up to 12 accuracies away at grazing light), and 8 leaves the fewest differing pixels on
/// the test scenes.
const SELF_CROSSING: f64 = 8.0;
/// Most function evaluations one ray may spend. Where the function stays within reach of the
/// threshold along the ray (a ray lying in the surface of `function { y }`), every piece may
/// hold a crossing and the search would visit all container/accuracy of them: with a tiny
/// accuracy, practically forever. Ordinary rays need hundreds; grazing ones a few thousand.
const MAX_EVALUATIONS: u32 = 100_000;
/// Deepest subdivision: a container 2^60 accuracies long is never searched exhaustively.
const MAX_DEPTH: u32 = 60;

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Container {
    Box { min: DVec3, max: DVec3 },
    Sphere { center: DVec3, radius: f64 },
}

impl Container {
    /// The stretch of the ray `o + s u` inside, or None.
    fn interval(&self, o: DVec3, u: DVec3) -> Option<(f64, f64)> {
        match *self {
            Container::Box { min, max } => {
                let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
                for i in 0..3 {
                    if u[i] != 0.0 {
                        let (a, b) = ((min[i] - o[i]) / u[i], (max[i] - o[i]) / u[i]);
                        lo = lo.max(a.min(b));
                        hi = hi.min(a.max(b));
                    } else if o[i] < min[i] || o[i] > max[i] {
                        return None;
                    }
                }
                (lo < hi).then_some((lo, hi))
            }
            Container::Sphere { center, radius } => {
                let d = o - center;
                let b = d.dot(u);
                let disc = b * b - (d.length_squared() - radius * radius);
                if disc <= 0.0 {
                    return None;
                }
                let h = disc.sqrt();
                Some((-b - h, -b + h))
            }
        }
    }

    fn contains(&self, p: DVec3) -> bool {
        match *self {
            Container::Box { min, max } => p.cmpge(min).all() && p.cmple(max).all(),
            Container::Sphere { center, radius } => {
                (p - center).length_squared() <= radius * radius
            }
        }
    }

    fn bounds(&self) -> Aabb {
        match *self {
            Container::Box { min, max } => Aabb::new(min, max),
            Container::Sphere { center, radius } => {
                Aabb::new(center - DVec3::splat(radius), center + DVec3::splat(radius))
            }
        }
    }

    fn normal(&self, p: DVec3) -> DVec3 {
        match *self {
            Container::Box { min, max } => {
                // The face the point is nearest to, relative to the box's size.
                let c = (min + max) * 0.5;
                let half = ((max - min) * 0.5).max(DVec3::splat(1e-300));
                let q = (p - c) / half;
                let a = q.abs();
                if a.x >= a.y && a.x >= a.z {
                    DVec3::new(q.x.signum(), 0.0, 0.0)
                } else if a.y >= a.z {
                    DVec3::new(0.0, q.y.signum(), 0.0)
                } else {
                    DVec3::new(0.0, 0.0, q.z.signum())
                }
            }
            Container::Sphere { center, .. } => p - center,
        }
    }
}

/// An isosurface as the parser reads it.
#[derive(Clone, Debug)]
pub struct IsoData {
    pub function: Arc<Function>,
    pub container: Container,
    pub threshold: f64,
    pub accuracy: f64,
    pub max_gradient: f64,
    /// `evaluate P0, P1, P2`: POV-Ray adapts the gradient bound while it renders.
    pub evaluate: Option<[f64; 3]>,
    pub open: bool,
    /// Most crossings per ray; `None` for `all_intersections`.
    pub max_trace: Option<u32>,
}

#[derive(Debug)]
pub struct Isosurface {
    data: IsoData,
    /// The gradient bound the search uses.
    gradient: f64,
    accuracy: f64,
    /// Nothing to hit: an empty container.
    empty: bool,
}

impl Isosurface {
    pub fn new(data: &IsoData) -> Isosurface {
        let accuracy = if data.accuracy > 0.0 && data.accuracy.is_finite() {
            data.accuracy
        } else {
            1e-6
        };
        let mut gradient = if data.max_gradient > 0.0 && data.max_gradient.is_finite() {
            data.max_gradient
        } else {
            1.1
        };
        let b = data.container.bounds();
        let empty = !(b.max.cmpgt(b.min).all() && b.min.is_finite() && b.max.is_finite());
        let mut iso = Isosurface {
            data: data.clone(),
            gradient,
            accuracy,
            empty,
        };
        if let (Some([p0, p1, _]), false) = (data.evaluate, empty) {
            // POV-Ray starts from P0 and raises the bound while it renders, by P1 over what it
            // finds. A render-order dependent estimate cannot be reproduced; sampling the
            // function's gradient over the container gives the bound it settles on.
            let found = iso.sampled_gradient(24);
            gradient = p0.max(found * p1.max(1.0));
            if gradient > 0.0 && gradient.is_finite() {
                iso.gradient = gradient;
            }
        }
        iso
    }

    /// The function minus the threshold: negative inside. NaN counts as far outside, so the
    /// search drops it at once.
    fn f(&self, p: DVec3) -> f64 {
        let v = self.data.function.eval_point([p.x, p.y, p.z]) - self.data.threshold;
        if v.is_nan() {
            f64::INFINITY
        } else {
            v
        }
    }

    /// The largest gradient magnitude seen by differences on an n³ grid over the container.
    fn sampled_gradient(&self, n: usize) -> f64 {
        let b = self.data.container.bounds();
        let size = b.max - b.min;
        let h = size / n as f64;
        let mut best: f64 = 0.0;
        for i in 0..n {
            for j in 0..n {
                for k in 0..n {
                    let p = b.min + h * DVec3::new(i as f64, j as f64, k as f64);
                    let f0 = self.f(p);
                    let g = DVec3::new(
                        self.f(p + DVec3::X * h.x) - f0,
                        self.f(p + DVec3::Y * h.y) - f0,
                        self.f(p + DVec3::Z * h.z) - f0,
                    ) / h;
                    let m = g.length();
                    if m.is_finite() {
                        best = best.max(m);
                    }
                }
            }
        }
        best
    }

    /// Crossings of the ray (object space) with t in (EPSILON, tmax), nearest first, at most
    /// `limit` of them.
    fn crossings(&self, ray: &Ray, tmax: f64, limit: usize, out: &mut Vec<Hit>) {
        if self.empty || limit == 0 {
            return;
        }
        let len = ray.dir.length();
        if !(len > 0.0 && len.is_finite() && ray.origin.is_finite()) {
            return;
        }
        let u = ray.dir / len;
        let Some((c0, c1)) = self.data.container.interval(ray.origin, u) else {
            return;
        };
        let min_s = EPSILON * len;
        let lo = c0.max(min_s);
        let hi = c1.min(tmax * len);
        if lo.is_nan() || hi.is_nan() || lo >= hi {
            return;
        }
        let start = out.len();
        let push = |out: &mut Vec<Hit>, s: f64, part: u32| {
            out.push(Hit::with_part(s / len, part));
            out.len() - start >= limit
        };
        let at = |s: f64| ray.origin + u * s;
        let f_lo = self.f(at(lo));
        // Entering the container where the function is inside: its wall is the surface.
        if !self.data.open && c0 > min_s && f_lo < 0.0 && push(out, lo, PART_CONTAINER) {
            return;
        }
        let f_hi = self.f(at(hi));
        let mut search = Search {
            iso: self,
            o: ray.origin,
            u,
            found: Vec::new(),
            limit: limit - (out.len() - start),
            skip: if c0 <= min_s && f_lo.abs() <= self.gradient * self.accuracy * SELF_CROSSING {
                lo + self.accuracy * SELF_CROSSING
            } else {
                f64::NEG_INFINITY
            },
            budget: MAX_EVALUATIONS,
        };
        search.run(lo, f_lo, hi, f_hi, 0);
        for s in std::mem::take(&mut search.found) {
            if push(out, s, PART_FIELD) {
                return;
            }
        }
        // Leaving through the wall while inside.
        if !self.data.open && c1 <= tmax * len && f_hi < 0.0 {
            push(out, hi, PART_CONTAINER);
        }
    }
}

/// One ray's recursive search, collecting crossings (distances along the unit direction).
struct Search<'a> {
    iso: &'a Isosurface,
    o: DVec3,
    u: DVec3,
    found: Vec<f64>,
    limit: usize,
    /// Crossings nearer than this are the surface the ray starts on (see `SELF_CROSSING`).
    skip: f64,
    /// Function evaluations left for this ray (see `MAX_EVALUATIONS`).
    budget: u32,
}

impl Search<'_> {
    fn f(&self, s: f64) -> f64 {
        self.iso.f(self.o + self.u * s)
    }

    /// Searches [a, b] (function values fa, fb) nearest part first; false once enough
    /// crossings were found.
    fn run(&mut self, a: f64, fa: f64, b: f64, fb: f64, depth: u32) -> bool {
        if self.found.len() >= self.limit {
            return false;
        }
        let len = b - a;
        let sides_differ = (fa < 0.0) != (fb < 0.0);
        if !sides_differ {
            // Both ends on one side: a crossing needs the function to travel |fa| + |fb| in
            // between, at most max_gradient per unit.
            if fa.abs() + fb.abs() > self.iso.gradient * len || fa.is_infinite() {
                return true;
            }
            if len <= self.iso.accuracy || depth >= MAX_DEPTH {
                return true;
            }
        } else if len <= self.iso.accuracy || depth >= MAX_DEPTH {
            // POV-Ray reports the far end of the final piece (measured: its hit points lie
            // up to `accuracy` beyond the root, on dyadic fractions of the container stretch),
            // and the normal there; so does lancer, for the same shading.
            if b > self.skip {
                self.found.push(b);
            }
            return self.found.len() < self.limit;
        }
        if self.budget == 0 {
            return false;
        }
        self.budget -= 1;
        let m = 0.5 * (a + b);
        let fm = self.f(m);
        self.run(a, fa, m, fm, depth + 1) && self.run(m, fm, b, fb, depth + 1)
    }
}

impl Shape for Isosurface {
    fn bounds(&self) -> Aabb {
        if self.empty {
            Aabb::EMPTY
        } else {
            self.data.container.bounds()
        }
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        let limit = self
            .data
            .max_trace
            .map_or(usize::MAX, |n| n.max(1) as usize);
        self.crossings(ray, f64::INFINITY, limit, out);
    }

    fn intersect_first(&self, ray: &Ray, tmax: f64, scratch: &mut Vec<Hit>) -> Option<Hit> {
        scratch.clear();
        self.crossings(ray, tmax, 1, scratch);
        scratch.first().copied().filter(|h| h.t < tmax)
    }

    fn inside(&self, p: DVec3) -> bool {
        !self.empty && self.data.container.contains(p) && self.f(p) < 0.0
    }

    fn normal(&self, p: DVec3, hit: &Hit) -> DVec3 {
        if hit.part == PART_CONTAINER {
            return self.data.container.normal(p);
        }
        // Forward differences with the accuracy as the step: matches povray's shading exactly
        // (measured on a rippled surface with accuracy 0.02, where other steps or central
        // differences visibly differ).
        let h = self.accuracy;
        let f0 = self.f(p);
        let n = DVec3::new(
            self.f(p + DVec3::X * h) - f0,
            self.f(p + DVec3::Y * h) - f0,
            self.f(p + DVec3::Z * h) - f0,
        );
        if n.is_finite() && n != DVec3::ZERO {
            n
        } else {
            DVec3::Y
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::func::{BinOp, Expr};

    fn slot(i: usize) -> Box<Expr> {
        Box::new(Expr::Slot(i))
    }

    fn mul(a: Box<Expr>, b: Box<Expr>) -> Box<Expr> {
        Box::new(Expr::Bin(BinOp::Mul, a, b))
    }

    fn add(a: Box<Expr>, b: Box<Expr>) -> Box<Expr> {
        Box::new(Expr::Bin(BinOp::Add, a, b))
    }

    /// sqrt(x² + y² + z²): a sphere of radius `threshold`.
    fn radius_fn() -> Arc<Function> {
        let sq = add(
            add(mul(slot(0), slot(0)), mul(slot(1), slot(1))),
            mul(slot(2), slot(2)),
        );
        let e = Expr::Math1(crate::func::Math1::Sqrt, sq);
        Arc::new(Function::from_expr(
            vec!["x".into(), "y".into(), "z".into()],
            &e,
            3,
        ))
    }

    fn iso(container: Container, threshold: f64, open: bool) -> Isosurface {
        Isosurface::new(&IsoData {
            function: radius_fn(),
            container,
            threshold,
            accuracy: 0.001,
            max_gradient: 1.1,
            evaluate: None,
            open,
            max_trace: None,
        })
    }

    fn unit_box() -> Container {
        Container::Box {
            min: DVec3::splat(-1.0),
            max: DVec3::splat(1.0),
        }
    }

    fn hits(s: &Isosurface, o: DVec3, d: DVec3) -> Vec<Hit> {
        let mut v = Vec::new();
        s.intersect_all(&Ray::new(o, d), &mut v);
        v
    }

    #[test]
    fn sphere_within_accuracy_beyond_the_root() {
        let s = iso(unit_box(), 0.5, false);
        let h = hits(&s, DVec3::new(0.1, 0.0, -5.0), DVec3::Z * 2.0);
        assert_eq!(h.len(), 2, "{h:?}");
        let root = (5.0 - (0.25f64 - 0.01).sqrt()) / 2.0;
        // Found at the far end of the last piece: past the root by less than the accuracy.
        assert!(
            h[0].t >= root && h[0].t < root + 0.001 / 2.0,
            "{h:?} {root}"
        );
        let n = s.normal(
            Ray::new(DVec3::new(0.1, 0.0, -5.0), DVec3::Z * 2.0).at(h[0].t),
            &h[0],
        );
        assert!((n.normalize() - DVec3::new(0.1, 0.0, -0.49).normalize()).length() < 0.01);
        assert!(s.inside(DVec3::ZERO) && !s.inside(DVec3::splat(0.4)));
        // The first hit alone, and none before tmax.
        let r = Ray::new(DVec3::new(0.1, 0.0, -5.0), DVec3::Z * 2.0);
        let first = s
            .intersect_first(&r, f64::INFINITY, &mut Vec::new())
            .unwrap();
        assert_eq!(first.t, h[0].t);
        assert!(s.intersect_first(&r, root * 0.9, &mut Vec::new()).is_none());
    }

    #[test]
    fn container_walls_close_the_solid_unless_open() {
        // Radius 2 overflows the unit box: the box itself is what is seen, unless open.
        let closed = iso(unit_box(), 2.0, false);
        let h = hits(&closed, DVec3::new(0.2, 0.3, -5.0), DVec3::Z);
        assert_eq!(h.len(), 2);
        assert!((h[0].t - 4.0).abs() < 1e-12 && (h[1].t - 6.0).abs() < 1e-12);
        assert_eq!(h[0].part, PART_CONTAINER);
        let n = closed.normal(DVec3::new(0.2, 0.3, -1.0), &h[0]);
        assert_eq!(n, DVec3::NEG_Z);
        let open = iso(unit_box(), 2.0, true);
        assert!(hits(&open, DVec3::new(0.2, 0.3, -5.0), DVec3::Z).is_empty());
        // A sphere container cut by a smaller sphere, seen through its wall.
        let s = iso(
            Container::Sphere {
                center: DVec3::ZERO,
                radius: 0.5,
            },
            0.8,
            false,
        );
        let h = hits(&s, DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
        assert!((h[0].t - 4.5).abs() < 1e-12);
    }

    #[test]
    fn max_trace_and_rays_from_inside() {
        let mut data = IsoData {
            function: radius_fn(),
            container: unit_box(),
            threshold: 0.5,
            accuracy: 0.001,
            max_gradient: 1.1,
            evaluate: None,
            open: false,
            max_trace: Some(1),
        };
        let one = Isosurface::new(&data);
        assert_eq!(hits(&one, DVec3::new(0.0, 0.0, -5.0), DVec3::Z).len(), 1);
        data.max_trace = Some(2);
        let two = Isosurface::new(&data);
        assert_eq!(hits(&two, DVec3::new(0.0, 0.0, -5.0), DVec3::Z).len(), 2);
        // From the centre outwards: the one crossing, just beyond the surface.
        let h = hits(&two, DVec3::ZERO, DVec3::X);
        assert_eq!(h.len(), 1);
        assert!(h[0].t >= 0.5 && h[0].t < 0.501, "{h:?}");
        // From a point just inside the surface: that surface is not hit again.
        assert!(hits(&two, DVec3::new(0.4999, 0.0, 0.0), DVec3::X).is_empty());
    }

    #[test]
    fn bad_input_never_hangs_or_panics() {
        let nan = Arc::new(Function::from_expr(
            vec!["x".into(), "y".into(), "z".into()],
            &Expr::Const(f64::NAN),
            3,
        ));
        let s = Isosurface::new(&IsoData {
            function: nan,
            container: unit_box(),
            threshold: 0.0,
            accuracy: 0.0,
            max_gradient: -1.0,
            evaluate: Some([f64::NAN, 1.0, 1.0]),
            open: false,
            max_trace: None,
        });
        assert!(hits(&s, DVec3::new(0.0, 0.0, -5.0), DVec3::Z).is_empty());
        assert!(!s.inside(DVec3::ZERO));
        let flat = iso(
            Container::Box {
                min: DVec3::ZERO,
                max: DVec3::new(1.0, 0.0, 1.0),
            },
            0.5,
            false,
        );
        assert!(flat.bounds().is_empty());
        assert!(hits(&flat, DVec3::new(0.5, 5.0, 0.5), DVec3::NEG_Y).is_empty());
        let s = iso(unit_box(), 0.5, false);
        assert!(hits(&s, DVec3::splat(f64::NAN), DVec3::Z).is_empty());
        assert!(hits(&s, DVec3::ZERO, DVec3::ZERO).is_empty());
        // A ray lying in the surface of `function { y }` with a tiny accuracy: every piece may
        // hold a crossing; the evaluation budget ends the search.
        let flat = Isosurface::new(&IsoData {
            function: Arc::new(Function::from_expr(
                vec!["x".into(), "y".into(), "z".into()],
                &Expr::Slot(1),
                3,
            )),
            container: unit_box(),
            threshold: 0.0,
            accuracy: 1e-300,
            max_gradient: 1.1,
            evaluate: None,
            open: true,
            max_trace: None,
        });
        let t0 = std::time::Instant::now();
        hits(&flat, DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
        assert!(t0.elapsed().as_secs_f64() < 5.0);
    }

    #[test]
    fn evaluate_raises_a_too_low_gradient() {
        // |grad| of 10·r is 10: with max_gradient 1.1 the search misses, evaluate finds it.
        let ten = Arc::new(Function::from_expr(
            vec!["x".into(), "y".into(), "z".into()],
            &Expr::Bin(
                BinOp::Mul,
                Box::new(Expr::Const(10.0)),
                Box::new(Expr::Call(
                    radius_fn(),
                    vec![Expr::Slot(0), Expr::Slot(1), Expr::Slot(2)],
                )),
            ),
            3,
        ));
        let data = IsoData {
            function: ten,
            container: unit_box(),
            threshold: 5.0,
            accuracy: 0.001,
            max_gradient: 1.1,
            evaluate: Some([1.0, 1.2, 0.7]),
            open: false,
            max_trace: None,
        };
        let s = Isosurface::new(&data);
        assert!(s.gradient >= 10.0, "{}", s.gradient);
        assert_eq!(hits(&s, DVec3::new(0.0, 0.0, -5.0), DVec3::Z).len(), 2);
    }
}
