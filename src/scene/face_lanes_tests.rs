//! The lanes against `Face::hit` / `Face::inside`, bit for bit.

use super::*;
use crate::geom::test_rng::Lcg;
use crate::math::Transform;
use crate::scene::csg_members::want_inside;

/// A random face: axis and sign, a distance (sometimes ±0), no transform or one whose row
/// has zeros (right-angle turns) or none.
fn face(rng: &mut Lcg, case: usize) -> Face {
    let axis = case % 3;
    let sign = if rng.next() < 0.5 { 1.0 } else { -1.0 };
    let distance = match case % 9 {
        0 => 0.0,
        1 => -0.0,
        _ => rng.next() * 3.0 - 1.0,
    };
    let t = match case % 4 {
        0 => None,
        1 => Some(Transform::rotate(rng.vec(720.0))),
        2 => Some(Transform::rotate(DVec3::new(
            90.0,
            0.0,
            180.0 * (case % 2) as f64,
        ))),
        _ => Some(
            Transform::scale(rng.vec(4.0) + DVec3::splat(2.5))
                .then(&Transform::rotate(rng.vec(360.0)))
                .then(&Transform::translate(rng.vec(6.0))),
        ),
    };
    let row = t.map(|t| {
        let m = t.inv;
        [
            m.x_axis[axis],
            m.y_axis[axis],
            m.z_axis[axis],
            m.w_axis[axis],
        ]
    });
    Face::for_test(axis, sign, distance, row)
}

/// Every member's crossing and inside answer through the lanes as through its `Face`, over
/// random polyhedra of 1 to 32 faces (partial last blocks), rays along axes, through the
/// origin and parallel to faces, `tmax` at a crossing exactly, and points on faces.
#[test]
fn lanes_answer_as_faces() {
    if !crate::math::has_avx() {
        return;
    }
    let mut rng = Lcg(7);
    let mut checked = 0;
    for poly in 0..300 {
        let count = 1 + poly % MAX_ALL;
        let faces: Vec<Option<Face>> = (0..count).map(|c| Some(face(&mut rng, c + poly))).collect();
        let lanes = FaceLanes::of(&faces, 0).unwrap();
        for k in 0..100 {
            let mut o = rng.vec(10.0);
            let mut d = rng.vec(2.0);
            match k % 6 {
                0 => d = DVec3::X,
                1 => o = DVec3::ZERO,
                2 => d = DVec3::new(0.0, rng.next(), 0.0),
                3 => {
                    // Parallel to face 0 when it has no transform.
                    let mut a = d.to_array();
                    a[poly % 3] = 0.0;
                    d = DVec3::from_array(a);
                }
                _ => {}
            }
            let ray = Ray::new(o, d);
            let one = |tmax: f64| {
                let ray = &ray;
                faces
                    .iter()
                    .map(move |f| f.as_ref().unwrap().hit(ray).filter(|&t| t < tmax))
            };
            let mut tmaxes = vec![f64::INFINITY, rng.next() * 8.0];
            tmaxes.extend(one(f64::INFINITY).flatten().take(2));
            for tmax in tmaxes {
                let mut ts = [f64::NAN; MAX_ALL];
                // SAFETY: AVX checked above.
                let bits = unsafe { lanes.hits_avx(&ray, tmax, &mut ts) };
                for (j, want) in one(tmax).enumerate() {
                    let got = (bits >> j & 1 == 1).then(|| ts[j].to_bits());
                    assert_eq!(got, want.map(f64::to_bits), "{ray:?} face {j} tmax {tmax}");
                }
                assert_eq!(bits & !lanes.members(), 0);
                checked += 1;
            }
            let mut points = vec![ray.at(rng.next() * 4.0), DVec3::ZERO, o];
            points.extend(one(f64::INFINITY).flatten().take(3).map(|t| ray.at(t)));
            for p in points {
                // SAFETY: AVX checked above.
                let bits = unsafe { lanes.inside_avx(p) };
                for (j, f) in faces.iter().enumerate() {
                    assert_eq!(
                        bits >> j & 1 == 1,
                        f.as_ref().unwrap().inside(p),
                        "{p:?} face {j}"
                    );
                }
                assert_eq!(bits & !lanes.members(), 0);
            }
        }
    }
    assert!(checked >= 300 * 100 * 2);
}

/// `expected` is `wants`' `want_inside(op, j) != inverse_j` for each member, for each node.
#[test]
fn expected_answers_as_wants() {
    let mut rng = Lcg(3);
    for count in 1..=MAX_ALL {
        let faces: Vec<Option<Face>> = (0..count).map(|c| Some(face(&mut rng, c))).collect();
        let inverse = (rng.next() * u32::MAX as f64) as u32 & (u64::MAX >> (64 - count)) as u32;
        let lanes = FaceLanes::of(&faces, inverse).unwrap();
        for op in [
            CsgOp::Intersection,
            CsgOp::Difference,
            CsgOp::Union,
            CsgOp::Merge,
        ] {
            for j in 0..count {
                let want = want_inside(op, j) != (inverse >> j & 1 == 1);
                assert_eq!(lanes.expected(op) >> j & 1 == 1, want, "{op:?} {j}");
            }
            assert_eq!(lanes.expected(op) & !lanes.members(), 0);
        }
    }
    assert!(FaceLanes::of(&[None, None], 0).is_none());
}
