//! The first crossing along the cells the ray crosses, one after another (a 2D DDA over the
//! grid's columns and rows), for rays with `Signs` when only the first crossing is wanted:
//! the same cells tested in the same order with the same `tmax` as the pyramid walk
//! (`walk_signed`), with fewer block tests. The walk steps through blocks of `BLOCK` levels
//! (8×8 cells) along the ray and through the cells of the blocks whose test passes.
//!
//! Why the answers are the same. A cell's test (`reaches_signed` on its own range, its entry
//! `key` from 0 and its exit along x and z, each a face distance `(f - o) · inv`) passes only
//! if its ancestors' tests pass: their faces lie outside the cell's, the distances are
//! monotone in the face, and their ranges hold the cell's. So the pyramid tests a cell iff
//! its key is within `tmax` (the sorted siblings' `break`) and its own test passes with the
//! `tmax` of its turn, and a block that fails its test holds no such cell. The order: siblings
//! sorted by key, blocks before their children, so two cells come in the order of their
//! ancestors' keys where the ancestors part. When each of two consecutive cells along the ray
//! spans more than the slack of the slab test, their ancestors where they part lie on either
//! side of the face between them and come in the ray's order. The walk keeps to those rays:
//! it gives up (and the pyramid walks the ray anew) when an x face and a z face are crossed
//! within `NEAR` of each other, or it starts within `NEAR` of a face, where a cell the ray only
//! grazes could pass by the slack, or two cells share a key. A cell two steps off the ray's
//! path cannot pass: the setup asks that a cell's width along the ray exceed the slack many
//! times. Cells before the ray reaches the field's highest (rising: lowest) height fail too,
//! so the walk starts there.

use super::walk::{slack, Signs};
use super::{fmax, fmin, GridRay, HeightField};

/// Relative distance within which an x and a z face crossing count as one corner: 100 times
/// the slab test's slack (`slack`: 1e-9 of the distance, at least 1e-9).
const NEAR: f64 = 1e-7;

/// The pyramid level whose blocks the walk steps through (capped by the pyramid's height).
const BLOCK: usize = 3;

/// The ray along x or z in grid units.
#[derive(Clone, Copy)]
struct Axis {
    o: f64,
    d: f64,
    inv: f64,
    /// Whether the ray runs towards larger coordinates.
    fwd: bool,
    /// Cells along the axis.
    n: usize,
}

impl Axis {
    /// The distance to face `b`, as `visit_body` finds it.
    #[inline(always)]
    fn face(&self, b: usize) -> f64 {
        // Through i64: one conversion instruction (a face index is far below 2^53, so the
        // same value as `b as f64`, whose unsigned conversion takes five).
        (b as i64 as f64 - self.o) * self.inv
    }

    /// The exit distance of cell `k` (`span(k, 0).1`: `k + 1` is within the grid).
    #[inline(always)]
    fn cell_exit(&self, k: usize) -> f64 {
        self.face(if self.fwd { k + 1 } else { k })
    }

    /// The entry and exit distances of span `k` of cells `2^l` wide (clamped to the grid).
    #[inline(always)]
    fn span(&self, k: usize, l: usize) -> (f64, f64) {
        let (a, b) = (k << l, ((k + 1) << l).min(self.n));
        if self.fwd {
            (self.face(a), self.face(b))
        } else {
            (self.face(b), self.face(a))
        }
    }

    /// The exit distance of span `k` of cells `2^l` wide (`span(k, l).1`).
    #[inline(always)]
    fn exit(&self, k: usize, l: usize) -> f64 {
        self.face(if self.fwd {
            ((k + 1) << l).min(self.n)
        } else {
            k << l
        })
    }

    /// The span after `k` along the ray among `n`, if any.
    #[inline(always)]
    fn next(&self, k: usize, n: usize) -> Option<usize> {
        if self.fwd {
            (k + 1 < n).then_some(k + 1)
        } else {
            k.checked_sub(1)
        }
    }

    /// The span before `k` along the ray among `n`, if any.
    #[inline(always)]
    fn back(&self, k: usize, n: usize) -> Option<usize> {
        if self.fwd {
            k.checked_sub(1)
        } else {
            (k + 1 < n).then_some(k + 1)
        }
    }

    /// The span of `2^l` cells (of `n`) the ray is in at `t`: entered at or before `t`, left
    /// after it (found by position, then set right by the distances), or None beyond the grid.
    /// Inlined: `l` is then a constant (the guess's scale by 1 folds away).
    #[inline(always)]
    fn locate(&self, t: f64, l: usize, n: usize) -> Option<usize> {
        // Only the first guess: the loops below make the answer exact from any.
        let p = ((self.o + t * self.d) * (1.0 / (1usize << l) as f64)).floor();
        let mut k = (p.max(0.0) as usize).min(n - 1);
        while self.span(k, l).1 <= t {
            k = self.next(k, n)?;
        }
        while self.span(k, l).0 > t {
            k = self.back(k, n)?;
        }
        Some(k)
    }

    /// Whether span `k` (of `n`, `2^l` cells) has a face crossed within `near` of `t`: at its
    /// entry if `entry` (a span behind it could pass by the slack), at its exit always.
    #[inline(always)]
    fn close(&self, t: f64, k: usize, l: usize, n: usize, near: f64, entry: bool) -> bool {
        let (e, x) = self.span(k, l);
        (entry && self.back(k, n).is_some() && t - e <= near) || x - t <= near
    }
}

impl HeightField {
    /// Walks a `first` ray with `Signs` along its cells, unless it passes within `NEAR` of a
    /// corner or starts within `NEAR` of a face; then it leaves `r` as it found it and returns
    /// false, for `walk_signed`.
    pub(super) fn walk_cells(&self, r: &mut GridRay, s: &Signs) -> bool {
        let top = self.levels.len() - 1;
        let lb = BLOCK.min(top);
        let (l0, lv) = (&self.levels[0], &self.levels[lb]);
        let ax = Axis {
            o: r.o.x,
            d: r.d.x,
            inv: r.inv.x,
            fwd: s.sx == 0,
            n: l0.nx,
        };
        let az = Axis {
            o: r.o.z,
            d: r.d.z,
            inv: r.inv.z,
            fwd: s.sz == 0,
            n: l0.nz,
        };
        // The root's test as `walk_signed` makes it.
        let ((xe, xx), (ze, zx)) = (ax.span(0, top), az.span(0, top));
        let t_in = fmax::<true>(fmax::<true>(0.0, xe), ze);
        let t_out = fmin::<true>(xx, zx);
        let root = self.levels[top].range(0, 0);
        if !self.reaches_signed(r, s, root, t_in, t_out) {
            return true;
        }
        let near = |t: f64| NEAR * fmax::<true>(t.abs(), 1.0);
        // A cell's crossing along x lasts |inv.x| (z alike): many times `near` over the walk,
        // so only the cells beside a corner could pass by the slack.
        if near(t_out) >= 0.25 * fmin::<true>(r.inv.x.abs(), r.inv.z.abs()) {
            return false;
        }
        // The ray meets the field's heights from `ye` (no cell's test passes before: its own
        // entry along y is no nearer) to `ystop` (no cell's test passes after).
        let [lo, hi] = root.map(f64::from);
        let (ye, yx) = if s.up { (lo, hi) } else { (hi, lo) };
        let (ye, ystop) = ((ye - r.o.y) * r.inv.y, slack((yx - r.o.y) * r.inv.y));
        let t0 = if ye > t_in { ye } else { t_in };
        if t0 > slack(t_out) {
            return true;
        }
        let (nbx, nbz) = (lv.nx, lv.nz);
        let (Some(mut bi), Some(mut bj)) = (ax.locate(t0, lb, nbx), az.locate(t0, lb, nbz)) else {
            return false;
        };
        let n0 = near(t0);
        if ax.close(t0, bi, lb, nbx, n0, true) || az.close(t0, bj, lb, nbz, n0, true) {
            return false;
        }
        let tmax0 = r.tmax;
        // The axis the walk entered the current block by (none for the first).
        let mut by: Option<bool> = None;
        let ((mut bxe, mut bxx), (mut bze, mut bzx)) = (ax.span(bi, lb), az.span(bj, lb));
        loop {
            // `visit_body`'s key and exit of the block.
            let k = if bxe > 0.0 { bxe } else { 0.0 };
            let bkey = if bze > k { bze } else { k };
            if bkey > r.tmax || bkey > ystop {
                return true;
            }
            let bexit = fmin::<true>(bxx, bzx);
            if self.reaches_signed(r, s, lv.range(bi, bj), bkey, bexit) {
                let entry = (by, if by == Some(true) { bxe } else { bze });
                match self.block_cells(r, s, (ax, az), (bi, bj), lb, entry, t0, ystop) {
                    Some(true) => return true,
                    Some(false) => {}
                    None => {
                        r.out.truncate(r.from);
                        r.tmax = tmax0;
                        return false;
                    }
                }
            }
            if bexit > r.tmax || bexit > ystop {
                return true;
            }
            if (bxx - bzx).abs() <= near(bexit) {
                r.out.truncate(r.from);
                r.tmax = tmax0;
                return false;
            }
            if bxx < bzx {
                let Some(k) = ax.next(bi, nbx) else {
                    return true;
                };
                (bi, by) = (k, Some(true));
                // The block's entry face is the exit face of the one before (`k` is within
                // the grid, so the clamp left that face alone): the same value.
                (bxe, bxx) = (bxx, ax.exit(bi, lb));
            } else {
                let Some(k) = az.next(bj, nbz) else {
                    return true;
                };
                (bj, by) = (k, Some(false));
                (bze, bzx) = (bzx, az.exit(bj, lb));
            }
        }
    }

    /// The cells of block (bi, bj) at level `lb` along the ray, from its entry (by x if `by`
    /// is `Some(true)`, by z if `Some(false)`, at distance `entry`, the block's face) or from
    /// `t0` in the walk's first block: Some(true) when the walk is over, Some(false) when the
    /// ray left the block, None when it gave up.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn block_cells(
        &self,
        r: &mut GridRay,
        s: &Signs,
        (ax, az): (Axis, Axis),
        (bi, bj): (usize, usize),
        lb: usize,
        (by, entry): (Option<bool>, f64),
        t0: f64,
        ystop: f64,
    ) -> Option<bool> {
        let l0 = &self.levels[0];
        let (nx, nz) = (l0.nx, l0.nz);
        let near = |t: f64| NEAR * fmax::<true>(t.abs(), 1.0);
        // The block's cells.
        let (ia, ib) = (bi << lb, ((bi + 1) << lb).min(nx));
        let (ja, jb) = (bj << lb, ((bj + 1) << lb).min(nz));
        let (mut i, mut j) = match by {
            None => (ax.locate(t0, 0, nx)?, az.locate(t0, 0, nz)?),
            Some(true) => (if ax.fwd { ia } else { ib - 1 }, az.locate(entry, 0, nz)?),
            Some(false) => (ax.locate(entry, 0, nx)?, if az.fwd { ja } else { jb - 1 }),
        };
        let (mut xe, mut xx) = ax.span(i, 0);
        let (mut ze, mut zx) = az.span(j, 0);
        let t = match by {
            None => t0,
            Some(true) => xe,
            Some(false) => ze,
        };
        // Near the start only the faces of the axis it was not entered by count (the block
        // before holds the cells behind the other).
        let n = near(t);
        if (by != Some(true) && ax.close(t, i, 0, nx, n, true))
            || (by != Some(false) && az.close(t, j, 0, nz, n, true))
        {
            return None;
        }
        // A cell of the block the walk enters within it lies within its faces.
        debug_assert!((ia..ib).contains(&i) && (ja..jb).contains(&j));
        // `visit_body`'s key of the first cell; each next cell's is the exit of the one before
        // (its new face, crossed after the other: the cells' keys rise).
        let k = if xe > 0.0 { xe } else { 0.0 };
        let mut key = if ze > k { ze } else { k };
        loop {
            if key > r.tmax || key > ystop {
                return Some(true);
            }
            let exit = fmin::<true>(xx, zx);
            if self.reaches_signed(r, s, l0.range(i, j), key, exit) {
                self.cell_hits(r, i, j);
            }
            if exit > r.tmax || exit > ystop {
                return Some(true);
            }
            if (xx - zx).abs() <= near(exit) {
                return None;
            }
            if xx < zx {
                i = match ax.next(i, nx) {
                    Some(k) if (ia..ib).contains(&k) => k,
                    _ => return Some(false),
                };
                // The cell's entry face is the exit face of the one before: the same value.
                (xe, xx) = (xx, ax.cell_exit(i));
            } else {
                j = match az.next(j, nz) {
                    Some(k) if (ja..jb).contains(&k) => k,
                    _ => return Some(false),
                };
                (ze, zx) = (zx, az.cell_exit(j));
            }
            debug_assert!(xe <= exit && ze <= exit);
            key = exit;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::{HeightData, Walk};
    use super::*;
    use crate::math::{DVec3, Ray};
    use std::sync::Arc;

    use super::super::walk::tests::bits;

    /// The cell walk against the pyramid walk, bit for bit and in order: grids whose sides are
    /// not powers of two, with water and flat steps (edge ties); rays from anywhere, from grid
    /// faces and vertices, aimed at vertices and along diagonals (corners crossed exactly),
    /// from afar, rising and falling, with and without a `tmax`; and most of them walked by the
    /// cells.
    #[test]
    fn cell_walk_finds_what_the_pyramid_finds() {
        let mut rng = crate::geom::test_rng::Lcg(31);
        let mut rnd = move || rng.next();
        let (mut checked, mut walked, mut rays) = (0, 0, 0);
        for (w, h, water) in [
            (2, 2, 0.0),
            (3, 5, 0.0),
            (17, 9, 0.3),
            (64, 65, 0.0),
            (160, 120, 0.1),
        ] {
            let heights = (0..w * h)
                .map(|k| {
                    let (i, j) = ((k % w) as f64, (k / w) as f64);
                    let v = 0.5 + 0.45 * ((i * 0.61).sin() * (j * 0.37).cos());
                    ((v * 7.0).floor() / 7.0 * 65535.0) as u16
                })
                .collect();
            let mut data = HeightData::new(w, h, heights);
            data.water_level = water;
            let hf = HeightField::new(Arc::new(data));
            let (cx, cz) = hf.cells();
            let vertex = |a: f64, b: f64| {
                DVec3::new(
                    (a * (cx + 1.0)).floor() / cx,
                    0.0,
                    (b * (cz + 1.0)).floor() / cz,
                )
            };
            for k in 0..8000 {
                let mut o = DVec3::new(rnd() * 1.6 - 0.3, rnd() * 2.0 - 0.2, rnd() * 1.6 - 0.3);
                let mut target = DVec3::new(rnd(), rnd(), rnd());
                match k % 6 {
                    0 => {
                        let v = vertex(rnd(), rnd());
                        (o.x, o.z) = (v.x, v.z);
                    }
                    1 => {
                        let v = vertex(rnd(), rnd());
                        (target.x, target.z) = (v.x, v.z);
                    }
                    2 => {
                        // Along a diagonal of the cells, through their corners.
                        let v = vertex(rnd(), rnd());
                        let s = (rnd() * 8.0).floor() + 1.0;
                        (o.x, o.z) = (v.x, v.z);
                        let (a, b) = (
                            if rnd() < 0.5 { -s } else { s },
                            if rnd() < 0.5 { -s } else { s },
                        );
                        (target.x, target.z) = (v.x + a / cx, v.z + b / cz);
                    }
                    3 => o.x = (rnd() * (cx + 1.0)).floor() / cx,
                    // From afar, as a camera's rays.
                    4 => o = o * 12.0 - DVec3::new(5.5, 2.0, 5.5),
                    _ => {}
                }
                let ray = Ray::new(o, target - o);
                let tmax = [f64::INFINITY, rnd() * 2.0, 0.0][k % 3];
                let (mut a, mut b) = (vec![], vec![]);
                hf.trace_by(&ray, (f64::NEG_INFINITY, tmax), true, &mut a, Walk::Cells);
                hf.trace_by(&ray, (f64::NEG_INFINITY, tmax), true, &mut b, Walk::Signed);
                assert_eq!(bits(&a), bits(&b), "{ray:?} {tmax}");
                checked += a.len();
                // Whether the cells walked it themselves.
                let d = ray.dir * DVec3::new(cx, 1.0, cz);
                let mut out = vec![];
                let mut r = GridRay {
                    o: ray.origin * DVec3::new(cx, 1.0, cz),
                    d,
                    inv: d.recip(),
                    tmax,
                    tmin: f64::NEG_INFINITY,
                    first: true,
                    from: 0,
                    out: &mut out,
                };
                if let Some(s) = Signs::new(&r) {
                    rays += 1;
                    walked += hf.walk_cells(&mut r, &s) as usize;
                }
            }
        }
        assert!(checked > 5000, "{checked}");
        assert!(walked * 10 > rays * 8, "{walked} of {rays}");
    }
}
