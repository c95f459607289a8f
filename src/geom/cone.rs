//! POV-Ray `cone { base, base_radius, cap, cap_radius [open] }`: a truncated cone (frustum).
//!
//! Either radius may be zero (a pointed cone). `Hit::part`: 0 side, 1 base disc, 2 cap disc.
//! Like the cylinder, an open cone keeps the enclosed solid as its inside.

use crate::geom::cylinder::{axis_between, circle_extent, AxisRay, BASE, CAP, SIDE};
use crate::geom::{Hit, Shape};
use crate::math::{Aabb, DVec3, Ray, EPSILON};

#[derive(Clone, Copy, Debug)]
pub struct Cone {
    base: DVec3,
    axis: DVec3,
    height: f64,
    base_radius: f64,
    cap_radius: f64,
    /// Radius change per unit of height.
    slope: f64,
    open: bool,
    empty: bool,
}

impl Cone {
    /// Negative radii are taken by magnitude. Coincident ends, two zero radii or non-finite
    /// input give an empty shape.
    pub fn new(base: DVec3, base_radius: f64, cap: DVec3, cap_radius: f64, open: bool) -> Cone {
        let (r0, r1) = (base_radius.abs(), cap_radius.abs());
        let frame =
            axis_between(base, cap).filter(|_| r0.is_finite() && r1.is_finite() && r0 + r1 > 0.0);
        let (axis, height) = frame.unwrap_or((DVec3::Y, 1.0));
        Cone {
            base,
            axis,
            height,
            base_radius: r0,
            cap_radius: r1,
            slope: (r1 - r0) / height,
            open,
            empty: frame.is_none(),
        }
    }

    fn radius_at(&self, z: f64) -> f64 {
        self.base_radius + self.slope * z
    }
}

impl Shape for Cone {
    fn bounds(&self) -> Aabb {
        if self.empty {
            return Aabb::EMPTY;
        }
        let cap = self.base + self.axis * self.height;
        let (e0, e1) = (
            circle_extent(self.axis, self.base_radius),
            circle_extent(self.axis, self.cap_radius),
        );
        Aabb::new(
            (self.base - e0).min(cap - e1),
            (self.base + e0).max(cap + e1),
        )
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        if self.empty {
            return;
        }
        let dd = ray.dir.length_squared();
        if dd == 0.0 {
            return;
        }
        // b² - a c cancels badly when the origin is far away; solving from the point of the
        // line nearest the cone's middle and adding that offset back keeps the digits.
        let mid = self.base + self.axis * (0.5 * self.height);
        let shift = (mid - ray.origin).dot(ray.dir) / dd;
        let near = Ray::new(ray.at(shift), ray.dir);
        let r = AxisRay::new(&near, self.base, self.axis);
        let k = self.slope;
        let rz = self.radius_at(r.oz);
        let a = r.dp.length_squared() - k * k * r.dz * r.dz;
        let b = r.op.dot(r.dp) - k * rz * r.dz;
        let c = r.op.length_squared() - rz * rz;
        let mut roots = [f64::NAN; 2];
        if a != 0.0 {
            let disc = b * b - a * c;
            if disc >= 0.0 {
                let q = -(b + b.signum() * disc.sqrt());
                roots = if q != 0.0 { [q / a, c / q] } else { [0.0, 0.0] };
            }
        } else if b != 0.0 {
            // Ray parallel to a generator line of the cone: one crossing.
            roots[0] = -c / (2.0 * b);
        }
        for s in roots {
            let z = r.oz + s * r.dz;
            // The quadratic also describes the mirrored cone beyond the apex; on [0, height]
            // the radius is non-negative, so that range picks the real surface.
            if s.is_finite() && shift + s > EPSILON && (0.0..=self.height).contains(&z) {
                out.push(Hit::with_part(shift + s, SIDE));
            }
        }
        if !self.open && r.dz != 0.0 {
            for (z, radius, part) in [
                (0.0, self.base_radius, BASE),
                (self.height, self.cap_radius, CAP),
            ] {
                let s = (z - r.oz) / r.dz;
                if radius > 0.0 && shift + s > EPSILON && r.radius2_at(s) <= radius * radius {
                    out.push(Hit::with_part(shift + s, part));
                }
            }
        }
    }

    fn inside(&self, p: DVec3) -> bool {
        if self.empty {
            return false;
        }
        let v = p - self.base;
        let z = v.dot(self.axis);
        let rz = self.radius_at(z);
        z > 0.0 && z < self.height && (v - self.axis * z).length_squared() < rz * rz
    }

    fn normal(&self, p: DVec3, hit: &Hit) -> DVec3 {
        match hit.part {
            BASE => -self.axis,
            CAP => self.axis,
            _ => {
                // Gradient of |radial| - radius(z): unit radial direction tilted by the slope.
                let v = p - self.base;
                let radial = (v - self.axis * v.dot(self.axis)).normalize_or_zero();
                radial - self.axis * self.slope
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn all(s: &dyn Shape, r: &Ray) -> Vec<(f64, u32)> {
        let mut v = Vec::new();
        s.intersect_all(r, &mut v);
        v.sort_by(|a, b| a.t.total_cmp(&b.t));
        v.iter().map(|h| (h.t, h.part)).collect()
    }

    fn close(a: &[(f64, u32)], b: &[(f64, u32)]) -> bool {
        a.len() == b.len()
            && a.iter()
                .zip(b)
                .all(|(x, y)| (x.0 - y.0).abs() < 1e-12 * x.0.abs().max(1.0) && x.1 == y.1)
    }

    #[test]
    fn pointed_cone() {
        // Apex at y = 2, base radius 1 at y = 0.
        let c = Cone::new(DVec3::ZERO, 1.0, DVec3::new(0.0, 2.0, 0.0), 0.0, false);
        let h = all(&c, &Ray::new(DVec3::new(-5.0, 1.0, 0.0), DVec3::X));
        assert!(close(&h, &[(4.5, SIDE), (5.5, SIDE)]), "{h:?}");
        let p = DVec3::new(-0.5, 1.0, 0.0);
        let n = c.normal(p, &Hit::with_part(4.5, SIDE)).normalize();
        let want = DVec3::new(-2.0, 1.0, 0.0).normalize();
        assert!((n - want).length() < 1e-12, "{n}");
        let h = all(&c, &Ray::new(DVec3::new(0.25, -3.0, 0.0), DVec3::Y));
        assert!(close(&h, &[(3.0, BASE), (4.5, SIDE)]), "{h:?}");
        // Through the apex region above the cone: the mirrored nappe must not be hit.
        assert!(all(&c, &Ray::new(DVec3::new(-5.0, 3.0, 0.0), DVec3::X)).is_empty());
        assert!(c.inside(DVec3::new(0.1, 1.0, 0.1)));
        assert!(!c.inside(DVec3::new(0.6, 1.0, 0.0)));
        assert!(!c.inside(DVec3::new(0.0, 2.1, 0.0)));
    }

    #[test]
    fn frustum_and_far_origin() {
        let c = Cone::new(
            DVec3::new(0.0, 0.0, 1.0),
            2.0,
            DVec3::new(0.0, 0.0, 3.0),
            1.0,
            false,
        );
        let h = all(&c, &Ray::new(DVec3::new(0.0, 0.0, -10.0), DVec3::Z));
        assert!(close(&h, &[(11.0, BASE), (13.0, CAP)]), "{h:?}");
        let far = all(&c, &Ray::new(DVec3::new(-1e8, 0.0, 2.0), DVec3::X));
        assert!(
            close(&far, &[(1e8 - 1.5, SIDE), (1e8 + 1.5, SIDE)]),
            "{far:?}"
        );
        let b = c.bounds();
        assert_eq!(
            (b.min, b.max),
            (DVec3::new(-2.0, -2.0, 1.0), DVec3::new(2.0, 2.0, 3.0))
        );
        // From inside.
        assert!(close(
            &all(&c, &Ray::new(DVec3::new(0.0, 0.0, 2.0), DVec3::Z)),
            &[(1.0, CAP)]
        ));
    }

    #[test]
    fn equal_radii_is_a_cylinder_and_open_has_no_caps() {
        let c = Cone::new(DVec3::ZERO, 1.0, DVec3::Y * 2.0, 1.0, true);
        assert!(close(
            &all(&c, &Ray::new(DVec3::new(-5.0, 1.0, 0.0), DVec3::X)),
            &[(4.0, SIDE), (6.0, SIDE)]
        ));
        assert!(all(&c, &Ray::new(DVec3::new(0.5, 5.0, 0.0), DVec3::NEG_Y)).is_empty());
        assert!(c.inside(DVec3::new(0.5, 1.0, 0.0)));
    }

    #[test]
    fn ray_parallel_to_generator() {
        // Side line from (1,0,0) to (0,1,0); a ray parallel to it crosses the surface once.
        let c = Cone::new(DVec3::ZERO, 1.0, DVec3::Y, 0.0, true);
        let h = all(
            &c,
            &Ray::new(DVec3::new(0.5, -0.25, 0.0), DVec3::new(-1.0, 1.0, 0.0)),
        );
        assert_eq!(h.len(), 1, "{h:?}");
        let p = DVec3::new(0.5, -0.25, 0.0) + DVec3::new(-1.0, 1.0, 0.0) * h[0].0;
        assert!((p.x.abs() - (1.0 - p.y)).abs() < 1e-12, "{p}");
    }

    #[test]
    fn degenerate() {
        let r = Ray::new(DVec3::new(0.0, 0.5, -5.0), DVec3::Z);
        for c in [
            Cone::new(DVec3::ZERO, 1.0, DVec3::ZERO, 0.5, false),
            Cone::new(DVec3::ZERO, 0.0, DVec3::Y, 0.0, false),
            Cone::new(DVec3::ZERO, f64::INFINITY, DVec3::Y, 0.0, false),
        ] {
            assert!(all(&c, &r).is_empty());
            assert!(!c.inside(DVec3::new(0.0, 0.5, 0.0)));
            assert!(c.bounds().is_empty());
        }
        let c = Cone::new(DVec3::ZERO, 1.0, DVec3::Y, 0.0, false);
        assert!(all(&c, &Ray::new(DVec3::ZERO, DVec3::ZERO)).is_empty());
    }
}
