//! Short cuts for the CSG members that are planes with an axis for their normal, each with its
//! own transform: shapes2.inc's polyhedra (`plane { -z, 1 rotate <...> }`, twelve of them in a
//! dodecahedron) and most `plane { y, 0 }` cuts.
//!
//! Such a member's crossing and inside test read one component of the ray or point in the
//! plane's own space, so only that row of the inverse transform is needed, not the whole
//! product, and no call through the shape. The answers are the same bit for bit:
//!
//! * the row is the one `Transform::inv_point` / `inv_vector` compute, with their products and
//!   sums in their order (glam's `transform_point3`: `((x·px + y·py) + z·pz) + w`);
//! * `Plane` dots its unit normal with the local point; with two components of the normal
//!   zero, that dot is `(±0 + ±0) + s·c` for the remaining component `c`, which is `s·c`
//!   exactly unless `s·c` is zero, and then a zero of either sign, which neither the
//!   comparison with the distance, nor `denominator == 0`, nor the sign test of `t` can tell
//!   apart (`distance - ±0` is `distance`, or +0 for a zero distance);
//! * the other components are finite (products of finite numbers under 1e150 and sums of
//!   four of them), so `0 · c` adds no NaN. Rays and points beyond 1e150 take the general path.

use crate::math::{DVec3, Ray, EPSILON};
use crate::scene::face_lanes::FaceLanes;
use crate::scene::object::{ObjKind, Object};

/// Components beyond this (rays, points, the inverse transform's entries) leave the short cut.
const LIMIT: f64 = 1e150;

/// One plane member: its normal `sign · e_axis`, distance and the inverse transform's row for
/// that axis, x, y and z coefficients then the offset (None without a transform).
#[derive(Clone, Debug)]
pub struct Face {
    axis: usize,
    sign: f64,
    distance: f64,
    row: Option<[f64; 4]>,
}

/// The faces of a CSG node's members, by member index (None for other members).
#[derive(Clone, Debug)]
pub struct Faces {
    faces: Box<[Option<Face>]>,
    /// Every member is a face with unbounded bounds, and there are at most `MAX_ALL` of them
    /// (`csg_hit`'s search of polyhedra).
    all: bool,
    /// With `all`, the faces four to a block for AVX (`face_lanes`).
    lanes: Option<Box<FaceLanes>>,
}

/// The most members a node whose members are all faces may have for `Faces::all`.
pub const MAX_ALL: usize = 32;

impl Faces {
    /// The faces of `children`, when at least two members are such planes.
    pub fn of(children: &[Object]) -> Option<Faces> {
        let faces: Box<[Option<Face>]> = children.iter().map(face_of).collect();
        let all = children.len() <= MAX_ALL
            && faces.iter().all(Option::is_some)
            && children
                .iter()
                .all(|c| c.bounds == crate::math::Aabb::INFINITE);
        let inverse = children
            .iter()
            .enumerate()
            .fold(0u32, |m, (j, c)| m | (c.inverse as u32) << (j % 32));
        let lanes = all
            .then(|| FaceLanes::of(&faces, inverse))
            .flatten()
            .map(Box::new);
        (faces.iter().flatten().count() >= 2).then_some(Faces { faces, all, lanes })
    }

    /// Member `i`'s face, when it is one.
    #[inline]
    pub fn get(&self, i: usize) -> Option<&Face> {
        self.faces.get(i).and_then(Option::as_ref)
    }

    /// The faces, when every member is one with unbounded bounds (at most `MAX_ALL`).
    #[inline]
    pub fn all(&self) -> Option<&[Option<Face>]> {
        self.all.then_some(&self.faces[..])
    }

    /// With `all`, the faces four to a block (`face_lanes`).
    #[inline]
    pub fn lanes(&self) -> Option<&FaceLanes> {
        self.lanes.as_deref()
    }
}

/// Whether a ray is within the short cut's limits (NaN is not).
#[inline]
pub fn ray_ok(ray: &Ray) -> bool {
    point_ok(ray.origin) && point_ok(ray.dir)
}

/// Whether a point is within the short cut's limits (NaN is not).
#[inline]
pub fn point_ok(p: DVec3) -> bool {
    p.abs().max_element() <= LIMIT && !p.is_nan()
}

fn face_of(o: &Object) -> Option<Face> {
    let ObjKind::Shape(shape, None) = &o.kind else {
        return None;
    };
    if !o.clip.is_empty() {
        return None;
    }
    let (n, distance) = shape.half_space()?;
    let n = n.to_array();
    let axis = (0..3).find(|&k| n[k].abs() == 1.0)?;
    if (0..3).any(|k| k != axis && n[k] != 0.0) {
        return None;
    }
    let row = match &o.transform {
        None => None,
        Some(t) => {
            let m = t.inv;
            let cols = m.to_cols_array_2d();
            let bounded = cols.iter().flatten().all(|v| v.abs() <= LIMIT);
            if !bounded || m.row(3) != glam::DVec4::W {
                return None;
            }
            Some([
                m.x_axis[axis],
                m.y_axis[axis],
                m.z_axis[axis],
                m.w_axis[axis],
            ])
        }
    };
    Some(Face {
        axis,
        sign: n[axis],
        distance,
        row,
    })
}

impl Face {
    /// The local point's component along the axis (`inv_point`).
    #[inline(always)]
    fn point(&self, p: DVec3) -> f64 {
        match &self.row {
            Some(r) => ((r[0] * p.x + r[1] * p.y) + r[2] * p.z) + r[3],
            None => p[self.axis],
        }
    }

    /// The local vector's component along the axis (`inv_vector`).
    #[inline(always)]
    fn vector(&self, v: DVec3) -> f64 {
        match &self.row {
            Some(r) => (r[0] * v.x + r[1] * v.y) + r[2] * v.z,
            None => v[self.axis],
        }
    }

    /// `Plane::intersect_all` of the local ray: the crossing's `t`, if any. The ray must be
    /// `ray_ok`.
    #[inline]
    pub fn hit(&self, ray: &Ray) -> Option<f64> {
        let denom = self.sign * self.vector(ray.dir);
        if denom == 0.0 {
            return None;
        }
        let t = (self.distance - self.sign * self.point(ray.origin)) / denom;
        (t > EPSILON && t.is_finite()).then_some(t)
    }

    /// The row `point` and `vector` use (the axis's unit row without a transform), the sign
    /// and the distance, for `face_lanes`.
    pub fn lane_values(&self) -> ([f64; 4], f64, f64) {
        let mut unit = [0.0; 4];
        unit[self.axis] = 1.0;
        (self.row.unwrap_or(unit), self.sign, self.distance)
    }

    /// A face made directly, for other modules' tests.
    #[cfg(test)]
    pub fn for_test(axis: usize, sign: f64, distance: f64, row: Option<[f64; 4]>) -> Face {
        Face {
            axis,
            sign,
            distance,
            row,
        }
    }

    /// `Plane::inside` of the local point. The point must be `point_ok`.
    #[inline]
    pub fn inside(&self, p: DVec3) -> bool {
        self.sign * self.point(p) < self.distance
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::plane::Plane;
    use crate::geom::test_rng::Lcg;
    use crate::geom::{Hit, Shape};
    use crate::math::Transform;

    /// A face's crossing and inside test against the plane's own through the whole transform,
    /// bit for bit, over random transforms and rays (some along axes and through the origin,
    /// where components are zero).
    #[test]
    fn faces_answer_as_their_planes() {
        let mut rng = Lcg(11);
        let mut checked = 0;
        for case in 0..400 {
            let axis = case % 3;
            let sign = if case % 2 == 0 { 1.0 } else { -1.0 };
            let mut n = [0.0; 3];
            n[axis] = sign;
            let distance = if case % 7 == 0 {
                0.0
            } else {
                rng.next() * 3.0 - 1.0
            };
            let plane = Plane::new(DVec3::from_array(n), distance);
            let t = match case % 4 {
                0 => None,
                1 => Some(Transform::rotate(rng.vec(720.0))),
                2 => Some(Transform::rotate(DVec3::new(-26.56505117708, -72.0, 0.0))),
                _ => Some(
                    Transform::scale(rng.vec(4.0) + DVec3::splat(2.5))
                        .then(&Transform::rotate(rng.vec(360.0)))
                        .then(&Transform::translate(rng.vec(6.0))),
                ),
            };
            let m = t.map_or(crate::math::DMat4::IDENTITY, |t| t.inv);
            let face = Face {
                axis,
                sign,
                distance,
                row: t.map(|_| {
                    [
                        m.x_axis[axis],
                        m.y_axis[axis],
                        m.z_axis[axis],
                        m.w_axis[axis],
                    ]
                }),
            };
            for k in 0..200 {
                let mut o = rng.vec(10.0);
                let mut d = rng.vec(2.0);
                match k % 5 {
                    0 => d = DVec3::from_array(n) * (rng.next() + 0.1),
                    1 => o = DVec3::ZERO,
                    2 => d = DVec3::X,
                    _ => {}
                }
                let ray = Ray::new(o, d);
                let local = t.map_or(ray, |t| t.inv_ray(&ray));
                let mut all: Vec<Hit> = Vec::new();
                plane.intersect_all(&local, &mut all);
                let want = all.first().map(|h| h.t.to_bits());
                assert_eq!(face.hit(&ray).map(f64::to_bits), want, "{ray:?} {t:?}");
                let p = ray.at(rng.next() * 4.0);
                let lp = t.map_or(p, |t| t.inv_point(p));
                assert_eq!(face.inside(p), plane.inside(lp));
                checked += 1;
            }
        }
        assert_eq!(checked, 80_000);
        assert!(ray_ok(&Ray::new(DVec3::ONE, DVec3::X)));
        assert!(!ray_ok(&Ray::new(DVec3::splat(f64::NAN), DVec3::X)));
        assert!(!point_ok(DVec3::new(0.0, 2e150, 0.0)));
    }
}
