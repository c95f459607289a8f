//! Whole and half-whole powers `x^k` (k = n or n + 1/2) with glibc's `pow` bits, without
//! calling it: the superellipsoid scenes' exponents 2/e, e/n and 2/n are often such numbers
//! (e or n of 0.1, 0.2, 0.4, 0.5, 0.8 give 20, 10, 5, 4, 2.5), and `pow` is a sixth of their
//! instructions.
//!
//! The power is computed in double-double arithmetic (products split exactly by FMA): binary
//! exponentiation, and for a half `sqrt(x)` with its correction term. Each step's relative
//! error is below 2^-103, and at most seven squarings follow any one, so the pair `(h, l)`
//! (with `h = fl(h + l)`) is within 2^-90 relative of the exact `x^k`. glibc's `pow` (2.28 and
//! later, from Arm's optimized routines) is documented to be within 0.54 units in the last
//! place of the exact value. Where `|l| < 0.4 ulp(h)` (and `h` is no power of two, so its two
//! neighbours are one `ulp(h)` away), the exact value is within 0.41 ulp of `h` and more than
//! 0.59 ulp from every other double, so `pow` can only have returned `h`. Elsewhere (about one
//! call in five, and outside the normal range) `pow` itself is called. The unit test compares
//! with `powf` on millions of arguments.

/// A whole or half-whole exponent from 3/2 to 128 on a CPU with FMA.
#[derive(Clone, Copy, Debug)]
pub(super) struct IntPow {
    /// The whole part of the exponent.
    n: u32,
    /// Whether a half is added.
    half: bool,
    /// The exponent, for `powf` where the fast path cannot decide.
    k: f64,
}

impl IntPow {
    /// The fast form of `x^k`, if `k` is such an exponent (not 1, 2 or 1/2, which `Power`
    /// handles itself) and the CPU has FMA.
    pub(super) fn new(k: f64) -> Option<IntPow> {
        let twice = k * 2.0;
        if !(3.0..=256.0).contains(&twice) || twice.fract() != 0.0 || k == 2.0 {
            return None;
        }
        if !has_fma() {
            return None;
        }
        let twice = twice as u32;
        Some(IntPow {
            n: twice / 2,
            half: twice % 2 == 1,
            k,
        })
    }

    pub(super) fn exponent(self) -> f64 {
        self.k
    }

    /// `x.powf(k)` to the bit, for `x >= 0`.
    #[inline]
    pub(super) fn of(self, x: f64) -> f64 {
        // SAFETY: `new` made this value only after finding FMA on the CPU.
        match unsafe { pow_fma(x, self.n, self.half) } {
            Some(p) => p,
            None => x.powf(self.k),
        }
    }
}

fn has_fma() -> bool {
    crate::cpu::fma()
}

/// `a + b` as a rounded sum and its exact error, for `|a| >= |b|` (or a zero).
#[inline(always)]
fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// The double-double product of `(ah, al)` and `(bh, bl)`; `al * bl` (below 2^-106 of the
/// product) left out.
#[inline(always)]
fn dd_mul((ah, al): (f64, f64), (bh, bl): (f64, f64)) -> (f64, f64) {
    let p = ah * bh;
    let e = ah.mul_add(bh, -p);
    fast_two_sum(p, e + (ah * bl + al * bh))
}

/// `x^(n + half/2)` as `powf` rounds it, or None where that is not certain (module doc).
#[cfg_attr(target_arch = "x86_64", target_feature(enable = "fma"))]
#[inline(never)]
unsafe fn pow_fma(x: f64, n: u32, half: bool) -> Option<f64> {
    if x == 1.0 {
        return Some(1.0);
    }
    let mut acc = (x, 0.0);
    // Binary exponentiation from the bit below the top one.
    let top = 31 - n.leading_zeros();
    for bit in (0..top).rev() {
        acc = dd_mul(acc, acc);
        if n >> bit & 1 == 1 {
            acc = dd_mul(acc, (x, 0.0));
        }
    }
    if half {
        let s = x.sqrt();
        // x − s² is exact with `s` the correctly rounded root; s + r is √x within 2^-104.
        let r = (-s).mul_add(s, x) / (2.0 * s);
        acc = dd_mul(acc, (s, r));
    }
    let (h, l) = acc;
    // Normal and far from both ends of the range, so no product above lost bits to underflow
    // and `ulp` below is exact; NaN fails too.
    if !(h > 1e-270 && h < 1e300) {
        return None;
    }
    let bits = h.to_bits();
    if bits & ((1u64 << 52) - 1) == 0 {
        return None;
    }
    let ulp = f64::from_bits(bits & 0x7ff0_0000_0000_0000) * f64::EPSILON;
    (l.abs() < 0.4 * ulp).then_some(h)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The fast powers are `powf`'s to the bit, over many binades and every exponent the
    /// sample scenes use (and some more), with how often the fast path decides.
    #[test]
    fn whole_and_half_powers_are_powf() {
        let Some(_) = IntPow::new(4.0) else {
            return; // no FMA: nothing to compare
        };
        let mut next = crate::geom::superellipsoid::near::tests::rng(0x6a09_e667_f3bc_c909);
        let (mut fast, mut all) = (0u64, 0u64);
        for twice in 3..=60u32 {
            let k = twice as f64 / 2.0;
            let Some(p) = IntPow::new(k) else {
                assert!(k == 2.0);
                continue;
            };
            for i in 0..60_000 {
                let x = match i % 4 {
                    0 => next(),
                    1 => 1.0 + next(),
                    2 => 1.0 - next() * 1e-3,
                    _ => next() * 2f64.powi(-(i % 40)),
                };
                let want = x.powf(k);
                assert_eq!(p.of(x).to_bits(), want.to_bits(), "{x} {k}");
                // SAFETY: `p` exists, so the CPU has FMA.
                fast += unsafe { pow_fma(x, p.n, p.half) }.is_some() as u64;
                all += 1;
            }
        }
        for k in [3.0, 4.0, 5.0, 10.0, 20.0, 2.5, 1.5, 128.0] {
            let p = IntPow::new(k).unwrap();
            for x in [
                0.0,
                1.0,
                2.0,
                0.5,
                f64::MIN_POSITIVE,
                5e-324,
                1e300,
                f64::INFINITY,
            ] {
                assert_eq!(p.of(x).to_bits(), x.powf(k).to_bits(), "{x} {k}");
            }
            assert!(p.of(f64::NAN).is_nan());
        }
        assert!(fast * 10 > all * 6, "{fast} of {all}");
        assert!(IntPow::new(2.0).is_none() && IntPow::new(1.0).is_none());
        assert!(IntPow::new(0.5).is_none() && IntPow::new(2.2).is_none());
    }
}
