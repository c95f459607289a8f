//! The picture must not depend on the thread count (frames split across machines must match
//! byte for byte), and every output format must be readable.

use std::path::Path;

use lancer::output::{write, FileType, OutputSpec};
use lancer::render::{RenderSettings, Window};

fn render_with_threads(n: usize, settings: &RenderSettings) -> Vec<u8> {
    render_scene_with_threads("scenes/glass.pov", n, settings)
}

fn render_scene_with_threads(rel: &str, n: usize, settings: &RenderSettings) -> Vec<u8> {
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join(rel);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(n)
        .build()
        .unwrap();
    let film = pool
        .install(|| lancer::api::render_file(&scene, &[], settings))
        .unwrap();
    lancer::output::to_rgb8(&film)
}

#[test]
fn same_bytes_for_any_thread_count() {
    // Anti-aliasing with jitter on is the case most likely to depend on scheduling.
    let s = RenderSettings {
        width: 96,
        height: 72,
        antialias: Some(0.1),
        ..RenderSettings::default()
    };
    let one = render_with_threads(1, &s);
    assert_eq!(one, render_with_threads(2, &s));
    assert_eq!(one, render_with_threads(5, &s));
}

#[test]
fn media_same_bytes_for_any_thread_count() {
    // Adaptive media sampling and scattering with shadow rays from every sample.
    let s = RenderSettings {
        width: 64,
        height: 48,
        antialias: Some(0.1),
        ..RenderSettings::default()
    };
    for rel in [
        "tests/probes_approx/media_density.pov",
        "tests/probes/media_spotlight_beam.pov",
    ] {
        let one = render_scene_with_threads(rel, 1, &s);
        assert_eq!(one, render_scene_with_threads(rel, 2, &s), "{rel}");
        assert_eq!(one, render_scene_with_threads(rel, 5, &s), "{rel}");
    }
}

#[test]
fn method2_same_bytes_for_any_thread_count_and_row_split() {
    let s = RenderSettings {
        width: 96,
        height: 72,
        antialias: Some(0.1),
        sampling_method: 2,
        ..RenderSettings::default()
    };
    let one = render_with_threads(1, &s);
    assert_eq!(one, render_with_threads(2, &s));
    assert_eq!(one, render_with_threads(5, &s));
    // A method-2 pixel depends on nothing outside itself (its corners and its own
    // sub-samples), so a picture rendered as bands of rows, as when a frame is split across
    // machines, must have the bands' pixels byte for byte.
    let row = 96 * 3;
    for (y0, y1) in [(0, 29), (29, 72)] {
        let band = RenderSettings {
            window: Some(Window {
                x0: 0,
                x1: 96,
                y0,
                y1,
            }),
            ..s.clone()
        };
        let part = render_with_threads(2, &band);
        let rows = y0 as usize * row..y1 as usize * row;
        assert_eq!(part[rows.clone()], one[rows], "rows {y0}..{y1}");
    }
}

#[test]
fn png16_and_exr_are_written_and_readable() {
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/phong.pov");
    let s = RenderSettings {
        width: 32,
        height: 24,
        ..RenderSettings::default()
    };
    let film = lancer::api::render_file(&scene, &[], &s).unwrap();
    let dir = std::env::temp_dir().join(format!("lancer-out-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p16 = dir.join("a.png");
    write(&film, &p16, &OutputSpec::new(FileType::Png).with_bits(16)).unwrap();
    let img = image::open(&p16).unwrap();
    assert!(matches!(img, image::DynamicImage::ImageRgb16(_)));
    let exr = dir.join("a.exr");
    write(&film, &exr, &OutputSpec::new(FileType::Exr)).unwrap();
    let img = image::open(&exr).unwrap().to_rgb32f();
    assert_eq!(img.dimensions(), (32, 24));
    // The 8-bit encoding of the EXR's linear value equals what the 8-bit PNG holds.
    let lin = img.get_pixel(16, 12)[0] as f64;
    let enc = (lancer::render::srgb_encode(lin.min(1.0)) * 255.0 + 0.5).floor() as u8;
    assert_eq!(enc, lancer::output::to_rgb8(&film)[(12 * 32 + 16) * 3]);
    let leftovers: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().ends_with(".tmp"))
        .collect();
    assert!(leftovers.is_empty(), "temporary files left behind");
}
