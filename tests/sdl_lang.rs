//! Snippet tests for the scene language's control flow, arrays, strings, splines, file I/O and
//! limits. Expected values come from running POV-Ray 3.7.0 on the same text (`#debug` output).

mod common;

use common::{parse, parse_err, parse_with, radii};
use lancer::scene::desc::{SceneDesc, ShapeDesc};
use lancer::sdl::{ParseOptions, Parser};

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

// ---- arrays ----

/// POV-Ray 3.7 prints "A0 undef", "1 1 3", "6 3", "5.000", "B00=1", "N=4", "after undef 0" for
/// the same declarations; subscripts are truncated (A[1.7] is A[1]).
#[test]
fn arrays_declare_read_and_query() {
    let s = parse(
        "#declare A = array[3];
         #declare A[1] = 5;
         #ifdef (A[0]) sphere { 0, 100 } #else sphere { 0, 101 } #end
         sphere { 0, defined(A[1]) } sphere { 0, dimensions(A) } sphere { 0, dimension_size(A, 1) }
         #declare B = array[2][3] {{1, 2, 3}, {4, 5, 6}};
         sphere { 0, B[1][2] } sphere { 0, dimension_size(B, 2) }
         #declare V = array[2] {<1, 2, 3>, <4, 5, 6>};
         sphere { V[1], V[1].y }
         #declare C = B; #declare C[0][0] = 99;
         sphere { 0, B[0][0] } sphere { 0, C[0][0] }
         #declare N = array[2] {A, B};
         sphere { 0, N[1][1][0] }
         sphere { 0, A[1.7] + B[1.9][0.2] }
         #undef A[1]
         sphere { 0, defined(A[1]) }",
    );
    assert_eq!(
        radii(&s),
        vec![101.0, 1.0, 1.0, 3.0, 6.0, 3.0, 5.0, 1.0, 99.0, 4.0, 9.0, 0.0]
    );
    assert_eq!(centers(&s)[6], [4.0, 5.0, 6.0]);
}

#[test]
fn array_elements_of_any_type_stand_where_their_type_may() {
    let s = parse(
        "#declare O = array[3] { sphere { 0, 1 }, sphere { x, 2 }, box { 0, 1 } };
         #declare T = array[2] { texture { pigment { rgb 1 } }, texture { pigment { rgb <1, 0, 0> } } };
         #declare P = array[1] { pigment { rgb 0.5 } };
         #declare S = array[2] { \"ab\", \"cd\" };
         union { #for (I, 0, 2) object { O[I] } #end }
         sphere { 0, strlen(concat(S[0], S[1])) texture { T[1] } }
         sphere { 0, 1 pigment { P[0] } }
         object { O[1] translate y }",
    );
    match &s.objects[0].shape {
        ShapeDesc::Csg { children, .. } => assert_eq!(children.len(), 3),
        other => panic!("{other:?}"),
    }
    assert_eq!(radii(&s), vec![4.0, 1.0, 2.0]);
    assert!(s.objects[1].texture.is_some());
}

#[test]
fn local_arrays_and_arrays_passed_to_macros() {
    let s = parse(
        "#macro Sum(Arr)
           #local Total = 0;
           #for (I, 0, dimension_size(Arr, 1) - 1) #local Total = Total + Arr[I]; #end
           Total
         #end
         #macro Fill(Arr, V)
           #local Tmp = array[2];
           #for (I, 0, 1) #declare Arr[I] = V + I; #local Tmp[I] = I; #end
         #end
         #declare A = array[2];
         Fill(A, 10)
         sphere { 0, Sum(A) }
         sphere { 0, Sum(array[3] {1, 2, 3}) }
         #ifdef (Tmp) sphere { 0, 99 } #end",
    );
    assert_eq!(radii(&s), vec![21.0, 6.0]);
}

/// POV-Ray 3.7: "Array subscript out of range", "Negative subscript", "Attempt to access
/// uninitialized array element", "Attempted to redefine float identifier as vector identifier".
#[test]
fn array_errors_name_the_element() {
    let e = parse_err("#declare A = array[3];\n#declare Q = A[3];");
    assert!(
        e.starts_with("snippet.pov:2:16")
            && e.contains("out of range in A[3]")
            && e.contains("0 to 2"),
        "{e}"
    );
    let e = parse_err("#declare A = array[3]; #declare Q = A[-1];");
    assert!(e.contains("negative array subscript"), "{e}");
    let e = parse_err("#declare A = array[3];\n#declare A[0] = 1;\n#declare Q = A[2];");
    assert!(
        e.starts_with("snippet.pov:3:14") && e.contains("A[2] is not initialised"),
        "{e}"
    );
    let e = parse_err("#declare A = array[3]; #declare A[0] = 1; #declare A[1] = <1, 2, 3>;");
    assert!(
        e.contains("cannot set A[1] to a vector: the array holds floats"),
        "{e}"
    );
    let e = parse_err("#declare A = array[2] {1, <1, 2, 3>};");
    assert!(e.contains("one type"), "{e}");
    let e = parse_err("#declare A = array[3] {1, 2};");
    assert!(
        e.contains("gives 2 elements where dimension 1 has 3"),
        "{e}"
    );
    let e = parse_err("#declare A = array[2] {1, 2, 3};");
    assert!(e.contains("expected '}'"), "{e}");
    let e = parse_err("#declare B = array[2][2]; #declare R = B[1];");
    assert!(e.contains("2 dimensions but only 1"), "{e}");
    let e = parse_err("#declare A = array[100000][100000];");
    assert!(e.contains("too large"), "{e}");
}

// ---- macro parameters by reference ----

/// POV-Ray 3.7 prints "inside X=5", "after X=5", "A1=6", "Y=10", "W still def".
#[test]
fn macro_parameters_bind_lone_identifiers_by_reference() {
    let s = parse(
        "#declare X = 1;
         #macro M(P) #declare P = 5; sphere { 0, X } #end
         M(X) sphere { 0, X }
         #macro Inc(P) #declare P = P + 1; #end
         #declare A = array[3] {1, 5, 9};
         Inc(A[1]) sphere { 0, A[1] }
         #macro L(P) #local P = 10; #end
         #declare Y = 1; L(Y) sphere { 0, Y }
         #declare Z = 1; Inc(Z + 0) Inc(+Z) sphere { 0, Z }
         #macro U(P) #undef P #end
         #declare W = 3; U(W) #ifdef (W) sphere { 0, W } #end
         #macro Outer(Q) Inc(Q) #end
         #declare K = 7; Outer(K) sphere { 0, K }",
    );
    assert_eq!(radii(&s), vec![5.0, 5.0, 6.0, 10.0, 1.0, 3.0, 8.0]);
}

/// macro2.pov's `Turn_Me`: the `#declare` that ends the macro body has no semicolon, so the
/// body's `#end` closes the value; the parameter must still be assigned by reference.
/// POV-Ray 3.7 prints "A=2" and "B=2" for the two calls.
#[test]
fn declare_ending_a_macro_body_still_assigns_by_reference() {
    let s = parse(
        "#macro Bump(P) #declare P = P + 1 #end
         #declare A = 1; Bump(A) sphere { 0, A }
         #macro Move(S) #declare S = object { S translate y } #end
         #declare B = sphere { 0, 1 } Move(B) object { B }",
    );
    assert_eq!(radii(&s)[0], 2.0);
    assert_eq!(s.objects.len(), 2);
    let moved = s.objects[1]
        .transform
        .get()
        .m
        .transform_point3(glam::DVec3::ZERO);
    assert_eq!(moved, glam::DVec3::Y);
}

// ---- strings ----

/// Each `Check` compares with the text POV-Ray 3.7.0 printed for the same call; a mismatch
/// stops the parse with an #error naming both.
const CHECK: &str = "#macro Check(Got, Want)
  #if (strcmp(Got, Want) != 0) #error concat(\"got [\", Got, \"] want [\", Want, \"]\") #end
#end
";

#[test]
fn string_functions_format_as_povray_does() {
    let src = format!(
        "{CHECK}
         Check(str(123.456, 9, 3), \"  123.456\")
         Check(str(123.456, -9, 3), \"00123.456\")
         Check(str(123.456, 0, -1), \"123.456000\")
         Check(str(-1.5, -8, 2), \"-0001.50\")
         Check(str(2.5, 0, 0), \"2\")
         Check(str(3.5, 0, 0), \"4\")
         Check(str(-0.0001, 0, 2), \"-0.00\")
         Check(str(1, 0, 30), \"1.000000000000000000000000000000\")
         Check(vstr(3, <1, 2, 3>, \", \", 0, 1), \"1.0, 2.0, 3.0\")
         Check(vstr(2, 1, \"/\", 4, 2), \"1.00/0.00\")
         Check(vstr(5, <1, 2, 3>, \",\", -5, -1), \"1.000000,2.000000,3.000000,0.000000,0.000000\")
         Check(vstr(1, <1, 2>, \",\", 0, 0), \"1,2\")
         Check(vstr(2, <1, 2, 3>, \",\", 0, 1), \"1.0,2.0\")
         Check(substr(\"ABCDEFGHI\", 4, 2), \"DE\")
         Check(strupr(\"Hello There!\"), \"HELLO THERE!\")
         Check(strlwr(\"Hello There!\"), \"hello there!\")
         Check(str(val(\"  12.5abc\"), 0, 3), \"12.500\")
         Check(str(val(\"abc\"), 0, 3), \"0.000\")
         Check(str(asc(\"A\"), 0, 0), \"65\")
         Check(str(asc(\"\"), 0, 0), \"0\")
         Check(str(strcmp(\"abcd\", \"abc\"), 0, 0), \"100\")
         Check(str(strcmp(\"abc\", \"abd\"), 0, 0), \"-1\")
         Check(chr(70), \"F\")
         Check(concat(\"a\", \"b\", \"c\"), \"abc\")
         Check(str(strlen(\"hello\"), 0, 0), \"5\")
         Check(str(0.1 + 0.2, 0, -1), \"0.300000\")
         #if (\"abc\" = \"abc\") sphere {{ 0, 1 }} #end
         #if (file_exists(\"no/such/file.inc\")) sphere {{ 0, 2 }} #end"
    );
    assert_eq!(radii(&parse(&src)), vec![1.0]);
}

#[test]
fn substr_out_of_range_is_an_error() {
    let e = parse_err("#declare S = substr(\"abc\", 3, 2);");
    assert!(e.contains("substr") && e.contains("length 3"), "{e}");
}

// ---- splines ----

/// Values printed by POV-Ray 3.7.0 (`vstr(3, S(T), ",", 0, 9)`) for one set of five points with
/// uneven spacing, for each spline type, including parameters outside the points.
#[test]
fn splines_match_povray() {
    let pts = "0,<0,0,0> 1,<1,2,0> 2.5,<3,1,1> 4,<2,0,5> 5,<0,1,-2>";
    let cases: &[(&str, f64, [f64; 3])] = &[
        ("linear_spline", -0.5, [0.0, 0.0, 0.0]),
        (
            "linear_spline",
            1.25,
            [1.333333333, 1.833333333, 0.166666667],
        ),
        ("linear_spline", 4.75, [0.5, 0.75, -0.25]),
        ("linear_spline", 5.5, [0.0, 1.0, -2.0]),
        ("quadratic_spline", 0.25, [0.225, 0.7, -0.05]),
        (
            "quadratic_spline",
            1.25,
            [1.291666667, 2.166666667, 0.083333333],
        ),
        (
            "quadratic_spline",
            2.75,
            [3.041666667, 0.833333333, 1.458333333],
        ),
        ("quadratic_spline", 4.25, [1.6, 0.125, 3.975]),
        ("cubic_spline", 0.5, [1.0, 2.0, 0.0]),
        (
            "cubic_spline",
            1.25,
            [1.339120370, 2.064814815, 0.074074074],
        ),
        (
            "cubic_spline",
            3.75,
            [2.317129630, 0.021990741, 5.137731481],
        ),
        ("cubic_spline", 4.5, [2.0, 0.0, 5.0]),
        (
            "natural_spline",
            0.25,
            [0.2109375, 0.629136029, 0.033547794],
        ),
        ("natural_spline", 2.25, [2.796875, 1.333843954, 0.357536765]),
        (
            "natural_spline",
            3.75,
            [2.383680556, -0.035641340, 5.263378268],
        ),
        (
            "natural_spline",
            4.75,
            [0.5390625, 0.676011029, 0.267922794],
        ),
    ];
    let mut src = String::new();
    for (kind, t, _) in cases {
        src.push_str(&format!(
            "#declare S = spline {{ {kind} {pts} }} sphere {{ S({t}), 1 }}\n"
        ));
    }
    let got = centers(&parse(&src));
    for ((kind, t, want), got) in cases.iter().zip(got) {
        for k in 0..3 {
            assert!(
                (got[k] - want[k]).abs() < 1e-6,
                "{kind} at {t}: got {got:?}, POV-Ray {want:?}"
            );
        }
    }
}

/// POV-Ray 3.7.0: two-point cubic gives the midpoint everywhere, three-point cubic the middle
/// point; mixed vector sizes pad with zeros and the longest sets the size; unsorted points sort
/// and a repeated parameter replaces; `spline { S }` copies and can add points; `S(t, type)`
/// evaluates as another type.
#[test]
fn spline_edge_cases_match_povray() {
    let s = parse(
        "#declare A = spline { cubic_spline 0,<0,0> 1,<1,2> }
         sphere { <A(-0.5).x, A(0.3).y, A(3).x>, 1 }
         #declare A = spline { cubic_spline 0,<0,0> 1,<1,2> 3,<2,2> }
         sphere { <A(0).x, A(2).y, 0>, 1 }
         #declare A = spline { natural_spline 0,<0,0,1> 1,<1,2> 3,<2,2,3,4,5> }
         #declare V = A(0.5);
         sphere { <V.x, V.y, V.z>, V.t }
         sphere { <V.transmit, 0, 0>, 1 }
         #declare A = spline { linear_spline 3,<3,0,0> 1,<1,0,0> 2,<2,0,0> 1,<5,0,0> }
         sphere { <A(0).x, A(1.5).x, A(2.5).x>, 1 }
         #declare A = spline { 0,<1,1,1> }
         #declare B = spline { A linear_spline 1, <2,2,2> }
         sphere { B(0.5), 1 } sphere { A(7), 1 }
         #declare C = spline { cubic_spline 0,<0,0,0> 1,<1,2,0> 2.5,<3,1,1> 4,<2,0,5> 5,<0,1,-2> }
         sphere { C(1.75, linear_spline), 1 } sphere { C(1.75, natural_spline), 1 }
         sphere { C(1.75, quadratic_spline), 1 }
         sphere { 0, C(1.75).y }",
    );
    let c = centers(&s);
    let want: &[[f64; 3]] = &[
        [0.5, 1.0, 0.5],
        [1.0, 2.0, 0.0],
        [0.53125, 1.125, 0.9375],
        [-0.15625, 0.0, 0.0],
        [5.0, 3.5, 2.5],
        [1.5, 1.5, 1.5],
        [1.0, 1.0, 1.0],
        [2.0, 1.5, 0.5],
        [2.140625, 1.915257353, -0.156801471],
        [1.925, 2.1, 0.35],
    ];
    for (g, w) in c.iter().zip(want) {
        for k in 0..3 {
            assert!((g[k] - w[k]).abs() < 1e-6, "got {c:?}");
        }
    }
    let r = radii(&s);
    assert!((r[2] - -0.125).abs() < 1e-9, "{r:?}");
    assert!((r[10] - 1.75).abs() < 1e-9, "{r:?}");
}

// ---- file I/O ----

/// A fresh directory for one test's files, below the cargo target directory.
fn scratch(name: &str) -> std::path::PathBuf {
    let d = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn parse_scene_file(
    dir: &std::path::Path,
    text: &str,
    opts: ParseOptions,
) -> Result<SceneDesc, String> {
    let path = dir.join("scene.pov");
    std::fs::write(&path, text).unwrap();
    let parsed = lancer::api::parse_file(&path, opts);
    match parsed.error {
        Some(e) => Err(e.one_line(&parsed.parser.sources)),
        None => Ok(parsed.parser.scene),
    }
}

/// `#write` output is POV-Ray 3.7.0's byte for byte: `%g` floats, vectors with a trailing space.
#[test]
fn write_then_read_round_trip() {
    let dir = scratch("io_round_trip");
    let out = dir.join("data.txt");
    let scene = format!(
        "#fopen F \"{0}\" write
         #write (F, 1.5, \",\", -2, \",\", <1,2,3>, \",\", <1,2>, \",\", 1/3, \",\", 1e20, \",\", \"\\\"str\\\"\", \",\\n\")
         #fclose F
         #fopen F \"{0}\" append
         #write (F, 123456789, \",\", 0.000001234, \",\")
         #fclose F
         #fopen G \"{0}\" read
         #read (G, A, B, C, D, E)
         sphere {{ C, A + B }} sphere {{ <D.x, D.y, 0>, E }}
         #declare N = 0;
         #while (defined(G))
           #read (G, V)
           #declare N = N + 1;
           #switch (N)
             #case (1) sphere {{ 0, V / 1e19 }} #break
             #case (2) #if (strcmp(V, \"str\") = 0) sphere {{ 0, 2 }} #end #break
             #else sphere {{ 0, V }}
           #end
         #end
         sphere {{ 0, 100 + N }}",
        out.display()
    );
    let s = parse_scene_file(&dir, &scene, ParseOptions::default()).unwrap();
    assert_eq!(
        std::fs::read_to_string(&out).unwrap(),
        "1.5,-2,<1,2,3> ,<1,2> ,0.333333,1e+20,\"str\",\n1.23457e+08,1.234e-06,"
    );
    let r = radii(&s);
    assert_eq!(centers(&s)[0], [1.0, 2.0, 3.0]);
    assert_eq!(&r[..5], &[-0.5, 0.333333, 10.0, 2.0, 123457000.0]);
    // The last value is followed by a comma, so it is read; the next #read meets the end of
    // the file, closes G and leaves V as it was, and the loop body finishes that round.
    assert!((r[5] - 1.234e-6).abs() < 1e-12, "{r:?}");
    assert_eq!(r[6], r[5]);
    assert_eq!(r[7], 105.0);
}

/// POV-Ray 3.7.0 reads 1, 2 and 3 from "1, 2, 3\n4\n": a missing comma swallows the token
/// after the value. A value followed by the end of the file is read and the file closed at
/// once, so `#ifdef (G)` right after that #read is false (checked with povray's #debug:
/// "1,2,3" read in a `#while (defined(G))` loop gives 1, 2, 3; "1,2,3," gives 1, 2, 3, 3).
#[test]
fn read_at_end_of_file_closes_as_povray_does() {
    let dir = scratch("io_eof");
    std::fs::write(dir.join("in.txt"), "1, 2, 3\n4\n").unwrap();
    std::fs::write(dir.join("in2.txt"), "1 2 3\n").unwrap();
    let s = parse_scene_file(
        &dir,
        "#fopen G \"in.txt\" read
         #while (defined(G)) #read (G, X) #ifdef (G) sphere { 0, X } #end #end
         #fopen G \"in2.txt\" read
         #while (defined(G)) #read (G, X) #ifdef (G) sphere { 0, 10 + X } #end #end
         #fclose G",
        ParseOptions::default(),
    )
    .unwrap();
    assert_eq!(radii(&s), vec![1.0, 2.0, 3.0, 11.0]);
    std::fs::write(dir.join("in3.txt"), "1,2,3").unwrap();
    std::fs::write(dir.join("in4.txt"), "1,2,3,").unwrap();
    std::fs::write(dir.join("in5.txt"), "\"s\",5,<1,2,3> \n").unwrap();
    let s = parse_scene_file(
        &dir,
        "#fopen G \"in3.txt\" read
         #while (defined(G)) #read (G, X) sphere { 0, X } #end
         #fopen G \"in4.txt\" read
         #while (defined(G)) #read (G, X) sphere { 0, 10 + X } #end
         #fopen G \"in5.txt\" read
         #read (G, S, F, V)
         sphere { V, F }",
        ParseOptions::default(),
    )
    .unwrap();
    assert_eq!(radii(&s), vec![1.0, 2.0, 3.0, 11.0, 12.0, 13.0, 13.0, 5.0]);
    assert_eq!(centers(&s).last().copied(), Some([1.0, 2.0, 3.0]));
}

#[test]
fn binary_words_in_write() {
    let dir = scratch("io_binary");
    parse_scene_file(
        &dir,
        "#fopen F \"lancer_sdl_lang_binary.bin\" write
         #write (F, uint8 65, 66, \"x\", sint16le 258, 3, <1,2,3>)
         #write (F, 67, sint8 -1)
         #fclose F",
        ParseOptions::default(),
    )
    .unwrap();
    // Where POV-Ray resolves a relative name to write: the current directory.
    let bytes = std::fs::read("lancer_sdl_lang_binary.bin").unwrap();
    let _ = std::fs::remove_file("lancer_sdl_lang_binary.bin");
    assert_eq!(bytes, b"A66x\x02\x013<1,2,3> 67\xff");
}

#[test]
fn io_outside_the_scene_and_current_directories_needs_permission() {
    let outside = std::env::temp_dir().join(format!("lancer_io_test_{}.txt", std::process::id()));
    let scene = format!(
        "#fopen F \"{}\" write #write (F, \"x\") #fclose F",
        outside.display()
    );
    let mut p = Parser::new(ParseOptions::default());
    let e = p.parse_str("snippet.pov", &scene).unwrap_err();
    let e = e.one_line(&p.sources);
    assert!(
        e.starts_with("snippet.pov:1:1")
            && e.contains("may not write")
            && e.contains("lancer_io_test_"),
        "{e}"
    );
    assert!(!outside.exists());
    let opts = ParseOptions {
        io_allowed_dirs: vec![std::env::temp_dir()],
        ..ParseOptions::default()
    };
    parse_with(opts, &scene);
    assert_eq!(std::fs::read_to_string(&outside).unwrap(), "x");
    std::fs::remove_file(&outside).unwrap();
    let e = parse_err("#fopen F \"/etc/hostname\" read");
    assert!(e.contains("may not read /etc/hostname"), "{e}");
    let e = parse_err("#declare X = 1; #read (X, Y)");
    assert!(e.contains("'X' is not an open file"), "{e}");
}

// ---- limits ----

#[test]
fn loop_iteration_cap_is_an_error_when_set() {
    let opts = ParseOptions {
        max_loop_iterations: Some(1000),
        ..ParseOptions::default()
    };
    let mut p = Parser::new(opts);
    let e = p.parse_str("snippet.pov", "#while (1)\n#end").unwrap_err();
    let e = e.one_line(&p.sources);
    assert!(
        e.starts_with("snippet.pov:2:1") && e.contains("more than 1000"),
        "{e}"
    );
    // Off by default: a long loop runs.
    let s = parse("#declare I = 0; #while (I < 20000) #declare I = I + 1; #end sphere { 0, I }");
    assert_eq!(radii(&s), vec![20000.0]);
}

/// POV-Ray 3.7.0 accepts 31 nested include files and stops at the 32nd.
#[test]
fn include_depth_is_limited_as_in_povray() {
    let dir = scratch("include_depth");
    std::fs::write(
        dir.join("self.inc"),
        "#declare N = N + 1;\n#if (N < Max) #include \"self.inc\" #end\n",
    )
    .unwrap();
    let s = parse_scene_file(
        &dir,
        "#declare Max = 31; #declare N = 0; #include \"self.inc\" sphere { 0, N }",
        ParseOptions::default(),
    )
    .unwrap();
    assert_eq!(radii(&s), vec![31.0]);
    let e = parse_scene_file(
        &dir,
        "#declare Max = 32; #declare N = 0; #include \"self.inc\"",
        ParseOptions::default(),
    )
    .unwrap_err();
    assert!(
        e.contains("self.inc:2:") && e.contains("too many nested include files"),
        "{e}"
    );
}

#[test]
fn runaway_recursion_names_povray_wording() {
    let e = parse_err("#macro R(N) R(N + 1) #end R(0)");
    assert!(e.contains("Too many nested symbol tables"), "{e}");
}

// ---- optional commas, deprecated identifiers ----

/// POV-Ray 3.7.0 reads initialisers and #write items without commas (allnormals.pov and
/// html_gen.inc among the sample scenes do this).
#[test]
fn commas_are_optional_in_initialisers_and_write() {
    let s = parse(
        "#declare A = array[3] {\"a\" \"bc\"\n \"def\"};
         #declare B = array[2][2] {{1 2}{3 4}};
         sphere { 0, strlen(A[2]) + B[1][0] }",
    );
    assert_eq!(radii(&s), vec![6.0]);
    let dir = scratch("io_no_commas");
    parse_scene_file(
        &dir,
        "#fopen F \"lancer_sdl_lang_nocomma.txt\" write #write(F \"a\" 1 \"b\") #fclose F",
        ParseOptions::default(),
    )
    .unwrap();
    let text = std::fs::read_to_string("lancer_sdl_lang_nocomma.txt").unwrap();
    let _ = std::fs::remove_file("lancer_sdl_lang_nocomma.txt");
    assert_eq!(text, "a1b");
}

#[test]
fn deprecated_identifiers_warn_where_used() {
    let mut p = Parser::new(ParseOptions::default());
    p.parse_str(
        "d.pov",
        "#declare deprecated once \"use T2\" T1 = 1;\n#declare deprecated Old = 2;\nsphere { 0, T1 + T1 }\nsphere { 0, Old }\nsphere { 0, Old }",
    )
    .unwrap();
    let w: Vec<String> = p.warnings.iter().map(|w| w.one_line(&p.sources)).collect();
    assert_eq!(w.len(), 3, "{w:?}");
    assert!(
        w[0].starts_with("d.pov:3:") && w[0].contains("use T2"),
        "{w:?}"
    );
    assert!(
        w[1].starts_with("d.pov:4:") && w[1].contains("Identifier Old was declared deprecated.")
    );
    assert!(w[2].starts_with("d.pov:5:"));
}
