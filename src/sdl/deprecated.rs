//! `#declare deprecated [once] ["message"] Name = ...`: the identifier works as usual, and
//! each use of it warns (only the first use with `once`), as POV-Ray 3.7 does.

use std::rc::Rc;

use rustc_hash::{FxHashMap, FxHashSet};

use super::lexer::Tok;
use super::parser::{PResult, Parser};
use super::source::Span;

#[derive(Default)]
pub struct Deprecations {
    /// Name → (message, warn only once). Once a file has declared a deprecated name, every
    /// identifier of the rest of the parse is looked up here (glass.inc's glass_old.inc
    /// declares fourteen): Fx, not SipHash (`hash_one` and `sip::Hasher::write`, 1.4 % of
    /// incdemo/glasses/samp_demo's 1x1 render).
    names: FxHashMap<Rc<str>, (Rc<str>, bool)>,
    /// Places already warned about (the parser peeks a token more than once).
    warned_at: FxHashSet<Span>,
    warned_once: FxHashSet<Rc<str>>,
}

impl Parser {
    /// After `#declare`/`#local`: reads `deprecated [once] ["message"]` if present and
    /// returns what to record once the name is known.
    pub(super) fn parse_deprecation(&mut self) -> PResult<Option<(Option<Rc<str>>, bool)>> {
        if !self.at_raw_ident("deprecated")? {
            return Ok(None);
        }
        self.advance();
        let once = self.at_raw_ident("once")?;
        if once {
            self.advance();
        }
        let mut msg = None;
        if let Some(t) = self.raw_peek()? {
            if let Tok::Str(s) = &t.tok {
                msg = Some(s.clone());
                self.advance();
            }
        }
        Ok(Some((msg, once)))
    }

    fn at_raw_ident(&mut self, k: &str) -> PResult<bool> {
        Ok(matches!(self.raw_peek()?, Some(t) if matches!(&t.tok, Tok::Ident(n) if &**n == k)))
    }

    pub(super) fn mark_deprecated(&mut self, name: Rc<str>, d: (Option<Rc<str>>, bool)) {
        let msg =
            d.0.unwrap_or_else(|| format!("Identifier {name} was declared deprecated.").into());
        self.deprecated.names.insert(name, (msg, d.1));
    }

    /// Called when the token stream meets an identifier.
    pub(super) fn check_deprecated(&mut self, name: &Rc<str>, span: Span) {
        let Some((msg, once)) = self.deprecated.names.get(name).cloned() else {
            return;
        };
        if !self.deprecated.warned_at.insert(span) {
            return;
        }
        if once && !self.deprecated.warned_once.insert(name.clone()) {
            return;
        }
        self.warn(span, format!("deprecated: {msg}"));
    }

    pub(super) fn has_deprecations(&self) -> bool {
        !self.deprecated.names.is_empty()
    }
}
