//! Pattern evaluation: the scalar value (or block index) of a pattern at a point in its own
//! space, independent of what the value then selects (colours, pigments, and later normals).
//!
//! Order, as POV-Ray 3.7 does it: warps from the last written to the first, then classic
//! turbulence (always innermost), then the pattern's function, then frequency and phase
//! (`fmod(v·f + phase, 1.00001)`, plus 1 when negative; the period just over 1 keeps a value of
//! exactly 1, such as `spherical` at its centre, at the top of the map), then the wave type.
//! The formulas of the deterministic patterns were measured against the `povray` binary with
//! 16-bit renders of each pattern on a plane (see tests/probes/pattern_*.pov).
//!
//! Parts of it live beside it: the block patterns in `pattern_blocks`, the normals' four
//! samples together in `pattern_lanes`, the surface slope and aoi read in `pattern_surface`,
//! ripples' and waves' sources in `pattern_waves`.

use std::f64::consts::{PI, TAU};

use crate::math::DVec3;
use crate::scene::pattern::{Pattern, PatternKind, Wave};

use super::fractal::fractal;
use super::noise;
use super::pattern_blocks::{brick, checker, cubic, hexagon, square, triangular};
use super::pattern_surface::{angle_value, slope};
use super::pattern_waves::waves;
use super::pattern_wrap::{fmod, fmod_by};
use super::warp;

pub use super::pattern_lanes::values_warped4;
pub use super::pattern_surface::{set_surface, surface, uses_surface, Surface};
pub use super::pattern_waves::{wave_count, WAVE_SOURCES};

/// POV-Ray's period for frequency and phase: a hair over 1 (measured: `spherical frequency 2`
/// keeps the centre at the top of the map).
const WRAP: f64 = 1.00001;

/// `1.0 / WRAP`, for `fmod_by`.
const WRAP_RECIP: f64 = 1.0 / WRAP;

/// The pattern's value in [0, 1] at `p` (pattern space, before warps), ready for a map lookup.
pub fn value(pat: &Pattern, p: DVec3) -> f64 {
    let q = warped(pat, p);
    let v = raw(pat, q);
    shape(pat, v)
}

/// Which listed item a block pattern (checker, hexagon, brick) picks at `p`; for other
/// patterns, whether the value is in the upper half.
pub fn index(pat: &Pattern, p: DVec3) -> usize {
    index_warped(pat, warped(pat, p))
}

/// The pattern's value at a point `warped` has already moved (maps and lists evaluate their
/// entries there too).
pub fn value_warped(pat: &Pattern, q: DVec3) -> f64 {
    shape(pat, raw(pat, q))
}

/// `index` at a point `warped` has already moved.
pub fn index_warped(pat: &Pattern, q: DVec3) -> usize {
    match &pat.kind {
        PatternKind::Checker => checker(q),
        PatternKind::Hexagon => hexagon(q),
        PatternKind::Brick { size, mortar } => brick(q, *size, *mortar),
        PatternKind::Square => square(q),
        PatternKind::Triangular => triangular(q),
        PatternKind::Cubic => cubic(q),
        PatternKind::MaterialMap(im, indices) => material_index(im, indices, q),
        _ => (shape(pat, raw(pat, q)) >= 0.5) as usize,
    }
}

/// The point after warps and turbulence: where the entries of a map or list are evaluated
/// (measured: a `pigment_map`, pigment list, `texture_map`, texture list or `normal_map` of
/// `gradient z` stripes under `warp { turbulence }` or plain turbulence shows wavy stripes in
/// povray; marble's and wood's own turbulence, which is not a warp, leaves them straight).
/// Inlined for its first test (no warps, and no turbulence or marble's and wood's own: the
/// point stays), which spares most patterns a ~30-instruction call.
#[inline]
pub fn warped(pat: &Pattern, p: DVec3) -> DVec3 {
    if pat.warps.is_empty()
        && (pat.turbulence.is_none() || matches!(pat.kind, PatternKind::Marble | PatternKind::Wood))
    {
        p
    } else {
        warped_moved(pat, p)
    }
}

/// `warped` of a pattern with warps or turbulence.
#[inline(never)]
fn warped_moved(pat: &Pattern, p: DVec3) -> DVec3 {
    let mut q = p;
    for w in pat.warps.iter().rev() {
        q = warp::apply(w, q, pat.noise_generator);
    }
    if let Some(t) = &pat.turbulence {
        // Marble and wood use their turbulence in their own formulas instead (see `raw`).
        if !matches!(pat.kind, PatternKind::Marble | PatternKind::Wood) && t.amount != DVec3::ZERO {
            q += t.amount
                * noise::turbulence_vec(q, t.octaves, t.omega, t.lambda, pat.noise_generator);
        }
    }
    q
}

/// Frequency, phase and wave type.
pub(super) fn shape(pat: &Pattern, v: f64) -> f64 {
    shape_inline(pat, v)
}

/// `shape` written into its caller: a normal's four samples (gradient, radial, the noises)
/// paid its call and an array `map` on each (~30 instructions a sample on normavg).
#[inline(always)]
pub(super) fn shape_inline(pat: &Pattern, v: f64) -> f64 {
    if pat.is_block() {
        return v;
    }
    let x = v * pat.frequency + pat.phase;
    // Inside the period fmod's own first exit answers x, here before its call (not inlined).
    let mut v = if x.abs() < WRAP {
        x
    } else {
        fmod_by(x, WRAP, WRAP_RECIP)
    };
    if v < 0.0 {
        // Measured: gradient x at x = -0.3 gives 0.7, so negatives wrap by 1, not WRAP.
        v += 1.0;
    }
    if !v.is_finite() {
        v = 0.0;
    }
    match pat.wave {
        Wave::Ramp => v,
        Wave::Triangle => {
            if v < 0.5 {
                2.0 * v
            } else {
                2.0 - 2.0 * v
            }
        }
        Wave::Sine => 0.5 + 0.5 * (TAU * v).sin(),
        Wave::Scallop => (PI * v).sin().abs(),
        Wave::Cubic => v * v * (3.0 - 2.0 * v),
        Wave::Poly(e) => v.max(0.0).powf(e),
    }
}

/// The pattern's own function before frequency, phase and wave.
fn raw(pat: &Pattern, q: DVec3) -> f64 {
    let gen = pat.noise_generator;
    match &pat.kind {
        PatternKind::Checker => checker(q) as f64,
        PatternKind::Hexagon => hexagon(q) as f64 / 2.0,
        PatternKind::Brick { size, mortar } => brick(q, *size, *mortar) as f64,
        PatternKind::Square => square(q) as f64,
        PatternKind::Triangular => triangular(q) as f64,
        PatternKind::Cubic => cubic(q) as f64,
        PatternKind::ImagePattern(im) => {
            let c = super::pigment::image(im, q);
            if im.use_alpha {
                // Measured: opaque pixels give 0, so the value is the transparency.
                c.transmit
            } else {
                0.297 * c.rgb.x + 0.589 * c.rgb.y + 0.114 * c.rgb.z
            }
        }
        PatternKind::PigmentPattern(p) => {
            let c = super::pigment::eval(p, q);
            0.297 * c.rgb.x + 0.589 * c.rgb.y + 0.114 * c.rgb.z
        }
        // Read by coordinates for the same reason as onion and spherical below: `dot` and the
        // three `abs` read y-z as one 16-byte load across the caller's x-y and z stores.
        PatternKind::Gradient(a) => gradient(crate::math::by_coordinates(&q), *a),
        // `length` of the caller's copy of `q` read as three 8-byte loads (`by_coordinates`):
        // it read y-z as one 16-byte load across the caller's x-y and z stores, which cannot
        // be forwarded (34 % of `raw`'s samples on interior/media/media4). Only here: read so
        // at the top of `raw`, the other patterns' pair loads were lost (wood_2 1.02).
        PatternKind::Onion => fmod(crate::math::by_coordinates(&q).length(), 1.0),
        PatternKind::Radial => radial(q),
        PatternKind::Spherical => 1.0 - crate::math::by_coordinates(&q).length().min(1.0),
        PatternKind::Cylindrical => 1.0 - (q.x * q.x + q.z * q.z).sqrt().min(1.0),
        PatternKind::Boxed => {
            let q = crate::math::by_coordinates(&q);
            1.0 - q.x.abs().max(q.y.abs()).max(q.z.abs()).min(1.0)
        }
        PatternKind::Planar => 1.0 - q.y.abs().min(1.0),
        PatternKind::Leopard => {
            let s = (q.x.sin() + q.y.sin() + q.z.sin()) / 3.0;
            s * s
        }
        PatternKind::Marble => {
            let t = pat.turbulence.map_or(0.0, |t| {
                t.amount.x * noise::turbulence(q, t.octaves, t.omega, t.lambda, gen)
            });
            q.x + t
        }
        PatternKind::Wood => match &pat.turbulence {
            Some(t) if t.amount != DVec3::ZERO => {
                // Not through turbulence_vec's per-thread cache, which a wood's point almost
                // never hits (a pigment read three times through functions, as the `_37`
                // woods' gamma correction does, is remembered whole by `pigment::eval_memo`).
                let tv = noise::turbulence_vec_uncached(q, t.octaves, t.omega, t.lambda);
                wood(q, t.amount, tv)
            }
            _ => (q.x * q.x + q.y * q.y).sqrt(),
        },
        PatternKind::Spiral1(arms) => {
            let r = (q.x * q.x + q.y * q.y).sqrt();
            if r == 0.0 {
                q.z
            } else {
                r + q.z + arms * (q.y.atan2(q.x) / TAU + 0.25)
            }
        }
        // Measured (scripts/measure_pattern.py): spiral1's value through an exact triangle wave
        // plus the radius's, so 0 to 2 before the pattern's own wave. The manual's "two
        // spirals twisting in opposite directions" is not what 3.7 computes.
        PatternKind::Spiral2(arms) => {
            let r = (q.x * q.x + q.y * q.y).sqrt();
            let s = if r == 0.0 {
                q.z
            } else {
                r + q.z + arms * (q.y.atan2(q.x) / TAU + 0.25)
            };
            tri(s) + tri(r)
        }
        PatternKind::Slope(sl) => slope(sl, q),
        PatternKind::Aoi => surface().map_or(0.0, |s| angle_value(-s.normal.dot(s.ray))),
        PatternKind::Bozo | PatternKind::Spotted => noise::noise(q, gen),
        PatternKind::Granite => noise::granite(q, gen),
        PatternKind::Agate { turb } => {
            let t = pat.turbulence.unwrap_or_default();
            agate(
                *turb,
                q,
                noise::turbulence(q, t.octaves, t.omega, t.lambda, gen),
            )
        }
        PatternKind::Wrinkles => noise::wrinkles(q, gen),
        PatternKind::Dents => noise::noise(q, gen).powi(3),
        PatternKind::Ripples(_) | PatternKind::Waves(_) => waves(pat, q),
        PatternKind::Crackle {
            form,
            metric,
            offset,
            solid,
        } => super::crackle::crackle(q, *form, *metric, *offset, *solid, gen),
        PatternKind::Cells => {
            noise::cell_value(q.x.floor() as i64, q.y.floor() as i64, q.z.floor() as i64)
        }
        PatternKind::MaterialMap(im, indices) => material_index(im, indices, q) as f64,
        PatternKind::Tiling(n) => super::tiling::value(*n, q),
        PatternKind::Quilted { c0, c1 } => {
            // Measured: a third of the cushion vector's component magnitudes.
            let v = quilted_vector(q, *c0, *c1);
            (v.x.abs() + v.y.abs() + v.z.abs()) / 3.0
        }
        PatternKind::Fractal(f) => fractal(f, (q.x, q.y)),
        PatternKind::DensityFile(d) => d.eval(q),
        PatternKind::Object(o) => o.inside(q) as u8 as f64,
        // Measured as gradient's: values above 1 are reduced first (2 and 3 give 0, 2.5 gives
        // 0.5, 1 stays 1; a density of 3 is no media at all).
        PatternKind::Function(f) => {
            if f.unsupported.is_some() {
                0.0
            } else {
                let v = f.eval(&[q.x, q.y, q.z]);
                if v > 1.0 {
                    fmod(v, 1.0)
                } else {
                    v
                }
            }
        }
        // Maps handle `average` themselves; as a plain value it is the middle.
        PatternKind::Unsupported | PatternKind::Average => 0.5,
    }
}

/// Radial's value before the wave: the angle about y from +x, in turns.
#[inline(always)]
pub(super) fn radial(q: DVec3) -> f64 {
    let a = (-q.z).atan2(q.x) / TAU;
    a - a.floor()
}

/// Gradient's value before the wave. Measured: gradient x gives 0.3 at x = 1.3, 1 at 1, 0 at
/// 2, but 0.80009 at -9.2 (only values above 1 are reduced before the 1.00001 wrap).
#[inline(always)]
pub(super) fn gradient(q: DVec3, a: DVec3) -> f64 {
    let v = q.dot(a);
    if v > 1.0 && v < 2.0 {
        // fmod's exact result here (Sterbenz: v − 1 is exact for v in [1, 2]).
        v - 1.0
    } else if v > 1.0 {
        fmod(v, 1.0)
    } else {
        v
    }
}

/// A material map's palette index at `q` (0 off a `once` image).
fn material_index(im: &crate::scene::desc::ImageMap, indices: &[u8], q: DVec3) -> usize {
    super::pigment::image_pixel(im, q)
        .and_then(|i| indices.get(i))
        .map_or(0, |&i| i as usize)
}

/// Quilted's cushion vector at `q`: the offset d from the centre of q's unit cube times
/// (2/√3)·B(|d|), B the cubic Bézier through 0, `c0`, `c1`, 1. Measured with
/// scripts/measure_pattern.py and scripts/measure_normals.py (docs/textures.md): the pattern
/// value is a third of the vector's |x| + |y| + |z| and the normal is n + amount·vector, both
/// to the printed precision at random points in ±3 for several control pairs.
pub fn quilted_vector(q: DVec3, c0: f64, c1: f64) -> DVec3 {
    let d = q - q.floor() - DVec3::splat(0.5);
    let t = d.length();
    let s = 1.0 - t;
    let b = 3.0 * s * s * t * c0 + 3.0 * s * t * t * c1 + t * t * t;
    d * (b * 2.0 / 3f64.sqrt())
}

/// Wood's rings under turbulence `amount`, v the vector turbulence at q. Measured: the rings'
/// x and y are x + sin(2π a.x (x + v.x)) and y + sin(2π a.y (y + v.y)).
pub(super) fn wood(q: DVec3, amount: DVec3, v: DVec3) -> f64 {
    let x = q.x + (TAU * amount.x * (q.x + v.x)).sin();
    let y = q.y + (TAU * amount.y * (q.y + v.y)).sin();
    (x * x + y * y).sqrt()
}

/// Agate from the scalar turbulence t at q. Measured: (1/2 + sin(2π(1.1 z + 1.3 agate_turb
/// t))/2)^0.77, t with the pattern's octaves, omega and lambda.
pub(super) fn agate(turb: f64, q: DVec3, t: f64) -> f64 {
    (0.5 + 0.5 * (TAU * (1.1 * q.z + 1.3 * (turb as f32 as f64) * t)).sin()).powf(0.77)
}

/// A triangle wave of period 1 from 0 (at integers) to 1 (at half-integers).
fn tri(v: f64) -> f64 {
    let f = v - v.floor();
    if f < 0.5 {
        2.0 * f
    } else {
        2.0 - 2.0 * f
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pat(kind: PatternKind) -> Pattern {
        Pattern::new(kind)
    }

    #[test]
    fn frequency_keeps_one_at_the_top_and_wraps_negatives() {
        let mut p = pat(PatternKind::Spherical);
        p.frequency = 2.0;
        assert!(value(&p, DVec3::ZERO) > 0.999);
        let mut g = pat(PatternKind::Gradient(DVec3::X));
        g.frequency = -1.5;
        g.phase = 0.3;
        // Measured with povray: gradient x, frequency -1.5, phase 0.3 at x = 1.4125.
        assert!((value(&g, DVec3::new(1.4125, 0.0, 0.0)) - 0.68125).abs() < 1e-4);
    }

    #[test]
    fn spiral2_matches_povray() {
        // scripts/measure_pattern.py 'spiral2 2.5' and 'spiral2 2.5 ramp_wave frequency 0.3
        // phase 0.1' at these points; 1e-6 is the 12 digits printed less rounding slack.
        let pts = [
            (DVec3::new(-0.7, 0.4, 1.3), 0.538982638, 0.480850412),
            (DVec3::new(0.3, -1.2, -0.45), 0.511916522, 0.323212532),
            (DVec3::new(0.0, 0.0, -0.35), 0.6, 0.310000010),
            (DVec3::new(1.7, 0.1, 0.2), 0.874790237, 0.531221554),
        ];
        // The parser truncates the arms as povray does.
        let tri = pat(PatternKind::Spiral2(2.0));
        let mut ramp = pat(PatternKind::Spiral2(2.0));
        ramp.wave = Wave::Ramp;
        ramp.frequency = 0.3;
        ramp.phase = 0.1;
        for (p, a, b) in pts {
            assert!((value(&tri, p) - a).abs() < 1e-6, "{p}: {}", value(&tri, p));
            assert!(
                (value(&ramp, p) - b).abs() < 1e-6,
                "{p}: {}",
                value(&ramp, p)
            );
        }
    }

    /// `warped`'s inline test keeps the point only where the whole warp would: no warps, and
    /// no turbulence or marble's and wood's own (zero turbulence too, which leaves it).
    #[test]
    fn warped_test_is_the_whole_warp() {
        use crate::scene::pattern::Turbulence;
        let turb = Turbulence {
            amount: DVec3::new(0.7, 0.2, 0.1),
            ..Default::default()
        };
        let still = Turbulence {
            amount: DVec3::ZERO,
            ..Default::default()
        };
        let kinds = [
            PatternKind::Wood,
            PatternKind::Marble,
            PatternKind::Granite,
            PatternKind::Agate { turb: 1.6 },
            PatternKind::Gradient(DVec3::X),
        ];
        for kind in kinds {
            for turbulence in [None, Some(turb), Some(still)] {
                let mut p = pat(kind.clone());
                p.turbulence = turbulence;
                for n in 0..200 {
                    let t = n as f64 * 0.37;
                    let q = DVec3::new(t.sin() * 5.0, t * 0.03 - 2.0, t.cos());
                    let bits = |v: DVec3| v.to_array().map(f64::to_bits);
                    assert_eq!(bits(warped(&p, q)), bits(warped_moved(&p, q)), "{kind:?}");
                }
            }
        }
    }

    #[test]
    fn waves_shape_the_value() {
        let mut g = pat(PatternKind::Gradient(DVec3::X));
        g.wave = Wave::Triangle;
        assert!((value(&g, DVec3::new(0.75, 0.0, 0.0)) - 0.5).abs() < 1e-9);
        g.wave = Wave::Scallop;
        assert!((value(&g, DVec3::new(0.5, 0.0, 0.0)) - 1.0).abs() < 1e-9);
        g.wave = Wave::Poly(2.0);
        assert!((value(&g, DVec3::new(0.5, 0.0, 0.0)) - 0.25).abs() < 1e-9);
    }
}
