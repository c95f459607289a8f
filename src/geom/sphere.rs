//! POV-Ray `sphere { center, radius }`.

use crate::geom::{Hit, Shape};
use crate::math::{Aabb, DVec3, Ray, EPSILON};

#[derive(Clone, Copy, Debug)]
pub struct Sphere {
    center: DVec3,
    radius: f64,
    radius2: f64,
}

impl Sphere {
    /// A zero or non-finite radius gives a sphere nothing hits; a negative one is taken by its
    /// magnitude, since only its square enters the surface equation.
    pub fn new(center: DVec3, radius: f64) -> Sphere {
        let radius = if radius.is_finite() {
            radius.abs()
        } else {
            0.0
        };
        Sphere {
            center,
            radius,
            radius2: radius * radius,
        }
    }

    /// Both crossings (t0 <= t1) of the full line, or None.
    #[inline]
    fn roots(&self, ray: &Ray) -> Option<(f64, f64)> {
        if self.radius == 0.0 {
            return None;
        }
        let oc = ray.origin - self.center;
        let a = ray.dir.length_squared();
        let b = oc.dot(ray.dir);
        // Computing c through the perpendicular distance of the line to the centre instead of
        // |oc|² - r² keeps the discriminant accurate for rays starting far away.
        let perp = oc - ray.dir * (b / a);
        let disc = a * (self.radius2 - perp.length_squared());
        if disc < 0.0 || a == 0.0 {
            return None;
        }
        let c = oc.length_squared() - self.radius2;
        let q = -(b + b.signum() * disc.sqrt());
        if q == 0.0 {
            return Some((0.0, 0.0));
        }
        // Citardauq form: the root that would need -b + sqrt(disc) comes from c / q instead.
        let (r1, r2) = (q / a, c / q);
        Some((r1.min(r2), r1.max(r2)))
    }
}

impl Shape for Sphere {
    fn bounds(&self) -> Aabb {
        if self.radius == 0.0 {
            return Aabb::EMPTY;
        }
        Aabb::new(
            self.center - DVec3::splat(self.radius),
            self.center + DVec3::splat(self.radius),
        )
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        if let Some((t0, t1)) = self.roots(ray) {
            for t in [t0, t1] {
                if t > EPSILON {
                    out.push(Hit::new(t));
                }
            }
        }
    }

    fn intersect_first(&self, ray: &Ray, tmax: f64, _scratch: &mut Vec<Hit>) -> Option<Hit> {
        let (t0, t1) = self.roots(ray)?;
        let t = if t0 > EPSILON { t0 } else { t1 };
        (t > EPSILON && t < tmax).then(|| Hit::new(t))
    }

    /// Shadow rays inside a sky sphere (advanced/quilt1: every area-light sample) skip the
    /// roots: a segment whose two ends lie well inside crosses nothing, and the margin (the
    /// ends at most 0.9995 r from the centre, so each root at least 0.0005 r / |dir| beyond
    /// them) is some 1e11 times the roots' rounding error, so `intersect_first` would find
    /// no crossing either: the same answer, not an approximation.
    fn any_hit(&self, ray: &Ray, tmax: f64, scratch: &mut Vec<Hit>) -> bool {
        let inner = self.radius2 * 0.999;
        let oc = ray.origin - self.center;
        if oc.length_squared() < inner && (oc + ray.dir * tmax).length_squared() < inner {
            return false;
        }
        self.intersect_first(ray, tmax, scratch).is_some()
    }

    fn inside(&self, p: DVec3) -> bool {
        (p - self.center).length_squared() < self.radius2
    }

    fn normal(&self, p: DVec3, _hit: &Hit) -> DVec3 {
        (p - self.center) / self.radius.max(f64::MIN_POSITIVE)
    }
    /// Longitude and latitude, measured against povray (tests/probes/uv_sphere.pov): u turns
    /// from +x towards +z (0 at +x, 0.75 at -z), v runs from 0 at the south pole to 1 at the
    /// north.
    fn uv(&self, p: DVec3, _hit: &Hit) -> Option<[f64; 2]> {
        let d = (p - self.center).normalize_or_zero();
        let u = d.z.atan2(d.x) / std::f64::consts::TAU;
        let u = if u < 0.0 { u + 1.0 } else { u };
        let v = d.y.clamp(-1.0, 1.0).asin() / std::f64::consts::PI + 0.5;
        Some([u, v])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn all(s: &Sphere, r: &Ray) -> Vec<f64> {
        let mut v = Vec::new();
        s.intersect_all(r, &mut v);
        let mut t: Vec<f64> = v.iter().map(|h| h.t).collect();
        t.sort_by(f64::total_cmp);
        t
    }

    #[test]
    fn hits_at_known_distances() {
        let s = Sphere::new(DVec3::new(0.0, 0.0, 5.0), 2.0);
        let r = Ray::new(DVec3::ZERO, DVec3::Z);
        assert_eq!(all(&s, &r), vec![3.0, 7.0]);
        let h = s
            .intersect_first(&r, f64::INFINITY, &mut Vec::new())
            .unwrap();
        assert_eq!(h.t, 3.0);
        let n = s.normal(r.at(h.t), &h);
        assert!((n - DVec3::NEG_Z).length() < 1e-12);
        // Unnormalised direction: t stays in units of dir.
        let r2 = Ray::new(DVec3::ZERO, DVec3::Z * 2.0);
        assert_eq!(all(&s, &r2), vec![1.5, 3.5]);
        assert!(s.intersect_first(&r, 2.9, &mut Vec::new()).is_none());
    }

    /// `any_hit` answers as `intersect_first` does, for segments inside, leaving, crossing
    /// and near the surface, on small and huge spheres.
    #[test]
    fn any_hit_is_intersect_first() {
        let mut scratch = Vec::new();
        let mut rng = crate::geom::test_rng::Lcg(12345);
        let mut rnd = move || rng.next() * 2.0 - 1.0;
        for r in [0.5, 1.0, 100000.0] {
            let s = Sphere::new(DVec3::new(0.25, -0.5, 1.0), r);
            for _ in 0..20000 {
                let o = DVec3::new(rnd(), rnd(), rnd()) * r * 1.2 + DVec3::new(0.25, -0.5, 1.0);
                let d = DVec3::new(rnd(), rnd(), rnd()) * (1.0 + 3.0 * rnd().abs());
                let tmax = [rnd().abs() * 2.0 * r, f64::INFINITY, 0.0, f64::NAN]
                    [(rnd().abs() * 3.999) as usize];
                let ray = Ray::new(o, d);
                assert_eq!(
                    s.any_hit(&ray, tmax, &mut scratch),
                    s.intersect_first(&ray, tmax, &mut scratch).is_some(),
                    "{o} {d} {tmax}"
                );
            }
        }
    }

    #[test]
    fn from_inside_and_behind() {
        let s = Sphere::new(DVec3::ZERO, 1.0);
        let r = Ray::new(DVec3::ZERO, DVec3::X);
        assert_eq!(all(&s, &r), vec![1.0]);
        assert_eq!(
            s.intersect_first(&r, f64::INFINITY, &mut Vec::new())
                .unwrap()
                .t,
            1.0
        );
        assert!(s.inside(DVec3::splat(0.5)));
        assert!(!s.inside(DVec3::splat(0.6)));
        let behind = Ray::new(DVec3::new(3.0, 0.0, 0.0), DVec3::X);
        assert!(all(&s, &behind).is_empty());
    }

    #[test]
    fn far_away_rays_stay_accurate() {
        let s = Sphere::new(DVec3::ZERO, 1.0);
        let r = Ray::new(DVec3::new(0.5, 0.0, -1e7), DVec3::Z);
        let t = all(&s, &r);
        let want = 1e7 - 0.75f64.sqrt();
        assert!((t[0] - want).abs() < 1e-8, "{t:?}");
    }

    #[test]
    fn grazing_and_degenerate() {
        let s = Sphere::new(DVec3::ZERO, 1.0);
        let r = Ray::new(DVec3::new(1.0 + 1e-9, 0.0, -5.0), DVec3::Z);
        assert!(all(&s, &r).is_empty());
        let r = Ray::new(DVec3::new(1.0 - 1e-9, 0.0, -5.0), DVec3::Z);
        assert_eq!(all(&s, &r).len(), 2);
        let z = Sphere::new(DVec3::ZERO, 0.0);
        assert!(all(&z, &Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z)).is_empty());
        assert!(z.bounds().is_empty());
        assert!(!z.inside(DVec3::ZERO));
        let zero_dir = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::ZERO);
        assert!(all(&s, &zero_dir).is_empty());
        let neg = Sphere::new(DVec3::ZERO, -2.0);
        assert_eq!(
            all(&neg, &Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z)),
            vec![3.0, 7.0]
        );
    }
}
