//! Unit tests of `geom::blob`: crossings against closed forms, the nearest crossing and
//! `any_kept` against the full list bit for bit.

use super::*;
use crate::geom::test_rng::Lcg;

fn sphere(c: DVec3, r: f64, s: f64) -> Component {
    Component {
        kind: ComponentKind::Sphere { center: c },
        radius: r,
        strength: s,
        transform: Transform::IDENTITY,
    }
}

fn hits(b: &Blob, o: DVec3, d: DVec3) -> Vec<f64> {
    let mut v = Vec::new();
    b.intersect_all(&Ray::new(o, d), &mut v);
    v.iter().map(|h| h.t).collect()
}

#[test]
fn single_sphere_radius() {
    // strength 1, threshold t: surface where (1 - d²/r²)² = t, d = r sqrt(1 - sqrt t).
    let b = Blob::new(&BlobData {
        components: vec![sphere(DVec3::ZERO, 2.0, 1.0)],
        threshold: 0.25,
        sturm: false,
    });
    let d = 2.0 * (0.5f64).sqrt();
    let t = hits(&b, DVec3::new(0.0, 0.0, -5.0), DVec3::Z * 2.0);
    assert_eq!(t.len(), 2, "{t:?}");
    assert!((t[0] - (5.0 - d) / 2.0).abs() < 1e-12 && (t[1] - (5.0 + d) / 2.0).abs() < 1e-12);
    let n = b.normal(DVec3::new(0.0, 0.0, -d), &Hit::new(0.0));
    assert!((n.normalize() - DVec3::NEG_Z).length() < 1e-12);
    assert!(b.inside(DVec3::ZERO) && !b.inside(DVec3::new(0.0, 1.5, 0.0)));
    // Above the strength the component vanishes.
    let b = Blob::new(&BlobData {
        components: vec![sphere(DVec3::ZERO, 2.0, 1.0)],
        threshold: 1.5,
        sturm: true,
    });
    assert!(hits(&b, DVec3::new(0.0, 0.0, -5.0), DVec3::Z).is_empty());
}

#[test]
fn cylinder_body_and_caps() {
    let c = Component {
        kind: ComponentKind::Cylinder {
            a: DVec3::new(-1.0, 0.0, 0.0),
            b: DVec3::new(1.0, 0.0, 0.0),
        },
        radius: 1.0,
        strength: 1.0,
        transform: Transform::IDENTITY,
    };
    for sturm in [false, true] {
        let b = Blob::new(&BlobData {
            components: vec![c],
            threshold: 0.25,
            sturm,
        });
        // Radius of the surface: (1 - d²)² = 0.25, d = sqrt(0.5).
        let d = 0.5f64.sqrt();
        // Along the axis: through both caps.
        let t = hits(&b, DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
        assert_eq!(t.len(), 2);
        assert!((t[0] - (4.0 - d)).abs() < 1e-12 && (t[1] - (6.0 + d)).abs() < 1e-12);
        // Across the body, and obliquely through a cap and the body.
        let t = hits(&b, DVec3::new(0.3, -5.0, 0.0), DVec3::Y);
        assert!((t[0] - (5.0 - d)).abs() < 1e-12, "{t:?}");
        let dir = DVec3::new(1.0, 1.0, 0.0).normalize();
        let t = hits(&b, DVec3::new(-1.5, -0.5, 0.0) - dir * 3.0, dir);
        assert_eq!(t.len(), 2, "{t:?}");
        for &ti in &t {
            let p = DVec3::new(-1.5, -0.5, 0.0) + dir * (ti - 3.0);
            assert!((b.field(p) - 0.25).abs() < 1e-12, "{p} {}", b.field(p));
        }
    }
}

#[test]
fn negative_and_transformed_components() {
    let mut squash = sphere(DVec3::ZERO, 1.0, 1.0);
    squash.transform = Transform::scale(DVec3::new(2.0, 1.0, 1.0));
    let b = Blob::new(&BlobData {
        components: vec![squash, sphere(DVec3::new(2.0, 0.0, 0.0), 1.0, -1.0)],
        threshold: 0.25,
        sturm: false,
    });
    let t = hits(&b, DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
    assert_eq!(t.len(), 2, "{t:?}");
    // Left end of the ellipsoid: x = -2 sqrt(0.5); the right end is dented inwards.
    assert!((t[0] - (5.0 - 2.0 * 0.5f64.sqrt())).abs() < 1e-12);
    assert!(t[1] < 5.0 + 2.0 * 0.5f64.sqrt() - 0.1);
    let p = DVec3::new(-5.0 + t[1], 0.0, 0.0);
    assert!((b.field(p) - 0.25).abs() < 1e-12);
    assert!(b.normal(p, &Hit::new(0.0)).x > 0.0);
    // The negative component adds nothing to the bounds.
    assert!(b.bounds().max.x <= 2.0 + 1e-12);
}

#[test]
fn first_hit_below_tmax() {
    // Two separate spheres along the ray: intersect_first agrees with the nearest of
    // intersect_all below tmax, for a tmax before, between and after the crossings.
    let b = Blob::new(&BlobData {
        components: vec![
            sphere(DVec3::ZERO, 1.0, 1.0),
            sphere(DVec3::new(0.0, 0.0, 3.0), 1.0, 1.0),
        ],
        threshold: 0.25,
        sturm: false,
    });
    let ray = Ray::new(DVec3::new(0.1, 0.0, -5.0), DVec3::new(0.0, 0.0, 0.5));
    let mut all = Vec::new();
    b.intersect_all(&ray, &mut all);
    assert_eq!(all.len(), 4);
    let mut scratch = Vec::new();
    for tmax in [1.0, all[0].t, all[1].t + 0.1, all[2].t, 100.0] {
        let want = all.iter().map(|h| h.t).find(|&t| t < tmax);
        let got = b.intersect_first(&ray, tmax, &mut scratch).map(|h| h.t);
        assert_eq!(got, want, "tmax {tmax}");
    }
}

/// A cylinder component across the x axis, rising a little: the shadow-ray tests' arm.
fn leaning_arm() -> Component {
    Component {
        kind: ComponentKind::Cylinder {
            a: DVec3::new(-1.5, 0.0, 0.0),
            b: DVec3::new(1.5, 0.2, 0.0),
        },
        radius: 1.2,
        strength: 1.0,
        transform: Transform::IDENTITY,
    }
}

/// The shadow-ray tests' rays: the leaning arm with four spheres (one negative), plain and
/// sturm, `rays` random lines and rays started on each crossing of them (roots at t <=
/// EPSILON in play) or at the line's origin, aimed at the blob or anywhere. Gives `f` the
/// blob, its sturm flag, the ray, its listed crossings, the generator and a scratch.
fn shadow_rays(
    seed: u64,
    rays: usize,
    mut f: impl FnMut(&Blob, bool, &Ray, &[f64], &mut Lcg, &mut Vec<Hit>),
) {
    let mut arm = leaning_arm();
    arm.transform = Transform::scale(DVec3::new(1.0, 0.7, 1.3));
    let comps = vec![
        arm,
        sphere(DVec3::new(0.0, 0.8, 0.0), 1.0, -1.5),
        sphere(DVec3::new(0.9, 0.0, 0.9), 0.8, 1.0),
        sphere(DVec3::new(-0.9, 0.0, -0.5), 0.7, 1.0),
        sphere(DVec3::new(2.5, 0.0, 0.0), 0.6, 1.0),
    ];
    let mut rng = Lcg(seed);
    for sturm in [false, true] {
        let b = Blob::new(&BlobData {
            components: comps.clone(),
            threshold: 0.4,
            sturm,
        });
        let mut scratch = Vec::new();
        for _ in 0..rays {
            let o = rng.vec(8.0);
            let d = rng.vec(2.0) - o * 0.2;
            let first = hits(&b, o, d);
            let starts = first.iter().map(|&t| o + d * t).chain([o]);
            for p in starts.collect::<Vec<_>>() {
                // Aimed at the blob, or anywhere.
                let aim = if rng.next() < 0.7 {
                    rng.vec(1.5)
                } else {
                    p + rng.vec(3.0)
                };
                let ray = Ray::new(p, (aim - p) * (0.3 + rng.next()));
                let listed = hits(&b, ray.origin, ray.dir);
                f(&b, sturm, &ray, &listed, &mut rng, &mut scratch);
            }
        }
    }
}

#[test]
fn first_hit_leaving_the_surface() {
    // Rays from crossings of the surface (shadow rays) and from points near it: the
    // nearest crossing, whose roots at t <= EPSILON are deferred rather than polished,
    // is intersect_all's nearest bit for bit, with and without a tmax.
    let mut arm = leaning_arm();
    let mut other = arm;
    other.kind = ComponentKind::Cylinder {
        a: DVec3::new(0.0, 0.0, -1.5),
        b: DVec3::new(0.0, 0.3, 1.5),
    };
    arm.transform = Transform::scale(DVec3::new(1.0, 0.7, 1.3));
    let b = Blob::new(&BlobData {
        components: vec![
            arm,
            other,
            sphere(DVec3::new(0.0, 0.8, 0.0), 1.0, -1.5),
            sphere(DVec3::new(0.9, 0.0, 0.9), 0.8, 1.0),
        ],
        threshold: 0.4,
        sturm: false,
    });
    let mut rng = Lcg(7);
    let (mut all, mut scratch, mut from_surface) = (Vec::new(), Vec::new(), 0);
    for _ in 0..3000 {
        let o = rng.vec(8.0);
        let d = rng.vec(2.0) - o * 0.2;
        all.clear();
        b.intersect_all(&Ray::new(o, d), &mut all);
        let starts = all.iter().map(|h| o + d * h.t).chain([o + rng.vec(0.1)]);
        for p in starts.collect::<Vec<_>>() {
            for _ in 0..4 {
                // Aimed at the blob, or anywhere.
                let aim = if rng.next() < 0.7 {
                    rng.vec(1.5)
                } else {
                    p + rng.vec(3.0)
                };
                let ray = Ray::new(p, (aim - p) * (0.3 + rng.next()));
                let mut hits = Vec::new();
                b.intersect_all(&ray, &mut hits);
                from_surface += 1;
                for tmax in [f64::INFINITY, 0.5 + rng.next()] {
                    let want = hits.iter().map(|h| h.t).find(|&t| t < tmax);
                    let got = b.intersect_first(&ray, tmax, &mut scratch).map(|h| h.t);
                    assert_eq!(got.map(f64::to_bits), want.map(f64::to_bits), "{ray:?}");
                }
            }
        }
    }
    assert!(from_surface > 10000);
}

#[test]
fn any_hit_is_intersect_first() {
    // Shadow rays: `any_hit` (a bracket that surely holds a counted crossing answers
    // unpolished) answers as `intersect_first(..).is_some()`, for rays from the surface
    // (roots at t <= EPSILON deferred, `last` and the backlog in play) and from anywhere,
    // `tmax` at every listed crossing, one ulp and 1 % either side, and elsewhere.
    let (mut hit, mut total) = (0, 0);
    shadow_rays(41, 2000, |b, _, ray, listed, rng, scratch| {
        let mut tmaxes = vec![f64::INFINITY, 0.0, EPSILON, rng.next() * 3.0];
        for &t in listed {
            let ulp = |k: i64| f64::from_bits((t.to_bits() as i64 + k) as u64);
            tmaxes.extend([t, ulp(-1), ulp(1), t * 0.99, t * 1.01]);
        }
        for tmax in tmaxes {
            let want = b.intersect_first(ray, tmax, scratch).is_some();
            let got = b.any_hit(ray, tmax, scratch);
            assert_eq!(got, want, "{ray:?} {tmax} {listed:?}");
            hit += usize::from(got);
            total += 1;
        }
    });
    assert!(hit > total / 5 && hit < total * 4 / 5, "{hit} of {total}");
}

#[test]
fn roots_surely_behind_are_behind() {
    // Quartics with a root at a shadow ray's start (near s = 0, where a blob's surface is
    // met again), brackets reaching past t = EPSILON: wherever the certificate gives a
    // bound, the polished root lies below it and maps to t <= EPSILON.
    let mut rng = Lcg(29);
    let (mut sure, mut total) = (0, 0);
    for case in 0..200_000 {
        let r0 = (rng.next() - 0.5) * [1e-15, 1e-9, 1e-7, 1e-6][case % 4];
        let roots = [
            r0,
            rng.next() * 6.0 - 3.0,
            rng.next() * 6.0 - 3.0,
            rng.next() * 6.0 - 3.0,
        ];
        let scale = (rng.next() - 0.5) * 8.0;
        let c: Vec<f64> = crate::geom::test_rng::from_roots(&roots)
            .iter()
            .map(|x| x * scale)
            .collect();
        let len = 0.2 + rng.next() * 4.0;
        let shift = if case % 5 == 0 {
            rng.next() * 1e-6
        } else {
            0.0
        };
        let a = -rng.next() * 3.0 * rng.next() - shift;
        let b = rng.next() * rng.next() * 3.0 + 1e-7;
        let (fa, fb) = (
            crate::geom::poly::eval(&c, a),
            crate::geom::poly::eval(&c, b),
        );
        if (fa < 0.0) == (fb < 0.0) || fa == 0.0 || fb == 0.0 {
            continue;
        }
        let cand = Candidate {
            c: &c,
            a,
            b,
            neg_at_a: fa < 0.0,
        };
        let behind = |s: f64| (s + shift) / len <= EPSILON;
        if !behind(a) || behind(b) {
            continue;
        }
        total += 1;
        if let Some(bound) = root_surely_behind(&cand, shift, len) {
            let r = cand.root();
            assert!(
                r <= bound && behind(r),
                "{c:?} {a} {b} {len} {shift}: {r} {bound}"
            );
            sure += 1;
        }
    }
    assert!(sure > total / 4 && total > 50_000, "{sure} of {total}");
}

#[test]
fn any_kept_is_intersect_all() {
    // CSG and clipped shadow rays (and `gather_kept`, the CSG camera search): `any_kept` asks exactly the listed crossings below
    // tmax, nearest first, bit for bit, up to the first kept one, for rays from the
    // surface (roots at t <= EPSILON deferred) and from anywhere.
    let (mut kept, mut total, mut skipped) = (0, 0, 0);
    shadow_rays(19, 3000, |b, sturm, ray, listed, rng, scratch| {
        let tmax = if rng.next() < 0.5 {
            f64::INFINITY
        } else {
            rng.next() * 3.0
        };
        // Keeps beyond a cut, or by the low bits (skips some, keeps a later one).
        let (cut, odd) = (rng.next() * 2.0, rng.next() < 0.5);
        let test = |t: f64| t > cut && (!odd || t.to_bits().is_multiple_of(3));
        let below: Vec<f64> = listed.iter().copied().filter(|&t| t < tmax).collect();
        let want = below.iter().position(|&t| test(t));
        let mut asked = Vec::new();
        let got = b.any_kept(ray, tmax, scratch, &mut |t| {
            asked.push(t);
            test(t)
        });
        assert_eq!(got, want.is_some(), "{ray:?} {tmax} {listed:?}");
        // `gather_kept`: the least kept crossing it appends is the listing's first
        // kept one below `tmax` (the listing is nearest first), bits and part.
        let mut out = Vec::new();
        b.gather_kept(ray, tmax, &mut out, scratch, &mut |t| test(t));
        let least = out
            .iter()
            .filter(|h| h.t < tmax && test(h.t))
            .min_by(|a, b| a.t.total_cmp(&b.t))
            .map(|h| (h.t.to_bits(), h.part));
        let mut all = Vec::new();
        b.intersect_all(ray, &mut all);
        let first = all
            .iter()
            .find(|h| h.t < tmax && test(h.t))
            .map(|h| (h.t.to_bits(), h.part));
        assert_eq!(least, first, "{ray:?} {tmax}");
        if !sturm {
            let upto = want.map_or(below.len(), |k| k + 1);
            let bits = |v: &[f64]| v.iter().map(|t| t.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&asked), bits(&below[..upto]), "{ray:?} {tmax}");
            skipped += usize::from(want.is_some_and(|k| k > 0));
        }
        kept += usize::from(got);
        total += 1;
    });
    // Both answers, and kept crossings beyond a skipped one, are exercised.
    assert!(
        kept > total / 10 && kept < total * 9 / 10,
        "{kept} of {total}"
    );
    assert!(skipped > 100, "{skipped}");
}

#[test]
fn shifting_quartics() {
    let c = [1.0, -2.0, 0.5, 3.0, -1.0];
    let s = shifted(&c, 1.5);
    for x in [-1.0, 0.0, 0.7, 2.0] {
        let a = crate::geom::poly::eval(&c, x + 1.5);
        let b = crate::geom::poly::eval(&s, x);
        assert!((a - b).abs() < 1e-9, "{a} {b}");
    }
}

#[test]
fn degenerate_input() {
    let b = Blob::new(&BlobData {
        components: vec![
            sphere(DVec3::ZERO, 0.0, 1.0),
            sphere(DVec3::ZERO, 1.0, f64::NAN),
        ],
        threshold: 0.5,
        sturm: false,
    });
    assert!(hits(&b, DVec3::new(0.0, 0.0, -5.0), DVec3::Z).is_empty());
    assert!(b.bounds().is_empty());
    let b = Blob::new(&BlobData {
        components: vec![sphere(DVec3::ZERO, 1.0, 1.0)],
        threshold: 0.5,
        sturm: false,
    });
    assert!(hits(&b, DVec3::splat(f64::NAN), DVec3::Z).is_empty());
    assert!(hits(&b, DVec3::ZERO, DVec3::ZERO).is_empty());
}

/// The normal, field and densities asked of the near components only (`each_near`) against
/// every component's, bit for bit: blobs of spheres and cylinders, plain and transformed
/// (rotations, uneven scales, shears), negative strengths, points anywhere about them and
/// points on a component's boundary sphere to within a few units in the last place.
#[test]
fn near_components_answer_as_all() {
    let mut rng = Lcg(0x5eed_b10b);
    let mut checked = 0;
    for blob in 0..60 {
        let n = 8 + (rng.next() * 60.0) as usize;
        let spread = [0.5, 4.0, 300.0][blob % 3];
        let mut components = Vec::new();
        for k in 0..n {
            let r = 0.05 + rng.next() * spread * 0.3;
            let s = if k % 5 == 4 { -0.7 } else { 0.5 + rng.next() };
            let mut c = if k % 3 == 2 {
                Component {
                    kind: ComponentKind::Cylinder {
                        a: rng.vec(spread),
                        b: rng.vec(spread),
                    },
                    radius: r,
                    strength: s,
                    transform: Transform::IDENTITY,
                }
            } else {
                sphere(rng.vec(spread), r, s)
            };
            match k % 4 {
                1 => c.transform = Transform::rotate(rng.vec(720.0)),
                3 => {
                    let shear = Transform {
                        m: DMat4::from_cols_array(&[
                            1.0, 0.3, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.2, 0.0, 1.0, 0.0, 0.0, 0.0,
                            0.0, 1.0,
                        ]),
                        inv: DMat4::IDENTITY,
                    };
                    let shear = Transform {
                        inv: shear.m.inverse(),
                        ..shear
                    };
                    c.transform = Transform::scale(DVec3::new(0.3, 2.0, 1.0) + rng.vec(1.0))
                        .then(&shear)
                        .then(&Transform::translate(rng.vec(spread)));
                }
                _ => {}
            }
            components.push(c);
        }
        let data = BlobData {
            components,
            threshold: 0.3,
            sturm: false,
        };
        let near = Blob::new(&data);
        assert!(near.near_pad.is_some());
        let mut all = Blob::new(&data);
        all.near_pad = None;
        let mut points: Vec<DVec3> = (0..400).map(|_| rng.vec(spread * 2.5)).collect();
        // On and about each component's boundary: its centre (or an end) plus r along a
        // random direction, taken to blob space, nudged by a few units in the last place.
        for c in &data.components {
            let a = match c.kind {
                ComponentKind::Sphere { center } => center,
                ComponentKind::Cylinder { a, .. } => a,
            };
            for _ in 0..6 {
                let dir = rng.vec(2.0).normalize_or_zero();
                let q = c.transform.point(a + dir * c.radius);
                for ulps in [-3i64, -1, 0, 1, 3] {
                    let nudge = |x: f64| f64::from_bits((x.to_bits() as i64 + ulps) as u64);
                    points.push(DVec3::new(nudge(q.x), nudge(q.y), nudge(q.z)));
                }
            }
        }
        let hit = Hit::new(0.0);
        let (mut dn, mut da) = (Vec::new(), Vec::new());
        for p in points {
            let (a, b) = (near.normal(p, &hit), all.normal(p, &hit));
            assert_eq!(
                a.to_array().map(f64::to_bits),
                b.to_array().map(f64::to_bits),
                "{p}"
            );
            assert_eq!(near.inside(p), all.inside(p), "{p}");
            let (fa, fb) = (near.field(p), all.field(p));
            assert!(fa == fb && (fa != 0.0 || fb == 0.0), "{p}: {fa} {fb}");
            near.densities(p, &mut dn);
            all.densities(p, &mut da);
            let bits = |v: &[(usize, f64)]| -> Vec<(usize, u64)> {
                v.iter().map(|&(i, d)| (i, d.to_bits())).collect()
            };
            assert_eq!(bits(&dn), bits(&da), "{p}");
            checked += usize::from(b != DVec3::ZERO);
        }
    }
    // Most points must meet some component for the comparison to mean anything.
    assert!(checked > 10_000, "{checked}");
}

/// `pieces` leaves a cylinder before its end planes' quotients when the ray is wide of the
/// body's and both caps' spheres (`Prepared::wide`): then `push` pushes nothing for any of the
/// three, whatever its stretch. Checked on random cylinders (plain, long, short, tiny radius)
/// and rays passing their surfaces at random, tangent, and within a few units in the last
/// place of tangent, where the rounding of the discriminants decides.
#[test]
fn wide_cylinders_push_nothing() {
    let mut rng = Lcg(0xc1_1ade);
    let mut wide = 0;
    for k in 0..3000 {
        let spread = [0.5, 4.0, 300.0][k % 3];
        let (a, b) = (rng.vec(spread), rng.vec(spread));
        let r = 0.01 + rng.next() * spread * 0.3;
        let blob = Blob::new(&BlobData {
            components: vec![Component {
                kind: ComponentKind::Cylinder { a, b },
                radius: r,
                strength: 1.0,
                transform: Transform::IDENTITY,
            }],
            threshold: 0.5,
            sturm: false,
        });
        let c = blob.comps[0];
        for j in 0..12 {
            let v = rng.vec(2.0).normalize_or(DVec3::X);
            // A point at distance about r from the axis (or a cap's centre), then the ray
            // through it: tangent or nearly so, nudged by a few ulps of its origin.
            let side = (v.cross(c.axis) + rng.vec(0.1)).normalize_or(DVec3::Y);
            let centre = c.a + c.axis * (c.len * (rng.next() * 1.4 - 0.2));
            let at = [0.0, 1e-12, 1e-3, 0.3][j % 4] * (rng.next() - 0.5);
            let mut q0 = centre + side * (r * (1.0 + at)) - v * spread;
            if j % 3 == 0 {
                let nudge =
                    |x: f64| f64::from_bits((x.to_bits() as i64 + (j as i64 % 7 - 3)) as u64);
                q0 = DVec3::new(nudge(q0.x), nudge(q0.y), nudge(q0.z));
            }
            let to_point = |p: DVec3| {
                let d = q0 - p;
                [d.length_squared(), 2.0 * d.dot(v), v.length_squared()]
            };
            let d = q0 - c.a;
            let (h0, h1) = (d.dot(c.axis), v.dot(c.axis));
            let pa = to_point(c.a);
            let pb = to_point(c.a + c.axis * c.len);
            let body = [pa[0] - h0 * h0, pa[1] - 2.0 * h0 * h1, pa[2] - h1 * h1];
            if !(c.wide(body) && c.wide(pa) && c.wide(pb)) {
                continue;
            }
            wide += 1;
            let mut out = Vec::new();
            for d2 in [body, pa, pb] {
                c.push(
                    d2,
                    f64::NEG_INFINITY,
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                    &mut out,
                );
            }
            c.pieces(q0, v, f64::NEG_INFINITY, &mut out);
            assert!(out.is_empty(), "{a} {b} {r} {q0} {v}");
        }
    }
    assert!(wide > 5_000, "{wide}");
}
