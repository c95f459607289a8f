//! POV-Ray's standard include library (Debian's povray-includes) parses: every file alone, and
//! all of them together. Skips, saying so, where the library is not installed; CI installs it.

use std::path::{Path, PathBuf};

use lancer::sdl::{ParseOptions, Parser};

const LIBRARY: &str = "/usr/share/povray-3.7/include";

/// Files POV-Ray 3.7 itself cannot parse alone, with what they rely on a scene to include
/// first (checked with `povray +I<file>`: each stops at the first colour or shape name).
const NEEDS: &[(&str, &[&str])] = &[
    ("shapes2.inc", &["shapes.inc"]),
    // Its Helix is clipped by shapes.inc's Cylinder_Z (povray: "undeclared identifier").
    ("shapesq.inc", &["shapes.inc"]),
    ("skies.inc", &["colors.inc"]),
    ("stdcam.inc", &["colors.inc"]),
    ("stoneold.inc", &["colors.inc"]),
    ("stones.inc", &["colors.inc"]),
    ("stones1.inc", &["colors.inc"]),
    ("stones2.inc", &["colors.inc"]),
];

fn library() -> Option<Vec<PathBuf>> {
    let dir = Path::new(LIBRARY);
    if !dir.join("colors.inc").exists() {
        eprintln!("skipped: {LIBRARY} is not installed (apt-get install povray-includes)");
        return None;
    }
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "inc"))
        .collect();
    files.sort();
    Some(files)
}

fn parse(text: &str) -> Result<(), String> {
    let mut p = Parser::new(ParseOptions {
        library_paths: vec![PathBuf::from(LIBRARY)],
        ..ParseOptions::default()
    });
    p.parse_str("includes.pov", text)
        .map_err(|e| e.one_line(&p.sources))
}

#[test]
fn every_include_file_parses_alone() {
    let Some(files) = library() else { return };
    let mut failures = Vec::new();
    for f in &files {
        let name = f.file_name().unwrap().to_string_lossy().into_owned();
        let needs = NEEDS
            .iter()
            .find(|(n, _)| *n == name)
            .map_or(&[][..], |(_, d)| *d);
        let mut text = String::from("#version 3.7;\n");
        for d in needs {
            text.push_str(&format!("#include \"{d}\"\n"));
        }
        text.push_str(&format!("#include \"{name}\"\n"));
        if let Err(e) = parse(&text) {
            failures.push(format!("{name}: {e}"));
        }
    }
    assert!(
        files.len() >= 30,
        "only {} include files found",
        files.len()
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn all_include_files_parse_together() {
    let Some(files) = library() else { return };
    let mut text =
        String::from("#version 3.7;\n#include \"colors.inc\"\n#include \"shapes.inc\"\n");
    for f in &files {
        text.push_str(&format!(
            "#include \"{}\"\n",
            f.file_name().unwrap().to_string_lossy()
        ));
    }
    parse(&text).unwrap();
}
