//! Shading probes: tiny scenes in tests/probes/ that each isolate one POV-Ray 3.7 rule
//! (filter/transmit weighting, shadow filtering per crossing, Fresnel where rays leave glass,
//! highlight formulas, ...), compared with povray's own renders in tests/probes/ref/ (made by
//! scripts/make_probe_references.sh) pixel for pixel.
//!
//! Tolerance: every channel within 1 of POV-Ray's 8-bit value on at least 99% of pixels. The 1
//! allows for rounding of values that land on a quantisation boundary; the 1% allows for
//! pixels whose ray grazes an edge, where the two programs' floating-point paths may pick
//! different sides.

use std::path::Path;

use lancer::render::RenderSettings;

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
        let reference = image::open(dir.join("ref").join(format!("{name}.png")))
            .expect("probe reference")
            .to_rgb8();
        let film = match lancer::api::render_file(&scene, &[], &settings) {
            Ok(f) => f,
            Err(e) => {
                failures.push(format!("{name}: {e}"));
                continue;
            }
        };
        let ours = lancer::output::to_rgb8(&film);
        let mut off = 0usize;
        let mut worst = 0i32;
        for (px, r) in ours.chunks(3).zip(reference.pixels()) {
            let d = (0..3)
                .map(|c| (px[c] as i32 - r[c] as i32).abs())
                .max()
                .unwrap();
            worst = worst.max(d);
            if d > 1 {
                off += 1;
            }
        }
        let total = ours.len() / 3;
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
