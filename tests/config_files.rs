//! POV-Ray's configuration files read as povray reads them (src/config.rs): with a temporary
//! POVINI, HOME and povray.conf, `lancer scene.pov` and `povray scene.pov` write the same file
//! name, type and picture size (povray's half runs only where povray is installed), and
//! povray.conf restricts `#fopen` as the manual describes. Debian's povray 3.7.0.10 does not
//! enforce povray.conf on `#fopen` or `#include` at all (scripts/measure_povray_conf.sh, as
//! root and as nobody), so there lancer is stricter than povray on purpose.

use std::path::{Path, PathBuf};
use std::process::Command;

const SCENE: &str = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\ncamera { location -3*z look_at 0 }\nlight_source { <1,2,-3> rgb 1 }\nsphere { 0, 1 pigment { rgb 1 } }\n";

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("lancer-config-files-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(d.join("home/.povray/3.7")).unwrap();
    d
}

fn has_povray() -> bool {
    Command::new("povray").arg("--version").output().is_ok()
}

/// Runs `program` in `dir` with HOME and POVINI set as given and nothing else configuring it.
fn run(program: &str, dir: &Path, home: &Path, povini: Option<&Path>, args: &[&str]) -> bool {
    let mut c = Command::new(program);
    c.current_dir(dir)
        .args(args)
        .env("HOME", home)
        .env_remove("POVINI")
        .env_remove("LANCER_NO_CONFIG");
    if let Some(p) = povini {
        c.env("POVINI", p);
    }
    c.output().expect("run").status.success()
}

fn lancer() -> &'static str {
    env!("CARGO_BIN_EXE_lancer")
}

/// File names in `dir` with their type (from the first bytes) and picture size.
fn pictures(dir: &Path) -> Vec<(String, String, (u32, u32))> {
    let mut v: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| {
            let p = e.ok()?.path();
            let name = p.file_name()?.to_string_lossy().into_owned();
            if name.ends_with(".pov") || name.ends_with(".txt") {
                return None;
            }
            // Targa has no magic number: the name says the type, the decoder checks it.
            let r = image::ImageReader::open(&p)
                .ok()?
                .with_guessed_format()
                .ok()?;
            let kind = r
                .format()
                .map_or_else(|| "unknown".into(), |f| format!("{f:?}"));
            let size = r
                .decode()
                .map(|i| (i.width(), i.height()))
                .unwrap_or((0, 0));
            Some((name, kind, size))
        })
        .collect();
    v.sort();
    v
}

#[test]
fn povini_sets_name_type_and_size_as_for_povray() {
    let d = scratch("povini");
    let ini = d.join("mine.ini");
    // Output_File_Type=C: run-length Targa, named .tga by both.
    std::fs::write(
        &ini,
        "Width=40\nHeight=30\nOutput_File_Type=C\nAntialias=off\n",
    )
    .unwrap();
    let mut seen = Vec::new();
    let mut programs = vec![lancer()];
    if has_povray() {
        programs.push("povray");
    }
    for prog in programs {
        let dir = d.join(if prog == "povray" { "pov" } else { "lan" });
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("s.pov"), SCENE).unwrap();
        let args = if prog == "povray" {
            vec!["-D", "-V", "s.pov"]
        } else {
            vec!["-q", "s.pov"]
        };
        assert!(
            run(prog, &dir, &d.join("home"), Some(&ini), &args),
            "{prog}"
        );
        seen.push(pictures(&dir));
    }
    assert_eq!(
        seen[0],
        vec![("s.tga".to_string(), "Tga".to_string(), (40, 30))]
    );
    if seen.len() == 2 {
        assert_eq!(seen[0], seen[1]);
    }
    // The command line wins over the main INI file, and --no-config reads none.
    let dir = d.join("lan");
    std::fs::remove_file(dir.join("s.tga")).unwrap();
    let args = ["-q", "s.pov", "+W20", "--no-config", "+FN"];
    assert!(run(lancer(), &dir, &d.join("home"), Some(&ini), &args));
    assert_eq!(
        pictures(&dir),
        vec![("s.png".to_string(), "Png".to_string(), (20, 240))]
    );
    // A file type from the main INI file does not stop lancer's -o from choosing one.
    std::fs::remove_file(dir.join("s.png")).unwrap();
    let args = ["-q", "s.pov", "-o", "o.ppm"];
    assert!(run(lancer(), &dir, &d.join("home"), Some(&ini), &args));
    assert_eq!(
        pictures(&dir),
        vec![("o.ppm".to_string(), "Pnm".to_string(), (40, 30))]
    );
}

#[test]
fn povray_conf_restricts_fopen_as_the_manual_says() {
    let system = Path::new("/etc/povray/3.7/povray.conf");
    let d = scratch("conf");
    let elsewhere = d.join("elsewhere");
    std::fs::create_dir_all(&elsewhere).unwrap();
    let scene_dir = d.join("scene");
    std::fs::create_dir_all(&scene_dir).unwrap();
    let target = elsewhere.join("out.txt");
    let scene = format!(
        "#fopen F \"{}\" write\n#write (F, \"x\")\n#fclose F\n{SCENE}",
        target.display()
    );
    std::fs::write(scene_dir.join("s.pov"), scene).unwrap();
    let home = d.join("home");
    let ini = d.join("small.ini");
    std::fs::write(&ini, "Width=8\nHeight=6\n").unwrap();
    let user_conf = home.join(".povray/3.7/povray.conf");
    {
        let prog = lancer();
        let args = &["-q", "s.pov"];
        // Readable and writable anywhere, as far as the files go.
        std::fs::write(&user_conf, "[File I/O Security]\nnone\n").unwrap();
        let _ = std::fs::remove_file(&target);
        let ok = run(prog, &scene_dir, &home, Some(&ini), args);
        if system.is_file() {
            // Debian's system file permits writing below /tmp only, and the user's file
            // cannot loosen it.
            let under_tmp = target.starts_with("/tmp");
            assert_eq!(ok && target.exists(), under_tmp, "{prog}, no restriction");
        } else {
            assert!(ok && target.exists(), "{prog}, no restriction");
        }
        // Restricted, the elsewhere directory not permitted: the write is refused.
        std::fs::write(
            &user_conf,
            "[File I/O Security]\nrestricted\n[Permitted Paths]\nread+write = .\n",
        )
        .unwrap();
        let _ = std::fs::remove_file(&target);
        let ok = run(prog, &scene_dir, &home, Some(&ini), args);
        assert!(!ok && !target.exists(), "{prog}, restricted");
    }
}
