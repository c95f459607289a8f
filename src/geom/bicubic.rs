//! POV-Ray `bicubic_patch`: a Bezier patch of 16 control points, rendered as POV-Ray renders
//! it, as a grid of smooth triangles.
//!
//! The manual says the patch is cut into `2^u_steps × 2^v_steps` pieces, each "pretended to be
//! a rectangle" (two triangles) with "normal interpolation". Here the grid is built once, when
//! the scene is built: its vertices lie on the true surface and carry the true surface normal,
//! and the triangles go behind the mesh's BVH, so a ray costs what a mesh ray costs whatever
//! the `type`. `flatness` lets POV-Ray stop subdividing early where a piece is flat; lancer
//! always subdivides fully, which is at least as close to the surface (see
//! docs/implicit-objects.md). A patch has no inside: in CSG it is never "inside" anything and
//! nothing is inside it, as a mesh without `inside_vector`.

use crate::math::DVec3;
use crate::scene::desc::MeshData;

/// Most subdivision levels per direction: 2^8 = 256 pieces already put several pieces in one
/// pixel for any patch that fits in a picture; more would only cost memory.
pub const MAX_STEPS: u32 = 8;

/// Bernstein weights of the cubic and of its derivative at `t`.
fn bernstein(t: f64) -> ([f64; 4], [f64; 4]) {
    let s = 1.0 - t;
    (
        [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t],
        [
            -3.0 * s * s,
            3.0 * s * s - 6.0 * t * s,
            6.0 * t * s - 3.0 * t * t,
            3.0 * t * t,
        ],
    )
}

/// The point and partial derivatives at (u, v); `p[row * 4 + col]`, u runs along a row.
fn eval(p: &[DVec3; 16], u: f64, v: f64) -> (DVec3, DVec3, DVec3) {
    #[cfg(target_arch = "x86_64")]
    if crate::math::has_avx() {
        // SAFETY: the CPU has AVX (checked just above).
        return unsafe { eval_avx(p, u, v) };
    }
    eval_scalar(p, u, v)
}

/// `eval` one coordinate at a time: the sums of `eval_avx`, lane by lane.
fn eval_scalar(p: &[DVec3; 16], u: f64, v: f64) -> (DVec3, DVec3, DVec3) {
    let (bu, du) = bernstein(u);
    let (bv, dv) = bernstein(v);
    let (mut s, mut su, mut sv) = (DVec3::ZERO, DVec3::ZERO, DVec3::ZERO);
    for r in 0..4 {
        for c in 0..4 {
            let q = p[r * 4 + c];
            s += q * (bu[c] * bv[r]);
            su += q * (du[c] * bv[r]);
            sv += q * (bu[c] * dv[r]);
        }
    }
    (s, su, sv)
}

/// `eval_scalar` with the point and both derivatives side by side in the lanes of one
/// 256-bit register per coordinate (the fourth lane unread): a weight product and a
/// product-and-sum per control point and coordinate become one instruction for all three
/// (the tessellation evaluates 66,049 points for a patch of 8 × 8 steps). The same IEEE
/// operations in the same order lane by lane (AVX, no FMA), so the same bits.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
unsafe fn eval_avx(p: &[DVec3; 16], u: f64, v: f64) -> (DVec3, DVec3, DVec3) {
    use std::arch::x86_64::{
        _mm256_add_pd, _mm256_mul_pd, _mm256_set1_pd, _mm256_set_pd, _mm256_setzero_pd,
        _mm256_storeu_pd,
    };
    let (bu, du) = bernstein(u);
    let (bv, dv) = bernstein(v);
    // Lanes (s, su, sv, sv): the weights `bu[c]·bv[r]`, `du[c]·bv[r]` and `bu[c]·dv[r]`
    // (the fourth lane repeats the third rather than holding a zero: LLVM builds a zero lane
    // with a register `vmovq` that valgrind 3.19 cannot run).
    let wc: [_; 4] = std::array::from_fn(|c| _mm256_set_pd(bu[c], bu[c], du[c], bu[c]));
    let mut acc = [_mm256_setzero_pd(); 3];
    for r in 0..4 {
        let wr = _mm256_set_pd(dv[r], dv[r], bv[r], bv[r]);
        for (c, &wc) in wc.iter().enumerate() {
            let w = _mm256_mul_pd(wc, wr);
            let q = p[r * 4 + c];
            for (a, x) in acc.iter_mut().zip([q.x, q.y, q.z]) {
                *a = _mm256_add_pd(*a, _mm256_mul_pd(_mm256_set1_pd(x), w));
            }
        }
    }
    let mut out = [[0.0; 4]; 3];
    for (o, a) in out.iter_mut().zip(acc) {
        _mm256_storeu_pd(o.as_mut_ptr(), a);
    }
    let lane = |k: usize| DVec3::new(out[0][k], out[1][k], out[2][k]);
    (lane(0), lane(1), lane(2))
}

/// `normal_from` with the derivatives evaluated here.
#[cfg(test)]
fn normal_at(p: &[DVec3; 16], u: f64, v: f64) -> DVec3 {
    let (_, su, sv) = eval(p, u, v);
    normal_from(p, u, v, su, sv)
}

/// The surface normal at (u, v), from the partial derivatives `eval` gave there (the
/// tessellation takes the point and these from one evaluation). Where a patch edge collapses
/// to a point (the teapot's lid and bottom) one partial derivative vanishes; the normal is
/// then taken a little way into the patch, where it is defined and tends to the limit.
fn normal_from(p: &[DVec3; 16], u: f64, v: f64, su: DVec3, sv: DVec3) -> DVec3 {
    let n = su.cross(sv);
    let scale = su.length_squared().max(sv.length_squared());
    if n.length_squared() > 1e-20 * scale * scale && n.is_finite() {
        return n;
    }
    for d in [1e-6, 1e-4, 1e-2] {
        let (uu, vv) = (u + (0.5 - u) * d, v + (0.5 - v) * d);
        let (_, su, sv) = eval(p, uu, vv);
        let n = su.cross(sv);
        if n.length_squared() > 0.0 && n.is_finite() {
            return n;
        }
    }
    DVec3::ZERO
}

/// The patch as smooth triangles, `2^u_steps` pieces along u and `2^v_steps` along v (both
/// at most `MAX_STEPS`).
pub fn tessellate(p: &[DVec3; 16], u_steps: u32, v_steps: u32) -> MeshData {
    let nu = 1usize << u_steps.min(MAX_STEPS);
    let nv = 1usize << v_steps.min(MAX_STEPS);
    let points = (nu + 1) * (nv + 1);
    let (mut vertices, mut normals, mut uvs) = (
        Vec::with_capacity(points),
        Vec::with_capacity(points),
        Vec::with_capacity(points),
    );
    let mut push = |u: f64, v: f64, (s, su, sv): (DVec3, DVec3, DVec3)| {
        vertices.push(s);
        normals.push(normal_from(p, u, v, su, sv));
        uvs.push([u, v]);
    };
    #[cfg(target_arch = "x86_64")]
    let avx = crate::math::has_avx();
    #[cfg(not(target_arch = "x86_64"))]
    let avx = false;
    // A row's weights along u, four points' to a batch: [batch][c][lane].
    let us: Vec<f64> = (0..=nu).map(|i| i as f64 / nu as f64).collect();
    let batches: Vec<_> = if avx {
        us.chunks_exact(4)
            .map(|u| {
                let w = [0, 1, 2, 3].map(|k| bernstein(u[k]));
                let lanes = |d: usize| {
                    std::array::from_fn(|c| [0, 1, 2, 3].map(|k| [w[k].0, w[k].1][d][c]))
                };
                (lanes(0), lanes(1))
            })
            .collect()
    } else {
        Vec::new()
    };
    for j in 0..=nv {
        let v = j as f64 / nv as f64;
        let done = 4 * batches.len();
        #[cfg(target_arch = "x86_64")]
        if !batches.is_empty() {
            let (bv, dv) = bernstein(v);
            for (b, (bu, du)) in batches.iter().enumerate() {
                // SAFETY: `batches` is filled only where the CPU has AVX.
                let four = unsafe { eval4_avx(p, bu, du, &bv, &dv) };
                for (k, e) in four.into_iter().enumerate() {
                    push(us[4 * b + k], v, e);
                }
            }
        }
        for &u in &us[done..] {
            push(u, v, eval(p, u, v));
        }
    }
    crate::geom::mesh::grid_mesh_of(nu, nv, vertices, normals, uvs)
}

/// `eval` at four points of one row (`v` fixed): `bu[c][k]` and `du[c][k]` are the weights
/// of `bernstein` at point k's u, `bv` and `dv` at v. Lane k holds point k, so each weight
/// product and product-and-sum serves four points, where `eval_avx` leaves a lane of four
/// unused and makes the weights of every point anew (most of a patch's set-up). Each lane
/// makes `eval_scalar`'s IEEE operations in its order (AVX, no FMA): the same bits.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
unsafe fn eval4_avx(
    p: &[DVec3; 16],
    bu: &[[f64; 4]; 4],
    du: &[[f64; 4]; 4],
    bv: &[f64; 4],
    dv: &[f64; 4],
) -> [(DVec3, DVec3, DVec3); 4] {
    use std::arch::x86_64::{
        _mm256_add_pd, _mm256_loadu_pd, _mm256_mul_pd, _mm256_set1_pd, _mm256_setzero_pd,
        _mm256_storeu_pd,
    };
    // Accumulators [output][coordinate]: the point, d/du and d/dv; x, y, z.
    let mut acc = [[_mm256_setzero_pd(); 3]; 3];
    for r in 0..4 {
        let (wv, wdv) = (_mm256_set1_pd(bv[r]), _mm256_set1_pd(dv[r]));
        for c in 0..4 {
            let (wu, wdu) = (
                _mm256_loadu_pd(bu[c].as_ptr()),
                _mm256_loadu_pd(du[c].as_ptr()),
            );
            let w = [
                _mm256_mul_pd(wu, wv),
                _mm256_mul_pd(wdu, wv),
                _mm256_mul_pd(wu, wdv),
            ];
            let q = p[r * 4 + c];
            for (a, x) in [q.x, q.y, q.z].into_iter().enumerate() {
                let x = _mm256_set1_pd(x);
                for (o, &w) in w.iter().enumerate() {
                    acc[o][a] = _mm256_add_pd(acc[o][a], _mm256_mul_pd(x, w));
                }
            }
        }
    }
    let mut out = [[[0.0; 4]; 3]; 3];
    for (o, a) in out.iter_mut().zip(acc) {
        for (o, a) in o.iter_mut().zip(a) {
            _mm256_storeu_pd(o.as_mut_ptr(), a);
        }
    }
    std::array::from_fn(|k| {
        let v = |o: usize| DVec3::new(out[o][0][k], out[o][1][k], out[o][2][k]);
        (v(0), v(1), v(2))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::mesh::Mesh;
    use crate::geom::Shape;
    use crate::math::Ray;
    use std::sync::Arc;

    fn flat() -> [DVec3; 16] {
        std::array::from_fn(|k| DVec3::new((k % 4) as f64, (k / 4) as f64, 0.0))
    }

    /// The AVX evaluation gives `eval_scalar`'s bits (where the CPU has AVX).
    #[test]
    fn avx_eval_is_the_scalar_one() {
        let mut rng = crate::geom::test_rng::Lcg(11);
        for _ in 0..200 {
            let p: [DVec3; 16] = std::array::from_fn(|_| rng.vec(3.0));
            for _ in 0..50 {
                let (u, v) = (rng.next(), rng.next());
                let (a, b) = (eval(&p, u, v), eval_scalar(&p, u, v));
                for (x, y) in [(a.0, b.0), (a.1, b.1), (a.2, b.2)] {
                    assert_eq!(
                        x.to_array().map(f64::to_bits),
                        y.to_array().map(f64::to_bits)
                    );
                }
            }
        }
    }

    /// The row-by-row tessellation (four points a batch where the CPU has AVX) gives the
    /// vertices, normals and uvs of `eval` and `normal_from` point by point, bit for bit,
    /// with the rows' last points (past the batches) and collapsed edges among them.
    #[test]
    fn batched_rows_are_pointwise_eval() {
        let mut rng = crate::geom::test_rng::Lcg(17);
        for case in 0..40 {
            let mut p: [DVec3; 16] = std::array::from_fn(|_| rng.vec(3.0));
            if case % 4 == 1 {
                for q in p.iter_mut().take(4) {
                    *q = DVec3::new(0.5, -1.0, 2.0);
                }
            }
            let (us, vs) = (case % 5, (case / 5) % 4 + 1);
            let m = tessellate(&p, us as u32, vs as u32);
            let (nu, nv) = (1usize << us, 1usize << vs);
            let want = crate::geom::mesh::grid_mesh(nu, nv, |i, j| {
                let (u, v) = (i as f64 / nu as f64, j as f64 / nv as f64);
                let (s, su, sv) = eval(&p, u, v);
                (s, normal_from(&p, u, v, su, sv), [u, v])
            });
            assert_eq!(format!("{m:?}"), format!("{want:?}"), "case {case}");
            let bits = |v: &[DVec3]| -> Vec<[u64; 3]> {
                v.iter().map(|x| x.to_array().map(f64::to_bits)).collect()
            };
            assert_eq!(bits(&m.vertices), bits(&want.vertices));
            assert_eq!(bits(&m.normals), bits(&want.normals));
        }
    }

    #[test]
    fn corners_are_on_the_patch_and_flat_patch_is_flat() {
        let p = flat();
        let m = tessellate(&p, 2, 3);
        assert_eq!(m.triangles.len(), 4 * 8 * 2);
        assert_eq!(m.vertices[0], p[0]);
        assert_eq!(*m.vertices.last().unwrap(), p[15]);
        for n in &m.normals {
            assert!(n.normalize().abs_diff_eq(DVec3::Z, 1e-12));
        }
    }

    #[test]
    fn a_ray_hits_the_patch_and_nothing_is_inside() {
        let mesh = Mesh::new(Arc::new(tessellate(&flat(), 3, 3)));
        let ray = Ray::new(DVec3::new(1.2, 1.7, -5.0), DVec3::Z);
        let mut hits = Vec::new();
        mesh.intersect_all(&ray, &mut hits);
        assert_eq!(hits.len(), 1);
        assert!((hits[0].t - 5.0).abs() < 1e-9);
        assert!(!mesh.inside(DVec3::new(1.0, 1.0, 0.0)));
    }

    #[test]
    fn collapsed_edge_still_has_a_normal() {
        // A dome: the whole first row is one point.
        let mut p = flat();
        for q in p.iter_mut().take(4) {
            *q = DVec3::new(1.5, 0.0, 1.0);
        }
        let n = normal_at(&p, 0.3, 0.0);
        assert!(n.length() > 0.0 && n.is_finite());
    }
}
