//! POV-Ray `sor` (surface of revolution): x² + z² = f(y) about the y axis, f a cubic on each
//! height interval between consecutive points, optionally capped by discs at both ends.
//!
//! With points P[0..n] (radius, height), segment j runs from P[j] to P[j+1] (j = 1..n−3) and
//! takes the values r² at both ends and the slopes d(r²)/dy = 2 r · (central difference of r)
//! there; the first and last points only steer those slopes. Measured against povray with
//! orthographic silhouettes (other slope rules, on r² directly, differ by whole pixels).
//!
//! A ray's squared distance from the axis is quadratic in t and its height linear, so each
//! segment gives a cubic in t, solved on the part of the ray within the segment's heights.

use crate::geom::poly::{eval, eval_with_derivative, roots_in};
use crate::geom::spline2d::{sign_changes_until, P2};
use crate::geom::{Hit, Shape};
use crate::math::{by_coordinates, Aabb, DVec3, Ray, EPSILON};

const CAP_LOW: u32 = u32::MAX - 1;
const CAP_HIGH: u32 = u32::MAX;

/// r² as a cubic in w = (y − y0) / dh, w in [0, 1], in scaled units.
#[derive(Clone, Copy, Debug)]
struct Segment {
    y0: f64,
    dh: f64,
    f: [f64; 4],
    /// r² at the two ends, exactly as written.
    v: [f64; 2],
}

#[derive(Clone, Debug)]
pub struct Sor {
    segments: Vec<Segment>,
    scale: f64,
    open: bool,
    /// Largest radius, scaled.
    radius: f64,
}

/// Checks the points as POV-Ray does: at least four, no negative radius, heights strictly
/// increasing from the second point to the second last.
pub fn check(p: &[P2]) -> Result<(), String> {
    if p.len() < 4 {
        return Err("Surface of revolution must have at least four points.".into());
    }
    if p.iter().any(|q| q[0] < 0.0) {
        return Err("Incorrect point in surface of revolution: a radius is negative.".into());
    }
    if p[1..p.len() - 1]
        .windows(2)
        .any(|w| w[1][1].is_nan() || w[1][1] <= w[0][1])
    {
        return Err(
            "Incorrect point in surface of revolution: heights must increase from the second \
             point to the second last."
                .into(),
        );
    }
    Ok(())
}

impl Sor {
    /// Points as checked by [`check`]; others give an empty shape rather than a panic.
    pub fn new(p: &[P2], open: bool) -> Sor {
        let n = p.len();
        let mut scale: f64 = 0.0;
        for q in p.iter().take(n.saturating_sub(1)).skip(1) {
            scale = scale.max(q[0].abs()).max(q[1].abs());
        }
        let scale = if scale > 0.0 && scale.is_finite() {
            scale
        } else {
            1.0
        };
        let k = 1.0 / scale;
        let p: Vec<P2> = p.iter().map(|q| [q[0] * k, q[1] * k]).collect();
        let mut segments = Vec::new();
        if check(&p).is_ok() {
            // d(r²)/dy at point i from its neighbours.
            let slope = |i: usize| {
                let dh = p[i + 1][1] - p[i - 1][1];
                if dh == 0.0 {
                    0.0
                } else {
                    2.0 * p[i][0] * (p[i + 1][0] - p[i - 1][0]) / dh
                }
            };
            for j in 1..n - 2 {
                let (y0, dh) = (p[j][1], p[j + 1][1] - p[j][1]);
                let (v0, v1) = (p[j][0] * p[j][0], p[j + 1][0] * p[j + 1][0]);
                let (m0, m1) = (slope(j) * dh, slope(j + 1) * dh);
                let f = [
                    v0,
                    m0,
                    3.0 * (v1 - v0) - 2.0 * m0 - m1,
                    2.0 * (v0 - v1) + m0 + m1,
                ];
                segments.push(Segment {
                    y0,
                    dh,
                    f,
                    v: [v0, v1],
                });
            }
        }
        let mut r2: f64 = 0.0;
        for s in &segments {
            let d = [s.f[1], 2.0 * s.f[2], 3.0 * s.f[3]];
            for w in roots_in(&d, 0.0, 1.0).iter().chain(&[0.0, 1.0]) {
                r2 = r2.max(eval(&s.f, *w));
            }
        }
        Sor {
            segments,
            scale,
            open,
            radius: r2.sqrt(),
        }
    }

    fn heights(&self) -> Option<[f64; 2]> {
        let (a, b) = (self.segments.first()?, self.segments.last()?);
        Some([a.y0, b.y0 + b.dh])
    }

    /// Hands each crossing (`t > EPSILON`) to `found`, segment by segment, then the caps;
    /// once `found` has said stop (true), no further segment or cap is solved. Before each
    /// Newton step of a segment's root, `sure(ta, tb)` sees the least and the greatest `t`
    /// the root can be handed with (the ends of its bracket taken to the ray's `t` by the
    /// same operations: rounding is monotone, so the root's `t` lies between them); true
    /// there stops as `found` would have, without the root's last bits. Says whether it
    /// stopped.
    ///
    /// With `rev` the segments are taken from the last to the first (the order along a
    /// descending ray). `skip(t)` is asked of each segment the stretch meets, before its
    /// expansion, with a `t` no crossing of the segment can be handed below (its stretch's
    /// near end taken to the ray's `t` by `found`'s operations); true passes the segment by.
    fn each_hit(
        &self,
        ray: &Ray,
        rev: bool,
        mut skip: impl FnMut(f64) -> bool,
        mut sure: impl FnMut(f64, f64) -> bool,
        mut found: impl FnMut(Hit) -> bool,
    ) -> bool {
        let Some([ylo, yhi]) = self.heights() else {
            return false;
        };
        // Each coordinate by its own 8-byte load: the caller's local ray was just stored as an
        // x-y pair and z, which a 16-byte y-z load cannot be forwarded from (small31 saw it
        // in the disassembly, as in the torus's set-up).
        let (dir, origin) = (by_coordinates(&ray.dir), by_coordinates(&ray.origin));
        let len = dir.length();
        if !(len > 0.0 && len.is_finite()) {
            return false;
        }
        let u = dir / len;
        let o = origin / self.scale;
        // The part of the ray inside the bounding cylinder.
        let a = u.x * u.x + u.z * u.z;
        let (b, c) = (o.x * u.x + o.z * u.z, o.x * o.x + o.z * o.z);
        let rr = self.radius * self.radius;
        let margin = 1e-9;
        let (mut lo, mut hi) = (EPSILON * len / self.scale, f64::INFINITY);
        if a > 0.0 {
            let disc = b * b - a * (c - rr);
            if disc < 0.0 {
                return false;
            }
            let h = disc.sqrt();
            lo = lo.max((-b - h) / a - margin);
            hi = hi.min((-b + h) / a + margin);
        } else if c > rr {
            return false;
        }
        if u.y != 0.0 {
            let (t0, t1) = ((ylo - o.y) / u.y, (yhi - o.y) / u.y);
            lo = lo.max(t0.min(t1) - margin);
            hi = hi.min(t0.max(t1) + margin);
        } else if o.y < ylo || o.y > yhi {
            return false;
        }
        if lo.is_nan() || hi.is_nan() || lo > hi {
            return false;
        }
        // Solve from the entry point, so the coefficients do not depend on a far origin.
        let o = o + u * lo;
        let c = o.x * o.x + o.z * o.z;
        let b = o.x * u.x + o.z * u.z;
        let (span, back) = (hi - lo, self.scale / len);
        let q = |t: f64| a * t * t + 2.0 * b * t + c;
        // Whether `found` said stop.
        let mut push = |t: f64, part: u32| {
            let t = (t + lo) * back;
            t > EPSILON && found(Hit::with_part(t, part))
        };
        let last = self.segments.len() - 1;
        // The stretch's heights, to skip the segments wholly above or below them before the
        // divisions that put their ends on the ray.
        let (y_a, y_b) = (o.y, o.y + u.y * span);
        let (y_bot, y_top) = (y_a.min(y_b), y_a.max(y_b));
        for k in 0..=last {
            let j = if rev { last - k } else { k };
            let s = &self.segments[j];
            let (mut t_lo, mut t_hi, mut f_lo, mut f_hi);
            if u.y == 0.0 {
                let w0 = (o.y - s.y0) / s.dh;
                if !(0.0..=1.0).contains(&w0) || (w0 == 1.0 && j != last) {
                    continue;
                }
                (t_lo, t_hi) = (0.0, span);
                f_lo = f64::NAN;
                f_hi = f64::NAN;
            } else {
                // Clear of the stretch by a margin far above the rounding of `y_top`, `y_bot`
                // and of the ends' quotients below: both ends' `t` then lie on one side of
                // [0, span], and the test after them would skip the segment all the same.
                let m = 1e-9 * (y_top.abs() + y_bot.abs() + s.y0.abs() + s.dh);
                if s.y0 > y_top + m || s.y0 + s.dh < y_bot - m {
                    continue;
                }
                // Segment ends in t; their values come from the exact end radii.
                let (ta, tb) = ((s.y0 - o.y) / u.y, (s.y0 + s.dh - o.y) / u.y);
                let (fa, fb) = (s.v[0] - q(ta), s.v[1] - q(tb));
                (t_lo, f_lo, t_hi, f_hi) = if ta <= tb {
                    (ta, fa, tb, fb)
                } else {
                    (tb, fb, ta, fa)
                };
            }
            if t_lo < 0.0 {
                (t_lo, f_lo) = (0.0, f64::NAN);
            }
            if t_hi > span {
                (t_hi, f_hi) = (span, f64::NAN);
            }
            if t_lo > t_hi || skip((t_lo + lo) * back) {
                continue;
            }
            // f(w(t)) − q(t) as a polynomial in t, the height as w = w0 + w1 t: divided and
            // expanded only once the stretch is known to meet the segment's band (most
            // segments a ray passes are skipped above).
            let (w0, w1) = ((o.y - s.y0) / s.dh, u.y / s.dh);
            let mut p = [0.0; 4];
            let mut pw = [1.0, 0.0, 0.0, 0.0];
            for k in 0..4 {
                for i in 0..4 {
                    p[i] += s.f[k] * pw[i];
                }
                // pw *= (w0 + w1 t)
                let mut next = [0.0; 4];
                for i in 0..4 {
                    next[i] += pw[i] * w0;
                    if i + 1 < 4 {
                        next[i + 1] += pw[i] * w1;
                    }
                }
                pw = next;
            }
            p[0] -= c;
            p[1] -= 2.0 * b;
            p[2] -= a;
            let f_lo = if f_lo.is_nan() { eval(&p, t_lo) } else { f_lo };
            let f_hi = if f_hi.is_nan() { eval(&p, t_hi) } else { f_hi };
            let mut stop = false;
            let settle = |ta: f64, tb: f64| sure((ta + lo) * back, (tb + lo) * back).then_some(());
            sign_changes_until(&p, t_lo, t_hi, f_lo, f_hi, settle, |r| {
                stop |= match r {
                    Ok(t) => push(t, j as u32),
                    Err(()) => true,
                }
            });
            if stop {
                return true;
            }
        }
        if !self.open && u.y != 0.0 {
            let (first, end) = (&self.segments[0], &self.segments[last]);
            for (y, r2, part) in [(ylo, first.v[0], CAP_LOW), (yhi, end.v[1], CAP_HIGH)] {
                let t = (y - o.y) / u.y;
                if t >= 0.0 && q(t) <= r2 && push(t, part) {
                    return true;
                }
            }
        }
        false
    }
}

impl Shape for Sor {
    fn bounds(&self) -> Aabb {
        let Some([ylo, yhi]) = self.heights() else {
            return Aabb::EMPTY;
        };
        let (r, k) = (self.radius * self.scale, self.scale);
        Aabb::new(DVec3::new(-r, ylo * k, -r), DVec3::new(r, yhi * k, r))
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        self.each_hit(
            ray,
            false,
            |_| false,
            |_, _| false,
            |h| {
                out.push(h);
                false
            },
        );
    }

    /// Whether the default `intersect_first` finds a crossing (one listed with
    /// `EPSILON < t < tmax`): a shadow ray stops at the segment holding the first such, where
    /// the listing solved every segment the ray's stretch meets, and a root whose bracket
    /// already lies within (EPSILON, tmax) is not refined to its last bits.
    fn any_hit(&self, ray: &Ray, tmax: f64, _scratch: &mut Vec<Hit>) -> bool {
        let sure = |ta: f64, tb: f64| ta > EPSILON && tb < tmax;
        self.each_hit(ray, false, |_| false, sure, |h| h.t < tmax)
    }

    /// The default's crossing (the first least `t` with `EPSILON < t < tmax` in
    /// `intersect_all`'s order: segments by index, each one's crossings by `t`, then the low
    /// and the high cap), with the segments taken along the ray and those whose crossings
    /// are all past the best (or not before `tmax`) neither expanded nor solved. A crossing
    /// replaces the best when its `t` is less, or equal and from an earlier segment (a part
    /// number less: the caps' come after every segment's).
    fn intersect_first(&self, ray: &Ray, tmax: f64, _scratch: &mut Vec<Hit>) -> Option<Hit> {
        let best = std::cell::Cell::new(None::<Hit>);
        // Past the best, or not before `tmax` (NaN included: the default keeps none then).
        let before = |t: f64| t.partial_cmp(&tmax) == Some(std::cmp::Ordering::Less);
        let past = |t: f64| best.get().is_some_and(|b| t > b.t) || !before(t);
        self.each_hit(
            ray,
            ray.dir.y < 0.0,
            past,
            |_, _| false,
            |h| {
                let better = |b: Hit| h.t < b.t || (h.t == b.t && h.part < b.part);
                if h.t < tmax && best.get().is_none_or(better) {
                    best.set(Some(h));
                }
                false
            },
        );
        best.get()
    }

    fn inside(&self, p: DVec3) -> bool {
        let q = p / self.scale;
        let r2 = q.x * q.x + q.z * q.z;
        self.segments.iter().any(|s| {
            let w = (q.y - s.y0) / s.dh;
            (0.0..=1.0).contains(&w) && r2 < eval(&s.f, w)
        })
    }

    fn normal(&self, p: DVec3, hit: &Hit) -> DVec3 {
        match hit.part {
            CAP_LOW => return DVec3::NEG_Y,
            CAP_HIGH => return DVec3::Y,
            _ => {}
        }
        let Some(s) = self.segments.get(hit.part as usize) else {
            return DVec3::Y;
        };
        let q = p / self.scale;
        let (_, df) = eval_with_derivative(&s.f, (q.y - s.y0) / s.dh);
        // Half the gradient of x² + z² − f(y).
        DVec3::new(q.x, -0.5 * df / s.dh, q.z)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ts(s: &Sor, r: &Ray) -> Vec<(f64, u32)> {
        let mut v = Vec::new();
        s.intersect_all(r, &mut v);
        let mut v: Vec<(f64, u32)> = v.iter().map(|h| (h.t, h.part)).collect();
        v.sort_by(|a, b| a.0.total_cmp(&b.0));
        v
    }

    #[test]
    fn cylinder_from_constant_radius() {
        let p = [[1.0, -1.0], [1.0, 0.0], [1.0, 2.0], [1.0, 3.0]];
        check(&p).unwrap();
        let s = Sor::new(&p, false);
        let r = Ray::new(DVec3::new(-5.0, 1.0, 0.0), DVec3::X);
        let t = ts(&s, &r);
        assert!(
            t.len() == 2 && (t[0].0 - 4.0).abs() < 1e-12 && (t[1].0 - 6.0).abs() < 1e-12,
            "{t:?}"
        );
        let r = Ray::new(DVec3::new(0.5, 5.0, 0.0), DVec3::NEG_Y * 0.5);
        assert_eq!(ts(&s, &r), vec![(6.0, CAP_HIGH), (10.0, CAP_LOW)]);
        assert!(ts(&Sor::new(&p, true), &r).is_empty());
        assert!(s.inside(DVec3::new(0.5, 1.0, 0.5)) && !s.inside(DVec3::new(0.5, 2.5, 0.0)));
        let n = s.normal(DVec3::new(0.0, 1.0, -1.0), &Hit::with_part(0.0, 0));
        assert!((n.normalize() - DVec3::NEG_Z).length() < 1e-12);
        assert_eq!(
            s.bounds(),
            Aabb::new(DVec3::new(-1.0, 0.0, -1.0), DVec3::new(1.0, 2.0, 1.0))
        );
    }

    /// The manual's vase, shared by the profile and the shadow-test tests.
    const VASE: [[f64; 2]; 7] = [
        [0.0, 0.0],
        [0.118143, 0.0],
        [0.620253, 0.540084],
        [0.210970, 0.827004],
        [0.194093, 0.962025],
        [0.286920, 1.0],
        [0.468354, 1.033755],
    ];

    #[test]
    fn vase_matches_its_profile() {
        // The manual's vase; a horizontal ray at each height meets x² = f(y).
        let s = Sor::new(&VASE, true);
        for k in 1..50 {
            let y = k as f64 / 50.0;
            for dy in [0.0, 1e-7, 1e-3] {
                let r = Ray::new(DVec3::new(-3.0, y, 0.0), DVec3::new(1.0, dy, 0.0));
                let t = ts(&s, &r);
                assert_eq!(t.len(), 2, "y {y} dy {dy}: {t:?}");
                if dy == 0.0 {
                    // Exits where it entered, mirrored about the axis.
                    let (x0, x1) = (t[0].0 - 3.0, t[1].0 - 3.0);
                    assert!((x0 + x1).abs() < 1e-12, "y {y}: {x0} {x1}");
                    let w = s
                        .segments
                        .iter()
                        .find(|g| y >= g.y0 && y <= g.y0 + g.dh)
                        .unwrap();
                    let f = eval(&w.f, (y - w.y0) / w.dh);
                    assert!((x1 * x1 - f).abs() < 1e-12);
                }
            }
        }
        assert!(check(&VASE[..3]).unwrap_err().contains("four"));
        assert!(check(&[[0.0, 0.0], [1.0, 1.0], [1.0, 0.5], [1.0, 3.0]]).is_err());
        assert!(check(&[[0.0, 0.0], [-1.0, 1.0], [1.0, 2.0], [1.0, 3.0]]).is_err());
        // Control points may lie anywhere in height.
        check(&[[0.0, 5.0], [1.0, 1.0], [1.0, 2.0], [1.0, 1.5]]).unwrap();
    }

    /// A ray from near the vase aimed into it, level when `level`.
    fn vase_ray(rng: &mut crate::geom::test_rng::Lcg, level: bool) -> Ray {
        let o = DVec3::new(0.0, 0.5, 0.0) + rng.vec(4.0);
        let mut d = DVec3::new(0.0, 0.5, 0.0) + rng.vec(0.8) - o;
        if level {
            d.y = 0.0;
        }
        Ray::new(o, d)
    }

    /// `any_hit` (which stops at the first segment holding a crossing before `tmax`) says
    /// whether the default `intersect_first` finds one: open and closed vases, rays from
    /// outside, from a crossing and level ones, `tmax` before, at, past and beyond it.
    #[test]
    fn any_hit_is_whether_there_is_a_first() {
        let mut rng = crate::geom::test_rng::Lcg(29);
        let mut seen = [0; 2];
        for open in [false, true] {
            let s = Sor::new(&VASE, open);
            for k in 0..4000 {
                let ray = vase_ray(&mut rng, k % 10 == 0);
                let first = s.intersect_first(&ray, f64::INFINITY, &mut Vec::new());
                let near = first.map_or(1.0, |h| h.t);
                let on = Ray::new(ray.at(near), rng.vec(1.0));
                let up = f64::from_bits(near.to_bits() + 1);
                for r in [ray, on] {
                    for tmax in [
                        f64::INFINITY,
                        near,
                        up,
                        near * 0.5,
                        rng.next() * 3.0,
                        f64::NAN,
                    ] {
                        let want = s.intersect_first(&r, tmax, &mut Vec::new()).is_some();
                        seen[want as usize] += 1;
                        assert_eq!(s.any_hit(&r, tmax, &mut Vec::new()), want, "{r:?} {tmax}");
                    }
                }
            }
        }
        assert!(seen[0] > 5000 && seen[1] > 5000, "{seen:?}");
    }

    /// `intersect_first` (segments along the ray, those past the best left unsolved) gives
    /// the listing's first least crossing to the bit: rising, falling and level rays, from
    /// outside and from a crossing, `tmax` at, an ulp past and before it, well before, NaN.
    #[test]
    fn nearest_is_the_listings() {
        let mut rng = crate::geom::test_rng::Lcg(31);
        let mut n_hits = 0;
        let key = |h: Option<Hit>| h.map(|h| (h.t.to_bits(), h.part));
        for open in [false, true] {
            let s = Sor::new(&VASE, open);
            for k in 0..4000 {
                let ray = vase_ray(&mut rng, k % 10 == 0);
                let first = crate::geom::test_rng::nearest_of_all(&s, &ray, f64::INFINITY);
                n_hits += first.is_some() as usize;
                let near = first.map_or(1.0, |h| h.t);
                let on = Ray::new(ray.at(near), rng.vec(1.0));
                let up = f64::from_bits(near.to_bits() + 1);
                let down = f64::from_bits(near.to_bits() - 1);
                for r in [ray, on] {
                    for tmax in [f64::INFINITY, near, up, down, near * 0.5, f64::NAN] {
                        let want = crate::geom::test_rng::nearest_of_all(&s, &r, tmax);
                        let got = s.intersect_first(&r, tmax, &mut Vec::new());
                        assert_eq!(key(got), key(want), "{r:?} {tmax}");
                    }
                }
            }
        }
        assert!(n_hits > 3000, "{n_hits}");
    }
}
