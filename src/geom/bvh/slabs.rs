//! The BVH's ray-box test: two boxes at once, one per SSE lane, read from a node that stores
//! its two children's boxes side by side (`Pair`), so each axis's faces are one aligned
//! 16-byte load instead of two scalar loads and a shuffle.

use crate::math::{Aabb, DVec3};

/// Two boxes, lane 0 and lane 1, each coordinate's pair adjacent: `lo[k]` holds both boxes'
/// minimum along axis k, `hi[k]` their maximum. 32-byte aligned, so that `Plain4`'s three
/// 32-byte rows are aligned loads: LLVM splits an unaligned 256-bit load into two halves for
/// the generic x86-64 tuning (two instructions more a row, and no memory operand).
#[derive(Clone, Copy, Debug)]
#[repr(C, align(32))]
pub(super) struct Pair {
    pub(super) lo: [[f64; 2]; 3],
    pub(super) hi: [[f64; 2]; 3],
}

impl Pair {
    pub(super) fn of(a: &Aabb, b: &Aabb) -> Pair {
        Pair {
            lo: [[a.min.x, b.min.x], [a.min.y, b.min.y], [a.min.z, b.min.z]],
            hi: [[a.max.x, b.max.x], [a.max.y, b.max.y], [a.max.z, b.max.z]],
        }
    }

    /// Box `k` (0 or 1), bit for bit as it was stored.
    #[inline]
    pub(super) fn get(&self, k: usize) -> Aabb {
        Aabb::new(
            DVec3::new(self.lo[0][k], self.lo[1][k], self.lo[2][k]),
            DVec3::new(self.hi[0][k], self.hi[1][k], self.hi[2][k]),
        )
    }
}

/// Which of a node's two boxes a ray crosses within (0, tmax), bit 0 the first and bit 1 the
/// second, and their entry distances (meaningful for the crossed ones): the walk branches on
/// the mask as the comparison left it, where an `Option` pair cost a few instructions a node
/// to build and take apart.
#[derive(Clone, Copy, Debug)]
pub(super) struct Crossing {
    pub(super) mask: u32,
    pub(super) near: [f64; 2],
}

impl Crossing {
    /// The crossing of two boxes tested one at a time (`Aabb::hit`'s entry distances).
    #[inline(always)]
    pub(super) fn of(a: Option<f64>, b: Option<f64>) -> Crossing {
        Crossing {
            mask: a.is_some() as u32 | (b.is_some() as u32) << 1,
            near: [a.unwrap_or(0.0), b.unwrap_or(0.0)],
        }
    }

    /// Each box's entry distance, or None where the ray misses it.
    #[inline]
    pub(super) fn options(self) -> (Option<f64>, Option<f64>) {
        (
            (self.mask & 1 != 0).then_some(self.near[0]),
            (self.mask & 2 != 0).then_some(self.near[1]),
        )
    }
}

/// The slab test of two boxes at once, one per SSE lane, for a ray whose slab distances cannot
/// be NaN except along its `flat` axes (computed apart). Each lane does `Aabb::hit`'s
/// operations in its order; without NaNs the minimum and maximum instructions give
/// `f64::min`'s and `f64::max`'s values (up to the sign of a zero, which no comparison sees),
/// so the answers and the entry distances are `Aabb::hit`'s bit for bit (unit tests
/// `paired_slabs_match_aabb_hit` and `..._for_flat_rays`). `Aabb::hit` spends a third of its
/// work on the NaN handling of `f64::min`.
#[cfg(target_arch = "x86_64")]
pub(super) struct Slabs2 {
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
    pub(super) fn new(origin: DVec3, inv_dir: DVec3) -> Option<Slabs2> {
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

    /// Whether some axis is flat (its reciprocal direction infinite): the test is not
    /// monotonic in the box then (`Bvh::traverse_inv`'s root).
    #[inline]
    pub(super) fn any_flat(&self) -> bool {
        self.flat[0] | self.flat[1] | self.flat[2]
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
    pub(super) fn hit2(&self, a: &Aabb, b: &Aabb, tmax: f64) -> (Option<f64>, Option<f64>) {
        self.hit_pair(&Pair::of(a, b), tmax).options()
    }

    /// `Aabb::hit` of both boxes of `p` within (0, tmax): the entry distances of those crossed.
    #[inline]
    pub(super) fn hit_pair(&self, p: &Pair, tmax: f64) -> Crossing {
        self.pair_test::<true>(p, tmax)
    }

    /// `hit_pair` for a ray with no flat axis (`any_flat` false): without the per-axis look
    /// at `flat`. The reference `Plain2::hit_pair` is checked against.
    #[cfg(test)]
    pub(super) fn hit_pair_unflat(&self, p: &Pair, tmax: f64) -> Crossing {
        debug_assert!(!self.any_flat());
        self.pair_test::<false>(p, tmax)
    }

    /// The paired test; `FLAT` false leaves out the flat axes' path, for rays that have none.
    #[inline(always)]
    fn pair_test<const FLAT: bool>(&self, p: &Pair, tmax: f64) -> Crossing {
        use std::arch::x86_64::*;
        // SAFETY: SSE2 is part of x86_64; `Pair` is 16-byte aligned and each `[f64; 2]` row
        // sits at a multiple of 16 bytes in it, as `_mm_load_pd` needs; the store writes two
        // doubles into a two-double array.
        unsafe {
            let axis = |k: usize| {
                if FLAT && self.flat[k] {
                    let (na, fa) = self.flat_axis(k, p.lo[k][0], p.hi[k][0]);
                    let (nb, fb) = self.flat_axis(k, p.lo[k][1], p.hi[k][1]);
                    return (_mm_set_pd(nb, na), _mm_set_pd(fb, fa));
                }
                let t0 = _mm_mul_pd(
                    _mm_sub_pd(_mm_load_pd(p.lo[k].as_ptr()), self.origin[k]),
                    self.inv_dir[k],
                );
                let t1 = _mm_mul_pd(
                    _mm_sub_pd(_mm_load_pd(p.hi[k].as_ptr()), self.origin[k]),
                    self.inv_dir[k],
                );
                (_mm_min_pd(t0, t1), _mm_max_pd(t0, t1))
            };
            pair_crossing(axis(0), axis(1), axis(2), tmax)
        }
    }
}

/// The pair's crossing from each axis's (near, far) slab distances: shared by `Slabs2` and
/// `Plain2`. max_element is x.max(y.max(z)), then .max(0.0); likewise for the far side. With
/// no NaN in them maxima and minima may be taken in any grouping (the value is the same up to
/// the sign of a zero, which no comparison sees): pairs first, for a chain of two operations
/// instead of three before the comparison.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn pair_crossing(
    (nx, fx): (std::arch::x86_64::__m128d, std::arch::x86_64::__m128d),
    (ny, fy): (std::arch::x86_64::__m128d, std::arch::x86_64::__m128d),
    (nz, fz): (std::arch::x86_64::__m128d, std::arch::x86_64::__m128d),
    tmax: f64,
) -> Crossing {
    use std::arch::x86_64::*;
    // SAFETY: SSE2 is part of x86_64.
    unsafe {
        let near = _mm_max_pd(_mm_max_pd(nx, _mm_setzero_pd()), _mm_max_pd(ny, nz));
        let far = _mm_min_pd(_mm_min_pd(fx, _mm_set1_pd(tmax)), _mm_min_pd(fy, fz));
        let mask = _mm_movemask_pd(_mm_cmple_pd(near, far)) as u32;
        let mut t = [0.0f64; 2];
        _mm_storeu_pd(t.as_mut_ptr(), near);
        Crossing { mask, near: t }
    }
}

/// The paired test for a plain ray (`Recip::plain`: a finite origin, finite and nonzero
/// reciprocals; no slab distance is NaN and no axis flat), each slab distance written as
/// `(o - face) * -inv`. That is `(face - o) * inv` bit for bit but for the sign of a zero:
/// `o - face` is `-(face - o)` exactly (round-to-nearest is symmetric, and an exact zero is
/// +0 both ways), and so is each product with the negated reciprocal. No comparison sees the
/// sign of a zero, so the mask, the entry distances' order and their tests against `tmax` are
/// `Slabs2::hit_pair`'s (unit test `the_plain_test_is_the_paired_test`). The face is then the
/// subtraction's second operand, which the AVX build (`Scene::first_hit`'s and the shadow
/// ray's copies compiled with `target_feature(enable = "avx")`) reads straight from memory
/// into the three-operand `vsubpd`, where SSE needs a load into a register the subtraction
/// then overwrites; with the copies between registers that min and max need gone as well, a
/// node costs ~14 instructions fewer.
#[cfg(target_arch = "x86_64")]
pub(super) struct Plain2 {
    origin: [std::arch::x86_64::__m128d; 3],
    neg_inv: [std::arch::x86_64::__m128d; 3],
}

#[cfg(target_arch = "x86_64")]
impl Plain2 {
    #[inline(always)]
    pub(super) fn new(origin: DVec3, inv_dir: DVec3) -> Plain2 {
        use std::arch::x86_64::_mm_set1_pd;
        debug_assert!(Slabs2::new(origin, inv_dir).is_some_and(|s| !s.any_flat()));
        // SAFETY: SSE2 is part of x86_64.
        unsafe {
            Plain2 {
                origin: [
                    _mm_set1_pd(origin.x),
                    _mm_set1_pd(origin.y),
                    _mm_set1_pd(origin.z),
                ],
                neg_inv: [
                    _mm_set1_pd(-inv_dir.x),
                    _mm_set1_pd(-inv_dir.y),
                    _mm_set1_pd(-inv_dir.z),
                ],
            }
        }
    }

    /// Which of the boxes of `p` the ray crosses within (0, tmax), and their entry distances
    /// (`Slabs2::hit_pair`'s, up to the sign of a zero).
    #[inline(always)]
    pub(super) fn hit_pair(&self, p: &Pair, tmax: f64) -> Crossing {
        use std::arch::x86_64::*;
        // SAFETY: SSE2 is part of x86_64; `Pair` is 16-byte aligned and each `[f64; 2]` row
        // sits at a multiple of 16 bytes in it, as `_mm_load_pd` needs; the store writes two
        // doubles into a two-double array.
        unsafe {
            let axis = |k: usize| {
                let t0 = _mm_mul_pd(
                    _mm_sub_pd(self.origin[k], _mm_load_pd(p.lo[k].as_ptr())),
                    self.neg_inv[k],
                );
                let t1 = _mm_mul_pd(
                    _mm_sub_pd(self.origin[k], _mm_load_pd(p.hi[k].as_ptr())),
                    self.neg_inv[k],
                );
                (_mm_min_pd(t0, t1), _mm_max_pd(t0, t1))
            };
            pair_crossing(axis(0), axis(1), axis(2), tmax)
        }
    }
}

/// `Plain2` in 256-bit AVX lanes, for the walks' AVX copies: the node's 96 bytes of faces
/// read as three 4-double rows (x and y faces below, z below and x above, y and z above),
/// each against its own broadcasts, so six subtractions and multiplications become three;
/// one cross-lane permute lines the far faces up with the near ones. Every distance, minimum
/// and maximum is `Plain2::hit_pair`'s, on the same operands in the same order, so the
/// answers are its to the bit (unit test `the_plain_test_is_the_paired_test`).
#[cfg(target_arch = "x86_64")]
pub(super) struct Plain4 {
    origin: [std::arch::x86_64::__m256d; 3],
    neg_inv: [std::arch::x86_64::__m256d; 3],
}

#[cfg(target_arch = "x86_64")]
impl Plain4 {
    /// For a plain ray (`Recip::plain`), as `Plain2::new`.
    #[target_feature(enable = "avx")]
    #[inline]
    pub(super) fn new(o: DVec3, inv_dir: DVec3) -> Plain4 {
        use std::arch::x86_64::_mm256_setr_pd;
        let n = -inv_dir;
        // The rows' axes: (x, y), (z, x), (y, z), each axis over both boxes.
        Plain4 {
            origin: [
                _mm256_setr_pd(o.x, o.x, o.y, o.y),
                _mm256_setr_pd(o.z, o.z, o.x, o.x),
                _mm256_setr_pd(o.y, o.y, o.z, o.z),
            ],
            neg_inv: [
                _mm256_setr_pd(n.x, n.x, n.y, n.y),
                _mm256_setr_pd(n.z, n.z, n.x, n.x),
                _mm256_setr_pd(n.y, n.y, n.z, n.z),
            ],
        }
    }

    /// `Plain2::hit_pair`, bit for bit.
    #[target_feature(enable = "avx")]
    #[inline]
    pub(super) fn hit_pair(&self, p: &Pair, tmax: f64) -> Crossing {
        use std::arch::x86_64::*;
        let faces = p as *const Pair as *const f64;
        // SAFETY: `Pair` is `repr(C, align(32))`, twelve doubles (`lo` then `hi`, each axis's
        // pair adjacent), so doubles 0..4, 4..8 and 8..12 lie within it at multiples of 32
        // bytes, as `_mm256_load_pd` needs; the store writes two doubles into a two-double
        // array.
        unsafe {
            let row = |k: usize| {
                _mm256_mul_pd(
                    _mm256_sub_pd(self.origin[k], _mm256_load_pd(faces.add(4 * k))),
                    self.neg_inv[k],
                )
            };
            // [x below, y below], [z below, x above], [y above, z above].
            let (a, b, c) = (row(0), row(1), row(2));
            let above = _mm256_permute2f128_pd(b, c, 0x21);
            let (nxy, fxy) = (_mm256_min_pd(a, above), _mm256_max_pd(a, above));
            let (bz, cz) = (_mm256_castpd256_pd128(b), _mm256_extractf128_pd(c, 1));
            let (nz, fz) = (_mm_min_pd(bz, cz), _mm_max_pd(bz, cz));
            let (nx, ny) = (_mm256_castpd256_pd128(nxy), _mm256_extractf128_pd(nxy, 1));
            let (fx, fy) = (_mm256_castpd256_pd128(fxy), _mm256_extractf128_pd(fxy, 1));
            // `Plain2::hit_pair`'s reductions, in its grouping (a NaN `tmax` drops out of
            // `far` as it does there).
            let near = _mm_max_pd(_mm_max_pd(nx, _mm_setzero_pd()), _mm_max_pd(ny, nz));
            let far = _mm_min_pd(_mm_min_pd(fx, _mm_set1_pd(tmax)), _mm_min_pd(fy, fz));
            let mask = _mm_movemask_pd(_mm_cmple_pd(near, far)) as u32;
            let mut t = [0.0f64; 2];
            _mm_storeu_pd(t.as_mut_ptr(), near);
            Crossing { mask, near: t }
        }
    }
}

/// Other targets take `Aabb::hit` for every ray.
#[cfg(not(target_arch = "x86_64"))]
pub(super) struct Slabs2;

#[cfg(not(target_arch = "x86_64"))]
impl Slabs2 {
    pub(super) fn new(_: DVec3, _: DVec3) -> Option<Slabs2> {
        None
    }
    pub(super) fn any_flat(&self) -> bool {
        unreachable!()
    }
    pub(super) fn hit2(&self, _: &Aabb, _: &Aabb, _: f64) -> (Option<f64>, Option<f64>) {
        unreachable!()
    }
    pub(super) fn hit_pair(&self, _: &Pair, _: f64) -> Crossing {
        unreachable!()
    }
}

/// Other targets take `Aabb::hit` for every ray.
#[cfg(not(target_arch = "x86_64"))]
pub(super) struct Plain2;

#[cfg(not(target_arch = "x86_64"))]
pub(super) struct Plain4;

#[cfg(not(target_arch = "x86_64"))]
impl Plain4 {
    pub(super) unsafe fn new(_: DVec3, _: DVec3) -> Plain4 {
        Plain4
    }
    pub(super) unsafe fn hit_pair(&self, _: &Pair, _: f64) -> Crossing {
        unreachable!()
    }
}

#[cfg(not(target_arch = "x86_64"))]
impl Plain2 {
    pub(super) fn new(_: DVec3, _: DVec3) -> Plain2 {
        Plain2
    }
    pub(super) fn hit_pair(&self, _: &Pair, _: f64) -> Crossing {
        unreachable!()
    }
}

#[cfg(all(test, target_arch = "x86_64"))]
mod tests {
    use super::super::Bvh;
    use super::*;
    use crate::geom::test_rng::Lcg;

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

    /// What lets `Bvh::traverse_inv` skip the root's own box for rays without a flat axis:
    /// where the paired test finds a ray missing a node's box (the union of its children's),
    /// it misses both children's. Boxes on a grid, flat in one or two axes, tiny, or from
    /// `Bvh::build`; origins on their faces and edges or anywhere; direction components from
    /// 1e-300 to 1e3 (reciprocals that overflow the slab distances included); finite,
    /// infinite and NaN `tmax`. Rays with a flat axis keep the root's test, and are skipped.
    #[test]
    fn the_root_test_is_implied_by_its_children() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let grid = |x: f64| (x * 16.0).floor() - 8.0;
        let mut checked = 0usize;
        for n in [2usize, 3, 5, 17, 200] {
            let boxes: Vec<Aabb> = (0..n)
                .map(|k| {
                    let a = DVec3::new(grid(next()), grid(next()), grid(next()));
                    let size = match k % 4 {
                        0 => DVec3::new(0.0, 1.0, 2.0),
                        1 => DVec3::new(3.0, 0.0, 0.0),
                        2 => DVec3::new(next() * 4.0, next() * 4.0, next() * 4.0),
                        _ => DVec3::splat(1e-9),
                    };
                    Aabb::new(a, a + size)
                })
                .collect();
            let bvh = Bvh::build(&boxes);
            let mut parents: Vec<(Aabb, &Pair)> = bvh
                .nodes
                .iter()
                .map(|n| (n.boxes.get(0).union(&n.boxes.get(1)), &n.boxes))
                .collect();
            if bvh.root.count == 0 {
                parents.push((bvh.root_box, &bvh.nodes[bvh.root.index as usize].boxes));
            }
            for k in 0..20_000usize {
                let origin = if k % 2 == 0 {
                    DVec3::new(grid(next()), grid(next()), grid(next()))
                } else {
                    DVec3::new(next(), next(), next()) * 24.0 - DVec3::splat(12.0)
                };
                let mut dir = DVec3::new(next(), next(), next()) * 2.0 - DVec3::ONE;
                match k % 7 {
                    0 => dir.x = 1e-300,
                    1 => dir.y = -1e-200 * next(),
                    2 => dir *= 1e3,
                    3 => dir.z = 1e-9,
                    _ => {}
                }
                let inv = DVec3::new(1.0 / dir.x, 1.0 / dir.y, 1.0 / dir.z);
                let Some(s) = Slabs2::new(origin, inv) else {
                    continue;
                };
                if s.any_flat() {
                    continue;
                }
                let tmax = match k % 5 {
                    0 => f64::INFINITY,
                    1 => f64::NAN,
                    2 => next() * 3.0,
                    _ => next() * 40.0,
                };
                for &(whole, pair) in &parents {
                    if s.hit2(&whole, &whole, tmax).0.is_none() {
                        assert_eq!(s.hit_pair(pair, tmax).mask, 0, "n={n} k={k}");
                        checked += 1;
                    }
                }
            }
        }
        assert!(checked > 10_000, "{checked}");
    }

    /// `hit_pair_unflat` is `hit_pair` bit for bit wherever the walk takes it (no flat axis),
    /// and `Plain2::hit_pair` is it up to the sign of a zero entry distance (and `Plain4`'s,
    /// where the CPU has AVX, `Plain2`'s to the bit): boxes from tiny to
    /// huge and infinite, origins on faces and anywhere, direction components down to 1e-300,
    /// `tmax` finite, infinite and NaN.
    #[test]
    fn the_plain_test_is_the_paired_test() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut compared = 0usize;
        for k in 0..50_000usize {
            let grid = |x: f64| (x * 16.0).floor() - 8.0;
            let mut corner = || DVec3::new(grid(next()), grid(next()), grid(next()));
            let (a0, b0) = (corner(), corner());
            let size = match k % 4 {
                0 => DVec3::splat(1e-9),
                1 => DVec3::new(0.0, 2.0, 1.0),
                2 => DVec3::splat(f64::INFINITY),
                _ => DVec3::new(3.0, 1.0, 5.0),
            };
            let (a, b) = (
                Aabb::new(a0, a0 + size),
                Aabb::new(b0.min(b0 + size), b0.max(b0)),
            );
            let origin = if k % 3 == 0 {
                a0
            } else {
                DVec3::new(next(), next(), next()) * 24.0 - DVec3::splat(12.0)
            };
            let mut dir = DVec3::new(next(), next(), next()) * 2.0 - DVec3::ONE;
            match k % 5 {
                0 => dir.y = 1e-300,
                1 => dir.z = -1e-12,
                _ => {}
            }
            let inv = DVec3::new(1.0 / dir.x, 1.0 / dir.y, 1.0 / dir.z);
            let Some(s) = Slabs2::new(origin, inv) else {
                continue;
            };
            if s.any_flat() {
                continue;
            }
            let tmax = match k % 4 {
                0 => f64::INFINITY,
                1 => f64::NAN,
                _ => next() * 30.0,
            };
            let pair = Pair::of(&a, &b);
            let bits = |c: Crossing| {
                let h = c.options();
                (h.0.map(f64::to_bits), h.1.map(f64::to_bits))
            };
            let want = s.hit_pair(&pair, tmax);
            assert_eq!(bits(s.hit_pair_unflat(&pair, tmax)), bits(want), "k={k}");
            // The plain test: the same mask, and entry distances equal as numbers (a zero's
            // sign may differ, which no comparison sees).
            let got = Plain2::new(origin, inv).hit_pair(&pair, tmax);
            assert_eq!(got.mask, want.mask, "k={k}");
            if crate::math::has_avx() {
                // SAFETY: the CPU has AVX.
                let wide = unsafe { Plain4::new(origin, inv).hit_pair(&pair, tmax) };
                assert_eq!(wide.mask, got.mask, "k={k}");
                assert_eq!(
                    wide.near.map(f64::to_bits),
                    got.near.map(f64::to_bits),
                    "k={k}"
                );
            }
            for b in 0..2 {
                if want.mask >> b & 1 != 0 {
                    let (g, w) = (got.near[b], want.near[b]);
                    assert!(g == w && (w == 0.0 || g.to_bits() == w.to_bits()), "k={k}");
                }
            }
            compared += 1;
        }
        assert!(compared > 40_000, "{compared}");
    }
}
