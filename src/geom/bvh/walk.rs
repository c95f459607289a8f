//! The BVH's ray walk: a ray's reciprocal direction worked out once (`Recip`), and the
//! iterative nearest-child-first traversal of the packed nodes, by the paired slab test for
//! the rays that allow it and by `Aabb::hit` for the others.

use std::mem::MaybeUninit;

use crate::math::{by_coordinates, DVec3, Ray};

use super::slabs::{Crossing, Plain2, Plain4, Slabs2};
use super::{Bvh, Node, STACK};

/// `1.0 / ray.dir`, each component read on its own. Callers have usually just written the ray
/// (a reflected ray, a shadow ray), often as one double and a pair; reading it back as another
/// split defeats store forwarding and stalls (a tenth of `Scene::first_hit`'s samples sat on
/// that load in mirror_spheres). A volatile read keeps each component an 8-byte load, which
/// forwards from any store holding it.
#[inline]
pub fn ray_recip(ray: &Ray) -> DVec3 {
    Recip::of(ray).inv
}

/// A ray's reciprocal direction (`ray_recip`), and whether the ray is `plain`: a finite origin
/// and finite, nonzero reciprocals, so that no slab distance to a finite box can be NaN and no
/// axis is flat (`Slabs2::new` would give a test with no flat axis). Worked out once per ray and
/// shared by everything along it that tests boxes (a shadow ray's cached blocker and the walk
/// each made their own checks, ~40 instructions a ray).
#[derive(Clone, Copy, Debug)]
pub struct Recip {
    pub inv: DVec3,
    pub plain: bool,
}

impl Recip {
    #[inline(always)]
    pub fn of(ray: &Ray) -> Recip {
        let DVec3 { x, y, z } = by_coordinates(&ray.dir);
        let inv = DVec3::new(1.0 / x, 1.0 / y, 1.0 / z);
        // A component times its reciprocal is within a few ulps of 1 where both are finite and
        // nonzero; a zero, infinite or NaN component or reciprocal makes it NaN or +inf (the
        // two share a sign, and 1/x is never zero for a finite x), and so does a non-finite
        // origin coordinate through `o - o`. No term is -inf, so the sum is below 4 exactly
        // for plain rays, in a dozen instructions where the three tests took ~40.
        let o = ray.origin;
        // `o - o` is meant: zero exactly for a finite coordinate, NaN for any other.
        #[allow(clippy::eq_op)]
        let sum = (x * inv.x + (o.x - o.x)) + (y * inv.y + (o.y - o.y)) + (z * inv.z + (o.z - o.z));
        Recip {
            inv,
            plain: sum < 4.0,
        }
    }
}

/// Which node test a walk may use: `Sse` anywhere, `Avx` (256-bit lanes, `Plain4`) only where
/// the CPU has AVX, which making an `Avx` asserts. A walk is compiled for its caller's target
/// features, so `Avx` pays only inside functions compiled with AVX (`Scene::first_hit`'s and
/// the shadow ray's AVX copies); elsewhere its intrinsics would be calls.
pub trait Lanes: Copy {
    const AVX: bool;
}

/// The x86-64-v2 node test (`Plain2`).
#[derive(Clone, Copy)]
pub struct Sse;

/// The AVX node test (`Plain4`), whose value says the CPU has AVX.
#[derive(Clone, Copy)]
pub struct Avx(());

impl Avx {
    /// # Safety
    /// The CPU must have AVX.
    #[inline(always)]
    pub unsafe fn new() -> Avx {
        Avx(())
    }
}

impl Lanes for Sse {
    const AVX: bool = false;
}

impl Lanes for Avx {
    const AVX: bool = true;
}

impl Bvh {
    /// Visits primitives whose box the ray crosses within (0, tmax), nearest child first. The
    /// callback gets the primitive index and `&mut tmax` (it lowers it after a closer hit,
    /// pruning the rest); returning `true` stops the traversal (any-hit queries).
    #[inline]
    pub fn traverse(&self, ray: &Ray, tmax: f64, f: impl FnMut(usize, &mut f64) -> bool) {
        self.traverse_recip(Sse, ray, &Recip::of(ray), tmax, f);
    }

    /// `traverse` with the ray's `Recip` already worked out. Always inlined: the scene's
    /// nearest-hit and shadow walks are each compiled twice (with and without AVX) around it,
    /// and a call between the copies would cost what they save. `Avx` lanes test plain rays'
    /// nodes in 256-bit lanes (`Plain4`, the same bits as `Plain2`).
    #[inline(always)]
    pub fn traverse_recip<L: Lanes>(
        &self,
        _lanes: L,
        ray: &Ray,
        r: &Recip,
        tmax: f64,
        f: impl FnMut(usize, &mut f64) -> bool,
    ) {
        // A ray built just before the walk (a shadow or reflected ray): `Plain4::new`'s rows
        // read its origin's y-z as one load (10-13 % of `shadow_avx`'s samples on
        // radiosity/cornell and lights/arealit1 before `by_coordinates`).
        let origin = by_coordinates(&ray.origin);
        let inv_dir = r.inv;
        // Nearly every ray: the walk compiled for the paired test without the flat axes' tests,
        // and without the root's own box. The root is then a node, whose two children's boxes
        // the walk tests first, and a ray missing the root's box misses both: every node's box
        // is the exact union of its children's, and without infinite reciprocals the paired
        // test's interval only widens as a box grows (a rounded difference times the same
        // finite reciprocal, then minima and maxima; no NaN). A flat axis breaks that: a box
        // flat in it holding the origin's plane passes, a larger box with the origin on its
        // face does not. Shadow and reflected rays start inside the root's box far more often
        // than camera rays miss it, and the test cost about as much as a node's (unit test
        // `the_root_test_is_implied_by_its_children`).
        if cfg!(target_arch = "x86_64") && r.plain && self.paired {
            if L::AVX {
                // SAFETY: `L` is `Avx`, whose value says the CPU has AVX.
                let s = unsafe { Plain4::new(origin, inv_dir) };
                return self.walk(tmax, f, |n, tmax| unsafe { s.hit_pair(&n.boxes, tmax) });
            }
            let s = Plain2::new(origin, inv_dir);
            return self.walk(tmax, f, |n, tmax| s.hit_pair(&n.boxes, tmax));
        }
        if self.prims.is_empty() {
            return;
        }
        // A tree of one leaf (a CSG node's few members, a scene of one bounded object) has no
        // pair of boxes to test: its root's box, then the leaf. A walk of its own, without
        // the paired test's set-up below, which LLVM worked out ahead of the branch in the AVX
        // copies (~30 instructions of every lights/soft shadow ray).
        if self.nodes.is_empty() {
            if self.root_box.hit(origin, inv_dir, tmax).is_some() {
                self.walk(tmax, f, |_, _| Crossing::of(None, None));
            }
            return;
        }
        let slabs = if self.paired {
            Slabs2::new(origin, inv_dir)
        } else {
            None
        };
        // Rays with a flat axis (and plain rays on other targets) test the root's box: the
        // paired test is not monotonic in the box along a flat axis.
        let root_missed = match &slabs {
            Some(s) => s.hit2(&self.root_box, &self.root_box, tmax).0.is_none(),
            None => self.root_box.hit(origin, inv_dir, tmax).is_none(),
        };
        if root_missed {
            return;
        }
        self.walk(tmax, f, |n, tmax| match &slabs {
            Some(s) => s.hit_pair(&n.boxes, tmax),
            None => Crossing::of(
                n.boxes.get(0).hit(origin, inv_dir, tmax).map(|t| t.0),
                n.boxes.get(1).hit(origin, inv_dir, tmax).map(|t| t.0),
            ),
        });
    }

    /// `traverse_recip`'s walk from the root, each node's pair of boxes tested by `test` (which
    /// of them the ray crosses within tmax, and their entry distances).
    #[inline(always)]
    fn walk(
        &self,
        mut tmax: f64,
        mut f: impl FnMut(usize, &mut f64) -> bool,
        test: impl Fn(&Node, f64) -> Crossing,
    ) {
        // Far children waiting, with their entry distance so they can be skipped once a
        // closer hit has lowered tmax. Left uninitialised: zeroing 2 KB on every traversal
        // (every camera, shadow and mesh ray) cost about a tenth of the render.
        let mut stack = [const { MaybeUninit::<(super::Ref, f64)>::uninit() }; STACK];
        let mut sp = 0;
        let mut at = self.root;
        loop {
            if at.count > 0 {
                let first = at.index as usize;
                // SAFETY: `from_binary` made every leaf's range from the builders' leaves,
                // which lie within `prims`; callers reach here only with primitives.
                let leaf = unsafe { self.prims.get_unchecked(first..first + at.count as usize) };
                for &p in leaf {
                    if f(p as usize, &mut tmax) {
                        return;
                    }
                }
            } else {
                // SAFETY: an interior `Ref` is a slot `from_binary` pushed into `nodes`; the
                // root is one only when `nodes` holds it (a tree with primitives).
                let n = unsafe { self.nodes.get_unchecked(at.index as usize) };
                let c = test(n, tmax);
                // Bit 0: the first child's box is crossed, bit 1: the second's.
                match c.mask {
                    3 => {
                        let (ta, tb) = (c.near[0], c.near[1]);
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
                    1 => {
                        at = n.child[0];
                        continue;
                    }
                    2 => {
                        at = n.child[1];
                        continue;
                    }
                    _ => {}
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
}

#[cfg(test)]
mod tests {
    use std::borrow::Cow;

    use super::super::build::{centroid, clamp_box, Builder};
    use super::super::BinNode;
    use super::*;
    use crate::geom::sphere::Sphere;
    use crate::geom::test_rng::Lcg;
    use crate::geom::Shape;
    use crate::math::Aabb;

    /// `Recip::plain` is `Slabs2::new` giving a test with no flat axis, for directions with
    /// zero, subnormal, tiny, huge, infinite and NaN components and origins with infinite or
    /// NaN coordinates; the reciprocal is `1.0 / dir` to the bit.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn plain_is_slabs_without_a_flat_axis() {
        let specials = [
            0.0,
            -0.0,
            1e-310,
            -4e-320,
            5e-309,
            5.6e-309,
            1e-300,
            -3.0,
            0.7,
            1e300,
            f64::MAX,
            -f64::MAX,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ];
        let mut rng = Lcg(31);
        let (mut plain, mut other) = (0, 0);
        for k in 0..60_000usize {
            let pick = |rng: &mut Lcg| {
                if rng.next() < 0.3 {
                    specials[(rng.next() * specials.len() as f64) as usize % specials.len()]
                } else {
                    (rng.next() - 0.5) * 10f64.powi((rng.next() * 40.0) as i32 - 20)
                }
            };
            let dir = DVec3::new(pick(&mut rng), pick(&mut rng), pick(&mut rng));
            let origin = if k % 3 == 0 {
                DVec3::new(pick(&mut rng), pick(&mut rng), pick(&mut rng))
            } else {
                rng.vec(50.0)
            };
            let ray = Ray::new(origin, dir);
            let r = Recip::of(&ray);
            let inv = DVec3::ONE / dir;
            assert_eq!(
                r.inv.to_array().map(f64::to_bits),
                inv.to_array().map(f64::to_bits)
            );
            let want = Slabs2::new(origin, inv).is_some_and(|s| !s.any_flat());
            assert_eq!(r.plain, want, "k={k} origin={origin:?} dir={dir:?}");
            if want {
                plain += 1;
            } else {
                other += 1;
            }
        }
        assert!(plain > 10_000 && other > 10_000, "{plain} {other}");
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
}
