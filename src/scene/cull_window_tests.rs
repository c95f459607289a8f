//! Quartics windowed by turned members and clipping objects answer every query as they do
//! without a window, bit for bit (the window only leaves out crossings the node drops).

use crate::geom::test_rng::Lcg;
use crate::math::Ray;
use crate::scene::object::{ObjKind, Object, Scratch};

/// trough's and monkey's saddles in turned boxes (moved, scaled unevenly, two boxes at once),
/// and clipped by a turned box and by a squashed turned sphere beside a plane; the monkey in a
/// turned, moved, evenly scaled sphere (folium's and witch's window: the ball alone).
const SCENE: &str = r#"
    #declare Saddle = quartic { < 0, 0, 0, 0, 0, 0, 0, 4, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
      0, 0, 0, 0, 0, 0, 0, 0, 0, -1, 0, 0, 0, 0, 0 > }
    #declare Monkey = quartic { < 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, -3, 0, 0, 0, 0, 0, 0, 0,
      0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1, 0 > }
    intersection { object { Saddle } box { -1, 1 } scale 2 rotate -10*y rotate -60*x translate 4*z }
    intersection { object { Monkey } box { -1, 1 scale 2 } rotate 20*y rotate -30*x }
    intersection { object { Saddle } box { <-1, -0.5, -2>, <1.5, 1, 1> rotate <10, 20, 30> }
      box { -1, 1 rotate 45*z } scale <1, 2, 0.5> translate <0.5, -0.25, 1> }
    object { Monkey clipped_by { box { -1.5, 1.5 rotate <30, 0, 20> } } }
    object { Saddle rotate 40*x clipped_by { sphere { 0, 2 scale <1, 0.5, 1> rotate 30*z } plane { y, 0.2 rotate 10*x } } }
    intersection { object { Monkey } sphere { <0.2, 0, 0.1>, 1.5 scale 1.2 } rotate <0, 50, 10> translate <1, 0, 2> }
"#;

fn scene() -> crate::scene::build::Scene {
    crate::scene::csg_hit::tests::built(SCENE)
}

/// Drops every window below `o`; counts those it dropped.
fn unwindow(o: &mut Object) -> usize {
    let mut n = 0;
    for c in &mut o.clip {
        n += unwindow(c);
    }
    match &mut o.kind {
        ObjKind::Shape(_, w) => n += w.take().is_some() as usize,
        ObjKind::Csg { children, .. } => n += children.iter_mut().map(unwindow).sum::<usize>(),
    }
    n
}

/// Asserts that `a` and `b` give `ray` the same first hit and the same crossings, bit for bit
/// (also used by cull.rs's tests); true when there is a first hit.
pub(super) fn same_hits<'a>(
    a: &'a Object,
    b: &'a Object,
    ray: &Ray,
    tmax: f64,
    sa: &mut Scratch<'a>,
    sb: &mut Scratch<'a>,
) -> bool {
    let (ha, hb) = (a.first_hit(ray, tmax, sa), b.first_hit(ray, tmax, sb));
    assert_eq!(ha.map(|h| h.t.to_bits()), hb.map(|h| h.t.to_bits()));
    a.all_hits(ray, tmax, sa);
    b.all_hits(ray, tmax, sb);
    let la: Vec<_> = sa.surface.iter().map(|h| (h.t.to_bits(), h.flip)).collect();
    let lb: Vec<_> = sb.surface.iter().map(|h| (h.t.to_bits(), h.flip)).collect();
    assert_eq!(la, lb);
    sa.surface.clear();
    sb.surface.clear();
    ha.is_some()
}

#[test]
fn turned_windows_keep_every_crossing() {
    let windowed = scene();
    let mut bare = scene();
    let dropped: usize = bare.objects.iter_mut().map(unwindow).sum();
    assert_eq!(dropped, 6);
    let mut rng = Lcg(11);
    let (mut sa, mut sb) = (Scratch::default(), Scratch::default());
    for (a, b) in windowed.objects.iter().zip(&bare.objects) {
        let mut hits = 0;
        for k in 0..6000 {
            // Rays from around the object, aimed near its middle, some along the axes.
            let o = rng.vec(8.0);
            let dir = if k % 5 == 0 {
                [
                    crate::math::DVec3::X,
                    crate::math::DVec3::Y,
                    crate::math::DVec3::Z,
                ][k % 3]
            } else {
                rng.vec(1.5) - o * 0.125
            };
            let ray = Ray::new(o, dir);
            let tmax = if rng.next() < 0.3 { 6.0 } else { f64::INFINITY };
            hits += same_hits(a, b, &ray, tmax, &mut sa, &mut sb) as usize;
        }
        assert!(hits > 100, "{hits}");
    }
}
