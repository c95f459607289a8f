//! Unit tests of `geom::torus`: `any_kept` and `gather_kept` against `intersect_all`, known crossings, far and
//! degenerate tori, and silhouettes and tangent rays against a signed-distance reference.

use super::*;

fn all(s: &Torus, r: &Ray) -> Vec<f64> {
    let mut v = Vec::new();
    s.intersect_all(r, &mut v);
    v.iter().map(|h| h.t).collect()
}

/// Thin, fat, horn, spindle and near-degenerate tori.
fn kinds() -> [Torus; 5] {
    [
        Torus::new(1.0, 0.25, false),
        Torus::new(0.3, 0.6, false),
        Torus::new(0.0, 0.5, false),
        Torus::new(1.0, 0.25, true),
        Torus::new(2.0, 1e-3, false),
    ]
}

/// A ray from anywhere near `s`, aimed near the ring or anywhere.
fn ring_ray(rng: &mut crate::geom::test_rng::Lcg, s: &Torus) -> Ray {
    let origin = rng.vec(6.0);
    let aim = if rng.next() < 0.7 {
        let a = rng.next() * std::f64::consts::TAU;
        DVec3::new(a.cos() * s.major, 0.0, a.sin() * s.major) + rng.vec(3.0 * s.minor)
    } else {
        rng.vec(4.0)
    };
    Ray::new(origin, (aim - origin) * (0.2 + rng.next()))
}

/// `any_kept` (and `gather_kept`) answers as `intersect_all`'s crossings below `tmax` do, for keep tests
/// that take some crossings and not others, and asks only crossings that list has (the
/// same bits): rays from inside and outside, grazing ones, spindle and degenerate tori.
#[test]
fn any_kept_is_intersect_all() {
    let mut rng = crate::geom::test_rng::Lcg(19);
    let shapes = kinds();
    let (mut kept, mut total) = (0, 0);
    for s in &shapes {
        for _ in 0..4000 {
            let ray = ring_ray(&mut rng, s);
            let listed = all(s, &ray);
            let tmax = if rng.next() < 0.5 {
                f64::INFINITY
            } else {
                rng.next() * 3.0
            };
            let cut = rng.next() * 2.0;
            let want = listed.iter().any(|&t| t < tmax && t > cut);
            let mut asked = Vec::new();
            let mut keep = |t: f64| {
                asked.push(t);
                t > cut
            };
            let got = s.any_kept(&ray, tmax, &mut Vec::new(), &mut keep);
            assert_eq!(got, want, "{s:?} {ray:?} {tmax} {cut} {listed:?}");
            for t in &asked {
                assert!(listed.iter().any(|l| l.to_bits() == t.to_bits()));
            }
            // `gather_kept`: the listing's least kept crossing below `tmax`, to the bit, is
            // the least kept one it appends (the CSG search's answer from this member).
            let least = |v: &[f64]| {
                v.iter()
                    .copied()
                    .filter(|&t| t < tmax && t > cut)
                    .min_by(f64::total_cmp)
                    .map(f64::to_bits)
            };
            let mut out = Vec::new();
            s.gather_kept(&ray, tmax, &mut out, &mut Vec::new(), &mut |t| t > cut);
            let gathered: Vec<f64> = out.iter().map(|h| h.t).collect();
            assert_eq!(
                least(&gathered),
                least(&listed),
                "{s:?} {ray:?} {tmax} {cut}"
            );
            kept += usize::from(got);
            total += 1;
        }
    }
    // Both answers are exercised.
    assert!(
        kept > total / 10 && kept < total * 9 / 10,
        "{kept} of {total}"
    );
}

/// The crossings as the solvers find them with no hole test and their own shortcut
/// (`roots_in`), the code before both were added.
fn solved(s: &Torus, ray: &Ray) -> Vec<f64> {
    let plain = Torus { hole2: -1.0, ..*s };
    let Some(q) = plain.setup(ray) else {
        return Vec::new();
    };
    let roots = match &q.poly {
        Poly::Sphere(c) => roots_in(c, 0.0, q.hi),
        Poly::Quartic(c) if s.sturm => sturm_roots_in(c, 0.0, q.hi),
        Poly::Quartic(c) => roots_in(c, 0.0, q.hi),
    };
    let mut v: Vec<f64> = roots
        .iter()
        .map(|&r| q.to_t(r))
        .filter(|&t| t > EPSILON)
        .collect();
    v.truncate(4);
    v
}

/// The hole test and the written-out certificate change no crossing: rays through and
/// around the hole of thin, fat and near-spindle tori (and the kinds without the test),
/// against `solved`, to the bit, for `intersect_all`, `intersect_first` and `any_kept`.
#[test]
fn hole_test_and_certificate_keep_the_crossings() {
    let mut rng = crate::geom::test_rng::Lcg(77);
    let shapes = [
        Torus::new(1.0, 0.25, false),
        Torus::new(5.2, 0.5, false),
        Torus::new(1.0, 0.9, false),
        Torus::new(1.0, 0.999_999, false),
        Torus::new(2.0, 1e-3, false),
        Torus::new(2.0, 1e-6, false),
        Torus::new(0.3, 0.6, false),
        Torus::new(0.0, 0.5, false),
        Torus::new(1.0, 0.25, true),
    ];
    let (mut holed, mut hits) = (0, 0);
    for s in &shapes {
        let h = s.major - s.minor;
        for i in 0..20_000 {
            // Starts in or near the hole, at the slab's faces or anywhere; aims near the
            // inner wall, across the hole or anywhere.
            let a = rng.next() * std::f64::consts::TAU;
            let radial = DVec3::new(a.cos(), 0.0, a.sin());
            let origin = match i % 3 {
                0 => {
                    radial * (h.abs() * rng.next() * 1.01)
                        + DVec3::Y * (s.minor * (2.0 * rng.next() - 1.0))
                }
                1 => {
                    radial * (h.abs() * rng.next())
                        + DVec3::Y * (s.minor * if rng.next() < 0.5 { -1.0 } else { 1.0 })
                }
                _ => rng.vec(3.0 * (s.major + s.minor)),
            };
            let b = rng.next() * std::f64::consts::TAU;
            let aim = match i % 4 {
                0 => {
                    DVec3::new(b.cos(), 0.0, b.sin()) * h * (0.999 + 0.002 * rng.next())
                        + rng.vec(s.minor)
                }
                1 => {
                    DVec3::new(b.cos(), 0.0, b.sin()) * h * rng.next()
                        + DVec3::Y * (4.0 * s.minor * (rng.next() - 0.5))
                }
                _ => rng.vec(2.0 * (s.major + s.minor)),
            };
            let ray = Ray::new(origin, (aim - origin) * (0.2 + rng.next()));
            let want = solved(s, &ray);
            let got = all(s, &ray);
            let bits = |v: &[f64]| v.iter().map(|t| t.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&got), bits(&want), "{s:?} {ray:?}");
            let first = s.intersect_first(&ray, f64::INFINITY, &mut Vec::new());
            assert_eq!(
                first.map(|h| h.t.to_bits()),
                want.first().map(|t| t.to_bits())
            );
            let cut = rng.next() * 2.0;
            let kept = s.any_kept(&ray, f64::INFINITY, &mut Vec::new(), &mut |t| t > cut);
            assert_eq!(kept, want.iter().any(|&t| t > cut), "{s:?} {ray:?}");
            let plain = Torus { hole2: -1.0, ..*s };
            holed += usize::from(plain.setup(&ray).is_some() && s.setup(&ray).is_none());
            hits += usize::from(!want.is_empty());
        }
    }
    // Both the hole test and real crossings are exercised.
    assert!(holed > 10_000 && hits > 10_000, "{holed} {hits}");
}

fn close(a: &[f64], b: &[f64], tol: f64) -> bool {
    a.len() == b.len()
        && a.iter()
            .zip(b)
            .all(|(x, y)| (x - y).abs() <= tol * y.abs().max(1.0))
}

#[test]
fn known_crossings() {
    for sturm in [false, true] {
        let t = Torus::new(2.0, 0.5, sturm);
        // Along x through the middle: four crossings at |x| = 2.5 and 1.5.
        let r = Ray::new(DVec3::new(-10.0, 0.0, 0.0), DVec3::X);
        assert!(
            close(&all(&t, &r), &[7.5, 8.5, 11.5, 12.5], 1e-12),
            "{:?}",
            all(&t, &r)
        );
        // Down through the tube.
        let r = Ray::new(DVec3::new(2.0, 5.0, 0.0), DVec3::NEG_Y * 2.0);
        assert!(
            close(&all(&t, &r), &[2.25, 2.75], 1e-12),
            "{:?}",
            all(&t, &r)
        );
        // Down through the hole.
        assert!(all(&t, &Ray::new(DVec3::new(0.0, 5.0, 0.0), DVec3::NEG_Y)).is_empty());
        // From inside the tube.
        let r = Ray::new(DVec3::new(0.0, 0.0, 2.0), DVec3::Z);
        assert!(close(&all(&t, &r), &[0.5], 1e-12));
        let h = t
            .intersect_first(&r, f64::INFINITY, &mut Vec::new())
            .unwrap();
        assert!((t.normal(r.at(h.t), &h).normalize() - DVec3::Z).length() < 1e-9);
        assert!(t.intersect_first(&r, 0.4, &mut Vec::new()).is_none());
    }
}

#[test]
fn inside_normals_bounds() {
    let t = Torus::new(2.0, 0.5, false);
    assert!(t.inside(DVec3::new(0.0, 0.4, -2.0)));
    assert!(!t.inside(DVec3::ZERO));
    assert!(!t.inside(DVec3::new(2.0, 0.6, 0.0)));
    let n = t.normal(DVec3::new(0.0, 0.5, 2.0), &Hit::new(1.0));
    assert!((n.normalize() - DVec3::Y).length() < 1e-12);
    let n = t.normal(DVec3::new(-1.5, 0.0, 0.0), &Hit::new(1.0));
    assert!((n.normalize() - DVec3::X).length() < 1e-12);
    assert_eq!(
        t.bounds(),
        Aabb::new(DVec3::new(-2.5, -0.5, -2.5), DVec3::new(2.5, 0.5, 2.5))
    );
}

#[test]
fn far_origins_and_large_scales() {
    let t = Torus::new(1000.0, 1.0, false);
    let r = Ray::new(DVec3::new(1000.5, 0.0, -1e6), DVec3::Z * 3.0);
    // The ray stays within the tube's outer wall only: two crossings where rho = 1001.
    let z = (1001.0f64 * 1001.0 - 1000.5 * 1000.5).sqrt();
    let want = [(1e6 - z) / 3.0, (1e6 + z) / 3.0];
    assert!(close(&all(&t, &r), &want, 1e-14), "{:?}", all(&t, &r));
    let t = Torus::new(1e-3, 2e-4, true);
    let r = Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
    assert!(close(
        &all(&t, &r),
        &[5.0 - 1.2e-3, 5.0 - 0.8e-3, 5.0 + 0.8e-3, 5.0 + 1.2e-3],
        1e-12
    ));
}

#[test]
fn degenerate() {
    let r = Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
    let e = Torus::new(1.0, 0.0, false);
    assert!(all(&e, &r).is_empty() && e.bounds().is_empty() && !e.inside(DVec3::X));
    assert!(all(&Torus::new(1.0, f64::NAN, false), &r).is_empty());
    let s = Torus::new(0.0, 1.0, false);
    assert!(close(&all(&s, &r), &[4.0, 6.0], 1e-12), "{:?}", all(&s, &r));
    assert!(all(
        &Torus::new(1.0, 0.5, false),
        &Ray::new(DVec3::X, DVec3::ZERO)
    )
    .is_empty());
    // Spindle torus: the quartic also has the inner lemon's surface.
    let sp = Torus::new(0.5, 1.0, false);
    let up = all(&sp, &Ray::new(DVec3::new(0.1, -5.0, 0.0), DVec3::Y));
    let (apple, lemon) = (0.84f64.sqrt(), 0.64f64.sqrt());
    assert!(
        close(
            &up,
            &[5.0 - apple, 5.0 - lemon, 5.0 + lemon, 5.0 + apple],
            1e-12
        ),
        "{up:?}"
    );
}

/// Exact distance to a ring torus, the brute-force reference.
fn sdf(major: f64, minor: f64, p: DVec3) -> f64 {
    let q = (p.x * p.x + p.z * p.z).sqrt() - major;
    (q * q + p.y * p.y).sqrt() - minor
}

/// Reference by dense sampling of the distance along the ray, each sampled local minimum
/// refined by golden-section search: Some(Some(t)) must hit first at t, Some(None) must
/// miss, None when the ray passes within `tol` of the surface (ambiguous).
fn reference(
    major: f64,
    minor: f64,
    o: DVec3,
    u: DVec3,
    far: f64,
    tol: f64,
) -> Option<Option<f64>> {
    const N: usize = 1500;
    let f = |s: f64| sdf(major, minor, o + u * s);
    let h = far / N as f64;
    let mut pts: Vec<(f64, f64)> = (0..=N).map(|i| (i as f64 * h, f(i as f64 * h))).collect();
    for i in 1..N {
        if pts[i].1 <= pts[i - 1].1 && pts[i].1 <= pts[i + 1].1 {
            let (mut a, mut b) = (pts[i - 1].0, pts[i + 1].0);
            let g = 0.5 * (5f64.sqrt() - 1.0);
            while b - a > 1e-13 {
                let (c, d) = (b - g * (b - a), a + g * (b - a));
                if f(c) < f(d) {
                    b = d;
                } else {
                    a = c;
                }
            }
            let m = 0.5 * (a + b);
            pts.push((m, f(m)));
        }
    }
    pts.sort_by(|a, b| a.0.total_cmp(&b.0));
    let Some(first) = pts.iter().position(|p| p.1 < tol) else {
        return Some(None);
    };
    if pts[first].1 > -tol {
        return None;
    }
    if first == 0 {
        return Some(Some(0.0));
    }
    // Shallow dips between samples were refined above, so the entry lies in this step.
    let (mut a, mut b) = (pts[first - 1].0, pts[first].0);
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if f(m) > 0.0 {
            a = m;
        } else {
            b = m;
        }
    }
    Some(Some(0.5 * (a + b)))
}

/// (rays checked, ambiguous, missed, spurious, wrong distance, odd crossing counts)
fn silhouette_grid(
    major: f64,
    minor: f64,
    sturm: bool,
    n: usize,
    elevation_deg: f64,
    dist: f64,
) -> [usize; 6] {
    let torus = Torus::new(major, minor, sturm);
    let e = elevation_deg.to_radians();
    // Viewing direction and the two screen axes of an orthographic camera.
    let u = DVec3::new(0.0, -e.sin(), e.cos());
    let right = DVec3::X;
    let up = right.cross(u).normalize() * -1.0;
    let half = (major + minor) * 1.02;
    let mut stats = [0; 6];
    for j in 0..n {
        for i in 0..n {
            let sx = (i as f64 + 0.5) / n as f64 * 2.0 - 1.0;
            let sy = (j as f64 + 0.5) / n as f64 * 2.0 - 1.0;
            let o = (right * sx + up * sy) * half - u * dist;
            let ray = Ray::new(o, u);
            let hits = all(&torus, &ray);
            stats[0] += 1;
            if hits.len() % 2 == 1 {
                stats[5] += 1;
            }
            let s0 = dist - (major + minor) * 1.1;
            match reference(
                major,
                minor,
                o + u * s0,
                u,
                2.2 * (major + minor),
                1e-9 * (major + minor),
            ) {
                None => stats[1] += 1,
                Some(None) if !hits.is_empty() => stats[3] += 1,
                Some(Some(_)) if hits.is_empty() => stats[2] += 1,
                Some(Some(t)) if (hits[0] - (t + s0)).abs() > 1e-7 * (major + minor) => {
                    stats[4] += 1
                }
                _ => {}
            }
        }
    }
    stats
}

#[test]
fn silhouettes_match_reference() {
    for sturm in [false, true] {
        for (elev, dist) in [(0.0, 10.0), (8.0, 10.0), (35.0, 1e4), (90.0, 10.0)] {
            let s = silhouette_grid(1.0, 0.25, sturm, 48, elev, dist);
            assert_eq!(s[2..], [0; 4], "sturm {sturm} elevation {elev}: {s:?}");
        }
    }
}

/// Rays tangent to the surface at random points, pushed in or out by tiny offsets: the
/// cases where a silhouette speckles or loses pixels.
#[test]
fn tangent_rays_match_reference() {
    let mut seed = 12345u64;
    let mut rnd = move || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut bad = Vec::new();
    let mut checked = 0;
    for (major, minor) in [(1.0, 0.25), (1.0, 0.7), (3.0, 0.1)] {
        let scale = major + minor;
        for _ in 0..300 {
            let (th, ph) = (rnd() * std::f64::consts::TAU, rnd() * std::f64::consts::TAU);
            let radial = DVec3::new(th.cos(), 0.0, th.sin());
            let n = radial * ph.cos() + DVec3::Y * ph.sin();
            let p = radial * major + n * minor;
            let a = n.any_orthonormal_vector();
            let b = n.cross(a);
            let w = rnd() * std::f64::consts::TAU;
            let tangent = a * w.cos() + b * w.sin();
            for delta in [-1e-3, -1e-5, -1e-7, 1e-7, 1e-5, 1e-3] {
                let o = p + n * (delta * scale) - tangent * (3.0 * scale);
                let s0 = 3.0 * scale - 2.05 * scale;
                let want = reference(
                    major,
                    minor,
                    o + tangent * s0,
                    tangent,
                    4.1 * scale,
                    1e-9 * scale,
                );
                for sturm in [false, true] {
                    let hits = all(&Torus::new(major, minor, sturm), &Ray::new(o, tangent));
                    checked += 1;
                    let ok = match want {
                        None => true,
                        Some(None) => hits.is_empty(),
                        Some(Some(t)) => {
                            !hits.is_empty() && (hits[0] - (t + s0)).abs() < 1e-7 * scale
                        }
                    };
                    if !ok || hits.len() % 2 == 1 {
                        bad.push((major, minor, delta, sturm, hits, want));
                    }
                }
            }
        }
    }
    assert!(
        bad.is_empty(),
        "{} of {checked} wrong: {:?}",
        bad.len(),
        &bad[..bad.len().min(5)]
    );
}

/// The full 400×400 check per view: `cargo test --release -- --ignored --nocapture torus`.
#[test]
#[ignore]
fn silhouettes_match_reference_400() {
    let mut total = [0; 6];
    for sturm in [false, true] {
        for (major, minor) in [(1.0, 0.25), (1.0, 0.6), (5.0, 0.05)] {
            for (elev, dist) in [
                (0.0, 10.0),
                (3.0, 10.0),
                (30.0, 10.0),
                (60.0, 1e3),
                (90.0, 10.0),
            ] {
                let s = silhouette_grid(major, minor, sturm, 400, elev, dist);
                eprintln!("torus {major},{minor} sturm {sturm} elev {elev}: [rays, ambiguous, missed, spurious, bad t, odd] = {s:?}");
                for k in 0..6 {
                    total[k] += s[k];
                }
            }
        }
    }
    eprintln!("total {total:?}");
    assert_eq!(total[2..], [0; 4]);
}

/// `any_hit`, whose brackets may settle the answer unpolished, answers as
/// `intersect_first(..).is_some()` (every root polished): rays aimed at the ring or anywhere,
/// `tmax` at every crossing, a hair either side, between, and infinite.
#[test]
fn any_hit_is_intersect_first() {
    let mut rng = crate::geom::test_rng::Lcg(77);
    let shapes = kinds();
    let (mut hits, mut total) = (0, 0);
    for s in &shapes {
        for _ in 0..3000 {
            let ray = ring_ray(&mut rng, s);
            let listed = all(s, &ray);
            let mut tmaxes = vec![0.0, EPSILON, 0.5, f64::INFINITY, rng.next() * 3.0];
            for &t in &listed {
                tmaxes.extend([t, t.next_up(), t.next_down(), t * 1.001, t * 0.999]);
            }
            for &tmax in &tmaxes {
                total += 1;
                let want = s.intersect_first(&ray, tmax, &mut Vec::new()).is_some();
                assert_eq!(
                    s.any_hit(&ray, tmax, &mut Vec::new()),
                    want,
                    "{s:?} {ray:?} {tmax}"
                );
                hits += want as usize;
            }
        }
    }
    assert!(hits > 10_000 && total > 50_000, "{hits} of {total}");
}
