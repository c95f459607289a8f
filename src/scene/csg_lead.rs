//! The lead of an intersection or difference: its first member when that is a plain leaf, or
//! the first leaf of a first member the search folds (`csg_hit::folded`). Every crossing such
//! a node keeps lies where the lead's inside test says yes (a crossing of any other leaf is
//! kept only if the lead holds its point: an intersection wants every member inside, a
//! difference its first, and a folded intersection every leaf), and that test says no at a
//! point outside the lead's bounds (`Object::leaf_inside`, `member_wants` and `quadric_keeps`
//! ask the bounds first; a box member's `BoxTest` is asked only of boxes its bounds hold).
//!
//! So when the ray's points are beyond the lead's bounds at every `t` of a stretch, no
//! crossing in that stretch is kept but the lead's own. `ray.at(t)` is monotone in `t` in
//! each coordinate (a product by a fixed direction component, then a sum, each correctly
//! rounded), so one point settles the whole stretch: if `ray.at(t0)` is beyond the bounds'
//! face the ray moves away from, so is `ray.at(t)` for every `t >= t0` (`beyond_after`), and
//! for every `t <= t0` past the face it moves towards (`beyond_before`).
//!
//! A shadow ray leaving a board's front face (incdemo/woods' `Test`: a box cut by two
//! cylinders) is beyond the box's bounds from `EPSILON` on, so only the box's crossings can
//! block it (`lead_any_hit`), and the cylinders' division and square root chains are not
//! run; a camera ray whose first crossing of the box is kept, with every earlier point
//! outside the box's bounds, has that crossing for its answer (`csg_first_hit`).

use std::cell::Cell;

use crate::math::{Aabb, DVec3, Ray, Slabs, EPSILON};
use crate::scene::csg_hit::folded;
use crate::scene::desc::CsgOp;
use crate::scene::faces::Faces;
use crate::scene::object::{csg_keeps, ObjKind, Object, Scratch};

/// Where a node's lead is (`Cull::lead`).
#[derive(Clone, Copy, PartialEq, Eq, Debug, Default)]
pub enum Lead {
    /// No lead: the searches ask every member.
    #[default]
    None,
    /// Member 0 is the lead.
    Member,
    /// Leaf 0 of member 0, a folded intersection, is the lead.
    Folded,
}

/// A leaf the searches gather through `gather_hits`' and `member_hits`' leaf path (no face,
/// clip or window), not `inverse`, with finite bounds.
fn plain_leaf(c: &Object, has_face: bool) -> bool {
    matches!(&c.kind, ObjKind::Shape(_, None))
        && c.clip.is_empty()
        && !c.inverse
        && !has_face
        && c.bounds.is_finite()
}

/// Whether leaf `c` is a box: its bounds are its own faces (or hold them closely when it is
/// turned), so a ray's points pass beyond them as soon as they leave the box, and the leads'
/// certificates hold for most rays. A round lead's bounds leave corners where they fail and
/// every ray pays the test for nothing (advanced/whiltile, swirlbox, objects/csg/cliptst2
/// were 3-8 % slower with leads on every plain first leaf).
fn boxed(c: &Object) -> bool {
    matches!(&c.kind, ObjKind::Shape(shape, None) if shape.solid_box().is_some())
}

/// The lead of a node `op` over `children` (its plane members' `faces`), for a node without
/// index or quadric lanes (whose searches gather member 0 first, in leaf order, through the
/// leaf path).
pub fn lead_of(op: CsgOp, children: &[Object], faces: Option<&Faces>) -> Lead {
    if !matches!(op, CsgOp::Intersection | CsgOp::Difference) {
        return Lead::None;
    }
    let Some(first) = children.first() else {
        return Lead::None;
    };
    if plain_leaf(first, faces.and_then(|f| f.get(0)).is_some()) && boxed(first) {
        return Lead::Member;
    }
    match folded(first) {
        Some((leaves, _, leaf_faces))
            if leaves.first().is_some_and(|l| {
                plain_leaf(l, leaf_faces.and_then(|f| f.get(0)).is_some()) && boxed(l)
            }) =>
        {
            Lead::Folded
        }
        _ => Lead::None,
    }
}

impl Object {
    /// This node's lead (`Cull::lead`).
    #[inline(always)]
    pub(super) fn lead(&self) -> Lead {
        match &self.kind {
            ObjKind::Csg { cull: Some(c), .. } => c.lead,
            _ => Lead::None,
        }
    }
}

/// The lead leaf of `children` for `lead`, not `Lead::None`.
#[inline(always)]
pub(super) fn lead_leaf(lead: Lead, children: &[Object]) -> &Object {
    match lead {
        Lead::Folded => {
            &folded(&children[0])
                .expect("a folded lead's member folds")
                .0[0]
        }
        _ => &children[0],
    }
}

/// Whether `ray.at(t)` is beyond `b` for every `t >= t0`: past a face of `b` the ray moves
/// away from (see the module's note).
#[inline(always)]
pub(super) fn beyond_after(ray: &Ray, b: &Aabb, t0: f64) -> bool {
    let (p, d) = (ray.at(t0), ray.dir);
    ((d.x > 0.0) & (p.x > b.max.x))
        | ((d.x < 0.0) & (p.x < b.min.x))
        | ((d.y > 0.0) & (p.y > b.max.y))
        | ((d.y < 0.0) & (p.y < b.min.y))
        | ((d.z > 0.0) & (p.z > b.max.z))
        | ((d.z < 0.0) & (p.z < b.min.z))
}

/// Whether `ray.at(t)` is outside `b` for every `t < t1` (`t1 > 0`): `ray.at` of the double
/// below `t1` is short of a face of `b` the ray moves towards.
#[inline(always)]
pub(super) fn beyond_before(ray: &Ray, b: &Aabb, t1: f64) -> bool {
    if t1.is_nan() || t1 <= 0.0 {
        return false;
    }
    let below = f64::from_bits(t1.to_bits() - 1);
    let (p, d) = (ray.at(below), ray.dir);
    ((d.x > 0.0) & (p.x < b.min.x))
        | ((d.x < 0.0) & (p.x > b.max.x))
        | ((d.y > 0.0) & (p.y < b.min.y))
        | ((d.y < 0.0) & (p.y > b.max.y))
        | ((d.z > 0.0) & (p.z < b.min.z))
        | ((d.z < 0.0) & (p.z > b.max.z))
}

/// `csg_any_hit`'s answer for a node with a `lead` when the ray is beyond the lead's bounds
/// from `EPSILON` on (every crossing has `t > EPSILON`, `Shape::intersect_all`): then only
/// the lead's own crossings can be kept, so the answer is whether one of them is, after the
/// same tests that reach it there (member 0's slab test, and for a folded member
/// `all_hits`' cull box, local box and the leaf's slab test) and kept by the same tests
/// (the folded member's `csg_keeps`, then the node's `keep(0, t)`). None otherwise.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub(super) fn lead_any_hit<'a>(
    lead: Lead,
    children: &'a [Object],
    ray: &Ray,
    inv_dir: DVec3,
    slabs: &Slabs,
    tmax: f64,
    s: &mut Scratch<'a>,
    keep: impl Fn(usize, f64) -> bool,
) -> Option<bool> {
    if lead == Lead::None {
        return None;
    }
    let leaf = lead_leaf(lead, children);
    if !beyond_after(ray, &leaf.bounds, EPSILON) {
        return None;
    }
    let m = &children[0];
    if !slabs.hits(&m.bounds, tmax) {
        return Some(false);
    }
    let ObjKind::Shape(shape, _) = &leaf.kind else {
        unreachable!("a lead is a leaf");
    };
    let mut local = None;
    let r = leaf.local_ray(ray, &mut local);
    if lead == Lead::Member {
        return Some(shape.any_kept(r, tmax, &mut s.hits, &mut |t| keep(0, t)));
    }
    // `all_hits_unclipped` of the folded member, its leaf 0 alone.
    let ObjKind::Csg {
        children: leaves,
        cull,
        ..
    } = &m.kind
    else {
        unreachable!("a folded lead's member is a node");
    };
    if let Some(c) = cull.as_deref() {
        if c.aabb
            .as_ref()
            .is_some_and(|b| b.hit(ray.origin, inv_dir, tmax).is_none())
            || c.local.as_deref().is_some_and(|l| l.misses(ray, tmax))
        {
            return Some(false);
        }
    }
    if !slabs.hits(&leaf.bounds, tmax) {
        return Some(false);
    }
    let faces = cull.as_ref().and_then(|c| c.faces.as_ref());
    let rejecter = Cell::new(usize::MAX);
    Some(shape.any_kept(r, tmax, &mut s.hits, &mut |t| {
        csg_keeps(
            CsgOp::Intersection,
            0,
            leaves,
            None,
            faces,
            ray.at(t),
            &rejecter,
        ) && keep(0, t)
    }))
}

/// Whether `csg_first_hit`'s gather reaches the lead (member 0's slab test, and for a folded
/// member its cull box and the leaf's slab test, as the gather asks them).
#[inline(always)]
pub(super) fn lead_reached(
    lead: Lead,
    children: &[Object],
    ray: &Ray,
    inv_dir: DVec3,
    slabs: &Slabs,
    tmax: f64,
) -> bool {
    let m = &children[0];
    if !slabs.hits(&m.bounds, tmax) {
        return false;
    }
    match lead {
        Lead::Folded => {
            let (leaves, leaf_cull, _) = folded(m).expect("a folded lead's member folds");
            leaf_cull.is_none_or(|b| b.hit(ray.origin, inv_dir, tmax).is_some())
                && slabs.hits(&leaves[0].bounds, tmax)
        }
        _ => true,
    }
}

#[cfg(test)]
#[path = "csg_lead_tests.rs"]
mod tests;
