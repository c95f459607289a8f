//! Helpers the integration tests share: parsing snippets and running the binary.
#![allow(dead_code)] // each test file uses its own subset

use std::path::Path;
use std::process::Command;

use lancer::scene::desc::{SceneDesc, ShapeDesc};
use lancer::sdl::{ParseOptions, Parser};

/// A parser that has read `src` as `snippet.pov`; panics with the error's place if it failed.
pub fn parser_with(opts: ParseOptions, src: &str) -> Parser {
    let mut p = Parser::new(opts);
    if let Err(e) = p.parse_str("snippet.pov", src) {
        panic!("{}", e.one_line(&p.sources));
    }
    p
}

pub fn parser(src: &str) -> Parser {
    parser_with(ParseOptions::default(), src)
}

pub fn parse(src: &str) -> SceneDesc {
    parser(src).scene
}

pub fn parse_with(opts: ParseOptions, src: &str) -> SceneDesc {
    parser_with(opts, src).scene
}

/// The one-line error `src` must give.
pub fn parse_err(src: &str) -> String {
    let mut p = Parser::new(ParseOptions::default());
    match p.parse_str("snippet.pov", src) {
        Ok(()) => panic!("expected an error"),
        Err(e) => e.one_line(&p.sources),
    }
}

/// Sphere radii in scene order: snippets print values as `sphere { 0, value }`.
pub fn radii(s: &SceneDesc) -> Vec<f64> {
    s.objects
        .iter()
        .filter_map(|o| match o.shape {
            ShapeDesc::Sphere { radius, .. } => Some(radius),
            _ => None,
        })
        .collect()
}

/// Runs the lancer binary in `dir` with `args`: exit code, stdout, stderr.
pub fn lancer_in(dir: &Path, args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_lancer"))
        .env("LANCER_NO_CONFIG", "1")
        .current_dir(dir)
        .args(args)
        .output()
        .expect("run lancer");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}
