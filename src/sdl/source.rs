//! Source files and spans: every token knows the file and byte range it came from, so any
//! error can show a caret under the source and the include/macro chain that led there.

use codespan_reporting::files::{Files, SimpleFiles};

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct Span {
    pub file: u32,
    pub start: u32,
    pub end: u32,
}

/// Every file read during a run, by index.
pub struct Sources {
    pub files: SimpleFiles<String, String>,
}

impl Default for Sources {
    fn default() -> Self {
        Sources {
            files: SimpleFiles::new(),
        }
    }
}

impl Sources {
    pub fn add(&mut self, name: String, text: String) -> u32 {
        self.files.add(name, text) as u32
    }
    /// How many files were read (ids 0..count).
    pub fn count(&self) -> usize {
        (0..).take_while(|&i| self.files.get(i).is_ok()).count()
    }
    pub fn name(&self, file: u32) -> String {
        self.files
            .get(file as usize)
            .map(|f| f.name().clone())
            .unwrap_or_default()
    }
    pub fn text(&self, file: u32) -> &str {
        self.files
            .get(file as usize)
            .map(|f| f.source().as_str())
            .unwrap_or("")
    }
    /// One-based line and column of a span's start.
    pub fn line_col(&self, span: Span) -> (usize, usize) {
        let id = span.file as usize;
        match self.files.location(id, span.start as usize) {
            Ok(loc) => (loc.line_number, loc.column_number),
            Err(_) => (0, 0),
        }
    }
    /// `file:line:col`, the form editors understand.
    pub fn place(&self, span: Span) -> String {
        let (l, c) = self.line_col(span);
        format!("{}:{}:{}", self.name(span.file), l, c)
    }
}
