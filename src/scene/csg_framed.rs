//! CSG nodes whose members are all transformed boxes: advanced/blocks' stacker blocks
//! (a box minus three bars, the block rotated and placed), ~29 % of stackerday's time through
//! the general search (`csg_first_hit`: a local ray, a vtable call and a list per member; every
//! keep question a member's `Object::inside`, each taking the point back through its own copy
//! of the block's matrix).
//!
//! The members' transforms are the same numbers to the bit (each member's copy of the node's
//! transform), and `Object::local_ray` and `Object::local_point` read only the inverse matrix:
//! the ray is taken into the members' space once per search and each crossing's point once
//! per keep test, and the results are the ones each member's own product gives. Members whose
//! transforms differ (advanced/swirlbox's rings: `intersection { box, box inverse }`, each
//! box with its own scale under the ring's) keep their own inverse matrices (`Frames::Own`),
//! and the ray and points are taken into each member's space by its own, as
//! `Object::local_ray` and `local_point` take them: the same products. Everything
//! else is the general search's steps: the same cull and slab tests (world space), the box's
//! own crossings (`BoxShape::each_crossing`, what its `intersect_all` lists) in the same
//! order, the keep test at the world point `ray.at(t)` with each member's bounds test and its
//! box's inside test (`Object::leaf_inside`), the clip, the flips.

use crate::geom::boxes::BoxShape;
use crate::math::{Aabb, DMat4, DVec3, Ray, Slabs, EPSILON};
use crate::scene::csg_boxes::{crossing_hit, insert_crossing, MAX_ALL};
use crate::scene::csg_members::want_inside;
use crate::scene::desc::CsgOp;
use crate::scene::object::{ObjKind, Object, SurfaceHit};

/// One member's box, bounds and what the node needs of it at a crossing of another member.
#[derive(Clone, Copy)]
struct Member {
    /// The member's bounds (world space): the search's slab test and `Object::leaf_inside`'s
    /// first test, read here beside the box rather than from the member's `Object`.
    bounds: Aabb,
    shape: BoxShape,
    /// `want_inside` of this member, turned by its `inverse`: the box's answer (strictly
    /// inside) that keeps a crossing when the point is in `bounds`.
    need: bool,
    /// The answer that keeps a crossing when the point is outside `bounds`: the member is
    /// then outside unless `inverse` (`leaf_inside`).
    outside_keeps: bool,
    /// The member's crossings' flip: its `inverse`, turned for a difference's subtracted
    /// member (the node's own `inverse` is added by the search).
    flip: bool,
}

impl Member {
    /// `BoxShape::inside` of a box that is not empty.
    #[inline(always)]
    fn holds(&self, p: DVec3) -> bool {
        let (min, max) = (self.shape.min(), self.shape.max());
        (p.x > min.x)
            & (p.y > min.y)
            & (p.z > min.z)
            & (p.x < max.x)
            & (p.y < max.y)
            & (p.z < max.z)
    }
}

/// A node's box members and their frames (`FramedBoxes::of`), in one block (with the
/// members' own matrices, when they differ, in another): a search reads nothing of the
/// members' `Object`s (scattered, 192 bytes each, with their transforms out of line) until it
/// returns a crossing.
pub struct FramedBoxes {
    /// The first member's inverse matrix (world to box space); what `Transform::inv_ray` and
    /// `inv_point` read.
    inv: DMat4,
    /// Each member's inverse matrix, when some member's is not `inv`'s bits.
    own: Option<Box<[DMat4]>>,
    n: usize,
    members: [Member; MAX_ALL],
}

/// `Transform::inv_ray` of a transform whose inverse matrix is `inv`.
#[inline(always)]
fn local_ray(inv: &DMat4, ray: &Ray) -> Ray {
    Ray {
        origin: inv.transform_point3(ray.origin),
        dir: inv.transform_vector3(ray.dir),
    }
}

/// The bits of a matrix, for comparing transforms as the products read them (`==` takes -0
/// for 0, whose products may differ in the sign of a zero).
fn bits(m: &DMat4) -> [u64; 16] {
    m.to_cols_array().map(f64::to_bits)
}

impl FramedBoxes {
    /// The members of a node `op` (not a union, no index, no faces) when there are one to
    /// `MAX_ALL` of them and each is a non-empty box leaf with a transform and without clip
    /// or window.
    pub fn of(op: CsgOp, children: &[Object]) -> Option<FramedBoxes> {
        if op == CsgOp::Union || children.is_empty() || children.len() > MAX_ALL {
            return None;
        }
        let inv = children[0].transform.as_deref()?.inv;
        let empty = Member {
            bounds: Aabb::EMPTY,
            shape: BoxShape::new(DVec3::ZERO, DVec3::ZERO),
            need: false,
            outside_keeps: false,
            flip: false,
        };
        let mut members = [empty; MAX_ALL];
        let mut shared = true;
        for (j, c) in children.iter().enumerate() {
            let ObjKind::Shape(shape, None) = &c.kind else {
                return None;
            };
            let t = c.transform.as_deref()?;
            if !c.clip.is_empty() {
                return None;
            }
            shared &= bits(&t.inv) == bits(&inv);
            members[j] = Member {
                bounds: c.bounds,
                shape: shape.solid_box()?,
                need: want_inside(op, j) != c.inverse,
                outside_keeps: c.inverse == want_inside(op, j),
                flip: c.inverse ^ (op == CsgOp::Difference && j > 0),
            };
        }
        let own = (!shared).then(|| {
            children
                .iter()
                .filter_map(|c| c.transform.as_deref().map(|t| t.inv))
                .collect()
        });
        Some(FramedBoxes {
            inv,
            own,
            n: children.len(),
            members,
        })
    }

    /// Whether the members have their own matrices (`own`), not one shared.
    #[inline(always)]
    fn shared(&self) -> bool {
        self.own.is_none()
    }

    #[inline(always)]
    fn members(&self) -> &[Member] {
        &self.members[..self.n.min(MAX_ALL)]
    }

    /// `Transform::inv_ray` of each member's transform, when they share one.
    #[inline(always)]
    fn local_ray(&self, ray: &Ray) -> Ray {
        local_ray(&self.inv, ray)
    }

    /// Member `j`'s own inverse matrix (`own`; `inv` when they share one).
    #[inline(always)]
    fn inv_of(&self, j: usize) -> &DMat4 {
        self.own.as_deref().map_or(&self.inv, |own| &own[j])
    }

    /// `csg_keeps(op, i, children, None, None, p, _)` of the node: every member but `i`
    /// answers at the world point `p` as the node needs. The point is taken into box space
    /// once (`Transform::inv_point`), when a member's bounds hold it (`leaf_inside`'s order
    /// of tests per member).
    /// With their own matrices, each member's point is its own product (`local_point`).
    #[inline(always)]
    fn keeps(&self, i: usize, p: DVec3) -> bool {
        let mut local = None;
        for (j, m) in self.members().iter().enumerate() {
            if j == i {
                continue;
            }
            let ok = if m.bounds.holds(p) {
                let q = match &self.own {
                    None => *local.get_or_insert_with(|| self.inv.transform_point3(p)),
                    Some(own) => own[j].transform_point3(p),
                };
                m.holds(q) == m.need
            } else {
                m.outside_keeps
            };
            if !ok {
                return false;
            }
        }
        true
    }
}

impl Object {
    /// `csg_first_hit::<false, false>` of a node whose members are `FramedBoxes`: the same
    /// search on the stack. The same crossings in the same order: each member's, after the
    /// same cull and slab tests, in `intersect_all`'s order and below `tmax`, inserted as
    /// they come after every equal key (so sorted by (order key, place in the gather), as
    /// `sort_crossings` sorts them). Each is kept by `FramedBoxes::keeps` (`csg_keeps`) and
    /// the clip; no test has a side effect, so the order of the questions cannot change it:
    /// the answer is the same crossing, bit for bit, with the same flip.
    #[inline(never)]
    pub(super) fn framed_first_hit<'a>(
        &'a self,
        children: &'a [Object],
        cull: Option<&Aabb>,
        framed: &FramedBoxes,
        ray: &Ray,
        tmax: f64,
    ) -> Option<SurfaceHit<'a>> {
        let inv_dir = ray.dir.recip();
        if cull.is_some_and(|c| c.hit(ray.origin, inv_dir, tmax).is_none()) {
            return None;
        }
        let slabs = Slabs::new(ray.origin, inv_dir);
        let mut local = None;
        let mut order = [(0i64, 0u32); 2 * MAX_ALL];
        let mut n = 0;
        for (i, m) in framed.members().iter().enumerate() {
            if !slabs.hits(&m.bounds, tmax) {
                continue;
            }
            let own;
            let r = match framed.shared() {
                true => local.get_or_insert_with(|| framed.local_ray(ray)),
                false => {
                    own = local_ray(framed.inv_of(i), ray);
                    &own
                }
            };
            m.shape.each_crossing(r, |hit| {
                if hit.t < tmax {
                    insert_crossing(&mut order, &mut n, i, hit);
                }
            });
        }
        let clip = &self.clip[..];
        for &(key, tag) in &order[..n] {
            let i = (tag >> 8) as usize;
            let hit = crossing_hit(key, tag);
            let p = ray.at(hit.t);
            if !framed.keeps(i, p) {
                continue;
            }
            if clip.is_empty() || (hit.t > EPSILON && clip.iter().all(|c| c.inside(p))) {
                return Some(SurfaceHit {
                    t: hit.t,
                    obj: &children[i],
                    hit,
                    flip: framed.members[i].flip ^ self.inverse,
                });
            }
        }
        None
    }

    /// `csg_any_hit::<false>` of a node whose members are `FramedBoxes`: whether any
    /// crossing `all_hits` lists is kept. The same crossings meet the same tests, member by
    /// member (`BoxShape::any_kept_by`, what the box's `any_kept` asks); no test has a side
    /// effect, so the answer is the general search's.
    #[inline(never)]
    pub(super) fn framed_any_hit(
        &self,
        cull: Option<&Aabb>,
        framed: &FramedBoxes,
        ray: &Ray,
        tmax: f64,
    ) -> bool {
        let inv_dir = ray.dir.recip();
        if cull.is_some_and(|c| c.hit(ray.origin, inv_dir, tmax).is_none()) {
            return false;
        }
        let slabs = Slabs::new(ray.origin, inv_dir);
        let clip = &self.clip[..];
        let mut local = None;
        for (i, m) in framed.members().iter().enumerate() {
            if !slabs.hits(&m.bounds, tmax) {
                continue;
            }
            let own;
            let r = match framed.shared() {
                true => local.get_or_insert_with(|| framed.local_ray(ray)),
                false => {
                    own = local_ray(framed.inv_of(i), ray);
                    &own
                }
            };
            let keep = |t: f64| {
                let p = ray.at(t);
                framed.keeps(i, p)
                    && (clip.is_empty() || (t > EPSILON && clip.iter().all(|c| c.inside(p))))
            };
            if m.shape.any_kept_by(r, tmax, keep) {
                return true;
            }
        }
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::test_rng::Lcg;
    use crate::scene::csg_hit::tests::built;
    use crate::scene::object::Scratch;

    /// Nodes of boxes under one transform (`framed_first_hit`) answer as `all_hits` does:
    /// the nearest crossing (t > EPSILON when clipped), bit for bit, with the same side and
    /// leaf, for the stacker block (bars sharing faces with each other and the outer box),
    /// inverse members and nodes, merges, intersections and a clipped difference, with rays
    /// from inside, outside and along the faces' planes.
    #[test]
    fn framed_nodes_match_all_hits() {
        let scene = built(
            r#"
            difference { box { -0.5, 0.5 } box { <-0.45, -0.45, -1>, <0.45, 0.45, 1> }
                         box { <-1, -0.45, -0.45>, <1, 0.45, 0.45> }
                         box { <-0.45, -1, -0.45>, <0.45, 1, 0.45> }
                         rotate <0, 12.9675, 0> translate <-2.5, 0.5, -10> }
            difference { box { -0.5, 0.5 } box { <-0.45, -0.45, -1>, <0.45, 0.45, 1> }
                         box { <-1, -0.45, -0.45>, <1, 0.45, 0.45> }
                         rotate -90 * y rotate <0, 2.16936, 0> translate <1, 0.5, 2> }
            intersection { box { -1, 1 } box { 0, 2 } box { -0.5, 0.5 inverse } rotate <10, 20, 30> }
            merge { box { -1, 1 } box { 0, 2 } box { <-1, 0, 0>, <1, 0, 1> } scale <1, 2, 0.5> rotate 40 * x }
            difference { box { -2, 2 } box { -1, 1 } inverse rotate 30 * z }
            difference { box { -2, 2 } box { <-1, -3, -1>, <1, 3, 1> } rotate 25 * y
                         clipped_by { plane { y, 1 } } }
            intersection { box { -1, 1 scale <5, 0.1, 5> } box { -1, 1 scale <4.75, 1.1, 4.75> inverse }
                           scale 0.4 translate <1, 0.5, -2> rotate <10, 35, 5> }
            difference { box { -1, 1 rotate 20 * z } box { 0, 2 scale <0.5, 3, 0.5> translate -x }
                         box { -0.5, 0.5 translate 0.8 * z rotate 45 * x } rotate 30 * y }
            "#,
        );
        let mut rng = Lcg(21);
        let (mut sa, mut sb) = (Scratch::default(), Scratch::default());
        let mut hits = 0;
        for (n, o) in scene.objects.iter().enumerate() {
            assert!(o.framed_boxes().is_some(), "object {n}");
            let centre = (o.bounds.min + o.bounds.max) * 0.5;
            for k in 0..20_000 {
                let mut from = centre + rng.vec(4.0);
                if k % 3 == 0 {
                    from = (from * 20.0).round() * 0.05;
                }
                let d = match k % 4 {
                    0 => [DVec3::X, DVec3::NEG_Y, DVec3::Z][k % 3],
                    1 => centre + rng.vec(0.6) - from,
                    _ => rng.vec(2.0),
                };
                let ray = Ray::new(from, d);
                let tmax = [f64::INFINITY, 3.0, rng.next() * 20.0][k % 3];
                let want = crate::scene::csg_hit::tests::reference(o, &ray, tmax, &mut sb)
                    .map(|h| (h.t.to_bits(), h.hit.part, h.flip, h.obj as *const Object));
                let got = o
                    .first_hit(&ray, tmax, &mut sa)
                    .map(|h| (h.t.to_bits(), h.hit.part, h.flip, h.obj as *const Object));
                assert_eq!(got, want, "object {n}, ray {k}");
                assert_eq!(
                    o.any_hit(&ray, tmax, &mut sa),
                    want.is_some(),
                    "object {n}, ray {k}"
                );
                hits += got.is_some() as usize;
            }
        }
        assert!(hits > 30_000, "{hits}");
    }
}
