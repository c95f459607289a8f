//! The four children's tests of a pyramid block (`walk::visit_signed`) in one 256-bit AVX
//! register per quantity, lane `g` holding child `g` in the order (0, 0), (1, 0), (0, 1),
//! (1, 1).
//!
//! The scalar tests were ~100 of a block visit's ~310 instructions (crater): per child the
//! f32 range widened, two products for the y entry and exit, three NaN-aware minima and
//! maxima, the slack's absolute value, maximum, product and sum, two comparisons. Each lane
//! makes exactly those IEEE operations in that order (no FMA): `if a > b { a } else { b }` is
//! `maxpd(a, b)` and `if b < a { b } else { a }` is `minpd(b, a)` to the bit, NaN and signed
//! zeros included (the instructions return their second operand unless the comparison holds),
//! and the comparisons are the ordered `<=` and the unordered "not less than" of `!(a < b)`.

use std::arch::x86_64::{
    _mm256_add_pd, _mm256_and_pd, _mm256_andnot_pd, _mm256_cmp_pd, _mm256_cvtps_pd, _mm256_max_pd,
    _mm256_min_pd, _mm256_movemask_pd, _mm256_mul_pd, _mm256_set1_pd, _mm256_set_pd,
    _mm256_storeu_pd, _mm256_sub_pd, _mm_loadu_ps, _mm_shuffle_ps, _CMP_LE_OQ, _CMP_NLT_UQ,
};

/// What `visit_signed` needs of a block's children: each one's entry (`key`, from 0) and exit
/// along x and z (`exit`, without `tmax`), and the bits of those the ray reaches.
pub(super) struct Children {
    pub key: [f64; 4],
    pub exit: [f64; 4],
    pub mask: u32,
}

/// The ray's part of the tests: its y origin, `1 / d.y`, whether it rises, its `tmax` and
/// `tmin`, and the water level.
pub(super) struct RayY {
    pub oy: f64,
    pub inv_y: f64,
    pub up: bool,
    pub tmax: f64,
    /// `GridRay::tmin`: a child the ray leaves along x or z before it holds no crossing the
    /// caller wants (its exit along x and z is at least that of every point in it).
    pub tmin: f64,
    pub water: f64,
}

/// `visit_signed`'s loop over the four children: `xe`/`xx` the entries and exits along x of
/// the children with `di` 0 and 1, `ze`/`zx` along z by `dj`, `quad` their height ranges.
/// The mask is not yet cut to the children that exist.
///
/// # Safety
/// The CPU must have AVX (the caller is compiled with it).
#[inline(always)]
pub(super) unsafe fn children(
    quad: &[[f32; 2]; 4],
    (xe, xx): ([f64; 2], [f64; 2]),
    (ze, zx): ([f64; 2], [f64; 2]),
    y: &RayY,
) -> Children {
    // Lane g: di = g & 1, dj = g >> 1 (`_mm256_set_pd` takes the highest lane first).
    let xe = _mm256_set_pd(xe[1], xe[0], xe[1], xe[0]);
    let xx = _mm256_set_pd(xx[1], xx[0], xx[1], xx[0]);
    let ze = _mm256_set_pd(ze[1], ze[1], ze[0], ze[0]);
    let zx = _mm256_set_pd(zx[1], zx[1], zx[0], zx[0]);
    // `let k = if xe > 0 { xe } else { 0 }; key = if ze > k { ze } else { k }`.
    let k = _mm256_max_pd(xe, _mm256_set1_pd(0.0));
    let key = _mm256_max_pd(ze, k);
    // `fmin::<true>(xx, zx)`: `if zx < xx { zx } else { xx }`.
    let exit = _mm256_min_pd(zx, xx);
    // The ranges, low and high of each child (f32 to f64 is exact).
    let p = quad.as_ptr() as *const f32;
    let (a, b) = (_mm_loadu_ps(p), _mm_loadu_ps(p.add(4)));
    let ylo = _mm256_cvtps_pd(_mm_shuffle_ps::<0b10_00_10_00>(a, b));
    let yhi = _mm256_cvtps_pd(_mm_shuffle_ps::<0b11_01_11_01>(a, b));
    // `reaches_signed`.
    let (oy, inv) = (_mm256_set1_pd(y.oy), _mm256_set1_pd(y.inv_y));
    let u = _mm256_mul_pd(_mm256_sub_pd(ylo, oy), inv);
    let v = _mm256_mul_pd(_mm256_sub_pd(yhi, oy), inv);
    let (ye, yx) = if y.up { (u, v) } else { (v, u) };
    let t0 = _mm256_max_pd(ye, key);
    // `fmin::<true>(fmin::<true>(tmax, exit), yx)`.
    let t1 = _mm256_min_pd(yx, _mm256_min_pd(exit, _mm256_set1_pd(y.tmax)));
    // `slack(t1)`: `t1 + 1e-9 * fmax::<true>(t1.abs(), 1.0)`.
    let abs = _mm256_andnot_pd(_mm256_set1_pd(-0.0), t1);
    let slack = _mm256_add_pd(
        t1,
        _mm256_mul_pd(
            _mm256_set1_pd(1e-9),
            _mm256_max_pd(_mm256_set1_pd(1.0), abs),
        ),
    );
    let dry = _mm256_cmp_pd::<_CMP_NLT_UQ>(yhi, _mm256_set1_pd(y.water));
    let within = _mm256_cmp_pd::<_CMP_LE_OQ>(t0, slack);
    // `!(exit < tmin)`: NaN and the default -inf leave every child in.
    let started = _mm256_cmp_pd::<_CMP_NLT_UQ>(exit, _mm256_set1_pd(y.tmin));
    let mask = _mm256_movemask_pd(_mm256_and_pd(_mm256_and_pd(dry, within), started)) as u32;
    let mut out = Children {
        key: [0.0; 4],
        exit: [0.0; 4],
        mask,
    };
    _mm256_storeu_pd(out.key.as_mut_ptr(), key);
    _mm256_storeu_pd(out.exit.as_mut_ptr(), exit);
    out
}
