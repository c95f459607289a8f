//! CSG members that are boxes, asked with the box's own code instead of through
//! `Object::inside`, `all_hits` and the `Shape` vtable: radiosity_37's walls and column bases
//! are differences of boxes, and their searches ask box members some 1.4 M times.
//!
//! A node without index whose members include box leaves without transform keeps a copy of
//! each such member's `BoxShape` (`BoxMembers`, in its `Cull`), and its searches run an
//! instance of `csg_first_hit`/`csg_any_hit` that asks those members here. The answers are the
//! same bit for bit: a box member's inside test (`BoxTest`) is `Object::inside`'s leaf path
//! (the bounds test, which such a box's bounds make redundant, and the box's own test),
//! asked before the other members', and `box_hits` is
//! `member_hits`' leaf path (the box's `intersect_all` crossings in its order, those below
//! `tmax` taken as surface hits),
//! calling the very functions the general path reaches through the vtable. Only the dispatch
//! is gone; a separate instance keeps nodes without box members on the code they had (code
//! added to `csg_keeps` itself cost more than it saved three times: csg18, csg21). A node
//! whose members are all boxes (radiosity_37's column bases) is searched on the stack
//! (`boxes_first_hit`), without the general search's lists.

use std::cell::Cell;

use crate::geom::boxes::BoxShape;
use crate::geom::Hit;
use crate::math::{Aabb, DVec3, Ray, Slabs, EPSILON};
use crate::scene::children::ChildIndex;
use crate::scene::csg_hit::{order_key, push_crossing};
use crate::scene::csg_members::{member_wants, want_inside};
use crate::scene::desc::CsgOp;
use crate::scene::faces::{self, Faces};
use crate::scene::object::{ObjKind, Object, Scratch, SurfaceHit};

/// Which search a node other than a union runs (`Object::node_search`), decided once the
/// indexes are attached (`children::attach_indexes`).
#[derive(Clone, Copy, PartialEq, Eq, Debug, Default)]
pub enum Search {
    /// `csg_first_hit` without folding or box members.
    #[default]
    Plain,
    /// A member is folded (`Cull::folds`) and no member is a box.
    Folds,
    /// Some member is a box (`Cull::boxes`): `boxes_search`.
    Boxes,
    /// Every member is a box under one transform (`Cull::framed`): `framed_first_hit`.
    Framed,
}

/// The most members a node whose members are all boxes may have for `boxes_first_hit`.
pub const MAX_ALL: usize = 8;

/// Puts a box member's crossing into a search's `order` list, kept sorted by `order_key`
/// (a later crossing with an equal key after the earlier ones), tagged `member << 8 | face`.
#[inline(always)]
pub(super) fn insert_crossing(
    order: &mut [(i64, u32); 2 * MAX_ALL],
    n: &mut usize,
    i: usize,
    hit: Hit,
) {
    let key = order_key(hit.t);
    let mut k = *n;
    while k > 0 && order[k - 1].0 > key {
        order[k] = order[k - 1];
        k -= 1;
    }
    order[k] = (key, (i as u32) << 8 | hit.part);
    *n += 1;
}

/// The crossing an `order` entry holds: `t` is the key's inverse (`order_key` is an
/// involution on the bits), the face the tag's low byte.
#[inline(always)]
pub(super) fn crossing_hit(key: i64, tag: u32) -> Hit {
    Hit::with_part(
        f64::from_bits(order_key(f64::from_bits(key as u64)) as u64),
        tag & 0xff,
    )
}

/// A box member: its shape, for a leaf without transform whose bounds hold the whole box, so
/// that `Object::inside`'s bounds test can be left out: a point strictly inside the box is
/// inside the bounds, and one outside the bounds is outside the box, so the box's own test
/// gives the answer either way. (Transformed boxes stay with `Object::inside`: answered here
/// they cost as much, and advanced/whiltile's tiles measured slower.)
#[derive(Clone, Copy)]
pub struct BoxMember {
    pub(super) shape: BoxShape,
}

/// A box member's question in `csg_keeps_boxes`: whether the point is strictly inside the
/// box (`BoxShape::inside` of a box that is not empty) is what the node needs of it.
#[derive(Clone, Copy)]
struct BoxTest {
    min: DVec3,
    max: DVec3,
    /// `member_wants`' wish for this member (inside for an intersection's, the first of a
    /// difference's; outside otherwise) turned by its `inverse`: the box's own answer that
    /// keeps a crossing.
    need: bool,
    member: usize,
}

impl BoxTest {
    /// `BoxShape::inside` of a box that is not empty (`solid_box`): the same six
    /// comparisons, joined without branches.
    #[inline(always)]
    fn holds(&self, p: DVec3) -> bool {
        (p.x > self.min.x)
            & (p.y > self.min.y)
            & (p.z > self.min.z)
            & (p.x < self.max.x)
            & (p.y < self.max.y)
            & (p.z < self.max.z)
    }
}

/// The box of each member that is a box leaf without clipping, by member number.
pub struct BoxMembers {
    boxes: Box<[Option<BoxMember>]>,
    /// Every member is one, and there are at most `MAX_ALL` (`boxes_first_hit`).
    all: bool,
    /// The box members' questions, in member order (`csg_keeps_boxes` asks them first).
    tests: Box<[BoxTest]>,
    /// The other members, in member order.
    rest: Box<[u32]>,
}

impl BoxMembers {
    /// The box members of `children` of a node `op`, when there is at least one.
    pub fn of(op: CsgOp, children: &[Object]) -> Option<BoxMembers> {
        let boxes: Box<[Option<BoxMember>]> = children
            .iter()
            .map(|c| match &c.kind {
                // The leaves `member_hits` and `Object::inside` answer on their short path.
                ObjKind::Shape(shape, None) if c.clip.is_empty() && c.transform.is_none() => shape
                    .solid_box()
                    .filter(|b| c.bounds.contains(b.min()) && c.bounds.contains(b.max()))
                    .map(|shape| BoxMember { shape }),
                _ => None,
            })
            .collect();
        let all = boxes.len() <= MAX_ALL && boxes.iter().all(Option::is_some);
        let tests = boxes
            .iter()
            .zip(children)
            .enumerate()
            .filter_map(|(j, (b, c))| {
                b.map(|b| BoxTest {
                    min: b.shape.min(),
                    max: b.shape.max(),
                    need: want_inside(op, j) != c.inverse,
                    member: j,
                })
            })
            .collect();
        let rest = (0..boxes.len() as u32)
            .filter(|&j| boxes[j as usize].is_none())
            .collect();
        boxes.iter().any(Option::is_some).then_some(BoxMembers {
            boxes,
            all,
            tests,
            rest,
        })
    }

    #[inline(always)]
    pub fn get(&self, i: usize) -> Option<&BoxMember> {
        self.boxes.get(i).and_then(Option::as_ref)
    }

    /// Whether every member is a box (at most `MAX_ALL` of them).
    #[inline(always)]
    pub fn all(&self) -> bool {
        self.all
    }
}

/// `o.inside(p)` of a member `o` whose shape is the box `m`: `Object::inside`'s leaf path
/// (what `BoxTest::holds` answers for the searches).
#[cfg(test)]
fn box_inside(o: &Object, m: &BoxMember, p: DVec3) -> bool {
    use crate::geom::Shape;
    m.shape.inside(p) != o.inverse
}

/// `member_hits(c, None, ray, tmax, s)` of a member `c` whose shape is the box `m`: its
/// crossings in `intersect_all`'s order, those below `tmax` gathered as `csg_first_hit`
/// gathers a leaf's (`csg_hit::push_crossing`: the `Hit` in `s.csg_hits`, its order entry
/// tagged `tag` in `s.csg_order`; the surface hit, of `c`, built only if it is kept).
#[inline(always)]
pub(super) fn box_hits(m: &BoxMember, ray: &Ray, tmax: f64, s: &mut Scratch<'_>, tag: u32) {
    m.shape.each_crossing(ray, |hit| {
        if hit.t < tmax {
            push_crossing(hit, s, tag);
        }
    });
}

/// `csg_keeps` of a node without index whose box members are `boxes`: whether every member
/// but `i` answers as the node needs. The box members are asked first, each by six
/// comparisons (`BoxTest`), then the others as `csg_keeps` asks them, the one that turned
/// the last crossing away first. No question has a side effect, so their order cannot
/// change the answer; asking the boxes first only spares the costlier members' questions
/// (radiosity_37's walls: three boxes and the arches' intersection).
#[inline(always)]
pub(super) fn csg_keeps_boxes(
    op: CsgOp,
    i: usize,
    children: &[Object],
    faces: Option<&Faces>,
    boxes: &BoxMembers,
    p: DVec3,
    rejecter: &Cell<usize>,
) -> bool {
    if op == CsgOp::Union {
        return true;
    }
    boxes
        .tests
        .iter()
        .all(|b| b.member == i || b.holds(p) == b.need)
        && (boxes.rest.is_empty() || keeps_rest(op, i, children, faces, boxes, p, rejecter))
}

/// `csg_keeps_boxes`' questions to the members that are not boxes.
fn keeps_rest(
    op: CsgOp,
    i: usize,
    children: &[Object],
    faces: Option<&Faces>,
    boxes: &BoxMembers,
    p: DVec3,
    rejecter: &Cell<usize>,
) -> bool {
    let faces = faces.filter(|_| faces::point_ok(p));
    let r = rejecter.get();
    if r != i && r < children.len() && !member_wants(op, faces, p, r, &children[r]) {
        return false;
    }
    for &j in boxes.rest.iter() {
        let j = j as usize;
        if j != i && j != r && !member_wants(op, faces, p, j, &children[j]) {
            rejecter.set(j);
            return false;
        }
    }
    true
}

impl Object {
    /// `first_hit` of a node other than a union, past its polyhedron case: the search its
    /// `Cull::search` names, the folding and box code compiled out of the instances
    /// that have none (through the folding one, objects/csg/intee1 and cliptst2 cost 2-3 %
    /// more instructions).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    pub(super) fn node_search<'a>(
        &'a self,
        op: CsgOp,
        children: &'a [Object],
        index: Option<&ChildIndex>,
        culls: (Option<&Aabb>, Option<&Faces>),
        ray: &Ray,
        tmax: f64,
        s: &mut Scratch<'a>,
    ) -> Option<SurfaceHit<'a>> {
        let (search, led) = match &self.kind {
            ObjKind::Csg { cull: Some(c), .. } => (c.search, c.lead.leads()),
            _ => (Search::Plain, false),
        };
        let fold = match search {
            // Box members without dispatch (`csg_boxes`); such nodes have no index.
            Search::Boxes => return self.boxes_search(op, children, culls, ray, tmax, s),
            Search::Framed => match self.framed_boxes() {
                Some(f) => return self.framed_first_hit(children, culls.0, f, ray, tmax),
                None => false,
            },
            Search::Folds => true,
            Search::Plain => false,
        };
        self.csg_first_hit_as::<false>((fold, led), op, children, index, culls, ray, tmax, s)
    }

    /// `csg_first_hit`'s instance for `(fold, led)`: its `FOLD` and `LEAD` parameters from
    /// the node's folding and lead (`BOXES` the caller's).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn csg_first_hit_as<'a, const BOXES: bool>(
        &'a self,
        (fold, led): (bool, bool),
        op: CsgOp,
        children: &'a [Object],
        index: Option<&ChildIndex>,
        culls: (Option<&Aabb>, Option<&Faces>),
        ray: &Ray,
        tmax: f64,
        s: &mut Scratch<'a>,
    ) -> Option<SurfaceHit<'a>> {
        match (fold, led) {
            (true, true) => {
                self.csg_first_hit::<true, BOXES, true>(op, children, index, culls, ray, tmax, s)
            }
            (true, false) => {
                self.csg_first_hit::<true, BOXES, false>(op, children, index, culls, ray, tmax, s)
            }
            (false, true) => {
                self.csg_first_hit::<false, BOXES, true>(op, children, index, culls, ray, tmax, s)
            }
            (false, false) => {
                self.csg_first_hit::<false, BOXES, false>(op, children, index, culls, ray, tmax, s)
            }
        }
    }

    /// This node's box members, if it has any (`Cull::boxes`).
    #[inline(always)]
    pub(super) fn box_members(&self) -> Option<&BoxMembers> {
        match &self.kind {
            ObjKind::Csg { cull: Some(c), .. } => c.boxes.as_ref(),
            _ => None,
        }
    }

    /// `first_hit` of a node (not a union) with box members, and so without index: the
    /// search on the stack when every member is a box, else `csg_first_hit`'s instance that
    /// asks the box members without dispatch. Out of line, so that `first_hit` grows by one
    /// test and call for the nodes without.
    #[inline(never)]
    pub(super) fn boxes_search<'a>(
        &'a self,
        op: CsgOp,
        children: &'a [Object],
        culls: (Option<&Aabb>, Option<&Faces>),
        ray: &Ray,
        tmax: f64,
        s: &mut Scratch<'a>,
    ) -> Option<SurfaceHit<'a>> {
        let led = self.lead().leads();
        match self.box_members() {
            Some(b) if b.all() => self.boxes_first_hit(op, children, culls.0, b, ray, tmax),
            _ => self.csg_first_hit_as::<true>(
                (self.folds(), led),
                op,
                children,
                None,
                culls,
                ray,
                tmax,
                s,
            ),
        }
    }

    /// This node's members as boxes under one transform, if they are (`Cull::framed`).
    #[inline(always)]
    pub(super) fn framed_boxes(&self) -> Option<&crate::scene::csg_framed::FramedBoxes> {
        match &self.kind {
            ObjKind::Csg { cull: Some(c), .. } => c.framed.as_deref(),
            _ => None,
        }
    }

    /// Whether this node's search folds members (`Cull::folds`).
    #[inline(always)]
    fn folds(&self) -> bool {
        matches!(&self.kind, ObjKind::Csg { cull: Some(c), .. } if c.folds)
    }

    /// `csg_first_hit::<false, _>` of a node (not a union, no index) whose members are all
    /// boxes (`BoxMembers::all`): the same search on the stack. The same crossings in the
    /// same order: each member's, after the same cull and slab tests, in `intersect_all`'s
    /// order and below `tmax`, inserted as they come after every equal key (so sorted by
    /// (order key, place in the gather), as `sort_crossings` sorts them). Each is kept by
    /// the members' `BoxTest`s (`Object::inside`) and the clip as `csg_keeps` asks them; no
    /// test has a side effect, so the order of the questions cannot change it: the answer is
    /// the same crossing, bit for bit, with the same flip.
    #[inline(never)]
    pub(super) fn boxes_first_hit<'a>(
        &'a self,
        op: CsgOp,
        children: &'a [Object],
        cull: Option<&Aabb>,
        boxes: &BoxMembers,
        ray: &Ray,
        tmax: f64,
    ) -> Option<SurfaceHit<'a>> {
        let inv_dir = ray.dir.recip();
        if cull.is_some_and(|c| c.hit(ray.origin, inv_dir, tmax).is_none()) {
            return None;
        }
        let slabs = Slabs::new(ray.origin, inv_dir);
        let members = &boxes.boxes[..children.len().min(MAX_ALL)];
        // (order key, member << 8 | face): `t` is the key's inverse (`order_key` is an
        // involution on the bits), and the box's hit is `Hit::with_part(t, face)`.
        let mut order = [(0i64, 0u32); 2 * MAX_ALL];
        let mut n = 0;
        for (i, (c, m)) in children.iter().zip(members).enumerate() {
            let Some(m) = m else { continue };
            if !slabs.hits(&c.bounds, tmax) {
                continue;
            }
            m.shape.each_crossing(ray, |hit| {
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
            // Every other member answers as `csg_keeps` needs (`BoxTest`: `box_inside`).
            if !boxes
                .tests
                .iter()
                .all(|b| b.member == i || b.holds(p) == b.need)
            {
                continue;
            }
            if clip.is_empty() || (hit.t > EPSILON && clip.iter().all(|c| c.inside(p))) {
                let c = &children[i];
                return Some(SurfaceHit {
                    t: hit.t,
                    obj: c,
                    hit,
                    flip: c.inverse ^ (op == CsgOp::Difference && i > 0) ^ self.inverse,
                });
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::test_rng::Lcg;
    use crate::scene::csg_hit::entry_place;
    use crate::scene::csg_hit::tests::built;

    /// `box_inside` is `Object::inside` and `box_hits` is `member_hits`, bit for bit, for box
    /// members plain, inverse and flat, with points on and near their faces; transformed
    /// boxes and other shapes are left to `Object::inside`.
    #[test]
    fn box_members_answer_as_objects() {
        let scene = built(
            r#"
            difference { box { <-10, -0.1, -10>, <10, 4, 10> } box { <-9, 0.3, -9>, <9, 3.5, 9> }
                         box { -1, 1 inverse } box { -1, 1 scale <2, 0.5, 1> rotate <10, 20, 30> translate x }
                         box { <-1, 0, -1>, <1, 0, 1> } sphere { 0, 1 } }
            "#,
        );
        let o = &scene.objects[0];
        let ObjKind::Csg { children, .. } = &o.kind else {
            panic!("a CSG node")
        };
        let boxes = BoxMembers::of(CsgOp::Difference, children).expect("box members");
        assert!(boxes.get(3).is_none() && boxes.get(5).is_none() && !boxes.all());
        assert!((0..3).chain([4]).all(|j| boxes.get(j).is_some()));
        let mut rng = Lcg(5);
        let (mut sa, mut sb) = (Scratch::default(), Scratch::default());
        let mut inside = 0;
        for k in 0..40_000 {
            let mut p = rng.vec(12.0);
            if k % 3 == 0 {
                // On a face's plane of the first boxes, or on an integer lattice.
                p = p.round();
            }
            if k % 5 == 1 {
                p.y = [-0.1, 4.0, 0.3, 3.5, 0.0][k % 5];
            }
            let d = match k % 4 {
                0 => [DVec3::X, DVec3::NEG_Y, DVec3::Z][k % 3],
                _ => rng.vec(2.0),
            };
            let ray = Ray::new(p, d);
            let tmax = [f64::INFINITY, 3.0, rng.next() * 20.0][k % 3];
            for (j, c) in children.iter().enumerate() {
                let Some(b) = boxes.get(j) else { continue };
                assert_eq!(box_inside(c, b, p), c.inside(p), "member {j}, point {p}");
                let t = boxes.tests.iter().find(|t| t.member == j).expect("a test");
                assert_eq!(
                    t.holds(p) == t.need,
                    c.inside(p) == want_inside(CsgOp::Difference, j),
                    "member {j}, point {p}"
                );
                inside += c.inside(p) as usize;
                crate::scene::object::member_hits(c, None, &ray, tmax, &mut sa);
                box_hits(b, &ray, tmax, &mut sb, j as u32);
                // Records in `csg_hits`, their places in gather order (`push_crossing`).
                let places: Vec<_> = sb
                    .csg_order
                    .iter()
                    .map(|&e| entry_place(e) as usize)
                    .collect();
                assert_eq!(
                    places,
                    (0..sb.csg_hits.len()).map(|k| k << 1).collect::<Vec<_>>()
                );
                sb.csg_order.clear();
                let key = |h: &SurfaceHit| (h.t.to_bits(), h.hit.part, h.flip);
                let a: Vec<_> = sa.surface.iter().map(key).collect();
                let b: Vec<_> = sb
                    .csg_hits
                    .iter()
                    .map(|&hit| (hit.t.to_bits(), hit.part, c.inverse))
                    .collect();
                assert_eq!(a, b, "member {j}, ray {k}");
                sa.surface.clear();
                sb.csg_hits.clear();
            }
        }
        assert!(inside > 10_000, "{inside}");
    }

    /// `csg_keeps_boxes` (box members first, by `BoxTest`) answers as `csg_keeps` does for
    /// every member's crossing: differences, intersections and merges of boxes plain,
    /// inverse and flat with spheres, moved boxes, planes (faces) and a nested node, at
    /// points on and near the boxes' faces, whatever member turned the last point away.
    #[test]
    fn keeps_boxes_match_csg_keeps() {
        let scene = built(
            r#"
            difference { box { <-10, -0.1, -10>, <10, 4, 10> } box { <-9, 0.3, -9>, <9, 3.5, 9> }
                         box { <-4, 0.1, -4>, <4, 5, 4> }
                         intersection { merge { cylinder { <0, 0.3, 0>, <0, 0.3, 12>, 2 }
                                                cylinder { <0, 0.3, 0>, <0, 0.3, 12>, 2 rotate 90 * y } }
                                        plane { y, 0.3 inverse } } }
            intersection { box { -1, 1 } sphere { 0, 1.3 } box { -0.5, 0.5 inverse }
                           plane { y, 0.5 } plane { x, 0.7 } box { -1, 1 scale 0.9 rotate <10, 20, 30> } }
            merge { box { -1, 1 } sphere { x, 0.8 } box { <-1, 0, -1>, <1, 0, 1> } box { 0, 2 inverse } }
            difference { sphere { 0, 2 } box { -1, 1 } box { <-3, -0.5, -0.5>, <3, 0.5, 0.5> } inverse }
            "#,
        );
        let mut rng = Lcg(17);
        let mut kept = 0;
        for (n, o) in scene.objects.iter().enumerate() {
            let ObjKind::Csg {
                op,
                children,
                index: None,
                cull,
            } = &o.kind
            else {
                panic!("object {n}: a node without index");
            };
            let boxes = o.box_members().expect("box members");
            let faces = cull.as_ref().and_then(|c| c.faces.as_ref());
            let (a, b) = (Cell::new(usize::MAX), Cell::new(usize::MAX));
            for k in 0..30_000 {
                let mut p = rng.vec(6.0);
                match k % 4 {
                    0 => p = (p * 2.0).round() * 0.5,
                    1 => p[k % 3] = [-1.0, 1.0, 0.3, 0.5, -0.1, 3.5, 4.0, 0.0][k % 8],
                    _ => {}
                }
                for i in 0..children.len() {
                    let want =
                        crate::scene::object::csg_keeps(*op, i, children, None, faces, p, &a);
                    let got = csg_keeps_boxes(*op, i, children, faces, boxes, p, &b);
                    assert_eq!(got, want, "object {n}, member {i}, point {p}");
                    kept += want as usize;
                }
            }
        }
        assert!(kept > 5_000, "{kept}");
    }

    /// Nodes whose members are all boxes (`boxes_first_hit`) answer as `all_hits` does: the
    /// nearest crossing (t > EPSILON when clipped), bit for bit, with the same side, for
    /// radiosity_37's column base, inverse members and nodes, merges, intersections and a
    /// clipped difference, with rays from inside, outside and along faces.
    #[test]
    fn all_box_nodes_match_all_hits() {
        let scene = built(
            r#"
            difference { box { <-4.7, 0, -4.7>, <4.7, 3.6, 4.7> } box { <-4.1, -0.1, -4.1>, <4.1, 4, 4.1> }
                         box { <-5, 0.5, -5>, <5, 3.3, 5> } }
            intersection { box { -1, 1 } box { 0, 2 } box { -0.5, 0.5 inverse } }
            merge { box { -1, 1 } box { 0, 2 } box { <-1, 0, 0>, <1, 0, 1> } }
            difference { box { -2, 2 } box { -1, 1 } inverse }
            difference { box { -2, 2 } box { <-1, -3, -1>, <1, 3, 1> } clipped_by { plane { y, 1 } } }
            "#,
        );
        let mut rng = Lcg(9);
        let (mut sa, mut sb) = (Scratch::default(), Scratch::default());
        let mut hits = 0;
        for (n, o) in scene.objects.iter().enumerate() {
            assert!(o.box_members().is_some_and(BoxMembers::all), "object {n}");
            for k in 0..20_000 {
                let mut from = rng.vec(8.0);
                if k % 3 == 0 {
                    from = from.round() * 0.5;
                }
                let d = match k % 4 {
                    0 => [DVec3::X, DVec3::NEG_Y, DVec3::Z][k % 3],
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
                hits += got.is_some() as usize;
            }
        }
        assert!(hits > 15_000, "{hits}");
    }
}
