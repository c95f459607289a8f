//! The pyramid walk for rays that run along no axis: the same blocks tested in the same order
//! with the same `tmax` as `HeightField::visit`, with less work per block.
//!
//! With every direction component nonzero (and every `1 / d` finite) the sign of each
//! component is known for the whole walk, so which face of a block the ray enters by is known
//! too: `(f - o) · inv` is monotone in `f` (a difference and a product, each correctly
//! rounded), so of a block's two face distances along an axis the smaller is the near face's
//! when `inv > 0` and the far face's when `inv < 0`. `visit` finds the same numbers with
//! `min` and `max`; here they are picked by index, and the x and z faces of the four children
//! (three distances per axis) are found once.

use super::{fmax, fmin, GridRay, HeightField};

/// What the walk keeps of a ray besides `GridRay`: the entry face along each axis.
pub(super) struct Signs {
    /// 1 when the ray runs towards smaller x (z): a child's entry distance along x (z) is then
    /// that of its far face, index `k + 1` of the three face distances.
    sx: usize,
    sz: usize,
    /// Whether the ray rises: it then enters a block's height range through its low face.
    up: bool,
}

impl Signs {
    /// The signs of a ray, or None when it runs along an axis (or a `1 / d` is not finite):
    /// `visit` handles those.
    pub(super) fn new(r: &GridRay) -> Option<Signs> {
        let ok = |d: f64, inv: f64| d != 0.0 && inv.is_finite();
        (ok(r.d.x, r.inv.x) && ok(r.d.y, r.inv.y) && ok(r.d.z, r.inv.z)).then_some(Signs {
            sx: (r.inv.x < 0.0) as usize,
            sz: (r.inv.z < 0.0) as usize,
            up: r.inv.y > 0.0,
        })
    }
}

/// A child block that passed its test: its entry along x and z (from 0: the sort key) and its
/// exit along them (without `tmax`), and its place in the level below.
#[derive(Clone, Copy, Default)]
struct Kid {
    key: f64,
    exit: f64,
    i: usize,
    j: usize,
    /// The entry and exit of its test, bounds for its children's (see `visit_signed`).
    t: (f64, f64),
}

/// The right side of the walk's slab test (`slack_ok::<true>`): a block whose entry is above
/// this function of its exit is missed. Monotone in the exit: each operation is, and below
/// -1 the sum still grows (the step in `t` outweighs the one in `1e-9 |t|`).
#[inline(always)]
fn slack(t1: f64) -> f64 {
    t1 + 1e-9 * fmax::<true>(t1.abs(), 1.0)
}

impl HeightField {
    /// `reaches::<true>` for a ray with `Signs`: the block's heights give its entry and exit
    /// along y by the sign of `d.y` rather than by `min` and `max` (the same values). Also
    /// gives the test's entry `t0` and exit `t1`, which bound those of every block inside
    /// this one (see `visit_signed`).
    #[inline(always)]
    fn reaches_signed(
        &self,
        r: &GridRay,
        s: &Signs,
        range: [f32; 2],
        k: &Kid,
    ) -> Option<(f64, f64)> {
        let [ylo, yhi] = range.map(f64::from);
        if yhi < self.data.water_level {
            return None;
        }
        let (u, v) = ((ylo - r.o.y) * r.inv.y, (yhi - r.o.y) * r.inv.y);
        let (ye, yx) = if s.up { (u, v) } else { (v, u) };
        let t0 = if ye > k.key { ye } else { k.key };
        let t1 = fmin::<true>(fmin::<true>(r.tmax, k.exit), yx);
        (t0 <= slack(t1)).then_some((t0, t1))
    }

    /// `visit::<true>` for a ray with `Signs` (see the module's comment for why the answers
    /// are the same). The caller has found that the ray reaches block (bi, bj) of `level`,
    /// with the entry and exit `t` (`lo`, `hi`) of that test, taken with the current `tmax`
    /// or a larger one; `ux` and `uz` are the distances to the block's near and far faces
    /// along x and z (by index, not by the ray's direction), which are its outer children's
    /// faces too.
    ///
    /// A child's entry is at least `lo` and its exit at most `hi` (its faces lie within the
    /// block's, `(f - o) · inv` is monotone in `f`, its height range lies within the block's,
    /// and `tmax` only shrinks), and at least the middle face's distance `m` for the children
    /// beyond that face, at most `m` for those before it. As `slack` is monotone, a side
    /// with `m > slack(hi)` (beyond) or `lo > slack(m)` (before) holds no child that passes
    /// its test: it is left out untested, which leaves the same children, in the same order.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn visit_signed(
        &self,
        r: &mut GridRay,
        s: &Signs,
        level: usize,
        (bi, bj): (usize, usize),
        (lo, hi): (f64, f64),
        ux: [f64; 2],
        uz: [f64; 2],
    ) {
        let below = &self.levels[level - 1];
        let (cx, cz) = self.cells();
        let sh = level - 1;
        // The middle faces as `visit` finds them: whole numbers, exact either way, clamped
        // to the grid. (A child that exists starts below the grid's edge, so its near face
        // needs no clamp: the outer faces are the block's own, `ux` and `uz`.)
        let mx = fmin::<true>(((bi * 2 + 1) << sh) as i64 as f64, cx);
        let mz = fmin::<true>(((bj * 2 + 1) << sh) as i64 as f64, cz);
        let ux = [ux[0], (mx - r.o.x) * r.inv.x, ux[1]];
        let uz = [uz[0], (mz - r.o.z) * r.inv.z, uz[1]];
        // Which sides of the middle faces may hold a child that passes: bit `di` of `sx_ok`
        // for the children at `bi * 2 + di` (the near one is `di == s.sx`).
        let shi = slack(hi);
        // Negated comparisons: a NaN (from `slack` of an infinite distance) must leave the
        // side in.
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        let side = |m: f64, near: usize| -> u32 {
            let far_ok = !(m > shi) as u32;
            let near_ok = !(lo > slack(m)) as u32;
            (near_ok << near) | (far_ok << (1 - near))
        };
        let (okx, okz) = (side(ux[1], s.sx), side(uz[1], s.sz));
        let mut kids = [Kid::default(); 4];
        let mut n = 0;
        for (di, dj) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
            let (ci, cj) = (bi * 2 + di, bj * 2 + dj);
            if ci < below.nx && cj < below.nz && (okx >> di) & (okz >> dj) & 1 != 0 {
                let (xe, xx) = (ux[di + s.sx], ux[di + 1 - s.sx]);
                let (ze, zx) = (uz[dj + s.sz], uz[dj + 1 - s.sz]);
                // `0.0f64.max(xe).max(ze)` of `visit`, whose sort key it is; comparisons give
                // +0 for a -0 entry, as `f64::max` with a constant 0 does on x86.
                let k = if xe > 0.0 { xe } else { 0.0 };
                let mut kid = Kid {
                    key: if ze > k { ze } else { k },
                    exit: fmin::<true>(xx, zx),
                    i: ci,
                    j: cj,
                    t: (0.0, 0.0),
                };
                if let Some(t) = self.reaches_signed(r, s, below.range[cj * below.nx + ci], &kid) {
                    kid.t = t;
                    kids[n] = kid;
                    n += 1;
                }
            }
        }
        let kids = &mut kids[..n];
        if r.first {
            // Stable, as `visit`'s: the keys are never NaN nor -0, so `>` orders them as
            // `total_cmp` does.
            for i in 1..kids.len() {
                let mut j = i;
                while j > 0 && kids[j - 1].key > kids[j].key {
                    kids.swap(j - 1, j);
                    j -= 1;
                }
            }
        }
        let tmax = r.tmax;
        for kid in kids.iter() {
            if r.first && kid.key > r.tmax {
                break;
            }
            let t = if r.tmax == tmax {
                Some(kid.t)
            } else {
                self.reaches_signed(r, s, below.range[kid.j * below.nx + kid.i], kid)
            };
            if let Some(t) = t {
                if level == 1 {
                    self.cell_hits(r, kid.i, kid.j);
                } else {
                    let (di, dj) = (kid.i & 1, kid.j & 1);
                    let (kx, kz) = ([ux[di], ux[di + 1]], [uz[dj], uz[dj + 1]]);
                    self.visit_signed(r, s, level - 1, (kid.i, kid.j), t, kx, kz);
                }
            }
        }
    }

    /// `visit_signed` from the root block of a pyramid of more than one level, if the ray
    /// reaches that block.
    pub(super) fn walk_signed(&self, r: &mut GridRay, s: &Signs) {
        let top = self.levels.len() - 1;
        let (cx, cz) = self.cells();
        // The root's faces as `visit` finds them for its children.
        let far = |c: f64| fmin::<true>(((2usize) << (top - 1)) as i64 as f64, c);
        let ux = [(0.0 - r.o.x) * r.inv.x, (far(cx) - r.o.x) * r.inv.x];
        let uz = [(0.0 - r.o.z) * r.inv.z, (far(cz) - r.o.z) * r.inv.z];
        // The root's test as `trace` makes it for `visit` (with the same numbers but for
        // the sign of a zero): the first bounds.
        let root = Kid {
            key: fmax::<true>(
                fmax::<true>(0.0, fmin::<true>(ux[0], ux[1])),
                fmin::<true>(uz[0], uz[1]),
            ),
            exit: fmin::<true>(fmax::<true>(ux[0], ux[1]), fmax::<true>(uz[0], uz[1])),
            ..Kid::default()
        };
        let Some(t) = self.reaches_signed(r, s, self.levels[top].range[0], &root) else {
            return;
        };
        self.visit_signed(r, s, top, (0, 0), t, ux, uz);
    }
}

#[cfg(test)]
mod tests {
    use super::super::HeightData;
    use super::*;
    use crate::geom::Hit;
    use crate::math::{DVec3, Ray};
    use std::sync::Arc;

    /// The hits as bits: the walks must agree on every crossing exactly, in order.
    fn bits(hits: &[Hit]) -> Vec<(u64, u32, u64, u64)> {
        let b = |h: &Hit| (h.t.to_bits(), h.part, h.uv[0].to_bits(), h.uv[1].to_bits());
        hits.iter().map(b).collect()
    }

    /// `visit_signed` against `visit` on rays of every slope, from origins anywhere and on
    /// the grid's faces (whole grid coordinates, where entries are zero), with and without a
    /// `tmax`, over grids whose sides are not powers of two (clamped faces, missing
    /// children), with water and with flat stretches (equal heights: edge ties).
    #[test]
    fn signed_walk_finds_what_visit_finds() {
        let mut rng = crate::geom::test_rng::Lcg(11);
        let mut rnd = move || rng.next();
        let mut checked = 0;
        for (w, h, water) in [(2, 3, 0.0), (5, 4, 0.0), (37, 23, 0.3), (64, 65, 0.0)] {
            let mut heights = Vec::new();
            for j in 0..h {
                for i in 0..w {
                    let v = 0.5 + 0.4 * ((i as f64 * 0.7).sin() * (j as f64 * 0.45).cos());
                    // Flat steps: neighbouring vertices share heights.
                    heights.push(((v * 8.0).floor() / 8.0 * 65535.0) as u16);
                }
            }
            let mut data = HeightData::new(w, h, heights);
            data.water_level = water;
            let hf = HeightField::new(Arc::new(data));
            let (cx, cz) = ((w - 1) as f64, (h - 1) as f64);
            for k in 0..4000 {
                let mut o = DVec3::new(rnd() * 1.6 - 0.3, rnd() * 2.0 - 0.2, rnd() * 1.6 - 0.3);
                if k % 3 == 0 {
                    // On grid faces.
                    o.x = (rnd() * (cx + 1.0)).floor() / cx;
                    o.z = (rnd() * (cz + 1.0)).floor() / cz;
                }
                let target = DVec3::new(rnd(), rnd(), rnd());
                let ray = Ray::new(o, target - o);
                let tmax = if k % 2 == 0 {
                    f64::INFINITY
                } else {
                    rnd() * 2.0
                };
                for first in [true, false] {
                    let (mut a, mut b) = (vec![], vec![]);
                    hf.trace_by(&ray, tmax, first, &mut a, true);
                    hf.trace_by(&ray, tmax, first, &mut b, false);
                    assert_eq!(bits(&a), bits(&b), "{ray:?} {tmax} {first}");
                    checked += a.len();
                }
            }
        }
        assert!(checked > 1000, "{checked}");
    }
}
