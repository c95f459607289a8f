//! The `compare` and `check` subcommands as a user's script meets them: what they print and
//! which exit codes they give.

mod common;

use std::path::{Path, PathBuf};

fn lancer(args: &[&str]) -> (i32, String, String) {
    common::lancer_in(Path::new("."), args)
}

fn reference(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("reference")
        .join(name)
        .to_string_lossy()
        .into_owned()
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("lancer-tools-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

fn value(stdout: &str, key: &str) -> f64 {
    let line = stdout
        .lines()
        .find(|l| l.starts_with(key))
        .unwrap_or_else(|| panic!("no {key} in {stdout}"));
    line.split_whitespace().nth(1).unwrap().parse().unwrap()
}

#[test]
fn compare_identical_pictures() {
    let a = reference("glass.png");
    let (code, out, err) = lancer(&["compare", &a, &a, "--min-ssim", "0.999"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(value(&out, "ssim"), 1.0);
    assert!(out.contains("psnr inf dB"), "{out}");
}

#[test]
fn compare_below_minimum_exits_1_and_writes_a_heat_map() {
    let diff = scratch("heat.png");
    let (code, out, err) = lancer(&[
        "compare",
        &reference("glass.png"),
        &reference("phong.png"),
        "--min-ssim",
        "0.95",
        "--diff",
        diff.to_str().unwrap(),
    ]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(value(&out, "ssim") < 0.95);
    assert!(value(&out, "worst_tile") <= value(&out, "ssim"));
    assert!(err.contains("below the minimum"), "{err}");
    let heat = image::open(&diff).expect("heat map is a PNG");
    assert_eq!((heat.width(), heat.height()), (320, 240));
}

#[test]
fn compare_unreadable_or_mismatched_exits_2() {
    let (code, _, err) = lancer(&["compare", &reference("glass.png"), "/no/such.png"]);
    assert_eq!(code, 2, "{err}");
    let small = scratch("small.png");
    image::RgbImage::new(32, 24).save(&small).unwrap();
    let (code, _, err) = lancer(&["compare", &reference("glass.png"), small.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("differ in size"), "{err}");
}

#[test]
fn check_parses_without_rendering() {
    let good = scratch("good.pov");
    std::fs::write(
        &good,
        "#declare R = 1;\nsphere { 0, R pigment { rgb 1 } }\n",
    )
    .unwrap();
    let bad = scratch("bad.pov");
    std::fs::write(&bad, "sphere { 0, Nope }\n").unwrap();
    let (code, _, err) = lancer(&["check", good.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("ok"), "{err}");
    assert!(!good.with_extension("png").exists());
    let (code, _, err) = lancer(&["check", good.to_str().unwrap(), bad.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(err.contains("bad.pov:1:"), "{err}");
    assert!(err.contains("1 of 2 files parsed"), "{err}");
}

#[test]
fn loop_cap_and_io_permission_from_the_command_line() {
    let endless = scratch("endless.pov");
    std::fs::write(&endless, "#while (1) #end\n").unwrap();
    let (code, _, err) = lancer(&[
        "check",
        "--max-loop-iterations",
        "1000",
        endless.to_str().unwrap(),
    ]);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("endless.pov:1:"), "{err}");
    let outside = std::env::temp_dir().join(format!("lancer-io-{}", std::process::id()));
    std::fs::create_dir_all(&outside).unwrap();
    let target = outside.join("out.txt");
    let writer = scratch("writer.pov");
    std::fs::write(
        &writer,
        format!(
            "#fopen F \"{}\" write #write (F, \"hi\") #fclose F\n",
            target.display()
        ),
    )
    .unwrap();
    let (code, _, err) = lancer(&["check", "-q", writer.to_str().unwrap()]);
    assert_eq!(
        code, 1,
        "writing outside the scene's directory needs permission: {err}"
    );
    let (code, _, err) = lancer(&[
        "check",
        "-q",
        "--allow-io",
        outside.to_str().unwrap(),
        writer.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(std::fs::read_to_string(&target).unwrap(), "hi");
}

#[test]
fn check_takes_the_options_a_render_would() {
    let f = scratch("declared.pov");
    std::fs::write(&f, "sphere { 0, Size * clock }\n").unwrap();
    let (code, _, err) = lancer(&["check", f.to_str().unwrap(), "Declare=Size=2", "+K0.5"]);
    assert_eq!(code, 0, "{err}");
}
