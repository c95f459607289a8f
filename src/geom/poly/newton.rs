//! `polish`'s Newton iteration one step at a time, so that a walk can polish two critical
//! points' brackets together: their steps are independent chains (each waits on its own
//! division), and interleaved they overlap on the core where one alone leaves it idle.
//!
//! Each bracket takes exactly the steps `polish_body` takes, the same IEEE operations in the
//! same order, so its root is `polish`'s, bit for bit (test `raced_polish_is_polish`).

use super::eval_with_derivative;

/// A bracket's polish part way through: the state of `polish_body`'s loop between steps.
#[derive(Clone, Copy, Debug)]
pub(super) struct Newton {
    a: f64,
    b: f64,
    x: f64,
    step: f64,
    prev_step: f64,
    neg_at_a: bool,
    left: u32,
}

/// A polish the walk started ahead of its turn: its root, or its state when its partner
/// finished first.
#[derive(Clone, Copy, Debug)]
pub(super) enum Ahead {
    Root(f64),
    Part(Newton),
}

impl Newton {
    #[inline(always)]
    pub(super) fn new(a: f64, b: f64, neg_at_a: bool) -> Newton {
        Newton {
            a,
            b,
            x: 0.5 * (a + b),
            step: b - a,
            prev_step: b - a,
            neg_at_a,
            left: 100,
        }
    }

    /// One pass of `polish_body`'s loop: the root once it is done.
    #[inline(always)]
    pub(super) fn step(&mut self, c: &[f64]) -> Option<f64> {
        if self.left == 0 {
            return Some(self.x);
        }
        self.left -= 1;
        let x = self.x;
        let (f, df) = eval_with_derivative(c, x);
        if f == 0.0 {
            return Some(x);
        }
        if (f < 0.0) == self.neg_at_a {
            self.a = x;
        } else {
            self.b = x;
        }
        let newton = x - f / df;
        let next = if newton > self.a
            && newton < self.b
            && (newton - x).abs() < 0.5 * self.prev_step.abs()
        {
            newton
        } else {
            0.5 * (self.a + self.b)
        };
        self.prev_step = self.step;
        self.step = next - x;
        let tol = 2.0 * f64::EPSILON * next.abs() + f64::MIN_POSITIVE;
        if self.step.abs() <= tol || self.b - self.a <= tol {
            return Some(next);
        }
        self.x = next;
        None
    }

    /// The rest of the polish alone.
    #[inline(always)]
    pub(super) fn finish(mut self, c: &[f64]) -> f64 {
        loop {
            if let Some(r) = self.step(c) {
                return r;
            }
        }
    }

    /// `self`'s root, with `other` stepped beside it until either is done: `other`'s root or
    /// its state, for the walk to take up when it reaches it.
    #[inline(always)]
    pub(super) fn race(mut self, mut other: Newton, c: &[f64]) -> (f64, Ahead) {
        loop {
            if let Some(r) = self.step(c) {
                return (r, Ahead::Part(other));
            }
            if let Some(r) = other.step(c) {
                return (self.finish(c), Ahead::Root(r));
            }
        }
    }
}
