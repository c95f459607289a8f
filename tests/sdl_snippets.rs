//! Snippet tests for the scene language: small texts parsed into scene descriptions.

mod common;

use common::{parse, parse_err, radii};
use lancer::scene::desc::{PigmentKind, ShapeDesc};
use lancer::sdl::{ParseOptions, Parser};

#[test]
fn expressions_and_promotion() {
    let s =
        parse("#declare A = 1 + 2 * 3; #declare V = <1,2,3> * 2 + 1; sphere { V, A - V.y + 1 }");
    match s.objects[0].shape {
        ShapeDesc::Sphere { center, radius } => {
            assert_eq!(center, glam::DVec3::new(3.0, 5.0, 7.0));
            assert_eq!(radius, 3.0);
        }
        _ => panic!(),
    }
}

#[test]
fn builtin_functions() {
    let s = parse("sphere { 0, sqrt(16) + pow(2,3) + max(1, 5, 3) + mod(7, 3) + abs(-2) + floor(1.5) + vlength(<3,4,0>) + select(-1, 10, 20) }");
    assert_eq!(
        radii(&s),
        vec![4.0 + 8.0 + 5.0 + 1.0 + 2.0 + 1.0 + 5.0 + 10.0]
    );
}

#[test]
fn comparisons_only_inside_parentheses_and_commas_optional() {
    // POV-Ray 3.7 reads `<`, `&`, `? :` only inside ( ); elsewhere `<` starts a vector, so
    // `<1 < 2, 0>` is an error there too ("Float expected but vector or color").
    let s = parse("#declare B = <(1 < 2), (3 > 2), 0>; sphere { B, 1 }");
    match s.objects[0].shape {
        ShapeDesc::Sphere { center, .. } => assert_eq!(center, glam::DVec3::new(1.0, 1.0, 0.0)),
        _ => panic!(),
    }
    parse_err("#declare B = <1 < 2, 0>;");
    // Two vectors without a comma, commas left out or trailing, `<1 -2 3>` as <-1, 3>:
    // all checked against povray's #debug output.
    let s =
        parse("box { <-.5, -1.5, -1> <.5, 1.5, 1> } sphere { <1 2 3> 1 } sphere { <1, 2, 3,>, 1 }");
    assert_eq!(s.objects.len(), 3);
    assert_eq!(radii(&s), vec![1.0, 1.0]);
    let s = parse("#declare U = <1 -2 3>; sphere { <U.u, U.v, 0>, 1 }");
    match s.objects[0].shape {
        ShapeDesc::Sphere { center, .. } => assert_eq!(center, glam::DVec3::new(-1.0, 3.0, 0.0)),
        _ => panic!(),
    }
}

#[test]
fn while_loop_spans_the_inside_of_an_object() {
    let s = parse(
        "#declare I = 0; union { #while (I < 4) sphere { x*I, 1 } #declare I = I + 1; #end }",
    );
    match &s.objects[0].shape {
        ShapeDesc::Csg { children, .. } => assert_eq!(children.len(), 4),
        _ => panic!(),
    }
}

#[test]
fn while_without_semicolon_before_end() {
    let s = parse("#declare I = 0; #while (I < 3) sphere { 0, I } #declare I = I + 1 #end");
    assert_eq!(radii(&s), vec![0.0, 1.0, 2.0]);
}

#[test]
fn macro_emits_half_an_object() {
    let s = parse("#macro Open(R) sphere { 0, R #end  Open(2) pigment { rgb 1 } }");
    assert_eq!(radii(&s), vec![2.0]);
    assert!(s.objects[0].texture.is_some());
}

#[test]
fn macro_local_shadows_declare() {
    let s =
        parse("#declare R = 5; #macro M() #local R = 1; sphere { 0, R } #end M() sphere { 0, R }");
    assert_eq!(radii(&s), vec![1.0, 5.0]);
}

#[test]
fn macro_as_expression_value() {
    let s = parse("#macro Twice(A) (A * 2) #end sphere { 0, Twice(3) + 1 }");
    assert_eq!(radii(&s), vec![7.0]);
}

#[test]
fn recursive_macro() {
    let s = parse(
        "#macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end sphere { 0, Fact(4) }",
    );
    assert_eq!(radii(&s), vec![24.0]);
}

#[test]
fn if_elseif_else() {
    let s = parse("#declare A = 2; #if (A = 1) sphere {0,1} #elseif (A = 2) sphere {0,2} #else sphere {0,3} #end");
    assert_eq!(radii(&s), vec![2.0]);
}

#[test]
fn ifdef_and_for() {
    let s = parse("#ifndef (Q) #declare Q = 1; #end #for (I, 1, 3) sphere { 0, I * Q } #end");
    assert_eq!(radii(&s), vec![1.0, 2.0, 3.0]);
}

#[test]
fn identifiers_redeclared_with_a_different_type() {
    let s = parse("#declare A = 1; #declare A = sphere { 0, 3 }; object { A }");
    assert_eq!(radii(&s), vec![3.0]);
}

#[test]
fn colours_and_promotion() {
    let s = parse("#declare C = rgb <1, 0.5, 0> * 0.5; sphere { 0, 1 pigment { color C filter 0.25 } } sphere { 0, 1 pigment { rgbf 0.5 } } sphere { 0, 1 pigment { color red 1 green 0.5 } }");
    let col = |i: usize| match &s.objects[i].texture.as_ref().unwrap().pigment.kind {
        PigmentKind::Solid(c) => *c,
        _ => panic!(),
    };
    assert_eq!(col(0).to_array(), [0.5, 0.25, 0.0, 0.25, 0.0]);
    assert_eq!(col(1).to_array(), [0.5, 0.5, 0.5, 0.5, 0.0]);
    assert_eq!(col(2).to_array(), [1.0, 0.5, 0.0, 0.0, 0.0]);
}

#[test]
fn texture_moves_with_object_only_when_given_before_transform() {
    let s = parse("sphere { 0, 1 pigment { checker } translate x } sphere { 0, 1 translate x pigment { checker } }");
    let t0 = *s.objects[0].texture.as_ref().unwrap().pigment.transform;
    let t1 = *s.objects[1].texture.as_ref().unwrap().pigment.transform;
    assert!(!t0.is_identity());
    assert!(t1.is_identity());
}

#[test]
fn string_escapes_and_concat() {
    let mut p = Parser::new(ParseOptions::default());
    p.parse_str(
        "s.pov",
        r#"#declare S = concat("a\"b", str(1.5, 0, 1)); #if (strlen(S) = 6) sphere { 0, 1 } #end"#,
    )
    .unwrap();
    assert_eq!(p.scene.objects.len(), 1);
}

#[test]
fn camera_items() {
    let s = parse("camera { location <0, 1, -5> look_at <0, 1, 0> angle 60 right x*4/3 }");
    assert_eq!(s.camera.location, glam::DVec3::new(0.0, 1.0, -5.0));
    assert_eq!(s.camera.angle, Some(60.0));
}

#[test]
fn unsupported_keyword_warns_with_place() {
    let mut p = Parser::new(ParseOptions::default());
    p.parse_str(
        "w.pov",
        "sphere { 0, 1 finish { subsurface { translucency 0.5 } } }\nsphere { 0, 1 pigment { tiling 3 } }",
    )
    .unwrap();
    let msgs: Vec<String> = p.warnings.iter().map(|w| w.one_line(&p.sources)).collect();
    assert!(
        msgs.iter()
            .any(|m| m.starts_with("w.pov:1:") && m.contains("subsurface")),
        "{msgs:?}"
    );
    assert!(
        msgs.iter()
            .any(|m| m.starts_with("w.pov:2:") && m.contains("tiling")),
        "{msgs:?}"
    );
}

#[test]
fn errors_name_file_line_and_column() {
    assert!(parse_err("sphere { 0, 1 ").contains("never closed"));
    let e = parse_err("\n  sphere { Foo, 1 }");
    assert!(
        e.starts_with("snippet.pov:2:12") && e.contains("undeclared identifier 'Foo'"),
        "{e}"
    );
    let e = parse_err("#declare S = \"abc");
    assert!(
        e.starts_with("snippet.pov:1:14") && e.contains("unterminated string"),
        "{e}"
    );
    let e = parse_err("#if (1) sphere { 0, 1 }");
    assert!(e.contains("#end"), "{e}");
}

#[test]
fn error_inside_macro_shows_the_call_chain() {
    let mut p = Parser::new(ParseOptions::default());
    let e = p
        .parse_str("m.pov", "#macro M(A)\n sphere { A, Nope }\n#end\nM(1)")
        .unwrap_err();
    assert!(e.one_line(&p.sources).starts_with("m.pov:2:"));
    assert_eq!(e.chain.len(), 1);
    assert!(e.chain[0].what.contains("macro M"));
}

#[test]
fn endless_recursion_is_an_error_not_a_crash() {
    let e = parse_err("#macro M() M() #end M()");
    assert!(e.contains("too many nested"), "{e}");
}

#[test]
fn include_found_on_the_library_path_with_local_scope() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures");
    let opts = ParseOptions {
        library_paths: vec![root.join("lib")],
        ..ParseOptions::default()
    };
    let parsed = lancer::api::parse_file(&root.join("uses_include.pov"), opts);
    if let Some(e) = parsed.error {
        panic!("{}", e.one_line(&parsed.parser.sources));
    }
    assert_eq!(radii(&parsed.parser.scene), vec![2.0]);
}

/// POV-Ray's own colors.inc, where Debian's povray-includes is installed (CI installs it).
#[test]
fn povray_colors_inc_parses_where_installed() {
    let dir = std::path::Path::new("/usr/share/povray-3.7/include");
    if !dir.join("colors.inc").exists() {
        eprintln!("skipped: povray-includes is not installed");
        return;
    }
    let s = parse("#include \"colors.inc\" sphere { 0, 1 pigment { color Gray30 } }");
    match &s.objects[0].texture.as_ref().unwrap().pigment.kind {
        PigmentKind::Solid(c) => assert!((c.rgb.x - 0.3).abs() < 1e-12),
        _ => panic!(),
    }
}

#[test]
fn unsupported_in_a_declaration_warns_only_when_used() {
    let warnings = |src: &str| {
        let mut p = Parser::new(ParseOptions::default());
        p.parse_str("d.pov", src).unwrap();
        p.warnings
            .iter()
            .map(|w| w.one_line(&p.sources))
            .collect::<Vec<_>>()
    };
    // Declared and never used, as shapes.inc's declarations are in most scenes: no warning.
    let decl = "#declare Q = lemon { <0.5, 0.5, 0, 0> }\n";
    assert!(warnings(decl).is_empty(), "{:?}", warnings(decl));
    // Testing for the name is not using it.
    let tested = format!("{decl}#ifdef (Q) #end\n");
    assert!(warnings(&tested).is_empty());
    // Used directly, or through another declaration: the warning points at the keyword.
    let used = format!("{decl}object {{ Q }}\n");
    let w = warnings(&used);
    assert!(
        w.len() == 1 && w[0].starts_with("d.pov:1:14") && w[0].contains("lemon"),
        "{w:?}"
    );
    let through = format!(
        "{decl}#declare U = union {{ object {{ Q }} sphere {{ 0, 1 }} }}\nobject {{ U }}\n"
    );
    assert_eq!(warnings(&through).len(), 1);
    let unused_outer = format!("{decl}#declare U = union {{ object {{ Q }} }}\n");
    assert!(warnings(&unused_outer).is_empty());
    // A value computed from it is wrong now, used or not (language/trace2.pov): said at once.
    let traced = format!("{decl}#declare P = trace(Q, <0,5,0>, -y);\n");
    let w = warnings(&traced);
    assert!(w.iter().any(|m| m.contains("trace")), "{w:?}");
}

#[test]
fn local_whose_value_comes_out_of_a_macro_lands_in_the_callers_scope() {
    // language/tracevines.pov: the macro's value ends while its scope is still open.
    let s = parse(
        "#macro Pick(A) #local Q = A * 2; Q #end
         #macro Use() #local N = Pick(3); sphere { 0, N } #end
         Use()",
    );
    assert_eq!(radii(&s), vec![6.0]);
}

#[test]
fn blocks_lancer_skips_still_run_their_directives() {
    // shapes.inc's mesh2 macros put the closing braces in #if branches.
    let s = parse(
        "#declare W = 0;
         lemon { <1,0,0,0> #if (W) sphere { 0, 1, 1 } } #else sphere { 0, 2, 1 } } #end
         #declare After = 3;
         sphere { 0, After }",
    );
    assert_eq!(radii(&s), vec![3.0]);
}

#[test]
fn older_and_looser_spellings_povray_accepts() {
    // `default { }` without '#', a '#' no directive follows, multi-line strings, macro
    // arguments without a comma after an object, a declared light_source reused.
    let s = parse(
        "default { finish { ambient 0.2 } }
         #declare S = \"two
lines\";
         #macro Two(O, V) object { O translate V } #end
         Two(sphere { 0, 1 } -y)
         #declare L = light_source { <1, 2, 3> color rgb 1 }
         light_source { L translate x }
         camera { location -5*z look_at 0# 
         }",
    );
    assert_eq!(s.objects.len(), 2);
}

#[test]
fn declared_mesh_reused_inside_mesh() {
    let s = parse(
        "#declare M = mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } }
         mesh { M translate x }",
    );
    assert!(matches!(s.objects[0].shape, ShapeDesc::Mesh(_)));
}

#[test]
fn lexed_files_carry_over_between_parses_until_they_change() {
    let dir = std::env::temp_dir().join(format!("lancer-lexed-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("s.pov");
    std::fs::write(&scene, "#include \"r.inc\"\nsphere { 0, R }\n").unwrap();
    std::fs::write(dir.join("r.inc"), "#declare R = 1;\n").unwrap();
    let radius = |p: &lancer::api::Parsed| match p.parser.scene.objects[0].shape {
        ShapeDesc::Sphere { radius, .. } => radius,
        _ => panic!(),
    };
    let first = lancer::api::parse_file_with(&scene, ParseOptions::default(), None);
    assert_eq!(radius(&first), 1.0);
    let again = lancer::api::parse_file_with(
        &scene,
        ParseOptions::default(),
        Some(first.parser.into_lexed()),
    );
    assert_eq!(radius(&again), 1.0);
    // Rewritten between frames (a longer file, so the stamp differs): read again.
    std::fs::write(dir.join("r.inc"), "#declare R = 2.5;\n").unwrap();
    let changed = lancer::api::parse_file_with(
        &scene,
        ParseOptions::default(),
        Some(again.parser.into_lexed()),
    );
    assert!(changed.error.is_none());
    assert_eq!(radius(&changed), 2.5);
}

#[test]
fn flag_values_are_any_float_expression() {
    // `hollow F` and `hollow (1)` are accepted by povray 3.7 (the value is a float).
    let s = parse("#declare F = 0; sphere { 0, 1 hollow F } sphere { 0, 2 hollow (1) }");
    assert_eq!(s.objects[0].hollow, Some(false));
    assert_eq!(s.objects[1].hollow, Some(true));
}

#[test]
fn light_colours_are_any_colour_expression() {
    // povray 3.7 takes every colour keyword here, srgbt included, and identifiers in
    // expressions.
    let s = parse(
        "#declare W = rgb 1;
         light_source { <0, 5, -5> srgbt <1, 1, 1, 0> }
         light_source { <0, 5, -5> W * 2 }
         light_source { <0, 5, -5> color red 0.5 }",
    );
    assert_eq!(s.objects.len(), 3);
}

#[test]
fn call_arguments_read_comparisons_only_inside_their_own_parentheses() {
    // povray 3.7: "Expected ')', > found" for the first; the second is fine.
    parse_err("#declare A = (max(1 > 0, 2));");
    let s = parse("#declare A = max((1 > 0), 2); sphere { 0, A }");
    assert_eq!(radii(&s), vec![2.0]);
}

#[test]
fn macro_value_ending_inside_an_if_takes_an_operator() {
    // arrays.inc's Rand_Array_Item yields its element inside `#if ... #else ... #end`;
    // advanced/isocacti.pov multiplies it: `pigment { Rand_Array_Item(A, S)*RRand(...) }`.
    let s = parse(
        "#declare Arr = array[2] { 0.5, 2 }
         #macro Item(A) #if (1) A[1] #else A[0] #end #end
         #macro Half() #if (0) 4 #else 0.5 #end #end
         sphere { 0, Item(Arr)*Half() + 1 }",
    );
    assert_eq!(radii(&s), vec![2.0]);
}

#[test]
fn uv_mapping_on_a_shape_without_uv_coordinates_warns() {
    let warned = |src: &str| {
        let mut p = Parser::new(ParseOptions::default());
        p.parse_str("t.pov", src).unwrap();
        p.warnings
            .iter()
            .map(|w| w.one_line(&p.sources))
            .filter(|m| m.contains("uv_mapping"))
            .collect::<Vec<_>>()
    };
    assert!(warned("sphere { 0, 1 pigment { uv_mapping checker } }").is_empty());
    let w = warned("box { -1, 1 texture { uv_mapping pigment { checker } } }");
    assert!(w[0].contains("'uv_mapping on box'"), "{w:?}");
    // A union's members without their own texture take the union's.
    let w = warned("union { sphere { 0, 1 } torus { 1, 0.2 } pigment { uv_mapping checker } }");
    assert!(w[0].contains("'uv_mapping on torus'"), "{w:?}");
    assert!(
        warned("union { torus { 1, 0.2 pigment { rgb 1 } } pigment { uv_mapping checker } }")
            .is_empty()
    );
}

#[test]
fn mesh_camera_reads_its_meshes_and_checks_them() {
    let s = parse(
        "#declare M = mesh { triangle { 0, x, y } }
         camera { mesh_camera { 2, 0 mesh { M } mesh { M translate z } } location 0.1*z }",
    );
    let m = s.camera.mesh.as_ref().expect("a mesh camera");
    assert_eq!(
        (m.rays_per_pixel, m.distribution, m.meshes.len()),
        (2, 0, 2)
    );
    assert!(!m.smooth);
    let s = parse("camera { mesh_camera { 1 3 mesh { triangle { 0, x, y } } smooth } }");
    assert!(s.camera.mesh.as_ref().expect("a mesh camera").smooth);
    // povray: "Smooth can only be used with distribution method #3".
    let e = parse_err("camera { mesh_camera { 1 0 mesh { triangle { 0, x, y } } smooth } }");
    assert!(e.contains("needs mesh_camera distribution 3"), "{e}");
    let e = parse_err(
        "#declare M = mesh { triangle { 0, x, y } } camera { mesh_camera { 2 0 mesh { M } } }",
    );
    assert!(e.contains("needs a mesh per ray"), "{e}");
    let e = parse_err("camera { mesh_camera { 1 4 mesh { triangle { 0, x, y } } } }");
    assert!(e.contains("distribution type must be 0, 1, 2 or 3"), "{e}");
    let e = parse_err("camera { mesh_camera { 1 0 sphere { 0, 1 } } }");
    assert!(e.contains("expected a mesh"), "{e}");
}

#[test]
fn media_blocks_parse() {
    let s = parse(
        "#declare M = media { emission 0.5 samples 5, 9 scattering { 5, rgb <1, 0.5, 0> eccentricity 0.3 extinction 0.5 } }\n\
         #declare D = density { spherical density_map { [0 rgb 0] [1 spherical] } }\n\
         media { M absorption 0.2 density { D } density { checker density { rgb 1 } density { rgb 0 } } }\n\
         sphere { 0, 1 hollow interior { media { M } media { emission 1 } } }",
    );
    assert_eq!(s.media.len(), 1);
    let m = &s.media[0];
    assert_eq!(m.samples, (5, 9));
    assert_eq!(m.absorption, glam::DVec3::splat(0.2));
    assert_eq!(m.density.len(), 2);
    let sc = m.scattering.unwrap();
    assert_eq!((sc.kind, sc.eccentricity, sc.extinction), (5, 0.3, 0.5));
    let int = s.objects[0].interior.as_ref().unwrap();
    assert_eq!(int.media().len(), 2);
    // povray refuses eccentricity outside Henyey-Greenstein scattering.
    assert!(parse_err("media { scattering { 1, 0.1 eccentricity 0.5 } }").contains("eccentricity"));
}
