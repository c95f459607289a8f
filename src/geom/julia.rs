//! POV-Ray `julia_fractal`: the 3-D slice of a 4-D Julia set in quaternion or hypercomplex
//! algebra.
//!
//! A 3-D point (x, y, z) is lifted onto the slice hyperplane `n · h = d` (its 4th coordinate
//! chosen to satisfy the equation, as "projecting the intersection to 3-D space" means) and
//! the map `h ← f(h) + p` iterated. Rules measured on the povray binary
//! (tests/probes/julia_fractal.pov, docs/implicit-objects.md):
//! * the iteration runs `max_iteration - 1` times and a point escapes when `|h| > 4`
//!   (hypercomplex `sqr`, p = 0: radius 4^(1/2^(N-1)) for N = 2, 3, 4);
//! * everything lies in the sphere of radius 2 (N = 1 fills exactly that ball);
//! * the quaternion algebra uses the distance estimate `|h| ln|h| / (2 |h'|)`, whose sign
//!   gives the surface: with p = 0 its surface is the unit sphere for every N >= 2, and
//!   N = 1 shows nothing; the surface lies where the estimate is -1/(16 precision^2) (the
//!   unit sphere shrinks to radius 0.865 at precision 1, 0.97 at 2, 0.995 at 5).
//!
//! Crossings are found by marching from where the ray enters the bounding sphere: by the
//! distance estimate where the orbit escapes (quaternion), else by steps of 1/precision, and
//! each change of inside-ness narrowed by bisection. The hypercomplex algebra is commutative
//! and splits into two complex planes (`h = e1 z1 + e2 z2`, e1,2 = (1 ∓ k)/2), so its
//! functions are the complex ones applied to both halves.

use num_complex::Complex64 as C;

use crate::geom::{Hit, Shape};
use crate::math::{Aabb, DVec3, Ray, EPSILON};

/// Escape radius of the orbit and radius of the bounding sphere (measured, see above).
const BAILOUT: f64 = 4.0;
const BOUND: f64 = 2.0;
/// Bisection steps for a crossing: 2^-40 of a march step is far below a pixel.
const BISECT: u32 = 40;

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Algebra {
    Quaternion,
    Hypercomplex,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum JuliaFn {
    Sqr,
    Cube,
    Exp,
    Reciprocal,
    Sin,
    Asin,
    Sinh,
    Asinh,
    Cos,
    Acos,
    Cosh,
    Acosh,
    Tan,
    Atan,
    Tanh,
    Atanh,
    Ln,
    Pwr(f64, f64),
}

impl JuliaFn {
    fn apply(self, z: C) -> C {
        match self {
            JuliaFn::Sqr => z * z,
            JuliaFn::Cube => z * z * z,
            JuliaFn::Exp => z.exp(),
            JuliaFn::Reciprocal => z.inv(),
            JuliaFn::Sin => z.sin(),
            JuliaFn::Asin => z.asin(),
            JuliaFn::Sinh => z.sinh(),
            JuliaFn::Asinh => z.asinh(),
            JuliaFn::Cos => z.cos(),
            JuliaFn::Acos => z.acos(),
            JuliaFn::Cosh => z.cosh(),
            JuliaFn::Acosh => z.acosh(),
            JuliaFn::Tan => z.tan(),
            JuliaFn::Atan => z.atan(),
            JuliaFn::Tanh => z.tanh(),
            JuliaFn::Atanh => z.atanh(),
            JuliaFn::Ln => z.ln(),
            JuliaFn::Pwr(x, y) => {
                if z == C::new(0.0, 0.0) {
                    z
                } else {
                    (C::new(x, y) * z.ln()).exp()
                }
            }
        }
    }
}

#[derive(Clone, Debug)]
pub struct Julia {
    pub param: [f64; 4],
    pub algebra: Algebra,
    pub func: JuliaFn,
    pub max_iteration: u32,
    pub precision: f64,
    /// Unit slice normal and distance.
    pub slice: ([f64; 4], f64),
    /// Orthonormal axes of the slice hyperplane for x, y and z: the 4-D axes with the
    /// normal's component removed, Gram-Schmidt in that order.
    basis: [[f64; 4]; 3],
    /// The field value below which a point is inside.
    threshold: f64,
}

/// What the iteration says about a point.
struct Orbit {
    /// Signed: negative inside.
    value: f64,
    /// A distance the ray may safely advance, when known.
    step: Option<f64>,
}

impl Julia {
    /// `slice` is normalised here; a zero 4th component is replaced by POV-Ray's default
    /// (the parser warns).
    pub fn new(
        param: [f64; 4],
        algebra: Algebra,
        func: JuliaFn,
        max_iteration: u32,
        precision: f64,
        slice: ([f64; 4], f64),
    ) -> Julia {
        let (n, d) = slice;
        let len = n.iter().map(|x| x * x).sum::<f64>().sqrt();
        let slice = if len > 0.0 && n[3] != 0.0 && len.is_finite() {
            (n.map(|x| x / len), d / len)
        } else {
            ([0.0, 0.0, 0.0, 1.0], 0.0)
        };
        let n = slice.0;
        let dot = |a: &[f64; 4], b: &[f64; 4]| (0..4).map(|i| a[i] * b[i]).sum::<f64>();
        let mut basis = [[0.0; 4]; 3];
        for k in 0..3 {
            let mut e = [0.0; 4];
            e[k] = 1.0;
            let mut v = e;
            for b in std::iter::once(&n).chain(basis[..k].iter()) {
                let c = dot(&e, b);
                v.iter_mut().zip(b).for_each(|(x, y)| *x -= c * y);
            }
            let len = dot(&v, &v).sqrt();
            basis[k] = v.map(|x| x / len);
        }
        Julia {
            basis,
            param,
            algebra,
            func,
            max_iteration,
            precision: precision.max(1.0),
            slice,
            threshold: match algebra {
                // Measured: with p = 0 the sphere's radius is 1 - 0.13/precision^2, where
                // the estimate is -1/(16 precision^2) (precision 1, 1.5, 2, 3, 5).
                Algebra::Quaternion => -1.0 / (16.0 * precision.max(1.0).powi(2)),
                Algebra::Hypercomplex => 0.0,
            },
        }
    }

    fn lift(&self, p: DVec3) -> [f64; 4] {
        let (b, o) = (&self.basis, self.slice.0.map(|x| x * self.slice.1));
        std::array::from_fn(|i| o[i] + b[0][i] * p.x + b[1][i] * p.y + b[2][i] * p.z)
    }

    fn orbit(&self, p: DVec3) -> Orbit {
        let mut h = self.lift(p);
        let c = self.param;
        let iters = self.max_iteration.saturating_sub(1);
        let norm = |h: &[f64; 4]| (h[0] * h[0] + h[1] * h[1] + h[2] * h[2] + h[3] * h[3]).sqrt();
        match self.algebra {
            Algebra::Quaternion => {
                if self.max_iteration < 2 {
                    return Orbit {
                        value: 1.0,
                        step: None,
                    };
                }
                let cube = self.func == JuliaFn::Cube;
                let mut dr = 1.0;
                for _ in 0..iters {
                    let r = norm(&h);
                    let (a, v) = (h[0], DVec3::new(h[1], h[2], h[3]));
                    let (a2, v2) = if cube {
                        // h^3 = h * h^2
                        let (sa, sv) = (a * a - v.dot(v), 2.0 * a * v);
                        (a * sa - v.dot(sv), a * sv + sa * v + v.cross(sv))
                    } else {
                        (a * a - v.dot(v), 2.0 * a * v)
                    };
                    dr *= if cube { 3.0 * r * r } else { 2.0 * r };
                    h = [a2 + c[0], v2.x + c[1], v2.y + c[2], v2.z + c[3]];
                    if norm(&h) > BAILOUT {
                        break;
                    }
                }
                let r = norm(&h);
                let de = 0.5 * r * r.max(1e-300).ln() / dr.max(1e-300);
                Orbit {
                    value: de,
                    step: (r > BAILOUT).then_some(de),
                }
            }
            Algebra::Hypercomplex => {
                let mut z1 = C::new(h[0] - h[3], h[1] + h[2]);
                let mut z2 = C::new(h[0] + h[3], h[1] - h[2]);
                let c1 = C::new(c[0] - c[3], c[1] + c[2]);
                let c2 = C::new(c[0] + c[3], c[1] - c[2]);
                let mut r = norm(&h);
                for _ in 0..iters {
                    z1 = self.func.apply(z1) + c1;
                    z2 = self.func.apply(z2) + c2;
                    // |h|^2 = (|z1|^2 + |z2|^2) / 2 for this decomposition.
                    r = (0.5 * (z1.norm_sqr() + z2.norm_sqr())).sqrt();
                    if r > BAILOUT || r.is_nan() {
                        break;
                    }
                }
                Orbit {
                    value: if r <= BAILOUT { r - BAILOUT - 1.0 } else { 1.0 },
                    step: None,
                }
            }
        }
    }

    fn is_in(&self, p: DVec3) -> bool {
        p.length_squared() <= BOUND * BOUND && self.orbit(p).value < self.threshold
    }

    /// Crossings along the unit direction `u` from `o` (both in object space), as distances.
    fn crossings(&self, o: DVec3, u: DVec3, first_only: bool, out: &mut Vec<f64>) {
        let b = o.dot(u);
        let disc = b * b - (o.length_squared() - BOUND * BOUND);
        if disc <= 0.0 {
            return;
        }
        let h = disc.sqrt();
        let (lo, hi) = ((-b - h).max(0.0), -b + h);
        if lo >= hi {
            return;
        }
        let step = 1.0 / self.precision;
        let mut s0 = lo;
        let mut in0 = self.is_in(o + u * s0);
        // Where the object fills the bounding sphere's surface, the ray enters it there.
        if in0 && -b - h > 0.0 {
            out.push(lo);
            if first_only {
                return;
            }
        }
        while s0 < hi {
            let orbit = self.orbit(o + u * s0);
            let adv = orbit.step.map_or(step, |d| d.max(step));
            let s1 = (s0 + adv).min(hi);
            let in1 = self.is_in(o + u * s1);
            if in1 != in0 {
                let (mut a, mut c) = (s0, s1);
                for _ in 0..BISECT {
                    let m = 0.5 * (a + c);
                    if self.is_in(o + u * m) == in0 {
                        a = m;
                    } else {
                        c = m;
                    }
                }
                out.push(0.5 * (a + c));
                if first_only {
                    return;
                }
            }
            if s1 >= hi {
                break;
            }
            (s0, in0) = (s1, in1);
        }
    }

    /// Gradient of the field by central differences, scaled to the march step.
    fn gradient(&self, p: DVec3) -> DVec3 {
        let e = 1e-4 / self.precision.max(1.0).sqrt();
        let f = |q: DVec3| self.smooth(q);
        DVec3::new(
            f(p + DVec3::X * e) - f(p - DVec3::X * e),
            f(p + DVec3::Y * e) - f(p - DVec3::Y * e),
            f(p + DVec3::Z * e) - f(p - DVec3::Z * e),
        )
    }

    /// A continuous field with the object's surface as a level set, for normals: the distance
    /// estimate for quaternions, the log of the orbit's size after a fixed number of steps
    /// for hypercomplex numbers.
    fn smooth(&self, p: DVec3) -> f64 {
        match self.algebra {
            Algebra::Quaternion => self.orbit(p).value,
            Algebra::Hypercomplex => {
                let h = self.lift(p);
                let c = self.param;
                let mut z1 = C::new(h[0] - h[3], h[1] + h[2]);
                let mut z2 = C::new(h[0] + h[3], h[1] - h[2]);
                let c1 = C::new(c[0] - c[3], c[1] + c[2]);
                let c2 = C::new(c[0] + c[3], c[1] - c[2]);
                let mut r = 0.0;
                for _ in 0..self.max_iteration.saturating_sub(1) {
                    z1 = self.func.apply(z1) + c1;
                    z2 = self.func.apply(z2) + c2;
                    r = 0.5 * (z1.norm_sqr() + z2.norm_sqr());
                    if r > 1e200 || !r.is_finite() {
                        break;
                    }
                }
                r.max(1e-300).ln()
            }
        }
    }
}

impl Shape for Julia {
    fn bounds(&self) -> Aabb {
        Aabb::new(DVec3::splat(-BOUND), DVec3::splat(BOUND))
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        let len = ray.dir.length();
        if !(len > 0.0 && len.is_finite()) {
            return;
        }
        let u = ray.dir / len;
        let mut s = Vec::new();
        self.crossings(ray.origin, u, false, &mut s);
        out.extend(
            s.into_iter()
                .map(|s| s / len)
                .filter(|&t| t > EPSILON)
                .map(Hit::new),
        );
    }

    fn intersect_first(&self, ray: &Ray, tmax: f64, scratch: &mut Vec<Hit>) -> Option<Hit> {
        let len = ray.dir.length();
        if !(len > 0.0 && len.is_finite()) {
            return None;
        }
        let u = ray.dir / len;
        // Start just beyond the ray's own origin so a shadow ray does not find its surface.
        let o = ray.origin + u * (EPSILON * len);
        let _ = scratch;
        let mut s = Vec::with_capacity(1);
        self.crossings(o, u, true, &mut s);
        let t = (s.first()? + EPSILON * len) / len;
        (t > EPSILON && t < tmax).then(|| Hit::new(t))
    }

    fn inside(&self, p: DVec3) -> bool {
        self.is_in(p)
    }

    fn normal(&self, p: DVec3, _hit: &Hit) -> DVec3 {
        let g = self.gradient(p);
        if g.length_squared() > 0.0 && g.is_finite() {
            g
        } else {
            p
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn julia(algebra: Algebra, n: u32) -> Julia {
        Julia::new(
            [0.0; 4],
            algebra,
            JuliaFn::Sqr,
            n,
            100.0,
            ([0.0, 0.0, 0.0, 1.0], 0.0),
        )
    }

    /// The radii measured on povray with p = 0 (module doc).
    #[test]
    fn zero_parameter_radii_match_povray() {
        let hit = |j: &Julia| {
            let r = Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
            j.intersect_first(&r, f64::INFINITY, &mut Vec::new())
                .map(|h| 5.0 - h.t)
        };
        for (n, r) in [(2, 2.0), (3, 2f64.sqrt()), (4, 2f64.powf(0.25))] {
            let got = hit(&julia(Algebra::Hypercomplex, n)).unwrap();
            assert!((got - r).abs() < 1e-6, "N={n}: {got}");
        }
        for n in [2, 3, 8] {
            // Precision 100 shrinks the sphere by 0.13/100^2 (module doc).
            let got = hit(&julia(Algebra::Quaternion, n)).unwrap();
            assert!((got - 1.0).abs() < 2e-5, "N={n}: {got}");
        }
        assert!(hit(&julia(Algebra::Quaternion, 1)).is_none());
    }

    #[test]
    fn hypercomplex_split_squares_like_the_algebra() {
        // (i)^2 = -1 and (k)^2 = +1 in the commutative hypercomplex numbers.
        let j = Julia::new(
            [0.0; 4],
            Algebra::Hypercomplex,
            JuliaFn::Sqr,
            2,
            10.0,
            ([0.0, 0.0, 0.0, 1.0], 0.0),
        );
        let h = j.lift(DVec3::new(0.0, 1.0, 0.0));
        let z1 = C::new(h[0] - h[3], h[1] + h[2]);
        assert_eq!(JuliaFn::Sqr.apply(z1), C::new(-1.0, 0.0));
        assert!(j.inside(DVec3::new(0.0, 1.9, 0.0)));
        assert!(!j.inside(DVec3::new(0.0, 2.1, 0.0)));
    }
}
