//! POV-Ray's adaptive anti-aliasing, run after the first pass of one sample per pixel.
//!
//! Samples are compared on linear light raised to 1/Antialias_Gamma (2.5 by default), the way
//! POV-Ray 3.7 compares them, not on the file's encoding.

use std::sync::atomic::{AtomicU64, Ordering};

use rayon::prelude::*;

use super::trace::{Seen, TraceCtx, Tracer};
use super::{jitter_hash, RenderSettings};
use crate::math::DVec3;
use crate::scene::build::GammaMode;

/// Refines `samples` (the first pass) in place; returns the rays it traced.
pub fn antialias(tracer: &Tracer, samples: &mut [Seen], s: &RenderSettings, threshold: f64) -> u64 {
    method1(tracer, samples, s, threshold)
}

/// Maps a working-space colour to the space where POV-Ray measures differences.
fn aa_space(tracer: &Tracer, s: &RenderSettings) -> impl Fn(DVec3) -> DVec3 {
    let working_gamma = match tracer.scene.gamma {
        GammaMode::Corrected(g) => g,
        GammaMode::None => 1.0,
    };
    let e = working_gamma / s.aa_gamma.max(1e-6);
    move |c: DVec3| {
        DVec3::new(
            c.x.clamp(0.0, 1.0).powf(e),
            c.y.clamp(0.0, 1.0).powf(e),
            c.z.clamp(0.0, 1.0).powf(e),
        )
    }
}

/// Method 1: a pixel whose colour differs from its left or upper neighbour by more than the
/// threshold (sum over channels) is supersampled on a depth×depth grid, and so is that
/// neighbour; the samples are averaged with the first one.
fn method1(tracer: &Tracer, samples: &mut [Seen], s: &RenderSettings, threshold: f64) -> u64 {
    let (w, h) = (s.width as usize, s.height as usize);
    let space = aa_space(tracer, s);
    let enc: Vec<DVec3> = samples.iter().map(|p| space(p.rgb)).collect();
    let differs = |a: usize, b: usize| (enc[a] - enc[b]).abs().element_sum() > threshold;
    // Outside a partial render's window nothing was traced, so nothing is compared there.
    let mut mark = vec![false; w * h];
    for y in 0..h {
        for x in 0..w {
            let i = y * w + x;
            if !s.inside(x, y) {
                continue;
            }
            if x > 0 && s.inside(x - 1, y) && differs(i, i - 1) {
                mark[i] = true;
                mark[i - 1] = true;
            }
            if y > 0 && s.inside(x, y - 1) && differs(i, i - w) {
                mark[i] = true;
                mark[i - w] = true;
            }
        }
    }
    let n = s.aa_depth.max(1);
    let cam = &tracer.scene.camera;
    let rays = AtomicU64::new(0);
    samples
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
                        let t = tracer.trace_camera(&cam.ray(sx, sy), ctx);
                        sum.rgb += t.rgb;
                        sum.clear += t.clear;
                    }
                }
                let k = (1 + n * n) as f64;
                *px = Seen {
                    rgb: sum.rgb / k,
                    clear: sum.clear / k,
                };
            }
            rays.fetch_add(std::mem::take(&mut ctx.rays), Ordering::Relaxed);
        });
    rays.into_inner()
}
