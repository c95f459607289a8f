//! Macro arguments passed by reference.
//!
//! In POV-Ray 3.7 a macro argument that is a lone identifier (or a lone array element) binds
//! the parameter to the caller's variable: `#declare P = ...` and even `#local P = ...` inside
//! the macro change the caller's value at once (a `#debug` of the caller's variable inside
//! the macro already shows it), while `#undef P` only drops the parameter. `M(X + 0)` or
//! `M(+X)` pass a value. lancer binds such a parameter to a `Value::Ref` naming the caller's
//! place; `lookup` and assignments follow it.

use std::rc::Rc;

use super::array::{ElemPath, ELEMENT_NAME};
use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};
use super::value::Value;

impl Parser {
    /// One macro argument: a reference for a lone identifier or element, a value otherwise.
    pub(super) fn parse_macro_arg(&mut self) -> PResult<Value> {
        let Some(t) = self.peek()? else {
            return Err(self.eof_error());
        };
        // Peeking resolves an element at once into its synthetic token; the element last
        // resolved is then this one.
        let first_element = match &t.tok {
            Tok::Ident(n) if &**n == ELEMENT_NAME => self.last_element.clone(),
            _ => None,
        };
        if let Tok::Ident(name) = &t.tok {
            let lone = self.frames.last().is_some_and(|f| {
                f.pos + 1 < f.end
                    && matches!(
                        f.tokens[f.pos + 1].tok,
                        Tok::Sym(Sym::Comma) | Tok::Sym(Sym::RParen)
                    )
            });
            if lone {
                if let Some(target) = self.ref_target(name, t.span) {
                    self.advance();
                    return Ok(Value::Ref(Rc::new(target)));
                }
            }
        }
        let v = self.parse_rvalue()?;
        self.raw_peek()?;
        let end = (self.frames.len(), self.frames.last().map_or(0, |f| f.pos));
        if let Some((p, _, e)) = first_element {
            if e == end && self.element(&p).is_some() {
                return Ok(Value::Ref(Rc::new(p)));
            }
        }
        Ok(v)
    }

    /// The caller's place an identifier names, if it holds a value that can be referenced.
    fn ref_target(&self, name: &str, span: super::source::Span) -> Option<ElemPath> {
        let scope = (0..self.scopes.len())
            .rev()
            .find(|&i| self.scopes[i].contains_key(name))?;
        match self.scopes[scope].get(name)? {
            // A parameter passed on keeps pointing at the original place.
            Value::Ref(r) => Some((**r).clone()),
            Value::Macro(_) => None,
            _ => Some(ElemPath {
                scope,
                name: name.into(),
                path: Vec::new(),
                span,
            }),
        }
    }

    /// `#declare`/`#local` of a name: writes through a by-reference parameter; otherwise
    /// `#local` binds in the innermost table and `#declare` updates a local that already holds
    /// the name (so loops in macros work) or binds globally.
    pub(super) fn assign_var(&mut self, name: Rc<str>, v: Value, local: bool) -> PResult<()> {
        let depth = self.scopes.len();
        self.assign_var_at(name, v, local, depth)
    }

    /// Like `assign_var`, as seen from the scopes `..depth`: a declaration whose value came out
    /// of a macro (`#local P = M();`) ends while the macro's scope is still open, and must
    /// not land in it.
    pub(super) fn assign_var_at(
        &mut self,
        name: Rc<str>,
        v: Value,
        local: bool,
        depth: usize,
    ) -> PResult<()> {
        let depth = depth.clamp(1, self.scopes.len());
        let idx = if local {
            depth - 1
        } else {
            (1..depth)
                .rev()
                .find(|&i| self.scopes[i].contains_key(&name))
                .unwrap_or(0)
        };
        if let Some(Value::Ref(r)) = self.scopes[idx].get(&name) {
            let r = (**r).clone();
            if r.path.is_empty() {
                self.scopes[r.scope].insert(r.name, v);
                return Ok(());
            }
            return self.set_element(&r, Some(v));
        }
        self.scopes[idx].insert(name, v);
        Ok(())
    }
}
