//! Four quadrics' crossings at once, one per AVX lane: a CSG node of quadric members
//! (objects/csg/intee1's four shapes.inc cylinders) asks each member on its own ray, and one
//! member's path is a chain of dependent square roots and divisions (|dir|, dir / |dir|, the
//! discriminant's root, the quadratic's quotients, t / |dir|) that left the core waiting:
//! four members in lanes wait on one chain instead of four.
//!
//! Each lane runs `Algebraic::low_order_roots` (the certificate, `Diagonal::along` in kind
//! order, `low_roots_in` with Cauchy's bound, `t / len`) with the same IEEE operations in the
//! same order, so the same bits. Where a lane meets what the scalar code handles by cases this
//! kernel leaves out (a coefficient, discriminant or quotient that is not finite, a direction
//! length near the ends of the range), it answers `None` and the caller asks the shape itself.

use super::{quadric::Diagonal, Algebraic, FAR};
use crate::math::DVec3;

/// What [`crossings_lanes`] answers: lane `j`'s crossings as `intersect_all` lists them are
/// `t[0][j]` when bit `j` of `keep[0]` is set, then `t[1][j]` when that of `keep[1]` is;
/// when bit `j` of `defer` is set, the shape must be asked instead (`intersect_all`).
/// Read lane by lane from the stored vectors: a lane's crossings copied into an array of
/// their own by 8-byte stores and read back as one 16-byte load stalled on every search.
pub struct LaneHits {
    pub t: [[f64; 4]; 2],
    pub keep: [u32; 2],
    pub defer: u32,
}

impl LaneHits {
    /// Lane `j`'s crossings, `None` when the shape must be asked (tests).
    #[cfg(test)]
    fn lane(&self, j: usize) -> Option<Vec<f64>> {
        (self.defer >> j & 1 == 0).then(|| {
            (0..2)
                .filter(|&r| self.keep[r] >> j & 1 != 0)
                .map(|r| self.t[r][j])
                .collect()
        })
    }
}

/// How many shapes [`crossings_lanes`] answers for at once.
pub const LANES: usize = 4;

impl Algebraic {
    /// Whether [`crossings_lanes`] can answer for this shape: a quadric without cross terms
    /// whose terms come in kind order (`Diagonal::in_order`: a `quadric { }`'s order).
    pub fn lanes_ready(&self) -> bool {
        self.diagonal.is_some_and(|d| d.in_order && d.n > 0)
    }
}

/// Four quadrics' diagonal forms laid out lane by lane, made once for a CSG node whose members
/// they are (`QuadricLanes::of`): the kernel loads each coefficient as one vector instead of
/// gathering it from the four shapes by scalar loads and inserts on every search, and the
/// node's searches reach neither the shapes' `as_algebraic` (a call through their tables)
/// nor the checks that picked them. The values are the shapes' own, bit for bit.
#[derive(Clone, Debug)]
#[repr(C, align(32))]
pub struct QuadricLanes {
    sq: [[f64; 4]; 3],
    lin: [[f64; 4]; 3],
    k: [f64; 4],
    coef: [[f64; 4]; 7],
    /// `Diagonal::has` as lane masks (all bits set where the lane's shape has the kind).
    has: [[u64; 4]; 7],
    /// Each lane's diagonal form, for `inside`.
    diag: [Diagonal; 4],
}

impl QuadricLanes {
    /// The lanes of `shapes` (two to four, each [`Algebraic::lanes_ready`]), the first
    /// repeated into the unused lanes; `None` otherwise.
    pub fn of(shapes: &[&Algebraic]) -> Option<QuadricLanes> {
        if !(2..=LANES).contains(&shapes.len()) || !shapes.iter().all(|s| s.lanes_ready()) {
            return None;
        }
        let diag: [Diagonal; 4] = std::array::from_fn(|j| {
            shapes
                .get(j)
                .unwrap_or(&shapes[0])
                .diagonal
                .expect("lanes_ready shapes have a diagonal form")
        });
        let lanes =
            |f: &dyn Fn(&Diagonal) -> f64| -> [f64; 4] { std::array::from_fn(|j| f(&diag[j])) };
        Some(QuadricLanes {
            sq: std::array::from_fn(|i| lanes(&|d| d.sq[i])),
            lin: std::array::from_fn(|i| lanes(&|d| d.lin[i])),
            k: lanes(&|d| d.k),
            coef: std::array::from_fn(|i| lanes(&|d| d.coef[i])),
            has: std::array::from_fn(|i| {
                std::array::from_fn(|j| if diag[j].has[i] { u64::MAX } else { 0 })
            }),
            diag,
        })
    }

    /// `inside` of lane `j`'s shape at `p` (in the shape's space): its `value` is its
    /// diagonal form's, here without the call through the shape's table.
    #[inline(always)]
    pub fn inside(&self, j: usize, p: DVec3) -> bool {
        self.diag[j].value(p) < 0.0
    }
}

/// The kernel's body, written once for both widths: it is expanded in `x4` and `x2`, each of
/// which names its own width's intrinsics `add`, `cmp`, `loadu`, ... and the vector type `V`
/// (a macro's function and type names resolve where it is expanded), so both run the same
/// IEEE operations in the same order.
macro_rules! quadric_kernel {
    ($(#[$m:meta])* $name:ident, $n:literal, $lane:expr) => {
        $(#[$m])*
        ///
        /// # Safety
        /// The CPU must have AVX (`math::has_avx`).
        #[target_feature(enable = "avx")]
        pub unsafe fn $name(q: &QuadricLanes, rays: [&Ray; $n]) -> LaneHits {
            let lane = $lane;
            let load = |v: &[f64; 4]| loadu(v.as_ptr());
            let splat = set1;
            let sign = splat(-0.0);
            let abs = |v: V| andnot(sign, v);
            let lt = |a: V, b: V| cmp::<_CMP_LT_OQ>(a, b);
            let gt = |a: V, b: V| cmp::<_CMP_GT_OQ>(a, b);
            let ge = |a: V, b: V| cmp::<_CMP_GE_OQ>(a, b);
            let le = |a: V, b: V| cmp::<_CMP_LE_OQ>(a, b);
            let eq = |a: V, b: V| cmp::<_CMP_EQ_OQ>(a, b);
            // `!=` as Rust compares: true for NaN.
            let ne = |a: V, b: V| cmp::<_CMP_NEQ_UQ>(a, b);
            // `m ? a : b`.
            let pick = |m: V, a: V, b: V| blendv(b, a, m);
            let inf = splat(f64::INFINITY);
            let finite = |v: V| lt(abs(v), inf);
            let zero = setzero();

            let (ox, oy, oz) = (
                lane(&|j| rays[j].origin.x),
                lane(&|j| rays[j].origin.y),
                lane(&|j| rays[j].origin.z),
            );
            let (dx, dy, dz) = (
                lane(&|j| rays[j].dir.x),
                lane(&|j| rays[j].dir.y),
                lane(&|j| rays[j].dir.z),
            );
            let (a0, a1, a2) = (load(&q.sq[0]), load(&q.sq[1]), load(&q.sq[2]));
            let (l0, l1, l2) = (load(&q.lin[0]), load(&q.lin[1]), load(&q.lin[2]));
            let k = load(&q.k);

            // `Diagonal::surely_misses`, term for term.
            let (ax, ay, az) = (mul(a0, ox), mul(a1, oy), mul(a2, oz));
            let two = splat(2.0);
            let four = splat(4.0);
            let c2 = add(
                add(mul(mul(a0, dx), dx), mul(mul(a1, dy), dy)),
                mul(mul(a2, dz), dz),
            );
            let c1 = add(
                add(
                    mul(add(mul(two, ax), l0), dx),
                    mul(add(mul(two, ay), l1), dy),
                ),
                mul(add(mul(two, az), l2), dz),
            );
            let c0 = add(
                add(
                    add(mul(add(ax, l0), ox), mul(add(ay, l1), oy)),
                    mul(add(az, l2), oz),
                ),
                k,
            );
            let disc = sub(mul(c1, c1), mul(mul(four, c2), c0));
            let (pax, pay, paz) = (abs(ax), abs(ay), abs(az));
            let (bl0, bl1, bl2) = (abs(l0), abs(l1), abs(l2));
            let (aox, aoy, aoz) = (abs(ox), abs(oy), abs(oz));
            let (adx, ady, adz) = (abs(dx), abs(dy), abs(dz));
            let m2 = add(
                add(mul(mul(abs(a0), adx), adx), mul(mul(abs(a1), ady), ady)),
                mul(mul(abs(a2), adz), adz),
            );
            let m1 = add(
                add(
                    mul(add(mul(two, pax), bl0), adx),
                    mul(add(mul(two, pay), bl1), ady),
                ),
                mul(add(mul(two, paz), bl2), adz),
            );
            let m0 = add(
                add(
                    add(mul(add(pax, bl0), aox), mul(add(pay, bl1), aoy)),
                    mul(add(paz, bl2), aoz),
                ),
                abs(k),
            );
            let scale = add(mul(m1, m1), mul(mul(four, m2), m0));
            let len2 = add(add(mul(dx, dx), mul(dy, dy)), mul(dz, dz));
            let miss = and(
                and(
                    and(lt(disc, zero), lt(disc, mul(splat(-1e-12), scale))),
                    and(gt(scale, splat(1e-150)), lt(scale, splat(1e150))),
                ),
                and(gt(len2, splat(1e-50)), lt(len2, splat(1e50))),
            );

            // `low_order_solved`: the unit direction (`dir.length()` is the root of the same sum).
            let len = sqrt(len2);
            let (ux, uy, uz) = (div(dx, len), div(dy, len), div(dz, len));

            // `Diagonal::along` in kind order.
            let p1 = |o: V, u: V| [add(zero, o), add(zero, u)];
            let p2 = |q: [V; 2], o: V, u: V| {
                [
                    add(zero, mul(q[0], o)),
                    add(add(zero, mul(q[0], u)), mul(q[1], o)),
                    add(zero, mul(q[1], u)),
                ]
            };
            let (x1, y1, z1) = (p1(ox, ux), p1(oy, uy), p1(oz, uz));
            let (x2, y2, z2) = (p2(x1, ox, ux), p2(y1, oy, uy), p2(z1, oz, uz));
            let coef = |kind: usize| load(&q.coef[kind]);
            let has = |kind: usize| casti(loadi(q.has[kind].as_ptr().cast()));
            let mut acc = [zero; 3];
            let add_nonzero = |acc: &mut [V; 3], kind: usize, p: &[V]| {
                let (c, h) = (coef(kind), has(kind));
                for (a, &pa) in p.iter().enumerate() {
                    let v = add(zero, pa);
                    acc[a] = pick(and(h, ne(v, zero)), add(acc[a], mul(c, v)), acc[a]);
                }
            };
            let add_all = |acc: &mut [V; 3], kind: usize, p: &[V]| {
                let (c, h) = (coef(kind), has(kind));
                for (b, &pb) in p.iter().enumerate() {
                    acc[b] = pick(h, add(acc[b], mul(c, pb)), acc[b]);
                }
            };
            add_nonzero(&mut acc, 0, &x2);
            add_nonzero(&mut acc, 1, &y2);
            add_all(&mut acc, 2, &z2);
            add_nonzero(&mut acc, 3, &x1);
            add_nonzero(&mut acc, 4, &y1);
            add_all(&mut acc, 5, &z1);
            acc[0] = pick(has(6), add(acc[0], coef(6)), acc[0]);
            let [cc, b, a] = acc;

            // `low_roots_in` on `c[..=lead]`: a quadratic where `a != 0`, else a line where `b != 0`.
            let quad = ne(a, zero);
            let line = andnot(quad, ne(b, zero));
            let d2 = sub(mul(b, b), mul(mul(four, a), cc));
            let pos = gt(d2, zero);
            let root = sqrt(pick(pos, d2, zero));
            // `b.signum()` for a finite `b`.
            let sgn = or(and(sign, b), splat(1.0));
            let q = mul(splat(-0.5), add(b, mul(sgn, root)));
            // `q / a`, `cc / q` (or `q / a` again when q is 0), `-0.5 * b / a`, `-c0 / c1` in two
            // divisions.
            let qa = and(quad, pos);
            let num1 = pick(
                quad,
                pick(pos, q, mul(splat(-0.5), b)),
                xor(sign, cc),
            );
            let den1 = pick(quad, a, b);
            let r1 = div(num1, den1);
            let qnz = ne(q, zero);
            let r2 = div(pick(qnz, cc, q), pick(qnz, q, a));
            // Neither quotient is NaN (finite numerators, finite nonzero denominators), where
            // `min`/`max` agree with `f64::min`/`max` up to the sign of a zero, and a zero root is
            // below `lo` either way.
            let x0 = pick(qa, min(r1, r2), r1);
            let x1r = max(r1, r2);
            let two_roots = and(qa, ne(x1r, x0));
            let one_root = or(line, and(quad, or(pos, eq(d2, zero))));

            // Cauchy's bound (`cauchy`): the largest |c_i| below the lead over the lead's size.
            let big = pick(quad, max(abs(cc), abs(b)), abs(cc));
            let cq = div(big, abs(pick(quad, a, b)));
            let m = pick(gt(cq, zero), cq, zero);
            let hi = min(add(splat(1.0), m), splat(FAR));
            let lo = mul(splat(EPSILON), len);
            let keep0 = and(one_root, and(ge(x0, lo), le(x0, hi)));
            let keep1 = and(two_roots, and(ge(x1r, lo), le(x1r, hi)));
            let (t0, t1) = (div(x0, len), div(x1r, len));

            // Lanes this kernel answers: coefficients, discriminant and q finite, |dir| well inside
            // the range (so `lo` is positive and the roots' zeros fall below it).
            let ok = and(
                and(and(finite(cc), finite(b)), and(finite(a), finite(d2))),
                and(
                    finite(q),
                    and(gt(len, splat(1e-200)), lt(len, splat(1e200))),
                ),
            );
            let bits = |v: V| movemask(v) as u32;
            let (miss, ok) = (bits(miss), bits(ok));
            let mut out = LaneHits {
                t: [[0.0; 4]; 2],
                keep: [bits(keep0) & ok & !miss, bits(keep1) & ok & !miss],
                defer: !ok & !miss & ((1 << $n) - 1),
            };
            storeu(out.t[0].as_mut_ptr(), t0);
            storeu(out.t[1].as_mut_ptr(), t1);
            out
        }
    };
}

/// Four lanes in 256-bit vectors: nodes of three or four members.
#[cfg(target_arch = "x86_64")]
mod x4 {
    use super::{LaneHits, QuadricLanes, FAR};
    use crate::math::{Ray, EPSILON};
    use std::arch::x86_64::{
        __m256d as V, _mm256_add_pd as add, _mm256_and_pd as and, _mm256_andnot_pd as andnot,
        _mm256_blendv_pd as blendv, _mm256_castsi256_pd as casti, _mm256_cmp_pd as cmp,
        _mm256_div_pd as div, _mm256_loadu_pd as loadu, _mm256_loadu_si256 as loadi,
        _mm256_max_pd as max, _mm256_min_pd as min, _mm256_movemask_pd as movemask,
        _mm256_mul_pd as mul, _mm256_or_pd as or, _mm256_set1_pd as set1, _mm256_set_pd,
        _mm256_setzero_pd as setzero, _mm256_sqrt_pd as sqrt, _mm256_storeu_pd as storeu,
        _mm256_sub_pd as sub, _mm256_xor_pd as xor, _CMP_EQ_OQ, _CMP_GE_OQ, _CMP_GT_OQ, _CMP_LE_OQ,
        _CMP_LT_OQ, _CMP_NEQ_UQ,
    };

    quadric_kernel!(
        /// `intersect_all` of lane `j`'s shape of `q` on `rays[j]`; a lane whose answer is not
        /// wanted may repeat another's.
        crossings_lanes,
        4,
        |f: &dyn Fn(usize) -> f64| _mm256_set_pd(f(3), f(2), f(1), f(0))
    );
}

/// Two lanes in 128-bit vectors: nodes of two members (textures/finishes/arches' differences
/// of two paraboloids), whose four-lane search spent half its lanes, and the 256-bit square
/// roots' and divisions' second halves, on copies of the first member.
#[cfg(target_arch = "x86_64")]
mod x2 {
    use super::{LaneHits, QuadricLanes, FAR};
    use crate::math::{Ray, EPSILON};
    use std::arch::x86_64::{
        __m128d as V, _mm_add_pd as add, _mm_and_pd as and, _mm_andnot_pd as andnot,
        _mm_blendv_pd as blendv, _mm_castsi128_pd as casti, _mm_cmp_pd as cmp, _mm_div_pd as div,
        _mm_loadu_pd as loadu, _mm_loadu_si128 as loadi, _mm_max_pd as max, _mm_min_pd as min,
        _mm_movemask_pd as movemask, _mm_mul_pd as mul, _mm_or_pd as or, _mm_set1_pd as set1,
        _mm_set_pd, _mm_setzero_pd as setzero, _mm_sqrt_pd as sqrt, _mm_storeu_pd as storeu,
        _mm_sub_pd as sub, _mm_xor_pd as xor, _CMP_EQ_OQ, _CMP_GE_OQ, _CMP_GT_OQ, _CMP_LE_OQ,
        _CMP_LT_OQ, _CMP_NEQ_UQ,
    };

    quadric_kernel!(
        /// `intersect_all` of the first two lanes' shapes of `q` on `rays[0]` and `rays[1]`
        /// (lanes 2 and 3 of the answer are empty).
        crossings_pair,
        2,
        |f: &dyn Fn(usize) -> f64| _mm_set_pd(f(1), f(0))
    );
}

#[cfg(target_arch = "x86_64")]
pub use x2::crossings_pair;
#[cfg(target_arch = "x86_64")]
pub use x4::crossings_lanes;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::{Hit, Shape};
    use crate::math::Ray;

    /// Each lane's crossings equal `intersect_all`'s bit for bit (or the lane defers), for
    /// quadrics of shapes.inc's kinds at many scales, rays through them, grazing them, along
    /// their axes, from their surface, with zeros, tiny, huge, infinite and NaN values; the
    /// two-lane kernel's lanes equal the four-lane one's.
    #[test]
    fn lanes_are_intersect_all() {
        if !crate::math::has_avx() {
            return;
        }
        let mut rnd = crate::math::xorshift_unit(0x5851_f42d_4c95_7f2du64);
        let special = [0.0, -0.0, 1.0, -1.0, 1e-300, 1e300, f64::INFINITY, f64::NAN];
        let mut pick = move |p: f64| -> f64 {
            let r = rnd();
            if r < p {
                special[((r / p) * special.len() as f64) as usize % special.len()]
            } else {
                (rnd() - 0.5) * 10f64.powi((rnd() * 10.0) as i32 - 5)
            }
        };
        let (mut answered, mut crossings) = (0, 0);
        for case in 0..60_000usize {
            let p = if case % 10 == 0 { 0.2 } else { 0.0 };
            let mut shapes = Vec::new();
            let mut rays = Vec::new();
            for _ in 0..4 {
                let small = [-1.0, 0.0, 1.0, 0.25, -4.0];
                let s = |r: f64| small[((r.abs() * 1e3) as usize) % small.len()];
                let sq = [s(pick(0.0)), s(pick(0.0)), s(pick(0.0))];
                let lin = [s(pick(0.0)) * 0.5, 0.0, s(pick(0.0))];
                let kk = if p > 0.0 { pick(p) } else { s(pick(0.0)) * 3.0 };
                let mut terms = Vec::new();
                for (i, pw) in [[2, 0, 0], [0, 2, 0], [0, 0, 2]].into_iter().enumerate() {
                    terms.push((pw, sq[i]));
                }
                for (i, pw) in [[1, 0, 0], [0, 1, 0], [0, 0, 1]].into_iter().enumerate() {
                    terms.push((pw, lin[i]));
                }
                terms.push(([0, 0, 0], kk));
                let q = Algebraic::new(2, &terms, false);
                let mut origin = DVec3::new(pick(p), pick(p), pick(p)) * 10.0;
                let mut dir = DVec3::new(pick(p), pick(p), pick(p));
                match case % 4 {
                    // From a point on the surface.
                    1 if q.value(origin).is_finite() => {
                        let g = q.normal(origin, &Hit::new(0.0));
                        if g.length_squared() > 0.0 {
                            origin += g * (-q.value(origin) / g.length_squared());
                        }
                    }
                    // Along an axis.
                    2 => dir = DVec3::new(0.0, 0.0, dir.z),
                    _ => {}
                }
                if case % 7 == 0 {
                    dir *= 1e-5;
                }
                shapes.push(q);
                rays.push(Ray::new(origin, dir));
            }
            if !shapes.iter().all(|s| s.lanes_ready()) {
                continue;
            }
            // Nodes of two and three members too: the unused lanes repeat the first.
            let n = 2 + case % 3;
            let refs: Vec<&Algebraic> = shapes.iter().take(n).collect();
            let lanes = QuadricLanes::of(&refs).expect("lanes_ready shapes");
            let got = unsafe { crossings_lanes(&lanes, [&rays[0], &rays[1], &rays[2], &rays[3]]) };
            // The two-lane kernel answers as the four-lane one for the first two, bit for bit.
            let pair = unsafe { crossings_pair(&lanes, [&rays[0], &rays[1]]) };
            for j in 0..2 {
                let (a, b) = (pair.lane(j), got.lane(j));
                let bits = |v: Option<Vec<f64>>| {
                    v.map(|v| v.iter().map(|t| t.to_bits()).collect::<Vec<_>>())
                };
                assert_eq!(bits(a), bits(b), "{:?} {:?}", shapes[j], rays[j]);
            }
            assert_eq!((pair.keep[0] | pair.keep[1] | pair.defer) >> 2, 0);
            for j in 0..n {
                let p = rays[j].at(pick(0.1));
                assert_eq!(lanes.inside(j, p), shapes[j].inside(p));
                let mut want = Vec::new();
                shapes[j].intersect_all(&rays[j], &mut want);
                if let Some(ts) = got.lane(j) {
                    answered += 1;
                    crossings += ts.len();
                    assert_eq!(ts.len(), want.len(), "{:?} {:?}", shapes[j], rays[j]);
                    for (t, h) in ts.iter().zip(&want) {
                        assert_eq!(t.to_bits(), h.t.to_bits(), "{:?} {:?}", shapes[j], rays[j]);
                    }
                }
            }
        }
        assert!(answered > 100_000, "{answered}");
        assert!(crossings > 70_000, "{crossings}");
    }
}
