//! The `text` object: parsing (fonts found like include files, string expressions, thickness
//! and offset forms), its errors and warnings, and the extents POV-Ray 3.7 reports for it.
//!
//! Tests that need POV-Ray's fonts skip, saying so, where Debian's povray-includes is not
//! installed (CI installs it).

mod common;

use std::path::{Path, PathBuf};

use common::{parse_err, parser};
use lancer::scene::desc::ShapeDesc;
use lancer::sdl::{ParseOptions, Parser};

const FONT_DIR: &str = "/usr/share/povray-3.7/include";

fn fonts_installed() -> bool {
    let ok = Path::new(FONT_DIR).join("timrom.ttf").exists();
    if !ok {
        eprintln!(
            "skipped: POV-Ray's fonts are not in {FONT_DIR} (apt-get install povray-includes)"
        );
    }
    ok
}

/// The vectors a snippet `#declare`s as `sphere { V, 1 }` lines, in order.
fn centres(src: &str) -> Vec<glam::DVec3> {
    parser(src)
        .scene
        .objects
        .iter()
        .filter_map(|o| match o.shape {
            ShapeDesc::Sphere { center, .. } => Some(center),
            _ => None,
        })
        .collect()
}

fn close(a: glam::DVec3, b: [f64; 3]) -> bool {
    (a - glam::DVec3::from(b)).abs().max_element() < 5e-5
}

#[test]
fn missing_font_names_the_file_and_the_directories() {
    let msg = parse_err("text { ttf \"no_such_font.ttf\" \"abc\" 1, 0 }");
    assert!(
        msg.contains("cannot find font file \"no_such_font.ttf\""),
        "{msg}"
    );
    let mut p = Parser::new(ParseOptions {
        library_paths: vec![PathBuf::from("/nonexistent/fonts")],
        ..ParseOptions::default()
    });
    let e = p
        .parse_str("snippet.pov", "text { ttf \"nope\" \"abc\" 1, 0 }")
        .unwrap_err();
    assert!(
        e.notes.iter().any(|n| n.contains("/nonexistent/fonts")),
        "{:?}",
        e.notes
    );
    let msg = parse_err("text { ttf_file \"x.ttf\" \"abc\" 1, 0 }");
    assert!(msg.contains("expected 'ttf' or 'internal'"), "{msg}");
}

#[test]
fn unreadable_font_file_is_an_error_not_a_panic() {
    let dir = std::env::temp_dir().join(format!("lancer-text-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("junk.ttf"), b"\0\x01\0\0 definitely not a font").unwrap();
    std::fs::write(dir.join("empty.ttf"), b"").unwrap();
    for name in ["junk.ttf", "empty.ttf"] {
        let mut p = Parser::new(ParseOptions {
            library_paths: vec![dir.clone()],
            ..ParseOptions::default()
        });
        let src = format!("text {{ ttf \"{name}\" \"abc\" 1, 0 }}");
        let e = p.parse_str("snippet.pov", &src).unwrap_err();
        assert!(e.message.contains(name), "{}", e.message);
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn extents_match_povray() {
    if !fonts_installed() {
        return;
    }
    // max_extent values printed by povray 3.7 for the same texts (min is 0 in x, as the
    // first glyph starts at the origin).
    let v = centres(
        r#"
        #declare A = text { ttf "timrom.ttf" "AV" 1, 0 }
        sphere { max_extent(A), 1 } sphere { min_extent(A), 1 }
        #declare B = text { ttf "timrom.ttf" "HH" 0.5, 0.1 }
        sphere { max_extent(B), 1 }
        #declare C = text { internal 3 "Hello" 1, 0 }
        sphere { max_extent(C), 1 }
        #declare D = text { ttf "cyrvetic" "AV" 1 0 }
        sphere { max_extent(D), 1 }
        #declare E = text { ttf "povlogo.ttf" "PV" 1, <0,0,0.3> }
        sphere { max_extent(E), 1 }
        "#,
    );
    assert!(close(v[0], [1.278, 0.696, 1.0]), "{}", v[0]);
    assert!(close(v[1], [0.0, -0.016, 0.0]), "{}", v[1]);
    // A float offset moves each following glyph along y too.
    assert!(close(v[2], [1.562, 0.78, 0.5]), "{}", v[2]);
    assert!(close(v[3], [2.44972, 0.69828, 1.0]), "{}", v[3]);
    assert!(close(v[4], [1.188, 0.728, 1.0]), "{}", v[4]);
    // An offset's z is not used.
    assert!(close(v[5], [1.373064, 1.001965, 1.0]), "{}", v[5]);
}

#[test]
fn string_expressions_thickness_and_offset_forms() {
    if !fonts_installed() {
        return;
    }
    let p = parser(
        r#"
        #declare F = "timrom.ttf";
        #declare S = concat("v", str(3.7, 0, 1), chr(33));
        text { ttf F, S, 0.25, <0.1, 0> }
        text { ttf concat("tim", "rom.ttf") "gj" -0.4, 0 }
        text { internal 9 "P" 1, 0 }
        text { ttf "timrom.ttf" "" 1, 0 }
        text { ttf "timrom.ttf" "flat" 0, 0 pigment { rgb 1 } translate x }
        "#,
    );
    let texts: Vec<_> = p
        .scene
        .objects
        .iter()
        .map(|o| match &o.shape {
            ShapeDesc::Text(t) => t.clone(),
            other => panic!("not a text: {other:?}"),
        })
        .collect();
    assert_eq!(texts.len(), 5);
    assert_eq!(texts[0].glyphs.len(), 5); // "v3.7!"
    assert_eq!(texts[0].thickness, 0.25);
    assert_eq!(texts[1].thickness, -0.4);
    assert_eq!(texts[1].glyphs.len(), 2);
    // Out-of-range internal font numbers mean font 0, povlogo, whose "P" is the logo.
    assert_eq!(texts[2].glyphs.len(), 1);
    assert!(texts[2].glyphs[0].glyph.bounds.is_some());
    assert!(texts[3].glyphs.is_empty());
    assert_eq!(p.scene.objects[4].transform.m.w_axis.x, 1.0);
    // The offset is required, as in POV-Ray.
    let msg = parse_err("text { ttf \"timrom.ttf\" \"abc\" 1 pigment { rgb 1 } }");
    assert!(msg.contains("error"), "{msg}");
}

#[test]
fn missing_glyphs_warn_and_charset_utf8_reads_unicode() {
    if !fonts_installed() {
        return;
    }
    let p = parser("text { ttf \"timrom.ttf\" \"a\u{2122}b\" 1, 0 }");
    let w: Vec<&str> = p.warnings.iter().map(|d| d.message.as_str()).collect();
    assert!(
        w.iter()
            .any(|m| m.contains("U+2122") && m.contains("charset utf8")),
        "{w:?}"
    );
    let p =
        parser("global_settings { charset utf8 } text { ttf \"timrom.ttf\" \"a\u{2122}b\" 1, 0 }");
    assert!(
        p.warnings.iter().all(|d| !d.message.contains("U+2122")),
        "{:?}",
        p.warnings
    );
    let msg = parse_err("global_settings { charset latin1 }");
    assert!(msg.contains("charset"), "{msg}");
}

#[test]
fn text_renders_and_hides_nothing_behind_an_empty_string() {
    if !fonts_installed() {
        return;
    }
    let dir = std::env::temp_dir().join(format!("lancer-text-render-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("t.pov");
    std::fs::write(
        &scene,
        r#"#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0.5,0.35,-2> right x*1.2 up y*0.9 }
light_source { <0,0,-10> rgb 1 }
background { rgb 0 }
text { ttf "timrom.ttf" "H" 0.5, 0 pigment { rgb 1 } finish { ambient 1 diffuse 0 } }
text { ttf "timrom.ttf" "" 0.5, 0 pigment { rgb <1,0,0> } }
text { ttf "timrom.ttf" "I" 0, 0 pigment { rgb <0,1,0> } translate <10,0,0> }
"#,
    )
    .unwrap();
    let settings = lancer::render::RenderSettings {
        width: 48,
        height: 36,
        antialias: None,
        ..Default::default()
    };
    let film = lancer::api::render_file(&scene, &[], &settings).unwrap();
    std::fs::remove_dir_all(&dir).ok();
    let at = |x: usize, y: usize| film.pixels[y * 48 + x];
    // Left stem of the H (x ≈ 0.05 to 0.25 of its 0.711) and the gap between the stems.
    let stem = at(8, 18);
    let gap = at(20, 12);
    assert!(stem.min_element() > 0.9, "{stem}");
    assert!(gap.max_element() < 0.1, "{gap}");
}
