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
    /// Every node's box is finite, so a ray with a finite origin and finite, nonzero
    /// direction components never makes a NaN in the slab test (`Slabs2`).
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

/// The slab test of two boxes at once, one per SSE lane, for a ray whose slab distances cannot
/// be NaN except along its `flat` axes (computed apart). Each lane does `Aabb::hit`'s
/// operations in its order; without NaNs the minimum and maximum instructions give
/// `f64::min`'s and `f64::max`'s values (up to the sign of a zero, which no comparison sees),
/// so the answers and the entry distances are `Aabb::hit`'s bit for bit (unit tests
/// `paired_slabs_match_aabb_hit` and `..._for_flat_rays`). `Aabb::hit` spends a third of its
/// work on the NaN handling of `f64::min`.
#[cfg(target_arch = "x86_64")]
struct Slabs2 {
    origin: [std::arch::x86_64::__m128d; 3],
    inv_dir: [std::arch::x86_64::__m128d; 3],
    /// Axes whose reciprocal direction is infinite (a direction component of ±0, as every
    /// ray of an axis-aligned orthographic or cylinder camera has): their slab distances can
    /// be NaN (0·∞ where the origin lies on a box's face), so they are computed as `Aabb::hit`
    /// computes them, NaN-aware, one box at a time (`flat_axis`).
    flat: [bool; 3],
    origin_s: DVec3,
    inv_s: DVec3,
}

#[cfg(target_arch = "x86_64")]
impl Slabs2 {
    /// None for a non-finite origin or a NaN direction: such rays take `Aabb::hit`. Axes of
    /// infinite reciprocal direction are `flat`.
    #[inline]
    fn new(origin: DVec3, inv_dir: DVec3) -> Option<Slabs2> {
        use std::arch::x86_64::_mm_set1_pd;
        if !origin.is_finite() || inv_dir.is_nan_mask().any() || inv_dir.cmpeq(DVec3::ZERO).any() {
            return None;
        }
        // SAFETY: SSE2 is part of x86_64.
        unsafe {
            Some(Slabs2 {
                origin: [
                    _mm_set1_pd(origin.x),
                    _mm_set1_pd(origin.y),
                    _mm_set1_pd(origin.z),
                ],
                inv_dir: [
                    _mm_set1_pd(inv_dir.x),
                    _mm_set1_pd(inv_dir.y),
                    _mm_set1_pd(inv_dir.z),
                ],
                flat: [
                    inv_dir.x.is_infinite(),
                    inv_dir.y.is_infinite(),
                    inv_dir.z.is_infinite(),
                ],
                origin_s: origin,
                inv_s: inv_dir,
            })
        }
    }

    /// A flat axis's (near, far) slab distances for one box, as `Aabb::hit` has them: its
    /// `f64::min` and `f64::max` of the two distances, which ignore a NaN. Both NaN (a box
    /// flat in this axis with the origin in its plane) gives (−∞, +∞), which the reductions
    /// that follow treat as `f64::max` and `f64::min` treat the NaNs: as absent.
    #[inline]
    fn flat_axis(&self, k: usize, lo: f64, hi: f64) -> (f64, f64) {
        let (o, inv) = (self.origin_s[k], self.inv_s[k]);
        let (t0, t1) = ((lo - o) * inv, (hi - o) * inv);
        let (near, far) = (t0.min(t1), t0.max(t1));
        if near.is_nan() {
            (f64::NEG_INFINITY, f64::INFINITY)
        } else {
            (near, far)
        }
    }

    /// `Aabb::hit` of `a` and of `b` within (0, tmax): the entry distances of those crossed.
    #[inline]
    fn hit2(&self, a: &Aabb, b: &Aabb, tmax: f64) -> (Option<f64>, Option<f64>) {
        use std::arch::x86_64::*;
        // SAFETY: SSE2 is part of x86_64; the stores write two doubles into a two-double array.
        unsafe {
            let axis = |k: usize, lo_a: f64, lo_b: f64, hi_a: f64, hi_b: f64| {
                if self.flat[k] {
                    let (na, fa) = self.flat_axis(k, lo_a, hi_a);
                    let (nb, fb) = self.flat_axis(k, lo_b, hi_b);
                    return (_mm_set_pd(nb, na), _mm_set_pd(fb, fa));
                }
                let t0 = _mm_mul_pd(
                    _mm_sub_pd(_mm_set_pd(lo_b, lo_a), self.origin[k]),
                    self.inv_dir[k],
                );
                let t1 = _mm_mul_pd(
                    _mm_sub_pd(_mm_set_pd(hi_b, hi_a), self.origin[k]),
                    self.inv_dir[k],
                );
                (_mm_min_pd(t0, t1), _mm_max_pd(t0, t1))
            };
            let (nx, fx) = axis(0, a.min.x, b.min.x, a.max.x, b.max.x);
            let (ny, fy) = axis(1, a.min.y, b.min.y, a.max.y, b.max.y);
            let (nz, fz) = axis(2, a.min.z, b.min.z, a.max.z, b.max.z);
            // max_element is x.max(y.max(z)), then .max(0.0); likewise for the far side.
            let near = _mm_max_pd(_mm_max_pd(nx, _mm_max_pd(ny, nz)), _mm_setzero_pd());
            let far = _mm_min_pd(_mm_min_pd(fx, _mm_min_pd(fy, fz)), _mm_set1_pd(tmax));
            let mask = _mm_movemask_pd(_mm_cmple_pd(near, far));
            let mut t = [0.0f64; 2];
            _mm_storeu_pd(t.as_mut_ptr(), near);
            (
                (mask & 1 != 0).then_some(t[0]),
                (mask & 2 != 0).then_some(t[1]),
            )
        }
    }
}

/// Other targets take `Aabb::hit` for every ray.
#[cfg(not(target_arch = "x86_64"))]
struct Slabs2;

#[cfg(not(target_arch = "x86_64"))]
impl Slabs2 {
    fn new(_: DVec3, _: DVec3) -> Option<Slabs2> {
        None
    }
    fn hit2(&self, _: &Aabb, _: &Aabb, _: f64) -> (Option<f64>, Option<f64>) {
        unreachable!()
    }
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
        // A tree of one leaf (a CSG node's few members) has no pair of boxes to test.
        let slabs = if self.finite && self.nodes.len() > 1 {
            Slabs2::new(origin, inv_dir)
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
