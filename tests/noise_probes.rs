//! POV-Ray's noise, turbulence and noise patterns against values the `povray` binary printed
//! at points none of the measurement used (tests/data/noise_probes.txt, written by
//! scripts/measure_noise.py and, for generator 3, scripts/measure_noise3.py). Tolerance 1e-6,
//! the bar; the generators, turbulence and the patterns built on them match to about
//! 1e-15 (float rounding order differs), so any real difference in the function shows.

mod common;

use common::parser;
use lancer::sdl::value::Value;

const TOL: f64 = 1e-6;

struct Group {
    pre: String,
    cases: Vec<(String, f64)>,
}

fn groups() -> Vec<Group> {
    let text = include_str!("data/noise_probes.txt");
    let mut out: Vec<Group> = Vec::new();
    for line in text.lines() {
        if line.starts_with('#') || line.is_empty() {
            continue;
        }
        if let Some(pre) = line.strip_prefix("P ").or(line.strip_prefix("P")) {
            if !line.contains('\t') {
                out.push(Group {
                    pre: pre.to_string(),
                    cases: Vec::new(),
                });
                continue;
            }
        }
        let (e, v) = line.split_once('\t').expect("expression<TAB>value");
        out.last_mut()
            .expect("a P line first")
            .cases
            .push((e.to_string(), v.parse().expect("a number")));
    }
    out
}

#[test]
fn noise_matches_povray_at_held_out_points() {
    if !std::path::Path::new("/usr/share/povray-3.7/include/functions.inc").is_file() {
        eprintln!("skipped: POV-Ray's include files are not installed");
        return;
    }
    let mut failures = Vec::new();
    for g in groups() {
        let mut src = format!("#version 3.7;\n#include \"functions.inc\"\n{}\n", g.pre);
        for (i, (e, _)) in g.cases.iter().enumerate() {
            src.push_str(&format!("#declare R{i} = {e};\n"));
        }
        let p = parser(&src);
        let mut worst = (0.0f64, String::new());
        for (i, (e, want)) in g.cases.iter().enumerate() {
            let got = match p.lookup(&format!("R{i}")) {
                Some(Value::Float(f)) => *f,
                other => panic!("{e} gave {other:?}"),
            };
            let err = (got - want).abs();
            if err > worst.0 || err.is_nan() {
                worst = (err, format!("{e} = {got}, povray {want}"));
            }
        }
        let first = g.cases.first().map_or("", |c| c.0.as_str());
        eprintln!("{:9.2e}  {} {}", worst.0, g.pre, first);
        if worst.0 > TOL || worst.0.is_nan() {
            failures.push(format!("{}: {}", g.pre, worst.1));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
