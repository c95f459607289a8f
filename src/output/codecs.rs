//! The formats left to the `image` crate: JPEG (lossy; its encoder does not subsample
//! chroma, which is also what POV-Ray 3.7 does), Radiance HDR (RGBE with the mantissas
//! truncated, as Ward's reference code and POV-Ray do) and OpenEXR. The floating-point two
//! hold linear light, unclipped; EXR alpha is associated (premultiplied) as its
//! specification and POV-Ray have it.

use std::io::Write;
use std::path::Path;

use image::ImageEncoder;

use super::pixels::{linear_rgb, Plane};
use crate::render::Film;

pub(crate) fn write_jpeg(plane: &Plane, quality: u8, mut out: impl Write) -> Result<(), String> {
    let rgb: Vec<u8> = plane.data.iter().map(|&q| q as u8).collect();
    image::codecs::jpeg::JpegEncoder::new_with_quality(&mut out, quality)
        .write_image(
            &rgb,
            plane.width,
            plane.height,
            image::ExtendedColorType::Rgb8,
        )
        .map_err(|e| e.to_string())?;
    out.flush().map_err(|e| e.to_string())
}

/// The colour over black, as POV-Ray writes an HDR file when alpha was asked for.
pub(crate) fn write_hdr(film: &Film, mut out: impl Write) -> Result<(), String> {
    let rgb: Vec<image::Rgb<f32>> = (0..film.pixels.len())
        .map(|i| image::Rgb(linear_rgb(film, i, false).map(|c| c as f32)))
        .collect();
    image::codecs::hdr::HdrEncoder::new(&mut out)
        .encode(&rgb, film.width as usize, film.height as usize)
        .map_err(|e| e.to_string())?;
    out.flush().map_err(|e| e.to_string())
}

pub(crate) fn write_exr(film: &Film, alpha: bool, tmp: &Path) -> Result<(), String> {
    let (w, h) = (film.width, film.height);
    let img = match film.alpha.as_ref().filter(|_| alpha) {
        Some(a) => {
            // Straight linear light times alpha: the same as the film's premultiplied colour
            // when the scene works in linear light, and right too when it does not.
            let data: Vec<f32> = (0..film.pixels.len())
                .flat_map(|i| {
                    let l = linear_rgb(film, i, true);
                    [l[0] * a[i], l[1] * a[i], l[2] * a[i], a[i]].map(|c| c as f32)
                })
                .collect();
            image::DynamicImage::ImageRgba32F(
                image::Rgba32FImage::from_raw(w, h, data).ok_or("bad film size")?,
            )
        }
        None => {
            let data: Vec<f32> = (0..film.pixels.len())
                .flat_map(|i| linear_rgb(film, i, false).map(|c| c as f32))
                .collect();
            image::DynamicImage::ImageRgb32F(
                image::Rgb32FImage::from_raw(w, h, data).ok_or("bad film size")?,
            )
        }
    };
    img.save_with_format(tmp, image::ImageFormat::OpenExr)
        .map_err(|e| e.to_string())
}
