//! Quantisation of a picture's colour channels by a table of thresholds instead of a `powf`
//! or two per sample.
//!
//! A channel's sample is q(v) = floor(encode(linear(v))·max + 0.5) of the film value v: a
//! non-decreasing step function of v with at most max + 1 steps. The table holds, for each
//! k in 1..=max, the least v with q(v) ≥ k, found by bisection over the doubles with q itself,
//! so a lookup gives q(v) bit for bit wherever q is non-decreasing. `powf` is accurate to
//! within an ulp but not guaranteed monotonic, so each threshold is also checked against q
//! over `CHECK` doubles either side of it; farther away, no one-ulp error can move q across
//! the step. If any check fails the table is not used and every sample is computed directly.
//! Worth it for 8-bit files (255 steps) of more than a few thousand pixels: a 512x512
//! picture spends 12 ms CPU in `powf` here otherwise.
//!
//! A lookup does not bisect the table: the bit patterns between the first positive threshold
//! and the last are cut into at most `BUCKETS` equal ranges, each remembering how many
//! thresholds lie at or below its start, and a lookup counts on from there (no step or one,
//! almost always). The bisection's eight dependent loads per sample were 5-10 % of small
//! scenes' CPU (three samples a pixel).

/// Doubles either side of a threshold where q is checked to be on the right side.
const CHECK: u64 = 16;

/// Most ranges of bit patterns a lookup starts from (a 8-bit sRGB table's span cut into
/// 4096 ranges leaves about one step per range in its steepest octave).
const BUCKETS: u64 = 4096;

/// The thresholds of a non-decreasing step function of film values.
pub(crate) struct Steps {
    /// How many thresholds the table holds (at most `MAX_STEPS`): q above the last.
    count: u16,
    /// q at zero and below (every curve clamps negative light to zero).
    base: u16,
    /// How many thresholds are zero (q of the smallest positive values).
    zeros: u16,
    /// The bits of the first positive threshold; lookups below it give `zeros`.
    first: u64,
    /// A range's index is (v's bits − `first`) >> `shift`.
    shift: u32,
    /// `start[i]`: how many thresholds are at or below the first value of range i (ranges
    /// past the last: unused). Fixed sizes and byte counts (at most `MAX_STEPS`
    /// thresholds), so that a lookup's indices need no test against a length.
    start: Box<[u8; BUCKETS as usize]>,
    /// The bits of the last threshold less `first`: a value whose bits less `first` are at
    /// most this lies in a range.
    span: u64,
    /// The thresholds, `scan[k - 1]` the least non-negative v with q(v) ≥ k, then NaNs,
    /// where a lookup's count stops (NaN ≤ v is false for every v).
    scan: Box<[f64; 256]>,
}

/// The most thresholds a table holds: an 8-bit sample's steps.
const MAX_STEPS: u16 = 255;

/// Non-negative doubles are ordered as their bit patterns.
fn at(bits: u64) -> f64 {
    f64::from_bits(bits)
}

impl Steps {
    /// The table of `q`, whose values are 0..=`max`; None if `q` is not a non-decreasing step
    /// function near some threshold (then it must be computed directly). Each threshold by
    /// bisection over all doubles (what `new_near` must agree with).
    #[cfg(test)]
    pub fn new(q: impl Fn(f64) -> u16, max: u16) -> Option<Steps> {
        Steps::new_near(q, |_| f64::NAN, max)
    }

    /// `new`, with `guess(k)` a value near the k-th threshold (the curve's inverse at k − ½,
    /// say; NaN for none) where the search for it starts. Since each threshold is checked
    /// to be the only step to k within `CHECK` doubles, and q steps nowhere else, any
    /// search that ends at a step to k ends at the same one; the guess only cuts the
    /// bisection's ~64 evaluations of q (two `powf` each for gamma 2.2 and sRGB) to a few.
    pub fn new_near(q: impl Fn(f64) -> u16, guess: impl Fn(u16) -> f64, max: u16) -> Option<Steps> {
        let top = f64::INFINITY.to_bits();
        if max > MAX_STEPS || q(f64::INFINITY) != max || q(-1.0) != q(0.0) || q(-0.0) != q(0.0) {
            return None;
        }
        let base = q(0.0);
        let mut t = Vec::with_capacity(max as usize);
        // Each threshold is at or above the one before.
        let mut lo = 0u64;
        for k in 1..=max {
            if base >= k {
                t.push(0.0);
                continue;
            }
            // Invariant: q(at(lo)) < k ≤ q(at(hi)).
            let mut hi = top;
            let g = guess(k);
            if g > 0.0 && g.is_finite() && g.to_bits() > lo {
                // Widen a bracket around the guess until q crosses k inside it.
                let gb = g.to_bits();
                let mut d = 2u64;
                let mut a = gb.saturating_sub(d).max(lo);
                while q(at(a)) >= k {
                    hi = a;
                    d = d.saturating_mul(4);
                    a = gb.saturating_sub(d).max(lo);
                }
                lo = a;
                if hi == top {
                    let mut b = gb.saturating_add(d).min(top);
                    while q(at(b)) < k {
                        lo = b;
                        d = d.saturating_mul(4);
                        b = gb.saturating_add(d).min(top);
                    }
                    hi = b;
                }
            }
            while hi - lo > 1 {
                let mid = lo + (hi - lo) / 2;
                if q(at(mid)) >= k {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            let below = hi.saturating_sub(CHECK).max(1)..hi;
            let above = hi..(hi + CHECK).min(top);
            if below.into_iter().any(|b| q(at(b)) >= k) || above.into_iter().any(|b| q(at(b)) < k) {
                return None;
            }
            t.push(at(hi));
        }
        Some(Steps::from_thresholds(t, base))
    }

    /// The lookup ranges over non-decreasing thresholds `t`.
    fn from_thresholds(t: Vec<f64>, base: u16) -> Steps {
        let zeros = t.iter().take_while(|&&x| x <= 0.0).count();
        let first = t.get(zeros).map_or(0, |x| x.to_bits());
        let span = t.last().map_or(0, |x| x.to_bits()).saturating_sub(first);
        let mut shift = 0;
        while span >> shift >= BUCKETS {
            shift += 1;
        }
        // The ranges' starts rise with i and `t` is sorted, so each count goes on from the
        // one before: one walk of the table instead of a bisection per range (4096 of
        // them, ~0.3 M instructions of every 8-bit render).
        assert!(t.len() <= MAX_STEPS as usize, "{} thresholds", t.len());
        let mut below = 0;
        let mut start = Box::new([t.len() as u8; BUCKETS as usize]);
        for (i, s) in start
            .iter_mut()
            .enumerate()
            .take((span >> shift) as usize + 1)
        {
            let v = at(first + ((i as u64) << shift));
            while below < t.len() && t[below] <= v {
                below += 1;
            }
            *s = below as u8;
        }
        let mut scan = Box::new([f64::NAN; 256]);
        scan[..t.len()].copy_from_slice(&t);
        Steps {
            zeros: zeros as u16,
            first,
            shift,
            start,
            span,
            scan,
            count: t.len() as u16,
            base,
        }
    }

    /// q(v): the number of thresholds at or below v (v ≤ 0 and NaN give q's value at zero,
    /// as every curve clamps them there).
    #[inline(always)]
    pub fn q(&self, v: f64) -> u16 {
        // One comparison once compiled (`ucomisd`, then `ja`).
        if v.is_nan() || v <= 0.0 {
            return self.base;
        }
        let bits = v.to_bits();
        let d = bits.wrapping_sub(self.first);
        if d > self.span {
            // Below the first positive threshold (d wrapped), or above the last.
            return if bits < self.first {
                self.zeros
            } else {
                self.count
            };
        }
        // d ≤ span: the range index is below BUCKETS (`from_thresholds`' shift), the mask
        // only tells the compiler so. Every threshold before the range's count is at or
        // below its start, so at or below v; the count stops at the first above v, at the
        // latest at `scan`'s first NaN (masked: no test against the length).
        let mut i = self.start[(d >> self.shift) as usize & (BUCKETS as usize - 1)] as usize;
        while self.scan[i & 255] <= v {
            i += 1;
        }
        i as u16
    }

    /// The thresholds, in order (for the tests: lookups read `scan` and `count`).
    #[cfg(test)]
    fn thresholds(&self) -> &[f64] {
        &self.scan[..self.count as usize]
    }

    /// `q` of a pixel's three channels, all computed before any is stored. (The table's
    /// fields copied into locals first made the compiler read all of them, rare cases' too,
    /// and save three registers: 84 instructions a pixel against 78.)
    #[inline]
    pub fn q3(&self, [r, g, b]: [f64; 3]) -> [u16; 3] {
        [self.q(r), self.q(g), self.q(b)]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn srgb8(v: f64) -> u16 {
        let l = v.max(0.0).powf(2.2).clamp(0.0, 1.0);
        let e = crate::render::srgb_encode(l);
        (e * 255.0 + 0.5).floor() as u16
    }

    #[test]
    fn the_table_gives_what_the_curve_gives() {
        let steps = Steps::new(srgb8, 255).expect("srgb is monotonic near its steps");
        let mut v = 0.0f64;
        // Every threshold, its neighbours, and a dense sweep.
        for &t in steps.thresholds() {
            for b in t.to_bits().saturating_sub(3)..t.to_bits() + 3 {
                assert_eq!(steps.q(at(b)), srgb8(at(b)), "{}", at(b));
            }
        }
        while v < 1.3 {
            assert_eq!(steps.q(v), srgb8(v), "{v}");
            v += 1.0e-5;
        }
        for v in [-1.0, -0.0, 0.0, f64::NAN, f64::INFINITY, 1e300, 1e-300] {
            let want = if v.is_nan() { srgb8(0.0) } else { srgb8(v) };
            assert_eq!(steps.q(v), want, "{v}");
        }
    }

    #[test]
    fn a_guess_finds_the_bisections_steps() {
        // 8-bit sRGB after gamma 2.2 working space (pinkmarb), 5-bit, linear, and gamma 1.8
        // output; exact guesses, guesses off by a few percent, and useless ones.
        let g22 = |v: f64| {
            let l = v.max(0.0).powf(2.2).clamp(0.0, 1.0);
            (crate::render::srgb_encode(l) * 255.0 + 0.5).floor() as u16
        };
        let inv22 = |k: u16| {
            let e = (k as f64 - 0.5) / 255.0;
            let l = if e <= 0.04045 {
                e / 12.92
            } else {
                ((e + 0.055) / 1.055).powf(2.4)
            };
            l.powf(1.0 / 2.2)
        };
        let lin5 = |v: f64| (v.clamp(0.0, 1.0) * 31.0 + 0.5).floor() as u16;
        let p18 = |v: f64| (v.clamp(0.0, 1.0).powf(1.0 / 1.8) * 255.0 + 0.5).floor() as u16;
        type Curve<'a> = &'a dyn Fn(f64) -> u16;
        type Guess<'a> = &'a dyn Fn(u16) -> f64;
        let cases: [(Curve, Guess, u16); 7] = [
            (&srgb8, &|k| inv22(k).powf(2.2), 255),
            (&g22, &inv22, 255),
            (&g22, &|k| inv22(k) * 1.03, 255),
            (&g22, &|k| inv22(k) * 0.9, 255),
            (&g22, &|_| 1e-300, 255),
            (&lin5, &|k| (k as f64 - 0.5) / 31.0, 31),
            (&p18, &|k| ((k as f64 - 0.5) / 255.0).powf(1.8), 255),
        ];
        for (i, (q, guess, max)) in cases.into_iter().enumerate() {
            let plain = Steps::new(q, max).expect("a monotonic curve");
            let near = Steps::new_near(q, guess, max).expect("a monotonic curve");
            let bits = |s: &Steps| {
                s.thresholds()
                    .iter()
                    .map(|t| t.to_bits())
                    .collect::<Vec<_>>()
            };
            assert_eq!(bits(&plain), bits(&near), "case {i}");
        }
    }

    #[test]
    fn the_ranges_count_as_a_bisection_does() {
        // Repeated, zero and far-apart thresholds, and tables of none, one and many.
        let tables: [&[f64]; 6] = [
            &[],
            &[0.0, 0.0],
            &[0.5],
            &[0.0, 1e-300, 1e-300, 2e-9, 0.25, 0.25, 0.5, 0.75, 1.0, 1e10],
            &[0.0, 0.001, 0.002, 0.003, 0.004, 0.0041, 0.9, 0.99, 0.999],
            &[0.5, 0.5, f64::INFINITY],
        ];
        for t in tables {
            let steps = Steps::from_thresholds(t.to_vec(), 7);
            // Each range's count is the bisection's.
            for (i, &s) in steps
                .start
                .iter()
                .enumerate()
                .take((steps.span >> steps.shift) as usize + 1)
            {
                let v = at(steps.first + ((i as u64) << steps.shift));
                assert_eq!(s as usize, t.partition_point(|&x| x <= v), "{i} in {t:?}");
            }
            let mut probes = vec![f64::MIN_POSITIVE, 1e-310, 1e300, f64::INFINITY, 0.3, 5.0];
            // Negative values and NaNs of every sign and payload are q at zero.
            for v in [
                -0.0,
                -1e-300,
                -1.0,
                f64::NEG_INFINITY,
                -f64::NAN,
                at(u64::MAX),
            ] {
                assert_eq!(steps.q(v), 7, "{v} in {t:?}");
            }
            for &x in t {
                for b in x.to_bits().saturating_sub(2)..x.to_bits() + 3 {
                    probes.push(at(b));
                }
            }
            for v in probes.into_iter().filter(|v| *v > 0.0) {
                let want = t.partition_point(|&x| x <= v) as u16;
                assert_eq!(steps.q(v), want, "{v} in {t:?}");
            }
            assert_eq!(steps.q(0.0), 7);
            assert_eq!(steps.q(f64::NAN), 7);
            assert_eq!(steps.q(at(f64::INFINITY.to_bits() + 1)), 7);
        }
    }

    #[test]
    fn a_curve_that_steps_back_is_refused() {
        // Down by one just past 0.5: no table may stand in for it.
        let q = |v: f64| {
            let base = (v.clamp(0.0, 1.0) * 255.0 + 0.5).floor() as u16;
            if v > 0.5 && v < 0.5 + 1e-15 {
                base - 1
            } else {
                base
            }
        };
        assert!(Steps::new(q, 255).is_none());
    }
}
