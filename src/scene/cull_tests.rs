//! cull.rs's unit tests: balls' chords hold the points inside, world balls hold the mapped
//! balls, plane windows and box maps answer as the shapes they bound.

use super::*;

/// A ball's chord holds the `t` of every point of the ray inside the ball, and is missing
/// only when no point is inside: rays from near and far, grazing and through.
#[test]
fn ball_chord_holds_the_points_inside() {
    let mut unit = crate::math::xorshift_unit(0x9e37_79b9_7f4a_7c15);
    let mut rnd = move || unit() * 2.0 - 1.0;
    for case in 0..4000 {
        let r = 0.5 + rnd().abs() * 10.0;
        let centre = DVec3::new(rnd(), rnd(), rnd()) * 20.0;
        let ball = Ball {
            inv: None,
            centre,
            radius: r * (1.0 + 1e-6),
        };
        let far = if case % 2 == 0 { 3.0 } else { 300.0 };
        let o = centre + DVec3::new(rnd(), rnd(), rnd()) * r * far;
        // Aim at a point near the sphere's surface (grazing) or inside it.
        let aim = centre + DVec3::new(rnd(), rnd(), rnd()).normalize() * r * (1.0 + 1e-9 * rnd());
        let ray = Ray::new(o, (aim - o) * (0.5 + rnd().abs()));
        let chord = ball.chord(&ray);
        for k in 0..=4000 {
            let t = k as f64 * 0.001;
            let p = ray.at(t);
            if (p - centre).length_squared() < r * r {
                let (b0, b1) = chord.expect("a point inside, but no chord");
                assert!(b0 <= t && t <= b1, "{t} {b0} {b1}");
            }
        }
    }
}

/// A sphere's ball carried into world space through a turn, an even scale and a move (and
/// through maps that squash it by up to 1e-6) holds the map of every point of the padded
/// ball; a map that squashes it more keeps the ball in the sphere's space.
#[test]
fn world_ball_holds_the_mapped_ball() {
    let mut unit = crate::math::xorshift_unit(0x5851_f42d_4c95_7f2d);
    let mut rnd = move || unit() * 2.0 - 1.0;
    for case in 0..3000 {
        let axis = DVec3::new(rnd(), rnd(), rnd()).normalize();
        let scale = 10f64.powf(3.0 * rnd());
        let squash = match case % 3 {
            0 => DVec3::ONE,
            1 => DVec3::new(1.0, 1.0 + 2e-7 * rnd(), 1.0 - 2e-7 * rnd().abs()),
            _ => DVec3::new(1.0, 1.0 + 1e-3 + rnd().abs(), 1.0),
        };
        let m = DMat4::from_scale_rotation_translation(
            squash * scale,
            glam::DQuat::from_axis_angle(axis, 3.0 * rnd()),
            DVec3::new(rnd(), rnd(), rnd()) * 10f64.powf(4.0 * rnd()),
        );
        let centre = DVec3::new(rnd(), rnd(), rnd()) * 5.0;
        let radius = (0.1 + rnd().abs() * 3.0) * (1.0 + 1e-6);
        let Some(b) = world_ball(&m, centre, radius) else {
            assert_eq!(case % 3, 2, "{m:?}");
            continue;
        };
        assert_ne!(case % 3, 2, "{m:?}");
        for _ in 0..200 {
            let v = DVec3::new(rnd(), rnd(), rnd()).normalize() * radius;
            let p = m.transform_point3(centre + v);
            assert!((p - b.centre).length() <= b.radius, "{p} {:?}", b.centre);
        }
    }
}

/// A window of turned half-spaces holds the `t` of every point of the ray inside them,
/// and says `Empty` only when the ray has no such point.
#[test]
fn plane_window_holds_the_points_inside() {
    let mut unit = crate::math::xorshift_unit(0x2545_f491_4f6c_dd1d);
    let mut rnd = move || unit() * 2.0 - 1.0;
    for case in 0..2000 {
        let n = DVec3::new(rnd(), rnd(), rnd()).normalize();
        let m = DVec3::new(rnd(), rnd(), rnd()).normalize();
        let planes = [(n, 0.5), (-n, 0.5), (m, 2.0 + rnd()), (-m * 3.0, 3.0)];
        let Some(w) = Window::choose(None, &planes) else {
            panic!("no window");
        };
        let scale = if case % 2 == 0 { 1.0 } else { 1e-9 };
        let ray = Ray::new(
            DVec3::new(rnd(), rnd(), rnd()) * 5.0,
            DVec3::new(rnd(), rnd(), rnd()) * scale,
        );
        let range = w.range(&ray);
        for k in 0..=200 {
            let t = (k as f64 - 100.0) * 0.1 / scale;
            let p = ray.at(t);
            if planes.iter().all(|&(n, d)| n.dot(p) <= d) {
                match range {
                    Range::All => {}
                    Range::Empty => panic!("empty, but {t} is inside"),
                    Range::Within(lo, hi) => assert!(lo <= t && t <= hi, "{t} {lo} {hi}"),
                }
            }
        }
    }
}

#[test]
fn boxes_through_maps() {
    let open_x = Aabb::new(
        DVec3::new(f64::NEG_INFINITY, 1.0, 2.0),
        DVec3::new(f64::INFINITY, 3.0, 4.0),
    );
    // Scale (with a mirror) and move: open sides stay open.
    let m = DMat4::from_scale_rotation_translation(
        DVec3::new(2.0, -1.0, 0.5),
        glam::DQuat::IDENTITY,
        DVec3::new(0.0, 5.0, 0.0),
    );
    let b = map_box(&open_x, &m).unwrap();
    assert_eq!(b.min, DVec3::new(f64::NEG_INFINITY, 2.0, 1.0));
    assert_eq!(b.max, DVec3::new(f64::INFINITY, 4.0, 2.0));
    // A rotation of an open box says nothing; of a finite one, its corners' box.
    let r = DMat4::from_rotation_y(0.5);
    assert!(map_box(&open_x, &r).is_none());
    let unit = Aabb::new(-DVec3::ONE, DVec3::ONE);
    let b = map_box(&unit, &r).unwrap();
    assert!(b.max.x > 1.0 && b.contains(r.transform_point3(DVec3::ONE)));
}

/// A difference's box leaves out what its subtracted planes take away, and answers every
/// query as the node without a box does, bit for bit: blobs and spheres less planes
/// (moved, rotated, scaled, inverted, one clipped, which does not count), with rays and
/// points on the planes themselves.
#[test]
fn difference_less_planes() {
    use crate::geom::test_rng::Lcg;
    use crate::math::Ray;
    use crate::scene::object::Scratch;
    const SCENE: &str = r#"
        #declare B = blob { threshold 0.6 sphere { 0, 1, 1 } sphere { 0, 1, 1 scale <0.3, 0.45, 0.8> } }
        difference { object { B } plane { y, 0 } plane { z, 0 inverse } plane { x, 0 inverse } scale <2, 1, 3> }
        difference { sphere { 0, 2 } plane { x, 0.5 rotate z * 30 } plane { y, -1 } translate x }
        difference { object { B } plane { y, 0 clipped_by { sphere { 0, 0.5 } } } }
        difference { box { -1, 1 } plane { x, 0 } plane { -x, -0.5 } rotate <10, 20, 30> }
    "#;
    let scene = || crate::scene::csg_hit::tests::built(SCENE);
    let culled = scene();
    let mut bare = scene();
    for o in &mut bare.objects {
        if let ObjKind::Csg { cull, .. } = &mut o.kind {
            *cull = None;
        }
    }
    let boxes: Vec<Option<Aabb>> = culled
        .objects
        .iter()
        .map(|o| match &o.kind {
            ObjKind::Csg { cull: Some(c), .. } => c.aabb,
            _ => None,
        })
        .collect();
    // The octant of the blob's box; the sphere's box above y = -1.
    let b = boxes[0].unwrap();
    assert!(b.max.x < 1e-3 && b.min.y > -1e-3 && b.max.z < 1e-3, "{b:?}");
    let b = boxes[1].unwrap();
    assert!(b.min.y > -1.0 - 1e-3, "{b:?}");
    // The clipped plane leaves the blob's own box.
    assert!(boxes[2].is_none_or(|b| b.min.y < -0.4), "{:?}", boxes[2]);
    let mut rng = Lcg(3);
    let (mut sa, mut sb) = (Scratch::default(), Scratch::default());
    for (a, b) in culled.objects.iter().zip(&bare.objects) {
        let mut hits = 0;
        for k in 0..4000 {
            // Every third ray starts on a plane of the scene and runs in it or across it.
            let ray = if k % 3 == 0 {
                let mut q = rng.vec(3.0);
                q[k % 2] = 0.0;
                Ray::new(q, [DVec3::X, DVec3::Y, DVec3::Z, rng.vec(1.0)][k % 4])
            } else {
                Ray::new(rng.vec(8.0), rng.vec(2.0))
            };
            let tmax = if rng.next() < 0.3 { 3.0 } else { f64::INFINITY };
            hits += super::window_tests::same_hits(a, b, &ray, tmax, &mut sa, &mut sb) as usize;
            let mut p = rng.vec(4.0);
            p[k % 3] = 0.0;
            assert_eq!(a.inside(p), b.inside(p));
        }
        assert!(hits > 30, "{hits}");
    }
}
