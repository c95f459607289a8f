//! POV-Ray `julia_fractal`: the 3-D slice of a 4-D Julia set in quaternion or hypercomplex
//! algebra, with the inside test, ray march and normals POV-Ray 3.7 computes (measured with
//! `inside()` and `trace()` on the povray binary: tests/data/julia/, docs/implicit-objects.md).
//!
//! * Lift: a 3-D point (x, y, z) becomes h = (x, y, z, w) with w solving `n·h = d` for the
//!   normalised slice. Hypercomplex functions other than sqr, cube and reciprocal read the
//!   point as (x, y, y) first: their shapes do not depend on z (measured, exactly).
//! * Inside: |h| stays at or below the bailout for h0 and the next `max_iteration − 1`
//!   iterates of h ← f(h) + c. The bailout is min(2, 1 + |c|) for quaternions, 4 for
//!   hypercomplex numbers. Hypercomplex `cube` iterates the square.
//! * Hypercomplex numbers split as h = e1 z1 + e2 z2 (z1 = (a − d) + (b + c)i,
//!   z2 = (a + d) + (b − c)i), every function the principal complex one on both halves except
//!   acos = −i ln(z + sqrt(z² − 1)) and acosh = i acos.
//! * March (quaternion, exact): from where the ray enters the sphere of the bailout radius
//!   (or from its origin inside it), samples advance by max(ln|h_n| / |h_n'|, 1/precision)
//!   while outside (n the escape step, |h_n'| the product of 2|h_k|, or 3|h_k|² for cube)
//!   and by 1/precision inside; a change of inside-ness is bisected. The entry point itself
//!   counts as outside (the c = 0 unit ball is found one step in, missed by chords shorter
//!   than a step). A chord shorter than a
//!   step can be missed, as in POV-Ray.
//! * Normal: the gradient of |h|² after `max_iteration` iterations, w held fixed (exact for
//!   quaternions and hypercomplex sqr).
//!
//! Not matched: the distance estimate of quaternion `cube` (3|h|² per step is the closest
//! simple rule found; 9 of 247 measured rays land elsewhere), the hypercomplex march (POV-Ray's steps there are neither 1/precision nor
//! the quaternion estimate; lancer uses the quaternion rule with the bailout 4) and the
//! normals of the transcendental hypercomplex functions.

use num_complex::Complex64 as C;

use crate::geom::{Hit, Shape};
use crate::math::{Aabb, DVec3, Ray, EPSILON};

/// The bisection stops below this interval: POV-Ray's hits lie within ~1e-7 of the exact
/// crossing (measured), far below a pixel.
const BISECT_TOL: f64 = 1e-8;
/// The march starts this far inside the entry sphere: POV-Ray's first sample there always
/// passes the |h0| test (measured on 8000 rays; exactly on the sphere rounding would decide).
const ENTRY_EPS: f64 = 1e-9;

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Algebra {
    Quaternion,
    Hypercomplex,
}

type Q = [f64; 4];

#[inline(always)]
fn qmul(p: &Q, q: &Q) -> Q {
    [
        p[0] * q[0] - p[1] * q[1] - p[2] * q[2] - p[3] * q[3],
        p[0] * q[1] + p[1] * q[0] + p[2] * q[3] - p[3] * q[2],
        p[0] * q[2] - p[1] * q[3] + p[2] * q[0] + p[3] * q[1],
        p[0] * q[3] + p[1] * q[2] - p[2] * q[1] + p[3] * q[0],
    ]
}

/// `qmul(h, h)` with its association and the same bits (`h_i·h_j` and `h_j·h_i` are one
/// rounded product), in scalar registers: LLVM's SLP vectoriser otherwise packs the orbit's
/// quaternion in two SSE pairs and spends shuffles between the halves on the loop's chain.
#[inline(always)]
fn qsquare(h: &Q) -> Q {
    let [a, b, c, d] = h.map(crate::math::opaque);
    let (aa, bb, cc, dd) = (a * a, b * b, c * c, d * d);
    let (ab, ac, ad) = (a * b, a * c, a * d);
    let (bc, bd, cd) = (b * c, b * d, c * d);
    [
        aa - bb - cc - dd,
        ab + ab + cd - cd,
        ac - bd + ac + bd,
        ad + bc - bc + ad,
    ]
}

#[inline(always)]
fn qadd(p: &Q, q: &Q) -> Q {
    std::array::from_fn(|i| p[i] + q[i])
}

#[inline(always)]
fn qnorm(h: &Q) -> f64 {
    qnorm_sq(h).sqrt()
}

#[inline(always)]
fn qnorm_sq(h: &Q) -> f64 {
    h[0] * h[0] + h[1] * h[1] + h[2] * h[2] + h[3] * h[3]
}

/// The two complex halves of a hypercomplex number.
fn split(h: &Q) -> (C, C) {
    (
        C::new(h[0] - h[3], h[1] + h[2]),
        C::new(h[0] + h[3], h[1] - h[2]),
    )
}

/// Where `intersect_first` and `any_hit` may end a march early: the ray direction's length
/// (distances along the unit direction over it are the ray's `t`), the `tmax` asked for, and
/// whether only the existence of a crossing before it matters.
#[derive(Clone, Copy)]
struct Stop {
    len: f64,
    tmax: f64,
    any: bool,
}

/// What the iteration says about a point.
#[derive(Clone, Copy)]
enum Orbit {
    Inside,
    /// Outside, with |h_n| and |h_n'|: the distance estimate is ln|h_n| / |h_n'| (`ln r / 1`
    /// is `ln r` to the bit, so an escape before any iteration has `dr` 1).
    Outside {
        r: f64,
        dr: f64,
    },
}

/// The bisection's next four midpoints of [a, c] where the ends' orbits decided `ga` and `gc`
/// off the bailout (`Julia::is_in4`, opposite signs across the crossing): the halvings toward
/// the zero of the line through them. Near the surface that number is smooth along the ray
/// (the last iterate's squared norm), so the zero is close to the crossing and a round takes
/// up to four halvings where the fixed plan takes two or three. Only which midpoints are asked
/// changes: each halving still takes its own midpoint's answer.
fn chain_plan(a: f64, c: f64, ga: f64, gc: f64) -> Option<[f64; 4]> {
    if (ga > 0.0) == (gc > 0.0) || !(ga.is_finite() && gc.is_finite()) {
        return None;
    }
    let x = a + (c - a) * (ga / (ga - gc));
    let (mut lo, mut hi) = (a, c);
    Some(std::array::from_fn(|_| {
        let m = 0.5 * (lo + hi);
        if m < x {
            lo = m;
        } else {
            hi = m;
        }
        m
    }))
}

/// How far the march advances after a sample: the distance estimate, at least `min_step`.
fn march_step(orbit: &Orbit, min_step: f64) -> f64 {
    match *orbit {
        // ln r <= r - 1, with a margin far above the logarithm's rounding once r is a little
        // above 1 (then (r - 1)² / 2 > 1e-13 r), and rounded division is monotone: when
        // (r - 1) / dr is below the least step, so is the estimate, and the step is the least
        // one, found without the logarithm.
        //
        // The division's latency is on the march's chain (each sample waits for its step):
        // `r - 1 < min_step·dr·(1 − 1e-12)` puts the exact quotient that far below `min_step`
        // (two roundings move it by ~2e-16), so the rounded one is below it too. Where the
        // product test fails (or is NaN), the quotient decides as before.
        Orbit::Outside { r, dr }
            if r >= 1.0 + 1e-6
                && ((r - 1.0) < min_step * dr * (1.0 - 1e-12) || (r - 1.0) / dr < min_step) =>
        {
            min_step
        }
        // `de.max(min_step)` for a finite `de`, else `min_step`, as a branch: `maxsd` and the
        // NaN blend of `f64::max` (or a compare and blend) sat on the march's chain (each
        // sample waits for its step), where a predicted branch adds no latency. `opaque`
        // keeps LLVM from turning the branch back into a select.
        Orbit::Outside { r, dr } => {
            let de = r.ln() / dr;
            if de > min_step && de < f64::INFINITY {
                crate::math::opaque(de)
            } else {
                min_step
            }
        }
        Orbit::Inside => min_step,
    }
}

#[derive(Clone, Debug)]
pub struct Julia {
    pub param: [f64; 4],
    pub algebra: Algebra,
    pub func: JuliaFn,
    pub max_iteration: u32,
    pub precision: f64,
    /// Unit slice normal and distance.
    pub slice: ([f64; 4], f64),
    /// Escape radius of the orbit and radius of the sphere the march runs in.
    bailout: f64,
    /// The largest squared norm whose square root is at most the bailout: `sqrt(s) > bailout`
    /// exactly when `s > bail_sq` (the rounded square root is monotone), so the inside test
    /// needs no square root.
    bail_sq: f64,
    /// `keep[j]`: a quaternion iterate of norm at most this stays inside the bailout for the
    /// next `j` iterations (−1 where no radius is sure to); `keep_sq` the same for squared
    /// norms. See `keep_radii`.
    keep: [f64; KEEP],
    keep_sq: [f64; KEEP],
    /// `keep_thr[j]`: the largest squared norm whose square root is at most `keep[j]`.
    keep_thr: [f64; KEEP],
    /// The slice is w = 0: n = (0, 0, 0, 1) (zeros of either sign) and d = +0 (see `lift`).
    flat_slice: bool,
    /// Every point the orbit calls inside lies within this radius (`inner_radius`; at most
    /// the bailout, then up to the norm's rounding): the march leaves out rays and stretches
    /// of rays outside it, with margins far above that rounding.
    inner: f64,
}

/// Samples the march takes ahead after a least step with four lanes (`Julia::crossings`).
const AHEAD: usize = 3;

/// How many of the last iterations an orbit may leave out (`Julia::keep`).
const KEEP: usize = 4;

impl Julia {
    /// `slice` is normalised here; a zero 4th component is replaced by POV-Ray's default
    /// (the parser warns).
    pub fn new(
        param: [f64; 4],
        algebra: Algebra,
        func: JuliaFn,
        max_iteration: u32,
        precision: f64,
        slice: ([f64; 4], f64),
    ) -> Julia {
        let (n, d) = slice;
        let len = n.iter().map(|x| x * x).sum::<f64>().sqrt();
        let slice = if len > 0.0 && n[3] != 0.0 && len.is_finite() {
            (n.map(|x| x / len), d / len)
        } else {
            ([0.0, 0.0, 0.0, 1.0], 0.0)
        };
        let bailout = match algebra {
            Algebra::Quaternion => (1.0 + qnorm(&param)).min(2.0),
            Algebra::Hypercomplex => 4.0,
        };
        let (keep, keep_sq) = match algebra {
            Algebra::Quaternion => keep_radii(bailout, qnorm(&param), func == JuliaFn::Cube),
            Algebra::Hypercomplex => ([-1.0; KEEP], [-1.0; KEEP]),
        };
        let inner = match algebra {
            Algebra::Quaternion => {
                inner_radius(bailout, qnorm(&param), func == JuliaFn::Cube, max_iteration)
            }
            Algebra::Hypercomplex if matches!(func, JuliaFn::Sqr | JuliaFn::Cube) => {
                let (c1, c2) = split(&param);
                hyper_inner_radius(bailout, c1.norm(), c2.norm(), max_iteration)
            }
            Algebra::Hypercomplex => bailout,
        };
        Julia {
            param,
            algebra,
            func,
            max_iteration,
            precision: precision.max(1.0),
            slice,
            bailout,
            bail_sq: sqrt_threshold(bailout),
            keep,
            keep_sq,
            keep_thr: keep.map(sqrt_threshold),
            flat_slice: slice.0[..3].iter().all(|&x| x == 0.0)
                && slice.0[3] == 1.0
                && slice.1.to_bits() == 0,
            inner,
        }
    }

    /// A hypercomplex set whose orbit iterates the square (sqr, and cube: module doc).
    fn squares(&self) -> bool {
        self.algebra == Algebra::Hypercomplex && matches!(self.func, JuliaFn::Sqr | JuliaFn::Cube)
    }

    fn mangled(&self) -> bool {
        self.algebra == Algebra::Hypercomplex && self.func.transcendental()
    }

    /// The 4-D point of a 3-D one, and the 4-D tangents of the 3-D axes that POV-Ray's
    /// normals follow: they leave out the slice's w (measured: with a slice the shading
    /// matches only without it).
    fn lift(&self, p: DVec3) -> (Q, [Q; 3]) {
        let (n, d) = self.slice;
        let z = if self.mangled() { p.y } else { p.z };
        // w's subtractions and division start every orbit's dependent chain; they are left
        // out where they cannot change a bit. With the slice's n = (0, 0, 0, 1) and d = +0,
        // each product is a zero and +0 − (±0) is +0 in every step for finite x, y and z; and
        // with n[3] = 1, x / 1 is x.
        let w = if self.flat_slice && p.x.is_finite() && p.y.is_finite() && z.is_finite() {
            0.0
        } else {
            let num = d - n[0] * p.x - n[1] * p.y - n[2] * z;
            if n[3] == 1.0 {
                num
            } else {
                num / n[3]
            }
        };
        let mut axes = [
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
        ];
        if self.mangled() {
            axes[1] = [0.0, 1.0, 1.0, 0.0];
            axes[2] = [0.0; 4];
        }
        ([p.x, p.y, z, w], axes)
    }

    #[inline(always)]
    fn quaternion_step(&self, h: &Q) -> Q {
        let h2 = qmul(h, h);
        let f = if self.func == JuliaFn::Cube {
            qmul(h, &h2)
        } else {
            h2
        };
        qadd(&f, &self.param)
    }

    /// `orbit_with::<true>`, out of line: its point and answer pass in registers
    /// (`orbit_regs`), not through memory as a `DVec3` and an `Orbit` would, whose store and
    /// reload sat on the march's chain.
    #[inline(always)]
    fn orbit(&self, p: DVec3) -> Orbit {
        let (r, dr) = self.orbit_regs(p.x, p.y, p.z);
        // An escape's `r` is a square root above the bailout's, so positive.
        if r < 0.0 {
            Orbit::Inside
        } else {
            Orbit::Outside { r, dr }
        }
    }

    /// `orbit_with::<true>` of (x, y, z), `Inside` as r = −1.
    #[inline(never)]
    fn orbit_regs(&self, x: f64, y: f64, z: f64) -> (f64, f64) {
        match self.orbit_with::<true>(DVec3::new(x, y, z)) {
            Orbit::Inside => (-1.0, 0.0),
            Orbit::Outside { r, dr } => (r, dr),
        }
    }

    /// The orbit of `p`; with `DE` false the distance estimate is left out (0), which saves
    /// its logarithm and products where only inside-ness is asked (the bisection): the
    /// iterates, and so the answer, are the same.
    #[inline(always)]
    fn orbit_with<const DE: bool>(&self, p: DVec3) -> Orbit {
        let (h, _) = self.lift(p);
        match self.algebra {
            Algebra::Quaternion if self.func == JuliaFn::Cube => {
                self.quaternion_orbit::<true, DE>(h)
            }
            Algebra::Quaternion => self.quaternion_orbit::<false, DE>(h),
            Algebra::Hypercomplex if self.squares() => self.hypercomplex_orbit::<true, DE>(h),
            Algebra::Hypercomplex => self.hypercomplex_orbit::<false, DE>(h),
        }
    }

    #[inline(always)]
    fn quaternion_orbit<const CUBE: bool, const DE: bool>(&self, mut h: Q) -> Orbit {
        let steps = self.max_iteration.saturating_sub(1);
        if !DE {
            let bail_sq = self.bail_sq;
            if qnorm_sq(&h) > bail_sq {
                return Orbit::Outside { r: 0.0, dr: 0.0 };
            }
            for k in 0..steps {
                let h2 = qmul(&h, &h);
                let f = if CUBE { qmul(&h, &h2) } else { h2 };
                h = qadd(&f, &self.param);
                let s = qnorm_sq(&h);
                if s > bail_sq {
                    return Orbit::Outside { r: 0.0, dr: 0.0 };
                }
                let left = (steps - 1 - k) as usize;
                if left < KEEP && s <= self.keep_sq[left] {
                    return Orbit::Inside;
                }
            }
            return Orbit::Inside;
        }
        // The branches compare the squared norm `s` with the thresholds of the radii
        // (`sqrt(s) > bailout` exactly when `s > bail_sq`, and `sqrt(s) <= keep[j]` exactly
        // when `s <= keep_thr[j]`): the escape is then known before the square root, whose
        // latency no longer delays the exit branch (mispredicted once an orbit) while `r`,
        // which the estimate needs, is computed beside it.
        let bail_sq = self.bail_sq;
        let mut s = qnorm_sq(&h);
        let mut r = s.sqrt();
        let mut dr = 1.0;
        if s > bail_sq {
            return Orbit::Outside { r, dr: 1.0 };
        }
        for k in 0..steps {
            let h2 = if CUBE { qmul(&h, &h) } else { qsquare(&h) };
            let f = if CUBE { qmul(&h, &h2) } else { h2 };
            h = qadd(&f, &self.param);
            dr *= if CUBE { 3.0 * r * r } else { 2.0 * r };
            s = qnorm_sq(&h);
            r = s.sqrt();
            if s > bail_sq {
                return Orbit::Outside { r, dr };
            }
            let left = (steps - 1 - k) as usize;
            if left < KEEP && s <= self.keep_thr[left] {
                return Orbit::Inside;
            }
        }
        Orbit::Inside
    }

    /// With `SQR` (sqr and cube, which iterates the square) each half's step is `z * z`,
    /// `JuliaFn::apply`'s own expression, in the loop: the call, its dispatch and the halves'
    /// trips through memory around it sat on the orbit's chain.
    #[inline(always)]
    fn hypercomplex_orbit<const SQR: bool, const DE: bool>(&self, h: Q) -> Orbit {
        let s = qnorm_sq(&h);
        let mut r = s.sqrt();
        let mut dr = 1.0;
        if s > self.bail_sq {
            return Orbit::Outside { r, dr: 1.0 };
        }
        let steps = self.max_iteration.saturating_sub(1);
        let (mut z1, mut z2) = split(&h);
        let (c1, c2) = split(&self.param);
        let f = |z: C| if SQR { z * z } else { self.func.apply(z) };
        for _ in 0..steps {
            z1 = f(z1) + c1;
            z2 = f(z2) + c2;
            if DE {
                dr *= 2.0 * r;
            }
            let s = 0.5 * (z1.norm_sqr() + z2.norm_sqr());
            r = s.sqrt();
            // NaN does not escape (POV-Ray compares `> bailout`); the squared norm is compared
            // as in `quaternion_orbit`.
            if s > self.bail_sq {
                return Orbit::Outside { r, dr };
            }
        }
        Orbit::Inside
    }

    fn is_in(&self, p: DVec3) -> bool {
        matches!(self.orbit_with::<false>(p), Orbit::Inside)
    }

    /// The ray's first crossing before `tmax`, as a ray parameter, for `intersect_first`
    /// (`any` false) and for `any_hit` (`any` true: a crossing sure to be kept may be reported
    /// at the far end of its bracket, see `crossings`).
    fn first_crossing(&self, ray: &Ray, tmax: f64, any: bool) -> Option<f64> {
        let len = ray.dir.length();
        if !(len > 0.0 && len.is_finite()) {
            return None;
        }
        let u = ray.dir / len;
        // The march pushes one crossing at most here (`first_only`): no vector for it.
        let mut first = None;
        let stop = Stop { len, tmax, any };
        self.crossings(
            ray.origin,
            u,
            EPSILON * len,
            true,
            &mut |t| first = first.or(Some(t)),
            Some(stop),
        );
        let t = first? / len;
        (t < tmax).then_some(t)
    }

    /// Crossings along the unit direction `u` from `o` (object space) beyond `tmin`, as
    /// distances: POV-Ray's march (module doc).
    ///
    /// With `stop` (for `intersect_first`, so `first_only`), crossings that would be turned
    /// away for lying beyond its `tmax` end the march unbisected, and for `any_hit` so does a
    /// crossing sure to be kept, which is pushed as the far end of its bracket: the bisection
    /// only moves a crossing within the bracket of its two samples.
    fn crossings(
        &self,
        o: DVec3,
        u: DVec3,
        tmin: f64,
        first_only: bool,
        out: &mut impl FnMut(f64),
        stop: Option<Stop>,
    ) {
        let rb = self.bailout;
        let b = o.dot(u);
        let disc = b * b - (o.length_squared() - rb * rb);
        if disc <= 0.0 {
            return;
        }
        let root = disc.sqrt();
        let (entry, exit) = (-b - root, -b + root);
        if exit <= 0.0 {
            return;
        }
        // No sample beyond the inner radius is inside (`inner_radius`); a sample p = o + u·t is
        // within ~1e-15·(|o| + |t|) of the exact point, and the ray's closest approach and exit
        // from the ball within ~1e-7·|o| of their computed values (the square root of the
        // discriminant's rounding), so the radius, the miss test and the exit take margins well
        // above those: a ray that misses the ball has no crossing, and past the ball's exit
        // every sample is outside, so once the last one was too no crossing can follow.
        let o2 = o.length_squared();
        let o_len = o2.sqrt();
        let ri = self.inner + 1e-9 * (1.0 + o_len);
        let disc_in = b * b - (o2 - ri * ri);
        if disc_in < -1e-9 * (o2 + ri * ri) {
            return;
        }
        let t_out = -b + disc_in.max(0.0).sqrt() + 1e-6 * (1.0 + o_len);
        let min_step = 1.0 / self.precision;
        let step = |orbit: &Orbit| march_step(orbit, min_step);
        let mut t = (entry + ENTRY_EPS).max(0.0);
        let mut prev: Option<(f64, bool)> = None;
        if t > 0.0 {
            // Entering the sphere: the entry counts as outside whatever its orbit does (an
            // object filling the sphere is found one step in: the c = 0 ball), and its
            // orbit gives the first step.
            prev = Some((t, false));
            t += step(&self.orbit(o + u * t));
        }
        // After a least step the next one is likely least too (the march is near the
        // surface), so the samples after this one are taken with it (`orbit_n`) and kept for
        // when the march arrives there: `t + min_step` is what `t += step` then gives. Three
        // ahead where four quaternion (or hypercomplex sqr) orbits take one AVX register per
        // component (about the instructions of two), else one (three measured the same as
        // one in time when the lanes were SSE2 pairs: fractal1 170.9/169.7 ms against
        // 170.1/169.1).
        let wide =
            (self.algebra == Algebra::Quaternion || self.squares()) && crate::math::has_avx();
        let mut ahead = [(0.0f64, Orbit::Inside); AHEAD];
        // `ahead[next..n_ahead]` are the samples still to come, in order.
        let (mut next, mut n_ahead) = (0, 0);
        let mut least = false;
        while t <= exit {
            if t > t_out && !matches!(prev, Some((_, true))) {
                return;
            }
            let orbit = if next < n_ahead && ahead[next].0.to_bits() == t.to_bits() {
                next += 1;
                ahead[next - 1].1
            } else if least {
                let mut ts = [t; AHEAD];
                let mut tk = t;
                for x in ts.iter_mut() {
                    tk += min_step;
                    *x = tk;
                }
                let at = |s: f64| o + u * s;
                let (now, later) = if wide {
                    let [now, a, b, c] = self.orbit_n([at(t), at(ts[0]), at(ts[1]), at(ts[2])]);
                    (now, [a, b, c])
                } else {
                    let [now, a] = self.orbit_n([at(t), at(ts[0])]);
                    (now, [a; AHEAD])
                };
                for (slot, (ta, orbit)) in ahead.iter_mut().zip(ts.into_iter().zip(later)) {
                    *slot = (ta, orbit);
                }
                (next, n_ahead) = (0, if wide { AHEAD } else { 1 });
                now
            } else {
                n_ahead = 0;
                self.orbit(o + u * t)
            };
            let inside = matches!(orbit, Orbit::Inside);
            if let Some((tp, was_in)) = prev {
                if was_in != inside {
                    if let Some(st) = stop {
                        // The crossing lies in [tp, t] (a midpoint of two numbers in it).
                        if tp / st.len >= st.tmax {
                            return;
                        }
                        if st.any && tp > tmin && t / st.len < st.tmax {
                            out(t);
                            return;
                        }
                    }
                    let (mut a, mut c) = (tp, t);
                    // Halving by halving, each midpoint's answer deciding the next bracket.
                    // Midpoints are tested four at a time (`is_in_n`): this one, both
                    // midpoints that can follow it, and the one after the right one; a
                    // midpoint found among them takes its answer from there.
                    let mut known = [(0.0f64, false, f64::NAN); 4];
                    let mut n_known = 0;
                    // Where the ends' orbits decided against the bailout (`is_in4`), once a
                    // round has answered for them.
                    let (mut ga, mut gc) = (f64::NAN, f64::NAN);
                    while c - a > BISECT_TOL {
                        let m = 0.5 * (a + c);
                        if m <= a || m >= c {
                            break;
                        }
                        let (inside, g) = match known[..n_known]
                            .iter()
                            .find(|k| k.0.to_bits() == m.to_bits())
                        {
                            Some(k) => (k.1, k.2),
                            None => {
                                // The hit ends within [a, c] (module doc of the march): at
                                // or below `tmin` it is turned away (`hit > tmin` fails after
                                // the break), and for `any_hit` above it and before `tmax`
                                // it is kept, which is all `any_hit` asks; either is known
                                // before the next round of orbits.
                                if c <= tmin {
                                    break;
                                }
                                if let Some(st) = stop {
                                    if st.any && a > tmin && c / st.len < st.tmax {
                                        out(c);
                                        return;
                                    }
                                }
                                // A bracket still reaching down to `tmin` is most often a
                                // ray leaving the surface it starts on, whose crossing lies
                                // at the bracket's low end: its next four midpoints are each
                                // the low half of the last, and a round that ends
                                // `c <= tmin` takes four halvings, not two.
                                let ts = if a <= tmin {
                                    let m2 = 0.5 * (a + m);
                                    let m3 = 0.5 * (a + m2);
                                    [m, m2, m3, 0.5 * (a + m3)]
                                } else if let Some(ts) = chain_plan(a, c, ga, gc) {
                                    ts
                                } else {
                                    let mr = 0.5 * (m + c);
                                    [m, 0.5 * (a + m), mr, 0.5 * (mr + c)]
                                };
                                let ps = ts.map(|s| o + u * s);
                                // Only the quaternion lanes tell where their orbits decided:
                                // the other sets ask as before (fractal4 6 % slower through
                                // `is_in4`'s pass-through, measured).
                                let (ins, gs) = if self.algebra == Algebra::Quaternion {
                                    self.is_in4(ps)
                                } else {
                                    (self.is_in_n(ps), [f64::NAN; 4])
                                };
                                known = std::array::from_fn(|i| (ts[i], ins[i], gs[i]));
                                n_known = 4;
                                (ins[0], gs[0])
                            }
                        };
                        if inside == was_in {
                            (a, ga) = (m, g);
                        } else {
                            (c, gc) = (m, g);
                        }
                    }
                    let hit = 0.5 * (a + c);
                    if hit > tmin {
                        out(hit);
                        if first_only {
                            return;
                        }
                    }
                }
            }
            prev = Some((t, inside));
            let st = step(&orbit);
            least = st == min_step;
            t += st;
        }
    }

    /// The quaternion orbit's `n`th iterate from `h0` and the tangents `axes` carried forward
    /// with it (`gradient`; `avx::tangents` is the same in lanes).
    fn tangents(&self, h0: Q, axes: [Q; 3], n: u32) -> (Q, [Q; 3]) {
        let (mut h, mut t) = (h0, axes);
        let cube = self.func == JuliaFn::Cube;
        for _ in 0..n {
            let h2 = qmul(&h, &h);
            for ti in t.iter_mut() {
                *ti = if cube {
                    let a = qmul(&qmul(ti, &h), &h);
                    let b = qmul(&qmul(&h, ti), &h);
                    let c = qmul(&h2, ti);
                    std::array::from_fn(|i| a[i] + b[i] + c[i])
                } else {
                    qadd(&qmul(ti, &h), &qmul(&h, ti))
                };
            }
            h = self.quaternion_step(&h);
        }
        (h, t)
    }

    /// Gradient of |h|² after `max_iteration` iterations, carried forward with the point.
    fn gradient(&self, p: DVec3) -> DVec3 {
        let (h0, axes) = self.lift(p);
        let n = self.max_iteration;
        let g = match self.algebra {
            #[cfg(target_arch = "x86_64")]
            Algebra::Quaternion if crate::math::has_avx() => {
                // SAFETY: the CPU has AVX (checked just above).
                let (h, t) = unsafe {
                    if self.func == JuliaFn::Cube {
                        avx::tangents::<true>(self, h0, axes, n)
                    } else {
                        avx::tangents::<false>(self, h0, axes, n)
                    }
                };
                t.map(|ti| (0..4).map(|i| h[i] * ti[i]).sum::<f64>())
            }
            Algebra::Quaternion => {
                let (h, t) = self.tangents(h0, axes, n);
                t.map(|ti| (0..4).map(|i| h[i] * ti[i]).sum::<f64>())
            }
            Algebra::Hypercomplex => {
                let (mut z1, mut z2) = split(&h0);
                let (c1, c2) = split(&self.param);
                let mut t = axes.map(|a| split(&a));
                for _ in 0..n {
                    let (f1, f2) = (self.func.apply(z1), self.func.apply(z2));
                    let (d1, d2) = (self.func.derivative(z1, f1), self.func.derivative(z2, f2));
                    for ti in t.iter_mut() {
                        *ti = (ti.0 * d1, ti.1 * d2);
                    }
                    (z1, z2) = (f1 + c1, f2 + c2);
                }
                t.map(|(t1, t2)| (z1.conj() * t1 + z2.conj() * t2).re)
            }
        };
        DVec3::new(g[0], g[1], g[2])
    }
}

impl Shape for Julia {
    fn bounds(&self) -> Aabb {
        Aabb::new(DVec3::splat(-self.bailout), DVec3::splat(self.bailout))
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        let len = ray.dir.length();
        if !(len > 0.0 && len.is_finite()) {
            return;
        }
        let u = ray.dir / len;
        let push = &mut |s: f64| out.push(Hit::new(s / len));
        self.crossings(ray.origin, u, EPSILON * len, false, push, None);
    }

    fn intersect_first(&self, ray: &Ray, tmax: f64, _scratch: &mut Vec<Hit>) -> Option<Hit> {
        self.first_crossing(ray, tmax, false).map(Hit::new)
    }

    fn any_hit(&self, ray: &Ray, tmax: f64, _scratch: &mut Vec<Hit>) -> bool {
        self.first_crossing(ray, tmax, true).is_some()
    }

    fn inside(&self, p: DVec3) -> bool {
        p.length_squared() <= self.bailout * self.bailout && self.is_in(p)
    }

    fn normal(&self, p: DVec3, _hit: &Hit) -> DVec3 {
        let g = self.gradient(p);
        if g.length_squared() > 0.0 && g.is_finite() {
            g
        } else {
            p
        }
    }
}

#[path = "julia_fn.rs"]
mod func;
pub use func::JuliaFn;

#[path = "julia_pair.rs"]
mod pair;

#[path = "julia_radii.rs"]
mod radii;
use radii::{hyper_inner_radius, inner_radius, keep_radii, sqrt_threshold};

#[cfg(target_arch = "x86_64")]
#[path = "julia_avx.rs"]
mod avx;

#[cfg(test)]
#[path = "julia_tests.rs"]
mod tests;

#[cfg(test)]
#[path = "julia_march_tests.rs"]
mod march_tests;
