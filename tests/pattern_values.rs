//! Pattern values through `function { pattern { ... } }`, against the values POV-Ray 3.7's
//! binary printed for the same SDL with scripts/measure_pattern.py (12 digits; the tolerance
//! 1e-9 is that printing's rounding).

mod common;

use common::parser;
use lancer::sdl::value::Value;

fn value(pattern: &str, p: [f64; 3]) -> f64 {
    let src = format!(
        "#declare P = function {{ pattern {{ {pattern} }} }}\n#declare R = P({}, {}, {});",
        p[0], p[1], p[2]
    );
    match parser(&src).lookup("R") {
        Some(Value::Float(f)) => *f,
        other => panic!("{pattern}: {other:?}"),
    }
}

fn check(pattern: &str, cases: &[([f64; 3], f64)]) {
    for &(p, want) in cases {
        let got = value(pattern, p);
        assert!(
            (got - want).abs() < 1e-9,
            "{pattern} at {p:?}: {got}, povray {want}"
        );
    }
}

/// `warp { planar n, d }` for axis normals: the point's x and y read on the plane of normal n
/// at distance d (docs/povray-behaviour.md, Patterns).
#[test]
fn planar_warp_matches_povray() {
    let (a, b) = ([0.3, 0.2, 0.7], [-1.2, 0.4, -0.9]);
    for (warp, want) in [
        ("planar", [0.515, 0.44, 0.51, 0.52, 0.5, 0.5]),
        ("planar y, 0.5", [0.515, 0.44, 0.45, 0.45, 0.51, 0.52]),
        ("planar -x, 0.5", [0.45, 0.45, 0.49, 0.48, 0.515, 0.44]),
    ] {
        for (k, c) in ["x", "y", "z"].iter().enumerate() {
            let pat = format!("function {{ 0.5+0.1*{c} }} warp {{ {warp} }} scale 2");
            check(&pat, &[(a, want[2 * k]), (b, want[2 * k + 1])]);
        }
    }
}

/// The magnet fractals: both formulas, mandel and julia forms, the bail-out bounds and the
/// interior and exterior types (docs/povray-behaviour.md, Patterns).
#[test]
fn magnet_fractals_match_povray() {
    check(
        "magnet 1 mandel 50 interior 1,200",
        &[
            ([0.6622684726831096, 1.4475111372089415, 0.0], 0.295479712),
            ([1.5, 0.5, 0.0], 0.12),
            ([-0.5, -0.5, 0.0], 0.12),
        ],
    );
    check(
        "magnet 2 julia <1.2,-0.3>, 40 interior 2,0.5",
        &[
            ([0.3, 0.2, 0.0], 0.944701732),
            ([0.1, 0.05, 0.0], 0.944701732),
        ],
    );
}
