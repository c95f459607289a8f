//! The CSG searches: which member crossings lie on a node's surface (`csg_keeps`), and the
//! nearest such crossing of an intersection, difference, merge or clipped object found without
//! testing every crossing (`first_hit`, `any_hit`). `Object::all_hits` lists them all.

use std::cell::Cell;

use crate::geom::Hit;
use crate::math::{has_avx, Aabb, Ray, Slabs, EPSILON};
use crate::scene::children::ChildIndex;
use crate::scene::csg_boxes::{box_hits, csg_keeps_boxes};
use crate::scene::csg_lead::{beyond_before, lead_any_hit, lead_leaf, lead_reached, Lead};
use crate::scene::csg_members::want_inside;
use crate::scene::csg_quadrics::{any_quadric_kept, gather_quadrics, quadric_keeps};
use crate::scene::desc::CsgOp;
use crate::scene::face_lanes::FaceLanes;
use crate::scene::faces::{self, Face, Faces, MAX_ALL};
use crate::scene::object::{
    csg_keeps, each_member, member_hits, ObjKind, Object, Scratch, SurfaceHit,
};

/// Crossings gathered for a search are tagged with their member `i`, and for the leaves of a
/// member folded in (`folded`) with the leaf's number plus one above this shift.
const LEAF_SHIFT: u32 = 16;

/// A gathered crossing's tag as (member, leaf + 1 or 0 for the member itself). Without
/// folding, tags are plain member numbers (a node may have more members than the tag's low
/// bits hold).
#[inline(always)]
fn split_tag<const FOLD: bool>(tag: u32) -> (usize, usize) {
    if FOLD {
        (
            (tag & ((1 << LEAF_SHIFT) - 1)) as usize,
            (tag >> LEAF_SHIFT) as usize,
        )
    } else {
        (tag as usize, 0)
    }
}

/// The leaves, tight box and faces of member `c` when the search may test its crossings itself
/// instead of through `c.all_hits`: an intersection without `clipped_by`, `inverse` or an index,
/// whose `all_hits` is the leaves' crossings, in leaf order, that every other leaf contains.
pub(super) fn folded(c: &Object) -> Option<(&[Object], Option<&Aabb>, Option<&Faces>)> {
    match &c.kind {
        ObjKind::Csg {
            op: CsgOp::Intersection,
            children,
            index: None,
            cull,
        } if c.clip.is_empty() && !c.inverse && children.len() < (1 << LEAF_SHIFT) - 1 => Some((
            children,
            cull.as_ref().and_then(|c| c.aabb.as_ref()),
            cull.as_ref().and_then(|c| c.faces.as_ref()),
        )),
        _ => None,
    }
}

/// An integer that orders crossings' `t` as `f64::total_cmp` does (its own mapping of the
/// bits), for sorting them by plain integer comparisons.
#[inline(always)]
pub(super) fn order_key(t: f64) -> i64 {
    let b = t.to_bits() as i64;
    b ^ (((b >> 63) as u64) >> 1) as i64
}

/// A search's order entry: (order key, place in the gather, tag) packed into one integer whose
/// order is the tuple's, the key in the high half (its sign bit flipped, so that unsigned order
/// is the key's signed order), the place and the tag in the low. As an integer, the gather's
/// pushes and the sort's loads and moves are all 8-byte halves: the tuple `(i64, u32, u32)`
/// was pushed as 8 + 4 + 4 bytes and moved by the sort as one 16-byte load, which cannot be
/// forwarded from the narrower stores still waiting behind the shapes' divisions (a stall of
/// ~4 % of csg_first_hit's samples on incdemo/woods/wood_2).
#[inline(always)]
pub(super) fn order_entry(key: i64, place: u32, tag: u32) -> u128 {
    ((key as u64 ^ 1 << 63) as u128) << 64 | (place as u128) << 32 | tag as u128
}

/// The place in the gather of an order entry (`order_entry`).
#[inline(always)]
pub(super) fn entry_place(e: u128) -> u32 {
    (e >> 32) as u32
}

/// The `t` an order entry's key was made from (`order_key` is its own inverse), bit for bit.
#[inline(always)]
fn entry_t(e: u128) -> f64 {
    f64::from_bits(order_key(f64::from_bits((e >> 64) as u64 ^ 1 << 63)) as u64)
}

/// A search's place for its next crossing: twice the crossing's index in `s.csg_hits` (the
/// order of the gather), plus one when the crossing was listed in `s.surface` (`LISTED`).
/// Places are unique and grow with the gather, as the tie order needs.
#[inline(always)]
fn next_place(s: &Scratch<'_>) -> u32 {
    (s.csg_hits.len() as u32) << 1
}

/// The low bit of a place (`next_place`): the crossing's surface hit is in `s.surface`, at
/// the `part` of its `s.csg_hits` record.
const LISTED: u32 = 1;

/// The tag of an order entry (`order_entry`).
#[inline(always)]
fn entry_tag(e: u128) -> u32 {
    e as u32
}

/// Sorts a search's order entries, the order `sort_unstable` gives them: no two entries
/// share a place, so every sort gives this one order, (order key, place). A short list is
/// sorted here by insertion, without the call into the library's sort (radiosity_37's walls
/// sort 211 k lists, most of two to four crossings).
#[inline(always)]
fn sort_crossings(order: &mut [u128]) {
    if order.len() > 8 {
        order.sort_unstable();
        return;
    }
    for k in 1..order.len() {
        let e = order[k];
        let mut m = k;
        while m > 0 && order[m - 1] > e {
            order[m] = order[m - 1];
            m -= 1;
        }
        order[m] = e;
    }
}

/// Member `i` as `each_member` offers it.
fn member_at<'a>(children: &'a [Object], index: Option<&ChildIndex>, i: usize) -> &'a Object {
    index.map_or(&children[i], |ix| ix.leaf(children, i))
}

/// Crossing `hit` of a leaf member (or folded leaf) appended to `s.csg_hits`, and its order
/// entry (order key, place, `tag`: `order_entry`) to `s.csg_order`. Its surface hit (the leaf,
/// `hit`, the leaf's `inverse`, as `take_hits` would list it) is built only if it is kept:
/// the 32-byte `Hit` is stored instead of a 56-byte `SurfaceHit` for every crossing.
#[inline(always)]
pub(super) fn push_crossing(hit: Hit, s: &mut Scratch<'_>, tag: u32) {
    s.csg_order
        .push(order_entry(order_key(hit.t), next_place(s), tag));
    s.csg_hits.push(hit);
}

/// `each_member`, with the loop of a node without index here, where `f` can be inlined in it.
#[inline(always)]
fn each_member_inline<'a>(
    children: &'a [Object],
    index: Option<&ChildIndex>,
    ray: &Ray,
    tmax: f64,
    s: &mut Scratch<'a>,
    mut f: impl FnMut(&'a Object, usize, &mut Scratch<'a>),
) {
    match index {
        None => {
            for (i, c) in children.iter().enumerate() {
                f(c, i, s);
            }
        }
        Some(_) => each_member(children, index, ray, tmax, s, f),
    }
}

/// `member_hits(c, face, ray, tmax, s)` with each crossing's order entry `(order key, place,
/// tag)` pushed to `s.csg_order` as it is listed: a leaf without face, clip or window
/// (`member_hits`' own case) has the shape list its crossings into `s.csg_hits` itself, and
/// those below `tmax` get entries (their surface hits are built from the leaf and the record
/// when kept: `push_crossing`); the others' surface hits are listed in `s.surface`, each
/// with a record in `s.csg_hits` giving its place there. The same crossings in the same
/// order as `member_hits` lists them.
#[inline(always)]
pub(super) fn gather_hits<'a>(
    c: &'a Object,
    face: Option<&Face>,
    ray: &Ray,
    tmax: f64,
    s: &mut Scratch<'a>,
    tag: u32,
    keeps: &impl Fn(u32, f64) -> bool,
) {
    match (face, &c.kind) {
        (None, ObjKind::Shape(shape, None)) if c.clip.is_empty() => {
            let mut local = None;
            let r = c.local_ray(ray, &mut local);
            // The shape appends (`Shape::intersect_all`); crossings beyond `tmax` stay
            // without an entry. Only `t` is read back: a copy of the whole `Hit` read `part`
            // with its padding as one 8-byte load, which cannot be forwarded from the shape's
            // 4-byte store of `part` (stall26).
            let from = s.csg_hits.len();
            let keep = &mut |t| keeps(tag, t);
            shape.gather_kept(r, tmax, &mut s.csg_hits, &mut s.hits, keep);
            for k in from..s.csg_hits.len() {
                let t = s.csg_hits[k].t;
                if t < tmax {
                    s.csg_order
                        .push(order_entry(order_key(t), (k as u32) << 1, tag));
                }
            }
        }
        _ => {
            let from = s.surface.len();
            member_hits(c, face, ray, tmax, s);
            for j in from..s.surface.len() {
                let t = s.surface[j].t;
                s.csg_order
                    .push(order_entry(order_key(t), next_place(s) | LISTED, tag));
                s.csg_hits.push(Hit::with_part(t, j as u32));
            }
        }
    }
}

impl Object {
    /// `first_hit` of an intersection, difference or merge, with or without `clipped_by`: the
    /// nearest of the crossings `all_hits` would keep (and `first_hit` take: t > EPSILON when
    /// clipped), found by testing the members' crossings nearest first and stopping at the
    /// first one kept. `all_hits` tests every crossing (for a polyhedron of n planes, n
    /// crossings each asking up to n - 1 members), and the nearest kept one is usually among the
    /// first few.
    ///
    /// The same crossings are gathered in the same order: a member that is a plain
    /// intersection (`folded`) gives its leaves' crossings unfiltered, each then kept only if
    /// that intersection's own `csg_keeps` keeps it too, and its kept crossings keep their
    /// relative order (`all_hits` filters them in place). Every test (`csg_keeps`, the clip's
    /// `inside`) has no side effect on the answer, and ties in `t` go to the earlier in that
    /// order, as `min_by` over `all_hits` does: the answer is the same crossing, bit for bit.
    ///
    /// `FOLD` false: no member is folded, for nodes that have none to fold (the common case),
    /// so that their search pays nothing for the folding. `LEAD` false: the node has no lead
    /// (`csg_lead`, most nodes since `csg_lead::pays`), and its search none of the lead's code.
    #[allow(clippy::too_many_arguments)]
    #[inline(never)]
    pub(super) fn csg_first_hit<'a, const FOLD: bool, const BOXES: bool, const LEAD: bool>(
        &'a self,
        op: CsgOp,
        children: &'a [Object],
        index: Option<&ChildIndex>,
        (cull, faces): (Option<&Aabb>, Option<&Faces>),
        ray: &Ray,
        tmax: f64,
        s: &mut Scratch<'a>,
    ) -> Option<SurfaceHit<'a>> {
        // Read here, not passed: the instances without box members keep their arguments.
        let boxes = BOXES.then(|| self.box_members()).flatten();
        let inv_dir = ray.dir.recip();
        if cull.is_some_and(|c| c.hit(ray.origin, inv_dir, tmax).is_none()) {
            return None;
        }
        let ray_faces = faces.filter(|_| faces::ray_ok(ray));
        let start = s.surface.len();
        let order_from = s.csg_order.len();
        let hits_from = s.csg_hits.len();
        let slabs = Slabs::new(ray.origin, inv_dir);
        let fold = FOLD && index.is_none() && children.len() <= 1 << LEAF_SHIFT;
        // Set only for nodes without index or box members.
        let quadrics = self.quadric_lanes();
        let rejecter = Cell::new(usize::MAX);
        let leaf_rejecter = Cell::new(usize::MAX);
        let clip = &self.clip[..];
        // Whether the crossing at `t` of the member (or folded leaf) `tag` is on the node's
        // surface: asked in the search below, and by shapes that find their first kept
        // crossing themselves while they are gathered (`Shape::gather_kept`).
        let keeps = |tag: u32, t: f64| {
            let (i, leaf) = split_tag::<FOLD>(tag);
            let p = ray.at(t);
            let leaf_kept = || match leaf {
                0 => true,
                k => {
                    let (leaves, _, leaf_faces) = folded(member_at(children, index, i))
                        .expect("tagged crossings come from folded members");
                    csg_keeps(
                        CsgOp::Intersection,
                        k - 1,
                        leaves,
                        None,
                        leaf_faces,
                        p,
                        &leaf_rejecter,
                    )
                }
            };
            let clip_kept = || clip.is_empty() || (t > EPSILON && clip.iter().all(|c| c.inside(p)));
            let kept = || match (boxes.filter(|_| BOXES), quadrics) {
                // Nodes with box members have no index (`children::attach_indexes`).
                (Some(b), _) => csg_keeps_boxes(op, i, children, faces, b, p, &rejecter),
                (None, Some(q)) => quadric_keeps(op, i, children, q, p, &rejecter),
                (None, None) => csg_keeps(op, i, children, index, faces, p, &rejecter),
            };
            leaf_kept() && kept() && clip_kept()
        };
        // Whether order entry `e` is kept, and its surface hit if so. Inlined at both of its
        // calls: as a call, its frame and arguments cost more than the lead's search saved.
        let accept = std::convert::identity(
            #[inline(always)]
            |e: u128, hits: &[Hit], surface: &[SurfaceHit<'a>]| {
                let (j, tag) = (entry_place(e), entry_tag(e));
                // From the key, not from the record: the keep tests read nothing else of it.
                let t = entry_t(e);
                let (i, leaf) = split_tag::<FOLD>(tag);
                keeps(tag, t).then(|| {
                    let rec = hits[(j >> 1) as usize];
                    let mut h = if j & LISTED != 0 {
                        surface[rec.part as usize]
                    } else {
                        // `push_crossing`'s leaf: member `i`, or its folded leaf.
                        let c = member_at(children, index, i);
                        let c = match leaf {
                            0 => c,
                            k => {
                                &folded(c)
                                    .expect("tagged crossings come from folded members")
                                    .0[k - 1]
                            }
                        };
                        SurfaceHit {
                            t: rec.t,
                            obj: c,
                            hit: rec,
                            flip: c.inverse,
                        }
                    };
                    h.flip ^= op == CsgOp::Difference && i > 0;
                    h.flip ^= self.inverse;
                    h
                })
            },
        );
        // The lead (`csg_lead`) gathered first, as the gather below would: when its nearest
        // crossing is kept and every point before it lies outside the lead's bounds (where no
        // other crossing is kept), that crossing is the answer, the others not listed.
        let lead = if LEAD { self.lead() } else { Lead::None };
        let led = match lead {
            Lead::None | Lead::Shut(_) => false,
            Lead::Folded if !fold => false,
            _ => lead_reached(lead, children, ray, inv_dir, &slabs, tmax),
        };
        if led {
            let leaf = lead_leaf(lead, children);
            let tag = if lead == Lead::Folded {
                1 << LEAF_SHIFT
            } else {
                0
            };
            gather_hits(leaf, None, ray, tmax, s, tag, &keeps);
            let first = (order_from..s.csg_order.len()).min_by_key(|&k| s.csg_order[k]);
            if let Some(k) =
                first.filter(|&k| beyond_before(ray, &leaf.bounds, entry_t(s.csg_order[k])))
            {
                match accept(s.csg_order[k], &s.csg_hits, &s.surface) {
                    Some(h) => {
                        s.csg_order.truncate(order_from);
                        s.csg_hits.truncate(hits_from);
                        s.surface.truncate(start);
                        return Some(h);
                    }
                    // Not kept, so not the answer: the search need not ask it again (the
                    // entries are sorted below, so their order here does not matter).
                    None => {
                        s.csg_order.swap_remove(k);
                    }
                }
            }
        }
        let skip = if led { lead } else { Lead::None };
        // A box member none of whose crossings is kept (`csg_lead::shut_of`), if any.
        let shut = self.lead().shut();
        if let Some(shapes) = quadrics {
            gather_quadrics(children, shapes, ray, &slabs, tmax, s, &keeps);
        } else {
            // Inlined in the member loop: called, its frame cost ~20 instructions a member visit
            // (advanced/whiltile visits 325 k members).
            each_member_inline(
                children,
                index,
                ray,
                tmax,
                s,
                #[inline(always)]
                |c: &'a Object, i: usize, s: &mut Scratch<'a>| {
                    // The lead is gathered already.
                    if (skip == Lead::Member && i == 0) || i == shut {
                        return;
                    }
                    if !slabs.hits(&c.bounds, tmax) {
                        return;
                    }
                    if let Some((leaves, leaf_cull, leaf_faces)) = fold.then(|| folded(c)).flatten()
                    {
                        // `c.all_hits`'s own tests, in its order.
                        if leaf_cull.is_some_and(|b| b.hit(ray.origin, inv_dir, tmax).is_none()) {
                            return;
                        }
                        let leaf_faces = leaf_faces.filter(|_| faces::ray_ok(ray));
                        for (k, g) in leaves.iter().enumerate() {
                            if skip == Lead::Folded && i == 0 && k == 0 {
                                continue;
                            }
                            if !slabs.hits(&g.bounds, tmax) {
                                continue;
                            }
                            let tag = i as u32 | (k as u32 + 1) << LEAF_SHIFT;
                            let face = leaf_faces.and_then(|f| f.get(k));
                            gather_hits(g, face, ray, tmax, s, tag, &keeps);
                        }
                        return;
                    }
                    match boxes.filter(|_| BOXES).and_then(|b| b.get(i)) {
                        // Box members without dispatch (`csg_boxes`): `member_hits`' leaf path.
                        Some(b) => box_hits(b, ray, tmax, s, i as u32),
                        None => {
                            let face = ray_faces.and_then(|f| f.get(i));
                            gather_hits(c, face, ray, tmax, s, i as u32, &keeps)
                        }
                    }
                },
            );
        }
        let order = &mut s.csg_order[order_from..];
        // By (t as `total_cmp` orders it, place in the gather): places differ between entries.
        sort_crossings(order);
        let best = order
            .iter()
            .find_map(|&e| accept(e, &s.csg_hits, &s.surface));
        s.csg_order.truncate(order_from);
        s.csg_hits.truncate(hits_from);
        s.surface.truncate(start);
        best
    }

    /// `any_hit` of an intersection, difference or merge, with or without `clipped_by`: whether
    /// `csg_first_hit` finds a crossing, that is whether any crossing `all_hits` lists is kept.
    /// Each member's crossings are tested as soon as they are gathered, and the search stops at
    /// the first one kept: a blocked shadow ray does not pay for the other members'
    /// intersections or for the sort. The same crossings meet the same tests: each member's
    /// are `member_hits` (through `all_hits` for a plain intersection, which gives what
    /// `csg_first_hit`'s folding gives: its leaves' crossings kept by its own `csg_keeps`),
    /// after the same culls and slab tests, and each is kept by `csg_keeps` and the clip
    /// exactly as there. No test has a side effect on an answer (the rejecter only orders the
    /// questions), so the order of the crossings cannot change whether one is kept.
    #[allow(clippy::too_many_arguments)]
    #[inline(never)]
    pub(super) fn csg_any_hit<'a, const BOXES: bool>(
        &'a self,
        op: CsgOp,
        children: &'a [Object],
        index: Option<&ChildIndex>,
        (cull, faces): (Option<&Aabb>, Option<&Faces>),
        ray: &Ray,
        tmax: f64,
        s: &mut Scratch<'a>,
    ) -> bool {
        let boxes = BOXES.then(|| self.box_members()).flatten();
        let inv_dir = ray.dir.recip();
        if cull.is_some_and(|c| c.hit(ray.origin, inv_dir, tmax).is_none()) {
            return false;
        }
        let ray_faces = faces.filter(|_| faces::ray_ok(ray));
        let slabs = Slabs::new(ray.origin, inv_dir);
        let rejecter = Cell::new(usize::MAX);
        let clip = &self.clip[..];
        if let Some(shapes) = self.quadric_lanes() {
            return any_quadric_kept(children, shapes, ray, &slabs, tmax, s, |i, t| {
                let p = ray.at(t);
                quadric_keeps(op, i, children, shapes, p, &rejecter)
                    && (clip.is_empty() || (t > EPSILON && clip.iter().all(|c| c.inside(p))))
            });
        }
        let keep_at = |i: usize, t: f64| {
            let p = ray.at(t);
            (match boxes.filter(|_| BOXES) {
                Some(b) => csg_keeps_boxes(op, i, children, faces, b, p, &rejecter),
                None => csg_keeps(op, i, children, index, faces, p, &rejecter),
            }) && (clip.is_empty() || (t > EPSILON && clip.iter().all(|c| c.inside(p))))
        };
        // Beyond the lead's bounds from `EPSILON` on, only its crossings can be kept.
        let lead = self.lead();
        if let Some(found) = lead_any_hit(lead, children, ray, inv_dir, &slabs, tmax, s, keep_at) {
            return found;
        }
        let shut = lead.shut();
        let mut found = false;
        each_member(children, index, ray, tmax, s, |c, i, s| {
            if found || i == shut || !slabs.hits(&c.bounds, tmax) {
                return;
            }
            let face = ray_faces.and_then(|f| f.get(i));
            let mut keep = |t: f64| keep_at(i, t);
            // A box member (`csg_boxes`): the leaf case below without dispatch.
            if let Some(b) = boxes.filter(|_| BOXES).and_then(|b| b.get(i)) {
                let mut local = None;
                let r = c.local_ray(ray, &mut local);
                found = b.shape.any_kept_by(r, tmax, keep);
                return;
            }
            // A leaf without face, clipping or window (`member_hits`' own case): its crossings
            // asked as the shape finds them, so that a torus stops polishing at the first kept.
            if let (ObjKind::Shape(shape, None), None, true) = (&c.kind, face, c.clip.is_empty()) {
                let mut local = None;
                let r = c.local_ray(ray, &mut local);
                found = shape.any_kept(r, tmax, &mut s.hits, &mut keep);
                return;
            }
            let from = s.surface.len();
            member_hits(c, face, ray, tmax, s);
            found = s.surface[from..].iter().any(|h| keep(h.t));
            s.surface.truncate(from);
        });
        found
    }

    /// `csg_first_hit::<false>` of a node without `clipped_by` or index whose members are all
    /// faces (`Faces::all`: shapes2.inc's polyhedra, textures/pigments/dodec2's twelve planes
    /// five times over), for a ray within `faces::ray_ok`: the same search without the
    /// general one's lists. The same crossings in the same order: a face has at most one
    /// crossing, so the gather's order is member order, and the insertion below sorts by
    /// (t, member) as `csg_first_hit` sorts by (t, place in the gather). The members'
    /// slab tests are left out: an unbounded box fails them only for `tmax < 0`, when no
    /// crossing (t > EPSILON, t < tmax) is left either, and the ray (finite, no NaN) makes no
    /// NaN against infinite bounds. Each crossing is kept by the faces' inside tests exactly as
    /// `csg_keeps` asks them (unbounded bounds hold every finite point; points beyond
    /// `faces::point_ok` go to `csg_keeps` itself). `inside` has no side effects, so the order
    /// of the questions cannot change the answer: the same crossing, bit for bit.
    #[inline(never)]
    pub(super) fn faces_first_hit<'a>(
        &'a self,
        op: CsgOp,
        children: &'a [Object],
        (cull, faces, all): (Option<&Aabb>, &Faces, &[Option<Face>]),
        ray: &Ray,
        tmax: f64,
    ) -> Option<SurfaceHit<'a>> {
        if cull.is_some_and(|c| c.hit(ray.origin, ray.dir.recip(), tmax).is_none()) {
            return None;
        }
        #[cfg(target_arch = "x86_64")]
        if let Some(lanes) = faces.lanes().filter(|_| has_avx()) {
            // SAFETY: the CPU has AVX.
            return unsafe { self.lanes_first_hit(op, children, (faces, lanes), ray, tmax) };
        }
        // Order entries (`order_entry`: t's order key, member), moved by the insertion in
        // 8-byte halves: as `(f64, u32)` they were stored as 8 + 4 bytes and moved as one
        // 16-byte load, which waits for both stores (`sort_crossings`' stall).
        let mut order = [0u128; MAX_ALL];
        let mut n = 0;
        for (k, f) in all.iter().enumerate().take(MAX_ALL) {
            if let Some(t) = f.as_ref().and_then(|f| f.hit(ray)).filter(|&t| t < tmax) {
                // Later members go after equal `t`s: ties in member order (the member is the
                // entry's low half, and larger than every member before it).
                insert_entry(&mut order, &mut n, order_entry(order_key(t), k as u32, 0));
            }
        }
        let mut rejecter = usize::MAX;
        let kept_cell = Cell::new(usize::MAX);
        let (t, i) = order[..n]
            .iter()
            .map(|&e| (entry_t(e), entry_place(e)))
            .find(|&(t, i)| {
                let i = i as usize;
                let p = ray.at(t);
                if !faces::point_ok(p) {
                    return csg_keeps(op, i, children, None, Some(faces), p, &kept_cell);
                }
                let wants = |j: usize| {
                    all[j]
                        .as_ref()
                        .is_some_and(|f| (f.inside(p) != children[j].inverse) == want_inside(op, j))
                };
                // The face that turned the last crossing away first, as `csg_keeps` does.
                if rejecter != i && rejecter < all.len() && !wants(rejecter) {
                    return false;
                }
                for j in 0..all.len() {
                    if j != i && j != rejecter && !wants(j) {
                        rejecter = j;
                        return false;
                    }
                }
                true
            })?;
        Some(self.face_hit(op, children, t, i as usize))
    }

    /// `faces_first_hit` with the faces' crossings and inside tests four lanes at a time
    /// (`face_lanes`, the same bits): the same entries inserted in member order, so the same
    /// order, and each candidate kept when every other face answers as `wants` asks, which
    /// is `wants` asked of each (their order cannot matter, as above).
    ///
    /// # Safety
    /// The CPU must have AVX.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    unsafe fn lanes_first_hit<'a>(
        &'a self,
        op: CsgOp,
        children: &'a [Object],
        (faces, lanes): (&Faces, &FaceLanes),
        ray: &Ray,
        tmax: f64,
    ) -> Option<SurfaceHit<'a>> {
        let mut ts = [0.0; MAX_ALL];
        let mut bits = lanes.hits_avx(ray, tmax, &mut ts);
        let mut order = [0u128; MAX_ALL];
        let mut n = 0;
        while bits != 0 {
            let k = bits.trailing_zeros() as usize;
            bits &= bits - 1;
            insert_entry(
                &mut order,
                &mut n,
                order_entry(order_key(ts[k]), k as u32, 0),
            );
        }
        let expected = lanes.expected(op);
        let kept_cell = Cell::new(usize::MAX);
        for &e in &order[..n] {
            let (t, i) = (entry_t(e), entry_place(e) as usize);
            let p = ray.at(t);
            let kept = if faces::point_ok(p) {
                (lanes.inside_avx(p) ^ expected) & lanes.members() & !(1 << i) == 0
            } else {
                csg_keeps(op, i, children, None, Some(faces), p, &kept_cell)
            };
            if kept {
                return Some(self.face_hit(op, children, t, i));
            }
        }
        None
    }

    /// The surface hit of member `i`'s face at `t` (`faces_first_hit`).
    #[inline(always)]
    fn face_hit<'a>(
        &'a self,
        op: CsgOp,
        children: &'a [Object],
        t: f64,
        i: usize,
    ) -> SurfaceHit<'a> {
        let c = &children[i];
        SurfaceHit {
            t,
            obj: c,
            hit: Hit::new(t),
            flip: c.inverse ^ (op == CsgOp::Difference && i > 0) ^ self.inverse,
        }
    }
}

/// Inserts `e` into the sorted `order[..n]` after every entry not above it (ties keep their
/// insertion order), one 8-byte half at a time (`order_entry`).
#[inline(always)]
fn insert_entry(order: &mut [u128; MAX_ALL], n: &mut usize, e: u128) {
    let mut m = *n;
    while m > 0 && order[m - 1] > e {
        order[m] = order[m - 1];
        m -= 1;
    }
    order[m] = e;
    *n += 1;
}

#[cfg(test)]
#[path = "csg_hit_tests.rs"]
pub(super) mod tests;
