//! Unit tests of `scene::children`: the union's child index, its walks and its copied leaf
//! boxes against the members' own answers.

use crate::geom::test_rng::Lcg;
use crate::math::{DVec3, Ray};
use crate::scene::csg_boxes::Search;
use crate::scene::csg_hit::tests::built;
use crate::scene::object::{ObjKind, Object, Scratch, SurfaceHit};

/// CSG nodes of many members, with exactly coincident surfaces (ties), unbounded and
/// inverted members, nested nodes and clipping.
const SCENE: &str = r#"
    #declare R = seed(3);
    #macro Parts()
      #local I = 0;
      #while (I < 30)
        #local C = <rand(R), rand(R), rand(R)> * 6 - 3;
        #if (mod(I, 3) = 0)
          box { C - 1, C + 1 }
          box { C - 1, C + 1 pigment { rgb 1 } }
        #else
          sphere { C, 0.3 + rand(R) }
        #end
        #local I = I + 1;
      #end
      plane { y, -2.5 }
      sphere { 0, 2.5 inverse }
      union { sphere { <1, 1, 1>, 1 } sphere { <1, 1, 1>, 1 } }
      union { box { -1, 1 } union { box { -1, 1 } sphere { 0, 1.2 } } inverse }
      union { box { -1, 1 } union { box { -1, 1 } sphere { 0, 1.2 } } clipped_by { plane { x, 0.5 } } }
    #end
    union { Parts() union { Parts() } union { union { Parts() } } }
    union { Parts() }
    merge { Parts() }
    difference { box { -3, 3 } Parts() }
    intersection {
      #local I = 0;
      #while (I < 12)
        sphere { <rand(R), rand(R), rand(R)> - 0.5, 2 + rand(R) }
        #local I = I + 1;
      #end
      box { -2, 2 }
      plane { x, 1 }
    }
    union { Parts() clipped_by { sphere { 0, 3 } } }
"#;

fn scene() -> crate::scene::build::Scene {
    // Nested unions, opened into their parent's index.
    built(SCENE)
}

fn strip(o: &mut Object) {
    if let ObjKind::Csg {
        children,
        index,
        cull,
        ..
    } = &mut o.kind
    {
        *index = None;
        *cull = None;
        children.iter_mut().for_each(strip);
    }
}

fn ordinal(root: &Object, leaf: &Object) -> Option<usize> {
    fn walk(o: &Object, leaf: &Object, n: &mut usize) -> bool {
        if std::ptr::eq(o, leaf) {
            return true;
        }
        *n += 1;
        let kids = match &o.kind {
            ObjKind::Csg { children, .. } => &children[..],
            ObjKind::Shape(..) => &[],
        };
        kids.iter().chain(&o.clip).any(|c| walk(c, leaf, n))
    }
    let mut n = 0;
    walk(root, leaf, &mut n).then_some(n)
}

fn key(h: &SurfaceHit) -> (u64, usize, bool) {
    (h.t.to_bits(), h.obj as *const Object as usize, h.flip)
}

/// Every query answers as the member scan does, bit for bit and in the same order.
#[test]
fn index_answers_as_the_scan() {
    let indexed = scene();
    let mut scanned = scene();
    scanned.objects.iter_mut().for_each(strip);
    assert!(indexed
        .objects
        .iter()
        .all(|o| matches!(&o.kind, ObjKind::Csg { index: Some(_), .. })));
    let mut rng = Lcg(11);
    let (mut sa, mut sb) = (Scratch::default(), Scratch::default());
    for (a, b) in indexed.objects.iter().zip(&scanned.objects) {
        let mut hits = 0;
        for _ in 0..3000 {
            let ray = Ray::new(rng.vec(14.0), rng.vec(2.0));
            let tmax = if rng.next() < 0.3 { 5.0 } else { f64::INFINITY };
            let ha = a.first_hit(&ray, tmax, &mut sa);
            let hb = b.first_hit(&ray, tmax, &mut sb);
            // The two scenes hold the same leaves: compare them by their place in the tree.
            let off = |h: Option<SurfaceHit>, root: &Object| {
                h.map(|h| (key(&h).0, ordinal(root, h.obj), h.flip))
            };
            assert_eq!(off(ha, a), off(hb, b));
            hits += ha.is_some() as usize;
            assert_eq!(a.any_hit(&ray, tmax, &mut sa), hb.is_some());
            a.all_hits(&ray, tmax, &mut sa);
            b.all_hits(&ray, tmax, &mut sb);
            let la: Vec<_> = sa.surface.iter().map(|h| (h.t.to_bits(), h.flip)).collect();
            let lb: Vec<_> = sb.surface.iter().map(|h| (h.t.to_bits(), h.flip)).collect();
            assert_eq!(la, lb);
            sa.surface.clear();
            sb.surface.clear();
            let p = rng.vec(8.0);
            assert_eq!(a.inside(p), b.inside(p));
        }
        assert!(hits > 10, "{hits}");
    }
}

/// Every index's copy of its leaves' boxes is the leaves' own `bounds`, bit for bit, in
/// the leaf order `leaf` reaches them by (nested, opened and unopened unions, a merge).
#[test]
fn leaf_bounds_are_the_leaves_bounds() {
    fn check(o: &Object, seen: &mut usize) {
        let ObjKind::Csg {
            children, index, ..
        } = &o.kind
        else {
            return;
        };
        if let Some(ix) = index {
            for (i, b) in ix.leaf_bounds.iter().enumerate() {
                let c = ix.leaf(children, i);
                let bits = |b: &crate::math::Aabb| {
                    [b.min.to_array(), b.max.to_array()].map(|v| v.map(f64::to_bits))
                };
                assert_eq!(bits(b), bits(&c.bounds));
                *seen += 1;
            }
        }
        children.iter().for_each(|c| check(c, seen));
    }
    let mut seen = 0;
    scene().objects.iter().for_each(|o| check(o, &mut seen));
    assert!(seen > 300, "{seen}");
}

/// `first_hit` of a CSG node (nearest first, stopping at the first crossing kept) is the
/// first least crossing of `all_hits`, bit for bit: polyhedra of transformed planes (their
/// faces meet along edges, where crossings tie), inverted, nested and subtracted.
#[test]
fn first_hit_is_the_least_of_all_hits() {
    const POLY: &str = r#"
        #declare R = seed(5);
        #declare Dodec = intersection {
          plane { -z, 1 rotate <-26.56505117708, 0, 0> }
          plane { -z, 1 rotate <-26.56505117708, -72, 0> }
          plane { -z, 1 rotate <-26.56505117708, -144, 0> }
          plane { -z, 1 rotate <-26.56505117708, -216, 0> }
          plane { -z, 1 rotate <-26.56505117708, -288, 0> }
          plane { z, 1 rotate <26.56505117708, -36, 0> }
          plane { z, 1 rotate <26.56505117708, -108, 0> }
          plane { z, 1 rotate <26.56505117708, -180, 0> }
          plane { z, 1 rotate <26.56505117708, -252, 0> }
          plane { z, 1 rotate <26.56505117708, -324, 0> }
          plane { y, 1 rotate <0, 0, 0> }
          plane { -y, 1 rotate <0, 0, 0> }
        }
        object { Dodec translate y * 1.8 rotate x * 72 }
        object { Dodec inverse scale 2 }
        difference { object { Dodec scale 2 } object { Dodec rotate y * 20 } sphere { 1.1 * x, 0.7 } }
        merge { object { Dodec } sphere { y, 1 } box { -0.5, <1, 2, 3> } }
        intersection { object { Dodec } box { -0.9, 2 } sphere { 0, 1.3 } plane { x, 0 } }
        intersection { plane { y, 0 } plane { y, 0 } plane { -y, 0 } box { -1, 1 } }
    "#;
    let scene = built(POLY);
    let mut rng = Lcg(7);
    let mut s = Scratch::default();
    assert_eq!(scene.objects.len(), 6);
    for o in &scene.objects {
        let mut hits = 0;
        for k in 0..4000 {
            // Every fourth ray starts on a vertex-ish lattice point and runs along an axis,
            // to meet faces at equal `t`.
            let ray = if k % 4 == 0 {
                let q = rng.vec(3.0);
                Ray::new(q.round(), [DVec3::X, DVec3::Y, DVec3::Z][k % 3])
            } else {
                Ray::new(rng.vec(6.0), rng.vec(2.0))
            };
            let tmax = if rng.next() < 0.3 { 3.0 } else { f64::INFINITY };
            let first = o.first_hit(&ray, tmax, &mut s).map(|h| key(&h));
            o.all_hits(&ray, tmax, &mut s);
            let least = s.surface.iter().min_by(|a, b| a.t.total_cmp(&b.t)).map(key);
            s.surface.clear();
            assert_eq!(first, least);
            hits += first.is_some() as usize;
        }
        // The last node, a flat slab, is met only by rays lying in it.
        assert!(
            hits > 50 || std::ptr::eq(o, scene.objects.last().unwrap()),
            "{hits}"
        );
    }
}

/// `Cull::folds`, set once, says what scanning the members for `folded` ones at every
/// search said, and `Cull::search` the search the two flags choose: nodes with and without members to fold, members that are not folded
/// (inverse, clipped, indexed), nested nodes and clipping objects, nodes with an index.
#[test]
fn folds_flag_is_the_members_scan() {
    let scene = built(
        r#"
        difference { box { -1, 1 } intersection { sphere { 0, 1 } box { 0, 2 } } }
        difference { box { -1, 1 } intersection { sphere { 0, 1 } box { 0, 2 } inverse } }
        merge { sphere { 0, 1 } intersection { sphere { 0, 1 } box { 0, 2 } clipped_by { plane { y, 0 } } } }
        intersection { box { -1, 1 } difference { box { -1, 1 } sphere { 0, 1 } }
                       clipped_by { intersection { sphere { 0, 2 } intersection { box { -1, 1 } sphere { 0, 1.2 } } } } }
        difference { box { -1, 1 } #for (i, 0, 40) sphere { <i / 20 - 1, 0, 0>, 0.1 } #end
                     intersection { sphere { 0, 1 } box { 0, 2 } } }
        difference { box { -1, 1 }
                     intersection { #for (i, 0, 40) sphere { <i / 200, 0, 0>, 1 } #end }
                     intersection { sphere { 0, 1 } intersection { box { 0, 2 } sphere { x, 1 } } } }
        union { intersection { sphere { 0, 1 } box { 0, 2 } } sphere { x, 1 } }
        "#,
    );
    fn check(o: &Object, seen: &mut [usize; 2]) {
        for c in &o.clip {
            check(c, seen);
        }
        if let ObjKind::Csg {
            op,
            children,
            index,
            cull,
        } = &o.kind
        {
            let scan = *op != crate::scene::desc::CsgOp::Union
                && index.is_none()
                && children
                    .iter()
                    .any(|c| crate::scene::csg_hit::folded(c).is_some());
            assert_eq!(cull.as_ref().is_some_and(|c| c.folds), scan);
            // The kind byte names the search the tests on `boxes` and `folds` chose.
            let boxes = cull.as_ref().is_some_and(|c| c.boxes.is_some());
            let framed = cull.as_ref().is_some_and(|c| c.framed.is_some());
            let want = match (boxes, scan, framed) {
                (true, _, _) => Search::Boxes,
                (false, true, _) => Search::Folds,
                (false, false, true) => Search::Framed,
                (false, false, false) => Search::Plain,
            };
            assert_eq!(cull.as_ref().map_or(Search::Plain, |c| c.search), want);
            seen[scan as usize] += 1;
            children.iter().for_each(|c| check(c, seen));
        }
    }
    let mut seen = [0; 2];
    scene.objects.iter().for_each(|o| check(o, &mut seen));
    assert!(seen[0] >= 8 && seen[1] >= 4, "{seen:?}");
}
