//! The polynomial along a ray, term by term, for the orders below 5 (`Algebraic::along`'s
//! expansion with its loops unrolled for each term's powers).
//!
//! A cubic's or quartic's term is expanded by a function made for its powers, chosen once
//! when the shape is built ([`quartic_term`]) and called through a pointer on every ray.
//! Dispatching on the powers inside the ray's loop instead let the compiler hoist every
//! possible term's products out of the loop (all 15 x-y products of the 35 terms, whichever
//! the shape has) and keep the sums in memory behind three nested jump tables: ~920
//! instructions a ray for objects/quartic/hyptorus's ten terms.

use crate::math::DVec3;

/// Powers of (o + t d) per axis as polynomials in t: `pw[axis][e][k]` multiplies `t^k` in
/// the `e`-th power.
pub(super) type Powers<const N: usize> = [[[f64; N]; N]; 3];

/// One term's expansion, `c·x^I·y^J·z^K` added to the coefficients (see [`add_term`]).
pub(super) type QuarticTerm = fn(f64, &Powers<5>, &mut [f64; 5]);

/// `Algebraic::powers` for every power below `N`, whatever the order (the rows above the
/// order are not used): loops of constant length, which the compiler unrolls into registers.
#[inline(always)]
pub(super) fn powers_unrolled<const N: usize>(origin: DVec3, dir: DVec3) -> Powers<N> {
    let mut pw = [[[0.0f64; N]; N]; 3];
    for (axis, (o, d)) in [(origin.x, dir.x), (origin.y, dir.y), (origin.z, dir.z)]
        .into_iter()
        .enumerate()
    {
        pw[axis][0][0] = 1.0;
        for e in 1..N {
            for k in 0..e {
                pw[axis][e][k] += pw[axis][e - 1][k] * o;
                pw[axis][e][k + 1] += pw[axis][e - 1][k] * d;
            }
        }
    }
    pw
}

/// One term `c·x^I·y^J·z^K` of `Algebraic::along_in` added to `out`, with the loops of
/// that function unrolled for these powers (the same operations in the same order).
///
/// A zeroth power is the constant polynomial 1 (`pw[axis][0][0]`, never written after it is
/// set), and a product by 1 is exact (a NaN stays a NaN), so those products are left out:
/// the same bits.
#[inline(always)]
pub(super) fn add_term<const N: usize, const I: usize, const J: usize, const K: usize>(
    c: f64,
    pw: &Powers<N>,
    out: &mut [f64; N],
) {
    let mut xy = [0.0f64; N];
    for a in 0..=I {
        for b in 0..=J {
            let p = if J == 0 {
                pw[0][I][a]
            } else if I == 0 {
                pw[1][J][b]
            } else {
                pw[0][I][a] * pw[1][J][b]
            };
            xy[a + b] += p;
        }
    }
    for a in 0..=I + J {
        if xy[a] == 0.0 {
            continue;
        }
        let cxy = c * xy[a];
        for b in 0..=K {
            out[a + b] += if K == 0 { cxy } else { cxy * pw[2][K][b] };
        }
    }
}

/// [`add_term`] for the powers `p` of a term of order at most 4, as a function of its own;
/// `None` above order 4.
pub(super) fn quartic_term(p: [u8; 3]) -> Option<QuarticTerm> {
    macro_rules! pick {
        ($(($i:literal, $j:literal, $k:literal)),*) => {
            match p {
                $([$i, $j, $k] => Some(add_term::<5, $i, $j, $k>),)*
                _ => None,
            }
        };
    }
    pick!(
        (4, 0, 0),
        (3, 1, 0),
        (3, 0, 1),
        (3, 0, 0),
        (2, 2, 0),
        (2, 1, 1),
        (2, 1, 0),
        (2, 0, 2),
        (2, 0, 1),
        (2, 0, 0),
        (1, 3, 0),
        (1, 2, 1),
        (1, 2, 0),
        (1, 1, 2),
        (1, 1, 1),
        (1, 1, 0),
        (1, 0, 3),
        (1, 0, 2),
        (1, 0, 1),
        (1, 0, 0),
        (0, 4, 0),
        (0, 3, 1),
        (0, 3, 0),
        (0, 2, 2),
        (0, 2, 1),
        (0, 2, 0),
        (0, 1, 3),
        (0, 1, 2),
        (0, 1, 1),
        (0, 1, 0),
        (0, 0, 4),
        (0, 0, 3),
        (0, 0, 2),
        (0, 0, 1),
        (0, 0, 0)
    )
}

/// The polynomial along `origin + t·dir` for the terms `plan` (in the shape's order), into
/// `out`: the powers, then each term's expansion added in turn.
///
/// The terms add into the caller's coefficients themselves. Summed in a local array that was
/// then returned and copied, the array was read back with 16-byte loads right after the last
/// term's 8-byte stores, which the store buffer cannot forward (a stall on every ray).
#[inline(always)]
pub(super) fn along_quartic(
    plan: &[(QuarticTerm, f64)],
    origin: DVec3,
    dir: DVec3,
    out: &mut [f64; 5],
) {
    let pw = powers_unrolled::<5>(origin, dir);
    *out = [0.0f64; 5];
    for (term, c) in plan {
        term(*c, &pw, out);
    }
}
