//! Loading image files for `image_map`, decoded to linear light as POV-Ray 3.7 does.

use std::path::Path;

use crate::color::Rgbft;
use crate::scene::desc::ImageMap;

/// sRGB transfer function to linear; PNGs without a gAMA chunk are taken as sRGB, as POV-Ray 3.7
/// does for 8-bit and 16-bit PNG image maps.
pub fn srgb_to_linear(c: f64) -> f64 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

pub fn load_image_map(path: &Path, map: &mut ImageMap) -> Result<(), String> {
    let img =
        image::open(path).map_err(|e| format!("cannot read image {}: {e}", path.display()))?;
    let is_float = matches!(
        img,
        image::DynamicImage::ImageRgb32F(_) | image::DynamicImage::ImageRgba32F(_)
    );
    let has_alpha = img.color().has_alpha();
    let rgba = img.to_rgba32f();
    map.width = rgba.width();
    map.height = rgba.height();
    map.pixels = rgba
        .pixels()
        .map(|p| {
            let lin = |v: f32| {
                if is_float {
                    v as f64
                } else {
                    srgb_to_linear(v as f64)
                }
            };
            // POV-Ray maps alpha to transmit (1 - alpha).
            let t = if has_alpha { 1.0 - p.0[3] as f64 } else { 0.0 };
            Rgbft::new(lin(p.0[0]), lin(p.0[1]), lin(p.0[2]), 0.0, t)
        })
        .collect();
    Ok(())
}
