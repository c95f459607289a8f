//! The stack machine that runs compiled function bodies.
//!
//! One flat instruction list per function; operands live on a value stack and parameters and
//! `sum`/`prod` variables in numbered slots. Both sit in one fixed array on the Rust stack, so
//! an evaluation allocates nothing unless a body is unusually large.

use std::sync::Arc;

use super::{truth, BinOp, Function};

/// Values kept on the Rust stack per evaluation (slots plus operand stack); bigger bodies fall
/// back to a heap buffer.
const INLINE: usize = 128;
/// The buffer for small bodies, the common case.
const SMALL: usize = 16;

#[derive(Clone, Debug)]
pub enum Op {
    Const(f64),
    Load(u32),
    /// Pops the top value into a slot.
    Store(u32),
    Neg,
    Not,
    /// Comparisons and logic; the four arithmetic operators have their own ops below.
    Bin(BinOp),
    Add,
    Sub,
    Mul,
    Div,
    /// `top = top <op> slots[s]`: a `Load(s)` and the operator in one dispatch.
    AddS(u32),
    SubS(u32),
    MulS(u32),
    DivS(u32),
    /// `top = top <op> c`: a `Const(c)` and the operator in one dispatch.
    AddC(f64),
    SubC(f64),
    MulC(f64),
    DivC(f64),
    /// Pushes `slots[a] * slots[b]` (`x*x`): two `Load`s and the product in one dispatch.
    MulSS(u32, u32),
    /// `f64::sqrt` and `f64::abs` as instructions rather than calls through a pointer.
    Sqrt,
    Abs,
    F1(fn(f64) -> f64),
    F2(fn(f64, f64) -> f64),
    /// Minimum or maximum of the top `n` values.
    Min(u32),
    Max(u32),
    Select3,
    Select4,
    /// Calls `callees[i]` with the top `n` values as arguments.
    Call(u32, u32),
    /// Pushes a copy of the value `k` places below the top.
    Pick(u32),
    /// Drops the value just below the top.
    Nip,
    Jump(u32),
    /// Pops a value and jumps when it is zero.
    JumpIfZero(u32),
}

#[derive(Debug)]
pub struct Code {
    pub(super) ops: Vec<Op>,
    pub(super) callees: Vec<Arc<Function>>,
    /// Parameter and iteration-variable slots.
    pub(super) slots: usize,
    /// Deepest operand stack the code reaches.
    pub(super) max_stack: usize,
}

impl Code {
    /// The instructions, for tests that check what the compiler made of a parsed body.
    #[cfg(test)]
    pub(crate) fn ops(&self) -> &[Op] {
        &self.ops
    }

    /// [`Code::eval`] for a hot caller (the isosurface search): a small body's buffer is set
    /// up in the caller, which then calls `run` directly, one call instead of three
    /// (`Function::eval`, `Code::eval`, `run`); bigger bodies take `eval`.
    #[inline]
    pub fn eval_small(&self, args: &[f64]) -> f64 {
        let need = self.slots + self.max_stack;
        if need <= SMALL {
            let mut buf = [0.0; SMALL];
            self.run(args, &mut buf[..need])
        } else {
            self.eval(args)
        }
    }

    pub fn eval(&self, args: &[f64]) -> f64 {
        let need = self.slots + self.max_stack;
        // Zeroing the whole inline buffer showed as 7% of an isosurface render; most bodies
        // need a few values.
        if need <= SMALL {
            let mut buf = [0.0; SMALL];
            self.run(args, &mut buf[..need])
        } else if need <= INLINE {
            let mut buf = [0.0; INLINE];
            self.run(args, &mut buf[..need])
        } else {
            let mut buf = vec![0.0; need];
            self.run(args, &mut buf)
        }
    }

    /// The top of the operand stack lives in a local (`top`), the values under it in
    /// `stack[..sp]`: most ops read and write only the top, so they chain through a register
    /// instead of a store and a reload. `stack[0]` holds whatever the top was when the first
    /// value was pushed (nothing), so `sp` equals the depth and the deepest point
    /// (`max_stack - 1`) still fits. The operations and their order are the plain stack's.
    #[inline(never)]
    fn run(&self, args: &[f64], buf: &mut [f64]) -> f64 {
        let (slots, stack) = buf.split_at_mut(self.slots);
        let n = args.len().min(slots.len());
        // Three arguments (x, y, z) are the common case; `copy_from_slice` of an unknown
        // length was a call to memmove, 2 % of an isosurface render.
        if n == 3 {
            slots[0] = args[0];
            slots[1] = args[1];
            slots[2] = args[2];
        } else {
            slots[..n].copy_from_slice(&args[..n]);
        }
        let mut sp = 0usize;
        let mut top = 0.0f64;
        let mut pc = 0usize;
        macro_rules! push {
            ($v:expr) => {{
                let v = $v;
                stack[sp] = top;
                sp += 1;
                top = v;
            }};
        }
        macro_rules! bin {
            ($f:expr) => {{
                sp -= 1;
                top = $f(stack[sp], top);
            }};
        }
        while let Some(op) = self.ops.get(pc) {
            pc += 1;
            match op {
                Op::Const(c) => push!(*c),
                Op::Load(s) => push!(slots[*s as usize]),
                Op::Store(s) => {
                    slots[*s as usize] = top;
                    sp -= 1;
                    top = stack[sp];
                }
                Op::Neg => top = -top,
                Op::Not => top = truth(top == 0.0),
                Op::Bin(o) => bin!(|a, b| o.apply(a, b)),
                Op::Add => bin!(|a, b| a + b),
                Op::Sub => bin!(|a, b| a - b),
                Op::Mul => bin!(|a, b| a * b),
                Op::Div => bin!(|a, b| a / b),
                Op::AddS(s) => top += slots[*s as usize],
                Op::SubS(s) => top -= slots[*s as usize],
                Op::MulS(s) => top *= slots[*s as usize],
                Op::DivS(s) => top /= slots[*s as usize],
                Op::AddC(c) => top += *c,
                Op::SubC(c) => top -= *c,
                Op::MulC(c) => top *= *c,
                Op::DivC(c) => top /= *c,
                Op::MulSS(a, b) => push!(slots[*a as usize] * slots[*b as usize]),
                Op::Sqrt => top = top.sqrt(),
                Op::Abs => top = top.abs(),
                Op::F1(f) => top = f(top),
                Op::F2(f) => bin!(f),
                Op::Min(n) | Op::Max(n) => {
                    // The values bottom to top: the `n - 1` under the top, then the top.
                    let n = *n as usize;
                    if n == 0 {
                        push!(if matches!(op, Op::Min(_)) {
                            f64::INFINITY
                        } else {
                            f64::NEG_INFINITY
                        });
                        continue;
                    }
                    let under = &stack[sp + 1 - n..sp];
                    top = if matches!(op, Op::Min(_)) {
                        f64::min(under.iter().copied().fold(f64::INFINITY, f64::min), top)
                    } else {
                        f64::max(under.iter().copied().fold(f64::NEG_INFINITY, f64::max), top)
                    };
                    sp -= n - 1;
                }
                Op::Select3 => {
                    sp -= 2;
                    let (a, b) = (stack[sp], stack[sp + 1]);
                    top = if a < 0.0 { b } else { top };
                }
                Op::Select4 => {
                    sp -= 3;
                    let (a, b, c) = (stack[sp], stack[sp + 1], stack[sp + 2]);
                    top = if a < 0.0 {
                        b
                    } else if a == 0.0 {
                        c
                    } else {
                        top
                    };
                }
                Op::Call(i, n) => {
                    // The arguments contiguous in memory: the top goes above the others.
                    let n = *n as usize;
                    stack[sp] = top;
                    let from = sp + 1 - n;
                    top = self.callees[*i as usize].eval(&stack[from..sp + 1]);
                    sp = from;
                }
                Op::Pick(k) => {
                    let v = if *k == 0 {
                        top
                    } else {
                        stack[sp - *k as usize]
                    };
                    push!(v);
                }
                Op::Nip => sp -= 1,
                Op::Jump(t) => pc = *t as usize,
                Op::JumpIfZero(t) => {
                    let c = top;
                    sp -= 1;
                    top = stack[sp];
                    if c == 0.0 {
                        pc = *t as usize;
                    }
                }
            }
        }
        if sp == 0 {
            f64::NAN
        } else {
            top
        }
    }
}
