//! Two quaternion orbits at once, for the julia bisection and march.
//!
//! A quaternion orbit is one dependent chain (each iterate waits for the last), so a lone
//! orbit leaves most of the floating-point units idle. Two orbits run side by side here, each
//! lane doing exactly the operations of `Julia::quaternion_orbit` in the same order (the same
//! products and sums, no fused multiply-add, no reassociation), so each lane's answer is the
//! lone orbit's to the bit. The lanes run in lockstep until both have decided.

use super::{qnorm, qnorm_sq, Julia, JuliaFn, Orbit, Q, KEEP};
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

impl V2 {
    #[inline(always)]
    fn sqrt(self) -> V2 {
        V2([self.0[0].sqrt(), self.0[1].sqrt()])
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

    /// `[self.orbit(p[0]), self.orbit(p[1])]`, the two orbits run side by side where they
    /// are quaternion ones.
    pub(super) fn orbit2(&self, p: [DVec3; 2]) -> [Orbit; 2] {
        match self.algebra {
            super::Algebra::Quaternion if self.func == JuliaFn::Cube => {
                self.orbits2::<true>([self.lift(p[0]).0, self.lift(p[1]).0])
            }
            super::Algebra::Quaternion => {
                self.orbits2::<false>([self.lift(p[0]).0, self.lift(p[1]).0])
            }
            super::Algebra::Hypercomplex => [self.orbit(p[0]), self.orbit(p[1])],
        }
    }

    /// `quaternion_orbit::<CUBE, true>` of two points.
    #[inline(always)]
    fn orbits2<const CUBE: bool>(&self, h: [Q; 2]) -> [Orbit; 2] {
        let steps = self.max_iteration.saturating_sub(1);
        let bail = self.bailout;
        let bits = |b: [bool; 2]| b[0] as u32 | (b[1] as u32) << 1;
        let mut r = V2([qnorm(&h[0]), qnorm(&h[1])]);
        let mut dr = V2([1.0, 1.0]);
        // Per lane, the `r` and `dr` of its escape (`out`'s bits) once `decided`.
        let mut found = [(r.0[0], 1.0), (r.0[1], 1.0)];
        let mut out = bits([r.0[0] > bail, r.0[1] > bail]);
        let mut decided = out;
        if decided != 3 {
            let mut h: Q2 = std::array::from_fn(|i| V2([h[0][i], h[1][i]]));
            let c: Q2 = self.param.map(|x| V2([x, x]));
            let (two, three) = (V2([2.0, 2.0]), V2([3.0, 3.0]));
            for k in 0..steps {
                let h2 = qmul2(&h, &h);
                let f = if CUBE { qmul2(&h, &h2) } else { h2 };
                h = std::array::from_fn(|i| f[i] + c[i]);
                dr = dr * if CUBE { three * r * r } else { two * r };
                r = qnorm_sq2(&h).sqrt();
                let esc = bits([r.0[0] > bail, r.0[1] > bail]);
                let left = (steps - 1 - k) as usize;
                let kept = if left < KEEP {
                    let q = self.keep[left];
                    bits([r.0[0] <= q, r.0[1] <= q])
                } else {
                    0
                };
                let new = esc & !decided;
                if new != 0 {
                    for (lane, f) in found.iter_mut().enumerate() {
                        if new >> lane & 1 == 1 {
                            *f = (r.0[lane], dr.0[lane]);
                        }
                    }
                    out |= new;
                }
                decided |= esc | kept;
                if decided == 3 {
                    break;
                }
            }
        }
        std::array::from_fn(|lane| {
            if out >> lane & 1 == 1 {
                Orbit::Outside {
                    r: found[lane].0,
                    dr: found[lane].1,
                }
            } else {
                Orbit::Inside
            }
        })
    }

    /// `quaternion_orbit::<CUBE, false>` of two points, as inside-ness.
    #[inline(always)]
    fn inside2<const CUBE: bool>(&self, h: [Q; 2]) -> [bool; 2] {
        let steps = self.max_iteration.saturating_sub(1);
        let bail_sq = self.bail_sq;
        // Lane bits: `decided` once a lane's lone orbit would have returned, `out` where it
        // returned outside (an escape; the kept radius answers inside).
        let bits = |b: [bool; 2]| b[0] as u32 | (b[1] as u32) << 1;
        let mut out = bits([qnorm_sq(&h[0]) > bail_sq, qnorm_sq(&h[1]) > bail_sq]);
        let mut decided = out;
        if decided != 3 {
            let mut h: Q2 = std::array::from_fn(|i| V2([h[0][i], h[1][i]]));
            let c: Q2 = self.param.map(|x| V2([x, x]));
            for k in 0..steps {
                let h2 = qmul2(&h, &h);
                let f = if CUBE { qmul2(&h, &h2) } else { h2 };
                h = std::array::from_fn(|i| f[i] + c[i]);
                let s = qnorm_sq2(&h).0;
                let esc = bits([s[0] > bail_sq, s[1] > bail_sq]);
                let left = (steps - 1 - k) as usize;
                let kept = if left < KEEP {
                    let r = self.keep_sq[left];
                    bits([s[0] <= r, s[1] <= r])
                } else {
                    0
                };
                out |= esc & !decided;
                decided |= esc | kept;
                if decided == 3 {
                    break;
                }
            }
        }
        [out & 1 == 0, out & 2 == 0]
    }
}
