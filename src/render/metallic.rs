//! POV-Ray's `metallic` fade: a metallic highlight or reflection takes the surface's colour
//! head-on and turns back towards the light's colour at glancing angles (the manual: "the
//! colour of the light is reflected at glancing angles"). The tint is
//! `1 + metallic·(1 − k(θ))·(colour − 1)`, with θ the angle between the normal and the light
//! for highlights (phong and specular alike) and between the normal and the ray for
//! reflection; both use the same k (measured: docs/textures.md).
//!
//! k is a table measured from the `povray` binary by scripts/measure_metallic.py (its
//! reflection column, every half degree from 0 to 89.5; 16-bit renders, so within about
//! 2e-5), read by linear interpolation and run out to 1 at 90°.

use crate::math::DVec3;

/// k at 0°, 0.5°, ..., 89.5° (scripts/measure_metallic.py).
const FADE: [f64; 180] = [
    0.000000, 0.000122, 0.000229, 0.000351, 0.000473, 0.000595, 0.000717, 0.000855, 0.000977,
    0.001114, 0.001239, 0.001373, 0.001511, 0.001654, 0.001801, 0.001938, 0.002090, 0.002241,
    0.002386, 0.002546, 0.002701, 0.002853, 0.003021, 0.003189, 0.003347, 0.003525, 0.003693,
    0.003868, 0.004044, 0.004227, 0.004410, 0.004604, 0.004796, 0.004990, 0.005188, 0.005396,
    0.005598, 0.005814, 0.006027, 0.006241, 0.006455, 0.006683, 0.006917, 0.007155, 0.007390,
    0.007630, 0.007886, 0.008133, 0.008392, 0.008652, 0.008927, 0.009201, 0.009476, 0.009762,
    0.010054, 0.010346, 0.010649, 0.010965, 0.011276, 0.011597, 0.011933, 0.012268, 0.012607,
    0.012955, 0.013317, 0.013676, 0.014054, 0.014435, 0.014829, 0.015224, 0.015646, 0.016066,
    0.016483, 0.016928, 0.017370, 0.017840, 0.018307, 0.018787, 0.019278, 0.019783, 0.020303,
    0.020842, 0.021384, 0.021937, 0.022513, 0.023103, 0.023703, 0.024326, 0.024959, 0.025615,
    0.026280, 0.026969, 0.027682, 0.028404, 0.029149, 0.029918, 0.030711, 0.031527, 0.032367,
    0.033229, 0.034109, 0.035024, 0.035959, 0.036929, 0.037934, 0.038969, 0.040032, 0.041126,
    0.042260, 0.043429, 0.044643, 0.045889, 0.047180, 0.048514, 0.049898, 0.051324, 0.052800,
    0.054331, 0.055911, 0.057561, 0.059270, 0.061045, 0.062880, 0.064783, 0.066764, 0.068825,
    0.070966, 0.073200, 0.075513, 0.077931, 0.080455, 0.083075, 0.085813, 0.088678, 0.091670,
    0.094791, 0.098066, 0.101485, 0.105064, 0.108822, 0.112774, 0.116903, 0.121256, 0.125827,
    0.130652, 0.135718, 0.141064, 0.146712, 0.152671, 0.158974, 0.165659, 0.172720, 0.180242,
    0.188217, 0.196699, 0.205729, 0.215369, 0.225666, 0.236666, 0.248466, 0.261125, 0.274730,
    0.289371, 0.305159, 0.322233, 0.340730, 0.360794, 0.382641, 0.406452, 0.432496, 0.461051,
    0.492439, 0.527074, 0.565405, 0.607978, 0.655440, 0.708569, 0.768310, 0.835802, 0.912454,
];

/// k for a unit normal and a unit direction (towards the light, or back along the ray) whose
/// cosine is `cos`.
pub fn fade(cos: f64) -> f64 {
    let deg = cos.clamp(0.0, 1.0).acos().to_degrees();
    let x = deg * 2.0;
    let i = (x.floor() as usize).min(179);
    let t = x - i as f64;
    let next = if i + 1 < 180 { FADE[i + 1] } else { 1.0 };
    (FADE[i] + (next - FADE[i]) * t).clamp(0.0, 1.0)
}

/// The colour a metallic highlight or reflection is multiplied by.
pub fn tint(colour: DVec3, metallic: f64, cos: f64) -> DVec3 {
    if metallic == 0.0 {
        return DVec3::ONE;
    }
    DVec3::ONE + (colour - DVec3::ONE) * (metallic * (1.0 - fade(cos)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn head_on_is_the_colour_and_grazing_is_white() {
        let c = DVec3::new(1.0, 0.2, 0.0);
        assert!((tint(c, 1.0, 1.0) - c).length() < 1e-12);
        assert!((tint(c, 1.0, 0.0) - DVec3::ONE).length() < 1e-12);
        assert_eq!(tint(c, 0.0, 0.3), DVec3::ONE);
        // povray's blue at 60° (scripts/measure_metallic.py): 0.05927.
        assert!((fade(0.5) - 0.05927).abs() < 1e-4);
    }
}
