//! Rendering a built scene into a film: one sample per pixel, then POV-Ray's anti-aliasing
//! method 1 on pixels that differ from their neighbours, or instead method 2's recursive
//! subdivision from the pixel corners. Rows are traced in parallel with rayon; jitter comes
//! from a hash of the pixel and sample, so the picture is the same for any thread count.

mod aa;
mod aa1;
mod background;
pub mod band;
pub mod camera;
mod cell_list;
mod cells_data;
mod crackle;
mod dispersion;
pub mod focal;
mod fog;
mod fractal;
mod irid;
mod layers;
mod legacy_sky;
mod lighting;
mod media;
mod media_beam;
mod metallic;
pub mod noise;
mod noise3_data;
mod noise_data;
mod noise_lattice;
pub mod normal;
pub mod pattern;
mod pattern_blocks;
mod pattern_lanes;
mod pattern_surface;
mod pattern_waves;
mod pattern_wrap;
mod photon_file;
mod photon_tree;
pub mod photons;
pub mod pigment;
pub mod progressive;
pub mod radiosity;
mod radiosity_cache;
mod shadow;
mod shadow_area;
mod sky;
pub mod texture_map;
mod tiling;
pub mod trace;
pub mod warp;

use std::sync::atomic::{AtomicU64, Ordering};

use rayon::prelude::*;

use crate::math::DVec3;
use crate::scene::build::{GammaMode, Scene};
use trace::{Quality, Seen, TraceCtx, Tracer};

#[derive(Clone, Debug)]
pub struct RenderSettings {
    pub width: u32,
    pub height: u32,
    /// Anti-aliasing threshold (`+A0.3`); None renders one sample per pixel.
    pub antialias: Option<f64>,
    /// Supersampling grid size (`+R`), POV-Ray's default 3.
    pub aa_depth: u32,
    /// Jitter the supersamples (`+J`, on by default in POV-Ray).
    pub jitter: f64,
    /// Partial render (`+SR +ER +SC +EC`): pixels `x0..x1` × `y0..y1` are traced and the rest
    /// of the picture stays black, as in POV-Ray's output file.
    pub window: Option<Window>,
    /// `+UA`: keep the background's share of each pixel as alpha.
    pub alpha: bool,
    /// `+Q0..11`: which parts of the lighting model are computed (9, all of them, by default).
    pub quality: u32,
    /// `+AG`: anti-aliasing compares and averages samples on linear light raised to 1/this.
    pub aa_gamma: f64,
    /// `+AM`: 1 is POV-Ray's non-recursive adaptive method, 2 the recursive one.
    pub sampling_method: u32,
    /// `+BS` (`Render_Block_Size`): method 1 refines the picture in blocks this wide, each on
    /// its own, so the block size changes the picture (`aa1`).
    pub aa_block: u32,
}

/// A rectangle of pixels, end-exclusive.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Window {
    pub x0: u32,
    pub x1: u32,
    pub y0: u32,
    pub y1: u32,
}

impl Window {
    fn contains(&self, x: usize, y: usize) -> bool {
        (self.x0 as usize..self.x1 as usize).contains(&x)
            && (self.y0 as usize..self.y1 as usize).contains(&y)
    }
}

impl Default for RenderSettings {
    fn default() -> Self {
        RenderSettings {
            width: 320,
            height: 240,
            antialias: None,
            aa_depth: 3,
            jitter: 1.0,
            window: None,
            alpha: false,
            quality: 9,
            aa_gamma: 2.5,
            sampling_method: 1,
            aa_block: aa1::DEFAULT_BLOCK,
        }
    }
}

/// Working-space colours, row-major, row 0 at the top.
pub struct Film {
    pub width: u32,
    pub height: u32,
    /// With alpha, premultiplied: the colour over black.
    pub pixels: Vec<DVec3>,
    /// `+UA`: each pixel's opacity, 1 − the share of background seen through it.
    pub alpha: Option<Vec<f64>>,
    pub gamma: GammaMode,
    /// Rays traced for this picture (camera, secondary and shadow rays).
    pub rays: u64,
    /// Of those, camera rays: one per pixel without anti-aliasing, more with it.
    pub camera_rays: u64,
}

impl Film {
    /// Linear light for one working-space channel (what EXR stores), unclipped above.
    pub fn linear(&self, v: f64) -> f64 {
        match self.gamma {
            GammaMode::Corrected(g) if g != 1.0 => v.max(0.0).powf(g),
            GammaMode::Corrected(_) => v.max(0.0),
            GammaMode::None => v,
        }
    }

    /// The value that goes into an integer file for one channel, in [0, 1].
    pub fn encode(&self, v: f64) -> f64 {
        match self.gamma {
            GammaMode::Corrected(_) => srgb_encode(self.linear(v).min(1.0)),
            GammaMode::None => v.clamp(0.0, 1.0),
        }
    }
}

pub fn srgb_encode(l: f64) -> f64 {
    if l <= 0.0031308 {
        l * 12.92
    } else {
        1.055 * l.powf(1.0 / 2.4) - 0.055
    }
}

/// A deterministic value in [-0.5, 0.5) for a pixel and sample index.
pub(crate) fn jitter_hash(x: u32, y: u32, i: u32) -> f64 {
    let mut h = (x as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15)
        ^ (y as u64).wrapping_mul(0xC2B2_AE3D_27D4_EB4F)
        ^ (i as u64).wrapping_mul(0x1656_67B1_9E37_79F9);
    h ^= h >> 33;
    h = h.wrapping_mul(0xFF51_AFD7_ED55_8CCD);
    h ^= h >> 33;
    (h >> 11) as f64 / (1u64 << 53) as f64 - 0.5
}

/// Renders the scene; `progress` is called once per finished row (from any thread).
pub fn render(scene: &Scene, s: &RenderSettings, progress: &(dyn Fn(u64) + Sync)) -> Film {
    with_tracer(scene, s, |tracer, pretrace_rays| {
        let pass = match s.antialias {
            // Method 2 never looks at a pixel's centre, so the first pass would be wasted.
            Some(threshold) if s.sampling_method == 2 => {
                aa::method2(tracer, s, threshold, progress)
            }
            Some(threshold) => {
                let mut pass = first_pass(tracer, s, progress);
                let (rays, camera_rays) = aa1::method1(tracer, &mut pass.samples, s, threshold);
                pass.rays += rays;
                pass.camera_rays += camera_rays;
                pass
            }
            None => {
                let mut film = film_rows(tracer, s, 0..s.height as usize, scene.gamma, progress);
                film.rays += pretrace_rays;
                return film;
            }
        };
        let (rays, camera) = (pass.rays + pretrace_rays, pass.camera_rays);
        film_of(&pass.samples, s, s.height, scene.gamma, (rays, camera))
    })
}

/// `render` without anti-aliasing (`s.antialias` must be None) into no film: each pixel, as
/// it is traced, goes to `put(seen, samples)` with its `per_pixel` samples of `out` (the
/// whole picture, row-major), the output's quantisation say. The same pixels as `render`'s
/// film, traced in the same order. Returns the rays traced and, of those, the camera rays.
pub fn render_into<T: Send>(
    scene: &Scene,
    s: &RenderSettings,
    progress: &(dyn Fn(u64) + Sync),
    out: &mut [T],
    per_pixel: usize,
    put: impl Fn(Seen, &mut [T]) + Sync,
) -> (u64, u64) {
    assert!(
        s.antialias.is_none(),
        "render_into traces one sample a pixel"
    );
    let row = s.width as usize * per_pixel;
    assert_eq!(out.len(), row * s.height as usize);
    with_tracer(scene, s, |tracer, pretrace_rays| {
        let rt = RowTracer::new(tracer, s, progress);
        if row > 0 {
            out.par_chunks_mut(row).enumerate().for_each_init(
                TraceCtx::default,
                |ctx, (y, samples)| {
                    rt.row(ctx, y, |x, seen| {
                        put(seen, &mut samples[x * per_pixel..(x + 1) * per_pixel]);
                    });
                },
            );
        }
        (
            rt.rays.into_inner() + pretrace_rays,
            rt.camera_rays.into_inner(),
        )
    })
}

/// `f(tracer, rays)` with the final trace's tracer of the scene (photons shot, radiosity's
/// pretrace done, `rays` the pretrace's rays).
fn with_tracer<R>(
    scene: &Scene,
    s: &RenderSettings,
    f: impl for<'t> FnOnce(&Tracer<'t>, u64) -> R,
) -> R {
    let map = photons::PhotonMap::shoot(scene);
    let camera = camera::Camera::of_scene(scene);
    let base = Tracer {
        photons: map.as_ref(),
        ..Tracer::new(scene, &camera, s.alpha, Quality::level(s.quality))
    };
    let cache = radiosity::pretrace(scene, s, &base);
    let tracer = with_radiosity(&base, cache.as_ref());
    let pretrace_rays = cache.as_ref().map_or(0, |c| c.rays);
    f(&tracer, pretrace_rays)
}

/// The final trace's tracer: `base`, reading the radiosity cache when there is one.
pub(crate) fn with_radiosity<'a>(
    base: &Tracer<'a>,
    cache: Option<&'a radiosity::Cache>,
) -> Tracer<'a> {
    match (base.scene.radiosity.as_ref(), cache) {
        (Some(set), Some(cache)) => radiosity::final_tracer(base, set, cache),
        _ => base.clone(),
    }
}

/// The film of finished samples: `height` whole rows of `s.width`; `rays` is (all, camera).
fn film_of(
    samples: &[Seen],
    s: &RenderSettings,
    height: u32,
    gamma: GammaMode,
    rays: (u64, u64),
) -> Film {
    Film {
        width: s.width,
        height,
        pixels: samples.iter().map(|p| p.rgb).collect(),
        alpha: s
            .alpha
            .then(|| samples.iter().map(|p| 1.0 - p.clear).collect()),
        gamma,
        rays: rays.0,
        camera_rays: rays.1,
    }
}

/// The film of picture rows `rows` with one sample at each pixel's centre, traced straight
/// into the film's buffers: the same values as `film_of(first_pass_rows(..))`, without the
/// samples' buffer (32 bytes a pixel) that would be filled, copied and freed. On small scenes
/// that buffer's page faults and copy were a tenth of the process's CPU time.
fn film_rows<'a>(
    tracer: &Tracer<'a>,
    s: &RenderSettings,
    rows: std::ops::Range<usize>,
    gamma: GammaMode,
    progress: &(dyn Fn(u64) + Sync),
) -> Film {
    let w = s.width as usize;
    let n = w * rows.len();
    let mut pixels: Vec<DVec3> = Vec::with_capacity(n);
    let mut alpha: Vec<f64> = Vec::with_capacity(if s.alpha { n } else { 0 });
    let rt = RowTracer::new(tracer, s, progress);
    let y0 = rows.start;
    if w > 0 {
        let px_rows = pixels.spare_capacity_mut()[..n].par_chunks_mut(w);
        if s.alpha {
            px_rows
                .zip(alpha.spare_capacity_mut()[..n].par_chunks_mut(w))
                .enumerate()
                .for_each_init(TraceCtx::default, |ctx, (ly, (prow, arow))| {
                    rt.row(ctx, y0 + ly, |x, seen| {
                        prow[x].write(seen.rgb);
                        arow[x].write(1.0 - seen.clear);
                    });
                });
        } else {
            px_rows
                .enumerate()
                .for_each_init(TraceCtx::default, |ctx, (ly, prow)| {
                    rt.row(ctx, y0 + ly, |x, seen| {
                        prow[x].write(seen.rgb);
                    });
                });
        }
    }
    // SAFETY: every row chunk of the first `n` elements was handed to `RowTracer::row`, which
    // writes each of its `w` pixels (and alpha values, when kept) exactly once.
    unsafe {
        pixels.set_len(n);
        if s.alpha {
            alpha.set_len(n);
        }
    }
    Film {
        width: s.width,
        height: rows.len() as u32,
        pixels,
        alpha: s.alpha.then_some(alpha),
        gamma,
        rays: rt.rays.into_inner(),
        camera_rays: rt.camera_rays.into_inner(),
    }
}

/// One sample at each pixel's centre.
fn first_pass(tracer: &Tracer, s: &RenderSettings, progress: &(dyn Fn(u64) + Sync)) -> aa::Pass {
    first_pass_rows(tracer, s, 0..s.height as usize, progress)
}

/// The first pass over picture rows `rows` only.
fn first_pass_rows(
    tracer: &Tracer,
    s: &RenderSettings,
    rows: std::ops::Range<usize>,
    progress: &(dyn Fn(u64) + Sync),
) -> aa::Pass {
    let w = s.width as usize;
    let mut samples = vec![Seen::default(); w * rows.len()];
    let rt = RowTracer::new(tracer, s, progress);
    samples
        .par_chunks_mut(w)
        .enumerate()
        .for_each_init(TraceCtx::default, |ctx, (ly, row)| {
            rt.row(ctx, rows.start + ly, |x, seen| row[x] = seen);
        });
    aa::Pass {
        samples,
        rays: rt.rays.into_inner(),
        camera_rays: rt.camera_rays.into_inner(),
    }
}

/// One sample at the centre of each pixel of a row, for `film_rows` and `first_pass_rows`,
/// with the ray counts of every row traced.
struct RowTracer<'t, 'a> {
    tracer: &'t Tracer<'a>,
    s: &'t RenderSettings,
    /// Radiosity's last completion pass lit some of these very rays (radiosity::pretrace).
    lit: Option<&'t radiosity::FirstPass>,
    progress: &'t (dyn Fn(u64) + Sync),
    rays: AtomicU64,
    camera_rays: AtomicU64,
}

impl<'t, 'a> RowTracer<'t, 'a> {
    fn new(
        tracer: &'t Tracer<'a>,
        s: &'t RenderSettings,
        progress: &'t (dyn Fn(u64) + Sync),
    ) -> Self {
        let lit = tracer
            .rad
            .as_ref()
            .and_then(|r| r.cache.first_pass.as_ref());
        RowTracer {
            tracer,
            s,
            lit,
            progress,
            rays: AtomicU64::new(0),
            camera_rays: AtomicU64::new(0),
        }
    }

    /// Picture row `y` into `out(x, seen)`, left to right; pixels outside a partial render's
    /// window give `Seen::default()` untraced.
    /// Generic in `out`: a `dyn` call per pixel, and the film's store behind it, were a
    /// few percent of a small scene.
    fn row(&self, ctx: &mut TraceCtx<'a>, y: usize, mut out: impl FnMut(usize, Seen)) {
        let w = self.s.width as usize;
        let mut traced = 0;
        for x in 0..w {
            let seen = if !self.s.inside(x, y) {
                Seen::default()
            } else {
                traced += 1;
                match self.lit.and_then(|l| l.get(y * w + x)) {
                    Some(seen) => seen,
                    None => self
                        .tracer
                        .trace_camera_at(x as f64 + 0.5, y as f64 + 0.5, ctx),
                }
            };
            out(x, seen);
        }
        self.camera_rays.fetch_add(traced, Ordering::Relaxed);
        self.rays
            .fetch_add(std::mem::take(&mut ctx.rays), Ordering::Relaxed);
        (self.progress)(1);
    }
}

impl RenderSettings {
    /// Whether pixel (x, y) is traced: outside a partial render's window it stays black.
    fn inside(&self, x: usize, y: usize) -> bool {
        self.window.is_none_or(|win| win.contains(x, y))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn jitter_is_bounded_and_deterministic() {
        for i in 0..1000 {
            let j = jitter_hash(i, i * 7, i * 13);
            assert!((-0.5..0.5).contains(&j));
            assert_eq!(j, jitter_hash(i, i * 7, i * 13));
        }
    }

    #[test]
    fn srgb_encode_matches_known_values() {
        assert!((srgb_encode(0.5) - 0.7353569830524495).abs() < 1e-12);
        assert_eq!(srgb_encode(0.0), 0.0);
        assert!((srgb_encode(1.0) - 1.0).abs() < 1e-12);
    }
}
