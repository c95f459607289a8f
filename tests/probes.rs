//! Shading probes: tiny scenes in tests/probes/ that each isolate one POV-Ray 3.7 rule
//! (filter/transmit weighting, shadow filtering per crossing, Fresnel where rays leave glass,
//! highlight formulas, ...), compared with povray's own renders in tests/probes/ref/ (made by
//! scripts/make_probe_references.sh) pixel for pixel.
//!
//! Tolerance: every channel within 1 of POV-Ray's 8-bit value on at least 99% of pixels. The 1
//! allows for rounding of values that land on a quantisation boundary; the 1% allows for
//! pixels whose ray grazes an edge, where the two programs' floating-point paths may pick
//! different sides.
//!
//! A probe whose first line is `// options: +Q2 +UA ...` is rendered with those POV-Ray options
//! by both programs; with `+UA` the alpha channel and the straight (unpremultiplied) colour are
//! compared the same way.
//!
//! Probes with `text` objects read POV-Ray's fonts from Debian's povray-includes (CI installs
//! it); where that is not installed they are skipped, saying so.

use std::path::Path;

use lancer::cli::{make_job, RenderArgs};
use lancer::render::{Film, RenderSettings};
use lancer::scene::build::GammaMode;

/// The probe's `// options:` line, parsed as lancer's command line would.
fn probe_settings(scene: &Path, base: &RenderSettings) -> Result<RenderSettings, String> {
    let text = std::fs::read_to_string(scene).map_err(|e| e.to_string())?;
    let opts: Vec<String> = text
        .lines()
        .next()
        .and_then(|l| l.strip_prefix("// options:"))
        .map(|o| o.split_whitespace().map(String::from).collect())
        .unwrap_or_default();
    if opts.is_empty() {
        return Ok(base.clone());
    }
    let args = RenderArgs {
        scene: Some(scene.to_path_buf()),
        ..RenderArgs::default()
    };
    let mut s = make_job(args, &opts)?.settings;
    s.width = base.width;
    s.height = base.height;
    s.antialias = base.antialias;
    Ok(s)
}

/// Where probes' `text` objects find their fonts (the system include directory lancer
/// searches by default).
const FONT_DIR: &str = "/usr/share/povray-3.7/include";

/// Whether the probe has a `text` object while POV-Ray's fonts are not installed.
fn needs_missing_fonts(scene: &Path) -> bool {
    let text = std::fs::read_to_string(scene).unwrap_or_default();
    text.contains("text {") && !Path::new(FONT_DIR).join("timrom.ttf").exists()
}

/// RGBA bytes as a PNG with straight alpha holds them (RGB with alpha 255 without `+UA`).
fn rgba8(film: &Film) -> Vec<[u8; 4]> {
    let q = |v: f64| (v.clamp(0.0, 1.0) * 255.0 + 0.5).floor() as u8;
    film.pixels
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let a = film.alpha.as_ref().map_or(1.0, |a| a[i]);
            // Dividing linear light by alpha, in the working space.
            let k = match film.gamma {
                GammaMode::Corrected(g) => a.powf(1.0 / g),
                GammaMode::None => a,
            };
            let straight = |v: f64| if a <= 0.0 { 0.0 } else { film.encode(v / k) };
            [q(straight(p.x)), q(straight(p.y)), q(straight(p.z)), q(a)]
        })
        .collect()
}

#[test]
fn shading_probes_match_povray() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/probes");
    let settings = RenderSettings {
        width: 80,
        height: 60,
        antialias: None,
        ..RenderSettings::default()
    };
    let mut failures = Vec::new();
    let mut count = 0;
    let mut entries: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "pov"))
        .collect();
    entries.sort();
    for scene in entries {
        let name = scene.file_stem().unwrap().to_string_lossy().into_owned();
        if needs_missing_fonts(&scene) {
            eprintln!("skipped probe {name}: its fonts are not in {FONT_DIR} (apt-get install povray-includes)");
            continue;
        }
        let reference = image::open(dir.join("ref").join(format!("{name}.png")))
            .expect("probe reference")
            .to_rgba8();
        let settings = match probe_settings(&scene, &settings) {
            Ok(s) => s,
            Err(e) => {
                failures.push(format!("{name}: options: {e}"));
                continue;
            }
        };
        let film = match lancer::api::render_file(&scene, &[], &settings) {
            Ok(f) => f,
            Err(e) => {
                failures.push(format!("{name}: {e}"));
                continue;
            }
        };
        let ours = rgba8(&film);
        let mut off = 0usize;
        let mut worst = 0i32;
        for (px, r) in ours.iter().zip(reference.pixels()) {
            let d = (0..4)
                .map(|c| (px[c] as i32 - r[c] as i32).abs())
                .max()
                .unwrap();
            worst = worst.max(d);
            if d > 1 {
                off += 1;
            }
        }
        let total = ours.len();
        if off * 100 > total {
            failures.push(format!(
                "{name}: {off} of {total} pixels differ by more than 1 (worst {worst})"
            ));
        }
        count += 1;
    }
    assert!(
        count >= 20,
        "expected the probes in tests/probes, found {count}"
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
