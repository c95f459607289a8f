//! The questions a CSG node asks its members: which members a ray may cross
//! (`each_member`), their crossings (`member_hits`), and whether a crossing is on the node's
//! surface (`csg_keeps`, through `member_wants`). The general search (`csg_hit`) and the box
//! members' instances (`csg_boxes`) share these, so the rule of which member must hold a
//! point is written once (`want_inside`).

use std::cell::Cell;

use crate::geom::Hit;
use crate::math::{DVec3, Ray};
use crate::scene::children::ChildIndex;
use crate::scene::desc::CsgOp;
use crate::scene::faces::{self, Face, Faces};
use crate::scene::object::{ObjKind, Object, Scratch, SurfaceHit};

/// What `csg_keeps` wishes of member `j` of a node `op`: to hold the point (true) or not.
#[inline(always)]
pub(super) fn want_inside(op: CsgOp, j: usize) -> bool {
    match op {
        CsgOp::Intersection => true,
        CsgOp::Difference => j == 0,
        CsgOp::Union | CsgOp::Merge => false,
    }
}

/// Whether member `j` (`o`) answers at `p` as a node `op` needs for a crossing of another
/// member to be kept, through its face when it has one. Inlined at every call: as a closure it
/// stayed out of line, a call per member asked (radiosity_37's gathering rays ask 1.7 M
/// members of its walls' difference).
#[inline(always)]
pub(super) fn member_wants(
    op: CsgOp,
    faces: Option<&Faces>,
    p: DVec3,
    j: usize,
    o: &Object,
) -> bool {
    let inside = match faces.and_then(|f| f.get(j)) {
        // `Object::inside` of a leaf, with the face's test for its shape's.
        Some(f) if o.bounds.holds(p) => f.inside(p) != o.inverse,
        Some(_) => o.inverse,
        // A plain leaf's answer inlined here (`Object::inside` may be out of line).
        None => o.leaf_inside(p).unwrap_or_else(|| o.inside(p)),
    };
    inside == want_inside(op, j)
}

/// Calls `f(member, i, s)` for every member of a CSG node a ray may cross within `tmax`: all of
/// them in member order without an index, else the index's candidates (a leaf of an opened
/// member union, numbered as the index numbers it).
pub(super) fn each_member<'a>(
    children: &'a [Object],
    index: Option<&ChildIndex>,
    ray: &Ray,
    tmax: f64,
    s: &mut Scratch<'a>,
    mut f: impl FnMut(&'a Object, usize, &mut Scratch<'a>),
) {
    match index {
        None => children.iter().enumerate().for_each(|(i, c)| f(c, i, s)),
        Some(ix) => {
            let from = s.members.len();
            ix.candidates(ray, tmax, &mut s.members);
            for k in from..s.members.len() {
                let i = s.members[k] as usize;
                f(ix.leaf(children, i), i, s);
            }
            s.members.truncate(from);
        }
    }
}

/// Whether a crossing at `p` of CSG member `i` is on the result's surface: every other member
/// must contain `p` (intersection), not contain it (union-like merge), or, for a difference,
/// the first member must and the subtracted ones must not.
pub(super) fn csg_keeps(
    op: CsgOp,
    i: usize,
    children: &[Object],
    index: Option<&ChildIndex>,
    faces: Option<&Faces>,
    p: DVec3,
    rejecter: &Cell<usize>,
) -> bool {
    // With an index only the members whose boxes hold `p` are asked: outside its box a member
    // without `inverse` is not inside (members with `inverse` have infinite boxes).
    match (op, index) {
        (CsgOp::Union, _) => return true,
        (CsgOp::Merge, Some(ix)) => return !ix.any_at(p, |j| j != i && children[j].inside(p)),
        (CsgOp::Difference, Some(ix)) => {
            return (i == 0 || children[0].inside(p))
                && !ix.any_at(p, |j| j != i && j != 0 && children[j].inside(p));
        }
        _ => {}
    }
    // Faces answer `inside` as the member would (`scene::faces`), points far out excepted.
    let faces = faces.filter(|_| faces::point_ok(p));
    // The member that turned the last crossing of this node away is asked first: crossings
    // outside a polyhedron are mostly turned away by the same face. `inside` has no side
    // effects, so the order of the questions cannot change the answer.
    let r = rejecter.get();
    if r != i && r < children.len() && !member_wants(op, faces, p, r, &children[r]) {
        return false;
    }
    for (j, o) in children.iter().enumerate() {
        if j != i && j != r && !member_wants(op, faces, p, j, o) {
            rejecter.set(j);
            return false;
        }
    }
    true
}

/// `c.all_hits(ray, tmax, s)` of CSG member `c`, through its face when it has one (`ray` then
/// within `faces::ray_ok`): a plane leaf without clipping has at most one crossing.
#[inline(always)]
pub(super) fn member_hits<'a>(
    c: &'a Object,
    face: Option<&Face>,
    ray: &Ray,
    tmax: f64,
    s: &mut Scratch<'a>,
) {
    match face {
        Some(f) => {
            if let Some(t) = f.hit(ray).filter(|&t| t < tmax) {
                s.surface.push(SurfaceHit {
                    t,
                    obj: c,
                    hit: Hit::new(t),
                    flip: c.inverse,
                });
            }
        }
        // A leaf without clipping or window, the common member: `all_hits`'s own steps for
        // it, here in the search's loop instead of through the general function's frame and
        // its tests for clips, windows and nodes (the same calls and arithmetic).
        None => match &c.kind {
            ObjKind::Shape(shape, None) if c.clip.is_empty() => {
                let mut local = None;
                let r = c.local_ray(ray, &mut local);
                s.hits.clear();
                shape.intersect_all(r, &mut s.hits);
                c.take_hits(tmax, s);
            }
            _ => c.all_hits(ray, tmax, s),
        },
    }
}
