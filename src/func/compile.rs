//! Turns a function body's expression tree into stack bytecode, folding constant parts.

use std::sync::Arc;

use super::vm::{Code, Op};
use super::{truth, BinOp, Expr, Function};

struct Emitter {
    ops: Vec<Op>,
    callees: Vec<Arc<Function>>,
    depth: usize,
    max_depth: usize,
}

impl Emitter {
    fn push(&mut self, op: Op, delta: isize) {
        self.ops.push(op);
        self.depth = (self.depth as isize + delta).max(0) as usize;
        self.max_depth = self.max_depth.max(self.depth);
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
                self.expr(a);
                self.expr(b);
                self.push(Op::Bin(*op), -1);
            }
            Expr::Math1(f, a) => {
                self.expr(a);
                self.push(Op::F1(*f), 0);
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
                for a in v {
                    self.expr(a);
                }
                let i = match self.callees.iter().position(|c| Arc::ptr_eq(c, f)) {
                    Some(i) => i,
                    None => {
                        self.callees.push(f.clone());
                        self.callees.len() - 1
                    }
                };
                let n = v.len() as u32;
                self.push(Op::Call(i as u32, n), 1 - n as isize);
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
                let top = self.ops.len() as u32;
                self.push(Op::Pick(1), 1);
                self.push(Op::Load(var), 1);
                self.push(Op::Bin(BinOp::Ge), -1);
                let jump_at = self.ops.len();
                self.push(Op::JumpIfZero(0), -1);
                self.expr(body);
                let step = if *product { BinOp::Mul } else { BinOp::Add };
                self.push(Op::Bin(step), -1);
                self.push(Op::Load(var), 1);
                self.push(Op::Const(1.0), 1);
                self.push(Op::Bin(BinOp::Add), -1);
                self.push(Op::Store(var), -1);
                self.push(Op::Jump(top), 0);
                let exit = self.ops.len() as u32;
                self.ops[jump_at] = Op::JumpIfZero(exit);
                self.push(Op::Nip, -1);
            }
        }
    }
}

/// The value of an expression that depends on no slot and calls nothing.
fn fold(e: &Expr) -> Option<f64> {
    Some(match e {
        Expr::Const(c) => *c,
        Expr::Slot(_) | Expr::Call(..) | Expr::Loop { .. } => return None,
        Expr::Neg(a) => -fold(a)?,
        Expr::Not(a) => truth(fold(a)? == 0.0),
        Expr::Math1(f, a) => f(fold(a)?),
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
    };
    e.expr(body);
    Code {
        ops: e.ops,
        callees: e.callees,
        slots,
        max_stack: e.max_depth + 1,
    }
}
