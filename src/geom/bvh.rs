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

use crate::math::{Aabb, DVec3, Ray};

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

/// A node as the builders lay it out: its own box, the first child right after it.
#[derive(Clone, Copy, Debug)]
struct BinNode {
    bounds: Aabb,
    /// Leaf: first entry in `Bvh::prims`. Interior: index of the second child.
    index: u32,
    /// Number of primitives in a leaf; 0 for interior nodes.
    count: u32,
}

/// A child as its parent refers to it: an interior node (`count` 0, `index` into
/// `Bvh::nodes`) or a leaf (`count` primitives from `Bvh::prims[index]`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Ref {
    index: u32,
    count: u32,
}

/// An interior node as the walk reads it: both children's boxes side by side (one aligned
/// load per axis and side for the paired slab test, where the builders' layout needed two
/// scalar loads and a shuffle from two nodes apart), then the children themselves. 112
/// bytes; half as many nodes as the builders' layout, so the same memory.
#[derive(Clone, Copy, Debug)]
#[repr(C)]
struct Node {
    boxes: Pair,
    child: [Ref; 2],
}

#[derive(Clone, Debug)]
pub struct Bvh {
    /// Interior nodes in depth-first order (the first child's subtree right after its
    /// parent); empty when the root is a leaf.
    nodes: Vec<Node>,
    prims: Vec<u32>,
    /// The root's box and the root itself (a leaf of no primitives when there are none).
    root_box: Aabb,
    root: Ref,
    /// Every node's box is finite, so a ray with a finite origin and finite, nonzero
    /// direction components never makes a NaN in the slab test (`Slabs2`).
    finite: bool,
}

impl Default for Bvh {
    fn default() -> Bvh {
        Bvh {
            nodes: Vec::new(),
            prims: Vec::new(),
            root_box: Aabb::EMPTY,
            root: Ref::default(),
            finite: false,
        }
    }
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
mod grid;
mod slabs;

use build::{centroid, clamp_box, Builder};
use slabs::{Pair, Slabs2};

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
        Bvh::from_binary(&nodes, prims)
    }

    /// The walk's layout of a tree the builders laid out as `bin` (non-empty) over `prims`.
    fn from_binary(bin: &[BinNode], prims: Vec<u32>) -> Bvh {
        // Interior nodes in `bin`'s order, so the walk meets them in the same order of
        // memory; a node's slot is taken before its children's.
        fn pack(bin: &[BinNode], i: usize, out: &mut Vec<Node>) -> Ref {
            let n = &bin[i];
            if n.count > 0 {
                return Ref {
                    index: n.index,
                    count: n.count,
                };
            }
            let (a, b) = (i + 1, n.index as usize);
            let slot = out.len();
            out.push(Node {
                boxes: Pair::of(&bin[a].bounds, &bin[b].bounds),
                child: [Ref::default(); 2],
            });
            let ra = pack(bin, a, out);
            let rb = pack(bin, b, out);
            out[slot].child = [ra, rb];
            Ref {
                index: slot as u32,
                count: 0,
            }
        }
        let mut nodes = Vec::with_capacity(bin.len() / 2);
        let root = pack(bin, 0, &mut nodes);
        Bvh {
            nodes,
            prims,
            root_box: bin[0].bounds,
            root,
            finite: bin.iter().all(|n| n.bounds.is_finite()),
        }
    }

    pub fn bounds(&self) -> Aabb {
        if self.prims.is_empty() {
            Aabb::EMPTY
        } else {
            self.root_box
        }
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
        tmax: f64,
        f: impl FnMut(usize, &mut f64) -> bool,
    ) {
        if self.prims.is_empty() {
            return;
        }
        let origin = ray.origin;
        // A tree of one leaf (a CSG node's few members) has no pair of boxes to test.
        let slabs = if self.finite && !self.nodes.is_empty() {
            Slabs2::new(origin, inv_dir)
        } else {
            None
        };
        // With the paired test and no flat axis the root's own box is not tested: the root
        // is then a node, whose two children's boxes the loop below tests first, and a ray
        // missing the root's box misses both. Every node's box is the exact union of its
        // children's, and without infinite reciprocals the paired test's interval only
        // widens as a box grows (a rounded difference times the same finite reciprocal, then
        // minima and maxima; no NaN). A flat axis breaks that: a box flat in it holding the
        // origin's plane passes, a larger box with the origin on its face does not. Shadow
        // and reflected rays start inside the root's box far more often than camera rays miss
        // it, and the test cost about as much as a node's (unit test
        // `the_root_test_is_implied_by_its_children`).
        let test_general = |n: &Node, tmax: f64| match &slabs {
            Some(s) => s.hit_pair(&n.boxes, tmax),
            None => (
                n.boxes.get(0).hit(origin, inv_dir, tmax).map(|t| t.0),
                n.boxes.get(1).hit(origin, inv_dir, tmax).map(|t| t.0),
            ),
        };
        let root_missed = match &slabs {
            Some(s) if !s.any_flat() => {
                // Nearly every ray: the walk compiled for it, without the flat axes' tests.
                return self.walk(tmax, f, |n, tmax| s.hit_pair_unflat(&n.boxes, tmax));
            }
            Some(s) => s.hit2(&self.root_box, &self.root_box, tmax).0.is_none(),
            None => self.root_box.hit(origin, inv_dir, tmax).is_none(),
        };
        if root_missed {
            return;
        }
        self.walk(tmax, f, test_general);
    }

    /// `traverse_inv`'s walk from the root, each node's pair of boxes tested by `test` (the
    /// entry distances of those the ray crosses within tmax).
    #[inline(always)]
    fn walk(
        &self,
        mut tmax: f64,
        mut f: impl FnMut(usize, &mut f64) -> bool,
        test: impl Fn(&Node, f64) -> (Option<f64>, Option<f64>),
    ) {
        // Far children waiting, with their entry distance so they can be skipped once a
        // closer hit has lowered tmax. Left uninitialised: zeroing 2 KB on every traversal
        // (every camera, shadow and mesh ray) cost about a tenth of the render.
        let mut stack = [const { MaybeUninit::<(Ref, f64)>::uninit() }; STACK];
        let mut sp = 0;
        let mut at = self.root;
        loop {
            if at.count > 0 {
                let first = at.index as usize;
                for &p in &self.prims[first..first + at.count as usize] {
                    if f(p as usize, &mut tmax) {
                        return;
                    }
                }
            } else {
                let n = &self.nodes[at.index as usize];
                match test(n, tmax) {
                    (Some(ta), Some(tb)) => {
                        let (near, far, tfar) = if ta <= tb {
                            (n.child[0], n.child[1], tb)
                        } else {
                            (n.child[1], n.child[0], ta)
                        };
                        if sp < STACK {
                            stack[sp].write((far, tfar));
                            sp += 1;
                        }
                        at = near;
                        continue;
                    }
                    (Some(_), None) => {
                        at = n.child[0];
                        continue;
                    }
                    (None, Some(_)) => {
                        at = n.child[1];
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
                    at = next;
                    break;
                }
            }
        }
    }

    /// Visits primitives whose box contains `p`, in no particular order; `f` returns `true` to
    /// stop. For point-in-solid queries over many objects.
    pub fn visit_point(&self, p: DVec3, mut f: impl FnMut(usize) -> bool) {
        if self.prims.is_empty() || !self.root_box.contains(p) {
            return;
        }
        // Depth first, the first child's subtree before the second's.
        let mut stack = [Ref::default(); STACK];
        let mut sp = 0;
        let mut at = self.root;
        loop {
            if at.count > 0 {
                let first = at.index as usize;
                for &i in &self.prims[first..first + at.count as usize] {
                    if f(i as usize) {
                        return;
                    }
                }
            } else {
                let n = &self.nodes[at.index as usize];
                let (ina, inb) = (n.boxes.get(0).contains(p), n.boxes.get(1).contains(p));
                if inb && sp < STACK {
                    stack[sp] = n.child[1];
                    sp += 1;
                }
                if ina {
                    at = n.child[0];
                    continue;
                }
            }
            if sp == 0 {
                return;
            }
            sp -= 1;
            at = stack[sp];
        }
    }

    /// Depth of the tree (1 for a single leaf); for tests and statistics.
    pub fn depth(&self) -> usize {
        fn rec(nodes: &[Node], r: Ref) -> usize {
            if r.count > 0 {
                1
            } else {
                let n = &nodes[r.index as usize];
                1 + rec(nodes, n.child[0]).max(rec(nodes, n.child[1]))
            }
        }
        if self.prims.is_empty() {
            0
        } else {
            rec(&self.nodes, self.root)
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
        let serial = Bvh::from_binary(&serial, prims);
        assert_eq!(serial.root, bvh.root);
        assert_eq!(serial.nodes.len(), bvh.nodes.len());
        for (a, b) in serial.nodes.iter().zip(&bvh.nodes) {
            assert_eq!(a.child, b.child);
            for k in 0..2 {
                let (x, y) = (a.boxes.get(k), b.boxes.get(k));
                assert_eq!((x.min, x.max), (y.min, y.max));
            }
        }
    }

    /// The walk over the builders' layout, one node's box at a time by `Aabb::hit`, as it
    /// was before nodes held their children's boxes: the reference for the visiting order.
    fn walk_binary(bin: &[BinNode], prims: &[u32], ray: &Ray, tmax: f64, out: &mut Vec<u32>) {
        let inv = ray_recip(ray);
        let mut tmax = tmax;
        let mut lower = |p: u32, tmax: &mut f64| {
            out.push(p);
            // Every third primitive "hits" at its place along the ray, pruning as a
            // nearest-hit query does.
            if p.is_multiple_of(3) {
                *tmax = tmax.min(1.0 + p as f64 * 0.01);
            }
        };
        if bin[0].bounds.hit(ray.origin, inv, tmax).is_none() {
            return;
        }
        let mut stack = Vec::new();
        let mut node = 0usize;
        loop {
            let n = &bin[node];
            if n.count > 0 {
                let first = n.index as usize;
                for &p in &prims[first..first + n.count as usize] {
                    lower(p, &mut tmax);
                }
            } else {
                let (a, b) = (node + 1, n.index as usize);
                let ha = bin[a].bounds.hit(ray.origin, inv, tmax).map(|t| t.0);
                let hb = bin[b].bounds.hit(ray.origin, inv, tmax).map(|t| t.0);
                match (ha, hb) {
                    (Some(ta), Some(tb)) => {
                        let (near, far, tfar) = if ta <= tb { (a, b, tb) } else { (b, a, ta) };
                        stack.push((far, tfar));
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
                let Some((next, tnear)) = stack.pop() else {
                    return;
                };
                if tnear <= tmax {
                    node = next;
                    break;
                }
            }
        }
    }

    /// The walk over nodes holding their children's boxes offers the same primitives in the
    /// same order as the walk over the builders' layout, with the caller lowering `tmax`:
    /// ordinary, axis-parallel (±0 direction components) and grazing rays, rays from box
    /// corners, and a tree of one leaf.
    #[test]
    fn packed_walk_keeps_the_binary_order() {
        let mut rng = Lcg(23);
        let grid = |rng: &mut Lcg| (rng.next() * 16.0).floor() - 8.0;
        for n in [1usize, 2, 3, 5, 40, 700] {
            let boxes: Vec<Aabb> = (0..n)
                .map(|k| {
                    if k % 4 == 0 {
                        let a = DVec3::new(grid(&mut rng), grid(&mut rng), grid(&mut rng));
                        Aabb::new(a, a + DVec3::new(1.0, 0.0, 2.0))
                    } else {
                        Sphere::new(rng.vec(8.0), 0.1 + rng.next()).bounds()
                    }
                })
                .collect();
            let mut prims: Vec<u32> = (0..n as u32).collect();
            let builder = Builder {
                bounds: &boxes,
                clamped: Cow::Owned(boxes.iter().map(clamp_box).collect()),
                centroids: boxes.iter().map(clamp_box).map(|b| centroid(&b)).collect(),
            };
            let mut bin = Vec::new();
            builder.node(&mut prims, 0, 0, &mut bin);
            let bvh = Bvh::from_binary(&bin, prims.clone());
            let (mut want, mut got) = (Vec::new(), Vec::new());
            for k in 0..4000usize {
                let origin = if k % 5 == 0 {
                    DVec3::new(grid(&mut rng), grid(&mut rng), grid(&mut rng))
                } else {
                    rng.vec(12.0)
                };
                let mut dir = rng.vec(2.0);
                match k % 6 {
                    0 => dir.x = 0.0,
                    1 => (dir.y, dir.z) = (-0.0, 0.0),
                    2 => dir = DVec3::new(0.0, 0.0, -1.0),
                    _ => {}
                }
                let ray = Ray::new(origin, dir);
                let tmax = if k % 3 == 0 {
                    f64::INFINITY
                } else {
                    4.0 + rng.next() * 20.0
                };
                want.clear();
                got.clear();
                walk_binary(&bin, &prims, &ray, tmax, &mut want);
                bvh.traverse(&ray, tmax, |p, t| {
                    got.push(p as u32);
                    if p.is_multiple_of(3) {
                        *t = t.min(1.0 + p as f64 * 0.01);
                    }
                    false
                });
                assert_eq!(want, got, "n={n} k={k}");
                // The point query: the same primitives in the same order as a depth-first
                // walk of the builders' nodes.
                let p = origin + dir * 0.5;
                let mut by_tree = Vec::new();
                bvh.visit_point(p, |i| {
                    by_tree.push(i);
                    false
                });
                let mut by_list = Vec::new();
                let mut st = vec![0usize];
                while let Some(i) = st.pop() {
                    let b = &bin[i];
                    if !b.bounds.contains(p) {
                        continue;
                    }
                    if b.count > 0 {
                        let first = b.index as usize;
                        by_list.extend(
                            prims[first..first + b.count as usize]
                                .iter()
                                .map(|&q| q as usize),
                        );
                    } else {
                        st.push(b.index as usize);
                        st.push(i + 1);
                    }
                }
                assert_eq!(by_tree, by_list, "n={n} k={k}");
            }
        }
    }

    /// The paired test's entry distance `h` against `Aabb::hit`'s answer `e` for ray `k`: the
    /// same hit or miss, and the same bits of the entry except for the sign of a zero.
    fn same_entry(h: Option<f64>, e: Option<(f64, f64)>, k: usize) {
        let e = e.map(|t| t.0);
        assert_eq!(h.map(|t| t == 0.0), e.map(|t| t == 0.0), "{k}");
        assert_eq!(
            h.filter(|t| *t != 0.0).map(f64::to_bits),
            e.filter(|t| *t != 0.0).map(f64::to_bits),
            "{k}"
        );
    }

    #[cfg(target_arch = "x86_64")]
    #[test]
    fn paired_slabs_match_aabb_hit() {
        let mut rng = Lcg(5);
        let mut boxes: Vec<Aabb> = (0..64)
            .map(|_| {
                let (a, b) = (rng.vec(10.0), rng.vec(10.0));
                Aabb::new(a.min(b), a.max(b))
            })
            .collect();
        // Flat boxes, a point box, and boxes the rays start on or inside.
        boxes.push(Aabb::new(
            DVec3::new(-1.0, 0.0, -1.0),
            DVec3::new(1.0, 0.0, 1.0),
        ));
        boxes.push(Aabb::new(DVec3::splat(0.5), DVec3::splat(0.5)));
        boxes.push(Aabb::new(DVec3::splat(-20.0), DVec3::splat(20.0)));
        let mut checked = 0;
        for k in 0..4000 {
            let origin = if k % 7 == 0 {
                DVec3::ZERO
            } else {
                rng.vec(15.0)
            };
            let dir = rng.vec(2.0);
            let inv_dir = DVec3::ONE / dir;
            let Some(s) = Slabs2::new(origin, inv_dir) else {
                continue;
            };
            let tmax = if k % 3 == 0 {
                f64::INFINITY
            } else {
                rng.next() * 30.0
            };
            let (a, b) = (&boxes[k % boxes.len()], &boxes[(k * 7 + 3) % boxes.len()]);
            let (ha, hb) = s.hit2(a, b, tmax);
            same_entry(ha, a.hit(origin, inv_dir, tmax), k);
            same_entry(hb, b.hit(origin, inv_dir, tmax), k);
            checked += 1;
        }
        assert!(checked > 3000);
        assert!(Slabs2::new(DVec3::splat(f64::INFINITY), DVec3::ONE).is_none());
        assert!(Slabs2::new(DVec3::ZERO, DVec3::splat(f64::NAN)).is_none());
    }

    /// Rays with direction components of ±0 (infinite reciprocals) whose origins lie inside,
    /// outside and exactly on the boxes' faces, where `Aabb::hit` meets 0·∞ = NaN: the paired
    /// test gives its answers and entry distances bit for bit.
    #[test]
    fn paired_slabs_match_aabb_hit_for_flat_rays() {
        let mut rng = Lcg(11);
        // Whole-number corners, so that origins picked on the same grid land on faces.
        let grid = |rng: &mut Lcg| (rng.next() * 8.0).floor() - 4.0;
        let mut boxes = Vec::new();
        for _ in 0..48 {
            let a = DVec3::new(grid(&mut rng), grid(&mut rng), grid(&mut rng));
            let b = DVec3::new(grid(&mut rng), grid(&mut rng), grid(&mut rng));
            boxes.push(Aabb::new(a.min(b), a.max(b)));
        }
        let zeros = [0.0, -0.0];
        let mut checked = 0;
        for k in 0..20_000usize {
            let origin = DVec3::new(grid(&mut rng), grid(&mut rng), grid(&mut rng))
                + if k % 2 == 0 {
                    DVec3::ZERO
                } else {
                    rng.vec(0.5)
                };
            let mut dir = rng.vec(2.0);
            // One or two components zero (of either sign); sometimes a subnormal one, whose
            // reciprocal overflows to infinity.
            let z = zeros[k % 2];
            match k % 7 {
                0 => dir.x = z,
                1 => dir.y = z,
                2 => dir.z = z,
                3 => (dir.x, dir.y) = (z, -z),
                4 => (dir.y, dir.z) = (z, z),
                5 => dir.x = 1e-310,
                _ => (dir.x, dir.z) = (-z, z),
            }
            let inv_dir = DVec3::ONE / dir;
            let s = Slabs2::new(origin, inv_dir).expect("flat rays take the paired test");
            let tmax = if k % 3 == 0 {
                f64::INFINITY
            } else {
                rng.next() * 30.0
            };
            let (a, b) = (&boxes[k % boxes.len()], &boxes[(k * 7 + 3) % boxes.len()]);
            let (ha, hb) = s.hit2(a, b, tmax);
            same_entry(ha, a.hit(origin, inv_dir, tmax), k);
            same_entry(hb, b.hit(origin, inv_dir, tmax), k);
            checked += 1;
        }
        assert_eq!(checked, 20_000);
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
