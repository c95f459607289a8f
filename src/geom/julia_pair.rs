//! Quaternion orbits side by side, for the julia bisection (four midpoints at a time) and
//! march (a sample and the one after a least step).
//!
//! A quaternion orbit is one dependent chain (each iterate waits for the last), so a lone
//! orbit leaves most of the floating-point units idle. Here `N` orbits run in lanes, each lane
//! doing exactly the operations of `Julia::quaternion_orbit` in the same order (the same
//! products and sums, no fused multiply-add, no reassociation), so each lane's answer is the
//! lone orbit's to the bit. The lanes run in lockstep until all have decided; a lane that has
//! decided goes on iterating unread (an escaped one may overflow, harmlessly). Where the CPU
//! has AVX, quaternion orbits of up to four lanes, and four hypercomplex sqr or cube ones, go
//! to `julia_avx.rs` instead (the same operations, one 256-bit register per component); the
//! code here serves the rest.

#[cfg(target_arch = "x86_64")]
use super::avx;
use super::{qnorm, qnorm_sq, Julia, JuliaFn, Orbit, KEEP, Q};
use crate::math::{has_avx, DVec3};

/// One number per lane; the element-wise operations vectorise to SSE2.
#[derive(Clone, Copy)]
struct V<const N: usize>([f64; N]);

impl<const N: usize> V<N> {
    #[inline(always)]
    fn sqrt(self) -> Self {
        V(self.0.map(f64::sqrt))
    }

    #[inline(always)]
    fn splat(x: f64) -> Self {
        V([x; N])
    }
}

impl<const N: usize> std::ops::Add for V<N> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        V(std::array::from_fn(|i| self.0[i] + o.0[i]))
    }
}

impl<const N: usize> std::ops::Sub for V<N> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        V(std::array::from_fn(|i| self.0[i] - o.0[i]))
    }
}

impl<const N: usize> std::ops::Mul for V<N> {
    type Output = Self;
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        V(std::array::from_fn(|i| self.0[i] * o.0[i]))
    }
}

/// A quaternion per lane.
type QN<const N: usize> = [V<N>; 4];

/// `qmul` lane by lane, with its association.
#[inline(always)]
fn qmul_n<const N: usize>(p: &QN<N>, q: &QN<N>) -> QN<N> {
    [
        p[0] * q[0] - p[1] * q[1] - p[2] * q[2] - p[3] * q[3],
        p[0] * q[1] + p[1] * q[0] + p[2] * q[3] - p[3] * q[2],
        p[0] * q[2] - p[1] * q[3] + p[2] * q[0] + p[3] * q[1],
        p[0] * q[3] + p[1] * q[2] - p[2] * q[1] + p[3] * q[0],
    ]
}

/// `qnorm_sq` lane by lane.
#[inline(always)]
fn qnorm_sq_n<const N: usize>(h: &QN<N>) -> V<N> {
    h[0] * h[0] + h[1] * h[1] + h[2] * h[2] + h[3] * h[3]
}

/// Lane bits of a lane-wise test.
#[inline(always)]
fn bits<const N: usize>(b: [bool; N]) -> u32 {
    b.iter()
        .enumerate()
        .fold(0, |m, (i, &x)| m | (x as u32) << i)
}

/// The first `N` lanes of an AVX orbit function's answer (escape bits, `r`, `dr`).
#[inline(always)]
fn lane_orbits<const N: usize>(out: u32, r: [f64; 4], dr: [f64; 4]) -> [Orbit; N] {
    std::array::from_fn(|i| {
        if out >> i & 1 == 1 {
            Orbit::Outside { r: r[i], dr: dr[i] }
        } else {
            Orbit::Inside
        }
    })
}

impl Julia {
    /// `p.map(|p| self.is_in(p))`, the orbits run side by side where they are quaternion
    /// ones.
    pub(super) fn is_in_n<const N: usize>(&self, p: [DVec3; N]) -> [bool; N] {
        #[cfg(target_arch = "x86_64")]
        if N == 4 && self.algebra == super::Algebra::Quaternion && has_avx() {
            let h: [Q; 4] = std::array::from_fn(|i| self.lift(p[i]).0);
            // SAFETY: the CPU has AVX (checked just above).
            let (ins, _) = unsafe {
                if self.func == JuliaFn::Cube {
                    avx::inside4::<true>(self, h)
                } else {
                    avx::inside4::<false>(self, h)
                }
            };
            return std::array::from_fn(|i| ins[i]);
        }
        #[cfg(target_arch = "x86_64")]
        if N == 4 && self.squares() && has_avx() {
            let h: [Q; 4] = std::array::from_fn(|i| self.lift(p[i]).0);
            // SAFETY: the CPU has AVX (checked just above).
            let ins = unsafe { avx::hyper_inside4(self, h) };
            return std::array::from_fn(|i| ins[i]);
        }
        match self.algebra {
            super::Algebra::Quaternion if self.func == JuliaFn::Cube => {
                self.inside_n::<N, true>(p.map(|p| self.lift(p).0))
            }
            super::Algebra::Quaternion => self.inside_n::<N, false>(p.map(|p| self.lift(p).0)),
            super::Algebra::Hypercomplex => p.map(|p| self.is_in(p)),
        }
    }

    /// `is_in_n` of four points, and per point where its orbit decided against the bailout
    /// (`avx::inside4`: NaN where not known), for the bisection's choice of midpoints.
    #[inline]
    pub(super) fn is_in4(&self, p: [DVec3; 4]) -> ([bool; 4], [f64; 4]) {
        #[cfg(target_arch = "x86_64")]
        if self.algebra == super::Algebra::Quaternion && has_avx() {
            let h: [Q; 4] = std::array::from_fn(|i| self.lift(p[i]).0);
            // SAFETY: the CPU has AVX (checked just above).
            return unsafe {
                if self.func == JuliaFn::Cube {
                    avx::inside4::<true>(self, h)
                } else {
                    avx::inside4::<false>(self, h)
                }
            };
        }
        (self.is_in_n(p), [f64::NAN; 4])
    }

    /// `p.map(|p| self.orbit(p))`, the orbits run side by side where they are quaternion
    /// ones.
    pub(super) fn orbit_n<const N: usize>(&self, p: [DVec3; N]) -> [Orbit; N] {
        #[cfg(target_arch = "x86_64")]
        if (1..=4).contains(&N) && self.algebra == super::Algebra::Quaternion && has_avx() {
            // Unused lanes repeat the last point: they decide with it and add no iteration.
            let h: [Q; 4] = std::array::from_fn(|i| self.lift(p[i.min(N - 1)]).0);
            // SAFETY: the CPU has AVX (checked just above).
            let (out, r, dr) = unsafe {
                if self.func == JuliaFn::Cube {
                    avx::orbits4::<true>(self, h)
                } else {
                    avx::orbits4::<false>(self, h)
                }
            };
            return lane_orbits(out, r, dr);
        }
        #[cfg(target_arch = "x86_64")]
        if (1..=4).contains(&N) && self.squares() && has_avx() {
            let h: [Q; 4] = std::array::from_fn(|i| self.lift(p[i.min(N - 1)]).0);
            // SAFETY: the CPU has AVX (checked just above).
            let (out, r, dr) = unsafe { avx::hyper_orbits4(self, h) };
            return lane_orbits(out, r, dr);
        }
        match self.algebra {
            super::Algebra::Quaternion if self.func == JuliaFn::Cube => {
                self.orbits_n::<N, true>(p.map(|p| self.lift(p).0))
            }
            super::Algebra::Quaternion => self.orbits_n::<N, false>(p.map(|p| self.lift(p).0)),
            super::Algebra::Hypercomplex => p.map(|p| self.orbit(p)),
        }
    }

    /// `quaternion_orbit::<CUBE, true>` of `N` points.
    #[inline(always)]
    fn orbits_n<const N: usize, const CUBE: bool>(&self, h: [Q; N]) -> [Orbit; N] {
        let steps = self.max_iteration.saturating_sub(1);
        let bail = self.bailout;
        let all = (1u32 << N) - 1;
        let mut r = V(h.map(|h| qnorm(&h)));
        let mut dr = V::<N>::splat(1.0);
        // Per lane, the `r` and `dr` of its escape (`out`'s bits) once `decided`.
        let mut found = r.0.map(|r| (r, 1.0));
        let mut out = bits(r.0.map(|r| r > bail));
        let mut decided = out;
        if decided != all {
            let mut h: QN<N> = std::array::from_fn(|i| V(h.map(|h| h[i])));
            let c: QN<N> = self.param.map(V::splat);
            let (two, three) = (V::splat(2.0), V::splat(3.0));
            for k in 0..steps {
                let h2 = qmul_n(&h, &h);
                let f = if CUBE { qmul_n(&h, &h2) } else { h2 };
                h = std::array::from_fn(|i| f[i] + c[i]);
                dr = dr * if CUBE { three * r * r } else { two * r };
                r = qnorm_sq_n(&h).sqrt();
                let esc = bits(r.0.map(|r| r > bail));
                let left = (steps - 1 - k) as usize;
                let kept = if left < KEEP {
                    let q = self.keep[left];
                    bits(r.0.map(|r| r <= q))
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
                if decided == all {
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

    /// `quaternion_orbit::<CUBE, false>` of `N` points, as inside-ness.
    #[inline(always)]
    fn inside_n<const N: usize, const CUBE: bool>(&self, h: [Q; N]) -> [bool; N] {
        let steps = self.max_iteration.saturating_sub(1);
        let bail_sq = self.bail_sq;
        let all = (1u32 << N) - 1;
        // Lane bits: `decided` once a lane's lone orbit would have returned, `out` where it
        // returned outside (an escape; the kept radius answers inside).
        let mut out = bits(h.map(|h| qnorm_sq(&h) > bail_sq));
        let mut decided = out;
        if decided != all {
            let mut h: QN<N> = std::array::from_fn(|i| V(h.map(|h| h[i])));
            let c: QN<N> = self.param.map(V::splat);
            for k in 0..steps {
                let h2 = qmul_n(&h, &h);
                let f = if CUBE { qmul_n(&h, &h2) } else { h2 };
                h = std::array::from_fn(|i| f[i] + c[i]);
                let s = qnorm_sq_n(&h).0;
                let esc = bits(s.map(|s| s > bail_sq));
                let left = (steps - 1 - k) as usize;
                let kept = if left < KEEP {
                    let r = self.keep_sq[left];
                    bits(s.map(|s| s <= r))
                } else {
                    0
                };
                out |= esc & !decided;
                decided |= esc | kept;
                if decided == all {
                    break;
                }
            }
        }
        std::array::from_fn(|i| out >> i & 1 == 0)
    }
}
