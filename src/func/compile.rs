//! Turns a function body's expression tree into stack bytecode, folding constant parts.

use std::sync::Arc;

use super::vm::{Code, Op};
use super::{truth, BinOp, Expr, FnKind, Function, Math1};

struct Emitter {
    ops: Vec<Op>,
    callees: Vec<Arc<Function>>,
    depth: usize,
    max_depth: usize,
    /// Ops before this index may not be fused with the next one: a jump lands at or after it.
    label: usize,
    /// The next slot free for an inlined call's computed argument (above the body's own
    /// slots), and the most slots used.
    next_slot: usize,
    max_slots: usize,
}

/// Longest callee body copied into its caller: past that the call's own cost is small beside
/// the body's, and copies would multiply.
const INLINE_OPS: usize = 64;

/// Where an inlined callee reads its parameter: a slot of the caller or a constant.
#[derive(Clone, Copy)]
enum Arg {
    Slot(u32),
    Const(f64),
}

impl Emitter {
    fn push(&mut self, op: Op, delta: isize) {
        self.ops.push(op);
        self.depth = (self.depth as isize + delta).max(0) as usize;
        self.max_depth = self.max_depth.max(self.depth);
    }

    /// A jump will land at the next op: it must stay an op of its own.
    fn mark_label(&mut self) -> u32 {
        self.label = self.ops.len();
        self.ops.len() as u32
    }

    /// An arithmetic operator, fused with the `Load` or `Const` just before it when that op
    /// is no jump target: the same operation on the same operands, one dispatch fewer.
    fn arith(&mut self, op: BinOp) {
        let last = if self.ops.len() > self.label {
            self.ops.last()
        } else {
            None
        };
        let fused = match (last, op) {
            (Some(Op::Load(s)), BinOp::Add) => Some(Op::AddS(*s)),
            (Some(Op::Load(s)), BinOp::Sub) => Some(Op::SubS(*s)),
            (Some(Op::Load(s)), BinOp::Mul) => Some(Op::MulS(*s)),
            (Some(Op::Load(s)), BinOp::Div) => Some(Op::DivS(*s)),
            (Some(Op::Const(c)), BinOp::Add) => Some(Op::AddC(*c)),
            (Some(Op::Const(c)), BinOp::Sub) => Some(Op::SubC(*c)),
            (Some(Op::Const(c)), BinOp::Mul) => Some(Op::MulC(*c)),
            (Some(Op::Const(c)), BinOp::Div) => Some(Op::DivC(*c)),
            _ => None,
        };
        if let Some(f) = fused {
            // The operand's push and the operator's pop cancel: the depth is the one before
            // the operand, and the deepest point so far is unchanged.
            self.ops.pop();
            self.depth -= 1;
            // `Load(a)` just before as well (the left operand): one op pushes the product.
            let n = self.ops.len();
            if let (Op::MulS(b), true) = (&f, n > self.label) {
                if let Some(&Op::Load(a)) = self.ops.last() {
                    self.ops[n - 1] = Op::MulSS(a, *b);
                    return;
                }
            }
            self.ops.push(f);
            return;
        }
        let plain = match op {
            BinOp::Add => Op::Add,
            BinOp::Sub => Op::Sub,
            BinOp::Mul => Op::Mul,
            BinOp::Div => Op::Div,
            _ => Op::Bin(op),
        };
        self.push(plain, -1);
    }

    fn callee(&mut self, f: &Arc<Function>) -> u32 {
        let i = match self.callees.iter().position(|c| Arc::ptr_eq(c, f)) {
            Some(i) => i,
            None => {
                self.callees.push(f.clone());
                self.callees.len() - 1
            }
        };
        i as u32
    }

    /// A call of a compiled function without loops, emitted as the callee's own ops reading
    /// the caller's slots: a plain slot or constant argument is read where the callee reads
    /// its parameter, any other is computed first (in argument order, as the call would) into
    /// a slot of its own. The callee's operations on the same values in the same order, with no
    /// second evaluation set up (dispatch on the kind, buffer, argument copy, loop). False
    /// (nothing emitted) when the call is not of that kind.
    fn inline(&mut self, f: &Function, args: &[Expr]) -> bool {
        let FnKind::Code(c) = &f.kind else {
            return false;
        };
        // A callee that stores (loops) could read a slot before writing it; an argument with
        // a loop could change a caller slot another argument reads later than the call would.
        if c.slots != args.len()
            || c.ops.len() > INLINE_OPS
            || args.iter().any(has_loop)
            || c.ops.iter().any(|op| {
                matches!(
                    op,
                    Op::Store(_) | Op::Jump(_) | Op::JumpIfZero(_) | Op::Pick(_) | Op::Nip
                )
            })
        {
            return false;
        }
        let mark = self.next_slot;
        let mut map = Vec::with_capacity(args.len());
        for a in args {
            if let Some(k) = fold(a) {
                map.push(Arg::Const(k));
            } else if let Expr::Slot(s) = a {
                map.push(Arg::Slot(*s as u32));
            } else {
                self.expr(a);
                let s = self.next_slot as u32;
                self.next_slot += 1;
                self.max_slots = self.max_slots.max(self.next_slot);
                self.push(Op::Store(s), -1);
                map.push(Arg::Slot(s));
            }
        }
        let depth = self.depth;
        self.max_depth = self.max_depth.max(depth + c.max_stack - 1);
        for op in &c.ops {
            let slot = |s: &u32| map[*s as usize];
            // An operation on a callee's slot becomes the same operation on the caller's slot,
            // or its constant form where the argument folded to a number.
            let on = |a: Arg, by_slot: fn(u32) -> Op, by_const: fn(f64) -> Op| match a {
                Arg::Slot(t) => by_slot(t),
                Arg::Const(k) => by_const(k),
            };
            let op = match op {
                Op::Load(s) => on(slot(s), Op::Load, Op::Const),
                Op::AddS(s) => on(slot(s), Op::AddS, Op::AddC),
                Op::SubS(s) => on(slot(s), Op::SubS, Op::SubC),
                Op::MulS(s) => on(slot(s), Op::MulS, Op::MulC),
                Op::DivS(s) => on(slot(s), Op::DivS, Op::DivC),
                Op::MulSS(a, b) => match (slot(a), slot(b)) {
                    (Arg::Slot(p), Arg::Slot(q)) => Op::MulSS(p, q),
                    // The left factor pushed, then the product with the right one.
                    (a, b) => {
                        self.ops.push(on(a, Op::Load, Op::Const));
                        on(b, Op::MulS, Op::MulC)
                    }
                },
                Op::Call(i, n) => Op::Call(self.callee(&c.callees[*i as usize]), *n),
                other => other.clone(),
            };
            self.ops.push(op);
        }
        self.depth = depth + 1;
        self.max_depth = self.max_depth.max(self.depth);
        self.next_slot = mark;
        true
    }

    fn expr(&mut self, e: &Expr) {
        if let Some(c) = fold(e) {
            self.push(Op::Const(c), 1);
            return;
        }
        match e {
            Expr::Const(c) => self.push(Op::Const(*c), 1),
            Expr::Slot(s) => self.push(Op::Load(*s as u32), 1),
            Expr::Neg(a) => {
                self.expr(a);
                self.push(Op::Neg, 0);
            }
            Expr::Not(a) => {
                self.expr(a);
                self.push(Op::Not, 0);
            }
            Expr::Bin(op, a, b) => {
                // `c + b` and `c * b` are `b + c` and `b * c` to the bit (IEEE sums and products
                // commute; with one operand a number, a NaN result is the other's NaN either
                // way), and a constant reads no slot that `b` could change: emitted as `b`
                // then `AddC`/`MulC`.
                if let (BinOp::Add | BinOp::Mul, Some(c)) = (op, fold(a)) {
                    if !c.is_nan() {
                        self.expr(b);
                        self.push(Op::Const(c), 1);
                        self.arith(*op);
                        return;
                    }
                }
                self.expr(a);
                self.expr(b);
                self.arith(*op);
            }
            Expr::Math1(f, a) => {
                self.expr(a);
                let op = match *f {
                    Math1::Sqrt => Op::Sqrt,
                    Math1::Abs => Op::Abs,
                    Math1::Call(g) => Op::F1(g),
                };
                self.push(op, 0);
            }
            Expr::Math2(f, a, b) => {
                self.expr(a);
                self.expr(b);
                self.push(Op::F2(*f), -1);
            }
            Expr::Min(v) | Expr::Max(v) => {
                for a in v {
                    self.expr(a);
                }
                let n = v.len() as u32;
                let op = if matches!(e, Expr::Min(_)) {
                    Op::Min(n)
                } else {
                    Op::Max(n)
                };
                self.push(op, 1 - n as isize);
            }
            Expr::Select(v) => {
                for a in v {
                    self.expr(a);
                }
                if v.len() == 4 {
                    self.push(Op::Select4, -3);
                } else {
                    self.push(Op::Select3, -2);
                }
            }
            Expr::Call(f, v) => {
                if self.inline(f, v) {
                    return;
                }
                for a in v {
                    self.expr(a);
                }
                let i = self.callee(f);
                let n = v.len() as u32;
                self.push(Op::Call(i, n), 1 - n as isize);
            }
            Expr::Loop {
                product,
                var,
                from,
                to,
                body,
            } => {
                // The end value is kept on the stack under the accumulator, so nested loops
                // need no hidden slots: [.., end, acc] at the top of each turn.
                let var = *var as u32;
                self.expr(from);
                self.push(Op::Store(var), -1);
                self.expr(to);
                self.push(Op::Const(if *product { 1.0 } else { 0.0 }), 1);
                let top = self.mark_label();
                self.push(Op::Pick(1), 1);
                self.push(Op::Load(var), 1);
                self.push(Op::Bin(BinOp::Ge), -1);
                let jump_at = self.ops.len();
                self.push(Op::JumpIfZero(0), -1);
                self.expr(body);
                let step = if *product { BinOp::Mul } else { BinOp::Add };
                self.arith(step);
                self.push(Op::Load(var), 1);
                self.push(Op::Const(1.0), 1);
                self.arith(BinOp::Add);
                self.push(Op::Store(var), -1);
                self.push(Op::Jump(top), 0);
                let exit = self.mark_label();
                self.ops[jump_at] = Op::JumpIfZero(exit);
                self.push(Op::Nip, -1);
            }
        }
    }
}

/// Whether a `sum` or `prod` (which stores into a slot) is anywhere in `e`.
fn has_loop(e: &Expr) -> bool {
    match e {
        Expr::Const(_) | Expr::Slot(_) => false,
        Expr::Loop { .. } => true,
        Expr::Neg(a) | Expr::Not(a) | Expr::Math1(_, a) => has_loop(a),
        Expr::Bin(_, a, b) | Expr::Math2(_, a, b) => has_loop(a) || has_loop(b),
        Expr::Min(v) | Expr::Max(v) | Expr::Select(v) | Expr::Call(_, v) => v.iter().any(has_loop),
    }
}

/// The value of an expression that depends on no slot and calls nothing.
fn fold(e: &Expr) -> Option<f64> {
    Some(match e {
        Expr::Const(c) => *c,
        Expr::Slot(_) | Expr::Call(..) | Expr::Loop { .. } => return None,
        Expr::Neg(a) => -fold(a)?,
        Expr::Not(a) => truth(fold(a)? == 0.0),
        Expr::Math1(f, a) => f.apply(fold(a)?),
        Expr::Math2(f, a, b) => f(fold(a)?, fold(b)?),
        Expr::Bin(op, a, b) => op.apply(fold(a)?, fold(b)?),
        Expr::Min(v) => v
            .iter()
            .map(fold)
            .try_fold(f64::INFINITY, |m, x| Some(m.min(x?)))?,
        Expr::Max(v) => v
            .iter()
            .map(fold)
            .try_fold(f64::NEG_INFINITY, |m, x| Some(m.max(x?)))?,
        Expr::Select(v) => {
            let a = fold(&v[0])?;
            let pick = if a < 0.0 {
                1
            } else if v.len() == 3 || a == 0.0 {
                2
            } else {
                3
            };
            // Only the chosen branch has to be constant.
            fold(&v[pick])?
        }
    })
}

/// Compiles a body whose parameters and iteration variables use `slots` slots.
pub fn compile(body: &Expr, slots: usize) -> Code {
    let mut e = Emitter {
        ops: Vec::new(),
        callees: Vec::new(),
        depth: 0,
        max_depth: 0,
        label: 0,
        next_slot: slots,
        max_slots: slots,
    };
    e.expr(body);
    Code {
        ops: e.ops,
        callees: e.callees,
        slots: e.max_slots,
        max_stack: e.max_depth + 1,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The expression's value by walking its tree, the order of operations the bytecode
    /// (fused or not) must keep.
    fn walk(e: &Expr, slots: &mut [f64]) -> f64 {
        match e {
            Expr::Const(c) => *c,
            Expr::Slot(s) => slots[*s],
            Expr::Neg(a) => -walk(a, slots),
            Expr::Not(a) => truth(walk(a, slots) == 0.0),
            Expr::Bin(op, a, b) => {
                let a = walk(a, slots);
                op.apply(a, walk(b, slots))
            }
            Expr::Math1(f, a) => f.apply(walk(a, slots)),
            Expr::Math2(f, a, b) => {
                let a = walk(a, slots);
                f(a, walk(b, slots))
            }
            Expr::Loop {
                product,
                var,
                from,
                to,
                body,
            } => {
                slots[*var] = walk(from, slots);
                let end = walk(to, slots);
                let mut acc = if *product { 1.0 } else { 0.0 };
                while end >= slots[*var] {
                    let b = walk(body, slots);
                    acc = if *product { acc * b } else { acc + b };
                    slots[*var] += 1.0;
                }
                acc
            }
            Expr::Min(v) => v
                .iter()
                .map(|a| walk(a, slots))
                .collect::<Vec<_>>()
                .into_iter()
                .fold(f64::INFINITY, f64::min),
            Expr::Max(v) => v
                .iter()
                .map(|a| walk(a, slots))
                .collect::<Vec<_>>()
                .into_iter()
                .fold(f64::NEG_INFINITY, f64::max),
            Expr::Select(v) => {
                let vals: Vec<f64> = v.iter().map(|a| walk(a, slots)).collect();
                if vals[0] < 0.0 {
                    vals[1]
                } else if vals.len() == 3 || vals[0] == 0.0 {
                    vals[2]
                } else {
                    vals[3]
                }
            }
            Expr::Call(f, v) => {
                let args: Vec<f64> = v.iter().map(|a| walk(a, slots)).collect();
                f.eval(&args)
            }
        }
    }

    fn bin(op: BinOp, a: Expr, b: Expr) -> Expr {
        Expr::Bin(op, Box::new(a), Box::new(b))
    }

    /// `a*a - b`: a callee with a two-slot product and a slot operand.
    fn sq_sub() -> std::sync::Arc<Function> {
        std::sync::Arc::new(Function::from_expr(
            vec!["a".into(), "b".into()],
            &bin(
                BinOp::Sub,
                bin(BinOp::Mul, Expr::Slot(0), Expr::Slot(0)),
                Expr::Slot(1),
            ),
            2,
        ))
    }

    #[test]
    fn fused_operators_give_the_tree_walks_bits() {
        use BinOp::*;
        use Expr::{Const as K, Slot as S};
        let (x, y, z) = (|| S(0), || S(1), || S(2));
        let sqrt = |a: Expr| Expr::Math1(Math1::Sqrt, Box::new(a));
        let bodies = [
            // y - sin(x*4*pi)*0.1
            bin(
                Sub,
                y(),
                bin(
                    Mul,
                    Expr::Math1(
                        Math1::Call(f64::sin),
                        Box::new(bin(Mul, bin(Mul, x(), K(4.0)), K(std::f64::consts::PI))),
                    ),
                    K(0.1),
                ),
            ),
            // sqrt(x*x + y*y + z*z) - 0.9 + abs(z / y) - 3 / x
            bin(
                Sub,
                bin(
                    Add,
                    bin(
                        Sub,
                        sqrt(bin(
                            Add,
                            bin(Add, bin(Mul, x(), x()), bin(Mul, y(), y())),
                            bin(Mul, z(), z()),
                        )),
                        K(0.9),
                    ),
                    Expr::Math1(Math1::Abs, Box::new(bin(Div, z(), y()))),
                ),
                bin(Div, K(3.0), x()),
            ),
            // sum(i, 1, 4, i * x) + prod(j, 2, 3, y / j) - z  (slots 3 and 4 are i and j)
            bin(
                Sub,
                bin(
                    Add,
                    Expr::Loop {
                        product: false,
                        var: 3,
                        from: Box::new(K(1.0)),
                        to: Box::new(K(4.0)),
                        body: Box::new(bin(Mul, S(3), x())),
                    },
                    Expr::Loop {
                        product: true,
                        var: 4,
                        from: Box::new(K(2.0)),
                        to: Box::new(K(3.0)),
                        body: Box::new(bin(Div, y(), S(4))),
                    },
                ),
                z(),
            ),
            // 12*atan2(x, z) + (0.5 + x*y) * -0.0: constants on the left of commuting ops
            bin(
                Add,
                bin(
                    Mul,
                    K(12.0),
                    Expr::Math2(f64::atan2, Box::new(x()), Box::new(z())),
                ),
                bin(Mul, bin(Add, K(0.5), bin(Mul, x(), y())), K(-0.0)),
            ),
            // a loop whose body is one slot: the step's add follows the body's load
            Expr::Loop {
                product: false,
                var: 3,
                from: Box::new(x()),
                to: Box::new(y()),
                body: Box::new(S(3)),
            },
            // min/max of one to four values (NaN and signed zeros reach them), select with
            // three and four values, comparisons, logic and `!`, deep enough to spill
            bin(
                Add,
                bin(
                    Sub,
                    Expr::Min(vec![x(), bin(Mul, y(), K(0.0)), bin(Div, z(), x())]),
                    Expr::Max(vec![bin(Sub, x(), x()), z()]),
                ),
                bin(
                    Mul,
                    Expr::Select(vec![
                        bin(Sub, x(), y()),
                        Expr::Min(vec![y()]),
                        Expr::Not(Box::new(bin(Lt, x(), z()))),
                        Expr::Max(vec![x(), y(), z(), bin(Mul, x(), y())]),
                    ]),
                    Expr::Select(vec![
                        z(),
                        bin(And, x(), bin(Ge, y(), K(0.5))),
                        bin(Or, bin(Eq, x(), y()), bin(Ne, z(), K(0.0))),
                    ]),
                ),
            ),
            // calls of a compiled function with plain and computed arguments, and with none
            bin(
                Sub,
                Expr::Call(
                    std::sync::Arc::new(Function::from_expr(
                        vec!["a".into(), "b".into(), "c".into()],
                        &bin(Sub, bin(Mul, S(0), S(1)), bin(Div, S(2), K(3.0))),
                        3,
                    )),
                    vec![z(), bin(Add, x(), K(1.0)), y()],
                ),
                bin(
                    Mul,
                    Expr::Call(
                        std::sync::Arc::new(Function::from_expr(
                            vec![],
                            &Expr::Math1(Math1::Call(f64::sin), Box::new(K(0.25))),
                            0,
                        )),
                        vec![],
                    ),
                    Expr::Neg(Box::new(x())),
                ),
            ),
            // a call in a loop body with the loop's variable as an argument, a call among
            // another call's arguments, a constant argument, and a callee squaring its argument
            Expr::Loop {
                product: false,
                var: 3,
                from: Box::new(K(-1.0)),
                to: Box::new(K(2.0)),
                body: Box::new(Expr::Call(
                    sq_sub(),
                    vec![S(3), Expr::Call(sq_sub(), vec![bin(Mul, x(), y()), K(0.5)])],
                )),
            },
        ];
        let mut rnd = crate::math::xorshift_unit(7);
        for body in &bodies {
            let code = compile(body, 5);
            let special = [
                [0.0, -0.0, 0.0],
                [f64::NAN, 1.0, -0.0],
                [f64::INFINITY, -0.5, f64::NEG_INFINITY],
            ];
            for k in 0..200 {
                let args = special
                    .get(k)
                    .copied()
                    .unwrap_or_else(|| [rnd() * 8.0 - 4.0, rnd() * 8.0 - 4.0, rnd() * 8.0 - 4.0]);
                let mut slots = [args[0], args[1], args[2], 0.0, 0.0];
                let want = walk(body, &mut slots);
                let got = code.eval(&args);
                assert_eq!(got.to_bits(), want.to_bits(), "{body:?} at {args:?}");
            }
        }
    }
}
