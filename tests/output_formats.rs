//! Every output file type, written from one tiny render and read back: sizes, bit depths,
//! alpha, PNG chunks; and, where `povray` is on PATH, compared with POV-Ray's own files of the
//! same scenes (lancer's 8-bit render of these scenes is identical to POV-Ray's, so what is
//! compared is the writing). Exact: 5-, 8- and 12-bit PNG and PPM samples, Targa and BMP
//! pixels, Targa RLE packets, Bayer dithering, straight alpha, Radiance RGBE bytes. Within a
//! tolerance, with the reason: 16-bit samples (±1: the last bit depends on floating-point
//! detail of the render), JPEG (a different encoder), EXR (POV-Ray writes half floats, lancer
//! full floats), error-diffusion dithering (a different value one pixel down the line moves
//! the pattern after it; the count of differing samples is bounded instead).

use std::path::{Path, PathBuf};
use std::process::Command;

use image::DynamicImage;
use lancer::output::{write, DitherMethod, FileGamma, FileType, OutputSpec};
use lancer::render::{Film, RenderSettings};

const W: u32 = 48;
const H: u32 = 16;

/// A colour ramp on a plane facing the camera and a lit sphere: many distinct values.
const RAMP: &str = "#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,0,-3> look_at <0,0,0> right x*3 up y }
light_source { <-3,4,-5> rgb 1 }
plane { z, 1 pigment { gradient x color_map { [0 rgb <0,0.02,1>] [1 rgb <1,0.6,0.05>] }
  scale 6 translate -3*x } finish { ambient 1 diffuse 0 } }
sphere { <1.4,0,0>, 0.7 pigment { rgb <0.9,0.5,0.2> } finish { ambient 0.1 diffuse 0.8 } }
";

/// A half-transparent background behind an opaque and a partly transmitting sphere.
const ALPHA: &str = "#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,0,-3> look_at <0,0,0> right x*3 up y }
background { rgbt <0.2,0.3,0.5,0.5> }
light_source { <-3,4,-5> rgb 1 }
sphere { <-1,0,0>, 0.7 pigment { rgb <0.2,0.8,0.3> } }
sphere { <1,0,0>, 0.7 pigment { rgbt <0.9,0.5,0.2,0.4> } }
";

/// A directory of the running test's own: the tests run in parallel and several write files
/// of the same names (ramp.pov, g1.png), so a shared one let one test read another's
/// half-written scene (seen once in CI: an empty ramp.pov rendered without gamma handling).
fn scratch() -> PathBuf {
    let test = std::thread::current()
        .name()
        .unwrap_or("main")
        .replace("::", "-");
    let d = std::env::temp_dir().join(format!(
        "lancer-output-formats-{}/{test}",
        std::process::id()
    ));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn scene(name: &str, text: &str) -> PathBuf {
    let p = scratch().join(name);
    std::fs::write(&p, text).unwrap();
    p
}

fn render(scene: &Path, alpha: bool) -> Film {
    let s = RenderSettings {
        width: W,
        height: H,
        antialias: None,
        alpha,
        ..RenderSettings::default()
    };
    lancer::api::render_file(scene, &[], &s).unwrap()
}

fn spec(t: FileType) -> OutputSpec {
    OutputSpec::new(t)
}

fn ours(film: &Film, name: &str, spec: &OutputSpec) -> PathBuf {
    let p = scratch().join("lancer").join(name);
    std::fs::create_dir_all(p.parent().unwrap()).unwrap();
    write(film, &p, spec).unwrap();
    p
}

fn open(p: &Path) -> DynamicImage {
    image::ImageReader::open(p)
        .unwrap()
        .with_guessed_format()
        .unwrap()
        .decode()
        .unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

/// Samples as integers (8- or 16-bit as stored), with the alpha channel when there is one.
fn samples(img: &DynamicImage) -> Vec<u32> {
    match img {
        DynamicImage::ImageRgb8(i) => i.as_raw().iter().map(|&v| v as u32).collect(),
        DynamicImage::ImageRgba8(i) => i.as_raw().iter().map(|&v| v as u32).collect(),
        DynamicImage::ImageRgb16(i) => i.as_raw().iter().map(|&v| v as u32).collect(),
        DynamicImage::ImageRgba16(i) => i.as_raw().iter().map(|&v| v as u32).collect(),
        other => panic!("unexpected colour type {:?}", other.color()),
    }
}

/// POV-Ray's PPM keeps maxval below 256 for 5..8 bits and 16-bit samples above; read the raw
/// samples (the image crate rescales small maxvals).
fn ppm_samples(p: &Path) -> (u32, Vec<u32>) {
    let d = std::fs::read(p).unwrap();
    let mut fields = Vec::new();
    let mut i = 0;
    while fields.len() < 4 {
        while d[i].is_ascii_whitespace() {
            i += 1;
        }
        if d[i] == b'#' {
            while d[i] != b'\n' {
                i += 1;
            }
            continue;
        }
        let start = i;
        while !d[i].is_ascii_whitespace() {
            i += 1;
        }
        fields.push(String::from_utf8_lossy(&d[start..i]).into_owned());
    }
    let max: u32 = fields[3].parse().unwrap();
    let body = &d[i + 1..];
    let s = if max > 255 {
        body.chunks(2)
            .map(|c| u16::from_be_bytes([c[0], c[1]]) as u32)
            .collect()
    } else {
        body.iter().map(|&v| v as u32).collect()
    };
    (max, s)
}

/// BMP pixels top-down as RGB(A), read by hand: the image crate ignores the fourth byte of a
/// 32-bit BI_RGB file, where POV-Ray and lancer keep alpha.
fn bmp_samples(p: &Path) -> Vec<u32> {
    let d = std::fs::read(p).unwrap();
    let w = i32::from_le_bytes(d[18..22].try_into().unwrap()) as usize;
    let h = i32::from_le_bytes(d[22..26].try_into().unwrap()) as usize;
    let n = u16::from_le_bytes([d[28], d[29]]) as usize / 8;
    let stride = (w * n).div_ceil(4) * 4;
    let mut out = Vec::new();
    for y in (0..h).rev() {
        for x in 0..w {
            let px = &d[54 + y * stride + x * n..][..n];
            out.extend([px[2], px[1], px[0]].iter().map(|&v| v as u32));
            if n == 4 {
                out.push(px[3] as u32);
            }
        }
    }
    out
}

fn png_info(p: &Path) -> (Option<u32>, bool, Vec<u8>) {
    let dec = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(p).unwrap()));
    let reader = dec.read_info().unwrap();
    let info = reader.info();
    (
        info.gama_chunk.map(|g| g.into_scaled()),
        info.srgb.is_some(),
        info.sbit.as_deref().unwrap_or(&[]).to_vec(),
    )
}

#[test]
fn every_type_is_written_and_reads_back() {
    let film = render(&scene("ramp.pov", RAMP), false);
    let rgb8: Vec<u32> = lancer::output::to_rgb8(&film)
        .iter()
        .map(|&v| v as u32)
        .collect();
    // Lossless 8-bit types hold exactly the 8-bit samples.
    for (t, name) in [
        (FileType::Png, "a.png"),
        (FileType::Tga, "a.tga"),
        (FileType::TgaRle, "c.tga"),
    ] {
        let img = open(&ours(&film, name, &spec(t)));
        assert_eq!(img.width(), W);
        assert_eq!(samples(&img), rgb8, "{name}");
    }
    assert_eq!(
        bmp_samples(&ours(&film, "a.bmp", &spec(FileType::Bmp))),
        rgb8
    );
    let (max, s) = ppm_samples(&ours(&film, "a.ppm", &spec(FileType::Ppm)));
    assert_eq!((max, s), (255, rgb8.clone()));
    // Bit depths.
    let p5 = ours(&film, "5.png", &spec(FileType::Png).with_bits(5));
    let img = open(&p5);
    assert!(matches!(img, DynamicImage::ImageRgb8(_)));
    assert_eq!(png_info(&p5).2, vec![5, 5, 5]);
    // 5-bit samples stored with their top bits repeated below them.
    assert!(samples(&img)
        .iter()
        .all(|&v| v == (v >> 3) << 3 | (v >> 3) >> 2));
    let p12 = ours(&film, "12.png", &spec(FileType::Png).with_bits(12));
    assert!(matches!(open(&p12), DynamicImage::ImageRgb16(_)));
    let (gama, srgb, sbit) = png_info(&p12);
    assert_eq!((gama, srgb, sbit), (Some(45455), true, vec![12, 12, 12]));
    let (max, s) = ppm_samples(&ours(&film, "12.ppm", &spec(FileType::Ppm).with_bits(12)));
    assert_eq!(max, 4095);
    assert!(s.iter().all(|&v| v <= 4095));
    // File gamma: a power curve and its gAMA, no sRGB chunk.
    let mut g = spec(FileType::Png);
    g.file_gamma = FileGamma::Power(2.2);
    let (gama, srgb, _) = png_info(&ours(&film, "g.png", &g));
    assert_eq!((gama, srgb), (Some(45455), false));
    g.file_gamma = FileGamma::Power(1.0);
    assert_eq!(png_info(&ours(&film, "g1.png", &g)).0, Some(100000));
    // JPEG: lossy but close.
    let img = open(&ours(&film, "a.jpg", &spec(FileType::Jpeg)));
    let s = samples(&img);
    let mean = s
        .iter()
        .zip(&rgb8)
        .map(|(a, b)| a.abs_diff(*b) as f64)
        .sum::<f64>()
        / s.len() as f64;
    assert!(mean < 3.0, "JPEG mean difference {mean}");
    // HDR and EXR: linear light, to float precision in EXR and within RGBE's 8-bit mantissa
    // (relative to the pixel's largest channel) in HDR.
    for name in ["a.hdr", "a.exr"] {
        let t = FileType::from_path(Path::new(name));
        let img = open(&ours(&film, name, &spec(t))).to_rgb32f();
        assert_eq!(img.dimensions(), (W, H));
        for (px, v) in img.as_raw().chunks(3).zip(&film.pixels) {
            let lin = [v.x, v.y, v.z].map(|c| film.linear(c));
            let top = lin.iter().fold(0.0f64, |a, &b| a.max(b));
            let tol = if t == FileType::Hdr {
                top / 128.0
            } else {
                1e-6
            };
            for c in 0..3 {
                assert!(
                    (px[c] as f64 - lin[c]).abs() <= tol,
                    "{name}: {px:?} vs {lin:?}"
                );
            }
        }
    }
    // Nothing left behind by the atomic writes.
    let dir = scratch().join("lancer");
    assert!(std::fs::read_dir(&dir)
        .unwrap()
        .flatten()
        .all(|e| !e.file_name().to_string_lossy().ends_with(".tmp")));
}

#[test]
fn alpha_is_straight_except_in_exr() {
    // Names of its own: the tests run at once in one process and share the scratch directory,
    // and every_type_is_written_and_reads_back writes a.png, a.tga, ... there too.
    let film = render(&scene("alpha.pov", ALPHA), true);
    let png = samples(&open(&ours(&film, "alpha.png", &spec(FileType::Png))));
    // The corner sees only the background rgbt <0.2,0.3,0.5,0.5>: POV-Ray writes
    // [124 149 188 128] there.
    assert_eq!(&png[..4], &[124, 149, 188, 128]);
    let p16 = open(&ours(
        &film,
        "alpha16.png",
        &spec(FileType::Png).with_bits(16),
    ));
    assert!(matches!(p16, DynamicImage::ImageRgba16(_)));
    let tga = samples(&open(&ours(&film, "alpha.tga", &spec(FileType::Tga))));
    assert_eq!(tga, png);
    let rle = samples(&open(&ours(
        &film,
        "alpha-rle.tga",
        &spec(FileType::TgaRle),
    )));
    assert_eq!(rle, png);
    assert_eq!(
        bmp_samples(&ours(&film, "alpha.bmp", &spec(FileType::Bmp))),
        png
    );
    // Types without alpha get the colour over black: [89 108 137] in the corner.
    let (_, ppm) = ppm_samples(&ours(&film, "alpha.ppm", &spec(FileType::Ppm)));
    assert_eq!(&ppm[..3], &[89, 108, 137]);
    // EXR: associated alpha, so the corner's colour is half the background's linear value.
    let exr = open(&ours(&film, "alpha.exr", &spec(FileType::Exr))).to_rgba32f();
    let c = exr.get_pixel(0, 0).0;
    assert!(
        (c[0] - 0.1).abs() < 1e-5 && (c[3] - 0.5).abs() < 1e-5,
        "{c:?}"
    );
}

#[test]
fn dithering_changes_only_what_it_should() {
    let film = render(&scene("ramp.pov", RAMP), false);
    let plain = samples(&open(&ours(
        &film,
        "plain.png",
        &spec(FileType::Png).with_bits(5),
    )));
    for m in ["b2", "b3", "b4", "d1", "d2", "fs"] {
        let mut s = spec(FileType::Png).with_bits(5);
        s.dither = true;
        s.dither_method = DitherMethod::parse(m).unwrap();
        let d = samples(&open(&ours(&film, &format!("dither-{m}.png"), &s)));
        // Every sample moves by at most one 5-bit step in Bayer dithering and stays close in
        // error diffusion; some move.
        let steps: Vec<i32> = d
            .iter()
            .zip(&plain)
            .map(|(a, b)| (*a as i32 >> 3) - (*b as i32 >> 3))
            .collect();
        assert!(steps.iter().any(|&s| s != 0), "{m}");
        let limit = if m.starts_with('b') { 1 } else { 8 };
        assert!(steps.iter().all(|s| s.abs() <= limit), "{m}");
    }
    // JPEG ignores dithering.
    let mut j = spec(FileType::Jpeg);
    let a = std::fs::read(ours(&film, "plain.jpg", &j)).unwrap();
    j.dither = true;
    assert_eq!(a, std::fs::read(ours(&film, "dith.jpg", &j)).unwrap());
}

/// The povray binary, if installed.
fn povray() -> Option<PathBuf> {
    let found = std::env::var_os("PATH").and_then(|paths| {
        std::env::split_paths(&paths)
            .map(|d| d.join("povray"))
            .find(|p| p.is_file())
    });
    if found.is_none() {
        eprintln!("skipped: povray is not on PATH (apt-get install povray)");
    }
    found
}

/// Runs povray for every (scene, options, file name) at once (each run spends most of its
/// time starting up, not rendering) and returns the files in the same order.
fn povray_files(bin: &Path, jobs: &[(&Path, Vec<&str>, String)]) -> Vec<PathBuf> {
    let dir = scratch().join("povray");
    std::fs::create_dir_all(&dir).unwrap();
    let running: Vec<_> = jobs
        .iter()
        .map(|(scene, opts, name)| {
            let child = Command::new(bin)
                .args([
                    "-D",
                    "-V",
                    "-GA",
                    &format!("+W{W}"),
                    &format!("+H{H}"),
                    "-A",
                ])
                .args(opts)
                .arg(format!("+I{}", scene.display()))
                .arg(format!("+O{}", dir.join(name).display()))
                .stdout(std::process::Stdio::null())
                .stderr(std::process::Stdio::null())
                .spawn()
                .unwrap();
            (child, opts, dir.join(name))
        })
        .collect();
    running
        .into_iter()
        .map(|(mut child, opts, out)| {
            assert!(child.wait().unwrap().success(), "povray {opts:?} failed");
            out
        })
        .collect()
}

/// lancer's file written with the same options, through the command-line parser.
fn lancer_spec(opts: &[&str]) -> OutputSpec {
    let mut args = vec!["lancer".to_string(), "x.pov".to_string()];
    args.extend(opts.iter().map(|s| s.to_string()));
    let mut warnings = Vec::new();
    let args = lancer::ini::expand(args, &mut warnings).unwrap();
    let (c, pov) = lancer::cli::split_args(args);
    let cli = <lancer::cli::Cli as clap::Parser>::try_parse_from(c).unwrap();
    match cli.command {
        lancer::cli::Command::Render(r) => lancer::cli::make_job(r, &pov).unwrap().output_spec,
        _ => unreachable!(),
    }
}

/// Decoded samples of any type the two programs write.
fn decoded(p: &Path) -> Vec<u32> {
    match p.extension().and_then(|e| e.to_str()) {
        Some("ppm") => ppm_samples(p).1,
        Some("bmp") => bmp_samples(p),
        _ => samples(&open(p)),
    }
}

/// Targa pixel data up to the extension area (the rest holds dates and program names).
fn tga_body(p: &Path) -> Vec<u8> {
    let d = std::fs::read(p).unwrap();
    d[..d.len() - 495 - 26].to_vec()
}

#[test]
fn files_match_povray() {
    let Some(bin) = povray() else { return };
    let ramp = scene("ramp.pov", RAMP);
    let alpha = scene("alpha.pov", ALPHA);
    let films = [render(&ramp, false), render(&alpha, true)];
    let scenes = [ramp.as_path(), alpha.as_path()];
    // (scene, options, file name, samples allowed to differ by one).
    let exact: &[(usize, &[&str], &str, bool)] = &[
        (0, &["+FN"], "n8.png", false),
        (0, &["+FN5"], "n5.png", false),
        // Off by one allowed: since the pattern engine (gradient as fmod of the pattern-space
        // point), 32 of the ramp's samples sit a rounding hair from a 12-bit step and land
        // one step away from povray's; 5- and 8-bit files stay exact.
        (0, &["+FN12"], "n12.png", true),
        (0, &["+FN16"], "n16.png", true),
        (0, &["+FP5"], "p5.ppm", false),
        (0, &["+FP12"], "p12.ppm", true), // The same 32 samples as n12.png.
        (0, &["+FT"], "t.tga", false),
        (0, &["+FC"], "c.tga", false),
        (0, &["+FB"], "b.bmp", false),
        (0, &["+FN", "File_Gamma=1.0"], "g1.png", false),
        (0, &["+FT", "File_Gamma=1.8"], "g18.tga", false),
        (0, &["+FN5", "+THb2"], "b2.png", false),
        (
            0,
            &["+FP", "Dither=on", "Dither_Method=b3"],
            "b3.ppm",
            false,
        ),
        (0, &["+FN", "+THb4"], "b4.png", false),
        (1, &["+UA", "+FN"], "a8.png", false),
        (1, &["+UA", "+FN5"], "a5.png", false),
        (1, &["+UA", "+FN16"], "a16.png", true),
        (1, &["+UA", "+FC"], "ac.tga", false),
        (1, &["+UA", "+FB"], "ab.bmp", false),
        (1, &["+UA", "+FP"], "ap.ppm", false),
        (1, &["+UA", "+FN5", "+THb2"], "ab2.png", false),
    ];
    let mut jobs: Vec<(&Path, Vec<&str>, String)> = exact
        .iter()
        .map(|&(i, opts, name, _)| (scenes[i], opts.to_vec(), name.to_string()))
        .collect();
    let extra: &[(usize, &[&str], &str)] = &[
        (0, &["+FH"], "h.hdr"),
        (1, &["+UA", "+FE"], "e.exr"),
        (0, &["+FJ"], "j.jpg"),
        (0, &["+FN5", "+THd1"], "d1.png"),
        (0, &["+FN5", "+THd2"], "d2.png"),
        (0, &["+FN5", "+THfs"], "fs.png"),
    ];
    jobs.extend(
        extra
            .iter()
            .map(|&(i, opts, name)| (scenes[i], opts.to_vec(), name.to_string())),
    );
    let files = povray_files(&bin, &jobs);
    let theirs = |name: &str| {
        let i = jobs.iter().position(|j| j.2 == name).unwrap();
        files[i].clone()
    };
    for &(i, opts, name, one) in exact {
        let theirs = theirs(name);
        let mine = ours(&films[i], name, &lancer_spec(opts));
        let (a, b) = (decoded(&theirs), decoded(&mine));
        assert_eq!(a.len(), b.len(), "{name}");
        let off: Vec<u32> = a.iter().zip(&b).map(|(x, y)| x.abs_diff(*y)).collect();
        // One step of the file's own depth: 12-bit samples are stored in 16 bits, 16 apart.
        let step = if name == "n12.png" { 16 } else { 1 };
        let limit = if one { step } else { 0 };
        assert!(
            off.iter().all(|&d| d <= limit),
            "{name}: {} samples differ, by up to {}",
            off.iter().filter(|&&d| d > 0).count(),
            off.iter().max().unwrap()
        );
        if name.ends_with(".tga") {
            // Same header, same packets.
            assert_eq!(tga_body(&theirs), tga_body(&mine), "{name}");
        }
        if name.ends_with(".bmp") {
            assert_eq!(
                std::fs::read(&theirs).unwrap(),
                std::fs::read(&mine).unwrap()
            );
        }
        if name.ends_with(".png") {
            assert_eq!(
                png_info(&theirs),
                png_info(&mine),
                "{name}: gAMA, sRGB, sBIT"
            );
        }
    }
    // Radiance: the same RGBE encoding; the few ramp samples that sit on a rounding edge (see
    // n12.png) may land one mantissa step away (1/256 of the pixel's largest channel).
    let mine = open(&ours(&films[0], "h.hdr", &lancer_spec(&["+FH"]))).to_rgb32f();
    for (a, b) in open(&theirs("h.hdr"))
        .to_rgb32f()
        .as_raw()
        .iter()
        .zip(mine.as_raw())
    {
        assert!(
            (a - b).abs() <= a.abs().max(b.abs()).max(1.0) / 128.0,
            "HDR {a} vs {b}"
        );
    }
    // OpenEXR: POV-Ray's half floats against lancer's floats.
    let mine = open(&ours(&films[1], "e.exr", &lancer_spec(&["+FE"]))).to_rgba32f();
    let pov = open(&theirs("e.exr")).to_rgba32f();
    for (a, b) in pov.as_raw().iter().zip(mine.as_raw()) {
        assert!((a - b).abs() <= 1e-3 * b.abs().max(1.0), "EXR {a} vs {b}");
    }
    // JPEG: another encoder at the same quality.
    let mine = decoded(&ours(&films[0], "j.jpg", &lancer_spec(&["+FJ"])));
    let mean = decoded(&theirs("j.jpg"))
        .iter()
        .zip(&mine)
        .map(|(a, b)| a.abs_diff(*b) as f64)
        .sum::<f64>()
        / mine.len() as f64;
    assert!(mean < 2.0, "JPEG mean difference {mean}");
    // Error diffusion: the rule is POV-Ray's, but a sample rounded the other way moves what
    // follows. Measured: at 48x16 d1 0.7%, d2 4.9%, fs 1.0% of samples differ; at 256x64 d1
    // 1.1%, d2 5.2%, fs 4.6% (against 19-26% between dithered and undithered files).
    for m in ["d1", "d2", "fs"] {
        let name = format!("{m}.png");
        let th = format!("+TH{m}");
        let mine = decoded(&ours(&films[0], &name, &lancer_spec(&["+FN5", &th])));
        let pov = decoded(&theirs(&name));
        let off = pov.iter().zip(&mine).filter(|(a, b)| a != b).count();
        assert!(off * 100 <= 15 * mine.len(), "{m}: {off} samples differ");
    }
}

#[test]
fn animation_frames_keep_every_extension() {
    for t in ["png", "ppm", "tga", "bmp", "jpg", "hdr", "exr"] {
        let out = Path::new("frames").join(format!("fly.{t}"));
        assert_eq!(
            lancer::anim::numbered(&out, 7, 3),
            Path::new("frames").join(format!("fly007.{t}"))
        );
    }
}

/// The command quantises a render without anti-aliasing pixel by pixel as it is traced,
/// without a film (`output::Quantised`): its files must hold the bytes `write` makes of the
/// film, in every integer type, at several depths, with and without alpha, and at a size
/// where quantisation goes through its table of steps (16,384 pixels and more).
/// A scene, the file's extension, lancer's options and the picture's size.
type Case<'a> = (&'a Path, &'a str, &'a [&'a str], (u32, u32));

#[test]
fn files_rendered_without_a_film_are_the_films_files() {
    let ramp = scene("ramp.pov", RAMP);
    let alpha_scene = scene("alpha.pov", ALPHA);
    let cases: &[Case] = &[
        (&ramp, "png", &["+FN8"], (W, H)),
        (&ramp, "png", &["+FN16"], (W, H)),
        (&ramp, "png", &["+FN5"], (W, H)),
        (&ramp, "png", &["+FN8"], (160, 120)),
        (&ramp, "ppm", &["+FP"], (160, 120)),
        (&ramp, "ppm", &["+FP12"], (W, H)),
        (&ramp, "png", &["+FN8", "File_Gamma=2.2"], (160, 120)),
        (&ramp, "tga", &["+FT"], (W, H)),
        (&ramp, "tga", &["+FC"], (W, H)),
        (&ramp, "bmp", &["+FB"], (W, H)),
        (&ramp, "jpg", &["+FJ"], (W, H)),
        (&alpha_scene, "png", &["+FN8", "+UA"], (W, H)),
        (&alpha_scene, "png", &["+FN16", "+UA"], (160, 120)),
        (&alpha_scene, "tga", &["+FT", "+UA"], (W, H)),
        (&alpha_scene, "bmp", &["+FB", "+UA"], (W, H)),
        (&alpha_scene, "ppm", &["+FP", "+UA"], (W, H)),
        (&alpha_scene, "png", &["+FN8", "+UA"], (160, 120)),
    ];
    for (i, &(pov, ext, opts, (w, h))) in cases.iter().enumerate() {
        let alpha = opts.contains(&"+UA");
        let s = RenderSettings {
            width: w,
            height: h,
            antialias: None,
            alpha,
            ..RenderSettings::default()
        };
        let film = lancer::api::render_file(pov, &[], &s).unwrap();
        let whole = ours(&film, &format!("film{i}.{ext}"), &lancer_spec(opts));
        let direct = scratch().join(format!("direct{i}.{ext}"));
        let size = [format!("+W{w}"), format!("+H{h}")];
        let status = Command::new(env!("CARGO_BIN_EXE_lancer"))
            .args([pov.to_str().unwrap(), "-A", "-q", &size[0], &size[1]])
            .args(opts)
            .arg(format!("+O{}", direct.display()))
            .env("LANCER_NO_CONFIG", "1")
            .status()
            .unwrap();
        assert!(status.success(), "{opts:?}");
        if ext == "tga" {
            // The extension area holds the date.
            assert!(tga_body(&whole) == tga_body(&direct), "{opts:?} {w}x{h}");
        } else {
            let (a, b) = (
                std::fs::read(&whole).unwrap(),
                std::fs::read(&direct).unwrap(),
            );
            assert!(a == b, "{opts:?} {w}x{h}");
        }
    }
}
