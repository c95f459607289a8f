//! A difference's tight box in its first member's own space, for a first member turned off
//! the world's axes. The world box `cull::cull_box` gives such a node holds the turned box's
//! corners, and most of it is empty: advanced/abyss's hull is four differences of a blob less
//! three planes, each a long, thin octant turned 15 degrees about y, and the media's shadow
//! rays (nearly vertical) crossed each world box about twice as often as the octant's. Each
//! such ray listed the blob's crossings and the planes' (with the blob's density at each),
//! all dropped. A ray missing the box in the member's space has no crossing on the node: the
//! test is only a skip of work whose answer is empty, so no picture changes.

use super::complement;
use super::polyhedron::polyhedron_box;
use crate::math::{Aabb, DMat4, DVec3, Ray};
use crate::scene::desc::CsgOp;
use crate::scene::object::{ObjKind, Object};

/// The local box is kept only when, taken back to the world, it fills at most this share of
/// the node's world box (a ray that the world box lets through is then often turned away).
const MAX_SHARE: f64 = 0.5;

/// Past this many box sizes from the box, the ray's start in the member's space is not
/// trusted to its padding (the rounding of the map grows with the distance): no test.
const NEAR: f64 = 1e6;

/// A difference's solid in the space of its first member (a turned shape leaf): inside that
/// member's own bounds and outside each subtracted plane, padded.
pub struct LocalBox {
    /// World to the first member's space: its transform's `inv`, as `Object::local_ray`
    /// maps a ray for the member's shape.
    inv: DMat4,
    bx: Aabb,
    /// `NEAR` box sizes, for `misses`' trust in the mapped start.
    near: f64,
}

impl LocalBox {
    /// The box of a difference whose first member is a shape turned off the axes, when it is
    /// finite and fills at most `MAX_SHARE` of `world` (the node's tight world box).
    pub fn of(op: CsgOp, children: &[Object], world: &Aabb) -> Option<LocalBox> {
        if op != CsgOp::Difference {
            return None;
        }
        let first = children.first()?;
        let (ObjKind::Shape(s, _), Some(t)) = (&first.kind, first.transform.as_deref()) else {
            return None;
        };
        // An inverted member's solid is outside its bounds.
        if first.inverse {
            return None;
        }
        let turned = (0..3).any(|c| (0..3).any(|r| r != c && t.m.col(c)[r] != 0.0));
        let local = s.bounds();
        if !turned || !local.is_finite() || local.is_empty() || !world.is_finite() {
            return None;
        }
        // The member's own box: every crossing of it, and every point it holds (which a
        // subtracted member's kept crossing is), lies in it, as its world bounds assume.
        let mut planes = Vec::new();
        for (axis, n) in [DVec3::X, DVec3::Y, DVec3::Z].into_iter().enumerate() {
            planes.push((n, local.max[axis]));
            planes.push((-n, -local.min[axis]));
        }
        // What each subtracted plane leaves, n·p <= d in the world, with p = m(q):
        // (mᵀn)·q <= d − n·m(0).
        let (mt, m0) = (t.m.transpose(), t.m.transform_point3(DVec3::ZERO));
        for c in &children[1..] {
            if let Some((n, d)) = complement(c) {
                let (nl, dl) = (mt.transform_vector3(n), d - n.dot(m0));
                if nl.is_finite() && dl.is_finite() && nl != DVec3::ZERO {
                    planes.push((nl, dl));
                }
            }
        }
        let bx = polyhedron_box(&planes)?;
        if !bx.is_finite() || bx.is_empty() {
            return None;
        }
        let volume = |b: &Aabb| (b.max - b.min).element_product();
        let share = volume(&bx) * t.m.determinant().abs() / volume(world);
        let near = NEAR * (1.0 + (bx.max - bx.min).max_element());
        (share <= MAX_SHARE).then_some(LocalBox {
            inv: t.inv,
            bx,
            near,
        })
    }

    /// Whether the ray crosses nothing of the node with `t` in [0, tmax]: its stretch in the
    /// box (the same slab test as `Aabb::hit`, in the member's space) is empty, or lies behind
    /// its start or past `tmax`, with 1e-7 of the distances to spare (as `cull::Window`'s box)
    /// for the rounding of the slab test. The box's own padding (1e-6 of its size, from
    /// `polyhedron_box`) covers the rounding of the map, for a start within `NEAR` box sizes.
    /// A start or direction not finite keeps the ray, and so does any infinite distance.
    #[inline]
    pub fn misses(&self, ray: &Ray, tmax: f64) -> bool {
        let o = self.inv.transform_point3(ray.origin);
        let d = self.inv.transform_vector3(ray.dir);
        let inv = d.recip();
        let (t0, t1) = ((self.bx.min - o) * inv, (self.bx.max - o) * inv);
        let lo = t0.min(t1).max_element();
        let hi = t0.max(t1).min_element();
        let pad = 1e-7 * (lo.abs().max(hi.abs()) + 1.0);
        let near =
            o.is_finite() && d.is_finite() && (o - self.bx.min).abs().max_element() < self.near;
        near && (lo - pad > hi + pad || hi + pad < 0.0 || lo - pad > tmax)
    }
}

#[cfg(test)]
mod tests {
    use super::super::window_tests::same_hits;
    use crate::geom::test_rng::Lcg;
    use crate::math::{DVec3, Ray};
    use crate::scene::object::{ObjKind, Object, Scratch};

    /// advanced/abyss's hull octants (a blob less three planes, turned), a turned squashed
    /// ball less a plane, a torus less a turned plane, a superellipsoid less a plane and a box.
    const SCENE: &str = r#"
        #declare Hull = blob { threshold 0.6 sphere { 0, 1, 1 } sphere { 0, 1, 1 scale <0.3, 0.45, 0.8> }
            cylinder { -y, y, 2, 2 scale <0.03, 0.3, 0.012> translate <0, 0.5, 0.45> } }
        difference { object { Hull } plane { y, 0 } plane { z, 0 } plane { x, 0 inverse }
            scale <18, 6, 300> rotate -15*y translate <30, 40, -150> }
        difference { object { Hull } plane { y, 0 inverse } plane { z, 0 inverse } plane { x, 0 inverse }
            scale <6, 10, 20> rotate <10, -15, 5> }
        difference { sphere { 0, 1 } plane { x, 0.2 } scale <1, 2, 8> rotate <0, 30, 20> }
        difference { torus { 1, 0.3 } plane { y + x, 0.1 } scale <1, 1, 4> rotate 40*y }
        difference { superellipsoid { <0.3, 0.3> } plane { z, 0 } box { -0.5, 0.5 }
            scale <2, 1, 5> rotate <20, 40, 0> }
    "#;

    /// Drops every local box below `o`; counts those it dropped.
    fn unbox(o: &mut Object) -> usize {
        match &mut o.kind {
            ObjKind::Shape(..) => 0,
            ObjKind::Csg { children, cull, .. } => {
                let own = cull.as_mut().and_then(|c| c.local.take()).is_some() as usize;
                own + children.iter_mut().map(unbox).sum::<usize>()
            }
        }
    }

    /// Each node lists the same crossings, bit for bit, with its local box as without: rays
    /// from around and inside it, along the axes, and from its surface (as shadow rays leave
    /// it), with and without an end; the box turns many of them away.
    #[test]
    fn local_boxes_drop_no_crossing() {
        let boxed = crate::scene::csg_hit::tests::built(SCENE);
        let mut plain = crate::scene::csg_hit::tests::built(SCENE);
        let dropped: usize = plain.objects.iter_mut().map(unbox).sum();
        assert!(dropped >= 4, "{dropped}");
        let mut rng = Lcg(32);
        let (mut sa, mut sb) = (Scratch::default(), Scratch::default());
        for (n, (a, b)) in boxed.objects.iter().zip(&plain.objects).enumerate() {
            let bx = a.bounds;
            let (centre, size) = ((bx.min + bx.max) * 0.5, bx.max - bx.min);
            let (mut hits, mut missed) = (0, 0);
            for k in 0..6000 {
                let o = centre + rng.vec(1.5) * size;
                // Half the rays aimed at the box's middle, where the node is.
                let dir = match k % 4 {
                    0 => [DVec3::X, DVec3::Y, DVec3::Z][k % 3],
                    1 => DVec3::new(rng.next() * 0.02, 1.0, rng.next() * 0.02),
                    _ => centre + rng.vec(0.3) * size - o,
                };
                let mut ray = Ray::new(o, dir);
                // Every fifth ray leaves the surface where the last one met it.
                if k % 5 == 0 {
                    if let Some(h) = a.first_hit(&ray, f64::INFINITY, &mut sa) {
                        ray = Ray::new(ray.at(h.t), rng.vec(2.0));
                    }
                }
                let tmax = match k % 3 {
                    0 => f64::INFINITY,
                    1 => rng.next() * size.max_element(),
                    _ => 1e3 * size.max_element(),
                };
                if let ObjKind::Csg { cull: Some(c), .. } = &a.kind {
                    missed += c.local.as_ref().is_some_and(|l| l.misses(&ray, tmax)) as usize;
                }
                hits += same_hits(a, b, &ray, tmax, &mut sa, &mut sb) as usize;
            }
            assert!(hits > 100, "object {n}: {hits} hits");
            assert!(missed > 300 || n >= 4, "object {n}: {missed} turned away");
        }
    }
}
