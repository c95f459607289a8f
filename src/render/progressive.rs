//! Progressive rendering for the preview window: a view is traced coarse to fine (one camera
//! ray per block of 2ⁿ×2ⁿ pixels, then each block split in four), every level reusing the
//! samples of the coarser ones, so that the last level is exactly the batch renderer's first
//! pass and, after the same anti-aliasing, the same pixels as `render`.
//!
//! The toolbox's switches (shadows, reflection, ...) are the flags of POV-Ray's quality levels
//! (`Quality`), set one by one instead of through `+Q`.

use std::sync::atomic::{AtomicU64, Ordering};

use rayon::prelude::*;

use super::camera::Camera;
use super::photons::PhotonMap;
use super::trace::{Quality, Seen, TraceCtx, Tracer};
use super::{aa, aa1, film_of, radiosity, with_radiosity, Film, RenderSettings};
use crate::scene::build::Scene;

/// What the preview switches beyond `RenderSettings`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Switches {
    pub quality: Quality,
    /// Radiosity's pretrace and cache (when the scene has radiosity).
    pub radiosity: bool,
    /// The photon map (when the scene shoots photons).
    pub photons: bool,
}

impl Switches {
    /// The switches a batch render with these settings uses.
    pub fn of(s: &RenderSettings) -> Switches {
        Switches {
            quality: Quality::level(s.quality),
            radiosity: true,
            photons: true,
        }
    }
}

/// One view of a scene (camera, settings and switches fixed) while it refines.
pub struct View<'a> {
    tracer: Tracer<'a>,
    s: &'a RenderSettings,
}

/// The photon map a scene's views share: shot once per scene, not once per view, since
/// photons do not depend on the camera.
pub fn shoot_photons(scene: &Scene) -> Option<PhotonMap> {
    PhotonMap::shoot(scene)
}

/// Runs `f` on the view of `scene` through `camera` with `s` and `sw`; radiosity's pretrace,
/// which depends on the camera, runs first when switched on.
pub fn with_view<R>(
    scene: &Scene,
    camera: &Camera,
    s: &RenderSettings,
    sw: &Switches,
    photons: Option<&PhotonMap>,
    f: impl FnOnce(&View) -> R,
) -> R {
    let base = Tracer {
        photons: photons.filter(|_| sw.photons),
        ..Tracer::new(scene, camera, s.alpha, sw.quality)
    };
    let cache = if sw.radiosity {
        radiosity::pretrace(scene, s, &base)
    } else {
        None
    };
    let tracer = with_radiosity(&base, cache.as_ref());
    f(&View { tracer, s })
}

/// The samples of a view so far.
pub struct Progress {
    samples: Vec<Seen>,
    /// The block size of the last finished level; None before the first.
    done: Option<usize>,
    pub rays: u64,
    pub camera_rays: u64,
}

impl Progress {
    /// The block size of the last finished level (1 when every pixel is traced).
    pub fn block(&self) -> Option<usize> {
        self.done
    }
}

impl View<'_> {
    pub fn start(&self) -> Progress {
        let n = self.s.width as usize * self.s.height as usize;
        Progress {
            samples: vec![Seen::default(); n],
            done: None,
            rays: 0,
            camera_rays: 0,
        }
    }

    /// Traces the pixels at the corners of the `block`×`block` grid that coarser levels did
    /// not trace. Returns false, leaving `p` unusable for further levels, when `cancel` says
    /// stop (checked once per band of rows).
    pub fn level(
        &self,
        p: &mut Progress,
        block: usize,
        cancel: &(dyn Fn() -> bool + Sync),
    ) -> bool {
        let s = self.s;
        let w = s.width as usize;
        let b = block.max(1);
        let coarser = p.done;
        let rays = AtomicU64::new(0);
        let camera_rays = AtomicU64::new(0);
        let stopped = std::sync::atomic::AtomicBool::new(false);
        p.samples.par_chunks_mut(w * b).enumerate().for_each_init(
            TraceCtx::default,
            |ctx, (band, rows)| {
                if stopped.load(Ordering::Relaxed) || cancel() {
                    stopped.store(true, Ordering::Relaxed);
                    return;
                }
                let y = band * b;
                let mut traced = 0;
                for x in (0..w).step_by(b) {
                    let old = coarser.is_some_and(|c| x.is_multiple_of(c) && y.is_multiple_of(c));
                    if old || !s.inside(x, y) {
                        continue;
                    }
                    rows[x] = self
                        .tracer
                        .trace_camera_at(x as f64 + 0.5, y as f64 + 0.5, ctx);
                    traced += 1;
                }
                camera_rays.fetch_add(traced, Ordering::Relaxed);
                rays.fetch_add(std::mem::take(&mut ctx.rays), Ordering::Relaxed);
            },
        );
        p.rays += rays.into_inner();
        p.camera_rays += camera_rays.into_inner();
        if stopped.into_inner() {
            return false;
        }
        p.done = Some(b);
        true
    }

    /// The picture so far, each block filled with its traced corner, as 8-bit RGB. Only the
    /// corners are converted (the conversion costs as much as a coarse level otherwise).
    pub fn preview_rgb8(&self, p: &Progress) -> Vec<u8> {
        let s = self.s;
        let (w, h) = (s.width as usize, s.height as usize);
        let b = p.done.unwrap_or(1);
        let gamma = self.tracer.scene.gamma;
        if b == 1 {
            return crate::output::to_rgb8(&film_of(&p.samples, s, s.height, gamma, (0, 0)));
        }
        let (cw, ch) = (w.div_ceil(b), h.div_ceil(b));
        let corners: Vec<Seen> = (0..cw * ch)
            .map(|i| p.samples[(i / cw) * b * w + (i % cw) * b])
            .collect();
        let small = RenderSettings {
            width: cw as u32,
            height: ch as u32,
            ..s.clone()
        };
        let rgb = crate::output::to_rgb8(&film_of(&corners, &small, ch as u32, gamma, (0, 0)));
        let mut out = vec![0u8; w * h * 3];
        for (y, row) in out.chunks_mut(w * 3).enumerate() {
            let src = &rgb[(y / b) * cw * 3..];
            for (x, px) in row.chunks_mut(3).enumerate() {
                px.copy_from_slice(&src[(x / b) * 3..(x / b) * 3 + 3]);
            }
        }
        out
    }

    /// The finished picture: anti-aliasing as the batch render does it, over the samples of
    /// the finest level (which must have been block size 1). Method 2 does not use the first
    /// pass and traces the picture anew.
    pub fn finish(&self, mut p: Progress) -> Film {
        let s = self.s;
        debug_assert_eq!(p.done, Some(1));
        let gamma = self.tracer.scene.gamma;
        match s.antialias {
            Some(threshold) if s.sampling_method == 2 => {
                let pass = aa::method2(&self.tracer, s, threshold, &|_| {});
                film_of(
                    &pass.samples,
                    s,
                    s.height,
                    gamma,
                    (pass.rays, pass.camera_rays),
                )
            }
            threshold => {
                if let Some(threshold) = threshold {
                    let (rays, camera_rays) =
                        aa1::method1(&self.tracer, &mut p.samples, s, threshold);
                    p.rays += rays;
                    p.camera_rays += camera_rays;
                }
                film_of(&p.samples, s, s.height, gamma, (p.rays, p.camera_rays))
            }
        }
    }
}

/// The block sizes from `start` (a power of two) down to one pixel.
pub fn levels(start: usize) -> impl Iterator<Item = usize> {
    let start = start.max(1).next_power_of_two();
    std::iter::successors(Some(start), |&b| (b > 1).then_some(b / 2))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn levels_halve_to_one() {
        assert_eq!(levels(8).collect::<Vec<_>>(), vec![8, 4, 2, 1]);
        assert_eq!(levels(1).collect::<Vec<_>>(), vec![1]);
        assert_eq!(levels(6).collect::<Vec<_>>(), vec![8, 4, 2, 1]);
    }

    fn scene(text: &str, w: u32, h: u32) -> Scene {
        let mut parser = crate::sdl::Parser::new(crate::sdl::ParseOptions::default());
        parser.parse_str("test.pov", text).expect("parses");
        crate::scene::build::build(&parser.scene, w, h).scene
    }

    /// `with_view` through the scene's own camera, without photons.
    fn view_of<R>(sc: &Scene, s: &RenderSettings, f: impl FnOnce(&View) -> R) -> R {
        with_view(sc, &Camera::of_scene(sc), s, &Switches::of(s), None, f)
    }

    /// The refined picture must be the batch render's, sample for sample (exactly: the same
    /// rays through the same code), with and without anti-aliasing, at a size that is not a
    /// multiple of the coarsest block.
    #[test]
    fn refined_view_is_the_batch_render() {
        let text = "global_settings { assumed_gamma 1 }
            camera { location <0, 1, -4> look_at 0 }
            light_source { <4, 5, -3> 1 }
            sphere { 0, 1 pigment { checker rgb 1 rgb <1, 0, 0> scale 0.3 }
                finish { reflection 0.3 phong 0.5 } }
            plane { y, -1 pigment { rgb 0.7 } }";
        for aa in [None, Some(0.1)] {
            let s = RenderSettings {
                width: 37,
                height: 29,
                antialias: aa,
                ..RenderSettings::default()
            };
            let sc = scene(text, s.width, s.height);
            let batch = crate::render::render(&sc, &s, &|_| {});
            let film = view_of(&sc, &s, |v| {
                let mut p = v.start();
                for b in levels(8) {
                    assert!(v.level(&mut p, b, &|| false));
                }
                v.finish(p)
            });
            assert_eq!(film.pixels, batch.pixels);
            assert_eq!(film.rays, batch.rays);
        }
    }

    /// A coarse level's picture is each block's corner pixel, converted as the final one.
    #[test]
    fn coarse_picture_fills_blocks_with_their_corner() {
        let s = RenderSettings {
            width: 21,
            height: 11,
            ..RenderSettings::default()
        };
        let sc = scene(
            "camera { location -3*z look_at 0 } light_source { <2, 3, -4> 1 }
             sphere { 0, 1 pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } } }",
            s.width,
            s.height,
        );
        view_of(&sc, &s, |v| {
            let mut p = v.start();
            assert!(v.level(&mut p, 4, &|| false));
            let coarse = v.preview_rgb8(&p);
            for b in [2, 1] {
                assert!(v.level(&mut p, b, &|| false));
            }
            let fine = v.preview_rgb8(&p);
            for y in 0..11 {
                for x in 0..21 {
                    let (i, c) = ((y * 21 + x) * 3, ((y - y % 4) * 21 + x - x % 4) * 3);
                    assert_eq!(coarse[i..i + 3], fine[c..c + 3], "pixel {x},{y}");
                }
            }
        });
    }

    #[test]
    fn cancelled_level_reports_it() {
        let s = RenderSettings::default();
        let sc = scene("sphere { 0, 1 pigment { rgb 1 } }", s.width, s.height);
        view_of(&sc, &s, |v| {
            let mut p = v.start();
            assert!(!v.level(&mut p, 4, &|| true));
            assert_eq!(p.block(), None);
        });
    }
}
