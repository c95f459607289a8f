//! Inputs that crashed or hung the parser (found by the fuzz targets in fuzz/, see
//! docs/fuzzing.md), kept so they stay fixed. Each must now end in an ordinary parse result,
//! usually an error, without panicking or overflowing the stack.
//!
//! Every case runs on a thread with a 2 MB stack, the default for spawned threads and the
//! smallest a library user is likely to give the parser. Unoptimised (debug) builds take
//! several times more stack per level of recursion, so there the thread gets 16 MB: the 2 MB
//! promise is about release builds.

use lancer::sdl::{ParseOptions, Parser};

/// Parses `text` on a 2 MB-stack thread; returns the error message, or None when it parsed.
fn parse_small_stack(text: String) -> Option<String> {
    std::thread::Builder::new()
        .stack_size(if cfg!(debug_assertions) {
            16 << 20
        } else {
            2 << 20
        })
        .spawn(move || {
            let mut p = Parser::new(ParseOptions::default());
            p.parse_str("fuzz.pov", &text)
                .err()
                .map(|e| e.message.clone())
        })
        .expect("spawn")
        .join()
        .expect("the parser panicked or overflowed its stack")
}

fn assert_too_deep(text: String) {
    let msg = parse_small_stack(text).expect("should be an error");
    assert!(
        msg.contains("nested more than"),
        "unexpected message: {msg}"
    );
}

fn deep(open: &str, middle: &str, close: &str, n: usize) -> String {
    format!("{}{middle}{}", open.repeat(n), close.repeat(n))
}

// Stack overflows from deep nesting: each recursive grammar rule now counts its depth.

#[test]
fn deep_parentheses() {
    assert_too_deep(format!("#declare A = {};", deep("(", "1", ")", 20_000)));
}

#[test]
fn deep_unary_operators() {
    assert_too_deep(format!("#declare A = {}1;", "-".repeat(20_000)));
    assert_too_deep(format!("#declare A = {}1;", "!".repeat(20_000)));
    assert_too_deep(format!("#declare A = {}1;", "+".repeat(20_000)));
}

#[test]
fn deep_vectors_calls_and_colours() {
    assert_too_deep(format!("#declare A = {};", deep("<", "1", ",1>", 5_000)));
    assert_too_deep(format!("#declare A = {};", deep("sin(", "1", ")", 5_000)));
    assert_too_deep(format!("#declare A = {}1;", "color ".repeat(5_000)));
    // `? :` is read only inside parentheses, as in POV-Ray.
    assert_too_deep(format!("#declare A = ({});", deep("1?", "1", ":1", 5_000)));
}

#[test]
fn deep_csg() {
    assert_too_deep(deep("union {", "", "}", 5_000));
    assert_too_deep(deep("object {", "sphere { 0, 1 }", "}", 5_000));
}

#[test]
fn deep_function_bodies() {
    assert_too_deep(format!(
        "#declare F = function {{ {} }}",
        deep("(", "x", ")", 20_000)
    ));
    assert_too_deep(format!(
        "#declare F = function {{ {}x }}",
        "-".repeat(20_000)
    ));
    assert_too_deep(format!(
        "#declare F = function {{ {} }}",
        deep("abs(", "x", ")", 5_000)
    ));
}

#[test]
fn nesting_below_the_limit_still_parses() {
    assert_eq!(
        parse_small_stack(format!("#declare A = {};", deep("(", "1", ")", 200))),
        None
    );
    assert_eq!(parse_small_stack(deep("union {", "", "}", 200)), None);
    // Recursive macros nest the parser too; 150 levels (more than POV-Ray allows) still work.
    let m = "#macro F(N) #if (N > 0) #local R = F(N - 1) + 1; #else #local R = 0; #end R #end
             #declare A = F(150);
             #macro U(N) union { sphere { 0, 1 } #if (N > 0) U(N - 1) #end } #end
             object { U(150) }";
    assert_eq!(parse_small_stack(m.to_string()), None);
}

// Panics in built-in functions.

#[test]
fn str_with_huge_width_or_precision() {
    // Rust's formatter panicked ("Formatting argument out of range") past 65535.
    for e in [
        "str(1, 0, 1e9)",
        "str(1, 1e10, 0)",
        "str(1, 1e18, 1e18)",
        "str(1, -1e300, 2)",
    ] {
        assert_eq!(parse_small_stack(format!("#declare S = {e};")), None, "{e}");
    }
}

// Quadratic time and stack overflow from long operator chains in function bodies.

#[test]
fn long_function_operator_chains() {
    // 100,000 terms overflowed the stack after ~30 s of quadratic constant folding.
    let long = format!("#declare F = function {{ x{} }}", "+x".repeat(100_000));
    let msg = parse_small_stack(long).expect("should be an error");
    assert!(msg.contains("at most"), "unexpected message: {msg}");
    // Long chains below the cap still compile (and on a 2 MB stack).
    let ok = format!(
        "#declare F = function {{ x{} }}\n#declare A = F(1, 0, 0);",
        "+x*1".repeat(4_000)
    );
    assert_eq!(parse_small_stack(ok), None);
}

#[test]
fn include_of_a_device_is_not_a_file() {
    // `#include "/dev/zero"` read until memory ran out; only regular files are included.
    let msg = parse_small_stack("#include \"/dev/zero\"\n".to_string()).expect("an error");
    assert!(msg.contains("cannot find include file"), "{msg}");
}
