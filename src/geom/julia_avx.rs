//! Four quaternion orbits in 256-bit AVX registers, written with the intrinsics: the julia
//! bisection's four midpoints (`inside4`) and the march's samples ahead (`orbits4`); the
//! same for hypercomplex sqr and cube (`hyper_inside4`, `hyper_orbits4`).
//!
//! The generic lane code (`julia_pair.rs`) compiled with AVX enabled still used 128-bit
//! registers, two per lane vector, plus shuffles between their halves (objdump of main's
//! `inside4_avx`: ~130 instructions an iteration); here one register holds one quaternion
//! component of all four lanes, so an iteration of the square is 10 products and 16 sums,
//! and the lane masks are one compare and one `movemask` each.
//!
//! Every lane does exactly `Julia::quaternion_orbit`'s IEEE operations in its order (AVX, no
//! FMA: nothing fused, nothing reassociated). The square shares products that are equal to
//! the bit (`a·b` and `b·a` round the same exact product), as LLVM already did in the scalar
//! `qmul(h, h)`. A lane that has decided iterates on unread, as in `julia_pair.rs`.

use std::arch::x86_64::{
    __m256d, _mm256_add_pd, _mm256_blendv_pd, _mm256_cmp_pd, _mm256_loadu_pd, _mm256_movemask_pd,
    _mm256_mul_pd, _mm256_set1_pd, _mm256_set_pd, _mm256_setzero_pd, _mm256_sqrt_pd,
    _mm256_storeu_pd, _mm256_sub_pd, _CMP_GT_OQ, _CMP_LE_OQ,
};

use super::{Julia, KEEP, Q};

/// A quaternion component per register, lane `l` holding point `l`.
type Q4 = [__m256d; 4];

#[inline(always)]
unsafe fn add(a: __m256d, b: __m256d) -> __m256d {
    _mm256_add_pd(a, b)
}

#[inline(always)]
unsafe fn sub(a: __m256d, b: __m256d) -> __m256d {
    _mm256_sub_pd(a, b)
}

#[inline(always)]
unsafe fn mul(a: __m256d, b: __m256d) -> __m256d {
    _mm256_mul_pd(a, b)
}

/// The four points' component `i` (`_mm256_set_pd` takes the highest lane first).
#[inline(always)]
unsafe fn lanes(h: &[Q; 4]) -> Q4 {
    std::array::from_fn(|i| _mm256_set_pd(h[3][i], h[2][i], h[1][i], h[0][i]))
}

/// `qmul(h, h)` with its association: the products `h_i·h_j` and `h_j·h_i` are the same
/// rounded number, so ten of them.
#[inline(always)]
unsafe fn square(h: &Q4) -> Q4 {
    let [a, b, c, d] = *h;
    let (aa, bb, cc, dd) = (mul(a, a), mul(b, b), mul(c, c), mul(d, d));
    let (ab, ac, ad) = (mul(a, b), mul(a, c), mul(a, d));
    let (bc, bd, cd) = (mul(b, c), mul(b, d), mul(c, d));
    [
        // a·a − b·b − c·c − d·d
        sub(sub(sub(aa, bb), cc), dd),
        // a·b + b·a + c·d − d·c
        sub(add(add(ab, ab), cd), cd),
        // a·c − b·d + c·a + d·b
        add(add(sub(ac, bd), ac), bd),
        // a·d + b·c − c·b + d·a
        add(sub(add(ad, bc), bc), ad),
    ]
}

/// `qmul(p, q)` with its association.
#[inline(always)]
unsafe fn product(p: &Q4, q: &Q4) -> Q4 {
    [
        sub(
            sub(sub(mul(p[0], q[0]), mul(p[1], q[1])), mul(p[2], q[2])),
            mul(p[3], q[3]),
        ),
        sub(
            add(add(mul(p[0], q[1]), mul(p[1], q[0])), mul(p[2], q[3])),
            mul(p[3], q[2]),
        ),
        add(
            add(sub(mul(p[0], q[2]), mul(p[1], q[3])), mul(p[2], q[0])),
            mul(p[3], q[1]),
        ),
        add(
            sub(add(mul(p[0], q[3]), mul(p[1], q[2])), mul(p[2], q[1])),
            mul(p[3], q[0]),
        ),
    ]
}

/// `qnorm_sq` with its association.
#[inline(always)]
unsafe fn norm_sq(h: &Q4) -> __m256d {
    add(
        add(add(mul(h[0], h[0]), mul(h[1], h[1])), mul(h[2], h[2])),
        mul(h[3], h[3]),
    )
}

/// One step `h ← h^p + c` (p = 2, or 3 for `CUBE`: `h·h²`).
#[inline(always)]
unsafe fn step<const CUBE: bool>(h: &Q4, c: &Q4) -> Q4 {
    let h2 = square(h);
    let f = if CUBE { product(h, &h2) } else { h2 };
    std::array::from_fn(|i| add(f[i], c[i]))
}

/// `quaternion_orbit::<CUBE, false>` of four points, as inside-ness (`Julia::inside_n`), and
/// per lane the squared norm `s` its orbit decided at less `bail_sq` (`Julia::is_in4`): above
/// zero for an escape, at or below it for an orbit that ran to its end; NaN where the keep
/// radius decided (its last norms unknown). The bisection reads it only to choose midpoints.
///
/// # Safety
/// The CPU must have AVX.
#[target_feature(enable = "avx")]
pub(super) unsafe fn inside4<const CUBE: bool>(j: &Julia, h: [Q; 4]) -> ([bool; 4], [f64; 4]) {
    let steps = j.max_iteration.saturating_sub(1);
    let bail_sq = _mm256_set1_pd(j.bail_sq);
    let mut h = lanes(&h);
    // Lane bits: `decided` once a lane's lone orbit would have returned, `out` where it
    // returned outside (an escape; the kept radius answers inside).
    let mut s = norm_sq(&h);
    let mut out = _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_GT_OQ>(s, bail_sq)) as u32;
    let mut decided = out;
    let mut found = s;
    if decided != 15 {
        let c: Q4 = j.param.map(|x| _mm256_set1_pd(x));
        let nan = _mm256_set1_pd(f64::NAN);
        for k in 0..steps {
            h = step::<CUBE>(&h, &c);
            s = norm_sq(&h);
            let esc = _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_GT_OQ>(s, bail_sq)) as u32;
            let left = (steps - 1 - k) as usize;
            let (kept, kept_v) = if left < KEEP {
                let r = _mm256_set1_pd(j.keep_sq[left]);
                let v = _mm256_cmp_pd::<_CMP_LE_OQ>(s, r);
                (_mm256_movemask_pd(v) as u32, v)
            } else {
                (0, _mm256_setzero_pd())
            };
            let new = (esc | kept) & !decided;
            if new != 0 {
                found = _mm256_blendv_pd(found, _mm256_blendv_pd(s, nan, kept_v), lane_mask(new));
            }
            out |= esc & !decided;
            decided |= esc | kept;
            if decided == 15 {
                break;
            }
        }
        found = _mm256_blendv_pd(found, s, lane_mask(!decided & 15));
    }
    let mut g = [0.0; 4];
    _mm256_storeu_pd(g.as_mut_ptr(), _mm256_sub_pd(found, bail_sq));
    (std::array::from_fn(|i| out >> i & 1 == 0), g)
}

/// `quaternion_orbit::<CUBE, true>` of four points (`Julia::orbits_n`): lane bits of the
/// escapes, and per lane the `r` and `dr` of its escape (unread where it did not escape).
///
/// # Safety
/// The CPU must have AVX.
#[target_feature(enable = "avx")]
pub(super) unsafe fn orbits4<const CUBE: bool>(j: &Julia, h: [Q; 4]) -> (u32, [f64; 4], [f64; 4]) {
    let steps = j.max_iteration.saturating_sub(1);
    // The masks compare squared norms with the radii's thresholds, as `quaternion_orbit`
    // does, so the branches do not wait for the square roots.
    let bail_sq = _mm256_set1_pd(j.bail_sq);
    let mut h = lanes(&h);
    let mut s = norm_sq(&h);
    let mut r = _mm256_sqrt_pd(s);
    let mut dr = _mm256_set1_pd(1.0);
    let esc0 = _mm256_cmp_pd::<_CMP_GT_OQ>(s, bail_sq);
    let mut out = _mm256_movemask_pd(esc0) as u32;
    let mut decided = out;
    // Per lane, the `r` and `dr` of its escape once `decided`: the lanes escaped at the start
    // keep their entries (`dr` 1).
    let (mut found_r, mut found_dr) = (r, dr);
    if decided != 15 {
        let c: Q4 = j.param.map(|x| _mm256_set1_pd(x));
        let (two, three) = (_mm256_set1_pd(2.0), _mm256_set1_pd(3.0));
        for k in 0..steps {
            h = step::<CUBE>(&h, &c);
            dr = mul(
                dr,
                if CUBE {
                    mul(mul(three, r), r)
                } else {
                    mul(two, r)
                },
            );
            s = norm_sq(&h);
            r = _mm256_sqrt_pd(s);
            let esc_v = _mm256_cmp_pd::<_CMP_GT_OQ>(s, bail_sq);
            let esc = _mm256_movemask_pd(esc_v) as u32;
            let left = (steps - 1 - k) as usize;
            let kept = if left < KEEP {
                let q = _mm256_set1_pd(j.keep_thr[left]);
                _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_LE_OQ>(s, q)) as u32
            } else {
                0
            };
            let new = esc & !decided;
            if new != 0 {
                // Only the lanes escaping now take this iteration's values.
                let mask = lane_mask(new);
                found_r = _mm256_blendv_pd(found_r, r, mask);
                found_dr = _mm256_blendv_pd(found_dr, dr, mask);
                out |= new;
            }
            decided |= esc | kept;
            if decided == 15 {
                break;
            }
        }
    }
    let (mut fr, mut fdr) = ([0.0; 4], [0.0; 4]);
    _mm256_storeu_pd(fr.as_mut_ptr(), found_r);
    _mm256_storeu_pd(fdr.as_mut_ptr(), found_dr);
    (out, fr, fdr)
}

/// Four hypercomplex orbits' halves (z1, z2 of `split`): real and imaginary parts of each,
/// lane `l` holding point `l`.
#[inline(always)]
unsafe fn hyper_halves(h: &Q4) -> Q4 {
    [
        sub(h[0], h[3]),
        add(h[1], h[2]),
        add(h[0], h[3]),
        sub(h[1], h[2]),
    ]
}

/// One hypercomplex sqr step of both halves, `z * z + c` with num_complex's association
/// (re·re − im·im, re·im + im·re: the two products of the imaginary part are one rounded
/// number), and the step's `0.5 * (|z1|² + |z2|²)`.
#[inline(always)]
unsafe fn hyper_step(z: &Q4, c: &Q4, half: __m256d) -> (Q4, __m256d) {
    let [ar, ai, br, bi] = *z;
    let (p, q) = (mul(ar, ai), mul(br, bi));
    let z = [
        add(sub(mul(ar, ar), mul(ai, ai)), c[0]),
        add(add(p, p), c[1]),
        add(sub(mul(br, br), mul(bi, bi)), c[2]),
        add(add(q, q), c[3]),
    ];
    let n1 = add(mul(z[0], z[0]), mul(z[1], z[1]));
    let n2 = add(mul(z[2], z[2]), mul(z[3], z[3]));
    (z, mul(half, add(n1, n2)))
}

/// The parameter's halves, each part in all four lanes.
#[inline(always)]
unsafe fn hyper_param(j: &Julia) -> Q4 {
    let (c1, c2) = super::split(&j.param);
    [c1.re, c1.im, c2.re, c2.im].map(|x| _mm256_set1_pd(x))
}

/// `hypercomplex_orbit::<true, false>` of four points (sqr, and cube, which iterates the
/// square), as inside-ness. A NaN orbit never escapes, as there.
///
/// # Safety
/// The CPU must have AVX.
#[target_feature(enable = "avx")]
pub(super) unsafe fn hyper_inside4(j: &Julia, h: [Q; 4]) -> [bool; 4] {
    let steps = j.max_iteration.saturating_sub(1);
    let bail_sq = _mm256_set1_pd(j.bail_sq);
    let h = lanes(&h);
    let mut out = _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_GT_OQ>(norm_sq(&h), bail_sq)) as u32;
    if out != 15 {
        let c = hyper_param(j);
        let half = _mm256_set1_pd(0.5);
        let mut z = hyper_halves(&h);
        for _ in 0..steps {
            let s;
            (z, s) = hyper_step(&z, &c, half);
            out |= _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_GT_OQ>(s, bail_sq)) as u32;
            if out == 15 {
                break;
            }
        }
    }
    std::array::from_fn(|i| out >> i & 1 == 0)
}

/// `hypercomplex_orbit::<true, true>` of four points (`Julia::orbit_n`), as `orbits4`: lane
/// bits of the escapes, and per lane the `r` and `dr` of its escape.
///
/// # Safety
/// The CPU must have AVX.
#[target_feature(enable = "avx")]
pub(super) unsafe fn hyper_orbits4(j: &Julia, h: [Q; 4]) -> (u32, [f64; 4], [f64; 4]) {
    let steps = j.max_iteration.saturating_sub(1);
    let bail_sq = _mm256_set1_pd(j.bail_sq);
    let h = lanes(&h);
    let s = norm_sq(&h);
    let mut r = _mm256_sqrt_pd(s);
    let mut dr = _mm256_set1_pd(1.0);
    let mut out = _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_GT_OQ>(s, bail_sq)) as u32;
    let (mut found_r, mut found_dr) = (r, dr);
    if out != 15 {
        let c = hyper_param(j);
        let (half, two) = (_mm256_set1_pd(0.5), _mm256_set1_pd(2.0));
        let mut z = hyper_halves(&h);
        for _ in 0..steps {
            let s;
            (z, s) = hyper_step(&z, &c, half);
            dr = mul(dr, mul(two, r));
            r = _mm256_sqrt_pd(s);
            let esc = _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_GT_OQ>(s, bail_sq)) as u32;
            let new = esc & !out;
            if new != 0 {
                let mask = lane_mask(new);
                found_r = _mm256_blendv_pd(found_r, r, mask);
                found_dr = _mm256_blendv_pd(found_dr, dr, mask);
                out |= new;
                if out == 15 {
                    break;
                }
            }
        }
    }
    let (mut fr, mut fdr) = ([0.0; 4], [0.0; 4]);
    _mm256_storeu_pd(fr.as_mut_ptr(), found_r);
    _mm256_storeu_pd(fdr.as_mut_ptr(), found_dr);
    (out, fr, fdr)
}

/// A set sign bit in the lanes whose bit is set (for `blendv`, which reads only the sign).
#[inline(always)]
unsafe fn lane_mask(bits: u32) -> __m256d {
    const MASKS: [[f64; 4]; 16] = {
        let mut m = [[1.0; 4]; 16];
        let mut b = 0;
        while b < 16 {
            let mut i = 0;
            while i < 4 {
                if b >> i & 1 == 1 {
                    m[b][i] = -1.0;
                }
                i += 1;
            }
            b += 1;
        }
        m
    };
    _mm256_loadu_pd(MASKS[bits as usize & 15].as_ptr())
}

/// `Julia::gradient`'s quaternion loop: the three tangents carried forward in lanes 0-2 (lane
/// 3 repeats lane 2, unread: a zero lane would be built with a register `vmovq` that valgrind
/// 3.19 cannot run), `h` itself as there. Returns the last `h` and the tangents.
///
/// # Safety
/// The CPU must have AVX.
#[target_feature(enable = "avx")]
pub(super) unsafe fn tangents<const CUBE: bool>(
    j: &Julia,
    h0: Q,
    axes: [Q; 3],
    n: u32,
) -> (Q, [Q; 3]) {
    let mut t: Q4 =
        std::array::from_fn(|k| _mm256_set_pd(axes[2][k], axes[2][k], axes[1][k], axes[0][k]));
    let mut h = h0;
    for _ in 0..n {
        let hb: Q4 = h.map(|x| _mm256_set1_pd(x));
        t = if CUBE {
            let h2 = super::qmul(&h, &h);
            let h2b: Q4 = h2.map(|x| _mm256_set1_pd(x));
            let a = product(&product(&t, &hb), &hb);
            let b = product(&product(&hb, &t), &hb);
            let c = product(&h2b, &t);
            std::array::from_fn(|i| add(add(a[i], b[i]), c[i]))
        } else {
            let a = product(&t, &hb);
            let b = product(&hb, &t);
            std::array::from_fn(|i| add(a[i], b[i]))
        };
        h = j.quaternion_step(&h);
    }
    let mut out = [[0.0; 4]; 4];
    for (o, tk) in out.iter_mut().zip(t) {
        _mm256_storeu_pd(o.as_mut_ptr(), tk);
    }
    (
        h,
        std::array::from_fn(|i| std::array::from_fn(|k| out[k][i])),
    )
}

#[cfg(test)]
mod tests {
    use super::super::tests::{julia, to_the_edge};
    use super::super::{Algebra, JuliaFn, Orbit};
    use super::*;

    /// `hyper_inside4` and `hyper_orbits4` give each lane the scalar hypercomplex orbit's
    /// answer, `r` and `dr` to the bit: points on the surface (bisected along the line to the
    /// origin), beside it and far out, and lifted points of edge values (signed zeros,
    /// subnormals, overflowing squares, infinities, NaN), each beside three others.
    #[test]
    fn hypercomplex_lanes_are_the_scalar_orbit() {
        if !crate::math::has_avx() {
            return;
        }
        let mut rng = crate::geom::test_rng::Lcg(41);
        let edge = [
            0.0,
            -0.0,
            1e-310,
            -1.0,
            0.5,
            2.0,
            1e160,
            -1e300,
            f64::INFINITY,
            f64::NAN,
        ];
        let key = |o: Orbit| match o {
            Orbit::Inside => None,
            Orbit::Outside { r, dr } => {
                let b = |x: f64| if x.is_nan() { 1 } else { x.to_bits() };
                Some((b(r), b(dr)))
            }
        };
        for (c, func, n) in [
            ([-0.745, 0.0, 0.113, 0.05], JuliaFn::Sqr, 9),
            ([0.2, 0.1, 0.59, -0.2], JuliaFn::Sqr, 7),
            ([0.4, 0.2, 0.1, 0.0], JuliaFn::Cube, 6),
            ([-0.5, 0.5, 0.0, 0.1], JuliaFn::Sqr, 1),
            ([0.0; 4], JuliaFn::Sqr, 30),
        ] {
            let j = julia(c, Algebra::Hypercomplex, func, n, 20.0);
            let mut points: Vec<Q> = Vec::new();
            let mut inside = 0;
            for i in 0..40_000 {
                let mut p = rng.vec(if i % 3 == 0 { 4.5 } else { 2.0 });
                if i % 3 == 1 {
                    let (lo, hi) = to_the_edge(&j, p);
                    p *= if i % 2 == 0 { lo } else { hi };
                }
                points.push(j.lift(p).0);
            }
            for k in 0..edge.len().pow(4) {
                points.push(std::array::from_fn(|i| {
                    edge[(k / edge.len().pow(i as u32)) % edge.len()]
                }));
            }
            for (i, four) in points.chunks_exact(4).enumerate() {
                // Rotate the lanes so an edge point sits beside ordinary ones too.
                let h: [Q; 4] = std::array::from_fn(|l| four[(l + i) % 4]);
                // SAFETY: the CPU has AVX (checked above).
                let (ins, (out, r, dr)) = unsafe { (hyper_inside4(&j, h), hyper_orbits4(&j, h)) };
                for l in 0..4 {
                    let lone = j.hypercomplex_orbit::<true, true>(h[l]);
                    let want_in =
                        matches!(j.hypercomplex_orbit::<true, false>(h[l]), Orbit::Inside);
                    assert_eq!(ins[l], want_in, "{c:?} at {:?}", h[l]);
                    let got = if out >> l & 1 == 1 {
                        Orbit::Outside { r: r[l], dr: dr[l] }
                    } else {
                        Orbit::Inside
                    };
                    assert_eq!(key(got), key(lone), "{c:?} at {:?}", h[l]);
                    inside += want_in as usize;
                }
            }
            assert!(inside > 1000, "{c:?}: {inside}");
        }
    }
}
