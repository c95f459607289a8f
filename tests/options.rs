//! POV-Ray options that change what the scene sees or how it is drawn, as a user's command
//! line or INI file gives them: Include_Header, Version, Frame_Step and subset fractions,
//! quality levels and options lancer accepts without effect. The pictures for quality levels
//! and alpha are checked against povray in tests/probes.rs.

mod common;

use std::path::{Path, PathBuf};

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("lancer-options-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

const SCENE: &str = "camera { location <0,0,-3> look_at 0 }
light_source { <2,3,-4> rgb 1 }
sphere { 0, 1 pigment { HeaderColour } }
#debug concat(\"version \", str(version,0,2), \"\\n\")
";

#[test]
fn include_header_and_version_reach_the_scene() {
    let dir = scratch("header");
    std::fs::write(dir.join("s.pov"), SCENE).unwrap();
    std::fs::write(
        dir.join("hdr.inc"),
        "#declare HeaderColour = rgb <1,0,0>;\n",
    )
    .unwrap();
    let (code, _, err) = common::lancer_in(
        &dir,
        &["s.pov", "+W8", "+H6", "+HIhdr.inc", "+MV3.5", "-Oout.png"],
    );
    assert_eq!(code, 0, "{err}");
    // povray prints the same for these options.
    assert!(err.contains("version 3.50"), "{err}");
    // The same through an INI file.
    std::fs::write(
        dir.join("s.ini"),
        "Input_File_Name=s.pov\nInclude_Header=hdr.inc\nVersion=3.6\nWidth=8\nHeight=6\n",
    )
    .unwrap();
    let (code, _, err) = common::lancer_in(&dir, &["s.ini"]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("version 3.60"), "{err}");
    assert!(dir.join("s.png").is_file());
}

#[test]
fn missing_include_header_names_the_file_and_option() {
    let dir = scratch("noheader");
    std::fs::write(dir.join("s.pov"), SCENE).unwrap();
    let (code, _, err) = common::lancer_in(&dir, &["s.pov", "+W8", "+H6", "+HInone.inc"]);
    assert_eq!(code, 1);
    assert!(
        err.contains("\"none.inc\"") && err.contains("+HI") && err.contains("searched"),
        "{err}"
    );
}

#[test]
fn frame_step_and_subset_fraction_pick_povrays_frames() {
    let dir = scratch("step");
    std::fs::write(dir.join("t.pov"), "sphere { 0, 1 pigment { rgb clock } }\n").unwrap();
    let (code, _, err) = common::lancer_in(
        &dir,
        &[
            "t.pov", "+W4", "+H3", "+KFI1", "+KFF10", "+SF0.333", "+STP2", "--quiet",
        ],
    );
    assert_eq!(code, 0, "{err}");
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".png"))
        .collect();
    names.sort();
    // Frames 3 to 10 (0.333 of 10 frames is frame 3), every second one.
    assert_eq!(names, ["t03.png", "t05.png", "t07.png", "t09.png"]);
}

#[test]
fn options_without_effect_are_accepted_quietly() {
    let dir = scratch("quiet");
    std::fs::write(
        dir.join("t.pov"),
        "global_settings { assumed_gamma 1 } sphere { 0, 1 pigment { rgb 1 } }\n",
    )
    .unwrap();
    let args = [
        "t.pov", "+W4", "+H3", "+MI64", "+RP3", "+RS2", "+BS16", "+WL2", "+UF", "+UO", "+BM2",
        "-UA",
    ];
    let (code, _, err) = common::lancer_in(&dir, &args);
    assert_eq!(code, 0, "{err}");
    assert!(!err.contains("warning"), "{err}");
    assert!(Path::new(&dir.join("t.png")).is_file());
}

#[test]
fn output_to_standard_output() {
    let dir = scratch("stdout");
    std::fs::write(
        dir.join("t.pov"),
        "global_settings { assumed_gamma 1 } sphere { 0, 1 pigment { rgb 1 } }\n",
    )
    .unwrap();
    let (code, out, err) = common::lancer_in(&dir, &["t.pov", "+W4", "+H3", "+O-", "+FP"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.starts_with("P6\n"), "{out:?}");
    assert!(!dir.join("-").exists() && !dir.join("-.ppm").exists());
    let (code, _, err) = common::lancer_in(&dir, &["t.pov", "+W4", "+H3", "+O-", "+KFF3"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("+O-"), "{err}");
}
