//! Two quaternion inside tests at once, for the julia bisection.
//!
//! A quaternion orbit is one dependent chain (each iterate waits for the last), so a lone
//! orbit leaves most of the floating-point units idle. Two orbits run side by side here, each
//! lane doing exactly the operations of `Julia::quaternion_orbit` in the same order (the same
//! products and sums, no fused multiply-add, no reassociation), so each lane's answer is the
//! lone orbit's to the bit. The lanes run in lockstep until both have decided.

use super::{qnorm_sq, Julia, JuliaFn, Q, KEEP};
use crate::math::DVec3;

/// Two numbers, one per lane; the element-wise operations vectorise to SSE2.
#[derive(Clone, Copy)]
struct V2([f64; 2]);

impl std::ops::Add for V2 {
    type Output = V2;
    #[inline(always)]
    fn add(self, o: V2) -> V2 {
        V2([self.0[0] + o.0[0], self.0[1] + o.0[1]])
    }
}

impl std::ops::Sub for V2 {
    type Output = V2;
    #[inline(always)]
    fn sub(self, o: V2) -> V2 {
        V2([self.0[0] - o.0[0], self.0[1] - o.0[1]])
    }
}

impl std::ops::Mul for V2 {
    type Output = V2;
    #[inline(always)]
    fn mul(self, o: V2) -> V2 {
        V2([self.0[0] * o.0[0], self.0[1] * o.0[1]])
    }
}

type Q2 = [V2; 4];

/// `qmul` lane by lane, with its association.
#[inline(always)]
fn qmul2(p: &Q2, q: &Q2) -> Q2 {
    [
        p[0] * q[0] - p[1] * q[1] - p[2] * q[2] - p[3] * q[3],
        p[0] * q[1] + p[1] * q[0] + p[2] * q[3] - p[3] * q[2],
        p[0] * q[2] - p[1] * q[3] + p[2] * q[0] + p[3] * q[1],
        p[0] * q[3] + p[1] * q[2] - p[2] * q[1] + p[3] * q[0],
    ]
}

/// `qnorm_sq` lane by lane.
#[inline(always)]
fn qnorm_sq2(h: &Q2) -> V2 {
    h[0] * h[0] + h[1] * h[1] + h[2] * h[2] + h[3] * h[3]
}

impl Julia {
    /// `[self.is_in(p[0]), self.is_in(p[1])]`, the two orbits run side by side where they are
    /// quaternion ones.
    pub(super) fn is_in2(&self, p: [DVec3; 2]) -> [bool; 2] {
        match self.algebra {
            super::Algebra::Quaternion if self.func == JuliaFn::Cube => {
                self.inside2::<true>([self.lift(p[0]).0, self.lift(p[1]).0])
            }
            super::Algebra::Quaternion => {
                self.inside2::<false>([self.lift(p[0]).0, self.lift(p[1]).0])
            }
            super::Algebra::Hypercomplex => [self.is_in(p[0]), self.is_in(p[1])],
        }
    }

    /// `quaternion_orbit::<CUBE, false>` of two points, as inside-ness.
    #[inline(always)]
    fn inside2<const CUBE: bool>(&self, h: [Q; 2]) -> [bool; 2] {
        let steps = self.max_iteration.saturating_sub(1);
        let bail_sq = self.bail_sq;
        // Per lane: None while undecided, then the lone orbit's answer.
        let mut done: [Option<bool>; 2] = [None, None];
        for (d, hl) in done.iter_mut().zip(&h) {
            if qnorm_sq(hl) > bail_sq {
                *d = Some(false);
            }
        }
        if done[0].is_some() && done[1].is_some() {
            return [false, false];
        }
        let mut h: Q2 = std::array::from_fn(|i| V2([h[0][i], h[1][i]]));
        let c: Q2 = self.param.map(|x| V2([x, x]));
        for k in 0..steps {
            let h2 = qmul2(&h, &h);
            let f = if CUBE { qmul2(&h, &h2) } else { h2 };
            h = std::array::from_fn(|i| f[i] + c[i]);
            let s = qnorm_sq2(&h);
            let left = (steps - 1 - k) as usize;
            for (d, &s) in done.iter_mut().zip(&s.0) {
                if d.is_none() {
                    if s > bail_sq {
                        *d = Some(false);
                    } else if left < KEEP && s <= self.keep_sq[left] {
                        *d = Some(true);
                    }
                }
            }
            if done[0].is_some() && done[1].is_some() {
                break;
            }
        }
        done.map(|d| d.unwrap_or(true))
    }
}
