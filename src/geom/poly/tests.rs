//! Unit tests of `geom::poly`: known roots, windows and first roots against `roots_in`,
//! the sized Sturm sequences, and the shortened loops against the full ones, bit for bit.

use super::*;
use crate::geom::test_rng::from_roots;

fn check(found: &[f64], want: &[f64], tol: f64) {
    assert_eq!(found.len(), want.len(), "found {found:?} want {want:?}");
    for (f, w) in found.iter().zip(want) {
        assert!((f - w).abs() < tol, "found {found:?} want {want:?}");
    }
}

#[test]
fn quartic_with_known_roots() {
    let cases: &[&[f64]] = &[
        &[-1.0, 0.5, 2.0, 3.0],
        &[0.1, 0.10001, 0.7, 0.70001],
        &[-3.0, -2.0, 5.0, 9.0],
        &[1.0, 2.0, 3.0, 4.0],
        &[1e-3, 2e-3, 1e3, 2e3],
    ];
    for roots in cases {
        let c = from_roots(roots);
        check(
            &roots_in(&c, -10.0, 1e4),
            roots,
            1e-9 * roots[3].abs().max(1.0),
        );
        check(
            &sturm_roots_in(&c, -10.0, 1e4),
            roots,
            1e-9 * roots[3].abs().max(1.0),
        );
    }
}

#[test]
fn interval_limits_roots() {
    let c = from_roots(&[-1.0, 0.5, 2.0, 3.0]);
    check(&roots_in(&c, 0.0, 2.5), &[0.5, 2.0], 1e-12);
    check(&sturm_roots_in(&c, 0.0, 2.5), &[0.5, 2.0], 1e-12);
    assert!(roots_in(&c, 3.5, 2.0).is_empty());
}

#[test]
fn no_real_roots() {
    // (x² + 1)(x² + 4)
    let c = [4.0, 0.0, 5.0, 0.0, 1.0];
    assert!(roots_in(&c, -100.0, 100.0).is_empty());
    assert!(sturm_roots_in(&c, -100.0, 100.0).is_empty());
}

#[test]
fn double_root_found_by_sturm() {
    // (x - 1)² (x + 2)(x - 3): tangent at 1.
    let c = from_roots(&[1.0, 1.0, -2.0, 3.0]);
    let s = sturm_roots_in(&c, -5.0, 5.0);
    check(&s, &[-2.0, 1.0, 3.0], 1e-6);
    let r = roots_in(&c, -5.0, 5.0);
    assert!(r.len() >= 2, "{r:?}");
}

#[test]
fn low_degrees_and_degenerate_input() {
    check(&roots_in(&[-2.0, 1.0], -5.0, 5.0), &[2.0], 1e-15);
    check(&roots_in(&[-4.0, 0.0, 1.0], -5.0, 5.0), &[-2.0, 2.0], 1e-15);
    check(
        &roots_in(&[-1.0, -1.0, 0.0, 1.0, 0.0], -5.0, 5.0),
        &[1.324_717_957_244_746],
        1e-12,
    );
    assert!(roots_in(&[], 0.0, 1.0).is_empty());
    assert!(roots_in(&[0.0, 0.0], 0.0, 1.0).is_empty());
    assert!(roots_in(&[3.0], 0.0, 1.0).is_empty());
    assert!(sturm_roots_in(&[3.0], 0.0, 1.0).is_empty());
    assert!(roots_in(&[f64::NAN, 1.0, 1.0, 1.0, 1.0], 0.0, 1.0).len() <= 4);
    assert!(roots_in(&[1.0; 40], 0.0, 1.0).is_empty());
}

/// Roots found with a window are those found without it (bit for bit) inside the window,
/// plus maybe some outside, never others: random quartics, quintics and sextics through
/// close and far roots, windows anywhere.
#[test]
fn window_keeps_the_roots_inside_exactly() {
    let mut rnd = crate::math::xorshift_unit(0x2545_f491_4f6c_dd1du64);
    for case in 0..20_000 {
        let deg = 4 + case % 3;
        let mut c: Vec<f64> = (0..=deg).map(|_| rnd() * 20.0 - 10.0).collect();
        if case % 4 == 0 {
            let roots: Vec<f64> = (0..deg).map(|_| rnd() * 10.0 - 2.0).collect();
            c = from_roots(&roots);
        }
        if case % 4 == 1 {
            // Roots in pairs, shifted by a hair: grazing crossings near the window.
            let roots: Vec<f64> = (0..deg).map(|k| (k / 2) as f64 * 3.0 + rnd()).collect();
            c = from_roots(&roots);
            c[0] += (rnd() - 0.5) * 1e-9;
        }
        let (lo, hi) = (1e-6, 1.0 + 50.0 * rnd());
        let full = roots_in(&c, lo, hi);
        let w0 = rnd() * 12.0 - 1.0;
        let (wlo, whi) = (w0, w0 + rnd() * 3.0);
        let part = roots_in_window(&c, lo, hi, wlo, whi);
        crate::geom::test_rng::check_window(&full, &part, (wlo, whi), &format!("{c:?}"));
        let all = roots_in_window(&c, lo, hi, f64::NEG_INFINITY, f64::INFINITY);
        assert_eq!(&*all, &*full);
    }
}

/// As `window_keeps_the_roots_inside_exactly`, with the window's edges right at a root or a
/// critical point (within 1e-15 to 1e-6 of it, either side): where the sign test beside the
/// edge decides whether a piece is polished at all.
#[test]
fn window_edges_beside_roots_keep_them_exactly() {
    let mut rnd = crate::math::xorshift_unit(0x9e37_79b9_7f4a_7c15u64);
    for case in 0..30_000 {
        let deg = 4 + case % 3;
        let roots: Vec<f64> = (0..deg).map(|_| rnd() * 10.0 - 1.0).collect();
        let mut c = from_roots(&roots);
        if case % 3 == 1 {
            c[0] += (rnd() - 0.5) * 1e-6;
        }
        if case % 5 == 0 {
            c = c.iter().map(|x| x * 1e-7).collect();
        }
        let (lo, hi) = (1e-6, 40.0 + 400.0 * rnd());
        let full = roots_in(&c, lo, hi);
        let near = |rnd: &mut dyn FnMut() -> f64, x: f64| {
            let e = 10f64.powf(-15.0 + 9.0 * rnd());
            x + if rnd() < 0.5 { -e } else { e } * (x.abs() + 1.0)
        };
        let pick = |rnd: &mut dyn FnMut() -> f64| {
            if !full.is_empty() && rnd() < 0.7 {
                full[(rnd() * full.len() as f64) as usize % full.len()]
            } else {
                rnd() * 10.0 - 1.0
            }
        };
        let (x0, x1) = (pick(&mut rnd), pick(&mut rnd));
        let (wlo, whi) = (near(&mut rnd, x0.min(x1)), near(&mut rnd, x0.max(x1)));
        let part = roots_in_window(&c, lo, hi, wlo, whi);
        crate::geom::test_rng::check_window(&full, &part, (wlo, whi), &format!("{c:?}"));
    }
}

/// The first root kept is `roots_in`'s first root kept, bit for bit: random polynomials
/// of degree 1 to 8 with clustered, double and far roots, and thresholds anywhere.
#[test]
fn first_root_is_roots_ins_first() {
    let mut rng = crate::geom::test_rng::Lcg(17);
    for case in 0..20_000 {
        let deg = 1 + case % 8;
        let mut roots: Vec<f64> = (0..deg).map(|_| rng.next() * 8.0 - 2.0).collect();
        if case % 3 == 0 {
            roots[0] = roots[deg - 1] + 1e-9 * rng.next();
        }
        let mut c = from_roots(&roots);
        if case % 5 == 0 {
            c[0] += rng.next() - 0.5;
        }
        let (lo, hi) = (rng.next() - 0.5, 4.0 + 4.0 * rng.next());
        let all = roots_in(&c, lo, hi);
        let first = |cut: f64| first_root_in(&c, lo, hi, |x| x > cut);
        crate::geom::test_rng::check_first_root(&mut rng, &all, (lo, hi), first, &format!("{c:?}"));
        // Without the `surely_no_root` shortcut: the same answer, bit for bit.
        let cut = lo + (hi - lo) * rng.next();
        let (a, b) = (
            first_root_in(&c, lo, hi, |x| x > cut),
            first_root_in_unchecked(&c, lo, hi, |x| x > cut),
        );
        assert_eq!(
            a.map(f64::to_bits),
            b.map(f64::to_bits),
            "{c:?} {lo} {hi} {cut}"
        );
    }
    assert_eq!(
        first_root_in(&[1.0, 0.0, 0.0, 1.0], f64::NAN, 1.0, |_| true),
        None
    );
    assert_eq!(
        first_root_in_unchecked(&[1.0, 0.0, 0.0, 1.0], f64::NAN, 1.0, |_| true),
        None
    );
}

/// A sequence sized for the polynomial holds the same members as the largest one: the
/// same counts everywhere, on random polynomials of degree 2 to 8 with double roots.
#[test]
fn sized_sturm_sequence_is_the_full_one() {
    let mut rng = crate::geom::test_rng::Lcg(5);
    for case in 0..3_000 {
        let deg = 2 + case % 7;
        let mut roots: Vec<f64> = (0..deg).map(|_| rng.next() * 6.0 - 3.0).collect();
        if case % 2 == 0 {
            roots[1] = roots[0];
        }
        let c = from_roots(&roots);
        let small: Sturm<9> = Sturm::new(&c);
        let full: Sturm<{ MAX_DEGREE + 1 }> = Sturm::new(&c);
        assert_eq!(small.count, full.count);
        for k in 0..small.count {
            assert_eq!(small.lens[k], full.lens[k]);
            for j in 0..small.lens[k] {
                assert_eq!(small.polys[k][j].to_bits(), full.polys[k][j].to_bits());
            }
        }
        if deg <= 4 {
            let tiny: Sturm<5> = Sturm::new(&c);
            assert_eq!(tiny.count, full.count);
        }
        for _ in 0..8 {
            let x = rng.next() * 8.0 - 4.0;
            assert_eq!(small.sign_changes(x), full.sign_changes(x));
        }
    }
}

/// `low_roots_in` gives `roots_in`'s roots bit for bit, with the interval end asked only
/// when a root reaches it: random quadratics and lines, double and near-double roots.
#[test]
fn low_roots_are_roots_ins() {
    let mut rng = crate::geom::test_rng::Lcg(11);
    for case in 0..50_000 {
        let mut c = [
            rng.next() * 8.0 - 4.0,
            rng.next() * 8.0 - 4.0,
            rng.next() - 0.5,
        ];
        match case % 5 {
            0 => c[2] = 0.0,
            1 => c[0] = c[1] * c[1] / (4.0 * c[2]),
            2 => c[1] = 0.0,
            _ => {}
        }
        let (lo, hi) = (rng.next() - 0.5, rng.next() * 10.0);
        let want = roots_in(&c, lo, hi);
        let asked = std::cell::Cell::new(false);
        let (got, n) = low_roots_in(&c, lo, || {
            asked.set(true);
            hi
        });
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&got[..n]), bits(&want), "{c:?} {lo} {hi}");
    }
}

/// A value's bits, every NaN as one: which NaN an operation on two NaNs (or a NaN and an
/// invalid product) gives depends on the operands' order, which the optimiser may swap in a
/// commutative product (`cargo test --release` differed from the test profile here), and no
/// caller reads a NaN's payload.
fn same_bits(v: f64) -> u64 {
    if v.is_nan() {
        f64::NAN.to_bits()
    } else {
        v.to_bits()
    }
}

/// The shortened Horner loops give the full loops' bits: random coefficients (zeros,
/// signed zeros and huge values among them) at random, zero, huge and infinite points.
#[test]
fn shortened_horner_is_the_full_one() {
    let mut rng = crate::geom::test_rng::Lcg(3);
    let special = [0.0, -0.0, 1e300, -1e-300, f64::INFINITY, f64::NAN];
    for case in 0..50_000 {
        let n = case % 7;
        let mut c: Vec<f64> = (0..=n).map(|_| rng.next() * 8.0 - 4.0).collect();
        if case % 3 == 0 {
            let k = (rng.next() * (n + 1) as f64) as usize;
            c[k] = special[(rng.next() * 6.0) as usize];
        }
        let x = if case % 5 == 0 {
            special[(rng.next() * 6.0) as usize]
        } else {
            rng.next() * 10.0 - 5.0
        };
        let full = c.iter().rev().fold(0.0, |acc, &ci| acc * x + ci);
        assert_eq!(same_bits(eval(&c, x)), same_bits(full), "{c:?} {x}");
        let (mut f, mut df) = (0.0, 0.0);
        for &ci in c.iter().rev() {
            df = df * x + f;
            f = f * x + ci;
        }
        let (g, dg) = eval_with_derivative(&c, x);
        assert_eq!(
            (same_bits(g), same_bits(dg)),
            (same_bits(f), same_bits(df)),
            "{c:?} {x}"
        );
    }
}

#[test]
fn root_on_boundary() {
    let c = from_roots(&[0.0, 1.0, 2.0, 3.0]);
    check(&roots_in(&c, 0.0, 3.0), &[0.0, 1.0, 2.0, 3.0], 1e-12);
    check(&sturm_roots_in(&c, 0.0, 3.0), &[0.0, 1.0, 2.0, 3.0], 1e-12);
}

/// Where `surely_no_root` certifies an interval, the Sturm search over it adds nothing to
/// `roots_in`'s (empty) answer, so `sturm_roots_in` may answer without the sequence: random
/// quartics to sextics, near-double roots and roots just outside the interval.
#[test]
fn certified_intervals_need_no_sturm_search() {
    let mut rng = crate::geom::test_rng::Lcg(41);
    let mut certified = 0;
    for case in 0..20_000 {
        let deg = 4 + case % 3;
        let mut roots: Vec<f64> = (0..deg).map(|_| rng.next() * 8.0 - 2.0).collect();
        if case % 3 == 0 {
            roots[1] = roots[0] + 1e-9 * rng.next();
        }
        let mut c = from_roots(&roots);
        // Lift some so the near-double roots leave the axis (a tangent ray just missing).
        c[0] += (rng.next() - 0.3) * if case % 2 == 0 { 1e-6 } else { 1.0 };
        let (lo, hi) = (rng.next() * 4.0 - 2.0, 2.0 + 6.0 * rng.next());
        if lo > hi || !surely_no_root(&c, lo, hi) {
            continue;
        }
        certified += 1;
        assert!(roots_in_isolated(&c, lo, hi).is_empty(), "{c:?}");
        let searched = sturm_search::<7>(&c, lo, hi, Roots::new());
        assert!(
            searched.is_empty(),
            "{c:?} on [{lo}, {hi}]: {:?}",
            &*searched
        );
        assert!(sturm_roots_in(&c, lo, hi).is_empty());
    }
    assert!(certified > 1000, "{certified}");
}
