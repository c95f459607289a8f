//! Unit tests of `scene::csg_lead`: nodes with a lead answer `first_hit` and `any_hit` as
//! `all_hits` does, bit for bit, for rays starting on their surfaces (where the lead's
//! certificates hold) as well as from anywhere.

use super::{beyond_after, beyond_before, lead_leaf, Lead};
use crate::geom::test_rng::Lcg;
use crate::math::{DVec3, Ray, EPSILON};
use crate::scene::csg_hit::tests::{answers_as_reference, built, reference};
use crate::scene::object::{Object, Scratch};

/// The woods' boards (a folded lead, moved, turned, scaled), a difference whose first
/// member, a box, is the lead, an intersection whose first member is a cylinder (no lead:
/// only boxes lead, `csg_lead::boxed`), a clipped one, a lead under a turn (bounds wider
/// than the box), an inverted node, and two nodes a box would lead where it does not pay
/// (`csg_lead::pays`): a difference of boxes, and a box whose faces a cylinder cuts away
/// (which is then left out of the searches instead: `csg_lead::shut_of`).
const SCENE: &str = r#"
    #declare Disk_X = cylinder { x, -x, 1 }
    #declare Disk_Y = cylinder { y, -y, 1 }
    #declare Test = intersection {
        intersection { box { -1, 1 scale <1, 1, 0.95> } object { Disk_X scale 1.15 } }
        object { Disk_Y scale 1.15 } }
    object { Test translate <-2.1, 4.2, 0> }
    object { Test rotate <10, 20, 30> translate <0.5, -1, 3> }
    object { Test scale <1e-3, 2e-3, 1e-3> translate <1e3, 0, 0> }
    difference { box { -1, 1 } cylinder { -2 * z, 2 * z, 0.5 } sphere { y, 0.7 } }
    intersection { cylinder { -x, x, 1 } box { <-2, -0.5, -0.5>, <2, 0.5, 2> } sphere { 0, 1.3 } }
    intersection { box { -1, 1 } object { Disk_X scale 1.4 } clipped_by { plane { y, 0.3 } } }
    intersection { box { -1, 1 rotate 30 * z } sphere { 0.3 * x, 1.5 } }
    intersection { box { -1, 1 } sphere { 0, 1.35 } inverse }
    difference { box { -1, 1 } box { -0.5, 0.5 } }
    intersection { box { -1, 1 } object { Disk_X scale 0.9 } }
"#;

/// 20,000 rays around a node: aimed near `c` from within three `size`s of it, so that most
/// meet it, a fifth with `tmax` = `size`; every other one restarted where the first ray meets
/// `o` (the reference's answer), as shadow rays leave a surface, and skipped when it misses.
/// Gives `f` the ray's number, the ray, its `tmax` and `sb`; returns how many started on the
/// surface.
fn rays_around<'a>(
    o: &'a Object,
    c: DVec3,
    size: f64,
    rng: &mut Lcg,
    sb: &mut Scratch<'a>,
    mut f: impl FnMut(usize, &Ray, f64, &mut Scratch<'a>),
) -> usize {
    let mut on_surface = 0;
    for k in 0..20000 {
        let from = c + rng.vec(3.0 * size);
        let mut ray = Ray::new(from, c + rng.vec(size) - from);
        let tmax = if rng.next() < 0.2 {
            size
        } else {
            f64::INFINITY
        };
        if k % 2 == 1 {
            match reference(o, &ray, f64::INFINITY, sb) {
                Some(h) => {
                    ray = Ray::new(ray.at(h.t), rng.vec(2.0));
                    on_surface += 1;
                }
                None => continue,
            }
        }
        f(k, &ray, tmax, sb);
    }
    on_surface
}

/// The centre and largest extent of a node's bounds, or of the unit box where they are
/// infinite (an inverted member).
fn centre_and_size(o: &Object) -> (DVec3, f64) {
    let b = if o.bounds.is_finite() {
        o.bounds
    } else {
        crate::math::Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0))
    };
    (b.center(), (b.max - b.min).max_element())
}

#[test]
fn leads_answer_as_all_hits() {
    let scene = built(SCENE);
    let leads: Vec<Lead> = scene.objects.iter().map(Object::lead).collect();
    assert_eq!(
        leads,
        [
            Lead::Folded,
            Lead::Folded,
            Lead::Folded,
            Lead::Member,
            Lead::None,
            Lead::Member,
            Lead::Member,
            Lead::Member,
            Lead::None,
            Lead::Shut(0)
        ]
    );
    let mut rng = Lcg(33);
    let (mut sa, mut sb) = (Scratch::default(), Scratch::default());
    for (n, o) in scene.objects.iter().enumerate() {
        let super::super::object::ObjKind::Csg { children, .. } = &o.kind else {
            panic!("object {n} is a node");
        };
        let lead = lead_leaf(leads[n], children);
        // Around the lead (an inverted node's own bounds are infinite).
        let c = lead.bounds.center();
        let size = (lead.bounds.max - lead.bounds.min).max_element();
        let (mut after, mut before) = (0, 0);
        let on_surface = rays_around(o, c, size, &mut rng, &mut sb, |k, ray, tmax, sb| {
            after += beyond_after(ray, &lead.bounds, EPSILON) as usize;
            if let Some(h) = reference(o, ray, tmax, sb) {
                before += beyond_before(ray, &lead.bounds, h.t) as usize;
            }
            let what = format!("object {n}, ray {k}");
            answers_as_reference(o, ray, tmax, (&mut sa, sb), &what);
        });
        // Rays from the surface on every object; the certificates put to the test on the
        // boards whose box is not turned (a turned box's bounds are wider than it).
        assert!(on_surface > 1000, "object {n}: {on_surface}");
        if n == 0 {
            assert!(after > 200 && before > 50, "object {n}: {after} {before}");
        }
    }
}

/// `beyond_after` and `beyond_before` at the doubles next to a face: the point at `t0` must
/// be strictly past it, as `Aabb::holds` counts a point on a face as held.
#[test]
fn certificates_at_the_faces() {
    let b = crate::math::Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0));
    let ray = Ray::new(DVec3::new(0.0, 0.0, -1.0), DVec3::new(0.0, 0.0, -1.0));
    assert!(!beyond_after(&ray, &b, 0.0));
    assert!(beyond_after(&ray, &b, 1e-15));
    // -3 + 2 (1 - 2^-53) is -1 - 2^-52, short of the face; -3 + 2 (1 + 2^-52) is past it.
    let ray = Ray::new(DVec3::new(0.0, 0.0, -3.0), DVec3::new(0.0, 0.0, 2.0));
    assert!(beyond_before(&ray, &b, 1.0));
    assert!(!beyond_before(
        &ray,
        &b,
        f64::from_bits(1.0f64.to_bits() + 2)
    ));
    // -2 + (1 - 2^-53) rounds to -1 itself: on the face, held, so no certificate.
    let ray = Ray::new(DVec3::new(0.0, 0.0, -2.0), DVec3::Z);
    assert!(!beyond_before(&ray, &b, 1.0));
    assert!(!beyond_before(&ray, &b, 0.0));
    assert!(!beyond_before(&ray, &b, f64::NAN));
    let ray = Ray::new(DVec3::new(0.0, 0.0, -2.0), DVec3::X);
    assert!(!beyond_before(&ray, &b, 1.0) && !beyond_after(&ray, &b, 1.0));
}

/// Nodes whose box member `shut_of` leaves out (whiltile's tile turned, moved and scaled; the
/// box under its own turn and scale, the cylinders under another; the box last, not first),
/// and nodes where it must not: the cylinders reach the box's faces (radius 1), a member
/// whose bounds are infinite but inverted (nothing bounds the sphere's outside), and a
/// difference (whose box leads instead).
const SHUT_SCENE: &str = r#"
    #declare Tile = intersection {
        box { -1, 1 }
        cylinder { -2 * x, 2 * x, 0.9 }
        cylinder { -2 * z, 2 * z, 0.9 }
        sphere { 0, 2.0 translate 2.6 * y inverse }
        scale <0.5, 0.2, 0.5> }
    object { Tile translate <3, 0, -2> rotate 30 * y }
    intersection {
        box { -1, 1 rotate <5, 10, 15> scale 1.2 }
        cylinder { -2 * x, 2 * x, 0.8 rotate 7 * z }
        sphere { 0, 0.6 }
        translate <1e3, 0, 0> }
    intersection { cylinder { -2 * x, 2 * x, 0.9 } cylinder { -2 * z, 2 * z, 0.9 } box { -1, 1 } }
    intersection { box { -1, 1 } cylinder { -2 * x, 2 * x, 1 } cylinder { -2 * z, 2 * z, 1 } }
    intersection { box { -1, 1 } sphere { 0, 1.5 inverse } }
    difference { box { -1, 1 } cylinder { -2 * x, 2 * x, 0.9 } }
"#;

#[test]
fn shut_boxes_answer_as_all_hits() {
    let scene = built(SHUT_SCENE);
    let leads: Vec<Lead> = scene.objects.iter().map(Object::lead).collect();
    assert_eq!(
        leads,
        [
            Lead::Shut(0),
            Lead::Shut(0),
            Lead::Shut(2),
            Lead::None,
            Lead::None,
            Lead::Member
        ]
    );
    let mut rng = Lcg(36);
    let (mut sa, mut sb) = (Scratch::default(), Scratch::default());
    for (n, o) in scene.objects.iter().enumerate() {
        let (c, size) = centre_and_size(o);
        let on_surface = rays_around(o, c, size, &mut rng, &mut sb, |k, ray, tmax, sb| {
            let what = format!("object {n}, ray {k}");
            answers_as_reference(o, ray, tmax, (&mut sa, sb), &what);
        });
        assert!(on_surface > 1000, "object {n}: {on_surface}");
    }
}

/// `all_hits` of a shut node (which leaves its box out) lists the same crossings, in the
/// same order, bit for bit, as the same node with the box gathered (its lead cleared): none
/// of the box's crossings is kept.
#[test]
fn shut_all_hits_answer_as_gathered() {
    let scene = built(SHUT_SCENE);
    let mut gathered = built(SHUT_SCENE);
    for o in &mut gathered.objects {
        if let super::super::object::ObjKind::Csg { cull: Some(c), .. } = &mut o.kind {
            if matches!(c.lead, Lead::Shut(_)) {
                c.lead = Lead::None;
            }
        }
    }
    let mut rng = Lcg(136);
    let (mut sa, mut sb) = (Scratch::default(), Scratch::default());
    let mut listed = 0;
    for (n, (o, g)) in scene.objects.iter().zip(&gathered.objects).enumerate() {
        let (c, size) = centre_and_size(o);
        for k in 0..20000 {
            let from = c + rng.vec(3.0 * size);
            let mut ray = Ray::new(from, c + rng.vec(size) - from);
            if k % 2 == 1 {
                // From a crossing, as the transparent shadow rays start.
                sb.surface.clear();
                g.all_hits(&ray, f64::INFINITY, &mut sb);
                match sb.surface.first() {
                    Some(h) => ray = Ray::new(ray.at(h.t), rng.vec(2.0)),
                    None => continue,
                }
            }
            let tmax = if rng.next() < 0.2 {
                size
            } else {
                f64::INFINITY
            };
            sa.surface.clear();
            sb.surface.clear();
            o.all_hits(&ray, tmax, &mut sa);
            g.all_hits(&ray, tmax, &mut sb);
            let bits = |s: &Scratch| -> Vec<(u64, u32, bool)> {
                s.surface
                    .iter()
                    .map(|h| (h.t.to_bits(), h.hit.part, h.flip))
                    .collect()
            };
            assert_eq!(bits(&sa), bits(&sb), "object {n}, ray {k}");
            listed += sa.surface.len();
        }
    }
    assert!(listed > 10000, "{listed}");
}
