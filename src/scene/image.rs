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
    if let Some(indexed) = IndexedPng::read(path) {
        let lut = srgb_lut();
        let has_alpha = indexed.has_alpha;
        map.width = indexed.width;
        map.height = indexed.height;
        map.pixels = ImagePixels::from_indices(indexed.indices, |i| {
            let p = indexed.rgba[i as usize];
            Rgbft::new(
                lut[p[0] as usize],
                lut[p[1] as usize],
                lut[p[2] as usize],
                0.0,
                if has_alpha {
                    1.0 - p[3] as f64 / 255.0
                } else {
                    0.0
                },
            )
        });
        return Ok(());
    }
    load_decoded(path, map)
}

/// `load_image_map` through the image crate's decode, for every file but palette PNGs.
fn load_decoded(path: &Path, map: &mut ImageMap) -> Result<(), String> {
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
            let lut = srgb_lut();
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

/// An 8-bit sample's linear value, for every sample.
fn srgb_lut() -> Vec<f64> {
    (0..256).map(|i| srgb_to_linear(i as f64 / 255.0)).collect()
}

/// A palette PNG read as its indices and palette, not expanded to RGBA pixels: the image
/// crate's decode wrote 3 or 4 bytes a pixel and `to_rgba8` copied them again, and each
/// pixel was then hashed as a 4-byte key (a 320x200 map: ~0.5 MB of fresh pages and 64,000
/// lookups for at most 256 colours).
struct IndexedPng {
    width: u32,
    height: u32,
    /// What the image crate reports: a tRNS chunk makes the expanded pixels RGBA.
    has_alpha: bool,
    /// Each index's expanded pixel, as the png crate's expansion gives it.
    rgba: [[u8; 4]; 256],
    /// Row-major, row 0 at the top.
    indices: Vec<u8>,
}

impl IndexedPng {
    /// None for anything but a readable palette PNG named `.png` (which `image::open`
    /// decodes as PNG), and for a palette PNG with an index past its palette: those take
    /// the image crate's path, which gives the same pixels or the same error.
    fn read(path: &Path) -> Option<IndexedPng> {
        let png_name = path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("png"));
        if !png_name {
            return None;
        }
        let data = std::fs::read(path).ok()?;
        // The image crate's decoder settings (its default 512 MiB allocation limit, text
        // chunks read), so that a file one path refuses the other refuses too.
        let limits = png::Limits {
            bytes: 512 * 1024 * 1024,
        };
        let mut dec = png::Decoder::new_with_limits(std::io::Cursor::new(&data), limits);
        dec.set_ignore_text_chunk(false);
        let header = dec.read_header_info().ok()?;
        if header.color_type != png::ColorType::Indexed {
            return None;
        }
        dec.set_transformations(png::Transformations::IDENTITY);
        let mut reader = dec.read_info().ok()?;
        let mut buf = vec![0u8; reader.output_buffer_size()?];
        let frame = reader.next_frame(&mut buf).ok()?;
        let info = reader.info();
        let palette = info.palette.as_deref()?;
        let entries = palette.len() / 3;
        // png's expansion: a tRNS with more entries than the palette is ignored, entries
        // past a short one are opaque.
        let trns = info.trns.as_deref();
        let alphas = trns.filter(|t| t.len() <= entries).unwrap_or(&[]);
        let mut rgba = [[0, 0, 0, 255]; 256];
        for (i, px) in rgba.iter_mut().enumerate().take(entries) {
            px[..3].copy_from_slice(&palette[3 * i..3 * i + 3]);
            px[3] = alphas.get(i).copied().unwrap_or(255);
        }
        let bits = frame.bit_depth as u32;
        let (w, h) = (frame.width as usize, frame.height as usize);
        let per = (8 / bits) as usize;
        let mask = ((1u16 << bits) - 1) as u8;
        let mut indices = Vec::with_capacity(w * h + per);
        for row in buf.chunks(frame.line_size).take(h) {
            if bits == 8 {
                indices.extend_from_slice(&row[..w]);
                continue;
            }
            // Byte by byte, the leftmost pixel in the high bits (a division and a remainder
            // by `per` for each pixel cost more than the rest of the decode); the last
            // byte's padding pixels are cut off.
            let end = indices.len() + w;
            for &byte in &row[..w.div_ceil(per)] {
                let mut b = byte;
                for _ in 0..per {
                    b = b.rotate_left(bits);
                    indices.push(b & mask);
                }
            }
            indices.truncate(end);
        }
        if indices.len() != w * h || indices.iter().any(|&i| i as usize >= entries) {
            return None;
        }
        Some(IndexedPng {
            width: frame.width,
            height: frame.height,
            has_alpha: trns.is_some(),
            rgba,
            indices,
        })
    }
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Writes a palette PNG of `w`×`h` pixels whose indices are `index(x, y)`.
    fn indexed_png(
        path: &Path,
        (w, h): (u32, u32),
        depth: png::BitDepth,
        palette: &[u8],
        trns: Option<&[u8]>,
        index: impl Fn(u32, u32) -> u8,
    ) {
        let file = std::io::BufWriter::new(std::fs::File::create(path).unwrap());
        let mut enc = png::Encoder::new(file, w, h);
        enc.set_color(png::ColorType::Indexed);
        enc.set_depth(depth);
        enc.set_palette(palette.to_vec());
        if let Some(t) = trns {
            enc.set_trns(t.to_vec());
        }
        let mut writer = enc.write_header().unwrap();
        let bits = depth as u32;
        let per = 8 / bits;
        let line = w.div_ceil(per) as usize;
        let mut data = vec![0u8; line * h as usize];
        for y in 0..h {
            for x in 0..w {
                let shift = 8 - bits * (x % per + 1);
                data[y as usize * line + (x / per) as usize] |= index(x, y) << shift;
            }
        }
        writer.write_image_data(&data).unwrap();
    }

    fn bits(p: &ImagePixels) -> Vec<[u64; 5]> {
        p.to_vec()
            .iter()
            .map(|c| [c.rgb.x, c.rgb.y, c.rgb.z, c.filter, c.transmit].map(f64::to_bits))
            .collect()
    }

    #[test]
    fn palette_pngs_load_as_the_image_crate_decodes_them() {
        let dir = std::env::temp_dir().join(format!("lancer-indexed-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let palette: Vec<u8> = (0..256u32 * 3).map(|i| (i * 97 % 256) as u8).collect();
        let long_trns = vec![7u8; 20];
        let cases: Vec<(png::BitDepth, usize, Option<&[u8]>)> = vec![
            (png::BitDepth::One, 2, None),
            (png::BitDepth::Two, 4, Some(&[0, 128])),
            (png::BitDepth::Four, 16, None),
            (png::BitDepth::Four, 16, Some(&[0, 1, 2, 254, 255])),
            (png::BitDepth::Four, 16, Some(&long_trns)),
            (png::BitDepth::Eight, 256, None),
            (png::BitDepth::Eight, 256, Some(&[255; 256])),
            (png::BitDepth::Eight, 3, Some(&[9, 10, 11])),
        ];
        for (n, (depth, entries, trns)) in cases.into_iter().enumerate() {
            for (w, h) in [(1, 1), (7, 3), (33, 17)] {
                let path = dir.join(format!("case{n}_{w}x{h}.png"));
                let used = entries as u32;
                let index = |x: u32, y: u32| ((x * 5 + y * 11 + x * y) % used) as u8;
                indexed_png(&path, (w, h), depth, &palette[..3 * entries], trns, index);
                let mut fast = ImageMap::new(false);
                load_image_map(&path, &mut fast).unwrap();
                assert!(IndexedPng::read(&path).is_some(), "{}", path.display());
                let mut slow = ImageMap::new(false);
                load_decoded(&path, &mut slow).unwrap();
                assert_eq!((fast.width, fast.height), (slow.width, slow.height));
                assert_eq!(bits(&fast.pixels), bits(&slow.pixels), "{}", path.display());
                assert_eq!(
                    fast.pixels.any(|c| !c.is_opaque()),
                    slow.pixels.any(|c| !c.is_opaque())
                );
            }
        }
        // An index past the palette takes the image crate's path.
        let path = dir.join("past.png");
        indexed_png(
            &path,
            (4, 4),
            png::BitDepth::Four,
            &palette[..6],
            None,
            |x, _| x as u8,
        );
        assert!(IndexedPng::read(&path).is_none());
        let _ = std::fs::remove_dir_all(&dir);
    }
}
