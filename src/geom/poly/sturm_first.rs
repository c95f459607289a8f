//! The nearest of [`sturm_roots_in`]'s roots without polishing those beyond it, for a
//! `sturm` shape's nearest crossing.
//!
//! [`sturm_roots_in`] takes every root [`roots_in`] finds and adds roots of even multiplicity
//! only when a Sturm count over the whole interval exceeds how many it found. That count
//! needs how many roots there are, not where: each sign-change piece holds exactly one, so
//! the pieces after the first kept root stay unpolished when the number of distinct values
//! they would give is certain. Where it is not, or where the Sturm search would run, the
//! answer comes from [`sturm_roots_in`] itself.

use super::{brackets, isolate, polish, sturm_roots_in, trim, Roots, Sturm, MAX_DEGREE};
use crate::geom::bernstein::surely_no_root;
use crate::geom::poly::eval;

/// The first of [`sturm_roots_in`]'s roots (increasing) for which `keep` holds, bit for bit.
pub fn sturm_first_root_in(
    c: &[f64],
    lo: f64,
    hi: f64,
    mut keep: impl FnMut(f64) -> bool,
) -> Option<f64> {
    let full = |keep: &mut dyn FnMut(f64) -> bool| {
        sturm_roots_in(c, lo, hi).iter().copied().find(|&x| keep(x))
    };
    let ct = match trim(c) {
        Some(ct) if ct.len() >= 4 && lo <= hi => ct,
        _ => return full(&mut keep),
    };
    // `sturm_roots_in` finds nothing then (see there).
    if surely_no_root(ct, lo, hi) {
        return None;
    }
    let n = ct.len() - 1;
    // `isolate`'s top level: the critical points, then the pieces as brackets (an exact zero
    // has equal ends), which `brackets` lists in `isolate`'s order.
    let mut d = [0.0; MAX_DEGREE];
    for i in 1..=n {
        d[i - 1] = ct[i] * i as f64;
    }
    let mut crit = Roots::new();
    isolate(&d[..n], lo, hi, &mut crit, true);
    let mut cands = [(0.0, 0.0, false); MAX_DEGREE + 2];
    let m = brackets(ct, crit.iter().copied(), lo, hi, &mut cands);
    if m > MAX_DEGREE {
        return full(&mut keep);
    }
    // The walk `Roots::push` makes (consecutive equal values kept once), polishing in order
    // until a root is kept; the pieces after it stay unpolished.
    let mut values = [None; MAX_DEGREE + 2];
    let (mut last, mut found) = (None, None);
    for k in 0..m {
        let (a, b, neg) = cands[k];
        let x = if a == b { a } else { polish(ct, a, b, neg) };
        values[k] = Some(x);
        if last == Some(x) {
            continue;
        }
        last = Some(x);
        if keep(x) {
            found = Some(x);
            break;
        }
    }
    match distinct_count(ct, lo, &cands[..m], &values[..m]) {
        Some(count) if sturm_adds_nothing(ct, lo, hi, count) => found,
        _ => full(&mut keep),
    }
}

/// [`sturm_roots_in`] for a caller that needs only the roots in `[wlo, whi]` (a clipped
/// `sturm` shape): as [`roots_in_window`](super::roots_in_window) gives [`roots_in`]'s,
/// roots outside may be left out and those inside come out bit for bit. A root is polished
/// only in a piece reaching into the window; the others are counted for the Sturm test.
pub fn sturm_roots_in_window(c: &[f64], lo: f64, hi: f64, wlo: f64, whi: f64) -> Roots {
    let ct = match trim(c) {
        Some(ct) if ct.len() >= 4 && lo <= hi => ct,
        _ => return sturm_roots_in(c, lo, hi),
    };
    if wlo.is_nan() || whi.is_nan() {
        return sturm_roots_in(c, lo, hi);
    }
    // No root inside the window, of either kind: `roots_in`'s (as in `roots_in_window`) or
    // the Sturm search's, which adds only points where the polynomial is within a few
    // rounding errors of zero (`numerically_zero`), far below `surely_no_root`'s margin over
    // the window. Neither the critical points nor the sequence are needed.
    let (wl, wh) = (lo.max(wlo), hi.min(whi));
    if wl > wh || surely_no_root(ct, wl, wh) {
        return Roots::new();
    }
    let n = ct.len() - 1;
    let mut d = [0.0; MAX_DEGREE];
    for i in 1..=n {
        d[i - 1] = ct[i] * i as f64;
    }
    let mut crit = Roots::new();
    isolate(&d[..n], lo, hi, &mut crit, true);
    let mut cands = [(0.0, 0.0, false); MAX_DEGREE + 2];
    let m = brackets(ct, crit.iter().copied(), lo, hi, &mut cands);
    if m > MAX_DEGREE {
        return sturm_roots_in(c, lo, hi);
    }
    let mut values = [None; MAX_DEGREE + 2];
    for k in 0..m {
        let (a, b, neg) = cands[k];
        if a == b {
            values[k] = Some(a);
        } else if b >= wlo && a <= whi {
            values[k] = Some(polish(ct, a, b, neg));
        }
    }
    let Some(count) = distinct_count(ct, lo, &cands[..m], &values[..m]) else {
        return sturm_roots_in(c, lo, hi);
    };
    if !sturm_adds_nothing(ct, lo, hi, count) {
        return sturm_roots_in(c, lo, hi);
    }
    let mut out = Roots::new();
    for x in values[..m].iter().flatten() {
        out.push(*x);
    }
    out
}

/// How many distinct values above `lo` the pieces give (`Roots::push`'s list as
/// `sturm_search` counts it), when that is certain: `values[k]` is piece `k`'s value when
/// known. An unknown value lies in its bracket; it repeats its neighbour's only when both
/// sit on their shared end, which `surely_not_on` rules out. `None` when unsure.
fn distinct_count(
    c: &[f64],
    lo: f64,
    cands: &[(f64, f64, bool)],
    values: &[Option<f64>],
) -> Option<usize> {
    let mut count = 0;
    for k in 0..cands.len() {
        let (a, b, _) = cands[k];
        let above = values[k].map_or(a > lo, |x| x > lo);
        if values[k].is_none() && !above {
            return None;
        }
        if k > 0 {
            let (pa, pb, _) = cands[k - 1];
            let distinct = match (values[k - 1], values[k]) {
                (Some(p), Some(x)) => {
                    if p == x {
                        // `Roots::push` keeps it once.
                        continue;
                    }
                    true
                }
                // An exact zero never equals a sign-change piece's root: the piece's ends
                // are nonzero and the zero lies at or beyond one of them.
                _ if (pa == pb) != (a == b) => true,
                (p, x) => {
                    let prev_hi = p.unwrap_or(pb);
                    let cur_lo = x.unwrap_or(a);
                    prev_hi < cur_lo || surely_not_on(c, a)
                }
            };
            if !distinct {
                return None;
            }
        }
        count += usize::from(above);
    }
    Some(count)
}

/// `sturm_search` returns its base unchanged: its count over the whole interval is no more
/// than the `count` roots already found.
fn sturm_adds_nothing(c: &[f64], lo: f64, hi: f64, count: usize) -> bool {
    let (v_lo, v_hi) = match c.len() {
        3..=5 => counts::<5>(c, lo, hi),
        6..=9 => counts::<9>(c, lo, hi),
        _ => counts::<{ MAX_DEGREE + 1 }>(c, lo, hi),
    };
    v_lo <= v_hi || v_lo - v_hi <= count as u32
}

/// `sturm_search`'s two counts over the whole interval.
fn counts<const N: usize>(c: &[f64], lo: f64, hi: f64) -> (u32, u32) {
    let seq = Sturm::<N>::new(c);
    (seq.sign_changes(lo), seq.sign_changes(hi))
}

/// Neither of the two sign-change pieces meeting at `p` polishes its root to `p` itself: the
/// polynomial has `p`'s sign at both neighbouring doubles. `polish` returns an end of its
/// bracket only by halving a bracket one double wide, and its bracket reaches the double
/// next to `p` only when the sign there is the other end's.
fn surely_not_on(c: &[f64], p: f64) -> bool {
    let s = eval(c, p);
    let below = eval(c, p.next_down());
    let above = eval(c, p.next_up());
    s != 0.0
        && below != 0.0
        && above != 0.0
        && (s < 0.0) == (below < 0.0)
        && (s < 0.0) == (above < 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::test_rng::{check_first_root, check_window, from_roots, Lcg};

    /// The first root kept is `sturm_roots_in`'s first root kept, bit for bit, and a window's
    /// roots are its roots inside the window (and maybe some outside, never others): random
    /// polynomials of degree 3 to 8 with clustered, double and far roots, thresholds
    /// anywhere.
    #[test]
    fn first_root_is_sturm_roots_ins_first() {
        let mut rng = Lcg(29);
        for case in 0..20_000 {
            let deg = 3 + case % 6;
            let mut roots: Vec<f64> = (0..deg).map(|_| rng.next() * 8.0 - 2.0).collect();
            if case % 3 == 0 {
                roots[1] = roots[0];
            }
            if case % 7 == 0 {
                roots[0] = roots[deg - 1] + 1e-9 * rng.next();
            }
            let mut c = from_roots(&roots);
            if case % 5 == 0 {
                c[0] += (rng.next() - 0.5) * if case % 2 == 0 { 1e-12 } else { 1.0 };
            }
            let (lo, hi) = (rng.next() - 0.5, 4.0 + 4.0 * rng.next());
            let all = sturm_roots_in(&c, lo, hi);
            let what = format!("{c:?}");
            let first = |cut: f64| sturm_first_root_in(&c, lo, hi, |x| x > cut);
            check_first_root(&mut rng, &all, (lo, hi), first, &what);
            let w0 = lo + (hi - lo) * rng.next();
            let (wlo, whi) = (w0, w0 + rng.next() * 3.0);
            let part = sturm_roots_in_window(&c, lo, hi, wlo, whi);
            check_window(&all, &part, (wlo, whi), &what);
        }
    }
}
