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
