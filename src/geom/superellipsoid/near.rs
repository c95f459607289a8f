//! The refinement of a superellipsoid crossing with most field values left unevaluated.
//!
//! The regula falsi (`refine`) asks the field at ~35 points per crossing, four glibc `pow` each
//! (the superellipsoid scenes' largest cost). Most of those points are bisection midpoints,
//! whose values only decide which end they replace (their sign) and whether the next step may
//! be a regula falsi step (the ratio of the two end values lying in [1e-3, 1e3]). Near a point
//! whose powers are known exactly (glibc's bits), a nearby point's powers follow from a short
//! binomial series with a proven error bound; where that bound settles the sign, and the ratio
//! test either way, the exact value is never needed. An end whose value is needed later (a
//! regula falsi step, an unsure ratio) is then evaluated exactly, with the halvings the Illinois
//! rule applied since, in the same order. Every decision is therefore the one the plain
//! refinement makes from exact values, and the root is its root to the bit (unit test
//! `lazy_refine_is_the_plain_one`).

use super::linear::{Lin, Line};
use super::{Power, Superellipsoid};
use crate::math::DVec3;

/// The powers `value` computes at a point (glibc's bits), with the point and the value. The
/// coordinates' sizes, the ratio, the base and the reciprocals the models need are computed
/// again from `p` (`sizes`) by the same operations, so to the same bits: an exact evaluation
/// copies this twice (into the answer, into `Reference`), and with its fourteen fields
/// that was ~40 instructions of the ~490.
#[derive(Clone, Copy, Debug)]
pub(super) struct Powers {
    p: DVec3,
    mc: f64,
    ra: f64,
    g: f64,
    zc: f64,
    v: f64,
}

impl Powers {
    /// max(|x|, |y|), min(|x|, |y|) and |z| at the point, as `value_powers` computed them.
    #[inline(always)]
    fn sizes(&self) -> (f64, f64, f64) {
        let (x, y, z) = (self.p.x.abs(), self.p.y.abs(), self.p.z.abs());
        (x.max(y), x.min(y), z)
    }

    /// The first-order model of the field at this point (`linear`).
    #[inline(always)]
    pub(super) fn lin(&self, se: &Superellipsoid) -> Lin {
        let (m, n, z) = self.sizes();
        Lin::new(
            se,
            (m, 1.0 / m),
            n,
            (z, 1.0 / z),
            (self.mc, self.ra, self.g, self.zc),
            self.v,
        )
    }

    /// `Line::new(&self.lin(se), ..)` in one function: with both inlined here `Lin` never
    /// goes through memory (as an argument it was fifteen stores and their loads, and its
    /// whole arithmetic ran before `Line::new`'s test for a zero coordinate).
    #[inline(never)]
    fn line(&self, se: &Superellipsoid, s: f64, u: DVec3, eta: DVec3) -> Line {
        Line::new(&self.lin(se), s, self.p, u, eta)
    }
}

/// The binomial series of `(1 + d)^k` to `d^5`, with what its remainder bound needs.
#[derive(Clone, Copy, Debug)]
pub(super) struct Series {
    /// C(k, 1) .. C(k, 5).
    coef: [f64; 5],
    /// The remainder bounds' factors: 2.02·|C(k, 3)| after two terms, 2.02·|C(k, 6)| after
    /// five (see `lim`; 2.02 also covers their rounding).
    c3: f64,
    c6: f64,
    /// |k| + 5, for the roundings of the coefficients and of `d`.
    kk: f64,
    /// The largest |d| the series is used for: the terms' ratios |C(k, j+1) / C(k, j)| |d| are
    /// at most (|k| + 1) |d| <= 1/2 beyond the third, so the remainder is at most twice the
    /// first term left out.
    lim: f64,
}

impl Series {
    pub(super) fn new(k: f64) -> Series {
        let mut coef = [0.0; 5];
        let mut c = 1.0;
        for (j, slot) in coef.iter_mut().enumerate() {
            c = c * (k - j as f64) / (j + 1) as f64;
            *slot = c;
        }
        Series {
            coef,
            c3: coef[2].abs() * 2.02,
            c6: (c * (k - 5.0) / 6.0).abs() * 2.02,
            kk: k.abs() + 5.0,
            lim: (0.5 / (k.abs() + 1.0)).min(1e-2),
        }
    }
}

/// `x^k` as `power.of(x)` gives it, from the same power `p0` of a nearby `x0` (`inv0` its
/// reciprocal), and a bound on the difference; None where the series is not used.
///
/// Bound: the remainder (at most twice the first term left out, times `p0`: `Series::lim`) plus relative
/// `3e-15 + (|k| + 5)·|d|·1e-15`, which covers glibc's error at both points (under one unit in
/// the last place each), the roundings of `d` (two) carried through the series (`|k||d|` times
/// them), those of the rounded coefficients, of the Horner steps (about five units of 1e-16 of
/// a value near 1) and of the product with `p0`: all of these are units of 1e-16.
#[inline(always)]
// Negated comparisons: a NaN must take the exact path.
#[allow(clippy::neg_cmp_op_on_partial_ord)]
fn near_power(power: Power, s: &Series, x: f64, x0: f64, inv0: f64, p0: f64) -> Option<(f64, f64)> {
    match power {
        Power::One => Some((x, 0.0)),
        Power::Two => Some((x * x, 0.0)),
        Power::Half => Some((x.sqrt(), 0.0)),
        Power::Whole(_) | Power::Other(_) => {
            // The same argument gives the same bits; `powf(0, k)` is 0 for k > 0.
            if x == x0 {
                return Some((p0, 0.0));
            }
            if x == 0.0 {
                return Some((0.0, 0.0));
            }
            if !p0.is_normal() {
                return None;
            }
            // x − x0 is exact (Sterbenz: |d| <= 1e-2).
            let d = (x - x0) * inv0;
            if !(d.abs() <= s.lim) {
                return None;
            }
            // Most points are within 1e-6 of the reference: two terms do there.
            let c = &s.coef;
            let da = d.abs();
            let d2 = d * d;
            let (t, tail) = if da <= 1e-6 {
                (1.0 + d * (c[0] + d * c[1]), s.c3 * (d2 * da))
            } else {
                let t = 1.0 + d * (c[0] + d * (c[1] + d * (c[2] + d * (c[3] + d * c[4]))));
                (t, s.c6 * (d2 * d2 * d2))
            };
            let p = p0 * t;
            let err = p * (3e-15 + s.kk * da * 1e-15) + p0 * tail;
            Some((p, err))
        }
    }
}

impl Superellipsoid {
    /// `value` (the same operations, so the same bits) and the powers it computed.
    // Negated comparisons: a NaN must take the exact path.
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    pub(super) fn value_powers(&self, p: DVec3) -> (f64, Option<Powers>) {
        let (x, y, z) = (p.x.abs(), p.y.abs(), p.z.abs());
        let m = x.max(y);
        if !(m > 0.0) {
            return (self.value(p), None);
        }
        let n = x.min(y);
        let r = n / m;
        let mc = self.c.of(m);
        let ra = self.a.of(r);
        let base = 1.0 + ra;
        let g = self.b.of(base);
        let xy = mc * g;
        let zc = self.c.of(z);
        let v = xy + zc - 1.0;
        let powers = Powers {
            p,
            mc,
            ra,
            g,
            zc,
            v,
        };
        (v, Some(powers))
    }

    /// `value(p)` within a bound, from the powers at a nearby point; None where a series is
    /// not used. The bound adds up each power's, carried through the sum and products
    /// (first order, plus the product of two errors), and the roundings of those operations,
    /// which both computations make (a few units of 1e-16 of values at most 2^b + 1); the
    /// whole is then grown by half.
    // Negated comparisons: a NaN must take the exact path.
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    pub(super) fn near(&self, pw: &Powers, p: DVec3) -> Option<(f64, f64)> {
        let (x, y, z) = (p.x.abs(), p.y.abs(), p.z.abs());
        let m = x.max(y);
        if !(m > 0.0) {
            return None;
        }
        let r = x.min(y) / m;
        // The reference's sizes, ratio and base as `value_powers` computed them.
        let (m0, n0, z0) = pw.sizes();
        let r0 = n0 / m0;
        let base0 = 1.0 + pw.ra;
        let (mc, emc) = near_power(self.c, &self.sc, m, m0, 1.0 / m0, pw.mc)?;
        let (ra, era) = near_power(self.a, &self.sa, r, r0, 1.0 / r0, pw.ra)?;
        let base = 1.0 + ra;
        // Against the exact path's base: `ra`'s error and the two sums' roundings (base <= 2).
        let ebase = era + 4.5e-16;
        let bk = self.lin.b.abs();
        if !(bk * ebase <= 1e-6) {
            return None;
        }
        let (g, eg0) = near_power(self.b, &self.sb, base, base0, 1.0 / base0, pw.g)?;
        // base >= 1, so base^b moves by at most b·ebase relative (1.01: the second order).
        let eg = eg0 + g * (bk * ebase * 1.01);
        let (zc, ezc) = near_power(self.c, &self.sc, z, z0, 1.0 / z0, pw.zc)?;
        let xy = mc * g;
        let exy = mc * eg + g * emc + emc * eg + xy * 4.5e-16;
        let sum = xy + zc;
        let v = sum - 1.0;
        let err = (exy + ezc + (sum.abs() + 1.0) * 4.5e-16) * 1.5;
        (v.is_finite() && err.is_finite()).then_some((v, err))
    }
}

/// A point the refinement evaluated exactly (`o + u·s`), with its powers and the first-order
/// models there, built when first asked: an exact end is often replaced by the other end's
/// exact evaluation before any midpoint needs it (a regula falsi step evaluates both).
struct Reference {
    pw: Powers,
    s: f64,
    models: Option<Line>,
}

impl Reference {
    fn new(pw: Powers, s: f64) -> Reference {
        Reference {
            pw,
            s,
            models: None,
        }
    }

    /// The powers and `Line` along the ray (`eta` as `Line::new` takes it), from `Lin` at
    /// the point.
    #[inline(always)]
    fn models(&mut self, se: &Superellipsoid, u: DVec3, eta: DVec3) -> (&Powers, &Line) {
        let Reference { pw, s, models } = self;
        let line = models.get_or_insert_with(|| pw.line(se, *s, u, eta));
        (pw, line)
    }
}

/// One end of the bracket: its value, exact when `err` is 0, else within `err` of the exact
/// value after `halvings` Illinois halvings.
#[derive(Clone, Copy)]
struct End {
    s: f64,
    v: f64,
    err: f64,
    halvings: u32,
}

impl End {
    fn halve(&mut self) {
        self.v *= 0.5;
        self.err *= 0.5;
        self.halvings += 1;
    }
}

/// Whether the exact ratio of the two ends' values is surely outside [1e-3, 1e3], so the
/// plain refinement bisects (an approximate value is finite, nonzero and below 1e300, and so
/// is the exact one). Without divisions: `|fa| >= va − ea.err` and `|fb| <= vb + eb.err`, and
/// the margin 1e-14 covers the roundings of these few operations and of `false_position`'s
/// quotient. With both ends exact it is `false_position`'s own test, which then bisects too.
#[inline(always)]
fn lopsided(ea: &End, eb: &End) -> bool {
    let (va, vb) = (ea.v.abs(), eb.v.abs());
    (va + ea.err) * (1.0 + 1e-14) < 1e-3 * (vb - eb.err)
        || (va - ea.err) * (1.0 - 1e-14) > 1e3 * (vb + eb.err)
}

/// The refinement's steps (ends, last side, steps taken so far), as `refine` keeps them.
#[derive(Clone, Copy)]
struct Ends {
    ea: End,
    eb: End,
    side: i8,
    steps: u32,
}

/// The plain refinement's step limit.
const STEPS: u32 = 200;

impl Ends {
    /// Takes the midpoint `em` (its sign certain) as the end of its sign, with the Illinois
    /// halving of the other end when the same side moves twice in a row.
    #[inline(always)]
    fn take(&mut self, em: End) {
        if (em.v < 0.0) == (self.ea.v < 0.0) {
            self.ea = em;
            if self.side == -1 {
                self.eb.halve();
            }
            self.side = -1;
        } else {
            self.eb = em;
            if self.side == 1 {
                self.ea.halve();
            }
            self.side = 1;
        }
    }

    /// The steps `refine` would take next while each is a bisection whose midpoint `line`
    /// settles: the same tests and updates in a loop that keeps the ends in registers (a
    /// lopsided step in `refine` costs ~95 instructions, most of them its state moving through
    /// the stack). Stops before the first step that needs more (the tolerance reached, a ratio
    /// not surely lopsided, a midpoint the line does not settle), which `refine` then takes
    /// from the same state, so every step is the one it would take.
    ///
    /// The bracket only shrinks, so where the line `covers` both ends at the start it
    /// covers every midpoint of the run.
    #[inline(never)]
    fn bisect_run(&mut self, line: &Line, tol: f64) {
        let line = *line;
        if line.covers(self.ea.s, self.eb.s) {
            self.run(tol, |m| line.at_between(m));
        } else {
            self.run(tol, |m| line.at(m));
        }
    }

    /// `bisect_run`'s loop, with `at` the line's answer at a midpoint.
    #[inline(always)]
    fn run(&mut self, tol: f64, at: impl Fn(f64) -> Option<(f64, f64)>) {
        let Ends {
            mut ea,
            mut eb,
            mut side,
            mut steps,
        } = *self;
        while steps < STEPS {
            let (a, b) = (ea.s, eb.s);
            if (b - a).abs() <= tol || !lopsided(&ea, &eb) {
                break;
            }
            let m = 0.5 * (a + b);
            let Some((v, err)) = at(m) else {
                break;
            };
            let em = End {
                s: m,
                v,
                err,
                halvings: 0,
            };
            if (v < 0.0) == (ea.v < 0.0) {
                ea = em;
                if side == -1 {
                    eb.halve();
                }
                side = -1;
            } else {
                eb = em;
                if side == 1 {
                    ea.halve();
                }
                side = 1;
            }
            steps += 1;
        }
        *self = Ends {
            ea,
            eb,
            side,
            steps,
        };
    }
}

/// A root of the field along `o + s·u` between `a` and `b` (the exact values `fa` and `fb`,
/// negative at exactly one end): regula falsi (Illinois variant), bisecting when the end
/// values are too lopsided for it to make progress. The steps and the root are those of the
/// plain refinement from exact values at every point (module doc).
pub(super) fn refine(
    se: &Superellipsoid,
    o: DVec3,
    u: DVec3,
    a: f64,
    fa: f64,
    b: f64,
    fb: f64,
) -> f64 {
    let ea = End {
        s: a,
        v: fa,
        err: 0.0,
        halvings: 0,
    };
    let mut br = Ends {
        ea,
        eb: End { s: b, v: fb, ..ea },
        side: 0,
        steps: 0,
    };
    let tol = 1e-13 * a.abs().max(b.abs()).max(1.0);
    // The last point evaluated exactly, whose powers the series start from (`Reference`).
    let mut reference: Option<Reference> = None;
    let eta = Line::eta(o, u, a.abs().max(b.abs()));
    let exact = |end: &mut End, reference: &mut Option<Reference>| {
        if end.err != 0.0 {
            let p = o + u * end.s;
            let (mut v, pw) = se.value_powers(p);
            for _ in 0..end.halvings {
                v *= 0.5;
            }
            (end.v, end.err) = (v, 0.0);
            if let Some(pw) = pw {
                *reference = Some(Reference::new(pw, end.s));
            }
        }
    };
    while br.steps < STEPS {
        let (a, b) = (br.ea.s, br.eb.s);
        if (b - a).abs() <= tol {
            break;
        }
        // A regula falsi point is evaluated exactly, never estimated: it lands next to the root,
        // where neither model settled it cheaply (the line from an older reference rarely, the
        // series at ~255 instructions), it usually stays an end until the next regula falsi
        // step, which then needed its exact value anyway, and as the new reference it gives the
        // bisection run that follows a line whose reach covers it. superel2: 209.4 -> 182.2 M
        // (72,300 exact evaluations against 65,500, but 22,700 model builds against 54,000,
        // ~10,000 series calls against 83,000).
        let lop = lopsided(&br.ea, &br.eb);
        let m = if lop {
            0.5 * (a + b)
        } else {
            exact(&mut br.ea, &mut reference);
            exact(&mut br.eb, &mut reference);
            false_position(a, br.ea.v, b, br.eb.v)
        };
        let p = || o + u * m;
        // The series where the model cannot settle the sign: it costs about 0.6 of an exact
        // evaluation and settles most of what the model leaves.
        let settles = |&(v, err): &(f64, f64)| v.abs() > err && v.abs() < 1e300;
        let mut line_settled = false;
        let estimate = reference.as_mut().filter(|_| lop).and_then(|r| {
            let (pw, line) = r.models(se, u, eta);
            let at = line.at(m);
            line_settled = at.is_some();
            // Not `Lin::at` where the line does not settle: it settled ~1 in 10 of those
            // midpoints (superel2), each ask ~60 instructions, and the series most of them.
            at.or_else(|| se.near(pw, p()).filter(settles))
        });
        let em = match estimate {
            Some((v, err)) if v.abs() > err && v.abs() < 1e300 => End {
                s: m,
                v,
                err,
                halvings: 0,
            },
            _ => {
                let p = p();
                let (fm, pw) = se.value_powers(p);
                if fm.is_nan() {
                    return m;
                }
                if let Some(pw) = pw {
                    reference = Some(Reference::new(pw, m));
                }
                End {
                    s: m,
                    v: fm,
                    err: 0.0,
                    halvings: 0,
                }
            }
        };
        // An approximate value's sign is the exact one's (|v| > err).
        br.take(em);
        br.steps += 1;
        // The reference is the one the line came from: a settled midpoint needs no exact
        // evaluation (and the line is read in place, not copied out of the closure).
        if line_settled {
            if let Some(Reference {
                models: Some(line), ..
            }) = &reference
            {
                br.bisect_run(line, tol);
            }
        }
    }
    0.5 * (br.ea.s + br.eb.s)
}

/// The refinement's next point: the false-position step between (a, fa) and (b, fb) when the
/// two values are finite and within a factor of 1000 of each other and the step lands strictly
/// between them, else the midpoint.
fn false_position(a: f64, fa: f64, b: f64, fb: f64) -> f64 {
    let ratio = (fa / fb).abs();
    if fa.is_finite() && fb.is_finite() && (1e-3..=1e3).contains(&ratio) {
        let m = b - fb * (b - a) / (fb - fa);
        if m > a.min(b) && m < a.max(b) {
            return m;
        }
    }
    0.5 * (a + b)
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;

    /// The plain refinement (exact values at every point), which `near::refine` must match
    /// to the bit.
    fn refine(f: &impl Fn(f64) -> f64, a: f64, fa: f64, b: f64, fb: f64) -> f64 {
        let (mut a, mut fa, mut b, mut fb) = (a, fa, b, fb);
        let tol = 1e-13 * a.abs().max(b.abs()).max(1.0);
        let mut side = 0i8;
        for _ in 0..200 {
            if (b - a).abs() <= tol {
                break;
            }
            let m = false_position(a, fa, b, fb);
            let fm = f(m);
            if fm.is_nan() {
                return m;
            }
            if (fm < 0.0) == (fa < 0.0) {
                (a, fa) = (m, fm);
                if side == -1 {
                    fb *= 0.5;
                }
                side = -1;
            } else {
                (b, fb) = (m, fm);
                if side == 1 {
                    fa *= 0.5;
                }
                side = 1;
            }
        }
        0.5 * (a + b)
    }

    pub(in crate::geom::superellipsoid) fn rng(seed: u64) -> impl FnMut() -> f64 {
        let mut state = seed;
        move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            f64::from_bits((state >> 12) | 0x3ff0_0000_0000_0000) - 1.0
        }
    }

    pub(in crate::geom::superellipsoid) const SHAPES: [(f64, f64); 10] = [
        (0.1, 0.1),
        (0.3, 0.3),
        (0.5, 0.5),
        (0.9, 0.9),
        (1.0, 0.3),
        (1.0, 0.1),
        (0.3, 2.0),
        (0.5, 3.0),
        (3.0, 0.5),
        (1.0, 1.0),
    ];

    /// A point of the surface near the direction `p` (bisection on the ray from the centre).
    pub(in crate::geom::superellipsoid) fn on_surface(s: &Superellipsoid, p: DVec3) -> DVec3 {
        let (mut lo, mut hi) = (0.0, 2.0);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if s.value(p * mid) < 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        p * lo
    }

    /// `value_powers` is `value` to the bit, and `near` is within its bound of it, from
    /// references on and off the surface and offsets from 1e-14 to 1e-2.
    #[test]
    fn near_values_are_within_their_bound() {
        let mut next = rng(0x2545_f491_4f6c_dd1d);
        let (mut used, mut worst) = (0, 0.0f64);
        for (e, n) in SHAPES {
            let s = Superellipsoid::new(e, n);
            for i in 0..20_000 {
                let dir = DVec3::new(next(), next(), next()) * 2.0 - DVec3::ONE;
                let p0 = if i % 4 == 0 { dir } else { on_surface(&s, dir) };
                let (v0, pw) = s.value_powers(p0);
                assert_eq!(v0.to_bits(), s.value(p0).to_bits(), "{e} {n} {p0}");
                let Some(pw) = pw else { continue };
                let step = 10f64.powf(-2.0 - 12.0 * next());
                let off = (DVec3::new(next(), next(), next()) * 2.0 - DVec3::ONE) * step;
                let p = p0 + off;
                let exact = s.value(p);
                if let Some((v, err)) = s.near(&pw, p) {
                    used += 1;
                    let miss = (v - exact).abs();
                    assert!(miss <= err, "{e} {n} {p0} {p}: {v} {exact} {err}");
                    worst = worst.max(miss / err);
                }
            }
        }
        assert!(used > 100_000, "{used}");
        assert!(worst < 0.5, "{worst}");
    }

    /// The lazy refinement gives the plain one's root to the bit, on brackets of the
    /// samples' kind along rays through the surface.
    #[test]
    fn lazy_refine_is_the_plain_one() {
        let mut next = rng(0x9e37_79b9_7f4a_7c15);
        let mut roots = 0;
        for (e, n) in SHAPES {
            let s = Superellipsoid::new(e, n);
            for _ in 0..3000 {
                let o = DVec3::new(next(), next(), next()) * 4.0 - DVec3::splat(2.0);
                let target = DVec3::new(next(), next(), next()) * 1.6 - DVec3::splat(0.8);
                let u = (target - o).normalize();
                let f = |t: f64| s.value(o + u * t);
                let step = 0.01 + 0.1 * next();
                let (mut t0, mut f0) = (0.0, f(0.0));
                for k in 1..200 {
                    let t1 = k as f64 * step;
                    let f1 = f(t1);
                    if (f0 < 0.0) != (f1 < 0.0) {
                        let plain = refine(&f, t0, f0, t1, f1);
                        let lazy = super::refine(&s, o, u, t0, f0, t1, f1);
                        assert_eq!(plain.to_bits(), lazy.to_bits(), "{e} {n} {o} {u} {t0}");
                        roots += 1;
                    }
                    (t0, f0) = (t1, f1);
                }
            }
        }
        assert!(roots > 20_000, "{roots}");
    }
}
