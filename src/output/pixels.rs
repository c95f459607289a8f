//! From a film to the integer samples a file holds: which colour goes in (straight colour
//! beside an alpha channel, the colour over black without one), the transfer curve
//! (`File_Gamma`), and quantisation as POV-Ray does it: q = floor(e·(2ⁿ−1) + 0.5) of the
//! clipped encoded value e, unless dithering says otherwise.

use rayon::prelude::*;

use super::dither;
use super::steps::Steps;
use super::{FileGamma, OutputSpec};
use crate::math::DVec3;
use crate::render::{srgb_encode, Film};
use crate::scene::build::GammaMode;

/// The transfer from linear light in [0, 1] to the encoded value an integer file stores.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Curve {
    /// Scenes without gamma handling (`#version` below 3.7 and no `assumed_gamma`): POV-Ray
    /// writes their working values as they are, whatever `File_Gamma` says (checked).
    Identity,
    Srgb,
    Power(f64),
}

impl Curve {
    pub fn encode(self, l: f64) -> f64 {
        let l = l.clamp(0.0, 1.0);
        match self {
            Curve::Identity => l,
            Curve::Srgb => srgb_encode(l),
            Curve::Power(g) => l.powf(1.0 / g),
        }
    }

    pub fn decode(self, e: f64) -> f64 {
        match self {
            Curve::Identity => e,
            Curve::Srgb if e <= 0.04045 => e / 12.92,
            Curve::Srgb => ((e + 0.055) / 1.055).powf(2.4),
            Curve::Power(g) => e.powf(g),
        }
    }

    fn of(film: &Film, spec: &OutputSpec) -> Curve {
        match (film.gamma, spec.file_gamma) {
            (GammaMode::None, _) => Curve::Identity,
            (_, FileGamma::Srgb) => Curve::Srgb,
            (_, FileGamma::Power(g)) => Curve::Power(g),
        }
    }
}

/// Quantised samples in file order: `channels` per pixel (3, or 4 with alpha last), each in
/// 0..=2^bits − 1.
pub(crate) struct Plane {
    pub width: u32,
    pub height: u32,
    pub channels: usize,
    pub bits: u32,
    pub data: Vec<u16>,
}

impl Plane {
    /// One pixel's samples.
    pub fn pixel(&self, x: u32, y: u32) -> &[u16] {
        let i = (y as usize * self.width as usize + x as usize) * self.channels;
        &self.data[i..i + self.channels]
    }
}

/// Linear light of pixel `i`: straight (divided by its alpha; black where nothing is opaque)
/// when `straight`, else the colour over black.
pub(crate) fn linear_rgb(film: &Film, i: usize, straight: bool) -> [f64; 3] {
    let mut v = film.pixels[i];
    if straight {
        if let Some(alpha) = &film.alpha {
            let a = alpha[i];
            if a <= 0.0 {
                return [0.0; 3];
            }
            v /= a;
        }
    }
    [film.linear(v.x), film.linear(v.y), film.linear(v.z)]
}

/// Pictures with fewer pixels compute each sample directly: the table's ~25,000 evaluations
/// of the curve would cost more than it saves.
const STEPS_MIN_PIXELS: usize = 16 * 1024;

/// `linear_rgb` before the channels' transfer to linear light: what `Steps` takes. Where
/// nothing is opaque, zero (which every curve takes to linear zero, as `linear_rgb` gives).
fn film_value(film: &Film, i: usize, straight: bool) -> DVec3 {
    let v = film.pixels[i];
    if straight {
        if let Some(alpha) = &film.alpha {
            let a = alpha[i];
            if a <= 0.0 {
                return DVec3::ZERO;
            }
            return v / a;
        }
    }
    v
}

/// The samples of `film` for `spec`, with an alpha channel when `alpha` (straight colour).
pub(crate) fn quantise(film: &Film, spec: &OutputSpec, alpha: bool) -> Plane {
    let alpha = alpha && film.alpha.is_some();
    let bits = spec.effective_bits();
    let max = ((1u32 << bits) - 1) as f64;
    let curve = Curve::of(film, spec);
    let n = film.pixels.len();
    let channels = if alpha { 4 } else { 3 };
    let coverage = |i: usize| film.alpha.as_ref().map_or(1.0, |a| a[i]);
    // Alpha is stored as it is, not through the colour's curve.
    let curves = [curve, curve, curve, Curve::Identity];
    let data = match spec.effective_dither() {
        // Each pixel on its own, straight into the file's samples: the two whole-picture
        // buffers in between cost more in page faults than the arithmetic (a 512x512
        // picture: 10 MB).
        None => {
            let row = film.width as usize * channels;
            let mut data = vec![0u16; n * channels];
            // A colour channel's sample as a function of its film value (after the division
            // by alpha), two `powf` each; a table of its steps replaces them on big 8-bit
            // pictures (output::steps).
            let q = |v: f64| (curve.encode(film.linear(v)) * max + 0.5).floor() as u16;
            // Where q steps to k, roughly: the curves' inverses at k − ½.
            let guess = |k: u16| {
                let l = curve.decode((k as f64 - 0.5) / max);
                match film.gamma {
                    GammaMode::Corrected(g) if g != 1.0 => l.powf(1.0 / g),
                    _ => l,
                }
            };
            let steps = if bits <= 8 && n >= STEPS_MIN_PIXELS {
                Steps::new_near(q, guess, max as u16)
            } else {
                None
            };
            data.par_chunks_mut(row.max(1))
                .enumerate()
                .for_each(|(y, out)| {
                    for (x, px) in out.chunks_exact_mut(channels).enumerate() {
                        let i = y * film.width as usize + x;
                        if let Some(steps) = &steps {
                            let v = film_value(film, i, alpha);
                            px[0] = steps.q(v.x);
                            px[1] = steps.q(v.y);
                            px[2] = steps.q(v.z);
                        } else {
                            let [r, g, b] = linear_rgb(film, i, alpha);
                            for (c, l) in [r, g, b].into_iter().enumerate() {
                                px[c] = (curve.encode(l) * max + 0.5).floor() as u16;
                            }
                        }
                        if channels == 4 {
                            // Alpha is stored as it is, not through the colour's curve.
                            let a = Curve::Identity.encode(coverage(i));
                            px[3] = (a * max + 0.5).floor() as u16;
                        }
                    }
                });
            data
        }
        Some(m) => {
            let lin: Vec<dither::Px> = (0..n)
                .into_par_iter()
                .map(|i| {
                    let [r, g, b] = linear_rgb(film, i, alpha);
                    [r, g, b, coverage(i)]
                })
                .collect();
            let samples = dither::quantise(&lin, film.width as usize, max, curves, m);
            samples
                .iter()
                .flat_map(|px| px[..channels].iter().copied())
                .collect()
        }
    };
    Plane {
        width: film.width,
        height: film.height,
        channels,
        bits,
        data,
    }
}

/// What a PNG says about its encoding: the gAMA value (100000 / gamma, rounded) and whether
/// an sRGB chunk goes with it. POV-Ray writes 45455 with the sRGB chunk for sRGB and for
/// scenes without gamma handling, and the power's own gAMA otherwise (checked with 1.0, 1.8
/// and 2.2).
pub(crate) struct PngGamma {
    pub gama: u32,
    pub srgb: bool,
}

pub(crate) fn png_gamma(film: &Film, spec: &OutputSpec) -> PngGamma {
    match Curve::of(film, spec) {
        Curve::Power(g) => PngGamma {
            gama: (100000.0 / g).round() as u32,
            srgb: false,
        },
        _ => PngGamma {
            gama: 45455,
            srgb: true,
        },
    }
}

/// The display gamma a Targa file records: 2.2 stands for sRGB, as in POV-Ray's files.
pub(crate) fn display_gamma(film: &Film, spec: &OutputSpec) -> f64 {
    match Curve::of(film, spec) {
        Curve::Power(g) => g,
        _ => 2.2,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::DVec3;

    pub(crate) fn film(pixels: Vec<DVec3>, alpha: Option<Vec<f64>>, w: u32) -> Film {
        let h = pixels.len() as u32 / w;
        Film {
            width: w,
            height: h,
            pixels,
            alpha,
            gamma: GammaMode::Corrected(1.0),
            rays: 0,
            camera_rays: 0,
        }
    }

    #[test]
    fn curves_round_trip() {
        for c in [
            Curve::Identity,
            Curve::Srgb,
            Curve::Power(2.2),
            Curve::Power(1.0),
        ] {
            for l in [0.0, 0.001, 0.2, 0.5, 1.0] {
                assert!((c.decode(c.encode(l)) - l).abs() < 1e-12, "{c:?} {l}");
            }
        }
        assert!((Curve::Srgb.encode(2.0) - 1.0).abs() < 1e-12);
        assert_eq!(Curve::Power(2.2).encode(-1.0), 0.0);
    }

    #[test]
    fn quantisation_matches_povray_samples() {
        // POV-Ray's +UA PNG of background rgbt <0.2,0.3,0.5,0.5>: [124 149 188 128], and a
        // fully transparent pixel [0 0 0 0]; the same pixel at 5 and 12 bits (before the bit
        // replication the PNG writer adds): 123>>3, 3969 = 31751>>4.
        let f = film(
            vec![DVec3::new(0.1, 0.15, 0.25), DVec3::ZERO],
            Some(vec![0.5, 0.0]),
            2,
        );
        let mut spec = OutputSpec::default();
        let p = quantise(&f, &spec, true);
        assert_eq!(p.data, vec![124, 149, 188, 128, 0, 0, 0, 0]);
        spec.set_bits(5);
        assert_eq!(quantise(&f, &spec, true).pixel(0, 0), &[15, 18, 23, 16]);
        spec.set_bits(12);
        assert_eq!(quantise(&f, &spec, true).pixel(0, 0)[0], 31751 >> 4);
        // Without alpha the colour over black goes in.
        spec.set_bits(8);
        assert_eq!(quantise(&f, &spec, false).pixel(0, 0), &[89, 108, 137]);
    }

    #[test]
    fn file_gamma_power_and_legacy_scenes() {
        let mut f = film(vec![DVec3::splat(0.2)], None, 1);
        let mut spec = OutputSpec {
            file_gamma: FileGamma::Power(1.0),
            ..OutputSpec::default()
        };
        assert_eq!(quantise(&f, &spec, false).data[0], 51);
        assert_eq!(png_gamma(&f, &spec).gama, 100000);
        spec.file_gamma = FileGamma::Power(1.8);
        assert_eq!(png_gamma(&f, &spec).gama, 55556);
        f.gamma = GammaMode::None;
        let g = png_gamma(&f, &spec);
        assert!(g.srgb && g.gama == 45455);
        assert_eq!(quantise(&f, &spec, false).data[0], 51);
    }
}
