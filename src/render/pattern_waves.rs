//! Ripples and waves: the ten wave sources and the pattern's value from them (the normals'
//! tilts from the same sources are `normal::waves`).

use std::f64::consts::TAU;

use crate::math::{has_avx, DVec3};
use crate::scene::pattern::{Pattern, PatternKind};

/// POV-Ray's ten wave sources (points on the unit sphere) that ripples and waves spread from,
/// with each source's frequency in waves. Measured by scripts/measure_waves.py: with
/// `number_of_waves N` the pigment adds source N, whose own field (N·v_N − (N−1)·v_(N−1)) fits
/// sin(2π·d) for ripples and (0.4/f)·sin(2π·f·d) for waves with rms error below 1e-4.
pub const WAVE_SOURCES: [(DVec3, f64); 10] = [
    (DVec3::new(-0.60437, 0.49205, -0.62658), 0.91912),
    (DVec3::new(-0.55258, -0.24607, -0.79631), 0.96004),
    (DVec3::new(-0.44454, 0.62333, 0.64330), 0.43317),
    (DVec3::new(0.49659, 0.66894, 0.55309), 0.70930),
    (DVec3::new(-0.06437, -0.80595, -0.58848), 0.68919),
    (DVec3::new(0.24619, -0.91456, -0.32090), 0.99144),
    (DVec3::new(-0.66610, -0.59187, -0.45387), 0.78297),
    (DVec3::new(-0.52050, -0.38602, -0.76162), 0.40067),
    (DVec3::new(0.13794, -0.70465, -0.69602), 0.22967),
    (DVec3::new(0.56490, 0.72204, -0.39943), 0.16851),
];

/// Ripples and waves: the mean of circular waves from the ten sources. Frequency and phase
/// act inside the waves and then once more on the value like any pattern's (measured: both
/// match povray's 16-bit values only so).
///
/// The sources' distances and sine arguments first (`wave_args`), then the sines, then the
/// sum in source order: the same operations as one loop over the sources.
pub(super) fn waves(pat: &Pattern, q: DVec3) -> f64 {
    let n = wave_count(pat);
    let ripples = matches!(pat.kind, PatternKind::Ripples(_));
    let mut a = wave_args(q, ripples, pat.frequency, pat.phase);
    for x in &mut a[..n] {
        *x = x.sin();
    }
    let mut sum = 0.0;
    for (k, &(_, f)) in WAVE_SOURCES[..n].iter().enumerate() {
        sum += if ripples { a[k] } else { 0.4 / f * a[k] };
    }
    0.5 + 0.5 * sum / n as f64
}

/// Lanes of the wave sources: ten, padded to a multiple of four.
const LANES: usize = 12;

/// The sources by component (padding at the origin with frequency 1, never summed).
const SRC_X: [f64; LANES] = source_column(0);
const SRC_Y: [f64; LANES] = source_column(1);
const SRC_Z: [f64; LANES] = source_column(2);
const SRC_F: [f64; LANES] = source_column(3);

const fn source_column(c: usize) -> [f64; LANES] {
    let mut out = [if c == 3 { 1.0 } else { 0.0 }; LANES];
    let mut k = 0;
    while k < WAVE_SOURCES.len() {
        let (p, f) = WAVE_SOURCES[k];
        out[k] = match c {
            0 => p.x,
            1 => p.y,
            2 => p.z,
            _ => f,
        };
        k += 1;
    }
    out
}

/// Every source's sine argument at `q` (before the sine), in the one-loop form's operations:
/// glam's `length` (x² + y², + z², then the square root) and 2π·((f·d)·frequency + phase),
/// f 1 for ripples (exact). Computed for the twelve lanes together: the ten square roots and
/// products were a chain of scalar operations waiting on each other's latency around the
/// libm calls (ripples, waves: 0.95 of the time).
#[inline]
fn wave_args(q: DVec3, ripples: bool, freq: f64, phase: f64) -> [f64; LANES] {
    #[cfg(target_arch = "x86_64")]
    if has_avx() {
        // SAFETY: AVX was detected.
        return unsafe { wave_args_avx(q, ripples, freq, phase) };
    }
    wave_args_lanes(q, ripples, freq, phase)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
unsafe fn wave_args_avx(q: DVec3, ripples: bool, freq: f64, phase: f64) -> [f64; LANES] {
    wave_args_lanes(q, ripples, freq, phase)
}

#[inline(always)]
fn wave_args_lanes(q: DVec3, ripples: bool, freq: f64, phase: f64) -> [f64; LANES] {
    let mut arg = [0.0; LANES];
    for (k, a) in arg.iter_mut().enumerate() {
        let (x, y, z) = (q.x - SRC_X[k], q.y - SRC_Y[k], q.z - SRC_Z[k]);
        let d = (x * x + y * y + z * z).sqrt();
        let f = if ripples { 1.0 } else { SRC_F[k] };
        *a = TAU * (f * d * freq + phase);
    }
    arg
}

/// How many wave sources a ripples or waves pattern uses (`number_of_waves`).
pub fn wave_count(pat: &Pattern) -> usize {
    match pat.kind {
        PatternKind::Ripples(n) | PatternKind::Waves(n) => {
            (n as usize).clamp(1, WAVE_SOURCES.len())
        }
        _ => WAVE_SOURCES.len(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `waves` (distances and arguments in lanes, the sines, then the sum) is the one-loop
    /// form bit for bit, for ripples and waves with every source count, frequency and phase.
    #[test]
    fn waves_are_the_one_loop_sum() {
        fn one_loop(pat: &Pattern, q: DVec3) -> f64 {
            let sources = &WAVE_SOURCES[..wave_count(pat)];
            let mut sum = 0.0;
            for &(c, f) in sources {
                let d = (q - c).length();
                sum += match pat.kind {
                    PatternKind::Ripples(_) => (TAU * (d * pat.frequency + pat.phase)).sin(),
                    _ => 0.4 / f * (TAU * (f * d * pat.frequency + pat.phase)).sin(),
                };
            }
            0.5 + 0.5 * sum / sources.len() as f64
        }
        for count in [1, 3, 10, 12] {
            for kind in [PatternKind::Ripples(count), PatternKind::Waves(count)] {
                let mut pat = Pattern::new(kind);
                for (freq, phase) in [(1.0, 0.0), (5000.0, 0.25), (0.3, -1.5)] {
                    pat.frequency = freq;
                    pat.phase = phase;
                    let mut points = vec![WAVE_SOURCES[0].0, WAVE_SOURCES[9].0];
                    for k in 0..300 {
                        let t = k as f64 * 0.37;
                        points.push(DVec3::new(t.sin() * 3.0, t * 0.05 - 4.0, (t * 0.7).cos()));
                    }
                    for q in points {
                        assert_eq!(waves(&pat, q).to_bits(), one_loop(&pat, q).to_bits());
                    }
                }
            }
        }
    }
}
