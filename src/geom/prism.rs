//! POV-Ray `prism`: closed 2-D spline outlines in the x-z plane swept along y, either straight
//! (`linear_sweep`) or shrinking towards the origin (`conic_sweep`, where the outline at height
//! y is the written one scaled by y).
//!
//! Wall crossings are found in the plane that holds the ray and the sweep direction (vertical
//! for a linear sweep, through the apex for a conic one): that plane cuts each outline piece
//! where a cubic in the piece's parameter changes sign. Caps and `inside` use the even-odd rule
//! over all sub-outlines, so nested outlines make holes as in POV-Ray.

use crate::geom::spline2d::{hull_on, inside_even_odd, sign_changes_until, Piece, SplineKind, P2};
use crate::geom::{Hit, Shape};
use crate::math::{Aabb, DVec3, Ray, EPSILON};
use window::{Keep, Window};

mod window;

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

    /// Whether the point `p` of the cap plane at height `h` lies on the cap: inside the
    /// outline there (even-odd).
    #[inline]
    fn on_cap(&self, p: DVec3, h: f64) -> bool {
        self.unswept(p.x, p.z, h)
            .is_some_and(|q| inside_even_odd(&self.pieces, q, false))
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

    /// The wall crossings of piece `i`, in increasing s; with `keep` (a linear sweep), only
    /// those it may keep are refined to the end, the others may be left out.
    fn piece_hits(
        &self,
        ray: &Ray,
        plane: (f64, f64, f64),
        i: usize,
        keep: Option<Keep>,
        mut found: impl FnMut(Hit),
    ) {
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
        // The numerator of `wall_t`'s linear `t` along the piece, and a margin far above its
        // rounding and the curve's (as in `wall_t_range`), made at the first bracket asked.
        let mut along: Option<([f64; 4], f64)> = None;
        let settle = |a: f64, b: f64| -> Option<()> {
            let k = keep?;
            let (n, m) = *along.get_or_insert_with(|| Self::along(pc, o, d));
            let (floor, ceil) = Self::bracket_t_range(&n, m, a, b, k.inv_dd);
            (ceil < k.lo || floor > k.hi || floor >= k.before).then_some(())
        };
        sign_changes_until(&c, 0.0, 1.0, g0, g1, settle, |r| {
            if let Ok(s) = r {
                hit(s, pc.at(s))
            }
        });
    }

    /// The numerator of `wall_t`'s linear `t` along piece `pc` (a cubic in its parameter),
    /// and a margin far above its rounding and the curve's (as in `wall_t_range`).
    #[inline(always)]
    fn along(pc: &Piece, o: DVec3, d: DVec3) -> ([f64; 4], f64) {
        let mut n: [f64; 4] = std::array::from_fn(|j| pc.x[j] * d.x + pc.y[j] * d.z);
        n[0] -= o.x * d.x + o.z * d.z;
        let size = (pc.hi[0] - pc.lo[0]).max(pc.hi[1] - pc.lo[1]);
        let far = |i: usize| pc.lo[i].abs().max(pc.hi[i].abs()) + size;
        let mag = (far(0) + o.x.abs()) * d.x.abs() + (far(1) + o.z.abs()) * d.z.abs();
        (n, 1e-9 * mag)
    }

    /// Bounds of the `t` `wall_t` can give a crossing whose parameter lies in `[a, b]`
    /// (linear sweep), from `along`'s numerator and margin: its hull there widened by the
    /// margin and by far more than the hull's rounding and the product by `inv_dd`'s.
    #[inline(always)]
    fn bracket_t_range(n: &[f64; 4], m: f64, a: f64, b: f64, inv_dd: f64) -> (f64, f64) {
        let (lo, hi) = hull_on(n, a, b);
        (
            (lo - (m + 1e-9 * lo.abs())) * inv_dd,
            (hi + (m + 1e-9 * hi.abs())) * inv_dd,
        )
    }

    /// Whether piece `i` holds a wall crossing `first_linear` would offer before `tmax`
    /// (linear sweep; `keep` as `first_linear` makes it before it has a best). A bracket
    /// whose `t` bounds lie wholly within `sure` (the `t` whose heights `in_heights` surely
    /// accepts), above `EPSILON` and below `tmax` holds such a crossing whatever its last
    /// bits: its refinement stops there.
    fn piece_crossed(
        &self,
        ray: &Ray,
        plane: (f64, f64, f64),
        i: usize,
        keep: Keep,
        sure: (f64, f64),
    ) -> bool {
        let pc = &self.pieces[i];
        let tmax = keep.before;
        let mut found = false;
        if pc.is_linear() {
            self.piece_hits(ray, plane, i, Some(keep), |h| found |= h.t < tmax);
            return found;
        }
        let (o, d) = (ray.origin, ray.dir);
        let (nx, c0, nz) = plane;
        let g = |q: P2| nx * q[0] + nz * q[1] + c0;
        let (g0, g1) = (g(pc.p0), g(pc.p1));
        let mut c: [f64; 4] = std::array::from_fn(|j| nx * pc.x[j] + nz * pc.y[j]);
        c[0] += c0;
        let mut along: Option<([f64; 4], f64)> = None;
        let settle = |a: f64, b: f64| -> Option<bool> {
            let (n, m) = *along.get_or_insert_with(|| Self::along(pc, o, d));
            let (floor, ceil) = Self::bracket_t_range(&n, m, a, b, keep.inv_dd);
            if ceil < keep.lo || floor > keep.hi || floor >= keep.before {
                Some(false)
            } else if floor > EPSILON && floor >= sure.0 && ceil <= sure.1 && ceil < tmax {
                Some(true)
            } else {
                None
            }
        };
        sign_changes_until(&c, 0.0, 1.0, g0, g1, settle, |r| {
            found |= match r {
                Ok(s) => self.wall_t(o, d, pc.at(s)).is_some_and(|t| t < tmax),
                Err(kept) => kept,
            }
        });
        found
    }

    /// `any_hit` of a linear sweep: whether `first_linear` finds a crossing. Its candidate
    /// pieces are asked in their order and the first crossing ends the search; the caps
    /// (their even-odd tests) are asked only when no wall is crossed.
    fn any_linear(&self, ray: &Ray, tmax: f64) -> bool {
        let (o, d) = (ray.origin, ray.dir);
        let inv_dd = Self::inv_dd(d);
        let ((y_lo, y_hi), sure) = self.height_t_ranges(o, d);
        if let Some(plane) = self.cut_plane(ray) {
            let (nx, c0, nz) = plane;
            let g = |q: P2| nx * q[0] + nz * q[1] + c0;
            let keep = Keep {
                lo: y_lo,
                hi: y_hi,
                before: tmax,
                inv_dd,
            };
            for (i, pc) in self.pieces.iter().enumerate() {
                if Self::may_cut(pc, g) {
                    let (floor, ceil) = Self::wall_t_range(pc, o, d, inv_dd);
                    // `first_linear`'s candidates (NaN floors kept).
                    if floor > y_hi || ceil < y_lo || !(floor < tmax || floor.is_nan()) {
                        continue;
                    }
                    if self.piece_crossed(ray, plane, i, keep, sure) {
                        return true;
                    }
                }
            }
        }
        // `first_linear` offers a cap only for `t < tmax`: none for a NaN `tmax`.
        !tmax.is_nan() && self.cap_before(ray, tmax)
    }

    /// Whether a closed prism's cap is crossed at a `t` with `EPSILON < t` and not
    /// `t >= tmax` (as a conic sweep's `intersect_first` skips caps: a NaN `tmax` skips none).
    fn cap_before(&self, ray: &Ray, tmax: f64) -> bool {
        let (o, d) = (ray.origin, ray.dir);
        if self.open || d.y == 0.0 {
            return false;
        }
        self.h.iter().any(|&h| {
            let t = (h - o.y) / d.y;
            if t.is_nan() || t <= EPSILON || t >= tmax {
                return false;
            }
            self.on_cap(o + d * t, h)
        })
    }

    fn walls(&self, ray: &Ray, out: &mut Vec<Hit>) {
        self.walls_in(ray, &self.window(ray), out);
    }

    /// The wall crossings of the pieces `window` lets through.
    fn walls_in(&self, ray: &Ray, window: &Window, out: &mut Vec<Hit>) {
        let Some(plane) = self.cut_plane(ray) else {
            return;
        };
        let (nx, c0, nz) = plane;
        let g = |q: P2| nx * q[0] + nz * q[1] + c0;
        let keep = window.keep();
        for (i, pc) in self.pieces.iter().enumerate() {
            if Self::may_cut(pc, g) && window.may_hold(pc) {
                self.piece_hits(ray, plane, i, keep, |h| out.push(h));
            }
        }
    }

    /// Which pieces can hold a wall crossing within the heights (see `Window`).
    fn window(&self, ray: &Ray) -> Window {
        let (o, d) = (ray.origin, ray.dir);
        if !self.conic {
            let (y_lo, y_hi) = self.height_t_range(o, d);
            return Window::Linear {
                o,
                d,
                inv_dd: Self::inv_dd(d),
                y_lo,
                y_hi,
            };
        }
        // Between the heights the ray keeps to one side of the apex (when both heights do),
        // and the central projection of a segment that does not reach y = 0 onto the plane
        // y = 1 (the outline's) is the segment between its ends' projections.
        let [h0, h1] = self.h;
        if d.y == 0.0 || h0 <= 0.0 && h1 >= 0.0 {
            return Window::All;
        }
        let end = |h: f64| {
            let p = o + d * ((h - o.y) / d.y);
            [p.x / h, p.z / h]
        };
        let (a, b) = (end(h0), end(h1));
        let lo = [a[0].min(b[0]), a[1].min(b[1])];
        let hi = [a[0].max(b[0]), a[1].max(b[1])];
        let size = lo
            .iter()
            .chain(hi.iter())
            .fold(0.0f64, |m, v| m.max(v.abs()));
        // NaN or infinite ends (a ray nearly level, far from the heights) prune nothing.
        if !size.is_finite() {
            return Window::All;
        }
        let margin = 1e-6 * size;
        Window::Conic {
            lo: [lo[0] - margin, lo[1] - margin],
            hi: [hi[0] + margin, hi[1] + margin],
        }
    }

    /// Bounds of the `t` any wall crossing of piece `pc` can get from `wall_t` (linear
    /// sweep): the least and the greatest of the linear `t(q)` over the piece's box, widened
    /// by a margin far above the rounding of `wall_t` and of the curve's points (a few ulps
    /// of the terms). `inv_dd` is `1 / (d.x² + d.z²)`, taken once per ray: a product by it
    /// differs from the quotient by an ulp, far inside the margin, and saves the piece its
    /// four divisions.
    fn wall_t_range(pc: &Piece, o: DVec3, d: DVec3, inv_dd: f64) -> (f64, f64) {
        let (x0, x1) = if d.x >= 0.0 {
            (pc.lo[0], pc.hi[0])
        } else {
            (pc.hi[0], pc.lo[0])
        };
        let (z0, z1) = if d.z >= 0.0 {
            (pc.lo[1], pc.hi[1])
        } else {
            (pc.hi[1], pc.lo[1])
        };
        let n0 = (x0 - o.x) * d.x + (z0 - o.z) * d.z;
        let n1 = (x1 - o.x) * d.x + (z1 - o.z) * d.z;
        let size = (pc.hi[0] - pc.lo[0]).max(pc.hi[1] - pc.lo[1]);
        let mag = |x: f64, z: f64| {
            (x.abs() + o.x.abs() + size) * d.x.abs() + (z.abs() + o.z.abs() + size) * d.z.abs()
        };
        (
            (n0 - 1e-9 * (mag(x0, z0) + n0.abs())) * inv_dd,
            (n1 + 1e-9 * (mag(x1, z1) + n1.abs())) * inv_dd,
        )
    }

    /// `1 / (d.x² + d.z²)` for `wall_t_range`, or NaN (which prunes nothing) when the sum
    /// is so small that its reciprocal could overflow where the quotients would not.
    fn inv_dd(d: DVec3) -> f64 {
        let dd = d.x * d.x + d.z * d.z;
        if dd >= 1e-300 {
            1.0 / dd
        } else {
            f64::NAN
        }
    }

    /// The `t` range outside which `wall_t` surely finds the ray beyond the heights: where
    /// `o.y + t d.y` lies in [h0, h1], widened by a margin far above the rounding of both
    /// that sum and the divisions here. Everything when the ray is level and within the
    /// heights, nothing (an empty range) when it is level outside them.
    fn height_t_range(&self, o: DVec3, d: DVec3) -> (f64, f64) {
        self.height_t_ranges(o, d).0
    }

    /// `height_t_range`, and the range narrowed by the same margin: within it `in_heights`
    /// surely accepts `o.y + t d.y` (empty when the margins overlap).
    #[inline(always)]
    fn height_t_ranges(&self, o: DVec3, d: DVec3) -> ((f64, f64), (f64, f64)) {
        if d.y == 0.0 {
            let r = if self.in_heights(o.y) {
                (f64::NEG_INFINITY, f64::INFINITY)
            } else {
                (f64::INFINITY, f64::NEG_INFINITY)
            };
            return (r, r);
        }
        let ta = (self.h[0] - o.y) / d.y;
        let tb = (self.h[1] - o.y) / d.y;
        let margin = 1e-9
            * (ta.abs() + tb.abs() + (o.y.abs() + self.h[0].abs() + self.h[1].abs()) / d.y.abs());
        let (lo, hi) = (ta.min(tb), ta.max(tb));
        ((lo - margin, hi + margin), (lo + margin, hi - margin))
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
        let inv_dd = Self::inv_dd(d);
        // A crossing outside the heights is dropped by `wall_t`: pieces whose `t` range
        // misses the heights' are never refined (a steep ray crosses the heights over a
        // short stretch, and most pieces the cut plane meets lie outside it).
        let (y_lo, y_hi) = self.height_t_range(o, d);
        if let Some((nx, c0, nz)) = plane {
            let g = |q: P2| nx * q[0] + nz * q[1] + c0;
            for (i, pc) in self.pieces.iter().enumerate() {
                if Self::may_cut(pc, g) {
                    let (floor, ceil) = Self::wall_t_range(pc, o, d, inv_dd);
                    if floor > y_hi || ceil < y_lo {
                        continue;
                    }
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
                    // A crossing is offered only within the heights, and kept only before
                    // `tmax` and the best (a tie cannot win: the best came earlier).
                    let keep = Keep {
                        lo: y_lo,
                        hi: y_hi.min(best.map_or(f64::INFINITY, |(b, _)| b.t)),
                        before: tmax,
                        inv_dd,
                    };
                    let i = c.part as usize;
                    self.piece_hits(ray, plane, i, Some(keep), |h| offer(h, c.part, &mut best));
                }
            } else {
                let (h, part) = if c.part == n_pieces {
                    (self.h[0], CAP_LOW)
                } else {
                    (self.h[1], CAP_HIGH)
                };
                if self.on_cap(o + d * c.t, h) {
                    offer(Hit::with_part(c.t, part), c.part, &mut best);
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
            if self.on_cap(o + d * t, h) {
                out.push(Hit::with_part(t, part));
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
                    if self.on_cap(o + d * t, h) {
                        best = Some(Hit::with_part(t, part));
                    }
                }
            }
            return best;
        }
        self.first_linear(ray, tmax, scratch)
    }

    /// Whether `intersect_first` finds a crossing. A conic sweep's `intersect_first` solves
    /// every piece the window lets through before it picks the nearest; a shadow ray stops
    /// at the first piece with a wall crossing before `tmax`, and asks the caps (their
    /// even-odd tests) only when no wall is crossed. A linear sweep does the same without
    /// refining a crossing its bounds already show kept (`any_linear`).
    fn any_hit(&self, ray: &Ray, tmax: f64, _scratch: &mut Vec<Hit>) -> bool {
        if !self.conic {
            return self.any_linear(ray, tmax);
        }
        let window = self.window(ray);
        if let Some(plane) = self.cut_plane(ray) {
            let (nx, c0, nz) = plane;
            let g = |q: P2| nx * q[0] + nz * q[1] + c0;
            let keep = window.keep();
            for (i, pc) in self.pieces.iter().enumerate() {
                if Self::may_cut(pc, g) && window.may_hold(pc) {
                    // `wall_t` gives only `t > EPSILON`, as `intersect_first` keeps.
                    let mut found = false;
                    self.piece_hits(ray, plane, i, keep, |h| found |= h.t < tmax);
                    if found {
                        return true;
                    }
                }
            }
        }
        // No wall crossing: `intersect_first` takes a cap below `tmax` (`t >= tmax` skips it
        // there, NaN `tmax` included).
        self.cap_before(ray, tmax)
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
mod tests;
