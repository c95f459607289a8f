//! User-defined functions of the scene language (`function { ... }`), compiled once when they
//! are declared and evaluated many times: while parsing (`F(1,2,3)`), and later by isosurfaces
//! and function patterns, possibly from many render threads at once.
//!
//! A float function body becomes a [`Expr`] tree (built by the SDL parser, which owns the token
//! stream), then a small stack bytecode ([`vm::Code`]) that evaluates without allocating.
//! `internal(N)` bodies point at the built-in functions of `functions.inc` ([`internal`]).
//! Special functions (`transform`, `pigment`, `pattern`, `spline`) are kept as what they are;
//! pigment and pattern functions are evaluated by the renderer's pigment and pattern code,
//! spline functions by [`spline`].
//!
//! A function that can be declared but not evaluated by lancer (an unknown internal number, a
//! pigment function, or a float function calling one of those) carries the reason in
//! [`Function::unsupported`]; callers check it once, before evaluating, so declaring such a
//! function (as `functions.inc` does for all of them) is never an error.

pub mod compile;
pub mod internal;
pub mod internal_curves;
pub mod internal_noise;
pub mod internal_polynomials;
pub mod internal_surfaces;
pub mod spline;
pub mod vm;

use std::sync::Arc;

use crate::math::{DVec3, Transform};

/// A one-argument maths built-in of the function language. `sqrt` and `abs` are named, not
/// held as function pointers, because the compiler turns them into instructions: recognising
/// them by pointer never worked reliably (an `#[inline]` function named in two codegen units is
/// two copies at two addresses).
#[derive(Clone, Copy, Debug)]
pub enum Math1 {
    Sqrt,
    Abs,
    /// Any other (`sin`, `exp`, `floor`, ...), called.
    Call(fn(f64) -> f64),
}

impl Math1 {
    #[inline]
    pub fn apply(self, x: f64) -> f64 {
        match self {
            Math1::Sqrt => x.sqrt(),
            Math1::Abs => x.abs(),
            Math1::Call(f) => f(x),
        }
    }
}

/// Most parameters a function may declare (POV-Ray's limit).
pub const MAX_PARAMS: usize = 56;

/// A declared function. Shared between identifiers and callers with `Arc`, because the render
/// threads of a later isosurface evaluate the same compiled code.
#[derive(Debug)]
pub struct Function {
    /// Parameter names in call order (`x`, `y`, `z` when none were written).
    pub params: Vec<String>,
    pub kind: FnKind,
    /// Why the function cannot be evaluated by lancer, if it cannot: it or a function it calls
    /// is not implemented.
    pub unsupported: Option<String>,
}

#[derive(Debug)]
pub enum FnKind {
    /// A float expression compiled to bytecode.
    Code(vm::Code),
    /// One of POV-Ray's built-in functions, bound by `functions.inc` as `internal(N)`.
    Internal(internal::Internal),
    /// `function { transform { ... } }`: a vector function of a point.
    Transform(Transform),
    /// `function { pigment {...} }`: a colour function of a point, with its key to the
    /// renderer's memo of the last value (read once per colour component at a point).
    Pigment(
        Box<crate::scene::desc::Pigment>,
        crate::render::pigment::Memo,
    ),
    /// `function { pattern {...} }`: the pattern's value (a block pattern's item number),
    /// kept as the pigment it was read as, for its transform.
    Pattern(Box<crate::scene::desc::Pigment>),
    /// One component of a vector or colour function's result (`F(x,y,z).y`, `P(..).gray`):
    /// 0-4 red, green, blue, filter, transmit; 5 POV-Ray's grey (0.297, 0.589, 0.114).
    Component(Arc<Function>, u8),
    /// `function { spline {...} }`: a vector function of one parameter, with as many
    /// components as the spline's longest point (2 to 5).
    Spline(Arc<spline::SplineDef>),
}

/// What a function returns when called from the scene language.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FnValue {
    Float(f64),
    Vector(DVec3),
    /// A spline function's point: components and how many of them there are (2 to 5).
    Components([f64; 5], u8),
}

/// A float expression in the function language, as the parser read it.
#[derive(Clone, Debug)]
pub enum Expr {
    Const(f64),
    /// A parameter or a `sum`/`prod` iteration variable, by slot.
    Slot(usize),
    Neg(Box<Expr>),
    Not(Box<Expr>),
    Bin(BinOp, Box<Expr>, Box<Expr>),
    /// A one-argument maths built-in (`sin`, `sqrt`, ...).
    Math1(Math1, Box<Expr>),
    /// A two-argument maths built-in (`pow`, `atan2`, `mod`, ...).
    Math2(fn(f64, f64) -> f64, Box<Expr>, Box<Expr>),
    Min(Vec<Expr>),
    Max(Vec<Expr>),
    /// `select(a, b, c)` or `select(a, b, c, d)`.
    Select(Vec<Expr>),
    Call(Arc<Function>, Vec<Expr>),
    /// `sum(i, from, to, body)` (`product` false) or `prod(...)` (`product` true).
    Loop {
        product: bool,
        var: usize,
        from: Box<Expr>,
        to: Box<Expr>,
        body: Box<Expr>,
    },
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinOp {
    Add,
    Sub,
    Mul,
    Div,
    Lt,
    Le,
    Eq,
    Ne,
    Ge,
    Gt,
    And,
    Or,
}

impl BinOp {
    /// The operator's value, for the VM and for constant folding alike. Comparisons and logic
    /// give 1 or 0, compared exactly as POV-Ray's function VM does.
    #[inline]
    pub fn apply(self, a: f64, b: f64) -> f64 {
        match self {
            BinOp::Add => a + b,
            BinOp::Sub => a - b,
            BinOp::Mul => a * b,
            BinOp::Div => a / b,
            BinOp::Lt => truth(a < b),
            BinOp::Le => truth(a <= b),
            BinOp::Eq => truth(a == b),
            BinOp::Ne => truth(a != b),
            BinOp::Ge => truth(a >= b),
            BinOp::Gt => truth(a > b),
            BinOp::And => truth(a != 0.0 && b != 0.0),
            BinOp::Or => truth(a != 0.0 || b != 0.0),
        }
    }
}

/// A condition as the function language's number: 1 or 0.
pub(super) fn truth(b: bool) -> f64 {
    if b {
        1.0
    } else {
        0.0
    }
}

impl Function {
    /// A float function from a parsed body; `slots` counts parameters plus iteration variables.
    pub fn from_expr(params: Vec<String>, body: &Expr, slots: usize) -> Function {
        let unsupported = first_unsupported(body);
        Function {
            params,
            kind: FnKind::Code(compile::compile(body, slots)),
            unsupported,
        }
    }

    pub fn internal(id: u32) -> Function {
        let f = internal::Internal::from_id(id);
        let unsupported = f.unsupported_reason();
        Function {
            params: (0..f.arity().unwrap_or(3))
                .map(|i| match i {
                    0 => "x".to_string(),
                    1 => "y".to_string(),
                    2 => "z".to_string(),
                    n => format!("P{}", n - 3),
                })
                .collect(),
            kind: FnKind::Internal(f),
            unsupported,
        }
    }

    pub fn transform(t: Transform) -> Function {
        Function {
            params: vec!["x".into(), "y".into(), "z".into()],
            kind: FnKind::Transform(t),
            unsupported: None,
        }
    }

    pub fn pigment(p: crate::scene::desc::Pigment) -> Function {
        let memo = crate::render::pigment::Memo::for_pigment(&p);
        Function {
            params: vec!["x".into(), "y".into(), "z".into()],
            kind: FnKind::Pigment(Box::new(p), memo),
            unsupported: None,
        }
    }

    pub fn pattern(p: crate::scene::desc::Pigment) -> Function {
        Function {
            params: vec!["x".into(), "y".into(), "z".into()],
            kind: FnKind::Pattern(Box::new(p)),
            unsupported: None,
        }
    }

    /// The float function giving component `index` (see [`FnKind::Component`]) of `f`.
    pub fn component(f: Arc<Function>, index: u8) -> Function {
        Function {
            params: f.params.clone(),
            unsupported: f.unsupported.clone(),
            kind: FnKind::Component(f, index),
        }
    }

    /// Whether `.x`, `.red`, `.gray` ... can be taken of this function's result.
    pub fn has_components(&self) -> bool {
        matches!(
            self.kind,
            FnKind::Transform(_) | FnKind::Pigment(..) | FnKind::Spline(_)
        )
    }

    /// `function { spline { ... } }`: called with the spline's parameter, it gives the spline's
    /// point with the spline's own type.
    pub fn spline(s: spline::SplineDef) -> Function {
        Function {
            params: vec!["x".into()],
            kind: FnKind::Spline(Arc::new(s)),
            unsupported: None,
        }
    }

    /// How many arguments a call must pass; `None` for internal functions whose parameter
    /// list lancer does not know (they are unsupported anyway).
    pub fn arity(&self) -> Option<usize> {
        match &self.kind {
            FnKind::Internal(f) => f.arity(),
            _ => Some(self.params.len()),
        }
    }

    /// Whether the function returns a float (as opposed to a vector or colour).
    pub fn is_float(&self) -> bool {
        matches!(
            self.kind,
            FnKind::Code(_) | FnKind::Internal(_) | FnKind::Pattern(_) | FnKind::Component(..)
        )
    }

    /// [`Function::eval`] of a point, for the isosurface search: compiled code (the common
    /// case) runs without the dispatch through `eval` and `Code::eval`.
    #[inline]
    pub fn eval_point(&self, p: [f64; 3]) -> f64 {
        match &self.kind {
            FnKind::Code(c) => c.eval_small(&p),
            _ => self.eval(&p),
        }
    }

    /// Evaluates a float function. `args` must have [`Function::arity`] values and the function
    /// must be supported (check [`Function::unsupported`] first); otherwise the result is
    /// meaningless (NaN), never a panic.
    pub fn eval(&self, args: &[f64]) -> f64 {
        match &self.kind {
            FnKind::Code(c) => c.eval(args),
            FnKind::Internal(f) => f.eval(args),
            FnKind::Pattern(p) => {
                use crate::scene::desc::PigmentKind;
                let world = point(args);
                let lp = p.transform.inv_point(world);
                match &p.kind {
                    PigmentKind::List { pattern, .. } => {
                        crate::render::pattern::index(pattern, lp) as f64
                    }
                    PigmentKind::Mapped { pattern, .. }
                    | PigmentKind::PigmentMap { pattern, .. } => {
                        crate::render::pattern::value(pattern, lp)
                    }
                    _ => 0.0,
                }
            }
            FnKind::Component(f, i) => match (&f.kind, *i) {
                (FnKind::Pigment(p, memo), i) => {
                    let c = crate::render::pigment::eval_memo(p, *memo, point(args));
                    match i {
                        0..=2 => c.rgb[i as usize],
                        3 => c.filter,
                        4 => c.transmit,
                        _ => 0.297 * c.rgb.x + 0.589 * c.rgb.y + 0.114 * c.rgb.z,
                    }
                }
                (FnKind::Transform(t), i) if i < 3 => t.point(point(args))[i as usize],
                (FnKind::Spline(s), i) if i < 5 => s.eval(first(args), s.kind)[i as usize],
                _ => f64::NAN,
            },
            FnKind::Transform(_) | FnKind::Pigment(..) | FnKind::Spline(_) => f64::NAN,
        }
    }

    /// Evaluates any supported function with the result type it has.
    pub fn call(&self, args: &[f64]) -> FnValue {
        match &self.kind {
            FnKind::Transform(t) => FnValue::Vector(t.point(point(args))),
            FnKind::Pigment(p, memo) => {
                FnValue::Vector(crate::render::pigment::eval_memo(p, *memo, point(args)).rgb)
            }
            FnKind::Spline(s) => FnValue::Components(s.eval(first(args), s.kind), s.dim.max(2)),
            _ => FnValue::Float(self.eval(args)),
        }
    }
}

/// A one-parameter function's argument (0 if the call gave none).
fn first(args: &[f64]) -> f64 {
    args.first().copied().unwrap_or(0.0)
}

/// The point a function of x, y, z is called at (missing arguments read as 0).
fn point(args: &[f64]) -> DVec3 {
    DVec3::new(
        args.first().copied().unwrap_or(0.0),
        args.get(1).copied().unwrap_or(0.0),
        args.get(2).copied().unwrap_or(0.0),
    )
}

/// The first reason a function called from `e` cannot be evaluated.
fn first_unsupported(e: &Expr) -> Option<String> {
    match e {
        Expr::Const(_) | Expr::Slot(_) => None,
        Expr::Neg(a) | Expr::Not(a) | Expr::Math1(_, a) => first_unsupported(a),
        Expr::Bin(_, a, b) | Expr::Math2(_, a, b) => {
            first_unsupported(a).or_else(|| first_unsupported(b))
        }
        Expr::Min(v) | Expr::Max(v) | Expr::Select(v) => v.iter().find_map(first_unsupported),
        Expr::Call(f, v) => f
            .unsupported
            .clone()
            .or_else(|| v.iter().find_map(first_unsupported)),
        Expr::Loop { from, to, body, .. } => first_unsupported(from)
            .or_else(|| first_unsupported(to))
            .or_else(|| first_unsupported(body)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn c(x: f64) -> Box<Expr> {
        Box::new(Expr::Const(x))
    }

    fn slot(i: usize) -> Box<Expr> {
        Box::new(Expr::Slot(i))
    }

    #[test]
    fn nested_loops_and_calls() {
        // sum(i, 1, x, prod(j, 1, i, y)) = y + y^2 + ... + y^x
        let body = Expr::Loop {
            product: false,
            var: 2,
            from: c(1.0),
            to: slot(0),
            body: Box::new(Expr::Loop {
                product: true,
                var: 3,
                from: c(1.0),
                to: slot(2),
                body: slot(1),
            }),
        };
        let f = Arc::new(Function::from_expr(vec!["x".into(), "y".into()], &body, 4));
        assert_eq!(f.eval(&[3.0, 2.0]), 14.0);
        assert_eq!(f.eval(&[0.0, 2.0]), 0.0);
        let g = Function::from_expr(
            vec!["a".into()],
            &Expr::Bin(
                BinOp::Add,
                Box::new(Expr::Call(f.clone(), vec![Expr::Slot(0), Expr::Const(3.0)])),
                Box::new(Expr::Call(f, vec![Expr::Const(1.0), Expr::Slot(0)])),
            ),
            1,
        );
        assert_eq!(g.eval(&[2.0]), (3.0 + 9.0) + 2.0);
    }

    #[test]
    fn constant_parts_are_folded_and_large_bodies_still_run() {
        let e = Expr::Bin(
            BinOp::Mul,
            c(2.0),
            Box::new(Expr::Math1(Math1::Sqrt, c(16.0))),
        );
        let f = Function::from_expr(vec!["x".into()], &e, 1);
        match &f.kind {
            FnKind::Code(code) => assert_eq!(code.ops.len(), 1),
            _ => unreachable!(),
        }
        assert_eq!(f.eval(&[0.0]), 8.0);
        // A right-leaning chain deeper than the inline stack: 1 + (x + (x + ...)).
        let mut e = Expr::Slot(0);
        for _ in 0..300 {
            e = Expr::Bin(BinOp::Add, slot(0), Box::new(e));
        }
        let f = Function::from_expr(vec!["x".into()], &e, 1);
        assert_eq!(f.eval(&[1.0]), 301.0);
    }

    #[test]
    fn select_and_comparisons_are_exact() {
        let e = Expr::Select(vec![
            Expr::Bin(BinOp::Sub, slot(0), slot(1)),
            Expr::Const(-1.0),
            Expr::Const(0.0),
            Expr::Const(1.0),
        ]);
        let f = Function::from_expr(vec!["a".into(), "b".into()], &e, 2);
        assert_eq!(f.eval(&[1.0, 1.0]), 0.0);
        assert_eq!(f.eval(&[1.0, 1.0 + 1e-12]), -1.0);
        assert_eq!(f.eval(&[2.0, 1.0]), 1.0);
    }
}
