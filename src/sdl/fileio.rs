//! File I/O directives: `#fopen`, `#fclose`, `#read`, `#write`, and the rule that keeps them
//! inside the directories a scene may touch.
//!
//! Behaviour measured with POV-Ray 3.7.0:
//! - `#write` writes strings as they are, floats as C's `%g`, vectors as `<%g,%g,%g> ` (with a
//!   trailing space); `uint8`, `sint16le`, ... before an item write that one item as binary.
//! - `#read` takes string, float and vector literals (signs and exponents allowed) separated by
//!   commas. After each value it consumes one more token, which should be a comma; when that
//!   token is the end of the file the value is dropped, the file is closed and its handle
//!   identifier is undefined, so `#while (defined(F))` ends. A non-comma token there is lost.
//!
//! Scenes may only read and write below the scene file's directory and the current working
//! directory (reads may also use the library paths), unless `ParseOptions::io_unrestricted`
//! is set or the directory is listed in `ParseOptions::io_allowed_dirs` or permitted by
//! povray.conf (`ParseOptions::io_permits`, `io_read_anywhere`; see config.rs).

use std::collections::HashMap;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::rc::Rc;

use super::lexer::{lex, Sym, Tok, Token};
use super::parser::{PResult, Parser};
use super::source::Span;
use super::value::Value;

pub enum OpenFile {
    Read { tokens: Vec<Token>, pos: usize },
    Write(std::io::BufWriter<std::fs::File>),
}

/// Open files by handle identifier.
pub type Files = HashMap<Rc<str>, OpenFile>;

/// C's `%g`: six significant digits, exponent form below 1e-4 or from 1e6, no trailing zeros.
pub fn format_g(v: f64) -> String {
    if !v.is_finite() {
        return if v.is_nan() {
            "nan".into()
        } else if v > 0.0 {
            "inf".into()
        } else {
            "-inf".into()
        };
    }
    if v == 0.0 {
        return if v.is_sign_negative() { "-0" } else { "0" }.into();
    }
    // The exponent after rounding to six significant digits decides the form.
    let sci = format!("{v:.5e}");
    let (mant, exp) = sci.split_once('e').expect("exponent form");
    let exp: i32 = exp.parse().unwrap_or(0);
    let trim = |s: &str| -> String {
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s.to_string()
        }
    };
    if !(-4..6).contains(&exp) {
        let sign = if exp < 0 { '-' } else { '+' };
        format!("{}e{sign}{:02}", trim(mant), exp.abs())
    } else {
        let decimals = (5 - exp).max(0) as usize;
        trim(&format!("{v:.decimals$}"))
    }
}

fn binary_word(kind: &str, v: f64) -> Option<Vec<u8>> {
    let r = v.round();
    let clamp = |lo: f64, hi: f64| r.clamp(lo, hi);
    Some(match kind {
        "uint8" => vec![clamp(0.0, 255.0) as u8],
        "sint8" => vec![clamp(-128.0, 127.0) as i8 as u8],
        "uint16be" => (clamp(0.0, 65535.0) as u16).to_be_bytes().to_vec(),
        "uint16le" => (clamp(0.0, 65535.0) as u16).to_le_bytes().to_vec(),
        "sint16be" => (clamp(-32768.0, 32767.0) as i16).to_be_bytes().to_vec(),
        "sint16le" => (clamp(-32768.0, 32767.0) as i16).to_le_bytes().to_vec(),
        "sint32be" => (clamp(i32::MIN as f64, i32::MAX as f64) as i32)
            .to_be_bytes()
            .to_vec(),
        "sint32le" => (clamp(i32::MIN as f64, i32::MAX as f64) as i32)
            .to_le_bytes()
            .to_vec(),
        _ => return None,
    })
}

impl Parser {
    /// Whether `path` (absolute, resolved) lies where the scene may read or write.
    fn io_permitted(&self, path: &Path, write: bool) -> bool {
        if self.options.io_unrestricted || (!write && self.options.io_read_anywhere) {
            return true;
        }
        let permitted = self.options.io_permits.iter().any(|p| {
            (p.write || !write)
                && p.dir.canonicalize().is_ok_and(|d| {
                    if p.subdirs {
                        path.starts_with(&d)
                    } else {
                        path.parent() == Some(d.as_path())
                    }
                })
        });
        if permitted {
            return true;
        }
        let mut roots: Vec<PathBuf> = vec![self.scene_dir.clone(), PathBuf::from(".")];
        roots.extend(self.options.io_allowed_dirs.iter().cloned());
        if !write {
            roots.extend(self.options.library_paths.iter().cloned());
            roots.extend(super::parser::SYSTEM_INCLUDE_DIRS.iter().map(PathBuf::from));
        }
        roots
            .iter()
            .filter_map(|r| r.canonicalize().ok())
            .any(|r| path.starts_with(r))
    }

    /// Resolves and checks a path for `#fopen`.
    fn io_path(&self, name: &str, write: bool, span: Span) -> PResult<PathBuf> {
        let path = if write {
            let p = Path::new(name);
            let parent = match p.parent() {
                Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
                _ => PathBuf::from("."),
            };
            let dir = parent.canonicalize().map_err(|e| {
                self.error_at(
                    span,
                    format!(
                        "cannot open \"{name}\" for writing: {}: {e}",
                        parent.display()
                    ),
                )
            })?;
            dir.join(p.file_name().unwrap_or_default())
        } else {
            let found = self.find_file(name).ok_or_else(|| {
                self.error_at(span, format!("cannot open \"{name}\" for reading: no such file in the scene directory, the current directory or the library path"))
            })?;
            found.canonicalize().unwrap_or(found)
        };
        if !self.io_permitted(&path, write) {
            let what = if write { "write" } else { "read" };
            let d = *self.error_at(
                span,
                format!(
                    "#fopen may not {what} {}: scenes may only {what} files below the scene's directory and the current directory",
                    path.display()
                ),
            );
            return Err(Box::new(d.with_note(
                "more directories can be allowed with ParseOptions::io_allowed_dirs, or all with io_unrestricted",
            )));
        }
        Ok(path)
    }

    /// `#fopen Id "name" read|write|append`.
    pub(super) fn fopen_directive(&mut self, span: Span) -> PResult<()> {
        let id = self.raw_ident("as the file handle after #fopen")?;
        let name = self.parse_string()?;
        let mode_t = self.next_tok()?;
        let mode = match &mode_t.tok {
            Tok::Ident(m) if matches!(&**m, "read" | "write" | "append") => m.clone(),
            other => {
                return Err(self.error_at(
                    mode_t.span,
                    format!("expected read, write or append after the file name, found {other}"),
                ))
            }
        };
        let path = self.io_path(&name, &*mode != "read", span)?;
        let file = if &*mode == "read" {
            let bytes = std::fs::read(&path)
                .map_err(|e| self.error_at(span, format!("cannot read {}: {e}", path.display())))?;
            let text = super::parser::utf8_text(bytes);
            let sid = self.sources.add(path.display().to_string(), text);
            let tokens = lex(self.sources.text(sid), sid).map_err(|e| {
                let s = Span {
                    file: sid,
                    start: e.start as u32,
                    end: e.end as u32,
                };
                self.error_at(s, format!("in a file opened with #fopen: {}", e.message))
            })?;
            OpenFile::Read { tokens, pos: 0 }
        } else {
            let f = std::fs::OpenOptions::new()
                .create(true)
                .write(true)
                .append(&*mode == "append")
                .truncate(&*mode == "write")
                .open(&path)
                .map_err(|e| {
                    self.error_at(
                        span,
                        format!("cannot open {} for writing: {e}", path.display()),
                    )
                })?;
            OpenFile::Write(std::io::BufWriter::new(f))
        };
        self.files.insert(id.clone(), file);
        self.built_objects.forget(&id);
        self.scopes[0].insert(id.clone(), Value::File(id));
        Ok(())
    }

    /// `#fclose Id`; closing a handle already closed by the end of a `#read` is allowed.
    pub(super) fn fclose_directive(&mut self, span: Span) -> PResult<()> {
        let id = self.raw_ident("after #fclose")?;
        match self.lookup(&id) {
            Some(Value::File(_)) | None => {}
            Some(other) => {
                return Err(self.error_at(
                    span,
                    format!(
                        "#fclose needs a file handle, '{id}' is a {}",
                        other.type_name()
                    ),
                ))
            }
        }
        self.close_file(&id, span)
    }

    fn close_file(&mut self, id: &Rc<str>, span: Span) -> PResult<()> {
        if let Some(OpenFile::Write(mut w)) = self.files.remove(id) {
            w.flush()
                .map_err(|e| self.error_at(span, format!("cannot write the file '{id}': {e}")))?;
        }
        self.built_objects.forget(id);
        self.scopes[0].remove(id);
        Ok(())
    }

    /// The open file a handle argument names.
    fn handle(&mut self, what: &str) -> PResult<Rc<str>> {
        self.expect_sym_with(Sym::LParen, || format!("after #{what}"))?;
        let t = self.raw_peek()?.ok_or_else(|| self.eof_error())?;
        let id = self.raw_ident(&format!("as the file handle in #{what}"))?;
        if !self.files.contains_key(&id) {
            return Err(self.error_at(
                t.span,
                format!(
                    "'{id}' is not an open file: open it with #fopen {id} \"name\" {}",
                    if what == "read" { "read" } else { "write" }
                ),
            ));
        }
        Ok(id)
    }

    /// `#write (Id, items...)`.
    pub(super) fn write_directive(&mut self, _span: Span) -> PResult<()> {
        let id = self.handle("write")?;
        let mut out: Vec<u8> = Vec::new();
        // Commas between items are optional to POV-Ray 3.7.0 (`#write (F "a" 1)`).
        loop {
            self.eat_sym(Sym::Comma)?;
            if self.peek_sym()? == Some(Sym::RParen) {
                break;
            }
            let mut binary = None;
            if let Some(k) = self.peek_ident()? {
                if binary_word(&k, 0.0).is_some() {
                    self.advance();
                    binary = Some(k);
                }
            }
            let vspan = self.next_span()?;
            let v = self.parse_expr()?;
            match (&v, &binary) {
                (Value::Str(s), None) => out.extend_from_slice(s.as_bytes()),
                (Value::Float(f), None) => out.extend_from_slice(format_g(*f).as_bytes()),
                (Value::Vector(c, n), None) => {
                    let parts: Vec<String> =
                        c[..*n as usize].iter().map(|&x| format_g(x)).collect();
                    out.extend_from_slice(format!("<{}> ", parts.join(",")).as_bytes());
                }
                (v, Some(k)) if v.components().is_some() => {
                    let (c, n) = v.components().expect("checked");
                    for x in &c[..n as usize] {
                        out.extend(binary_word(k, *x).expect("checked"));
                    }
                }
                (other, _) => {
                    return Err(self.error_at(
                        vspan,
                        format!(
                            "#write takes strings, floats and vectors, found a {}",
                            other.type_name()
                        ),
                    ))
                }
            }
        }
        self.expect_sym(Sym::RParen, "to close #write")?;
        let Some(OpenFile::Write(w)) = self.files.get_mut(&id) else {
            return Err(self.error_at(_span, format!("'{id}' was opened for reading, not writing")));
        };
        let r = w.write_all(&out);
        r.map_err(|e| self.error_at(_span, format!("cannot write the file '{id}': {e}")))
    }

    /// `#read (Id, Var, ...)`.
    pub(super) fn read_directive(&mut self, span: Span) -> PResult<()> {
        let id = self.handle("read")?;
        let mut targets = Vec::new();
        loop {
            self.eat_sym(Sym::Comma)?;
            if self.raw_peek_sym()? == Some(Sym::RParen) {
                break;
            }
            targets.push(self.raw_ident_or_element("to read into")?);
        }
        self.expect_sym(Sym::RParen, "to close #read")?;
        if !matches!(self.files.get(&id), Some(OpenFile::Read { .. })) {
            return Err(self.error_at(span, format!("'{id}' was opened for writing, not reading")));
        }
        for (name, elem) in targets {
            let Some((v, last)) = self.read_value(&id)? else {
                return self.close_file(&id, span);
            };
            match elem {
                Some(p) => self.set_element(&p, Some(v))?,
                None => self.assign_var(name, v, false)?,
            }
            // The file's last item, with no comma after it, is read and the file closed at
            // once (POV-Ray reads "1,2,3" as three values, and a loop on defined() stops).
            if last {
                return self.close_file(&id, span);
            }
        }
        Ok(())
    }

    /// One data item and the comma after it, with whether it was the file's last; `None` at
    /// the end of the file.
    fn read_value(&mut self, id: &Rc<str>) -> PResult<Option<(Value, bool)>> {
        let Some(OpenFile::Read { tokens, pos }) = self.files.get_mut(id) else {
            return Ok(None);
        };
        let mut next = || {
            let t = tokens.get(*pos).cloned();
            *pos += 1;
            t
        };
        let num = |first: Token, next: &mut dyn FnMut() -> Option<Token>| -> Result<f64, Token> {
            let mut sign = 1.0;
            let mut t = first;
            loop {
                match &t.tok {
                    Tok::Sym(Sym::Minus) => sign = -sign,
                    Tok::Sym(Sym::Plus) => {}
                    Tok::Num(n) => return Ok(sign * n),
                    _ => return Err(t),
                }
                match next() {
                    Some(n) => t = n,
                    None => return Err(t),
                }
            }
        };
        let Some(first) = next() else { return Ok(None) };
        let bad = |t: &Token| {
            (
                t.span,
                format!(
                    "#read expects a string, float or vector literal in the file, found {}",
                    t.tok
                ),
            )
        };
        let v = match &first.tok {
            Tok::Str(s) => Ok(Value::Str(s.clone())),
            Tok::Sym(Sym::Lt) => {
                let mut c = [0.0; 5];
                let mut n = 0;
                let mut r = Ok(());
                loop {
                    let Some(t) = next() else { return Ok(None) };
                    match num(t, &mut next) {
                        Ok(x) if n < 5 => {
                            c[n] = x;
                            n += 1;
                        }
                        Ok(_) => r = Err((first.span, "a vector has at most 5 components".into())),
                        Err(t) => {
                            r = Err(bad(&t));
                            break;
                        }
                    }
                    match next() {
                        Some(Token {
                            tok: Tok::Sym(Sym::Comma),
                            ..
                        }) => {}
                        Some(Token {
                            tok: Tok::Sym(Sym::Gt),
                            ..
                        }) => break,
                        Some(t) => {
                            r = Err(bad(&t));
                            break;
                        }
                        None => return Ok(None),
                    }
                }
                r.and_then(|_| {
                    if n < 2 {
                        Err((first.span, "a vector needs at least 2 components".into()))
                    } else {
                        Ok(Value::Vector(c, n as u8))
                    }
                })
            }
            _ => num(first.clone(), &mut next)
                .map(Value::Float)
                .map_err(|t| bad(&t)),
        };
        let after = next();
        match v {
            Err((s, m)) => Err(self.error_at(s, m)),
            Ok(v) => Ok(Some((v, after.is_none()))),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Values POV-Ray 3.7.0 wrote with #write.
    #[test]
    fn g_format_matches_printf() {
        assert_eq!(format_g(1.5), "1.5");
        assert_eq!(format_g(-2.0), "-2");
        assert_eq!(format_g(1.0 / 3.0), "0.333333");
        assert_eq!(format_g(1e20), "1e+20");
        assert_eq!(format_g(123456789.0), "1.23457e+08");
        assert_eq!(format_g(0.000001234), "1.234e-06");
        assert_eq!(format_g(0.0001), "0.0001");
        assert_eq!(format_g(999999.5), "1e+06");
        assert_eq!(format_g(100000.0), "100000");
    }

    #[test]
    fn binary_words_clamp_and_order_bytes() {
        assert_eq!(binary_word("uint8", 300.0), Some(vec![255]));
        assert_eq!(binary_word("sint8", -1.0), Some(vec![0xff]));
        assert_eq!(binary_word("sint16le", 258.0), Some(vec![2, 1]));
        assert_eq!(binary_word("uint16be", 258.0), Some(vec![1, 2]));
        assert_eq!(binary_word("float", 1.0), None);
    }
}
