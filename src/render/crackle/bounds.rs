//! Cheap bounds on each cube's Σ|d|^metric for crackle's metrics that take powers.
//!
//! libm's `pow` is most of a crackle with such a metric (crackle2, crackle3: 55-60 % of the
//! scene), three per cube. Only the cubes that may hold one of the three smallest sums need
//! their exact powers; the others only need to be shown too far. A polynomial `pow`, good to
//! ~3e-5 relative and branch-free (so that the 27 cubes' 81 terms run in vector lanes),
//! gives each sum to within a relative `SLACK` far wider than its error, and a cube whose
//! lower bound is above the third smallest upper bound cannot be among the three smallest.

/// Below this a difference's power is bounded by the power of `TINY` and from below by 0
/// (the polynomial stays in the normal range: TINY^16 = 2^-960).
const TINY: f64 = 1.0 / (1u64 << 60) as f64;

/// The relative width given to each approximate sum: the polynomial's own error is below
/// 3e-5 (see `approx_pow`, tested against libm), libm's below an ulp, the sums' roundings
/// a few ulps; 1e-2 leaves over two orders of magnitude for what the analysis missed while
/// still separating all but the nearest three cubes in most evaluations (about 0.05-0.1
/// more cubes summed exactly a call than with 1e-3, by a simulation with uniform points,
/// for two fewer polynomial terms: 3 % faster on crackle2 and crackle3).
const SLACK: f64 = 1e-2;

/// The metrics the bounds are valid for: x^m of a difference in [TINY, 4] stays a normal
/// number, and the polynomial's error (proportional to m) stays far below `SLACK`.
pub(super) fn metric_in_range(m: f64) -> bool {
    (0.25..=16.0).contains(&m)
}

/// x^m for x in [TINY, 4] and m in [0.25, 16] (x not NaN), within 3e-5 relative of
/// `x.powf(m)` (about m / 16 of that for smaller m): 2^(m log2 x), log2 from the exponent and an
/// atanh series on the mantissa in [√½, √2), 2^y as 2^round(y) times a Taylor series of
/// e^r, |r| <= ln2 / 2.
#[inline(always)]
fn approx_pow(x: f64, m: f64) -> f64 {
    const MANTISSA: u64 = 0x000f_ffff_ffff_ffff;
    const ONE: u64 = 0x3ff0_0000_0000_0000;
    // 2^52 as an f64's bits: or-ing an 11-bit integer into its mantissa gives 2^52 + integer.
    const TWO52: u64 = 0x4330_0000_0000_0000;
    let bits = x.to_bits();
    // The biased exponent as a float without an integer conversion (which would not vectorize).
    let biased = f64::from_bits((bits >> 52) | TWO52) - 4503599627370496.0;
    let f = f64::from_bits((bits & MANTISSA) | ONE);
    let big = f > std::f64::consts::SQRT_2;
    let f = if big { f * 0.5 } else { f };
    let e = if big {
        biased - 1022.0
    } else {
        biased - 1023.0
    };
    // ln f = 2 atanh s, s = (f - 1) / (f + 1), |s| <= 0.1716: the terms left out, from
    // 2 s^7 / 7, sum to below 1.3e-6, times m log2(e) <= 23 in y, 2.1e-5 relative in 2^y.
    let s = (f - 1.0) / (f + 1.0);
    let s2 = s * s;
    let mut p = 1.0 / 5.0;
    p = p * s2 + 1.0 / 3.0;
    p = p * s2 + 1.0;
    let ln_f = 2.0 * s * p;
    let y = m * (e + ln_f * std::f64::consts::LOG2_E);
    // y + 1.5 * 2^52 + 1023 lies in [2^52, 2^53), where the rounding leaves round(y) + 1023
    // in the low mantissa bits: shifted into the exponent field they make 2^round(y)
    // (round(y) + 1023 is in [63, 1055] for the inputs allowed).
    const MAGIC: f64 = 6755399441055744.0 + 1023.0;
    let t = y + MAGIC;
    let n = t - MAGIC;
    let scale = f64::from_bits(t.to_bits() << 52);
    let r = (y - n) * std::f64::consts::LN_2;
    // e^r to r^5 / 5!: the terms left out are below 2.5e-6 for |r| <= 0.347.
    let mut e_r = 1.0 / 120.0;
    e_r = e_r * r + 1.0 / 24.0;
    e_r = e_r * r + 1.0 / 6.0;
    e_r = e_r * r + 0.5;
    e_r = e_r * r + 1.0;
    e_r = e_r * r + 1.0;
    scale * e_r
}

/// Lower and upper bounds of each cube's exact sum `(|d.x|^m + |d.y|^m) + |d.z|^m` (libm's
/// powers), from its differences by axis (`d[axis][cube]`, not negative, at most 4; the
/// 28th cube a pad). `m` satisfies `metric_in_range`.
#[inline(always)]
fn sum_bounds_body(d: &[[f64; 28]; 3], m: f64) -> ([f64; 28], [f64; 28]) {
    let mut low = [0.0; 28];
    let mut high = [0.0; 28];
    for i in 0..28 {
        let (mut lo, mut hi) = (0.0, 0.0);
        for axis in d {
            let x = axis[i];
            // x^m is monotonic in x: below TINY it lies in [0, TINY^m].
            let p = approx_pow(x.max(TINY), m);
            hi += p;
            lo += if x >= TINY { p } else { 0.0 };
        }
        low[i] = lo * (1.0 - SLACK);
        high[i] = hi * (1.0 + SLACK);
    }
    (low, high)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
unsafe fn sum_bounds_avx(d: &[[f64; 28]; 3], m: f64) -> ([f64; 28], [f64; 28]) {
    sum_bounds_body(d, m)
}

/// `sum_bounds_body` in four lanes where the CPU has AVX (the same bounds either way: each
/// lane's operations are the scalar ones, and the bounds hold whatever the last bits).
pub(super) fn sum_bounds(d: &[[f64; 28]; 3], m: f64) -> ([f64; 28], [f64; 28]) {
    #[cfg(target_arch = "x86_64")]
    if crate::math::has_avx() {
        // SAFETY: the CPU has AVX.
        return unsafe { sum_bounds_avx(d, m) };
    }
    sum_bounds_body(d, m)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::test_rng::Lcg;

    /// The polynomial power is within 3e-5 of libm's over the whole allowed range (the
    /// bounds' `SLACK` is 1e-2), at random and at the edges (powers of two, the mantissa's
    /// switch at √2, TINY, 4, the metrics' ends).
    #[test]
    fn approx_pow_is_libm_pow_to_3e_5() {
        let mut rng = Lcg(5);
        let mut xs = vec![
            TINY,
            4.0,
            1.0,
            2.0,
            0.5,
            std::f64::consts::SQRT_2,
            1.9999999999,
        ];
        xs.push(f64::from_bits(std::f64::consts::SQRT_2.to_bits() + 1));
        xs.push(f64::from_bits(std::f64::consts::SQRT_2.to_bits() - 1));
        for k in -60..2 {
            let p = (2.0f64).powi(k);
            xs.extend([
                p,
                f64::from_bits(p.to_bits() - 1),
                f64::from_bits(p.to_bits() + 1),
            ]);
        }
        for _ in 0..200_000 {
            xs.push(4.0 * rng.next());
            xs.push((2.0f64).powf(-60.0 + 62.0 * rng.next()));
        }
        let mut ms = vec![
            0.25,
            16.0,
            1.5,
            2.2,
            2.5,
            3.0,
            0.5,
            1.0 / 3.0,
            1.6,
            4.0,
            6.0,
        ];
        for _ in 0..40 {
            ms.push(0.25 + 15.75 * rng.next());
            ms.push(16.0 - 0.5 * rng.next());
        }
        for &m in &ms {
            for &x in &xs {
                if x < TINY {
                    continue;
                }
                let (a, p) = (approx_pow(x, m), x.powf(m));
                assert!((a / p - 1.0).abs() < 3e-5, "{x} {m}: {a} against {p}");
            }
        }
    }

    /// Every cube's exact sum lies within its bounds, in both the plain and the AVX build.
    #[test]
    fn bounds_hold_the_exact_sums() {
        let mut rng = Lcg(9);
        for n in 0..20_000 {
            let m = [0.25, 16.0, 2.5, 1.5, 3.0, 0.5 + 10.0 * rng.next()][n % 6];
            let mut d = [[0.0; 28]; 3];
            for a in d.iter_mut() {
                for (i, x) in a.iter_mut().enumerate() {
                    *x = match (i + n) % 9 {
                        0 => 0.0,
                        1 => 1e-25 * rng.next(),
                        2 => TINY,
                        3 => 4.0 * rng.next(),
                        _ => 2.0 * rng.next(),
                    };
                }
            }
            let plain = sum_bounds_body(&d, m);
            assert_eq!(sum_bounds(&d, m), plain);
            for (i, (lo, hi)) in plain.0.iter().zip(&plain.1).enumerate() {
                let s = (d[0][i].powf(m) + d[1][i].powf(m)) + d[2][i].powf(m);
                assert!(*lo <= s && s <= *hi, "{m} {i}: {s} {lo} {hi}");
            }
        }
    }
}
