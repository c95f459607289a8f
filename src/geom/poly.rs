//! Real roots of polynomials inside an interval, for the torus and any later polynomial shape.
//!
//! Closed forms (Ferrari, Cardano) lose most of their digits exactly where it shows on screen:
//! where two roots merge along a silhouette. So roots are isolated first and then polished with
//! Horner evaluations, which stay accurate near the roots themselves:
//! * [`roots_in`]: the critical points (roots of the derivative, found recursively) cut the
//!   interval into monotone pieces, and each piece whose ends differ in sign holds one root.
//! * [`sturm_roots_in`]: the same, plus roots of even multiplicity (exact tangency), which
//!   have no sign change; a Sturm sequence counts the distinct roots to find those. Slower.
//!
//! Roots are polished with Newton's method kept inside a shrinking bracket by bisection.
//!
//! Coefficients are in ascending order: `c[i]` multiplies `x^i`.

use std::ops::Deref;

use crate::geom::bernstein::surely_no_root;

mod definite;
mod sturm_first;
mod window;
pub use definite::surely_definite_quartic;
pub use sturm_first::{sturm_first_root_in, sturm_roots_in_window};
pub use window::roots_in_window;

/// Highest degree handled; higher-degree input yields no roots rather than a panic.
pub const MAX_DEGREE: usize = 16;

/// Up to [`MAX_DEGREE`] roots in increasing order, without heap allocation.
#[derive(Clone, Copy, Debug)]
pub struct Roots {
    len: usize,
    buf: [f64; MAX_DEGREE],
}

impl Roots {
    pub const fn new() -> Roots {
        Roots {
            len: 0,
            buf: [0.0; MAX_DEGREE],
        }
    }
    fn push(&mut self, x: f64) {
        // A root sitting on a breakpoint can be reported from both sides.
        if self.len < MAX_DEGREE && (self.len == 0 || self.buf[self.len - 1] != x) {
            self.buf[self.len] = x;
            self.len += 1;
        }
    }
}

impl Default for Roots {
    fn default() -> Self {
        Roots::new()
    }
}

impl Deref for Roots {
    type Target = [f64];
    fn deref(&self) -> &[f64] {
        &self.buf[..self.len]
    }
}

/// The coefficients without exactly-zero leading terms; `None` beyond [`MAX_DEGREE`].
fn trim(c: &[f64]) -> Option<&[f64]> {
    let n = c.iter().rposition(|&x| x != 0.0).map_or(0, |i| i + 1);
    (n <= MAX_DEGREE + 1).then_some(&c[..n])
}

/// Horner evaluation, from 0: `((0·x + c_n)·x + c_{n-1})…`.
///
/// The first step, `0·x + c_n`, is `c_n` itself when `x` is finite and `c_n` nonzero (a
/// zero's sign and a NaN from an infinite `x` are the only ways it differs), so it is
/// skipped then: one multiply-add less in the dependent chain, the same bits.
#[inline]
pub fn eval(c: &[f64], x: f64) -> f64 {
    match c.split_last() {
        Some((&lead, rest)) if lead != 0.0 && x.is_finite() => {
            rest.iter().rev().fold(lead, |acc, &ci| acc * x + ci)
        }
        _ => c.iter().rev().fold(0.0, |acc, &ci| acc * x + ci),
    }
}

/// Value and first derivative in one Horner pass, from `f = df = 0`. For a finite `x` and a
/// nonzero leading coefficient the first two steps give `df = c_n` and `f = c_n·x + c_{n-1}`
/// exactly (`0·x + 0` is `+0`, and `±0 + c_n` is `c_n`), so they are skipped (see [`eval`]).
#[inline]
pub fn eval_with_derivative(c: &[f64], x: f64) -> (f64, f64) {
    if let [rest @ .., c1, lead] = c {
        if *lead != 0.0 && x.is_finite() {
            let mut df = *lead;
            let mut f = lead * x + c1;
            for &ci in rest.iter().rev() {
                df = df * x + f;
                f = f * x + ci;
            }
            return (f, df);
        }
    }
    let mut f = 0.0;
    let mut df = 0.0;
    for &ci in c.iter().rev() {
        df = df * x + f;
        f = f * x + ci;
    }
    (f, df)
}

/// Real roots of `c[2] x² + c[1] x + c[0]` (or of a line), increasing, anywhere on the axis.
fn quadratic(c: &[f64], out: &mut Roots, with_vertex: bool) {
    match c.len() {
        0 | 1 => {}
        2 => out.push(-c[0] / c[1]),
        _ => {
            let (a, b, cc) = (c[2], c[1], c[0]);
            let disc = b * b - 4.0 * a * cc;
            if disc > 0.0 {
                // Citardauq form for the smaller root: no cancellation between -b and sqrt.
                let q = -0.5 * (b + b.signum() * disc.sqrt());
                let (r1, r2) = (q / a, if q != 0.0 { cc / q } else { q / a });
                out.push(r1.min(r2));
                out.push(r1.max(r2));
            } else if disc == 0.0 || with_vertex {
                // As a breakpoint the vertex is harmless even when rounding pushed a true
                // double root's discriminant below zero.
                out.push(-0.5 * b / a);
            }
        }
    }
}

/// Real roots of the polynomial in `[lo, hi]`, increasing, each simple root once.
///
/// Roots of even multiplicity (the polynomial touching zero without crossing) are found only
/// when the polynomial evaluates to exactly zero at a critical point; for ray tracing these are
/// grazing rays, which are equally ambiguous in POV-Ray.
pub fn roots_in(c: &[f64], lo: f64, hi: f64) -> Roots {
    let mut out = Roots::new();
    roots_in_into(c, lo, hi, &mut out);
    out
}

/// [`roots_in`] appended to a list the caller holds: the roots in place, where a returned
/// `Roots` (136 bytes) could be copied by a `memcpy` call into the caller's frame and its
/// length read back from that copy's fresh stores (the spline sweeps' `sign_changes`).
#[inline(always)]
pub fn roots_in_into(c: &[f64], lo: f64, hi: f64, out: &mut Roots) {
    if let Some(c) = trim(c) {
        if lo <= hi && !surely_no_root(c, lo, hi) {
            isolate(c, lo, hi, out, false);
        }
    }
}

/// [`roots_in`] for a polynomial of degree at most 2 whose interval end `hi` costs something
/// (Cauchy's bound: a division per coefficient) and is asked only when a root at or above
/// `lo` must be checked against it: the same roots, bit for bit (`quadratic`'s arithmetic and
/// `Roots::push`'s merging of equal values), in a two-entry array with their count.
#[inline]
pub fn low_roots_in(c: &[f64], lo: f64, hi: impl Fn() -> f64) -> ([f64; 2], usize) {
    let (mut r, mut n) = ([0.0; 2], 0);
    match trim(c) {
        Some([c0, c1]) => {
            r[0] = -c0 / c1;
            n = 1;
        }
        Some([cc, b, a]) => {
            let disc = b * b - 4.0 * a * cc;
            if disc > 0.0 {
                let q = -0.5 * (b + b.signum() * disc.sqrt());
                let (r1, r2) = (q / a, if q != 0.0 { cc / q } else { q / a });
                r = [r1.min(r2), r1.max(r2)];
                n = if r[1] != r[0] { 2 } else { 1 };
            } else if disc == 0.0 {
                r[0] = -0.5 * b / a;
                n = 1;
            }
        }
        _ => {}
    }
    let (mut out, mut m) = ([0.0; 2], 0);
    let mut end = None;
    for &x in &r[..n] {
        // `roots_in` keeps the roots in [lo, hi] when lo <= hi, which x >= lo and x <= hi
        // imply.
        if x >= lo && x <= *end.get_or_insert_with(&hi) {
            out[m] = x;
            m += 1;
        }
    }
    (out, m)
}

/// The roots `isolate` reports for `d` on [lo, hi] with critical points `crit` (ascending),
/// in order, each as its bracket (a, b, sign of d at a) written into `out`; an exact zero
/// has a == b. Returns how many.
#[inline(always)]
fn brackets(
    d: &[f64],
    crit: impl Iterator<Item = f64>,
    lo: f64,
    hi: f64,
    out: &mut [(f64, f64, bool); MAX_DEGREE + 2],
) -> usize {
    let mut m = 0;
    let mut a = lo;
    let mut fa = eval(d, a);
    for b in crit.chain(std::iter::once(hi)) {
        let fb = eval(d, b);
        if fa == 0.0 {
            out[m] = (a, a, false);
            m += 1;
        } else if (fa < 0.0) != (fb < 0.0) && fb != 0.0 {
            out[m] = (a, b, fa < 0.0);
            m += 1;
        }
        a = b;
        fa = fb;
    }
    if fa == 0.0 {
        out[m] = (a, a, false);
        m += 1;
    }
    m
}

fn isolate(c: &[f64], lo: f64, hi: f64, out: &mut Roots, breakpoints: bool) {
    // As in `polish`: a quartic's and its cubic derivative's evaluations unrolled, the same
    // operations.
    match c.len() {
        5 => isolate_body(<&[f64; 5]>::try_from(c).unwrap(), lo, hi, out, breakpoints),
        4 => isolate_body(<&[f64; 4]>::try_from(c).unwrap(), lo, hi, out, breakpoints),
        _ => isolate_body(c, lo, hi, out, breakpoints),
    }
}

#[inline(always)]
fn isolate_body(c: &[f64], lo: f64, hi: f64, out: &mut Roots, breakpoints: bool) {
    let n = c.len().saturating_sub(1);
    if n <= 2 {
        let mut r = Roots::new();
        quadratic(c, &mut r, breakpoints);
        for &x in r.iter().filter(|&&x| x >= lo && x <= hi) {
            out.push(x);
        }
        return;
    }
    let mut d = [0.0; MAX_DEGREE];
    for i in 1..=n {
        d[i - 1] = c[i] * i as f64;
    }
    let mut crit = Roots::new();
    isolate(&d[..n], lo, hi, &mut crit, true);

    let mut a = lo;
    let mut fa = eval(c, a);
    for &b in crit.iter().chain(std::iter::once(&hi)) {
        let fb = eval(c, b);
        if fa == 0.0 {
            out.push(a);
        } else if (fa < 0.0) != (fb < 0.0) && fb != 0.0 {
            out.push(polish(c, a, b, fa < 0.0));
        }
        a = b;
        fa = fb;
    }
    if fa == 0.0 {
        out.push(a);
    }
}

/// A root of [`first_root_with`]'s walk before it is polished: the bracket `[a, b]` of a
/// sign change (the sign at `a` negative when `neg_at_a`), or an exact root with `a == b`.
/// [`Candidate::root`] gives the root bit for bit as [`roots_in`] gives it, and it lies in
/// `[a, b]` (every step of `polish` stays inside its shrinking bracket), so a caller that
/// would discard every value there can leave it unpolished.
#[derive(Clone, Copy, Debug)]
pub struct Candidate<'a> {
    pub c: &'a [f64],
    pub a: f64,
    pub b: f64,
    pub neg_at_a: bool,
}

impl Candidate<'_> {
    /// An exact root (nothing to polish).
    fn exact(x: f64) -> Candidate<'static> {
        Candidate {
            c: &[],
            a: x,
            b: x,
            neg_at_a: false,
        }
    }

    /// The root, polished when it is a bracket.
    #[inline]
    pub fn root(&self) -> f64 {
        if self.a == self.b {
            self.a
        } else {
            polish(self.c, self.a, self.b, self.neg_at_a)
        }
    }
}

/// The first of [`roots_in`]'s roots (in increasing order) for which `keep` holds, bit for bit
/// as [`roots_in`] gives it, for a caller that wants only the nearest crossing: the roots and
/// critical points beyond it are not polished. The pieces are walked as `isolate` walks them,
/// each critical point polished only when the walk reaches it (see `window::critical_brackets`
/// for the brackets), so every piece reached has the same ends as in [`roots_in`].
#[inline]
pub fn first_root_in(
    c: &[f64],
    lo: f64,
    hi: f64,
    mut keep: impl FnMut(f64) -> bool,
) -> Option<f64> {
    first_root_with(c, lo, hi, |cand| {
        let x = cand.root();
        keep(x).then_some(x)
    })
}

/// [`first_root_in`] for a caller that sees each root as its [`Candidate`] (in increasing
/// order) and answers with the root it keeps, or `None` to walk on: a caller may decide from
/// the bracket alone, without the root's polishing.
pub fn first_root_with(
    c: &[f64],
    lo: f64,
    hi: f64,
    take: impl FnMut(Candidate) -> Option<f64>,
) -> Option<f64> {
    first_root_before(c, lo, hi, true, |_| false, take)
}

/// [`first_root_in`] without its [`surely_no_root`] shortcut, for a caller whose own
/// certificate of "no root" (see `definite`) has just failed, where that shortcut seldom
/// succeeds: the same answer, bit for bit, since the shortcut only ever answers `None` where
/// the walk finds nothing (see `surely_no_root`).
pub fn first_root_in_unchecked(
    c: &[f64],
    lo: f64,
    hi: f64,
    mut keep: impl FnMut(f64) -> bool,
) -> Option<f64> {
    first_root_before(
        c,
        lo,
        hi,
        false,
        |_| false,
        |cand| {
            let x = cand.root();
            keep(x).then_some(x)
        },
    )
}

/// [`first_root_with`] without its [`surely_no_root`] shortcut, for a caller that has just
/// asked its own (see [`first_root_in_unchecked`]).
pub fn first_root_with_unchecked(
    c: &[f64],
    lo: f64,
    hi: f64,
    take: impl FnMut(Candidate) -> Option<f64>,
) -> Option<f64> {
    first_root_before(c, lo, hi, false, |_| false, take)
}

/// [`first_root_with`] (its [`surely_no_root`] shortcut asked when `shortcut`) for a caller
/// whose answer for a root at or past a point where `past` holds is the answer for no root
/// (a ray's crossings at or past its `tmax`), `past` holding at every point above one where
/// it holds: the walk gives `None` at the first piece whose start `past` holds, before it
/// polishes the critical point ending that piece, since every root still to come lies at or
/// past that start. Below that piece the walk and its candidates are [`first_root_with`]'s.
#[inline(always)]
pub fn first_root_before(
    c: &[f64],
    lo: f64,
    hi: f64,
    shortcut: bool,
    past: impl Fn(f64) -> bool,
    take: impl FnMut(Candidate) -> Option<f64>,
) -> Option<f64> {
    let c = trim(c)?;
    // As in `polish`: a quartic's walk (a torus's) compiled with the length known, so its
    // evaluations are unrolled: the same operations in the same order.
    match c.len() {
        5 => first_root_body(
            <&[f64; 5]>::try_from(c).unwrap(),
            lo,
            hi,
            shortcut,
            past,
            take,
        ),
        _ => first_root_body(c, lo, hi, shortcut, past, take),
    }
}

#[inline(always)]
fn first_root_body(
    c: &[f64],
    lo: f64,
    hi: f64,
    shortcut: bool,
    past: impl Fn(f64) -> bool,
    mut take: impl FnMut(Candidate) -> Option<f64>,
) -> Option<f64> {
    let n = c.len().saturating_sub(1);
    if lo > hi || lo.is_nan() || hi.is_nan() || (shortcut && surely_no_root(c, lo, hi)) {
        return None;
    }
    if n <= 2 {
        let mut out = Roots::new();
        isolate(c, lo, hi, &mut out, false);
        return out.iter().find_map(|&x| take(Candidate::exact(x)));
    }
    let mut d = [0.0; MAX_DEGREE];
    for i in 1..=n {
        d[i - 1] = c[i] * i as f64;
    }
    let d = &d[..n];
    // The critical points as brackets still to polish (an exact point has equal ends): a
    // cubic's are a quadratic's, found at once; otherwise the brackets are those
    // `window::critical_brackets` finds.
    let mut cands = [(0.0, 0.0, false); MAX_DEGREE + 2];
    let mut m = 0;
    if n == 3 {
        let mut crit = Roots::new();
        isolate(d, lo, hi, &mut crit, true);
        for &x in crit.iter() {
            cands[m] = (x, x, false);
            m += 1;
        }
    } else {
        let mut dd = [0.0; MAX_DEGREE];
        for i in 1..n {
            dd[i - 1] = d[i] * i as f64;
        }
        let mut crit2 = Roots::new();
        isolate(&dd[..n - 1], lo, hi, &mut crit2, true);
        m = brackets(d, crit2.iter().copied(), lo, hi, &mut cands);
    }
    let piece = |a: f64, b: f64, neg_at_a: bool| Candidate { c, a, b, neg_at_a };
    // `isolate`'s loop over the pieces. The critical points are deduplicated and capped as
    // `Roots::push` does when `isolate` collects them.
    let mut a = lo;
    let mut fa = eval(c, a);
    let (mut last, mut count) = (None, 0);
    let mut k = 0;
    loop {
        // Every root from here on is at or past `a` (the last piece, `[a, hi]`, is asked
        // here too: the loop leaves below only after this test).
        if past(a) {
            return None;
        }
        let b = if k < m {
            let (x0, x1, neg) = cands[k];
            k += 1;
            let x = if x0 == x1 { x0 } else { polish(d, x0, x1, neg) };
            if count >= MAX_DEGREE || last == Some(x) {
                continue;
            }
            last = Some(x);
            count += 1;
            x
        } else {
            break;
        };
        let fb = eval(c, b);
        if fa == 0.0 {
            if let Some(x) = take(Candidate::exact(a)) {
                return Some(x);
            }
        } else if (fa < 0.0) != (fb < 0.0) && fb != 0.0 {
            if let Some(x) = take(piece(a, b, fa < 0.0)) {
                return Some(x);
            }
        }
        a = b;
        fa = fb;
    }
    let fb = eval(c, hi);
    if fa == 0.0 {
        if let Some(x) = take(Candidate::exact(a)) {
            return Some(x);
        }
    } else if (fa < 0.0) != (fb < 0.0) && fb != 0.0 {
        if let Some(x) = take(piece(a, hi, fa < 0.0)) {
            return Some(x);
        }
    }
    if fb == 0.0 {
        take(Candidate::exact(hi))
    } else {
        None
    }
}

/// [`roots_in`] without the [`surely_no_root`] shortcut, for the tests of that shortcut and
/// for a caller that has just asked its own (the torus's written-out quartic certificate):
/// the same roots, bit for bit, wherever the shortcut would not have answered.
pub(crate) fn roots_in_isolated(c: &[f64], lo: f64, hi: f64) -> Roots {
    let mut out = Roots::new();
    if let Some(c) = trim(c) {
        if lo <= hi {
            isolate(c, lo, hi, &mut out, false);
        }
    }
    out
}

/// Newton iteration kept inside the sign-change bracket `[a, b]`; `neg_at_a` is the sign of
/// the polynomial at `a`.
///
/// Quartics (a torus) and their cubic derivatives are most of the calls: for them the body
/// is compiled with the length known, so each step's Horner pass is unrolled (the same
/// operations in the same order, only without the loop's bookkeeping).
fn polish(c: &[f64], a: f64, b: f64, neg_at_a: bool) -> f64 {
    match c.len() {
        5 => polish_body(<&[f64; 5]>::try_from(c).unwrap(), a, b, neg_at_a),
        4 => polish_body(<&[f64; 4]>::try_from(c).unwrap(), a, b, neg_at_a),
        _ => polish_body(c, a, b, neg_at_a),
    }
}

#[inline(always)]
fn polish_body(c: &[f64], mut a: f64, mut b: f64, neg_at_a: bool) -> f64 {
    let mut x = 0.5 * (a + b);
    let mut step = b - a;
    let mut prev_step = step;
    for _ in 0..100 {
        let (f, df) = eval_with_derivative(c, x);
        if f == 0.0 {
            return x;
        }
        if (f < 0.0) == neg_at_a {
            a = x;
        } else {
            b = x;
        }
        let newton = x - f / df;
        // Fall back to bisection when Newton leaves the bracket (or df is 0/NaN) or when it
        // stops converging fast, so the iteration can never wander or stall.
        let next = if newton > a && newton < b && (newton - x).abs() < 0.5 * prev_step.abs() {
            newton
        } else {
            0.5 * (a + b)
        };
        prev_step = step;
        step = next - x;
        let tol = 2.0 * f64::EPSILON * next.abs() + f64::MIN_POSITIVE;
        if step.abs() <= tol || b - a <= tol {
            return next;
        }
        x = next;
    }
    x
}

/// A Sturm sequence, each member scaled to unit max coefficient (signs are all that count),
/// for polynomials of at most `N` coefficients (a quartic's sequence fits in 5×5, not the
/// 17×17 of the highest degree: less to zero and to copy on every ray).
struct Sturm<const N: usize> {
    polys: [[f64; N]; N],
    lens: [usize; N],
    count: usize,
}

impl<const N: usize> Sturm<N> {
    /// The sequence of `c`, which has at most `N` coefficients. Each member's degree is below
    /// the previous one's, so at most `N` members: `count` never reaches past the arrays.
    fn new(c: &[f64]) -> Sturm<N> {
        let mut s = Sturm {
            polys: [[0.0; N]; N],
            lens: [0; N],
            count: 0,
        };
        s.set(0, c);
        let mut d = [0.0; N];
        for i in 1..c.len() {
            d[i - 1] = c[i] * i as f64;
        }
        s.set(1, &d[..c.len() - 1]);
        s.count = 2;
        while s.count < N && s.lens[s.count - 1] > 1 {
            let (a, b) = (s.count - 2, s.count - 1);
            let (la, lb) = (s.lens[a], s.lens[b]);
            let mut r = s.polys[a];
            // Bound on the size of the terms summed into each coefficient: what survives
            // below rounding level of that is cancellation noise, and keeping it would turn an
            // exactly zero remainder (a multiple root) into garbage.
            let mut size = r.map(f64::abs);
            for i in (lb - 1..la).rev() {
                let q = r[i] / s.polys[b][lb - 1];
                for j in 0..lb {
                    r[i + 1 - lb + j] -= q * s.polys[b][j];
                    size[i + 1 - lb + j] += (q * s.polys[b][j]).abs();
                }
                r[i] = 0.0;
            }
            let mut neg = [0.0; N];
            for j in 0..lb - 1 {
                neg[j] = if r[j].abs() <= 64.0 * f64::EPSILON * size[j] {
                    0.0
                } else {
                    -r[j]
                };
            }
            if !s.set(s.count, &neg[..lb - 1]) {
                break;
            }
            s.count += 1;
        }
        s
    }

    /// Stores a scaled copy; false when the polynomial is zero (the sequence ends).
    fn set(&mut self, k: usize, c: &[f64]) -> bool {
        let len = c.iter().rposition(|&x| x != 0.0).map_or(0, |i| i + 1);
        let scale = c[..len].iter().fold(0.0f64, |m, x| m.max(x.abs()));
        if len == 0 || scale == 0.0 || !scale.is_finite() {
            self.lens[k] = 0;
            return false;
        }
        for (dst, &src) in self.polys[k].iter_mut().zip(&c[..len]) {
            *dst = src / scale;
        }
        self.lens[k] = len;
        true
    }

    fn sign_changes(&self, x: f64) -> u32 {
        let mut changes = 0;
        let mut last = 0.0;
        for k in 0..self.count {
            let v = eval(&self.polys[k][..self.lens[k]], x);
            if v != 0.0 {
                if last != 0.0 && (v < 0.0) != (last < 0.0) {
                    changes += 1;
                }
                last = v;
            }
        }
        changes
    }
}

/// Real roots in `[lo, hi]`: those of [`roots_in`] plus roots of even multiplicity (exact
/// tangency), located with a Sturm sequence. Slower than [`roots_in`].
///
/// Sturm sequences alone are fragile in floating point (remainders of a member with a small
/// leading coefficient lose every digit and the counts go wrong), which shows as lost roots.
/// So the sign-change roots always come from [`roots_in`], and a root the Sturm search adds
/// is kept only where the polynomial is zero to within its rounding error.
pub fn sturm_roots_in(c: &[f64], lo: f64, hi: f64) -> Roots {
    let c = match trim(c) {
        Some(c) if c.len() >= 3 && lo <= hi => c,
        _ => return roots_in(c, lo, hi),
    };
    // No root at all, as `roots_in` finds: and the Sturm search could add one only at a
    // point where `numerically_zero` holds, i.e. where the polynomial is within
    // `8·len·2^-53·Σ|c_i||x|^i` of zero, while `surely_no_root`'s certificate puts it above
    // 1e-11 of that sum (over the interval's reach, which bounds |x|) everywhere in
    // `[lo, hi]`, where every point the search tries lies. So the sequence need not be built.
    if surely_no_root(c, lo, hi) {
        return Roots::new();
    }
    let mut base = Roots::new();
    isolate(c, lo, hi, &mut base, false);
    match c.len() {
        3..=5 => sturm_search::<5>(c, lo, hi, base),
        6..=9 => sturm_search::<9>(c, lo, hi, base),
        _ => sturm_search::<{ MAX_DEGREE + 1 }>(c, lo, hi, base),
    }
}

/// [`sturm_roots_in`]'s search for the roots `base` (from [`roots_in`]) lacks, with a
/// sequence sized for `c` (at most `N` coefficients).
fn sturm_search<const N: usize>(c: &[f64], lo: f64, hi: f64, base: Roots) -> Roots {
    let seq = Sturm::<N>::new(c);
    let (v_lo, v_hi) = (seq.sign_changes(lo), seq.sign_changes(hi));
    // The search's first step, before its stack is set up: nothing to add when the count over
    // the whole interval is no more than the roots already found (most rays).
    if v_lo <= v_hi || v_lo - v_hi <= base.iter().filter(|&&x| x > lo && x <= hi).count() as u32 {
        return base;
    }
    let mut extra = Roots::new();
    // Depth-first over (lo, hi, changes at lo, changes at hi, depth), left half first so
    // the candidates come out sorted; 64 levels of bisection exhaust f64 resolution.
    let mut stack = [(0.0, 0.0, 0u32, 0u32, 0u32); 2 * 64 + 2];
    stack[0] = (lo, hi, v_lo, v_hi, 0);
    let mut sp = 1;
    while sp > 0 {
        sp -= 1;
        let (a, b, va, vb, depth) = stack[sp];
        if va <= vb {
            continue;
        }
        let known = base.iter().filter(|&&x| x > a && x <= b).count() as u32;
        if va - vb <= known {
            continue;
        }
        let m = 0.5 * (a + b);
        if depth >= 64 || m <= a || m >= b {
            if numerically_zero(c, m) {
                extra.push(m);
            }
            continue;
        }
        let vm = seq.sign_changes(m);
        stack[sp] = (m, b, vm, vb, depth + 1);
        stack[sp + 1] = (a, m, va, vm, depth + 1);
        sp += 2;
    }
    if extra.is_empty() {
        return base;
    }
    let mut out = Roots::new();
    let (mut i, mut j) = (0, 0);
    while i < base.len() || j < extra.len() {
        if j == extra.len() || (i < base.len() && base[i] <= extra[j]) {
            out.push(base[i]);
            i += 1;
        } else {
            out.push(extra[j]);
            j += 1;
        }
    }
    out
}

/// Whether `c(x)` is zero to within the rounding error of evaluating it.
fn numerically_zero(c: &[f64], x: f64) -> bool {
    let size = c
        .iter()
        .rev()
        .fold(0.0, |acc, &ci| acc * x.abs() + ci.abs());
    eval(c, x).abs() <= 8.0 * c.len() as f64 * f64::EPSILON * size
}

#[cfg(test)]
mod tests;
