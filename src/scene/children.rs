//! An acceleration index over the members of one CSG node (union, merge, intersection,
//! difference), so a ray or a point meets only the members near it instead of all of them.
//!
//! POV-Ray splits unions into its global bounding hierarchy (`split_union`). lancer keeps the
//! CSG tree and gives each large node its own BVH instead: the scene's top-level hierarchy stays
//! the one built over top-level objects, and every query below returns exactly what a scan of
//! the members in order returns (same nearest hit, ties to the earlier member, crossings listed
//! in member order), so pictures do not change by a single bit whatever the index visits first.
//! Also here: a union's nearest crossing through its index, and the in-order scan of a small
//! union's members that has none.

use crate::geom::bvh::{Avx, Bvh, Lanes, Recip, Sse};
use crate::geom::Hit;
use crate::math::{Aabb, DVec3, Ray, Slabs};
use crate::scene::csg_boxes::Search;
use crate::scene::desc::CsgOp;
use crate::scene::object::{ObjKind, Object, Scratch, SurfaceHit};

/// Below this many members a plain scan with a box test per member is as fast.
pub const MIN_MEMBERS: usize = 8;

/// The same for a union's leaves, whose scan tests two members' boxes at a time
/// (`union_scan_first_hit`, `Object::any_hit`): cornell's two ten-triangle blocks scanned
/// instead of indexed, 1141 -> 1039 ms (160x120 +WT1, 3 alternating runs); stackerday,
/// chess2, pawns, glasschess, abyss, isocacti within ±1%.
pub const MIN_UNION_MEMBERS: usize = 12;

/// The members a node's index covers. A union's members that are themselves unions (without
/// `clipped_by` or `inverse`) are opened, recursively, as POV-Ray's `split_union` does: their
/// members are the union's leaves, in depth-first order. That order is the scan's, so nearest
/// hits, ties and crossing lists come out as from the nested scans. Other nodes index their
/// direct members.
pub struct ChildIndex {
    /// Over the leaves with finite, non-empty boxes; primitive i is leaf i.
    bvh: Bvh,
    /// Leaves with infinite, empty or NaN boxes, which every query looks at (as the scan did).
    others: Vec<u32>,
    /// Leaf i's own `bounds` (set when the object is made, never changed after), side by side:
    /// a union's walk tests a candidate's box here before it reaches the leaf's `Object`
    /// through its member path, two dependent cache misses a candidate in stackerday's union
    /// of 3,200 leaves, most of whose candidates the exact box turns away.
    leaf_bounds: Vec<Aabb>,
    /// Leaf i is reached from the node's members by the member numbers
    /// `steps[starts[i]..starts[i + 1]]`; both are empty when every leaf is a direct member.
    steps: Vec<u32>,
    starts: Vec<u32>,
}

fn indexed(b: &Aabb) -> bool {
    b.is_finite() && !b.is_empty()
}

/// The box a leaf is indexed by: its bounds, or for an unbounded one (a clipped quartic) the
/// finite box its planes and clipping give, if any. The index's boxes only pick the leaves to
/// ask, so a tighter one changes no answer.
fn leaf_box(o: &Object) -> Aabb {
    crate::scene::cull::solid_box(o).unwrap_or(o.bounds)
}

/// A union whose members can stand in for it in every query of an enclosing union.
fn opens(o: &Object) -> bool {
    matches!(
        o.kind,
        ObjKind::Csg {
            op: CsgOp::Union,
            ..
        }
    ) && o.clip.is_empty()
        && !o.inverse
}

fn members(o: &Object) -> &[Object] {
    match &o.kind {
        ObjKind::Csg { children, .. } => children,
        ObjKind::Shape(..) => &[],
    }
}

/// Gives every CSG node of the tree with enough leaves its index, except unions opened by an
/// enclosing union's index: queries reach their members through that one (`inside_without`,
/// which walks the tree, finds them without an index and scans).
pub fn attach(o: &mut Object, opened: bool) {
    set_culls(o);
    attach_indexes(o, opened);
}

/// Every CSG node's tight box (`scene::cull::cull_box`), members first: a union's box is
/// made of its members' boxes, some of which are their own culls.
fn set_culls(o: &mut Object) {
    for c in &mut o.clip {
        set_culls(c);
    }
    if let ObjKind::Csg {
        op, children, cull, ..
    } = &mut o.kind
    {
        children.iter_mut().for_each(set_culls);
        let aabb = crate::scene::cull::cull_box(*op, children, &o.bounds);
        // A union asks no member whether it holds a point, but its plane members' crossings
        // come cheaper through their faces (advanced/quilt1's clipped floor and wall). A union
        // given an index below drops them: the index numbers its leaves, not its members.
        let faces = crate::scene::faces::Faces::of(children);
        let local = crate::scene::cull::LocalBox::of(*op, children, &aabb.unwrap_or(o.bounds))
            .map(Box::new);
        *cull = (aabb.is_some() || faces.is_some() || local.is_some()).then(|| {
            Box::new(crate::scene::object::Cull {
                aabb,
                faces,
                local,
                ..Default::default()
            })
        });
    }
}

fn attach_indexes(o: &mut Object, opened: bool) {
    for c in &mut o.clip {
        attach_indexes(c, false);
    }
    if let ObjKind::Shape(shape, _) = &o.kind {
        // A clipped shape whose crossings outside a box are all clipped away (a clipped
        // quartic) is asked only for crossings in that box.
        let window = (!o.clip.is_empty() && shape.windowed())
            .then(|| crate::scene::cull::Window::of(o))
            .flatten();
        if let ObjKind::Shape(_, w) = &mut o.kind {
            *w = window.map(Box::new);
        }
        return;
    }
    let bounds = o.bounds;
    let ObjKind::Csg {
        op,
        children,
        index,
        cull,
    } = &mut o.kind
    else {
        return;
    };
    let mine = if opened {
        None
    } else {
        ChildIndex::build(*op, children)
    };
    let opening = *op == CsgOp::Union && (opened || mine.is_some());
    if *op == CsgOp::Union && mine.is_some() {
        if let Some(c) = cull {
            c.faces = None;
        }
        if cull.as_ref().is_some_and(|c| c.aabb.is_none()) {
            *cull = None;
        }
    }
    for c in children.iter_mut() {
        let open = opening && opens(c);
        attach_indexes(c, open);
    }
    // An intersection keeps only crossings in its tight box (`all_hits_unclipped` tests it
    // first), so a member that can save work there (a quartic: `roots_in_window` leaves the
    // pieces reaching Cauchy's bound unpolished) is asked only for those; the window is padded
    // against rounding where it is used. objects/quartic/trough 141 -> 106 ms, monkey 81 -> 59.
    if *op == CsgOp::Intersection {
        // Its bounds hold every crossing it keeps (the walk skips a ray that misses them;
        // `bounded_by` is not read), and its cull box, when it has one, is tighter.
        let tight = cull.as_ref().and_then(|c| c.aabb).unwrap_or(bounds);
        if let Some(bx) = Some(tight).filter(|b| b.is_finite() && !b.is_empty()) {
            let window = crate::scene::cull::Window::within(children, bx);
            for c in children.iter_mut() {
                if !c.clip.is_empty() || c.inverse {
                    continue;
                }
                if let ObjKind::Shape(shape, w) = &mut c.kind {
                    if w.is_none() && shape.windowed() {
                        *w = window.clone().map(Box::new);
                    }
                }
            }
        }
    }
    // Whether the search folds members: each member's index is attached by now (a member
    // with one is not folded), and a node given its own folds none.
    let folds = mine.is_none()
        && *op != CsgOp::Union
        && children
            .iter()
            .any(|c| crate::scene::csg_hit::folded(c).is_some());
    // Box members asked without dispatch (`csg_boxes`); `csg_keeps_boxes` has no index path.
    let boxes = (mine.is_none() && *op != CsgOp::Union)
        .then(|| crate::scene::csg_boxes::BoxMembers::of(*op, children))
        .flatten();
    let boxes_none = boxes.is_none();
    // Members that are all boxes under one transform (`csg_framed`): no member is folded
    // or an untransformed box, and none is a plane (no faces).
    let framed = (mine.is_none() && !folds && boxes_none)
        .then(|| {
            cull.as_ref()
                .is_none_or(|c| c.faces.is_none())
                .then(|| crate::scene::csg_framed::FramedBoxes::of(*op, children))
                .flatten()
        })
        .flatten();
    if let Some(f) = framed {
        let c = cull.get_or_insert_with(Box::default);
        c.search = Search::Framed;
        c.framed = Some(Box::new(f));
    }
    if folds || boxes.is_some() {
        let c = cull.get_or_insert_with(Box::default);
        c.search = match (folds, &boxes) {
            (_, Some(_)) => Search::Boxes,
            (true, None) => Search::Folds,
            (false, None) => Search::Plain,
        };
        c.folds = folds;
        c.boxes = boxes;
    }
    // The same nodes and members as the searches asked for them on every ray before:
    // without index or box members, the members (their windows set above) plain quadrics.
    let framed_none = cull.as_ref().is_none_or(|c| c.framed.is_none());
    let quadrics = (mine.is_none() && *op != CsgOp::Union && boxes_none && framed_none)
        .then(|| {
            let faces = cull.as_ref().and_then(|c| c.faces.as_ref());
            crate::scene::csg_quadrics::quadric_lanes_of(children, faces)
        })
        .flatten();
    let quadrics_none = quadrics.is_none();
    if let Some(q) = quadrics {
        let c = cull.get_or_insert_with(Box::default);
        c.quadrics = Some(Box::new(q));
    }
    // The leaf every kept crossing lies in (`csg_lead`), for the searches that gather it first.
    if mine.is_none() && quadrics_none {
        let faces = cull.as_ref().and_then(|c| c.faces.as_ref());
        let lead = match crate::scene::csg_lead::lead_of(*op, children, faces, &o.clip) {
            crate::scene::csg_lead::Lead::None => crate::scene::csg_lead::shut_of(*op, children),
            lead => lead,
        };
        if lead != crate::scene::csg_lead::Lead::None {
            cull.get_or_insert_with(Box::default).lead = lead;
        }
    }
    *index = mine;
}

impl ChildIndex {
    fn build(op: CsgOp, children: &[Object]) -> Option<Box<ChildIndex>> {
        let (mut boxes, mut leaf_bounds) = (Vec::new(), Vec::new());
        let (mut steps, mut starts) = (Vec::new(), Vec::new());
        let mut deep = false;
        if op == CsgOp::Union {
            fn walk(
                objs: &[Object],
                path: &mut Vec<u32>,
                boxes: &mut Vec<Aabb>,
                bounds: &mut Vec<Aabb>,
                steps: &mut Vec<u32>,
                starts: &mut Vec<u32>,
            ) {
                for (k, c) in objs.iter().enumerate() {
                    path.push(k as u32);
                    if opens(c) {
                        walk(members(c), path, boxes, bounds, steps, starts);
                    } else {
                        starts.push(steps.len() as u32);
                        steps.extend_from_slice(path);
                        boxes.push(leaf_box(c));
                        bounds.push(c.bounds);
                    }
                    path.pop();
                }
            }
            walk(
                children,
                &mut Vec::new(),
                &mut boxes,
                &mut leaf_bounds,
                &mut steps,
                &mut starts,
            );
            starts.push(steps.len() as u32);
            deep = steps.len() != boxes.len();
        } else {
            boxes.extend(children.iter().map(leaf_box));
            leaf_bounds.extend(children.iter().map(|c| c.bounds));
        }
        let min = if op == CsgOp::Union {
            MIN_UNION_MEMBERS
        } else {
            MIN_MEMBERS
        };
        if boxes.len() < min {
            return None;
        }
        if !deep {
            steps = Vec::new();
            starts = Vec::new();
        }
        let others = (0..boxes.len() as u32)
            .filter(|&i| !indexed(&boxes[i as usize]))
            .collect();
        for b in &mut boxes {
            if !indexed(b) {
                *b = Aabb::EMPTY;
            }
        }
        Some(Box::new(ChildIndex {
            bvh: Bvh::build(&boxes),
            others,
            leaf_bounds,
            steps,
            starts,
        }))
    }

    /// Leaf `i`'s `bounds`, from the index's copy (the leaf itself is reached through its
    /// member path, scattered in memory).
    #[inline(always)]
    pub fn leaf_box(&self, i: usize) -> &Aabb {
        &self.leaf_bounds[i]
    }

    /// Leaf `i` of the node whose members are `children`.
    #[inline(always)]
    pub fn leaf<'a>(&self, children: &'a [Object], i: usize) -> &'a Object {
        if self.starts.is_empty() {
            return &children[i];
        }
        let path = &self.steps[self.starts[i] as usize..self.starts[i + 1] as usize];
        let mut o = &children[path[0] as usize];
        for &k in &path[1..] {
            o = &members(o)[k as usize];
        }
        o
    }

    /// The member that leaf `i` is or belongs to.
    #[inline]
    pub fn member_of(&self, i: usize) -> usize {
        if self.starts.is_empty() {
            i
        } else {
            self.steps[self.starts[i] as usize] as usize
        }
    }

    /// Leaves whose box the ray may cross within (0, tmax], as `f(leaf, &mut tmax)`, which
    /// may lower `tmax` (inclusive: a leaf whose box starts exactly at `tmax` is still
    /// offered, so ties can be settled by leaf order). The caller works out the ray's `Recip`
    /// and chooses the node test's lanes (`Avx`: `Plain4`, the same bits as `Plain2`).
    #[inline(always)]
    pub fn traverse_recip<L: Lanes>(
        &self,
        lanes: L,
        ray: &Ray,
        r: &Recip,
        tmax: f64,
        mut f: impl FnMut(usize, &mut f64),
    ) {
        let mut t = tmax;
        for &i in &self.others {
            f(i as usize, &mut t);
        }
        self.bvh.traverse_recip(lanes, ray, r, t, |i, t| {
            f(i, t);
            false
        });
    }

    /// Like `traverse_recip` but stopping when `f` returns true.
    pub fn any(&self, ray: &Ray, tmax: f64, mut f: impl FnMut(usize) -> bool) -> bool {
        if self.others.iter().any(|&i| f(i as usize)) {
            return true;
        }
        let mut found = false;
        self.bvh.traverse(ray, tmax, |i, _| {
            found = f(i);
            found
        });
        found
    }

    /// Appends to `out` the leaves whose box the ray may cross within (0, tmax), in leaf
    /// order (a superset: the caller applies its own box test).
    pub fn candidates(&self, ray: &Ray, tmax: f64, out: &mut Vec<u32>) {
        let start = out.len();
        out.extend_from_slice(&self.others);
        self.bvh.traverse(ray, tmax, |i, _| {
            out.push(i as u32);
            false
        });
        out[start..].sort_unstable();
    }

    /// Whether `f` holds for some leaf whose box may contain `p`.
    pub fn any_at(&self, p: DVec3, mut f: impl FnMut(usize) -> bool) -> bool {
        if self.others.iter().any(|&i| f(i as usize)) {
            return true;
        }
        let mut found = false;
        self.bvh.visit_point(p, |i| {
            found = f(i);
            found
        });
        found
    }
}

/// A copy of a crossing a call has just returned, field by field at the fields' own widths.
/// The callee stores it field by field (`flip` as one byte, `part` as four, the others as
/// eight, some pairs as sixteen); a copy of the whole struct read it as 8- and 16-byte pieces
/// spanning several of those stores, which the store buffer cannot forward, so each such load
/// waited for the callee's stores to reach the cache (a tenth of `Object::first_hit`'s samples
/// on camera/perspective, in the inlined scan below). Volatile reads keep LLVM from merging
/// the fields' loads back into those pieces.
#[inline(always)]
pub(crate) fn fresh_copy<'a>(h: &SurfaceHit<'a>) -> SurfaceHit<'a> {
    use std::ptr::read_volatile as get;
    // SAFETY: every read is of an initialised field through a reference.
    unsafe {
        SurfaceHit {
            t: get(&h.t),
            obj: get(&h.obj),
            hit: fresh_hit(&h.hit),
            flip: get(&h.flip),
        }
    }
}

/// `fresh_copy` of a shape's `Hit` (its `part` is stored as four bytes).
#[inline(always)]
pub(crate) fn fresh_hit(h: &Hit) -> Hit {
    use std::ptr::read_volatile as get;
    // SAFETY: every read is of an initialised field through a reference.
    unsafe {
        Hit {
            t: get(&h.t),
            part: get(&h.part),
            uv: [get(&h.uv[0]), get(&h.uv[1])],
        }
    }
}

/// The nearest crossing of an unindexed union's members, scanned in order: the nearest, and of
/// crossings at the same distance the earliest member's. Members' boxes are tested two at a
/// time; the second is tested again when the first member's crossing lowered `tmax`, so each
/// member is asked exactly when the one-by-one scan would ask it.
pub(crate) fn union_scan_first_hit<'a>(
    children: &'a [Object],
    ray: &Ray,
    tmax: f64,
    s: &mut Scratch<'a>,
) -> Option<SurfaceHit<'a>> {
    let slabs = Slabs::new(ray.origin, ray.dir.recip());
    let mut best: Option<SurfaceHit<'a>> = None;
    let mut tmax = tmax;
    let mut pairs = children.chunks_exact(2);
    for pair in &mut pairs {
        let (ha, mut hb) = slabs.hits2(&pair[0].bounds, &pair[1].bounds, tmax);
        if ha {
            if let Some(h) = &pair[0].first_hit(ray, tmax, s) {
                let h = fresh_copy(h);
                tmax = h.t;
                best = Some(h);
                hb = hb && slabs.hits(&pair[1].bounds, tmax);
            }
        }
        if hb {
            if let Some(h) = &pair[1].first_hit(ray, tmax, s) {
                let h = fresh_copy(h);
                tmax = h.t;
                best = Some(h);
            }
        }
    }
    for c in pairs.remainder() {
        if slabs.hits(&c.bounds, tmax) {
            if let Some(h) = &c.first_hit(ray, tmax, s) {
                let h = fresh_copy(h);
                tmax = h.t;
                best = Some(h);
            }
        }
    }
    best
}

/// A union's nearest crossing through its index, exactly as the scan over its members in order
/// finds it: the nearest, and of crossings at the same distance the earliest member's (the scan
/// keeps a crossing only when strictly nearer than the best so far).
#[inline]
pub(crate) fn union_first_hit<'a>(
    children: &'a [Object],
    ix: &ChildIndex,
    ray: &Ray,
    tmax: f64,
    s: &mut Scratch<'a>,
) -> Option<SurfaceHit<'a>> {
    #[cfg(target_arch = "x86_64")]
    if crate::cpu::avx() {
        // SAFETY: the CPU has AVX.
        return unsafe { union_first_hit_avx(children, ix, ray, tmax, s) };
    }
    union_first_hit_base(children, ix, ray, tmax, s)
}

/// `union_first_hit_in` in three-operand AVX encodings with the index's nodes tested in
/// 256-bit lanes (`Plain4`); no fused multiply-add, so the same operations give the same bits.
/// Compiled without AVX the walk spent ~48 instructions a node against ~32 (the scene walk's
/// copies, walk23), and stackerday's gathering rays walk a union of 3,200 leaves.
///
/// # Safety
/// The CPU must have AVX.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
unsafe fn union_first_hit_avx<'a>(
    children: &'a [Object],
    ix: &ChildIndex,
    ray: &Ray,
    tmax: f64,
    s: &mut Scratch<'a>,
) -> Option<SurfaceHit<'a>> {
    // SAFETY: the caller says the CPU has AVX.
    union_first_hit_in(unsafe { Avx::new() }, children, ix, ray, tmax, s)
}

/// `union_first_hit_in` for CPUs without AVX.
#[inline(never)]
fn union_first_hit_base<'a>(
    children: &'a [Object],
    ix: &ChildIndex,
    ray: &Ray,
    tmax: f64,
    s: &mut Scratch<'a>,
) -> Option<SurfaceHit<'a>> {
    union_first_hit_in(Sse, children, ix, ray, tmax, s)
}

/// `union_first_hit`'s body. The members' slab tests and the index's walk share one
/// reciprocal (`Recip::of` is `1.0 / dir` per component, as `DVec3::recip`, and its `plain`
/// is `Slabs::new`'s test).
#[inline(always)]
fn union_first_hit_in<'a, L: Lanes>(
    lanes: L,
    children: &'a [Object],
    ix: &ChildIndex,
    ray: &Ray,
    tmax: f64,
    s: &mut Scratch<'a>,
) -> Option<SurfaceHit<'a>> {
    let r = Recip::of(ray);
    let slabs = Slabs::known(ray.origin, r.inv, r.plain);
    let mut best: Option<(usize, SurfaceHit<'a>)> = None;
    ix.traverse_recip(lanes, ray, &r, tmax, |i, t| {
        // An earlier member than the best so far also wins at the same distance.
        let limit = match &best {
            Some((bi, h)) if i < *bi => h.t.next_up(),
            Some((_, h)) => h.t,
            None => tmax,
        };
        // `c.bounds`, read from the index's copy (`leaf_bounds`).
        if !slabs.hits(&ix.leaf_bounds[i], limit) {
            return;
        }
        let c = ix.leaf(children, i);
        if let Some(h) = &c.first_hit(ray, limit, s) {
            let h = fresh_copy(h);
            *t = h.t;
            best = Some((i, h));
        }
    });
    best.map(|(_, h)| h)
}

#[cfg(test)]
#[path = "children_tests.rs"]
mod tests;
