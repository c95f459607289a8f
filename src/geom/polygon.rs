//! POV-Ray `polygon`: flat sub-polygons in one plane, filled by the even-odd rule, so where an
//! even number of them overlap there is a hole. Like a triangle it has no inside.

use crate::geom::spline2d::{inside_even_odd, Piece, P2};
use crate::geom::{Hit, Shape};
use crate::math::{Aabb, DVec3, Ray, EPSILON};

#[derive(Clone, Debug)]
pub struct Polygon {
    /// Unit plane normal and offset: n · p = d.
    n: DVec3,
    d: f64,
    /// The two axes kept when projecting to 2-D (the normal's largest component dropped).
    axes: [usize; 2],
    edges: Vec<Piece>,
    bounds: Aabb,
}

/// The edges of the sub-polygons as POV-Ray closes them: a sub-polygon ends where its first
/// point comes again and the next point starts another. Returns the edges (as point pairs)
/// and whether the last sub-polygon had to be closed.
pub fn edges(p: &[DVec3]) -> (Vec<(DVec3, DVec3)>, bool) {
    let mut out = Vec::new();
    let mut st = 0;
    let n = p.len();
    while st < n {
        let mut k = st + 1;
        while k < n && p[k] != p[st] {
            out.push((p[k - 1], p[k]));
            k += 1;
        }
        if k == n {
            if n - st >= 2 {
                out.push((p[n - 1], p[st]));
                return (out, true);
            }
            break;
        }
        out.push((p[k - 1], p[k]));
        st = k + 1;
    }
    (out, false)
}

impl Polygon {
    /// Points off the plane or all on one line give an empty shape, as in POV-Ray.
    pub fn new(edges: &[(DVec3, DVec3)]) -> Polygon {
        // Newell's normal: the area-weighted plane of all edges, which a single collinear
        // triple cannot spoil.
        let mut n = DVec3::ZERO;
        let mut bounds = Aabb::EMPTY;
        let mut centre = DVec3::ZERO;
        for &(a, b) in edges {
            n += DVec3::new(
                (a.y - b.y) * (a.z + b.z),
                (a.z - b.z) * (a.x + b.x),
                (a.x - b.x) * (a.y + b.y),
            );
            bounds = bounds.grow(a).grow(b);
            centre += a;
        }
        let n = n.normalize_or_zero();
        let centre = centre / edges.len().max(1) as f64;
        let planar = is_planar(edges, n);
        let a = n.abs();
        let drop = if a.x >= a.y && a.x >= a.z {
            0
        } else if a.y >= a.z {
            1
        } else {
            2
        };
        let axes = [[1, 2], [0, 2], [0, 1]][drop];
        let flat = |v: DVec3| -> P2 { [v[axes[0]], v[axes[1]]] };
        let edges = if !planar || !centre.is_finite() {
            Vec::new()
        } else {
            edges
                .iter()
                .map(|&(a, b)| Piece::linear(flat(a), flat(b)))
                .collect()
        };
        Polygon {
            n,
            d: n.dot(centre),
            axes,
            edges,
            bounds,
        }
    }
}

/// Whether every point lies on the plane through the first with normal `n`. POV-Ray draws
/// nothing when a point is off by more than about 1e-10 (measured: 1e-10 renders, 3e-10 does
/// not, the same at scales 0.01 to 100), so the test is absolute, not relative.
pub fn is_planar(edges: &[(DVec3, DVec3)], n: DVec3) -> bool {
    let Some(&(p0, _)) = edges.first() else {
        return false;
    };
    n != DVec3::ZERO && edges.iter().all(|&(a, _)| n.dot(a - p0).abs() <= 1.5e-10)
}

impl Shape for Polygon {
    fn bounds(&self) -> Aabb {
        if self.edges.is_empty() {
            Aabb::EMPTY
        } else {
            self.bounds
        }
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        let dn = self.n.dot(ray.dir);
        if dn == 0.0 || self.edges.is_empty() {
            return;
        }
        let t = (self.d - self.n.dot(ray.origin)) / dn;
        // Also rejects NaN.
        if t.is_nan() || t <= EPSILON {
            return;
        }
        let p = ray.at(t);
        if inside_even_odd(&self.edges, [p[self.axes[0]], p[self.axes[1]]], false) {
            out.push(Hit::new(t));
        }
    }

    fn inside(&self, _p: DVec3) -> bool {
        false
    }

    fn normal(&self, _p: DVec3, _hit: &Hit) -> DVec3 {
        self.n
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v2(p: &[(f64, f64)]) -> Vec<DVec3> {
        p.iter().map(|&(x, y)| DVec3::new(x, y, 0.0)).collect()
    }

    fn hit(poly: &Polygon, x: f64, y: f64) -> bool {
        let mut v = Vec::new();
        poly.intersect_all(&Ray::new(DVec3::new(x, y, -1.0), DVec3::Z), &mut v);
        v.len() == 1 && (v[0].t - 1.0).abs() < 1e-12
    }

    #[test]
    fn letter_p_has_its_hole() {
        // The manual's letter P: outline and a rectangular hole, both closed.
        let p = v2(&[
            (0.0, 0.0),
            (0.0, 6.0),
            (4.0, 6.0),
            (4.0, 3.0),
            (1.0, 3.0),
            (1.0, 0.0),
            (0.0, 0.0),
            (1.0, 4.0),
            (1.0, 5.0),
            (3.0, 5.0),
            (3.0, 4.0),
            (1.0, 4.0),
        ]);
        let (e, closed) = edges(&p);
        assert_eq!((e.len(), closed), (10, false));
        let poly = Polygon::new(&e);
        assert!(hit(&poly, 0.5, 0.5) && hit(&poly, 3.5, 5.5));
        assert!(!hit(&poly, 2.0, 4.5) && !hit(&poly, 2.0, 2.0) && !hit(&poly, 5.0, 1.0));
        assert!((poly.normal(DVec3::ZERO, &Hit::new(0.0)).abs() - DVec3::Z).length() < 1e-12);
        assert!(!poly.inside(DVec3::new(0.5, 0.5, 0.0)));
    }

    #[test]
    fn unclosed_and_tilted() {
        let (e, closed) = edges(&v2(&[(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)]));
        assert!(closed && e.len() == 3);
        // A stray point after a closed sub-polygon adds nothing.
        let (e2, closed) = edges(&v2(&[
            (0.0, 0.0),
            (1.0, 0.0),
            (0.0, 1.0),
            (0.0, 0.0),
            (5.0, 5.0),
        ]));
        assert!(!closed && e2.len() == 3);
        // In the plane x + y + z = 1.
        let p = [DVec3::X, DVec3::Y, DVec3::Z];
        let (e, _) = edges(&p);
        let poly = Polygon::new(&e);
        let mut v = Vec::new();
        poly.intersect_all(&Ray::new(DVec3::ZERO, DVec3::ONE), &mut v);
        assert!(v.len() == 1 && (v[0].t - 1.0 / 3.0).abs() < 1e-12);
        v.clear();
        poly.intersect_all(
            &Ray::new(DVec3::new(0.0, 0.0, -1.0), DVec3::new(2.0, 2.0, 1.0)),
            &mut v,
        );
        assert!(v.is_empty());
        // A point off the plane by more than POV-Ray's tolerance: nothing is drawn.
        let mut p = v2(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]);
        p[2].z = 2e-11;
        assert!(!Polygon::new(&edges(&p).0).bounds().is_empty());
        p[2].z = 1e-9;
        assert!(Polygon::new(&edges(&p).0).bounds().is_empty());
        // Collinear points make no plane: nothing to hit, no panic.
        let (e, _) = edges(&v2(&[(0.0, 0.0), (1.0, 0.0), (2.0, 0.0)]));
        assert!(Polygon::new(&e).bounds().is_empty());
    }
}
