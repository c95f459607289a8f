//! The library's front door: parse a scene file, build it and render it, as the command line
//! and the tests do.

use std::path::{Path, PathBuf};

use crate::diag::Diagnostic;
use crate::render::{Film, RenderSettings};
use crate::sdl::{ParseOptions, Parser};

/// A parse attempt: the parser keeps the sources (for rendering diagnostics) and warnings.
pub struct Parsed {
    pub parser: Parser,
    pub error: Option<Box<Diagnostic>>,
}

pub fn parse_file(path: &Path, options: ParseOptions) -> Parsed {
    parse_file_with(path, options, None)
}

/// Like `parse_file`, reusing the files an earlier parse of the same run read and lexed (the
/// frames of an animation).
pub fn parse_file_with(
    path: &Path,
    options: ParseOptions,
    lexed: Option<crate::sdl::parser::Lexed>,
) -> Parsed {
    let mut parser = match lexed {
        Some(l) => Parser::with_lexed(options, l),
        None => Parser::new(options),
    };
    let error = parser.parse_file(path).err();
    Parsed { parser, error }
}

/// Parses, builds and renders a scene; errors come back as one-line `file:line:col` text.
pub fn render_file(
    path: &Path,
    library_paths: &[PathBuf],
    settings: &RenderSettings,
) -> Result<Film, String> {
    let opts = ParseOptions {
        library_paths: library_paths.to_vec(),
        image_width: settings.width,
        image_height: settings.height,
        ..ParseOptions::default()
    };
    let parsed = parse_file(path, opts);
    if let Some(e) = parsed.error {
        return Err(e.one_line(&parsed.parser.sources));
    }
    let built = crate::scene::build::build(&parsed.parser.scene, settings.width, settings.height);
    Ok(crate::render::render(&built.scene, settings, &|_| {}))
}

/// The picture as 8-bit samples, row by row, quantised as a PNG file of `spec` holds them
/// (file gamma, dithering), with alpha (RGBA, straight) when the film has it and `alpha` is
/// asked: what the Python module hands back as `uint8`. Returns the samples and the channels.
pub fn samples8(film: &Film, spec: &crate::output::OutputSpec, alpha: bool) -> (Vec<u8>, usize) {
    crate::output::samples8(film, spec, alpha)
}

/// The picture as linear light (premultiplied alpha last when present): what an EXR file
/// holds, and what the Python module hands back as `float32`.
pub fn linear_f32(film: &Film) -> (Vec<f32>, usize) {
    let channels = if film.alpha.is_some() { 4 } else { 3 };
    let mut v = Vec::with_capacity(film.pixels.len() * channels);
    for (i, p) in film.pixels.iter().enumerate() {
        v.extend([film.linear(p.x), film.linear(p.y), film.linear(p.z)].map(|c| c as f32));
        if let Some(a) = &film.alpha {
            v.push(a[i] as f32);
        }
    }
    (v, channels)
}

/// A scene error's place and message, for callers that are not a terminal (the Python
/// module's `SceneError`): 1-based line and column, as the caret diagnostics print them.
#[derive(Clone, Debug)]
pub struct ErrorPlace {
    pub file: Option<String>,
    pub line: Option<usize>,
    pub column: Option<usize>,
    pub message: String,
    /// `file:line:col: error: message`.
    pub one_line: String,
}

impl ErrorPlace {
    pub fn of(e: &Diagnostic, sources: &crate::sdl::source::Sources) -> ErrorPlace {
        let (file, line, column) = match e.span {
            Some(s) => {
                let (l, c) = sources.line_col(s);
                (Some(sources.name(s.file)), Some(l), Some(c))
            }
            None => (None, None, None),
        };
        ErrorPlace {
            file,
            line,
            column,
            message: e.message.clone(),
            one_line: e.one_line(sources),
        }
    }
}
