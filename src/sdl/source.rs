//! Source files and spans: every token knows the file and byte range it came from, so any
//! error can show a caret under the source and the include/macro chain that led there.

use std::ops::Range;
use std::sync::OnceLock;

use codespan_reporting::files::{line_starts, Error, Files};

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct Span {
    pub file: u32,
    pub start: u32,
    pub end: u32,
}

/// Every file read during a run, by index.
#[derive(Default)]
pub struct Sources {
    pub files: SourceFiles,
}

/// The files of a run as codespan's `SimpleFiles` serves them, with each file's line starts
/// found when a diagnostic first asks for a line: `SimpleFiles` scanned every file for its
/// newlines as it was added, ~3.5 % of an include-heavy scene's process
/// (DarkBlueSky_Axes), for line numbers that only an error or a warning reads.
#[derive(Default)]
pub struct SourceFiles {
    files: Vec<SourceFile>,
}

pub struct SourceFile {
    name: String,
    source: String,
    line_starts: OnceLock<Vec<usize>>,
}

impl SourceFile {
    pub fn name(&self) -> &String {
        &self.name
    }
    pub fn source(&self) -> &String {
        &self.source
    }
    fn line_starts(&self) -> &[usize] {
        self.line_starts
            .get_or_init(|| line_starts(&self.source).collect())
    }
    /// `SimpleFile::line_start`: the source's length one past the last line, an error beyond.
    fn line_start(&self, line_index: usize) -> Result<usize, Error> {
        let starts = self.line_starts();
        match line_index.cmp(&starts.len()) {
            std::cmp::Ordering::Less => Ok(starts[line_index]),
            std::cmp::Ordering::Equal => Ok(self.source.len()),
            std::cmp::Ordering::Greater => Err(Error::LineTooLarge {
                given: line_index,
                max: starts.len() - 1,
            }),
        }
    }
}

impl SourceFiles {
    pub fn add(&mut self, name: String, source: String) -> usize {
        self.files.push(SourceFile {
            name,
            source,
            line_starts: OnceLock::new(),
        });
        self.files.len() - 1
    }
    pub fn get(&self, file_id: usize) -> Result<&SourceFile, Error> {
        self.files.get(file_id).ok_or(Error::FileMissing)
    }
}

impl<'a> Files<'a> for SourceFiles {
    type FileId = usize;
    type Name = String;
    type Source = &'a str;

    fn name(&self, file_id: usize) -> Result<String, Error> {
        Ok(self.get(file_id)?.name.clone())
    }

    fn source(&self, file_id: usize) -> Result<&str, Error> {
        Ok(&self.get(file_id)?.source)
    }

    fn line_index(&self, file_id: usize, byte_index: usize) -> Result<usize, Error> {
        Ok(self
            .get(file_id)?
            .line_starts()
            .binary_search(&byte_index)
            .unwrap_or_else(|next_line| next_line - 1))
    }

    fn line_range(&self, file_id: usize, line_index: usize) -> Result<Range<usize>, Error> {
        let f = self.get(file_id)?;
        Ok(f.line_start(line_index)?..f.line_start(line_index + 1)?)
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

#[cfg(test)]
mod tests {
    use super::*;
    use codespan_reporting::files::SimpleFiles;

    /// The lazy table answers every question codespan asks as `SimpleFiles` does: names,
    /// sources, line indices, line ranges (and their errors one past the end), locations.
    #[test]
    fn answers_as_simple_files_does() {
        let texts = [
            "",
            "\n",
            "a",
            "foo\nbar\r\n\nbaz",
            "x\n\n\ny\n",
            "/* \u{e9} */\n#declare A = 1;\r\n",
        ];
        let mut ours = SourceFiles::default();
        let mut theirs = SimpleFiles::new();
        for (i, t) in texts.iter().enumerate() {
            assert_eq!(ours.add(format!("f{i}"), t.to_string()), i);
            assert_eq!(theirs.add(format!("f{i}"), t.to_string()), i);
        }
        for id in 0..texts.len() + 1 {
            assert_eq!(ours.name(id).ok(), theirs.name(id).ok());
            assert_eq!(ours.source(id).ok(), theirs.source(id).ok());
            for b in 0..texts.get(id).map_or(1, |t| t.len() + 2) {
                assert_eq!(
                    format!("{:?}", ours.line_index(id, b)),
                    format!("{:?}", theirs.line_index(id, b))
                );
                assert_eq!(
                    format!("{:?}", ours.location(id, b)),
                    format!("{:?}", theirs.location(id, b))
                );
            }
            for l in 0..8 {
                assert_eq!(
                    format!("{:?}", ours.line_range(id, l)),
                    format!("{:?}", theirs.line_range(id, l))
                );
            }
        }
    }
}
