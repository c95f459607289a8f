//! The copies of a cell's list that lookups reading whole cells keep per sub-cell
//! (`Cache::near_memo`'s fresh normals of level 1: a curved surface's camera rays): of the
//! samples filed under a cell, only those whose reach may cover a point of the sub-cell. A
//! conservative test, so the lookups take the same samples in the same order from the copy
//! as from the cell, to the bit; in AVX lanes where the CPU has them (a branchy scalar sift
//! took more time than the copies saved: gamma_showcase 1.16 of the time).

use super::{floors_key, Cache, Footprint, Scale, SPLIT};
use crate::math::DVec3;
use crate::scene::scratch::{ProbeCell, ProbeMemo};

impl Cache {
    /// Readies `memo` for lookups at `bound` in this filing: its sub-cells emptied if made
    /// for another, one per scale.
    #[inline(always)]
    pub(super) fn sub_memo(&self, memo: &mut ProbeMemo, bound: f64) {
        if memo.stamp != self.stamp || memo.bound != bound.to_bits() {
            memo.stamp = self.stamp;
            memo.bound = bound.to_bits();
            for c in &mut memo.cells {
                c.floors = [f64::NAN; 3];
            }
        }
        if memo.cells.len() < self.scales.len() {
            memo.cells.resize_with(self.scales.len(), Default::default);
        }
    }

    /// `c` (the memo's copy for `scale`) made the sub-cell holding `p`, unless it is already:
    /// the level-1 samples of its cell that can reach a point of it (`sift`). A neighbouring
    /// lookup mostly falls in the same sub-cell and reads the copy, without a key or a grid
    /// probe, and meets fewer samples out of reach than the whole cell holds.
    #[inline(always)]
    pub(super) fn sub_cell(&self, scale: &Scale, p: DVec3, bound: f64, c: &mut ProbeCell) {
        let fine = scale.sub_floors(p);
        // A NaN is equal to nothing: a point or a memo cell with one asks the grid.
        if c.floors != fine {
            c.floors = fine;
            c.ids.clear();
            if let Some(ids) = scale.grid1.get(&floors_key(scale.floors(p))) {
                sift(self, ids, fine, scale.cell / SPLIT, bound, &mut c.ids);
            }
        }
    }
}

/// Into `out`, the samples of `ids` (a cell's list) whose reach at `bound` may cover a point
/// of the sub-cell `fine` (its `sub_floors`, `sub` its size), in their order. Only samples
/// `within` surely turns away at every point of it are left out: the squared distance from
/// the sample to the sub-cell's box passes its squared reach by a margin (10⁻⁶ of it) far
/// above both sides' rounding (a few units in the last place). A sample with a NaN position
/// or reach is never within reach, kept or not; a sub-cell too far out for its bounds to be
/// exact keeps everything.
pub(super) fn sift(
    cache: &Cache,
    ids: &[u32],
    fine: [f64; 3],
    sub: f64,
    bound: f64,
    out: &mut Vec<u32>,
) {
    out.clear();
    // Below 2^52 in size, f + 1 is exact, and so are both bounds.
    if !fine.iter().all(|f| f.abs() < 4.0e15) {
        out.extend_from_slice(ids);
        return;
    }
    let lo = fine.map(|f| f * sub);
    let hi = fine.map(|f| (f + 1.0) * sub);
    #[cfg(target_arch = "x86_64")]
    if cache.lanes && ids.len() >= 4 {
        // SAFETY: `lanes` is only set where the CPU has AVX (`Cache::with_pool`).
        unsafe { sift_avx(&cache.foot, ids, (lo, hi), bound, out) };
        return;
    }
    sift_scalar(&cache.foot, ids, (lo, hi), bound, out);
}

/// Whether sample `s` may reach a point of the box [lo, hi] at `bound` (`sift`'s test).
#[inline(always)]
fn may_reach(s: &Footprint, (lo, hi): ([f64; 3], [f64; 3]), bound: f64) -> bool {
    let gap = |v: f64, a: usize| (lo[a] - v).max(v - hi[a]).max(0.0);
    let (gx, gy, gz) = (gap(s.p.x, 0), gap(s.p.y, 1), gap(s.p.z, 2));
    let far = s.r * bound;
    // Ordered: a NaN keeps the sample.
    let out_of_reach = gx * gx + gy * gy + gz * gz > far * far * MARGIN;
    !out_of_reach
}

/// How far past the squared reach a squared gap must be to leave a sample out.
const MARGIN: f64 = 1.000_001;

fn sift_scalar(
    foot: &[Footprint],
    ids: &[u32],
    boxed: ([f64; 3], [f64; 3]),
    bound: f64,
    out: &mut Vec<u32>,
) {
    out.extend(
        ids.iter()
            .copied()
            .filter(|&i| may_reach(&foot[i as usize], boxed, bound)),
    );
}

/// `sift_scalar` four samples at a time: the gaps by `maxpd` (as `f64::max`, up to a NaN's,
/// which never matters: such a sample reaches nothing) and the kept ids written without a
/// branch.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
unsafe fn sift_avx(
    foot: &[Footprint],
    ids: &[u32],
    (lo, hi): ([f64; 3], [f64; 3]),
    bound: f64,
    out: &mut Vec<u32>,
) {
    use std::arch::x86_64::*;
    use std::mem::offset_of;
    const PX: usize = offset_of!(Footprint, p) / 8;
    const PZ: usize = PX + 2;
    const _: () = assert!(offset_of!(Footprint, r) == (PZ + 1) * 8);
    out.reserve(ids.len());
    let (lx, ly, lz) = (
        _mm256_set1_pd(lo[0]),
        _mm256_set1_pd(lo[1]),
        _mm256_set1_pd(lo[2]),
    );
    let (hx, hy, hz) = (
        _mm256_set1_pd(hi[0]),
        _mm256_set1_pd(hi[1]),
        _mm256_set1_pd(hi[2]),
    );
    let zero = _mm256_setzero_pd();
    let vbound = _mm256_set1_pd(bound);
    let margin = _mm256_set1_pd(MARGIN);
    let start = out.len();
    let spare = out.spare_capacity_mut();
    let mut n = 0;
    let mut quads = ids.chunks_exact(4);
    for q in &mut quads {
        let s = [q[0], q[1], q[2], q[3]].map(|i| &foot[i as usize]);
        let ptr =
            |k: usize, field: usize| (s[k] as *const Footprint as *const f64).wrapping_add(field);
        // SAFETY: pairs of consecutive f64 fields of a `Footprint` ((p.x, p.y), (p.z, r)),
        // lanes 0 and 2 of one register and 1 and 3 of the other.
        let (xy, zr) = unsafe {
            (
                (
                    _mm256_loadu2_m128d(ptr(2, PX), ptr(0, PX)),
                    _mm256_loadu2_m128d(ptr(3, PX), ptr(1, PX)),
                ),
                (
                    _mm256_loadu2_m128d(ptr(2, PZ), ptr(0, PZ)),
                    _mm256_loadu2_m128d(ptr(3, PZ), ptr(1, PZ)),
                ),
            )
        };
        let (sx, sy) = (
            _mm256_unpacklo_pd(xy.0, xy.1),
            _mm256_unpackhi_pd(xy.0, xy.1),
        );
        let (sz, r) = (
            _mm256_unpacklo_pd(zr.0, zr.1),
            _mm256_unpackhi_pd(zr.0, zr.1),
        );
        let gap = |v, l, h| {
            _mm256_max_pd(
                _mm256_max_pd(_mm256_sub_pd(l, v), _mm256_sub_pd(v, h)),
                zero,
            )
        };
        let (gx, gy, gz) = (gap(sx, lx, hx), gap(sy, ly, hy), gap(sz, lz, hz));
        let g2 = _mm256_add_pd(
            _mm256_add_pd(_mm256_mul_pd(gx, gx), _mm256_mul_pd(gy, gy)),
            _mm256_mul_pd(gz, gz),
        );
        let far = _mm256_mul_pd(r, vbound);
        let limit = _mm256_mul_pd(_mm256_mul_pd(far, far), margin);
        let out_of_reach = _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_GT_OQ>(g2, limit));
        for (k, &i) in q.iter().enumerate() {
            spare[n].write(i);
            n += (((out_of_reach >> k) & 1) ^ 1) as usize;
        }
    }
    // SAFETY: the first `n` of the spare room were written above (n <= ids.len(), reserved).
    unsafe { out.set_len(start + n) };
    sift_scalar(foot, quads.remainder(), (lo, hi), bound, out);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The lanes keep what the scalar sift keeps, and neither leaves out a sample that
    /// reaches some point of the sub-cell (points on its faces and corners, and inside).
    #[test]
    fn sift_keeps_every_sample_in_reach() {
        let mut seed = 7u64;
        let mut rnd = move || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut cache = Cache::with_pool(Vec::new(), 1);
        for i in 0..2000 {
            let p = DVec3::new(rnd(), rnd(), rnd()) * 4.0 - DVec3::splat(2.0);
            let r = match i % 97 {
                0 => f64::NAN,
                1 => f64::INFINITY,
                _ => 0.01 + rnd() * 0.8,
            };
            let p = if i % 89 == 0 {
                DVec3::new(f64::NAN, p.y, p.z)
            } else {
                p
            };
            let n = DVec3::Z;
            cache.samples.push(crate::scene::scratch::RadiositySample {
                p,
                n,
                irr: DVec3::ONE,
                r,
                level: 1,
            });
            cache.foot.push(cache.samples[i].footprint());
        }
        let ids: Vec<u32> = (0..2000).collect();
        for t in 0..200 {
            let sub = [0.125, 0.25, 0.5][t % 3];
            let bound = [0.5, 1.8][t % 2];
            let fine = [rnd(), rnd(), rnd()].map(|v| ((v * 4.0 - 2.0) / sub).floor());
            let (mut lanes, mut scalar) = (Vec::new(), Vec::new());
            sift(&cache, &ids[t % 5..], fine, sub, bound, &mut lanes);
            let lo = fine.map(|f| f * sub);
            let hi = fine.map(|f| (f + 1.0) * sub);
            sift_scalar(&cache.foot, &ids[t % 5..], (lo, hi), bound, &mut scalar);
            assert_eq!(lanes, scalar);
            for _ in 0..50 {
                // Inside, or on a face or corner (the upper ones just below, as a point of
                // the sub-cell is).
                let mut pick = |a: usize| match (rnd() * 4.0) as u32 {
                    0 => lo[a],
                    1 => hi[a] - hi[a].abs() * 1e-16 - 1e-300,
                    _ => lo[a] + rnd() * sub,
                };
                let p = DVec3::new(pick(0), pick(1), pick(2));
                for &i in &ids[t % 5..] {
                    let s = &cache.foot[i as usize];
                    if super::super::within(s, p, bound) {
                        assert!(
                            scalar.contains(&i),
                            "sample {i} reaches {p} but was left out"
                        );
                    }
                }
            }
        }
    }
}
