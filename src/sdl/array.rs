//! Arrays: `array[N][M] { initialiser }`, element reads and assignments, `dimensions`,
//! `dimension_size`, and `defined`/`#ifdef`/`#undef` on elements.
//!
//! POV-Ray resolves `A[i]` in its token getter, so an element can stand wherever its value's
//! type may (`object { A[i] }`, `texture { T[i] }`, a macro argument). lancer does the same:
//! when the token stream meets an array identifier followed by `[`, it reads the subscripts and
//! replaces the whole reference with one synthetic identifier bound to the element's value, in
//! a one-token frame of its own.
//!
//! Rules measured with POV-Ray 3.7.0: subscripts are truncated; a negative one is an error, as
//! is one past the end; reading an unset element is an error; the first element set fixes the
//! type of all others (float, uv vector, vector, 4d vector, colour, string, object, ...);
//! `#declare B = A` copies the whole array; an element may itself be an array.

use std::rc::Rc;

use super::lexer::{Sym, Tok, Token};
use super::parser::{FrameKind, PResult, Parser};
use super::source::Span;
use super::value::Value;

/// POV-Ray's limit on the number of dimensions.
const MAX_DIMS: usize = 5;
/// Elements in one array; beyond this a scene is almost surely runaway (about 1 GB).
pub const MAX_ARRAY_ELEMENTS: usize = 1 << 24;
/// The name the synthetic token for a resolved element carries; no scene can spell it.
pub(super) const ELEMENT_NAME: &str = "\u{1}array element";

#[derive(Clone, Debug)]
pub struct ArrayVal {
    pub dims: Vec<usize>,
    pub items: Vec<Option<Value>>,
    /// The type every element must have, once one is set.
    pub kind: Option<&'static str>,
}

/// Where an element lives: the array's identifier, the scope holding it, and one flat index
/// per level of nesting (an element that is itself an array adds a level).
#[derive(Clone, Debug)]
pub struct ElemPath {
    pub scope: usize,
    pub name: Rc<str>,
    pub path: Vec<usize>,
    pub span: Span,
}

/// An element reference and the (frame depth, position) where its text began and ended.
pub(super) type LastElement = (ElemPath, (usize, usize), (usize, usize));

/// The type name POV-Ray reports, which also decides whether two values may share an array.
pub(super) fn kind_of(v: &Value) -> &'static str {
    match v {
        Value::Vector(_, 2) => "uv vector",
        Value::Vector(_, 3) => "vector",
        Value::Vector(_, 4) => "4d vector",
        Value::Vector(..) => "colour",
        other => other.type_name(),
    }
}

impl ArrayVal {
    pub fn new(dims: Vec<usize>) -> ArrayVal {
        let n = dims.iter().product();
        ArrayVal {
            dims,
            items: vec![None; n],
            kind: None,
        }
    }
}

impl Parser {
    /// Whether the raw token after the current one opens a subscript.
    pub(super) fn at_subscript(&self) -> bool {
        self.frames.last().is_some_and(|f| {
            f.pos + 1 < f.end && f.tokens[f.pos + 1].tok == Tok::Sym(Sym::LBracket)
        })
    }

    /// Called with the array identifier consumed: reads its subscripts and pushes the
    /// synthetic token that stands for the element.
    pub(super) fn push_element(&mut self, name: Rc<str>, span: Span) -> PResult<()> {
        let start = (
            self.frames.len(),
            self.frames.last().map_or(0, |f| f.pos - 1),
        );
        let p = self.parse_subscripts(name, span)?;
        let Some(v) = self.element(&p).cloned() else {
            return Err(self.error_at(
                p.span,
                format!(
                    "array element {} is not initialised (POV-Ray: attempt to access uninitialized array element)",
                    self.describe(&p)
                ),
            ));
        };
        let end = (self.frames.len(), self.frames.last().map_or(0, |f| f.pos));
        self.last_element = Some((p.clone(), start, end));
        let tok = Token {
            tok: Tok::Ident(ELEMENT_NAME.into()),
            span: p.span,
        };
        self.push_frame_range(Rc::from(vec![tok]), 0, 1, FrameKind::Macro, None, true);
        if let Some(s) = self.scopes.last_mut() {
            s.insert(ELEMENT_NAME.into(), v);
        }
        Ok(())
    }

    /// `A[i]...` text for messages.
    fn describe(&self, p: &ElemPath) -> String {
        let mut s = p.name.to_string();
        let mut cur = self.scopes[p.scope].get(&p.name);
        for &flat in &p.path {
            let Some(Value::Array(a)) = cur else { break };
            let mut rem = flat;
            let mut idx = vec![0; a.dims.len()];
            for (d, size) in a.dims.iter().enumerate().rev() {
                idx[d] = rem % size;
                rem /= size;
            }
            for i in idx {
                s.push_str(&format!("[{i}]"));
            }
            cur = a.items[flat].as_ref();
        }
        s
    }

    /// Reads `[i]...` after array identifier `name` (already consumed), checking bounds.
    pub(super) fn parse_subscripts(&mut self, name: Rc<str>, span: Span) -> PResult<ElemPath> {
        let Some(scope) = (0..self.scopes.len())
            .rev()
            .find(|&i| self.scopes[i].contains_key(&name))
        else {
            return Err(self.error_at(span, format!("undeclared identifier '{name}'")));
        };
        let mut p = match self.scopes[scope].get(&name) {
            Some(Value::Ref(r)) => ElemPath {
                span,
                ..(**r).clone()
            },
            _ => ElemPath {
                scope,
                name: name.clone(),
                path: Vec::new(),
                span,
            },
        };
        loop {
            // Copied out (at most MAX_DIMS) rather than cloned: this runs for every `A[i]`.
            let (dims, nd) = match self.value_at(&p) {
                Some(Value::Array(a)) => {
                    let mut d = [0usize; MAX_DIMS];
                    d[..a.dims.len()].copy_from_slice(&a.dims);
                    (d, a.dims.len())
                }
                Some(other) => {
                    let t = other.type_name();
                    return Err(self.error_at(
                        p.span,
                        format!("{} is a {t}, not an array: it cannot take a subscript", self.describe(&p)),
                    ));
                }
                None => {
                    return Err(self.error_at(
                        p.span,
                        format!(
                            "array element {} is not initialised (POV-Ray: attempt to access uninitialized array element)",
                            self.describe(&p)
                        ),
                    ))
                }
            };
            let mut flat = 0usize;
            // The subscripts read so far, spelled out only in an error message.
            let mut subs = [0.0f64; MAX_DIMS];
            let shown = |me: &Self, p: &ElemPath, subs: &[f64]| {
                let mut s = me.describe(p);
                for i in subs {
                    s.push_str(&format!("[{i}]"));
                }
                s
            };
            for (d, &size) in dims[..nd].iter().enumerate() {
                if self.raw_peek_sym()? != Some(Sym::LBracket) {
                    let here = self.next_span()?;
                    return Err(self.error_at(
                        here,
                        format!(
                            "{} has {} dimensions but only {d} subscripts are given; a row of a multi-dimensional array cannot be used on its own",
                            self.describe(&p),
                            nd
                        ),
                    ));
                }
                self.advance();
                let ispan = self.next_span()?;
                let i = self.with_rel(false, |p| p.parse_float())?.trunc();
                let close = self.expect_sym(Sym::RBracket, "to close the array subscript")?;
                p.span = Span {
                    end: close.end,
                    ..p.span
                };
                subs[d] = i;
                if i < 0.0 {
                    let shown = shown(self, &p, &subs[..=d]);
                    return Err(
                        self.error_at(ispan, format!("negative array subscript in {shown}"))
                    );
                }
                if i >= size as f64 {
                    let shown = shown(self, &p, &subs[..=d]);
                    return Err(self.error_at(
                        ispan,
                        format!(
                            "array subscript {i} out of range in {shown} (dimension {} has size {size}, so subscripts run from 0 to {})",
                            d + 1,
                            size as i64 - 1
                        ),
                    ));
                }
                flat = flat * size + i as usize;
            }
            p.path.push(flat);
            let nested = matches!(self.value_at(&p), Some(Value::Array(_)));
            if !(nested && self.raw_peek_sym()? == Some(Sym::LBracket)) {
                return Ok(p);
            }
        }
    }

    /// The value at a path: the array itself for an empty path, an element otherwise (also
    /// what a by-reference parameter points at, if it is still there).
    pub(super) fn value_at(&self, p: &ElemPath) -> Option<&Value> {
        let mut cur = self.scopes.get(p.scope)?.get(&p.name)?;
        for &flat in &p.path {
            let Value::Array(a) = cur else { return None };
            cur = a.items.get(flat)?.as_ref()?;
        }
        Some(cur)
    }

    pub(super) fn element(&self, p: &ElemPath) -> Option<&Value> {
        if p.path.is_empty() {
            return None;
        }
        self.value_at(p)
    }

    /// The array holding the element at `p`, for changing it.
    fn array_mut(&mut self, p: &ElemPath) -> Option<&mut ArrayVal> {
        let mut cur = self.scopes.get_mut(p.scope)?.get_mut(&p.name)?;
        let (_, walk) = p.path.split_last()?;
        for &flat in walk {
            let Value::Array(a) = cur else { return None };
            cur = Rc::make_mut(a).items.get_mut(flat)?.as_mut()?;
        }
        match cur {
            Value::Array(a) => Some(Rc::make_mut(a)),
            _ => None,
        }
    }

    /// Sets (or with `None` unsets) an element, enforcing one type per array.
    pub(super) fn set_element(&mut self, p: &ElemPath, v: Option<Value>) -> PResult<()> {
        let flat = *p.path.last().expect("an element path");
        let new_kind = v.as_ref().map(kind_of);
        // The element's name is spelled out only for an error: assignments in loops are common.
        let Some(kind) = self.array_mut(p).map(|a| a.kind) else {
            let desc = self.describe(p);
            return Err(self.error_at(p.span, format!("{desc} is not an array element")));
        };
        if let (Some(k), Some(nk)) = (kind, new_kind) {
            if k != nk {
                let desc = self.describe(p);
                return Err(self.error_at(
                    p.span,
                    format!("cannot set {desc} to a {nk}: the array holds {k}s (POV-Ray: attempted to redefine {k} identifier as {nk} identifier)"),
                ));
            }
        }
        let a = self.array_mut(p).expect("found just above");
        if a.kind.is_none() {
            a.kind = new_kind;
        }
        a.items[flat] = v;
        Ok(())
    }

    /// `#declare A[i]... = value`, with the identifier read and `[` next.
    pub(super) fn declare_element(&mut self, name: Rc<str>, span: Span) -> PResult<()> {
        let p = self.parse_subscripts(name, span)?;
        self.expect_sym(Sym::Eq, "after the array element in the declaration")?;
        let v = self.parse_rvalue()?;
        if self.raw_peek_sym()? == Some(Sym::Semi) {
            self.advance();
        }
        self.set_element(&p, Some(v))?;
        // A macro parameter bound to this element by reference sees the change through it.
        Ok(())
    }

    /// After `#ifdef (`, `#undef` or `defined (`: an identifier, possibly with subscripts.
    /// Returns the place; `None` path means a plain identifier.
    pub(super) fn raw_ident_or_element(
        &mut self,
        context: &str,
    ) -> PResult<(Rc<str>, Option<ElemPath>)> {
        let span = self.raw_peek()?.map(|t| t.span).unwrap_or_default();
        let name = self.raw_ident(context)?;
        if self.raw_peek_sym()? == Some(Sym::LBracket)
            && matches!(self.lookup(&name), Some(Value::Array(_)))
        {
            let p = self.parse_subscripts(name.clone(), span)?;
            return Ok((name, Some(p)));
        }
        Ok((name, None))
    }

    /// Whether an identifier or element (as `raw_ident_or_element` read it) holds a value.
    pub(super) fn is_defined(&self, name: &str, p: &Option<ElemPath>) -> bool {
        match p {
            Some(p) => self.element(p).is_some(),
            None => self.lookup_quiet(name).is_some(),
        }
    }

    /// `array[...] [{ ... }]`, after the keyword.
    pub(super) fn parse_array(&mut self, span: Span) -> PResult<Value> {
        let mut dims = Vec::new();
        while self.raw_peek_sym()? == Some(Sym::LBracket) {
            self.advance();
            let dspan = self.next_span()?;
            let n = self.parse_float()?.trunc();
            self.expect_sym(Sym::RBracket, "to close the array size")?;
            if n < 1.0 {
                return Err(self.error_at(dspan, format!("array size {n} is not positive")));
            }
            dims.push(n.min(usize::MAX as f64) as usize);
            if dims.len() > MAX_DIMS {
                return Err(
                    self.error_at(dspan, format!("an array has at most {MAX_DIMS} dimensions"))
                );
            }
        }
        if dims.is_empty() {
            if self.peek_ident()?.as_deref() == Some("mixed") {
                return Err(self.error_at(span, "'array mixed' is POV-Ray 3.8 syntax, not supported by lancer (POV-Ray 3.7 arrays hold one type)"));
            }
            return Err(self.error_at(span, "expected '[' and a size after 'array'"));
        }
        let total = dims
            .iter()
            .try_fold(1usize, |acc, &d| acc.checked_mul(d))
            .filter(|&n| n <= MAX_ARRAY_ELEMENTS);
        if total.is_none() {
            return Err(self.error_at(
                span,
                format!(
                    "array {} is too large: lancer allows at most {MAX_ARRAY_ELEMENTS} elements per array",
                    dims.iter().map(|d| format!("[{d}]")).collect::<String>()
                ),
            ));
        }
        let mut a = ArrayVal::new(dims);
        if self.raw_peek_sym()? == Some(Sym::LBrace) {
            let mut next = 0;
            self.parse_initialiser(&mut a, 0, &mut next)?;
        }
        Ok(Value::Array(Rc::new(a)))
    }

    /// One `{ ... }` level of an initialiser for dimension `d`; `next` is the flat index.
    fn parse_initialiser(&mut self, a: &mut ArrayVal, d: usize, next: &mut usize) -> PResult<()> {
        let open = self.expect_sym(Sym::LBrace, "to open the array initialiser")?;
        let size = a.dims[d];
        for i in 0..size {
            // The manual asks for commas, but POV-Ray 3.7.0 reads `{"a" "b"}` and
            // `{{1 2}{3 4}}` too, and the sample scenes rely on it.
            if i > 0 {
                self.eat_sym(Sym::Comma)?;
            }
            if self.peek_sym()? == Some(Sym::RBrace) {
                let here = self.next_span()?;
                return Err(self.error_at(
                    here,
                    format!(
                        "the array initialiser gives {i} elements where dimension {} has {size}",
                        d + 1
                    ),
                ));
            }
            if d + 1 < a.dims.len() {
                self.parse_initialiser(a, d + 1, next)?;
            } else {
                let vspan = self.next_span()?;
                let v = self.parse_rvalue()?;
                let k = kind_of(&v);
                match a.kind {
                    Some(ak) if ak != k => {
                        return Err(self.error_at(
                            vspan,
                            format!("array elements must all have one type: this is a {k}, earlier ones are {ak}s"),
                        ))
                    }
                    _ => a.kind = Some(k),
                }
                a.items[*next] = Some(v);
                *next += 1;
            }
        }
        self.eat_sym(Sym::Comma)?;
        let t = self.next_tok()?;
        if t.tok != Tok::Sym(Sym::RBrace) {
            let _ = open;
            return Err(self.error_at(
                t.span,
                format!(
                    "expected '}}' after the {size} elements of dimension {}, found {}",
                    d + 1,
                    t.tok
                ),
            ));
        }
        Ok(())
    }

    /// `dimensions(A)` and `dimension_size(A, n)`.
    pub(super) fn array_function(&mut self, name: &str, span: Span) -> PResult<Value> {
        self.expect_sym_with(Sym::LParen, || format!("after {name}"))?;
        let aspan = self.next_span()?;
        let v = self.parse_expr()?;
        let Value::Array(a) = &v else {
            return Err(self.error_at(
                aspan,
                format!("{name} needs an array, found a {}", v.type_name()),
            ));
        };
        let r = if name == "dimensions" {
            a.dims.len() as f64
        } else {
            self.expect_sym(Sym::Comma, "after the array in dimension_size")?;
            let dspan = self.next_span()?;
            let d = self.parse_float()?.trunc();
            if d < 1.0 || d > a.dims.len() as f64 {
                return Err(self.error_at(
                    dspan,
                    format!(
                        "dimension {d} out of range: the array has {} dimension(s), numbered from 1",
                        a.dims.len()
                    ),
                ));
            }
            a.dims[d as usize - 1] as f64
        };
        let _ = span;
        self.expect_sym_with(Sym::RParen, || format!("to close {name}"))?;
        Ok(Value::Float(r))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kinds_follow_povray_type_names() {
        assert_eq!(kind_of(&Value::Float(1.0)), "float");
        assert_eq!(kind_of(&Value::Vector([0.0; 5], 2)), "uv vector");
        assert_eq!(kind_of(&Value::Vector([0.0; 5], 3)), "vector");
        assert_eq!(kind_of(&Value::Str("a".into())), "string");
    }

    #[test]
    fn new_array_is_unset() {
        let a = ArrayVal::new(vec![2, 3]);
        assert_eq!(a.items.len(), 6);
        assert!(a.items.iter().all(Option::is_none));
    }
}
