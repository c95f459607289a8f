//! POV-Ray's adaptive anti-aliasing: method 1 (`aa1`) refines the first pass of one sample per
//! pixel, method 2 (here) replaces it with recursive subdivision from the pixel corners.
//!
//! Samples are compared on linear light raised to 1/Antialias_Gamma (2.5 by default), the way
//! POV-Ray 3.7 compares them, not on the file's encoding; they are averaged in the working
//! space.

use std::sync::atomic::{AtomicU64, Ordering};

use rayon::prelude::*;

use super::trace::{Seen, TraceCtx, Tracer};
use super::{jitter_hash, RenderSettings};
use crate::math::DVec3;
use crate::scene::build::GammaMode;

/// A finished pass: one `Seen` per pixel and the rays it cost.
pub struct Pass {
    pub samples: Vec<Seen>,
    /// Every ray (camera, secondary, shadow), for the statistics line.
    pub rays: u64,
    /// Camera rays only: what the sampling method itself decides.
    pub camera_rays: u64,
}

/// How POV-Ray measures the difference between two samples.
pub(super) struct Measure {
    /// Working space to linear light to the 1/Antialias_Gamma power, in one exponent.
    exponent: f64,
    alpha: bool,
}

impl Measure {
    pub(super) fn new(tracer: &Tracer, s: &RenderSettings) -> Measure {
        let working_gamma = match tracer.scene.gamma {
            GammaMode::Corrected(g) => g,
            GammaMode::None => 1.0,
        };
        Measure {
            exponent: working_gamma / s.aa_gamma.max(1e-6),
            alpha: s.alpha,
        }
    }

    pub(super) fn sample(&self, seen: Seen) -> Sample {
        let e = self.exponent;
        let c = seen.rgb;
        Sample {
            seen,
            enc: DVec3::new(
                c.x.clamp(0.0, 1.0).powf(e),
                c.y.clamp(0.0, 1.0).powf(e),
                c.z.clamp(0.0, 1.0).powf(e),
            ),
        }
    }

    pub(super) fn distance(&self, a: &Sample, b: &Sample) -> f64 {
        let d = (a.enc - b.enc).abs().element_sum();
        // With +UA POV-Ray adds the difference in transparency, as it is (no gamma): black
        // spheres with transmit T (T² through both surfaces) over the background start being
        // supersampled, by either method, when 1 − T² passes the threshold (tests/probes
        // measured at +A0.3: T 0.834 splits, 0.838 does not).
        if self.alpha {
            d + (a.seen.clear - b.seen.clear).abs()
        } else {
            d
        }
    }
}

/// A sample with its colour in the space where differences are measured, converted once
/// however often it is compared.
#[derive(Clone, Copy, Default)]
pub(super) struct Sample {
    pub(super) seen: Seen,
    enc: DVec3,
}

/// Method 2, adaptive recursive supersampling. What POV-Ray 3.7.0.10 does was measured with
/// orthographic probe scenes whose colour is a known function of the image position, rendered
/// to 16-bit linear files and matched against a model of the algorithm:
///
/// - The first pass's centre sample is not used: a pixel is the mean of the rays at its four
///   corners (integer pixel coordinates) when nothing differs, so even a threshold that never
///   splits softens the picture by half a pixel. The caller skips the first pass.
/// - A square is split when any of its six corner pairs (edges and diagonals) differs by more
///   than the threshold, summed over channels as for method 1; the mean is not involved.
/// - A split traces the four edge midpoints and the centre; a square's colour is the plain
///   mean of its four quarters, whatever their depth.
/// - `+Rn` allows n − 1 levels of splitting: +R1 never splits (4 shared corner rays per
///   pixel), +R2 takes at most 9 samples per pixel, +R3 25, +R4 81: one level less than the
///   table in the manual.
/// - Corners are traced once (POV-Ray traces them once per 32×32 block); sub-samples are
///   shared by the squares of one pixel but not with the neighbouring pixel, which traces its
///   own copy of their common edge's midpoint (POV-Ray's sample counts say the same).
/// - Jitter moves every sub-sample, never a corner, by an independent uniform offset per axis
///   spanning Jitter_Amount / (2^n + 1) pixels at every level: ±0.1 px at +R2, ±0.056 at +R3,
///   ±0.029 at +R4 (fitted to the variance and kurtosis of jittered renders of a linear ramp;
///   POV-Ray's sequence is its own, only its amount is matched).
pub fn method2(
    tracer: &Tracer,
    s: &RenderSettings,
    threshold: f64,
    progress: &(dyn Fn(u64) + Sync),
) -> Pass {
    let (w, h) = (s.width as usize, s.height as usize);
    let measure = Measure::new(tracer, s);
    let rays = AtomicU64::new(0);
    let camera_rays = AtomicU64::new(0);
    // A corner is needed when a pixel it bounds is traced.
    let corner_needed = |i: usize, j: usize| {
        s.window.is_none_or(|win| {
            (win.x0 as usize..=win.x1 as usize).contains(&i)
                && (win.y0 as usize..=win.y1 as usize).contains(&j)
        })
    };
    // Corners first, in their own parallel pass, so that every pixel row can then read both
    // of its corner rows without waiting for a neighbour or tracing them twice.
    // Kept as plain colours (converted for comparison by each pixel row that reads them) so
    // the grid costs no more memory than the picture's own samples.
    let mut corners = vec![Seen::default(); (w + 1) * (h + 1)];
    corners
        .par_chunks_mut(w + 1)
        .enumerate()
        .for_each_init(TraceCtx::default, |ctx, (j, row)| {
            let mut traced = 0;
            for (i, c) in row.iter_mut().enumerate() {
                if corner_needed(i, j) {
                    *c = tracer.trace_camera_at(i as f64, j as f64, ctx);
                    traced += 1;
                }
            }
            camera_rays.fetch_add(traced, Ordering::Relaxed);
            rays.fetch_add(std::mem::take(&mut ctx.rays), Ordering::Relaxed);
        });

    let depth = s.aa_depth.clamp(1, MAX_DEPTH);
    let divisions = 1u32 << (depth - 1);
    let jitter = s.jitter / ((1u32 << depth) + 1) as f64;
    let mut samples = vec![Seen::default(); w * h];
    samples.par_chunks_mut(w).enumerate().for_each_init(
        || (TraceCtx::default(), SubCache::new(divisions), Vec::new()),
        |(ctx, cache, edges), (y, row)| {
            edges.clear();
            let edge_rows = &corners[y * (w + 1)..(y + 2) * (w + 1)];
            edges.extend(edge_rows.iter().map(|c| measure.sample(*c)));
            let mut traced = 0;
            for (x, px) in row.iter_mut().enumerate() {
                if !s.inside(x, y) {
                    continue;
                }
                let at = |i: usize, j: usize| edges[j * (w + 1) + x + i];
                cache.start();
                let mut pixel = Pixel {
                    tracer,
                    measure: &measure,
                    threshold,
                    x: x as u32,
                    y: y as u32,
                    divisions,
                    jitter,
                    cache,
                    ctx,
                    traced: 0,
                };
                let c = [at(0, 0), at(1, 0), at(0, 1), at(1, 1)];
                *px = pixel.square(0, 0, divisions, c);
                traced += pixel.traced;
            }
            camera_rays.fetch_add(traced, Ordering::Relaxed);
            rays.fetch_add(std::mem::take(&mut ctx.rays), Ordering::Relaxed);
            progress(1);
        },
    );
    Pass {
        samples,
        rays: rays.into_inner(),
        camera_rays: camera_rays.into_inner(),
    }
}

/// POV-Ray accepts Antialias_Depth 1 to 9.
const MAX_DEPTH: u32 = 9;

/// One pixel's sub-samples by position on its finest grid ((divisions + 1)² points), so a
/// point two squares share is traced once. An entry is valid when it carries the current
/// pixel's stamp, which saves clearing the grid (66049 points at +R9) for every pixel.
struct SubCache {
    side: usize,
    stamp: u32,
    stamps: Vec<u32>,
    samples: Vec<Sample>,
}

impl SubCache {
    fn new(divisions: u32) -> SubCache {
        let side = divisions as usize + 1;
        SubCache {
            side,
            stamp: 0,
            stamps: vec![0; side * side],
            samples: vec![Sample::default(); side * side],
        }
    }

    /// Forgets the previous pixel's samples.
    fn start(&mut self) {
        self.stamp = self.stamp.wrapping_add(1);
        if self.stamp == 0 {
            self.stamps.fill(0);
            self.stamp = 1;
        }
    }
}

/// The recursion over one pixel's squares, positions in units of its finest grid.
struct Pixel<'p, 's> {
    tracer: &'p Tracer<'s>,
    measure: &'p Measure,
    threshold: f64,
    x: u32,
    y: u32,
    divisions: u32,
    /// Width of the uniform jitter, in pixels.
    jitter: f64,
    cache: &'p mut SubCache,
    ctx: &'p mut TraceCtx<'s>,
    traced: u64,
}

impl Pixel<'_, '_> {
    /// The colour of the square at grid position (gx, gy) with side `size`; corners in the
    /// order top-left, top-right, bottom-left, bottom-right.
    fn square(&mut self, gx: u32, gy: u32, size: u32, c: [Sample; 4]) -> Seen {
        if size > 1 && self.differ(&c) {
            let m = size / 2;
            let top = self.sample(gx + m, gy);
            let left = self.sample(gx, gy + m);
            let mid = self.sample(gx + m, gy + m);
            let right = self.sample(gx + size, gy + m);
            let bottom = self.sample(gx + m, gy + size);
            let q = [
                self.square(gx, gy, m, [c[0], top, left, mid]),
                self.square(gx + m, gy, m, [top, c[1], mid, right]),
                self.square(gx, gy + m, m, [left, mid, c[2], bottom]),
                self.square(gx + m, gy + m, m, [mid, right, bottom, c[3]]),
            ];
            mean(q)
        } else {
            mean(c.map(|s| s.seen))
        }
    }

    fn differ(&self, c: &[Sample; 4]) -> bool {
        (0..4).any(|a| (a + 1..4).any(|b| self.measure.distance(&c[a], &c[b]) > self.threshold))
    }

    fn sample(&mut self, gi: u32, gj: u32) -> Sample {
        let k = gj as usize * self.cache.side + gi as usize;
        if self.cache.stamps[k] == self.cache.stamp {
            return self.cache.samples[k];
        }
        let n = self.divisions as f64;
        // The hash of the pixel and grid point, not a running sequence, keeps the picture
        // independent of which thread traces which row.
        let (jx, jy) = if self.jitter > 0.0 {
            let k = k as u32;
            (
                jitter_hash(self.x, self.y, 2 * k) * self.jitter,
                jitter_hash(self.x, self.y, 2 * k + 1) * self.jitter,
            )
        } else {
            (0.0, 0.0)
        };
        let sx = self.x as f64 + gi as f64 / n + jx;
        let sy = self.y as f64 + gj as f64 / n + jy;
        let seen = self.tracer.trace_camera_at(sx, sy, self.ctx);
        self.traced += 1;
        let s = self.measure.sample(seen);
        self.cache.stamps[k] = self.cache.stamp;
        self.cache.samples[k] = s;
        s
    }
}

fn mean(q: [Seen; 4]) -> Seen {
    Seen {
        rgb: (q[0].rgb + q[1].rgb + q[2].rgb + q[3].rgb) / 4.0,
        clear: (q[0].clear + q[1].clear + q[2].clear + q[3].clear) / 4.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::camera::Camera;
    use crate::render::trace::Quality;
    use crate::render::Window;
    use crate::scene::build::{build, Scene};
    use crate::sdl::{ParseOptions, Parser};

    const W: u32 = 8;
    const H: u32 = 6;

    fn scene(text: &str) -> Scene {
        let mut p = Parser::new(ParseOptions::default());
        p.parse_str("test.pov", text).expect("test scene parses");
        build(&p.scene, W, H).scene
    }

    /// A wall whose brightness grows across the picture: every pair of corners in a row
    /// differs, so a zero threshold splits every square as deep as allowed.
    fn ramp() -> Scene {
        scene(
            "#version 3.7; global_settings { assumed_gamma 1.0 }
             camera { location <0,0,-5> look_at 0 }
             plane { -z, 0 pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] }
                                     scale 8 translate -4*x }
                     finish { ambient 1 diffuse 0 } }",
        )
    }

    fn settings(depth: u32, jitter: f64) -> RenderSettings {
        RenderSettings {
            width: W,
            height: H,
            aa_depth: depth,
            jitter,
            sampling_method: 2,
            ..RenderSettings::default()
        }
    }

    fn run(scene: &Scene, s: &RenderSettings, threshold: f64) -> Pass {
        let camera = Camera::of_scene(scene);
        let tracer = Tracer::new(scene, &camera, s.alpha, Quality::level(9));
        method2(&tracer, s, threshold, &|_| {})
    }

    fn trace(scene: &Scene, sx: f64, sy: f64) -> Seen {
        let camera = Camera::of_scene(scene);
        let tracer = Tracer::new(scene, &camera, false, Quality::level(9));
        tracer.trace_camera(camera.ray(sx, sy), &mut TraceCtx::default())
    }

    fn close(a: Seen, b: Seen) -> bool {
        (a.rgb - b.rgb).abs().max_element() < 1e-12 && (a.clear - b.clear).abs() < 1e-12
    }

    const CORNERS: u64 = ((W + 1) * (H + 1)) as u64;

    #[test]
    fn a_flat_colour_is_never_split() {
        let flat = scene("background { rgb <0.2, 0.4, 0.6> }");
        let pass = run(&flat, &settings(4, 1.0), 0.0);
        assert_eq!(pass.camera_rays, CORNERS);
        for p in &pass.samples {
            assert!((p.rgb - DVec3::new(0.2, 0.4, 0.6)).abs().max_element() < 1e-12);
        }
    }

    #[test]
    fn depth_n_allows_n_minus_one_levels() {
        let ramp = ramp();
        for (depth, per_pixel) in [(1, 0), (2, 9 - 4), (3, 25 - 4), (4, 81 - 4)] {
            let pass = run(&ramp, &settings(depth, 0.0), 0.0);
            let expected = CORNERS + (W * H) as u64 * per_pixel;
            assert_eq!(pass.camera_rays, expected, "+R{depth}");
        }
    }

    #[test]
    fn an_unsplit_pixel_is_the_mean_of_its_corners_not_its_centre() {
        let ramp = ramp();
        let pass = run(&ramp, &settings(3, 1.0), 3.0);
        assert_eq!(pass.camera_rays, CORNERS);
        let (x, y) = (5.0, 2.0);
        let corners = [(x, y), (x + 1.0, y), (x, y + 1.0), (x + 1.0, y + 1.0)];
        let want = mean(corners.map(|(sx, sy)| trace(&ramp, sx, sy)));
        assert!(close(pass.samples[2 * W as usize + 5], want));
    }

    #[test]
    fn quarters_weigh_the_same() {
        // One level: corners count once, edge midpoints twice, the centre four times.
        let ramp = ramp();
        let pass = run(&ramp, &settings(2, 0.0), 0.0);
        let (x, y) = (3.0, 4.0);
        let at = |i: f64, j: f64, k: f64| trace(&ramp, x + i, y + j).rgb * k;
        let want = (at(0.0, 0.0, 1.0)
            + at(1.0, 0.0, 1.0)
            + at(0.0, 1.0, 1.0)
            + at(1.0, 1.0, 1.0)
            + at(0.5, 0.0, 2.0)
            + at(0.0, 0.5, 2.0)
            + at(1.0, 0.5, 2.0)
            + at(0.5, 1.0, 2.0)
            + at(0.5, 0.5, 4.0))
            / 16.0;
        let got = pass.samples[4 * W as usize + 3].rgb;
        assert!((got - want).abs().max_element() < 1e-12);
    }

    #[test]
    fn jitter_moves_sub_samples_only_and_is_repeatable() {
        let ramp = ramp();
        let still = run(&ramp, &settings(3, 0.0), 0.0);
        let a = run(&ramp, &settings(3, 1.0), 0.0);
        let b = run(&ramp, &settings(3, 1.0), 0.0);
        assert_eq!(a.samples, b.samples);
        assert_ne!(a.samples, still.samples);
        // Unsplit pixels have no sub-samples to move.
        let flat = run(&ramp, &settings(3, 1.0), 3.0);
        let flat_still = run(&ramp, &settings(3, 0.0), 3.0);
        assert_eq!(flat.samples, flat_still.samples);
    }

    #[test]
    fn a_window_traces_only_its_pixels_corners() {
        let flat = scene("background { rgb 1 }");
        let s = RenderSettings {
            window: Some(Window {
                x0: 2,
                x1: 5,
                y0: 1,
                y1: 3,
            }),
            ..settings(3, 1.0)
        };
        let pass = run(&flat, &s, 0.0);
        assert_eq!(pass.camera_rays, 4 * 3);
        for (i, p) in pass.samples.iter().enumerate() {
            let inside = s.inside(i % W as usize, i / W as usize);
            assert_eq!(p.rgb, if inside { DVec3::ONE } else { DVec3::ZERO });
        }
    }

    #[test]
    fn alpha_counts_in_the_difference_only_with_alpha_on() {
        let flat = scene("background { rgb 0 }");
        let camera = Camera::of_scene(&flat);
        let tracer = Tracer::new(&flat, &camera, false, Quality::level(9));
        let mut s = settings(3, 0.0);
        let clear = |c| Seen {
            rgb: DVec3::ZERO,
            clear: c,
        };
        let m = Measure::new(&tracer, &s);
        assert_eq!(
            m.distance(&m.sample(clear(1.0)), &m.sample(clear(0.7))),
            0.0
        );
        s.alpha = true;
        let m = Measure::new(&tracer, &s);
        let d = m.distance(&m.sample(clear(1.0)), &m.sample(clear(0.7)));
        assert!((d - 0.3).abs() < 1e-12);
    }
}
