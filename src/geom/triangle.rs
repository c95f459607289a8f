//! POV-Ray `triangle` and `smooth_triangle`, plus the ray/triangle test meshes share.
//!
//! `Hit::uv` holds the barycentrics (u, v) of the crossing, weights of the second and third
//! corner, so a smooth normal needs no second intersection. The geometric normal is
//! `(p1 - p0) × (p2 - p0)`; triangles have no inside, and the renderer is expected to face
//! normals toward the viewer as POV-Ray does.

use crate::geom::{Hit, Shape};
use crate::math::{Aabb, DVec3, Ray, EPSILON};

/// Corner and edge vectors, the form the intersection test wants.
#[derive(Clone, Copy, Debug)]
pub(crate) struct TriGeom {
    pub p0: DVec3,
    pub e1: DVec3,
    pub e2: DVec3,
}

impl TriGeom {
    /// None for triangles without area (coincident or collinear corners, non-finite input).
    pub fn new(p: [DVec3; 3]) -> Option<TriGeom> {
        let (e1, e2) = (p[1] - p[0], p[2] - p[0]);
        let n = e1.cross(e2).length();
        // Relative test: collinear corners leave only rounding noise in the cross product.
        let ok = n.is_finite() && n > 1e-14 * e1.length() * e2.length() && p[0].is_finite();
        ok.then_some(TriGeom { p0: p[0], e1, e2 })
    }

    pub fn bounds(&self) -> Aabb {
        let (p1, p2) = (self.p0 + self.e1, self.p0 + self.e2);
        Aabb::new(self.p0.min(p1).min(p2), self.p0.max(p1).max(p2))
    }

    pub fn geometric_normal(&self) -> DVec3 {
        self.e1.cross(self.e2)
    }

    /// Möller–Trumbore: (t, u, v) for a crossing with `EPSILON < t < tmax`.
    #[inline]
    pub fn intersect(&self, ray: &Ray, tmax: f64) -> Option<(f64, f64, f64)> {
        let pvec = ray.dir.cross(self.e2);
        let det = self.e1.dot(pvec);
        // Exactly parallel rays give det = 0; NaN (zero direction) fails every test below.
        if det == 0.0 {
            return None;
        }
        let inv = 1.0 / det;
        let tvec = ray.origin - self.p0;
        let u = tvec.dot(pvec) * inv;
        if !(0.0..=1.0).contains(&u) {
            return None;
        }
        let qvec = tvec.cross(self.e1);
        let v = ray.dir.dot(qvec) * inv;
        if !(v >= 0.0 && u + v <= 1.0) {
            return None;
        }
        let t = self.e2.dot(qvec) * inv;
        (t > EPSILON && t < tmax).then_some((t, u, v))
    }
}

/// Interpolated vertex normal, falling back to `geometric` where the interpolation cancels.
pub(crate) fn smooth_normal(n: &[DVec3; 3], uv: [f64; 2], geometric: DVec3) -> DVec3 {
    let s = n[0] * (1.0 - uv[0] - uv[1]) + n[1] * uv[0] + n[2] * uv[1];
    if s.length_squared() > 1e-24 {
        s
    } else {
        geometric
    }
}

fn hit_of((t, u, v): (f64, f64, f64)) -> Hit {
    Hit {
        t,
        part: 0,
        uv: [u, v],
    }
}

/// A flat triangle, or a smooth one when vertex normals are given.
#[derive(Clone, Copy, Debug)]
pub struct Triangle {
    geom: Option<TriGeom>,
    /// Unit vertex normals of a smooth triangle (zero where one was given as zero).
    normals: Option<[DVec3; 3]>,
}

impl Triangle {
    /// Degenerate triangles (no area) give an empty shape.
    pub fn new(p: [DVec3; 3]) -> Triangle {
        Triangle {
            geom: TriGeom::new(p),
            normals: None,
        }
    }

    /// Vertex normals are normalised so their lengths do not skew the interpolation.
    pub fn smooth(p: [DVec3; 3], n: [DVec3; 3]) -> Triangle {
        Triangle {
            geom: TriGeom::new(p),
            normals: Some(n.map(|v| v.normalize_or_zero())),
        }
    }
}

impl Shape for Triangle {
    fn bounds(&self) -> Aabb {
        self.geom.map_or(Aabb::EMPTY, |g| g.bounds())
    }
    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        if let Some(h) = self.geom.and_then(|g| g.intersect(ray, f64::INFINITY)) {
            out.push(hit_of(h));
        }
    }
    fn intersect_first(&self, ray: &Ray, tmax: f64, _scratch: &mut Vec<Hit>) -> Option<Hit> {
        self.geom?.intersect(ray, tmax).map(hit_of)
    }
    /// Without the `Hit` and the default's call of `intersect_first` (cornell's shadow rays
    /// test ~2 triangles each).
    fn any_hit(&self, ray: &Ray, tmax: f64, _scratch: &mut Vec<Hit>) -> bool {
        self.geom.is_some_and(|g| g.intersect(ray, tmax).is_some())
    }
    fn inside(&self, _p: DVec3) -> bool {
        false
    }
    fn normal(&self, _p: DVec3, hit: &Hit) -> DVec3 {
        let g = self.geom.map_or(DVec3::Y, |g| g.geometric_normal());
        match &self.normals {
            Some(n) => smooth_normal(n, hit.uv, g),
            None => g,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const P: [DVec3; 3] = [
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(2.0, 0.0, 0.0),
        DVec3::new(0.0, 2.0, 0.0),
    ];

    #[test]
    fn hit_barycentrics_and_normal() {
        let tri = Triangle::new(P);
        let r = Ray::new(DVec3::new(0.5, 1.0, -3.0), DVec3::Z * 0.5);
        let h = tri
            .intersect_first(&r, f64::INFINITY, &mut Vec::new())
            .unwrap();
        assert_eq!(h.t, 6.0);
        assert_eq!(h.uv, [0.25, 0.5]);
        assert_eq!(tri.normal(r.at(h.t), &h).normalize(), DVec3::Z);
        assert!(tri.intersect_first(&r, 6.0, &mut Vec::new()).is_none());
        // Back side hits too.
        let back = Ray::new(DVec3::new(0.5, 0.5, 3.0), DVec3::NEG_Z);
        let mut v = Vec::new();
        tri.intersect_all(&back, &mut v);
        assert_eq!(v.len(), 1);
        assert!(!tri.inside(DVec3::new(0.5, 0.5, 0.0)));
        assert_eq!(
            tri.bounds(),
            Aabb::new(DVec3::ZERO, DVec3::new(2.0, 2.0, 0.0))
        );
    }

    #[test]
    fn misses_outside_edges_and_parallel() {
        let tri = Triangle::new(P);
        let mut v = Vec::new();
        tri.intersect_all(&Ray::new(DVec3::new(1.5, 1.5, -1.0), DVec3::Z), &mut v);
        tri.intersect_all(&Ray::new(DVec3::new(-0.1, 0.5, -1.0), DVec3::Z), &mut v);
        tri.intersect_all(&Ray::new(DVec3::new(-1.0, 0.5, 0.0), DVec3::X), &mut v);
        tri.intersect_all(&Ray::new(DVec3::new(0.5, 0.5, -1.0), DVec3::ZERO), &mut v);
        tri.intersect_all(&Ray::new(DVec3::new(0.5, 0.5, 1.0), DVec3::Z), &mut v);
        assert!(v.is_empty());
        // On an edge counts.
        tri.intersect_all(&Ray::new(DVec3::new(1.0, 1.0, -1.0), DVec3::Z), &mut v);
        assert_eq!(v.len(), 1);
    }

    #[test]
    fn smooth_normals_interpolate() {
        let n = [
            DVec3::Z,
            DVec3::new(1.0, 0.0, 1.0),
            DVec3::new(0.0, 3.0, 3.0),
        ];
        let tri = Triangle::smooth(P, n);
        let at = |x: f64, y: f64| {
            let r = Ray::new(DVec3::new(x, y, -1.0), DVec3::Z);
            let h = tri
                .intersect_first(&r, f64::INFINITY, &mut Vec::new())
                .unwrap();
            tri.normal(r.at(h.t), &h).normalize()
        };
        assert!((at(0.0, 0.0) - DVec3::Z).length() < 1e-12);
        assert!((at(2.0, 0.0) - DVec3::new(1.0, 0.0, 1.0).normalize()).length() < 1e-12);
        assert!((at(0.0, 2.0) - DVec3::new(0.0, 1.0, 1.0).normalize()).length() < 1e-12);
        let mid = at(1.0, 0.0);
        assert!(mid.x > 0.0 && mid.y.abs() < 1e-12);
        // Opposing vertex normals cancel: fall back to the face normal.
        let flat = Triangle::smooth(P, [DVec3::Z, DVec3::NEG_Z, DVec3::ZERO]);
        let h = Hit {
            t: 1.0,
            part: 0,
            uv: [0.5, 0.0],
        };
        assert_eq!(flat.normal(DVec3::X, &h).normalize(), DVec3::Z);
    }

    #[test]
    fn degenerate() {
        let r = Ray::new(DVec3::new(0.5, 0.0, -1.0), DVec3::Z);
        let mut v = Vec::new();
        for p in [
            [DVec3::ZERO; 3],
            [DVec3::ZERO, DVec3::X, DVec3::X * 2.0],
            [DVec3::ZERO, DVec3::X, DVec3::NAN],
        ] {
            let t = Triangle::new(p);
            t.intersect_all(&r, &mut v);
            assert!(t.bounds().is_empty());
            assert!(t.normal(DVec3::ZERO, &Hit::new(1.0)).is_finite());
            let s = Triangle::smooth(p, [DVec3::ZERO; 3]);
            s.intersect_all(&r, &mut v);
            assert!(s.normal(DVec3::ZERO, &Hit::new(1.0)).is_finite());
        }
        assert!(v.is_empty());
    }
}
