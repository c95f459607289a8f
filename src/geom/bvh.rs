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

use crate::math::{Aabb, DVec3};

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
/// scalar loads and a shuffle from two nodes apart), then the children themselves. 128
/// bytes (112 and the padding of `Pair`'s 32-byte alignment); half as many nodes as the
/// builders' layout, so about the same memory.
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
    /// The root is a node (so there are pairs of boxes to test) and every node's box is
    /// finite, so a ray with a finite origin and finite, nonzero direction components never
    /// makes a NaN in the paired slab test (`Slabs2`).
    paired: bool,
}

impl Default for Bvh {
    fn default() -> Bvh {
        Bvh {
            nodes: Vec::new(),
            prims: Vec::new(),
            root_box: Aabb::EMPTY,
            root: Ref::default(),
            paired: false,
        }
    }
}

mod build;
mod grid;
mod slabs;
mod walk;

use build::{centroid, clamp_box, Builder};
use slabs::Pair;
pub use walk::{ray_recip, Avx, Lanes, Recip, Sse};

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
        let paired = !nodes.is_empty() && bin.iter().all(|n| n.bounds.is_finite());
        Bvh {
            nodes,
            prims,
            root_box: bin[0].bounds,
            root,
            paired,
        }
    }

    pub fn bounds(&self) -> Aabb {
        if self.prims.is_empty() {
            Aabb::EMPTY
        } else {
            self.root_box
        }
    }

    /// Visits primitives whose box contains `p`, in no particular order; `f` returns `true` to
    /// stop. For point-in-solid queries over many objects.
    pub fn visit_point(&self, p: DVec3, f: impl FnMut(usize) -> bool) {
        self.visit_holding(|b| b.contains(p), f);
    }

    /// Visits primitives whose box grown by `pad` on every side contains `p`, in no
    /// particular order. A parent's box holds its children's, so the grown parent holds the
    /// grown children and nothing within `pad` of a box is missed: a caller whose boxes are
    /// exact only up to rounding asks with a `pad` above that rounding.
    pub fn visit_near(&self, p: DVec3, pad: f64, mut f: impl FnMut(usize)) {
        let near = |b: &Aabb| {
            p.x >= b.min.x - pad
                && p.y >= b.min.y - pad
                && p.z >= b.min.z - pad
                && p.x <= b.max.x + pad
                && p.y <= b.max.y + pad
                && p.z <= b.max.z + pad
        };
        self.visit_holding(near, |i| {
            f(i);
            false
        });
    }

    /// `visit_point`'s and `visit_near`'s walk: the primitives of every leaf whose path of
    /// boxes all `holds`, depth first (the first child's subtree before the second's); `f`
    /// returns `true` to stop.
    #[inline(always)]
    fn visit_holding(&self, holds: impl Fn(&Aabb) -> bool, mut f: impl FnMut(usize) -> bool) {
        if self.prims.is_empty() || !holds(&self.root_box) {
            return;
        }
        // Left uninitialised, as the ray walk's (walk.rs): zeroing its 1 KB was a `memset`
        // call on every query whose point lies in the root box (each fogged camera ray's
        // inside test, each indexed union's `any_at`).
        let mut stack = [const { MaybeUninit::<Ref>::uninit() }; STACK];
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
                let (ina, inb) = (holds(&n.boxes.get(0)), holds(&n.boxes.get(1)));
                if inb && sp < STACK {
                    stack[sp].write(n.child[1]);
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
            // SAFETY: entries below `sp` were all written by the push above, and `sp` only
            // counts down over them.
            at = unsafe { stack[sp].assume_init() };
        }
    }

    /// Whether the tree holds no primitive (none given, or all with empty boxes).
    pub fn is_empty(&self) -> bool {
        self.prims.is_empty()
    }

    /// Renames every primitive `i` to `name(i)`, which the walks and the point query then pass
    /// to their callbacks instead of `i`: the scene names its objects by their index and what
    /// kind of leaf they are, one lookup a leaf fewer than a table from `i` to the object.
    pub fn rename(&mut self, name: impl Fn(u32) -> u32) {
        for p in &mut self.prims {
            *p = name(*p);
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
    use crate::math::Ray;

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
