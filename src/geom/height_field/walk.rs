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
    pub(super) sx: usize,
    pub(super) sz: usize,
    /// Whether the ray rises: it then enters a block's height range through its low face.
    pub(super) up: bool,
    /// The children's tests in AVX lanes (`walk_avx`).
    avx: bool,
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
            avx: crate::math::has_avx(),
        })
    }
}

/// The right side of the walk's slab test (`slack_ok::<true>`): a block whose entry is above
/// this function of its exit is missed.
#[inline(always)]
pub(super) fn slack(t1: f64) -> f64 {
    t1 + 1e-9 * fmax::<true>(t1.abs(), 1.0)
}

impl HeightField {
    /// `reaches::<true>` for a ray with `Signs`, given the block's height range and the x and
    /// z part of its slab test (`key`, its entry from 0, and `exit`, without `tmax`): the
    /// block's heights give its entry and exit along y by the sign of `d.y` rather than by
    /// `min` and `max` (the same values). No branch: the walk tests four blocks at once.
    // Negated: a NaN `water_level` leaves every block in, as `visit`'s early return does.
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    #[inline(always)]
    pub(super) fn reaches_signed(
        &self,
        r: &GridRay,
        s: &Signs,
        range: [f32; 2],
        key: f64,
        exit: f64,
    ) -> bool {
        let [ylo, yhi] = range.map(f64::from);
        let (u, v) = ((ylo - r.o.y) * r.inv.y, (yhi - r.o.y) * r.inv.y);
        let (ye, yx) = if s.up { (u, v) } else { (v, u) };
        let t0 = if ye > key { ye } else { key };
        let t1 = fmin::<true>(fmin::<true>(r.tmax, exit), yx);
        !(yhi < self.data.water_level) & (t0 <= slack(t1))
    }

    /// `visit::<true>` for a ray with `Signs` (see the module's comment for why the answers
    /// are the same). The caller has found that the ray reaches block (bi, bj) of `level`;
    /// `ux` and `uz` are the distances to the block's low and high faces along x and z (by
    /// coordinate, not by the ray's direction), which are its outer children's faces too.
    ///
    /// The four children are tested together, without a branch per child (their ranges are
    /// one `Quad`), and a bit mask keeps those that exist and pass; they are then visited
    /// as `visit` visits them: sorted by their entry (stable, in the order (0, 0), (1, 0),
    /// (0, 1), (1, 1)) when only the first crossing is wanted, and asked again if `tmax`
    /// shrank before their turn.
    pub(super) fn visit_signed(
        &self,
        r: &mut GridRay,
        s: &Signs,
        level: usize,
        b: (usize, usize),
        ux: [f64; 2],
        uz: [f64; 2],
    ) {
        self.visit_body::<false>(r, s, level, b, ux, uz);
    }

    /// `visit_signed` with the children's tests in AVX lanes (`walk_avx`), the same answers.
    ///
    /// # Safety
    /// The CPU must have AVX (`Signs::avx`).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    unsafe fn visit_avx(
        &self,
        r: &mut GridRay,
        s: &Signs,
        level: usize,
        b: (usize, usize),
        ux: [f64; 2],
        uz: [f64; 2],
    ) {
        self.visit_body::<true>(r, s, level, b, ux, uz);
    }

    /// `visit_signed`'s body, its children's tests in lanes when `AVX` (only called so from
    /// `visit_avx`, which is compiled with AVX).
    #[inline(always)]
    fn visit_body<const AVX: bool>(
        &self,
        r: &mut GridRay,
        s: &Signs,
        level: usize,
        (bi, bj): (usize, usize),
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
        // Each child's entry and exit along x (z), by its index `di` (`dj`): the ray enters
        // by the low face when it runs towards larger x.
        let (xe, xx) = if s.sx == 0 {
            ([ux[0], ux[1]], [ux[1], ux[2]])
        } else {
            ([ux[1], ux[2]], [ux[0], ux[1]])
        };
        let (ze, zx) = if s.sz == 0 {
            ([uz[0], uz[1]], [uz[1], uz[2]])
        } else {
            ([uz[1], uz[2]], [uz[0], uz[1]])
        };
        let quad = &below.quads[bj * below.px + bi].0;
        // The children beyond the grid's edge (only the high ones can be).
        let hx = bi * 2 + 1 < below.nx;
        let hz = bj * 2 + 1 < below.nz;
        let exists = [true, hx, hz, hx & hz];
        let mut key = [0.0f64; 4];
        let mut exit = [0.0f64; 4];
        let mut mask = 0u32;
        #[cfg(target_arch = "x86_64")]
        if AVX {
            let y = super::walk_avx::RayY {
                oy: r.o.y,
                inv_y: r.inv.y,
                up: s.up,
                tmax: r.tmax,
                tmin: r.tmin,
                water: self.data.water_level,
            };
            // SAFETY: `AVX` is only true in `visit_avx`, compiled with AVX and called only
            // when the CPU has it.
            let c = unsafe { super::walk_avx::children(quad, (xe, xx), (ze, zx), &y) };
            let exists_bits = 1 | (hx as u32) << 1 | (hz as u32) << 2 | ((hx & hz) as u32) << 3;
            (key, exit, mask) = (c.key, c.exit, c.mask & exists_bits);
        }
        if !AVX {
            for g in 0..4 {
                let (di, dj) = (g & 1, g >> 1);
                // `0.0f64.max(xe).max(ze)` of `visit`, whose sort key it is; comparisons give
                // +0 for a -0 entry, as `f64::max` with a constant 0 does on x86.
                let k = if xe[di] > 0.0 { xe[di] } else { 0.0 };
                key[g] = if ze[dj] > k { ze[dj] } else { k };
                exit[g] = fmin::<true>(xx[di], zx[dj]);
                let ok = self.reaches_signed(r, s, quad[g], key[g], exit[g]);
                // `walk_avx::children`'s start test: a child left before `tmin` is skipped
                // (negated as there: NaN leaves it in).
                #[allow(clippy::neg_cmp_op_on_partial_ord)]
                let started = !(exit[g] < r.tmin);
                mask |= ((ok & exists[g] & started) as u32) << g;
            }
        }
        if mask == 0 {
            return;
        }
        let mut order = [0usize; 4];
        let mut n = 0;
        while mask != 0 {
            order[n] = mask.trailing_zeros() as usize;
            n += 1;
            mask &= mask - 1;
        }
        let order = &mut order[..n];
        if r.first {
            // Stable, as `visit`'s: the keys are never NaN nor -0, so `>` orders them as
            // `total_cmp` does.
            for i in 1..order.len() {
                let mut j = i;
                while j > 0 && key[order[j - 1]] > key[order[j]] {
                    order.swap(j - 1, j);
                    j -= 1;
                }
            }
        }
        let tmax = r.tmax;
        for &g in order.iter() {
            if r.first && key[g] > r.tmax {
                break;
            }
            if r.tmax != tmax && !self.reaches_signed(r, s, quad[g], key[g], exit[g]) {
                continue;
            }
            let (di, dj) = (g & 1, g >> 1);
            let (ci, cj) = (bi * 2 + di, bj * 2 + dj);
            if level == 1 {
                self.cell_hits(r, ci, cj);
            } else {
                let (kx, kz) = ([ux[di], ux[di + 1]], [uz[dj], uz[dj + 1]]);
                #[cfg(target_arch = "x86_64")]
                if AVX {
                    // SAFETY: as above, this is `visit_avx` on a CPU with AVX.
                    unsafe { self.visit_avx(r, s, level - 1, (ci, cj), kx, kz) };
                    continue;
                }
                self.visit_signed(r, s, level - 1, (ci, cj), kx, kz);
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
        // the sign of a zero).
        let key = fmax::<true>(
            fmax::<true>(0.0, fmin::<true>(ux[0], ux[1])),
            fmin::<true>(uz[0], uz[1]),
        );
        let exit = fmin::<true>(fmax::<true>(ux[0], ux[1]), fmax::<true>(uz[0], uz[1]));
        if self.reaches_signed(r, s, self.levels[top].range(0, 0), key, exit) {
            #[cfg(target_arch = "x86_64")]
            if s.avx {
                // SAFETY: `Signs::avx` says the CPU has AVX.
                unsafe { self.visit_avx(r, s, top, (0, 0), ux, uz) };
                return;
            }
            self.visit_signed(r, s, top, (0, 0), ux, uz);
        }
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::super::{HeightData, Walk};
    use super::*;
    use crate::geom::Hit;
    use crate::math::{DVec3, Ray};
    use std::sync::Arc;

    /// The hits as bits: the walks must agree on every crossing exactly, in order.
    pub(in crate::geom::height_field) fn bits(hits: &[Hit]) -> Vec<(u64, u32, u64, u64)> {
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
                    hf.trace_by(&ray, (f64::NEG_INFINITY, tmax), first, &mut a, Walk::Signed);
                    hf.trace_by(
                        &ray,
                        (f64::NEG_INFINITY, tmax),
                        first,
                        &mut b,
                        Walk::Pyramid,
                    );
                    assert_eq!(bits(&a), bits(&b), "{ray:?} {tmax} {first}");
                    checked += a.len();
                }
            }
        }
        assert!(checked > 1000, "{checked}");
    }

    /// The children's tests in AVX lanes give the scalar walk's crossings, bit for bit and in
    /// order (the walk above is checked against `visit` with whichever the CPU has): grids
    /// with water, flat steps and missing children, rays rising and falling, from grid faces.
    #[test]
    fn avx_lanes_walk_as_the_scalar_tests() {
        if !crate::math::has_avx() {
            return;
        }
        let mut rng = crate::geom::test_rng::Lcg(23);
        let mut rnd = move || rng.next();
        let mut checked = 0;
        for (w, h, water) in [(3, 2, 0.0), (9, 6, 0.45), (33, 40, 0.0), (64, 65, 0.2)] {
            let heights = (0..w * h)
                .map(|k| {
                    let (i, j) = ((k % w) as f64, (k / w) as f64);
                    let v = 0.5 + 0.45 * ((i * 0.9).sin() * (j * 0.35).cos());
                    ((v * 6.0).floor() / 6.0 * 65535.0) as u16
                })
                .collect();
            let mut data = HeightData::new(w, h, heights);
            data.water_level = water;
            let hf = HeightField::new(Arc::new(data));
            let (cx, cz) = hf.cells();
            for k in 0..6000 {
                let mut o = DVec3::new(rnd() * 1.6 - 0.3, rnd() * 2.0 - 0.2, rnd() * 1.6 - 0.3);
                if k % 3 == 0 {
                    o.x = (rnd() * (cx + 1.0)).floor() / cx;
                    o.z = (rnd() * (cz + 1.0)).floor() / cz;
                }
                let d = DVec3::new(rnd(), rnd(), rnd()) - o;
                let (o, d) = (o * DVec3::new(cx, 1.0, cz), d * DVec3::new(cx, 1.0, cz));
                let tmax = [f64::INFINITY, rnd() * 2.0, 0.0][k % 3];
                for first in [true, false] {
                    let mut outs = [vec![], vec![]];
                    for (avx, out) in [false, true].into_iter().zip(outs.iter_mut()) {
                        let mut r = GridRay {
                            o,
                            d,
                            inv: d.recip(),
                            tmax,
                            tmin: f64::NEG_INFINITY,
                            first,
                            from: 0,
                            out,
                        };
                        let Some(mut s) = Signs::new(&r) else {
                            continue;
                        };
                        s.avx = avx;
                        hf.walk_signed(&mut r, &s);
                    }
                    assert_eq!(bits(&outs[0]), bits(&outs[1]), "{o} {d} {tmax} {first}");
                    checked += outs[0].len();
                }
            }
        }
        assert!(checked > 1000, "{checked}");
    }
}
