//! Area lights' shadows: one shaded point's walk over an area light's array of points,
//! its corners shot first and split into quarters where they disagree (`adaptive`).
//!
//! Moved out of shadow.rs unchanged (it had grown past 800 lines); the shadow ray itself
//! (`Tracer::shadow_apart`) stays there.

use crate::math::DVec3;
use crate::scene::desc::AreaLightDesc;
use crate::scene::light::{AreaGrid, Light};

use super::trace::{point_seed, TraceCtx, Tracer};

/// Corner samples within this (summed over channels) count as the same light, so an adaptive
/// area light stops splitting.
const AREA_SAME: f64 = 0.1;

impl<'a> Tracer<'a> {
    pub(super) fn area_seen(
        &self,
        p: DVec3,
        (slot, light): (usize, &Light),
        a: &AreaLightDesc,
        ctx: &mut TraceCtx<'a>,
    ) -> DVec3 {
        let (n1, n2) = (a.size1, a.size2);
        // The corners of the array, split into quarters where they disagree, the first
        // `adaptive` splits made regardless. Without `adaptive` povray 3.7 samples as with
        // `adaptive 0` (the manual says every point; the binary's pictures say otherwise).
        let levels = a.adaptive.unwrap_or(0);
        let mut cache = std::mem::take(&mut ctx.area_samples);
        cache.clear();
        cache.resize((n1 * n2) as usize, None);
        let mut walk = AreaWalk {
            tracer: self,
            p,
            slot,
            centre: light.position,
            jitter: a.jitter,
            // The array's axes face the point the same way for all of its samples.
            grid: a.grid(a.axes((p - light.position).normalize_or_zero())),
            seed: point_seed(p),
            n1,
            cache,
        };
        let seen = walk.quad(ctx, (0, n1 - 1, 0, n2 - 1), levels);
        ctx.area_samples = walk.cache;
        seen
    }
}

/// One shaded point's walk over an area light's array (`area_seen`): each point's light
/// after shadows, shot once and kept in `cache`.
struct AreaWalk<'t, 'a> {
    tracer: &'t Tracer<'a>,
    p: DVec3,
    slot: usize,
    /// The light's centre.
    centre: DVec3,
    jitter: bool,
    grid: AreaGrid,
    seed: u32,
    n1: u32,
    cache: Vec<Option<DVec3>>,
}

impl<'a> AreaWalk<'_, 'a> {
    /// The shadow ray to array point (i, j): its unit direction and length (the length not
    /// above zero when `p` is on the point, and then the direction is not used).
    #[inline(always)]
    fn ray_to(&self, i: u32, j: u32) -> (DVec3, f64) {
        let jit = if self.jitter {
            (
                super::jitter_hash(i, j, self.seed),
                super::jitter_hash(j, i, self.seed ^ 0x5bd1_e995),
            )
        } else {
            (0.0, 0.0)
        };
        let to = self.centre + self.grid.point(i, j, jit) - self.p;
        let d = to.length();
        (to / d, d)
    }

    /// `ray_to` for a point not yet shot (zeros for one in the cache, not used).
    #[inline(always)]
    fn corner_ray(&self, i: u32, j: u32) -> (DVec3, f64) {
        if self.cache[(j * self.n1 + i) as usize].is_some() {
            (DVec3::ZERO, 0.0)
        } else {
            self.ray_to(i, j)
        }
    }

    /// The corners of the quarter (i0..=i1, j0..=j1), and its light: their mean, or the
    /// mean of its quarters where the corners disagree or `forced` splits remain.
    fn quad(
        &mut self,
        ctx: &mut TraceCtx<'a>,
        (i0, i1, j0, j1): (u32, u32, u32, u32),
        forced: u32,
    ) -> DVec3 {
        let corners = [(i0, j0), (i1, j0), (i0, j1), (i1, j1)];
        // Every corner's ray worked out before any is shot: the square root and divisions
        // of one no longer wait for the shadow test of the one before.
        // Four calls written out, not `corners.map(..)`: its closure was compiled out of line
        // behind the array iterator's machinery, in one of two shapes depending on inlining
        // elsewhere in the crate (lights/soft: 5 M instructions apart between two builds of
        // the same walk).
        let rays = [
            self.corner_ray(i0, j0),
            self.corner_ray(i1, j0),
            self.corner_ray(i0, j1),
            self.corner_ray(i1, j1),
        ];
        let mut c = [DVec3::ZERO; 4];
        for (k, &(i, j)) in corners.iter().enumerate() {
            let at = (j * self.n1 + i) as usize;
            c[k] = match self.cache[at] {
                Some(v) => v,
                None => {
                    let (dir, d) = rays[k];
                    let v = if d <= 0.0 {
                        DVec3::ONE
                    } else {
                        self.tracer.shadow_apart(self.p, dir, d, self.slot, ctx)
                    };
                    self.cache[at] = Some(v);
                    v
                }
            };
        }
        let mean = (c[0] + c[1] + c[2] + c[3]) / 4.0;
        let splittable = i1 - i0 > 1 || j1 - j0 > 1;
        let differ = c
            .iter()
            .any(|v| (*v - mean).abs().element_sum() > AREA_SAME);
        if !splittable || (forced == 0 && !differ) {
            return mean;
        }
        // A side one cell long is not split; an even number of points splits into two
        // halves that share no point (measured: a 4x4 light whose columns are hidden one
        // by one gives 3/4, 1/2, 1/4, as 5x5's shared middle gives its fifths' levels).
        let halves = |a: u32, b: u32| {
            if b - a > 1 {
                ([(a, (a + b) / 2), ((a + b).div_ceil(2), b)], 2)
            } else {
                ([(a, b), (a, b)], 1)
            }
        };
        let next = forced.saturating_sub(1);
        let (is, ni) = halves(i0, i1);
        let (js, nj) = halves(j0, j1);
        let mut sum = DVec3::ZERO;
        for &(a0, a1) in &is[..ni] {
            for &(b0, b1) in &js[..nj] {
                sum += self.quad(ctx, (a0, a1, b0, b1), next);
            }
        }
        sum / (ni * nj) as f64
    }
}
