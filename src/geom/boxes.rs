//! POV-Ray `box { corner1, corner2 }`: an axis-aligned solid box.
//!
//! Named `BoxShape` so importing it never shadows `std::boxed::Box`. `Hit::part` is the face
//! crossed: `2 * axis` for the low face, `2 * axis + 1` for the high face.

use crate::geom::{Hit, Shape};
use crate::math::{Aabb, DVec3, Ray, EPSILON};

#[derive(Clone, Copy, Debug)]
pub struct BoxShape {
    min: DVec3,
    max: DVec3,
    empty: bool,
}

impl BoxShape {
    /// Corners in any order. A box flat in one axis is kept (both of its crossings coincide);
    /// non-finite corners give an empty shape.
    pub fn new(corner1: DVec3, corner2: DVec3) -> BoxShape {
        let empty = !(corner1.is_finite() && corner2.is_finite());
        BoxShape {
            min: corner1.min(corner2),
            max: corner1.max(corner2),
            empty,
        }
    }

    /// Entry and exit of the full line as ((t, face), (t, face)). Inlined: called, its
    /// answer went back through memory and cost a frame per box crossing.
    #[inline(always)]
    fn slabs(&self, ray: &Ray) -> Option<((f64, u32), (f64, u32))> {
        if self.empty {
            return None;
        }
        let mut near = (f64::NEG_INFINITY, 0u32);
        let mut far = (f64::INFINITY, 0u32);
        // The axes written out, x then y then z: a loop indexing the vectors by a variable
        // compiled to address arithmetic and branches around each axis (radiosity_37's
        // gathering rays cross boxes 680 k times).
        let (o, d) = (ray.origin, ray.dir);
        let (lo, hi) = (self.min, self.max);
        if !(slab(o.x, d.x, lo.x, hi.x, 0, &mut near, &mut far)
            && slab(o.y, d.y, lo.y, hi.y, 1, &mut near, &mut far)
            && slab(o.z, d.z, lo.z, hi.z, 2, &mut near, &mut far))
        {
            return None;
        }
        (near.0 <= far.0 && near.0.is_finite() && far.0.is_finite()).then_some((near, far))
    }

    pub fn min(&self) -> DVec3 {
        self.min
    }

    pub fn max(&self) -> DVec3 {
        self.max
    }

    /// `any_kept` with the test known to the compiler (CSG searches of box members,
    /// `scene::csg_boxes`): the same crossings asked in the same order.
    #[inline(always)]
    pub fn any_kept_by(&self, ray: &Ray, tmax: f64, mut keep: impl FnMut(f64) -> bool) -> bool {
        let Some((near, far)) = self.slabs(ray) else {
            return false;
        };
        (near.0 > EPSILON && near.0 < tmax && keep(near.0))
            || (far.0 > EPSILON && far.0 < tmax && keep(far.0))
    }

    /// `intersect_all`'s crossings handed to `f` in its order (near, then far) instead of
    /// pushed to a list: CSG searches of box members (`scene::csg_boxes`) take them straight
    /// into their own list.
    #[inline(always)]
    pub fn each_crossing(&self, ray: &Ray, mut f: impl FnMut(Hit)) {
        if let Some((near, far)) = self.slabs(ray) {
            for (t, face) in [near, far] {
                if t > EPSILON {
                    f(Hit::with_part(t, face));
                }
            }
        }
    }
}

/// One axis of `BoxShape::slabs`: narrows `near` and `far` to the pair of faces across `axis`
/// (a tie keeps the earlier axis's face); false when the line, parallel to them, runs outside.
#[inline(always)]
fn slab(
    o: f64,
    d: f64,
    lo: f64,
    hi: f64,
    axis: u32,
    near: &mut (f64, u32),
    far: &mut (f64, u32),
) -> bool {
    if d == 0.0 {
        // Parallel to this pair of faces: either always between them or never.
        return !(o < lo || o > hi);
    }
    let (mut t0, mut t1) = ((lo - o) / d, (hi - o) / d);
    let (mut f0, mut f1) = (2 * axis, 2 * axis + 1);
    if t0 > t1 {
        std::mem::swap(&mut t0, &mut t1);
        std::mem::swap(&mut f0, &mut f1);
    }
    if t0 > near.0 {
        *near = (t0, f0);
    }
    if t1 < far.0 {
        *far = (t1, f1);
    }
    true
}

impl Shape for BoxShape {
    fn bounds(&self) -> Aabb {
        if self.empty {
            Aabb::EMPTY
        } else {
            Aabb::new(self.min, self.max)
        }
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        self.each_crossing(ray, |h| out.push(h));
    }

    fn intersect_first(&self, ray: &Ray, tmax: f64, _scratch: &mut Vec<Hit>) -> Option<Hit> {
        let (near, far) = self.slabs(ray)?;
        let (t, face) = if near.0 > EPSILON { near } else { far };
        (t > EPSILON && t < tmax).then(|| Hit::with_part(t, face))
    }

    #[inline]
    fn inside_bounded(&self) -> bool {
        true
    }

    fn inside(&self, p: DVec3) -> bool {
        !self.empty && p.cmpgt(self.min).all() && p.cmplt(self.max).all()
    }

    /// Near crossing then far, as `intersect_all` lists them, without the list: CSG shadow
    /// rays ask each box member through here (radiosity_37's walls).
    fn any_kept(
        &self,
        ray: &Ray,
        tmax: f64,
        _scratch: &mut Vec<Hit>,
        keep: &mut dyn FnMut(f64) -> bool,
    ) -> bool {
        self.any_kept_by(ray, tmax, keep)
    }

    fn solid_box(&self) -> Option<BoxShape> {
        (!self.empty).then_some(*self)
    }

    fn normal(&self, _p: DVec3, hit: &Hit) -> DVec3 {
        let mut n = DVec3::ZERO;
        n[(hit.part as usize / 2).min(2)] = if hit.part & 1 == 0 { -1.0 } else { 1.0 };
        n
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn all(b: &BoxShape, r: &Ray) -> Vec<Hit> {
        let mut v = Vec::new();
        b.intersect_all(r, &mut v);
        v.sort_by(|a, b| a.t.total_cmp(&b.t));
        v
    }

    #[test]
    fn hits_faces_and_normals() {
        let b = BoxShape::new(DVec3::new(1.0, 1.0, 1.0), DVec3::new(-1.0, -2.0, -1.0));
        let r = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
        let h = all(&b, &r);
        assert_eq!((h[0].t, h[1].t), (4.0, 6.0));
        assert_eq!(b.normal(r.at(4.0), &h[0]), DVec3::NEG_Z);
        assert_eq!(b.normal(r.at(6.0), &h[1]), DVec3::Z);
        let r = Ray::new(DVec3::new(0.5, 10.0, 0.5), DVec3::NEG_Y * 2.0);
        let h = all(&b, &r);
        assert_eq!((h[0].t, h[1].t), (4.5, 6.0));
        assert_eq!(b.normal(r.at(4.5), &h[0]), DVec3::Y);
        assert_eq!(b.normal(r.at(6.0), &h[1]), DVec3::NEG_Y);
        assert_eq!(
            b.intersect_first(&r, f64::INFINITY, &mut Vec::new())
                .unwrap()
                .t,
            4.5
        );
        assert!(b.intersect_first(&r, 4.0, &mut Vec::new()).is_none());
        assert_eq!(
            b.bounds(),
            Aabb::new(DVec3::new(-1.0, -2.0, -1.0), DVec3::ONE)
        );
    }

    #[test]
    fn inside_and_from_inside() {
        let b = BoxShape::new(DVec3::splat(-1.0), DVec3::splat(1.0));
        assert!(b.inside(DVec3::splat(0.99)));
        assert!(!b.inside(DVec3::new(0.0, 1.01, 0.0)));
        let r = Ray::new(DVec3::ZERO, DVec3::new(1.0, 0.5, 0.0));
        let h = all(&b, &r);
        assert_eq!(h.len(), 1);
        assert_eq!((h[0].t, h[0].part), (1.0, 1));
        assert_eq!(
            b.intersect_first(&r, f64::INFINITY, &mut Vec::new())
                .unwrap()
                .t,
            1.0
        );
    }

    #[test]
    fn grazing_parallel_and_degenerate() {
        let b = BoxShape::new(DVec3::splat(-1.0), DVec3::splat(1.0));
        assert!(all(&b, &Ray::new(DVec3::new(0.0, 1.5, -5.0), DVec3::Z)).is_empty());
        assert_eq!(
            all(&b, &Ray::new(DVec3::new(0.0, 0.5, -5.0), DVec3::Z)).len(),
            2
        );
        // Along an edge: inclusive slabs keep it.
        assert_eq!(
            all(&b, &Ray::new(DVec3::new(1.0, 1.0, -5.0), DVec3::Z)).len(),
            2
        );
        assert!(all(&b, &Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::ZERO)).is_empty());
        assert!(all(&b, &Ray::new(DVec3::ZERO, DVec3::ZERO)).is_empty());
        let flat = BoxShape::new(DVec3::new(-1.0, 0.0, -1.0), DVec3::new(1.0, 0.0, 1.0));
        let h = all(&flat, &Ray::new(DVec3::new(0.0, 3.0, 0.0), DVec3::NEG_Y));
        assert_eq!(h.len(), 2);
        assert_eq!(h[0].t, 3.0);
        assert!(!flat.inside(DVec3::ZERO));
        let bad = BoxShape::new(DVec3::splat(f64::NAN), DVec3::ONE);
        assert!(all(&bad, &Ray::new(DVec3::new(0.5, 0.5, -5.0), DVec3::Z)).is_empty());
        assert!(bad.bounds().is_empty());
    }

    /// `any_kept` answers as the default's listing does, and asks `keep` about the same
    /// crossings in the same order up to the first kept: rays from inside, outside, along
    /// faces and edges, flat and empty boxes, random cuts `tmax` and keep tests.
    #[test]
    fn any_kept_is_the_listing() {
        let mut rng = crate::geom::test_rng::Lcg(7);
        let boxes = [
            BoxShape::new(DVec3::splat(-1.0), DVec3::splat(1.0)),
            BoxShape::new(DVec3::new(-1.0, 0.0, -1.0), DVec3::new(1.0, 0.0, 1.0)),
            BoxShape::new(DVec3::new(-10.0, -0.1, -10.0), DVec3::new(10.0, 4.0, 10.0)),
            BoxShape::new(DVec3::splat(f64::NAN), DVec3::ONE),
        ];
        let mut kept = 0;
        for (n, b) in boxes.iter().enumerate() {
            for k in 0..20_000 {
                let mut o = rng.vec(12.0);
                if k % 4 == 0 {
                    o = o.round();
                }
                let d = match k % 5 {
                    0 => [DVec3::X, DVec3::NEG_Y, DVec3::Z][k % 3],
                    1 => DVec3::ZERO,
                    _ => rng.vec(2.0),
                };
                let ray = Ray::new(o, d);
                let tmax = [f64::INFINITY, 3.0, rng.next() * 20.0, -1.0][k % 4];
                let cut = rng.next() * 20.0;
                let (mut asked_a, mut asked_b) = (Vec::new(), Vec::new());
                let got = b.any_kept(&ray, tmax, &mut Vec::new(), &mut |t| {
                    asked_a.push(t.to_bits());
                    t > cut
                });
                let want = crate::geom::any_listed_kept(b, &ray, tmax, &mut Vec::new(), &mut |t| {
                    asked_b.push(t.to_bits());
                    t > cut
                });
                assert_eq!((got, &asked_a), (want, &asked_b), "box {n}, ray {k}");
                kept += got as usize;
            }
        }
        assert!(kept > 1_000, "{kept}");
    }
}
