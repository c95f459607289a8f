//! The binary's behaviour on bad input: exit 1 with file and line, never a panic or a hang;
//! exit 2 on usage errors.

mod common;

use std::path::{Path, PathBuf};

/// Exit code and stderr.
fn lancer(args: &[&str]) -> (i32, String) {
    let (code, _, err) = common::lancer_in(Path::new("."), args);
    (code, err)
}

fn scene_file(name: &str, content: &[u8]) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("lancer-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, content).unwrap();
    p
}

fn expect_scene_error(name: &str, content: &[u8], needle: &str) {
    let p = scene_file(name, content);
    let out = p.with_extension("png");
    let (code, err) = lancer(&[
        p.to_str().unwrap(),
        "-q",
        "-o",
        out.to_str().unwrap(),
        "+W8",
        "+H8",
    ]);
    assert_eq!(code, 1, "{name}: {err}");
    assert!(
        err.contains(&format!("{name}:")),
        "{name}: no file:line in {err}"
    );
    assert!(err.contains(needle), "{name}: expected '{needle}' in {err}");
    assert!(!err.contains("panicked"), "{err}");
    assert!(!out.exists(), "no picture may be written on error");
}

#[test]
fn malformed_input_is_exit_1_with_a_place() {
    expect_scene_error("unclosed.pov", b"sphere { 0, 1\n", "never closed");
    expect_scene_error(
        "undeclared.pov",
        b"sphere { Here, 1 }\n",
        "undeclared identifier 'Here'",
    );
    expect_scene_error(
        "missing_include.pov",
        b"#include \"no_such_file.inc\"\n",
        "povray-includes",
    );
    expect_scene_error("bad_number.pov", b"sphere { 0, 1.2.3 }\n", "unexpected");
    expect_scene_error(
        "string.pov",
        b"#declare S = \"never closed\n",
        "unterminated string",
    );
    expect_scene_error(
        "garbage.pov",
        &[0x7f, 0x45, 0x4c, 0x46, 0x02, 0x01, 0x00, 0xff, 0xfe, 0x00],
        "does not look like scene text",
    );
}

#[test]
fn usage_errors_exit_2() {
    let (code, _) = lancer(&["render", "--width", "abc", "x.pov"]);
    assert_eq!(code, 2);
    let (code, err) = lancer(&[]);
    assert_eq!(code, 2, "{err}");
}

#[test]
fn renders_a_tiny_scene_to_png() {
    let p = scene_file("tiny.pov", b"#version 3.7; global_settings { assumed_gamma 1 } camera { location -3*z look_at 0 } light_source { <1,1,-3> rgb 1 } sphere { 0, 1 pigment { rgb <1,0,0> } }");
    let out = p.with_file_name("tiny_out.png");
    let (code, err) = lancer(&[
        p.to_str().unwrap(),
        "+W16",
        "+H12",
        "-A",
        &format!("+O{}", out.display()),
        "-q",
    ]);
    assert_eq!(code, 0, "{err}");
    let img = image::open(&out).unwrap().to_rgb8();
    assert_eq!(img.dimensions(), (16, 12));
    assert!(
        img.get_pixel(8, 6)[0] > 100,
        "the sphere is red in the middle"
    );
}

/// A picture too big for memory in a format written whole is refused before any work, with
/// the memory it needs and the options that avoid it: never an allocation abort (exit 134).
/// PNG and PPM of that size are rendered band by band instead (src/render/band.rs tests).
#[test]
fn a_picture_too_big_for_memory_is_refused_up_front() {
    let p = scene_file("huge.pov", b"sphere { 0, 1 pigment { rgb 1 } }\n");
    let out = p.with_extension("jpg");
    let (code, err) = lancer(&[
        p.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "+W100000",
        "+H100000",
        "+FJ",
        "-A",
    ]);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("100000x100000") && err.contains("GB"), "{err}");
    assert!(err.contains("+FN") && err.contains("+FP"), "{err}");
    assert!(!out.exists());
}
