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

/// The thresholds of a non-decreasing step function of film values.
pub(crate) struct Steps {
    /// `t[k - 1]`: the least non-negative v with q(v) ≥ k.
    t: Vec<f64>,
    /// q at zero and below (every curve clamps negative light to zero).
    base: u16,
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
        Some(Steps { t, base })
    }

    /// q(v): the number of thresholds at or below v (v ≤ 0 and NaN give q's value at zero,
    /// as every curve clamps them there).
    #[inline]
    pub fn q(&self, v: f64) -> u16 {
        if v.is_nan() || v <= 0.0 {
            return self.base;
        }
        self.t.partition_point(|&t| t <= v) as u16
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
        for v in [-1.0, -0.0, 0.0, f64::NAN, f64::INFINITY, 1e300, 1e-300] {
            let want = if v.is_nan() { srgb8(0.0) } else { srgb8(v) };
            assert_eq!(steps.q(v), want, "{v}");
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
