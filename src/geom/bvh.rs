//! Bounding volume hierarchy over primitives known only by their boxes: mesh triangles here,
//! top-level scene objects in the renderer.
//!
//! Built with a binned surface-area heuristic and stored as a flat depth-first node array (the
//! first child follows its parent, so only the second child's index is stored). Traversal is
//! iterative with a fixed stack, visits the nearer child first and lets the caller shrink the
//! search distance, so a nearest-hit query prunes everything behind the first hit found.

use std::borrow::Cow;
use std::mem::MaybeUninit;

use rayon::prelude::*;

use crate::math::{Aabb, DVec3, Ray, Slabs};

const BINS: usize = 16;
const MAX_LEAF: usize = 4;
/// SAH splits can be lopsided; past this depth splits are at the median, which halves the
/// count each level, so depth stays below `SAH_DEPTH + 32` and the traversal stack suffices.
const SAH_DEPTH: u32 = 64;
const STACK: usize = 128;
/// Infinite or empty boxes are clamped to this for the heuristic only, keeping its arithmetic
/// finite; node bounds keep the real boxes.
const BIG: f64 = 1e30;
/// Cost of visiting an interior node relative to testing one primitive.
const TRAVERSAL_COST: f64 = 1.0;

#[derive(Clone, Copy, Debug)]
struct Node {
    bounds: Aabb,
    /// Leaf: first entry in `Bvh::prims`. Interior: index of the second child.
    index: u32,
    /// Number of primitives in a leaf; 0 for interior nodes.
    count: u32,
}

#[derive(Clone, Debug, Default)]
pub struct Bvh {
    nodes: Vec<Node>,
    prims: Vec<u32>,
    /// Every node's box is finite: the walk takes the paired slab test (`Slabs::hit2`).
    finite: bool,
}

/// `1.0 / ray.dir`, each component read on its own. Callers have usually just written the ray
/// (a reflected ray, a shadow ray), often as one double and a pair; reading it back as another
/// split defeats store forwarding and stalls (a tenth of `Scene::first_hit`'s samples sat on
/// that load in mirror_spheres). A volatile read keeps each component an 8-byte load, which
/// forwards from any store holding it.
#[inline]
pub fn ray_recip(ray: &Ray) -> DVec3 {
    // SAFETY: the pointers come from references to initialised doubles.
    let (x, y, z) = unsafe {
        (
            std::ptr::read_volatile(&ray.dir.x),
            std::ptr::read_volatile(&ray.dir.y),
            std::ptr::read_volatile(&ray.dir.z),
        )
    };
    DVec3::new(1.0 / x, 1.0 / y, 1.0 / z)
}

mod build;

use build::{centroid, clamp_box, Builder};

impl Bvh {
    /// Binned SAH (16 bins), leaves of at most 4 primitives; `bounds[i]` is primitive i's box.
    /// Primitives with empty boxes are never visited. Infinite boxes are accepted, but one makes
    /// every ancestor infinite, so the renderer does better keeping unbounded objects out.
    pub fn build(bounds: &[Aabb]) -> Bvh {
        // Primitives with empty boxes can never be hit; leaving them out also keeps the slab
        // test away from inverted boxes, which it would report as crossed.
        let mut prims: Vec<u32> = (0..bounds.len() as u32)
            .filter(|&i| !bounds[i as usize].is_empty())
            .collect();
        if prims.is_empty() {
            return Bvh::default();
        }
        // The boxes of bounded objects need no clamping; not copying them saves 48 bytes a
        // primitive at the build's peak.
        let needs_clamp = |b: &Aabb| {
            let c = clamp_box(b);
            c.min.to_array().map(f64::to_bits) != b.min.to_array().map(f64::to_bits)
                || c.max.to_array().map(f64::to_bits) != b.max.to_array().map(f64::to_bits)
        };
        let clamped: Cow<[Aabb]> = if bounds.par_iter().any(needs_clamp) {
            Cow::Owned(bounds.par_iter().map(clamp_box).collect())
        } else {
            Cow::Borrowed(bounds)
        };
        let centroids = clamped.par_iter().map(centroid).collect();
        let builder = Builder {
            bounds,
            clamped,
            centroids,
        };
        // At most 2n - 1 nodes; reserving them keeps the build from copying the array as it
        // grows (the pages never written cost no memory).
        let mut nodes = Vec::with_capacity(2 * prims.len());
        builder.subtree(&mut prims, 0, 0, &mut nodes);
        let finite = nodes.iter().all(|n| n.bounds.is_finite());
        Bvh {
            nodes,
            prims,
            finite,
        }
    }

    pub fn bounds(&self) -> Aabb {
        self.nodes.first().map_or(Aabb::EMPTY, |n| n.bounds)
    }

    /// Visits primitives whose box the ray crosses within (0, tmax), nearest child first. The
    /// callback gets the primitive index and `&mut tmax` (it lowers it after a closer hit,
    /// pruning the rest); returning `true` stops the traversal (any-hit queries).
    #[inline]
    pub fn traverse(&self, ray: &Ray, tmax: f64, f: impl FnMut(usize, &mut f64) -> bool) {
        self.traverse_inv(ray, ray_recip(ray), tmax, f);
    }

    /// `traverse` with the ray's reciprocal direction (`ray_recip`) already computed.
    #[inline]
    pub fn traverse_inv(
        &self,
        ray: &Ray,
        inv_dir: DVec3,
        mut tmax: f64,
        mut f: impl FnMut(usize, &mut f64) -> bool,
    ) {
        let Some(root) = self.nodes.first() else {
            return;
        };
        let origin = ray.origin;
        // A tree of one leaf (a CSG node's few members) has no pair of boxes to test; rays that
        // may make NaNs other than along flat axes take `Aabb::hit`.
        let slabs = if self.finite && self.nodes.len() > 1 {
            Some(Slabs::new(origin, inv_dir)).filter(Slabs::paired)
        } else {
            None
        };
        // The root's box by the paired test too where it applies (the same answer): with
        // few objects, `Aabb::hit`'s NaN-aware minima and maxima at the root were a
        // twentieth of a small scene's time.
        let root_missed = match &slabs {
            Some(s) => s.hit2(&root.bounds, &root.bounds, tmax).0.is_none(),
            None => root.bounds.hit(origin, inv_dir, tmax).is_none(),
        };
        if root_missed {
            return;
        }
        // Far children waiting, with their entry distance so they can be skipped once a
        // closer hit has lowered tmax. Left uninitialised: zeroing 2 KB on every traversal
        // (every camera, shadow and mesh ray) cost about a tenth of the render.
        let mut stack = [const { MaybeUninit::<(u32, f64)>::uninit() }; STACK];
        let mut sp = 0;
        let mut node = 0usize;
        loop {
            let n = &self.nodes[node];
            if n.count > 0 {
                let first = n.index as usize;
                for &p in &self.prims[first..first + n.count as usize] {
                    if f(p as usize, &mut tmax) {
                        return;
                    }
                }
            } else {
                let (a, b) = (node + 1, n.index as usize);
                let (ha, hb) = match &slabs {
                    Some(s) => s.hit2(&self.nodes[a].bounds, &self.nodes[b].bounds, tmax),
                    None => (
                        self.nodes[a].bounds.hit(origin, inv_dir, tmax).map(|t| t.0),
                        self.nodes[b].bounds.hit(origin, inv_dir, tmax).map(|t| t.0),
                    ),
                };
                match (ha, hb) {
                    (Some(ta), Some(tb)) => {
                        let (near, far, tfar) = if ta <= tb { (a, b, tb) } else { (b, a, ta) };
                        if sp < STACK {
                            stack[sp].write((far as u32, tfar));
                            sp += 1;
                        }
                        node = near;
                        continue;
                    }
                    (Some(_), None) => {
                        node = a;
                        continue;
                    }
                    (None, Some(_)) => {
                        node = b;
                        continue;
                    }
                    (None, None) => {}
                }
            }
            loop {
                if sp == 0 {
                    return;
                }
                sp -= 1;
                // SAFETY: entries below `sp` were all written by the push above, and `sp` only
                // counts down over them.
                let (next, tnear) = unsafe { stack[sp].assume_init() };
                if tnear <= tmax {
                    node = next as usize;
                    break;
                }
            }
        }
    }

    /// Visits primitives whose box contains `p`, in no particular order; `f` returns `true` to
    /// stop. For point-in-solid queries over many objects.
    pub fn visit_point(&self, p: DVec3, mut f: impl FnMut(usize) -> bool) {
        if self.nodes.is_empty() {
            return;
        }
        let mut stack = [0u32; STACK];
        let mut sp = 0;
        let mut node = 0usize;
        loop {
            let n = &self.nodes[node];
            if n.bounds.contains(p) {
                if n.count > 0 {
                    let first = n.index as usize;
                    for &i in &self.prims[first..first + n.count as usize] {
                        if f(i as usize) {
                            return;
                        }
                    }
                } else {
                    if sp < STACK {
                        stack[sp] = n.index;
                        sp += 1;
                    }
                    node += 1;
                    continue;
                }
            }
            if sp == 0 {
                return;
            }
            sp -= 1;
            node = stack[sp] as usize;
        }
    }

    /// Depth of the tree (1 for a single leaf); for tests and statistics.
    pub fn depth(&self) -> usize {
        fn rec(nodes: &[Node], i: usize) -> usize {
            let n = &nodes[i];
            if n.count > 0 {
                1
            } else {
                1 + rec(nodes, i + 1).max(rec(nodes, n.index as usize))
            }
        }
        if self.nodes.is_empty() {
            0
        } else {
            rec(&self.nodes, 0)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::sphere::Sphere;
    use crate::geom::Shape;

    use crate::geom::test_rng::Lcg;

    fn nearest_brute(spheres: &[Sphere], ray: &Ray) -> Option<(usize, f64)> {
        let mut scratch = Vec::new();
        let mut best: Option<(usize, f64)> = None;
        for (i, s) in spheres.iter().enumerate() {
            if let Some(h) = s.intersect_first(ray, f64::INFINITY, &mut scratch) {
                if best.is_none_or(|b| h.t < b.1) {
                    best = Some((i, h.t));
                }
            }
        }
        best
    }

    fn nearest_bvh(bvh: &Bvh, spheres: &[Sphere], ray: &Ray) -> Option<(usize, f64)> {
        let mut scratch = Vec::new();
        let mut best = None;
        bvh.traverse(ray, f64::INFINITY, |i, tmax| {
            if let Some(h) = spheres[i].intersect_first(ray, *tmax, &mut scratch) {
                *tmax = h.t;
                best = Some((i, h.t));
            }
            false
        });
        best
    }

    #[test]
    fn nearest_hit_matches_brute_force() {
        let mut rng = Lcg(7);
        for &n in &[1usize, 3, 17, 500, 3000] {
            let spheres: Vec<Sphere> = (0..n)
                .map(|_| Sphere::new(rng.vec(20.0), 0.05 + rng.next() * 0.6))
                .collect();
            let bvh = Bvh::build(&spheres.iter().map(|s| s.bounds()).collect::<Vec<_>>());
            assert!(bvh.depth() < 100);
            for _ in 0..2000 {
                let ray = Ray::new(rng.vec(30.0), rng.vec(2.0));
                let a = nearest_brute(&spheres, &ray);
                let b = nearest_bvh(&bvh, &spheres, &ray);
                assert_eq!(a.map(|x| x.0), b.map(|x| x.0), "n={n}");
            }
        }
    }

    #[test]
    fn parallel_build_lays_out_the_serial_tree() {
        let mut rng = Lcg(11);
        let boxes: Vec<Aabb> = (0..3 * build::PARALLEL_MIN)
            .map(|_| Sphere::new(rng.vec(50.0), 0.05 + rng.next()).bounds())
            .collect();
        let bvh = Bvh::build(&boxes);
        let mut prims: Vec<u32> = (0..boxes.len() as u32).collect();
        let builder = Builder {
            bounds: &boxes,
            clamped: Cow::Owned(boxes.iter().map(clamp_box).collect()),
            centroids: boxes.iter().map(clamp_box).map(|b| centroid(&b)).collect(),
        };
        let mut serial = Vec::new();
        builder.node(&mut prims, 0, 0, &mut serial);
        assert_eq!(prims, bvh.prims);
        assert_eq!(serial.len(), bvh.nodes.len());
        for (a, b) in serial.iter().zip(&bvh.nodes) {
            assert_eq!((a.index, a.count), (b.index, b.count));
            assert_eq!((a.bounds.min, a.bounds.max), (b.bounds.min, b.bounds.max));
        }
    }

    #[test]
    fn any_hit_stops_early() {
        let boxes = vec![Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0)); 50];
        let bvh = Bvh::build(&boxes);
        let mut visits = 0;
        bvh.traverse(
            &Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z),
            f64::INFINITY,
            |_, _| {
                visits += 1;
                true
            },
        );
        assert_eq!(visits, 1);
    }

    #[test]
    fn degenerate_inputs() {
        let ray = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
        let empty = Bvh::build(&[]);
        assert!(empty.bounds().is_empty());
        empty.traverse(&ray, f64::INFINITY, |_, _| panic!("no primitives"));

        // Identical boxes: centroids all equal, so the builder must split by position.
        let same = vec![Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0)); 1000];
        let bvh = Bvh::build(&same);
        assert!(bvh.depth() <= 12, "depth {}", bvh.depth());
        let mut seen = vec![false; 1000];
        bvh.traverse(&ray, f64::INFINITY, |i, _| {
            seen[i] = true;
            false
        });
        assert!(seen.iter().all(|&s| s));

        // Infinite, empty and point boxes mixed with normal ones.
        let mixed = vec![
            Aabb::INFINITE,
            Aabb::EMPTY,
            Aabb::new(DVec3::ZERO, DVec3::ZERO),
            Aabb::new(DVec3::new(-1.0, -1.0, 2.0), DVec3::new(1.0, 1.0, 3.0)),
            Aabb::new(DVec3::splat(10.0), DVec3::splat(11.0)),
            Aabb::new(
                DVec3::new(f64::NEG_INFINITY, -1.0, -1.0),
                DVec3::new(0.0, 1.0, 1.0),
            ),
        ];
        let bvh = Bvh::build(&mixed);
        let mut seen = vec![false; mixed.len()];
        bvh.traverse(&ray, f64::INFINITY, |i, _| {
            seen[i] = true;
            false
        });
        assert!(
            seen[0] && seen[3] && seen[5] && !seen[1] && !seen[4],
            "{seen:?}"
        );
    }

    #[test]
    fn collinear_points_and_axis_parallel_rays() {
        let boxes: Vec<Aabb> = (0..100)
            .map(|i| {
                Aabb::new(
                    DVec3::new(i as f64, 0.0, 0.0),
                    DVec3::new(i as f64, 0.0, 0.0),
                )
            })
            .collect();
        let bvh = Bvh::build(&boxes);
        let mut count = 0;
        bvh.traverse(
            &Ray::new(DVec3::new(-1.0, 0.0, 0.0), DVec3::X),
            f64::INFINITY,
            |_, _| {
                count += 1;
                false
            },
        );
        assert_eq!(count, 100);
        let mut count = 0;
        bvh.traverse(
            &Ray::new(DVec3::new(-1.0, 0.0, 0.0), DVec3::X),
            10.5,
            |_, _| {
                count += 1;
                false
            },
        );
        // Leaves are visited whole, so a few primitives beyond tmax may be offered.
        assert!((10..=10 + MAX_LEAF).contains(&count), "{count}");
    }
}
