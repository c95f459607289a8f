//! The lookups' blend of a listed cell (`Cache::near_memo`'s lists, kept in quads of four
//! samples field by field, `ListedQuad`) four samples at a time in AVX lanes. Each lane makes
//! `within`'s and `weight_listed`'s IEEE operations in their order (no FMA, the comparisons'
//! NaN cases kept), so every weight is the scalar one to the bit; the weights are then summed
//! one by one in the list's order, as `Blend::take` does, so the blend's sums are the same
//! bits too. On the radiosity scenes most of a lookup's work is reading these lists
//! (rad_def_test_37: ~800 k samples read, 45 % of them taken). Cells read
//! whole (not listed, listed for the first time, or read by a probe's lookup) have their
//! samples' reach and normal tested the same way (`quad_masks`); a whole read's weights are
//! then worked out in the lanes too (`quad_weights`), a listing's by the scalar code.

use crate::math::DVec3;

#[cfg(test)]
use super::weight_listed;
use super::{enough, normal_err, within, Blend, Cache, Footprint};
use crate::scene::scratch::ListedQuad;

/// `Blend::add_listed` of every sample of `quads` (a list, four samples a quad) that reaches
/// `p` (`within`), in the list's order.
#[inline]
pub(super) fn blend_listed(
    cache: &Cache,
    quads: &[ListedQuad],
    p: DVec3,
    bound: f64,
    b: &mut Blend,
) {
    #[cfg(target_arch = "x86_64")]
    if cache.lanes {
        // SAFETY: `lanes` is only set where the CPU has AVX (`Cache::with_pool`).
        unsafe { blend_listed_avx(&cache.irr, quads, p, bound, b) };
        return;
    }
    blend_listed_scalar(&cache.irr, quads, p, bound, b);
}

/// The scalar form: `within` and `weight_listed` of each sample, their operations in their
/// order on the quad's fields (which hold the same bits as what they compute from the
/// sample, the entry's normal and bound: `far2`, `front`, `mx`..`mz`).
pub(super) fn blend_listed_scalar(
    irr: &[DVec3],
    quads: &[ListedQuad],
    p: DVec3,
    bound: f64,
    b: &mut Blend,
) {
    for q in quads {
        for k in 0..4 {
            let (dx, dy, dz) = (p.x - q.px[k], p.y - q.py[k], p.z - q.pz[k]);
            let d2 = dx * dx + dy * dy + dz * dz;
            // Ordered: a NaN reaches nothing, as in `within`.
            let reach = d2 < q.far2[k];
            if !reach {
                continue;
            }
            let dist = d2.sqrt();
            if (dx * q.mx[k] + dy * q.my[k] + dz * q.mz[k]) * 0.5 < q.front[k] {
                continue;
            }
            let err = dist / q.r[k] + q.nerr[k];
            if err >= bound {
                continue;
            }
            b.take(irr[q.ids[k] as usize], Some((1.0 - err / bound).sqrt()));
        }
    }
}

/// `blend_listed_scalar` with the tests and weights of a quad's four samples in the lanes of
/// one register per quantity, each loaded whole from the quad. The same operations per lane
/// (no FMA; the comparisons' NaN cases kept: `d2 < far2` ordered, the front test kept where
/// not `<`, the error where not `>=`); the taken weights are then summed one by one in the
/// list's order, as `Blend::take` does.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
pub(super) unsafe fn blend_listed_avx(
    irr: &[DVec3],
    quads: &[ListedQuad],
    p: DVec3,
    bound: f64,
    b: &mut Blend,
) {
    use std::arch::x86_64::*;
    let (px, py, pz) = (
        _mm256_set1_pd(p.x),
        _mm256_set1_pd(p.y),
        _mm256_set1_pd(p.z),
    );
    let vbound = _mm256_set1_pd(bound);
    let half = _mm256_set1_pd(0.5);
    let one = _mm256_set1_pd(1.0);
    // The sums in registers: through `b` each was stored at every sample (a bounds check
    // may panic between two).
    let (mut sum, mut weight, mut count) = (b.sum, b.weight, b.count);
    for q in quads {
        macro_rules! load {
            ($f:expr) => {{
                let f: &[f64; 4] = $f;
                // SAFETY: four f64s of the quad.
                unsafe { _mm256_loadu_pd(f.as_ptr()) }
            }};
        }
        let dx = _mm256_sub_pd(px, load!(&q.px));
        let dy = _mm256_sub_pd(py, load!(&q.py));
        let dz = _mm256_sub_pd(pz, load!(&q.pz));
        let d2 = _mm256_add_pd(
            _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)),
            _mm256_mul_pd(dz, dz),
        );
        let reach = _mm256_cmp_pd::<_CMP_LT_OQ>(d2, load!(&q.far2));
        // Ward's front test: not (d · (n + s.n) · 0.5 < -0.05 · s.r).
        let dot = _mm256_add_pd(
            _mm256_add_pd(
                _mm256_mul_pd(dx, load!(&q.mx)),
                _mm256_mul_pd(dy, load!(&q.my)),
            ),
            _mm256_mul_pd(dz, load!(&q.mz)),
        );
        let behind = _mm256_cmp_pd::<_CMP_NLT_UQ>(_mm256_mul_pd(dot, half), load!(&q.front));
        // A quad none of whose lanes both reach and face the point skips the error's
        // square root and division: the divider's work is most of this loop's time (a ymm
        // `vsqrtpd` or `vdivpd` every ~2.2 ns here), and on rad_def_test_37 the front test
        // turns away a quarter of the lanes in reach.
        let front = _mm256_and_pd(reach, behind);
        if _mm256_movemask_pd(front) == 0 {
            continue;
        }
        // err = sqrt(d2) / s.r + normal_err; not (err >= bound).
        let err = _mm256_add_pd(
            _mm256_div_pd(_mm256_sqrt_pd(d2), load!(&q.r)),
            load!(&q.nerr),
        );
        let inside = _mm256_cmp_pd::<_CMP_NGE_UQ>(err, vbound);
        let take = _mm256_movemask_pd(_mm256_and_pd(front, inside));
        if take == 0 {
            continue;
        }
        let w = _mm256_sqrt_pd(_mm256_sub_pd(one, _mm256_div_pd(err, vbound)));
        let mut ws = [0.0; 4];
        _mm256_storeu_pd(ws.as_mut_ptr(), w);
        // The taken lanes by their set bits, in the ids' order: one loop whose length is the
        // count taken, rather than a branch per lane on an unpredictable mask.
        let mut left = take as u32;
        while left != 0 {
            let k = left.trailing_zeros() as usize;
            left &= left - 1;
            // `Blend::take`'s operations.
            sum += irr[q.ids[k] as usize] * ws[k];
            weight += ws[k];
            count += 1;
        }
    }
    (b.sum, b.weight, b.count) = (sum, weight, count);
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

/// `($foot, $q, $at)`: the four samples of `$q` (four ids of a cell, from the cache) and
/// the masks (bit k: sample k) of those that reach the lookup `$at` (`within`) and of those
/// not turned away by `weight`'s normal test (`cos < 0.5`; a NaN cosine passes, as there).
/// The same IEEE operations in the same order as the scalar tests (no FMA), so the same bits
/// decide. A macro, used in AVX functions only: as a function it was not inlined.
#[cfg(target_arch = "x86_64")]
macro_rules! quad_masks {
    ($foot:expr, $q:expr, $at:expr) => {{
        use std::arch::x86_64::*;
        let (foot, q, at): (&[Footprint], &[u32], &Lookup4) = ($foot, $q, $at);
        let s = [q[0], q[1], q[2], q[3]].map(|i| &foot[i as usize]);
        let ptr =
            |k: usize, field: usize| (s[k] as *const Footprint as *const f64).wrapping_add(field);
        // SAFETY: as in `blend_listed_avx`: pairs of consecutive f64 fields of a `Footprint`
        // (`PX`, `PZ`, `NX`), lanes 0 and 2 of one register and 1 and 3 of the other.
        let (xy, zr, nxy) = unsafe {
            (
                (
                    _mm256_loadu2_m128d(ptr(2, PX), ptr(0, PX)),
                    _mm256_loadu2_m128d(ptr(3, PX), ptr(1, PX)),
                ),
                (
                    _mm256_loadu2_m128d(ptr(2, PZ), ptr(0, PZ)),
                    _mm256_loadu2_m128d(ptr(3, PZ), ptr(1, PZ)),
                ),
                (
                    _mm256_loadu2_m128d(ptr(2, NX), ptr(0, NX)),
                    _mm256_loadu2_m128d(ptr(3, NX), ptr(1, NX)),
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
        let (snx, sny) = (
            _mm256_unpacklo_pd(nxy.0, nxy.1),
            _mm256_unpackhi_pd(nxy.0, nxy.1),
        );
        let snz = _mm256_set_pd(s[3].n.z, s[2].n.z, s[1].n.z, s[0].n.z);
        let (dx, dy, dz) = (
            _mm256_sub_pd(at.px, sx),
            _mm256_sub_pd(at.py, sy),
            _mm256_sub_pd(at.pz, sz),
        );
        let d2 = _mm256_add_pd(
            _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)),
            _mm256_mul_pd(dz, dz),
        );
        let far = _mm256_mul_pd(r, at.bound);
        let reach = _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_LT_OQ>(d2, _mm256_mul_pd(far, far)));
        // `n.dot(s.n)`: (x·x' + y·y') + z·z'.
        let cos = _mm256_add_pd(
            _mm256_add_pd(_mm256_mul_pd(at.nx, snx), _mm256_mul_pd(at.ny, sny)),
            _mm256_mul_pd(at.nz, snz),
        );
        let facing = _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_NLT_UQ>(cos, at.half));
        let lanes = Quad4 {
            dx,
            dy,
            dz,
            d2,
            r,
            cos,
            snx,
            sny,
            snz,
        };
        (s, reach, facing, lanes)
    }};
}

/// What `quad_masks` worked out of a quad's four samples for a lookup, one lane each: the
/// offsets from the samples to the point, their squared length, the samples' harmonic
/// distances, normals, and cosines with the lookup's normal.
#[cfg(target_arch = "x86_64")]
struct Quad4 {
    dx: std::arch::x86_64::__m256d,
    dy: std::arch::x86_64::__m256d,
    dz: std::arch::x86_64::__m256d,
    d2: std::arch::x86_64::__m256d,
    r: std::arch::x86_64::__m256d,
    cos: std::arch::x86_64::__m256d,
    snx: std::arch::x86_64::__m256d,
    sny: std::arch::x86_64::__m256d,
    snz: std::arch::x86_64::__m256d,
}

/// `weight_tail`'s operations in the lanes (after `quad_masks`' reach and normal tests):
/// each lane's weight (the scalar's bits, NaN where it is NaN) and the mask of the lanes whose
/// front and error tests pass. The same IEEE operations in the same order, no FMA; where
/// the scalar code returns None on `<` or `>=`, the lane is kept on the unordered negation.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn quad_weights(at: &Lookup4, q: &Quad4) -> (std::arch::x86_64::__m256d, i32) {
    use std::arch::x86_64::*;
    let dist = _mm256_sqrt_pd(q.d2);
    // Ward's front test: not (d · (n + s.n) · 0.5 < -0.05 · s.r).
    let (mx, my, mz) = (
        _mm256_add_pd(at.nx, q.snx),
        _mm256_add_pd(at.ny, q.sny),
        _mm256_add_pd(at.nz, q.snz),
    );
    let dot = _mm256_add_pd(
        _mm256_add_pd(_mm256_mul_pd(q.dx, mx), _mm256_mul_pd(q.dy, my)),
        _mm256_mul_pd(q.dz, mz),
    );
    let front = _mm256_mul_pd(_mm256_set1_pd(-0.05), q.r);
    let behind = _mm256_cmp_pd::<_CMP_NLT_UQ>(_mm256_mul_pd(dot, at.half), front);
    // `normal_err`: 2 · sqrt(max(1 - cos, 0)), `max` giving 0 for a NaN as `f64::max` does
    // (`maxpd` returns its second operand when either is NaN).
    let one = _mm256_set1_pd(1.0);
    let turn = _mm256_max_pd(_mm256_sub_pd(one, q.cos), _mm256_setzero_pd());
    let nerr = _mm256_mul_pd(_mm256_set1_pd(2.0), _mm256_sqrt_pd(turn));
    let err = _mm256_add_pd(_mm256_div_pd(dist, q.r), nerr);
    let inside = _mm256_cmp_pd::<_CMP_NGE_UQ>(err, at.bound);
    let w = _mm256_sqrt_pd(_mm256_sub_pd(one, _mm256_div_pd(err, at.bound)));
    (w, _mm256_movemask_pd(_mm256_and_pd(behind, inside)))
}

/// A lookup's point, normal and bound in every lane.
#[cfg(target_arch = "x86_64")]
struct Lookup4 {
    px: std::arch::x86_64::__m256d,
    py: std::arch::x86_64::__m256d,
    pz: std::arch::x86_64::__m256d,
    nx: std::arch::x86_64::__m256d,
    ny: std::arch::x86_64::__m256d,
    nz: std::arch::x86_64::__m256d,
    bound: std::arch::x86_64::__m256d,
    half: std::arch::x86_64::__m256d,
}

#[cfg(target_arch = "x86_64")]
impl Lookup4 {
    #[target_feature(enable = "avx")]
    fn new(p: DVec3, n: DVec3, bound: f64) -> Lookup4 {
        use std::arch::x86_64::_mm256_set1_pd as splat;
        Lookup4 {
            px: splat(p.x),
            py: splat(p.y),
            pz: splat(p.z),
            nx: splat(n.x),
            ny: splat(n.y),
            nz: splat(n.z),
            bound: splat(bound),
            half: splat(0.5),
        }
    }
}

/// `Blend::add` (level 1) of every sample of `ids` (a cell's) that reaches `p` (`within`),
/// in their order, until the blend is `enough` (then false). A sample `weight` turns away
/// for its normal adds nothing and leaves `enough` as it was, so the lanes skip it: most
/// samples a probe's lookup meets in reach face another way (rad_def_test_37: 80 k of 119 k).
#[inline(always)]
pub(super) fn blend_until(
    cache: &Cache,
    ids: &[u32],
    (p, n): (DVec3, DVec3),
    bound: f64,
    need: u32,
    b: &mut Blend,
) -> bool {
    blend_taken(cache, ids, (p, n), 1, bound, b, |b| enough(b, need))
}

/// `Blend::add` of every sample of `ids` (a cell read whole) that reaches `p`, in their
/// order. The lanes skip the samples out of reach or facing another way, which `weight`
/// turns away (radiosity2's curved surfaces: 84 % out of reach).
#[inline(always)]
pub(super) fn blend_whole(
    cache: &Cache,
    ids: &[u32],
    (p, n): (DVec3, DVec3),
    level: u32,
    bound: f64,
    b: &mut Blend,
) {
    blend_taken(cache, ids, (p, n), level, bound, b, |_| false);
}

/// `Blend::add` at `level` of every sample of `ids` that reaches `p`, in their order, until
/// `done` says the blend has enough (then false).
#[inline(always)]
fn blend_taken(
    cache: &Cache,
    ids: &[u32],
    (p, n): (DVec3, DVec3),
    level: u32,
    bound: f64,
    b: &mut Blend,
    done: impl Fn(&Blend) -> bool,
) -> bool {
    #[cfg(target_arch = "x86_64")]
    if cache.lanes && ids.len() >= 4 {
        // SAFETY: `lanes` is only set where the CPU has AVX (`Cache::with_pool`).
        return unsafe {
            blend_taken_avx(&cache.foot, &cache.irr, ids, (p, n), level, bound, b, done)
        };
    }
    blend_taken_scalar(&cache.foot, &cache.irr, ids, (p, n), level, bound, b, done)
}

#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn blend_taken_scalar(
    foot: &[Footprint],
    irr: &[DVec3],
    ids: &[u32],
    (p, n): (DVec3, DVec3),
    level: u32,
    bound: f64,
    b: &mut Blend,
    done: impl Fn(&Blend) -> bool,
) -> bool {
    for &i in ids {
        let s = &foot[i as usize];
        if within(s, p, bound) {
            b.add(s, irr[i as usize], p, n, level, bound);
            if done(b) {
                return false;
            }
        }
    }
    true
}

#[allow(clippy::too_many_arguments)]
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
unsafe fn blend_taken_avx(
    foot: &[Footprint],
    irr: &[DVec3],
    ids: &[u32],
    (p, n): (DVec3, DVec3),
    level: u32,
    bound: f64,
    b: &mut Blend,
    done: impl Fn(&Blend) -> bool,
) -> bool {
    use std::arch::x86_64::_mm256_storeu_pd;
    let at = Lookup4::new(p, n, bound);
    let mut quads = ids.chunks_exact(4);
    for q in &mut quads {
        let (s, reach, facing, lanes) = quad_masks!(foot, q, &at);
        // `weight`'s level test too: deeper lookups' cells hold samples of deeper levels.
        let low = (0..4).fold(0, |m, k| m | (i32::from(s[k].level <= level) << k));
        let near = reach & facing & low;
        if near == 0 {
            continue;
        }
        // The weights of the four at once: one chain of divisions and square roots instead
        // of one per sample taken (radiosity2's curved surfaces read whole cells).
        let (w, kept) = quad_weights(&at, &lanes);
        let take = near & kept;
        if take == 0 {
            continue;
        }
        let mut ws = [0.0; 4];
        _mm256_storeu_pd(ws.as_mut_ptr(), w);
        // `Blend::take`'s operations, in the ids' order, by the taken lanes' set bits (as
        // in `blend_listed_avx`).
        let mut left = take as u32;
        while left != 0 {
            let k = left.trailing_zeros() as usize;
            left &= left - 1;
            b.take(irr[q[k] as usize], Some(ws[k]));
            if done(b) {
                return false;
            }
        }
    }
    blend_taken_scalar(foot, irr, quads.remainder(), (p, n), level, bound, b, done)
}

/// A list being made (`list_cell`): its quads, and how many samples it holds.
pub(super) struct Listing<'l> {
    pub(super) quads: &'l mut Vec<ListedQuad>,
    pub(super) len: usize,
}

/// A quad's padding: a lane that reaches nothing (`d2 < -1` never holds).
const PAD: ListedQuad = ListedQuad {
    px: [0.0; 4],
    py: [0.0; 4],
    pz: [0.0; 4],
    far2: [-1.0; 4],
    r: [1.0; 4],
    front: [0.0; 4],
    mx: [0.0; 4],
    my: [0.0; 4],
    mz: [0.0; 4],
    nerr: [0.0; 4],
    ids: [0; 4],
};

impl Listing<'_> {
    /// Appends sample `i` (`s`), of `normal_err` `e`, for the entry's normal `n` and bound.
    #[inline(always)]
    fn push(&mut self, s: &Footprint, i: u32, e: f64, n: DVec3, bound: f64) {
        let k = self.len % 4;
        if k == 0 {
            self.quads.push(PAD);
        }
        let Some(q) = self.quads.last_mut() else {
            unreachable!("a quad was pushed")
        };
        // `within`'s and `weight_tail`'s operations on the sample alone or with n and bound.
        let far = s.r * bound;
        q.px[k] = s.p.x;
        q.py[k] = s.p.y;
        q.pz[k] = s.p.z;
        q.far2[k] = far * far;
        q.r[k] = s.r;
        q.front[k] = -0.05 * s.r;
        let m = n + s.n;
        q.mx[k] = m.x;
        q.my[k] = m.y;
        q.mz[k] = m.z;
        q.nerr[k] = e;
        q.ids[k] = i;
        self.len += 1;
    }
}

/// A cell's first read by a memo entry (`near_memo`): lists each sample of `ids` that
/// `weight`'s level and normal tests let through for `n`, with its `normal_err`, and blends
/// those in reach, in their order. The lanes skip the samples facing another way (raddem:
/// 70 % of those listing reads).
#[inline(always)]
pub(super) fn list_cell(
    cache: &Cache,
    ids: &[u32],
    (p, n): (DVec3, DVec3),
    level: u32,
    bound: f64,
    list: &mut Listing,
    b: &mut Blend,
) {
    #[cfg(target_arch = "x86_64")]
    if cache.lanes && ids.len() >= 4 {
        // SAFETY: `lanes` is only set where the CPU has AVX (`Cache::with_pool`).
        unsafe { list_cell_avx(&cache.foot, &cache.irr, ids, (p, n), level, bound, list, b) };
        return;
    }
    for &i in ids {
        list_one(&cache.foot, &cache.irr, i, (p, n), level, bound, list, b);
    }
}

/// One sample of `list_cell`: `near_memo`'s listing loop's body as it was.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn list_one(
    foot: &[Footprint],
    irr: &[DVec3],
    i: u32,
    (p, n): (DVec3, DVec3),
    level: u32,
    bound: f64,
    list: &mut Listing,
    b: &mut Blend,
) {
    let s = &foot[i as usize];
    // `weight`'s first tests, as it writes them (a NaN cosine passes).
    let cos = n.dot(s.n);
    if s.level > level || cos < 0.5 {
        return;
    }
    let e = normal_err(cos);
    list.push(s, i, e, n, bound);
    if within(s, p, bound) {
        b.add_listed(s, irr[i as usize], p, n, bound, e);
    }
}

#[allow(clippy::too_many_arguments)]
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
unsafe fn list_cell_avx(
    foot: &[Footprint],
    irr: &[DVec3],
    ids: &[u32],
    (p, n): (DVec3, DVec3),
    level: u32,
    bound: f64,
    list: &mut Listing,
    b: &mut Blend,
) {
    let at = Lookup4::new(p, n, bound);
    let mut quads = ids.chunks_exact(4);
    for q in &mut quads {
        let (_, _, facing, _) = quad_masks!(foot, q, &at);
        if facing == 0 {
            continue;
        }
        for (k, &i) in q.iter().enumerate() {
            if facing & (1 << k) != 0 {
                list_one(foot, irr, i, (p, n), level, bound, list, b);
            }
        }
    }
    for &i in quads.remainder() {
        list_one(foot, irr, i, (p, n), level, bound, list, b);
    }
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

    /// A blend's fields as bits, to compare two blends exactly.
    fn bits(b: &Blend) -> (u32, u64, [u64; 3]) {
        (
            b.count,
            b.weight.to_bits(),
            b.sum.to_array().map(f64::to_bits),
        )
    }

    /// The lanes of `blend_until`, `blend_whole` and `list_cell` give what their scalar
    /// loops give, to the bit, stopping where they stop: cells of every length, points near
    /// and far, normals every way, a few NaN and infinite fields.
    #[test]
    fn lanes_read_cells_as_the_scalar_loops() {
        if !crate::math::has_avx() {
            return;
        }
        let (mut foot, irr) = footprints();
        for (k, s) in foot.iter_mut().enumerate() {
            s.level = 1 + (k % 5 == 0) as u32;
            if k % 89 == 7 {
                s.n.z = f64::NAN;
            }
        }
        let mut rnd = rng(11);
        for trial in 0..400 {
            let p = DVec3::new(rnd(), rnd(), rnd()) * 4.0;
            let n = DVec3::new(rnd() - 0.5, rnd() - 0.5, rnd() - 0.5).normalize();
            let bound = [0.2, 0.9, 1.8][trial % 3];
            let level = 1 + (trial % 2) as u32;
            let need = (trial % 9) as u32;
            let ids: Vec<u32> = (0..trial % 45)
                .map(|_| (rnd() * foot.len() as f64) as u32)
                .collect();
            let (mut want, mut got) = (Blend::default(), Blend::default());
            let until = |b: &Blend| enough(b, need);
            let stop_want =
                blend_taken_scalar(&foot, &irr, &ids, (p, n), 1, bound, &mut want, until);
            // SAFETY: the CPU has AVX (checked above).
            let stop_got =
                unsafe { blend_taken_avx(&foot, &irr, &ids, (p, n), 1, bound, &mut got, until) };
            assert_eq!(stop_got, stop_want, "trial {trial}");
            assert_eq!(bits(&got), bits(&want), "blend_until, trial {trial}");

            let (mut want, mut got) = (Blend::default(), Blend::default());
            let whole = |_: &Blend| false;
            blend_taken_scalar(&foot, &irr, &ids, (p, n), level, bound, &mut want, whole);
            // SAFETY: the CPU has AVX (checked above).
            unsafe { blend_taken_avx(&foot, &irr, &ids, (p, n), level, bound, &mut got, whole) };
            assert_eq!(bits(&got), bits(&want), "blend_whole, trial {trial}");

            let (mut want, mut got) = (Blend::default(), Blend::default());
            let (mut quads_want, mut quads_got) = (Vec::new(), Vec::new());
            let mut list_want = Listing {
                quads: &mut quads_want,
                len: 0,
            };
            for &i in &ids {
                list_one(
                    &foot,
                    &irr,
                    i,
                    (p, n),
                    level,
                    bound,
                    &mut list_want,
                    &mut want,
                );
            }
            let mut list_got = Listing {
                quads: &mut quads_got,
                len: 0,
            };
            // SAFETY: the CPU has AVX (checked above).
            unsafe {
                list_cell_avx(
                    &foot,
                    &irr,
                    &ids,
                    (p, n),
                    level,
                    bound,
                    &mut list_got,
                    &mut got,
                )
            };
            assert_eq!(list_got.len, list_want.len, "trial {trial}");
            assert_eq!(bits(&got), bits(&want), "list_cell, trial {trial}");
            let as_bits = |l: &[ListedQuad]| -> Vec<u64> { l.iter().flat_map(quad_bits).collect() };
            assert_eq!(as_bits(&quads_got), as_bits(&quads_want), "trial {trial}");
        }
    }

    /// Every field of a quad, as bits.
    fn quad_bits(q: &ListedQuad) -> Vec<u64> {
        let fields = [
            q.px, q.py, q.pz, q.far2, q.r, q.front, q.mx, q.my, q.mz, q.nerr,
        ];
        let mut out: Vec<u64> = fields.iter().flatten().map(|v| v.to_bits()).collect();
        out.extend(q.ids.map(u64::from));
        out
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
            // The list as `near_memo` makes it, and the blend `within` and `weight_listed`
            // give of it in its order (`near_memo`'s loop before the quads).
            let mut quads = Vec::new();
            let mut list = Listing {
                quads: &mut quads,
                len: 0,
            };
            let mut want = Blend::default();
            for &(i, e) in &items {
                let s = &foot[i as usize];
                list.push(s, i, e, n, bound);
                if within(s, p, bound) {
                    want.add_listed(s, irr[i as usize], p, n, bound, e);
                }
            }
            let (mut scalar, mut got) = (Blend::default(), Blend::default());
            blend_listed_scalar(&irr, &quads, p, bound, &mut scalar);
            // SAFETY: the CPU has AVX (checked above).
            unsafe { blend_listed_avx(&irr, &quads, p, bound, &mut got) };
            assert_eq!(bits(&scalar), bits(&want), "trial {trial}");
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
