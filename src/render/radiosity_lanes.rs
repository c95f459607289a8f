//! The lookups' blend of a listed cell (`Cache::near_memo`'s lists) four samples at a time in
//! AVX lanes. Each lane makes `within`'s and `weight_listed`'s IEEE operations in their order
//! (no FMA, the comparisons' NaN cases kept), so every weight is the scalar one to the bit;
//! the weights are then summed one by one in the list's order, as `Blend::take` does, so the
//! blend's sums are the same bits too. On the radiosity scenes most of a lookup's work is
//! reading these lists (rad_def_test_37: ~800 k samples read, 45 % of them taken). Cells read
//! whole (not listed) have their samples' reach tested the same way (`each_within`).

use crate::math::DVec3;

#[cfg(test)]
use super::weight_listed;
use super::{within, Blend, Cache, Footprint};

/// `Blend::add_listed` of every sample of `items` (a list: (sample, its `normal_err`)) that
/// reaches `p` (`within`), in the list's order.
#[inline]
pub(super) fn blend_listed(
    cache: &Cache,
    items: &[(u32, f64)],
    p: DVec3,
    n: DVec3,
    bound: f64,
    b: &mut Blend,
) {
    let (foot, irr) = (&cache.foot[..], &cache.irr[..]);
    #[cfg(target_arch = "x86_64")]
    if cache.lanes && items.len() >= 4 {
        // SAFETY: `lanes` is only set where the CPU has AVX (`Cache::with_pool`).
        unsafe { blend_listed_avx(foot, irr, items, p, n, bound, b) };
        return;
    }
    blend_listed_scalar(foot, irr, items, p, n, bound, b);
}

/// The scalar form (and the lanes' tail): `near_memo`'s loop as it was.
#[inline(always)]
pub(super) fn blend_listed_scalar(
    foot: &[Footprint],
    irr: &[DVec3],
    items: &[(u32, f64)],
    p: DVec3,
    n: DVec3,
    bound: f64,
    b: &mut Blend,
) {
    for &(i, e) in items {
        let s = &foot[i as usize];
        if within(s, p, bound) {
            b.add_listed(s, irr[i as usize], p, n, bound, e);
        }
    }
}

/// Where the lanes load pairs of a `Footprint`'s fields from, in f64s: (p.x, p.y), (p.z, r),
/// (n.x, n.y).
const PX: usize = 0;
const PZ: usize = 2;
const NX: usize = 4;
const _: () = {
    use std::mem::offset_of;
    assert!(offset_of!(Footprint, p) == PX * 8 && offset_of!(DVec3, x) == 0);
    assert!(offset_of!(DVec3, y) == 8 && offset_of!(DVec3, z) == 16);
    assert!(offset_of!(Footprint, r) == PZ * 8 + 8);
    assert!(offset_of!(Footprint, n) == NX * 8);
};

/// `blend_listed_scalar` with the tests and weights of four samples in the lanes of one
/// register per quantity.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
pub(super) unsafe fn blend_listed_avx(
    foot: &[Footprint],
    irr: &[DVec3],
    items: &[(u32, f64)],
    p: DVec3,
    n: DVec3,
    bound: f64,
    b: &mut Blend,
) {
    use std::arch::x86_64::*;
    let (px, py, pz) = (
        _mm256_set1_pd(p.x),
        _mm256_set1_pd(p.y),
        _mm256_set1_pd(p.z),
    );
    let (nx, ny, nz) = (
        _mm256_set1_pd(n.x),
        _mm256_set1_pd(n.y),
        _mm256_set1_pd(n.z),
    );
    let vbound = _mm256_set1_pd(bound);
    let half = _mm256_set1_pd(0.5);
    let front = _mm256_set1_pd(-0.05);
    let one = _mm256_set1_pd(1.0);
    // The sums in registers: through `b` each was stored at every sample (a bounds check
    // may panic between two).
    let (mut sum, mut weight, mut count) = (b.sum, b.weight, b.count);
    let irr = &irr[..foot.len()];
    let mut quads = items.chunks_exact(4);
    for q in &mut quads {
        let ids = [q[0].0, q[1].0, q[2].0, q[3].0].map(|i| i as usize);
        // One bounds check for the four (and for `irr`, as long).
        let top = ids[0].max(ids[1]).max(ids[2].max(ids[3]));
        let (foot, irr) = (&foot[..=top], &irr[..=top]);
        let s = ids.map(|i| &foot[i]);
        // Pairs of neighbouring fields, lanes 0 and 2 of one register and 1 and 3 of the
        // other, then split into one register per field by the unpacks.
        let at =
            |k: usize, field: usize| (s[k] as *const Footprint as *const f64).wrapping_add(field);
        macro_rules! pair {
            ($field:expr) => {{
                // SAFETY: `field` is the place (in f64s) of the first of two consecutive f64
                // fields of a `Footprint` (`PX`, `PZ`, `NX`, checked above): inside the value.
                let (even, odd) = unsafe {
                    (
                        _mm256_loadu2_m128d(at(2, $field), at(0, $field)),
                        _mm256_loadu2_m128d(at(3, $field), at(1, $field)),
                    )
                };
                (_mm256_unpacklo_pd(even, odd), _mm256_unpackhi_pd(even, odd))
            }};
        }
        let (sx, sy) = pair!(PX);
        let (sz, r) = pair!(PZ);
        let (snx, sny) = pair!(NX);
        let snz = _mm256_set_pd(s[3].n.z, s[2].n.z, s[1].n.z, s[0].n.z);
        // `within`: (p - s.p).length_squared() < (s.r * bound)².
        let (dx, dy, dz) = (
            _mm256_sub_pd(px, sx),
            _mm256_sub_pd(py, sy),
            _mm256_sub_pd(pz, sz),
        );
        let d2 = _mm256_add_pd(
            _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)),
            _mm256_mul_pd(dz, dz),
        );
        let far = _mm256_mul_pd(r, vbound);
        let reach = _mm256_cmp_pd::<_CMP_LT_OQ>(d2, _mm256_mul_pd(far, far));
        if _mm256_movemask_pd(reach) == 0 {
            continue;
        }
        // Ward's front test: not (d · (n + s.n) · 0.5 < -0.05 · s.r).
        let dot = _mm256_add_pd(
            _mm256_add_pd(
                _mm256_mul_pd(dx, _mm256_add_pd(nx, snx)),
                _mm256_mul_pd(dy, _mm256_add_pd(ny, sny)),
            ),
            _mm256_mul_pd(dz, _mm256_add_pd(nz, snz)),
        );
        let behind =
            _mm256_cmp_pd::<_CMP_NLT_UQ>(_mm256_mul_pd(dot, half), _mm256_mul_pd(front, r));
        // err = sqrt(d2) / s.r + normal_err; not (err >= bound).
        let nerr = _mm256_set_pd(q[3].1, q[2].1, q[1].1, q[0].1);
        let err = _mm256_add_pd(_mm256_div_pd(_mm256_sqrt_pd(d2), r), nerr);
        let inside = _mm256_cmp_pd::<_CMP_NGE_UQ>(err, vbound);
        let w = _mm256_sqrt_pd(_mm256_sub_pd(one, _mm256_div_pd(err, vbound)));
        let take = _mm256_movemask_pd(_mm256_and_pd(_mm256_and_pd(reach, behind), inside));
        if take == 0 {
            continue;
        }
        let mut ws = [0.0; 4];
        _mm256_storeu_pd(ws.as_mut_ptr(), w);
        for (k, (&i, &w)) in ids.iter().zip(&ws).enumerate() {
            if take & (1 << k) != 0 {
                // `Blend::take`'s operations.
                sum += irr[i] * w;
                weight += w;
                count += 1;
            }
        }
    }
    (b.sum, b.weight, b.count) = (sum, weight, count);
    blend_listed_scalar(foot, irr, quads.remainder(), p, n, bound, b);
}

/// `f` of every sample of `ids` that reaches `p` (`within`), in their order, until `f`
/// returns false (then false). The reach of four samples is tested at a time where the CPU
/// has AVX: in a cell read whole most samples are out of reach (radiosity2's lookups on its
/// curved surfaces: 84 %).
#[inline(always)]
pub(super) fn each_within(
    cache: &Cache,
    ids: &[u32],
    p: DVec3,
    bound: f64,
    f: impl FnMut(usize, &Footprint) -> bool,
) -> bool {
    #[cfg(target_arch = "x86_64")]
    if cache.lanes && ids.len() >= 4 {
        // SAFETY: `lanes` is only set where the CPU has AVX (`Cache::with_pool`).
        return unsafe { each_within_avx(&cache.foot, ids, p, bound, f) };
    }
    each_within_scalar(&cache.foot, ids, p, bound, f)
}

#[inline(always)]
fn each_within_scalar(
    foot: &[Footprint],
    ids: &[u32],
    p: DVec3,
    bound: f64,
    mut f: impl FnMut(usize, &Footprint) -> bool,
) -> bool {
    for &i in ids {
        let s = &foot[i as usize];
        if within(s, p, bound) && !f(i as usize, s) {
            return false;
        }
    }
    true
}

/// `each_within_scalar` with `within` of four samples in the lanes of one register per
/// quantity (its IEEE operations in its order, so the same samples pass).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
unsafe fn each_within_avx(
    foot: &[Footprint],
    ids: &[u32],
    p: DVec3,
    bound: f64,
    mut f: impl FnMut(usize, &Footprint) -> bool,
) -> bool {
    use std::arch::x86_64::*;
    let (px, py, pz) = (
        _mm256_set1_pd(p.x),
        _mm256_set1_pd(p.y),
        _mm256_set1_pd(p.z),
    );
    let vbound = _mm256_set1_pd(bound);
    let mut quads = ids.chunks_exact(4);
    for q in &mut quads {
        let ids = [q[0], q[1], q[2], q[3]].map(|i| i as usize);
        let s = ids.map(|i| &foot[i]);
        let at =
            |k: usize, field: usize| (s[k] as *const Footprint as *const f64).wrapping_add(field);
        // SAFETY: as in `blend_listed_avx`: pairs of consecutive f64 fields of a `Footprint`.
        let (xy, zr) = unsafe {
            let xy = (
                _mm256_loadu2_m128d(at(2, PX), at(0, PX)),
                _mm256_loadu2_m128d(at(3, PX), at(1, PX)),
            );
            let zr = (
                _mm256_loadu2_m128d(at(2, PZ), at(0, PZ)),
                _mm256_loadu2_m128d(at(3, PZ), at(1, PZ)),
            );
            (xy, zr)
        };
        let dx = _mm256_sub_pd(px, _mm256_unpacklo_pd(xy.0, xy.1));
        let dy = _mm256_sub_pd(py, _mm256_unpackhi_pd(xy.0, xy.1));
        let dz = _mm256_sub_pd(pz, _mm256_unpacklo_pd(zr.0, zr.1));
        let r = _mm256_unpackhi_pd(zr.0, zr.1);
        let d2 = _mm256_add_pd(
            _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)),
            _mm256_mul_pd(dz, dz),
        );
        let far = _mm256_mul_pd(r, vbound);
        let reach = _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_LT_OQ>(d2, _mm256_mul_pd(far, far)));
        if reach == 0 {
            continue;
        }
        for k in 0..4 {
            if reach & (1 << k) != 0 && !f(ids[k], s[k]) {
                return false;
            }
        }
    }
    each_within_scalar(foot, quads.remainder(), p, bound, f)
}

/// The scalar weight of a listed sample, for the tests: `weight_listed` behind `within`.
#[cfg(test)]
fn listed_weight(s: &Footprint, p: DVec3, n: DVec3, bound: f64, e: f64) -> Option<f64> {
    if within(s, p, bound) {
        weight_listed(s, p, n, bound, e)
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Numbers in [0, 1) from a xorshift of `seed`.
    fn rng(mut seed: u64) -> impl FnMut() -> f64 {
        move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    /// 400 samples in a 4-unit cube facing every way, a few with a NaN or infinite field.
    fn footprints() -> (Vec<Footprint>, Vec<DVec3>) {
        let mut rnd = rng(3);
        let mut foot = Vec::new();
        let mut irr = Vec::new();
        for k in 0..400 {
            let mut p = DVec3::new(rnd(), rnd(), rnd()) * 4.0;
            let mut r = 0.05 + rnd() * 2.0;
            let nv = DVec3::new(rnd() - 0.5, rnd() - 0.5, rnd() - 0.5).normalize();
            match k % 97 {
                13 => p.y = f64::NAN,
                29 => r = f64::NAN,
                41 => r = f64::INFINITY,
                _ => {}
            }
            foot.push(Footprint {
                p,
                r,
                n: nv,
                level: 1,
            });
            irr.push(DVec3::new(rnd(), rnd(), rnd()));
        }
        (foot, irr)
    }

    /// The lanes find the samples in reach the scalar loop finds, in its order, and stop
    /// where it stops.
    #[test]
    fn lanes_find_what_within_finds() {
        if !crate::math::has_avx() {
            return;
        }
        let (foot, _) = footprints();
        let mut rnd = rng(5);
        for trial in 0..400 {
            let p = DVec3::new(rnd(), rnd(), rnd()) * 4.0;
            let bound = [0.2, 0.9, 1.8][trial % 3];
            let ids: Vec<u32> = (0..trial % 45)
                .map(|_| (rnd() * foot.len() as f64) as u32)
                .collect();
            let stop = trial % 7;
            let run = |lanes: bool| {
                let mut met = Vec::new();
                let f = |i: usize, _: &Footprint| {
                    met.push(i);
                    met.len() != stop
                };
                let done = if lanes {
                    // SAFETY: the CPU has AVX (checked above).
                    unsafe { each_within_avx(&foot, &ids, p, bound, f) }
                } else {
                    each_within_scalar(&foot, &ids, p, bound, f)
                };
                (done, met)
            };
            assert_eq!(run(true), run(false), "trial {trial}");
        }
    }

    /// The lanes blend lists of every length as the scalar loop does, to the bit: points
    /// near and far, samples facing every way (some behind the point), reaches around the
    /// bound, and a few NaN and infinite fields.
    #[test]
    fn lanes_blend_as_the_scalar_loop() {
        if !crate::math::has_avx() {
            return;
        }
        let (foot, irr) = footprints();
        let mut rnd = rng(7);
        for trial in 0..300 {
            let p = DVec3::new(rnd(), rnd(), rnd()) * 4.0;
            let n = DVec3::new(rnd() - 0.5, rnd() - 0.5, rnd() - 0.5).normalize();
            let bound = [0.2, 0.9, 1.8][trial % 3];
            let len = trial % 41;
            let items: Vec<(u32, f64)> = (0..len)
                .map(|_| {
                    let i = (rnd() * foot.len() as f64) as u32;
                    let e = if trial % 53 == 4 {
                        f64::NAN
                    } else {
                        rnd() * 0.8
                    };
                    (i, e)
                })
                .collect();
            let (mut want, mut got) = (Blend::default(), Blend::default());
            blend_listed_scalar(&foot, &irr, &items, p, n, bound, &mut want);
            // SAFETY: the CPU has AVX (checked above).
            unsafe { blend_listed_avx(&foot, &irr, &items, p, n, bound, &mut got) };
            let taken = items
                .iter()
                .filter(|&&(i, e)| listed_weight(&foot[i as usize], p, n, bound, e).is_some())
                .count();
            assert_eq!(got.count as usize, taken);
            assert_eq!(got.count, want.count, "trial {trial}");
            assert_eq!(got.weight.to_bits(), want.weight.to_bits(), "trial {trial}");
            assert_eq!(
                got.sum.to_array().map(f64::to_bits),
                want.sum.to_array().map(f64::to_bits),
                "trial {trial}"
            );
        }
    }
}
