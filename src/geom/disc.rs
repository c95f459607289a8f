//! POV-Ray `disc { center, normal, radius [, hole_radius] }`: an infinitely thin flat ring.
//!
//! The manual defines its inside as the inside of the containing plane (the side opposite the
//! normal), unbounded by the radius, so CSG with a disc behaves like CSG with that plane.

use crate::geom::cylinder::circle_extent;
use crate::geom::{Hit, Shape};
use crate::math::{dot_xy_z, Aabb, DVec3, Ray, EPSILON};

#[derive(Clone, Copy, Debug)]
pub struct Disc {
    center: DVec3,
    /// Unit normal; zero when degenerate.
    normal: DVec3,
    radius: f64,
    radius2: f64,
    hole2: f64,
}

impl Disc {
    /// A zero normal, a zero radius or a hole at least as large as the disc gives an empty
    /// shape; negative radii are taken by magnitude.
    pub fn new(center: DVec3, normal: DVec3, radius: f64, hole_radius: f64) -> Disc {
        let len = normal.length();
        let (radius, hole) = (radius.abs(), hole_radius.abs());
        let ok = len > 0.0
            && len.is_finite()
            && center.is_finite()
            && radius.is_finite()
            && radius > hole;
        let normal = if ok { normal / len } else { DVec3::ZERO };
        Disc {
            center,
            normal,
            radius,
            radius2: radius * radius,
            hole2: hole * hole,
        }
    }

    #[inline]
    fn hit_t(&self, ray: &Ray) -> Option<f64> {
        let denom = self.normal.dot(ray.dir);
        if denom == 0.0 {
            return None;
        }
        let t = self.normal.dot(self.center - ray.origin) / denom;
        if !(t > EPSILON && t.is_finite()) {
            return None;
        }
        let d2 = (ray.at(t) - self.center).length_squared();
        (d2 <= self.radius2 && d2 >= self.hole2).then_some(t)
    }
}

impl Shape for Disc {
    fn bounds(&self) -> Aabb {
        if self.normal == DVec3::ZERO {
            return Aabb::EMPTY;
        }
        let e = circle_extent(self.normal, self.radius);
        Aabb::new(self.center - e, self.center + e)
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        if let Some(t) = self.hit_t(ray) {
            out.push(Hit::new(t));
        }
    }

    fn intersect_first(&self, ray: &Ray, tmax: f64, _scratch: &mut Vec<Hit>) -> Option<Hit> {
        self.hit_t(ray).filter(|&t| t < tmax).map(Hit::new)
    }

    /// `normal · (p - center) < 0` by `dot_xy_z` (a load of p that the caller's stores can
    /// forward). A zero normal needs no test of its own: its products are zeros or NaN,
    /// never below zero.
    fn inside(&self, p: DVec3) -> bool {
        dot_xy_z(self.normal, p - self.center) < 0.0
    }

    fn normal(&self, _p: DVec3, _hit: &Hit) -> DVec3 {
        self.normal
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ring_hits_and_misses() {
        let d = Disc::new(DVec3::new(0.0, 1.0, 0.0), DVec3::Y * 3.0, 2.0, 0.5);
        let mut s = Vec::new();
        let down = |x: f64| Ray::new(DVec3::new(x, 5.0, 0.0), DVec3::NEG_Y);
        assert_eq!(
            d.intersect_first(&down(1.0), f64::INFINITY, &mut s)
                .unwrap()
                .t,
            4.0
        );
        assert!(d
            .intersect_first(&down(0.25), f64::INFINITY, &mut s)
            .is_none());
        assert!(d
            .intersect_first(&down(2.5), f64::INFINITY, &mut s)
            .is_none());
        assert!(d.intersect_first(&down(1.0), 3.0, &mut s).is_none());
        assert_eq!(d.normal(DVec3::Y, &Hit::new(4.0)), DVec3::Y);
        let mut v = Vec::new();
        d.intersect_all(&Ray::new(DVec3::new(1.0, 0.0, 0.0), DVec3::Y), &mut v);
        assert_eq!(v.len(), 1);
        assert_eq!(v[0].t, 1.0);
    }

    #[test]
    fn inside_is_the_half_space() {
        let d = Disc::new(DVec3::ZERO, DVec3::Z, 1.0, 0.0);
        assert!(d.inside(DVec3::new(50.0, 0.0, -0.1)));
        assert!(!d.inside(DVec3::new(0.0, 0.0, 0.1)));
    }

    #[test]
    fn bounds_are_tight() {
        let d = Disc::new(DVec3::ONE, DVec3::Y, 2.0, 0.0);
        assert_eq!(
            d.bounds(),
            Aabb::new(DVec3::new(-1.0, 1.0, -1.0), DVec3::new(3.0, 1.0, 3.0))
        );
    }

    #[test]
    fn degenerate() {
        let r = Ray::new(DVec3::new(0.0, 5.0, 0.0), DVec3::NEG_Y);
        let mut v = Vec::new();
        for d in [
            Disc::new(DVec3::ZERO, DVec3::ZERO, 1.0, 0.0),
            Disc::new(DVec3::ZERO, DVec3::Y, 0.0, 0.0),
            Disc::new(DVec3::ZERO, DVec3::Y, 1.0, 1.0),
        ] {
            d.intersect_all(&r, &mut v);
            assert!(!d.inside(DVec3::NEG_Y));
            assert!(d.bounds().is_empty());
        }
        Disc::new(DVec3::ZERO, DVec3::Y, 1.0, 0.0)
            .intersect_all(&Ray::new(DVec3::Y, DVec3::X), &mut v);
        assert!(v.is_empty());
    }
}
