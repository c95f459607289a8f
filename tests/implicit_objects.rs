//! Reading the implicit and field objects (superellipsoid, blob, isosurface, height_field):
//! what the parser makes of them, and the errors and warnings bad input gets.

mod common;

use common::{parse, parse_err, parser};
use lancer::geom::blob::ComponentKind;
use lancer::scene::desc::ShapeDesc;

#[test]
fn superellipsoid_exponents() {
    let s = parse("superellipsoid { <0.25, 1> scale 2 }");
    match s.objects[0].shape {
        ShapeDesc::Superellipsoid { e, n } => assert_eq!((e, n), (0.25, 1.0)),
        ref other => panic!("{other:?}"),
    }
    // Exponents must be positive: warned about and replaced, never a division by zero.
    let p = parser("superellipsoid { <0, -1> }");
    match p.scene.objects[0].shape {
        ShapeDesc::Superellipsoid { e, n } => assert!(e > 0.0 && n > 0.0),
        ref other => panic!("{other:?}"),
    }
    assert_eq!(p.warnings.len(), 2, "{:?}", p.warnings);
}

#[test]
fn blob_components_textures_and_modifiers() {
    let s = parse(
        "blob { threshold 0.6
           sphere { <1,0,0>, 2, 1 pigment { rgb 1 } scale 2 }
           cylinder { 0, y, 0.5, strength -2 }
           component 1, 0.5, <0,0,3>
           sturm hierarchy off
           pigment { rgb <1,0,0> } translate x }",
    );
    let o = &s.objects[0];
    let ShapeDesc::Blob { data, textures } = &o.shape else {
        panic!("{:?}", o.shape)
    };
    assert_eq!(data.threshold, 0.6);
    assert!(data.sturm);
    assert_eq!(data.components.len(), 3);
    let c = &data.components;
    assert_eq!(
        c[0].kind,
        ComponentKind::Sphere {
            center: glam::DVec3::X
        }
    );
    assert_eq!(c[0].transform.point(glam::DVec3::X), glam::DVec3::X * 2.0);
    assert_eq!((c[1].radius, c[1].strength), (0.5, -2.0));
    assert!(matches!(c[1].kind, ComponentKind::Cylinder { .. }));
    assert_eq!(c[2].strength, 1.0);
    assert!(textures[0].is_some() && textures[1].is_none() && textures[2].is_none());
    // The component's texture moves with the blob's transforms as well as its own.
    let t = &textures[0].as_ref().unwrap().pigment.transform;
    assert_eq!(t.point(glam::DVec3::ZERO), glam::DVec3::X);
    assert_eq!(o.transform.point(glam::DVec3::ZERO), glam::DVec3::X);
}

#[test]
fn blob_errors() {
    let e = parse_err("blob { threshold 1 }");
    assert!(
        e.starts_with("snippet.pov:1:6") && e.contains("at least one component"),
        "{e}"
    );
    let e = parse_err("blob { sphere { 0, 1, 1 }\n  box { 0, 1 } }");
    assert!(
        e.starts_with("snippet.pov:2:3") && e.contains("not a blob component"),
        "{e}"
    );
    let e = parse_err("blob { sphere { 0, 1, 1 interior { } } }");
    assert!(e.contains("in a blob sphere"), "{e}");
    let p = parser("blob { threshold -1 sphere { 0, 1, 1 } }");
    assert!(
        p.warnings.iter().any(|w| w.message.contains("threshold")),
        "{:?}",
        p.warnings
    );
}

#[test]
fn isosurface_items() {
    use lancer::geom::isosurface::Container;
    let s = parse(
        "#declare F = function { x*x + y*y + z*z };
         isosurface { function { F(x, y, z) - 1 }
           contained_by { sphere { <0,1,0>, -2 } }
           threshold 0.5 accuracy 0.01 max_gradient 3 evaluate 1, 2, 0.5
           open max_trace 3 scale 2 }
         isosurface { function { x } all_intersections }",
    );
    let ShapeDesc::Isosurface(d) = &s.objects[0].shape else {
        panic!("{:?}", s.objects[0].shape)
    };
    assert_eq!(
        d.container,
        Container::Sphere {
            center: glam::DVec3::Y,
            radius: 2.0
        }
    );
    assert_eq!((d.threshold, d.accuracy, d.max_gradient), (0.5, 0.01, 3.0));
    assert_eq!(d.evaluate, Some([1.0, 2.0, 0.5]));
    assert!(d.open);
    assert_eq!(d.max_trace, Some(3));
    assert_eq!(d.function.eval(&[1.0, 1.0, 1.0]), 2.0);
    assert_eq!(
        s.objects[0].transform.point(glam::DVec3::X),
        glam::DVec3::X * 2.0
    );
    let ShapeDesc::Isosurface(d) = &s.objects[1].shape else {
        panic!()
    };
    assert_eq!(d.max_trace, None);
    assert_eq!(
        d.container,
        Container::Box {
            min: glam::DVec3::splat(-1.0),
            max: glam::DVec3::splat(1.0)
        }
    );
}

#[test]
fn isosurface_errors_and_unsupported_functions() {
    let e = parse_err("isosurface { contained_by { box { -1, 1 } } }");
    assert!(
        e.starts_with("snippet.pov:1:14") && e.contains("function"),
        "{e}"
    );
    let e = parse_err("isosurface { function { x }\n contained_by { torus { 1, 0.5 } } }");
    assert!(
        e.starts_with("snippet.pov:2:17") && e.contains("box or a sphere"),
        "{e}"
    );
    let e = parse_err("isosurface { function { x } hierarchy }");
    assert!(e.contains("not an isosurface item"), "{e}");
    // A function lancer cannot evaluate (f_cushion): not rendered, with the reason.
    let p = parser(
        "#declare C = function { internal(13) }
         isosurface { function { C(x, y, z) - 0.5 } }",
    );
    assert!(matches!(p.scene.objects[0].shape, ShapeDesc::Csg { .. }));
    assert!(
        p.warnings
            .iter()
            .any(|w| w.message.contains("isosurface is not rendered")),
        "{:?}",
        p.warnings
    );
    // A body lancer cannot read or evaluate (a spline function's component): the scene
    // still renders, without the isosurface, and says why.
    let p = parser(
        "#declare S = function { spline { linear_spline 0, <0,0,0>, 1, <1,1,1> } }
         isosurface { function { S(x).y - y } contained_by { box { -1, 1 } } scale 2 }
         sphere { 0, 1 }",
    );
    assert!(matches!(p.scene.objects[0].shape, ShapeDesc::Csg { .. }));
    assert!(matches!(p.scene.objects[1].shape, ShapeDesc::Sphere { .. }));
    assert!(
        p.warnings
            .iter()
            .any(|w| w.message.contains("isosurface is not rendered")),
        "{:?}",
        p.warnings
    );
    let p = parser("isosurface { function { x } accuracy 0 max_gradient -1 }");
    assert_eq!(p.warnings.len(), 2, "{:?}", p.warnings);
}
