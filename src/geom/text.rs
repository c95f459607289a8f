//! POV-Ray `text`: glyph outlines extruded along +z from 0 to the thickness.
//!
//! Each placed glyph is a solid: its outline's region (non-zero winding, as TrueType fills)
//! between two caps. A ray meets the caps where it crosses the planes z = 0 and z = thickness
//! inside the outline, and the side walls where its projection onto the xy plane crosses an
//! outline piece with z in range. Glyphs are found through a BVH over their boxes, so a ray
//! tests only the few glyphs it can reach. Overlapping glyphs keep all their surfaces, like
//! POV-Ray's union of glyphs.
//!
//! `Hit::part` is the placed glyph's index; `Hit::uv[0]` the outline piece (or `CAP_LOW` /
//! `CAP_HIGH`) and `uv[1]` the curve parameter there, for the normal.

use std::sync::Arc;

use glam::DVec2;

use crate::geom::bvh::Bvh;
use crate::geom::font::{Glyph, Piece, PlacedGlyph};
use crate::geom::{Hit, Shape};
use crate::math::{Aabb, DVec3, Ray, EPSILON};

/// What the parser makes of a `text` statement: the laid-out glyphs and the depth.
#[derive(Clone, Debug)]
pub struct TextData {
    pub glyphs: Vec<PlacedGlyph>,
    pub thickness: f64,
}

const CAP_LOW: f64 = -1.0;
const CAP_HIGH: f64 = -2.0;

pub struct Text {
    data: Arc<TextData>,
    /// The extrusion's z range: [0, thickness], or [thickness, 0] when it is negative.
    z0: f64,
    z1: f64,
    /// A negative thickness gives POV-Ray only the two caps, at 0 and at the thickness: no
    /// side walls and no inside (seen from above, such a text vanishes in POV-Ray 3.7).
    solid: bool,
    boxes: Vec<Aabb>,
    bvh: Bvh,
    bounds: Aabb,
}

impl std::fmt::Debug for Text {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Text")
            .field("glyphs", &self.data.glyphs.len())
            .field("bounds", &self.bounds)
            .finish()
    }
}

impl Text {
    pub fn new(data: Arc<TextData>) -> Text {
        let th = if data.thickness.is_finite() {
            data.thickness
        } else {
            0.0
        };
        let (z0, z1) = (th.min(0.0), th.max(0.0));
        let boxes: Vec<Aabb> = data
            .glyphs
            .iter()
            .map(|g| match g.glyph.bounds {
                Some((min, max)) if g.origin.is_finite() => {
                    Aabb::new((min + g.origin).extend(z0), (max + g.origin).extend(z1))
                }
                _ => Aabb::EMPTY,
            })
            .collect();
        // The tree's boxes are a little larger: a ray grazing a glyph's top (an "H" is flat
        // there) must not miss it on rounding in the slab test.
        let grown: Vec<Aabb> = boxes
            .iter()
            .map(|b| Aabb::new(b.min - DVec3::splat(1e-9), b.max + DVec3::splat(1e-9)))
            .collect();
        let bvh = Bvh::build(&grown);
        // Outline-less glyphs (spaces) still count at their pen position, as in POV-Ray's
        // min_extent/max_extent of a text.
        let bounds = data
            .glyphs
            .iter()
            .zip(&boxes)
            .fold(Aabb::EMPTY, |acc, (g, b)| {
                if !b.is_empty() {
                    acc.union(b)
                } else if g.origin.is_finite() {
                    acc.union(&Aabb::new(g.origin.extend(z0), g.origin.extend(z1)))
                } else {
                    acc
                }
            });
        Text {
            data,
            z0,
            z1,
            solid: th >= 0.0,
            boxes,
            bvh,
            bounds,
        }
    }

    /// Every crossing of the ray with placed glyph `gi`, with t > EPSILON.
    fn glyph_hits(&self, gi: usize, ray: &Ray, mut emit: impl FnMut(Hit)) {
        let pg = &self.data.glyphs[gi];
        let glyph: &Glyph = &pg.glyph;
        let o = ray.origin - pg.origin.extend(0.0);
        let d = ray.dir;
        let (oxy, dxy) = (o.truncate(), d.truncate());
        let hit = |t: f64, piece: f64, s: f64| Hit {
            t,
            part: gi as u32,
            uv: [piece, s],
        };
        // The part of the ray inside the slab z0 <= z <= z1: walls count only there.
        let (zlo, zhi) = if d.z != 0.0 {
            let (a, b) = ((self.z0 - o.z) / d.z, (self.z1 - o.z) / d.z);
            for (t, cap) in [(a, CAP_LOW), (b, CAP_HIGH)] {
                if t > EPSILON && glyph.contains(oxy + dxy * t) {
                    emit(hit(t, cap, 0.0));
                }
            }
            (a.min(b), a.max(b))
        } else if o.z >= self.z0 && o.z <= self.z1 {
            (f64::NEG_INFINITY, f64::INFINITY)
        } else {
            return;
        };
        let len = dxy.length();
        let Some((bmin, bmax)) = glyph.bounds else {
            return;
        };
        if !self.solid || len == 0.0 || !len.is_finite() {
            return;
        }
        let zlo = zlo.max(EPSILON);
        // Clipped further to the outline's box (a little enlarged: a crossing on the box's
        // edge, the top of an "H", must not be lost to rounding), the stretch of ray that
        // pieces are compared with is short even for rays along the walls.
        let (mut tlo, mut thi) = (zlo, zhi);
        const MARGIN: f64 = 1e-9;
        for k in 0..2 {
            let (lo, hi) = (bmin[k] - MARGIN, bmax[k] + MARGIN);
            if dxy[k] != 0.0 {
                let (a, b) = ((lo - oxy[k]) / dxy[k], (hi - oxy[k]) / dxy[k]);
                tlo = tlo.max(a.min(b));
                thi = thi.min(a.max(b));
            } else if oxy[k] < lo || oxy[k] > hi {
                return;
            }
        }
        if tlo > thi {
            return;
        }
        let (q0, q1) = (oxy + dxy * tlo, oxy + dxy * thi);
        let (smin, smax) = (q0.min(q1) - MARGIN, q0.max(q1) + MARGIN);
        let u = dxy / len;
        // The bands give the pieces the full scan would reach, in its order (ties keep their
        // first-found piece).
        glyph
            .bands
            .each_in(glyph.pieces.len(), smin.y, smax.y, |i| {
                let p = &glyph.pieces[i];
                if p.max.x < smin.x || p.min.x > smax.x || p.max.y < smin.y || p.min.y > smax.y {
                    return;
                }
                wall_crossings(p, oxy, u, |s, along| {
                    let t = along / len;
                    if t >= zlo && t <= zhi {
                        emit(hit(t, i as f64, s));
                    }
                });
            });
    }
}

/// Where the line through `o` along the unit vector `u` crosses the piece: calls
/// `f(s, distance along u)` for each curve parameter s in [0, 1) (half-open, so a point shared
/// by two pieces counts once).
fn wall_crossings(p: &Piece, o: DVec2, u: DVec2, mut f: impl FnMut(f64, f64)) {
    let side = |q: DVec2| u.perp_dot(q - o);
    let (f0, fc, f1) = (side(p.p0), side(p.c), side(p.p1));
    // The curve lies in its control triangle: all on one side means no crossing.
    if (f0 > 0.0 && fc > 0.0 && f1 > 0.0) || (f0 < 0.0 && fc < 0.0 && f1 < 0.0) {
        return;
    }
    // side(P(s)) = a s² + b s + c.
    let a = f0 - 2.0 * fc + f1;
    let b = 2.0 * (fc - f0);
    let c = f0;
    let mut visit = |s: f64| {
        if (0.0..1.0).contains(&s) {
            f(s, (p.at(s) - o).dot(u));
        }
    };
    let scale = f0.abs().max(fc.abs()).max(f1.abs());
    if a.abs() <= 1e-12 * scale {
        if b != 0.0 {
            visit(-c / b);
        }
        return;
    }
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return;
    }
    let q = -0.5 * (b + disc.sqrt().copysign(b));
    let r1 = q / a;
    visit(r1);
    if q != 0.0 {
        let r2 = c / q;
        if r2 != r1 {
            visit(r2);
        }
    }
}

impl Shape for Text {
    fn bounds(&self) -> Aabb {
        self.bounds
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        self.bvh.traverse(ray, f64::INFINITY, |i, _| {
            self.glyph_hits(i, ray, |h| out.push(h));
            false
        });
    }

    fn intersect_first(&self, ray: &Ray, tmax: f64, _scratch: &mut Vec<Hit>) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        self.bvh.traverse(ray, tmax, |i, tmax| {
            self.glyph_hits(i, ray, |h| {
                if h.t < *tmax {
                    *tmax = h.t;
                    best = Some(h);
                }
            });
            false
        });
        best
    }

    fn inside(&self, p: DVec3) -> bool {
        if !self.solid || p.z < self.z0 || p.z > self.z1 {
            return false;
        }
        self.data
            .glyphs
            .iter()
            .zip(&self.boxes)
            .any(|(g, b)| b.contains(p) && g.glyph.contains(p.truncate() - g.origin))
    }

    fn normal(&self, _p: DVec3, hit: &Hit) -> DVec3 {
        let piece = hit.uv[0];
        if piece == CAP_LOW {
            return DVec3::NEG_Z;
        }
        match self.data.glyphs.get(hit.part as usize) {
            Some(g) if piece >= 0.0 => g.glyph.wall_normal(piece as usize, hit.uv[1]).extend(0.0),
            _ => DVec3::Z,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::test_rng::Lcg;

    /// A square 1×1 glyph with a square hole, contours as TrueType winds them (outer
    /// clockwise, hole anticlockwise), straight pieces only.
    fn square_glyph() -> Arc<Glyph> {
        let mut pieces = Vec::new();
        let mut contour = |pts: &[(f64, f64)]| {
            for k in 0..pts.len() {
                let a = DVec2::new(pts[k].0, pts[k].1);
                let (x, y) = pts[(k + 1) % pts.len()];
                let b = DVec2::new(x, y);
                pieces.push(Piece {
                    p0: a,
                    c: (a + b) * 0.5,
                    p1: b,
                    min: a.min(b),
                    max: a.max(b),
                });
            }
        };
        contour(&[(0.0, 0.0), (0.0, 1.0), (1.0, 1.0), (1.0, 0.0)]);
        contour(&[(0.25, 0.25), (0.75, 0.25), (0.75, 0.75), (0.25, 0.75)]);
        let g = Glyph::new(1, 1.2, 0.0, pieces, true);
        assert_eq!(g.bounds, Some((DVec2::ZERO, DVec2::ONE)));
        Arc::new(g)
    }

    fn text(thickness: f64, n: usize) -> Text {
        let g = square_glyph();
        let glyphs = (0..n)
            .map(|i| PlacedGlyph {
                glyph: g.clone(),
                origin: DVec2::new(1.2 * i as f64, 0.0),
            })
            .collect();
        Text::new(Arc::new(TextData { glyphs, thickness }))
    }

    fn all(t: &Text, r: &Ray) -> Vec<Hit> {
        let mut v = Vec::new();
        t.intersect_all(r, &mut v);
        v.sort_by(|a, b| a.t.total_cmp(&b.t));
        v
    }

    #[test]
    fn caps_walls_and_hole() {
        let t = text(0.5, 2);
        // Straight through the frame of the first glyph: front cap, back cap.
        let r = Ray::new(DVec3::new(0.1, 0.5, -2.0), DVec3::Z);
        let h = all(&t, &r);
        assert_eq!(h.len(), 2);
        assert!((h[0].t - 2.0).abs() < 1e-12 && (h[1].t - 2.5).abs() < 1e-12);
        assert_eq!(t.normal(r.at(h[0].t), &h[0]), DVec3::NEG_Z);
        assert_eq!(t.normal(r.at(h[1].t), &h[1]), DVec3::Z);
        // Through the hole: nothing.
        assert!(all(&t, &Ray::new(DVec3::new(0.5, 0.5, -2.0), DVec3::Z)).is_empty());
        // Sideways along x at mid depth, y = 0.5: walls at x = 0, .25, .75, 1, 1.2, ...
        let r = Ray::new(DVec3::new(-1.0, 0.5, 0.25), DVec3::X);
        let ts: Vec<f64> = all(&t, &r).iter().map(|h| h.t - 1.0).collect();
        let want = [0.0, 0.25, 0.75, 1.0, 1.2, 1.45, 1.95, 2.2];
        assert_eq!(ts.len(), want.len(), "{ts:?}");
        for (a, b) in ts.iter().zip(want) {
            assert!((a - b).abs() < 1e-12, "{ts:?}");
        }
        let h = all(&t, &r);
        assert!((t.normal(r.at(h[0].t), &h[0]).normalize() - DVec3::NEG_X).length() < 1e-12);
        assert!((t.normal(r.at(h[1].t), &h[1]).normalize() - DVec3::X).length() < 1e-12);
        // Above the slab or beside the glyphs: nothing.
        assert!(all(&t, &Ray::new(DVec3::new(-1.0, 0.5, 0.6), DVec3::X)).is_empty());
        assert!(all(&t, &Ray::new(DVec3::new(-1.0, 1.5, 0.2), DVec3::X)).is_empty());
    }

    #[test]
    fn inside_matches_hit_parity() {
        let t = text(0.4, 3);
        assert!(t.inside(DVec3::new(0.1, 0.1, 0.2)));
        assert!(!t.inside(DVec3::new(0.5, 0.5, 0.2)));
        assert!(!t.inside(DVec3::new(0.1, 0.1, 0.5)));
        assert!(t.inside(DVec3::new(2.5, 0.1, 0.2)));
        // Random rays from outside: crossings alternate in/out, so their count is even, and
        // a point just past an odd number of crossings is inside.
        let mut rng = Lcg(7);
        let mut checked = 0;
        for _ in 0..2000 {
            let o = rng.vec(8.0) + DVec3::new(1.7, 0.5, 0.2);
            if t.inside(o) {
                continue;
            }
            let r = Ray::new(o, rng.vec(2.0) + DVec3::new(1.7, 0.5, 0.2) - o);
            let h = all(&t, &r);
            assert_eq!(h.len() % 2, 0, "{o} {:?}", r.dir);
            for (k, w) in h.windows(2).enumerate() {
                let mid = r.at((w[0].t + w[1].t) * 0.5);
                assert_eq!(t.inside(mid), k % 2 == 0, "{o} {:?} {k}", r.dir);
            }
            checked += h.len();
            let first = t.intersect_first(&r, f64::INFINITY, &mut Vec::new());
            assert_eq!(first.map(|f| f.t), h.first().map(|f| f.t));
        }
        assert!(checked > 500, "{checked}");
    }

    #[test]
    fn bounds_and_degenerate_input() {
        let t = text(-0.5, 2);
        assert_eq!(
            t.bounds(),
            Aabb::new(DVec3::new(0.0, 0.0, -0.5), DVec3::new(2.2, 1.0, 0.0))
        );
        // Negative thickness: both caps, no walls, no inside, as POV-Ray.
        let h = all(&t, &Ray::new(DVec3::new(0.1, 0.1, -1.0), DVec3::Z));
        assert_eq!(h.len(), 2);
        assert!((h[0].t - 0.5).abs() < 1e-12 && (h[1].t - 1.0).abs() < 1e-12);
        assert!(all(&t, &Ray::new(DVec3::new(-1.0, 0.5, -0.25), DVec3::X)).is_empty());
        assert!(!t.inside(DVec3::new(0.1, 0.1, -0.25)));
        let flat = text(0.0, 1);
        let h = all(&flat, &Ray::new(DVec3::new(0.1, 0.1, -1.0), DVec3::Z));
        assert_eq!(h.len(), 2);
        let empty = Text::new(Arc::new(TextData {
            glyphs: vec![],
            thickness: 1.0,
        }));
        assert!(empty.bounds().is_empty());
        assert!(all(&empty, &Ray::new(DVec3::ZERO, DVec3::Z)).is_empty());
        let nan = text(f64::NAN, 1);
        assert!(all(&nan, &Ray::new(DVec3::new(0.1, 0.1, -1.0), DVec3::Z)).len() == 2);
        assert!(all(&t, &Ray::new(DVec3::new(0.1, 0.1, -1.0), DVec3::ZERO)).is_empty());
        assert_eq!(t.normal(DVec3::ZERO, &Hit::with_part(1.0, 99)), DVec3::Z);
    }
}
