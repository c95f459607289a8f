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

    fn of(gamma: GammaMode, spec: &OutputSpec) -> Curve {
        match (gamma, spec.file_gamma) {
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

/// Linear light of one working-space channel in a picture of `gamma` (`Film::linear`).
fn linear_of(gamma: GammaMode, v: f64) -> f64 {
    match gamma {
        GammaMode::Corrected(g) if g != 1.0 => v.max(0.0).powf(g),
        GammaMode::Corrected(_) => v.max(0.0),
        GammaMode::None => v,
    }
}

/// How the samples of one picture are made from its pixels, one pixel at a time and in any
/// order: what `quantise` does without dithering, and what a render without anti-aliasing
/// does as each pixel is traced (`render::render_quantised`), so that picture needs no film.
pub(crate) struct Quantiser {
    gamma: GammaMode,
    curve: Curve,
    max: f64,
    bits: u32,
    /// 4 with alpha (straight colour, alpha last), else 3 (the colour over black).
    pub channels: usize,
    /// The table of a colour channel's steps (output::steps), on big 8-bit pictures.
    steps: Option<Steps>,
}

impl Quantiser {
    /// For a `pixels`-pixel picture of `gamma` written as `spec` says, with an alpha channel
    /// when `alpha`; None when `spec` dithers (that needs the whole picture).
    pub fn new(gamma: GammaMode, spec: &OutputSpec, alpha: bool, pixels: usize) -> Option<Self> {
        if spec.effective_dither().is_some() {
            return None;
        }
        let bits = spec.effective_bits();
        let max = ((1u32 << bits) - 1) as f64;
        let curve = Curve::of(gamma, spec);
        // A colour channel's sample as a function of its film value (after the division
        // by alpha), two `powf` each; a table of its steps replaces them on big 8-bit
        // pictures (output::steps).
        let q = |v: f64| (curve.encode(linear_of(gamma, v)) * max + 0.5).floor() as u16;
        // Where q steps to k, roughly: the curves' inverses at k − ½.
        let guess = |k: u16| {
            let l = curve.decode((k as f64 - 0.5) / max);
            match gamma {
                GammaMode::Corrected(g) if g != 1.0 => l.powf(1.0 / g),
                _ => l,
            }
        };
        let steps = if bits <= 8 && pixels >= STEPS_MIN_PIXELS {
            Steps::new_near(q, guess, max as u16)
        } else {
            None
        };
        Some(Quantiser {
            gamma,
            curve,
            max,
            bits,
            channels: if alpha { 4 } else { 3 },
            steps,
        })
    }

    /// An empty plane of `width`×`height` pixels for `put` to fill.
    pub fn plane(&self, width: u32, height: u32) -> Plane {
        Plane {
            width,
            height,
            channels: self.channels,
            bits: self.bits,
            data: vec![0u16; width as usize * height as usize * self.channels],
        }
    }

    /// The samples of one pixel, `r`, `g`, `b` its film colour and `coverage` its opacity
    /// (read only with alpha), into `px` (`channels` long).
    /// The colour comes as three numbers, not a `DVec3`: passed in memory, its `y` and `z`
    /// were read with one 16-byte load from the tracer's two 8-byte stores just made, a
    /// store-forwarding stall on every pixel (a third of this function's time).
    /// `inline(always)`: with a plain `#[inline]` the thirty-sixth pass's merged build called
    /// it out of line, once a pixel (2.4 % of language/arrays/array1.pov, ~3 % of the short
    /// scenes).
    #[inline(always)]
    pub fn put(&self, r: f64, g: f64, b: f64, coverage: f64, px: &mut [u16]) {
        // Nearly every picture's pixels: three table lookups. Apart, so that this path does
        // not pay for the other's frame (five registers saved, 80 bytes of stack).
        if let (Some(steps), 3) = (&self.steps, self.channels) {
            px[..3].copy_from_slice(&steps.q3([r, g, b]));
            return;
        }
        self.put_other(r, g, b, coverage, px);
    }

    /// `put` with an alpha channel or without a table.
    #[inline(never)]
    fn put_other(&self, r: f64, g: f64, b: f64, coverage: f64, px: &mut [u16]) {
        let rgb = DVec3::new(r, g, b);
        let alpha = self.channels == 4;
        let max = self.max;
        if let Some(steps) = &self.steps {
            // `linear_rgb` before the channels' transfer to linear light: what `Steps` takes.
            // Where nothing is opaque, zero (which every curve takes to linear zero, as
            // `linear_rgb` gives).
            let v = if !alpha {
                rgb
            } else if coverage <= 0.0 {
                DVec3::ZERO
            } else {
                rgb / coverage
            };
            px[0] = steps.q(v.x);
            px[1] = steps.q(v.y);
            px[2] = steps.q(v.z);
        } else {
            let [r, g, b] = self.linear_rgb(rgb, coverage);
            for (c, l) in [r, g, b].into_iter().enumerate() {
                px[c] = (self.curve.encode(l) * max + 0.5).floor() as u16;
            }
        }
        if alpha {
            // Alpha is stored as it is, not through the colour's curve.
            let a = Curve::Identity.encode(coverage);
            px[3] = (a * max + 0.5).floor() as u16;
        }
    }

    /// Linear light of a pixel: straight (divided by its alpha; black where nothing is
    /// opaque) with alpha, else the colour over black.
    fn linear_rgb(&self, mut v: DVec3, coverage: f64) -> [f64; 3] {
        if self.channels == 4 {
            if coverage <= 0.0 {
                return [0.0; 3];
            }
            v /= coverage;
        }
        let g = self.gamma;
        [linear_of(g, v.x), linear_of(g, v.y), linear_of(g, v.z)]
    }
}

/// The samples of `film` for `spec`, with an alpha channel when `alpha` (straight colour).
pub(crate) fn quantise(film: &Film, spec: &OutputSpec, alpha: bool) -> Plane {
    let alpha = alpha && film.alpha.is_some();
    let n = film.pixels.len();
    let coverage = |i: usize| film.alpha.as_ref().map_or(1.0, |a| a[i]);
    // Each pixel on its own, straight into the file's samples: the two whole-picture
    // buffers in between cost more in page faults than the arithmetic (a 512x512
    // picture: 10 MB).
    if let Some(q) = Quantiser::new(film.gamma, spec, alpha, n) {
        let mut plane = q.plane(film.width, film.height);
        let row = film.width as usize * q.channels;
        plane
            .data
            .par_chunks_mut(row.max(1))
            .enumerate()
            .for_each(|(y, out)| {
                for (x, px) in out.chunks_exact_mut(q.channels).enumerate() {
                    let i = y * film.width as usize + x;
                    let v = film.pixels[i];
                    q.put(v.x, v.y, v.z, coverage(i), px);
                }
            });
        return plane;
    }
    let bits = spec.effective_bits();
    let max = ((1u32 << bits) - 1) as f64;
    let curve = Curve::of(film.gamma, spec);
    let channels = if alpha { 4 } else { 3 };
    // Alpha is stored as it is, not through the colour's curve.
    let curves = [curve, curve, curve, Curve::Identity];
    let m = spec
        .effective_dither()
        .expect("Quantiser::new declines only dithering");
    let lin: Vec<dither::Px> = (0..n)
        .into_par_iter()
        .map(|i| {
            let [r, g, b] = linear_rgb(film, i, alpha);
            [r, g, b, coverage(i)]
        })
        .collect();
    let samples = dither::quantise(&lin, film.width as usize, max, curves, m);
    Plane {
        width: film.width,
        height: film.height,
        channels,
        bits,
        data: samples
            .iter()
            .flat_map(|px| px[..channels].iter().copied())
            .collect(),
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

pub(crate) fn png_gamma(gamma: GammaMode, spec: &OutputSpec) -> PngGamma {
    match Curve::of(gamma, spec) {
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
pub(crate) fn display_gamma(gamma: GammaMode, spec: &OutputSpec) -> f64 {
    match Curve::of(gamma, spec) {
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
        assert_eq!(png_gamma(f.gamma, &spec).gama, 100000);
        spec.file_gamma = FileGamma::Power(1.8);
        assert_eq!(png_gamma(f.gamma, &spec).gama, 55556);
        f.gamma = GammaMode::None;
        let g = png_gamma(f.gamma, &spec);
        assert!(g.srgb && g.gama == 45455);
        assert_eq!(quantise(&f, &spec, false).data[0], 51);
    }
}
