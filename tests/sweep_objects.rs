//! `prism`, `lathe`, `sor`, `polygon` and `sphere_sweep` as the parser reads them: POV-Ray's
//! refusals as errors at the object's line, its warnings, and no panic on odd input (the
//! pictures themselves are checked against povray by the probes in tests/probes/).

mod common;

use common::{parse, parse_err};
use lancer::geom::Shape;
use lancer::math::{DVec3, Ray};
use lancer::scene::desc::{SceneDesc, ShapeDesc};
use lancer::sdl::{ParseOptions, Parser};

fn warnings(src: &str) -> Vec<String> {
    let mut p = Parser::new(ParseOptions::default());
    p.parse_str("w.pov", src).unwrap();
    p.warnings.iter().map(|w| w.one_line(&p.sources)).collect()
}

#[test]
fn every_object_is_read() {
    let s = parse(
        "prism { conic_sweep cubic_spline 0.2, 1, 8, <0,-1>, <1,0>, <0,1>, <-1,0>, <0,-1>, <1,0>, <0,1>, <-1,0> open sturm pigment { rgb 1 } }
         lathe { bezier_spline 4, <1,0>, <2,1>, <2,2>, <1,3> sturm }
         sor { 4, <0,0>, <1,1>, <1,2>, <0,3> open translate x }
         polygon { 4, <0,0>, <1,0>, <1,1>, <0,0> }
         sphere_sweep { b_spline 4, <0,0,0>, 1 <1,0,0>, 1, <2,1,0>, 0.5 <3,0,0>, 1 tolerance 1e-4 scale 2 }",
    );
    let kinds: Vec<&str> = s
        .objects
        .iter()
        .map(|o| match o.shape {
            ShapeDesc::Prism(_) => "prism",
            ShapeDesc::Lathe(_) => "lathe",
            ShapeDesc::Sor(_) => "sor",
            ShapeDesc::Polygon(_) => "polygon",
            ShapeDesc::SphereSweep(_) => "sphere_sweep",
            _ => "other",
        })
        .collect();
    assert_eq!(kinds, ["prism", "lathe", "sor", "polygon", "sphere_sweep"]);
    assert!(!s.objects[2].transform.is_identity());
}

#[test]
fn refusals_name_the_object_and_the_problem() {
    let cases = [
        ("prism { 0, 1, 2, <0,0>, <1,0> }", "at least three points"),
        (
            "prism { quadratic_spline 0, 1, 3, <0,0>, <1,0>, <1,1> }",
            "at least five",
        ),
        (
            "prism { cubic_spline 0, 1, 5, <0,0>, <1,0>, <1,1>, <0,1>, <0,0> }",
            "at least six",
        ),
        (
            "prism { bezier_spline 0, 1, 5, <0,0>, <1,0>, <1,1>, <0,1>, <0,0> }",
            "four points per segment",
        ),
        // A quadratic outline that never comes back to its first point: nothing left to draw.
        (
            "prism { quadratic_spline 0, 1, 5, <0,0>, <1,0>, <1,1>, <0,1>, <2,2> }",
            "Too few points",
        ),
        ("lathe { 1, <1,0> }", "at least two"),
        (
            "lathe { quadratic_spline 2, <1,0>, <1,1> }",
            "at least three",
        ),
        (
            "lathe { cubic_spline 3, <1,0>, <1,1>, <1,2> }",
            "at least four",
        ),
        (
            "lathe { bezier_spline 5, <1,0>, <1,1>, <1,2>, <1,3>, <1,4> }",
            "four points per segment",
        ),
        ("sor { 3, <0,0>, <1,1>, <1,2> }", "at least four"),
        (
            "sor { 4, <0,0>, <1,1>, <1,0.5>, <1,3> }",
            "heights must increase",
        ),
        ("sor { 4, <0,0>, <-1,1>, <1,2>, <1,3> }", "negative"),
        ("polygon { 2, <0,0>, <1,1> }", "at least three points"),
        (
            "sphere_sweep { linear_spline 1, <0,0,0>, 1 }",
            "Too few modeling spheres",
        ),
        (
            "sphere_sweep { cubic_spline 3, <0,0,0>, 1 <1,0,0>, 1 <2,0,0>, 1 }",
            "Too few modeling spheres",
        ),
        (
            "sphere_sweep { 2, <0,0,0>, 1 <1,0,0>, 1 }",
            "linear_spline, b_spline or cubic_spline",
        ),
    ];
    for (src, want) in cases {
        let e = parse_err(&format!("// first\n{src}"));
        assert!(e.starts_with("snippet.pov:2:"), "{src}: {e}");
        assert!(e.contains(want), "{src}: {e}");
    }
    // `open` belongs right after the points, as in POV-Ray.
    let e = parse_err("sor { 4, <0,0>, <1,1>, <1,2>, <1,3> pigment { rgb 1 } open foo }");
    assert!(e.contains("foo"), "{e}");
}

#[test]
fn povray_warnings() {
    let w = warnings("prism { 0, 1, 4, <0,0>, <1,0>, <1,1>, <0,1> }");
    assert!(
        w.len() == 1 && w[0].contains("Linear prism not closed"),
        "{w:?}"
    );
    let w = warnings(
        "prism { bezier_spline 0, 1, 8, <0,0>, <1,0>, <1,1>, <0,0>, <2,2>, <3,2>, <3,3>, <2,3> }",
    );
    assert!(
        w.len() == 1 && w[0].contains("Prism not closed. Ignoring it."),
        "{w:?}"
    );
    let w = warnings("\npolygon { 3, <0,0>, <1,0>, <0,1> }");
    assert!(
        w.len() == 1 && w[0].starts_with("w.pov:2:1") && w[0].contains("Polygon not closed"),
        "{w:?}"
    );
    let w = warnings("polygon { 5, <0,0,0>, <1,0,0>, <1,1,0.01>, <0,1,0>, <0,0,0> }");
    assert!(
        w.len() == 1 && w[0].contains("not all in one plane"),
        "{w:?}"
    );
    assert!(warnings(
        "polygon { 4, <0,0>, <1,0>, <1,1>, <0,0> } sor { 4, <0,0>, <1,1>, <1,2>, <1,3> }"
    )
    .is_empty());
}

fn shapes(s: &SceneDesc) -> Vec<std::sync::Arc<dyn Shape>> {
    s.objects
        .iter()
        .map(|o| lancer::scene::shapes::make_shape(&o.shape))
        .collect()
}

/// Degenerate but accepted input: every shape answers every query without panicking.
#[test]
fn odd_input_does_not_panic() {
    let s = parse(
        "prism { 0, 0, 3, <0,0>, <0,0>, <0,0> }
         prism { conic_sweep -1, 1, 4, <0,0>, <1,0>, <0,1>, <0,0> }
         prism { 1e300, -1e300, 4, <0,0>, <1e-300,0>, <0,1e300>, <0,0> }
         lathe { 2, <0,0>, <0,0> }
         lathe { cubic_spline 4, <0,0>, <0,0>, <0,0>, <0,0> }
         lathe { linear_spline 2, <1,0>, <1,0> }
         sor { 4, <0,0>, <0,1>, <0,2>, <0,2.5> }
         sor { 4, <0,5>, <1,1>, <1,1.0000001>, <0,-5> }
         polygon { 3, <0,0>, <1,0>, <2,0> }
         polygon { 5, <0,0>, <1,0>, <0,0>, <1,1>, <1,1> }
         sphere_sweep { linear_spline 2, <0,0,0>, 0 <0,0,0>, 0 }
         sphere_sweep { cubic_spline 4, <0,0,0>, 1 <0,0,0>, 1 <0,0,0>, 1 <0,0,0>, 1 }
         sphere_sweep { b_spline 4, <0,0,0>, -1 <1,0,0>, 2 <2,0,0>, -1 <3,0,0>, 1 }",
    );
    let dirs = [
        DVec3::X,
        DVec3::Y,
        DVec3::NEG_Y,
        DVec3::new(1.0, 1e-9, 0.0),
        DVec3::new(0.3, -0.2, 0.9),
        DVec3::ZERO,
        DVec3::splat(f64::NAN),
    ];
    let origins = [
        DVec3::new(-5.0, 0.5, 0.0),
        DVec3::ZERO,
        DVec3::new(0.5, 0.5, 0.5),
        DVec3::splat(1e300),
    ];
    for sh in shapes(&s) {
        let _ = sh.bounds();
        for &o in &origins {
            let _ = sh.inside(o);
            for &d in &dirs {
                let mut hits = Vec::new();
                sh.intersect_all(&Ray::new(o, d), &mut hits);
                for h in &hits {
                    let _ = sh.normal(o + d * h.t, h);
                }
            }
        }
    }
}

#[test]
fn points_may_come_from_loops_and_arrays() {
    // As lemon.inc builds its Bezier prisms.
    let s = parse(
        "#declare A = array[4] { <0,0>, <1,0>, <1,1>, <0,0> }
         #declare J = 0;
         prism { bezier_spline -0.5, 0.5, 4, #while (J < 4) A[J] #declare J = J + 1; #end }",
    );
    let sh = &shapes(&s)[0];
    let mut hits = Vec::new();
    sh.intersect_all(
        &Ray::new(DVec3::new(0.5, 5.0, 0.2), DVec3::NEG_Y),
        &mut hits,
    );
    assert_eq!(hits.len(), 2);
}
