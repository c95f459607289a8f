//! The remainder a pattern's value wraps by (`fmod`, Rust's `%` on f64), computed without
//! the software loop of `compiler_builtins`' fmod (2 % of normavg, 1 % of a wood: every
//! textured hit wraps its value by 1.00001 after frequency and phase; 4 % of mist, whose
//! brick normal takes four remainders per sample).
//!
//! fmod's result is exact: x − n·y for the integer n = trunc(x / y), which is always
//! representable. The quotient's rounding can make the computed n one too big or too small;
//! then the computed remainder falls outside [0, y) and the software fmod answers instead.
//! With n right, n·y is split into two exact products (y cut into a 26-bit head and the
//! rest, n below 2^26), the head's subtraction is exact (Sterbenz: within a factor 2, which
//! is checked), and the last subtraction rounds the exact remainder to itself.

/// 2^900 and 2^-900: bounds well inside the exponent range, so the split and the products
/// neither overflow nor lose bits to underflow.
const BIG: f64 = f64::from_bits((1023 + 900) << 52);
const SMALL: f64 = f64::from_bits((1023 - 900) << 52);

/// `x % y`, bit for bit.
#[inline]
pub fn fmod(x: f64, y: f64) -> f64 {
    remainder(x, y, |ax| ax / y)
}

/// `x % y`, bit for bit, with `y_recip` = `1.0 / y`: the quotient's estimate `ax · y_recip`
/// is a multiplication (about 4 cycles) instead of a division (about 14, on the chain of
/// every pattern value's wrap: `pattern::shape`'s samples waited on it). The product is
/// within two roundings of ax / y, as the quotient was within one: n is again right or one
/// off near a multiple of y, and one off is caught and answered by the software fmod.
#[inline]
pub fn fmod_by(x: f64, y: f64, y_recip: f64) -> f64 {
    remainder(x, y, |ax| ax * y_recip)
}

/// `fmod`'s steps with `quotient(|x|)` as the estimate of |x| / y whose truncation is n.
#[inline(always)]
fn remainder(x: f64, y: f64, quotient: impl Fn(f64) -> f64) -> f64 {
    let ax = x.abs();
    // Past these bounds (or NaN, infinities, y ≤ 0), the general routine.
    if !(ax < BIG && y > SMALL && y < BIG) {
        return x % y;
    }
    if ax < y {
        return x;
    }
    let n = quotient(ax).trunc();
    if n >= (1u64 << 26) as f64 {
        return x % y;
    }
    // Veltkamp's split: `yh` holds y's top 26 bits, `yl` the rest (27 bits with its sign).
    let c = 134_217_729.0 * y;
    let yh = c - (c - y);
    let yl = y - yh;
    let head = n * yh;
    if 2.0 * head < ax {
        return x % y;
    }
    let r = (ax - head) - n * yl;
    if !(0.0..y).contains(&r) {
        return x % y;
    }
    if x < 0.0 {
        -r
    } else {
        r
    }
}

/// `x.rem_euclid(y)` (std's: the remainder, plus |y| when negative), with `fmod`.
#[inline]
pub fn rem_euclid(x: f64, y: f64) -> f64 {
    let r = fmod(x, y);
    if r < 0.0 {
        r + y.abs()
    } else {
        r
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A small deterministic generator (xorshift) for the sweeps.
    struct Rng(u64);
    impl Rng {
        fn next(&mut self) -> u64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            self.0
        }
        fn unit(&mut self) -> f64 {
            (self.next() >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    fn same(x: f64, y: f64) {
        let (a, b) = (fmod(x, y), x % y);
        assert!(
            a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()),
            "fmod({x:e}, {y:e}) = {a:e}, % gives {b:e}"
        );
        let a = fmod_by(x, y, 1.0 / y);
        assert!(
            a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()),
            "fmod_by({x:e}, {y:e}) = {a:e}, % gives {b:e}"
        );
        let (a, b) = (rem_euclid(x, y), x.rem_euclid(y));
        assert!(
            a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()),
            "rem_euclid({x:e}, {y:e}) = {a:e}, std gives {b:e}"
        );
    }

    #[test]
    fn the_remainder_is_the_software_fmods() {
        let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
        for y in [1.00001, 1.0, 0.3, 2.5, 1e-3, 7.0 / 3.0] {
            // Magnitudes from tiny to past 2^26 periods, both signs, and the multiples of y
            // and their neighbours, where the quotient's rounding decides n.
            for _ in 0..200_000 {
                let m = rng.unit() * 2f64.powi((rng.next() % 40) as i32 - 8);
                let x = if rng.next() & 1 == 0 { m } else { -m };
                same(x, y);
            }
            for k in 1..5000u64 {
                let m = k as f64 * y;
                for b in m.to_bits() - 3..m.to_bits() + 4 {
                    same(f64::from_bits(b), y);
                    same(-f64::from_bits(b), y);
                }
            }
        }
        let odd = [
            0.0,
            -0.0,
            f64::NAN,
            f64::INFINITY,
            -f64::INFINITY,
            1e300,
            5e-324,
            2f64.powi(26),
        ];
        for x in odd {
            for y in [
                1.00001,
                1.0,
                0.0,
                -1.0,
                f64::NAN,
                f64::INFINITY,
                1e-310,
                1e300,
            ] {
                same(x, y);
                same(x * 3.3, y);
            }
        }
    }
}
