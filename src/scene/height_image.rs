//! Reading height_field images into 16-bit heights by POV-Ray's rules.
//!
//! Measured with povray 3.7's `trace` on uniform images, heights are a 16-bit value over 65536:
//! * 8-bit grey: v·257 (so 255 gives 65535/65536), except that povray reads a third of the
//!   values of a grey PNG without alpha one lower (see `GREY_PNG_LOSS`);
//! * 16-bit grey: v;
//! * palette images: the index·256, whatever the colours (the manual's rule);
//! * 8-bit colour (PNG, TGA, PPM, BMP, JPEG): red·256 + green, red the high byte;
//! * 16-bit and floating-point colour: the grey 0.297 r + 0.589 g + 0.114 b, as 16 bits;
//! * alpha is ignored;
//! * `gamma G` or `gamma srgb` after the file name decodes each channel first, then truncates
//!   it back to its bit depth.
//!
//! * GIF: the palette index·256; POT (Fractint's 16-bit GIFs): see `load_gif`.
//!
//! The data is linear by default, unlike image maps. PNG files are decoded with the `png`
//! crate and GIFs by `scene::gif` so palette indices survive; other formats through the `image`
//! crate.

use std::io::BufReader;
use std::path::Path;

/// Most pixels a height field image may have (8192 × 8192): each becomes two triangles.
pub const MAX_PIXELS: u64 = 1 << 26;

/// Which 8-bit values povray reads one lower from a grey PNG without alpha (bit v of the mask;
/// measured with `trace` on a 256-step ramp: 84 values are, in no pattern lancer could derive
/// from a formula; grey+alpha PNG, PGM and TGA files keep every value).
const GREY_PNG_LOSS: [u64; 4] = [
    0x64ad6908a3901468,
    0x9630e65194610840,
    0x4912140120421000,
    0x41962d88761c91a1,
];

fn grey_png_loss(v: u16) -> u16 {
    let v = v.min(255) as usize;
    ((GREY_PNG_LOSS[v / 64] >> (v % 64)) & 1) as u16
}

/// A `gamma` given after a height field's file name.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum HfGamma {
    Power(f64),
    Srgb,
}

impl HfGamma {
    fn decode(self, v: f64) -> f64 {
        match self {
            HfGamma::Power(g) => v.max(0.0).powf(g),
            HfGamma::Srgb => crate::scene::image::srgb_to_linear(v),
        }
    }

    /// A channel of `bits` bits decoded and truncated back to `bits` bits.
    fn channel(self, v: u16, bits: u32) -> u16 {
        let max = ((1u32 << bits) - 1) as f64;
        (self.decode(v as f64 / max) * max).floor().clamp(0.0, max) as u16
    }
}

/// An image's heights, row 0 at the top, and its size.
pub struct HeightImage {
    pub width: usize,
    pub height: usize,
    pub heights: Vec<u16>,
}

/// The weights are single-precision numbers in POV-Ray: with them in double precision white
/// gives 65535 where povray gives 65534.
fn grey16(r: f64, g: f64, b: f64) -> u16 {
    let v = 0.297f32 as f64 * r + 0.589f32 as f64 * g + 0.114f32 as f64 * b;
    (v.clamp(0.0, 1.0) * 65535.0).floor() as u16
}

fn check_size(w: u64, h: u64, path: &Path) -> Result<(), String> {
    if w * h > MAX_PIXELS {
        return Err(format!(
            "height field image {} is {w}×{h}; lancer takes at most {MAX_PIXELS} pixels",
            path.display()
        ));
    }
    if w < 2 || h < 2 {
        return Err(format!(
            "height field image {} is {w}×{h}; it needs at least 2×2 pixels",
            path.display()
        ));
    }
    Ok(())
}

/// The heights of an image file; `pot` reads a GIF as Fractint's POT format.
pub fn load_heights(path: &Path, gamma: Option<HfGamma>, pot: bool) -> Result<HeightImage, String> {
    let data = std::fs::read(path)
        .map_err(|e| format!("cannot read height field image {}: {e}", path.display()))?;
    if data.starts_with(b"\x89PNG") {
        load_png(path, gamma)
    } else if data.starts_with(b"GIF8") {
        load_gif(&data, path, pot)
    } else {
        load_other(path, gamma)
    }
}

/// GIF: the palette index·256. POT: a GIF twice as wide, the left half holding each height's
/// high byte and the right half its low byte.
fn load_gif(data: &[u8], path: &Path, pot: bool) -> Result<HeightImage, String> {
    let img = super::gif::decode(data, MAX_PIXELS)
        .map_err(|e| format!("cannot read GIF {}: {e}", path.display()))?;
    let (w, h) = (img.width, img.height);
    if !pot {
        check_size(w as u64, h as u64, path)?;
        let heights = img.pixels.iter().map(|&i| i as u16 * 256).collect();
        return Ok(HeightImage {
            width: w,
            height: h,
            heights,
        });
    }
    let half = w / 2;
    check_size(half as u64, h as u64, path)?;
    let mut heights = Vec::with_capacity(half * h);
    for y in 0..h {
        let row = &img.pixels[y * w..(y + 1) * w];
        heights.extend((0..half).map(|x| (row[x] as u16) << 8 | row[x + half] as u16));
    }
    Ok(HeightImage {
        width: half,
        height: h,
        heights,
    })
}

fn load_png(path: &Path, gamma: Option<HfGamma>) -> Result<HeightImage, String> {
    let err = |e: &dyn std::fmt::Display| format!("cannot read PNG {}: {e}", path.display());
    let file = std::fs::File::open(path).map_err(|e| err(&e))?;
    let mut dec = png::Decoder::new(BufReader::new(file));
    dec.set_transformations(png::Transformations::IDENTITY);
    let mut reader = dec.read_info().map_err(|e| err(&e))?;
    let (w, h) = reader.info().size();
    check_size(w as u64, h as u64, path)?;
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| err(&"image too large"))?;
    let mut buf = vec![0u8; size];
    let info = reader.next_frame(&mut buf).map_err(|e| err(&e))?;
    let bits = info.bit_depth as u32;
    let channels = info.color_type.samples();
    let (w, h) = (w as usize, h as usize);
    let mut heights = Vec::with_capacity(w * h);
    for y in 0..h {
        let row = &buf[y * info.line_size..(y + 1) * info.line_size];
        // Sample k of the row at this bit depth.
        let sample = |k: usize| -> u16 {
            match bits {
                16 => u16::from_be_bytes([row[2 * k], row[2 * k + 1]]),
                8 => row[k] as u16,
                b => {
                    let per = 8 / b as usize;
                    let byte = row[k / per];
                    let shift = 8 - b as usize * (k % per + 1);
                    ((byte >> shift) & ((1u8 << b) - 1)) as u16
                }
            }
        };
        for x in 0..w {
            let base = x * channels;
            let v = match info.color_type {
                png::ColorType::Indexed => sample(base) * 256,
                png::ColorType::Grayscale | png::ColorType::GrayscaleAlpha => {
                    let mut v = sample(base);
                    if bits < 8 {
                        v = v * 255 / ((1 << bits) - 1);
                    }
                    if bits == 8 && info.color_type == png::ColorType::Grayscale {
                        v -= grey_png_loss(v);
                    }
                    let b = bits.max(8);
                    if let Some(g) = gamma {
                        v = g.channel(v, b);
                    }
                    if b == 16 {
                        v
                    } else {
                        v * 257
                    }
                }
                png::ColorType::Rgb | png::ColorType::Rgba => {
                    let mut c = [sample(base), sample(base + 1), sample(base + 2)];
                    if let Some(g) = gamma {
                        c = c.map(|v| g.channel(v, bits));
                    }
                    if bits == 16 {
                        let f = |v: u16| v as f64 / 65535.0;
                        grey16(f(c[0]), f(c[1]), f(c[2]))
                    } else {
                        c[0] * 256 + c[1]
                    }
                }
            };
            heights.push(v);
        }
    }
    Ok(HeightImage {
        width: w,
        height: h,
        heights,
    })
}

fn load_other(path: &Path, gamma: Option<HfGamma>) -> Result<HeightImage, String> {
    use image::DynamicImage as D;
    let img = image::open(path)
        .map_err(|e| format!("cannot read height field image {}: {e}", path.display()))?;
    let (w, h) = (img.width() as usize, img.height() as usize);
    check_size(w as u64, h as u64, path)?;
    let g8 = |v: u8| gamma.map_or(v as u16, |g| g.channel(v as u16, 8));
    let g16 = |v: u16| gamma.map_or(v, |g| g.channel(v, 16));
    let heights: Vec<u16> = match &img {
        D::ImageLuma8(_) | D::ImageLumaA8(_) => {
            img.to_luma8().pixels().map(|p| g8(p.0[0]) * 257).collect()
        }
        D::ImageLuma16(_) | D::ImageLumaA16(_) => {
            img.to_luma16().pixels().map(|p| g16(p.0[0])).collect()
        }
        D::ImageRgb8(_) | D::ImageRgba8(_) => img
            .to_rgb8()
            .pixels()
            .map(|p| g8(p.0[0]) * 256 + g8(p.0[1]))
            .collect(),
        D::ImageRgb16(_) | D::ImageRgba16(_) => img
            .to_rgb16()
            .pixels()
            .map(|p| {
                let f = |v: u16| g16(v) as f64 / 65535.0;
                grey16(f(p.0[0]), f(p.0[1]), f(p.0[2]))
            })
            .collect(),
        _ => img
            .to_rgb32f()
            .pixels()
            .map(|p| {
                let f = |v: f32| gamma.map_or(v as f64, |g| g.decode(v as f64));
                grey16(f(p.0[0]), f(p.0[1]), f(p.0[2]))
            })
            .collect(),
    };
    Ok(HeightImage {
        width: w,
        height: h,
        heights,
    })
}
