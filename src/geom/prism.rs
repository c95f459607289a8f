//! POV-Ray `prism`: closed 2-D spline outlines in the x-z plane swept along y, either straight
//! (`linear_sweep`) or shrinking towards the origin (`conic_sweep`, where the outline at height
//! y is the written one scaled by y).
//!
//! Wall crossings are found in the plane that holds the ray and the sweep direction (vertical
//! for a linear sweep, through the apex for a conic one): that plane cuts each outline piece
//! where a cubic in the piece's parameter changes sign. Caps and `inside` use the even-odd rule
//! over all sub-outlines, so nested outlines make holes as in POV-Ray.

use crate::geom::spline2d::{inside_even_odd, sign_changes, Piece, SplineKind, P2};
use crate::geom::{Hit, Shape};
use crate::math::{Aabb, DVec3, Ray, EPSILON};

const CAP_LOW: u32 = u32::MAX - 1;
const CAP_HIGH: u32 = u32::MAX;

#[derive(Clone, Debug)]
pub struct Prism {
    pieces: Vec<Piece>,
    /// Heights, low then high.
    h: [f64; 2],
    conic: bool,
    open: bool,
    /// Bounds of the outline.
    lo: P2,
    hi: P2,
}

/// The outline pieces of a prism read from its points, or why POV-Ray refuses them.
#[derive(Debug, PartialEq)]
pub struct Outline {
    pub pieces: Vec<Piece>,
    /// POV-Ray's warning about a sub-outline it closed or dropped.
    pub warning: Option<&'static str>,
}

/// Splits the points into sub-outlines as POV-Ray does: each closes where its first point on
/// the curve comes again. Control points come before (quadratic, cubic) and after (cubic)
/// each sub-outline's own points; Bézier pieces take four points each.
pub fn outline(kind: SplineKind, p: &[P2]) -> Result<Outline, String> {
    let n = p.len();
    let need = match kind {
        SplineKind::Linear => 3,
        SplineKind::Quadratic => 5,
        SplineKind::Cubic => 6,
        SplineKind::Bezier => 4,
    };
    if kind == SplineKind::Bezier && (!n.is_multiple_of(4) || n == 0) {
        return Err("Prism with Bezier splines must have four points per segment.".into());
    }
    if n < need {
        let words = ["", "", "", "three", "four", "five", "six"];
        return Err(format!(
            "Prism with {} splines must have at least {} points.",
            kind.name(),
            words[need]
        ));
    }
    let mut pieces = Vec::new();
    let mut warning = None;
    let mut st = 0;
    match kind {
        SplineKind::Linear => {
            while st < n {
                let mut k = st + 1;
                let mut closed = false;
                while k < n {
                    pieces.push(Piece::linear(p[k - 1], p[k]));
                    if p[k] == p[st] {
                        closed = true;
                        break;
                    }
                    k += 1;
                }
                if !closed {
                    // A lone point left over is dropped silently, as POV-Ray does.
                    if n - st >= 2 {
                        warning = Some("Linear prism not closed. Closing it.");
                        pieces.push(Piece::linear(p[n - 1], p[st]));
                    }
                    break;
                }
                st = k + 1;
            }
        }
        SplineKind::Quadratic | SplineKind::Cubic => {
            let cubic = kind == SplineKind::Cubic;
            while st + 1 < n {
                let start = st + 1;
                let mut sub = Vec::new();
                let mut end = None;
                let mut k = start;
                while k + 1 < n {
                    if cubic {
                        if k + 2 >= n {
                            break;
                        }
                        sub.push(Piece::cubic(p[k - 1], p[k], p[k + 1], p[k + 2]));
                    } else {
                        sub.push(Piece::quadratic(p[k - 1], p[k], p[k + 1]));
                    }
                    if p[k + 1] == p[start] {
                        end = Some(k + 1);
                        break;
                    }
                    k += 1;
                }
                match end {
                    Some(e) => {
                        pieces.extend(sub);
                        st = e + if cubic { 2 } else { 1 };
                    }
                    None => {
                        warning = Some("Prism not closed. Ignoring it.");
                        break;
                    }
                }
            }
        }
        SplineKind::Bezier => {
            let mut sub = Vec::new();
            for g in (0..n).step_by(4) {
                sub.push(Piece::bezier(p[g], p[g + 1], p[g + 2], p[g + 3]));
                if p[g + 3] == p[st] {
                    pieces.append(&mut sub);
                    st = g + 4;
                }
            }
            if !sub.is_empty() {
                warning = Some("Prism not closed. Ignoring it.");
            }
        }
    }
    if pieces.is_empty() {
        return Err("Too few points in prism (no closed outline).".into());
    }
    Ok(Outline { pieces, warning })
}

impl Prism {
    pub fn new(pieces: Vec<Piece>, h1: f64, h2: f64, conic: bool, open: bool) -> Prism {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for pc in &pieces {
            for i in 0..2 {
                lo[i] = lo[i].min(pc.lo[i]);
                hi[i] = hi[i].max(pc.hi[i]);
            }
        }
        Prism {
            pieces,
            h: [h1.min(h2), h1.max(h2)],
            conic,
            open,
            lo,
            hi,
        }
    }

    fn in_heights(&self, y: f64) -> bool {
        y >= self.h[0] && y <= self.h[1]
    }

    /// The outline point a height-`y` point at (x, z) corresponds to.
    fn unswept(&self, x: f64, z: f64, y: f64) -> Option<P2> {
        if !self.conic {
            Some([x, z])
        } else if y != 0.0 {
            Some([x / y, z / y])
        } else {
            None
        }
    }

    /// The plane holding the ray and the sweep direction, `g(q) = n · (q, 1) + k`, as
    /// (nx, ny + k, nz); None when the ray runs along the sweep direction.
    fn cut_plane(&self, ray: &Ray) -> Option<(f64, f64, f64)> {
        let (o, d) = (ray.origin, ray.dir);
        let (nx, ny, nz, k) = if self.conic {
            let n = o.cross(d);
            (n.x, n.y, n.z, 0.0)
        } else {
            (-d.z, 0.0, d.x, d.z * o.x - d.x * o.z)
        };
        if nx == 0.0 && nz == 0.0 {
            return None;
        }
        Some((nx, ny + k, nz))
    }

    /// Whether the cut plane can meet piece `pc`: it must separate the piece's bounding box
    /// corners.
    fn may_cut(pc: &Piece, g: impl Fn(P2) -> f64) -> bool {
        let c = [
            g(pc.lo),
            g(pc.hi),
            g([pc.lo[0], pc.hi[1]]),
            g([pc.hi[0], pc.lo[1]]),
        ];
        !(c.iter().all(|&v| v > 0.0) || c.iter().all(|&v| v < 0.0))
    }

    /// The wall crossings of piece `i`, in increasing s.
    fn piece_hits(&self, ray: &Ray, plane: (f64, f64, f64), i: usize, mut found: impl FnMut(Hit)) {
        let (o, d) = (ray.origin, ray.dir);
        let (nx, c0, nz) = plane;
        let g = |q: P2| nx * q[0] + nz * q[1] + c0;
        let pc = &self.pieces[i];
        let (g0, g1) = (g(pc.p0), g(pc.p1));
        let mut hit = |s: f64, q: P2| {
            if let Some(t) = self.wall_t(o, d, q) {
                found(Hit {
                    t,
                    part: i as u32,
                    uv: [s, 0.0],
                });
            }
        };
        if pc.is_linear() {
            if (g0 >= 0.0) != (g1 >= 0.0) {
                let s = g0 / (g0 - g1);
                let q = [
                    pc.p0[0] + s * (pc.p1[0] - pc.p0[0]),
                    pc.p0[1] + s * (pc.p1[1] - pc.p0[1]),
                ];
                hit(s, q);
            }
            return;
        }
        let mut c: [f64; 4] = std::array::from_fn(|j| nx * pc.x[j] + nz * pc.y[j]);
        c[0] += c0;
        sign_changes(&c, 0.0, 1.0, g0, g1, |s| hit(s, pc.at(s)));
    }

    fn walls(&self, ray: &Ray, out: &mut Vec<Hit>) {
        let Some(plane) = self.cut_plane(ray) else {
            return;
        };
        let (nx, c0, nz) = plane;
        let g = |q: P2| nx * q[0] + nz * q[1] + c0;
        for (i, pc) in self.pieces.iter().enumerate() {
            if Self::may_cut(pc, g) {
                self.piece_hits(ray, plane, i, |h| out.push(h));
            }
        }
    }

    /// A lower bound of the `t` any wall crossing of piece `pc` can get from `wall_t` (linear
    /// sweep): the least of the linear `t(q)` over the piece's box, less a margin far above
    /// the rounding of `wall_t` and of the curve's points (a few ulps of the terms).
    fn wall_t_floor(pc: &Piece, o: DVec3, d: DVec3, dd: f64) -> f64 {
        let x = if d.x >= 0.0 { pc.lo[0] } else { pc.hi[0] };
        let z = if d.z >= 0.0 { pc.lo[1] } else { pc.hi[1] };
        let t = ((x - o.x) * d.x + (z - o.z) * d.z) / dd;
        let size = (pc.hi[0] - pc.lo[0]).max(pc.hi[1] - pc.lo[1]);
        let mag = ((x.abs() + o.x.abs() + size) * d.x.abs()
            + (z.abs() + o.z.abs() + size) * d.z.abs())
            / dd;
        t - 1e-9 * (mag + t.abs())
    }

    /// `intersect_first` of a linear sweep: the same crossing the default (every crossing,
    /// then the first least `t` in `intersect_all`'s order) picks, with pieces and caps taken
    /// by the least `t` they can reach and the search stopped when that is beyond the best
    /// found. A crossing replaces the best when its `t` is less, or equal and earlier in
    /// `intersect_all`'s order (walls by piece, then the low and the high cap).
    fn first_linear(&self, ray: &Ray, tmax: f64, cand: &mut Vec<Hit>) -> Option<Hit> {
        let (o, d) = (ray.origin, ray.dir);
        cand.clear();
        let plane = self.cut_plane(ray);
        if let Some((nx, c0, nz)) = plane {
            let g = |q: P2| nx * q[0] + nz * q[1] + c0;
            let dd = d.x * d.x + d.z * d.z;
            for (i, pc) in self.pieces.iter().enumerate() {
                if Self::may_cut(pc, g) {
                    let floor = Self::wall_t_floor(pc, o, d, dd);
                    // NaN floors are kept (and never stop the search).
                    if floor < tmax || floor.is_nan() {
                        cand.push(Hit::with_part(floor, i as u32));
                    }
                }
            }
        }
        let n_pieces = self.pieces.len() as u32;
        if !self.open && d.y != 0.0 {
            for (h, key) in [(self.h[0], n_pieces), (self.h[1], n_pieces + 1)] {
                let t = (h - o.y) / d.y;
                if !t.is_nan() && t > EPSILON && t < tmax {
                    cand.push(Hit::with_part(t, key));
                }
            }
        }
        cand.sort_unstable_by(|a, b| a.t.total_cmp(&b.t).then(a.part.cmp(&b.part)));
        // (t, order key) of the best crossing so far.
        let mut best: Option<(Hit, u32)> = None;
        let offer = |h: Hit, key: u32, best: &mut Option<(Hit, u32)>| {
            if h.t < tmax && best.is_none_or(|(b, bk)| h.t < b.t || (h.t == b.t && key < bk)) {
                *best = Some((h, key));
            }
        };
        for c in cand.iter() {
            if best.is_some_and(|(b, _)| c.t > b.t) {
                break;
            }
            if c.part < n_pieces {
                if let Some(plane) = plane {
                    self.piece_hits(ray, plane, c.part as usize, |h| offer(h, c.part, &mut best));
                }
            } else {
                let (h, part) = if c.part == n_pieces {
                    (self.h[0], CAP_LOW)
                } else {
                    (self.h[1], CAP_HIGH)
                };
                let p = o + d * c.t;
                if let Some(q) = self.unswept(p.x, p.z, h) {
                    if inside_even_odd(&self.pieces, q, false) {
                        offer(Hit::with_part(c.t, part), c.part, &mut best);
                    }
                }
            }
        }
        best.map(|(h, _)| h)
    }

    /// Where the ray meets the wall line through outline point `q`, within the heights.
    fn wall_t(&self, o: DVec3, d: DVec3, q: P2) -> Option<f64> {
        let t = if self.conic {
            // The line λ (x, 1, z) through the apex.
            let w = DVec3::new(q[0], 1.0, q[1]);
            let dw = d.cross(w);
            let l2 = dw.length_squared();
            if l2 == 0.0 {
                return None;
            }
            -o.cross(w).dot(dw) / l2
        } else {
            let dd = d.x * d.x + d.z * d.z;
            ((q[0] - o.x) * d.x + (q[1] - o.z) * d.z) / dd
        };
        (t > EPSILON && self.in_heights(o.y + t * d.y)).then_some(t)
    }

    fn caps(&self, ray: &Ray, out: &mut Vec<Hit>) {
        let (o, d) = (ray.origin, ray.dir);
        if self.open || d.y == 0.0 {
            return;
        }
        for (h, part) in [(self.h[0], CAP_LOW), (self.h[1], CAP_HIGH)] {
            let t = (h - o.y) / d.y;
            // Also rejects NaN.
            if t.is_nan() || t <= EPSILON {
                continue;
            }
            let p = o + d * t;
            if let Some(q) = self.unswept(p.x, p.z, h) {
                if inside_even_odd(&self.pieces, q, false) {
                    out.push(Hit::with_part(t, part));
                }
            }
        }
    }
}

impl Shape for Prism {
    fn bounds(&self) -> Aabb {
        if self.pieces.is_empty() {
            return Aabb::EMPTY;
        }
        if !self.conic {
            return Aabb::new(
                DVec3::new(self.lo[0], self.h[0], self.lo[1]),
                DVec3::new(self.hi[0], self.h[1], self.hi[1]),
            );
        }
        // The outline scaled by each height; the scaling is linear in y, so the ends bound it.
        let mut b = Aabb::EMPTY;
        for h in self.h {
            for (x, z) in [
                (self.lo[0], self.lo[1]),
                (self.hi[0], self.hi[1]),
                (self.lo[0], self.hi[1]),
                (self.hi[0], self.lo[1]),
            ] {
                b = b.grow(DVec3::new(x * h, h, z * h));
            }
        }
        b
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        self.walls(ray, out);
        self.caps(ray, out);
    }

    fn intersect_first(&self, ray: &Ray, tmax: f64, scratch: &mut Vec<Hit>) -> Option<Hit> {
        if self.conic {
            // Every wall crossing, then a cap only where it comes strictly before the best
            // (the caps come after the walls in `intersect_all`'s order, so ties go to walls):
            // the caps' even-odd tests are the costly part.
            scratch.clear();
            self.walls(ray, scratch);
            let mut best = scratch
                .iter()
                .filter(|h| h.t > EPSILON && h.t < tmax)
                .min_by(|a, b| a.t.total_cmp(&b.t))
                .copied();
            let (o, d) = (ray.origin, ray.dir);
            if !self.open && d.y != 0.0 {
                for (h, part) in [(self.h[0], CAP_LOW), (self.h[1], CAP_HIGH)] {
                    let t = (h - o.y) / d.y;
                    if t.is_nan() || t <= EPSILON || t >= best.map_or(tmax, |b| b.t) {
                        continue;
                    }
                    let p = o + d * t;
                    if let Some(q) = self.unswept(p.x, p.z, h) {
                        if inside_even_odd(&self.pieces, q, false) {
                            best = Some(Hit::with_part(t, part));
                        }
                    }
                }
            }
            return best;
        }
        self.first_linear(ray, tmax, scratch)
    }

    fn inside(&self, p: DVec3) -> bool {
        self.in_heights(p.y)
            && self
                .unswept(p.x, p.z, p.y)
                .is_some_and(|q| inside_even_odd(&self.pieces, q, false))
    }

    fn normal(&self, p: DVec3, hit: &Hit) -> DVec3 {
        match hit.part {
            CAP_LOW => return DVec3::NEG_Y,
            CAP_HIGH => return DVec3::Y,
            _ => {}
        }
        let Some(pc) = self.pieces.get(hit.part as usize) else {
            return DVec3::Y;
        };
        let s = hit.uv[0];
        let (q, tan) = (pc.at(s), pc.tangent(s));
        let mut m = [tan[1], -tan[0]];
        // Outward is the side not inside the outline: test a point just off the curve.
        let len = (m[0] * m[0] + m[1] * m[1]).sqrt();
        if len > 0.0 {
            let size = (self.hi[0] - self.lo[0]).max(self.hi[1] - self.lo[1]);
            let e = 1e-7 * size / len;
            if inside_even_odd(&self.pieces, [q[0] + e * m[0], q[1] + e * m[1]], false) {
                m = [-m[0], -m[1]];
            }
        }
        if self.conic {
            // Normal to both (x, 1, z) and the tangent (x', 0, z'); the outline at negative
            // heights is mirrored through the axis, which turns outward around.
            let n = DVec3::new(m[0], -(q[0] * m[0] + q[1] * m[1]), m[1]);
            if p.y < 0.0 {
                -n
            } else {
                n
            }
        } else {
            DVec3::new(m[0], 0.0, m[1])
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(a: f64, b: f64) -> Vec<P2> {
        vec![[a, a], [b, a], [b, b], [a, b], [a, a]]
    }

    fn hits(s: &Prism, r: &Ray) -> Vec<(f64, u32)> {
        let mut v = Vec::new();
        s.intersect_all(r, &mut v);
        let mut v: Vec<(f64, u32)> = v.iter().map(|h| (h.t, h.part)).collect();
        v.sort_by(|a, b| a.0.total_cmp(&b.0));
        v
    }

    #[test]
    fn outlines_close_as_povray_does() {
        let mut p = square(0.0, 6.0);
        p.extend(square(1.0, 5.0));
        let o = outline(SplineKind::Linear, &p).unwrap();
        assert_eq!((o.pieces.len(), o.warning), (8, None));
        // The last outline is closed with a warning; a stray point after a closed one is not.
        let o = outline(SplineKind::Linear, &p[..8]).unwrap();
        assert_eq!(o.pieces.len(), 7);
        assert!(o.warning.unwrap().contains("Closing"));
        let mut q = square(0.0, 1.0);
        q.push([5.0, 5.0]);
        let o = outline(SplineKind::Linear, &q).unwrap();
        assert_eq!((o.pieces.len(), o.warning), (4, None));
        assert!(outline(SplineKind::Linear, &q[..2])
            .unwrap_err()
            .contains("three"));
        // Quadratic: control point, then the outline up to its first point again.
        let quad = [
            [1.0, -1.0],
            [0.0, 0.0],
            [6.0, 0.0],
            [6.0, 8.0],
            [0.0, 8.0],
            [0.0, 0.0],
        ];
        let o = outline(SplineKind::Quadratic, &quad).unwrap();
        assert_eq!((o.pieces.len(), o.warning), (4, None));
        let e = outline(SplineKind::Quadratic, &quad[..5]).unwrap_err();
        assert!(e.contains("Too few"), "{e}");
        let mut cub = quad.to_vec();
        cub.push([-1.0, 1.0]);
        assert_eq!(outline(SplineKind::Cubic, &cub).unwrap().pieces.len(), 4);
        assert!(outline(SplineKind::Cubic, &cub[..5]).is_err());
        let bez = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 0.0]];
        assert_eq!(outline(SplineKind::Bezier, &bez).unwrap().pieces.len(), 1);
        assert!(outline(SplineKind::Bezier, &bez[..3])
            .unwrap_err()
            .contains("four points per"));
        let open_bez = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.5, 0.0]];
        assert!(outline(SplineKind::Bezier, &open_bez).is_err());
    }

    #[test]
    fn frame_with_hole() {
        let mut p = square(0.0, 6.0);
        p.extend(square(1.0, 5.0));
        let pr = Prism::new(
            outline(SplineKind::Linear, &p).unwrap().pieces,
            1.0,
            0.0,
            false,
            false,
        );
        // Along x through the frame at mid height: in, out of the rim, into the rim, out.
        let r = Ray::new(DVec3::new(-1.0, 0.5, 3.0), DVec3::X);
        let t: Vec<f64> = hits(&pr, &r).iter().map(|h| h.0).collect();
        assert_eq!(t, vec![1.0, 2.0, 6.0, 7.0]);
        // Down onto the rim hits the top cap; down through the hole misses.
        let down = Ray::new(DVec3::new(0.5, 5.0, 0.5), DVec3::NEG_Y);
        assert_eq!(hits(&pr, &down), vec![(4.0, CAP_HIGH), (5.0, CAP_LOW)]);
        assert!(hits(&pr, &Ray::new(DVec3::new(3.0, 5.0, 3.0), DVec3::NEG_Y)).is_empty());
        assert!(pr.inside(DVec3::new(0.5, 0.5, 3.0)));
        assert!(!pr.inside(DVec3::new(3.0, 0.5, 3.0)));
        assert!(!pr.inside(DVec3::new(0.5, 1.5, 3.0)));
        // Normals point out of the material, also on the hole's walls.
        let n = |x: f64, z: f64, part: u32| {
            let hit = Hit {
                t: 0.0,
                part,
                uv: [0.5, 0.0],
            };
            pr.normal(DVec3::new(x, 0.5, z), &hit).normalize()
        };
        // Piece 0 runs along z = 0 (outer), piece 4 along z = 1 (the hole's edge).
        assert!((n(3.0, 0.0, 0) - DVec3::NEG_Z).length() < 1e-12);
        assert!((n(3.0, 1.0, 4) - DVec3::Z).length() < 1e-12);
        let open = Prism::new(pr.pieces.clone(), 0.0, 1.0, false, true);
        assert!(hits(&open, &down).is_empty());
    }

    #[test]
    fn conic_sweep_scales_with_height() {
        let p = square(-1.0, 1.0);
        let pieces = outline(SplineKind::Linear, &p).unwrap().pieces;
        let pr = Prism::new(pieces, 0.5, 2.0, true, false);
        // At height 1 the section is the written square; at 2 twice as large.
        let r = Ray::new(DVec3::new(-5.0, 1.0, 0.0), DVec3::X);
        let t: Vec<f64> = hits(&pr, &r).iter().map(|h| h.0).collect();
        assert!(
            (t[0] - 4.0).abs() < 1e-12 && (t[1] - 6.0).abs() < 1e-12,
            "{t:?}"
        );
        let r = Ray::new(DVec3::new(1.5, 5.0, 0.0), DVec3::NEG_Y);
        let h = hits(&pr, &r);
        assert_eq!(h.len(), 2);
        assert_eq!(h[0], (3.0, CAP_HIGH));
        assert!((h[1].0 - 3.5).abs() < 1e-12);
        let b = pr.bounds();
        assert_eq!(b.min, DVec3::new(-2.0, 0.5, -2.0));
        assert!(pr.inside(DVec3::new(1.5, 1.9, 0.0)) && !pr.inside(DVec3::new(1.5, 1.0, 0.0)));
        let hit = Hit {
            t: 0.0,
            part: 1,
            uv: [0.5, 0.0],
        };
        // Piece 1 is the edge x = 1; at height y the wall is x = y, leaning outward.
        let n = pr.normal(DVec3::new(1.0, 1.0, 0.0), &hit).normalize();
        let want = DVec3::new(1.0, -1.0, 0.0).normalize();
        assert!((n - want).length() < 1e-12, "{n}");
    }

    /// Random rays against the crossings found by walking the ray with the inside test.
    #[test]
    fn random_rays_match_the_inside_test() {
        use crate::geom::test_rng::Lcg;
        let quad: Vec<P2> = vec![
            [1.0, -1.0],
            [0.0, 0.0],
            [6.0, 0.0],
            [6.0, 8.0],
            [0.0, 8.0],
            [0.0, 0.0],
            [2.0, 0.0],
            [1.0, 1.0],
            [5.0, 1.0],
            [5.0, 7.0],
            [1.0, 7.0],
            [1.0, 1.0],
        ];
        let bez: Vec<P2> = vec![
            [0.0, 0.0],
            [4.0, -2.0],
            [7.0, 3.0],
            [6.0, 6.0],
            [6.0, 6.0],
            [3.0, 9.0],
            [-2.0, 4.0],
            [0.0, 0.0],
        ];
        let mut rng = Lcg(11);
        for (kind, pts, conic) in [
            (SplineKind::Quadratic, &quad, false),
            (SplineKind::Bezier, &bez, false),
            (SplineKind::Bezier, &bez, true),
        ] {
            let pieces = outline(kind, pts).unwrap().pieces;
            let pr = Prism::new(pieces, 0.3, 2.0, conic, false);
            let mut bad = 0;
            for _ in 0..300 {
                let target = DVec3::new(3.0, 1.0, 3.0) + rng.vec(10.0);
                let origin = target + rng.vec(1.0).normalize() * 25.0;
                let r = Ray::new(origin, (target - origin) * 0.1);
                let got: Vec<f64> = hits(&pr, &r).iter().map(|h| h.0).collect();
                let far = 50.0 / r.dir.length();
                let mut want = Vec::new();
                let steps = 5000;
                let mut prev = pr.inside(r.at(0.0));
                for i in 1..=steps {
                    let (mut a, mut b) = (
                        far * (i - 1) as f64 / steps as f64,
                        far * i as f64 / steps as f64,
                    );
                    let cur = pr.inside(r.at(b));
                    if cur != prev {
                        for _ in 0..80 {
                            let m = 0.5 * (a + b);
                            if pr.inside(r.at(m)) == prev {
                                a = m;
                            } else {
                                b = m;
                            }
                        }
                        want.push(0.5 * (a + b));
                    }
                    prev = cur;
                }
                let ok = got.len() == want.len()
                    && got.iter().zip(&want).all(|(a, b)| (a - b).abs() < 1e-6);
                if !ok {
                    bad += 1;
                    eprintln!("{kind:?} conic {conic}: got {got:?} want {want:?}");
                }
            }
            // A step may hold two crossings closer than it: allow a rare miss.
            assert!(bad <= 3, "{kind:?} conic {conic}: {bad} of 300");
        }
    }

    #[test]
    fn curved_outline_round_trip() {
        // A Catmull-Rom ring: rays from the centre leave it once, wherever they point.
        let ring: Vec<P2> = (0..9)
            .map(|i| {
                let a = (i % 6) as f64 * std::f64::consts::TAU / 6.0;
                [a.cos(), a.sin()]
            })
            .collect();
        let pieces = outline(SplineKind::Cubic, &ring).unwrap().pieces;
        assert_eq!(pieces.len(), 6);
        let pr = Prism::new(pieces, -1.0, 1.0, false, false);
        for k in 0..50 {
            let a = k as f64 * 0.37;
            let d = DVec3::new(a.cos(), 0.1 * (k as f64 - 25.0) / 25.0, a.sin());
            let mut h = Vec::new();
            pr.intersect_all(&Ray::new(DVec3::ZERO, d), &mut h);
            assert_eq!(h.len(), 1, "{k}: {h:?}");
            // The normal points away from the centre.
            let p = d * h[0].t;
            assert!(pr.normal(p, &h[0]).dot(DVec3::new(p.x, 0.0, p.z)) > 0.0);
        }
    }

    /// `intersect_first` skips pieces and caps that cannot come first: it must give the
    /// default's answer (every crossing, the first least `t`) to the bit, part and uv
    /// included, for both sweeps and every spline kind, rays from inside and outside.
    #[test]
    fn nearest_crossing_is_the_defaults() {
        let mut seed = 0x1234_5678_9abc_def1u64;
        let mut unit = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let star: Vec<P2> = (0..11)
            .map(|k| {
                let a = k as f64 * std::f64::consts::TAU / 10.0;
                let r = if k % 2 == 0 { 1.0 } else { 0.45 };
                [r * a.cos(), r * a.sin()]
            })
            .collect();
        let mut holed = square(-1.0, 1.0);
        holed.extend(square(-0.5, 0.5));
        let mut quad = vec![star[9]];
        quad.extend(&star[..10]);
        quad.push(star[0]);
        quad.push(star[1]);
        let kinds: Vec<(SplineKind, Vec<P2>)> = vec![
            (SplineKind::Linear, star.clone()),
            (SplineKind::Linear, holed),
            (SplineKind::Quadratic, quad[..12].to_vec()),
            (SplineKind::Cubic, quad.clone()),
        ];
        let mut n_hits = 0;
        for (kind, pts) in kinds {
            let pieces = outline(kind, &pts).unwrap().pieces;
            for conic in [false, true] {
                let pr = Prism::new(pieces.clone(), 0.2, 1.0, conic, false);
                for _ in 0..4000 {
                    let o = DVec3::new(4.0 * unit() - 2.0, 3.0 * unit() - 1.0, 4.0 * unit() - 2.0);
                    let target = DVec3::new(2.0 * unit() - 1.0, unit(), 2.0 * unit() - 1.0);
                    let ray = Ray::new(o, target - o);
                    let tmax = if unit() < 0.3 {
                        0.5 + unit()
                    } else {
                        f64::INFINITY
                    };
                    let want = crate::geom::test_rng::nearest_of_all(&pr, &ray, tmax);
                    let got = pr.intersect_first(&ray, tmax, &mut Vec::new());
                    n_hits += want.is_some() as usize;
                    let key =
                        |h: Option<Hit>| h.map(|h| (h.t.to_bits(), h.part, h.uv[0].to_bits()));
                    assert_eq!(key(got), key(want), "{kind:?} conic {conic} {ray:?}");
                }
            }
        }
        assert!(n_hits > 10_000, "{n_hits}");
    }
}
