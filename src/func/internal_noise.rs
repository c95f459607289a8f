//! POV-Ray's noise-based internal functions: `f_ridged_mf`, `f_hetero_mf` and `f_ridge`
//! (`functions.inc` numbers 59, 29, 58), built on the noise generators of
//! [`crate::render::noise`] (the same values as POV-Ray's `f_noise_generator`).
//!
//! The formulas were fitted to values the `povray` binary printed (scripts/hetero_ridge.py
//! measures them; the tests in `internal` hold what it printed) and agree to ~1e-15.

use crate::math::DVec3;

fn noise(q: DVec3, gen: u8) -> f64 {
    crate::render::noise::noise(q, gen)
}

/// Musgrave's ridged multifractal ("Texturing and Modeling", ch. 16) with POV-Ray's noise
/// made signed: each octave is (offset − |noise|)², the ones after the first weighted by
/// the previous octave times `gain` (clamped to [0, 1]) and by lacunarity^(−i·H). Checked
/// against povray's printed values (tests in `internal`). One difference is kept on purpose:
/// povray computes the lacunarity^(−i·H) weights once, from the first call it makes in a
/// run, and uses them for every later call whatever their H and lacunarity (measured: a
/// call with H 0 first makes H do nothing in all later calls); lancer uses each call's own,
/// which is what povray draws whenever a scene calls f_ridged_mf with one parameter set.
pub fn ridged_mf(p: DVec3, [h, lacunarity, octaves, offset, gain]: [f64; 5], gen: u8) -> f64 {
    let signed = |q: DVec3| 2.0 * noise(q, gen) - 1.0;
    let mut signal = offset - signed(p).abs();
    signal *= signal;
    let mut result = signal;
    let mut q = p;
    let n = octaves.max(1.0) as u32;
    OCTAVE_WEIGHTS.with_borrow_mut(|w| {
        // Each octave's weight lacunarity^(-i·H), kept per thread for the last (H,
        // lacunarity) asked: an isosurface asks the same ones at every point, and `powf`
        // was a sixth of the benchmark scene's render.
        let key = (h.to_bits(), lacunarity.to_bits());
        if w.0 != key {
            *w = (key, Vec::new());
        }
        while (w.1.len() as u32) < n {
            let i = w.1.len();
            w.1.push(lacunarity.powf(-(i as f64) * h));
        }
        for i in 1..n {
            q *= lacunarity;
            let weight = (signal * gain).clamp(0.0, 1.0);
            signal = offset - signed(q).abs();
            signal = signal * signal * weight;
            result += signal * w.1[i as usize];
        }
    });
    result
}

thread_local! {
    /// f_ridged_mf's octave weights for one (H, lacunarity) pair, by their bits.
    static OCTAVE_WEIGHTS: std::cell::RefCell<((u64, u64), Vec<f64>)> =
        const { std::cell::RefCell::new(((0, 0), Vec::new())) };
}

/// Musgrave's heterogeneous terrain over signed noise s: the first octave is offset + s(p);
/// each later octave i adds (s + offset)·lacunarity^(−i·H) times value^T, where T counts
/// as an integer (truncated; 0 and below give 1, measured: T = 0.99 and −2 act as 0, 2.5 as
/// 2). Octaves are counted while i < octaves; a fractional rest adds its share of one more
/// octave times the value, whatever T. The weights are each call's own (no first-call
/// quirk as in `ridged_mf`: measured).
pub fn hetero_mf(p: DVec3, [h, lacunarity, octaves, offset, t]: [f64; 5], gen: u8) -> f64 {
    let signed = |q: DVec3| 2.0 * noise(q, gen) - 1.0;
    let power = t.trunc();
    let mut value = offset + signed(p);
    let mut q = p;
    let mut i = 1.0;
    while i < octaves {
        q *= lacunarity;
        let increment = (signed(q) + offset) * lacunarity.powf(-i * h);
        let mut f = 1.0;
        let mut k = 1.0;
        while k <= power {
            f *= value;
            k += 1.0;
        }
        value += increment * f;
        i += 1.0;
    }
    let rest = octaves - octaves.trunc();
    if rest != 0.0 {
        q *= lacunarity;
        let increment = (signed(q) + offset) * lacunarity.powf(-i * h);
        value += rest * increment * value;
    }
    value
}

/// A weighted mean of octaves of noise n (in [0, 1]) at points scaled by lambda^i, with
/// weights omega^i, then shifted by offset and divided by max(offset, 1 − offset). Each
/// octave is folded to |1 − n/ridge|, scaled to at most 1 over n in [0, 1] (unless ridge is
/// 0: n itself). The first octave always counts; then whole octaves up to the integer part
/// of octaves, and the fractional part as a share of one more (measured: octaves 0 and −1
/// give the first octave alone, 0.5 and 1.5 the same value). lambda^i and omega^i are
/// powers, not running products: at 12 octaves the products differ from povray's values in
/// the 12th digit, the powers do not.
pub fn ridge(p: DVec3, [lambda, octaves, omega, offset, ridge]: [f64; 5], gen: u8) -> f64 {
    let top = (1.0 - 1.0 / ridge).abs().max(1.0);
    let octave = |i: f64| {
        let n = noise(p * lambda.powf(i), gen);
        let folded = if ridge != 0.0 {
            (1.0 - n / ridge).abs() / top
        } else {
            n
        };
        (omega.powf(i), folded)
    };
    let (mut sum, mut weights) = (octave(0.0).1, 1.0);
    let whole = octaves.trunc();
    let mut i = 1.0;
    while i < whole {
        let (w, v) = octave(i);
        sum += w * v;
        weights += w;
        i += 1.0;
    }
    let rest = octaves - whole;
    if rest != 0.0 {
        let (w, v) = octave(i);
        sum += rest * w * v;
        weights += rest * w;
    }
    (sum / weights - offset) / offset.max(1.0 - offset)
}
