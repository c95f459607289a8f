//! Rendering a picture band by band, so that memory is bounded by a band of rows whatever the
//! picture's size: a 100000×100000 picture held whole would need over a terabyte.
//!
//! Every pixel is computed exactly as `render` computes it (same rays, same jitter, same
//! anti-aliasing decisions), so the pixels are the same; only their delivery differs. Method 1
//! anti-aliasing refines blocks of rows on their own (`aa1`), so with it a band holds whole
//! block rows and is given the first-pass row above it by the band before, so that no row is
//! traced twice and the ray counts agree too. Method 2 shares corner samples between rows and
//! is not banded: callers keep it in memory or refuse.

use super::trace::{Quality, Seen, Tracer};
use super::{aa1, film_of, film_rows, first_pass_rows, Film, RenderSettings};
use crate::scene::build::Scene;

/// Bytes a pixel costs while a picture is rendered and written whole: the first pass's
/// samples, anti-aliasing's converted copies and marks, the film, and the quantised planes
/// and file bytes of the writer (measured sizes of those buffers, rounded up).
pub const BYTES_PER_PIXEL_WHOLE: u64 = 176;

/// Bytes a pixel of a band costs: the same buffers, for the band's rows only.
const BYTES_PER_PIXEL_BAND: u64 = 200;

/// What a band of rows may take.
const BAND_BUDGET: u64 = 256 << 20;

/// The memory a picture rendered and written whole takes, about.
pub fn whole_picture_bytes(s: &RenderSettings) -> u64 {
    s.width as u64 * s.height as u64 * BYTES_PER_PIXEL_WHOLE
}

/// Whether `render_bands` can render with these settings (method 2 cannot).
pub fn can_band(s: &RenderSettings) -> bool {
    s.antialias.is_none() || s.sampling_method != 2
}

/// Rows a band holds within `BAND_BUDGET`, at least one.
pub fn band_rows(s: &RenderSettings) -> usize {
    let row = (s.width as u64 * BYTES_PER_PIXEL_BAND).max(1);
    ((BAND_BUDGET / row).max(1) as usize).min(s.height.max(1) as usize)
}

/// Renders the picture `rows` rows at a time, handing each finished band (a film of those rows,
/// top band first) to `sink`; returns (all rays, camera rays). `progress` is called once per
/// traced row. Panics on method 2 anti-aliasing (see `can_band`).
pub fn render_bands(
    scene: &Scene,
    s: &RenderSettings,
    rows: usize,
    progress: &(dyn Fn(u64) + Sync),
    sink: &mut dyn FnMut(&Film) -> Result<(), String>,
) -> Result<(u64, u64), String> {
    assert!(
        can_band(s),
        "method 2 anti-aliasing is not rendered in bands"
    );
    let map = super::photons::PhotonMap::shoot(scene);
    let camera = super::camera::Camera::of_scene(scene);
    let base = Tracer {
        photons: map.as_ref(),
        ..Tracer::new(scene, &camera, s.alpha, Quality::level(s.quality))
    };
    let cache = super::radiosity::pretrace(scene, s, &base);
    let tracer = super::with_radiosity(&base, cache.as_ref());
    let (w, h) = (s.width as usize, s.height as usize);
    let rows = rows.max(1);
    let (mut rays, mut camera_rays) = (cache.as_ref().map_or(0, |c| c.rays), 0);
    // Method 1 refines whole blocks, so its bands hold whole block rows, counted from the
    // window's top; each needs only the first pass of the row above it, which the band before
    // traced and hands on.
    let block = aa1::block_size(s);
    let top = aa1::block_top(s);
    let aligned = rows.div_ceil(block) * block;
    let mut above: Option<Vec<Seen>> = None;
    let mut y0 = 0;
    while y0 < h {
        let Some(threshold) = s.antialias else {
            let y1 = (y0 + rows).min(h);
            let film = film_rows(&tracer, s, y0..y1, scene.gamma, progress);
            rays += film.rays;
            camera_rays += film.camera_rays;
            sink(&Film {
                rays: 0,
                camera_rays: 0,
                ..film
            })?;
            y0 = y1;
            continue;
        };
        let y1 = if y0 < top {
            (y0 + aligned).min(top)
        } else {
            y0 + aligned
        }
        .min(h);
        let mut pass = first_pass_rows(&tracer, s, y0..y1, progress);
        rays += pass.rays;
        camera_rays += pass.camera_rays;
        let last = pass.samples[(y1 - 1 - y0) * w..].to_vec();
        let (r, c) = aa1::refine_rows(
            &tracer,
            &mut pass.samples,
            y0,
            above.as_deref(),
            s,
            threshold,
        );
        above = Some(last);
        rays += r;
        camera_rays += c;
        let film = film_of(&pass.samples, s, (y1 - y0) as u32, scene.gamma, (0, 0));
        sink(&film)?;
        y0 = y1;
    }
    Ok((rays, camera_rays))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::render;

    fn scene() -> Scene {
        let dir = std::env::temp_dir().join(format!("lancer-band-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("band.pov");
        std::fs::write(
            &path,
            "#version 3.7; global_settings { assumed_gamma 1.0 }
             camera { location <0, 1, -4> look_at <0, 0.5, 0> }
             light_source { <-5, 8, -6> rgb 1 }
             sphere { <0, 0.6, 0>, 0.6 pigment { rgbt <0.9, 0.3, 0.2, 0.3> } finish { phong 0.7 } }
             plane { y, 0 pigment { checker rgb 1 rgb 0.1 scale 0.3 } }",
        )
        .unwrap();
        let parsed = crate::api::parse_file(&path, Default::default());
        assert!(parsed.error.is_none());
        let _ = std::fs::remove_dir_all(&dir);
        crate::scene::build::build(&parsed.parser.scene, 37, 29).scene
    }

    fn banded(scene: &Scene, s: &RenderSettings, rows: usize) -> (Vec<f64>, (u64, u64)) {
        let mut out = Vec::new();
        let counts = render_bands(scene, s, rows, &|_| {}, &mut |f| {
            for (i, p) in f.pixels.iter().enumerate() {
                out.extend([p.x, p.y, p.z]);
                out.push(f.alpha.as_ref().map_or(1.0, |a| a[i]));
            }
            Ok(())
        })
        .unwrap();
        (out, counts)
    }

    /// Bands of any height give the picture and the ray counts of a whole render, bit for bit,
    /// with and without anti-aliasing, alpha and a partial-render window.
    #[test]
    fn bands_render_the_whole_picture_exactly() {
        let scene = scene();
        let windowed = super::super::Window {
            x0: 3,
            x1: 30,
            y0: 5,
            y1: 20,
        };
        for (aa, alpha, window) in [
            (None, false, None),
            (Some(0.1), false, None),
            (Some(0.1), true, Some(windowed)),
        ] {
            // Blocks of 4 rows, so that method 1's bands are several.
            let s = RenderSettings {
                width: 37,
                height: 29,
                antialias: aa,
                alpha,
                window,
                aa_block: 4,
                ..RenderSettings::default()
            };
            let whole = render(&scene, &s, &|_| {});
            let mut expect = Vec::new();
            for (i, p) in whole.pixels.iter().enumerate() {
                expect.extend([p.x, p.y, p.z]);
                expect.push(whole.alpha.as_ref().map_or(1.0, |a| a[i]));
            }
            for rows in [1, 2, 5, 29, 100] {
                let (got, counts) = banded(&scene, &s, rows);
                assert!(
                    got == expect,
                    "{rows} rows a band, aa {aa:?}, alpha {alpha}"
                );
                assert_eq!(counts, (whole.rays, whole.camera_rays), "{rows} rows");
            }
        }
    }

    #[test]
    fn bands_fit_the_budget() {
        let s = RenderSettings {
            width: 100_000,
            height: 100_000,
            ..RenderSettings::default()
        };
        let rows = band_rows(&s) as u64;
        assert!(rows >= 1 && rows * 100_000 * BYTES_PER_PIXEL_BAND <= BAND_BUDGET);
        assert_eq!(
            whole_picture_bytes(&s),
            10_000_000_000 * BYTES_PER_PIXEL_WHOLE
        );
    }
}
