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
    // A function lancer cannot evaluate (f_comma): not rendered, with the reason.
    let p = parser(
        "#declare C = function { internal(9) }
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
    // A spline function's component in a body is evaluated (it used to be left out): the
    // isosurface renders, with no warning about it.
    let p = parser(
        "#declare S = function { spline { linear_spline 0, <0,0,0>, 1, <1,1,1> } }
         isosurface { function { S(x).y - y } contained_by { box { -1, 1 } } scale 2 }
         sphere { 0, 1 }",
    );
    assert!(matches!(p.scene.objects[0].shape, ShapeDesc::Isosurface(_)));
    assert!(matches!(p.scene.objects[1].shape, ShapeDesc::Sphere { .. }));
    assert!(
        !p.warnings
            .iter()
            .any(|w| w.message.contains("isosurface is not rendered")),
        "{:?}",
        p.warnings
    );
    let p = parser("isosurface { function { x } accuracy 0 max_gradient -1 }");
    assert_eq!(p.warnings.len(), 2, "{:?}", p.warnings);
}

/// A scratch directory for image files the height field tests write.
fn scratch(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("lancer-implicit-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn parse_in(dir: &std::path::Path, src: &str) -> Result<lancer::sdl::Parser, String> {
    let path = dir.join("scene.pov");
    std::fs::write(&path, src).unwrap();
    let mut p = lancer::sdl::Parser::new(lancer::sdl::ParseOptions::default());
    match p.parse_file(&path) {
        Ok(()) => Ok(p),
        Err(e) => Err(e.one_line(&p.sources)),
    }
}

fn heights(p: &lancer::sdl::Parser) -> (usize, usize, Vec<u16>) {
    match &p.scene.objects[0].shape {
        ShapeDesc::HeightField(d) => (d.width, d.depth, d.heights.clone()),
        other => panic!("{other:?}"),
    }
}

#[test]
fn height_field_images_by_povrays_rules() {
    let dir = scratch("images");
    // 8-bit grey: rows run from z = 1 down; 128 stays, 102 is one of the values povray
    // reads one lower from a grey PNG.
    let mut g = image::GrayImage::new(2, 2);
    g.put_pixel(0, 0, image::Luma([128]));
    g.put_pixel(1, 0, image::Luma([102]));
    g.save(dir.join("g.png")).unwrap();
    let p = parse_in(
        &dir,
        "height_field { png \"g.png\" smooth water_level 0.1 }",
    )
    .unwrap();
    let (w, h, v) = heights(&p);
    assert_eq!((w, h), (2, 2));
    assert_eq!(v, vec![0, 0, 128 * 257, 101 * 257]);
    let ShapeDesc::HeightField(d) = &p.scene.objects[0].shape else {
        unreachable!()
    };
    assert!(d.smooth && d.water_level == 0.1);
    // 8-bit colour: red is the high byte, green the low one; the same in a TGA.
    let mut c = image::RgbImage::new(2, 2);
    c.put_pixel(0, 1, image::Rgb([100, 200, 50]));
    c.save(dir.join("c.png")).unwrap();
    c.save(dir.join("c.tga")).unwrap();
    for f in ["png \"c.png\"", "tga \"c.tga\"", "\"c.tga\""] {
        let p = parse_in(&dir, &format!("height_field {{ {f} }}")).unwrap();
        assert_eq!(heights(&p).2[0], 100 * 256 + 200, "{f}");
    }
    // A gamma decodes first and truncates back to 8 bits.
    let p = parse_in(&dir, "height_field { png \"g.png\" gamma 2.2 }").unwrap();
    assert_eq!(heights(&p).2[2], 55 * 257);
}

#[test]
fn height_field_functions_wrap_like_povray() {
    let s = parse("height_field { function 3, 2 { x - 0.5 } }");
    let ShapeDesc::HeightField(d) = &s.objects[0].shape else {
        panic!()
    };
    assert_eq!((d.width, d.depth), (3, 2));
    // -0.5 wraps to 0.5 (truncated towards zero first), 0 stays, 0.5 stays.
    assert_eq!(&d.heights[..3], &[32769, 0, 32767]);
    // y runs down the "image": row 0 (y = 0) is at z = 1.
    let s = parse("height_field { function 2, 2 { y * 0.5 } }");
    let ShapeDesc::HeightField(d) = &s.objects[0].shape else {
        panic!()
    };
    assert_eq!(d.heights, vec![32767, 32767, 0, 0]);
}

#[test]
fn height_field_errors() {
    let dir = scratch("errors");
    let e = parse_in(&dir, "\nheight_field { png \"missing.png\" }")
        .err()
        .unwrap();
    assert!(
        e.contains("scene.pov:2:20") && e.contains("cannot find height field image"),
        "{e}"
    );
    std::fs::write(dir.join("bad.png"), b"\x89PNG not really").unwrap();
    let e = parse_in(&dir, "height_field { png \"bad.png\" }")
        .err()
        .unwrap();
    assert!(e.contains("cannot read PNG"), "{e}");
    let e = parse_err("height_field { function 1, 5 { x } }");
    assert!(e.contains("at least 2×2"), "{e}");
    let e = parse_err("height_field { function 100000, 100000 { x } }");
    assert!(e.contains("at most"), "{e}");
    let e = parse_err("height_field { function 2, 2 { x } sturm 3 }");
    assert!(e.contains("unexpected"), "{e}");
    // A format lancer does not read leaves the object out with a warning.
    let p = parser("height_field { tiff \"x.tif\" smooth }");
    assert!(matches!(p.scene.objects[0].shape, ShapeDesc::Csg { .. }));
    assert!(!p.warnings.is_empty());
}
