//! Rendering a built scene into a film: one sample per pixel, then POV-Ray's anti-aliasing
//! method 1 on pixels that differ from their neighbours. Rows are traced in parallel with
//! rayon; jitter comes from a hash of the pixel and sample, so the picture is the same for any
//! thread count.

pub mod camera;
pub mod pigment;
pub mod trace;

use std::sync::atomic::{AtomicU64, Ordering};

use rayon::prelude::*;

use crate::math::DVec3;
use crate::scene::build::{GammaMode, Scene};
use trace::{TraceCtx, Tracer};

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
        }
    }
}

/// Working-space colours, row-major, row 0 at the top.
pub struct Film {
    pub width: u32,
    pub height: u32,
    pub pixels: Vec<DVec3>,
    pub gamma: GammaMode,
    /// Rays traced for this picture (camera, secondary and shadow rays).
    pub rays: u64,
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
fn jitter_hash(x: u32, y: u32, i: u32) -> f64 {
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
    let (w, h) = (s.width as usize, s.height as usize);
    let tracer = Tracer::new(scene);
    let mut pixels = vec![DVec3::ZERO; w * h];
    let inside = |x: usize, y: usize| s.window.is_none_or(|win| win.contains(x, y));
    let rays = AtomicU64::new(0);
    pixels
        .par_chunks_mut(w)
        .enumerate()
        .for_each_init(TraceCtx::default, |ctx, (y, row)| {
            for (x, px) in row.iter_mut().enumerate() {
                if !inside(x, y) {
                    continue;
                }
                let ray = scene.camera.ray(x as f64 + 0.5, y as f64 + 0.5);
                *px = tracer.trace(&ray, 1, 1.0, ctx);
            }
            rays.fetch_add(std::mem::take(&mut ctx.rays), Ordering::Relaxed);
            progress(1);
        });
    let mut film = Film {
        width: s.width,
        height: s.height,
        pixels,
        gamma: scene.gamma,
        rays: rays.into_inner(),
    };
    if let Some(threshold) = s.antialias {
        antialias(&tracer, &mut film, s, threshold);
    }
    film
}

/// POV-Ray compares pixels for anti-aliasing on linear light raised to 1/2.5 (its default
/// Antialias_Gamma), not on the file's encoding.
const AA_GAMMA: f64 = 2.5;

/// Method 1: a pixel whose gamma-adjusted colour differs from its left or upper neighbour by
/// more than the threshold (sum over channels) is supersampled on a depth×depth grid, and so
/// is that neighbour; the samples are averaged with the first one.
fn antialias(tracer: &Tracer, film: &mut Film, s: &RenderSettings, threshold: f64) {
    let (w, h) = (film.width as usize, film.height as usize);
    let working_gamma = match film.gamma {
        GammaMode::Corrected(g) => g,
        GammaMode::None => 1.0,
    };
    let adjust = |v: f64| v.clamp(0.0, 1.0).powf(working_gamma / AA_GAMMA);
    let enc: Vec<DVec3> = film
        .pixels
        .iter()
        .map(|p| DVec3::new(adjust(p.x), adjust(p.y), adjust(p.z)))
        .collect();
    let differs = |a: usize, b: usize| (enc[a] - enc[b]).abs().element_sum() > threshold;
    // Outside a partial render's window nothing was traced, so nothing is compared there.
    let inside = |x: usize, y: usize| s.window.is_none_or(|win| win.contains(x, y));
    let mut mark = vec![false; w * h];
    for y in 0..h {
        for x in 0..w {
            let i = y * w + x;
            if !inside(x, y) {
                continue;
            }
            if x > 0 && inside(x - 1, y) && differs(i, i - 1) {
                mark[i] = true;
                mark[i - 1] = true;
            }
            if y > 0 && inside(x, y - 1) && differs(i, i - w) {
                mark[i] = true;
                mark[i - w] = true;
            }
        }
    }
    let n = s.aa_depth.max(1);
    let cam = &tracer.scene.camera;
    let rays = AtomicU64::new(0);
    film.pixels
        .par_chunks_mut(w)
        .enumerate()
        .for_each_init(TraceCtx::default, |ctx, (y, row)| {
            for (x, px) in row.iter_mut().enumerate() {
                if !mark[y * w + x] {
                    continue;
                }
                let mut sum = *px;
                for j in 0..n {
                    for i in 0..n {
                        let k = j * n + i;
                        let jx = jitter_hash(x as u32, y as u32, 2 * k) * s.jitter;
                        let jy = jitter_hash(x as u32, y as u32, 2 * k + 1) * s.jitter;
                        let sx = x as f64 + (i as f64 + 0.5 + jx) / n as f64;
                        let sy = y as f64 + (j as f64 + 0.5 + jy) / n as f64;
                        sum += tracer.trace(&cam.ray(sx, sy), 1, 1.0, ctx);
                    }
                }
                *px = sum / (1 + n * n) as f64;
            }
            rays.fetch_add(std::mem::take(&mut ctx.rays), Ordering::Relaxed);
        });
    film.rays += rays.into_inner();
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
