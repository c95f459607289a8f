//! Turns scene text into tokens with byte spans.
//!
//! The lexer knows no symbols: keywords and identifiers are both `Ident`, and directives are
//! `Directive` tokens that the parser executes when it meets them. Comments (`//`, nested
//! `/* */`) vanish here.

use super::source::Span;

#[derive(Clone, Debug, PartialEq)]
pub enum Tok {
    Num(f64),
    Str(std::rc::Rc<str>),
    Ident(std::rc::Rc<str>),
    /// `#name`, without the hash.
    Directive(std::rc::Rc<str>),
    Sym(Sym),
    /// The entries of a literal mesh2 list, between its braces (`super::bulk`).
    Bulk(std::rc::Rc<super::bulk::Bulk>),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sym {
    LBrace,
    RBrace,
    LParen,
    RParen,
    LBracket,
    RBracket,
    Lt,
    Gt,
    Le,
    Ge,
    Eq,
    Ne,
    Comma,
    Semi,
    Plus,
    Minus,
    Star,
    Slash,
    Dot,
    Colon,
    Question,
    Bang,
    And,
    Or,
}

impl Sym {
    pub fn text(self) -> &'static str {
        use Sym::*;
        match self {
            LBrace => "{",
            RBrace => "}",
            LParen => "(",
            RParen => ")",
            LBracket => "[",
            RBracket => "]",
            Lt => "<",
            Gt => ">",
            Le => "<=",
            Ge => ">=",
            Eq => "=",
            Ne => "!=",
            Comma => ",",
            Semi => ";",
            Plus => "+",
            Minus => "-",
            Star => "*",
            Slash => "/",
            Dot => ".",
            Colon => ":",
            Question => "?",
            Bang => "!",
            And => "&",
            Or => "|",
        }
    }
}

impl std::fmt::Display for Tok {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Tok::Num(n) => write!(f, "number {n}"),
            Tok::Str(s) => write!(f, "string \"{s}\""),
            Tok::Ident(s) => write!(f, "'{s}'"),
            Tok::Directive(s) => write!(f, "'#{s}'"),
            Tok::Sym(s) => write!(f, "'{}'", s.text()),
            Tok::Bulk(b) => write!(f, "a list of {} entries", b.vectors.len()),
        }
    }
}

#[derive(Clone, Debug)]
pub struct Token {
    pub tok: Tok,
    pub span: Span,
}

/// A lexing failure: message and the byte range it points at.
#[derive(Debug)]
pub struct LexError {
    pub message: String,
    pub start: usize,
    pub end: usize,
}

/// The names (identifiers, keywords, directive names) read so far, one allocation each: a
/// scene file names the same few hundred keywords and identifiers thousands of times, and its
/// include files name the same ones again. A set of `Rc<str>` looked up by `&str`, kept by the
/// parser for all its files: a map per file (from the text's `&str` to the `Rc`) allocated
/// every keyword again for each include and grew its table from empty each time.
pub type Names = rustc_hash::FxHashSet<std::rc::Rc<str>>;

pub fn lex(text: &str, file: u32) -> Result<Vec<Token>, LexError> {
    lex_with(text, file, &mut Names::default())
}

/// `lex`, sharing `names` with the other files of a parse.
pub fn lex_with(text: &str, file: u32, names: &mut Names) -> Result<Vec<Token>, LexError> {
    let mut out = Vec::with_capacity(text.len() / 4);
    let mut rest = text;
    loop {
        rest = skip_trivia(rest, text.len())?;
        if rest.is_empty() {
            return Ok(out);
        }
        // POV-Ray passes over a `#` that no directive name follows (`look_at <0,2,0>#` at the
        // end of a line in camera/spherical.pov).
        if let Some(after) = rest.strip_prefix('#') {
            let t = after.trim_start_matches([' ', '\t']);
            if !t.bytes().next().is_some_and(is_ident_start) {
                rest = after;
                continue;
            }
        }
        let start = text.len() - rest.len();
        let span = |start: usize, end: usize| Span {
            file,
            start: start as u32,
            end: end as u32,
        };
        let before = out.len();
        // `token` writes into this free slot (`put`).
        out.reserve(1);
        let next = token(rest, names, &mut out, |next: &str| {
            span(start, text.len() - next.len())
        })
        .ok_or_else(|| {
            let c = rest.chars().next().unwrap_or('?');
            LexError {
                message: if c == '"' {
                    "unterminated string: no closing '\"' before the end of the file".to_string()
                } else if c.is_control() || c == '\u{fffd}' {
                    format!(
                        "unexpected byte {:#04x}: this does not look like scene text",
                        c as u32
                    )
                } else {
                    format!("unexpected character '{c}'")
                },
                start,
                end: start + c.len_utf8(),
            }
        })?
        .map_err(|message| LexError {
            message,
            start,
            end: start + 1,
        })?;
        let bulk_kind = match out.get(before).map(|t| &t.tok) {
            Some(Tok::Ident(name)) => super::bulk::list_kind(name),
            _ => None,
        };
        rest = next;
        if let Some(kind) = bulk_kind {
            let Ok(at_brace) = skip_trivia(rest, text.len()) else {
                continue;
            };
            let Some(inner) = at_brace.strip_prefix('{') else {
                continue;
            };
            if let Some((bulk, close)) = super::bulk::scan(inner, kind) {
                let open = text.len() - at_brace.len();
                out.push(Token {
                    tok: Tok::Sym(Sym::LBrace),
                    span: span(open, open + 1),
                });
                out.push(Token {
                    tok: Tok::Bulk(bulk.into()),
                    span: span(open + 1, text.len() - close.len()),
                });
                rest = close;
            }
        }
    }
}

/// A number literal at the start of `s` as the lexer reads it, and the text after it.
pub(super) fn number_value(s: &str) -> Option<(f64, &str)> {
    number(s).map(|(rest, v)| (v, rest))
}

/// Skips white space and comments; an unclosed block comment is an error at its start.
fn skip_trivia(mut s: &str, total: usize) -> Result<&str, LexError> {
    loop {
        // ASCII white space byte by byte; `trim_start` for the rest (Unicode spaces).
        let ascii = s.bytes().take_while(u8::is_ascii_whitespace).count();
        s = s[ascii..].trim_start();
        if let Some(r) = s.strip_prefix("//") {
            s = r.find('\n').map_or("", |i| &r[i..]);
        } else if s.starts_with("/*") {
            let start = total - s.len();
            let mut depth = 0usize;
            let mut i = 0;
            let b = s.as_bytes();
            loop {
                if i + 1 >= b.len() {
                    return Err(LexError {
                        message: "unterminated comment: '/*' has no matching '*/'".into(),
                        start,
                        end: start + 2,
                    });
                }
                if b[i] == b'/' && b[i + 1] == b'*' {
                    depth += 1;
                    i += 2;
                } else if b[i] == b'*' && b[i + 1] == b'/' {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    i += 1;
                }
            }
            s = &s[i..];
        } else {
            return Ok(s);
        }
    }
}

/// Pushes the token at the start of `s` (which starts with no trivia) onto `out`, which has
/// room for it, and returns the text after it; `None` when no token starts there, `Some(Err)` for a string with a bad
/// escape. Dispatched on the first byte: every token kind starts with a byte of its own (a
/// number's `.` is followed by a digit, a symbol's is not), so this is the longest-match
/// reading the scene language needs, without trying each kind in turn. Each arm builds its
/// token where it is stored (`put`): a `Tok` returned and then moved into the vector was
/// copied through the stack piece by piece and read back whole, a store-forwarding stall on
/// every token.
fn token<'s>(
    s: &'s str,
    names: &mut Names,
    out: &mut Vec<Token>,
    span: impl Fn(&str) -> Span,
) -> Option<Result<&'s str, String>> {
    let b = s.as_bytes();
    match *b.first()? {
        b'0'..=b'9' => push_number(s, out, span),
        b'.' if b.get(1).is_some_and(u8::is_ascii_digit) => push_number(s, out, span),
        b'"' => {
            let (r, raw) = string(s)?;
            Some(unescape(raw).map(|text| {
                put(out, Tok::Str(text.into()), span(r));
                r
            }))
        }
        c if is_ident_start(c) => {
            let (r, text) = ident_text(s)?;
            put(out, Tok::Ident(name(names, text)), span(r));
            Some(Ok(r))
        }
        b'#' => {
            let r = s[1..].trim_start_matches([' ', '\t']);
            let (r, text) = ident_text(r)?;
            put(out, Tok::Directive(name(names, text)), span(r));
            Some(Ok(r))
        }
        _ => {
            let (r, sym) = symbol(s)?;
            put(out, Tok::Sym(sym), span(r));
            Some(Ok(r))
        }
    }
}

/// Appends a token to `out`, which the caller made room for. `Vec::push` keeps a path that
/// grows the vector (a call), so the token was built on the stack before the capacity test
/// and copied into the vector from there: 16-byte loads over its tag byte and 4-byte span
/// stores, two failed store forwards per token (~40 % of `lex`'s own samples in
/// DarkBlueSky_Axes's parse). Written into the spare slot, its fields go from registers
/// straight to the vector.
#[inline(always)]
fn put(out: &mut Vec<Token>, tok: Tok, span: Span) {
    let len = out.len();
    // Panics (never silently writes) if the caller did not reserve.
    out.spare_capacity_mut()[0].write(Token { tok, span });
    // SAFETY: slot `len` was just initialised and lies within the capacity.
    unsafe { out.set_len(len + 1) };
}

fn push_number<'s>(
    s: &'s str,
    out: &mut Vec<Token>,
    span: impl Fn(&str) -> Span,
) -> Option<Result<&'s str, String>> {
    let (r, v) = number(s)?;
    put(out, Tok::Num(v), span(r));
    Some(Ok(r))
}

fn name(names: &mut Names, text: &str) -> std::rc::Rc<str> {
    if let Some(n) = names.get(text) {
        return n.clone();
    }
    let n: std::rc::Rc<str> = text.into();
    names.insert(n.clone());
    n
}

/// The length of the run of ASCII digits at the start of `b`.
fn digits(b: &[u8]) -> usize {
    b.iter().take_while(|c| c.is_ascii_digit()).count()
}

/// `digits ['.' digits*] | '.' digits`, then an exponent `e [+-] digits` when it is complete
/// (`1e` is the number 1 and the identifier `e`).
fn number(s: &str) -> Option<(&str, f64)> {
    let b = s.as_bytes();
    let mut i = digits(b);
    if i > 0 {
        if b.get(i) == Some(&b'.') {
            i += 1 + digits(&b[i + 1..]);
        }
    } else {
        if b.first() != Some(&b'.') {
            return None;
        }
        let d = digits(&b[1..]);
        if d == 0 {
            return None;
        }
        i = 1 + d;
    }
    if matches!(b.get(i), Some(b'e' | b'E')) {
        let sign = usize::from(matches!(b.get(i + 1), Some(b'+' | b'-')));
        let d = digits(&b[i + 1 + sign..]);
        if d > 0 {
            i += 1 + sign + d;
        }
    }
    let (text, rest) = s.split_at(i);
    Some((rest, text.parse().unwrap_or(0.0)))
}

fn string(s: &str) -> Option<(&str, &str)> {
    let r = s.strip_prefix('"')?;
    let b = r.as_bytes();
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'\\' => i += 2,
            b'"' => return Some((&r[i + 1..], &r[..i])),
            // POV-Ray strings may run over several lines (shapes3.inc's #warning texts).
            _ => i += 1,
        }
    }
    None
}

fn unescape(raw: &str) -> Result<String, String> {
    let mut out = String::with_capacity(raw.len());
    let mut it = raw.chars();
    while let Some(c) = it.next() {
        if c != '\\' {
            out.push(c);
            continue;
        }
        match it.next() {
            Some('n') => out.push('\n'),
            Some('t') => out.push('\t'),
            Some('r') => out.push('\r'),
            Some('a') => out.push('\x07'),
            Some('b') => out.push('\x08'),
            Some('f') => out.push('\x0c'),
            Some('v') => out.push('\x0b'),
            Some('0') => out.push('\0'),
            Some('\\') => out.push('\\'),
            Some('"') => out.push('"'),
            Some('\'') => out.push('\''),
            // POV-Ray keeps an unknown escape as written (paths on Windows rely on it).
            Some(o) => {
                out.push('\\');
                out.push(o);
            }
            None => return Err("string ends with a lone backslash".into()),
        }
    }
    Ok(out)
}

fn is_ident_start(c: u8) -> bool {
    c.is_ascii_alphabetic() || c == b'_'
}

fn is_ident_char(c: u8) -> bool {
    c.is_ascii_alphanumeric() || c == b'_'
}

/// The identifier at the start of `s` and the text after it (ASCII letters, digits and `_`,
/// not starting with a digit).
fn ident_text(s: &str) -> Option<(&str, &str)> {
    let b = s.as_bytes();
    if !is_ident_start(*b.first()?) {
        return None;
    }
    let n = 1 + b[1..].iter().take_while(|&&c| is_ident_char(c)).count();
    let (text, rest) = s.split_at(n);
    Some((rest, text))
}

fn symbol(s: &str) -> Option<(&str, Sym)> {
    use Sym::*;
    let b = s.as_bytes();
    let two = match (b.first()?, b.get(1)) {
        (b'<', Some(b'=')) => Some(Le),
        (b'>', Some(b'=')) => Some(Ge),
        (b'!', Some(b'=')) => Some(Ne),
        _ => None,
    };
    if let Some(sym) = two {
        return Some((&s[2..], sym));
    }
    let sym = match b[0] {
        b'{' => LBrace,
        b'}' => RBrace,
        b'(' => LParen,
        b')' => RParen,
        b'[' => LBracket,
        b']' => RBracket,
        b'<' => Lt,
        b'>' => Gt,
        b'=' => Eq,
        b',' => Comma,
        b';' => Semi,
        b'+' => Plus,
        b'-' => Minus,
        b'*' => Star,
        b'/' => Slash,
        b'.' => Dot,
        b':' => Colon,
        b'?' => Question,
        b'!' => Bang,
        b'&' => And,
        b'|' => Or,
        _ => return None,
    };
    Some((&s[1..], sym))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn toks(s: &str) -> Vec<Tok> {
        lex(s, 0).unwrap().into_iter().map(|t| t.tok).collect()
    }

    #[test]
    fn numbers_and_symbols() {
        assert_eq!(
            toks("<1, .5, 2.e1> 3."),
            vec![
                Tok::Sym(Sym::Lt),
                Tok::Num(1.0),
                Tok::Sym(Sym::Comma),
                Tok::Num(0.5),
                Tok::Sym(Sym::Comma),
                Tok::Num(20.0),
                Tok::Sym(Sym::Gt),
                Tok::Num(3.0)
            ]
        );
    }

    /// The edges of the number grammar, read as the nom combinators this lexer replaced read
    /// them (checked token for token against them on every .pov/.inc file of POV-Ray 3.7's
    /// samples and includes, and on lancer's own scenes and tests).
    #[test]
    fn numbers_end_where_their_grammar_does() {
        use Sym::*;
        let id = |s: &str| Tok::Ident(s.into());
        assert_eq!(toks("1e"), vec![Tok::Num(1.0), id("e")]);
        assert_eq!(toks("1e+"), vec![Tok::Num(1.0), id("e"), Tok::Sym(Plus)]);
        assert_eq!(
            toks("1.e5 1E-3x"),
            vec![Tok::Num(1e5), Tok::Num(1e-3), id("x")]
        );
        assert_eq!(toks(".e5"), vec![Tok::Sym(Dot), id("e5")]);
        assert_eq!(toks("1..2"), vec![Tok::Num(1.0), Tok::Num(0.2)]);
        assert_eq!(toks("a.5"), vec![id("a"), Tok::Num(0.5)]);
        assert_eq!(toks("1abc"), vec![Tok::Num(1.0), id("abc")]);
        assert_eq!(toks("1e5.5"), vec![Tok::Num(1e5), Tok::Num(0.5)]);
        assert_eq!(
            toks("<=>=!=!|&"),
            vec![
                Tok::Sym(Le),
                Tok::Sym(Ge),
                Tok::Sym(Ne),
                Tok::Sym(Bang),
                Tok::Sym(Or),
                Tok::Sym(And)
            ]
        );
        assert_eq!(
            toks("# \t _y9 #x"),
            vec![Tok::Directive("_y9".into()), Tok::Directive("x".into())]
        );
        // A `#` with no name after it is passed over; a letter outside ASCII is no token.
        assert_eq!(toks("x# 5"), vec![id("x"), Tok::Num(5.0)]);
        assert!(lex("\u{e9}", 0)
            .unwrap_err()
            .message
            .contains("unexpected character"));
    }

    #[test]
    fn comments_nest_and_vanish() {
        assert_eq!(
            toks("a /* x /* y */ z */ b // c\n d"),
            vec![
                Tok::Ident("a".into()),
                Tok::Ident("b".into()),
                Tok::Ident("d".into())
            ]
        );
    }

    #[test]
    fn directives_and_strings() {
        assert_eq!(
            toks("# declare S=\"a\\\"b\""),
            vec![
                Tok::Directive("declare".into()),
                Tok::Ident("S".into()),
                Tok::Sym(Sym::Eq),
                Tok::Str("a\"b".into())
            ]
        );
    }

    #[test]
    fn errors_point_at_the_problem() {
        let e = lex("a \"open", 0).unwrap_err();
        assert_eq!(e.start, 2);
        let e = lex("x /* never closed", 0).unwrap_err();
        assert!(e.message.contains("unterminated comment"));
        let e = lex("sphere \u{1}", 0).unwrap_err();
        assert!(e.message.contains("does not look like scene text"));
    }
}
