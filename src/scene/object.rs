//! Runtime objects: a shape placed in the world with its texture and flags, or a CSG node.
//!
//! Only leaves carry transforms (CSG transforms were pushed down to the leaves by the parser),
//! so every CSG inside test and hit filter works in world space.

use std::sync::Arc;

use crate::geom::{Hit, Shape};
use crate::math::{Aabb, DVec3, Ray, Slabs, Transform};
use crate::scene::children::{fresh_hit, union_first_hit, union_scan_first_hit, ChildIndex};
use crate::scene::cull::{Range, Window};
use crate::scene::desc::{CsgOp, MeshData, Texture};
use crate::scene::faces::{self, Faces};
pub use crate::scene::scratch::Scratch;

pub enum ObjKind {
    /// A shape, and for a clipped leaf whose crossings outside a box (`scene::cull::object_cull`)
    /// or its clipping's half-spaces are all clipped away, that window: the shape is asked only
    /// for crossings in it.
    Shape(Arc<dyn Shape>, Option<Box<Window>>),
    Csg {
        op: CsgOp,
        children: Vec<Object>,
        /// A BVH over the members, for nodes with many of them.
        index: Option<Box<ChildIndex>>,
        /// What lets rays and points skip work: a tight box, the plane members.
        cull: Option<Box<Cull>>,
    },
}

/// What a CSG node keeps to skip work; one box for both, so nodes stay as small as before.
#[derive(Default)]
pub struct Cull {
    /// A box tighter than `bounds` holding the node's solid (before `inverse`), for
    /// intersections whose members are unbounded planes (`scene::cull`).
    pub aabb: Option<Aabb>,
    /// The members that are planes with an axis normal (`scene::faces`), of nodes other than
    /// unions (whose index, if any, numbers their members as `children` does).
    pub faces: Option<Faces>,
    /// The node has no index and a member `csg_hit::folded` searches through: its
    /// `csg_first_hit` is the folding one. Set once the indexes are attached
    /// (`children::attach`), so that no search scans the members for it.
    pub folds: bool,
    /// The members that are box leaves, of a node other than a union without index: its
    /// searches ask them without dispatch (`scene::csg_boxes`).
    pub boxes: Option<crate::scene::csg_boxes::BoxMembers>,
    /// Which search `first_hit` runs, set with the fields above (one byte, not a test a kind).
    pub search: crate::scene::csg_boxes::Search,
    /// The members' diagonal forms in AVX lanes, for a node without index or box members
    /// whose 2-4 members are plain quadric leaves (`csg_quadrics`), solved four at a time.
    pub quadrics: Option<Box<crate::geom::algebraic::QuadricLanes>>,
    /// The members, when they are all boxes under one transform, of a node other than a
    /// union without index, box members, folds or faces (`scene::csg_framed`).
    pub framed: Option<Box<crate::scene::csg_framed::FramedBoxes>>,
    /// A difference's box in its turned first member's space (`cull::LocalBox`), which a
    /// ray listing the node's crossings must cross.
    pub local: Option<Box<crate::scene::cull::LocalBox>>,
    /// The leaf every kept point lies in, for nodes without index or quadric lanes.
    pub lead: crate::scene::csg_lead::Lead,
}

/// A shape's data with the textures of its parts (mesh triangles, blob components).
pub type PartTextures<T> = Box<(Arc<T>, Vec<Arc<Texture>>)>;

pub struct Object {
    pub kind: ObjKind,
    /// Object to world; `None` when identity, to skip two matrix products per ray.
    /// Boxed: most objects of a big scene have none, and inline it would be 256 bytes each.
    pub transform: Option<Box<Transform>>,
    pub texture: Arc<Texture>,
    /// `interior_texture`: shades the surface where the ray meets it from inside.
    pub interior_texture: Option<Arc<Texture>>,
    /// Per-triangle textures of a mesh, indexed by `MeshData::triangles[i].texture`.
    /// Boxed, as `blob`: few objects have one, and every object would pay 32 bytes inline.
    pub mesh: Option<PartTextures<MeshData>>,
    /// A blob whose components have textures, and each component's texture (see
    /// `geom::blob::PART_BLENDED`).
    pub blob: Option<PartTextures<crate::geom::blob::Blob>>,
    pub ior: f64,
    pub no_shadow: bool,
    /// Unseen by camera rays and their transmitted continuations (`no_image`).
    pub no_image: bool,
    /// Unseen by reflected rays (`no_reflection`).
    pub no_reflection: bool,
    /// Unseen by radiosity's gathering rays (`no_radiosity`).
    pub no_radiosity: bool,
    /// `radiosity { importance }` in 1/255ths (255, all, when not written): the share of
    /// radiosity's gathering rays meeting it that are followed. One byte fits beside the
    /// flags; anything wider grows every object by 8 (tests/memory_layout.rs).
    pub importance: u8,
    /// Lit from behind its surface too (`double_illuminate`).
    pub double_illuminate: bool,
    /// `hollow`: fog and other atmosphere reach inside it (they stop inside solid objects).
    pub hollow: bool,
    /// Which lights light it: an index into `Scene::light_sets` (0: the lights outside any
    /// `light_group`).
    pub light_set: u16,
    pub inverse: bool,
    /// World-space bounds (`Aabb::INFINITE` for unbounded objects).
    pub bounds: Aabb,
    /// Whether any colour of the texture has filter or transmit, so shadow rays must look at
    /// the surface colour instead of stopping at the first crossing.
    pub transparent: bool,
    /// `clipped_by`: crossings outside any of these are dropped.
    pub clip: Vec<Object>,
    /// An interior that fades light passing through it, holds media, splits light into
    /// colours (`dispersion`) or fakes caustics.
    pub interior: Option<Box<crate::scene::desc::Interior>>,
    /// `photons { }` flags (scene::photon::flags), a CSG's given to its members too; `pass_through`
    /// is set for `no_shadow` objects unless turned off.
    pub photons: u8,
    /// `photons { target Float }`: the spacing multiplier of photons shot at it.
    pub photon_mult: f32,
}

pub(super) use crate::scene::csg_members::{csg_keeps, each_member, member_hits};

/// A crossing of a ray with a leaf object.
#[derive(Clone, Copy)]
pub struct SurfaceHit<'a> {
    pub t: f64,
    pub obj: &'a Object,
    pub hit: Hit,
    /// The surface belongs to a subtracted CSG operand, so its normal points inwards.
    pub flip: bool,
}

impl Object {
    /// The ray in object space: `ray` itself when there is no transform (a copy costs more
    /// than the plane or sphere test reading it), else the transformed ray put in `local`.
    #[inline]
    pub(super) fn local_ray<'r>(&self, ray: &'r Ray, local: &'r mut Option<Ray>) -> &'r Ray {
        match &self.transform {
            Some(t) => local.insert(t.inv_ray(ray)),
            None => ray,
        }
    }

    /// `first_hit` of an object with `clipped_by`, or with `nearest` false some crossing it
    /// could have chosen (only whether there is one is meant: `any_hit`). Out of line: the
    /// unclipped path of `first_hit` is the hot one.
    #[inline(never)]
    fn clipped_hit<'a>(
        &'a self,
        ray: &Ray,
        tmax: f64,
        s: &mut Scratch<'a>,
        nearest: bool,
    ) -> Option<SurfaceHit<'a>> {
        match &self.kind {
            ObjKind::Csg {
                op,
                children,
                index,
                cull,
            } if *op != CsgOp::Union => {
                let culls = (
                    cull.as_ref().and_then(|c| c.aabb.as_ref()),
                    cull.as_ref().and_then(|c| c.faces.as_ref()),
                );
                // As `first_hit` chooses.
                self.node_search(*op, children, index.as_deref(), culls, ray, tmax, s)
            }
            _ => self.clipped_first_hit(ray, tmax, s, nearest),
        }
    }

    /// Nearest crossing with `t` in (EPSILON, tmax).
    pub fn first_hit<'a>(
        &'a self,
        ray: &Ray,
        tmax: f64,
        s: &mut Scratch<'a>,
    ) -> Option<SurfaceHit<'a>> {
        if !self.clip.is_empty() {
            return self.clipped_hit(ray, tmax, s, true);
        }
        match &self.kind {
            ObjKind::Shape(shape, _) => {
                let mut local = None;
                let r = self.local_ray(ray, &mut local);
                // Field by field (`fresh_hit`): the shape has just stored the crossing.
                let found = shape.intersect_first(r, tmax, &mut s.hits);
                let hit = fresh_hit(found.as_ref()?);
                Some(SurfaceHit {
                    t: hit.t,
                    obj: self,
                    hit,
                    flip: self.inverse,
                })
            }
            ObjKind::Csg {
                op: CsgOp::Union,
                children,
                index: Some(ix),
                ..
            } => union_first_hit(children, ix, ray, tmax, s),
            ObjKind::Csg {
                op: CsgOp::Union,
                children,
                index: None,
                ..
            } => union_scan_first_hit(children, ray, tmax, s),
            ObjKind::Csg {
                op,
                children,
                index,
                cull,
            } if *op != CsgOp::Union => {
                let culls = (
                    cull.as_ref().and_then(|c| c.aabb.as_ref()),
                    cull.as_ref().and_then(|c| c.faces.as_ref()),
                );
                // Polyhedra: members that are all faces. An index, if any, changes nothing
                // for them: a plane's leaf box is never finite (one half-space), so the index
                // offers every member to every ray, in member order (`ChildIndex::others`),
                // and asks every member in `csg_keeps` (`any_at`).
                if let Some(f) = culls.1 {
                    if let Some(all) = f.all().filter(|_| faces::ray_ok(ray)) {
                        return self.faces_first_hit(*op, children, (culls.0, f, all), ray, tmax);
                    }
                }
                // Members that are plain intersections are searched through (`csg_hit`), box
                // members asked without dispatch (`csg_boxes`).
                self.node_search(*op, children, index.as_deref(), culls, ray, tmax, s)
            }
            ObjKind::Csg { .. } => {
                let start = s.surface.len();
                self.all_hits(ray, tmax, s);
                let best = s.surface[start..]
                    .iter()
                    .min_by(|a, b| a.t.total_cmp(&b.t))
                    .copied();
                s.surface.truncate(start);
                best
            }
        }
    }

    /// Appends every crossing with t in (EPSILON, tmax), in no particular order, to
    /// `s.surface`. Crossings beyond `tmax` are dropped before the CSG inside tests, which
    /// are the expensive part.
    pub fn all_hits<'a>(&'a self, ray: &Ray, tmax: f64, s: &mut Scratch<'a>) {
        let start = s.surface.len();
        self.all_hits_unclipped(ray, tmax, s);
        if !self.clip.is_empty() {
            let mut k = start;
            // `t` read alone (`all_hits_unclipped`'s filter: a copy of a crossing just pushed
            // waits for its stores to reach the cache).
            for j in start..s.surface.len() {
                let p = ray.at(s.surface[j].t);
                if self.clip.iter().all(|c| c.inside(p)) {
                    s.surface[k] = s.surface[j];
                    k += 1;
                }
            }
            s.surface.truncate(k);
        }
    }

    /// For a union without `clipped_by` or `inverse`, true, with the members whose crossings
    /// `all_hits` lists appended to `out` in its order: `all_hits` of such a union is exactly
    /// their `all_hits`, one after another (a union keeps every crossing and flips none), so
    /// a caller may ask them one by one. False, with nothing appended, for other objects.
    pub fn union_members<'a>(
        &'a self,
        ray: &Ray,
        tmax: f64,
        s: &mut Scratch<'a>,
        out: &mut Vec<&'a Object>,
    ) -> bool {
        let ObjKind::Csg {
            op: CsgOp::Union,
            children,
            index,
            cull,
        } = &self.kind
        else {
            return false;
        };
        if self.inverse || !self.clip.is_empty() {
            return false;
        }
        // The same tests, in the same order, as `all_hits_unclipped`.
        let inv_dir = ray.dir.recip();
        if cull
            .as_ref()
            .and_then(|c| c.aabb.as_ref())
            .is_some_and(|c| c.hit(ray.origin, inv_dir, tmax).is_none())
        {
            return true;
        }
        let slabs = Slabs::new(ray.origin, inv_dir);
        // `each_member`'s two loops written out here, the box test in them: through it, the
        // test was a closure called per candidate (advanced/abyss's transparent container
        // union asks it for every shadow ray of its media).
        match index.as_deref() {
            None => {
                for c in children {
                    if slabs.hits(&c.bounds, tmax) {
                        out.push(c);
                    }
                }
            }
            Some(ix) => {
                let from = s.members.len();
                ix.candidates(ray, tmax, &mut s.members);
                for k in from..s.members.len() {
                    // The box from the index's copy, so that a candidate it rejects costs no
                    // walk of its member path (advanced/abyss: a tenth of this walk's
                    // samples sat on that path's loads).
                    let i = s.members[k] as usize;
                    if slabs.hits(ix.leaf_box(i), tmax) {
                        out.push(ix.leaf(children, i));
                    }
                }
                s.members.truncate(from);
            }
        }
        true
    }

    // Always inline: the hot caller is `all_hits` (measured: 1 % more instructions on
    // objects/csg/intee1 when it is called).
    #[inline(always)]
    pub(super) fn all_hits_unclipped<'a>(&'a self, ray: &Ray, tmax: f64, s: &mut Scratch<'a>) {
        match &self.kind {
            ObjKind::Shape(shape, window) => {
                self.shape_hits(&**shape, window.as_deref(), ray, tmax, &mut s.hits);
                self.take_hits(tmax, s);
            }
            ObjKind::Csg {
                op,
                children,
                index,
                cull,
            } => {
                let mine = s.surface.len();
                let inv_dir = ray.dir.recip();
                // Every crossing lies in the tight box, and in a turned difference's box in
                // its first member's space.
                if let Some(c) = cull.as_deref() {
                    if c.aabb
                        .as_ref()
                        .is_some_and(|b| b.hit(ray.origin, inv_dir, tmax).is_none())
                        || c.local.as_deref().is_some_and(|l| l.misses(ray, tmax))
                    {
                        return;
                    }
                }
                let index = index.as_deref();
                let faces = cull.as_ref().and_then(|c| c.faces.as_ref());
                let ray_faces = faces.filter(|_| faces::ray_ok(ray));
                let rejecter = std::cell::Cell::new(usize::MAX);
                let slabs = Slabs::new(ray.origin, inv_dir);
                // A box member none of whose crossings is kept (`csg_lead::shut_of`: its
                // faces lie outside where the others may hold a point), so none is listed:
                // not gathered, as in `csg_first_hit` (whiltile's shadow rays through its
                // crystal tiles). Only set without an index, where `i` is the member's place.
                let shut = cull.as_deref().map_or(usize::MAX, |c| c.lead.shut());
                // Member `i` is `c`; in a union's index `c` may be a leaf of an opened member
                // union (its number then does not matter: a union keeps every crossing).
                // In member order, as the scan: callers see crossings in this order. The
                // closure inlined in the member loop (called, a frame per member visit).
                each_member(
                    children,
                    index,
                    ray,
                    tmax,
                    s,
                    #[inline(always)]
                    |c: &'a Object, i: usize, s: &mut Scratch<'a>| {
                        // A child whose box the ray misses adds no crossings (transparent shadows
                        // through a union of many parts would otherwise test every part).
                        if i == shut || !slabs.hits(&c.bounds, tmax) {
                            return;
                        }
                        // Each child's crossings are appended, then filtered in place.
                        let start = s.surface.len();
                        member_hits(c, ray_faces.and_then(|f| f.get(i)), ray, tmax, s);
                        // `t` read alone, the crossing copied only once kept: a copy of the
                        // whole `SurfaceHit` just pushed read its hit's `t` and `part` as one
                        // 16-byte load, which the two narrower stores cannot forward (15 %
                        // of each_member's samples on advanced/whiltile).
                        let mut k = start;
                        for j in start..s.surface.len() {
                            let t = s.surface[j].t;
                            if csg_keeps(*op, i, children, index, faces, ray.at(t), &rejecter) {
                                s.surface[k] = s.surface[j];
                                // Surfaces of subtracted operands face into the result.
                                s.surface[k].flip ^= *op == CsgOp::Difference && i > 0;
                                k += 1;
                            }
                        }
                        s.surface.truncate(k);
                    },
                );
                if self.inverse {
                    s.surface[mine..].iter_mut().for_each(|h| h.flip = !h.flip);
                }
            }
        }
    }

    /// Whether `p` lies inside this object where it is solid (not `hollow`), for the rule
    /// that no atmosphere or media is computed inside solid objects. POV-Ray judges a union by
    /// its members (measured: a hollow media sphere in a union that is not hollow shows its
    /// media around the camera; a solid member around the camera hides it until the ray
    /// leaves that member), other objects by their own flag (an intersection or merge with a
    /// hollow member is solid).
    #[inline(always)]
    pub fn solid_at(&self, p: DVec3) -> bool {
        // An unclipped leaf, nearly every top-level object, answered in the caller's loop
        // (the fog's inside test at every camera ray): `!hollow && inside` as below, without
        // the call that took the point through memory.
        match (&self.kind, self.clip.is_empty()) {
            (ObjKind::Shape(_, _), true) => !self.hollow && self.leaf_inside(p) == Some(true),
            _ => self.solid_at_node(p),
        }
    }

    /// `solid_at` of a CSG node or a clipped leaf.
    #[inline(never)]
    fn solid_at_node(&self, p: DVec3) -> bool {
        match &self.kind {
            ObjKind::Csg {
                op: CsgOp::Union,
                children,
                ..
            } if !self.inverse && self.clip.is_empty() => {
                self.bounds.contains(p) && children.iter().any(|c| c.solid_at(p))
            }
            _ => !self.hollow && self.inside(p),
        }
    }

    /// `p` in the object's own space (its shape's coordinates).
    #[inline(always)]
    pub(super) fn local_point(&self, p: DVec3) -> DVec3 {
        match &self.transform {
            Some(t) => t.inv_point(p),
            None => p,
        }
    }

    /// A leaf's shape crossings, all of them (`intersect_all`) but those the shape may leave out
    /// at or past `tmax` (the callers keep only `t < tmax`), into `hits`:
    /// `all_hits_unclipped` of a leaf before its `take_hits`.
    #[inline(always)]
    pub(super) fn shape_hits(
        &self,
        shape: &dyn Shape,
        window: Option<&Window>,
        ray: &Ray,
        tmax: f64,
        hits: &mut Vec<Hit>,
    ) {
        let mut local = None;
        let r = self.local_ray(ray, &mut local);
        hits.clear();
        match window {
            // Crossings outside the box are clipped away: the shape may leave them
            // out. The range is over the whole line, padded against rounding.
            Some(w) => match w.range(ray) {
                Range::Within(lo, hi) => shape.intersect_all_within(r, lo, hi, hits),
                Range::Empty => {}
                Range::All => shape.intersect_all(r, hits),
            },
            // Crossings at or past `tmax` are dropped by the caller.
            None => shape.intersect_all_before(r, tmax, hits),
        }
    }

    /// The shape crossings left in `s.hits` closer than `tmax`, as this object's surface hits
    /// (a leaf's part of `all_hits`, shared with the CSG searches' inlined leaf members).
    #[inline(always)]
    pub(super) fn take_hits<'a>(&'a self, tmax: f64, s: &mut Scratch<'a>) {
        // Field by field, in a loop with `push`: a copy of the whole `Hit` (as `extend` of
        // `|&hit|` made, even of its fields) read `t` and `part` as one 16-byte load, which
        // cannot be forwarded from the shape's 8- and 4-byte stores of them: the load waits
        // until they reach the cache (12 % of each_member's samples on advanced/whiltile).
        for k in 0..s.hits.len() {
            let h = &s.hits[k];
            let (t, part, uv) = (h.t, h.part, h.uv);
            if t < tmax {
                s.surface.push(SurfaceHit {
                    t,
                    obj: self,
                    hit: Hit { t, part, uv },
                    flip: self.inverse,
                });
            }
        }
    }

    /// Whether `p` is inside this object (`inverse` and `clipped_by` applied).
    #[inline]
    pub fn inside(&self, p: DVec3) -> bool {
        self.leaf_inside(p).unwrap_or_else(|| self.inside_node(p))
    }

    /// `inside` of a leaf without clipping, the common CSG member, answered inline in the
    /// callers' loops (`inside`, `csg_keeps`) without the frame of the recursive
    /// `inside_node`; None for any other object. The same tests as there: its bounds, the
    /// point in object space, the shape's own test.
    #[inline(always)]
    pub(super) fn leaf_inside(&self, p: DVec3) -> Option<bool> {
        match (&self.kind, self.clip.is_empty()) {
            (ObjKind::Shape(s, _), true) if self.bounds.holds(p) => {
                Some(s.inside(self.local_point(p)) != self.inverse)
            }
            (ObjKind::Shape(_, _), true) => Some(self.inverse),
            _ => None,
        }
    }

    /// `inside` of a CSG node or a clipped leaf.
    #[inline(never)]
    fn inside_node(&self, p: DVec3) -> bool {
        // Bounds enclose the (un-inverted) solid, so outside them the answer is known.
        if !self.bounds.contains(p) {
            return self.inverse;
        }
        let r = match &self.kind {
            ObjKind::Shape(s, _) => s.inside(self.local_point(p)),
            ObjKind::Csg { cull: Some(c), .. } if c.aabb.is_some_and(|a| !a.contains(p)) => false,
            ObjKind::Csg {
                op,
                children,
                index: Some(ix),
                ..
            } => match op {
                CsgOp::Union | CsgOp::Merge => ix.any_at(p, |j| ix.leaf(children, j).inside(p)),
                CsgOp::Intersection => children.iter().all(|c| c.inside(p)),
                CsgOp::Difference => {
                    children[0].inside(p) && !ix.any_at(p, |j| j > 0 && children[j].inside(p))
                }
            },
            ObjKind::Csg { op, children, .. } => match op {
                CsgOp::Union | CsgOp::Merge => children.iter().any(|c| c.inside(p)),
                CsgOp::Intersection => !children.is_empty() && children.iter().all(|c| c.inside(p)),
                CsgOp::Difference => {
                    children.first().is_some_and(|c| c.inside(p))
                        && !children[1..].iter().any(|c| c.inside(p))
                }
            },
        };
        let r = r && self.clip.iter().all(|c| c.inside(p));
        // A shape's own `inverse` is folded in here; CSG nodes likewise.
        r != self.inverse
    }

    /// Whether the ray crosses this object within (EPSILON, tmax): `first_hit(..).is_some()`,
    /// but a union stops at the first member it finds crossed (shadow rays).
    pub fn any_hit<'a>(&'a self, ray: &Ray, tmax: f64, s: &mut Scratch<'a>) -> bool {
        if let Some((children, ix)) = self.indexed_union() {
            let slabs = Slabs::new(ray.origin, ray.dir.recip());
            return ix.any(ray, tmax, |i| {
                let c = ix.leaf(children, i);
                slabs.hits(&c.bounds, tmax) && c.member_any_hit(ray, tmax, s)
            });
        }
        if let Some(members) = self.scanned_union() {
            let slabs = Slabs::new(ray.origin, ray.dir.recip());
            return Self::scan_any_hit(members, ray, &slabs, tmax, s);
        }
        if let (ObjKind::Shape(shape, _), true) = (&self.kind, self.clip.is_empty()) {
            // `first_hit` of a leaf without clipping is the shape's `intersect_first`.
            let mut local = None;
            return shape.any_hit(self.local_ray(ray, &mut local), tmax, &mut s.hits);
        }
        if let ObjKind::Csg {
            op,
            children,
            index,
            cull,
        } = &self.kind
        {
            if *op != CsgOp::Union {
                let culls = (
                    cull.as_ref().and_then(|c| c.aabb.as_ref()),
                    cull.as_ref().and_then(|c| c.faces.as_ref()),
                );
                // Polyhedra keep their own search (`first_hit`'s first case).
                if let (Some(f), true) = (culls.1, self.clip.is_empty()) {
                    if let Some(all) = f.all().filter(|_| faces::ray_ok(ray)) {
                        return self
                            .faces_first_hit(*op, children, (culls.0, f, all), ray, tmax)
                            .is_some();
                    }
                }
                let index = index.as_deref();
                if let Some(f) = self.framed_boxes() {
                    // Boxes under one transform (`csg_framed`).
                    return self.framed_any_hit(culls.0, f, ray, tmax);
                }
                return if cull.as_ref().is_some_and(|c| c.boxes.is_some()) {
                    // Box members without dispatch (`csg_boxes`); such nodes have no index.
                    self.csg_any_hit::<true>(*op, children, index, culls, ray, tmax, s)
                } else {
                    self.csg_any_hit::<false>(*op, children, index, culls, ray, tmax, s)
                };
            }
        }
        if !self.clip.is_empty() {
            if let ObjKind::Shape(shape, None) = &self.kind {
                return self.clipped_leaf_any_hit(&**shape, ray, tmax, s);
            }
            return self.clipped_hit(ray, tmax, s, false).is_some();
        }
        self.first_hit(ray, tmax, s).is_some()
    }

    /// The members of a union that `any_hit` walks through its index (no clipping), and the
    /// index.
    #[inline(always)]
    pub fn indexed_union(&self) -> Option<(&[Object], &ChildIndex)> {
        match (&self.kind, self.clip.is_empty()) {
            (
                ObjKind::Csg {
                    op: CsgOp::Union,
                    children,
                    index: Some(ix),
                    ..
                },
                true,
            ) => Some((children, ix)),
            _ => None,
        }
    }

    /// The members of a union that `any_hit` scans box by box (no index, no clipping).
    #[inline(always)]
    pub fn scanned_union(&self) -> Option<&[Object]> {
        match (&self.kind, self.clip.is_empty()) {
            (
                ObjKind::Csg {
                    op: CsgOp::Union,
                    children,
                    index: None,
                    ..
                },
                true,
            ) => Some(children),
            _ => None,
        }
    }

    /// `any_hit` of a `scanned_union`'s `members` along the ray whose `slabs` are given (a
    /// shadow ray has them already: `Slabs::new(ray.origin, ray.dir.recip())` took three
    /// divisions for every union it met). Unlike `first_hit`, it stops at the first member
    /// crossed.
    #[inline]
    pub fn scan_any_hit<'a>(
        members: &'a [Object],
        ray: &Ray,
        slabs: &Slabs,
        tmax: f64,
        s: &mut Scratch<'a>,
    ) -> bool {
        let mut pairs = members.chunks_exact(2);
        for pair in &mut pairs {
            let (ha, hb) = slabs.hits2(&pair[0].bounds, &pair[1].bounds, tmax);
            if (ha && pair[0].member_any_hit(ray, tmax, s))
                || (hb && pair[1].member_any_hit(ray, tmax, s))
            {
                return true;
            }
        }
        pairs
            .remainder()
            .iter()
            .any(|c| slabs.hits(&c.bounds, tmax) && c.member_any_hit(ray, tmax, s))
    }

    /// `any_hit` of a union's member, with a plain leaf's case (an untransformed, unclipped
    /// shape: cornell's triangles) asked here rather than through a call of `any_hit`, whose
    /// frame (it saves six registers and sets up the CSG cases' stack) cost more than the
    /// triangle's own test.
    #[inline(always)]
    fn member_any_hit<'a>(&'a self, ray: &Ray, tmax: f64, s: &mut Scratch<'a>) -> bool {
        match (&self.kind, self.clip.is_empty(), &self.transform) {
            (ObjKind::Shape(shape, _), true, None) => shape.any_hit(ray, tmax, &mut s.hits),
            _ => self.any_hit(ray, tmax, s),
        }
    }

    /// Like `inside`, but as if `leaf` were not part of this object.
    pub fn inside_without(&self, p: DVec3, leaf: &Object) -> bool {
        if std::ptr::eq(self, leaf) || (!self.inverse && !self.bounds.contains(p)) {
            return false;
        }
        match &self.kind {
            ObjKind::Csg {
                op: CsgOp::Union | CsgOp::Merge,
                children,
                ..
            } if self.contains(leaf) => {
                children.iter().any(|c| c.inside_without(p, leaf)) != self.inverse
            }
            _ if self.contains(leaf) => false,
            _ => self.inside(p),
        }
    }

    /// `inside_without(p, chain[0])` for the object `chain.last()` (this one), where `chain`
    /// is the leaf and its nodes upwards: no search for the leaf.
    pub fn inside_without_chain(&self, p: DVec3, chain: &[usize]) -> bool {
        let Some((_, below)) = chain.split_last() else {
            return false;
        };
        if below.is_empty() || (!self.inverse && !self.bounds.contains(p)) {
            return false;
        }
        let next = below[below.len() - 1];
        match &self.kind {
            ObjKind::Csg {
                op: CsgOp::Union | CsgOp::Merge,
                children,
                index: Some(ix),
                ..
            } => {
                // The member holding the leaf, and through the index the other members'
                // leaves (a member union's inside is its leaves').
                let m = (next - children.as_ptr() as usize) / std::mem::size_of::<Object>();
                (ix.any_at(p, |j| {
                    ix.member_of(j) != m && ix.leaf(children, j).inside(p)
                }) || children[m].inside_without_chain(p, below))
                    != self.inverse
            }
            ObjKind::Csg {
                op: CsgOp::Union | CsgOp::Merge,
                children,
                ..
            } => {
                children.iter().any(|c| {
                    if c as *const Object as usize == next {
                        c.inside_without_chain(p, below)
                    } else {
                        // Members not holding the leaf: inside_without is inside.
                        c.inside(p)
                    }
                }) != self.inverse
            }
            _ => false,
        }
    }

    fn contains(&self, leaf: &Object) -> bool {
        std::ptr::eq(self, leaf)
            || match &self.kind {
                ObjKind::Csg { children, .. } => children.iter().any(|c| c.contains(leaf)),
                ObjKind::Shape(..) => false,
            }
    }
}
