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
        let target = self.assign_target(&name, local);
        self.assign_to(target, name, v)
    }

    /// Where `#declare`/`#local` of `name` writes, decided when the declaration starts: its
    /// value may run past the end of a macro body (an object declared without a semicolon as
    /// the body's last statement: language/macros/macro2.pov), which closes the macro's scope
    /// and its by-reference parameters with it; and a value that came out of a macro
    /// (`#local P = M();`) must not land in that macro's scope.
    pub(super) fn assign_target(&self, name: &str, local: bool) -> AssignTarget {
        let depth = self.scopes.len().max(1);
        let idx = if local {
            depth - 1
        } else {
            (1..depth)
                .rev()
                .find(|&i| self.scopes[i].contains_key(name))
                .unwrap_or(0)
        };
        match self.scopes[idx].get(name) {
            Some(Value::Ref(r)) => AssignTarget::Ref((**r).clone()),
            _ => AssignTarget::Scope(idx),
        }
    }

    pub(super) fn assign_to(
        &mut self,
        target: AssignTarget,
        name: Rc<str>,
        v: Value,
    ) -> PResult<()> {
        match &target {
            AssignTarget::Ref(r) => self.built_objects.forget(&r.name),
            AssignTarget::Scope(_) => self.built_objects.forget(&name),
        }
        match target {
            AssignTarget::Ref(r) if r.path.is_empty() => {
                if let Some(scope) = self.scopes.get_mut(r.scope) {
                    scope.insert(r.name, v);
                }
                Ok(())
            }
            AssignTarget::Ref(r) => self.set_element(&r, Some(v)),
            // A local of a macro whose body ended while the value was read: gone with it.
            AssignTarget::Scope(idx) if idx >= self.scopes.len() => Ok(()),
            AssignTarget::Scope(idx) => {
                self.scopes[idx].insert(name, v);
                Ok(())
            }
        }
    }
}

/// Where a declaration writes (see `Parser::assign_target`).
pub(super) enum AssignTarget {
    /// Through a by-reference macro parameter to the caller's variable or element.
    Ref(ElemPath),
    /// Into the symbol table at this depth.
    Scope(usize),
}
