//! POV-Ray `sphere_sweep`: the space a sphere of varying radius fills while its centre moves
//! along a spline (linear, uniform cubic B-spline, or Catmull-Rom through the spheres).
//!
//! The solid is the union of the balls B(C(s), R(s)). For a ray o + t·u (u unit) ball s
//! covers t1(s) ≤ t ≤ t2(s) with t = −β ∓ √Δ, β = u·(o − C), Δ = β² − |o − C|² + R², which
//! is a degree-6 polynomial for cubic pieces. Over an interval of s where Δ ≥ 0 those spans
//! overlap into one, from min t1 to max t2. The extremes lie at the interval's ends or where
//! t1' or t2' vanish, that is where 4 β'² Δ − Δ'² = 0 (degree 10): polynomial roots, no
//! marching. The spans of all pieces are merged and their ends are the crossings; the normal
//! at a crossing points away from the centre of the ball that reached it.

use crate::geom::poly::{eval, roots_in};
use crate::geom::{Hit, Shape};
use crate::math::{Aabb, DVec3, Ray, EPSILON};

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SweepKind {
    Linear,
    BSpline,
    CatmullRom,
}

/// One piece: centre and radius as cubics in s ∈ [0, 1] (scaled units).
#[derive(Clone, Copy, Debug)]
struct Piece {
    c: [[f64; 4]; 3],
    r: [f64; 4],
    bounds: Aabb,
}

#[derive(Clone, Debug)]
pub struct SphereSweep {
    pieces: Vec<Piece>,
    scale: f64,
    bounds: Aabb,
}

fn mul<const A: usize, const B: usize>(a: &[f64; A], b: &[f64; B]) -> [f64; 11] {
    let mut c = [0.0; 11];
    for i in 0..A {
        for j in 0..B {
            c[i + j] += a[i] * b[j];
        }
    }
    c
}

fn deriv(c: &[f64; 11]) -> [f64; 11] {
    let mut d = [0.0; 11];
    for i in 1..11 {
        d[i - 1] = c[i] * i as f64;
    }
    d
}

impl Piece {
    /// From 4-D control values (x, y, z, r) in power-basis coefficients.
    fn new(k: [[f64; 4]; 4]) -> Piece {
        let c = [k[0], k[1], k[2]];
        let r = k[3];
        // The Bézier control points of each cubic bound it.
        let hull = |c: [f64; 4]| {
            let b = [
                c[0],
                c[0] + c[1] / 3.0,
                c[0] + (2.0 * c[1] + c[2]) / 3.0,
                c[0] + c[1] + c[2] + c[3],
            ];
            b.iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
                    (lo.min(v), hi.max(v))
                })
        };
        let (rl, rh) = hull(r);
        let rmax = rl.abs().max(rh.abs());
        let (x, y, z) = (hull(c[0]), hull(c[1]), hull(c[2]));
        let bounds = Aabb::new(
            DVec3::new(x.0, y.0, z.0) - rmax,
            DVec3::new(x.1, y.1, z.1) + rmax,
        );
        Piece { c, r, bounds }
    }

    fn centre(&self, s: f64) -> DVec3 {
        DVec3::new(
            eval(&self.c[0], s),
            eval(&self.c[1], s),
            eval(&self.c[2], s),
        )
    }

    /// Calls `span(t_in, s_in, t_out, s_out)` for each stretch of the ray this piece covers.
    fn spans(&self, o: DVec3, u: DVec3, mut span: impl FnMut(f64, f64, f64, f64)) {
        let mut w = self.c.map(|row| row.map(|x| -x));
        for (i, wi) in w.iter_mut().enumerate() {
            wi[0] += o[i];
        }
        let mut beta = [0.0; 4];
        for k in 0..4 {
            beta[k] = u.x * w[0][k] + u.y * w[1][k] + u.z * w[2][k];
        }
        let b2 = mul(&beta, &beta);
        let r2 = mul(&self.r, &self.r);
        let mut disc = [0.0; 11];
        for k in 0..11 {
            disc[k] = b2[k] + r2[k];
        }
        for wi in &w {
            let sq = mul(wi, wi);
            for k in 0..11 {
                disc[k] -= sq[k];
            }
        }
        // Where Δ ≥ 0: cut [0, 1] at Δ's roots.
        let cuts = roots_in(&disc[..7], 0.0, 1.0);
        let mut ends = [0.0; 18];
        let mut n = 0;
        ends[n] = 0.0;
        n += 1;
        for &x in cuts.iter() {
            if x > 0.0 && x < 1.0 && n < 17 {
                ends[n] = x;
                n += 1;
            }
        }
        ends[n] = 1.0;
        n += 1;
        let db = [beta[1], 2.0 * beta[2], 3.0 * beta[3]];
        let dd = deriv(&disc);
        let e = {
            let a = mul(&[db[0], db[1], db[2]], &[db[0], db[1], db[2]]);
            let mut e = [0.0; 17];
            for i in 0..5 {
                for j in 0..7 {
                    e[i + j] += 4.0 * a[i] * disc[j];
                }
            }
            for i in 0..6 {
                for j in 0..6 {
                    e[i + j] -= dd[i] * dd[j];
                }
            }
            e
        };
        for k in 0..n - 1 {
            let (sa, sb) = (ends[k], ends[k + 1]);
            let mid = 0.5 * (sa + sb);
            if eval(&disc[..7], mid) < 0.0 {
                continue;
            }
            let mut best = (f64::INFINITY, sa, f64::NEG_INFINITY, sa);
            let mut try_s = |s: f64| {
                let (b, d) = (eval(&beta, s), eval(&disc[..7], s).max(0.0).sqrt());
                if -b - d < best.0 {
                    (best.0, best.1) = (-b - d, s);
                }
                if -b + d > best.2 {
                    (best.2, best.3) = (-b + d, s);
                }
            };
            try_s(sa);
            try_s(sb);
            for &s in roots_in(&e[..11], sa, sb).iter() {
                try_s(s);
            }
            // Where β' and Δ' vanish together the extremum is a double root of the product,
            // which sign changes miss (a ray square to a straight piece); t1 and t2 are flat
            // there, so the roots of either factor are as good as the exact point.
            for &s in roots_in(&dd[..6], sa, sb).iter() {
                try_s(s);
            }
            for &s in roots_in(&db, sa, sb).iter() {
                try_s(s);
            }
            span(best.0, best.1, best.2, best.3);
        }
    }
}

impl SphereSweep {
    /// Spheres as (centre, radius); too few for the kind give an empty shape.
    pub fn new(kind: SweepKind, spheres: &[(DVec3, f64)]) -> SphereSweep {
        let v: Vec<[f64; 4]> = spheres.iter().map(|(c, r)| [c.x, c.y, c.z, *r]).collect();
        let mut raw = Vec::new();
        let n = v.len();
        let coeff = |f: &dyn Fn(usize) -> [f64; 4]| [f(0), f(1), f(2), f(3)];
        match kind {
            SweepKind::Linear => {
                for i in 1..n {
                    let (a, b) = (v[i - 1], v[i]);
                    raw.push(coeff(&|j| [a[j], b[j] - a[j], 0.0, 0.0]));
                }
            }
            SweepKind::BSpline => {
                for i in 3..n {
                    let (p0, p1, p2, p3) = (v[i - 3], v[i - 2], v[i - 1], v[i]);
                    raw.push(coeff(&|j| {
                        [
                            (p0[j] + 4.0 * p1[j] + p2[j]) / 6.0,
                            0.5 * (p2[j] - p0[j]),
                            0.5 * (p0[j] - 2.0 * p1[j] + p2[j]),
                            (-p0[j] + 3.0 * p1[j] - 3.0 * p2[j] + p3[j]) / 6.0,
                        ]
                    }));
                }
            }
            SweepKind::CatmullRom => {
                for i in 3..n {
                    let (p0, p1, p2, p3) = (v[i - 3], v[i - 2], v[i - 1], v[i]);
                    raw.push(coeff(&|j| {
                        let (d0, d1) = (0.5 * (p2[j] - p0[j]), 0.5 * (p3[j] - p1[j]));
                        [
                            p1[j],
                            d0,
                            3.0 * (p2[j] - p1[j]) - 2.0 * d0 - d1,
                            2.0 * (p1[j] - p2[j]) + d0 + d1,
                        ]
                    }));
                }
            }
        }
        let mut scale: f64 = 0.0;
        for k in &raw {
            for row in k {
                scale = row.iter().fold(scale, |m, x| m.max(x.abs()));
            }
        }
        let scale = if scale > 0.0 && scale.is_finite() {
            scale
        } else {
            1.0
        };
        let pieces: Vec<Piece> = raw
            .iter()
            .map(|k| Piece::new(k.map(|row| row.map(|x| x / scale))))
            .collect();
        let bounds = pieces.iter().fold(Aabb::EMPTY, |b, p| b.union(&p.bounds));
        SphereSweep {
            pieces,
            scale,
            bounds,
        }
    }
}

impl Shape for SphereSweep {
    fn bounds(&self) -> Aabb {
        if self.pieces.is_empty() {
            return Aabb::EMPTY;
        }
        Aabb::new(self.bounds.min * self.scale, self.bounds.max * self.scale)
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        let len = ray.dir.length();
        if !(len > 0.0 && len.is_finite()) || self.pieces.is_empty() {
            return;
        }
        let u = ray.dir / len;
        let o = ray.origin / self.scale;
        let inv = u.recip();
        let Some((t0, _)) = self.bounds.hit(o, inv, f64::INFINITY) else {
            return;
        };
        // Solve from the entry point so a far origin costs no digits.
        let shift = t0.max(0.0);
        let o2 = o + u * shift;
        let mut spans: Vec<(f64, Hit, f64, Hit)> = Vec::new();
        for (i, pc) in self.pieces.iter().enumerate() {
            if pc.bounds.hit(o2, inv, f64::INFINITY).is_none() {
                continue;
            }
            pc.spans(o2, u, |ta, sa, tb, sb| {
                let hit = |t: f64, s: f64| Hit {
                    t: (t + shift) * self.scale / len,
                    part: i as u32,
                    uv: [s, 0.0],
                };
                spans.push((ta, hit(ta, sa), tb, hit(tb, sb)));
            });
        }
        // The union of the spans: only its ends are on the surface.
        spans.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut cur: Option<(Hit, f64, Hit)> = None;
        let mut emit = |h: Hit| {
            if h.t > EPSILON {
                out.push(h);
            }
        };
        for (ta, ha, tb, hb) in spans {
            match &mut cur {
                Some((_, end, end_hit)) if ta <= *end => {
                    if tb > *end {
                        (*end, *end_hit) = (tb, hb);
                    }
                }
                _ => {
                    if let Some((a, _, b)) = cur.take() {
                        emit(a);
                        emit(b);
                    }
                    cur = Some((ha, tb, hb));
                }
            }
        }
        if let Some((a, _, b)) = cur {
            emit(a);
            emit(b);
        }
    }

    fn inside(&self, p: DVec3) -> bool {
        let q = p / self.scale;
        self.pieces.iter().any(|pc| {
            if !pc.bounds.contains(q) {
                return false;
            }
            // min over s of |q − C(s)|² − R(s)²: at an end or where its derivative vanishes.
            let mut f = [0.0; 11];
            let r2 = mul(&pc.r, &pc.r);
            for i in 0..3 {
                let mut w = pc.c[i].map(|x| -x);
                w[0] += q[i];
                let sq = mul(&w, &w);
                for k in 0..11 {
                    f[k] += sq[k];
                }
            }
            for k in 0..11 {
                f[k] -= r2[k];
            }
            let d = deriv(&f);
            roots_in(&d[..6], 0.0, 1.0)
                .iter()
                .chain(&[0.0, 1.0])
                .any(|&s| eval(&f[..7], s) < 0.0)
        })
    }

    fn normal(&self, p: DVec3, hit: &Hit) -> DVec3 {
        match self.pieces.get(hit.part as usize) {
            Some(pc) => p / self.scale - pc.centre(hit.uv[0]),
            None => DVec3::Y,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ts(s: &SphereSweep, r: &Ray) -> Vec<f64> {
        let mut v = Vec::new();
        s.intersect_all(r, &mut v);
        let mut t: Vec<f64> = v.iter().map(|h| h.t).collect();
        t.sort_by(f64::total_cmp);
        t
    }

    #[test]
    fn linear_capsule() {
        let s = SphereSweep::new(
            SweepKind::Linear,
            &[(DVec3::ZERO, 1.0), (DVec3::new(4.0, 0.0, 0.0), 1.0)],
        );
        // Along the axis: the two end caps.
        let t = ts(&s, &Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X));
        assert!(t.len() == 2 && (t[0] - 4.0).abs() < 1e-12 && (t[1] - 10.0).abs() < 1e-12);
        // Across the tube.
        let r = Ray::new(DVec3::new(2.0, -5.0, 0.5), DVec3::Y * 2.0);
        let t = ts(&s, &r);
        let h = 0.75f64.sqrt();
        assert!(
            t.len() == 2 && (t[0] - (5.0 - h) / 2.0).abs() < 1e-12,
            "{t:?}"
        );
        let mut v = Vec::new();
        s.intersect_all(&r, &mut v);
        let n = s.normal(r.at(v[0].t), &v[0]).normalize();
        assert!((n - DVec3::new(0.0, -h, 0.5)).length() < 1e-9, "{n}");
        assert!(s.inside(DVec3::new(3.0, 0.5, 0.5)) && !s.inside(DVec3::new(2.0, 1.1, 0.0)));
        assert!(s.inside(DVec3::new(4.9, 0.0, 0.0)) && !s.inside(DVec3::new(5.1, 0.0, 0.0)));
        // From inside only the exit.
        let t = ts(&s, &Ray::new(DVec3::new(1.0, 0.0, 0.0), DVec3::Y));
        assert!(t.len() == 1 && (t[0] - 1.0).abs() < 1e-12);
    }

    #[test]
    fn cone_frustum_between_spheres() {
        // Radii 1 and 2 at distance 10: the tangent cone's silhouette, compared with sampled
        // balls along the axis.
        let s = SphereSweep::new(
            SweepKind::Linear,
            &[(DVec3::ZERO, 1.0), (DVec3::new(10.0, 0.0, 0.0), 2.0)],
        );
        for k in 0..40 {
            let x = -1.5 + 13.0 * k as f64 / 40.0;
            let r = Ray::new(DVec3::new(x, -5.0, 0.3), DVec3::Y);
            let t = ts(&s, &r);
            let mut lo = f64::INFINITY;
            for i in 0..=20000 {
                let sa = i as f64 / 20000.0;
                let (cx, rr) = (10.0 * sa, 1.0 + sa);
                let d2 = rr * rr - (x - cx) * (x - cx) - 0.09;
                if d2 >= 0.0 {
                    lo = lo.min(5.0 - d2.sqrt());
                }
            }
            if lo.is_finite() {
                assert!((t[0] - lo).abs() < 1e-6, "x {x}: {t:?} vs {lo}");
            } else {
                assert!(t.is_empty(), "x {x}: {t:?}");
            }
        }
    }

    #[test]
    fn curved_sweeps_are_closed_tubes() {
        let pts = [
            (DVec3::new(-3.0, 0.0, 0.0), 0.5),
            (DVec3::new(-1.0, 2.0, 0.0), 0.7),
            (DVec3::new(1.0, -1.0, 0.0), 0.4),
            (DVec3::new(3.0, 1.0, 0.5), 0.6),
            (DVec3::new(4.0, 0.0, 0.0), 0.5),
        ];
        for kind in [SweepKind::BSpline, SweepKind::CatmullRom] {
            let s = SphereSweep::new(kind, &pts);
            let mut hits = 0;
            for k in 0..200 {
                let x = -4.0 + 8.0 * k as f64 / 200.0;
                let r = Ray::new(DVec3::new(x, 0.2, -5.0), DVec3::Z);
                let t = ts(&s, &r);
                assert!(t.len().is_multiple_of(2), "{kind:?} x {x}: {t:?}");
                hits += t.len();
                if t.len() == 2 {
                    assert!(s.inside(r.at(0.5 * (t[0] + t[1]))));
                    assert!(!s.inside(r.at(t[0] - 1e-6)));
                }
            }
            assert!(hits > 0);
        }
    }
}
