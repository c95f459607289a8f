//! POV-Ray's anti-aliasing method 1 (`+AM1`, the default), block by block as POV-Ray 3.7
//! does it. Measured with probe scenes against povray's pictures and its sample counts
//! (`scripts/measure_aa_method1.sh`):
//!
//! - The picture (or the partial render's window) is cut into square blocks of
//!   `Render_Block_Size` pixels (32 by default) from its top-left corner. Each block is
//!   refined on its own: it sees its pixels plus its own copy of the column left of it and the
//!   row above it (not the corner between them), even where those lie outside the picture,
//!   so a 32×32 block traces 33×33 − 1 first-pass rays.
//! - The block's pixels are visited row by row. A pixel is compared, by its first-pass colour,
//!   with its left and upper neighbours as they are at that moment, refined or not; when they
//!   differ by more than the threshold, the pixel and that neighbour are supersampled (each
//!   once) on a depth×depth grid and averaged with their first sample. A refined pixel can so
//!   set off its right and lower neighbours, but never one already visited.
//! - The border copies are compared but never refined (each is compared with one pixel of the
//!   block only, so refining it could change nothing, and povray's sample counts leave them
//!   out); the neighbouring block computes its own pixels itself.
//!
//! Since no block reads another's results, blocks run in parallel and the picture is the same
//! for any thread count; a band of whole block rows needs only the first-pass row above it.

use std::sync::atomic::{AtomicU64, Ordering};

use rayon::prelude::*;

use super::aa::{Measure, Sample};
use super::trace::{Seen, TraceCtx, Tracer};
use super::{jitter_hash, RenderSettings};

/// POV-Ray's default `Render_Block_Size`.
pub const DEFAULT_BLOCK: u32 = 32;

/// The block edge POV-Ray uses for these settings: at least 4, clipped to the larger side of
/// the picture (its manual).
pub fn block_size(s: &RenderSettings) -> usize {
    let larger = s.width.max(s.height).max(1);
    s.aa_block.max(4).min(larger) as usize
}

/// The first row of block rows: the window's top (0 without a window). Bands of rows given to
/// `refine_rows` start at this row plus a multiple of the block size.
pub fn block_top(s: &RenderSettings) -> usize {
    s.window.map_or(0, |win| win.y0 as usize)
}

/// Method 1 over the whole picture's first pass `samples`, in place; returns all rays and
/// camera rays traced.
pub fn method1(
    tracer: &Tracer,
    samples: &mut [Seen],
    s: &RenderSettings,
    threshold: f64,
) -> (u64, u64) {
    refine_rows(tracer, samples, 0, None, s, threshold)
}

/// Method 1 over first-pass `samples` holding whole picture rows from `first_y` on, where
/// `first_y` and the end of the rows fall on block rows (or the picture's ends); `above` is the
/// first pass of row `first_y - 1` when it was traced (by the band before).
pub fn refine_rows(
    tracer: &Tracer,
    samples: &mut [Seen],
    first_y: usize,
    above: Option<&[Seen]>,
    s: &RenderSettings,
    threshold: f64,
) -> (u64, u64) {
    let w = s.width as usize;
    let rows = samples.len() / w.max(1);
    let (x_start, x_end, y_start, y_end) = match s.window {
        Some(win) => (
            win.x0 as usize,
            (win.x1 as usize).min(w),
            win.y0 as usize,
            win.y1 as usize,
        ),
        None => (0, w, 0, s.height as usize),
    };
    let b = block_size(s);
    let y_from = first_y.max(y_start);
    let y_to = (first_y + rows).min(y_end);
    let mut blocks = Vec::new();
    let mut by = y_from;
    while by < y_to {
        debug_assert_eq!((by - y_start) % b, 0, "bands start on block rows");
        let bh = b.min(y_to - by);
        for bx in (x_start..x_end).step_by(b) {
            blocks.push((bx, by, b.min(x_end - bx), bh));
        }
        by += bh;
    }
    let measure = Measure::new(tracer, s);
    let rays = AtomicU64::new(0);
    let camera_rays = AtomicU64::new(0);
    let source = &*samples;
    let done: Vec<Vec<Seen>> = blocks
        .par_iter()
        .map_init(TraceCtx::default, |ctx, &(bx, by, bw, bh)| {
            let first = |x: i64, y: i64| -> Option<Seen> {
                let (ux, uy) = (x as usize, y as usize);
                if x < 0 || y < 0 || ux >= w || !s.inside(ux, uy) {
                    return None;
                }
                if uy >= first_y && uy < first_y + rows {
                    Some(source[(uy - first_y) * w + ux])
                } else if uy + 1 == first_y {
                    above.map(|row| row[ux])
                } else {
                    None
                }
            };
            let mut block = Block {
                tracer,
                measure: &measure,
                s,
                x0: bx as i64 - 1,
                y0: by as i64 - 1,
                side: bw + 1,
                grid: Vec::with_capacity((bw + 1) * (bh + 1)),
                refined: vec![false; (bw + 1) * (bh + 1)],
                ctx,
                camera_rays: 0,
            };
            for gy in 0..=bh {
                for gx in 0..=bw {
                    let (x, y) = (block.x0 + gx as i64, block.y0 + gy as i64);
                    let seen = if gx == 0 && gy == 0 {
                        Seen::default() // Never compared.
                    } else {
                        match first(x, y) {
                            Some(seen) => seen,
                            None => {
                                block.camera_rays += 1;
                                block.trace(x as f64 + 0.5, y as f64 + 0.5)
                            }
                        }
                    };
                    block.grid.push(measure.sample(seen));
                }
            }
            for gy in 1..=bh {
                for gx in 1..=bw {
                    let i = gy * block.side + gx;
                    let left = block.differs(i, i - 1, threshold);
                    let up = block.differs(i, i - block.side, threshold);
                    if left || up {
                        block.refine(i);
                    }
                    // A border copy is compared with this pixel only, so refining it could
                    // change nothing; povray's sample counts say it does not refine them.
                    if left && gx > 1 {
                        block.refine(i - 1);
                    }
                    if up && gy > 1 {
                        block.refine(i - block.side);
                    }
                }
            }
            camera_rays.fetch_add(block.camera_rays, Ordering::Relaxed);
            rays.fetch_add(std::mem::take(&mut block.ctx.rays), Ordering::Relaxed);
            let mut out = Vec::with_capacity(bw * bh);
            for gy in 1..=bh {
                out.extend(
                    block.grid[gy * block.side + 1..(gy + 1) * block.side]
                        .iter()
                        .map(|p| p.seen),
                );
            }
            out
        })
        .collect();
    for (&(bx, by, bw, _), pixels) in blocks.iter().zip(&done) {
        for (row, chunk) in pixels.chunks(bw).enumerate() {
            let at = (by + row - first_y) * w + bx;
            samples[at..at + bw].copy_from_slice(chunk);
        }
    }
    (rays.into_inner(), camera_rays.into_inner())
}

/// One block's grid: its pixels and its border, row-major from (x0, y0), the corner left
/// above the block first.
struct Block<'p, 's> {
    tracer: &'p Tracer<'s>,
    measure: &'p Measure,
    s: &'p RenderSettings,
    x0: i64,
    y0: i64,
    side: usize,
    grid: Vec<Sample>,
    refined: Vec<bool>,
    ctx: &'p mut TraceCtx<'s>,
    camera_rays: u64,
}

impl Block<'_, '_> {
    fn trace(&mut self, sx: f64, sy: f64) -> Seen {
        self.tracer.trace_camera_at(sx, sy, self.ctx)
    }

    fn differs(&self, a: usize, b: usize, threshold: f64) -> bool {
        self.measure.distance(&self.grid[a], &self.grid[b]) > threshold
    }

    /// Supersamples grid point `i` unless it already was: a depth×depth grid of (jittered)
    /// rays averaged with the first sample.
    fn refine(&mut self, i: usize) {
        if std::mem::replace(&mut self.refined[i], true) {
            return;
        }
        let x = self.x0 + (i % self.side) as i64;
        let y = self.y0 + (i / self.side) as i64;
        // The hash of a pixel left of or above the picture takes its coordinate's bits.
        let (hx, hy) = (x as i32 as u32, y as i32 as u32);
        let n = self.s.aa_depth.max(1);
        let mut sum = self.grid[i].seen;
        for j in 0..n {
            for k in 0..n {
                let m = j * n + k;
                let jx = jitter_hash(hx, hy, 2 * m) * self.s.jitter;
                let jy = jitter_hash(hx, hy, 2 * m + 1) * self.s.jitter;
                let sx = x as f64 + (k as f64 + 0.5 + jx) / n as f64;
                let sy = y as f64 + (j as f64 + 0.5 + jy) / n as f64;
                let t = self.trace(sx, sy);
                sum.rgb += t.rgb;
                sum.clear += t.clear;
            }
        }
        self.camera_rays += (n * n) as u64;
        let count = (1 + n * n) as f64;
        self.grid[i] = self.measure.sample(Seen {
            rgb: sum.rgb / count,
            clear: sum.clear / count,
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::trace::Quality;
    use crate::scene::build::Scene;

    /// A white wall filling a 32×32 orthographic view 0.32 wide, with a black box over it.
    fn scene(black_box: &str) -> Scene {
        let text = format!(
            "#version 3.7; global_settings {{ assumed_gamma 1.0 }}
             camera {{ orthographic location <0,0,-5> look_at 0 right x*0.32 up y*0.32 }}
             plane {{ z, 0 pigment {{ rgb 1 }} finish {{ ambient 1 diffuse 0 }} }}
             box {{ {black_box} pigment {{ rgb 0 }} finish {{ ambient 1 diffuse 0 }} }}"
        );
        let mut parser = crate::sdl::Parser::new(crate::sdl::ParseOptions::default());
        parser.parse_str("aa1.pov", &text).expect("parses");
        crate::scene::build::build(&parser.scene, 32, 32).scene
    }

    /// Sub-sample rays of a 32×32 render: camera rays less the first pass and the 64 border
    /// rays left of and above the picture.
    fn supersamples(scene: &Scene, depth: u32, block: u32) -> u64 {
        let s = RenderSettings {
            width: 32,
            height: 32,
            antialias: Some(0.3),
            aa_depth: depth,
            jitter: 0.0,
            aa_block: block,
            ..RenderSettings::default()
        };
        let camera = crate::render::camera::Camera::of_scene(scene);
        let tracer = Tracer::new(scene, &camera, false, Quality::level(9));
        let mut samples: Vec<Seen> = (0..32 * 32)
            .map(|i| {
                let (x, y) = ((i % 32) as f64 + 0.5, (i / 32) as f64 + 0.5);
                tracer.trace_camera_at(x, y, &mut TraceCtx::default())
            })
            .collect();
        let (_, camera) = method1(&tracer, &mut samples, &s, 0.3);
        camera - 64
    }

    // The expected counts are povray's "Samples" for the same scenes and options
    // (scripts/measure_aa_method1.sh).

    #[test]
    fn a_refined_pixel_sets_off_its_right_neighbour() {
        // The edge lies in the left quarter of column 16: its first sample is white, its
        // refined colour grey, which then differs from the white column 17 as well.
        let edge = scene("<-1,-1,-1>, <0.0026,1,-0.1>");
        assert_eq!(supersamples(&edge, 3, 32), 32 * 3 * 9);
        assert_eq!(supersamples(&edge, 4, 32), 32 * 3 * 16);
        // +R1 refines with the centre again: nothing changes, nothing is set off.
        assert_eq!(supersamples(&edge, 1, 32), 32 * 2);
    }

    #[test]
    fn blocks_are_refined_on_their_own() {
        // In 16-wide blocks the edge's column 16 starts a block: column 15 is only the
        // block's border copy, compared but never refined.
        let edge = scene("<-1,-1,-1>, <0.0026,1,-0.1>");
        assert_eq!(supersamples(&edge, 3, 16), 32 * 2 * 9);
        assert_eq!(supersamples(&edge, 3, 4), 32 * 2 * 9);
    }

    #[test]
    fn a_pixel_is_compared_by_its_first_sample() {
        // The box's corner: the pixel right of its top row is refined (its left neighbour
        // differs) to grey, but the white pixel above it was compared with its first sample,
        // so it is not refined (povray: 711 samples; 720 if it were).
        let corner = scene("<-1,-1,-1>, <0.0026,0,-0.1>");
        assert_eq!(supersamples(&corner, 3, 32), 711);
        assert_eq!(supersamples(&corner, 2, 32), 316);
    }
}
