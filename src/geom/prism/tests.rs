//! Prism tests: outlines as POV-Ray closes them, known crossings, random rays against the
//! inside test, and the nearest-crossing search and piece window against the plain search.

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

/// A quadratic-spline 6 x 8 rectangle (with its leading and trailing control points) for
/// the random-ray tests.
fn quadratic_frame() -> Vec<P2> {
    vec![
        [1.0, -1.0],
        [0.0, 0.0],
        [6.0, 0.0],
        [6.0, 8.0],
        [0.0, 8.0],
        [0.0, 0.0],
        [2.0, 0.0],
    ]
}

#[test]
fn the_window_drops_no_crossing() {
    use crate::geom::test_rng::Lcg;
    let quad = quadratic_frame();
    let mut rng = Lcg(5);
    let pieces = outline(SplineKind::Quadratic, &quad).unwrap().pieces;
    for conic in [false, true] {
        for (h0, h1) in [(0.3, 2.0), (-2.0, -0.5), (-1.0, 1.0)] {
            let pr = Prism::new(pieces.clone(), h0, h1, conic, false);
            let (mut kept, mut all) = (0, 0);
            for k in 0..3000 {
                let target = DVec3::new(3.0, 1.0, 3.0) + rng.vec(10.0);
                let mut dir = rng.vec(1.0);
                if k % 10 == 0 {
                    dir.y = 0.0;
                }
                let r = Ray::new(target - dir * 20.0, dir);
                let (mut got, mut want) = (Vec::new(), Vec::new());
                pr.walls(&r, &mut got);
                pr.walls_in(&r, &Window::All, &mut want);
                let key = |h: &Vec<Hit>| -> Vec<(u64, u32, u64)> {
                    h.iter()
                        .map(|h| (h.t.to_bits(), h.part, h.uv[0].to_bits()))
                        .collect()
                };
                assert_eq!(
                    key(&got),
                    key(&want),
                    "conic {conic} heights {h0}..{h1} {r:?}"
                );
                let plane = pr.cut_plane(&r);
                for pc in &pr.pieces {
                    let cut = plane.is_some_and(|(nx, c0, nz)| {
                        Prism::may_cut(pc, |q| nx * q[0] + nz * q[1] + c0)
                    });
                    all += cut as u32;
                    kept += (cut && pr.window(&r).may_hold(pc)) as u32;
                }
            }
            // The window must prune something where the heights allow it.
            if conic && h0 <= 0.0 && h1 >= 0.0 {
                assert_eq!(kept, all);
            } else {
                assert!(
                    kept < all,
                    "conic {conic} heights {h0} {h1}: {kept} of {all}"
                );
            }
        }
    }
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
    let mut quad = quadratic_frame();
    quad.extend([[1.0, 1.0], [5.0, 1.0], [5.0, 7.0], [1.0, 7.0], [1.0, 1.0]]);
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
            let ok =
                got.len() == want.len() && got.iter().zip(&want).all(|(a, b)| (a - b).abs() < 1e-6);
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
    let mut unit = crate::math::xorshift_unit(0x1234_5678_9abc_def1u64);
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
    let mut n_any = [0; 2];
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
                let key = |h: Option<Hit>| h.map(|h| (h.t.to_bits(), h.part, h.uv[0].to_bits()));
                assert_eq!(key(got), key(want), "{kind:?} conic {conic} {ray:?}");
                // The shadow test says whether there is a nearest, also from a crossing
                // (a ray leaving the surface) and with `tmax` at, an ulp past, an ulp before
                // and well before it.
                let from = got.map(|h| Ray::new(ray.at(h.t), target - ray.at(h.t) + o * 0.1));
                let near = got.map_or(1.0, |h| h.t);
                let up = f64::from_bits(near.to_bits() + 1);
                let down = f64::from_bits(near.to_bits() - 1);
                for r in [Some(ray), from].into_iter().flatten() {
                    for tmax in [tmax, near, up, down, near * 0.5, f64::INFINITY, f64::NAN] {
                        let first = pr.intersect_first(&r, tmax, &mut Vec::new()).is_some();
                        n_any[first as usize] += 1;
                        assert_eq!(pr.any_hit(&r, tmax, &mut Vec::new()), first, "{r:?} {tmax}");
                    }
                }
            }
        }
    }
    assert!(n_hits > 10_000, "{n_hits}");
    assert!(n_any[0] > 10_000 && n_any[1] > 10_000, "{n_any:?}");
}
