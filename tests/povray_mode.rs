//! lancer installed under the name `povray` (a symlink): POV-Ray's message lines on stderr and
//! POV-Ray's exit codes (src/app/povray_msgs.rs), checked against Debian's povray where it is
//! installed: a parse error, a missing scene, an output that cannot be written, a success with
//! its statistics, and a user abort (SIGINT).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const OK: &str = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\ncamera { location -3*z look_at 0 }\nlight_source { <1,2,-3> rgb 1 }\nsphere { 0, 1 pigment { rgb 1 } }\n";
const BAD: &str = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\nsphere { 0, 1 pigment { rgb 1 }\nbox { 0, 1 }\n";

fn setup(name: &str) -> (PathBuf, PathBuf) {
    let d = std::env::temp_dir().join(format!("lancer-povray-mode-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    std::fs::write(d.join("ok.pov"), OK).unwrap();
    std::fs::write(d.join("bad.pov"), BAD).unwrap();
    let link = d.join("povray");
    std::os::unix::fs::symlink(env!("CARGO_BIN_EXE_lancer"), &link).unwrap();
    (d, link)
}

fn run(program: &Path, dir: &Path, args: &[&str]) -> Output {
    Command::new(program)
        .current_dir(dir)
        .args(args)
        .env("LANCER_NO_CONFIG", "1")
        .output()
        .expect("run")
}

/// The lines of stderr that POV-Ray's tools look for.
fn key_lines(o: &Output) -> Vec<String> {
    String::from_utf8_lossy(&o.stderr)
        .lines()
        .filter_map(|l| {
            if let Some(i) = l.find("Parse Error:") {
                // The wording of the message is lancer's own; the place is POV-Ray's.
                return Some(l[..i + "Parse Error:".len()].to_string());
            }
            [
                "Fatal error in parser: Cannot parse input.",
                "Render failed",
                "Render Time:",
                "POV-Ray finished",
            ]
            .contains(&l)
            .then(|| l.to_string())
        })
        .collect()
}

fn has_povray() -> bool {
    Command::new("povray").arg("--version").output().is_ok()
}

#[test]
fn messages_and_exit_codes_as_povray() {
    let (d, link) = setup("messages");
    let cases: [(&[&str], i32, &[&str]); 4] = [
        (
            &["-D", "-V", "+W8", "+H6", "bad.pov", "+Obad.png"],
            1,
            &[
                "File 'bad.pov' line 4: Parse Error:",
                "Fatal error in parser: Cannot parse input.",
                "Render failed",
            ],
        ),
        (
            &["-D", "-V", "+W8", "+H6", "missing.pov"],
            1,
            &[
                "Possible Parse Error:",
                "Parse Error:",
                "Fatal error in parser: Cannot parse input.",
                "Render failed",
            ],
        ),
        (
            &[
                "-D",
                "-V",
                "+W8",
                "+H6",
                "ok.pov",
                "+O/nonexistent/dir/x.png",
            ],
            1,
            &["Render failed"],
        ),
        (
            &["-D", "-V", "+W8", "+H6", "ok.pov", "+Ook.png"],
            0,
            &["Render Time:", "POV-Ray finished"],
        ),
    ];
    let povray = has_povray();
    for (args, code, lines) in cases {
        let o = run(&link, &d, args);
        assert_eq!(o.status.code(), Some(code), "{args:?}");
        assert_eq!(key_lines(&o), lines.to_vec(), "{args:?}");
        if povray {
            let p = run(Path::new("povray"), &d, args);
            assert_eq!(p.status.code(), Some(code), "povray {args:?}");
            assert_eq!(key_lines(&p), lines.to_vec(), "povray {args:?}");
        }
    }
    // Invoked as lancer, the exit codes are the same and POV-Ray's lines are not printed.
    let o = run(Path::new(env!("CARGO_BIN_EXE_lancer")), &d, &["bad.pov"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(key_lines(&o).is_empty());
    // ... unless asked for.
    let o = run(
        Path::new(env!("CARGO_BIN_EXE_lancer")),
        &d,
        &["bad.pov", "--povray-messages"],
    );
    assert_eq!(key_lines(&o).len(), 3);
}

/// Until the process catches SIGINT (its handler is set at start), read from
/// /proc/PID/status: a fixed sleep could send the signal before, on a loaded machine, and the
/// default action would kill it with no exit code. Without /proc, half a second.
fn wait_for_sigint_handler(pid: u32) {
    let start = std::time::Instant::now();
    let status = format!("/proc/{pid}/status");
    while start.elapsed() < std::time::Duration::from_secs(20) {
        let Ok(text) = std::fs::read_to_string(&status) else {
            std::thread::sleep(std::time::Duration::from_millis(500));
            return;
        };
        let caught = text
            .lines()
            .find_map(|l| l.strip_prefix("SigCgt:"))
            .and_then(|h| u64::from_str_radix(h.trim(), 16).ok())
            .unwrap_or(0);
        // SIGINT is signal 2: bit 1.
        if caught & 2 != 0 {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
    // The render under way, as the test means it.
    std::thread::sleep(std::time::Duration::from_millis(200));
}

#[test]
fn user_abort_exits_with_2() {
    let (d, link) = setup("abort");
    // Big and supersampled enough to be still rendering when the signal comes.
    let child = Command::new(&link)
        .current_dir(&d)
        .args(["+W3000", "+H3000", "+A0.0", "+R6", "ok.pov", "+Oabort.png"])
        .env("LANCER_NO_CONFIG", "1")
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    wait_for_sigint_handler(child.id());
    Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    let o = child.wait_with_output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("Render cancelled by user"), "{err}");
    assert!(!d.join("abort.png").exists());
}

/// `+O-` writes the picture to standard output in every type POV-Ray streams (PNG, PPM,
/// Targa, RLE Targa): the same bytes as the file lancer writes, starting as povray's do.
#[test]
fn pictures_to_standard_output() {
    let (d, link) = setup("stdout");
    let povray = has_povray();
    for (letter, ext) in [("N", "png"), ("P", "ppm"), ("T", "tga"), ("C", "tga")] {
        let ty = format!("+F{letter}");
        let piped = run(&link, &d, &["-D", "+W8", "+H6", "ok.pov", &ty, "+O-"]);
        assert!(piped.status.success(), "{ty}");
        let file = format!("+Oout.{ext}");
        assert!(run(&link, &d, &["-D", "+W8", "+H6", "ok.pov", &ty, &file])
            .status
            .success());
        let written = std::fs::read(d.join(format!("out.{ext}"))).unwrap();
        assert_eq!(piped.stdout, written, "{ty}");
        if povray {
            let p = run(
                Path::new("povray"),
                &d,
                &["-D", "-V", "+W8", "+H6", "ok.pov", &ty, "+O-"],
            );
            assert!(p.status.success(), "povray {ty}");
            // The magic number, or Targa's image type byte.
            let n = if ext == "tga" { 3 } else { 2 };
            assert_eq!(p.stdout[..n], piped.stdout[..n], "povray {ty}");
        }
    }
}
