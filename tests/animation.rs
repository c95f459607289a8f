//! Animations through the binary: POV-Ray's frame names, the clock each frame sees, `+C`
//! resuming, and frames that are the same bytes however the run is split (the basis of
//! spreading an animation over machines).

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

const SCENE: &str = "#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -6> look_at 0 }
light_source { <3, 5, -4> rgb 1 }
plane { y, -1 pigment { checker rgb 0.2 rgb 0.9 } }
sphere { <-2 + 4 * clock, 0, 0>, 0.8 pigment { rgb <1, frame_number / 6, 0.2> } }
";

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("lancer-anim-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    std::fs::write(d.join("spin.pov"), SCENE).unwrap();
    d
}

/// Renders frames 1-6 of spin.pov in `d` (more options after), which must succeed; stderr.
fn lancer(d: &Path, args: &[&str]) -> String {
    let mut all = vec!["spin.pov", "+W48", "+H36", "+A0.3", "+KFI1", "+KFF6"];
    all.extend_from_slice(args);
    let (code, _, err) = common::lancer_in(d, &all);
    assert_eq!(code, 0, "{err}");
    err
}

fn frame(d: &Path, n: u32) -> Vec<u8> {
    std::fs::read(d.join(format!("spin{n}.png"))).unwrap_or_default()
}

#[test]
fn frames_are_the_same_bytes_whole_or_split() {
    let whole = dir("whole");
    lancer(&whole, &[]);
    let split = dir("split");
    for (a, b) in [("1", "2"), ("3", "4"), ("5", "6")] {
        lancer(&split, &[&format!("+SF{a}"), &format!("+EF{b}"), "+WT1"]);
    }
    for n in 1..=6 {
        let w = frame(&whole, n);
        assert!(!w.is_empty(), "frame {n} missing");
        assert_eq!(w, frame(&split, n), "frame {n} differs between the runs");
    }
    // The clock moved the sphere: consecutive frames differ.
    assert_ne!(frame(&whole, 1), frame(&whole, 2));
}

#[test]
fn continue_skips_frames_already_written() {
    let d = dir("resume");
    std::fs::write(d.join("spin2.png"), b"left by an earlier run").unwrap();
    let err = lancer(&d, &["+C"]);
    assert!(err.contains("frame 2 done already"), "{err}");
    assert_eq!(frame(&d, 2), b"left by an earlier run");
    for n in [1, 3, 4, 5, 6] {
        assert!(
            image::open(d.join(format!("spin{n}.png"))).is_ok(),
            "frame {n}"
        );
    }
}

#[test]
fn ten_or_more_frames_are_padded_to_the_last_frames_digits() {
    let d = dir("pad");
    lancer(&d, &["+KFF12", "+SF9", "+EF10", "-A"]);
    assert!(d.join("spin09.png").exists());
    assert!(d.join("spin10.png").exists());
}

#[test]
fn ini_file_with_a_section_and_switches_after_it() {
    let d = dir("ini");
    std::fs::write(
        d.join("spin.ini"),
        "; the whole animation\nInput_File_Name=spin.pov\nInitial_Frame=1\nFinal_Frame=4\n\
         Antialias=off\n[Small]\nInput_File_Name=spin.pov\nWidth=32\nHeight=24\nFinal_Frame=3\n\
         Pre_Frame_Command=touch hacked\n",
    )
    .unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_lancer"))
        .env("LANCER_NO_CONFIG", "1")
        .current_dir(&d)
        .args(["spin.ini[small]", "+EF2"])
        .output()
        .expect("run lancer");
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    assert!(err.contains("never runs shell commands"), "{err}");
    assert!(!d.join("hacked").exists());
    // The section's Final_Frame=3 (one digit), the command line's +EF2 after the INI file.
    assert!(d.join("spin1.png").exists() && d.join("spin2.png").exists());
    assert!(!d.join("spin3.png").exists());
    let img = image::open(d.join("spin1.png")).unwrap();
    assert_eq!((img.width(), img.height()), (32, 24));
}

#[test]
fn partial_render_is_the_whole_render_inside_the_window_and_black_outside() {
    let d = dir("partial");
    let run = |out: &str, extra: &[&str]| {
        let mut args = vec!["spin.pov", "+W40", "+H30", "-A", "+K0.5", "-q"];
        args.extend_from_slice(extra);
        args.push(out);
        let o = Command::new(env!("CARGO_BIN_EXE_lancer"))
            .env("LANCER_NO_CONFIG", "1")
            .current_dir(&d)
            .args(&args)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        image::open(d.join(&out[2..])).unwrap().to_rgb8()
    };
    let whole = run("+Owhole.png", &[]);
    // Rows 25%..80% (7..24), columns 10..30 counted from 1 (9..30): as povray 3.7 reads them.
    let part = run("+Opart.png", &["+SR0.25", "+ER0.8", "+SC10", "+EC30"]);
    assert_eq!(part.dimensions(), (40, 30));
    for (x, y, p) in part.enumerate_pixels() {
        let inside = (7..24).contains(&y) && (9..30).contains(&x);
        if inside {
            assert_eq!(p, whole.get_pixel(x, y), "({x}, {y})");
        } else {
            assert_eq!(p.0, [0, 0, 0], "({x}, {y}) should be black");
        }
    }
}

#[test]
fn declare_and_output_to_file_from_the_command_line() {
    let d = dir("declare");
    std::fs::write(
        d.join("size.pov"),
        "#version 3.7;\nglobal_settings { assumed_gamma 1 }\ncamera { location -5*z look_at 0 }\n\
         light_source { <1, 2, -3> rgb 1 }\n#if (Big > 1) sphere { 0, 1 pigment { rgb 1 } } #end\n",
    )
    .unwrap();
    let run = |args: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_lancer"))
            .env("LANCER_NO_CONFIG", "1")
            .current_dir(&d)
            .args(args)
            .output()
            .unwrap()
    };
    // Without the declaration `Big` is undeclared: an error.
    assert!(!run(&["size.pov", "+W16", "+H12", "-q"]).status.success());
    let o = run(&["size.pov", "+W16", "+H12", "Declare=Big=2", "-q"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(d.join("size.png").exists());
    std::fs::remove_file(d.join("size.png")).unwrap();
    let o = run(&[
        "size.pov",
        "+W16",
        "+H12",
        "Declare=Big=2",
        "Output_To_File=off",
    ]);
    assert!(o.status.success());
    assert!(
        !d.join("size.png").exists(),
        "Output_To_File=off writes nothing"
    );
}
