//! A z² + c fractal pattern asked at one point per camera ray, with the orbits of the points
//! the next rays are likely to ask stepped beside it.
//!
//! One orbit is a chain of dependent products and sums (~9 cycles a step), so a pattern of
//! 10,000 iterations waits on its own latency; vector lanes beside it cost nothing. Camera
//! rays along a row meet a flat pattern at points that step evenly (on
//! animations/fractalzoom 97 % of points are exactly the previous point plus the last step,
//! 90 % seven steps ahead), so the lanes follow the points p + d, p + 2d, … (d = p − the
//! previous point). Each lane's orbit is kept where it stood when the asked orbit ended,
//! finished or not, and the next call at that very point (bits compared) resumes it: every
//! orbit is the same arithmetic in the same order as `fractal2`, only spread over calls, so
//! every value is the same to the bit whatever was guessed.

use super::{exterior_value, orbit_value, Lanes};
use crate::scene::pattern::Fractal;
use std::cell::RefCell;

/// Lanes per run: the asked orbit and `L − 1` guesses (one 256-bit register each with AVX).
const L: usize = 4;

/// One orbit, as far as it has been stepped.
#[derive(Clone, Copy)]
struct Orbit {
    p: (f64, f64),
    z: (f64, f64),
    /// zr², zi² of `z` (the next step's products).
    sq: (f64, f64),
    min_abs2: f64,
    /// Steps done.
    k: u32,
    /// The pattern's value once the orbit has ended.
    value: Option<f64>,
}

impl Orbit {
    fn start(p: (f64, f64)) -> Orbit {
        let sq = (p.0 * p.0, p.1 * p.1);
        Orbit {
            p,
            z: p,
            sq,
            min_abs2: sq.0 + sq.1,
            k: 0,
            value: None,
        }
    }

    fn at(&self, p: (f64, f64)) -> bool {
        self.p.0.to_bits() == p.0.to_bits() && self.p.1.to_bits() == p.1.to_bits()
    }
}

/// What a thread keeps between calls: the fractal it was for, the last point asked and the
/// last run's orbits.
struct Ahead {
    key: [u64; 7],
    prev: Option<(f64, f64)>,
    /// The step to `prev` from the point asked before it.
    step: Option<(f64, f64)>,
    kept: [Option<Orbit>; L],
    /// Calls in a row whose point no earlier run had guessed.
    misses: u32,
}

thread_local! {
    static AHEAD: RefCell<Ahead> = const {
        RefCell::new(Ahead { key: [u64::MAX; 7], prev: None, step: None, kept: [None; L], misses: 0 })
    };
}

/// Everything of `f` its values depend on (floats by their bits).
fn key(f: &Fractal) -> [u64; 7] {
    let (jr, ji) = f
        .julia
        .map_or((u64::MAX, u64::MAX), |j| (j.0.to_bits(), j.1.to_bits()));
    [
        jr,
        ji,
        u64::from(f.julia.is_some()),
        u64::from(f.iterations) | u64::from(f.exponent) << 32,
        u64::from(f.magnet) | u64::from(f.interior.0) << 8 | u64::from(f.exterior.0) << 16,
        f.interior.1.to_bits(),
        f.exterior.1.to_bits(),
    ]
}

/// `fractal2::<MIN>(f, p)`, from or into the orbits kept by the calls before.
pub(in crate::render) fn fractal2_ahead<const MIN: bool>(f: &Fractal, p: (f64, f64)) -> f64 {
    AHEAD.with_borrow_mut(|a| a.value::<MIN>(f, p))
}

impl Ahead {
    fn value<const MIN: bool>(&mut self, f: &Fractal, p: (f64, f64)) -> f64 {
        let key = key(f);
        if self.key != key {
            self.key = key;
            self.prev = None;
            self.step = None;
            self.kept = [None; L];
        }
        let kept = |q: (f64, f64)| self.kept.iter().flatten().find(|o| o.at(q)).copied();
        let own = kept(p);
        let prev = self.prev.replace(p);
        let d = prev.map(|q| (p.0 - q.0, p.1 - q.1));
        let step = std::mem::replace(&mut self.step, d);
        if let Some(Orbit { value: Some(v), .. }) = own {
            self.misses = 0;
            return v;
        }
        // Where the guesses miss (curved surfaces: textures/patterns/mandel.pov hits none),
        // their bookkeeping costs ~4 % over the plain loop; guess once in 8 calls there.
        self.misses = if own.is_some() {
            0
        } else {
            self.misses.wrapping_add(1)
        };
        if self.misses > 8 && !self.misses.is_multiple_of(8) {
            return super::fractal2::<MIN>(f, p);
        }
        let mut lanes = [None; L];
        lanes[0] = Some(own.unwrap_or_else(|| Orbit::start(p)));
        if let Some(d) = d {
            let add = |a: (f64, f64), b: (f64, f64)| (a.0 + b.0, a.1 + b.1);
            let bits = |a: (f64, f64)| (a.0.to_bits(), a.1.to_bits());
            let guesses = match step {
                // Points rounded to a grid step by one of two amounts (the grid's spacing
                // does not divide the rays' spacing; on fractals3's rotated pattern the
                // last step repeats for 27 % of the points, one of the last two for 94 %).
                Some(e) if bits(e) != bits(d) => [add(p, d), add(p, e), add(add(p, d), e)],
                _ => [add(p, d), add(add(p, d), d), add(add(add(p, d), d), d)],
            };
            for (lane, q) in lanes[1..].iter_mut().zip(guesses) {
                *lane = Some(kept(q).unwrap_or_else(|| Orbit::start(q)));
            }
        }
        run::<MIN>(f, &mut lanes);
        self.kept = lanes;
        lanes[0].and_then(|o| o.value).unwrap_or(0.0)
    }
}

/// Steps the orbits of `lanes` until the first has ended.
fn run<const MIN: bool>(f: &Fractal, lanes: &mut [Option<Orbit>; L]) {
    #[cfg(target_arch = "x86_64")]
    if crate::math::has_avx() {
        // SAFETY: the CPU has AVX (checked just above).
        unsafe { run_avx::<MIN>(f, lanes) };
        return;
    }
    run_lanes::<MIN, false>(f, lanes)
}

/// `run_lanes` with AVX.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
unsafe fn run_avx<const MIN: bool>(f: &Fractal, lanes: &mut [Option<Orbit>; L]) {
    run_lanes::<MIN, true>(f, lanes)
}

/// The orbits' state between runs of steps, a lane per orbit.
pub(super) struct State {
    pub(super) zr: Lanes<L>,
    pub(super) zi: Lanes<L>,
    pub(super) rr: Lanes<L>,
    pub(super) ii: Lanes<L>,
    pub(super) min_abs2: Lanes<L>,
}

/// `fractal2`'s steps, a lane per orbit. Orbits start at different step counts, so the
/// steps go in segments no longer than any live orbit has left; an orbit that reaches
/// `iterations` at a segment's end takes its interior value there. Ended and empty lanes go
/// on stepping unread. `AVX`: step with `steps_avx` (the caller has checked the CPU).
#[inline(always)]
fn run_lanes<const MIN: bool, const AVX: bool>(f: &Fractal, lanes: &mut [Option<Orbit>; L]) {
    let n = f.iterations;
    let empty = Orbit {
        value: Some(0.0),
        ..Orbit::start((0.0, 0.0))
    };
    let o = lanes.map(|o| o.unwrap_or(empty));
    let c = o.map(|o| f.julia.unwrap_or(o.p));
    let (cr, ci) = (Lanes(c.map(|c| c.0)), Lanes(c.map(|c| c.1)));
    let mut s = State {
        zr: Lanes(o.map(|o| o.z.0)),
        zi: Lanes(o.map(|o| o.z.1)),
        rr: Lanes(o.map(|o| o.sq.0)),
        ii: Lanes(o.map(|o| o.sq.1)),
        min_abs2: Lanes(o.map(|o| o.min_abs2)),
    };
    let k0 = o.map(|o| o.k);
    let mut value = o.map(|o| o.value);
    let mut live = (0..L).fold(0u32, |m, l| m | u32::from(value[l].is_none()) << l);
    let mut done = 0;
    'run: while live & 1 != 0 {
        let mut left = (0..L)
            .filter(|&l| live >> l & 1 != 0)
            .map(|l| n - k0[l] - done)
            .min()
            .unwrap_or(0);
        while left > 0 {
            let (m, new, a2) = if AVX {
                #[cfg(target_arch = "x86_64")]
                // SAFETY: AVX is only asked for where the CPU has it (`run`).
                unsafe {
                    steps_avx::<MIN>(&mut s, (cr, ci), live, left)
                }
                #[cfg(not(target_arch = "x86_64"))]
                unreachable!()
            } else {
                steps::<MIN>(&mut s, (cr, ci), live, left)
            };
            done += m;
            left -= m;
            if new != 0 {
                for l in (0..L).filter(|&l| new >> l & 1 != 0) {
                    let (zr, zi) = (s.zr.0[l], s.zi.0[l]);
                    let v = exterior_value(f, k0[l] + done - 1, zr, zi, a2.0[l], s.min_abs2.0[l]);
                    value[l] = Some(v);
                }
                live &= !new;
                if MIN {
                    s.min_abs2 = s.min_abs2.zip(a2, f64::min);
                }
                if live & 1 == 0 {
                    break 'run;
                }
            }
        }
        let (t, factor) = f.interior;
        for l in 0..L {
            if live >> l & 1 != 0 && k0[l] + done == n {
                value[l] = Some(orbit_value(t, s.zr.0[l], s.zi.0[l], s.min_abs2.0[l]) * factor);
                live &= !(1 << l);
            }
        }
    }
    for (l, lane) in lanes.iter_mut().enumerate() {
        if let Some(orbit) = lane {
            orbit.value = value[l];
            orbit.z = (s.zr.0[l], s.zi.0[l]);
            orbit.sq = (s.rr.0[l], s.ii.0[l]);
            orbit.min_abs2 = s.min_abs2.0[l];
            orbit.k = k0[l] + done;
        }
    }
}

/// Up to `max` steps of the orbits in `s`, stopping after the first step at which a `live`
/// lane leaves the radius-2 disc: the steps taken, the lanes that left (0 if none did) and
/// that step's |z|² (whose smallest-|z|² update is the caller's, after reading the leaving
/// lanes' values).
#[inline(always)]
fn steps<const MIN: bool>(
    s: &mut State,
    (cr, ci): (Lanes<L>, Lanes<L>),
    live: u32,
    max: u32,
) -> (u32, u32, Lanes<L>) {
    for j in 0..max {
        let ri = s.zr * s.zi;
        s.zr = (s.rr - s.ii) + cr;
        s.zi = (ri + ri) + ci;
        s.rr = s.zr * s.zr;
        s.ii = s.zi * s.zi;
        let a2 = s.rr + s.ii;
        let new = a2.mask(|x| x > 4.0) & live;
        if new != 0 {
            return (j + 1, new, a2);
        }
        if MIN {
            s.min_abs2 = s.min_abs2.zip(a2, f64::min);
        }
    }
    (max, 0, Lanes([0.0; L]))
}

/// `steps` with AVX intrinsics: the compiler, left to itself, split the lanes into
/// 128-bit halves with shuffles on the orbit's chain (1.9x slower than one scalar orbit on
/// textures/patterns/fractals3). The same IEEE operations lane by lane (nothing fused);
/// the smallest |z|² as `f64::min` takes it (the other operand where one is NaN).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
#[inline]
pub(super) unsafe fn steps_avx<const MIN: bool>(
    s: &mut State,
    (cr, ci): (Lanes<L>, Lanes<L>),
    live: u32,
    max: u32,
) -> (u32, u32, Lanes<L>) {
    use std::arch::x86_64::*;
    let ld = |a: &Lanes<L>| _mm256_loadu_pd(a.0.as_ptr());
    let (cr, ci) = (ld(&cr), ld(&ci));
    let (mut zr, mut zi, mut rr, mut ii) = (ld(&s.zr), ld(&s.zi), ld(&s.rr), ld(&s.ii));
    let mut min_abs2 = ld(&s.min_abs2);
    let four = _mm256_set1_pd(4.0);
    let mut out = (max, 0, _mm256_setzero_pd());
    for j in 0..max {
        let ri = _mm256_mul_pd(zr, zi);
        zr = _mm256_add_pd(_mm256_sub_pd(rr, ii), cr);
        zi = _mm256_add_pd(_mm256_add_pd(ri, ri), ci);
        rr = _mm256_mul_pd(zr, zr);
        ii = _mm256_mul_pd(zi, zi);
        let a2 = _mm256_add_pd(rr, ii);
        let new = _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_GT_OQ>(a2, four)) as u32 & live;
        if new != 0 {
            out = (j + 1, new, a2);
            break;
        }
        if MIN {
            let less = _mm256_min_pd(a2, min_abs2);
            let nan = _mm256_cmp_pd::<_CMP_UNORD_Q>(min_abs2, min_abs2);
            min_abs2 = _mm256_blendv_pd(less, a2, nan);
        }
    }
    let st = |a: &mut Lanes<L>, v: __m256d| _mm256_storeu_pd(a.0.as_mut_ptr(), v);
    st(&mut s.zr, zr);
    st(&mut s.zi, zi);
    st(&mut s.rr, rr);
    st(&mut s.ii, ii);
    st(&mut s.min_abs2, min_abs2);
    let mut a2 = Lanes([0.0; L]);
    st(&mut a2, out.2);
    (out.0, out.1, a2)
}

#[cfg(test)]
mod tests {
    use super::super::fractal2;
    use super::*;

    /// Every value asked through the kept orbits is `fractal2`'s to the bit: rows of evenly
    /// stepped points (guessed), points off the guesses, repeats, points asked again after
    /// others, fractals switched between calls, orbits inside the set and leaving it.
    #[test]
    fn ahead_is_the_plain_loop() {
        let fractals: Vec<Fractal> = [
            (None, 300, (0, 1.0), (1, 1.0)),
            (None, 300, (1, 200.0), (5, 1.0)),
            (Some((-0.75, 0.11)), 120, (6, 2.0), (6, 0.3)),
            (Some((0.3, 0.44)), 0, (1, 1.0), (1, 1.0)),
            (None, 50, (2, 1.0), (8, 3.0)),
        ]
        .into_iter()
        .map(|(julia, iterations, interior, exterior)| Fractal {
            julia,
            iterations,
            exponent: 2,
            magnet: 0,
            interior,
            exterior,
        })
        .collect();
        let mut asked = Vec::new();
        for i in 0..fractals.len() {
            for row in 0..12 {
                let y = -0.05 + 0.0173 * row as f64;
                let mut px = -0.78;
                for x in 0..90 {
                    // Stepped by adding, as camera rays' points often are.
                    px += 0.00071;
                    let mut p = (px, y);
                    if x % 17 == 5 {
                        // Off the guesses.
                        p.1 += 1e-9;
                    }
                    asked.push((i, p));
                    if x % 23 == 7 {
                        asked.push((i, p));
                    }
                    if x % 29 == 3 {
                        asked.push((i, (p.0 - 0.00142, y)));
                    }
                }
                // Another fractal's point between rows.
                asked.push(((i + 1) % fractals.len(), (0.1, 0.2)));
            }
        }
        let mut hits = 0;
        for (i, p) in asked {
            let f = &fractals[i];
            let (want, got) = if f.interior.0 == 1 {
                (fractal2::<true>(f, p), fractal2_ahead::<true>(f, p))
            } else {
                (fractal2::<false>(f, p), fractal2_ahead::<false>(f, p))
            };
            assert_eq!(want.to_bits(), got.to_bits(), "{p:?} {i}");
            hits += AHEAD.with_borrow(|a| u32::from(a.misses == 0));
        }
        assert!(hits > 1000, "{hits} points found kept");
    }

    /// The portable steps (CPUs without AVX) resume orbits as the AVX ones do: each orbit
    /// run to its end, a lane at a time, beside orbits kept from the runs before.
    #[test]
    fn portable_steps_are_the_plain_loop() {
        for interior in [(0, 1.0), (1, 200.0)] {
            let f = Fractal {
                julia: None,
                iterations: 400,
                exponent: 2,
                magnet: 0,
                interior,
                exterior: (1, 1.0),
            };
            let ps: Vec<(f64, f64)> = (0..60).map(|x| (-0.76 + 0.0005 * x as f64, 0.09)).collect();
            let mut kept: [Option<Orbit>; L] = [None; L];
            for (i, &p) in ps.iter().enumerate() {
                let mut lanes = [None; L];
                for (l, lane) in lanes.iter_mut().enumerate() {
                    let q = *ps.get(i + l).unwrap_or(&p);
                    let old = kept.iter().flatten().find(|o| o.at(q)).copied();
                    *lane = Some(old.unwrap_or_else(|| Orbit::start(q)));
                }
                if interior.0 == 1 {
                    run_lanes::<true, false>(&f, &mut lanes);
                } else {
                    run_lanes::<false, false>(&f, &mut lanes);
                }
                kept = lanes;
                let got = lanes[0].unwrap().value.unwrap();
                let want = if interior.0 == 1 {
                    fractal2::<true>(&f, p)
                } else {
                    fractal2::<false>(&f, p)
                };
                assert_eq!(got.to_bits(), want.to_bits(), "{p:?}");
            }
        }
    }
}
