//! Windows along a ray outside which a CSG member cannot contain a point, so that the crossings
//! of the other members there are turned away without their inside tests, and a member none of
//! whose crossings could be kept is not intersected at all.
//!
//! `Object::inside` of a member without `inverse` is false for every point outside its world
//! bounds (its first test; `csg_keeps`'s face path asks the bounds first too). A crossing at `t`
//! is tested at `ray.at(t) = origin + dir * t`, and each coordinate of that rounded point is a
//! monotone function of `t` (a rounded product with a fixed factor, then a rounded sum with a
//! fixed term: both monotone). So once one point `ray.at(t₁)` is seen outside the bounds on an
//! axis along which the ray moves away from them, every `t ≥ t₁` is outside too, and likewise
//! below. The windows' ends are such points, checked with the very computation `csg_keeps` uses:
//! no error bound is needed, and an end that cannot be confirmed is left open (infinite). A
//! crossing outside a window is one that `csg_keeps` would turn away; leaving it out changes
//! neither which crossings are kept nor their order, so the answers are the same, bit for bit.
//!
//! Used by intersections (every member constrains the others) and differences (the first
//! member constrains the subtracted ones) without an index and with at most `MAX_WINDOWED`
//! members: shapes.inc's rounded boxes (the woods' tiles: a box cut by two cylinders), tiles,
//! bridge spans. A shadow ray leaving such a tile from its face meets the box's window ending
//! at its origin, and the cylinders are not asked at all.

use crate::math::{Aabb, DVec3, Ray, EPSILON};
use crate::scene::desc::CsgOp;
use crate::scene::object::Object;

/// Nodes with more members keep the plain search (polyhedra have their faces, big nodes an
/// index).
pub(super) const MAX_WINDOWED: usize = 8;

/// `(lo, hi)` such that `ray.at(t)` lies outside `b` for every `t ≤ lo` and every `t ≥ hi`
/// (each possibly infinite: nothing known on that side). Scalar code with plain comparisons:
/// a NaN anywhere only leaves an end unconfirmed.
#[inline]
pub(super) fn bounds_window(b: &Aabb, ray: &Ray, inv_dir: DVec3) -> (f64, f64) {
    // A few units in the last place of the coordinates involved: the slabs of the bounds grown
    // by this much put the rounded ends just outside (the check below decides).
    const PAD: f64 = 1.0 / (1u64 << 48) as f64;
    let (o, d, inv) = (
        ray.origin.to_array(),
        ray.dir.to_array(),
        inv_dir.to_array(),
    );
    let (lo_b, hi_b) = (b.min.to_array(), b.max.to_array());
    let (mut near, mut near_k) = (f64::NEG_INFINITY, 3);
    let (mut far, mut far_k) = (f64::INFINITY, 3);
    for k in 0..3 {
        let (l, h) = (lo_b[k].abs(), hi_b[k].abs());
        let pad = (o[k].abs() + if l > h { l } else { h }) * PAD;
        let ta = (lo_b[k] - pad - o[k]) * inv[k];
        let tb = (hi_b[k] + pad - o[k]) * inv[k];
        let (a, z) = if ta < tb { (ta, tb) } else { (tb, ta) };
        if a > near {
            (near, near_k) = (a, k);
        }
        if z < far {
            (far, far_k) = (z, k);
        }
    }
    // An end holds when at it the point (as `Ray::at` rounds it) is beyond the bounds on the
    // axis that gave it, on the side the ray moves away to: `ahead` for the far end.
    let beyond = |t: f64, k: usize, ahead: bool| {
        k < 3 && {
            let p = o[k] + d[k] * t;
            if d[k] > 0.0 {
                if ahead {
                    p > hi_b[k]
                } else {
                    p < lo_b[k]
                }
            } else if d[k] < 0.0 {
                if ahead {
                    p < lo_b[k]
                } else {
                    p > hi_b[k]
                }
            } else {
                false
            }
        }
    };
    let hi = if beyond(far, far_k, true) {
        far
    } else {
        f64::INFINITY
    };
    let lo = if beyond(near, near_k, false) {
        near
    } else {
        f64::NEG_INFINITY
    };
    (lo, hi)
}

/// For each member of a node, the window its crossings must fall in (strictly inside) to be
/// kept: for an intersection the meet of every other member's bounds window, for a subtracted
/// member of a difference the first member's.
pub(super) struct Windows {
    lo: [f64; MAX_WINDOWED],
    hi: [f64; MAX_WINDOWED],
}

/// The window that keeps everything.
pub(super) const OPEN: (f64, f64) = (f64::NEG_INFINITY, f64::INFINITY);

impl Windows {
    /// The windows of a node's members, or `None` when the node is not one that uses them.
    #[inline]
    pub(super) fn new(
        op: CsgOp,
        children: &[Object],
        ray: &Ray,
        inv_dir: DVec3,
    ) -> Option<Windows> {
        let n = children.len();
        if !matches!(op, CsgOp::Intersection | CsgOp::Difference) || n > MAX_WINDOWED || n < 2 {
            return None;
        }
        let own = |c: &Object| {
            if c.inverse {
                OPEN
            } else {
                bounds_window(&c.bounds, ray, inv_dir)
            }
        };
        let mut w = Windows {
            lo: [f64::NEG_INFINITY; MAX_WINDOWED],
            hi: [f64::INFINITY; MAX_WINDOWED],
        };
        match op {
            CsgOp::Intersection => {
                // The largest and second largest `lo` (smallest `hi`), so that each member gets
                // the meet of the others' in one pass.
                let (mut lo1, mut lo2, mut lo_at) = (f64::NEG_INFINITY, f64::NEG_INFINITY, n);
                let (mut hi1, mut hi2, mut hi_at) = (f64::INFINITY, f64::INFINITY, n);
                for (j, c) in children.iter().enumerate() {
                    let (lo, hi) = own(c);
                    if lo > lo1 {
                        (lo2, lo1, lo_at) = (lo1, lo, j);
                    } else if lo > lo2 {
                        lo2 = lo;
                    }
                    if hi < hi1 {
                        (hi2, hi1, hi_at) = (hi1, hi, j);
                    } else if hi < hi2 {
                        hi2 = hi;
                    }
                }
                for i in 0..n {
                    w.lo[i] = if i == lo_at { lo2 } else { lo1 };
                    w.hi[i] = if i == hi_at { hi2 } else { hi1 };
                }
            }
            CsgOp::Difference => {
                let (lo, hi) = own(&children[0]);
                w.lo[1..n].fill(lo);
                w.hi[1..n].fill(hi);
            }
            CsgOp::Union | CsgOp::Merge => return None,
        }
        Some(w)
    }

    /// Member `i`'s window.
    #[inline(always)]
    pub(super) fn get(&self, i: usize) -> (f64, f64) {
        (self.lo[i], self.hi[i])
    }
}

/// Whether no crossing a shape reports (t > EPSILON) below `tmax` can fall in window `w`.
#[inline(always)]
pub(super) fn shut(w: (f64, f64), tmax: f64) -> bool {
    w.1 <= EPSILON || w.0 >= tmax
}

/// Whether `t` lies strictly inside window `w`.
#[inline(always)]
pub(super) fn within(w: (f64, f64), t: f64) -> bool {
    w.0 < t && t < w.1
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::test_rng::Lcg;

    /// Every `t` at or beyond a window's ends puts the rounded point outside the box: rays
    /// from inside, outside and on the faces, along axes and at random, boxes from 1e-6 to
    /// 1e6 and far from the origin, and the ends themselves and a few ulps either side.
    #[test]
    fn points_beyond_the_ends_are_outside() {
        let mut rng = Lcg(17);
        let (mut ends, mut checked) = (0, 0);
        for k in 0..200_000 {
            let scale = [1e-6, 1e-2, 1.0, 1e3, 1e6][k % 5];
            let centre = rng.vec(1.0) * [0.0, 1.0, 1e4][k % 3] * scale;
            let half = (rng.vec(1.0).abs() + DVec3::splat(0.01)) * scale;
            let b = Aabb::new(centre - half, centre + half);
            let mut o = centre + rng.vec(3.0) * scale;
            if k % 4 == 0 {
                // On a face.
                o[k % 3] = if k % 8 == 0 {
                    b.min[k % 3]
                } else {
                    b.max[k % 3]
                };
            }
            let mut d = rng.vec(1.0);
            if k % 7 == 0 {
                d = [DVec3::X, DVec3::NEG_Y, DVec3::Z][k % 3];
            }
            let ray = Ray::new(o, d * [1.0, 1e-3, 1e3][k % 3]);
            let (lo, hi) = bounds_window(&b, &ray, ray.dir.recip());
            for (end, sign) in [(lo, -1.0), (hi, 1.0)] {
                if !end.is_finite() {
                    continue;
                }
                ends += 1;
                let mut t = end;
                for step in 0..40 {
                    assert!(!b.contains(ray.at(t)), "ray {k}: t {t} (end {end})");
                    checked += 1;
                    t = if step < 8 {
                        if sign > 0.0 {
                            t.next_up()
                        } else {
                            t.next_down()
                        }
                    } else {
                        t + sign * (end.abs() + scale) * rng.next() * 0.1
                    };
                }
            }
        }
        assert!(ends > 200_000 && checked > 8_000_000, "{ends} {checked}");
    }
}
