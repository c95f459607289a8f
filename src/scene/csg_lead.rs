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

use crate::math::{Aabb, DMat4, DVec3, Ray, Slabs, EPSILON};
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
    /// No lead, and member `k`, a box, has no crossing the node keeps (`shut_of`): the
    /// searches and `Object::all_hits` do not gather it (they still ask it whether it holds
    /// the others' points).
    Shut(u8),
}

impl Lead {
    /// Whether a leaf leads (`Member`, `Folded`): the searches' lead instances.
    #[inline(always)]
    pub(super) fn leads(self) -> bool {
        matches!(self, Lead::Member | Lead::Folded)
    }

    /// The member the searches leave out (`Shut`), or `usize::MAX`.
    #[inline(always)]
    pub(super) fn shut(self) -> usize {
        match self {
            Lead::Shut(k) => k as usize,
            _ => usize::MAX,
        }
    }
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

/// The lead of a node `op` over `children` (its plane members' `faces`, its `clip`), for a
/// node without index or quadric lanes (whose searches gather member 0 first, in leaf order,
/// through the leaf path), when it pays (`pays`).
pub fn lead_of(op: CsgOp, children: &[Object], faces: Option<&Faces>, clip: &[Object]) -> Lead {
    if !matches!(op, CsgOp::Intersection | CsgOp::Difference) {
        return Lead::None;
    }
    let Some(first) = children.first() else {
        return Lead::None;
    };
    let lead = if plain_leaf(first, faces.and_then(|f| f.get(0)).is_some()) && boxed(first) {
        Lead::Member
    } else {
        match folded(first) {
            Some((leaves, _, leaf_faces))
                if leaves.first().is_some_and(|l| {
                    plain_leaf(l, leaf_faces.and_then(|f| f.get(0)).is_some()) && boxed(l)
                }) =>
            {
                Lead::Folded
            }
            _ => return Lead::None,
        }
    };
    if pays(lead, op, children, faces, clip) {
        lead
    } else {
        Lead::None
    }
}

/// How far, as a share of its size, the box `shut_of` leaves out must reach past the other
/// members' bounds on every side: crossings of the box lie on its faces up to the rounding of
/// `t`, `ray.at` and the transforms (~1e-16 of the coordinates), far inside this.
const SHUT_MARGIN: f64 = 1e-3;

/// The box in `shut_of`'s box member `b`'s space that holds every point where member `o`
/// may answer that it holds a point: `o`'s own bounds when its shape's test stays in them
/// (`Shape::inside_bounded`), taken through `o`'s transform, else its bounds in the world
/// (every member's test answers no outside them: `Object::leaf_inside`, `inside_node`,
/// `member_wants`' faces, and the box and quadric tests ask the bounds first), taken into
/// `b`'s space as the box of its eight corners (`Aabb::corners_mapped`: the image of a box
/// under an affine map is the hull of its corners' images) through the one matrix from `o`'s
/// space to `b`'s (its rounding is far inside `SHUT_MARGIN`).
fn held_in(b: &Object, o: &Object) -> Aabb {
    let (own, to_world) = match &o.kind {
        ObjKind::Shape(shape, _) if o.clip.is_empty() && shape.inside_bounded() => {
            (shape.bounds(), o.transform.as_deref().map(|t| t.m))
        }
        _ => (o.bounds, None),
    };
    if !own.is_finite() || own.is_empty() {
        return if own.is_empty() {
            Aabb::EMPTY
        } else {
            Aabb::INFINITE
        };
    }
    let to_b = b.transform.as_deref().map(|t| t.inv);
    let m = match (to_b, to_world) {
        (Some(inv), Some(m)) => inv * m,
        (Some(inv), None) => inv,
        (None, Some(m)) => m,
        (None, None) => DMat4::IDENTITY,
    };
    own.corners_mapped(&m)
}

/// `Lead::Shut(k)` for the first member `k` of an intersection (without lead or index) that
/// is a plain box leaf holding, with `SHUT_MARGIN` to spare on every side, the box `w` (in
/// its own space) where the other members that are not `inverse` may hold points
/// (`held_in`). A crossing of the box is kept only where every other member holds its
/// point, so in `w`, which lies inside the box, off its faces: none of the box's crossings
/// is kept, and a search that leaves them out finds the same first kept crossing (the others
/// keep their order) and the same answer to any-hit. The box is still asked whether it holds
/// the others' crossings. advanced/whiltile's tiles: their box (-1 to 1) holds the meeting
/// of the two rounding cylinders (-0.9 to 0.9); their world bounds, turned 30 degrees about
/// y, do not meet inside it.
pub fn shut_of(op: CsgOp, children: &[Object]) -> Lead {
    if op != CsgOp::Intersection || children.len() < 2 || children.len() > u8::MAX as usize {
        return Lead::None;
    }
    for (k, c) in children.iter().enumerate() {
        let ObjKind::Shape(shape, None) = &c.kind else {
            continue;
        };
        let Some(b) = shape.solid_box().filter(|_| plain_leaf(c, false)) else {
            continue;
        };
        let w = children
            .iter()
            .enumerate()
            .filter(|&(j, o)| j != k && !o.inverse)
            .fold(Aabb::INFINITE, |w, (_, o)| w.intersection(&held_in(c, o)));
        if !w.is_finite() || w.is_empty() {
            continue;
        }
        let pad = (w.max - w.min) * SHUT_MARGIN;
        let room = (b.max() - b.min()) * SHUT_MARGIN;
        if (w.min - pad).cmpgt(b.min() + room).all() && (w.max + pad).cmplt(b.max() - room).all() {
            return Lead::Shut(k as u8);
        }
    }
    Lead::None
}

/// Points across each face of a lead box in `kept_share`'s sample (`SAMPLES` squared).
const SAMPLES: usize = 8;

/// The least share of a lead box's surface where the node keeps the box's crossings for the
/// lead to be set (`pays`). Measured: incdemo/woods' boards 0.52 (their leads kept, the woods
/// 4-5 % faster with them), advanced/mist's spans 0.33 (1.5-3 % slower with), swirlbox's
/// rings 0.04-0.4 and whiltile's tiles 0 (4-7 % slower with).
const MIN_KEPT: f64 = 0.4;

/// Whether `lead` is worth its cost: the search's certificate (`csg_first_hit`) needs the
/// lead's first crossing kept, and saves the other members' crossings. So the lead is set
/// only where the node keeps the box's crossings on much of its surface (`kept_share`: a
/// box whose faces the other members cut away everywhere, as advanced/whiltile's tiles' two
/// rounding cylinders do, makes every ray pay the lead's tests for nothing), and where some
/// other leaf or member is more than a box (a box's crossings cost little more than the
/// lead's tests: objects/csg/granite's box frame and swirlbox's rings, differences of boxes,
/// were 4-7 % slower with leads). The answers are the same with or without a lead.
fn pays(
    lead: Lead,
    op: CsgOp,
    children: &[Object],
    faces: Option<&Faces>,
    clip: &[Object],
) -> bool {
    let dear = |c: &Object| !boxed(c);
    let leaves = match lead {
        Lead::Folded => folded(&children[0]).map_or(&[][..], |(l, _, _)| &l[1..]),
        _ => &[],
    };
    (children[1..].iter().any(dear) || leaves.iter().any(dear))
        && kept_share(lead, op, children, faces, clip) >= MIN_KEPT
}

/// The share, by area, of the lead box's surface where the node keeps a crossing of the box:
/// `SAMPLES` squared points across each face (the cells' centres), each asked as the
/// searches ask a crossing of the lead (the folded member's other leaves, the node's other
/// members, the clip).
fn kept_share(
    lead: Lead,
    op: CsgOp,
    children: &[Object],
    faces: Option<&Faces>,
    clip: &[Object],
) -> f64 {
    let leaf = lead_leaf(lead, children);
    let Some(b) = (match &leaf.kind {
        ObjKind::Shape(shape, _) => shape.solid_box(),
        _ => None,
    }) else {
        return 0.0;
    };
    let world = |p: DVec3| leaf.transform.as_ref().map_or(p, |t| t.point(p));
    let (node_rejecter, leaf_rejecter) = (Cell::new(usize::MAX), Cell::new(usize::MAX));
    let kept = |p: DVec3| {
        let leaf_kept = match lead {
            Lead::Folded => {
                let (leaves, _, leaf_faces) = folded(&children[0]).expect("a folded lead folds");
                csg_keeps(
                    CsgOp::Intersection,
                    0,
                    leaves,
                    None,
                    leaf_faces,
                    p,
                    &leaf_rejecter,
                )
            }
            _ => true,
        };
        leaf_kept
            && csg_keeps(op, 0, children, None, faces, p, &node_rejecter)
            && clip.iter().all(|c| c.inside(p))
    };
    let (lo, hi) = (b.min(), b.max());
    let (mut all, mut kept_area) = (0.0, 0.0);
    for axis in 0..3 {
        let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
        for side in [lo[axis], hi[axis]] {
            let mut corner = lo;
            corner[axis] = side;
            let (mut du, mut dv) = (DVec3::ZERO, DVec3::ZERO);
            du[u] = (hi[u] - lo[u]) / SAMPLES as f64;
            dv[v] = (hi[v] - lo[v]) / SAMPLES as f64;
            // Each cell's area in the world (the transform is affine).
            let (o, a, c) = (world(corner), world(corner + du), world(corner + dv));
            let cell = (a - o).cross(c - o).length();
            for i in 0..SAMPLES {
                for j in 0..SAMPLES {
                    let p = corner + du * (i as f64 + 0.5) + dv * (j as f64 + 0.5);
                    all += cell;
                    if kept(world(p)) {
                        kept_area += cell;
                    }
                }
            }
        }
    }
    if all > 0.0 && all.is_finite() {
        kept_area / all
    } else {
        0.0
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
    if !lead.leads() {
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
