//! Writing films to every file type POV-Ray 3.7 writes (PNG, PPM, Targa, BMP, JPEG, Radiance
//! HDR, OpenEXR) with its bit depths, file gamma, alpha and dithering, never leaving a
//! half-written file: the picture goes to a temporary name beside the target and is renamed
//! into place.
//!
//! `OutputSpec` is what the options (`+F<x><n>`, `Bits_Per_Color`, `File_Gamma`, `+TH`,
//! `Compression`) amount to; `pixels` turns a film into the integer samples a file holds,
//! `dither` spreads the quantisation error, and one file per family writes the bytes.

mod codecs;
mod dither;
mod pixels;
mod png;
mod simple;
mod steps;
mod stream;

use std::path::{Path, PathBuf};

use crate::render::Film;
use crate::scene::build::GammaMode;

pub use dither::DitherMethod;
pub use stream::{why_not_streamable, write_banded};

/// POV-Ray's output file types, by their `+F` letter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FileType {
    /// `N`
    Png,
    /// `P`: binary PPM (P6).
    Ppm,
    /// `T`: uncompressed Targa.
    Tga,
    /// `C`: run-length encoded Targa.
    TgaRle,
    /// `B`
    Bmp,
    /// `J`
    Jpeg,
    /// `H`: Radiance RGBE.
    Hdr,
    /// `E`
    Exr,
}

impl FileType {
    /// The type for a `+F` letter. `S` (system format) is refused as POV-Ray 3.7 on Linux
    /// refuses it.
    pub fn from_letter(c: char) -> Result<FileType, String> {
        Ok(match c.to_ascii_uppercase() {
            'N' => FileType::Png,
            'P' => FileType::Ppm,
            'T' => FileType::Tga,
            'C' => FileType::TgaRle,
            'B' => FileType::Bmp,
            'J' => FileType::Jpeg,
            'H' => FileType::Hdr,
            'E' => FileType::Exr,
            'S' => {
                return Err(
                    "the system-specific file type S is rejected by POV-Ray 3.7 on \
                            Linux ('Failed to parse command-line option'); use +FN for PNG"
                        .into(),
                )
            }
            other => {
                return Err(format!(
                    "unknown output file type '{other}' (N, P, T, C, B, J, H or E)"
                ))
            }
        })
    }

    /// lancer's `--format` names, with the bits they imply.
    pub fn from_format_name(name: &str) -> Result<(FileType, u32), String> {
        Ok(match name.to_ascii_lowercase().as_str() {
            "png" => (FileType::Png, 8),
            "png16" => (FileType::Png, 16),
            "ppm" => (FileType::Ppm, 8),
            "ppm16" => (FileType::Ppm, 16),
            "tga" => (FileType::Tga, 8),
            "tga-rle" => (FileType::TgaRle, 8),
            "bmp" => (FileType::Bmp, 8),
            "jpeg" | "jpg" => (FileType::Jpeg, 8),
            "hdr" => (FileType::Hdr, 8),
            "exr" => (FileType::Exr, 8),
            other => {
                return Err(format!(
                    "unknown --format '{other}' (png, png16, ppm, ppm16, tga, tga-rle, bmp, \
                     jpeg, hdr or exr)"
                ))
            }
        })
    }

    /// The type a file name asks for when no option names one.
    pub fn from_path(p: &Path) -> FileType {
        let ext = p
            .extension()
            .and_then(|e| e.to_str())
            .map(|e| e.to_ascii_lowercase());
        match ext.as_deref() {
            Some("ppm" | "pnm") => FileType::Ppm,
            Some("tga") => FileType::Tga,
            Some("bmp") => FileType::Bmp,
            Some("jpg" | "jpeg") => FileType::Jpeg,
            Some("hdr") => FileType::Hdr,
            Some("exr") => FileType::Exr,
            _ => FileType::Png,
        }
    }

    /// The extension POV-Ray gives a file of this type.
    pub fn extension(self) -> &'static str {
        match self {
            FileType::Png => "png",
            FileType::Ppm => "ppm",
            FileType::Tga | FileType::TgaRle => "tga",
            FileType::Bmp => "bmp",
            FileType::Jpeg => "jpg",
            FileType::Hdr => "hdr",
            FileType::Exr => "exr",
        }
    }

    /// Whether POV-Ray writes an alpha channel with `+UA` (it warns for the others and writes
    /// the colour over black).
    pub fn has_alpha(self) -> bool {
        matches!(
            self,
            FileType::Png | FileType::Tga | FileType::TgaRle | FileType::Bmp | FileType::Exr
        )
    }

    /// Whether the type holds integers that `File_Gamma` and dithering apply to.
    fn is_integer(self) -> bool {
        !matches!(self, FileType::Hdr | FileType::Exr)
    }
}

/// `File_Gamma`: the transfer function integer files are encoded with.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FileGamma {
    Srgb,
    Power(f64),
}

impl FileGamma {
    /// `sRGB` or a positive number, as `File_Gamma=` takes them.
    pub fn parse(v: &str) -> Result<FileGamma, String> {
        if v.eq_ignore_ascii_case("srgb") {
            return Ok(FileGamma::Srgb);
        }
        match v.trim().parse::<f64>() {
            Ok(g) if g > 0.0 && g.is_finite() => Ok(FileGamma::Power(g)),
            _ => Err(format!(
                "File_Gamma={v}: expected sRGB or a positive number"
            )),
        }
    }
}

/// Everything that decides the bytes of the output file besides the film.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OutputSpec {
    pub file_type: FileType,
    /// Bits per colour asked for, 5..=16; only PNG and PPM use other than 8.
    pub bits: u32,
    pub file_gamma: FileGamma,
    /// `+TH` / `Dither=on`.
    pub dither: bool,
    /// `Dither_Method` / `+THxx`: kept while dithering is off, as POV-Ray keeps it.
    pub dither_method: DitherMethod,
    /// JPEG quality 2..=100 (`Compression`; POV-Ray's default 85).
    pub jpeg_quality: u8,
}

impl Default for OutputSpec {
    fn default() -> OutputSpec {
        OutputSpec::new(FileType::Png)
    }
}

impl OutputSpec {
    pub fn new(file_type: FileType) -> OutputSpec {
        OutputSpec {
            file_type,
            bits: 8,
            file_gamma: FileGamma::Srgb,
            dither: false,
            dither_method: DitherMethod::FloydSteinberg,
            jpeg_quality: 85,
        }
    }

    pub fn with_bits(mut self, bits: u32) -> OutputSpec {
        self.set_bits(bits);
        self
    }

    /// POV-Ray clips the depth to 5..=16 rather than refusing it.
    pub fn set_bits(&mut self, bits: u32) {
        self.bits = bits.clamp(5, 16);
    }

    /// `Compression=n` as POV-Ray reads it for JPEG: 0 and 1 mean the default 85, others are
    /// clipped to 2..=100.
    pub fn set_compression(&mut self, n: i64) {
        self.jpeg_quality = match n.clamp(0, 100) {
            0 | 1 => 85,
            q => q as u8,
        };
    }

    /// The bits per colour the file gets.
    pub fn effective_bits(&self) -> u32 {
        match self.file_type {
            FileType::Png | FileType::Ppm => self.bits,
            _ => 8,
        }
    }

    /// The dithering that applies: none for JPEG (it would fight the compression) and the
    /// floating-point types.
    fn effective_dither(&self) -> Option<DitherMethod> {
        (self.dither && self.file_type.is_integer() && self.file_type != FileType::Jpeg)
            .then_some(self.dither_method)
    }

    /// POV-Ray's warning when `+UA` meets a type without (official) alpha.
    pub fn alpha_warning(&self, alpha: bool) -> Option<String> {
        if !alpha {
            return None;
        }
        if self.file_type == FileType::Bmp {
            // POV-Ray warns here too, yet writes the alpha.
            return Some(
                "alpha in BMP files is not officially supported: written as POV-Ray writes it \
                 (32-bit, straight alpha in the fourth byte), which many readers ignore"
                    .into(),
            );
        }
        (!self.file_type.has_alpha()).then(|| {
            format!(
                "alpha channel output is not supported for {} files: written without alpha \
                 (the colour over black), as POV-Ray does",
                self.file_type.extension().to_ascii_uppercase()
            )
        })
    }
}

/// 8-bit RGB bytes as POV-Ray quantises them: floor(v·255 + 0.5) of the clipped encoded value.
pub fn to_rgb8(film: &Film) -> Vec<u8> {
    let spec = OutputSpec::default();
    let plane = pixels::quantise(film, &spec, false);
    plane.data.iter().map(|&v| v as u8).collect()
}

/// 8-bit samples as an 8-bit PNG of `spec` would hold them, RGB or RGBA (`alpha` and a film
/// with alpha), and the channel count.
pub fn samples8(film: &Film, spec: &OutputSpec, alpha: bool) -> (Vec<u8>, usize) {
    let mut spec = *spec;
    spec.file_type = FileType::Png;
    spec.set_bits(8);
    let plane = pixels::quantise(film, &spec, alpha);
    (
        plane.data.iter().map(|&v| v as u8).collect(),
        plane.channels,
    )
}

/// Writes the picture to `path`, or to standard output when `path` is `-` (POV-Ray's `+O-`,
/// for piping into another program).
pub fn write(film: &Film, path: &Path, spec: &OutputSpec) -> Result<(), String> {
    write_by(path, spec, |tmp| write_to(film, tmp, spec))
}

/// Writes to `path` (or standard output for `-`) what `write_to` writes to a file.
fn write_by(
    path: &Path,
    spec: &OutputSpec,
    write_to: impl FnOnce(&Path) -> Result<(), String>,
) -> Result<(), String> {
    if path == Path::new("-") {
        return write_stdout(spec, write_to);
    }
    write_atomic(path, write_to)
}

fn write_stdout(
    spec: &OutputSpec,
    write_to: impl FnOnce(&Path) -> Result<(), String>,
) -> Result<(), String> {
    use std::io::Write;
    // The encoders write files; the finished file is copied out whole, so a failed render
    // sends nothing down the pipe.
    let tmp = std::env::temp_dir().join(format!(
        "lancer-stdout-{}.{}",
        std::process::id(),
        spec.file_type.extension()
    ));
    let r = write_to(&tmp).and_then(|()| {
        let bytes = std::fs::read(&tmp).map_err(|e| e.to_string())?;
        let mut out = std::io::stdout().lock();
        out.write_all(&bytes)
            .and_then(|()| out.flush())
            .map_err(|e| e.to_string())
    });
    let _ = std::fs::remove_file(&tmp);
    r.map_err(|e| format!("cannot write the picture to standard output: {e}"))
}

/// A picture quantised pixel by pixel while it is rendered, for files of integer samples
/// written whole: the render needs no film (24 bytes a pixel, a few hundred page faults at
/// 320x240, and the quantisation's pass reading it back) and the file gets the same bytes
/// as `write` of the film would give it.
pub(crate) struct Quantised {
    pub(crate) plane: pixels::Plane,
    pub(crate) q: pixels::Quantiser,
    gamma: GammaMode,
}

impl Quantised {
    /// For a `width`×`height` picture of `gamma` written as `spec` says, the film keeping
    /// alpha when `alpha` (`+UA`); None for types written from the film (HDR, EXR) and for
    /// dithering.
    pub(crate) fn new(
        spec: &OutputSpec,
        gamma: GammaMode,
        width: u32,
        height: u32,
        alpha: bool,
    ) -> Option<Quantised> {
        if !spec.file_type.is_integer() {
            return None;
        }
        let alpha = alpha && spec.file_type.has_alpha();
        let n = width as usize * height as usize;
        let q = pixels::Quantiser::new(gamma, spec, alpha, n)?;
        Some(Quantised {
            plane: q.plane(width, height),
            q,
            gamma,
        })
    }

    /// The samples, row-major, `channels()` a pixel, for `put` to fill.
    pub(crate) fn samples(&mut self) -> (&mut [u16], &Quantiser) {
        (&mut self.plane.data, &self.q)
    }

    /// Writes the finished picture as `write` writes a film.
    pub(crate) fn write(&self, path: &Path, spec: &OutputSpec) -> Result<(), String> {
        write_by(path, spec, |tmp| {
            write_plane_to(&self.plane, self.gamma, tmp, spec)
        })
    }
}

pub(crate) use pixels::Quantiser;

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

fn write_to(film: &Film, tmp: &Path, spec: &OutputSpec) -> Result<(), String> {
    let alpha = film.alpha.is_some() && spec.file_type.has_alpha();
    match spec.file_type {
        FileType::Exr => codecs::write_exr(film, alpha, tmp),
        FileType::Hdr => codecs::write_hdr(film, create(tmp)?),
        // JPEG and PPM have no alpha (`has_alpha`): the colour over black.
        _ => write_plane_to(&pixels::quantise(film, spec, alpha), film.gamma, tmp, spec),
    }
}

fn create(tmp: &Path) -> Result<std::io::BufWriter<std::fs::File>, String> {
    std::fs::File::create(tmp)
        .map(std::io::BufWriter::new)
        .map_err(|e| e.to_string())
}

/// Writes the samples of an integer file type; `gamma` is the picture's.
fn write_plane_to(
    plane: &pixels::Plane,
    gamma: GammaMode,
    tmp: &Path,
    spec: &OutputSpec,
) -> Result<(), String> {
    match spec.file_type {
        FileType::Exr | FileType::Hdr => Err("HDR and EXR files are written from the film".into()),
        FileType::Jpeg => codecs::write_jpeg(plane, spec.jpeg_quality, create(tmp)?),
        FileType::Png => png::write(plane, pixels::png_gamma(gamma, spec), create(tmp)?),
        FileType::Ppm => simple::write_ppm(plane, create(tmp)?),
        FileType::Tga | FileType::TgaRle => {
            let rle = spec.file_type == FileType::TgaRle;
            simple::write_tga(plane, rle, pixels::display_gamma(gamma, spec), create(tmp)?)
        }
        FileType::Bmp => simple::write_bmp(plane, create(tmp)?),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn letters_extensions_and_paths() {
        for (c, ext) in [
            ('N', "png"),
            ('p', "ppm"),
            ('T', "tga"),
            ('C', "tga"),
            ('B', "bmp"),
            ('J', "jpg"),
            ('H', "hdr"),
            ('e', "exr"),
        ] {
            let t = FileType::from_letter(c).unwrap();
            assert_eq!(t.extension(), ext);
            if !c.eq_ignore_ascii_case(&'C') {
                assert_eq!(FileType::from_path(Path::new(&format!("a.{ext}"))), t);
            }
        }
        let e = FileType::from_letter('S').unwrap_err();
        assert!(e.contains("+FN"), "{e}");
        assert!(FileType::from_letter('X').is_err());
        assert_eq!(FileType::from_path(Path::new("a.JPEG")), FileType::Jpeg);
        assert_eq!(FileType::from_path(Path::new("noext")), FileType::Png);
    }

    #[test]
    fn bits_compression_and_gamma_are_read_as_povray_reads_them() {
        let mut s = OutputSpec::new(FileType::Png).with_bits(4);
        assert_eq!(s.bits, 5);
        s.set_bits(20);
        assert_eq!(s.effective_bits(), 16);
        s.file_type = FileType::Tga;
        assert_eq!(s.effective_bits(), 8);
        for (n, q) in [(-3, 85), (0, 85), (1, 85), (2, 2), (60, 60), (250, 100)] {
            s.set_compression(n);
            assert_eq!(s.jpeg_quality, q, "Compression={n}");
        }
        assert_eq!(FileGamma::parse("srgb").unwrap(), FileGamma::Srgb);
        assert_eq!(FileGamma::parse("2.2").unwrap(), FileGamma::Power(2.2));
        assert!(FileGamma::parse("0").is_err());
        assert!(FileGamma::parse("x").is_err());
    }

    #[test]
    fn dithering_and_alpha_apply_where_povray_applies_them() {
        let mut s = OutputSpec::new(FileType::Jpeg);
        s.dither = true;
        assert_eq!(s.effective_dither(), None);
        s.file_type = FileType::Exr;
        assert_eq!(s.effective_dither(), None);
        s.file_type = FileType::Bmp;
        assert_eq!(s.effective_dither(), Some(DitherMethod::FloydSteinberg));
        assert!(s.alpha_warning(true).unwrap().contains("BMP"));
        s.file_type = FileType::Tga;
        assert!(s.alpha_warning(true).is_none());
        s.file_type = FileType::Ppm;
        assert!(s.alpha_warning(true).is_some());
        assert!(s.alpha_warning(false).is_none());
    }
}
