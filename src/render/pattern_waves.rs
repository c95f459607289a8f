//! Ripples and waves: the ten wave sources and the pattern's value from them (the normals'
//! tilts from the same sources are `normal::waves`).

use std::f64::consts::TAU;

use crate::math::DVec3;
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
pub(super) fn waves(pat: &Pattern, q: DVec3) -> f64 {
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

/// How many wave sources a ripples or waves pattern uses (`number_of_waves`).
pub fn wave_count(pat: &Pattern) -> usize {
    match pat.kind {
        PatternKind::Ripples(n) | PatternKind::Waves(n) => {
            (n as usize).clamp(1, WAVE_SOURCES.len())
        }
        _ => WAVE_SOURCES.len(),
    }
}
