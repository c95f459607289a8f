//! A pattern's value at a normal's four samples together (`values_warped4`): fractals'
//! orbits and the noise patterns' lattice walks stepped side by side, gradient, radial,
//! onion, spherical and cylindrical without `raw`'s call and dispatch per sample.

use crate::math::{by_coordinates, DVec3};
use crate::scene::pattern::{Pattern, PatternKind};

use super::fractal::{fractal2_lanes4, magnet_lanes4};
use super::noise;
use super::pattern::{agate, gradient, radial, shape, shape_inline, value_warped, wood};
use super::pattern_wrap::fmod;

/// `values_warped4` of the noise patterns, whose samples' lattice walks go together; None
/// for the others. Always inlined: its one caller's other checks had it moved out of line.
#[inline(always)]
fn noise_values4(pat: &Pattern, qs: &[DVec3; 4]) -> Option<[f64; 4]> {
    let gen = pat.noise_generator;
    let raw = match &pat.kind {
        PatternKind::Bozo | PatternKind::Spotted => noise::noise4(*qs, gen),
        PatternKind::Dents => noise::noise4(*qs, gen).map(|v| v.powi(3)),
        PatternKind::Granite => noise::granite4(*qs, gen),
        PatternKind::Agate { turb } => {
            let t = pat.turbulence.unwrap_or_default();
            let ts = noise::turbulence4(*qs, t.octaves, t.omega, t.lambda, gen);
            std::array::from_fn(|k| agate(*turb, qs[k], ts[k]))
        }
        PatternKind::Wood => match &pat.turbulence {
            Some(t) if t.amount != DVec3::ZERO => {
                let vs = noise::turbulence_vec4(*qs, t.octaves, t.omega, t.lambda);
                std::array::from_fn(|k| wood(qs[k], t.amount, vs[k]))
            }
            _ => return None,
        },
        PatternKind::Marble => {
            let t = pat.turbulence?;
            let ts = noise::turbulence4(*qs, t.octaves, t.omega, t.lambda, gen);
            std::array::from_fn(|k| qs[k].x + t.amount.x * ts[k])
        }
        _ => return None,
    };
    let mut out = [0.0; 4];
    for (o, v) in out.iter_mut().zip(raw) {
        *o = shape_inline(pat, v);
    }
    Some(out)
}

/// `value_warped` at four points (a normal's samples): the same values, with z² + c
/// fractals' orbits stepped together (`fractal2_lanes`).
pub fn values_warped4(pat: &Pattern, qs: &[DVec3; 4]) -> [f64; 4] {
    if let PatternKind::Fractal(f) = &pat.kind {
        if f.magnet != 0 {
            return magnet_lanes4(f, qs.map(|q| (q.x, q.y))).map(|v| shape(pat, v));
        }
        if f.exponent == 2 {
            let ps = qs.map(|q| (q.x, q.y));
            let raw = if f.interior.0 == 1 {
                fractal2_lanes4::<true>(f, ps)
            } else {
                fractal2_lanes4::<false>(f, ps)
            };
            return raw.map(|v| shape(pat, v));
        }
    }
    if let Some(vs) = noise_values4(pat, qs) {
        return vs;
    }
    // Gradient normals (normal maps of gradients, slope maps) read four samples of a dot
    // product: `raw`'s call and dispatch per sample cost more than the pattern. Radial's
    // samples, likewise, are `raw`'s angle and `shape`.
    // The points by coordinates (`by_coordinates`): `normal::slope` has just stored them as
    // x-y pairs and single coordinates, and the dot product's 16-byte y-z loads spanned two
    // of those stores, which the store buffer cannot forward (15 % of this function's
    // samples on normavg).
    let mut out = [0.0; 4];
    match &pat.kind {
        PatternKind::Gradient(a) => {
            for (o, q) in out.iter_mut().zip(qs) {
                *o = shape_inline(pat, gradient(by_coordinates(q), *a));
            }
        }
        PatternKind::Radial => {
            for (o, q) in out.iter_mut().zip(qs) {
                *o = shape_inline(pat, radial(by_coordinates(q)));
            }
        }
        // The distance patterns likewise (slopemap's onion normals): `raw`'s expressions.
        PatternKind::Onion => {
            for (o, q) in out.iter_mut().zip(qs) {
                *o = shape_inline(pat, fmod(by_coordinates(q).length(), 1.0));
            }
        }
        PatternKind::Spherical => {
            for (o, q) in out.iter_mut().zip(qs) {
                *o = shape_inline(pat, 1.0 - by_coordinates(q).length().min(1.0));
            }
        }
        PatternKind::Cylindrical => {
            for (o, q) in out.iter_mut().zip(qs) {
                *o = shape_inline(pat, 1.0 - (q.x * q.x + q.z * q.z).sqrt().min(1.0));
            }
        }
        _ => {
            for (o, &q) in out.iter_mut().zip(qs) {
                *o = value_warped(pat, q);
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::pattern::Wave;

    fn pat(kind: PatternKind) -> Pattern {
        Pattern::new(kind)
    }

    /// The noise patterns' four samples together are their values one at a time.
    #[test]
    fn noise_samples_together_are_the_values() {
        use crate::scene::pattern::Turbulence;
        let turb = Turbulence {
            amount: DVec3::new(0.7, 0.2, 0.1),
            ..Default::default()
        };
        let kinds = [
            PatternKind::Bozo,
            PatternKind::Spotted,
            PatternKind::Dents,
            PatternKind::Granite,
            PatternKind::Agate { turb: 1.6 },
            PatternKind::Marble,
            PatternKind::Wood,
            // Not noise, but with their own four-sample paths (`shape_inline`).
            PatternKind::Gradient(DVec3::new(0.3, 1.0, -0.7)),
            PatternKind::Radial,
            PatternKind::Onion,
            PatternKind::Spherical,
            PatternKind::Cylindrical,
        ];
        for kind in kinds {
            for (gen, turbulence, wave) in [
                (2, None, Wave::Ramp),
                (1, Some(turb), Wave::Sine),
                (3, Some(turb), Wave::Triangle),
            ] {
                let mut p = pat(kind.clone());
                (p.noise_generator, p.turbulence, p.wave) = (gen, turbulence, wave);
                p.frequency = 1.3;
                for n in 0..1500 {
                    let t = n as f64 * 0.71;
                    // Near the origin too (inside spherical's and cylindrical's unit
                    // distance), and far out (onion's remainders of big lengths).
                    let r = [0.2, 3.0, 4.0e5][n % 3];
                    let c = DVec3::new(t.sin() * r, t * 0.01, t.cos() * r - 0.1);
                    let qs = [0.0, 0.003, -0.004, 0.2].map(|d| c + DVec3::new(d, 2.0 * d, -d));
                    let want = qs.map(|q| value_warped(&p, q).to_bits());
                    assert_eq!(values_warped4(&p, &qs).map(f64::to_bits), want, "{kind:?}");
                }
            }
        }
    }
}
