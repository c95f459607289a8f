//! The CSG searches: which member crossings lie on a node's surface (`csg_keeps`), and the
//! nearest such crossing of an intersection, difference, merge or clipped object found without
//! testing every crossing (`first_hit`, `any_hit`). `Object::all_hits` lists them all.

use std::cell::Cell;

use crate::geom::{Hit, Shape};
use crate::math::{Aabb, Ray, Slabs, EPSILON};
use crate::scene::children::ChildIndex;
use crate::scene::csg_boxes::{box_hits, csg_keeps_boxes};
use crate::scene::desc::CsgOp;
use crate::scene::faces::{self, Face, Faces, MAX_ALL};
use crate::scene::object::{
    csg_keeps, each_member, member_hits, ObjKind, Object, Scratch, SurfaceHit,
};

/// Crossings gathered for a search are tagged with their member `i`, and for the leaves of a
/// member folded in (`folded`) with the leaf's number plus one above this shift.
const LEAF_SHIFT: u32 = 16;

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

/// Sorts a search's crossings by (order key, place in the gather), the order
/// `sort_unstable` gives them: no two entries share a place, so every sort gives this one
/// order. A short list is sorted here by insertion, without the call into the library's
/// sort (radiosity_37's walls sort 211 k lists, most of two to four crossings).
#[inline(always)]
fn sort_crossings(order: &mut [(i64, u32, u32)]) {
    if order.len() > 8 {
        order.sort_unstable();
        return;
    }
    for k in 1..order.len() {
        let e = order[k];
        let mut m = k;
        while m > 0 && (order[m - 1].0, order[m - 1].1) > (e.0, e.1) {
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

/// Crossing `hit` of leaf `c` appended to `s.surface` as `take_hits` appends it, and its order
/// entry (order key, place, `tag`) to `s.csg_order`.
#[inline(always)]
pub(super) fn push_crossing<'a>(c: &'a Object, hit: Hit, s: &mut Scratch<'a>, tag: u32) {
    s.csg_order
        .push((order_key(hit.t), s.surface.len() as u32, tag));
    s.surface.push(SurfaceHit {
        t: hit.t,
        obj: c,
        hit,
        flip: c.inverse,
    });
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

/// `member_hits(c, face, ray, tmax, s)` with each crossing's order entry `(order key, place
/// in s.surface, tag)` pushed to `s.csg_order` as it is listed: a leaf without face, clip or
/// window (`member_hits`' own case) takes the shape's crossings below `tmax` in one pass
/// instead of listing them (`take_hits`) and reading them back for their keys. The same
/// surface hits in the same places, and the same entries in the same order.
#[inline(always)]
fn gather_hits<'a>(
    c: &'a Object,
    face: Option<&Face>,
    ray: &Ray,
    tmax: f64,
    s: &mut Scratch<'a>,
    tag: u32,
) {
    match (face, &c.kind) {
        (None, ObjKind::Shape(shape, None)) if c.clip.is_empty() => {
            let mut local = None;
            let r = c.local_ray(ray, &mut local);
            s.hits.clear();
            shape.intersect_all(r, &mut s.hits);
            for k in 0..s.hits.len() {
                let hit = s.hits[k];
                if hit.t < tmax {
                    push_crossing(c, hit, s, tag);
                }
            }
        }
        _ => {
            let from = s.surface.len();
            member_hits(c, face, ray, tmax, s);
            for j in from..s.surface.len() {
                s.csg_order.push((order_key(s.surface[j].t), j as u32, tag));
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
    /// so that their search pays nothing for the folding.
    #[allow(clippy::too_many_arguments)]
    #[inline(never)]
    pub(super) fn csg_first_hit<'a, const FOLD: bool, const BOXES: bool>(
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
        let slabs = Slabs::new(ray.origin, inv_dir);
        let fold = FOLD && index.is_none() && children.len() <= 1 << LEAF_SHIFT;
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
                if !slabs.hits(&c.bounds, tmax) {
                    return;
                }
                if let Some((leaves, leaf_cull, leaf_faces)) = fold.then(|| folded(c)).flatten() {
                    // `c.all_hits`'s own tests, in its order.
                    if leaf_cull.is_some_and(|b| b.hit(ray.origin, inv_dir, tmax).is_none()) {
                        return;
                    }
                    let leaf_faces = leaf_faces.filter(|_| faces::ray_ok(ray));
                    for (k, g) in leaves.iter().enumerate() {
                        if !slabs.hits(&g.bounds, tmax) {
                            continue;
                        }
                        let tag = i as u32 | (k as u32 + 1) << LEAF_SHIFT;
                        gather_hits(g, leaf_faces.and_then(|f| f.get(k)), ray, tmax, s, tag);
                    }
                    return;
                }
                match boxes.filter(|_| BOXES).and_then(|b| b.get(i)) {
                    // Box members without dispatch (`csg_boxes`): `member_hits`' leaf path.
                    Some(b) => box_hits(c, b, ray, tmax, s, i as u32),
                    None => {
                        gather_hits(c, ray_faces.and_then(|f| f.get(i)), ray, tmax, s, i as u32)
                    }
                }
            },
        );
        let order = &mut s.csg_order[order_from..];
        // By (t as `total_cmp` orders it, place in the gather): `j` differs between entries.
        sort_crossings(order);
        let rejecter = Cell::new(usize::MAX);
        let leaf_rejecter = Cell::new(usize::MAX);
        let clip = &self.clip[..];
        let best = order.iter().find_map(|&(_, j, tag)| {
            let t = s.surface[j as usize].t;
            // Without folding, tags are plain member numbers (a node may have more than
            // the tag's low bits hold).
            let i = if FOLD {
                tag & ((1 << LEAF_SHIFT) - 1)
            } else {
                tag
            } as usize;
            let p = ray.at(t);
            let leaf_kept = || match if FOLD {
                (tag >> LEAF_SHIFT) as usize
            } else {
                0
            } {
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
            let kept = || match boxes.filter(|_| BOXES) {
                // Nodes with box members have no index (`children::attach_indexes`).
                Some(b) => csg_keeps_boxes(op, i, children, faces, b, p, &rejecter),
                None => csg_keeps(op, i, children, index, faces, p, &rejecter),
            };
            (leaf_kept() && kept() && clip_kept()).then(|| {
                let mut h = s.surface[j as usize];
                h.flip ^= op == CsgOp::Difference && i > 0;
                h.flip ^= self.inverse;
                h
            })
        });
        s.csg_order.truncate(order_from);
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
        let mut found = false;
        each_member(children, index, ray, tmax, s, |c, i, s| {
            if found || !slabs.hits(&c.bounds, tmax) {
                return;
            }
            let face = ray_faces.and_then(|f| f.get(i));
            let mut keep = |t: f64| {
                let p = ray.at(t);
                (match boxes.filter(|_| BOXES) {
                    Some(b) => csg_keeps_boxes(op, i, children, faces, b, p, &rejecter),
                    None => csg_keeps(op, i, children, index, faces, p, &rejecter),
                }) && (clip.is_empty() || (t > EPSILON && clip.iter().all(|c| c.inside(p))))
            };
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
        let mut order = [(0.0f64, 0u32); MAX_ALL];
        let mut n = 0;
        for (k, f) in all.iter().enumerate().take(MAX_ALL) {
            if let Some(t) = f.as_ref().and_then(|f| f.hit(ray)).filter(|&t| t < tmax) {
                // Later members go after equal `t`s: ties in member order.
                let mut m = n;
                while m > 0 && order[m - 1].0.total_cmp(&t).is_gt() {
                    order[m] = order[m - 1];
                    m -= 1;
                }
                order[m] = (t, k as u32);
                n += 1;
            }
        }
        let want_inside = |j: usize| match op {
            CsgOp::Intersection => true,
            CsgOp::Difference => j == 0,
            CsgOp::Union | CsgOp::Merge => false,
        };
        let mut rejecter = usize::MAX;
        let kept_cell = Cell::new(usize::MAX);
        let &(t, i) = order[..n].iter().find(|&&(t, i)| {
            let i = i as usize;
            let p = ray.at(t);
            if !faces::point_ok(p) {
                return csg_keeps(op, i, children, None, Some(faces), p, &kept_cell);
            }
            let wants = |j: usize| {
                all[j]
                    .as_ref()
                    .is_some_and(|f| (f.inside(p) != children[j].inverse) == want_inside(j))
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
        let c = &children[i as usize];
        Some(SurfaceHit {
            t,
            obj: c,
            hit: Hit::new(t),
            flip: c.inverse ^ (op == CsgOp::Difference && i > 0) ^ self.inverse,
        })
    }

    /// `any_hit` of a leaf `shape` (this object's) with `clipped_by` and without window:
    /// whether `clipped_first_hit` would find a crossing, that is whether any crossing
    /// `all_hits_unclipped` lists (the shape's `intersect_all` below `tmax`) has t > EPSILON
    /// and lies inside every clipping object. The shape asks them in its own order
    /// (`Shape::any_kept`): a clipped torus stops polishing at the first one kept.
    #[inline(never)]
    pub(super) fn clipped_leaf_any_hit(
        &self,
        shape: &dyn Shape,
        ray: &Ray,
        tmax: f64,
        s: &mut Scratch<'_>,
    ) -> bool {
        let mut local = None;
        let r = self.local_ray(ray, &mut local);
        shape.any_kept(r, tmax, &mut s.hits, &mut |t| {
            t > EPSILON && self.clip.iter().all(|c| c.inside(ray.at(t)))
        })
    }

    /// `first_hit` of a leaf or union with `clipped_by`: the nearest of its crossings with
    /// t > EPSILON inside every clipping object (ties to the earlier in `all_hits`'s order, as
    /// `min_by` over it), asking the clip only about crossings that would be nearer. With
    /// `nearest` false, any such crossing (`any_hit`): a union's members are then asked one
    /// at a time, stopping at the first crossing the clip keeps.
    pub(super) fn clipped_first_hit<'a>(
        &'a self,
        ray: &Ray,
        tmax: f64,
        s: &mut Scratch<'a>,
        nearest: bool,
    ) -> Option<SurfaceHit<'a>> {
        let start = s.surface.len();
        let kept =
            |h: &SurfaceHit| h.t > EPSILON && self.clip.iter().all(|c| c.inside(ray.at(h.t)));
        if let ObjKind::Csg {
            op: CsgOp::Union,
            children,
            index,
            cull,
        } = &self.kind
        {
            if !nearest {
                // `all_hits_unclipped`'s tests of a union, member by member.
                let inv_dir = ray.dir.recip();
                if cull
                    .as_ref()
                    .and_then(|c| c.aabb.as_ref())
                    .is_some_and(|c| c.hit(ray.origin, inv_dir, tmax).is_none())
                {
                    return None;
                }
                let slabs = Slabs::new(ray.origin, inv_dir);
                // Plane members through their faces, as `all_hits_unclipped` asks them.
                let faces = cull.as_ref().and_then(|c| c.faces.as_ref());
                let ray_faces = faces.filter(|_| faces::ray_ok(ray));
                let mut found = None;
                each_member(children, index.as_deref(), ray, tmax, s, |c, i, s| {
                    if found.is_some() || !slabs.hits(&c.bounds, tmax) {
                        return;
                    }
                    let from = s.surface.len();
                    member_hits(c, ray_faces.and_then(|f| f.get(i)), ray, tmax, s);
                    found = s.surface[from..].iter().find(|h| kept(h)).copied();
                    s.surface.truncate(from);
                });
                return found;
            }
        }
        self.all_hits_unclipped(ray, tmax, s);
        let best = if nearest {
            // A running minimum that asks the clip only about crossings nearer than the best
            // so far: one that is not cannot become the minimum, kept or not, and the strict
            // comparison keeps the earliest of equal ones.
            let mut best: Option<SurfaceHit<'a>> = None;
            for h in &s.surface[start..] {
                if best.is_none_or(|b| h.t.total_cmp(&b.t).is_lt()) && kept(h) {
                    best = Some(*h);
                }
            }
            best
        } else {
            s.surface[start..].iter().find(|h| kept(h)).copied()
        };
        s.surface.truncate(start);
        best
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::sort_crossings;
    use crate::geom::test_rng::Lcg;
    use crate::math::{DVec3, Ray, EPSILON};
    use crate::scene::object::{ObjKind, Object, Scratch, SurfaceHit};
    use crate::sdl::{ParseOptions, Parser};

    /// The built scene of `text` (csg_boxes' tests use it too).
    pub(in crate::scene) fn built(text: &str) -> crate::scene::build::Scene {
        let mut p = Parser::new(ParseOptions::default());
        p.parse_str("t.pov", text)
            .map_err(|e| e.message.clone())
            .unwrap();
        crate::scene::build::build(&p.scene, 64, 48).scene
    }

    /// What two crossings must share bit for bit.
    fn key(h: &SurfaceHit) -> (u64, bool, u32) {
        (h.t.to_bits(), h.flip, h.hit.part)
    }

    /// The short lists' insertion sort gives `sort_unstable`'s order: lists of every length
    /// up to past the cut-over, with ties in the key (and in the tag) broken by the place.
    #[test]
    fn crossings_sort_as_sort_unstable() {
        let mut rng = Lcg(3);
        for n in 0..14 {
            for _ in 0..500 {
                let mut places: Vec<u32> = (0..n as u32).collect();
                // Places in any order, keys from a few values so that they tie.
                for k in (1..places.len()).rev() {
                    places.swap(k, (rng.next() * (k + 1) as f64) as usize % (k + 1));
                }
                let mut a: Vec<(i64, u32, u32)> = places
                    .iter()
                    .map(|&j| ((rng.next() * 4.0) as i64 - 2, j, (rng.next() * 3.0) as u32))
                    .collect();
                let mut b = a.clone();
                sort_crossings(&mut a);
                b.sort_unstable();
                assert_eq!(a, b);
            }
        }
    }

    /// `first_hit` as `all_hits` defines it: the nearest crossing (t > EPSILON when clipped),
    /// the earliest listed of equal ones.
    fn reference<'a>(
        o: &'a Object,
        ray: &Ray,
        tmax: f64,
        s: &mut Scratch<'a>,
    ) -> Option<SurfaceHit<'a>> {
        s.surface.clear();
        o.all_hits(ray, tmax, s);
        let best = s
            .surface
            .iter()
            .filter(|h| o.clip.is_empty() || h.t > EPSILON)
            .min_by(|a, b| a.t.total_cmp(&b.t))
            .copied();
        s.surface.clear();
        best
    }

    /// The searches answer as `all_hits` does, bit for bit and with the same surface and
    /// side: nested intersections (folded, and not: inverse, clipped), clipped differences,
    /// unions and leaves, with rays from inside and outside and along the members' faces.
    #[test]
    fn searches_match_all_hits() {
        const SCENE: &str = r#"
            #declare Disk_X = cylinder { x, -x, 1 }
            #declare Disk_Y = cylinder { y, -y, 1 }
            #declare Disk_Z = cylinder { z, -z, 1 }
            intersection { intersection { box { -1, 1 scale <1, 1, 0.95> } object { Disk_X scale 1.15 } }
                           object { Disk_Y scale 1.15 } rotate <10, 20, 30> }
            intersection { sphere { 0, 1.2 } intersection { box { -1, 1 } plane { x + y, 0.5 } } }
            difference { box { -1, 1 } intersection { sphere { x, 1 } sphere { -x, 1.5 } } sphere { y, 0.7 } }
            intersection { intersection { box { -1, 1 } sphere { 0, 1.3 } inverse } sphere { 0, 1.6 } }
            intersection { intersection { box { -1, 1 } sphere { 0, 1.3 } clipped_by { plane { y, 0.2 } } } sphere { 0, 1.6 } }
            merge { intersection { box { -1, 1 } sphere { 0, 1.3 } } sphere { x, 0.8 } }
            difference { box { -1, 1 } object { Disk_Z scale <0.85, 0.75, 1.5> } object { Disk_X scale <1.15, 0.7, 0.7> }
                         clipped_by { plane { -y, 0 } } scale <1, 2, 1> }
            union { plane { z, 0 } plane { y, 0 inverse }
                    cylinder { <-3, 1, -1>, <3, 1, -1>, 1 clipped_by { box { <-2, 0, -1>, <2, 1, 0> } } }
                    clipped_by { box { <-1.9, -0.1, -100>, <2.1, 100, 1> } } rotate -y * 2 }
            sphere { 0, 1 clipped_by { plane { y, 0.25 } } translate x }
            sphere { 0, 1 clipped_by { plane { y, 0.25 } plane { x, 0.1 } } inverse }
            intersection { quadric { <0, 1, 1>, 0, 0, -1 } quadric { <1, 0, 1>, 0, 0, -1 }
                           quadric { <0, 1, 1>, 0, 0, -1 inverse scale <1, 0.5, 0.5> }
                           quadric { <1, 0, 1>, 0, 0, -1 inverse scale <0.5, 1, 0.5> } rotate y * 45 }
            difference { box { -1, 1 } #for (i, 0, 9) sphere { <i / 5 - 0.9, 0.5, 0.3>, 0.3 } #end
                         clipped_by { sphere { 0, 1.5 } } }
            intersection { #for (i, 0, 9) sphere { <i / 20, 0, 0>, 1.2 } #end }
            difference { quadric { <1, 1, 1>, 0, 0, -1.4 } quadric { <0, 1, 1>, 0, <0, 0.2, 0>, -0.3 }
                         quadric { <1, 0, 1>, 0, 0, -0.3 } rotate <20, 30, 0> translate <0.2, 0, 0.1> }
            merge { quadric { <1, 1, 0.5>, 0, 0, -1 } quadric { <1, 0, 1>, 0, 0, -0.5 } scale <1, 1.5, 1> }
        "#;
        let scene = built(SCENE);
        let mut rng = Lcg(11);
        let (mut sa, mut sb) = (Scratch::default(), Scratch::default());
        for (n, o) in scene.objects.iter().enumerate() {
            let mut hits = 0;
            for k in 0..6000 {
                // Every third ray runs along an axis through a point on a face of the box.
                let ray = if k % 3 == 0 {
                    let mut q = rng.vec(2.0);
                    q[k % 2] = [1.0, -1.0, 0.0][k % 3];
                    Ray::new(q, [DVec3::X, DVec3::Y, DVec3::Z, rng.vec(1.0)][k % 4])
                } else {
                    Ray::new(rng.vec(5.0), rng.vec(2.0))
                };
                let tmax = if rng.next() < 0.3 { 2.5 } else { f64::INFINITY };
                let key = |h: Option<SurfaceHit>| {
                    h.map(|h| (h.t.to_bits(), h.flip, h.obj as *const Object, h.hit.part))
                };
                let want = key(reference(o, &ray, tmax, &mut sb));
                assert_eq!(
                    key(o.first_hit(&ray, tmax, &mut sa)),
                    want,
                    "object {n}, ray {k}"
                );
                assert_eq!(
                    o.any_hit(&ray, tmax, &mut sa),
                    want.is_some(),
                    "object {n}, ray {k}"
                );
                assert!(sa.surface.is_empty() && sa.csg_order.is_empty());
                hits += want.is_some() as usize;
            }
            assert!(hits > 100, "object {n}: {hits}");
        }
    }

    /// Nodes whose members are all faces (`faces_first_hit`) answer as the general search
    /// (`csg_first_hit`) and as `all_hits` do, bit for bit: polyhedra rotated, scaled from
    /// 1e-4 to 1e5 and moved far out; members inverted, coincident and duplicated faces; a
    /// difference, a merge and an inverted node. Rays at random, along axes through lattice
    /// points (in and grazing the cube's faces and edges), through vertices, starting on the
    /// surface (at a crossing of an earlier ray), and far out (points beyond `point_ok`).
    #[test]
    fn polyhedra_match_the_general_search() {
        const DODECAHEDRON: &str = r#"
            plane { -z, 1 rotate <-26.56505117708, 0, 0> }
            plane { -z, 1 rotate <-26.56505117708, -72, 0> }
            plane { -z, 1 rotate <-26.56505117708, -144, 0> }
            plane { -z, 1 rotate <-26.56505117708, -216, 0> }
            plane { -z, 1 rotate <-26.56505117708, -288, 0> }
            plane { -z, 1 rotate <26.56505117708, -36, 0> }
            plane { -z, 1 rotate <26.56505117708, -108, 0> }
            plane { -z, 1 rotate <26.56505117708, -180, 0> }
            plane { -z, 1 rotate <26.56505117708, -252, 0> }
            plane { -z, 1 rotate <26.56505117708, -324, 0> }
            plane { y, 1 } plane { -y, 1 }
        "#;
        const CUBE: &str = "plane { x, 1 } plane { -x, 1 } plane { y, 1 } plane { -y, 1 } \
                            plane { z, 1 } plane { -z, 1 }";
        let scene_text = format!(
            r#"
            intersection {{ {DODECAHEDRON} translate y * 1.8 rotate x * 72 rotate z * 144 }}
            intersection {{ {DODECAHEDRON} scale 1e-4 translate <1e-4, 0, 0> }}
            intersection {{ {DODECAHEDRON} scale 1e5 rotate <10, 20, 30> translate 1e6 }}
            intersection {{ {CUBE} }}
            intersection {{ {CUBE} scale <1, 1e-3, 1e3> }}
            intersection {{ {CUBE} plane {{ y, 1 }} plane {{ y, 1 rotate z * 45 }} rotate y * 45 }}
            intersection {{ {CUBE} plane {{ y, 0 inverse }} rotate <0, 0, 30> }}
            intersection {{ {CUBE} inverse }}
            difference {{ plane {{ y, 1 }} plane {{ y, 0.5 inverse }} plane {{ -x, 0.3 inverse rotate z * 45 }} }}
            merge {{ plane {{ y, 0 }} plane {{ x, 0 }} plane {{ -z, 1 rotate x * 30 }} }}
            intersection {{ plane {{ y, 1 }} plane {{ -y, -1 }} plane {{ x, 1 }} }}
        "#
        );
        let scene = built(&scene_text);
        let big = if cfg!(debug_assertions) {
            4_000
        } else {
            150_000
        };
        let mut rng = Lcg(29);
        let (mut sa, mut sb) = (Scratch::default(), Scratch::default());
        let key = |h: Option<SurfaceHit>| {
            h.map(|h| (h.t.to_bits(), h.flip, h.obj as *const Object, h.hit.part))
        };
        let mut indexed = 0;
        for (n, o) in scene.objects.iter().enumerate() {
            let ObjKind::Csg {
                op,
                children,
                index,
                cull: Some(cull),
            } = &o.kind
            else {
                panic!("object {n} is not a node with faces");
            };
            assert!(
                cull.faces.as_ref().is_some_and(|f| f.all().is_some()),
                "object {n}"
            );
            indexed += index.is_some() as usize;
            // The object's scale and place, for rays that reach it.
            let b = cull.aabb.unwrap_or(o.bounds);
            let finite = b.min.is_finite() && b.max.is_finite();
            let (lo, hi) = if finite {
                (b.min, b.max)
            } else {
                (DVec3::splat(-3.0), DVec3::splat(3.0))
            };
            let (centre, size) = ((lo + hi) * 0.5, (hi - lo).max_element().max(1e-4));
            let mut on_surface = None;
            let (mut hits, mut surface_starts) = (0, 0);
            for k in 0..big {
                let axis = [
                    DVec3::X,
                    DVec3::Y,
                    DVec3::Z,
                    -DVec3::X,
                    -DVec3::Y,
                    -DVec3::Z,
                ];
                let ray = match k % 6 {
                    // Along an axis from a lattice point of the cube's faces (-1, 0, 1).
                    0 => Ray::new(
                        (rng.vec(6.0))
                            .round()
                            .clamp(DVec3::splat(-1.0), DVec3::splat(1.0))
                            * [1.0, 1.5, 3.0][k % 3],
                        axis[(k / 6) % 6],
                    ),
                    // From a crossing of an earlier ray.
                    1 if on_surface.is_some() => {
                        surface_starts += 1;
                        Ray::new(on_surface.unwrap(), rng.vec(2.0))
                    }
                    // Through a point at random on the object's scale, from far or near.
                    2 | 3 => {
                        let target = centre + rng.vec(size * 1.2);
                        let from = centre + rng.vec(size * [3.0, 40.0][k % 2]);
                        Ray::new(from, (target - from) * [1.0, 1e-3, 1e3][k % 3])
                    }
                    // Far out, where points leave the faces' limits.
                    4 if k % 60 == 4 => Ray::new(rng.vec(2e150), rng.vec(1e10)),
                    _ => Ray::new(rng.vec(8.0), rng.vec(2.0)),
                };
                let tmax = match k % 7 {
                    0 => 2.5,
                    1 => -1.0,
                    _ => f64::INFINITY,
                };
                let want = key(reference(o, &ray, tmax, &mut sb));
                let general = o.csg_first_hit::<false, false>(
                    *op,
                    children,
                    index.as_deref(),
                    (cull.aabb.as_ref(), cull.faces.as_ref()),
                    &ray,
                    tmax,
                    &mut sb,
                );
                assert_eq!(key(general), want, "object {n}, ray {k}");
                let got = o.first_hit(&ray, tmax, &mut sa);
                assert_eq!(key(got), want, "object {n}, ray {k}");
                assert_eq!(
                    o.any_hit(&ray, tmax, &mut sa),
                    want.is_some(),
                    "object {n}, ray {k}"
                );
                assert!(sa.surface.is_empty() && sa.csg_order.is_empty());
                if let Some(h) = got {
                    hits += 1;
                    on_surface = Some(ray.at(h.t)).filter(|p| p.abs().max_element() < 1e140);
                }
            }
            assert!(
                hits > big / 100 && surface_starts > big / 100,
                "object {n}: {hits}"
            );
        }
        // The dodecahedra (twelve members) and the cubes with two more faces have an index.
        assert_eq!(indexed, 4);
    }

    /// Unions ask their plane members through their faces (`scene::faces`) and answer as
    /// without them, bit for bit: quilt1's clipped floor and wall, rotated; a plain union of
    /// planes and a sphere; and a union big enough for an index, which keeps no faces (its
    /// index numbers leaves, not members).
    #[test]
    fn unions_answer_through_faces_as_without() {
        const SCENE: &str = r#"
            union { plane { z, 0 hollow on } plane { y, 0 inverse }
                    cylinder { <-200, 1, -1>, <200, 1, -1>, 1 clipped_by { box { <-100, 0, -1>, <100, 1, 0> } } }
                    clipped_by { box { <-99.9, -0.1, -10000>, <100.1, 1000, 1> } } rotate -y * 2 }
            union { plane { x, 0.5 rotate <10, 20, 30> } plane { -y, 0.25 scale 2 } sphere { 0, 1 } }
            union { plane { x, 0.5 rotate <10, 20, 30> } plane { -y, 0.25 } sphere { 0, 1 }
                    clipped_by { sphere { 0, 2 } } inverse }
            union {
              #local I = 0;
              #while (I < 14)
                sphere { <I, 0, 0>, 0.4 }
                #local I = I + 1;
              #end
              plane { z, 1 } plane { y, -1 rotate x * 5 }
            }
        "#;
        let (with, mut without) = (built(SCENE), built(SCENE));
        let faces = |o: &Object| match &o.kind {
            ObjKind::Csg { cull, .. } => cull.as_ref().is_some_and(|c| c.faces.is_some()),
            ObjKind::Shape(..) => false,
        };
        let has: Vec<bool> = with.objects.iter().map(faces).collect();
        assert_eq!(has, [true, true, true, false]);
        for o in &mut without.objects {
            if let ObjKind::Csg { cull: Some(c), .. } = &mut o.kind {
                c.faces = None;
            }
        }
        let mut rng = Lcg(5);
        let (mut sa, mut sb) = (Scratch::default(), Scratch::default());
        for (n, (a, b)) in with.objects.iter().zip(&without.objects).enumerate() {
            let mut hits = 0;
            for k in 0..4000 {
                let ray = if k % 4 == 0 {
                    Ray::new(rng.vec(3.0).round(), [DVec3::X, DVec3::Y, DVec3::Z][k % 3])
                } else {
                    Ray::new(rng.vec(6.0), rng.vec(2.0))
                };
                let tmax = if rng.next() < 0.3 { 2.5 } else { f64::INFINITY };
                let ha = a.first_hit(&ray, tmax, &mut sa);
                let hb = b.first_hit(&ray, tmax, &mut sb);
                assert_eq!(
                    ha.as_ref().map(key),
                    hb.as_ref().map(key),
                    "object {n}, ray {k}"
                );
                assert_eq!(
                    a.any_hit(&ray, tmax, &mut sa),
                    hb.is_some(),
                    "object {n}, ray {k}"
                );
                a.all_hits(&ray, tmax, &mut sa);
                b.all_hits(&ray, tmax, &mut sb);
                let list = |s: &Scratch| -> Vec<_> { s.surface.iter().map(key).collect() };
                assert_eq!(list(&sa), list(&sb), "object {n}, ray {k}");
                sa.surface.clear();
                sb.surface.clear();
                hits += hb.is_some() as usize;
            }
            assert!(hits > 100, "object {n}: {hits}");
        }
    }
}
