//! String built-ins (`str`, `vstr`, `substr`, `strupr`, `strlwr`, `strlen`, `strcmp`, `val`,
//! `asc`, `chr`, `concat`, `file_exists`) and the one hook through which the language-level
//! built-ins reach the expression parser: spline calls, `dimensions`, `dimension_size` and
//! `defined`.
//!
//! Formatting follows C's printf, as POV-Ray 3.7.0 does (checked with its `#debug` output):
//! `str(A, L, P)` is `%L.Pf`, zero-padded after the sign when L is negative, six decimals when
//! P is negative, ties rounded to even on the exact binary value. `vstr` formats each of N
//! components (N clipped to 2..5) the same way; a float given as the vector fills only the
//! first component.

use std::rc::Rc;

use super::lexer::Sym;
use super::parser::{PResult, Parser};
use super::source::Span;
use super::value::Value;

/// Longest string a scene may build; longer ones are surely runaway loops.
pub const MAX_STRING_LEN: usize = 1 << 24;
/// Widest `str()` field honoured.
const MAX_STR_WIDTH: usize = 1000;
/// printf precision beyond this only pads zeros; capped to keep strings bounded.
const MAX_PRECISION: i64 = 300;

/// `str(v, l, p)` as POV-Ray formats it.
pub fn format_float(v: f64, l: i64, p: i64) -> String {
    let p = if p < 0 {
        6
    } else {
        p.min(MAX_PRECISION) as usize
    };
    // Rust's formatter panics on widths past 65535 (found by fuzzing); no scene needs more
    // than a screenful of padding.
    let w = (l.unsigned_abs() as usize).min(MAX_STR_WIDTH);
    if !v.is_finite() {
        let s = if v.is_nan() {
            "nan".to_string()
        } else if v > 0.0 {
            "inf".to_string()
        } else {
            "-inf".to_string()
        };
        return format!("{s:>w$}");
    }
    if l < 0 {
        format!("{v:0w$.p$}")
    } else {
        format!("{v:w$.p$}")
    }
}

/// C's strtod on the longest prefix that reads as a number; 0 when none does.
pub fn parse_val(s: &str) -> f64 {
    let s = s.trim_start();
    let b = s.as_bytes();
    let mut i = 0;
    if i < b.len() && (b[i] == b'+' || b[i] == b'-') {
        i += 1;
    }
    let digits_start = i;
    while i < b.len() && b[i].is_ascii_digit() {
        i += 1;
    }
    if i < b.len() && b[i] == b'.' {
        i += 1;
        while i < b.len() && b[i].is_ascii_digit() {
            i += 1;
        }
    }
    if i == digits_start || (i == digits_start + 1 && b[digits_start] == b'.') {
        return 0.0;
    }
    let mant_end = i;
    if i < b.len() && (b[i] == b'e' || b[i] == b'E') {
        let mut j = i + 1;
        if j < b.len() && (b[j] == b'+' || b[j] == b'-') {
            j += 1;
        }
        if j < b.len() && b[j].is_ascii_digit() {
            while j < b.len() && b[j].is_ascii_digit() {
                j += 1;
            }
            i = j;
        }
    }
    s[..i]
        .parse()
        .or_else(|_| s[..mant_end].parse())
        .unwrap_or(0.0)
}

/// C's strcmp: the difference of the first differing bytes, 0 when equal.
pub fn strcmp(a: &str, b: &str) -> f64 {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    for i in 0..a.len().max(b.len()) {
        let x = a.get(i).copied().unwrap_or(0) as i32;
        let y = b.get(i).copied().unwrap_or(0) as i32;
        if x != y {
            return (x - y) as f64;
        }
    }
    0.0
}

impl Parser {
    /// Built-ins handled by the language modules (for a name no identifier holds); `None` when
    /// `k` is none of them.
    pub(super) fn lang_ident_value(&mut self, k: &Rc<str>, span: Span) -> PResult<Option<Value>> {
        let v = match &**k {
            "dimensions" | "dimension_size" => self.array_function(k, span)?,
            "defined" => {
                self.expect_sym(Sym::LParen, "after defined")?;
                let (name, elem) = self.raw_ident_or_element("in defined()")?;
                self.expect_sym(Sym::RParen, "to close defined()")?;
                Value::Float(self.is_defined(&name, &elem) as u8 as f64)
            }
            "str" | "vstr" | "substr" | "strupr" | "strlwr" | "strlen" | "str_len" | "strcmp"
            | "val" | "asc" | "chr" | "concat" | "file_exists" => self.string_function(k, span)?,
            "input_file_name" => {
                let name = self
                    .frames
                    .first()
                    .and_then(|f| f.tokens.first())
                    .map(|t| self.sources.name(t.span.file))
                    .unwrap_or_default();
                Value::Str(name.into())
            }
            "datetime" => self.string_function(k, span)?,
            _ => return Ok(None),
        };
        Ok(Some(v))
    }

    pub(super) fn string_function(&mut self, name: &str, span: Span) -> PResult<Value> {
        let args = self.call_args(name)?;
        let want = |p: &Parser, n: usize| -> PResult<()> {
            if args.len() == n {
                Ok(())
            } else {
                Err(p.error_at(
                    span,
                    format!("{name} takes {n} argument(s), {} given", args.len()),
                ))
            }
        };
        let fl = |p: &Parser, i: usize| p.float_of(args[i].0.clone(), args[i].1);
        let st = |p: &Parser, i: usize| -> PResult<Rc<str>> {
            match &args[i].0 {
                Value::Str(s) => Ok(s.clone()),
                o => Err(p.error_at(
                    args[i].1,
                    format!("{name} needs a string here, found a {}", o.type_name()),
                )),
            }
        };
        let out = match name {
            "datetime" => {
                if args.is_empty() || args.len() > 2 {
                    return Err(self.error_at(span, "datetime takes 1 or 2 arguments"));
                }
                let days = fl(self, 0)?;
                let format = if args.len() == 2 {
                    st(self, 1)?
                } else {
                    "%Y-%m-%d %H:%M:%SZ".into()
                };
                match datetime(days, &format) {
                    Some(s) => Value::Str(s.into()),
                    None => {
                        return Err(self.error_at(
                            span,
                            format!("datetime cannot format {days} days with \"{format}\""),
                        ))
                    }
                }
            }
            "str" => {
                want(self, 3)?;
                let (v, l, p) = (fl(self, 0)?, fl(self, 1)?, fl(self, 2)?);
                Value::Str(format_float(v, l as i64, p as i64).into())
            }
            "vstr" => {
                want(self, 5)?;
                let n = (fl(self, 0)? as i64).clamp(2, 5) as usize;
                let c = match &args[1].0 {
                    Value::Float(f) => [*f, 0.0, 0.0, 0.0, 0.0],
                    Value::Vector(c, k) => super::expr::pad((*c, *k)),
                    Value::Color(c) => c.to_array(),
                    o => {
                        return Err(self.error_at(
                            args[1].1,
                            format!("vstr needs a vector, found a {}", o.type_name()),
                        ))
                    }
                };
                let sep = st(self, 2)?;
                let (l, p) = (fl(self, 3)? as i64, fl(self, 4)? as i64);
                let parts: Vec<String> = c[..n].iter().map(|&x| format_float(x, l, p)).collect();
                Value::Str(parts.join(&sep).into())
            }
            "substr" => {
                want(self, 3)?;
                let s = st(self, 0)?;
                let (p, l) = (fl(self, 1)?.trunc(), fl(self, 2)?.trunc());
                let chars: Vec<char> = s.chars().collect();
                if p < 1.0 || l < 0.0 || p + l - 1.0 > chars.len() as f64 {
                    return Err(self.error_at(
                        span,
                        format!(
                            "substr({p}, {l}) is outside the string of length {}: the start counts from 1 and start + length - 1 may not pass the end",
                            chars.len()
                        ),
                    ));
                }
                let p = p as usize - 1;
                Value::Str(chars[p..p + l as usize].iter().collect::<String>().into())
            }
            "strupr" | "strlwr" => {
                want(self, 1)?;
                let s = st(self, 0)?;
                Value::Str(if name == "strupr" {
                    s.to_ascii_uppercase().into()
                } else {
                    s.to_ascii_lowercase().into()
                })
            }
            "strlen" | "str_len" => {
                want(self, 1)?;
                Value::Float(st(self, 0)?.chars().count() as f64)
            }
            "strcmp" => {
                want(self, 2)?;
                Value::Float(strcmp(&st(self, 0)?, &st(self, 1)?))
            }
            "val" => {
                want(self, 1)?;
                Value::Float(parse_val(&st(self, 0)?))
            }
            "asc" => {
                want(self, 1)?;
                Value::Float(st(self, 0)?.chars().next().map_or(0.0, |c| c as u32 as f64))
            }
            "chr" => {
                want(self, 1)?;
                let c = fl(self, 0)?;
                let ch = (c >= 0.0).then(|| char::from_u32(c as u32)).flatten();
                let Some(ch) = ch else {
                    return Err(
                        self.error_at(args[0].1, format!("chr({c}) is not a character code"))
                    );
                };
                Value::Str(ch.to_string().into())
            }
            "concat" => {
                if args.is_empty() {
                    return Err(self.error_at(span, "concat needs at least one string"));
                }
                let mut s = String::new();
                for i in 0..args.len() {
                    s.push_str(&st(self, i)?);
                }
                Value::Str(s.into())
            }
            _ => {
                want(self, 1)?;
                let s = st(self, 0)?;
                Value::Float(self.find_file(&s).is_some() as u8 as f64)
            }
        };
        if let Value::Str(s) = &out {
            if s.len() > MAX_STRING_LEN {
                return Err(self.error_at(
                    span,
                    format!("{name} would make a string of {} bytes; lancer allows at most {MAX_STRING_LEN}", s.len()),
                ));
            }
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Values from POV-Ray 3.7.0 and the manual.
    #[test]
    fn str_matches_povray() {
        assert_eq!(format_float(123.456, 0, 3), "123.456");
        assert_eq!(format_float(123.456, 9, 3), "  123.456");
        assert_eq!(format_float(123.456, -9, 3), "00123.456");
        assert_eq!(format_float(123.456, 0, 0), "123");
        assert_eq!(format_float(123.456, 0, -1), "123.456000");
        assert_eq!(format_float(-1.5, -8, 2), "-0001.50");
        assert_eq!(format_float(2.5, 0, 0), "2");
        assert_eq!(format_float(3.5, 0, 0), "4");
        assert_eq!(format_float(-0.0001, 0, 2), "-0.00");
        assert_eq!(format_float(1e20, 0, 2), "100000000000000000000.00");
    }

    #[test]
    fn val_reads_a_leading_number() {
        assert_eq!(parse_val("  12.5abc"), 12.5);
        assert_eq!(parse_val("abc"), 0.0);
        assert_eq!(parse_val("1e3"), 1000.0);
        assert_eq!(parse_val("-.5e"), -0.5);
        assert_eq!(parse_val("."), 0.0);
    }

    #[test]
    fn strcmp_is_c_strcmp() {
        assert_eq!(strcmp("abc", "abd"), -1.0);
        assert_eq!(strcmp("b", "a"), 1.0);
        assert_eq!(strcmp("abc", "abc"), 0.0);
        assert_eq!(strcmp("abcd", "abc"), 100.0);
    }
}

/// `datetime(days, format)`: days since 2000-01-01 00:00:00 UTC (what `now` gives) formatted
/// with strftime's conversions. `None` for a date out of range or a bad conversion, which
/// chrono reports as a formatting error rather than text.
fn datetime(days: f64, format: &str) -> Option<String> {
    use std::fmt::Write as _;
    let epoch = chrono::NaiveDate::from_ymd_opt(2000, 1, 1)?.and_hms_opt(0, 0, 0)?;
    let ms = days * 86_400_000.0;
    if !ms.is_finite() || ms.abs() > 1e15 {
        return None;
    }
    let t = epoch.checked_add_signed(chrono::TimeDelta::milliseconds(ms as i64))?;
    let mut out = String::new();
    write!(out, "{}", t.format(format)).ok()?;
    Some(out)
}

#[cfg(test)]
mod datetime_tests {
    #[test]
    fn formats_days_since_2000() {
        // The same strings as povray 3.7 prints for datetime(0) and datetime(366.5, "%Y-%m-%d %H:%M").
        assert_eq!(
            super::datetime(0.0, "%Y-%m-%d %H:%M:%SZ").unwrap(),
            "2000-01-01 00:00:00Z"
        );
        assert_eq!(
            super::datetime(366.5, "%Y-%m-%d %H:%M").unwrap(),
            "2001-01-01 12:00"
        );
        assert!(super::datetime(0.0, "%Q").is_none());
        assert!(super::datetime(f64::NAN, "%Y").is_none());
    }
}
