//! Snippet tests for the scene language's control flow, arrays, strings, splines, file I/O and
//! limits. Expected values come from running POV-Ray 3.7.0 on the same text (`#debug` output).

use lancer::scene::desc::{SceneDesc, ShapeDesc};
use lancer::sdl::{ParseOptions, Parser};

fn parse(src: &str) -> SceneDesc {
    parse_with(ParseOptions::default(), src)
}

fn parse_with(opts: ParseOptions, src: &str) -> SceneDesc {
    let mut p = Parser::new(opts);
    if let Err(e) = p.parse_str("snippet.pov", src) {
        panic!("{}", e.one_line(&p.sources));
    }
    p.scene
}

fn parse_err(src: &str) -> String {
    let mut p = Parser::new(ParseOptions::default());
    match p.parse_str("snippet.pov", src) {
        Ok(()) => panic!("expected an error"),
        Err(e) => e.one_line(&p.sources),
    }
}

/// Sphere radii in scene order: the snippets print values as `sphere { 0, value }`.
fn radii(s: &SceneDesc) -> Vec<f64> {
    s.objects
        .iter()
        .filter_map(|o| match o.shape {
            ShapeDesc::Sphere { radius, .. } => Some(radius),
            _ => None,
        })
        .collect()
}

#[allow(dead_code)]
fn centers(s: &SceneDesc) -> Vec<[f64; 3]> {
    s.objects
        .iter()
        .filter_map(|o| match o.shape {
            ShapeDesc::Sphere { center, .. } => Some(center.to_array()),
            _ => None,
        })
        .collect()
}

// ---- #switch and #break ----

/// POV-Ray 3.7 prints "c1 c2 r57 / c2 r57 / c3 else / r57 / else / c1 c2 r57" for this macro.
#[test]
fn switch_falls_through_until_break() {
    let s = parse(
        "#macro T(V)
           #switch (V)
             #case (1) sphere { 0, 1 }
             #case (2) sphere { 0, 2 }
             #range (5, 7) sphere { 0, 57 }
             #break
             #case (3) sphere { 0, 3 }
             #else sphere { 0, 99 }
           #end
         #end
         T(1) T(2) T(3) T(6) T(9) T(1 + 1e-11)",
    );
    assert_eq!(
        radii(&s),
        vec![1.0, 2.0, 57.0, 2.0, 57.0, 3.0, 99.0, 57.0, 99.0, 1.0, 2.0, 57.0]
    );
}

#[test]
fn switch_runs_tokens_before_the_first_case_and_breaks_from_inside_if() {
    let s = parse(
        "#switch (4)
           sphere { 0, 1 }
           #case (4) sphere { 0, 4 } #if (1) #break #end sphere { 0, 44 }
           #case (5) sphere { 0, 5 }
         #end",
    );
    assert_eq!(radii(&s), vec![1.0, 4.0]);
}

#[test]
fn nested_switch_in_a_skipped_clause_is_skipped_whole() {
    let s = parse(
        "#switch (1)
           #case (0)
             #switch (2) #case (2) sphere { 0, 22 } #break #else sphere { 0, 23 } #end
             sphere { 0, 20 }
           #break
           #case (1) sphere { 0, 1 }
         #end
         #if (0) #switch (1) #case (1) #else #end #else sphere { 0, 2 } #end",
    );
    assert_eq!(radii(&s), vec![1.0, 2.0]);
}

/// POV-Ray 3.7 prints "012" and "0123": #break ends loops, but inside a #switch only the switch.
#[test]
fn break_ends_while_and_for_loops() {
    let s = parse(
        "#declare I = 0;
         #while (I < 10)
           #if (I = 3) #break #end
           sphere { 0, I }
           #declare I = I + 1;
         #end
         #for (J, 0, 5)
           #switch (J) #case (2) #break #end
           #if (J = 4) #break #end
           sphere { 0, 10 + J }
         #end
         sphere { 0, 100 + J }",
    );
    assert_eq!(
        radii(&s),
        vec![0.0, 1.0, 2.0, 10.0, 11.0, 12.0, 13.0, 104.0]
    );
}

#[test]
fn stray_case_and_break_are_errors() {
    let e = parse_err("#case (1)");
    assert!(e.contains("#case outside a #switch"), "{e}");
    let e = parse_err("sphere { 0, 1 }\n#break");
    assert!(
        e.starts_with("snippet.pov:2:1") && e.contains("#break outside"),
        "{e}"
    );
    let e = parse_err("#switch (1) #case (1) sphere { 0, 1 }");
    assert!(e.contains("#end"), "{e}");
}
