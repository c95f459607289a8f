//! `function { ... }` literals: parameter lists, the function language's expression grammar,
//! and the special bodies (`internal(N)`, `transform`, `pigment`, `pattern`, `spline`).
//!
//! The function language is not the scene language: it has floats only, no vectors or
//! strings, `>` always compares, and its built-ins are the maths functions plus `select`,
//! `sum` and `prod`. Identifiers are parameters, `sum`/`prod` variables, declared floats
//! (their value is taken now, as POV-Ray does) or declared functions (called at run time).
//! Directives and macro calls inside a body run once, while it is read, like everywhere else.

use std::rc::Rc;
use std::sync::Arc;

use crate::func::{BinOp, Expr, Function, Math1, MAX_PARAMS};

use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};
use super::source::Span;
use super::value::Value;

/// Names in scope while a body is read.
struct FnScope {
    params: Vec<String>,
    /// `sum`/`prod` iteration variables, innermost last, with their slots.
    locals: Vec<(String, usize)>,
    max_slot: usize,
    /// Binary operators read so far (see `MAX_FN_OPERATORS`).
    operators: usize,
}

/// Binary operators one function body may hold. `x + x + ... + x` builds a left-deep tree that
/// the compiler walks recursively (and folds constants at every node, quadratic in the depth):
/// 40,000 terms took 5 s and 100,000 overflowed the stack. 10,000 compile in well under a
/// second on a 2 MB stack.
const MAX_FN_OPERATORS: usize = 10_000;

impl FnScope {
    fn slot(&self, name: &str) -> Option<usize> {
        if let Some((_, s)) = self.locals.iter().rev().find(|(n, _)| n == name) {
            return Some(*s);
        }
        // x and u, y and v name the same parameter.
        let alias = match name {
            "x" => "u",
            "u" => "x",
            "y" => "v",
            "v" => "y",
            _ => name,
        };
        self.params.iter().position(|p| p == name || p == alias)
    }
}

fn math1(name: &str) -> Option<Math1> {
    Some(Math1::Call(match name {
        "abs" => return Some(Math1::Abs),
        "sqrt" => return Some(Math1::Sqrt),
        "sin" => f64::sin,
        "cos" => f64::cos,
        "tan" => f64::tan,
        "asin" => f64::asin,
        "acos" => f64::acos,
        "atan" => f64::atan,
        "sinh" => f64::sinh,
        "cosh" => f64::cosh,
        "tanh" => f64::tanh,
        "asinh" => f64::asinh,
        "acosh" => f64::acosh,
        "atanh" => f64::atanh,
        "exp" => f64::exp,
        "ln" => f64::ln,
        "log" => f64::log10,
        "floor" => f64::floor,
        "ceil" => f64::ceil,
        "int" => f64::trunc,
        "radians" => f64::to_radians,
        "degrees" => f64::to_degrees,
        _ => return None,
    }))
}

fn math2(name: &str) -> Option<fn(f64, f64) -> f64> {
    Some(match name {
        "atan2" => f64::atan2,
        "pow" => f64::powf,
        "mod" => |a: f64, b: f64| a % b,
        _ => return None,
    })
}

/// The function language's binary operators by precedence, loosest first.
const LEVELS: [&[(Sym, BinOp)]; 5] = [
    &[(Sym::Or, BinOp::Or)],
    &[(Sym::And, BinOp::And)],
    &[
        (Sym::Lt, BinOp::Lt),
        (Sym::Le, BinOp::Le),
        (Sym::Eq, BinOp::Eq),
        (Sym::Ne, BinOp::Ne),
        (Sym::Ge, BinOp::Ge),
        (Sym::Gt, BinOp::Gt),
    ],
    &[(Sym::Plus, BinOp::Add), (Sym::Minus, BinOp::Sub)],
    &[(Sym::Star, BinOp::Mul), (Sym::Slash, BinOp::Div)],
];

impl Parser {
    /// After the keyword `function`: an optional parameter list and the body in braces.
    pub(super) fn parse_function_literal(&mut self, span: Span) -> PResult<Value> {
        let params = if self.eat_sym(Sym::LParen)? {
            self.function_params(span)?
        } else {
            vec!["x".to_string(), "y".to_string(), "z".to_string()]
        };
        self.expect_sym(Sym::LBrace, "to open the function body")?;
        let special = match self.peek_ident()?.as_deref() {
            Some(k @ ("internal" | "transform" | "pigment" | "pattern" | "spline")) => {
                Some(k.to_string())
            }
            _ => None,
        };
        let f = match special.as_deref() {
            Some("internal") => {
                self.advance();
                self.expect_sym(Sym::LParen, "after internal")?;
                let n = self.parse_float()?;
                self.expect_sym(Sym::RParen, "to close internal( )")?;
                Function::internal(n.max(0.0) as u32)
            }
            Some("transform") => {
                self.advance();
                Function::transform(self.parse_transform_block()?)
            }
            Some("pigment") => {
                self.advance();
                // The scene's generator as it stands here: POV-Ray's is the one in force when
                // the function runs, which differs only if global_settings comes later.
                let mut p = self.parse_pigment_block(None)?;
                p.take_generator(self.scene.global.noise_generator);
                Function::pigment(p)
            }
            Some("pattern") => {
                // A pattern body reads like a pigment's; only its pattern is used.
                self.advance();
                self.open_brace("pattern")?;
                let mut p = self.parse_pigment_body_in_braces()?;
                p.take_generator(self.scene.global.noise_generator);
                Function::pattern(p)
            }
            Some(_) => {
                let kspan = self.cur_span();
                self.advance();
                Function::spline(self.parse_spline_def(kspan)?)
            }
            None => {
                let mut scope = FnScope {
                    max_slot: params.len(),
                    params,
                    locals: Vec::new(),
                    operators: 0,
                };
                let body = self.fn_or(&mut scope)?;
                Function::from_expr(scope.params, &body, scope.max_slot)
            }
        };
        self.expect_sym(Sym::RBrace, "to close the function body")?;
        Ok(Value::Function(Arc::new(f)))
    }

    fn function_params(&mut self, span: Span) -> PResult<Vec<String>> {
        let mut params: Vec<String> = Vec::new();
        loop {
            let t = self.raw_peek()?.ok_or_else(|| self.eof_error())?;
            self.advance();
            match &t.tok {
                Tok::Ident(p) => {
                    let scope = FnScope {
                        params: params.clone(),
                        locals: Vec::new(),
                        max_slot: 0,
                        operators: 0,
                    };
                    if scope.slot(p).is_some() {
                        return Err(self.error_at(
                            t.span,
                            format!("the function parameter '{p}' is given twice (x and u, y and v are the same parameter)"),
                        ));
                    }
                    params.push(p.to_string());
                }
                _ => {
                    return Err(self.error_at(
                        t.span,
                        format!(
                            "expected a parameter name in the function's parameter list, found {}",
                            t.tok
                        ),
                    ))
                }
            }
            let t = self.next_tok()?;
            match t.tok {
                Tok::Sym(Sym::Comma) => {}
                Tok::Sym(Sym::RParen) => break,
                _ => {
                    return Err(self.error_at(
                        t.span,
                        format!(
                            "expected ',' or ')' in the function's parameter list, found {}",
                            t.tok
                        ),
                    ))
                }
            }
        }
        if params.len() > MAX_PARAMS {
            return Err(self.error_at(
                span,
                format!("a function takes at most {MAX_PARAMS} parameters"),
            ));
        }
        Ok(params)
    }

    fn count_operator(&mut self, s: &mut FnScope) -> PResult<()> {
        s.operators += 1;
        if s.operators > MAX_FN_OPERATORS {
            let span = self.cur_span();
            return Err(self.error_at(
                span,
                format!("a function body may hold at most {MAX_FN_OPERATORS} binary operators"),
            ));
        }
        Ok(())
    }

    fn fn_or(&mut self, s: &mut FnScope) -> PResult<Expr> {
        // Parentheses and call arguments recurse through here.
        self.nested(|p| p.fn_level(s, 0))
    }

    /// One precedence level of binary operators (`LEVELS[level]`), left-associative, whose
    /// operands are the next tighter level or, past the last, a unary expression.
    fn fn_level(&mut self, s: &mut FnScope, level: usize) -> PResult<Expr> {
        let operand = |p: &mut Self, s: &mut FnScope| {
            if level + 1 < LEVELS.len() {
                p.fn_level(s, level + 1)
            } else {
                p.fn_unary(s)
            }
        };
        let mut a = operand(self, s)?;
        loop {
            let sym = self.raw_peek_sym()?;
            let Some(&(_, op)) = LEVELS[level].iter().find(|(t, _)| Some(*t) == sym) else {
                return Ok(a);
            };
            self.advance();
            let b = operand(self, s)?;
            self.count_operator(s)?;
            a = Expr::Bin(op, Box::new(a), Box::new(b));
        }
    }

    fn fn_unary(&mut self, s: &mut FnScope) -> PResult<Expr> {
        match self.peek_sym()? {
            Some(Sym::Minus) => {
                self.advance();
                Ok(Expr::Neg(Box::new(self.nested(|p| p.fn_unary(s))?)))
            }
            Some(Sym::Plus) => {
                self.advance();
                self.nested(|p| p.fn_unary(s))
            }
            Some(Sym::Bang) => {
                self.advance();
                Ok(Expr::Not(Box::new(self.nested(|p| p.fn_unary(s))?)))
            }
            _ => self.fn_primary(s),
        }
    }

    fn fn_primary(&mut self, s: &mut FnScope) -> PResult<Expr> {
        let t = self.next_tok()?;
        match &t.tok {
            Tok::Num(n) => Ok(Expr::Const(*n)),
            Tok::Sym(Sym::LParen) => {
                let e = self.fn_or(s)?;
                self.expect_sym(Sym::RParen, "to close the parenthesis")?;
                Ok(e)
            }
            Tok::Ident(k) => self.fn_ident(s, k.clone(), t.span),
            _ => Err(self.error_at(
                t.span,
                format!("expected a value in the function body, found {}", t.tok),
            )),
        }
    }

    /// Comma-separated function-language arguments up to `)`, after the `(`.
    fn fn_args(&mut self, s: &mut FnScope, name: &str) -> PResult<Vec<Expr>> {
        self.expect_sym_with(Sym::LParen, || format!("after {name}"))?;
        let mut v = Vec::new();
        if self.eat_sym(Sym::RParen)? {
            return Ok(v);
        }
        loop {
            v.push(self.fn_or(s)?);
            if self.eat_sym(Sym::RParen)? {
                return Ok(v);
            }
            self.expect_sym_with(Sym::Comma, || format!("between the arguments of {name}"))?;
        }
    }

    fn fn_ident(&mut self, s: &mut FnScope, k: Rc<str>, span: Span) -> PResult<Expr> {
        if let Some(slot) = s.slot(&k) {
            return Ok(Expr::Slot(slot));
        }
        match self.lookup(&k).cloned() {
            Some(Value::Float(f)) => return Ok(Expr::Const(f)),
            Some(v @ (Value::Vector(..) | Value::Color(_))) => {
                // A declared vector may give one component: `V.x`.
                if self.raw_peek_sym()? == Some(Sym::Dot) {
                    self.advance();
                    let c = self.next_tok()?;
                    let idx = component_index(&c.tok).filter(|&i| i < 5);
                    if let (Some(i), Some((comp, _))) = (idx, v.components()) {
                        return Ok(Expr::Const(comp[i as usize]));
                    }
                    return Err(self.error_at(c.span, format!("unknown component {}", c.tok)));
                }
                return Err(self.error_at(
                    span,
                    format!("'{k}' is a {} and a function body works with floats only; use one component such as {k}.x", v.type_name()),
                ));
            }
            Some(Value::Function(f)) => {
                let args = self.fn_args(s, &k)?;
                if f.has_components() && self.raw_peek_sym()? == Some(Sym::Dot) {
                    self.advance();
                    let c = self.next_tok()?;
                    let idx = component_index(&c.tok);
                    let Some(idx) = idx else {
                        return Err(self.error_at(c.span, format!("unknown component {}", c.tok)));
                    };
                    return Ok(Expr::Call(
                        Arc::new(Function::component(f.clone(), idx)),
                        args,
                    ));
                }
                if !f.is_float()
                    && f.unsupported.is_some()
                    && self.raw_peek_sym()? == Some(Sym::Dot)
                {
                    // `P(x,y,z).gray` of a pigment function lancer cannot evaluate: the call
                    // makes the whole function unsupported, reported where it is used.
                    self.advance();
                    self.next_tok()?;
                    return Ok(Expr::Call(f, args));
                }
                if !f.is_float() {
                    return Err(self.error_at(
                        span,
                        format!("'{k}' returns a vector or colour and cannot be called inside a float function"),
                    ));
                }
                if let Some(n) = f.arity() {
                    if args.len() != n {
                        return Err(self.error_at(
                            span,
                            format!(
                                "the function {k} takes {n} argument(s), {} given",
                                args.len()
                            ),
                        ));
                    }
                }
                return Ok(Expr::Call(f, args));
            }
            Some(other) => {
                return Err(self.error_at(
                    span,
                    format!(
                        "'{k}' is a {} and cannot be used in a function body",
                        other.type_name()
                    ),
                ))
            }
            None => {}
        }
        if let Some(c) = self.builtin_float_ident(&k) {
            return Ok(Expr::Const(c));
        }
        if let Some(f) = math1(&k) {
            let mut a = self.fn_args(s, &k)?;
            if k.as_ref() == "atan" && a.len() == 2 {
                let b = a.pop().expect("two arguments");
                let x = a.pop().expect("two arguments");
                return Ok(Expr::Math2(f64::atan2, Box::new(x), Box::new(b)));
            }
            if a.len() != 1 {
                return Err(self.error_at(span, format!("{k} takes 1 argument, {} given", a.len())));
            }
            return Ok(Expr::Math1(f, Box::new(a.pop().expect("one argument"))));
        }
        if let Some(f) = math2(&k) {
            let mut a = self.fn_args(s, &k)?;
            if a.len() != 2 {
                return Err(
                    self.error_at(span, format!("{k} takes 2 arguments, {} given", a.len()))
                );
            }
            let b = a.pop().expect("two arguments");
            return Ok(Expr::Math2(
                f,
                Box::new(a.pop().expect("two arguments")),
                Box::new(b),
            ));
        }
        match &*k {
            "min" | "max" => {
                let a = self.fn_args(s, &k)?;
                if a.is_empty() {
                    return Err(self.error_at(span, format!("{k} needs at least one argument")));
                }
                Ok(if &*k == "min" { Expr::Min(a) } else { Expr::Max(a) })
            }
            "select" => {
                let a = self.fn_args(s, &k)?;
                if a.len() != 3 && a.len() != 4 {
                    return Err(self.error_at(span, "select takes 3 or 4 arguments"));
                }
                Ok(Expr::Select(a))
            }
            "sum" | "prod" => self.fn_loop(s, &k, span),
            _ => Err(self.error_at(
                span,
                format!("'{k}' in a function body is not a parameter, a declared float or function, or a built-in the function language has"),
            )),
        }
    }

    /// `sum(i, from, to, expr)` and `prod(...)`.
    fn fn_loop(&mut self, s: &mut FnScope, k: &str, span: Span) -> PResult<Expr> {
        self.expect_sym_with(Sym::LParen, || format!("after {k}"))?;
        let var = self.raw_ident(&format!("as the {k} variable"))?;
        self.expect_sym_with(Sym::Comma, || format!("after the {k} variable"))?;
        let slot = s.params.len() + s.locals.len();
        if slot >= MAX_PARAMS + 56 {
            return Err(self.error_at(span, format!("{k} is nested too deeply")));
        }
        s.locals.push((var.to_string(), slot));
        s.max_slot = s.max_slot.max(slot + 1);
        let r = (|| {
            let from = self.fn_or(s)?;
            self.expect_sym_with(Sym::Comma, || format!("after the {k} start value"))?;
            let to = self.fn_or(s)?;
            self.expect_sym_with(Sym::Comma, || format!("after the {k} end value"))?;
            let body = self.fn_or(s)?;
            self.expect_sym_with(Sym::RParen, || format!("to close {k}"))?;
            Ok(Expr::Loop {
                product: k == "prod",
                var: slot,
                from: Box::new(from),
                to: Box::new(to),
                body: Box::new(body),
            })
        })();
        s.locals.pop();
        r
    }
}

/// The component `.name` selects in a function body: 0-4 of a vector or colour (x/u/red,
/// y/v/green, z/blue, t/filter, transmit), 5 the gray of a pigment function's result.
fn component_index(tok: &Tok) -> Option<u8> {
    let Tok::Ident(n) = tok else { return None };
    match &**n {
        "x" | "u" | "red" => Some(0),
        "y" | "v" | "green" => Some(1),
        "z" | "blue" => Some(2),
        "t" | "filter" => Some(3),
        "transmit" => Some(4),
        "gray" | "grey" => Some(5),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use crate::func::vm::Op;
    use crate::func::FnKind;
    use crate::sdl::value::Value;
    use crate::sdl::{ParseOptions, Parser};

    /// The parser's `sqrt` and `abs` become instructions, not calls through `F1` (they were
    /// calls while the compiler recognised them by function pointer).
    #[test]
    fn parsed_sqrt_and_abs_become_instructions() {
        let mut p = Parser::new(ParseOptions::default());
        p.parse_str(
            "t.pov",
            "#declare F = function { sqrt(x*x + z*z) - abs(y) }",
        )
        .unwrap();
        let Some(Value::Function(f)) = p.lookup("F") else {
            panic!("F is a function");
        };
        let FnKind::Code(code) = &f.kind else {
            panic!("F is compiled");
        };
        let ops = code.ops();
        assert!(ops.iter().any(|o| matches!(o, Op::Sqrt)), "{ops:?}");
        assert!(ops.iter().any(|o| matches!(o, Op::Abs)), "{ops:?}");
        assert!(!ops.iter().any(|o| matches!(o, Op::F1(_))), "{ops:?}");
        assert_eq!(f.eval(&[3.0, -2.0, 4.0]), 3.0);
    }
}
