//! Probes whose objects lancer draws by POV-Ray's measured rules but whose every pixel it
//! does not yet reproduce: tests/probes_approx/*.pov against povray's renders in
//! tests/probes_approx/ref/ (made like tests/probes/ref by scripts/make_probe_references.sh,
//! pointed at this directory), at 80x60 without anti-aliasing.
//!
//! Tolerance: SSIM >= 0.94 per probe. `julia_fractal`: the shapes' sizes and outlines match
//! (the rules in geom::julia), but hypercomplex normals differ from povray's on ~15% of the
//! pixels (its normal rule is not measured yet), which gives 0.95; the margin allows for
//! last-bit differences of grazing rays. `parametric`: lancer draws a fine smooth mesh where
//! povray subdivides (u, v) space per ray; outlines and uv texture agree (0.98), shading
//! differs a little near the surface's inner edge.
//! `media_density` (0.998): varying densities are sampled adaptively, and povray's rule
//! for halving a step is not measured exactly.

use std::path::Path;

use lancer::render::RenderSettings;
use lancer::ssim::{ssim, Picture};

#[test]
fn approximate_probes_match_povray() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/probes_approx");
    let settings = RenderSettings {
        width: 80,
        height: 60,
        antialias: None,
        ..RenderSettings::default()
    };
    let mut failures = Vec::new();
    let mut entries: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "pov"))
        .collect();
    entries.sort();
    assert!(!entries.is_empty(), "no probes in {}", dir.display());
    for scene in entries {
        let name = scene.file_stem().unwrap().to_string_lossy().into_owned();
        let reference = Picture::load(&dir.join("ref").join(format!("{name}.png"))).unwrap();
        let film = lancer::api::render_file(&scene, &[], &settings).unwrap();
        let q = |v: f64| (film.encode(v).clamp(0.0, 1.0) * 255.0 + 0.5).floor() as u8;
        let rgb: Vec<u8> = film
            .pixels
            .iter()
            .flat_map(|p| [q(p.x), q(p.y), q(p.z)])
            .collect();
        let ours = Picture::from_rgb8(film.width, film.height, &rgb);
        let s = ssim(&reference, &ours).unwrap();
        if s < 0.94 {
            failures.push(format!("{name}: SSIM {s:.4} < 0.94"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
