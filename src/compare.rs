//! `lancer compare A.png B.png`: the picture comparison a user puts in a regression test
//! (render with lancer, compare with a stored POV-Ray picture), and the heat map that shows
//! where two pictures disagree.

use std::path::Path;

use crate::ssim::{self, Picture};

/// Side of the tiles whose mean SSIM is reported as the worst spot.
pub const TILE: u32 = 16;

/// The numbers `lancer compare` prints.
#[derive(Clone, Debug)]
pub struct Comparison {
    pub width: u32,
    pub height: u32,
    pub ssim: f64,
    /// Top-left corner and mean SSIM of the worst `TILE`×`TILE` tile.
    pub worst_tile: (u32, u32, f64),
    pub psnr: f64,
    map: (u32, u32, Vec<f32>),
}

/// Why two pictures could not be compared (exit code 2 on the command line).
#[derive(Debug)]
pub struct CompareError(pub String);

/// Loads both pictures and compares them. Sizes must match; pictures smaller than SSIM's
/// 11-pixel window cannot be compared.
pub fn compare_files(a: &Path, b: &Path) -> Result<(Comparison, Picture), CompareError> {
    let pa = Picture::load(a).map_err(CompareError)?;
    let pb = Picture::load(b).map_err(CompareError)?;
    if (pa.width, pa.height) != (pb.width, pb.height) {
        return Err(CompareError(format!(
            "the pictures differ in size: {} is {}x{}, {} is {}x{}",
            a.display(),
            pa.width,
            pa.height,
            b.display(),
            pb.width,
            pb.height
        )));
    }
    let c = compare(&pa, &pb).map_err(CompareError)?;
    Ok((c, pa))
}

pub fn compare(a: &Picture, b: &Picture) -> Result<Comparison, String> {
    let (ssim, map) = ssim::ssim_and_map(a, b)?;
    let worst_tile = ssim::worst_tile_at(&map, TILE);
    let psnr = ssim::psnr(a, b)?;
    Ok(Comparison {
        width: a.width,
        height: a.height,
        ssim,
        worst_tile,
        psnr,
        map,
    })
}

impl Comparison {
    /// The report `lancer compare` prints: one `key value` pair per line, easy to grep.
    pub fn report(&self) -> String {
        let psnr = if self.psnr.is_infinite() {
            "inf".to_string()
        } else {
            format!("{:.2}", self.psnr)
        };
        format!(
            "ssim {:.6}\nworst_tile {:.6} at {},{} ({TILE}x{TILE})\npsnr {psnr} dB\nsize {}x{}\n",
            self.ssim,
            self.worst_tile.2,
            self.worst_tile.0,
            self.worst_tile.1,
            self.width,
            self.height
        )
    }

    /// Writes the heat map: the first picture dimmed to grey, with the disagreement painted over
    /// it from dark red (slight) through orange to yellow-white (none alike). The square root
    /// makes the small differences that still fail a 0.95 threshold visible. Written under a
    /// temporary name and renamed, like every output.
    pub fn write_heat_map(&self, base: &Picture, path: &Path) -> Result<(), String> {
        let png = self.heat_map_png(base)?;
        crate::output::write_atomic(path, |tmp| {
            std::fs::write(tmp, &png).map_err(|e| e.to_string())
        })
    }

    /// The heat map as PNG file bytes (see `write_heat_map`).
    pub fn heat_map_png(&self, base: &Picture) -> Result<Vec<u8>, String> {
        let (w, h, values) = &self.map;
        let mut bytes = Vec::with_capacity(values.len() * 3);
        for (i, &s) in values.iter().enumerate() {
            let lum = base.rgb[i * 3] * 0.2126
                + base.rgb[i * 3 + 1] * 0.7152
                + base.rgb[i * 3 + 2] * 0.0722;
            let grey = 0.3 * lum;
            let d = (1.0 - s.clamp(0.0, 1.0)).sqrt();
            let (hr, hg, hb) = heat(d);
            let alpha = (d * 3.0).min(1.0);
            for hc in [hr, hg, hb] {
                let v = grey * (1.0 - alpha) + hc * alpha;
                bytes.push((v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8);
            }
        }
        rgb8_png(*w, *h, &bytes)
    }
}

/// 8-bit RGB samples as PNG file bytes.
pub fn rgb8_png(w: u32, h: u32, bytes: &[u8]) -> Result<Vec<u8>, String> {
    let mut out = std::io::Cursor::new(Vec::new());
    image::write_buffer_with_format(
        &mut out,
        bytes,
        w,
        h,
        image::ExtendedColorType::Rgb8,
        image::ImageFormat::Png,
    )
    .map_err(|e| e.to_string())?;
    Ok(out.into_inner())
}

/// A picture as loaded for comparison (any file type `lancer compare` reads) as an 8-bit PNG,
/// for showing it in a browser.
pub fn picture_png(p: &Picture) -> Result<Vec<u8>, String> {
    let bytes: Vec<u8> = p
        .rgb
        .iter()
        .map(|v| (v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8)
        .collect();
    rgb8_png(p.width, p.height, &bytes)
}

/// A black-body-like ramp: 0 black, 0.33 red, 0.66 orange-yellow, 1 near white.
fn heat(d: f32) -> (f32, f32, f32) {
    let r = (d * 3.0).min(1.0);
    let g = ((d - 0.33) * 3.0).clamp(0.0, 1.0);
    let b = ((d - 0.66) * 3.0).clamp(0.0, 1.0);
    (r, g, b)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pic(w: u32, h: u32, f: impl Fn(u32, u32) -> u8) -> Picture {
        let mut data = Vec::new();
        for y in 0..h {
            for x in 0..w {
                let v = f(x, y);
                data.extend_from_slice(&[v, v / 2, 255 - v]);
            }
        }
        Picture::from_rgb8(w, h, &data)
    }

    #[test]
    fn identical_pictures_score_one_and_infinite_psnr() {
        let a = pic(32, 24, |x, y| ((x * 7 + y * 3) % 256) as u8);
        let c = compare(&a, &a).unwrap();
        assert!((c.ssim - 1.0).abs() < 1e-12);
        assert!(c.psnr.is_infinite());
        assert!(c.report().contains("psnr inf dB"));
    }

    #[test]
    fn worst_tile_finds_the_damaged_spot() {
        let a = pic(64, 48, |x, y| ((x * 5 + y * 9) % 256) as u8);
        let b = pic(64, 48, |x, y| {
            if (48..64).contains(&x) && (16..32).contains(&y) {
                255 - ((x * 5 + y * 9) % 256) as u8
            } else {
                ((x * 5 + y * 9) % 256) as u8
            }
        });
        let c = compare(&a, &b).unwrap();
        assert_eq!((c.worst_tile.0, c.worst_tile.1), (48, 16));
        assert!(c.worst_tile.2 < c.ssim);
    }

    #[test]
    fn heat_ramp_is_black_when_alike() {
        assert_eq!(heat(0.0), (0.0, 0.0, 0.0));
        assert_eq!(heat(1.0), (1.0, 1.0, 1.0));
    }
}
