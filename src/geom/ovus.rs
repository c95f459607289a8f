//! POV-Ray `ovus { bottom_radius, top_radius }`: an egg made of a bottom sphere at the origin,
//! a top sphere centred on the bottom one's top (0, bottom, 0), and between them the lemon
//! (inner part of a spindle torus) tangent to both.
//!
//! The manual leaves the lemon's size open; measured on povray's silhouettes
//! (orthographic, 0.01 units per pixel, radii 1/0.5, 1/1, 1/1.5: every profile within half a
//! pixel), its profile circle has radius `2 · max(bottom, top)` and touches both spheres from
//! inside. Whenever the top radius is at least twice the bottom one the manual says the ovus
//! is the top sphere alone.

use crate::geom::torus::Torus;
use crate::geom::{Hit, Shape};
use crate::math::{by_coordinates, Aabb, DVec3, Ray};

const PART_BOTTOM: u32 = 0;
const PART_TOP: u32 = 1;
const PART_LEMON: u32 = 2;

#[derive(Clone, Debug)]
pub struct Ovus {
    bottom: f64,
    top: f64,
    /// The lemon: profile circle centred at (-a, yc) in the (ρ, y) half-plane, radius `rc`;
    /// None when the ovus is the top sphere alone.
    lemon: Option<Lemon>,
}

#[derive(Clone, Debug)]
struct Lemon {
    a: f64,
    yc: f64,
    rc: f64,
    /// Heights where it meets the bottom and top spheres.
    y_bottom: f64,
    y_top: f64,
    torus: Torus,
}

impl Ovus {
    /// Radii are taken by magnitude.
    pub fn new(bottom: f64, top: f64) -> Ovus {
        let (b, t) = (bottom.abs(), top.abs());
        let lemon = (t < 2.0 * b && b > 0.0 && t > 0.0).then(|| {
            let rc = 2.0 * b.max(t);
            let (d1, d2) = (rc - b, rc - t);
            let yc = (d1 * d1 - d2 * d2 + b * b) / (2.0 * b);
            let a = (d1 * d1 - yc * yc).max(0.0).sqrt();
            Lemon {
                a,
                yc,
                rc,
                y_bottom: yc - rc * yc / d1,
                y_top: yc + rc * (b - yc) / d2,
                torus: Torus::new(a, rc, false),
            }
        });
        Ovus {
            bottom: b,
            top: t,
            lemon,
        }
    }

    fn sphere_hits(o: DVec3, d: DVec3, c: DVec3, r: f64, out: &mut [f64; 2]) -> usize {
        let oc = o - c;
        let (qa, qb, qc) = (d.dot(d), oc.dot(d), oc.length_squared() - r * r);
        let disc = qb * qb - qa * qc;
        if disc < 0.0 || qa == 0.0 {
            return 0;
        }
        let h = disc.sqrt();
        out[0] = (-qb - h) / qa;
        out[1] = (-qb + h) / qa;
        2
    }

    fn crossings(&self, ray: &Ray, mut push: impl FnMut(Hit)) {
        // By coordinates: see `Sor::each_hit` (a just-stored local ray read as a y-z pair).
        let (o, d) = (by_coordinates(&ray.origin), by_coordinates(&ray.dir));
        let mut t2 = [0.0; 2];
        let top_c = DVec3::new(0.0, self.bottom, 0.0);
        let Some(l) = &self.lemon else {
            let n = Self::sphere_hits(o, d, top_c, self.top, &mut t2);
            for &t in &t2[..n] {
                push(Hit::with_part(t, PART_TOP));
            }
            return;
        };
        let n = Self::sphere_hits(o, d, DVec3::ZERO, self.bottom, &mut t2);
        for &t in &t2[..n] {
            if o.y + d.y * t <= l.y_bottom {
                push(Hit::with_part(t, PART_BOTTOM));
            }
        }
        let n = Self::sphere_hits(o, d, top_c, self.top, &mut t2);
        for &t in &t2[..n] {
            if o.y + d.y * t >= l.y_top {
                push(Hit::with_part(t, PART_TOP));
            }
        }
        let shifted = Ray::new(o - DVec3::new(0.0, l.yc, 0.0), d);
        let mut t4 = [0.0; 4];
        let n = l.torus.crossings(&shifted, &mut t4);
        for &t in &t4[..n] {
            let p = o + d * t;
            if p.y <= l.y_bottom || p.y >= l.y_top {
                continue;
            }
            // The lemon is the arc of the circle on the far side of the axis; the torus's
            // other arc (the apple) is not part of the ovus.
            let rho = (p.x * p.x + p.z * p.z).sqrt();
            let dy2 = (p.y - l.yc).powi(2);
            let lemon = ((rho + l.a).powi(2) + dy2 - l.rc * l.rc).abs();
            let apple = ((rho - l.a).powi(2) + dy2 - l.rc * l.rc).abs();
            if lemon <= apple {
                push(Hit::with_part(t, PART_LEMON));
            }
        }
    }
}

impl Shape for Ovus {
    fn bounds(&self) -> Aabb {
        let r = match &self.lemon {
            Some(l) => self.bottom.max(self.top).max(l.rc - l.a),
            None => self.top,
        };
        let lo = if self.lemon.is_some() {
            -self.bottom
        } else {
            self.bottom - self.top
        };
        Aabb::new(
            DVec3::new(-r, lo, -r),
            DVec3::new(r, self.bottom + self.top, r),
        )
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        self.crossings(ray, |h| {
            if h.t > crate::math::EPSILON {
                out.push(h)
            }
        });
    }

    fn intersect_first(&self, ray: &Ray, tmax: f64, _scratch: &mut Vec<Hit>) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        self.crossings(ray, |h| {
            if h.t > crate::math::EPSILON && h.t < tmax && best.is_none_or(|b| h.t < b.t) {
                best = Some(h);
            }
        });
        best
    }

    fn inside(&self, p: DVec3) -> bool {
        let top_c = DVec3::new(0.0, self.bottom, 0.0);
        let Some(l) = &self.lemon else {
            return (p - top_c).length_squared() <= self.top * self.top;
        };
        if p.y <= l.y_bottom {
            p.length_squared() <= self.bottom * self.bottom
        } else if p.y >= l.y_top {
            (p - top_c).length_squared() <= self.top * self.top
        } else {
            let rho = (p.x * p.x + p.z * p.z).sqrt();
            let dy2 = (p.y - l.yc).powi(2);
            rho + l.a <= (l.rc * l.rc - dy2).max(0.0).sqrt()
        }
    }

    fn normal(&self, p: DVec3, hit: &Hit) -> DVec3 {
        match (hit.part, &self.lemon) {
            (PART_BOTTOM, _) => p,
            (PART_LEMON, Some(l)) => {
                let rho = (p.x * p.x + p.z * p.z).sqrt();
                let radial = if rho > 0.0 {
                    DVec3::new(p.x / rho, 0.0, p.z / rho)
                } else {
                    DVec3::ZERO
                };
                p - (-l.a * radial + DVec3::new(0.0, l.yc, 0.0))
            }
            _ => p - DVec3::new(0.0, self.bottom, 0.0),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Widest point measured on povray: radius 1.13 for ovus { 1, 1 } (module doc).
    #[test]
    fn equal_radii_bulge_like_povray() {
        let o = Ovus::new(1.0, 1.0);
        let l = o.lemon.as_ref().unwrap();
        assert!((l.rc - l.a - 1.134).abs() < 0.001);
        assert!(o.inside(DVec3::new(1.12, 0.5, 0.0)));
        assert!(!o.inside(DVec3::new(1.14, 0.5, 0.0)));
        let ray = Ray::new(DVec3::new(-5.0, 0.5, 0.0), DVec3::X);
        let h = o
            .intersect_first(&ray, f64::INFINITY, &mut Vec::new())
            .unwrap();
        assert!((5.0 - h.t - 1.134).abs() < 0.001, "{}", h.t);
        let mut all = Vec::new();
        o.intersect_all(&ray, &mut all);
        assert_eq!(all.len(), 2);
    }

    #[test]
    fn profile_is_continuous_at_the_tangent_points() {
        let o = Ovus::new(1.0, 0.5);
        let l = o.lemon.as_ref().unwrap();
        let rho_lemon = |y: f64| (l.rc * l.rc - (y - l.yc).powi(2)).sqrt() - l.a;
        let yb = l.y_bottom;
        assert!((rho_lemon(yb) - (1.0 - yb * yb).sqrt()).abs() < 1e-9);
        let yt = l.y_top;
        assert!((rho_lemon(yt) - (0.25 - (yt - 1.0).powi(2)).sqrt()).abs() < 1e-9);
    }
}
