//! Unit tests of `scene::csg_hit`: the searches against `all_hits` bit for bit, the short
//! lists' sort against `sort_unstable`.

use super::{order_entry, sort_crossings};
use crate::geom::test_rng::Lcg;
use crate::math::{DVec3, Ray, EPSILON};
use crate::scene::object::{ObjKind, Object, Scratch, SurfaceHit};
use crate::sdl::{ParseOptions, Parser};

/// The built scene of `text` (csg_boxes' tests use it too).
pub(in crate::scene) fn built(text: &str) -> crate::scene::build::Scene {
    let mut p = Parser::new(ParseOptions::default());
    p.parse_str("t.pov", text)
        .map_err(|e| e.message.clone())
        .unwrap();
    crate::scene::build::build(&p.scene, 64, 48).scene
}

/// What two crossings must share bit for bit.
fn key(h: &SurfaceHit) -> (u64, bool, u32) {
    (h.t.to_bits(), h.flip, h.hit.part)
}

/// The short lists' insertion sort gives `sort_unstable`'s order: lists of every length
/// up to past the cut-over, with ties in the key (and in the tag) broken by the place, the
/// entries packed by `order_entry` (whose integer order must be the tuple's).
#[test]
fn crossings_sort_as_sort_unstable() {
    let mut rng = Lcg(3);
    for n in 0..14 {
        for _ in 0..500 {
            let mut places: Vec<u32> = (0..n as u32).collect();
            // Places in any order, keys from a few values so that they tie.
            for k in (1..places.len()).rev() {
                places.swap(k, (rng.next() * (k + 1) as f64) as usize % (k + 1));
            }
            let b: Vec<(i64, u32, u32)> = places
                .iter()
                .map(|&j| ((rng.next() * 5.0) as i64 - 2, j, (rng.next() * 3.0) as u32))
                .collect();
            // Keys across the sign and at the ends, as `order_key` gives them.
            let b: Vec<_> = b
                .into_iter()
                .map(|(k, j, g)| match k {
                    -2 => (i64::MIN, j, g),
                    2 => (i64::MAX, j, g),
                    k => (k, j, g),
                })
                .collect();
            let mut a: Vec<u128> = b.iter().map(|&(k, j, g)| order_entry(k, j, g)).collect();
            let mut b = b;
            sort_crossings(&mut a);
            b.sort_unstable();
            let b: Vec<u128> = b.iter().map(|&(k, j, g)| order_entry(k, j, g)).collect();
            assert_eq!(a, b);
        }
    }
}

/// Asserts that `o.first_hit` and `o.any_hit` answer as `reference` does, bit for bit (the
/// crossing's `t`, side, object and part), and that the search leaves `sa` as it found it;
/// whether there is a hit. `what` names the case in a failure.
pub(in crate::scene) fn answers_as_reference<'a>(
    o: &'a Object,
    ray: &Ray,
    tmax: f64,
    (sa, sb): (&mut Scratch<'a>, &mut Scratch<'a>),
    what: &str,
) -> bool {
    let key = |h: Option<SurfaceHit>| {
        h.map(|h| (h.t.to_bits(), h.flip, h.obj as *const Object, h.hit.part))
    };
    let want = key(reference(o, ray, tmax, sb));
    assert_eq!(key(o.first_hit(ray, tmax, sa)), want, "{what}");
    assert_eq!(o.any_hit(ray, tmax, sa), want.is_some(), "{what}");
    assert!(sa.surface.is_empty() && sa.csg_order.is_empty() && sa.csg_hits.is_empty());
    want.is_some()
}

/// `first_hit` as `all_hits` defines it: the nearest crossing (t > EPSILON when clipped),
/// the earliest listed of equal ones (csg_boxes' and csg_framed's tests use it too).
pub(in crate::scene) fn reference<'a>(
    o: &'a Object,
    ray: &Ray,
    tmax: f64,
    s: &mut Scratch<'a>,
) -> Option<SurfaceHit<'a>> {
    s.surface.clear();
    o.all_hits(ray, tmax, s);
    let best = s
        .surface
        .iter()
        .filter(|h| o.clip.is_empty() || h.t > EPSILON)
        .min_by(|a, b| a.t.total_cmp(&b.t))
        .copied();
    s.surface.clear();
    best
}

/// The searches answer as `all_hits` does, bit for bit and with the same surface and
/// side: nested intersections (folded, and not: inverse, clipped), clipped differences,
/// unions and leaves, with rays from inside and outside and along the members' faces.
#[test]
fn searches_match_all_hits() {
    const SCENE: &str = r#"
        #declare Disk_X = cylinder { x, -x, 1 }
        #declare Disk_Y = cylinder { y, -y, 1 }
        #declare Disk_Z = cylinder { z, -z, 1 }
        intersection { intersection { box { -1, 1 scale <1, 1, 0.95> } object { Disk_X scale 1.15 } }
                       object { Disk_Y scale 1.15 } rotate <10, 20, 30> }
        intersection { sphere { 0, 1.2 } intersection { box { -1, 1 } plane { x + y, 0.5 } } }
        difference { box { -1, 1 } intersection { sphere { x, 1 } sphere { -x, 1.5 } } sphere { y, 0.7 } }
        intersection { intersection { box { -1, 1 } sphere { 0, 1.3 } inverse } sphere { 0, 1.6 } }
        intersection { intersection { box { -1, 1 } sphere { 0, 1.3 } clipped_by { plane { y, 0.2 } } } sphere { 0, 1.6 } }
        merge { intersection { box { -1, 1 } sphere { 0, 1.3 } } sphere { x, 0.8 } }
        difference { box { -1, 1 } object { Disk_Z scale <0.85, 0.75, 1.5> } object { Disk_X scale <1.15, 0.7, 0.7> }
                     clipped_by { plane { -y, 0 } } scale <1, 2, 1> }
        union { plane { z, 0 } plane { y, 0 inverse }
                cylinder { <-3, 1, -1>, <3, 1, -1>, 1 clipped_by { box { <-2, 0, -1>, <2, 1, 0> } } }
                clipped_by { box { <-1.9, -0.1, -100>, <2.1, 100, 1> } } rotate -y * 2 }
        sphere { 0, 1 clipped_by { plane { y, 0.25 } } translate x }
        sphere { 0, 1 clipped_by { plane { y, 0.25 } plane { x, 0.1 } } inverse }
        plane { z, 0.1 clipped_by { box { -2, 2 } } translate <-0.5, 0.3, 0> }
        plane { <1, 1, 0>, 0.2 clipped_by { sphere { 0, 1.5 } } inverse rotate 30 * z }
        intersection { quadric { <0, 1, 1>, 0, 0, -1 } quadric { <1, 0, 1>, 0, 0, -1 }
                       quadric { <0, 1, 1>, 0, 0, -1 inverse scale <1, 0.5, 0.5> }
                       quadric { <1, 0, 1>, 0, 0, -1 inverse scale <0.5, 1, 0.5> } rotate y * 45 }
        difference { box { -1, 1 } #for (i, 0, 9) sphere { <i / 5 - 0.9, 0.5, 0.3>, 0.3 } #end
                     clipped_by { sphere { 0, 1.5 } } }
        intersection { #for (i, 0, 9) sphere { <i / 20, 0, 0>, 1.2 } #end }
        difference { quadric { <1, 1, 1>, 0, 0, -1.4 } quadric { <0, 1, 1>, 0, <0, 0.2, 0>, -0.3 }
                     quadric { <1, 0, 1>, 0, 0, -0.3 } rotate <20, 30, 0> translate <0.2, 0, 0.1> }
        merge { quadric { <1, 1, 0.5>, 0, 0, -1 } quadric { <1, 0, 1>, 0, 0, -0.5 } scale <1, 1.5, 1> }
    "#;
    let scene = built(SCENE);
    let mut rng = Lcg(11);
    let (mut sa, mut sb) = (Scratch::default(), Scratch::default());
    for (n, o) in scene.objects.iter().enumerate() {
        let mut hits = 0;
        for k in 0..6000 {
            // Every third ray runs along an axis through a point on a face of the box.
            let ray = if k % 3 == 0 {
                let mut q = rng.vec(2.0);
                q[k % 2] = [1.0, -1.0, 0.0][k % 3];
                Ray::new(q, [DVec3::X, DVec3::Y, DVec3::Z, rng.vec(1.0)][k % 4])
            } else {
                Ray::new(rng.vec(5.0), rng.vec(2.0))
            };
            let tmax = if rng.next() < 0.3 { 2.5 } else { f64::INFINITY };
            let what = format!("object {n}, ray {k}");
            hits += answers_as_reference(o, &ray, tmax, (&mut sa, &mut sb), &what) as usize;
        }
        assert!(hits > 100, "object {n}: {hits}");
    }
}

/// Nodes whose members are all faces (`faces_first_hit`) answer as the general search
/// (`csg_first_hit`) and as `all_hits` do, bit for bit: polyhedra rotated, scaled from
/// 1e-4 to 1e5 and moved far out; members inverted, coincident and duplicated faces; a
/// difference, a merge and an inverted node. Rays at random, along axes through lattice
/// points (in and grazing the cube's faces and edges), through vertices, starting on the
/// surface (at a crossing of an earlier ray), and far out (points beyond `point_ok`).
#[test]
fn polyhedra_match_the_general_search() {
    const DODECAHEDRON: &str = r#"
        plane { -z, 1 rotate <-26.56505117708, 0, 0> }
        plane { -z, 1 rotate <-26.56505117708, -72, 0> }
        plane { -z, 1 rotate <-26.56505117708, -144, 0> }
        plane { -z, 1 rotate <-26.56505117708, -216, 0> }
        plane { -z, 1 rotate <-26.56505117708, -288, 0> }
        plane { -z, 1 rotate <26.56505117708, -36, 0> }
        plane { -z, 1 rotate <26.56505117708, -108, 0> }
        plane { -z, 1 rotate <26.56505117708, -180, 0> }
        plane { -z, 1 rotate <26.56505117708, -252, 0> }
        plane { -z, 1 rotate <26.56505117708, -324, 0> }
        plane { y, 1 } plane { -y, 1 }
    "#;
    const CUBE: &str = "plane { x, 1 } plane { -x, 1 } plane { y, 1 } plane { -y, 1 } \
                        plane { z, 1 } plane { -z, 1 }";
    let scene_text = format!(
        r#"
        intersection {{ {DODECAHEDRON} translate y * 1.8 rotate x * 72 rotate z * 144 }}
        intersection {{ {DODECAHEDRON} scale 1e-4 translate <1e-4, 0, 0> }}
        intersection {{ {DODECAHEDRON} scale 1e5 rotate <10, 20, 30> translate 1e6 }}
        intersection {{ {CUBE} }}
        intersection {{ {CUBE} scale <1, 1e-3, 1e3> }}
        intersection {{ {CUBE} plane {{ y, 1 }} plane {{ y, 1 rotate z * 45 }} rotate y * 45 }}
        intersection {{ {CUBE} plane {{ y, 0 inverse }} rotate <0, 0, 30> }}
        intersection {{ {CUBE} inverse }}
        difference {{ plane {{ y, 1 }} plane {{ y, 0.5 inverse }} plane {{ -x, 0.3 inverse rotate z * 45 }} }}
        merge {{ plane {{ y, 0 }} plane {{ x, 0 }} plane {{ -z, 1 rotate x * 30 }} }}
        intersection {{ plane {{ y, 1 }} plane {{ -y, -1 }} plane {{ x, 1 }} }}
    "#
    );
    let scene = built(&scene_text);
    let big = if cfg!(debug_assertions) {
        4_000
    } else {
        150_000
    };
    let mut rng = Lcg(29);
    let (mut sa, mut sb) = (Scratch::default(), Scratch::default());
    let key = |h: Option<SurfaceHit>| {
        h.map(|h| (h.t.to_bits(), h.flip, h.obj as *const Object, h.hit.part))
    };
    let mut indexed = 0;
    for (n, o) in scene.objects.iter().enumerate() {
        let ObjKind::Csg {
            op,
            children,
            index,
            cull: Some(cull),
        } = &o.kind
        else {
            panic!("object {n} is not a node with faces");
        };
        assert!(
            cull.faces.as_ref().is_some_and(|f| f.all().is_some()),
            "object {n}"
        );
        indexed += index.is_some() as usize;
        // The object's scale and place, for rays that reach it.
        let b = cull.aabb.unwrap_or(o.bounds);
        let finite = b.min.is_finite() && b.max.is_finite();
        let (lo, hi) = if finite {
            (b.min, b.max)
        } else {
            (DVec3::splat(-3.0), DVec3::splat(3.0))
        };
        let (centre, size) = ((lo + hi) * 0.5, (hi - lo).max_element().max(1e-4));
        let mut on_surface = None;
        let (mut hits, mut surface_starts) = (0, 0);
        for k in 0..big {
            let axis = [
                DVec3::X,
                DVec3::Y,
                DVec3::Z,
                -DVec3::X,
                -DVec3::Y,
                -DVec3::Z,
            ];
            let ray = match k % 6 {
                // Along an axis from a lattice point of the cube's faces (-1, 0, 1).
                0 => Ray::new(
                    (rng.vec(6.0))
                        .round()
                        .clamp(DVec3::splat(-1.0), DVec3::splat(1.0))
                        * [1.0, 1.5, 3.0][k % 3],
                    axis[(k / 6) % 6],
                ),
                // From a crossing of an earlier ray.
                1 if on_surface.is_some() => {
                    surface_starts += 1;
                    Ray::new(on_surface.unwrap(), rng.vec(2.0))
                }
                // Through a point at random on the object's scale, from far or near.
                2 | 3 => {
                    let target = centre + rng.vec(size * 1.2);
                    let from = centre + rng.vec(size * [3.0, 40.0][k % 2]);
                    Ray::new(from, (target - from) * [1.0, 1e-3, 1e3][k % 3])
                }
                // Far out, where points leave the faces' limits.
                4 if k % 60 == 4 => Ray::new(rng.vec(2e150), rng.vec(1e10)),
                _ => Ray::new(rng.vec(8.0), rng.vec(2.0)),
            };
            let tmax = match k % 7 {
                0 => 2.5,
                1 => -1.0,
                _ => f64::INFINITY,
            };
            let want = key(reference(o, &ray, tmax, &mut sb));
            let general = o.csg_first_hit::<false, false, false>(
                *op,
                children,
                index.as_deref(),
                (cull.aabb.as_ref(), cull.faces.as_ref()),
                &ray,
                tmax,
                &mut sb,
            );
            assert_eq!(key(general), want, "object {n}, ray {k}");
            let got = o.first_hit(&ray, tmax, &mut sa);
            assert_eq!(key(got), want, "object {n}, ray {k}");
            assert_eq!(
                o.any_hit(&ray, tmax, &mut sa),
                want.is_some(),
                "object {n}, ray {k}"
            );
            assert!(sa.surface.is_empty() && sa.csg_order.is_empty() && sa.csg_hits.is_empty());
            if let Some(h) = got {
                hits += 1;
                on_surface = Some(ray.at(h.t)).filter(|p| p.abs().max_element() < 1e140);
            }
        }
        assert!(
            hits > big / 100 && surface_starts > big / 100,
            "object {n}: {hits}"
        );
    }
    // The dodecahedra (twelve members) and the cubes with two more faces have an index.
    assert_eq!(indexed, 4);
}

/// Unions ask their plane members through their faces (`scene::faces`) and answer as
/// without them, bit for bit: quilt1's clipped floor and wall, rotated; a plain union of
/// planes and a sphere; and a union big enough for an index, which keeps no faces (its
/// index numbers leaves, not members).
#[test]
fn unions_answer_through_faces_as_without() {
    const SCENE: &str = r#"
        union { plane { z, 0 hollow on } plane { y, 0 inverse }
                cylinder { <-200, 1, -1>, <200, 1, -1>, 1 clipped_by { box { <-100, 0, -1>, <100, 1, 0> } } }
                clipped_by { box { <-99.9, -0.1, -10000>, <100.1, 1000, 1> } } rotate -y * 2 }
        union { plane { x, 0.5 rotate <10, 20, 30> } plane { -y, 0.25 scale 2 } sphere { 0, 1 } }
        union { plane { x, 0.5 rotate <10, 20, 30> } plane { -y, 0.25 } sphere { 0, 1 }
                clipped_by { sphere { 0, 2 } } inverse }
        union {
          #local I = 0;
          #while (I < 14)
            sphere { <I, 0, 0>, 0.4 }
            #local I = I + 1;
          #end
          plane { z, 1 } plane { y, -1 rotate x * 5 }
        }
    "#;
    let (with, mut without) = (built(SCENE), built(SCENE));
    let faces = |o: &Object| match &o.kind {
        ObjKind::Csg { cull, .. } => cull.as_ref().is_some_and(|c| c.faces.is_some()),
        ObjKind::Shape(..) => false,
    };
    let has: Vec<bool> = with.objects.iter().map(faces).collect();
    assert_eq!(has, [true, true, true, false]);
    for o in &mut without.objects {
        if let ObjKind::Csg { cull: Some(c), .. } = &mut o.kind {
            c.faces = None;
        }
    }
    let mut rng = Lcg(5);
    let (mut sa, mut sb) = (Scratch::default(), Scratch::default());
    for (n, (a, b)) in with.objects.iter().zip(&without.objects).enumerate() {
        let mut hits = 0;
        for k in 0..4000 {
            let ray = if k % 4 == 0 {
                Ray::new(rng.vec(3.0).round(), [DVec3::X, DVec3::Y, DVec3::Z][k % 3])
            } else {
                Ray::new(rng.vec(6.0), rng.vec(2.0))
            };
            let tmax = if rng.next() < 0.3 { 2.5 } else { f64::INFINITY };
            let ha = a.first_hit(&ray, tmax, &mut sa);
            let hb = b.first_hit(&ray, tmax, &mut sb);
            assert_eq!(
                ha.as_ref().map(key),
                hb.as_ref().map(key),
                "object {n}, ray {k}"
            );
            assert_eq!(
                a.any_hit(&ray, tmax, &mut sa),
                hb.is_some(),
                "object {n}, ray {k}"
            );
            a.all_hits(&ray, tmax, &mut sa);
            b.all_hits(&ray, tmax, &mut sb);
            let list = |s: &Scratch| -> Vec<_> { s.surface.iter().map(key).collect() };
            assert_eq!(list(&sa), list(&sb), "object {n}, ray {k}");
            sa.surface.clear();
            sb.surface.clear();
            hits += hb.is_some() as usize;
        }
        assert!(hits > 100, "object {n}: {hits}");
    }
}
