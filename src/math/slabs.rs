//! One ray's slab tests against many boxes, two at a time where SSE2 is there: the BVH walk's
//! child pairs (entry distances) and the union and CSG member scans (answers only). The hottest
//! loop of every scene; each form gives `Aabb::hit`'s answers bit for bit, without its NaN
//! handling where no slab distance can be NaN.

use super::{Aabb, DVec3};

/// A ray's origin and reciprocal direction, sorted once into the cases the tests take:
///
/// - `plain`: finite origin, finite nonzero reciprocals. `(bound - origin) * inv_dir` is never
///   NaN (an infinite bound gives an infinite distance), and without NaNs a comparison (or the
///   SSE minimum and maximum) gives `f64::min`'s and `f64::max`'s values up to the sign of a
///   zero, which no comparison sees. `Aabb::hit` spends a third of its work on the NaN handling.
/// - `paired` (includes `plain`): also reciprocals of ±∞ (a direction component of ±0, as every
///   ray of an axis-aligned orthographic or cylinder camera has, or a subnormal one). Those
///   `flat` axes can make 0·∞ = NaN where the origin lies on a box's face, so the paired tests
///   compute them as `Aabb::hit` does, one box at a time (`flat_axis`).
/// - neither (a non-finite origin, a NaN or infinite direction): `Aabb::hit` for every box.
///
/// `hits` and `hits2` give `Aabb::hit`'s answers exactly, also for a NaN `tmax`; `hit2`, the
/// BVH walk's test, misses both boxes for a NaN `tmax` on the paired path, as the walk has
/// always done (the two differ only in the order of the operands of one minimum).
#[derive(Clone, Copy)]
pub struct Slabs {
    origin: DVec3,
    inv_dir: DVec3,
    plain: bool,
    paired: bool,
    flat: [bool; 3],
    /// The origin's components, then the reciprocal's, each in both lanes: made once per ray,
    /// so that the walk's loop reads them rather than making them at every pair.
    #[cfg(target_arch = "x86_64")]
    wide: [std::arch::x86_64::__m128d; 6],
}

impl Slabs {
    #[inline]
    pub fn new(origin: DVec3, inv_dir: DVec3) -> Slabs {
        // The common case first and cheaply: the member scans make one per ray and CSG node.
        if origin.is_finite() && inv_dir.is_finite() && !inv_dir.cmpeq(DVec3::ZERO).any() {
            return Slabs {
                origin,
                inv_dir,
                plain: true,
                paired: cfg!(target_arch = "x86_64"),
                flat: [false; 3],
                #[cfg(target_arch = "x86_64")]
                wide: wide(origin, inv_dir),
            };
        }
        Slabs::odd(origin, inv_dir)
    }

    /// `new` for a ray with an infinite reciprocal (flat axes), a non-finite origin or a NaN.
    #[cold]
    #[inline(never)]
    fn odd(origin: DVec3, inv_dir: DVec3) -> Slabs {
        Slabs {
            origin,
            inv_dir,
            plain: false,
            paired: cfg!(target_arch = "x86_64")
                && origin.is_finite()
                && !inv_dir.is_nan_mask().any()
                && !inv_dir.cmpeq(DVec3::ZERO).any(),
            flat: [
                inv_dir.x.is_infinite(),
                inv_dir.y.is_infinite(),
                inv_dir.z.is_infinite(),
            ],
            #[cfg(target_arch = "x86_64")]
            wide: wide(origin, inv_dir),
        }
    }

    /// Whether `hit2` takes the paired test (else `Aabb::hit`, box by box): a finite origin
    /// and no NaN or zero reciprocal, on x86_64.
    #[inline]
    pub fn paired(&self) -> bool {
        self.paired
    }

    /// Whether the ray crosses `b` within `[0, tmax]`: `b.hit(origin, inv_dir, tmax).is_some()`.
    #[inline(always)]
    pub fn hits(&self, b: &Aabb, tmax: f64) -> bool {
        if !self.plain {
            return self.hits_nan(b, tmax);
        }
        #[inline(always)]
        fn lo(a: f64, b: f64) -> f64 {
            if a < b {
                a
            } else {
                b
            }
        }
        #[inline(always)]
        fn hi(a: f64, b: f64) -> f64 {
            if a > b {
                a
            } else {
                b
            }
        }
        let t0 = (b.min - self.origin) * self.inv_dir;
        let t1 = (b.max - self.origin) * self.inv_dir;
        let tnear = hi(hi(lo(t0.x, t1.x), hi(lo(t0.y, t1.y), lo(t0.z, t1.z))), 0.0);
        let far = lo(hi(t0.x, t1.x), lo(hi(t0.y, t1.y), hi(t0.z, t1.z)));
        // `far.min(tmax)` keeps `far` when `tmax` is NaN; so does this order.
        let tfar = if tmax < far { tmax } else { far };
        tnear <= tfar
    }

    /// `hits` for a ray that may make NaNs (rare: axis-parallel rays), out of the way of the
    /// inlined plain test.
    #[cold]
    #[inline(never)]
    fn hits_nan(&self, b: &Aabb, tmax: f64) -> bool {
        b.hit(self.origin, self.inv_dir, tmax).is_some()
    }

    /// `hits` of two boxes at once: `Aabb::hit(..).is_some()` of each, also for a NaN `tmax`.
    #[inline(always)]
    pub fn hits2(&self, a: &Aabb, b: &Aabb, tmax: f64) -> (bool, bool) {
        #[cfg(target_arch = "x86_64")]
        if self.plain {
            return Slabs::answers(self.lanes::<false>(a, b), tmax);
        }
        self.hits2_odd(a, b, tmax)
    }

    /// `hits2` for a ray with flat axes (the paired test with them apart) or one that may make
    /// NaNs (`Aabb::hit`), out of the way of the inlined plain test.
    #[cold]
    #[inline(never)]
    fn hits2_odd(&self, a: &Aabb, b: &Aabb, tmax: f64) -> (bool, bool) {
        #[cfg(target_arch = "x86_64")]
        if self.paired {
            return Slabs::answers(self.lanes::<true>(a, b), tmax);
        }
        (self.hits(a, tmax), self.hits(b, tmax))
    }

    /// `hits2`'s answers from the paired entry and exit distances.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    fn answers(
        (near, far): (std::arch::x86_64::__m128d, std::arch::x86_64::__m128d),
        tmax: f64,
    ) -> (bool, bool) {
        use std::arch::x86_64::*;
        // SAFETY: SSE2 is part of x86_64.
        let mask = unsafe {
            // `far.min(tmax)`, which keeps `far` when `tmax` is NaN: minpd returns its second
            // operand when either is NaN, and `far` never is.
            let far = _mm_min_pd(_mm_set1_pd(tmax), far);
            _mm_movemask_pd(_mm_cmple_pd(near, far))
        };
        (mask & 1 != 0, mask & 2 != 0)
    }

    /// The entry distances of `a` and of `b` where the ray crosses them within `[0, tmax]`, as
    /// `Aabb::hit` has them, except that a NaN `tmax` misses both boxes on the paired path
    /// (the BVH walk, this test's user, has always stopped there: the operand order below).
    #[inline(always)]
    pub fn hit2(&self, a: &Aabb, b: &Aabb, tmax: f64) -> (Option<f64>, Option<f64>) {
        #[cfg(target_arch = "x86_64")]
        if self.paired {
            use std::arch::x86_64::*;
            // One body for plain and flat rays, as the walk has always had it: its loop is
            // tight, and a second copy for flat rays cost 1-2 % of cornell.
            let (near, far) = self.lanes::<true>(a, b);
            // SAFETY: SSE2 is part of x86_64; the store writes two doubles into a two-double
            // array.
            unsafe {
                // minpd returns its second operand, `tmax`, when it is NaN.
                let far = _mm_min_pd(far, _mm_set1_pd(tmax));
                let mask = _mm_movemask_pd(_mm_cmple_pd(near, far));
                let mut t = [0.0f64; 2];
                _mm_storeu_pd(t.as_mut_ptr(), near);
                return (
                    (mask & 1 != 0).then_some(t[0]),
                    (mask & 2 != 0).then_some(t[1]),
                );
            }
        }
        (
            a.hit(self.origin, self.inv_dir, tmax).map(|t| t.0),
            b.hit(self.origin, self.inv_dir, tmax).map(|t| t.0),
        )
    }

    /// The paired test's entry distances (`a` low lane, `b` high) and exit distances before
    /// the `tmax` clamp, each lane `Aabb::hit`'s operations in its order: per axis the minimum
    /// and maximum of the two slab distances, then `max_element` as `x.max(y.max(z))` and
    /// `.max(0.0)`, `min_element` likewise. Neither can be NaN. `FLAT`: the ray may have flat
    /// axes (not `plain`); a plain ray's test then has no branch.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    fn lanes<const FLAT: bool>(
        &self,
        a: &Aabb,
        b: &Aabb,
    ) -> (std::arch::x86_64::__m128d, std::arch::x86_64::__m128d) {
        use std::arch::x86_64::*;
        // SAFETY: SSE2 is part of x86_64.
        unsafe {
            let axis = |k: usize, lo_a: f64, lo_b: f64, hi_a: f64, hi_b: f64| {
                if FLAT && self.flat[k] {
                    let (na, fa) = self.flat_axis(k, lo_a, hi_a);
                    let (nb, fb) = self.flat_axis(k, lo_b, hi_b);
                    return (_mm_set_pd(nb, na), _mm_set_pd(fb, fa));
                }
                let (o, inv) = (self.wide[k], self.wide[3 + k]);
                let t0 = _mm_mul_pd(_mm_sub_pd(_mm_set_pd(lo_b, lo_a), o), inv);
                let t1 = _mm_mul_pd(_mm_sub_pd(_mm_set_pd(hi_b, hi_a), o), inv);
                (_mm_min_pd(t0, t1), _mm_max_pd(t0, t1))
            };
            let (nx, fx) = axis(0, a.min.x, b.min.x, a.max.x, b.max.x);
            let (ny, fy) = axis(1, a.min.y, b.min.y, a.max.y, b.max.y);
            let (nz, fz) = axis(2, a.min.z, b.min.z, a.max.z, b.max.z);
            let near = _mm_max_pd(_mm_max_pd(nx, _mm_max_pd(ny, nz)), _mm_setzero_pd());
            let far = _mm_min_pd(fx, _mm_min_pd(fy, fz));
            (near, far)
        }
    }

    /// A flat axis's (near, far) slab distances for one box, as `Aabb::hit` has them: its
    /// `f64::min` and `f64::max` of the two distances, which ignore a NaN. Both NaN (a box
    /// flat in this axis with the origin in its plane) gives (−∞, +∞), which the reductions
    /// that follow treat as `f64::max` and `f64::min` treat the NaNs: as absent.
    #[inline]
    fn flat_axis(&self, k: usize, lo: f64, hi: f64) -> (f64, f64) {
        let (o, inv) = (self.origin[k], self.inv_dir[k]);
        let (t0, t1) = ((lo - o) * inv, (hi - o) * inv);
        let (near, far) = (t0.min(t1), t0.max(t1));
        if near.is_nan() {
            (f64::NEG_INFINITY, f64::INFINITY)
        } else {
            (near, far)
        }
    }
}

/// `Slabs::wide`.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn wide(o: DVec3, inv: DVec3) -> [std::arch::x86_64::__m128d; 6] {
    use std::arch::x86_64::_mm_set1_pd;
    // SAFETY: SSE2 is part of x86_64.
    unsafe {
        [
            _mm_set1_pd(o.x),
            _mm_set1_pd(o.y),
            _mm_set1_pd(o.z),
            _mm_set1_pd(inv.x),
            _mm_set1_pd(inv.y),
            _mm_set1_pd(inv.z),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::test_rng::Lcg;

    /// Every form of the test against `Aabb::hit` for one ray and the pair (`a`, `b`) in both
    /// orders: the answers, and the entry distances bit for bit (a zero of either sign counts
    /// as zero, as no comparison tells them apart). Returns whether `a` was crossed.
    fn check_pair(origin: DVec3, inv_dir: DVec3, a: &Aabb, b: &Aabb, tmax: f64, ctx: &str) -> bool {
        let s = Slabs::new(origin, inv_dir);
        let want = |x: &Aabb| x.hit(origin, inv_dir, tmax).map(|t| t.0);
        let (wa, wb) = (want(a), want(b));
        assert_eq!(s.hits(a, tmax), wa.is_some(), "hits {ctx}");
        assert_eq!(
            s.hits2(a, b, tmax),
            (wa.is_some(), wb.is_some()),
            "hits2 {ctx}"
        );
        assert_eq!(
            s.hits2(b, a, tmax),
            (wb.is_some(), wa.is_some()),
            "hits2 {ctx}"
        );
        let entry = |t: Option<f64>| t.map(|t| if t == 0.0 { 0 } else { t.to_bits() });
        let (ha, hb) = s.hit2(a, b, tmax);
        if tmax.is_nan() && s.paired {
            assert_eq!((ha, hb), (None, None), "hit2 {ctx}");
        } else {
            assert_eq!(entry(ha), entry(wa), "hit2 {ctx}");
            assert_eq!(entry(hb), entry(wb), "hit2 {ctx}");
        }
        wa.is_some()
    }

    /// Rays with and without NaN-prone directions against random, flat, infinite and empty
    /// boxes, with finite, infinite and NaN `tmax`.
    #[test]
    fn slabs_match_aabb_hit() {
        let mut rng = Lcg(7);
        let mut rnd = || rng.next() * 2.0 - 1.0;
        let specials = [0.0, -0.0, 1.0, f64::INFINITY, f64::NEG_INFINITY];
        let mut crossed = 0;
        let mut prev = Aabb::INFINITE;
        for k in 0..20000 {
            let mut origin = DVec3::new(rnd(), rnd(), rnd()) * 4.0;
            let mut dir = DVec3::new(rnd(), rnd(), rnd());
            if k % 5 == 0 {
                dir[k / 5 % 3] = 0.0;
            }
            if k % 11 == 0 {
                origin[k / 11 % 3] = 1.0;
            }
            if k % 97 == 0 {
                origin[k % 3] = f64::INFINITY;
            }
            let mut b = Aabb::new(
                DVec3::new(rnd(), rnd(), rnd()) * 3.0,
                DVec3::new(rnd(), rnd(), rnd()) * 3.0,
            );
            match k % 7 {
                0 => b.max.y = b.min.y,
                1 => b.min[k % 3] = specials[k / 7 % 5],
                2 => b = Aabb::INFINITE,
                3 => b = Aabb::EMPTY,
                _ => {}
            }
            let tmax = match k % 13 {
                0 => f64::INFINITY,
                1 => f64::NAN,
                _ => rnd().abs() * 10.0,
            };
            let ctx = format!("{k}: {origin} {dir} {b:?} {tmax}");
            crossed += usize::from(check_pair(origin, dir.recip(), &b, &prev, tmax, &ctx));
            prev = b;
        }
        assert!(crossed > 2000, "{crossed}");
    }

    /// Finite boxes, flat ones, a point and one around the origin, for rays from random points
    /// and from the origin (on faces).
    #[test]
    fn paired_slabs_match_aabb_hit() {
        let mut rng = Lcg(5);
        let mut boxes: Vec<Aabb> = (0..64)
            .map(|_| {
                let (a, b) = (rng.vec(10.0), rng.vec(10.0));
                Aabb::new(a.min(b), a.max(b))
            })
            .collect();
        boxes.push(Aabb::new(
            DVec3::new(-1.0, 0.0, -1.0),
            DVec3::new(1.0, 0.0, 1.0),
        ));
        boxes.push(Aabb::new(DVec3::splat(0.5), DVec3::splat(0.5)));
        boxes.push(Aabb::new(DVec3::splat(-20.0), DVec3::splat(20.0)));
        for k in 0..4000 {
            let origin = if k % 7 == 0 {
                DVec3::ZERO
            } else {
                rng.vec(15.0)
            };
            let inv_dir = DVec3::ONE / rng.vec(2.0);
            let tmax = if k % 3 == 0 {
                f64::INFINITY
            } else {
                rng.next() * 30.0
            };
            let (a, b) = (&boxes[k % boxes.len()], &boxes[(k * 7 + 3) % boxes.len()]);
            check_pair(origin, inv_dir, a, b, tmax, &format!("{k}"));
        }
        assert!(!Slabs::new(DVec3::splat(f64::INFINITY), DVec3::ONE).paired);
        assert!(!Slabs::new(DVec3::ZERO, DVec3::splat(f64::NAN)).paired);
    }

    /// Rays with direction components of ±0 (infinite reciprocals) whose origins lie inside,
    /// outside and exactly on the boxes' faces, where `Aabb::hit` meets 0·∞ = NaN.
    #[test]
    fn paired_slabs_match_aabb_hit_for_flat_rays() {
        let mut rng = Lcg(11);
        // Whole-number corners, so that origins picked on the same grid land on faces.
        let grid = |rng: &mut Lcg| (rng.next() * 8.0).floor() - 4.0;
        let mut boxes = Vec::new();
        for _ in 0..48 {
            let a = DVec3::new(grid(&mut rng), grid(&mut rng), grid(&mut rng));
            let b = DVec3::new(grid(&mut rng), grid(&mut rng), grid(&mut rng));
            boxes.push(Aabb::new(a.min(b), a.max(b)));
        }
        let zeros = [0.0, -0.0];
        for k in 0..20_000usize {
            let origin = DVec3::new(grid(&mut rng), grid(&mut rng), grid(&mut rng))
                + if k % 2 == 0 {
                    DVec3::ZERO
                } else {
                    rng.vec(0.5)
                };
            let mut dir = rng.vec(2.0);
            // One or two components zero (of either sign); sometimes a subnormal one, whose
            // reciprocal overflows to infinity.
            let z = zeros[k % 2];
            match k % 7 {
                0 => dir.x = z,
                1 => dir.y = z,
                2 => dir.z = z,
                3 => (dir.x, dir.y) = (z, -z),
                4 => (dir.y, dir.z) = (z, z),
                5 => dir.x = 1e-310,
                _ => (dir.x, dir.z) = (-z, z),
            }
            let inv_dir = DVec3::ONE / dir;
            assert!(
                Slabs::new(origin, inv_dir).paired || cfg!(not(target_arch = "x86_64")),
                "flat rays take the paired test"
            );
            let tmax = if k % 3 == 0 {
                f64::INFINITY
            } else {
                rng.next() * 30.0
            };
            let (a, b) = (&boxes[k % boxes.len()], &boxes[(k * 7 + 3) % boxes.len()]);
            check_pair(origin, inv_dir, a, b, tmax, &format!("{k}"));
        }
    }
}
