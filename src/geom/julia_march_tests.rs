//! Unit tests of the julia march's short cuts (`inner_radius`, the bisection's ends at `tmin`
//! and for `any_hit`, its low-end midpoints, the samples ahead): every crossing, to the bit,
//! against the march written plainly (lone orbits, one midpoint at a time, every sample up to
//! the bailout sphere's exit).

use super::tests::{julia, FRACTAL3};
use super::*;

/// The plain march: crossings beyond `tmin` along the unit direction `u`, as distances.
fn plain_crossings(j: &Julia, o: DVec3, u: DVec3, tmin: f64) -> Vec<f64> {
    let mut out = Vec::new();
    let rb = j.bailout;
    let b = o.dot(u);
    let disc = b * b - (o.length_squared() - rb * rb);
    if disc <= 0.0 {
        return out;
    }
    let root = disc.sqrt();
    let (entry, exit) = (-b - root, -b + root);
    if exit <= 0.0 {
        return out;
    }
    let min_step = 1.0 / j.precision;
    let mut t = (entry + ENTRY_EPS).max(0.0);
    let mut prev: Option<(f64, bool)> = None;
    if t > 0.0 {
        prev = Some((t, false));
        t += march_step(&j.orbit(o + u * t), min_step);
    }
    while t <= exit {
        let orbit = j.orbit(o + u * t);
        let inside = matches!(orbit, Orbit::Inside);
        if let Some((tp, was_in)) = prev {
            if was_in != inside {
                let (mut a, mut c) = (tp, t);
                while c - a > BISECT_TOL {
                    let m = 0.5 * (a + c);
                    if m <= a || m >= c {
                        break;
                    }
                    if j.is_in(o + u * m) == was_in {
                        a = m;
                    } else {
                        c = m;
                    }
                }
                let hit = 0.5 * (a + c);
                if hit > tmin {
                    out.push(hit);
                }
            }
        }
        prev = Some((t, inside));
        t += march_step(&orbit, min_step);
    }
    out
}

/// `intersect_all`, `intersect_first` and `any_hit` against the plain march, on rays from
/// afar and on rays leaving points of the surface (shadow and reflected rays, whose crossing
/// at their start the bisection turns away early), for quaternion sets of the sample scenes,
/// a sliced one, one whose inner radius is the bailout, and hypercomplex sqr and cube sets.
#[test]
fn march_short_cuts_answer_as_the_plain_march() {
    let mut rng = crate::geom::test_rng::Lcg(41);
    let slice = ([0.3, -0.2, 0.1, 0.9], 0.15);
    let sets = [
        julia(
            [-0.083, 0.0, -0.83, -0.025],
            Algebra::Quaternion,
            JuliaFn::Sqr,
            8,
            15.0,
        ),
        julia(
            [-0.03, 0.5, -0.2, -0.5],
            Algebra::Quaternion,
            JuliaFn::Cube,
            8,
            15.0,
        ),
        julia(FRACTAL3, Algebra::Quaternion, JuliaFn::Sqr, 7, 400.0),
        Julia::new(FRACTAL3, Algebra::Quaternion, JuliaFn::Cube, 6, 30.0, slice),
        julia(
            [1.2, 0.3, -0.4, 0.2],
            Algebra::Quaternion,
            JuliaFn::Sqr,
            5,
            20.0,
        ),
        julia(
            [-0.745, 0.0, 0.113, 0.05],
            Algebra::Hypercomplex,
            JuliaFn::Sqr,
            9,
            20.0,
        ),
        julia(
            [0.4, 0.2, 0.1, 0.0],
            Algebra::Hypercomplex,
            JuliaFn::Cube,
            6,
            20.0,
        ),
    ];
    let (mut hits, mut surface) = (0, 0);
    for (k, j) in sets.iter().enumerate() {
        if k < 4 {
            assert!(j.inner < j.bailout, "{k}: no inner radius to test");
        }
        let mut starts = Vec::new();
        for i in 0..400 {
            let o = if i % 2 == 0 {
                rng.vec(8.0)
            } else {
                rng.vec(1.5)
            };
            let d = rng.vec(1.0) - o * (0.2 + rng.next());
            let ray = if i % 4 < 2 || starts.is_empty() {
                Ray::new(o, d)
            } else {
                surface += 1;
                Ray::new(starts[i % starts.len()], d)
            };
            let len = ray.dir.length();
            let u = ray.dir / len;
            let want: Vec<u64> = plain_crossings(j, ray.origin, u, EPSILON * len)
                .iter()
                .map(|s| (s / len).to_bits())
                .collect();
            let mut all = Vec::new();
            j.intersect_all(&ray, &mut all);
            let got: Vec<u64> = all.iter().map(|h| h.t.to_bits()).collect();
            assert_eq!(got, want, "{k} {ray:?}");
            for tmax in [f64::INFINITY, 0.5, 2.0, rng.next() * 3.0] {
                let first = want
                    .first()
                    .map(|&b| f64::from_bits(b))
                    .filter(|&t| t < tmax);
                let f = j.intersect_first(&ray, tmax, &mut Vec::new());
                assert_eq!(
                    f.map(|h| h.t.to_bits()),
                    first.map(f64::to_bits),
                    "{k} {ray:?}"
                );
                assert_eq!(j.any_hit(&ray, tmax, &mut Vec::new()), first.is_some());
                hits += first.is_some() as usize;
            }
            if let Some(t) = all.first().map(|h| h.t) {
                starts.push(ray.at(t));
            }
        }
    }
    assert!(hits > 500 && surface > 500, "{hits} {surface}");
}

/// No point beyond the inner radius is inside: points of the surface and just beyond it, for
/// quaternion and hypercomplex sets (the latter's radius below the bailout, asserted).
#[test]
fn inner_radius_holds_the_set() {
    use Algebra::{Hypercomplex as H, Quaternion as Q};
    let mut rng = crate::geom::test_rng::Lcg(43);
    for (c, algebra, func, n) in [
        ([-0.083, 0.0, -0.83, -0.025], Q, JuliaFn::Sqr, 8),
        ([-0.03, 0.5, -0.2, -0.5], Q, JuliaFn::Cube, 8),
        (FRACTAL3, Q, JuliaFn::Sqr, 7),
        ([0.0; 4], Q, JuliaFn::Sqr, 12),
        ([-0.745, 0.0, 0.113, 0.05], H, JuliaFn::Sqr, 9),
        ([0.2, 0.1, 0.59, -0.2], H, JuliaFn::Sqr, 7),
        ([0.4, 0.2, 0.1, 0.0], H, JuliaFn::Cube, 6),
        ([0.0; 4], H, JuliaFn::Sqr, 2),
        ([0.0; 4], H, JuliaFn::Sqr, 12),
        ([-1.2, 0.3, 0.6, -0.4], H, JuliaFn::Sqr, 4),
    ] {
        let j = julia(c, algebra, func, n, 20.0);
        if algebra == H {
            assert!(j.inner < j.bailout, "{c:?}: {}", j.inner);
        }
        for _ in 0..20_000 {
            let dir = rng.vec(2.0).normalize();
            // A point of the surface along the direction, where one lies inside at `lo`.
            let (mut lo, mut hi) = (0.0, j.bailout * 1.01);
            if j.is_in(dir * lo) {
                for _ in 0..60 {
                    let m = 0.5 * (lo + hi);
                    if j.is_in(dir * m) {
                        lo = m;
                    } else {
                        hi = m;
                    }
                }
                assert!(
                    (dir * lo).length() <= j.inner * (1.0 + 1e-12),
                    "{c:?} {dir:?}: {lo} {}",
                    j.inner
                );
            }
            for s in [1.0 + 1e-12, 1.001, 1.1] {
                assert!(!j.is_in(dir * (j.inner * s)), "{c:?} {dir:?}");
            }
        }
    }
}
