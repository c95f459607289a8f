//! Objects that are only moved (`translate`, or any transform whose inverse has exactly the
//! identity's linear part): their object-space ray worked out inline, to the bit what
//! `Transform::inv_ray` gives, so that the walks can ask a moved sphere's crossings without
//! the object's general path (the call through the shape's table, the object-space ray built
//! and checked in `Object::first_hit`).
//!
//! Folding the translation into the sphere's centre would be cheaper but is not the same
//! arithmetic: `(o - t) - c` and `o - (c + t)` round differently. Here the product is kept,
//! with the matrix's ones and zeros as constants: `1 * x` is `x` to the bit (LLVM folds it),
//! `0 * y` is not (it is -0 for a negative `y` and NaN for an infinite one, and a -0 can turn
//! a sum's zero or a root's sign), so those products stay.

use crate::math::{DVec3, Ray, Transform};
use glam::DVec4;

/// Whether `t`'s inverse has exactly the identity's linear part: ones on the diagonal and +0
/// elsewhere, bit for bit (a -0 would change `0 * y`'s sign), so that `moved_ray` with its
/// offset is its `inv_ray`. The fourth row is not read by `inv_ray`.
pub(super) fn only_moved(t: &Transform) -> bool {
    let bits = |v: DVec4| [v.x, v.y, v.z].map(f64::to_bits);
    let (one, zero) = (1f64.to_bits(), 0f64.to_bits());
    bits(t.inv.x_axis) == [one, zero, zero]
        && bits(t.inv.y_axis) == [zero, one, zero]
        && bits(t.inv.z_axis) == [zero, zero, one]
}

/// The identity's linear part applied as `DMat4::transform_vector3` applies a matrix's:
/// `z_axis * v.z + (y_axis * v.y + x_axis * v.x)`, each component in that order, with
/// `zero` for the matrix's zeros.
#[inline(always)]
fn unit_product(v: DVec3, zero: f64) -> DVec3 {
    DVec3::new(
        zero * v.z + (zero * v.y + 1.0 * v.x),
        zero * v.z + (1.0 * v.y + zero * v.x),
        1.0 * v.z + (zero * v.y + zero * v.x),
    )
}

/// `Transform::inv_ray` for a transform that `only_moved` accepts, whose inverse's fourth
/// column is `w`: `transform_point3` adds it last (`w + product`), `transform_vector3` not at
/// all.
#[inline(always)]
pub(super) fn moved_ray(ray: &Ray, w: &DVec4) -> Ray {
    // A zero the optimiser cannot see through: with the literal, the products depend on the
    // ray alone, and LLVM hoisted them out of the walk's loop into every ray's set-up, where
    // scenes without a moved sphere paid for them too (mirror_spheres: 31 instructions a
    // ray, +2.1 %).
    let zero = std::hint::black_box(0.0);
    let o = unit_product(ray.origin, zero);
    Ray {
        origin: DVec3::new(w.x + o.x, w.y + o.y, w.z + o.z),
        dir: unit_product(ray.dir, zero),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::test_rng::Lcg;

    /// Awkward coordinates: signed zeros, subnormals, huge and infinite values, NaN.
    const ODD: [f64; 12] = [
        0.0,
        -0.0,
        1.0,
        -2.5,
        5e-324,
        -5e-324,
        1e300,
        -1e-300,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
        0.1,
    ];

    fn same(a: DVec3, b: DVec3) -> bool {
        a.to_array()
            .iter()
            .zip(b.to_array())
            .all(|(x, y)| x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan()))
    }

    /// `moved_ray` is `inv_ray` bit for bit (NaN as NaN) for translations by every awkward
    /// offset (zero ones give a -0 in the inverse's last column) and chains of them, rays
    /// with every awkward component; other transforms are refused.
    #[test]
    fn moved_ray_is_inv_ray() {
        let mut rng = Lcg(41);
        let mut offsets: Vec<DVec3> = Vec::new();
        for &a in &ODD {
            for &b in &ODD[..4] {
                offsets.push(DVec3::new(a, b, -a));
            }
        }
        for _ in 0..40 {
            offsets.push(rng.vec(10.0));
        }
        let mut checked = 0;
        for (k, &v) in offsets.iter().enumerate() {
            let mut t = Transform::translate(v);
            if k % 3 == 1 {
                t = t.then(&Transform::translate(offsets[k / 2]));
            }
            if !only_moved(&t) {
                // Infinite or NaN offsets spoil the product's zeros.
                assert!(!v.is_finite() || !offsets[k / 2].is_finite(), "{v}");
                continue;
            }
            for i in 0..ODD.len() * ODD.len() {
                let (a, b) = (ODD[i % ODD.len()], ODD[i / ODD.len()]);
                let rays = [
                    Ray::new(DVec3::new(a, b, 0.5), DVec3::new(b, -0.0, a)),
                    Ray::new(DVec3::new(-0.0, a, b), DVec3::new(a, b, 0.0)),
                    Ray::new(rng.vec(5.0), DVec3::new(-0.0, a, -b)),
                ];
                for ray in rays {
                    let want = t.inv_ray(&ray);
                    let got = moved_ray(&ray, &t.inv.w_axis);
                    assert!(same(want.origin, got.origin), "{v} {ray:?}");
                    assert!(same(want.dir, got.dir), "{v} {ray:?}");
                    checked += 1;
                }
            }
        }
        assert!(checked > 10_000, "{checked}");
        // A -0 in the linear part would turn `0 * y`'s sign: refused like any other matrix.
        let mut signed = Transform::translate(DVec3::ONE);
        signed.inv.y_axis.x = -0.0;
        for t in [
            Transform::scale(DVec3::new(1.0, 2.0, 1.0)),
            Transform::rotate(DVec3::new(0.0, 90.0, 0.0)),
            signed,
        ] {
            assert!(!only_moved(&t));
        }
        assert!(only_moved(&Transform::IDENTITY));
    }
}
