//! The magnet fractals' four orbits (a normal's samples) stepped in AVX registers written out
//! with intrinsics.
//!
//! Left to the vectoriser, `magnet_lanes` at four lanes came out as 256-bit registers in one
//! build and as 128-bit halves with spills in another, with no change to its source: which
//! one depended on how the crate happened to be split into codegen units (the thirtieth
//! pass: `magnet4_avx` 1,160 -> 1,385 lines of machine code and textures/patterns/fractals1
//! 7 % slower after a merge that only added a module). Intrinsics fix the register width.
//! Each lane is `magnet`'s arithmetic at its point, the same IEEE operations in the same
//! order (nothing fused), so the same bits.

use std::arch::x86_64::*;

use super::{exterior_value, magnet_start, orbit_value};
use crate::scene::pattern::Fractal;

/// A complex number per lane: real parts, imaginary parts.
type C4 = (__m256d, __m256d);

/// `magnet_lanes` for four lanes with AVX: the lanes' set-up, steps and ends in one
/// function, so the orbits stay in registers whatever the caller's codegen unit.
#[target_feature(enable = "avx")]
pub(super) unsafe fn magnet4_avx(f: &Fractal, ps: [(f64, f64); 4]) -> [f64; 4] {
    if f.magnet == 1 {
        magnet4_k::<1>(f, ps)
    } else {
        magnet4_k::<2>(f, ps)
    }
}

/// `(a, b, c, d)` as lanes 0 to 3.
#[target_feature(enable = "avx")]
#[inline]
unsafe fn lanes(v: [f64; 4]) -> __m256d {
    _mm256_loadu_pd(v.as_ptr())
}

/// `magnet4_avx` for magnet `KIND`: `magnet_lanes_k`'s loop.
#[target_feature(enable = "avx")]
#[inline]
unsafe fn magnet4_k<const KIND: u8>(f: &Fractal, ps: [(f64, f64); 4]) -> [f64; 4] {
    let start = ps.map(|p| magnet_start(f, p));
    let c1 = (lanes(start.map(|s| s.0 .0)), lanes(start.map(|s| s.0 .1)));
    let c2 = (lanes(start.map(|s| s.1 .0)), lanes(start.map(|s| s.1 .1)));
    let mut z = (lanes(start.map(|s| s.2 .0)), lanes(start.map(|s| s.2 .1)));
    let mut min_abs2 = lanes(start.map(|s| s.3));
    let mut out = [0.0; 4];
    let mut ended = 0u32;
    let (one, big, small) = (
        _mm256_set1_pd(1.0),
        _mm256_set1_pd(1e4),
        _mm256_set1_pd(1e-4),
    );
    let arr = |v: __m256d| {
        let mut a = [0.0; 4];
        _mm256_storeu_pd(a.as_mut_ptr(), v);
        a
    };
    for k in 0..f.iterations {
        z = step::<KIND>(z, c1, c2);
        let a2 = _mm256_add_pd(_mm256_mul_pd(z.0, z.0), _mm256_mul_pd(z.1, z.1));
        let r1 = _mm256_sub_pd(z.0, one);
        let d1 = _mm256_add_pd(_mm256_mul_pd(r1, r1), _mm256_mul_pd(z.1, z.1));
        let ends = _mm256_or_pd(
            _mm256_cmp_pd::<_CMP_GT_OQ>(a2, big),
            _mm256_cmp_pd::<_CMP_LT_OQ>(d1, small),
        );
        let new = _mm256_movemask_pd(ends) as u32 & !ended;
        if new != 0 {
            let (zr, zi, a2s, mins) = (arr(z.0), arr(z.1), arr(a2), arr(min_abs2));
            for l in (0..4).filter(|&l| new >> l & 1 != 0) {
                out[l] = exterior_value(f, k, zr[l], zi[l], a2s[l], mins[l]);
            }
            ended |= new;
            if ended == 0b1111 {
                return out;
            }
        }
        // `f64::min(min_abs2, a2)`: the other operand where one is NaN (minpd gives its
        // second where either is).
        let less = _mm256_min_pd(a2, min_abs2);
        let nan = _mm256_cmp_pd::<_CMP_UNORD_Q>(min_abs2, min_abs2);
        min_abs2 = _mm256_blendv_pd(less, a2, nan);
    }
    let (t, factor) = f.interior;
    let (zr, zi, mins) = (arr(z.0), arr(z.1), arr(min_abs2));
    for l in (0..4).filter(|&l| ended >> l & 1 == 0) {
        out[l] = orbit_value(t, zr[l], zi[l], mins[l]) * factor;
    }
    out
}

/// a·b, as `magnet_step`'s `mul`.
#[target_feature(enable = "avx")]
#[inline]
unsafe fn mul(a: C4, b: C4) -> C4 {
    (
        _mm256_sub_pd(_mm256_mul_pd(a.0, b.0), _mm256_mul_pd(a.1, b.1)),
        _mm256_add_pd(_mm256_mul_pd(a.0, b.1), _mm256_mul_pd(a.1, b.0)),
    )
}

/// a / b, as `magnet_step`'s `div`.
#[target_feature(enable = "avx")]
#[inline]
unsafe fn div(a: C4, b: C4) -> C4 {
    let d = _mm256_add_pd(_mm256_mul_pd(b.0, b.0), _mm256_mul_pd(b.1, b.1));
    (
        _mm256_div_pd(
            _mm256_add_pd(_mm256_mul_pd(a.0, b.0), _mm256_mul_pd(a.1, b.1)),
            d,
        ),
        _mm256_div_pd(
            _mm256_sub_pd(_mm256_mul_pd(a.1, b.0), _mm256_mul_pd(a.0, b.1)),
            d,
        ),
    )
}

/// `magnet_step(KIND, z, c1, c2)` in four lanes, operation for operation.
#[target_feature(enable = "avx")]
#[inline]
unsafe fn step<const KIND: u8>(z: C4, c1: C4, c2: C4) -> C4 {
    let add = |a: __m256d, b: __m256d| _mm256_add_pd(a, b);
    let times = |a: __m256d, b: __m256d| _mm256_mul_pd(a, b);
    let (two, three) = (_mm256_set1_pd(2.0), _mm256_set1_pd(3.0));
    let q = if KIND == 1 {
        let num = mul(z, z);
        div(
            (add(num.0, c1.0), add(num.1, c1.1)),
            (add(times(two, z.0), c2.0), add(times(two, z.1), c2.1)),
        )
    } else {
        let z2 = mul(z, z);
        let z3 = mul(z2, z);
        let cc = mul(c1, c2);
        let a = mul((times(three, c1.0), times(three, c1.1)), z);
        let b = mul((times(three, c2.0), times(three, c2.1)), z);
        div(
            (add(add(z3.0, a.0), cc.0), add(add(z3.1, a.1), cc.1)),
            (
                add(add(add(times(three, z2.0), b.0), cc.0), _mm256_set1_pd(1.0)),
                add(add(times(three, z2.1), b.1), cc.1),
            ),
        )
    };
    mul(q, q)
}
