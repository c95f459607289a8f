//! A 4-wide copy of a `Bvh`'s tree with single-precision boxes, tested four at a time with
//! SSE, for queries whose answer does not depend on the order primitives are offered in (the
//! scene's nearest hit with its explicit tie rule, a union index's queries).
//!
//! The boxes are the binary tree's, rounded outward to f32, and the ray's slab distances are
//! widened by a bound on every rounding the f32 arithmetic makes (relative, and absolute for
//! the origin's and the boxes' rounding), so the test never rejects a box the f64 slab test of
//! the binary walk (`Aabb::hit`) accepts within (0, tmax]: the wide walk offers every
//! primitive the binary walk offers, perhaps a few more, and in another order. Rays the bound
//! does not cover (flat axes, huge or tiny components) take the binary walk.

use std::mem::MaybeUninit;

use super::Node;
use crate::math::{Aabb, DVec3};

/// Pending entries: up to three children a level, over at most the binary tree's depth.
const STACK: usize = 384;
/// Coordinates, origins and reciprocal directions beyond this take the binary walk: the
/// widened f32 slab distances then stay far from overflow.
const REACH: f64 = 1e15;
/// Reciprocal directions below this in magnitude take the binary walk (their f32 value would
/// not be a normal number).
const TINY_INV: f64 = 1e-30;
/// Relative widening of the reduced slab distances: more than twice the worst relative error
/// of the f32 subtraction and product (3 · 2^-24) and the f64 test's own rounding.
const REL: f32 = 1.0 / (1u32 << 20) as f32;

/// Four children's boxes, child indices and leaf sizes.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(64))]
pub(super) struct WNode {
    /// `planes[axis][0]` the four lower faces, `[axis][1]` the upper ones; an empty lane has
    /// an inverted box, which every ray misses.
    planes: [[[f32; 4]; 2]; 3],
    /// An interior child's node index, or a leaf child's first entry in `Bvh::prims`.
    child: [u32; 4],
    /// A leaf child's number of primitives; 0 for an interior child.
    count: [u32; 4],
}

#[derive(Clone, Debug)]
pub(super) struct Wide {
    nodes: Vec<WNode>,
    /// The largest magnitude of any box coordinate on each axis (the root's).
    reach: [f64; 3],
}

/// `x` rounded to f32 downwards (`up` false) or upwards.
fn round32(x: f64, up: bool) -> f32 {
    let f = x as f32;
    if up && (f as f64) < x {
        f.next_up()
    } else if !up && (f as f64) > x {
        f.next_down()
    } else {
        f
    }
}

/// Surface area, to pick which child to open first when collapsing.
fn area(b: &Aabb) -> f64 {
    let d = b.max - b.min;
    d.x * d.y + d.y * d.z + d.z * d.x
}

impl Wide {
    /// The 4-wide tree of a binary tree whose boxes are all finite and whose root is interior;
    /// None when its coordinates are too large for the f32 bound.
    pub(super) fn build(nodes: &[Node]) -> Option<Wide> {
        let root = nodes.first()?;
        if root.count > 0 || !root.bounds.is_finite() {
            return None;
        }
        let m = root.bounds.min.abs().max(root.bounds.max.abs());
        if m.max_element() > REACH {
            return None;
        }
        let mut out = Vec::with_capacity(nodes.len() / 2 + 1);
        collapse(nodes, 0, &mut out);
        Some(Wide {
            nodes: out,
            reach: m.to_array(),
        })
    }

    pub(super) fn memory(&self) -> usize {
        self.nodes.capacity() * std::mem::size_of::<WNode>()
    }
}

/// Appends the wide node standing for binary interior node `at` and its subtree; returns its
/// index.
fn collapse(nodes: &[Node], at: usize, out: &mut Vec<WNode>) -> u32 {
    let mut kids = [at + 1, nodes[at].index as usize, 0, 0];
    let mut n = 2;
    // Open the interior child of largest area until there are four.
    while n < 4 {
        let open = (0..n)
            .filter(|&j| nodes[kids[j]].count == 0)
            .max_by(|&a, &b| area(&nodes[kids[a]].bounds).total_cmp(&area(&nodes[kids[b]].bounds)));
        let Some(j) = open else { break };
        let k = kids[j];
        kids[j] = k + 1;
        kids[n] = nodes[k].index as usize;
        n += 1;
    }
    let me = out.len();
    out.push(WNode {
        planes: [[[f32::MAX; 4], [-f32::MAX; 4]]; 3],
        child: [0; 4],
        count: [0; 4],
    });
    for (lane, &k) in kids[..n].iter().enumerate() {
        let b = &nodes[k].bounds;
        for axis in 0..3 {
            out[me].planes[axis][0][lane] = round32(b.min[axis], false);
            out[me].planes[axis][1][lane] = round32(b.max[axis], true);
        }
        let (child, count) = if nodes[k].count > 0 {
            (nodes[k].index, nodes[k].count)
        } else {
            (collapse(nodes, k, out), 0)
        };
        out[me].child[lane] = child;
        out[me].count[lane] = count;
    }
    me as u32
}

/// A ray's f32 form for the wide test.
#[cfg(target_arch = "x86_64")]
struct WRay {
    origin: [std::arch::x86_64::__m128; 3],
    inv: [std::arch::x86_64::__m128; 3],
    /// The absolute widening of each axis's slab distances.
    slack: [std::arch::x86_64::__m128; 3],
    /// Which face (0 lower, 1 upper) the ray enters each axis's slab by.
    near: [usize; 3],
}

/// `tmax` rounded up to f32.
#[inline]
fn up32(t: f64) -> f32 {
    if t >= f32::MAX as f64 {
        f32::INFINITY
    } else {
        round32(t, true)
    }
}

#[cfg(target_arch = "x86_64")]
impl Wide {
    #[inline]
    fn ray(&self, origin: DVec3, inv: DVec3) -> Option<WRay> {
        use std::arch::x86_64::_mm_set1_ps;
        let a = inv.abs();
        let fits = origin.abs().max_element() <= REACH
            && a.min_element() >= TINY_INV
            && a.max_element() <= REACH;
        // NaN fails every comparison above but max_element/min_element skip it; `a` is checked
        // for NaN (and so `inv` for NaN) here.
        if !fits || a.is_nan_mask().any() || origin.is_nan_mask().any() {
            return None;
        }
        // The rounding of a face and of the origin to f32 (each within 2^-23 of its
        // magnitude) moves a slab distance by up to their sum times |inv|; twice more for the
        // relative errors this term adds to, and a floor for subnormal faces and products.
        // The f64 value is at most 2e30 · 2^-20, so its f32 rounding needs a relative step up
        // (next_up would do, but a multiplication keeps this straight-line code).
        let reach = DVec3::from_array(self.reach);
        let s = ((reach + origin.abs() + DVec3::splat(1e-30))
            * inv.abs()
            * (1.0 / (1u64 << 20) as f64)
            + DVec3::splat(1e-30))
            * (1.0 + 1e-6);
        let o = origin.as_vec3();
        let i = inv.as_vec3();
        let s = s.as_vec3();
        // SAFETY: SSE is part of x86_64.
        unsafe {
            Some(WRay {
                origin: [_mm_set1_ps(o.x), _mm_set1_ps(o.y), _mm_set1_ps(o.z)],
                inv: [_mm_set1_ps(i.x), _mm_set1_ps(i.y), _mm_set1_ps(i.z)],
                slack: [_mm_set1_ps(s.x), _mm_set1_ps(s.y), _mm_set1_ps(s.z)],
                near: [
                    (inv.x < 0.0) as usize,
                    (inv.y < 0.0) as usize,
                    (inv.z < 0.0) as usize,
                ],
            })
        }
    }

    /// Entry distances (lower bounds of the f64 test's) of the four children, and the mask of
    /// those the ray may cross within (0, tmax].
    #[inline]
    fn test(n: &WNode, r: &WRay, tmax: f32) -> ([f32; 4], i32) {
        use std::arch::x86_64::*;
        // SAFETY: SSE is part of x86_64; the loads read four f32 of a 16-byte aligned array
        // (`WNode` is 64-byte aligned, each plane row 16 bytes from its start), the store
        // writes four into a four-element array.
        unsafe {
            let slab = |k: usize| {
                let lo = _mm_load_ps(n.planes[k][r.near[k]].as_ptr());
                let hi = _mm_load_ps(n.planes[k][1 - r.near[k]].as_ptr());
                let t0 = _mm_mul_ps(_mm_sub_ps(lo, r.origin[k]), r.inv[k]);
                let t1 = _mm_mul_ps(_mm_sub_ps(hi, r.origin[k]), r.inv[k]);
                (_mm_sub_ps(t0, r.slack[k]), _mm_add_ps(t1, r.slack[k]))
            };
            let (nx, fx) = slab(0);
            let (ny, fy) = slab(1);
            let (nz, fz) = slab(2);
            let near = _mm_max_ps(nx, _mm_max_ps(ny, nz));
            let far = _mm_min_ps(fx, _mm_min_ps(fy, fz));
            let near = _mm_max_ps(_mm_mul_ps(near, _mm_set1_ps(1.0 - REL)), _mm_setzero_ps());
            let far = _mm_min_ps(_mm_mul_ps(far, _mm_set1_ps(1.0 + REL)), _mm_set1_ps(tmax));
            let mask = _mm_movemask_ps(_mm_cmple_ps(near, far));
            let mut t = [0.0f32; 4];
            _mm_storeu_ps(t.as_mut_ptr(), near);
            (t, mask)
        }
    }

    /// Offers every primitive the binary walk would offer for this ray within (0, tmax] (and
    /// perhaps a few more), nearer children first; `f` as for `Bvh::traverse`. False when the
    /// ray does not fit the f32 bound and nothing was visited.
    #[inline]
    // The lane number picks from three arrays and the mask bit; an iterator over one of them
    // says less.
    #[allow(clippy::needless_range_loop)]
    pub(super) fn walk(
        &self,
        prims: &[u32],
        origin: DVec3,
        inv: DVec3,
        mut tmax: f64,
        f: &mut impl FnMut(usize, &mut f64) -> bool,
    ) -> bool {
        let Some(r) = self.ray(origin, inv) else {
            return false;
        };
        let mut stack = [const { MaybeUninit::<(u32, u32, f32)>::uninit() }; STACK];
        let mut sp = 0;
        let (mut at, mut count) = (0u32, 0u32);
        let mut t32 = up32(tmax);
        loop {
            if count > 0 {
                let first = at as usize;
                for &p in &prims[first..first + count as usize] {
                    if f(p as usize, &mut tmax) {
                        return true;
                    }
                }
                t32 = up32(tmax);
            } else {
                let n = &self.nodes[at as usize];
                let (near, mask) = Wide::test(n, &r, t32);
                if mask != 0 {
                    // The children crossed, nearest first.
                    let mut hit = [(0.0f32, 0u32, 0u32); 4];
                    let mut m = 0;
                    for lane in 0..4 {
                        if mask & (1 << lane) != 0 {
                            let e = (near[lane], n.child[lane], n.count[lane]);
                            let mut j = m;
                            while j > 0 && hit[j - 1].0 > e.0 {
                                hit[j] = hit[j - 1];
                                j -= 1;
                            }
                            hit[j] = e;
                            m += 1;
                        }
                    }
                    for &(t, c, k) in hit[1..m].iter().rev() {
                        if sp < STACK {
                            stack[sp].write((c, k, t));
                            sp += 1;
                        }
                    }
                    (at, count) = (hit[0].1, hit[0].2);
                    continue;
                }
            }
            loop {
                if sp == 0 {
                    return true;
                }
                sp -= 1;
                // SAFETY: entries below `sp` were all written by the push above, and `sp`
                // only counts down over them.
                let (c, k, t) = unsafe { stack[sp].assume_init() };
                if t as f64 <= tmax {
                    (at, count) = (c, k);
                    break;
                }
            }
        }
    }
}

#[cfg(not(target_arch = "x86_64"))]
impl Wide {
    pub(super) fn walk(
        &self,
        _: &[u32],
        _: DVec3,
        _: DVec3,
        _: f64,
        _: &mut impl FnMut(usize, &mut f64) -> bool,
    ) -> bool {
        false
    }
}

#[cfg(test)]
mod tests {
    use super::super::Bvh;
    use crate::geom::test_rng::Lcg;
    use crate::math::{Aabb, DVec3, Ray};

    fn offered_binary(bvh: &Bvh, ray: &Ray, inv: DVec3, tmax: f64) -> Vec<usize> {
        let mut v = Vec::new();
        bvh.traverse_inv(ray, inv, tmax, |i, _| {
            v.push(i);
            false
        });
        v.sort_unstable();
        v
    }

    fn offered_wide(bvh: &Bvh, ray: &Ray, inv: DVec3, tmax: f64) -> Vec<usize> {
        let mut v = Vec::new();
        bvh.traverse_any_order(ray, inv, tmax, |i, _| {
            v.push(i);
            false
        });
        v.sort_unstable();
        v
    }

    /// The wide walk offers every primitive the binary walk offers, each once, for boxes of
    /// many sizes and places (thin, flat, far from the origin, touching the ray's origin)
    /// and rays of every kind, including ones starting on faces and grazing them.
    #[test]
    fn wide_walk_offers_what_the_binary_walk_offers() {
        let mut rng = Lcg(23);
        for &(n, spread, size) in &[
            (40usize, 10.0, 2.0),
            (700, 50.0, 0.5),
            (3000, 1000.0, 3.0),
            (500, 1e-3, 1e-4),
            (300, 1e6, 10.0),
        ] {
            let mut boxes: Vec<Aabb> = (0..n)
                .map(|k| {
                    let c = rng.vec(spread);
                    let mut e = (rng.vec(size)).abs();
                    // Flat and point boxes too.
                    match k % 9 {
                        0 => e.x = 0.0,
                        1 => e = DVec3::ZERO,
                        _ => {}
                    }
                    Aabb::new(c - e, c + e)
                })
                .collect();
            boxes.push(Aabb::new(DVec3::splat(-spread), DVec3::splat(spread)));
            let mut bvh = Bvh::build(&boxes);
            bvh.widen();
            assert!(bvh.wide.is_some());
            let (mut total, mut extra) = (0, 0);
            for k in 0..3000 {
                // Origins on box corners and faces as well as anywhere.
                let origin = if k % 3 == 0 {
                    let b = &boxes[k % boxes.len()];
                    DVec3::new(b.min.x, b.max.y, (b.min.z + b.max.z) * 0.5)
                } else {
                    rng.vec(spread * 1.5)
                };
                let dir = if k % 5 == 0 {
                    // Towards a corner, grazing the box.
                    let b = &boxes[(k * 7) % boxes.len()];
                    b.max - origin
                } else {
                    rng.vec(1.0)
                };
                let ray = Ray::new(origin, dir);
                let inv = DVec3::ONE / dir;
                let tmax = match k % 4 {
                    0 => f64::INFINITY,
                    1 => rng.next() * spread,
                    2 => (boxes[k % boxes.len()].min - origin).length() / dir.length(),
                    _ => rng.next() * spread * 3.0,
                };
                let a = offered_binary(&bvh, &ray, inv, tmax);
                let b = offered_wide(&bvh, &ray, inv, tmax);
                let mut j = 0;
                for p in &a {
                    while j < b.len() && b[j] < *p {
                        j += 1;
                    }
                    assert!(j < b.len() && b[j] == *p, "n {n} ray {k}: {p} not offered");
                }
                assert!(b.windows(2).all(|w| w[0] < w[1]), "offered twice");
                total += a.len();
                extra += b.len() - a.len();
            }
            // Conservative, not loose: few primitives more than the binary walk.
            assert!(extra <= total / 5 + 50, "{extra} extra of {total}");
        }
    }

    /// A nearest-hit query with a tie rule gives the same answer whichever walk it takes.
    #[test]
    fn nearest_with_ties_is_the_same_either_walk() {
        let mut rng = Lcg(3);
        // Pairs of equal boxes: coincident surfaces.
        let mut boxes = Vec::new();
        for _ in 0..400 {
            let c = rng.vec(20.0);
            let e = rng.vec(1.0).abs() + DVec3::splat(0.05);
            boxes.push(Aabb::new(c - e, c + e));
            boxes.push(Aabb::new(c - e, c + e));
        }
        let mut bvh = Bvh::build(&boxes);
        bvh.widen();
        let nearest = |wide: bool, ray: &Ray| {
            let inv = DVec3::ONE / ray.dir;
            let mut best: Option<(usize, f64)> = None;
            let mut f = |i: usize, tmax: &mut f64| {
                let limit = match best {
                    Some((bi, _)) if i < bi => tmax.next_up(),
                    _ => *tmax,
                };
                if let Some((t, _)) = boxes[i].hit(ray.origin, inv, f64::INFINITY) {
                    if t > 0.0 && t < limit {
                        *tmax = t;
                        best = Some((i, t));
                    }
                }
                false
            };
            if wide {
                bvh.traverse_any_order(ray, inv, f64::INFINITY, &mut f);
            } else {
                bvh.traverse_inv(ray, inv, f64::INFINITY, &mut f);
            }
            best.map(|(i, t)| (i, t.to_bits()))
        };
        let mut hits = 0;
        for _ in 0..5000 {
            let ray = Ray::new(rng.vec(30.0), rng.vec(1.0));
            let a = nearest(false, &ray);
            assert_eq!(a, nearest(true, &ray));
            hits += a.is_some() as usize;
        }
        assert!(hits > 500, "{hits}");
    }
}
