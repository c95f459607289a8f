//! CSG nodes whose two to four members are plain quadric leaves: their searches solve the
//! members four at a time in AVX lanes (`QuadricLanes`) and ask their inside tests there,
//! the same crossings and answers as `csg_hit`'s general paths (moved here from csg_hit.rs).

use std::cell::Cell;

#[cfg(target_arch = "x86_64")]
use crate::geom::algebraic::{crossings_lanes, crossings_pair};
use crate::geom::algebraic::{QuadricLanes, LANES};
use crate::geom::Hit;
use crate::math::{has_avx, DVec3, Ray, Slabs};
use crate::scene::csg_hit::{gather_hits, order_entry, order_key};
use crate::scene::csg_members::want_inside;
use crate::scene::desc::CsgOp;
use crate::scene::faces::Faces;
use crate::scene::object::{ObjKind, Object, Scratch};

/// The lanes (`QuadricLanes`) of a node's members when they are two to four plain quadric
/// leaves (no face, clip or window) that `crossings_lanes` answers for; `None` for any other
/// node, or without AVX. Asked once, when the node's index is attached
/// (`children::attach_indexes`, `Cull::quadrics`): per search, it cost a call through each
/// member's table (`as_algebraic`) and the kernel gathered the coefficients lane by lane.
pub(super) fn quadric_lanes_of(children: &[Object], faces: Option<&Faces>) -> Option<QuadricLanes> {
    if !(2..=LANES).contains(&children.len()) || !cfg!(target_arch = "x86_64") || !has_avx() {
        return None;
    }
    let mut q = Vec::with_capacity(LANES);
    for (i, c) in children.iter().enumerate() {
        match &c.kind {
            ObjKind::Shape(shape, None)
                if c.clip.is_empty() && faces.and_then(|f| f.get(i)).is_none() =>
            {
                q.push(shape.as_algebraic()?);
            }
            _ => return None,
        }
    }
    QuadricLanes::of(&q)
}

impl Object {
    /// This node's members in lanes (`Cull::quadrics`), if it has them.
    #[inline(always)]
    pub(super) fn quadric_lanes(&self) -> Option<&QuadricLanes> {
        match &self.kind {
            ObjKind::Csg { cull: Some(c), .. } => c.quadrics.as_deref(),
            _ => None,
        }
    }
}

/// `csg_first_hit`'s gather for the members in lanes (`quadric_lanes_of`): each member's crossings
/// from its lane, pushed as `gather_hits` pushes a leaf's (the shape's `intersect_all` into
/// `s.csg_hits`, an order entry for those below `tmax`), after the same slab tests, in member
/// order; a lane the kernel leaves to the shape goes through `gather_hits` itself.
#[inline(always)]
pub(super) fn gather_quadrics<'a>(
    children: &'a [Object],
    shapes: &QuadricLanes,
    ray: &Ray,
    slabs: &Slabs,
    tmax: f64,
    s: &mut Scratch<'a>,
    keeps: &impl Fn(u32, f64) -> bool,
) {
    let mut rays = [*ray; LANES];
    let mut live = [false; LANES];
    for (j, c) in children.iter().enumerate() {
        live[j] = slabs.hits(&c.bounds, tmax);
        if let Some(t) = &c.transform {
            rays[j] = t.inv_ray(ray);
        }
    }
    if !live.contains(&true) {
        return;
    }
    #[cfg(target_arch = "x86_64")]
    {
        // SAFETY: `quadric_lanes_of` answers only with AVX.
        // Two members in two 128-bit lanes: four would spend half their work on copies.
        let got = unsafe {
            if children.len() == 2 {
                crossings_pair(shapes, [&rays[0], &rays[1]])
            } else {
                crossings_lanes(shapes, [&rays[0], &rays[1], &rays[2], &rays[3]])
            }
        };
        for (j, c) in children.iter().enumerate() {
            if !live[j] {
                continue;
            }
            if got.defer >> j & 1 != 0 {
                gather_hits(c, None, ray, tmax, s, j as u32, keeps);
                continue;
            }
            for r in 0..2 {
                if got.keep[r] >> j & 1 != 0 {
                    let t = got.t[r][j];
                    let k = s.csg_hits.len();
                    s.csg_hits.push(Hit::new(t));
                    if t < tmax {
                        s.csg_order
                            .push(order_entry(order_key(t), (k as u32) << 1, j as u32));
                    }
                }
            }
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = (shapes, rays, s, keeps);
}

/// `csg_keeps(op, i, children, None, faces, p, rejecter)` for the members in lanes
/// (`quadric_lanes_of`): the same questions in the same order (none of them has a face, so
/// each is asked as `member_wants` asks a plain leaf), each shape's `inside` answered by its
/// diagonal form in the lanes, without the dispatch through the shape's table.
#[inline(always)]
pub(super) fn quadric_keeps(
    op: CsgOp,
    i: usize,
    children: &[Object],
    shapes: &QuadricLanes,
    p: DVec3,
    rejecter: &Cell<usize>,
) -> bool {
    if op == CsgOp::Union {
        return true;
    }
    let wants = |j: usize| {
        let c = &children[j];
        let inside = if c.bounds.holds(p) {
            shapes.inside(j, c.local_point(p)) != c.inverse
        } else {
            c.inverse
        };
        inside == want_inside(op, j)
    };
    let r = rejecter.get();
    if r != i && r < children.len() && !wants(r) {
        return false;
    }
    for j in 0..children.len() {
        if j != i && j != r && !wants(j) {
            rejecter.set(j);
            return false;
        }
    }
    true
}

/// `csg_any_hit`'s member loop for the members in lanes (`quadric_lanes_of`): whether `keep(i, t)`
/// holds for a crossing `t < tmax` of a member `i` that passes its slab test, each member's
/// crossings from its lane (a lane the kernel leaves to the shape is asked as `csg_any_hit`
/// asks a leaf: `any_kept`). The same crossings meet the same tests as there, and no test has
/// a side effect on an answer, so the answer is the same.
#[inline(always)]
pub(super) fn any_quadric_kept<'a>(
    children: &'a [Object],
    shapes: &QuadricLanes,
    ray: &Ray,
    slabs: &Slabs,
    tmax: f64,
    s: &mut Scratch<'a>,
    keep: impl Fn(usize, f64) -> bool,
) -> bool {
    let mut rays = [*ray; LANES];
    let mut live = [false; LANES];
    for (j, c) in children.iter().enumerate() {
        live[j] = slabs.hits(&c.bounds, tmax);
        if let Some(t) = &c.transform {
            rays[j] = t.inv_ray(ray);
        }
    }
    if !live.contains(&true) {
        return false;
    }
    #[cfg(target_arch = "x86_64")]
    {
        // SAFETY: `quadric_lanes_of` answers only with AVX.
        // Two members in two 128-bit lanes: four would spend half their work on copies.
        let got = unsafe {
            if children.len() == 2 {
                crossings_pair(shapes, [&rays[0], &rays[1]])
            } else {
                crossings_lanes(shapes, [&rays[0], &rays[1], &rays[2], &rays[3]])
            }
        };
        for j in 0..children.len() {
            if !live[j] {
                continue;
            }
            if got.defer >> j & 1 != 0 {
                // The member's own shape (`quadric_lanes_of` took plain leaves only).
                let ObjKind::Shape(shape, _) = &children[j].kind else {
                    unreachable!("quadric lanes are leaves");
                };
                if shape.any_kept(&rays[j], tmax, &mut s.hits, &mut |t| keep(j, t)) {
                    return true;
                }
                continue;
            }
            for r in 0..2 {
                let t = got.t[r][j];
                if got.keep[r] >> j & 1 != 0 && t < tmax && keep(j, t) {
                    return true;
                }
            }
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = (shapes, s, keep);
    false
}
