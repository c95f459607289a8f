//! Loading image files for `image_map`, decoded to linear light as POV-Ray 3.7 does.

use std::path::Path;

use crate::color::Rgbft;
use crate::scene::desc::ImageMap;
use crate::scene::image_pixels::ImagePixels;

/// sRGB transfer function to linear; PNGs without a gAMA chunk are taken as sRGB, as POV-Ray 3.7
/// does for 8-bit and 16-bit PNG image maps.
pub fn srgb_to_linear(c: f64) -> f64 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// Linear back to the sRGB-encoded value (image patterns read the file's own values).
pub fn linear_to_srgb(c: f64) -> f64 {
    if c <= 0.0031308 {
        c * 12.92
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    }
}

/// Re-encodes a loaded image's pixels to the values stored in the file, for `image_pattern`
/// (measured: POV-Ray's value is the grey of the raw 8-bit values, 128 giving 0.502). Float
/// images (EXR, HDR) are stored linear and stay so.
pub fn to_file_values(map: &mut ImageMap) {
    let float = map
        .path
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("exr") || e.eq_ignore_ascii_case("hdr"));
    if float {
        return;
    }
    map.pixels.map_values(|p| {
        p.rgb = crate::math::DVec3::new(
            linear_to_srgb(p.rgb.x),
            linear_to_srgb(p.rgb.y),
            linear_to_srgb(p.rgb.z),
        )
    });
}

pub fn load_image_map(path: &Path, map: &mut ImageMap) -> Result<(), String> {
    let img =
        image::open(path).map_err(|e| format!("cannot read image {}: {e}", path.display()))?;
    let has_alpha = img.color().has_alpha();
    map.width = img.width();
    map.height = img.height();
    // POV-Ray maps alpha to transmit (1 - alpha).
    let transmit = |a: f64| if has_alpha { 1.0 - a } else { 0.0 };
    let n = img.width() as usize * img.height() as usize;
    map.pixels = match &img {
        image::DynamicImage::ImageRgb32F(_) | image::DynamicImage::ImageRgba32F(_) => {
            ImagePixels::from_vec(
                img.to_rgba32f()
                    .pixels()
                    .map(|p| {
                        Rgbft::new(
                            p.0[0] as f64,
                            p.0[1] as f64,
                            p.0[2] as f64,
                            0.0,
                            transmit(p.0[3] as f64),
                        )
                    })
                    .collect(),
            )
        }
        _ if img.color().bytes_per_pixel() / img.color().channel_count() == 1 => {
            // 8-bit images: decode through a table instead of a powf per channel.
            let lut: Vec<f64> = (0..256).map(|i| srgb_to_linear(i as f64 / 255.0)).collect();
            let rgba = img.to_rgba8();
            ImagePixels::from_keys(n, rgba.pixels().map(|p| p.0), |p| {
                Rgbft::new(
                    lut[p[0] as usize],
                    lut[p[1] as usize],
                    lut[p[2] as usize],
                    0.0,
                    transmit(p[3] as f64 / 255.0),
                )
            })
        }
        _ => {
            let rgba = img.to_rgba32f();
            // Keyed by the samples' bits: equal samples decode alike.
            let keys = rgba.pixels().map(|p| p.0.map(f32::to_bits));
            ImagePixels::from_keys(n, keys, |k| {
                let p = k.map(f32::from_bits);
                Rgbft::new(
                    srgb_to_linear(p[0] as f64),
                    srgb_to_linear(p[1] as f64),
                    srgb_to_linear(p[2] as f64),
                    0.0,
                    transmit(p[3] as f64),
                )
            })
        }
    };
    Ok(())
}

/// The palette index of every pixel of an indexed PNG or a GIF (row 0 at the top), for
/// `filter N, v` / `transmit N, v` on an image map; None for images without a palette.
pub fn palette_indices(path: &Path) -> Option<Vec<u8>> {
    let data = std::fs::read(path).ok()?;
    if data.starts_with(b"GIF8") {
        return super::gif::decode(&data, 1 << 28)
            .ok()
            .map(|img| img.pixels);
    }
    let mut dec = png::Decoder::new(std::io::Cursor::new(&data));
    dec.set_transformations(png::Transformations::IDENTITY);
    let mut reader = dec.read_info().ok()?;
    let mut buf = vec![0u8; reader.output_buffer_size()?];
    let info = reader.next_frame(&mut buf).ok()?;
    if info.color_type != png::ColorType::Indexed {
        return None;
    }
    let bits = info.bit_depth as usize;
    let per = 8 / bits;
    let (w, h) = (info.width as usize, info.height as usize);
    let mut out = Vec::with_capacity(w * h);
    for y in 0..h {
        let row = &buf[y * info.line_size..(y + 1) * info.line_size];
        out.extend((0..w).map(|x| {
            let byte = row[x / per];
            let shift = 8 - bits * (x % per + 1);
            (byte >> shift) & ((1u16 << bits) - 1) as u8
        }));
    }
    Some(out)
}
