//! Lathe tests: known crossings, and every spline kind against a brute-force reference that
//! walks the ray with the even-odd inside test.

use super::*;
use crate::geom::test_rng::Lcg;

fn ts(l: &Lathe, r: &Ray) -> Vec<f64> {
    let mut v = Vec::new();
    l.intersect_all(r, &mut v);
    let mut t: Vec<f64> = v.iter().map(|h| h.t).collect();
    t.sort_by(f64::total_cmp);
    t
}

/// A thick tube: radii 2 to 3, heights 0 to 5 (the manual's example).
fn tube() -> Lathe {
    let p = [[2.0, 0.0], [3.0, 0.0], [3.0, 5.0], [2.0, 5.0], [2.0, 0.0]];
    Lathe::new(profile(SplineKind::Linear, &p).unwrap())
}

#[test]
fn tube_crossings() {
    let l = tube();
    let r = Ray::new(DVec3::new(-10.0, 1.0, 0.0), DVec3::X);
    let t = ts(&l, &r);
    assert_eq!(t.len(), 4);
    for (a, b) in t.iter().zip([7.0, 8.0, 12.0, 13.0]) {
        assert!((a - b).abs() < 1e-12, "{t:?}");
    }
    // Nearly horizontal and sloped rays agree with the straight walls.
    for dy in [1e-9, 1e-5, 2e-3, 0.1] {
        let r = Ray::new(DVec3::new(-10.0, 1.0, 0.0), DVec3::new(1.0, dy, 0.0));
        let t = ts(&l, &r);
        assert_eq!(t.len(), 4, "dy {dy}: {t:?}");
        for (a, b) in t.iter().zip([7.0, 8.0, 12.0, 13.0]) {
            assert!((a - b).abs() < 1e-9, "dy {dy}: {t:?}");
        }
    }
    // Down through the wall: top and bottom rims.
    let r = Ray::new(DVec3::new(2.5, 10.0, 0.0), DVec3::NEG_Y * 2.0);
    let t = ts(&l, &r);
    assert!(
        (t[0] - 2.5).abs() < 1e-12 && (t[1] - 5.0).abs() < 1e-12,
        "{t:?}"
    );
    assert!(ts(&l, &Ray::new(DVec3::new(0.0, 10.0, 0.0), DVec3::NEG_Y)).is_empty());
    assert!(l.inside(DVec3::new(0.0, 1.0, 2.5)) && !l.inside(DVec3::new(0.0, 1.0, 1.5)));
    let n = l.normal(DVec3::new(0.0, 1.0, -3.0), &Hit::with_part(0.0, 1));
    assert!((n.normalize() - DVec3::NEG_Z).length() < 1e-12);
    let n = l.normal(DVec3::new(0.0, 1.0, -2.0), &Hit::with_part(0.0, 3));
    assert!((n.normalize() - DVec3::Z).length() < 1e-12);
    assert!(profile(SplineKind::Linear, &[[0.0, 0.0]])
        .unwrap_err()
        .contains("two"));
    assert!(profile(SplineKind::Bezier, &[[0.0, 0.0]; 5]).is_err());
}

/// The crossings of a ray with a closed profile from the inside test sampled along it,
/// each refined by bisection; None where a sample lands too near a crossing to tell.
fn reference(l: &Lathe, r: &Ray, far: f64) -> Vec<f64> {
    const N: usize = 4000;
    let mut out = Vec::new();
    let f = |t: f64| l.inside(r.at(t));
    let mut prev = f(0.0);
    for i in 1..=N {
        let t = far * i as f64 / N as f64;
        let cur = f(t);
        if cur != prev {
            let (mut a, mut b) = (far * (i - 1) as f64 / N as f64, t);
            for _ in 0..80 {
                let m = 0.5 * (a + b);
                if f(m) == prev {
                    a = m;
                } else {
                    b = m;
                }
            }
            out.push(0.5 * (a + b));
        }
        prev = cur;
    }
    out
}

#[test]
fn every_spline_kind_matches_reference() {
    let shapes: Vec<(SplineKind, Vec<P2>)> = vec![
        (
            SplineKind::Quadratic,
            vec![
                [0.5, 3.0],
                [1.0, 0.0],
                [4.0, 1.0],
                [3.0, 5.0],
                [2.0, 6.0],
                [0.5, 3.0],
                [1.0, 0.0],
            ],
        ),
        (
            SplineKind::Cubic,
            vec![
                [0.5, 3.0],
                [1.0, 0.0],
                [4.0, 1.0],
                [3.0, 5.0],
                [2.0, 6.0],
                [0.5, 3.0],
                [1.0, 0.0],
                [4.0, 1.0],
            ],
        ),
        (
            SplineKind::Bezier,
            vec![
                [1.0, 0.0],
                [4.0, -1.0],
                [4.5, 3.0],
                [3.0, 5.0],
                [3.0, 5.0],
                [2.0, 7.0],
                [0.5, 1.0],
                [1.0, 0.0],
            ],
        ),
    ];
    let mut rng = Lcg(7);
    for (kind, p) in shapes {
        let l = Lathe::new(profile(kind, &p).unwrap());
        let mut bad = 0;
        let mut checked = 0;
        for _ in 0..300 {
            let target = DVec3::new(0.0, 3.0, 0.0) + rng.vec(8.0);
            let origin = target + rng.vec(1.0).normalize() * 15.0;
            let r = Ray::new(origin, (target - origin) * 0.37);
            let got = ts(&l, &r);
            let want = reference(&l, &r, 30.0 / r.dir.length());
            checked += 1;
            let close =
                got.len() == want.len() && got.iter().zip(&want).all(|(a, b)| (a - b).abs() < 1e-6);
            if !close {
                bad += 1;
                eprintln!("{kind:?}: got {got:?} want {want:?}");
            }
        }
        // A sample may straddle two crossings closer than its step: allow a rare miss.
        assert!(bad * 100 <= checked, "{kind:?}: {bad} of {checked}");
    }
}

/// `intersect_first` skips pieces whose height band lies beyond the best crossing: it must
/// give the default's answer (every crossing, the first least `t`) to the bit, part and uv
/// included, for every spline kind, from inside and outside, with and without `tmax`.
#[test]
fn nearest_crossing_is_the_defaults() {
    let mut rng = Lcg(0x5eed_1a7e);
    let vase = VASE;
    let mut hits = 0;
    for (kind, pts) in [
        (SplineKind::Linear, &vase[1..8]),
        (SplineKind::Quadratic, &vase[..8]),
        (SplineKind::Cubic, &vase[..]),
    ] {
        let l = Lathe::new(profile(kind, pts).unwrap());
        for _ in 0..6000 {
            let o = DVec3::new(
                6.0 * rng.next() - 3.0,
                5.0 * rng.next() - 1.0,
                6.0 * rng.next() - 3.0,
            );
            let target = DVec3::new(
                2.0 * rng.next() - 1.0,
                3.2 * rng.next(),
                2.0 * rng.next() - 1.0,
            );
            let ray = Ray::new(o, target - o);
            let tmax = if rng.next() < 0.3 {
                0.5 + rng.next()
            } else {
                f64::INFINITY
            };
            let want = crate::geom::test_rng::nearest_of_all(&l, &ray, tmax);
            let got = l.intersect_first(&ray, tmax, &mut Vec::new());
            hits += want.is_some() as usize;
            let key = |h: Option<Hit>| h.map(|h| (h.t.to_bits(), h.part, h.uv[0].to_bits()));
            assert_eq!(key(got), key(want), "{kind:?} {ray:?}");
        }
    }
    assert!(hits > 5000, "{hits}");
}

/// `sloped`'s straight-piece path finds the crossings the general path (`mul` over all seven
/// terms) finds, bit for bit, on random rays through random straight profiles.
#[test]
fn straight_pieces_match_the_general_path() {
    let mut rng = Lcg(0x11e_a7e);
    let mut found = 0;
    for _ in 0..200 {
        let mut p: Vec<P2> = (0..6)
            .map(|_| [rng.next() * 3.0 - 0.5, rng.next() * 4.0 - 2.0])
            .collect();
        // Flat pieces: h1 = 0, where `mul`'s sums meet zero products.
        for k in 1..6 {
            if rng.next() < 0.3 {
                p[k][1] = p[k - 1][1];
            }
        }
        let l = Lathe::new(profile(SplineKind::Linear, &p).unwrap());
        for n in 0..50 {
            let mut o = rng.vec(6.0);
            if n % 4 == 0 {
                // Level with a vertex: h0 = 0 for the pieces there.
                o.y = l.pieces[n % l.pieces.len()].p0[1];
            }
            let u = (rng.vec(2.0) - o * 0.1).normalize();
            if u.y.abs() < FLAT {
                continue;
            }
            let (a, b, c) = (
                u.x * u.x + u.z * u.z,
                o.x * u.x + o.z * u.z,
                o.x * o.x + o.z * o.z,
            );
            for (i, pc) in l.pieces.iter().enumerate() {
                let mut fast = Vec::new();
                l.sloped(pc, i, o, [a, b, c], u.y, None, &mut |t, _, s| {
                    fast.push((t.to_bits(), s.to_bits()))
                });
                // The general path, as `sloped` computes it for any piece.
                let mut hh = pc.y;
                hh[0] -= o.y;
                let mut slow = Vec::new();
                l.sloped_general(pc, i, o, [a, b, c], u.y, hh, None, &mut |t, _, s| {
                    slow.push((t.to_bits(), s.to_bits()))
                });
                assert_eq!(fast, slow);
                found += fast.len();
            }
        }
    }
    assert!(found > 1000, "{found}");
}

/// The vase profile the lathe tests' rays are drawn around (the slices of it each spline
/// kind takes: `vase_rays`).
const VASE: [[f64; 2]; 9] = [
    [0.0, -0.2],
    [1.0, 0.0],
    [1.4, 0.8],
    [0.6, 1.6],
    [0.9, 2.4],
    [1.3, 3.0],
    [0.0, 3.2],
    [1.0, 0.0],
    [1.4, 0.8],
];

/// The lathe tests' rays: for each spline kind a vase-shaped lathe, and 6000 rays from
/// around it at points inside its hull (every seventh nearly flat), with a `tmax` of
/// infinity, a short cut or a random one; `each` may draw more numbers from `rng`.
fn vase_rays(seed: u64, mut each: impl FnMut(&mut Lcg, SplineKind, &Lathe, Ray, f64)) {
    let mut rng = Lcg(seed);
    let vase = VASE;
    for (kind, pts) in [
        (SplineKind::Linear, &vase[1..8]),
        (SplineKind::Quadratic, &vase[..8]),
        (SplineKind::Cubic, &vase[..]),
        (SplineKind::Bezier, &vase[1..9]),
    ] {
        let l = Lathe::new(profile(kind, pts).unwrap());
        for k in 0..6000 {
            let o = DVec3::new(
                6.0 * rng.next() - 3.0,
                5.0 * rng.next() - 1.0,
                6.0 * rng.next() - 3.0,
            );
            let target = DVec3::new(
                2.0 * rng.next() - 1.0,
                3.2 * rng.next(),
                2.0 * rng.next() - 1.0,
            );
            let mut d = target - o;
            if k % 7 == 0 {
                d.y = d.length() * 1e-4 * (rng.next() - 0.5);
            }
            let ray = Ray::new(o, d);
            let tmax = [f64::INFINITY, 0.5 + rng.next(), rng.next() * 8.0][k % 3];
            each(&mut rng, kind, &l, ray, tmax);
        }
    }
}

/// `any_kept` answers as the default's listing does and asks `keep` about the same crossings
/// in the same order up to the first kept: every spline kind, sloped and nearly flat rays,
/// random cuts `tmax` and keep tests.
#[test]
fn any_kept_is_the_listing() {
    let (mut kept, mut asked) = (0, 0);
    vase_rays(0xa11_c0de, |rng, kind, l, ray, tmax| {
        let cut = rng.next() * 8.0;
        let (mut got_asked, mut want_asked) = (Vec::new(), Vec::new());
        let got = l.any_kept(&ray, tmax, &mut Vec::new(), &mut |t| {
            got_asked.push(t.to_bits());
            t > cut
        });
        let want = crate::geom::any_listed_kept(l, &ray, tmax, &mut Vec::new(), &mut |t| {
            want_asked.push(t.to_bits());
            t > cut
        });
        assert_eq!((got, &got_asked), (want, &want_asked), "{kind:?} {ray:?}");
        kept += got as usize;
        asked += got_asked.len();
    });
    assert!(kept > 2000 && asked > 10_000, "{kept} {asked}");
}

/// `gather_kept` appends crossings of the listing, the same bits, among them the one a CSG
/// search would take: the first by `t`, then by place in the listing, of those below `tmax`
/// that `keep` holds for. Every spline kind, sloped and nearly flat rays, random `tmax`.
#[test]
fn gathered_first_kept_is_the_listings() {
    let key = |h: &Hit| (h.t.to_bits(), h.part, h.uv[0].to_bits(), h.uv[1].to_bits());
    let mut found = 0;
    vase_rays(0x6a7_4e12, |rng, kind, l, ray, tmax| {
        // A keep test of the point, as a CSG node's is (here: outside a slab).
        let (lo, hi) = (rng.next() * 4.0 - 1.0, rng.next() * 4.0 - 1.0);
        let keep = |t: f64| {
            let y = ray.at(t).y;
            !(y > lo.min(hi) && y < lo.max(hi))
        };
        let mut all = Vec::new();
        l.intersect_all(&ray, &mut all);
        let first = |v: &[Hit]| {
            v.iter()
                .enumerate()
                .filter(|(_, h)| h.t < tmax && keep(h.t))
                .min_by(|(i, a), (j, b)| a.t.total_cmp(&b.t).then(i.cmp(j)))
                .map(|(_, h)| key(h))
        };
        let mut got = Vec::new();
        l.gather_kept(&ray, tmax, &mut got, &mut Vec::new(), &mut |t| keep(t));
        let listed: Vec<_> = all.iter().map(key).collect();
        assert!(
            got.iter().all(|h| listed.contains(&key(h))),
            "{kind:?} {ray:?}"
        );
        assert_eq!(first(&got), first(&all), "{kind:?} {ray:?}");
        found += first(&all).is_some() as usize;
    });
    assert!(found > 4000, "{found}");
}
