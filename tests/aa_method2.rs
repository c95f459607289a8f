//! Anti-aliasing method 2 (`+AM2`) against the `povray` binary itself, at depths and jitter
//! settings the stored references (reference/*_am2.png: depth 3, no jitter) leave out.
//! Skipped, with a note, where `povray` is not installed.

use std::path::{Path, PathBuf};
use std::process::Command;

use clap::Parser as _;
use lancer::cli::{make_job, split_args, Cli, Command as LancerCommand};
use lancer::ssim::{ssim, Picture};

const INCLUDE: &str = "/usr/share/povray-3.7/include";

struct Case {
    scene: &'static str,
    options: &'static str,
    min_ssim: f64,
    /// Whether the sub-sample count must agree with POV-Ray's: only without jitter, where
    /// both programs make the same decisions.
    count: bool,
}

const CASES: &[Case] = &[
    // +R1 never splits: only the corners.
    Case {
        scene: "mirror_spheres.pov",
        options: "+W80 +H60 +A0.3 +AM2 -J +R1",
        min_ssim: 0.995,
        count: true,
    },
    Case {
        scene: "mirror_spheres.pov",
        options: "+W80 +H60 +A0.3 +AM2 -J +R2",
        min_ssim: 0.995,
        count: true,
    },
    Case {
        scene: "mirror_spheres.pov",
        options: "+W80 +H60 +A0.3 +AM2 -J +R4",
        min_ssim: 0.995,
        count: true,
    },
    // Jitter: POV-Ray's offsets are its own, so only their amount can agree (0.996 measured).
    Case {
        scene: "mirror_spheres.pov",
        options: "+W80 +H60 +A0.3 +AM2 +J +R3",
        min_ssim: 0.98,
        count: false,
    },
    Case {
        scene: "glass.pov",
        options: "+W80 +H60 +A0.1 +AM2 +J0.5 +R2 +AG1.0",
        min_ssim: 0.98,
        count: false,
    },
];

fn povray_available() -> bool {
    Command::new("povray").arg("--version").output().is_ok()
}

/// POV-Ray's picture and its sub-sample count ("Samples:" in its statistics).
fn povray(scene: &Path, options: &str, out: &Path) -> (Picture, u64) {
    let scenes = scene.parent().unwrap();
    let output = Command::new("povray")
        .args(["-D", "+V", "+FN8"])
        .args(options.split_whitespace())
        .arg(format!("+L{}", scenes.display()))
        .arg(format!("+L{INCLUDE}"))
        .arg(format!("+I{}", scene.display()))
        .arg(format!("+O{}", out.display()))
        .output()
        .expect("run povray");
    let log = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "povray failed:\n{log}");
    let samples = log
        .lines()
        .find_map(|l| {
            let rest = l.split("Samples:").nth(1)?;
            rest.split_whitespace().next()?.parse().ok()
        })
        .expect("povray's statistics give a sample count");
    (Picture::load(out).expect("povray's picture"), samples)
}

/// lancer's picture and its sub-sample count (camera rays besides the corner grid).
fn lancer(scene: &Path, options: &str) -> (Picture, u64) {
    let mut args = vec!["lancer".to_string(), scene.display().to_string()];
    args.extend(options.split_whitespace().map(String::from));
    let (c, pov) = split_args(args);
    let LancerCommand::Render(r) = Cli::try_parse_from(c).unwrap().command else {
        panic!("{options} is not a render");
    };
    let job = make_job(r, &pov).unwrap();
    let s = &job.settings;
    let film = lancer::api::render_file(&job.scene, &job.library_paths, s).unwrap();
    let corners = ((s.width + 1) * (s.height + 1)) as u64;
    let picture = Picture::from_rgb8(film.width, film.height, &lancer::output::to_rgb8(&film));
    (picture, film.camera_rays - corners)
}

#[test]
fn method2_matches_povray_at_other_depths_and_with_jitter() {
    if !povray_available() {
        eprintln!("skipped: povray is not on PATH (apt-get install povray)");
        return;
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = std::env::temp_dir().join(format!("lancer-am2-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut failures = Vec::new();
    for (i, case) in CASES.iter().enumerate() {
        let scene: PathBuf = root.join("scenes").join(case.scene);
        let (theirs, their_samples) = povray(&scene, case.options, &dir.join(format!("{i}.png")));
        let (ours, our_samples) = lancer(&scene, case.options);
        let s = ssim(&ours, &theirs).unwrap();
        eprintln!(
            "{} {}: ssim {s:.4}, sub-samples {our_samples} (povray {their_samples})",
            case.scene, case.options
        );
        if s < case.min_ssim {
            failures.push(format!("{} {}: SSIM {s:.4}", case.scene, case.options));
        }
        // Edge pixels where the two programs' floating point differs may split differently.
        let off = our_samples.abs_diff(their_samples) as f64;
        if case.count && off > 0.02 * their_samples.max(50) as f64 {
            failures.push(format!(
                "{} {}: {our_samples} sub-samples, povray {their_samples}",
                case.scene, case.options
            ));
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
