//! `#switch`/`#case`/`#range`/`#else` and `#break`, with POV-Ray 3.7's fall-through rules.
//!
//! Measured with POV-Ray 3.7.0: tokens between `#switch` and the first clause are parsed; once a
//! clause matches, later `#case`/`#range`/`#else` markers are passed over without being
//! evaluated until `#break` or `#end`; a false clause skips to the next clause, and `#else`
//! after a false clause runs. `#case` values within 1e-10 of the switch value match. `#break`
//! leaves the innermost `#switch`, `#while` or `#for` even from inside a nested `#if`.

use std::rc::Rc;

use super::lexer::{Sym, Tok};
use super::parser::{Cond, PResult, Parser};
use super::source::Span;

/// Directives that open a block closed by `#end`, for skipping nested blocks.
fn opens_block(d: &str) -> bool {
    matches!(
        d,
        "if" | "ifdef" | "ifndef" | "while" | "for" | "switch" | "macro"
    )
}

/// POV-Ray compares `#case` values with this tolerance against round-off.
const CASE_EPSILON: f64 = 1e-10;

impl Parser {
    pub(super) fn switch_directive(&mut self, _span: Span) -> PResult<()> {
        let value = self.parse_float()?;
        let frame = self.frames.len() - 1;
        self.conds.push(Cond::Switch {
            frame,
            value,
            matched: false,
        });
        Ok(())
    }

    /// The switch this clause belongs to: the innermost open block must be it.
    fn current_switch(&self, d: &str, span: Span) -> PResult<(f64, bool)> {
        let depth = self.frames.len() - 1;
        match self.conds.last() {
            Some(Cond::Switch {
                frame,
                value,
                matched,
            }) if *frame == depth => Ok((*value, *matched)),
            _ => Err(self.error_at(
                span,
                format!("#{d} outside a #switch (or inside an #if/#while not closed before it)"),
            )),
        }
    }

    fn set_matched(&mut self) {
        if let Some(Cond::Switch { matched, .. }) = self.conds.last_mut() {
            *matched = true;
        }
    }

    /// `#case (v)` or `#range (lo, hi)` met while parsing normally.
    pub(super) fn case_directive(&mut self, d: &str, span: Span) -> PResult<()> {
        let (value, matched) = self.current_switch(d, span)?;
        if matched {
            // Falling through: the clause's condition is not evaluated.
            return self.skip_parens_raw(d, span);
        }
        if self.clause_true(d, value)? {
            self.set_matched();
            Ok(())
        } else {
            self.skip_clauses(span, value)
        }
    }

    /// `#else` inside a switch: runs after a false clause and when falling through alike.
    pub(super) fn switch_else(&mut self) {
        self.set_matched();
    }

    fn clause_true(&mut self, d: &str, value: f64) -> PResult<bool> {
        if d == "case" {
            let v = self.parse_float()?;
            return Ok((v - value).abs() < CASE_EPSILON);
        }
        self.expect_sym(Sym::LParen, "after #range")?;
        let lo = self.parse_float()?;
        self.expect_sym(Sym::Comma, "between the #range bounds")?;
        let hi = self.parse_float()?;
        self.expect_sym(Sym::RParen, "to close #range")?;
        Ok(lo <= value && value <= hi)
    }

    /// Skips false clauses until one matches, an `#else` runs, or the switch's `#end`.
    fn skip_clauses(&mut self, open: Span, value: f64) -> PResult<()> {
        loop {
            let d = self.skip_to_directive(open, 0, &["case", "range", "else"])?;
            match &*d {
                "end" => {
                    self.conds.pop();
                    return Ok(());
                }
                "else" => {
                    self.set_matched();
                    return Ok(());
                }
                _ => {
                    if self.clause_true(&d, value)? {
                        self.set_matched();
                        return Ok(());
                    }
                }
            }
        }
    }

    /// `#break`: leaves the innermost `#switch`, `#while` or `#for` of this file or macro,
    /// closing any `#if` blocks it stands in.
    pub(super) fn break_directive(&mut self, span: Span) -> PResult<()> {
        let depth = self.frames.len() - 1;
        let mut ifs = 0;
        for c in self.conds.iter().rev() {
            match c {
                Cond::If { frame } if *frame == depth => ifs += 1,
                Cond::Switch { frame, .. }
                | Cond::While { frame, .. }
                | Cond::For { frame, .. }
                    if *frame == depth =>
                {
                    let keep = self.conds.len() - ifs - 1;
                    self.conds.truncate(keep);
                    self.skip_to_directive(span, ifs, &[])?;
                    return Ok(());
                }
                _ => break,
            }
        }
        Err(self.error_at(
            span,
            "#break outside a #switch, #while or #for of this file or macro",
        ))
    }

    /// Skips raw tokens to a directive in `stops` (or `#end`) at nesting `depth` zero, starting
    /// `depth` blocks deep, and consumes it. Inactive `#if` branches and loop bodies are skipped
    /// with this too.
    pub(super) fn skip_to_directive(
        &mut self,
        open: Span,
        mut depth: usize,
        stops: &[&str],
    ) -> PResult<Rc<str>> {
        loop {
            let Some(f) = self.frames.last_mut() else {
                return Err(self.eof_error());
            };
            if f.pos >= f.end {
                return Err(self.error_at(
                    open,
                    "this block has no matching #end before the end of its file or macro",
                ));
            }
            let t = &f.tokens[f.pos];
            f.pos += 1;
            if let Tok::Directive(d) = &t.tok {
                match &**d {
                    x if opens_block(x) => depth += 1,
                    "end" if depth == 0 => return Ok(d.clone()),
                    "end" => depth -= 1,
                    x if depth == 0 && stops.contains(&x) => return Ok(d.clone()),
                    _ => {}
                }
            }
        }
    }

    /// Passes over a clause's parenthesised condition without evaluating it.
    fn skip_parens_raw(&mut self, d: &str, span: Span) -> PResult<()> {
        let t = self.raw_peek()?.ok_or_else(|| self.eof_error())?;
        if t.tok != Tok::Sym(Sym::LParen) {
            return Err(self.error_at(t.span, format!("expected '(' after #{d}, found {}", t.tok)));
        }
        let mut depth = 0usize;
        loop {
            let Some(t) = self.raw_peek()? else {
                return Err(
                    self.error_at(span, format!("the condition of this #{d} is not closed"))
                );
            };
            self.advance();
            match t.tok {
                Tok::Sym(Sym::LParen) => depth += 1,
                Tok::Sym(Sym::RParen) => {
                    depth -= 1;
                    if depth == 0 {
                        return Ok(());
                    }
                }
                _ => {}
            }
        }
    }
}
