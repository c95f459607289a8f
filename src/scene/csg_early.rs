//! The nearest kept crossing of a CSG node without an index found without listing every
//! member's crossings first (`Object::csg_first_hit_early`): members are listed in the order
//! the ray may first meet them, and crossings nearer than every member not yet listed are
//! asked as soon as they are known. A kept one is the answer: radiosity_37's walls (a
//! difference of boxes and a folded intersection of cylinders) no longer list the arches'
//! cylinders for a ray that meets a wall before it reaches their bounds.
//!
//! Why the answer is `csg_first_hit`'s, bit for bit:
//! - The same crossings are listed, by the same tests (`Gather::member`, after the same slab
//!   test, `Slabs::entry` being `Slabs::hits` with the entry kept), and each is asked the same
//!   questions (`Object::kept`), which have no side effect on the answer.
//! - `csg_first_hit` answers the first kept crossing in (t as `total_cmp` orders it, place in
//!   its gather), which lists the members in member order, a folded member's leaves in leaf
//!   order, each one's crossings as listed. Here crossings carry the tag member << 16 | leaf
//!   and are ordered by (t, tag, place): the same order, though listed in another.
//! - A member whose bit is set in `Cull::bounded` lists only crossings that lie in its bounds
//!   up to rounding (`crossings_in_bounds`), so none of them (kept or not: a folded member's
//!   leaves' crossings are listed unfiltered, but a leaf's crossing outside the intersection's
//!   bounds lies outside another leaf's bounds, where `inside` says no) is kept before
//!   `least_t` of its slab entry. A crossing whose t lies below the `least_t` of every member
//!   not yet listed therefore comes, in that order, before every kept crossing those members
//!   could add: asked in order among the listed ones, the first kept is the answer. Members
//!   without the bit, or that the ray enters at 0, have `least_t` minus infinity: listed
//!   before anything is asked.
//!
//! The margin: a shape that `Shape::crossings_hug_surface` reports crossings within a few
//! roundings (relative 2^-52 times the coordinates involved, times the condition of its
//! transform) of its surface, so of its world bounds; a point that far outside the bounds on an
//! axis is met at most that distance times that axis' |1 / dir| before the slab entry. The
//! margin, 1e-4 of (entry + the largest coordinate of the origin and bounds times the largest
//! |1 / dir|), is some 10^11 such roundings: a grazing crossing of a sphere of radius r seen
//! from distance d lies about 2^-52 d² / r off its surface, inside the margin while d / r
//! stays below ~10^11.

use std::cell::Cell;

use crate::math::{Aabb, Ray, Slabs};
use crate::scene::csg_hit::{Ask, Gather, LEAF_SHIFT};
use crate::scene::desc::CsgOp;
use crate::scene::faces::{self, Faces};
use crate::scene::object::{ObjKind, Object, Scratch, SurfaceHit};

/// The most members a node searched here may have (the visit order is a stack array).
pub const MAX_EARLY: usize = 16;

/// The margin's share of the distances (module comment).
const MARGIN: f64 = 1e-4;

/// Whether every crossing `o.all_hits` lists lies in `o.bounds`, up to the roundings of a
/// shape whose crossings hug its surface. A leaf: its shape's (a clip only drops crossings,
/// and the bounds are the shape's within the clip's). A difference: its first member's (the
/// bounds are that member's, and a subtracted member's crossing is kept only inside it, which
/// `inside` answers no to outside its bounds). Other nodes: every member's (their bounds are
/// the union or the intersection of the members').
fn crossings_in_bounds(o: &Object) -> bool {
    match &o.kind {
        ObjKind::Shape(shape, _) => shape.crossings_hug_surface(),
        ObjKind::Csg {
            op: CsgOp::Difference,
            children,
            ..
        } => children.first().is_some_and(crossings_in_bounds),
        ObjKind::Csg { children, .. } => children.iter().all(crossings_in_bounds),
    }
}

/// `Cull::bounded` of a node: bit `i` for member `i` with finite bounds that hold its
/// crossings. None for unions (their search is `children::union_first_hit`) or nodes of more
/// than `MAX_EARLY` members.
pub fn bounded_members(op: CsgOp, children: &[Object]) -> u64 {
    if op == CsgOp::Union || children.len() > MAX_EARLY {
        return 0;
    }
    let finite = |b: &Aabb| b.is_finite() && !b.is_empty();
    children
        .iter()
        .enumerate()
        .filter(|(_, c)| finite(&c.bounds) && crossings_in_bounds(c))
        .fold(0, |m, (i, _)| m | 1 << i)
}

/// The least t at which a member whose bounds `b` hold its crossings, entered at `entry`,
/// can list one (module comment); minus infinity when that is not above 0.
#[inline(always)]
fn least_t(entry: f64, b: &Aabb, origin_scale: f64, reach: f64) -> f64 {
    let scale = origin_scale
        .max(b.min.abs().max_element())
        .max(b.max.abs().max_element());
    let least = entry - MARGIN * (entry + scale * reach);
    if least > 0.0 {
        least
    } else {
        f64::NEG_INFINITY
    }
}

/// Sorts crossings by (order key, tag, place): `csg_first_hit`'s order (module comment). Short
/// lists by insertion (they are mostly sorted already: earlier rounds' tails).
#[inline(always)]
fn sort_by_tag(order: &mut [(i64, u32, u32)]) {
    if order.len() > 8 {
        order.sort_unstable_by_key(|e| (e.0, e.2, e.1));
        return;
    }
    for k in 1..order.len() {
        let e = order[k];
        let mut m = k;
        while m > 0 && (order[m - 1].0, order[m - 1].2, order[m - 1].1) > (e.0, e.2, e.1) {
            order[m] = order[m - 1];
            m -= 1;
        }
        order[m] = e;
    }
}

impl Object {
    /// `csg_first_hit` of a node without index whose `Cull::bounded` is not 0: the same
    /// answer (module comment), listing members by their `least_t` and asking the crossings
    /// below the next member's as soon as they are listed.
    #[allow(clippy::too_many_arguments)]
    #[inline(never)]
    pub(super) fn csg_first_hit_early<'a, const FOLD: bool>(
        &'a self,
        op: CsgOp,
        children: &'a [Object],
        (cull, faces): (Option<&Aabb>, Option<&Faces>),
        bounded: u64,
        ray: &Ray,
        tmax: f64,
        s: &mut Scratch<'a>,
    ) -> Option<SurfaceHit<'a>> {
        debug_assert!(children.len() <= MAX_EARLY);
        let inv_dir = ray.dir.recip();
        if cull.is_some_and(|c| c.hit(ray.origin, inv_dir, tmax).is_none()) {
            return None;
        }
        let ray_faces = faces.filter(|_| faces::ray_ok(ray));
        let slabs = Slabs::new(ray.origin, inv_dir);
        let (origin_scale, reach) = (ray.origin.abs().max_element(), inv_dir.abs().max_element());
        // The members `csg_first_hit` lists, by `least_t`, ties in member order.
        let mut visit = [(0.0f64, 0u32); MAX_EARLY];
        let mut n = 0;
        for (i, c) in children.iter().enumerate() {
            let Some(entry) = slabs.entry(&c.bounds, tmax) else {
                continue;
            };
            let least = if entry > 0.0 && bounded >> i & 1 != 0 {
                least_t(entry, &c.bounds, origin_scale, reach)
            } else {
                f64::NEG_INFINITY
            };
            let mut m = n;
            while m > 0 && visit[m - 1].0 > least {
                visit[m] = visit[m - 1];
                m -= 1;
            }
            visit[m] = (least, i as u32);
            n += 1;
        }
        let start = s.surface.len();
        let order_from = s.csg_order.len();
        let the = Gather {
            ray,
            inv_dir,
            slabs: &slabs,
            ray_faces,
            tmax,
        };
        let (rejecter, leaf_rejecter) = (Cell::new(usize::MAX), Cell::new(usize::MAX));
        let ask = Ask {
            op,
            children,
            index: None,
            faces,
            ray,
            rejecter: &rejecter,
            leaf_rejecter: &leaf_rejecter,
        };
        // `s.csg_order[order_from..asked]`: asked, none kept, each before every crossing
        // listed after it.
        let mut asked = order_from;
        let mut best = None;
        'rounds: for r in 0..n {
            let i = visit[r].1;
            the.member(
                &children[i as usize],
                i as usize,
                FOLD,
                |k| i << LEAF_SHIFT | k,
                s,
            );
            let last = r + 1 == n;
            let bound = if last { f64::INFINITY } else { visit[r + 1].0 };
            if !(bound > 0.0) {
                continue;
            }
            sort_by_tag(&mut s.csg_order[asked..]);
            while asked < s.csg_order.len() {
                let (_, j, tag) = s.csg_order[asked];
                let h = &s.surface[j as usize];
                if !(last || h.t < bound) {
                    break;
                }
                asked += 1;
                let (i, k) = (tag >> LEAF_SHIFT, tag & ((1 << LEAF_SHIFT) - 1));
                best = self.kept(&ask, h, i as usize, k as usize);
                if best.is_some() {
                    break 'rounds;
                }
            }
        }
        s.csg_order.truncate(order_from);
        s.surface.truncate(start);
        best
    }
}

#[cfg(test)]
mod tests {
    use super::{bounded_members, sort_by_tag};
    use crate::geom::test_rng::Lcg;
    use crate::math::{DVec3, Ray, EPSILON};
    use crate::scene::object::{ObjKind, Object, Scratch, SurfaceHit};
    use crate::sdl::{ParseOptions, Parser};

    fn built(text: &str) -> crate::scene::build::Scene {
        let mut p = Parser::new(ParseOptions::default());
        p.parse_str("t.pov", text)
            .map_err(|e| e.message.clone())
            .unwrap();
        crate::scene::build::build(&p.scene, 64, 48).scene
    }

    /// The insertion sort gives `sort_unstable_by_key`'s order on (key, tag, place).
    #[test]
    fn sorts_by_key_tag_place() {
        let mut rng = Lcg(7);
        for n in 0..12 {
            for _ in 0..300 {
                let mut a: Vec<(i64, u32, u32)> = (0..n as u32)
                    .map(|j| {
                        let t = (rng.next() * 3.0) as i64;
                        (t, (j * 7 + 3) % 13, (rng.next() * 3.0) as u32)
                    })
                    .collect();
                let mut b = a.clone();
                sort_by_tag(&mut a);
                b.sort_unstable_by_key(|e| (e.0, e.2, e.1));
                assert_eq!(a, b);
            }
        }
    }

    /// Which members may be left for later: shapes with closed-form crossings and nodes of
    /// them, a difference by its first member, nothing unbounded or iterated (a torus).
    #[test]
    fn bounded_members_by_kind() {
        let scene = built(
            r#"
            difference { box { -1, 1 } sphere { 0, 1.2 } torus { 1, 0.2 } plane { y, 0 }
                         intersection { cylinder { -x, x, 0.5 } sphere { 0, 0.8 } }
                         difference { torus { 1, 0.2 } box { -0.5, 0.5 } }
                         difference { box { -0.5, 0.5 } torus { 1, 0.2 } }
                         merge { cone { 0, 1, y, 0.5 } torus { 1, 0.2 } }
                         sphere { 0, 1 inverse } }
            union { box { -1, 1 } sphere { 0, 2 } }
            "#,
        );
        let masks: Vec<u64> = scene
            .objects
            .iter()
            .map(|o| match &o.kind {
                ObjKind::Csg { op, children, .. } => bounded_members(*op, children),
                ObjKind::Shape(..) => u64::MAX,
            })
            .collect();
        assert_eq!(masks, [0b0101_0011, 0]);
    }

    /// Nearest kept crossing as `all_hits` defines it (the earliest listed of equal ones).
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

    /// The search answers as `all_hits` and as the search that lists every member do, bit
    /// for bit, with the same surface and side: radiosity_37's walls, differences and
    /// intersections of boxes, spheres, cylinders and cones with coincident faces (ties
    /// between members), folded and clipped members, rotated, scaled from 1e-3 to 1e3 and
    /// moved far out. Rays from far and near, along axes through lattice points, from a
    /// crossing of an earlier ray, and with short `tmax`.
    #[test]
    fn early_search_matches_all_hits() {
        const SCENE: &str = r#"
            #declare Walls = difference {
              box { <-10, -0.1, -10>, <10, 4, 10> }
              box { < -9,  0.3,  -9>, < 9, 3.5,  9> }
              box { < -4,  0.1,  -4>, < 4, 5,  4> }
              intersection {
                merge {
                  cylinder { <0, 0.3, 0>, <0, 0.3, 12>, 2 }
                  cylinder { <0, 0.3, 0>, <0, 0.3, 12>, 2 rotate 180*y }
                  cylinder { <0, 0.3, 0>, <0, 0.3, 12>, 2 rotate  90*y }
                  cylinder { <0, 0.3, 0>, <0, 0.3, 12>, 2 rotate -90*y }
                }
                plane { y, 0.3 inverse }
              }
              scale 0.2
            }
            object { Walls }
            difference { box { -1, 1 } box { <-1, -0.5, -0.5>, <1, 0.5, 0.5> }
                         box { <0.5, -1, -1>, <1, 1, 1> } sphere { <0, 1, 0>, 0.5 } }
            difference { box { -1, 1 } #for (i, 0, 7) box { <-1, -1, i / 4 - 1>, <1, -0.5, i / 4 - 0.9> } #end
                         rotate <10, 20, 30> }
            intersection { box { -1, 1 } cylinder { -x, x, 1 } cylinder { -z, z, 1 } sphere { 0, 1.2 }
                           scale <1, 0.2, 1> }
            difference { sphere { 0, 1 } cone { -y, 0.5, y, 0 } cylinder { -x * 2, x * 2, 0.3 }
                         intersection { box { -2, 2 } sphere { x, 0.8 } } scale 1e-3 translate 1e3 }
            merge { sphere { 0, 1 } sphere { x, 1 } box { <-0.5, -2, -0.5>, <0.5, 2, 0.5> } scale 1e3 }
            difference { box { -1, 1 } sphere { 0, 1.2 clipped_by { plane { y, 0.5 } } }
                         difference { box { -0.5, 0.5 } sphere { 0, 0.3 } } clipped_by { plane { x, 0.8 } }
                         translate <1e5, 0, -1e5> }
            difference { box { -1, 1 } torus { 1, 0.3 } box { -0.5, 0.5 } inverse }
        "#;
        let scene = built(SCENE);
        let mut without = built(SCENE);
        for o in &mut without.objects {
            if let ObjKind::Csg { cull: Some(c), .. } = &mut o.kind {
                assert_ne!(c.bounded, 0);
                c.bounded = 0;
            }
        }
        let big = if cfg!(debug_assertions) { 3000 } else { 40_000 };
        let mut rng = Lcg(23);
        let (mut sa, mut sb, mut sc) = (Scratch::default(), Scratch::default(), Scratch::default());
        let key = |h: Option<SurfaceHit>| {
            h.map(|h| (h.t.to_bits(), h.flip, h.obj as *const Object, h.hit.part))
        };
        for (n, (o, w)) in scene.objects.iter().zip(&without.objects).enumerate() {
            let b = o.bounds;
            let (lo, hi) = if b.min.is_finite() && b.max.is_finite() {
                (b.min, b.max)
            } else {
                (DVec3::splat(-2.0), DVec3::splat(2.0))
            };
            let (centre, size) = ((lo + hi) * 0.5, (hi - lo).max_element());
            let mut on_surface = None;
            let mut hits = 0;
            for k in 0..big {
                let ray = match k % 5 {
                    0 => {
                        let q = (rng.vec(2.0) * 4.0).round() / 4.0;
                        let axis = [DVec3::X, DVec3::Y, DVec3::Z, -DVec3::X][k % 4];
                        Ray::new(centre + q * size * 0.5, axis)
                    }
                    1 if on_surface.is_some() => Ray::new(on_surface.unwrap(), rng.vec(1.0)),
                    _ => {
                        let target = centre + rng.vec(size * 0.6);
                        let from = centre + rng.vec(size * [0.5, 2.0, 50.0][k % 3]);
                        Ray::new(from, (target - from) * [1.0, 1e-3, 1e3][k % 3])
                    }
                };
                let tmax = match k % 7 {
                    0 => 1.5,
                    1 => -1.0,
                    _ => f64::INFINITY,
                };
                // Each scene against its own `all_hits` (the surfaces are each scene's own).
                let without_early = key(w.first_hit(&ray, tmax, &mut sb));
                assert_eq!(without_early, key(reference(w, &ray, tmax, &mut sc)));
                let want = key(reference(o, &ray, tmax, &mut sc));
                let got = o.first_hit(&ray, tmax, &mut sa);
                let bits = |k: Option<(u64, bool, *const Object, u32)>| k.map(|k| (k.0, k.1, k.3));
                assert_eq!(bits(key(got)), bits(without_early), "object {n}, ray {k}");
                assert_eq!(key(got), want, "object {n}, ray {k}");
                assert!(sa.surface.is_empty() && sa.csg_order.is_empty());
                if let Some(h) = got {
                    hits += 1;
                    on_surface = Some(ray.at(h.t));
                }
            }
            assert!(hits > big / 20, "object {n}: {hits}");
        }
    }
}
