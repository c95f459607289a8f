//! Writing a picture band by band while it is rendered, for pictures too big to hold whole:
//! PNG and PPM, whose rows go into the file top to bottom. The pixels are quantised exactly as
//! for a whole picture; a streamed PNG splits its compressed data into other IDAT chunks than
//! a whole one, so its bytes differ while its pixels do not. Like every output, the file is
//! written under a temporary name and renamed when finished.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;

use super::{pixels, png, simple, write_atomic, FileType, OutputSpec};
use crate::render::Film;

/// Why pictures of `spec` cannot be written band by band, when they cannot.
pub fn why_not_streamable(spec: &OutputSpec) -> Option<String> {
    if !matches!(spec.file_type, FileType::Png | FileType::Ppm) {
        return Some(format!(
            "{} files are written whole",
            spec.file_type.extension().to_ascii_uppercase()
        ));
    }
    if spec.effective_dither().is_some() {
        return Some("dithering spreads errors across the whole picture".into());
    }
    None
}

enum Writer {
    Png(Box<::png::StreamWriter<'static, BufWriter<File>>>),
    Ppm(BufWriter<File>),
}

/// Writes the `width`×`height` picture that `render` delivers band by band (top band first)
/// to `path` (`-`: standard output, once finished); returns what `render` returns.
pub fn write_banded<T>(
    path: &Path,
    spec: &OutputSpec,
    width: u32,
    height: u32,
    render: impl FnOnce(&mut dyn FnMut(&Film) -> Result<(), String>) -> Result<T, String>,
) -> Result<T, String> {
    if let Some(why) = why_not_streamable(spec) {
        return Err(format!("cannot write this picture band by band: {why}"));
    }
    let mut result = None;
    let write = |tmp: &Path| -> Result<(), String> {
        let mut out = Some(BufWriter::new(
            File::create(tmp).map_err(|e| e.to_string())?,
        ));
        let mut writer: Option<Writer> = None;
        let r = render(&mut |band: &Film| {
            let alpha = band.alpha.is_some() && spec.file_type.has_alpha();
            let plane = pixels::quantise(band, spec, alpha);
            if writer.is_none() {
                let out = out.take().expect("one output");
                writer = Some(match spec.file_type {
                    FileType::Png => {
                        let gamma = pixels::png_gamma(band.gamma, spec);
                        let w = png::header(&plane, height, gamma, out)?;
                        Writer::Png(Box::new(w.into_stream_writer().map_err(|e| e.to_string())?))
                    }
                    _ => {
                        let mut out = out;
                        out.write_all(&simple::ppm_header(&plane, height))
                            .map_err(|e| e.to_string())?;
                        Writer::Ppm(out)
                    }
                });
            }
            let r = match writer.as_mut().expect("started above") {
                Writer::Png(w) => w.write_all(&png::sample_bytes(&plane)),
                Writer::Ppm(w) => simple::write_ppm_samples(&plane, w),
            };
            r.map_err(|e| e.to_string())
        })?;
        match writer {
            Some(Writer::Png(w)) => w.finish().map_err(|e| e.to_string())?,
            Some(Writer::Ppm(mut w)) => w.flush().map_err(|e| e.to_string())?,
            None => {
                return Err(format!(
                    "no rows were rendered for a {width}x{height} picture"
                ))
            }
        }
        result = Some(r);
        Ok(())
    };
    if path == Path::new("-") {
        let tmp = std::env::temp_dir().join(format!(
            "lancer-stdout-{}.{}",
            std::process::id(),
            spec.file_type.extension()
        ));
        let r = write(&tmp).and_then(|()| {
            let mut file = File::open(&tmp).map_err(|e| e.to_string())?;
            let mut stdout = std::io::stdout().lock();
            std::io::copy(&mut file, &mut stdout)
                .and_then(|_| stdout.flush())
                .map_err(|e| e.to_string())
        });
        let _ = std::fs::remove_file(&tmp);
        r.map_err(|e| format!("cannot write the picture to standard output: {e}"))?;
    } else {
        write_atomic(path, write)?;
    }
    Ok(result.expect("set when writing succeeded"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::DVec3;
    use crate::scene::build::GammaMode;

    fn band(y0: u32, rows: u32, w: u32, alpha: bool) -> Film {
        let n = (rows * w) as usize;
        let pixels: Vec<DVec3> = (0..n)
            .map(|i| {
                let (x, y) = (i as u32 % w, y0 + i as u32 / w);
                DVec3::new(x as f64 / w as f64, y as f64 / 20.0, 0.3)
            })
            .collect();
        Film {
            width: w,
            height: rows,
            alpha: alpha.then(|| {
                (0..n)
                    .map(|i| ((y0 * w) as usize + i) % 7)
                    .map(|a| a as f64 / 6.0)
                    .collect()
            }),
            pixels,
            gamma: GammaMode::Corrected(1.0),
            rays: 0,
            camera_rays: 0,
        }
    }

    /// A picture written in bands decodes to the samples of the same picture written whole
    /// (PPM: to the same bytes).
    #[test]
    fn banded_files_hold_the_whole_pictures_samples() {
        let dir = std::env::temp_dir().join(format!("lancer-stream-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let (w, h) = (13, 20);
        for (file_type, bits, alpha) in [
            (FileType::Png, 8, false),
            (FileType::Png, 16, true),
            (FileType::Png, 5, false),
            (FileType::Ppm, 8, false),
            (FileType::Ppm, 12, false),
        ] {
            let spec = OutputSpec::new(file_type).with_bits(bits);
            let ext = file_type.extension();
            let whole = dir.join(format!("whole.{ext}"));
            let banded = dir.join(format!("banded.{ext}"));
            super::super::write(&band(0, h, w, alpha), &whole, &spec).unwrap();
            write_banded(&banded, &spec, w, h, |sink| {
                for y0 in (0..h).step_by(3) {
                    sink(&band(y0, 3.min(h - y0), w, alpha))?;
                }
                Ok(())
            })
            .unwrap();
            let (a, b) = (
                std::fs::read(&whole).unwrap(),
                std::fs::read(&banded).unwrap(),
            );
            if file_type == FileType::Ppm {
                assert!(a == b, "{ext} {bits}");
            } else {
                let decode = |bytes: &[u8]| {
                    let d = ::png::Decoder::new(std::io::Cursor::new(bytes.to_vec()));
                    let mut r = d.read_info().unwrap();
                    let mut buf = vec![0; r.output_buffer_size().unwrap()];
                    let info = r.next_frame(&mut buf).unwrap();
                    buf.truncate(info.buffer_size());
                    (info.width, info.height, info.color_type, buf)
                };
                assert!(decode(&a) == decode(&b), "{ext} {bits} alpha {alpha}");
            }
        }
        let jpeg = OutputSpec::new(FileType::Jpeg);
        assert!(why_not_streamable(&jpeg).unwrap().contains("JPG"));
        let _ = std::fs::remove_dir_all(&dir);
    }
}
