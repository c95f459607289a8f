//! POV-Ray `cylinder { base, cap, radius [open] }`.
//!
//! `Hit::part`: 0 side, 1 base disc, 2 cap disc. An open cylinder loses its end discs but, as
//! in POV-Ray, still counts the enclosed solid as its inside for CSG.

use crate::geom::{Hit, Shape};
use crate::math::{Aabb, DVec3, Ray, EPSILON};

pub(crate) const SIDE: u32 = 0;
pub(crate) const BASE: u32 = 1;
pub(crate) const CAP: u32 = 2;

/// A ray split into its components along and across an axis through `base`.
pub(crate) struct AxisRay {
    /// Axial coordinate of the origin and axial speed.
    pub oz: f64,
    pub dz: f64,
    /// Perpendicular parts of the origin (relative to `base`) and of the direction.
    pub op: DVec3,
    pub dp: DVec3,
}

impl AxisRay {
    pub fn new(ray: &Ray, base: DVec3, axis: DVec3) -> AxisRay {
        let o = ray.origin - base;
        let (oz, dz) = (o.dot(axis), ray.dir.dot(axis));
        AxisRay {
            oz,
            dz,
            op: o - axis * oz,
            dp: ray.dir - axis * dz,
        }
    }
    /// Squared distance from the axis at parameter t.
    pub fn radius2_at(&self, t: f64) -> f64 {
        (self.op + self.dp * t).length_squared()
    }
}

/// Half-extents of the box around a circle of radius `r` perpendicular to the unit `axis`.
pub(crate) fn circle_extent(axis: DVec3, r: f64) -> DVec3 {
    (DVec3::ONE - axis * axis).max(DVec3::ZERO).powf(0.5) * r
}

/// Unit axis and length from `base` to `cap`, or None when they coincide.
pub(crate) fn axis_between(base: DVec3, cap: DVec3) -> Option<(DVec3, f64)> {
    let h = (cap - base).length();
    (h > 0.0 && h.is_finite() && base.is_finite()).then(|| ((cap - base) / h, h))
}

#[derive(Clone, Copy, Debug)]
pub struct Cylinder {
    base: DVec3,
    axis: DVec3,
    height: f64,
    radius2: f64,
    open: bool,
    /// Coincident ends or a zero radius: nothing to hit.
    empty: bool,
}

impl Cylinder {
    pub fn new(base: DVec3, cap: DVec3, radius: f64, open: bool) -> Cylinder {
        let frame = axis_between(base, cap).filter(|_| radius != 0.0 && radius.is_finite());
        let (axis, height) = frame.unwrap_or((DVec3::Y, 0.0));
        Cylinder {
            base,
            axis,
            height,
            radius2: radius * radius,
            open,
            empty: frame.is_none(),
        }
    }
}

impl Shape for Cylinder {
    fn bounds(&self) -> Aabb {
        if self.empty {
            return Aabb::EMPTY;
        }
        let e = circle_extent(self.axis, self.radius2.sqrt());
        let cap = self.base + self.axis * self.height;
        Aabb::new(self.base.min(cap) - e, self.base.max(cap) + e)
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        self.crossings(ray, |t, part| out.push(Hit::with_part(t, part)));
    }

    /// The nearest of `intersect_all`'s crossings below `tmax`, without listing them: the
    /// default's scratch vector, its pushes and its pass cost about a third of the shape's
    /// time on advanced/cliche/sign. On equal `t` the first one listed, as `min_by` keeps.
    fn intersect_first(&self, ray: &Ray, tmax: f64, _scratch: &mut Vec<Hit>) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        self.crossings(ray, |t, part| {
            if t < tmax && best.is_none_or(|b| t < b.t) {
                best = Some(Hit::with_part(t, part));
            }
        });
        best
    }

    fn inside_bounded(&self) -> bool {
        true
    }

    fn inside(&self, p: DVec3) -> bool {
        if self.empty {
            return false;
        }
        let v = p - self.base;
        let z = v.dot(self.axis);
        z > 0.0 && z < self.height && (v - self.axis * z).length_squared() < self.radius2
    }

    fn normal(&self, p: DVec3, hit: &Hit) -> DVec3 {
        match hit.part {
            BASE => -self.axis,
            CAP => self.axis,
            _ => {
                let v = p - self.base;
                v - self.axis * v.dot(self.axis)
            }
        }
    }
}

impl Cylinder {
    /// Each crossing beyond `EPSILON` as `found(t, part)`: the sides' two roots, then the
    /// base and the cap.
    #[inline(always)]
    fn crossings(&self, ray: &Ray, mut found: impl FnMut(f64, u32)) {
        if self.empty {
            return;
        }
        let r = AxisRay::new(ray, self.base, self.axis);
        let a = r.dp.length_squared();
        if a > 0.0 {
            let b = r.op.dot(r.dp);
            // Discriminant from the line's closest approach to the axis: accurate even for
            // origins far from the cylinder, unlike b² - a c.
            let closest = r.op - r.dp * (b / a);
            let disc = a * (self.radius2 - closest.length_squared());
            if disc >= 0.0 {
                let q = -(b + b.signum() * disc.sqrt());
                let c = r.op.length_squared() - self.radius2;
                let roots = if q != 0.0 { [q / a, c / q] } else { [0.0, 0.0] };
                for t in roots {
                    let z = r.oz + t * r.dz;
                    if t > EPSILON && (0.0..=self.height).contains(&z) {
                        found(t, SIDE);
                    }
                }
            }
        }
        if !self.open && r.dz != 0.0 {
            for (z, part) in [(0.0, BASE), (self.height, CAP)] {
                let t = (z - r.oz) / r.dz;
                if t > EPSILON && r.radius2_at(t) <= self.radius2 {
                    found(t, part);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn all(s: &dyn Shape, r: &Ray) -> Vec<Hit> {
        let mut v = Vec::new();
        s.intersect_all(r, &mut v);
        v.sort_by(|a, b| a.t.total_cmp(&b.t));
        v
    }

    /// The default `intersect_first`: `intersect_all`'s crossings, the first least one.
    fn first_listed(c: &Cylinder, r: &Ray, tmax: f64) -> Option<Hit> {
        all_unsorted(c, r)
            .into_iter()
            .filter(|h| h.t > EPSILON && h.t < tmax)
            .min_by(|a, b| a.t.total_cmp(&b.t))
    }

    fn all_unsorted(s: &dyn Shape, r: &Ray) -> Vec<Hit> {
        let mut v = Vec::new();
        s.intersect_all(r, &mut v);
        v
    }

    #[test]
    fn first_crossing_is_the_listed_ones_first() {
        let shapes = [
            Cylinder::new(DVec3::ZERO, DVec3::new(0.0, 2.0, 0.0), 1.0, false),
            Cylinder::new(DVec3::ZERO, DVec3::new(0.0, 2.0, 0.0), 1.0, true),
            Cylinder::new(
                DVec3::new(1.0, -2.0, 0.5),
                DVec3::new(-3.0, 4.0, 2.0),
                0.7,
                false,
            ),
            Cylinder::new(DVec3::ZERO, DVec3::ZERO, 1.0, false),
        ];
        // Origins and directions over a box, axis-aligned and rim-grazing rays among them
        // (equal side and cap t).
        let mut rng = crate::geom::test_rng::Lcg(0x2545_f491_4f6c_dd1d);
        let mut next = move || rng.next() * 8.0 - 4.0;
        let mut rays = vec![
            Ray::new(DVec3::new(1.0, 5.0, 0.0), DVec3::NEG_Y),
            Ray::new(DVec3::new(-5.0, 2.0, 0.0), DVec3::X),
            Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X),
            Ray::new(DVec3::new(0.0, 1.0, 0.0), DVec3::X),
            Ray::new(DVec3::new(-2.0, 3.0, 0.0), DVec3::new(1.0, -1.0, 0.0)),
        ];
        for _ in 0..4000 {
            let o = DVec3::new(next(), next(), next());
            let d = DVec3::new(next(), next(), next());
            rays.push(Ray::new(o, d));
            rays.push(Ray::new(o, DVec3::new(0.0, d.y, 0.0)));
        }
        for c in &shapes {
            for r in &rays {
                for tmax in [f64::INFINITY, 3.0, 0.5] {
                    let mut scratch = Vec::new();
                    let got = c.intersect_first(r, tmax, &mut scratch);
                    let want = first_listed(c, r, tmax);
                    assert_eq!(
                        got.map(|h| (h.t.to_bits(), h.part)),
                        want.map(|h| (h.t.to_bits(), h.part))
                    );
                }
            }
        }
    }

    #[test]
    fn side_and_caps() {
        let c = Cylinder::new(DVec3::ZERO, DVec3::new(0.0, 2.0, 0.0), 1.0, false);
        let r = Ray::new(DVec3::new(-5.0, 1.0, 0.0), DVec3::X);
        let h = all(&c, &r);
        assert_eq!(
            h.iter().map(|h| (h.t, h.part)).collect::<Vec<_>>(),
            vec![(4.0, SIDE), (6.0, SIDE)]
        );
        let n = c.normal(r.at(4.0), &h[0]);
        assert!((n.normalize() - DVec3::NEG_X).length() < 1e-12);
        let r = Ray::new(DVec3::new(0.5, 5.0, 0.0), DVec3::NEG_Y);
        let h = all(&c, &r);
        assert_eq!(
            h.iter().map(|h| (h.t, h.part)).collect::<Vec<_>>(),
            vec![(3.0, CAP), (5.0, BASE)]
        );
        assert_eq!(c.normal(r.at(3.0), &h[0]), DVec3::Y);
        assert_eq!(c.normal(r.at(5.0), &h[1]), DVec3::NEG_Y);
        // Diagonal through a cap and out of the side.
        let r = Ray::new(DVec3::new(0.0, 3.0, 0.0), DVec3::new(0.5, -1.0, 0.0));
        let h = all(&c, &r);
        assert_eq!(
            h.iter().map(|h| (h.t, h.part)).collect::<Vec<_>>(),
            vec![(1.0, CAP), (2.0, SIDE)]
        );
    }

    #[test]
    fn open_keeps_solid_inside() {
        let c = Cylinder::new(DVec3::ZERO, DVec3::new(0.0, 2.0, 0.0), 1.0, true);
        assert!(all(&c, &Ray::new(DVec3::new(0.5, 5.0, 0.0), DVec3::NEG_Y)).is_empty());
        let h = all(
            &c,
            &Ray::new(DVec3::new(0.0, 3.0, 0.0), DVec3::new(0.5, -1.0, 0.0)),
        );
        assert_eq!(
            h.iter().map(|h| (h.t, h.part)).collect::<Vec<_>>(),
            vec![(2.0, SIDE)]
        );
        assert!(c.inside(DVec3::new(0.2, 1.0, 0.2)));
        assert!(!c.inside(DVec3::new(0.2, 2.1, 0.2)));
        assert!(!c.inside(DVec3::new(0.9, 1.0, 0.9)));
    }

    #[test]
    fn oblique_axis_bounds_and_inside_ray() {
        let c = Cylinder::new(
            DVec3::new(1.0, 1.0, 1.0),
            DVec3::new(3.0, 1.0, 1.0),
            0.5,
            false,
        );
        let b = c.bounds();
        assert!(
            (b.min - DVec3::new(1.0, 0.5, 0.5)).length() < 1e-12,
            "{b:?}"
        );
        assert!(
            (b.max - DVec3::new(3.0, 1.5, 1.5)).length() < 1e-12,
            "{b:?}"
        );
        let h = all(&c, &Ray::new(DVec3::new(2.0, 1.0, 1.0), DVec3::X));
        assert_eq!(
            h.iter().map(|h| (h.t, h.part)).collect::<Vec<_>>(),
            vec![(1.0, CAP)]
        );
        let c = Cylinder::new(DVec3::ZERO, DVec3::ONE, 0.5, false);
        let b = c.bounds();
        let e = 0.5 * (2.0f64 / 3.0).sqrt();
        assert!((b.max - DVec3::splat(1.0 + e)).length() < 1e-12, "{b:?}");
    }

    #[test]
    fn degenerate() {
        let r = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
        for c in [
            Cylinder::new(DVec3::ZERO, DVec3::ZERO, 1.0, false),
            Cylinder::new(DVec3::ZERO, DVec3::Y, 0.0, false),
            Cylinder::new(DVec3::ZERO, DVec3::splat(f64::NAN), 1.0, false),
        ] {
            assert!(all(&c, &r).is_empty());
            assert!(!c.inside(DVec3::ZERO));
            assert!(c.bounds().is_empty());
        }
        let c = Cylinder::new(DVec3::ZERO, DVec3::Y, 1.0, false);
        assert!(all(&c, &Ray::new(DVec3::ZERO, DVec3::ZERO)).is_empty());
        // Grazing the side.
        assert!(all(&c, &Ray::new(DVec3::new(1.0 + 1e-9, 0.5, -5.0), DVec3::Z)).is_empty());
        assert_eq!(
            all(&c, &Ray::new(DVec3::new(1.0 - 1e-9, 0.5, -5.0), DVec3::Z)).len(),
            2
        );
    }
}
