//! Thin-film iridescence (`finish { irid { amount thickness t turbulence u } }`), measured
//! from the `povray` binary (docs/textures.md): each light's diffuse and highlight terms are
//! multiplied per channel by `1 + amount·cos(π·t′·(cos θ_light + cos θ_view)/λ)`, with
//! λ = 0.35, 0.26 and 0.24 for red, green and blue under the default `irid_wavelength`, and
//! t′ the thickness varied by the turbulence (ambient is not touched).

use crate::math::DVec3;
use crate::scene::desc::Irid;

use super::noise;

/// The wavelengths the phase divides by, for the default irid_wavelength <0.25, 0.18, 0.14>
/// (measured: the phase is exactly linear in thickness and in the cosines' sum).
const WAVELENGTHS: DVec3 = DVec3::new(0.35, 0.26, 0.24);

/// The per-channel factor on a light's diffuse term at world point `p`, for the cosines of
/// the light's and the viewer's angle to the normal. Never inlined: iridescence is rare, and
/// inlined into shading's per-layer closure (as a change of codegen units once did) it made
/// that closure ~0.8 M instructions dearer on wood_8 without any iridescence.
#[inline(never)]
pub fn factor(irid: &Irid, p: DVec3, cos_light: f64, cos_view: f64) -> DVec3 {
    // Measured: the turbulence's change is proportional to the thickness.
    let t = irid.thickness * (1.0 + irid.turbulence * thickness_noise(p));
    let phase = std::f64::consts::PI * t * (cos_light + cos_view);
    let wave = |l: f64| (phase / l).cos();
    DVec3::ONE
        + DVec3::new(
            wave(WAVELENGTHS.x),
            wave(WAVELENGTHS.y),
            wave(WAVELENGTHS.z),
        ) * irid.amount
}

/// How the turbulence varies the thickness (relative to it): a least-squares fit of what
/// povray does to five octaves of its noise (the thickness recovered per pixel from the three
/// channels on 64 pixels of a plane, residual up to 0.15); POV-Ray's own rule is not
/// recovered, and lancer warns about irid turbulence.
fn thickness_noise(p: DVec3) -> f64 {
    const WEIGHTS: [f64; 5] = [3.9203, 1.9997, 0.987, 0.5467, 0.2873];
    let mut sum = -2.93;
    let mut scale = 1.0;
    for w in WEIGHTS {
        sum += w * noise::noise(p * scale, 2);
        scale *= 2.0;
    }
    sum
}
