//! POV-Ray `sphere { center, radius }`.

use crate::geom::{Hit, Shape};
use crate::math::{Aabb, DVec3, Ray, EPSILON};

#[derive(Clone, Copy, Debug)]
pub struct Sphere {
    center: DVec3,
    radius: f64,
    radius2: f64,
}

impl Sphere {
    /// A zero or non-finite radius gives a sphere nothing hits; a negative one is taken by its
    /// magnitude, since only its square enters the surface equation.
    pub fn new(center: DVec3, radius: f64) -> Sphere {
        let radius = if radius.is_finite() {
            radius.abs()
        } else {
            0.0
        };
        Sphere {
            center,
            radius,
            radius2: radius * radius,
        }
    }

    /// Whether the ray starts outside the sphere (`c > 0`) and heads away from its centre
    /// (`b > 0`): then the roots are both at or below zero (or NaN), which no caller keeps
    /// (they keep `t > EPSILON`), so the division, square root and two more divisions of
    /// `quadratic` and `roots` can be skipped. With `b > 0`, `q = -(b + sqrt(disc))` is below
    /// zero (its sum rounds to at least `b`), so `q / a` (`a > 0`) and `c / q` (`c > 0`) are
    /// both at most zero, or NaN where `a` or `c` is infinite; a NaN `b` or `c` fails the
    /// test and takes the full path. `b` and `c` are `quadratic`'s own expressions. Origins
    /// on the surface (`c` within a millionth of r² of zero: rays leaving this sphere) take
    /// the full path too: there the sign of `c` is rounding noise, and a branch on it would
    /// mispredict half the time.
    #[inline(always)]
    fn behind(&self, ray: &Ray) -> bool {
        let oc = ray.origin - self.center;
        oc.dot(ray.dir) > 0.0 && oc.length_squared() - self.radius2 > self.radius2 * 1e-6
    }

    /// Both crossings (t0 <= t1) of the full line, or None.
    #[inline]
    fn roots(&self, ray: &Ray) -> Option<(f64, f64)> {
        self.quadratic(ray).map(|q| q.roots())
    }

    /// The crossing equation's parts, or None when the line misses (or the sphere or the
    /// direction is empty).
    #[inline(always)]
    fn quadratic(&self, ray: &Ray) -> Option<Quadratic> {
        if self.radius == 0.0 {
            return None;
        }
        let oc = ray.origin - self.center;
        let a = ray.dir.length_squared();
        let b = oc.dot(ray.dir);
        // Computing c through the perpendicular distance of the line to the centre instead of
        // |oc|² - r² keeps the discriminant accurate for rays starting far away.
        let perp = oc - ray.dir * (b / a);
        let disc = a * (self.radius2 - perp.length_squared());
        if disc < 0.0 || a == 0.0 {
            return None;
        }
        let c = oc.length_squared() - self.radius2;
        Some(Quadratic { a, b, c, disc })
    }

    /// `intersect_first`'s crossing: the nearest in (EPSILON, tmax). Public and inlined so
    /// that the scene's walk, which knows a leaf is an untransformed sphere, asks it without
    /// the call through the shape's table (the same code, so the same bits).
    #[inline(always)]
    pub fn first_t(&self, ray: &Ray, tmax: f64) -> Option<f64> {
        if self.behind(ray) {
            return None;
        }
        self.quadratic(ray)?.first(tmax)
    }

    /// Whether both ends of the segment `[0, tmax]` lie well inside (see `blocks`): then no
    /// root falls in (EPSILON, tmax).
    #[inline(always)]
    fn holds(&self, ray: &Ray, tmax: f64) -> bool {
        let inner = self.radius2 * 0.999;
        let oc = ray.origin - self.center;
        oc.length_squared() < inner && (oc + ray.dir * tmax).length_squared() < inner
    }

    /// `any_hit`'s answer (`first_t(..).is_some()`), inlined into the shadow walk as
    /// `first_t` is into the nearest-hit walk.
    ///
    /// Shadow rays inside a sky sphere (advanced/quilt1: every area-light sample) skip the
    /// roots: a segment whose two ends lie well inside crosses nothing, and the margin (the
    /// ends at most 0.9995 r from the centre, so each root at least 0.0005 r / |dir| beyond
    /// them) is some 1e11 times the roots' rounding error, so `intersect_first` would find
    /// no crossing either: the same answer, not an approximation.
    #[inline(always)]
    pub fn blocks(&self, ray: &Ray, tmax: f64) -> bool {
        if self.holds(ray, tmax) {
            return false;
        }
        if self.behind(ray) {
            return false;
        }
        // `intersect_first(..).is_some()`, from one working of the equation.
        let Some(q) = self.quadratic(ray) else {
            return false;
        };
        q.surely_crossed(tmax) || q.first(tmax).is_some()
    }
}

/// `a t² + 2 b t + c = 0` of a line and a sphere, and its discriminant `b² - a c` (worked out
/// through the line's closest approach, not from that formula).
#[derive(Clone, Copy)]
struct Quadratic {
    a: f64,
    b: f64,
    c: f64,
    disc: f64,
}

impl Quadratic {
    #[inline(always)]
    fn roots(self) -> (f64, f64) {
        let Quadratic { a, b, c, disc } = self;
        let q = -(b + b.signum() * disc.sqrt());
        if q == 0.0 {
            return (0.0, 0.0);
        }
        // Citardauq form: the root that would need -b + sqrt(disc) comes from c / q instead.
        let (r1, r2) = (q / a, c / q);
        (r1.min(r2), r1.max(r2))
    }

    /// The nearest crossing in (EPSILON, tmax).
    #[inline(always)]
    fn first(self, tmax: f64) -> Option<f64> {
        let (t0, t1) = self.roots();
        let t = if t0 > EPSILON { t0 } else { t1 };
        (t > EPSILON && t < tmax).then_some(t)
    }

    /// Whether `intersect_first` would surely find a crossing in (EPSILON, tmax), told without
    /// the square root and the two divisions of the roots: a shadow ray meeting a blocker
    /// (advanced/quilt1's mirror sphere, under an area light) needs only that answer. False
    /// means "not sure", never "no crossing".
    ///
    /// For a ray heading towards the centre (`b < 0`) from outside (`c > 0`) with
    /// `0 <= disc <= b²`: `roots` computes `q = |b| + √disc`, between `|b|` and `2|b|`
    /// (each rounding within 2^-52 of that), and the roots `q / a >= |b| / a` and `c / q`,
    /// between `c / 2|b|` and `c / |b|`. So `c > 4 ε |b|`, `|b| > 2 ε a` and
    /// `c < |b| tmax (1 - 1e-12)` put both roots above ε and the lesser below `tmax`, margins
    /// far wider than the few roundings between: `intersect_first` takes the lesser and
    /// returns it. Anything else (NaN included) fails a comparison and is not sure.
    #[inline(always)]
    fn surely_crossed(self, tmax: f64) -> bool {
        let Quadratic { a, b, c, disc } = self;
        b < 0.0
            && disc <= b * b
            && c > 4.0 * EPSILON * -b
            && -b > 2.0 * EPSILON * a
            && c < -b * tmax * (1.0 - 1e-12)
    }
}

impl Shape for Sphere {
    fn bounds(&self) -> Aabb {
        if self.radius == 0.0 {
            return Aabb::EMPTY;
        }
        Aabb::new(
            self.center - DVec3::splat(self.radius),
            self.center + DVec3::splat(self.radius),
        )
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        if self.behind(ray) {
            return;
        }
        if let Some((t0, t1)) = self.roots(ray) {
            for t in [t0, t1] {
                if t > EPSILON {
                    out.push(Hit::new(t));
                }
            }
        }
    }

    /// A segment whose two ends lie well inside crosses nothing in (EPSILON, tmax): `blocks`'
    /// certificate (advanced/abyss: every media sample's shadow ray listed the roots of the
    /// media sphere around it, both beyond the segment's ends).
    fn intersect_all_before(&self, ray: &Ray, tmax: f64, out: &mut Vec<Hit>) {
        if self.holds(ray, tmax) {
            return;
        }
        self.intersect_all(ray, out)
    }

    fn intersect_first(&self, ray: &Ray, tmax: f64, _scratch: &mut Vec<Hit>) -> Option<Hit> {
        self.first_t(ray, tmax).map(Hit::new)
    }

    /// `blocks`.
    fn any_hit(&self, ray: &Ray, tmax: f64, _scratch: &mut Vec<Hit>) -> bool {
        self.blocks(ray, tmax)
    }

    fn inside(&self, p: DVec3) -> bool {
        (p - self.center).length_squared() < self.radius2
    }

    fn ball(&self) -> Option<(DVec3, f64)> {
        Some((self.center, self.radius))
    }

    fn as_sphere(&self) -> Option<&Sphere> {
        Some(self)
    }

    fn normal(&self, p: DVec3, _hit: &Hit) -> DVec3 {
        (p - self.center) / self.radius.max(f64::MIN_POSITIVE)
    }
    /// Longitude and latitude, measured against povray (tests/probes/uv_sphere.pov): u turns
    /// from +x towards +z (0 at +x, 0.75 at -z), v runs from 0 at the south pole to 1 at the
    /// north.
    fn uv(&self, p: DVec3, _hit: &Hit) -> Option<[f64; 2]> {
        let d = (p - self.center).normalize_or_zero();
        let u = d.z.atan2(d.x) / std::f64::consts::TAU;
        let u = if u < 0.0 { u + 1.0 } else { u };
        let v = d.y.clamp(-1.0, 1.0).asin() / std::f64::consts::PI + 0.5;
        Some([u, v])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn all(s: &Sphere, r: &Ray) -> Vec<f64> {
        let mut v = Vec::new();
        s.intersect_all(r, &mut v);
        let mut t: Vec<f64> = v.iter().map(|h| h.t).collect();
        t.sort_by(f64::total_cmp);
        t
    }

    #[test]
    fn hits_at_known_distances() {
        let s = Sphere::new(DVec3::new(0.0, 0.0, 5.0), 2.0);
        let r = Ray::new(DVec3::ZERO, DVec3::Z);
        assert_eq!(all(&s, &r), vec![3.0, 7.0]);
        let h = s
            .intersect_first(&r, f64::INFINITY, &mut Vec::new())
            .unwrap();
        assert_eq!(h.t, 3.0);
        let n = s.normal(r.at(h.t), &h);
        assert!((n - DVec3::NEG_Z).length() < 1e-12);
        // Unnormalised direction: t stays in units of dir.
        let r2 = Ray::new(DVec3::ZERO, DVec3::Z * 2.0);
        assert_eq!(all(&s, &r2), vec![1.5, 3.5]);
        assert!(s.intersect_first(&r, 2.9, &mut Vec::new()).is_none());
    }

    /// The `behind` shortcut answers as the full working of the equation does: rays from
    /// outside, inside, on and near the surface, heading every way, on small and huge spheres,
    /// t bit for bit.
    #[test]
    fn behind_is_the_full_answer() {
        let mut rng = crate::geom::test_rng::Lcg(777);
        let mut rnd = move || rng.next() * 2.0 - 1.0;
        let mut skipped = 0;
        for r in [1e-3, 0.5, 1.0, 1e5] {
            let s = Sphere::new(DVec3::new(0.25, -0.5, 1.0), r);
            for k in 0..20000 {
                let scale = [0.5, 1.0, 1.0000001, 3.0, 1e4][k % 5] * r;
                let o = s.center + DVec3::new(rnd(), rnd(), rnd()).normalize_or_zero() * scale;
                let d = DVec3::new(rnd(), rnd(), rnd()) * [1.0, 1e-6, 1e6][k % 3];
                let ray = Ray::new(o, d);
                let tmax = [f64::INFINITY, 1.0, 1e-3][k % 3];
                let full = s.quadratic(&ray).and_then(|q| q.first(tmax));
                let got = s.intersect_first(&ray, tmax, &mut Vec::new());
                assert_eq!(got.map(|h| h.t.to_bits()), full.map(f64::to_bits));
                let mut all_full = Vec::new();
                if let Some((t0, t1)) = s.roots(&ray) {
                    all_full.extend([t0, t1].into_iter().filter(|&t| t > EPSILON));
                }
                let mut v = Vec::new();
                s.intersect_all(&ray, &mut v);
                let got: Vec<u64> = v.iter().map(|h| h.t.to_bits()).collect();
                let want: Vec<u64> = all_full.iter().map(|t| t.to_bits()).collect();
                assert_eq!(got, want);
                skipped += usize::from(s.behind(&ray));
            }
        }
        assert!(skipped > 1000, "the shortcut was taken {skipped} times");
    }

    /// `any_hit` answers as `intersect_first` does, for segments inside, leaving, crossing
    /// and near the surface, on small and huge spheres.
    #[test]
    fn any_hit_is_intersect_first() {
        let mut scratch = Vec::new();
        let mut rng = crate::geom::test_rng::Lcg(12345);
        let mut rnd = move || rng.next() * 2.0 - 1.0;
        for r in [0.5, 1.0, 100000.0] {
            let s = Sphere::new(DVec3::new(0.25, -0.5, 1.0), r);
            for _ in 0..20000 {
                let o = DVec3::new(rnd(), rnd(), rnd()) * r * 1.2 + DVec3::new(0.25, -0.5, 1.0);
                let d = DVec3::new(rnd(), rnd(), rnd()) * (1.0 + 3.0 * rnd().abs());
                let tmax = [rnd().abs() * 2.0 * r, f64::INFINITY, 0.0, f64::NAN]
                    [(rnd().abs() * 3.999) as usize];
                let ray = Ray::new(o, d);
                assert_eq!(
                    s.any_hit(&ray, tmax, &mut scratch),
                    s.intersect_first(&ray, tmax, &mut scratch).is_some(),
                    "{o} {d} {tmax}"
                );
            }
        }
    }

    /// `any_hit` answers as `intersect_first` for rays aimed at a sphere from just outside
    /// its surface to far away, with `tmax` near either crossing (where the short cut of
    /// `surely_crossed` has to give way), and the short cut is taken.
    #[test]
    fn any_hit_is_intersect_first_for_aimed_rays() {
        let mut scratch = Vec::new();
        let mut rng = crate::geom::test_rng::Lcg(777);
        let mut sure = 0;
        for r in [1e-3, 0.5, 2.0, 1e5] {
            let centre = DVec3::new(-2.0, 1.5, 0.25) * r;
            let s = Sphere::new(centre, r);
            for k in 0..30000 {
                let dir =
                    (rng.vec(1.0) + DVec3::splat(1e-3)).normalize() * (0.1 + rng.next() * 3.0);
                let gap = r * [1e-9, 1e-7, 1e-5, 1e-3, 0.1, 1.0, 30.0][k % 7] * rng.next();
                // Aimed at a point inside (or near) the sphere.
                let target = centre + rng.vec(1.0) * r * 1.1;
                let from = target - dir.normalize() * (r * 2.5 + gap);
                let o = centre + (from - centre).normalize() * (r + gap);
                let d = (target - o).normalize() * dir.length();
                let ray = Ray::new(o, d);
                let want = s.intersect_first(&ray, f64::INFINITY, &mut scratch);
                let tmax = match (want, k % 5) {
                    (_, 0) => f64::INFINITY,
                    (Some(h), 1) => h.t,
                    (Some(h), 2) => h.t * (1.0 + 1e-15),
                    (Some(h), 3) => h.t * (1.0 + rng.next()),
                    _ => rng.next() * 4.0 * r,
                };
                let first = s.intersect_first(&ray, tmax, &mut scratch).is_some();
                assert_eq!(s.any_hit(&ray, tmax, &mut scratch), first, "{o} {d} {tmax}");
                if s.quadratic(&ray).is_some_and(|q| q.surely_crossed(tmax)) {
                    assert!(first);
                    sure += 1;
                }
            }
        }
        assert!(sure > 10000, "{sure}");
    }

    #[test]
    fn from_inside_and_behind() {
        let s = Sphere::new(DVec3::ZERO, 1.0);
        let r = Ray::new(DVec3::ZERO, DVec3::X);
        assert_eq!(all(&s, &r), vec![1.0]);
        assert_eq!(
            s.intersect_first(&r, f64::INFINITY, &mut Vec::new())
                .unwrap()
                .t,
            1.0
        );
        assert!(s.inside(DVec3::splat(0.5)));
        assert!(!s.inside(DVec3::splat(0.6)));
        let behind = Ray::new(DVec3::new(3.0, 0.0, 0.0), DVec3::X);
        assert!(all(&s, &behind).is_empty());
    }

    #[test]
    fn far_away_rays_stay_accurate() {
        let s = Sphere::new(DVec3::ZERO, 1.0);
        let r = Ray::new(DVec3::new(0.5, 0.0, -1e7), DVec3::Z);
        let t = all(&s, &r);
        let want = 1e7 - 0.75f64.sqrt();
        assert!((t[0] - want).abs() < 1e-8, "{t:?}");
    }

    #[test]
    fn grazing_and_degenerate() {
        let s = Sphere::new(DVec3::ZERO, 1.0);
        let r = Ray::new(DVec3::new(1.0 + 1e-9, 0.0, -5.0), DVec3::Z);
        assert!(all(&s, &r).is_empty());
        let r = Ray::new(DVec3::new(1.0 - 1e-9, 0.0, -5.0), DVec3::Z);
        assert_eq!(all(&s, &r).len(), 2);
        let z = Sphere::new(DVec3::ZERO, 0.0);
        assert!(all(&z, &Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z)).is_empty());
        assert!(z.bounds().is_empty());
        assert!(!z.inside(DVec3::ZERO));
        let zero_dir = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::ZERO);
        assert!(all(&s, &zero_dir).is_empty());
        let neg = Sphere::new(DVec3::ZERO, -2.0);
        assert_eq!(
            all(&neg, &Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z)),
            vec![3.0, 7.0]
        );
    }
}
