//! Where the parser's tokens come from: files found as POV-Ray finds them (the scene's
//! directory, the library path, the system include directories), lexed once and cached for
//! the run (an animation's frames re-read nothing unchanged), included or read as the
//! `Include_Header`.

use std::collections::{HashMap, HashSet};
use std::path::{Path, PathBuf};
use std::rc::Rc;

use crate::diag::Diagnostic;

use super::{FrameKind, PResult, ParseOptions, Parser, SYSTEM_INCLUDE_DIRS};
use crate::sdl::lexer::{lex_with, Token};
use crate::sdl::source::{Sources, Span};

/// A file's tokens, kept for as long as the file on disk is unchanged.
pub(super) struct CachedFile {
    id: u32,
    tokens: Rc<Vec<Token>>,
    stamp: Option<FileStamp>,
}

/// Size and modification time: enough to notice a file rewritten between two frames.
#[derive(Clone, Copy, PartialEq, Eq)]
struct FileStamp {
    len: u64,
    modified: Option<std::time::SystemTime>,
}

impl FileStamp {
    fn of(path: &Path) -> Option<FileStamp> {
        let m = std::fs::metadata(path).ok()?;
        Some(FileStamp {
            len: m.len(),
            modified: m.modified().ok(),
        })
    }
}

/// Sources and lexed files carried from one parse to the next within a run.
pub struct Lexed {
    sources: Sources,
    files: HashMap<PathBuf, CachedFile>,
}

impl Lexed {
    /// Bytes the files' tokens take (their vectors' lengths, not the names they share).
    pub fn token_bytes(&self) -> usize {
        let token = std::mem::size_of::<Token>();
        self.files.values().map(|f| f.tokens.len() * token).sum()
    }
}

impl Parser {
    /// `Include_Header`: the file is read as if the scene's first line included it.
    pub(super) fn include_header(&mut self, name: &str) -> PResult<()> {
        let Some(path) = self.find_file(name) else {
            return Err(Box::new(
                Diagnostic::error(
                    format!("cannot find the Include_Header file \"{name}\" (+HI option)"),
                    None,
                )
                .with_note(self.searched_note()),
            ));
        };
        let (_, tokens) = self.load(&path, None)?;
        self.push_frame(tokens, FrameKind::Include, None, true)
    }

    pub(super) fn lex_file(&mut self, id: u32) -> PResult<Rc<Vec<Token>>> {
        match lex_with(self.sources.text(id), id, &mut self.names) {
            // Into an `Rc` as it is: making an `Rc<[Token]>` would copy the tokens, and for a
            // big mesh2 file they are most of the parse's memory (40 bytes a token).
            Ok(mut t) => {
                t.shrink_to_fit();
                Ok(Rc::new(t))
            }
            Err(e) => Err(self.error_at(
                Span {
                    file: id,
                    start: e.start as u32,
                    end: e.end as u32,
                },
                e.message,
            )),
        }
    }

    /// Reads and lexes a file once per run; later includes reuse the tokens.
    pub(super) fn load(
        &mut self,
        path: &Path,
        site: Option<Span>,
    ) -> PResult<(u32, Rc<Vec<Token>>)> {
        let key = path.canonicalize().unwrap_or_else(|_| path.to_path_buf());
        let stamp = FileStamp::of(path);
        if let Some(c) = self.file_cache.get(&key) {
            // A file the scene rewrote (#write, then #include) is read again.
            if c.stamp == stamp {
                return Ok((c.id, c.tokens.clone()));
            }
        }
        let bytes = std::fs::read(path).map_err(|e| {
            let msg = format!("cannot read {}: {e}", path.display());
            match site {
                Some(s) => self.error_at(s, msg),
                None => Box::new(Diagnostic::error(msg, None)),
            }
        })?;
        // Old scenes carry Latin-1 in comments; replacement characters outside comments and
        // strings are reported by the lexer as not being scene text.
        let text = utf8_text(bytes);
        let id = self.sources.add(path.display().to_string(), text);
        let tokens = self.lex_file(id)?;
        self.file_cache.insert(
            key,
            CachedFile {
                id,
                tokens: tokens.clone(),
                stamp,
            },
        );
        Ok((id, tokens))
    }

    /// The files read so far, lexed, for the next parse of the same run (the next frame of an
    /// animation): include files are then read and lexed once per run, not once per frame.
    /// Takes the files read and their tokens out of a finished parse (see `into_lexed`),
    /// leaving the scene description: the tokens of a big file can then be freed before the
    /// scene is built, or kept for the next frame.
    pub fn take_lexed(&mut self) -> Lexed {
        // The scene file's frame stays on the stack at the end of a parse; it holds the tokens.
        self.frames.clear();
        Lexed {
            sources: std::mem::take(&mut self.sources),
            files: std::mem::take(&mut self.file_cache),
        }
    }

    pub fn into_lexed(self) -> Lexed {
        Lexed {
            sources: self.sources,
            files: self.file_cache,
        }
    }

    /// A parser that starts with the files an earlier parse of this run read.
    pub fn with_lexed(options: ParseOptions, lexed: Lexed) -> Parser {
        let mut p = Parser::new(options);
        p.sources = lexed.sources;
        p.file_cache = lexed.files;
        p
    }

    /// Finds a file the way POV-Ray does: as given, the scene directory, the library path,
    /// then the system include directories.
    pub fn find_file(&self, name: &str) -> Option<PathBuf> {
        let p = Path::new(name);
        if p.is_absolute() {
            return p.is_file().then(|| p.to_path_buf());
        }
        self.search_dirs()
            .into_iter()
            .map(|d| d.join(p))
            .find(|c| c.is_file())
    }

    /// Where relative include and image names are looked for, in order: the scene's
    /// directory, the directory of the file being read, the library paths, the system include
    /// directories, the current directory.
    pub(in crate::sdl) fn search_dirs(&self) -> Vec<PathBuf> {
        let mut dirs: Vec<PathBuf> = vec![self.scene_dir.clone()];
        // The directory of the file being read, so includes next to includes are found.
        if let Some(f) = self
            .frames
            .iter()
            .rev()
            .find(|f| f.kind != FrameKind::Macro)
        {
            if let Some(t) = f.tokens.first() {
                if let Some(d) = Path::new(&self.sources.name(t.span.file)).parent() {
                    dirs.push(d.to_path_buf());
                }
            }
        }
        dirs.extend(self.options.library_paths.iter().cloned());
        dirs.extend(SYSTEM_INCLUDE_DIRS.iter().map(PathBuf::from));
        dirs.push(PathBuf::from("."));
        // A scene named without a directory has "" as its directory: that is ".", and each
        // directory is searched (and listed in a "searched:" note) once.
        let mut seen = HashSet::new();
        dirs.into_iter()
            .map(|d| {
                if d.as_os_str().is_empty() {
                    PathBuf::from(".")
                } else {
                    d
                }
            })
            .filter(|d| seen.insert(d.clone()))
            .collect()
    }

    /// The "searched: a, b, c" note of a file not found, listing `search_dirs` in order.
    pub(in crate::sdl) fn searched_note(&self) -> String {
        let dirs: Vec<String> = self
            .search_dirs()
            .iter()
            .map(|d| d.display().to_string())
            .collect();
        format!("searched: {}", dirs.join(", "))
    }

    pub(in crate::sdl) fn include(&mut self, name: &str, site: Span) -> PResult<()> {
        let Some(path) = self.find_file(name) else {
            let d = self.error_at(site, format!("cannot find include file \"{name}\""));
            return Err(Box::new(
                d.with_note(self.searched_note())
                    .with_note("POV-Ray's standard include files come with Debian's povray-includes package (apt-get install povray-includes); other directories can be added with +L<dir>"),
            ));
        };
        self.check_include_depth(site)?;
        let (_, tokens) = self.load(&path, Some(site))?;
        self.push_frame(
            tokens,
            FrameKind::Include,
            Some((site, format!("included from here ({name})").into())),
            true,
        )
    }
}

/// A file's bytes as text: valid UTF-8 as it is (no copy), anything else through
/// `from_utf8_lossy`. Every include file took the lossy path's slower scan and a copy.
pub(in crate::sdl) fn utf8_text(bytes: Vec<u8>) -> String {
    String::from_utf8(bytes).unwrap_or_else(|e| String::from_utf8_lossy(e.as_bytes()).into_owned())
}
