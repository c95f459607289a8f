//! Turns scene text into tokens with byte spans, using nom combinators.
//!
//! The lexer knows no symbols: keywords and identifiers are both `Ident`, and directives are
//! `Directive` tokens that the parser executes when it meets them. Comments (`//`, nested
//! `/* */`) vanish here.

use nom::branch::alt;
use nom::bytes::complete::{tag, take_while, take_while1};
use nom::character::complete::{char, digit0, digit1, one_of};
use nom::combinator::{opt, recognize};
use nom::sequence::{pair, tuple};
use nom::IResult;

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

pub fn lex(text: &str, file: u32) -> Result<Vec<Token>, LexError> {
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
            if !t.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_') {
                rest = after;
                continue;
            }
        }
        let start = text.len() - rest.len();
        let (next, tok) = token(rest).map_err(|_| {
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
        })?;
        let tok = match tok {
            Tok::Str(raw) => Tok::Str(
                unescape(&raw)
                    .map_err(|m| LexError {
                        message: m,
                        start,
                        end: start + 1,
                    })?
                    .into(),
            ),
            t => t,
        };
        let end = text.len() - next.len();
        let bulk_kind = match &tok {
            Tok::Ident(name) => super::bulk::list_kind(name),
            _ => None,
        };
        let span = |start: usize, end: usize| Span {
            file,
            start: start as u32,
            end: end as u32,
        };
        out.push(Token {
            tok,
            span: span(start, end),
        });
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
    match number(s) {
        Ok((rest, Tok::Num(v))) => Some((v, rest)),
        _ => None,
    }
}

/// Skips white space and comments; an unclosed block comment is an error at its start.
fn skip_trivia(mut s: &str, total: usize) -> Result<&str, LexError> {
    loop {
        s = s.trim_start();
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

fn token(s: &str) -> IResult<&str, Tok> {
    alt((number, string, ident, directive, symbol))(s)
}

fn number(s: &str) -> IResult<&str, Tok> {
    let exponent = tuple((one_of("eE"), opt(one_of("+-")), digit1));
    let mantissa = alt((
        recognize(tuple((digit1, opt(pair(char('.'), digit0))))),
        recognize(pair(char('.'), digit1)),
    ));
    let (rest, text) = recognize(pair(mantissa, opt(exponent)))(s)?;
    Ok((rest, Tok::Num(text.parse().unwrap_or(0.0))))
}

fn string(s: &str) -> IResult<&str, Tok> {
    let (r, _) = char('"')(s)?;
    let b = r.as_bytes();
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'\\' => i += 2,
            b'"' => return Ok((&r[i + 1..], Tok::Str(r[..i].into()))),
            // POV-Ray strings may run over several lines (shapes3.inc's #warning texts).
            _ => i += 1,
        }
    }
    Err(nom::Err::Error(nom::error::Error::new(
        s,
        nom::error::ErrorKind::Char,
    )))
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

fn is_ident_start(c: char) -> bool {
    c.is_ascii_alphabetic() || c == '_'
}

fn is_ident_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

fn ident(s: &str) -> IResult<&str, Tok> {
    let (r, text) = recognize(pair(take_while1(is_ident_start), take_while(is_ident_char)))(s)?;
    Ok((r, Tok::Ident(text.into())))
}

fn directive(s: &str) -> IResult<&str, Tok> {
    let (r, _) = char('#')(s)?;
    let r = r.trim_start_matches([' ', '\t']);
    let (r, Tok::Ident(name)) = ident(r)? else {
        unreachable!()
    };
    Ok((r, Tok::Directive(name)))
}

fn symbol(s: &str) -> IResult<&str, Tok> {
    let two = alt((tag("<="), tag(">="), tag("!=")));
    let (r, text) = alt((two, recognize(one_of("{}()[]<>=,;+-*/.:?!&|"))))(s)?;
    use Sym::*;
    let sym = match text {
        "<=" => Le,
        ">=" => Ge,
        "!=" => Ne,
        "{" => LBrace,
        "}" => RBrace,
        "(" => LParen,
        ")" => RParen,
        "[" => LBracket,
        "]" => RBracket,
        "<" => Lt,
        ">" => Gt,
        "=" => Eq,
        "," => Comma,
        ";" => Semi,
        "+" => Plus,
        "-" => Minus,
        "*" => Star,
        "/" => Slash,
        "." => Dot,
        ":" => Colon,
        "?" => Question,
        "!" => Bang,
        "&" => And,
        _ => Or,
    };
    Ok((r, Tok::Sym(sym)))
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
