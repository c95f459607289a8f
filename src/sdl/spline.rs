//! Splines in the scene language: `spline { [Other] [type] t, <v>, ... }` and calls
//! `S(t [, type])`. The evaluation (fitted to POV-Ray 3.7's output) is in [`crate::func::spline`],
//! shared with spline functions.

use std::rc::Rc;

pub use crate::func::spline::{SplineDef, SplineKind};

use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};
use super::source::Span;
use super::value::Value;

impl Parser {
    /// `spline { ... }` after the keyword.
    pub(super) fn parse_spline(&mut self, span: Span) -> PResult<Value> {
        Ok(Value::Spline(Rc::new(self.parse_spline_def(span)?)))
    }

    /// The spline itself, for a value or a spline function.
    pub(super) fn parse_spline_def(&mut self, span: Span) -> PResult<SplineDef> {
        self.expect_sym(Sym::LBrace, "after 'spline'")?;
        let mut s = SplineDef::new(SplineKind::Linear);
        // A point with fewer components than an earlier one keeps that one's extra components:
        // POV-Ray 3.7.0 gives `0,<0,0,1> 1,<1,2>` the second point <1,2,1>.
        let mut carry = [0.0; 5];
        loop {
            let t = self.peek()?.ok_or_else(|| self.eof_error())?;
            match &t.tok {
                Tok::Sym(Sym::RBrace) => {
                    self.advance();
                    break;
                }
                Tok::Ident(k) if SplineKind::from_keyword(k).is_some() => {
                    self.advance();
                    s.kind = SplineKind::from_keyword(k).expect("checked");
                }
                Tok::Ident(k) if matches!(self.lookup(k), Some(Value::Spline(_))) => {
                    if let Some(Value::Spline(o)) = self.lookup(k) {
                        s = (**o).clone();
                    }
                    self.advance();
                }
                _ => {
                    let tv = self.parse_float()?;
                    self.expect_sym(Sym::Comma, "after the spline parameter")?;
                    let vspan = self.next_span()?;
                    let (c, n) = match self.parse_expr()? {
                        Value::Float(f) => ([f; 5], 1),
                        Value::Vector(c, n) => (c, n),
                        Value::Color(c) => (c.to_array(), 5),
                        other => {
                            return Err(self.error_at(
                                vspan,
                                format!(
                                    "a spline point must be a vector, found a {}",
                                    other.type_name()
                                ),
                            ))
                        }
                    };
                    carry[..n as usize].copy_from_slice(&c[..n as usize]);
                    s.insert(tv, carry, n);
                    self.eat_sym(Sym::Comma)?;
                }
            }
        }
        if s.points.is_empty() {
            return Err(self.error_at(span, "a spline needs at least one point"));
        }
        Ok(s)
    }

    /// `S(t)` or `S(t, spline_type)` with the spline identifier consumed.
    pub(super) fn call_spline(&mut self, s: Rc<SplineDef>, name: &str) -> PResult<Value> {
        self.expect_sym_with(Sym::LParen, || format!("after the spline {name}"))?;
        let t = self.with_rel(false, |p| p.parse_float())?;
        let mut kind = s.kind;
        if self.eat_sym(Sym::Comma)? {
            let tk = self.next_tok()?;
            kind = match &tk.tok {
                Tok::Ident(k) => SplineKind::from_keyword(k),
                _ => None,
            }
            .ok_or_else(|| {
                self.error_at(
                    tk.span,
                    format!("expected a spline type (linear_spline, quadratic_spline, cubic_spline or natural_spline), found {}", tk.tok),
                )
            })?;
        }
        self.expect_sym(Sym::RParen, "to close the spline call")?;
        Ok(Value::Vector(s.eval(t, kind), s.dim.max(2)))
    }
}
