//! Geometry primitives shared by every stage: rays, affine transforms and bounding boxes.
//!
//! Everything is f64 because POV-Ray computes in double precision and quadrics, tori and
//! polynomial roots visibly differ in single precision.

pub use glam::{DMat3, DMat4, DVec3};

/// Distances below this along a ray are treated as self-intersections.
pub const EPSILON: f64 = 1e-6;

#[derive(Clone, Copy, Debug)]
pub struct Ray {
    pub origin: DVec3,
    /// Not necessarily unit length: object-space rays keep the scale of the transform so that
    /// `t` means the same distance in world and object space.
    pub dir: DVec3,
}

impl Ray {
    pub fn new(origin: DVec3, dir: DVec3) -> Ray {
        Ray { origin, dir }
    }
    pub fn at(&self, t: f64) -> DVec3 {
        self.origin + self.dir * t
    }
}

/// An affine transform with its inverse kept alongside, so rays can be taken into object space
/// and normals brought back without inverting per ray.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    pub m: DMat4,
    pub inv: DMat4,
}

impl Default for Transform {
    fn default() -> Self {
        Transform::IDENTITY
    }
}

/// The identity at one address: `is_identity` answers a reference to it with one compare,
/// where the entry-by-entry test cost ~60 instructions a normal for every plain layer (which
/// passes its space as the identity). `&Transform::IDENTITY` may be a copy at another address
/// and is then compared entry by entry, with the same answer.
pub static IDENTITY: Transform = Transform::IDENTITY;

impl Transform {
    pub const IDENTITY: Transform = Transform {
        m: DMat4::IDENTITY,
        inv: DMat4::IDENTITY,
    };

    pub fn from_matrix(m: DMat4) -> Transform {
        Transform {
            m,
            inv: m.inverse(),
        }
    }
    pub fn translate(v: DVec3) -> Transform {
        Transform {
            m: DMat4::from_translation(v),
            inv: DMat4::from_translation(-v),
        }
    }
    pub fn scale(v: DVec3) -> Transform {
        // POV-Ray replaces a zero scale by 1 (with a warning) rather than making it singular.
        let v = DVec3::new(nz(v.x), nz(v.y), nz(v.z));
        Transform {
            m: DMat4::from_scale(v),
            inv: DMat4::from_scale(1.0 / v),
        }
    }
    /// POV-Ray `rotate <x,y,z>` in degrees: about x, then y, then z, left-handed.
    pub fn rotate(deg: DVec3) -> Transform {
        let r = deg * (std::f64::consts::PI / 180.0);
        let m =
            DMat4::from_rotation_z(r.z) * DMat4::from_rotation_y(r.y) * DMat4::from_rotation_x(r.x);
        Transform {
            m,
            inv: m.transpose(),
        }
    }
    /// The 12-number `matrix < ... >` of POV-Ray: rows are the images of x, y, z then the offset.
    pub fn pov_matrix(v: &[f64; 12]) -> Transform {
        let m = DMat4::from_cols_array(&[
            v[0], v[1], v[2], 0.0, v[3], v[4], v[5], 0.0, v[6], v[7], v[8], 0.0, v[9], v[10],
            v[11], 1.0,
        ]);
        Transform::from_matrix(m)
    }
    /// `self` followed by `next`.
    pub fn then(&self, next: &Transform) -> Transform {
        Transform {
            m: next.m * self.m,
            inv: self.inv * next.inv,
        }
    }
    pub fn inverse(&self) -> Transform {
        Transform {
            m: self.inv,
            inv: self.m,
        }
    }
    /// Whether `m` is the identity, entry for entry (`==`: −0 counts as 0).
    #[inline]
    pub fn is_identity(&self) -> bool {
        // The first entry alone first: a scale or rotation (most pattern transforms) differs
        // there, and the whole comparison, which the compiler makes branch-free, was ~45
        // instructions on every pigment and normal evaluation. The static identity (plain
        // layers' space, absent transforms) is known by its address.
        self.m.x_axis.x == 1.0 && (std::ptr::eq(self, &IDENTITY) || self.m == DMat4::IDENTITY)
    }
    pub fn point(&self, p: DVec3) -> DVec3 {
        self.m.transform_point3(p)
    }
    pub fn vector(&self, v: DVec3) -> DVec3 {
        self.m.transform_vector3(v)
    }
    pub fn inv_point(&self, p: DVec3) -> DVec3 {
        self.inv.transform_point3(p)
    }
    pub fn inv_vector(&self, v: DVec3) -> DVec3 {
        self.inv.transform_vector3(v)
    }
    /// Object-space normal to world space (inverse transpose), not normalised.
    pub fn normal(&self, n: DVec3) -> DVec3 {
        self.inv.transpose().transform_vector3(n)
    }
    pub fn inv_ray(&self, r: &Ray) -> Ray {
        Ray {
            origin: self.inv_point(r.origin),
            dir: self.inv_vector(r.dir),
        }
    }
}

/// A transform kept out of line: 8 bytes in the common case of none at all, where the inline
/// `Transform` (two 4×4 matrices) is 256. Scene descriptions hold one per object and per
/// pigment, a million of them in a big `#while` loop. Reads see the same `Transform` values
/// as before (`Transform::IDENTITY` when none was given), so pictures do not change.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Xform(Option<Box<Transform>>);

impl Xform {
    pub const IDENTITY: Xform = Xform(None);

    pub fn get(&self) -> &Transform {
        self.0.as_deref().unwrap_or(&IDENTITY)
    }

    /// `get().is_identity()`, answered without a look at the matrix when there is none.
    #[inline]
    pub fn is_identity(&self) -> bool {
        self.0.as_deref().is_none_or(Transform::is_identity)
    }

    /// Follows this transform by `t` (what `Transform::then` computes, identity included, so
    /// the result is bit for bit the same).
    pub fn apply(&mut self, t: &Transform) {
        *self = Xform::from(self.get().then(t));
    }
}

impl From<Transform> for Xform {
    fn from(t: Transform) -> Xform {
        Xform(Some(Box::new(t)))
    }
}

impl std::ops::Deref for Xform {
    type Target = Transform;
    fn deref(&self) -> &Transform {
        self.get()
    }
}

fn nz(x: f64) -> f64 {
    if x == 0.0 {
        1.0
    } else {
        x
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    pub min: DVec3,
    pub max: DVec3,
}

impl Aabb {
    pub const EMPTY: Aabb = Aabb {
        min: DVec3::splat(f64::INFINITY),
        max: DVec3::splat(f64::NEG_INFINITY),
    };
    pub const INFINITE: Aabb = Aabb {
        min: DVec3::splat(f64::NEG_INFINITY),
        max: DVec3::splat(f64::INFINITY),
    };

    pub fn new(min: DVec3, max: DVec3) -> Aabb {
        Aabb { min, max }
    }
    pub fn is_finite(&self) -> bool {
        self.min.is_finite() && self.max.is_finite()
    }
    pub fn is_empty(&self) -> bool {
        self.min.x > self.max.x || self.min.y > self.max.y || self.min.z > self.max.z
    }
    pub fn union(&self, o: &Aabb) -> Aabb {
        Aabb {
            min: self.min.min(o.min),
            max: self.max.max(o.max),
        }
    }
    pub fn intersection(&self, o: &Aabb) -> Aabb {
        Aabb {
            min: self.min.max(o.min),
            max: self.max.min(o.max),
        }
    }
    /// Whether `p` lies in the box (its faces included).
    pub fn contains(&self, p: DVec3) -> bool {
        p.cmpge(self.min).all() && p.cmple(self.max).all()
    }

    /// `contains` by six scalar comparisons (each false for a NaN, as there), for a `p` the
    /// caller has just stored for a call: `contains` inlined read p's y and z as one 16-byte
    /// load, which the store buffer cannot forward from the copy's x-y and z stores (a stall
    /// of ~30 % of `csg_keeps`' own samples on objects/csg/cliptst2).
    #[inline(always)]
    pub fn holds(&self, p: DVec3) -> bool {
        (p.x >= self.min.x)
            & (p.y >= self.min.y)
            & (p.z >= self.min.z)
            & (p.x <= self.max.x)
            & (p.y <= self.max.y)
            & (p.z <= self.max.z)
    }

    pub fn grow(&self, p: DVec3) -> Aabb {
        Aabb {
            min: self.min.min(p),
            max: self.max.max(p),
        }
    }
    pub fn center(&self) -> DVec3 {
        (self.min + self.max) * 0.5
    }
    pub fn surface_area(&self) -> f64 {
        if self.is_empty() {
            return 0.0;
        }
        let d = self.max - self.min;
        2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)
    }
    /// Bounds of this box after an affine transform (all eight corners).
    pub fn transformed(&self, t: &Transform) -> Aabb {
        if !self.is_finite() {
            return if self.is_empty() {
                *self
            } else {
                Aabb::INFINITE
            };
        }
        self.corners_mapped(&t.m)
    }
    /// The box of this finite box's eight corners taken through the affine matrix `m`.
    pub fn corners_mapped(&self, m: &DMat4) -> Aabb {
        let mut out = Aabb::EMPTY;
        for i in 0..8 {
            let p = DVec3::new(
                if i & 1 == 0 { self.min.x } else { self.max.x },
                if i & 2 == 0 { self.min.y } else { self.max.y },
                if i & 4 == 0 { self.min.z } else { self.max.z },
            );
            out = out.grow(m.transform_point3(p));
        }
        out
    }
    /// Slab test; returns the entry and exit distances when the ray crosses the box within
    /// `[0, tmax]`. `inv_dir` is 1/dir, precomputed once per ray.
    #[inline]
    pub fn hit(&self, origin: DVec3, inv_dir: DVec3, tmax: f64) -> Option<(f64, f64)> {
        let t0 = (self.min - origin) * inv_dir;
        let t1 = (self.max - origin) * inv_dir;
        let tnear = t0.min(t1).max_element().max(0.0);
        let tfar = t0.max(t1).min_element().min(tmax);
        // NaN from 0*inf (ray in a slab plane) compares false, which keeps the box.
        if tnear <= tfar {
            Some((tnear, tfar))
        } else {
            None
        }
    }
}

/// One ray's slab tests against many boxes (a union's members): `Aabb::hit(..).is_some()`,
/// through plain comparisons where no slab distance can be NaN. With a finite origin and
/// finite, nonzero `inv_dir` components, `(bound - origin) * inv_dir` is never NaN (an
/// infinite bound gives an infinite distance), and without NaNs a comparison-and-select gives
/// `f64::min`'s and `f64::max`'s values (up to the sign of a zero, which `<=` does not see),
/// so the answer is `Aabb::hit`'s; their NaN handling was a third of the test (cornell's room
/// is a union of six triangles, tested box by box for every shadow and gathering ray).
#[derive(Clone, Copy)]
pub struct Slabs {
    origin: DVec3,
    inv_dir: DVec3,
    /// No NaN possible: the plain comparisons apply.
    clean: bool,
}

impl Slabs {
    #[inline]
    pub fn new(origin: DVec3, inv_dir: DVec3) -> Slabs {
        let clean = origin.is_finite() && inv_dir.is_finite() && !inv_dir.cmpeq(DVec3::ZERO).any();
        Slabs {
            origin,
            inv_dir,
            clean,
        }
    }

    /// `new` for a ray whose `clean` is already known (`geom::bvh::Recip::plain` is `new`'s
    /// test), without testing it again.
    #[inline]
    pub fn known(origin: DVec3, inv_dir: DVec3, clean: bool) -> Slabs {
        debug_assert_eq!(clean, Slabs::new(origin, inv_dir).clean);
        Slabs {
            origin,
            inv_dir,
            clean,
        }
    }

    /// Whether the ray crosses `b` within `[0, tmax]`: `b.hit(origin, inv_dir, tmax).is_some()`.
    #[inline(always)]
    pub fn hits(&self, b: &Aabb, tmax: f64) -> bool {
        if !self.clean {
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
        // Each component by an 8-byte load, as in `hits2`: the callers build their `Slabs`
        // just before (the x-y pair and z as they came), and LLVM copied the origin for a
        // member loop as x and a y-z pair, a 16-byte load across two stores that the store
        // buffer cannot forward (csg_first_hit on advanced/whiltile).
        let (origin, inv_dir) = (by_coordinates(&self.origin), by_coordinates(&self.inv_dir));
        let t0 = (b.min - origin) * inv_dir;
        let t1 = (b.max - origin) * inv_dir;
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

    /// `hits` of two boxes at once, one per SSE lane (each lane the scalar test's operations
    /// in its order).
    #[inline(always)]
    pub fn hits2(&self, a: &Aabb, b: &Aabb, tmax: f64) -> (bool, bool) {
        #[cfg(target_arch = "x86_64")]
        if self.clean {
            use std::arch::x86_64::*;
            // SAFETY: SSE2 is part of x86_64; the volatile reads read initialised doubles
            // through references.
            unsafe {
                let axis = |o: f64, inv: f64, lo_a: f64, lo_b: f64, hi_a: f64, hi_b: f64| {
                    let (o, inv) = (_mm_set1_pd(o), _mm_set1_pd(inv));
                    let t0 = _mm_mul_pd(_mm_sub_pd(_mm_set_pd(lo_b, lo_a), o), inv);
                    let t1 = _mm_mul_pd(_mm_sub_pd(_mm_set_pd(hi_b, hi_a), o), inv);
                    (_mm_min_pd(t0, t1), _mm_max_pd(t0, t1))
                };
                // Each component by an 8-byte load. The callers (a union's scan) build their
                // `Slabs` just before, stored as the x-y pair and z it came in as; LLVM read
                // y-z back as one 16-byte load spanning both stores, which the store buffer
                // cannot forward (a fifth of `Object::first_hit`'s samples on
                // camera/perspective). A volatile read keeps each load its own.
                let (o, inv) = (&self.origin, &self.inv_dir);
                let get = |v: &f64| std::ptr::read_volatile(v);
                let (nx, fx) = axis(get(&o.x), get(&inv.x), a.min.x, b.min.x, a.max.x, b.max.x);
                let (ny, fy) = axis(get(&o.y), get(&inv.y), a.min.y, b.min.y, a.max.y, b.max.y);
                let (nz, fz) = axis(get(&o.z), get(&inv.z), a.min.z, b.min.z, a.max.z, b.max.z);
                let near = _mm_max_pd(_mm_max_pd(nx, _mm_max_pd(ny, nz)), _mm_setzero_pd());
                let far = _mm_min_pd(fx, _mm_min_pd(fy, fz));
                // `far.min(tmax)`, which keeps `far` when `tmax` is NaN: minpd returns its
                // second operand when either is NaN.
                let far = _mm_min_pd(_mm_set1_pd(tmax), far);
                let mask = _mm_movemask_pd(_mm_cmple_pd(near, far));
                return (mask & 1 != 0, mask & 2 != 0);
            }
        }
        (self.hits(a, tmax), self.hits(b, tmax))
    }
}

/// Numbers in [0, 1) from a xorshift generator started at `seed`: the random inputs of tests
/// that compare two computations over many cases.
#[cfg(test)]
pub(crate) fn xorshift_unit(mut seed: u64) -> impl FnMut() -> f64 {
    move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// `*v`, read as three 8-byte loads. A `DVec3` a caller has just written is stored as an x-y
/// pair (16 bytes) and z (8); LLVM may read it back as x and a y-z pair, and a 16-byte load
/// spanning both stores cannot be forwarded from the store buffer: it waits until the stores
/// reach the cache (~12 cycles, invisible to callgrind, a tenth to a third of the samples of
/// the functions that did it: the BVH walk, the shadow test, `Light::beam_from`). Volatile
/// reads keep LLVM from merging the loads again.
#[inline(always)]
pub fn by_coordinates(v: &DVec3) -> DVec3 {
    // SAFETY: the pointers come from a reference to initialised doubles.
    unsafe {
        DVec3::new(
            std::ptr::read_volatile(&v.x),
            std::ptr::read_volatile(&v.y),
            std::ptr::read_volatile(&v.z),
        )
    }
}

/// `a.dot(b)` bit for bit (`(x + y) + z`, the same products), with x and y multiplied as one
/// SSE pair. A `DVec3` passed to a shape's `inside` is the caller's copy, stored as x-y (16
/// bytes) and z (8); LLVM vectorised `dot` as x alone and y-z as a pair, and a 16-byte load
/// of y-z spans both stores, so the store buffer cannot forward it: the load waits until
/// the stores reach the cache (~35 % of `Plane::inside`'s own samples on
/// objects/csg/cliptst2). Loading x-y as the pair matches the store.
#[inline(always)]
pub fn dot_xy_z(a: DVec3, b: DVec3) -> f64 {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::*;
        // SAFETY: SSE2 is part of x86_64.
        unsafe {
            let m = _mm_mul_pd(_mm_set_pd(a.y, a.x), _mm_set_pd(b.y, b.x));
            _mm_cvtsd_f64(_mm_add_sd(m, _mm_unpackhi_pd(m, m))) + a.z * b.z
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        a.dot(b)
    }
}

/// Whether the CPU has AVX, for the paths built with `#[target_feature(enable = "avx")]` (the
/// build targets x86-64-v2, which lacks it): the noise lattice and the julia orbits. The
/// query is made once (`cpu`).
#[inline(always)]
pub fn has_avx() -> bool {
    crate::cpu::avx()
}

/// `x` unchanged, through an empty `asm!` the optimiser cannot see into: a value it cannot
/// pack with its neighbours into one vector register (where LLVM's SLP vectoriser would
/// spend shuffles between the lanes on a loop's dependency chain).
#[inline(always)]
pub fn opaque(x: f64) -> f64 {
    #[cfg(target_arch = "x86_64")]
    {
        let mut y = x;
        // SAFETY: an empty template; the value stays in its register.
        unsafe {
            std::arch::asm!(
                "/* {0} */",
                inout(xmm_reg) y,
                options(pure, nomem, nostack, preserves_flags)
            );
        }
        y
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        x
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `dot_xy_z` is `DVec3::dot` bit for bit: signed zeros, infinities, NaN, huge and tiny
    /// components, and random vectors.
    #[test]
    fn dot_xy_z_is_dot() {
        let mut rnd = xorshift_unit(77);
        let special = [
            0.0,
            -0.0,
            1.0,
            -1.5,
            1e300,
            -1e-300,
            f64::INFINITY,
            f64::NAN,
        ];
        let mut pick = |k: usize| match k % 3 {
            0 => special[(k / 3) % special.len()],
            _ => (rnd() - 0.5) * [1.0, 1e8, 1e-8][k % 3],
        };
        for k in 0..60000 {
            let a = DVec3::new(pick(k), pick(k / 2 + 1), pick(k / 5 + 2));
            let b = DVec3::new(pick(k / 7 + 1), pick(k / 3 + 2), pick(k / 11));
            assert_eq!(dot_xy_z(a, b).to_bits(), a.dot(b).to_bits(), "{a} {b}");
        }
    }

    /// `is_identity` is DMat4's `==` against the identity for every single-entry change
    /// (signed zeros, NaN, ones off the diagonal) and for the usual transforms.
    #[test]
    fn identity_is_the_matrix_compare() {
        let mut cases = vec![
            Transform::IDENTITY,
            Transform::scale(DVec3::splat(0.5)),
            Transform::translate(DVec3::new(1.0, 0.0, 0.0)),
            Transform::rotate(DVec3::new(0.0, 90.0, 0.0)),
        ];
        for k in 0..16 {
            for v in [0.0, -0.0, 1.0, -1.0, f64::NAN, 2.0] {
                let mut a = DMat4::IDENTITY.to_cols_array();
                a[k] = v;
                cases.push(Transform {
                    m: DMat4::from_cols_array(&a),
                    inv: DMat4::IDENTITY,
                });
            }
        }
        for t in cases {
            assert_eq!(t.is_identity(), t.m == DMat4::IDENTITY, "{:?}", t.m);
            // The same through an `Xform` (which answers an absent transform itself).
            assert_eq!(Xform::from(t).is_identity(), t.m == DMat4::IDENTITY);
        }
        // The static identity (known by its address), an absent transform and `get`'s
        // stand-in for it.
        assert!(IDENTITY.is_identity());
        assert!(Xform::IDENTITY.is_identity());
        assert!(Xform::IDENTITY.get().is_identity());
        assert!(std::ptr::eq(Xform::IDENTITY.get(), &IDENTITY));
    }

    #[test]
    fn rotate_is_left_handed_pov_order() {
        // POV-Ray: rotate 90*y takes +x to -z? In a left-handed system rotating x by +90 about y
        // gives -z (the manual's left-hand rule: thumb along +y, fingers curl from +z to +x).
        let t = Transform::rotate(DVec3::new(0.0, 90.0, 0.0));
        let p = t.point(DVec3::X);
        assert!((p - DVec3::new(0.0, 0.0, -1.0)).length() < 1e-12, "{p}");
    }

    /// `Slabs::hits` answers as `Aabb::hit` does, for rays with and without NaN-prone
    /// directions and for flat, infinite and empty boxes.
    #[test]
    fn slabs_match_aabb_hit() {
        let mut h = 7u64;
        let mut rnd = || {
            h = h
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (h >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        let specials = [0.0, -0.0, 1.0, f64::INFINITY, f64::NEG_INFINITY];
        let mut checked = 0;
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
            let inv_dir = dir.recip();
            let want = b.hit(origin, inv_dir, tmax).is_some();
            let slabs = Slabs::new(origin, inv_dir);
            assert_eq!(slabs.hits(&b, tmax), want, "{origin} {dir} {b:?} {tmax}");
            assert_eq!(
                slabs.hits2(&b, &prev, tmax),
                (want, prev.hit(origin, inv_dir, tmax).is_some())
            );
            assert_eq!(
                slabs.hits2(&prev, &b, tmax),
                (prev.hit(origin, inv_dir, tmax).is_some(), want)
            );
            prev = b;
            checked += usize::from(want);
        }
        assert!(checked > 2000, "{checked}");
    }

    #[test]
    fn then_composes_in_order() {
        let a = Transform::scale(DVec3::splat(2.0));
        let b = Transform::translate(DVec3::X);
        let p = a.then(&b).point(DVec3::X);
        assert_eq!(p, DVec3::new(3.0, 0.0, 0.0));
        let q = a.then(&b).inv_point(p);
        assert!((q - DVec3::X).length() < 1e-12);
    }
}
