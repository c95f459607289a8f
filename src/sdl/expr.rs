//! Expressions: floats, vectors, colours and strings, evaluated as they are parsed.
//!
//! Precedence from loosest: `?:`, `|`, `&`, comparisons, `+ -`, `* /`, unary `- + !`, then
//! `.x`-style component access. Inside `< >` a bare `>` closes the vector.

use std::rc::Rc;

use crate::color::Rgbft;
use crate::math::DVec3;

use super::lexer::{Sym, Tok};
use super::parser::{IdentClass, PResult, Parser};
use super::source::Span;
use super::value::Value;

type Comp = ([f64; 5], u8);

fn binop(a: Value, b: Value, f: impl Fn(f64, f64) -> f64) -> Option<Value> {
    let (ca, na) = a.components()?;
    let (cb, nb) = b.components()?;
    let mut out = [0.0; 5];
    for i in 0..5 {
        out[i] = f(ca[i], cb[i]);
    }
    Some(match (&a, &b) {
        (Value::Color(_), _) | (_, Value::Color(_)) => Value::Color(Rgbft::from_array(out)),
        (Value::Float(_), Value::Float(_)) => Value::Float(out[0]),
        _ => Value::Vector(out, na.max(nb)),
    })
}

/// A vector widened to more components: the new ones are zero (a float fills them all).
pub(super) fn pad(c: Comp) -> [f64; 5] {
    let (mut v, len) = c;
    if len > 1 {
        for x in v.iter_mut().skip(len as usize) {
            *x = 0.0;
        }
    }
    v
}

impl Parser {
    pub fn parse_expr(&mut self) -> PResult<Value> {
        // Parentheses, vectors, calls and colours all come back here: the one depth check.
        self.nested(Self::parse_conditional)
    }

    fn parse_conditional(&mut self) -> PResult<Value> {
        if let Some(v) = self.lone_float_operand()? {
            return Ok(v);
        }
        let c = self.parse_binary(1)?;
        if self.rel_ok && self.raw_peek_sym()? == Some(Sym::Question) {
            self.advance();
            let span = self.cur_span();
            let cond = self.float_of(c, span)?;
            let a = self.parse_expr()?;
            self.expect_sym(Sym::Colon, "in the conditional expression ( ? : )")?;
            let b = self.parse_expr()?;
            return Ok(if cond != 0.0 { a } else { b });
        }
        Ok(c)
    }

    /// The whole expression when it is one number or float identifier followed by a symbol
    /// that ends every expression (`I` and `100` in `mod(I, 100)`): the value is had without
    /// passing it up through the operator levels, each of which would only look at that same
    /// symbol. Leaves `last_span` at the symbol, as the levels' look-ahead does.
    #[inline]
    fn lone_float_operand(&mut self) -> PResult<Option<Value>> {
        if !self.ready()? {
            return Ok(None);
        }
        let Some(f) = self.frames.last() else {
            return Ok(None);
        };
        let x = match f.tokens[f.pos].tok {
            Tok::Num(n) => n,
            Tok::Ident(_) => match self.plain_ident_class() {
                Some(IdentClass::Float(x)) => x,
                _ => return Ok(None),
            },
            _ => return Ok(None),
        };
        // The symbol must be in the same token list: at its end, the levels' look-ahead
        // would pop the frame (and report an unclosed #if there).
        let Some(next) = f.tokens[..f.end].get(f.pos + 1) else {
            return Ok(None);
        };
        let ends = match next.tok {
            Tok::Sym(Sym::Comma | Sym::RParen | Sym::RBrace | Sym::RBracket | Sym::Semi) => true,
            // Inside parentheses `>` is a comparison.
            Tok::Sym(Sym::Gt) => !self.rel_ok,
            _ => false,
        };
        if !ends {
            return Ok(None);
        }
        let span = next.span;
        self.advance();
        self.last_span = span;
        Ok(Some(Value::Float(x)))
    }

    fn arith(
        &mut self,
        a: Value,
        b: Value,
        span: Span,
        f: impl Fn(f64, f64) -> f64,
    ) -> PResult<Value> {
        let (ta, tb) = (a.type_name(), b.type_name());
        if let (Value::Str(_), _) | (_, Value::Str(_)) = (&a, &b) {
            return Err(self.error_at(span, format!("cannot do arithmetic on a {ta} and a {tb}")));
        }
        let (na, nb) = (a.components().map(|c| c.1), b.components().map(|c| c.1));
        // Pad shorter vectors with zeros before combining (floats promote to every component).
        let a = match (a, na, nb) {
            (Value::Vector(c, n), _, Some(m)) if m > n && m > 1 => Value::Vector(pad((c, n)), m),
            (a, _, _) => a,
        };
        let b = match (b, nb, na) {
            (Value::Vector(c, n), _, Some(m)) if m > n && m > 1 => Value::Vector(pad((c, n)), m),
            (b, _, _) => b,
        };
        binop(a, b, f).ok_or_else(|| {
            self.error_at(span, format!("cannot do arithmetic on a {ta} and a {tb}"))
        })
    }

    /// Binary operators by precedence climbing: `|` < `&` < comparisons < `+ -` < `* /`, all
    /// left-associative. One loop instead of a function per level keeps the value of a plain
    /// operand from being returned through five levels (a million-iteration `#while` parses
    /// millions of operands). POV-Ray reads comparisons, `&` and `|` only inside parentheses
    /// (`rel_ok`), so that `box { <0,0,0> <1,1,1> }` is two vectors rather than a comparison.
    fn parse_binary(&mut self, min: u8) -> PResult<Value> {
        let mut a = self.parse_unary()?;
        loop {
            let Some(op) = self.raw_peek_sym()? else {
                return Ok(a);
            };
            let prec = match op {
                Sym::Star | Sym::Slash => 5,
                Sym::Plus | Sym::Minus => 4,
                _ if !self.rel_ok => return Ok(a),
                Sym::Lt | Sym::Le | Sym::Eq | Sym::Ne | Sym::Ge | Sym::Gt => 3,
                Sym::And => 2,
                Sym::Or => 1,
                _ => return Ok(a),
            };
            if prec < min {
                return Ok(a);
            }
            self.advance();
            let span = self.cur_span();
            let b = self.parse_binary(prec + 1)?;
            a = self.binary(op, a, b, span)?;
        }
    }

    fn binary(&mut self, op: Sym, a: Value, b: Value, span: Span) -> PResult<Value> {
        if let (Value::Float(x), Value::Float(y)) = (&a, &b) {
            // Two floats, the loops' arithmetic: `arith` on them computes exactly this.
            if let Some(r) = float_op(op, *x, *y) {
                return Ok(Value::Float(r));
            }
        }
        match op {
            Sym::Star => self.arith(a, b, span, |x, y| x * y),
            Sym::Slash => self.arith(a, b, span, div_or_big),
            Sym::Plus => self.arith(a, b, span, |x, y| x + y),
            Sym::Minus => self.arith(a, b, span, |x, y| x - y),
            Sym::And => self.arith(a, b, span, |x, y| ((x != 0.0) && (y != 0.0)) as u8 as f64),
            Sym::Or => self.arith(a, b, span, |x, y| ((x != 0.0) || (y != 0.0)) as u8 as f64),
            _ => {
                if let (Value::Str(x), Value::Str(y)) = (&a, &b) {
                    let o = x.cmp(y);
                    let r = match op {
                        Sym::Lt => o.is_lt(),
                        Sym::Le => o.is_le(),
                        Sym::Eq => o.is_eq(),
                        Sym::Ne => o.is_ne(),
                        Sym::Ge => o.is_ge(),
                        _ => o.is_gt(),
                    };
                    return Ok(Value::Float(r as u8 as f64));
                }
                let f = move |x: f64, y: f64| {
                    (match op {
                        Sym::Lt => x < y,
                        Sym::Le => x <= y,
                        Sym::Eq => x == y,
                        Sym::Ne => x != y,
                        Sym::Ge => x >= y,
                        _ => x > y,
                    }) as u8 as f64
                };
                self.arith(a, b, span, f)
            }
        }
    }

    fn parse_unary(&mut self) -> PResult<Value> {
        match self.peek_sym()? {
            Some(Sym::Minus) => {
                self.advance();
                let span = self.cur_span();
                let v = self.nested(Self::parse_unary)?;
                self.arith(Value::Float(0.0), v, span, |x, y| x - y)
            }
            Some(Sym::Plus) => {
                self.advance();
                self.nested(Self::parse_unary)
            }
            Some(Sym::Bang) => {
                self.advance();
                let span = self.cur_span();
                let v = self.nested(Self::parse_unary)?;
                let f = self.float_of(v, span)?;
                Ok(Value::Float((f == 0.0) as u8 as f64))
            }
            _ => self.parse_postfix(),
        }
    }

    fn parse_postfix(&mut self) -> PResult<Value> {
        let mut v = self.parse_primary()?;
        while self.raw_peek_sym()? == Some(Sym::Dot) {
            self.advance();
            let t = self.next_tok()?;
            let Tok::Ident(k) = &t.tok else {
                return Err(self.error_at(
                    t.span,
                    format!("expected a component name after '.', found {}", t.tok),
                ));
            };
            let idx = match &**k {
                "x" | "u" | "red" => 0,
                "y" | "v" | "green" => 1,
                "z" | "blue" => 2,
                "t" | "filter" => 3,
                "transmit" => 4,
                "gray" | "grey" => {
                    let Some((c, _)) = v.components() else {
                        return Err(self.error_at(t.span, format!("'.{k}' needs a colour")));
                    };
                    v = Value::Float(c[0] * 0.297 + c[1] * 0.589 + c[2] * 0.114);
                    continue;
                }
                "hf" => {
                    let Some((c, _)) = v.components() else {
                        return Err(self.error_at(t.span, format!("'.{k}' needs a colour")));
                    };
                    v = Value::Float(c[0] + c[1] / 255.0);
                    continue;
                }
                _ => return Err(self.error_at(t.span, format!("unknown component '.{k}'"))),
            };
            match v.components() {
                Some((c, n)) if n == 1 || idx < n as usize || matches!(v, Value::Color(_)) => {
                    v = Value::Float(c[idx])
                }
                _ => {
                    return Err(self.error_at(
                        t.span,
                        format!("'.{k}' does not apply to a {}", v.type_name()),
                    ))
                }
            }
        }
        Ok(v)
    }

    fn parse_primary(&mut self) -> PResult<Value> {
        // The token is read in place (`ready`): copying it out was a tenth of a `#while`
        // loop's parse.
        if !self.ready()? {
            return Err(self.eof_error());
        }
        let Some(t) = self.current_token() else {
            return Err(self.eof_error());
        };
        let span = t.span;
        match &t.tok {
            Tok::Num(n) => {
                let n = *n;
                self.advance();
                return Ok(Value::Float(n));
            }
            Tok::Ident(k) => {
                let k = k.clone();
                // `ready` looked the identifier up already.
                let class = self.plain_ident_class();
                self.advance();
                return match class {
                    Some(IdentClass::Float(f)) => Ok(Value::Float(f)),
                    Some(IdentClass::Undeclared) => self.builtin_ident_value(k, span),
                    _ => self.parse_ident_value(k, span),
                };
            }
            _ => {}
        }
        let t = self.next_tok()?;
        match &t.tok {
            Tok::Str(s) => Ok(Value::Str(s.clone())),
            Tok::Sym(Sym::LParen) => {
                let v = self.with_rel(true, |p| p.parse_expr())?;
                self.expect_sym(Sym::RParen, "to close the parenthesis")?;
                Ok(v)
            }
            Tok::Sym(Sym::Lt) => self.parse_vector_literal(),
            _ => Err(self.error_at(
                t.span,
                format!(
                    "expected a value (number, vector, colour or identifier), found {}",
                    t.tok
                ),
            )),
        }
    }

    fn parse_vector_literal(&mut self) -> PResult<Value> {
        self.with_rel(false, |p| {
            let mut c = [0.0; 5];
            let mut n = 0usize;
            loop {
                let span = p.cur_span();
                let v = p.parse_expr()?;
                if n == 5 {
                    return Err(p.error_at(span, "a vector has at most 5 components"));
                }
                c[n] = p.float_of(v, span)?;
                n += 1;
                // Commas are optional and may trail (`<1 2 3>`, `<1,2,3,>`), as in POV-Ray.
                p.skip_optional_comma()?;
                if p.eat_sym(Sym::Gt)? {
                    break;
                }
            }
            if n < 2 {
                let span = p.cur_span();
                return Err(p.error_at(span, "a vector needs at least 2 components"));
            }
            Ok(Value::Vector(c, n as u8))
        })
    }

    fn parse_ident_value(&mut self, k: Rc<str>, span: Span) -> PResult<Value> {
        // One lookup per identifier. Function and spline identifiers are called when `(`
        // follows; alone they are values (passed to a macro, say).
        match self.lookup(&k) {
            Some(Value::Function(f)) => {
                let f = f.clone();
                if self.raw_peek_sym()? == Some(Sym::LParen) {
                    return self.call_function(&k, &f, span);
                }
                return Ok(Value::Function(f));
            }
            Some(Value::Spline(s)) => {
                let s = s.clone();
                if self.raw_peek_sym()? == Some(Sym::LParen) {
                    return self.call_spline(s, &k);
                }
                return Ok(Value::Spline(s));
            }
            Some(v) => return Ok(v.clone()),
            None => {}
        }
        self.builtin_ident_value(k, span)
    }

    /// An identifier no symbol table holds: a built-in value or call, or an error.
    fn builtin_ident_value(&mut self, k: Rc<str>, span: Span) -> PResult<Value> {
        // The maths built-ins first: `mod(I, 100)` in a loop should not be compared with every
        // other built-in name on the way (no name is both; see builtins_math's tests).
        if let Some(r) = self.math_builtin(&k, span) {
            return r;
        }
        if let Some(v) = self.lang_ident_value(&k, span)? {
            return Ok(v);
        }
        if let Some(x) = self.builtin_float_ident(&k) {
            return Ok(Value::Float(x));
        }
        match &*k {
            "x" => Ok(Value::vec3(DVec3::X)),
            "y" => Ok(Value::vec3(DVec3::Y)),
            "z" => Ok(Value::vec3(DVec3::Z)),
            "t" => Ok(Value::Vector([0.0, 0.0, 0.0, 1.0, 0.0], 4)),
            "u" => Ok(Value::Vector([1.0, 0.0, 0.0, 0.0, 0.0], 2)),
            "v" => Ok(Value::Vector([0.0, 1.0, 0.0, 0.0, 0.0], 2)),
            "function" => self.parse_function_literal(span),
            "color" | "colour" => self.parse_color_body(),
            "rgb" | "rgbf" | "rgbt" | "rgbft" | "srgb" | "srgbf" | "srgbt" | "srgbft" => {
                let vspan = self.cur_span();
                let v = self.parse_expr()?;
                self.color_from(&k, v, vspan).map(Value::Color)
            }
            "red" | "green" | "blue" | "filter" | "transmit" => {
                // `color red 1 green 0.5`: start from black and set components.
                self.color_components(Rgbft::BLACK, Some(k))
                    .map(Value::Color)
            }
            _ => self.builtin_call(&k, span),
        }
    }

    /// After `color`/`colour`: a base expression and any `red 1`, `filter 0.5`, ... modifiers.
    pub(super) fn parse_color_body(&mut self) -> PResult<Value> {
        let base = match self.peek_ident()?.as_deref() {
            Some("red" | "green" | "blue" | "filter" | "transmit") => Rgbft::BLACK,
            _ => {
                let span = self.cur_span();
                let v = self.parse_expr()?;
                self.color_of(v, span)?
            }
        };
        self.color_components(base, None).map(Value::Color)
    }

    fn color_components(&mut self, mut c: Rgbft, mut pending: Option<Rc<str>>) -> PResult<Rgbft> {
        loop {
            let k = match pending.take() {
                Some(k) => k,
                None => match self.peek_ident()?.as_deref() {
                    Some(k @ ("red" | "green" | "blue" | "filter" | "transmit")) => {
                        let k: Rc<str> = k.into();
                        self.advance();
                        k
                    }
                    _ => return Ok(c),
                },
            };
            let x = self.parse_float()?;
            match &*k {
                "red" => c.rgb.x = x,
                "green" => c.rgb.y = x,
                "blue" => c.rgb.z = x,
                "filter" => c.filter = x,
                _ => c.transmit = x,
            }
        }
    }

    /// `rgb v` and friends: promotion by the keyword's component count; `srgb` decodes sRGB.
    fn color_from(&self, kw: &str, v: Value, span: Span) -> PResult<Rgbft> {
        let Some((c, n)) = v.components() else {
            return Err(self.error_at(
                span,
                format!("'{kw}' needs a number or vector, found a {}", v.type_name()),
            ));
        };
        let c = if n == 1 { [c[0]; 5] } else { pad((c, n)) };
        let base = kw.trim_start_matches('s');
        let (f, t) = match base {
            "rgb" => (0.0, 0.0),
            "rgbf" => (c[3], 0.0),
            "rgbt" => (0.0, c[3]),
            _ => (c[3], c[4]),
        };
        let mut out = Rgbft::new(c[0], c[1], c[2], f, t);
        if kw.starts_with('s') {
            out.rgb = DVec3::new(srgb_decode(c[0]), srgb_decode(c[1]), srgb_decode(c[2]));
        }
        Ok(out)
    }

    pub fn color_of(&self, v: Value, span: Span) -> PResult<Rgbft> {
        match v {
            Value::Color(c) => Ok(c),
            Value::Float(f) => Ok(Rgbft::new(f, f, f, f, f)),
            Value::Vector(c, n) => Ok(Rgbft::from_array(pad((c, n)))),
            other => Err(self.error_at(
                span,
                format!("expected a colour, found a {}", other.type_name()),
            )),
        }
    }

    pub fn float_of(&self, v: Value, span: Span) -> PResult<f64> {
        match v {
            Value::Float(f) => Ok(f),
            // POV-Ray takes the first component when a colour or vector stands for a float.
            Value::Color(c) => Ok(c.rgb.x),
            other => Err(self.error_at(
                span,
                format!("expected a float, found a {}", other.type_name()),
            )),
        }
    }

    pub fn parse_float(&mut self) -> PResult<f64> {
        let span = self.next_span()?;
        let v = self.parse_expr()?;
        self.float_of(v, span)
    }

    /// Span of the next token, for messages about the value that starts there.
    pub(super) fn next_span(&mut self) -> PResult<Span> {
        Ok(if self.ready()? {
            self.last_span
        } else {
            Span::default()
        })
    }

    pub fn parse_vector(&mut self) -> PResult<DVec3> {
        let span = self.next_span()?;
        let v = self.parse_expr()?;
        self.vector_of(&v, span, "expected a vector")
    }

    /// A value as a 3-vector: a float fills all three, a shorter vector gets zeros (its unused
    /// components may hold a float that was added to it), a colour gives its rgb. `what` starts
    /// the error message.
    pub(super) fn vector_of(&self, v: &Value, span: Span, what: &str) -> PResult<DVec3> {
        match v {
            Value::Float(f) => Ok(DVec3::splat(*f)),
            Value::Vector(c, n) => {
                let c = pad((*c, *n));
                Ok(DVec3::new(c[0], c[1], c[2]))
            }
            Value::Color(c) => Ok(c.rgb),
            other => Err(self.error_at(span, format!("{what}, found a {}", other.type_name()))),
        }
    }

    /// One string term (a literal, identifier or call, no operators after it), as POV-Ray reads
    /// the strings of a `text`, where a signed thickness may follow without a comma:
    /// `text { ttf "timrom.ttf" "gj" -0.4, 0 }`.
    pub(super) fn parse_string_term(&mut self) -> PResult<String> {
        let span = self.next_span()?;
        match self.nested(Self::parse_postfix)? {
            Value::Str(s) => Ok(s.to_string()),
            other => Err(self.error_at(
                span,
                format!("expected a string, found a {}", other.type_name()),
            )),
        }
    }

    pub fn parse_string(&mut self) -> PResult<String> {
        let span = self.next_span()?;
        match self.parse_expr()? {
            Value::Str(s) => Ok(s.to_string()),
            other => Err(self.error_at(
                span,
                format!("expected a string, found a {}", other.type_name()),
            )),
        }
    }

    /// A colour where the grammar wants one: `color ...`, `rgb ...`, an identifier or an
    /// expression, followed by optional component modifiers.
    pub fn parse_color(&mut self) -> PResult<Rgbft> {
        if self.eat_keyword("color")? || self.eat_keyword("colour")? {
            let span = self.cur_span();
            let v = self.parse_color_body()?;
            return self.color_of(v, span);
        }
        let span = self.next_span()?;
        let v = self.parse_expr()?;
        let c = self.color_of(v, span)?;
        self.color_components(c, None)
    }

    /// Math built-ins (string ones and `defined` are read earlier, in `lang_ident_value`).
    fn builtin_call(&mut self, name: &str, span: Span) -> PResult<Value> {
        if let Some(r) = self.math_builtin(name, span) {
            return r;
        }
        Err(self.error_at(span, format!("undeclared identifier '{name}'")))
    }
}

/// A binary operator on two floats, as `Parser::binary` computes it through `arith`.
fn float_op(op: Sym, x: f64, y: f64) -> Option<f64> {
    Some(match op {
        Sym::Star => x * y,
        Sym::Slash => div_or_big(x, y),
        Sym::Plus => x + y,
        Sym::Minus => x - y,
        Sym::Lt => (x < y) as u8 as f64,
        Sym::Le => (x <= y) as u8 as f64,
        Sym::Eq => (x == y) as u8 as f64,
        Sym::Ne => (x != y) as u8 as f64,
        Sym::Ge => (x >= y) as u8 as f64,
        Sym::Gt => (x > y) as u8 as f64,
        _ => return None,
    })
}

/// POV-Ray divides by zero with a warning and a huge result; keep it finite.
fn div_or_big(x: f64, y: f64) -> f64 {
    if y == 0.0 {
        if x == 0.0 {
            0.0
        } else {
            x.signum() * 1e10
        }
    } else {
        x / y
    }
}

fn srgb_decode(c: f64) -> f64 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}
