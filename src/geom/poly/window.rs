//! [`roots_in`]'s roots inside a window (a clipped shape's crossings inside its clipping box,
//! a CSG member's inside its partner's box), the others possibly left out, those inside bit
//! for bit.
//!
//! `roots_in` cuts `[lo, hi]` at the critical points and polishes one root in each piece whose
//! ends differ in sign; the last piece usually reaches Cauchy's bound, and its polish (and its
//! start's, the largest critical point, whose own bracket reaches the bound too) takes most
//! of the steps. Here a piece is polished only when it reaches into the window, and the piece
//! straddling an edge of the window only when a sign at that edge cannot put its root outside:
//! the critical point beyond the edge, which would only bound such a piece, then stays
//! unpolished too.

use super::{brackets, eval, isolate, polish, trim, Roots, MAX_DEGREE};
use crate::geom::bernstein::surely_no_root;

/// [`roots_in`](super::roots_in) for a caller that needs only the roots in `[wlo, whi]`:
/// roots outside may be left out, and those inside come out bit for bit as `roots_in` gives
/// them. A root is polished only in a piece reaching into the window (a critical point only
/// when it bounds such a piece, so each piece reaching in has the same ends as in `roots_in`),
/// and not even then when [`sure_sign`] at a point just beyond the window's edge shows that
/// the piece's root lies beyond it (see `edge_rules_out` for why that holds for the polished
/// root too).
pub fn roots_in_window(c: &[f64], lo: f64, hi: f64, wlo: f64, whi: f64) -> Roots {
    let mut out = Roots::new();
    let Some(c) = trim(c) else {
        return out;
    };
    let n = c.len().saturating_sub(1);
    if lo > hi {
        return out;
    }
    if n <= 2 || wlo.is_nan() || whi.is_nan() {
        isolate(c, lo, hi, &mut out, false);
        return out;
    }
    // No root inside the window. Without a change of sign in the window `roots_in` may
    // still polish a root from a bracket reaching into it, but only where the polynomial is
    // within a few rounding errors of zero (a Newton step of a few ulps, or a collapsed
    // bracket next to a negative end), and `surely_no_root` asks for values far above that.
    let (wl, wh) = (lo.max(wlo), hi.min(whi));
    if wl > wh || surely_no_root(c, wl, wh) {
        return out;
    }
    let mut d = [0.0; MAX_DEGREE];
    for i in 1..=n {
        d[i - 1] = c[i] * i as f64;
    }
    let d = &d[..n];
    let mut pts = [(0.0, 0.0, false); MAX_DEGREE + 2];
    let np = critical_brackets(d, lo, hi, wlo, whi, &mut pts);
    let value = |p: (f64, f64, bool)| {
        if p.0 == p.1 {
            p.0
        } else {
            polish(d, p.0, p.1, p.2)
        }
    };
    // Just beyond the window's edges: far above `polish`'s tolerance (a few ulps), so a root
    // shown to lie beyond them is polished beyond the edge itself.
    let (wlo_out, whi_out) = (
        wlo - 1e-9 * (wlo.abs() + 1.0),
        whi + 1e-9 * (whi.abs() + 1.0),
    );
    // `isolate`'s loop over the pieces `[a, b]`, `a` known (polished) or still a bracket
    // (`None`: it lies below the window, and is polished only if its piece needs it).
    let mut a_val = Some(lo);
    let mut a_br = (lo, lo, false);
    let mut ended = false;
    for b_br in pts[..np]
        .iter()
        .copied()
        .chain(std::iter::once((hi, hi, false)))
    {
        // Wholly below the window (`b` is at most its bracket's end).
        if b_br.1 < wlo {
            a_val = None;
            a_br = b_br;
            continue;
        }
        // Wholly above, and so are the pieces after it.
        if a_br.0 > whi {
            ended = true;
            break;
        }
        let mut b_val = None;
        let a = match a_val {
            Some(a) => a,
            None => {
                if b_br.0 <= whi {
                    let b = value(b_br);
                    let fb = eval(c, b);
                    b_val = Some(b);
                    // The piece's root, if any, lies below the window: `a` stays unpolished.
                    if fb != 0.0
                        && a_br.0 > 0.0
                        && wlo_out > a_br.1
                        && wlo_out < b
                        && sure_sign(c, wlo_out, b) == Some(fb < 0.0)
                    {
                        a_val = Some(b);
                        a_br = b_br;
                        continue;
                    }
                }
                value(a_br)
            }
        };
        let fa = eval(c, a);
        // The piece's root, if any, lies above the window: `b` stays unpolished, and every
        // later piece lies above too.
        if fa != 0.0
            && a > 0.0
            && whi_out > a
            && b_br.0 > whi_out
            && sure_sign(c, whi_out, whi_out) == Some(fa < 0.0)
        {
            ended = true;
            break;
        }
        let b = b_val.unwrap_or_else(|| value(b_br));
        let fb = eval(c, b);
        if fa == 0.0 {
            out.push(a);
        } else if (fa < 0.0) != (fb < 0.0) && fb != 0.0 && b >= wlo && a <= whi {
            out.push(polish(c, a, b, fa < 0.0));
        }
        a_val = Some(b);
        a_br = b_br;
    }
    // `isolate`'s exact zero at `hi` (the walk ended there).
    if !ended && a_val == Some(hi) && eval(c, hi) == 0.0 {
        out.push(hi);
    }
    out
}

/// The sign of `c` at `w` (whether negative) when it is certain by a wide margin: the value
/// exceeds `1e-9` times `Σ |c_i| r^i` with `r = max(|w|, |reach|)`.
///
/// Why that is enough to leave a piece's root out (`edge_rules_out`): say the piece is
/// `[a, b]`, `0 < a < w < b`, with `c(a)` computed of that sign and `w` beyond the window's
/// upper edge (`reach = w`). The polynomial is monotone on the piece (its ends are polished
/// critical points, off the true ones by ulps where the polynomial is flat), so if its root lies in
/// `[w, b]`, `|c|` falls from `a` to `w` and every `x` in `[a, w]` has `|c(x)| >= |c(w)|`,
/// which is far above the rounding of a Horner evaluation there (~1e-15 of the same sum, no
/// larger at `|x| <= r`): `polish` computes that sign at every step it takes in `[a, w]` and
/// so never moves its upper end below `w`. Its Newton steps there are not below its
/// tolerance either (`|c'(x)|·x <= n·Σ|c_i|x^i`, so the step is at least `1e-9·x/n`, while
/// the tolerance is a few ulps of `x`). So its answer is at least `w` less a few ulps, which
/// is beyond the window (`w` is 1e-9 beyond it). If the root lies below `w` instead (only
/// when `c(a)` was computed with the wrong sign), then `c(b)` has the sign of `c(w)` with
/// `|c(b)| >= |c(w)|`, so `b` is computed with that sign as well and `roots_in` finds no
/// change of sign in the piece at all. The lower edge is the mirror image, with `reach = b`
/// (the steps taken in `[w, b]`).
fn sure_sign(c: &[f64], w: f64, reach: f64) -> Option<bool> {
    let r = w.abs().max(reach.abs());
    let size = c.iter().rev().fold(0.0, |acc, &ci| acc * r + ci.abs());
    let v = eval(c, w);
    (size.is_finite() && v.abs() > 1e-9 * size).then_some(v < 0.0)
}

/// The critical points of the polynomial whose derivative is `d`, as brackets `(a, b, sign of
/// d at a)` still to polish (an exact point has `a == b`), written into `out` in increasing
/// order; returns how many. They are `isolate(d, lo, hi, _, true)`'s, less those that bound
/// only pieces lying wholly outside `[wlo, whi]`: a point is left out when the next one's
/// bracket ends below `wlo` or the previous one's starts above `whi`. The nearest point below
/// the window and the nearest above are always kept, so the pieces reaching into the window
/// are bounded as without a window. Polishing each gives `isolate`'s value bit for bit; where
/// two give equal values `isolate` keeps one, and the piece between them, `[x, x]`, changes
/// nothing `roots_in` reports (no change of sign, and `Roots::push` merges a repeated zero).
fn critical_brackets(
    d: &[f64],
    lo: f64,
    hi: f64,
    wlo: f64,
    whi: f64,
    out: &mut [(f64, f64, bool); MAX_DEGREE + 2],
) -> usize {
    let n = d.len().saturating_sub(1);
    let mut cands = [(0.0, 0.0, false); MAX_DEGREE + 2];
    let m = if n <= 2 {
        let mut crit = Roots::new();
        isolate(d, lo, hi, &mut crit, true);
        for (k, &x) in crit.iter().enumerate() {
            cands[k] = (x, x, false);
        }
        crit.len()
    } else {
        let mut dd = [0.0; MAX_DEGREE];
        for i in 1..=n {
            dd[i - 1] = d[i] * i as f64;
        }
        let mut crit = Roots::new();
        isolate(&dd[..n], lo, hi, &mut crit, true);
        brackets(d, crit.iter().copied(), lo, hi, &mut cands)
    };
    let mut np = 0;
    for k in 0..m {
        if (k + 1 < m && cands[k + 1].1 < wlo) || (k > 0 && cands[k - 1].0 > whi) {
            continue;
        }
        out[np] = cands[k];
        np += 1;
    }
    np
}
