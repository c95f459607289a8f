//! POV-Ray `plane { normal, distance }`: an infinite solid half-space.
//!
//! POV-Ray normalises the normal and divides the distance by its length, so
//! `plane { 2*y, 4 }` is the plane y = 2. The normal points to the outside.

use crate::geom::{Hit, Shape};
use crate::math::{dot_xy_z, Aabb, DVec3, Ray, EPSILON};

#[derive(Clone, Copy, Debug)]
pub struct Plane {
    /// Unit normal, or zero for a degenerate plane that nothing hits.
    normal: DVec3,
    distance: f64,
}

impl Plane {
    /// Points p with `normal · p = distance`; a zero or non-finite normal gives an empty shape.
    pub fn new(normal: DVec3, distance: f64) -> Plane {
        let len = normal.length();
        if len > 0.0 && len.is_finite() && distance.is_finite() {
            Plane {
                normal: normal / len,
                distance: distance / len,
            }
        } else {
            Plane {
                normal: DVec3::ZERO,
                distance: 0.0,
            }
        }
    }

    /// The plane of a half-space as `Shape::half_space` gives it (a plane's own normal and
    /// distance): the same plane, bit for bit, for callers that hold the shape behind a
    /// `dyn Shape` and want its crossings without the call through the table.
    pub fn from_half_space((normal, distance): (DVec3, f64)) -> Plane {
        Plane { normal, distance }
    }

    /// The crossing `intersect_first` reports when it is below its `tmax`: the one crossing
    /// with `t > EPSILON`, if any.
    #[inline]
    pub fn hit_t(&self, ray: &Ray) -> Option<f64> {
        // `dot_xy_z`: the ray is often just stored (an object-space ray by `local_ray`, a
        // camera or reflected ray by the caller) as x-y and z; `dot` read its y-z as one load
        // spanning both stores, which waited for them (two fifths of `intersect_first`'s
        // samples on interior/nufog2).
        let denom = dot_xy_z(self.normal, ray.dir);
        if denom == 0.0 {
            return None;
        }
        let num = self.distance - dot_xy_z(self.normal, ray.origin);
        // A quotient's sign is the xor of its operands' signs: where they differ, `t` is at
        // most zero and fails `t > EPSILON` anyway, so the division is skipped for the rays
        // that leave the plane behind (every sky ray over a floor), the same answer. Not for
        // origins within EPSILON of the plane (shadow and reflected rays leaving it), where
        // the numerator's sign is rounding noise: a branch on it mispredicted half the time
        // (templates/Basic_Scenes/Checkered_plane 1.4 % slower), and the division's answer
        // is as predictable.
        if (num < -EPSILON && denom > 0.0) || (num > EPSILON && denom < 0.0) {
            return None;
        }
        let t = num / denom;
        (t > EPSILON && t.is_finite()).then_some(t)
    }
}

impl Shape for Plane {
    fn bounds(&self) -> Aabb {
        if self.normal == DVec3::ZERO {
            Aabb::EMPTY
        } else {
            Aabb::INFINITE
        }
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        if let Some(t) = self.hit_t(ray) {
            out.push(Hit::new(t));
        }
    }

    fn intersect_first(&self, ray: &Ray, tmax: f64, _scratch: &mut Vec<Hit>) -> Option<Hit> {
        self.hit_t(ray).filter(|&t| t < tmax).map(Hit::new)
    }

    /// The one crossing `intersect_all` lists, asked without the list (a clipped plane's
    /// shadow rays: the scratch's clear, push and read were half of this call).
    fn any_kept(
        &self,
        ray: &Ray,
        tmax: f64,
        _scratch: &mut Vec<Hit>,
        keep: &mut dyn FnMut(f64) -> bool,
    ) -> bool {
        self.hit_t(ray).is_some_and(|t| t < tmax && keep(t))
    }

    /// `normal · p < distance` by `dot_xy_z` (a load of p that the caller's stores can
    /// forward). A degenerate plane (zero normal, zero distance) needs no test of its own:
    /// its products are zeros (or NaN for an infinite `p`), never below zero.
    fn inside(&self, p: DVec3) -> bool {
        dot_xy_z(self.normal, p) < self.distance
    }

    fn normal(&self, _p: DVec3, _hit: &Hit) -> DVec3 {
        self.normal
    }

    fn half_space(&self) -> Option<(DVec3, f64)> {
        (self.normal != DVec3::ZERO).then_some((self.normal, self.distance))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hits_inside_and_normal() {
        let p = Plane::new(DVec3::new(0.0, 2.0, 0.0), 4.0);
        let r = Ray::new(DVec3::new(1.0, 10.0, 3.0), DVec3::NEG_Y);
        let h = p
            .intersect_first(&r, f64::INFINITY, &mut Vec::new())
            .unwrap();
        assert_eq!(h.t, 8.0);
        assert_eq!(p.normal(r.at(h.t), &h), DVec3::Y);
        assert!(p.inside(DVec3::new(5.0, 1.9, -7.0)));
        assert!(!p.inside(DVec3::new(5.0, 2.1, -7.0)));
        assert!(p.intersect_first(&r, 7.9, &mut Vec::new()).is_none());
        assert_eq!(p.bounds(), Aabb::INFINITE);
        // From the inside, going out.
        let mut v = Vec::new();
        p.intersect_all(&Ray::new(DVec3::ZERO, DVec3::new(0.0, 0.5, 0.0)), &mut v);
        assert_eq!(v.len(), 1);
        assert_eq!(v[0].t, 4.0);
    }

    /// Skipping the division by signs answers as the division does, t bit for bit: rays
    /// towards, away from, along and on planes, with zero, tiny and huge components.
    #[test]
    fn sign_test_is_the_division() {
        let mut rng = crate::geom::test_rng::Lcg(4242);
        let mut rnd = move || rng.next() * 2.0 - 1.0;
        let pick = |v: f64, k: usize| [v, 0.0, -0.0, v * 1e-300, v * 1e300][k % 5];
        for k in 0..50000 {
            let n = DVec3::new(rnd(), pick(rnd(), k / 5), rnd());
            let p = Plane::new(n, [0.0, rnd(), 1e10 * rnd()][k % 3]);
            let o = DVec3::new(pick(rnd(), k / 25), rnd(), rnd()) * [1.0, 1e-8, 1e8][k % 3];
            let d = DVec3::new(rnd(), pick(rnd(), k), pick(rnd(), k / 7));
            let ray = Ray::new(o, d);
            let denom = p.normal.dot(ray.dir);
            let full = (denom != 0.0)
                .then(|| (p.distance - p.normal.dot(ray.origin)) / denom)
                .filter(|&t| t > EPSILON && t.is_finite());
            assert_eq!(p.hit_t(&ray).map(f64::to_bits), full.map(f64::to_bits));
        }
    }

    /// `any_kept` without the list answers as the listing does (`any_listed_kept`), and asks
    /// `keep` about the same `t`, bit for bit: rays towards, away from and along planes,
    /// with limits below and beyond the crossing.
    #[test]
    fn any_kept_is_the_listing() {
        let mut rng = crate::geom::test_rng::Lcg(77);
        let mut rnd = move || rng.next() * 2.0 - 1.0;
        for k in 0..20000 {
            let p = Plane::new(DVec3::new(rnd(), rnd(), [rnd(), 0.0][k % 2]), rnd());
            let d = DVec3::new(rnd(), [rnd(), 0.0, -0.0][k % 3], rnd());
            let ray = Ray::new(DVec3::new(rnd(), rnd(), rnd()) * 3.0, d);
            let tmax = [f64::INFINITY, 1.0, 0.0][k % 3];
            let cut = rnd();
            let (mut a, mut b) = (Vec::new(), Vec::new());
            let fast = p.any_kept(&ray, tmax, &mut Vec::new(), &mut |t| {
                a.push(t.to_bits());
                t > cut
            });
            let listed = crate::geom::any_listed_kept(&p, &ray, tmax, &mut Vec::new(), &mut |t| {
                b.push(t.to_bits());
                t > cut
            });
            assert_eq!((fast, a), (listed, b), "ray {k}");
        }
    }

    #[test]
    fn parallel_behind_and_degenerate() {
        let p = Plane::new(DVec3::Y, 0.0);
        let mut v = Vec::new();
        p.intersect_all(&Ray::new(DVec3::Y, DVec3::X), &mut v);
        p.intersect_all(&Ray::new(DVec3::Y, DVec3::Y), &mut v);
        // Starting on the surface is a self-intersection.
        p.intersect_all(&Ray::new(DVec3::ZERO, DVec3::NEG_Y), &mut v);
        assert!(v.is_empty());
        let d = Plane::new(DVec3::ZERO, 1.0);
        d.intersect_all(&Ray::new(DVec3::Y, DVec3::NEG_Y), &mut v);
        assert!(v.is_empty());
        assert!(!d.inside(DVec3::NEG_Y * 5.0));
        assert!(d.bounds().is_empty());
    }
}
