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

/// Doubles either side of a threshold where q is checked to be on the right side.
const CHECK: u64 = 16;

/// Buckets of film values the lookup starts from: `BUCKETS` equal parts of [0, 1), the last
/// also holding everything above.
const BUCKETS: usize = 1024;

/// The thresholds of a non-decreasing step function of film values.
pub(crate) struct Steps {
    /// `t[k - 1]`: the least non-negative v with q(v) ≥ k.
    t: Vec<f64>,
    /// q at zero and below (every curve clamps negative light to zero).
    base: u16,
    /// `first[b]`: how many thresholds lie in buckets before b (`bucket`), so that the
    /// thresholds of bucket b are `t[first[b]..first[b + 1]]`. A value's q is `first` of its
    /// bucket plus the thresholds of that bucket at or below it: one multiplication and a
    /// comparison or two instead of a binary search over all of `t` (which was a twelfth of
    /// a small scene's CPU time).
    first: Vec<u16>,
}

/// The bucket of a positive film value (or +∞). Non-decreasing in v, so a threshold in an
/// earlier bucket than v's is below v and one in a later bucket is above it.
#[inline]
fn bucket(v: f64) -> usize {
    debug_assert!(v > 0.0);
    let x = (v * BUCKETS as f64).min((BUCKETS - 1) as f64);
    // SAFETY: v is positive (not NaN), so x is in [0, BUCKETS - 1]; the checked conversion's
    // range tests were a third of the lookup.
    unsafe { x.to_int_unchecked::<u32>() as usize }
}

/// Non-negative doubles are ordered as their bit patterns.
fn at(bits: u64) -> f64 {
    f64::from_bits(bits)
}

impl Steps {
    /// The table of `q`, whose values are 0..=`max`; None if `q` is not a non-decreasing step
    /// function near some threshold (then it must be computed directly).
    pub fn new(q: impl Fn(f64) -> u16, max: u16) -> Option<Steps> {
        let top = f64::INFINITY.to_bits();
        if q(f64::INFINITY) != max || q(-1.0) != q(0.0) || q(-0.0) != q(0.0) {
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
        let mut first = vec![0u16; BUCKETS + 1];
        for &v in &t {
            // Zero thresholds (at or below `base`) are never compared: `q` answers v ≤ 0
            // itself, and every positive v is above them, so they count in bucket 0's start.
            let after = if v > 0.0 { bucket(v) + 1 } else { 0 };
            for f in &mut first[after..] {
                *f += 1;
            }
        }
        Some(Steps { t, base, first })
    }

    /// q(v): the number of thresholds at or below v (v ≤ 0 and NaN give q's value at zero,
    /// as every curve clamps them there).
    #[inline]
    pub fn q(&self, v: f64) -> u16 {
        if v.is_nan() || v <= 0.0 {
            return self.base;
        }
        let b = bucket(v);
        let (lo, hi) = (self.first[b] as usize, self.first[b + 1] as usize);
        (lo + self.t[lo..hi].partition_point(|&t| t <= v)) as u16
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
        for &t in &steps.t {
            for b in t.to_bits().saturating_sub(3)..t.to_bits() + 3 {
                assert_eq!(steps.q(at(b)), srgb8(at(b)), "{}", at(b));
            }
        }
        while v < 1.3 {
            assert_eq!(steps.q(v), srgb8(v), "{v}");
            v += 1.0e-5;
        }
        // Bucket edges and their neighbours.
        for b in 0..=BUCKETS as u64 {
            let e = b as f64 / BUCKETS as f64;
            for bits in e.to_bits().saturating_sub(2)..e.to_bits() + 2 {
                assert_eq!(steps.q(at(bits)), srgb8(at(bits)), "{}", at(bits));
            }
        }
        for v in [-1.0, -0.0, 0.0, f64::NAN, f64::INFINITY, 1e300, 1e-300] {
            let want = if v.is_nan() { srgb8(0.0) } else { srgb8(v) };
            assert_eq!(steps.q(v), want, "{v}");
        }
    }

    /// The bucketed lookup counts the thresholds at or below v as a search of the whole table
    /// does, for curves whose steps crowd near zero (low exponents), spread out (high ones)
    /// or start above zero (a curve lifted by 3).
    #[test]
    fn buckets_count_as_the_whole_table_does() {
        let mut built = 0;
        for (g, lift) in [(0.2, 0.0), (1.0, 0.0), (2.2, 0.0), (5.0, 0.0), (1.0, 3.0)] {
            let q = |v: f64| {
                let l = v.max(0.0).powf(g).clamp(0.0, 1.0);
                (l * (255.0 - lift) + lift + 0.5).floor() as u16
            };
            let Some(steps) = Steps::new(q, 255) else {
                continue;
            };
            built += 1;
            let whole = |v: f64| {
                if v.is_nan() || v <= 0.0 {
                    steps.base
                } else {
                    steps.t.partition_point(|&t| t <= v) as u16
                }
            };
            let mut state = 0x9e37_79b9_7f4a_7c15u64;
            for i in 0..200_000u64 {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                // Dense over [0, 1.25), then random bit patterns of positive doubles.
                let v = if i < 100_000 {
                    i as f64 * 1.25e-5
                } else {
                    at(state >> 2)
                };
                assert_eq!(steps.q(v), whole(v), "exponent {g}, lift {lift}, v {v}");
                assert_eq!(steps.q(v), q(v), "exponent {g}, lift {lift}, v {v}");
            }
        }
        // powf may step back somewhere for some exponent; most tables must still be built.
        assert!(built >= 4, "{built} tables");
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
