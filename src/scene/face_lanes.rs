//! A polyhedron's faces (`Faces::all`: every member a plane with an axis normal) laid out four
//! to a block, coordinate by coordinate, so that a ray's crossings with all of them, and a
//! point's inside tests against all of them, are a few AVX operations per four faces.
//!
//! textures/pigments/dodec2 spends ~70 % of its time in `faces_first_hit`: per ray twelve
//! divisions one after another, then per candidate crossing the inside tests as one call per
//! face. Each lane here is `Face::hit` / `Face::inside`'s arithmetic for its face, the same
//! IEEE operations in the same order (nothing fused), so the same bits. A face without a
//! transform (`point` reads the point's component itself) gets the unit row of its axis:
//! `((±0 + ±0) + 1·c) + 0` is `c` unless `c` is zero, and then a zero of either sign, which
//! `faces`' module documentation shows no answer can tell apart.

use crate::math::{DVec3, Ray, EPSILON};
use crate::scene::desc::CsgOp;
use crate::scene::faces::{Face, MAX_ALL};

/// Four faces' inverse-transform rows (x, y, z coefficients and offset), signs and
/// distances, one lane per face.
#[repr(C, align(32))]
#[derive(Clone, Copy, Debug)]
struct Block {
    x: [f64; 4],
    y: [f64; 4],
    z: [f64; 4],
    w: [f64; 4],
    sign: [f64; 4],
    distance: [f64; 4],
}

/// Lanes past the last face: no crossing (a zero row makes the denominator zero) and masked
/// out of every answer anyway.
const PAD: Block = Block {
    x: [0.0; 4],
    y: [0.0; 4],
    z: [0.0; 4],
    w: [0.0; 4],
    sign: [1.0; 4],
    distance: [0.0; 4],
};

/// The faces of a node whose members are all faces, by member, four to a block.
#[derive(Clone, Debug)]
pub struct FaceLanes {
    blocks: Box<[Block]>,
    /// Bit j: member j is `inverse`.
    inverse: u32,
    /// Bit j set for each member.
    members: u32,
}

impl FaceLanes {
    /// The lanes of `faces` (each `Some`, at most `MAX_ALL`), `inverse` bit j for member j.
    pub fn of(faces: &[Option<Face>], inverse: u32) -> Option<FaceLanes> {
        if faces.len() > MAX_ALL || faces.is_empty() {
            return None;
        }
        let mut blocks = vec![PAD; faces.len().div_ceil(4)].into_boxed_slice();
        for (j, f) in faces.iter().enumerate() {
            let (row, sign, distance) = f.as_ref()?.lane_values();
            let (b, l) = (&mut blocks[j / 4], j % 4);
            (b.x[l], b.y[l], b.z[l], b.w[l]) = (row[0], row[1], row[2], row[3]);
            (b.sign[l], b.distance[l]) = (sign, distance);
        }
        let members = (u64::MAX >> (64 - faces.len())) as u32;
        Some(FaceLanes {
            blocks,
            inverse,
            members,
        })
    }

    /// Bit j set for each member.
    #[inline]
    pub fn members(&self) -> u32 {
        self.members
    }

    /// Bit j: the inside answer member j must give for another member's crossing to be kept
    /// by a node `op` (`wants` in `faces_first_hit`: `(inside != inverse) == want_inside`).
    #[inline]
    pub fn expected(&self, op: CsgOp) -> u32 {
        let want = match op {
            CsgOp::Intersection => self.members,
            CsgOp::Difference => 1,
            CsgOp::Union | CsgOp::Merge => 0,
        };
        (want ^ self.inverse) & self.members
    }

    /// `Face::hit` of every member below `tmax`: bit j set when member j crosses the ray at
    /// `ts[j]` (`ts` of the others is left unspecified). The ray must be `faces::ray_ok`.
    ///
    /// # Safety
    /// The CPU must have AVX.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    pub unsafe fn hits_avx(&self, ray: &Ray, tmax: f64, ts: &mut [f64; MAX_ALL]) -> u32 {
        use std::arch::x86_64::*;
        let (o, d) = (ray.origin, ray.dir);
        let (ox, oy, oz) = (
            _mm256_set1_pd(o.x),
            _mm256_set1_pd(o.y),
            _mm256_set1_pd(o.z),
        );
        let (dx, dy, dz) = (
            _mm256_set1_pd(d.x),
            _mm256_set1_pd(d.y),
            _mm256_set1_pd(d.z),
        );
        let (eps, inf, tmax) = (
            _mm256_set1_pd(EPSILON),
            _mm256_set1_pd(f64::INFINITY),
            _mm256_set1_pd(tmax),
        );
        let mut bits = 0u32;
        for (k, b) in self.blocks.iter().enumerate() {
            let (x, y, z) = (
                _mm256_load_pd(b.x.as_ptr()),
                _mm256_load_pd(b.y.as_ptr()),
                _mm256_load_pd(b.z.as_ptr()),
            );
            let sign = _mm256_load_pd(b.sign.as_ptr());
            // `vector`: (x·dx + y·dy) + z·dz; `point`: ((x·ox + y·oy) + z·oz) + w.
            let v = _mm256_add_pd(
                _mm256_add_pd(_mm256_mul_pd(x, dx), _mm256_mul_pd(y, dy)),
                _mm256_mul_pd(z, dz),
            );
            let p = _mm256_add_pd(
                _mm256_add_pd(
                    _mm256_add_pd(_mm256_mul_pd(x, ox), _mm256_mul_pd(y, oy)),
                    _mm256_mul_pd(z, oz),
                ),
                _mm256_load_pd(b.w.as_ptr()),
            );
            let denom = _mm256_mul_pd(sign, v);
            let num = _mm256_sub_pd(_mm256_load_pd(b.distance.as_ptr()), _mm256_mul_pd(sign, p));
            let t = _mm256_div_pd(num, denom);
            // `hit`'s `denom == 0` needs no test of its own: anything over ±0 is ±inf or
            // NaN, which `t > EPSILON && t < inf` turns away as `is_finite` does.
            let ok = _mm256_and_pd(
                _mm256_and_pd(
                    _mm256_cmp_pd::<_CMP_GT_OQ>(t, eps),
                    _mm256_cmp_pd::<_CMP_LT_OQ>(t, inf),
                ),
                _mm256_cmp_pd::<_CMP_LT_OQ>(t, tmax),
            );
            _mm256_storeu_pd(ts.as_mut_ptr().add(4 * k), t);
            bits |= (_mm256_movemask_pd(ok) as u32) << (4 * k);
        }
        bits & self.members
    }

    /// `Face::inside` of every member at `p`: bit j set when `p` is inside member j. The
    /// point must be `faces::point_ok`.
    ///
    /// # Safety
    /// The CPU must have AVX.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    pub unsafe fn inside_avx(&self, p: DVec3) -> u32 {
        use std::arch::x86_64::*;
        let (px, py, pz) = (
            _mm256_set1_pd(p.x),
            _mm256_set1_pd(p.y),
            _mm256_set1_pd(p.z),
        );
        let mut bits = 0u32;
        for (k, b) in self.blocks.iter().enumerate() {
            let q = _mm256_add_pd(
                _mm256_add_pd(
                    _mm256_add_pd(
                        _mm256_mul_pd(_mm256_load_pd(b.x.as_ptr()), px),
                        _mm256_mul_pd(_mm256_load_pd(b.y.as_ptr()), py),
                    ),
                    _mm256_mul_pd(_mm256_load_pd(b.z.as_ptr()), pz),
                ),
                _mm256_load_pd(b.w.as_ptr()),
            );
            let inside = _mm256_cmp_pd::<_CMP_LT_OQ>(
                _mm256_mul_pd(_mm256_load_pd(b.sign.as_ptr()), q),
                _mm256_load_pd(b.distance.as_ptr()),
            );
            bits |= (_mm256_movemask_pd(inside) as u32) << (4 * k);
        }
        bits & self.members
    }
}

#[cfg(all(test, target_arch = "x86_64"))]
#[path = "face_lanes_tests.rs"]
mod tests;
