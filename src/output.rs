//! Writing films to PNG (8 or 16 bit) and OpenEXR, never leaving a half-written file: the
//! picture goes to a temporary name beside the target and is renamed into place.

use std::path::{Path, PathBuf};

use rayon::prelude::*;

use crate::render::Film;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Png8,
    Png16,
    Exr,
}

impl Format {
    /// The format a file name asks for when no option says otherwise.
    pub fn from_path(p: &Path) -> Format {
        match p
            .extension()
            .and_then(|e| e.to_str())
            .map(|e| e.to_ascii_lowercase())
        {
            Some(e) if e == "exr" => Format::Exr,
            _ => Format::Png8,
        }
    }
    pub fn extension(self) -> &'static str {
        match self {
            Format::Exr => "exr",
            _ => "png",
        }
    }
}

/// 8-bit RGB bytes as POV-Ray quantises them: floor(v·255 + 0.5) of the clipped encoded value.
pub fn to_rgb8(film: &Film) -> Vec<u8> {
    channels(film, |v| (film.encode(v) * 255.0 + 0.5).floor() as u8)
}

/// Every channel of every pixel through `f`, in file order, computed in parallel.
fn channels<T: Send>(film: &Film, f: impl Fn(f64) -> T + Sync) -> Vec<T> {
    film.pixels
        .par_iter()
        .flat_map_iter(|p| [f(p.x), f(p.y), f(p.z)])
        .collect()
}

pub fn write(film: &Film, path: &Path, format: Format) -> Result<(), String> {
    write_atomic(path, |tmp| write_to(film, tmp, format))
}

/// Writes `path` under a temporary name beside it, then renames: whoever sees the name sees
/// a finished file (frames skipped by `+C`, cache records, reports). `write` gets the
/// temporary path; on any failure the temporary file is removed.
pub fn write_atomic(
    path: &Path,
    write: impl FnOnce(&Path) -> Result<(), String>,
) -> Result<(), String> {
    let tmp = temp_name(path);
    if let Err(e) = write(&tmp) {
        let _ = std::fs::remove_file(&tmp);
        return Err(format!("cannot write {}: {e}", path.display()));
    }
    std::fs::rename(&tmp, path).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        format!("cannot move the finished file to {}: {e}", path.display())
    })
}

/// `write_atomic` for text.
pub fn write_text_atomic(path: &Path, text: &str) -> Result<(), String> {
    write_atomic(path, |tmp| {
        std::fs::write(tmp, text).map_err(|e| e.to_string())
    })
}

fn temp_name(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "out".into());
    path.with_file_name(format!(".{name}.{}.tmp", std::process::id()))
}

fn write_to(film: &Film, tmp: &Path, format: Format) -> Result<(), String> {
    let (w, h) = (film.width, film.height);
    match format {
        Format::Png8 => {
            let img = image::RgbImage::from_raw(w, h, to_rgb8(film)).ok_or("bad film size")?;
            img.save_with_format(tmp, image::ImageFormat::Png)
                .map_err(|e| e.to_string())
        }
        Format::Png16 => {
            let data = channels(film, |v| (film.encode(v) * 65535.0 + 0.5).floor() as u16);
            let img = image::ImageBuffer::<image::Rgb<u16>, _>::from_raw(w, h, data)
                .ok_or("bad film size")?;
            img.save_with_format(tmp, image::ImageFormat::Png)
                .map_err(|e| e.to_string())
        }
        Format::Exr => {
            // EXR holds linear light, unclipped.
            let data = channels(film, |v| film.linear(v) as f32);
            let img = image::Rgb32FImage::from_raw(w, h, data).ok_or("bad film size")?;
            image::DynamicImage::ImageRgb32F(img)
                .save_with_format(tmp, image::ImageFormat::OpenExr)
                .map_err(|e| e.to_string())
        }
    }
}
