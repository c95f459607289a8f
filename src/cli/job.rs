//! Putting a render job together: the main INI file's switches, lancer's long options and
//! POV-Ray's `+W640 -A +Oout.png` switches merged in that order (the later wins), then the
//! scene located and the output named.

use std::path::PathBuf;

use super::{Job, RenderArgs};
use crate::output::{DitherMethod, FileGamma, FileType, OutputSpec};
use crate::render::RenderSettings;

pub fn make_job(a: RenderArgs, pov: &[String]) -> Result<Job, String> {
    make_job_with(a, &crate::config::Config::default(), pov)
}

/// Like `make_job`, starting from POV-Ray's configuration files (config.rs): the main INI
/// file's options come first, so lancer's long options and the command line's switches win.
/// A file type the main INI file sets does not count as asked for: `-o out.exr` still writes
/// OpenEXR.
pub fn make_job_with(
    mut a: RenderArgs,
    config: &crate::config::Config,
    pov: &[String],
) -> Result<Job, String> {
    let mut s = RenderSettings::default();
    let mut out = OutputOpts::default();
    let mut warnings = Vec::new();
    let mut anim = AnimOpts::default();
    let mut partial = PartialOpts::default();
    let mut declares = Vec::new();
    let mut version = None;
    let mut include_header = None;
    let mut show = (false, false);
    let cli_scene = a.scene.take();
    let cli_output = a.output.take();
    let cli_libs = std::mem::take(&mut a.library_path);
    let cli_threads = a.threads.take();
    // The switches' view of the job being built, borrowed afresh for each loop below (the
    // code between them reads and changes the same values).
    macro_rules! switches {
        () => {
            &mut Switches {
                s: &mut s,
                a: &mut a,
                out: &mut out,
                warnings: &mut warnings,
                anim: &mut anim,
                partial: &mut partial,
                declares: &mut declares,
                version: &mut version,
                include_header: &mut include_header,
                show: &mut show,
            }
        };
    }
    for opt in &config.switches {
        apply_switch(opt, switches!()).map_err(|e| match &config.ini {
            Some(f) => format!("{}: {e}", f.display()),
            None => e,
        })?;
    }
    out.type_given = false;
    a.scene = cli_scene.or(a.scene.take());
    a.output = cli_output.or(a.output.take());
    a.library_path.extend(cli_libs);
    a.threads = cli_threads.or(a.threads);
    a.safety.conf = config.io.clone();
    if let Some(w) = a.width {
        s.width = w;
    }
    if let Some(h) = a.height {
        s.height = h;
    }
    if let Some(t) = a.antialias {
        s.antialias = Some(t);
    }
    if a.no_antialias {
        s.antialias = None;
    }
    if let Some(d) = a.aa_depth {
        s.aa_depth = d;
    }
    if a.no_jitter {
        s.jitter = 0.0;
    }
    if let Some(f) = &a.format {
        let (t, bits) = FileType::from_format_name(f)?;
        out.spec.file_type = t;
        out.spec.set_bits(bits);
        out.type_given = true;
    }
    for opt in pov {
        apply_switch(opt, switches!())?;
    }
    let scene = a
        .scene
        .clone()
        .ok_or("no scene file given (lancer scene.pov, or +Iscene.pov)")?;
    let scene = locate_scene(scene, &a.library_path);
    if s.width == 0 || s.height == 0 {
        return Err("width and height must be at least 1".into());
    }
    s.window = partial.window(s.width, s.height)?;
    let mut spec = out.spec;
    if !out.type_given {
        if let Some(o) = a
            .output
            .as_deref()
            .filter(|o| o.extension().is_some() && !o.is_dir())
        {
            spec.file_type = FileType::from_path(o);
        }
    }
    warnings.extend(spec.alpha_warning(s.alpha));
    let ext = spec.file_type.extension();
    let output = match a.output.clone() {
        // `+O-`: standard output, for a still picture only (frames need names).
        Some(o) if o.as_os_str() == "-" => {
            if anim.animation.is_animation() {
                return Err(
                    "+O- writes one picture to standard output; an animation's frames need file names"
                        .into(),
                );
            }
            o
        }
        Some(o) if o.is_dir() => o.join(default_name(&scene, ext)),
        Some(o) if o.extension().is_none() => o.with_extension(ext),
        Some(o) => o,
        None => PathBuf::from(default_name(&scene, ext)),
    };
    Ok(Job {
        scene,
        output,
        output_spec: spec,
        settings: s,
        library_paths: a.library_path,
        threads: a.threads,
        quiet: a.quiet,
        safety: a.safety.clone(),
        animation: anim.animation,
        declares,
        write_output: out.to_file,
        continue_trace: anim.continue_trace,
        version,
        include_header,
        display: show.0,
        pause: show.1,
        warnings,
    })
}

/// Everything a POV-Ray switch may change while a job is put together.
struct Switches<'a> {
    s: &'a mut RenderSettings,
    a: &'a mut RenderArgs,
    out: &'a mut OutputOpts,
    warnings: &'a mut Vec<String>,
    anim: &'a mut AnimOpts,
    partial: &'a mut PartialOpts,
    declares: &'a mut Vec<(String, f64)>,
    version: &'a mut Option<f64>,
    include_header: &'a mut Option<String>,
    /// `+D` and `+P`.
    show: &'a mut (bool, bool),
}

fn apply_switch(opt: &str, w: &mut Switches) -> Result<(), String> {
    let upper = opt.to_ascii_uppercase();
    if let Some(d) = upper.strip_prefix("+DECLARE=") {
        // Keep the name's own spelling: identifiers are case-sensitive.
        let rest = &opt[opt.len() - d.len()..];
        let (name, v) = rest
            .split_once('=')
            .ok_or_else(|| format!("{opt}: expected Declare=Name=number"))?;
        let v: f64 = v
            .parse()
            .map_err(|_| format!("{opt}: expected Declare=Name=number"))?;
        w.declares.push((name.to_string(), v));
    } else if let Some(v) = upper[1..].strip_prefix("MV") {
        *w.version = Some(
            v.parse::<f64>()
                .map_err(|_| format!("{opt}: expected a version number such as +MV3.7"))?,
        );
    } else if upper[1..] == *"P" {
        w.show.1 = upper.starts_with('+');
    } else if upper[1..].starts_with('D')
        && upper.len() <= 4
        && upper[1..].chars().all(|c| c.is_ascii_alphanumeric())
    {
        // +D, or +D with POV-Ray's display type and palette letters after it (+D0, +DGT):
        // show the picture.
        w.show.0 = upper.starts_with('+');
    } else if upper[1..].starts_with("HI") {
        // A file name keeps its own spelling.
        *w.include_header = Some(opt[3..].to_string()).filter(|n| !n.is_empty());
    } else if !w.anim.apply(opt)? && !w.partial.apply(opt)? {
        apply_pov_option(opt, w.s, w.a, w.out, w.warnings)?;
    }
    Ok(())
}

/// `+SR +ER +SC +EC` (Start_Row, End_Row, Start_Column, End_Column): above 1 a pixel number
/// counted from 1, below 1 a fraction of the size, as POV-Ray reads them.
#[derive(Default)]
struct PartialOpts {
    /// Start row, end row, start column, end column.
    given: [Option<f64>; 4],
}

impl PartialOpts {
    fn apply(&mut self, opt: &str) -> Result<bool, String> {
        let upper = opt[1..].to_ascii_uppercase();
        let slot = match upper.get(..2) {
            Some("SR") => 0,
            Some("ER") => 1,
            Some("SC") => 2,
            Some("EC") => 3,
            _ => return Ok(false),
        };
        let v: f64 = upper[2..]
            .parse()
            .map_err(|_| format!("bad number in option {opt}"))?;
        if v < 0.0 {
            return Err(format!("{opt}: rows and columns cannot be negative"));
        }
        self.given[slot] = Some(v);
        Ok(true)
    }

    /// The window in pixels (end-exclusive), or None for the whole picture.
    fn window(&self, width: u32, height: u32) -> Result<Option<crate::render::Window>, String> {
        if self.given.iter().all(Option::is_none) {
            return Ok(None);
        }
        // Fractions land on floor(f * size); pixel n is index n - 1 and ends before n. Exactly 1
        // is the first pixel as a start and the whole size as an end (checked with povray).
        let start = |v: Option<f64>, size: u32| match v {
            None => 0,
            Some(v) if v < 1.0 => (v * size as f64).floor() as u32,
            Some(v) => v as u32 - 1,
        };
        let end = |v: Option<f64>, size: u32| match v {
            None => size,
            Some(v) if v <= 1.0 => (v * size as f64).floor() as u32,
            Some(v) => v as u32,
        };
        let w = crate::render::Window {
            y0: start(self.given[0], height).min(height),
            y1: end(self.given[1], height).min(height),
            x0: start(self.given[2], width).min(width),
            x1: end(self.given[3], width).min(width),
        };
        if w.y0 >= w.y1 || w.x0 >= w.x1 {
            return Err(format!(
                "the partial render is empty: rows {}..{} and columns {}..{} of {width}x{height}",
                w.y0, w.y1, w.x0, w.x1
            ));
        }
        Ok(Some(w))
    }
}

/// The animation options among POV-Ray's: `+KFI1 +KFF24 +KI0 +KF1 +KC +SF5 +EF8 +K0.5 +C`.
#[derive(Default)]
struct AnimOpts {
    animation: crate::anim::Animation,
    continue_trace: bool,
}

impl AnimOpts {
    /// Takes `opt` if it is an animation option.
    fn apply(&mut self, opt: &str) -> Result<bool, String> {
        let on = opt.starts_with('+');
        let upper = opt[1..].to_ascii_uppercase();
        let num = |t: &str| -> Result<f64, String> {
            t.parse::<f64>()
                .map_err(|_| format!("bad number in option {opt}"))
        };
        let a = &mut self.animation;
        if let Some(v) = upper.strip_prefix("KFI") {
            a.initial_frame = Some(num(v)? as i64);
        } else if let Some(v) = upper.strip_prefix("KFF") {
            a.final_frame = Some(num(v)? as i64);
        } else if upper == "KC" {
            a.cyclic = on;
        } else if let Some(v) = upper.strip_prefix("KI") {
            a.initial_clock = Some(num(v)?);
        } else if let Some(v) = upper.strip_prefix("KF") {
            a.final_clock = Some(num(v)?);
        } else if let Some(v) = upper.strip_prefix('K') {
            a.clock = Some(num(v)?);
        } else if let Some(v) = upper.strip_prefix("STP") {
            a.step = Some(num(v)? as i64);
        } else if let Some(v) = upper.strip_prefix("SF") {
            a.subset_start = Some(num(v)?);
        } else if let Some(v) = upper.strip_prefix("EF") {
            a.subset_end = Some(num(v)?);
        } else if upper == "C" {
            self.continue_trace = on;
        } else {
            return Ok(false);
        }
        Ok(true)
    }
}

/// Like POV-Ray: a scene not found where it is named is looked for in the library paths, and
/// `.pov` is assumed when the name has no extension.
fn locate_scene(scene: PathBuf, library: &[PathBuf]) -> PathBuf {
    let mut names = vec![scene.clone()];
    if scene.extension().is_none() {
        names.push(scene.with_extension("pov"));
    }
    for n in &names {
        if n.is_file() {
            return n.clone();
        }
    }
    if scene.is_relative() {
        for dir in library {
            for n in &names {
                if dir.join(n).is_file() {
                    return dir.join(n);
                }
            }
        }
    }
    scene
}

fn default_name(scene: &std::path::Path, ext: &str) -> String {
    let stem = scene
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "scene".into());
    format!("{stem}.{ext}")
}

/// The file output options as they are read, before the output name may pick the type.
struct OutputOpts {
    spec: OutputSpec,
    /// A type option was given; otherwise the output name's extension picks the type.
    type_given: bool,
    /// `+F` / `-F` / `Output_To_File`.
    to_file: bool,
}

impl Default for OutputOpts {
    fn default() -> OutputOpts {
        OutputOpts {
            spec: OutputSpec::default(),
            type_given: false,
            to_file: true,
        }
    }
}

/// Takes `opt` if it is a file output option: `+F<type><bits>` / `-F<type><bits>` (`-F`
/// turns file output off but keeps the type for later, as in POV-Ray; a type without bits
/// keeps the bits already set), `+TH[method]` / `-TH[method]`, and the INI-only keys that
/// ini.rs passes on as `+Key=value` (`File_Gamma`, `Bits_Per_Color`, `Dither_Method`,
/// `Compression`).
fn apply_output_option(opt: &str, out: &mut OutputOpts) -> Result<bool, String> {
    let on = opt.starts_with('+');
    let body = &opt[1..];
    let upper = body.to_ascii_uppercase();
    let spec = &mut out.spec;
    let whole = |v: &str| -> Result<i64, String> {
        v.trim()
            .parse::<i64>()
            .map_err(|_| format!("{body}: expected a whole number"))
    };
    if let Some((key, value)) = body.split_once('=') {
        match key.to_ascii_lowercase().as_str() {
            "file_gamma" => spec.file_gamma = FileGamma::parse(value)?,
            "bits_per_color" => spec.set_bits(whole(value)?.clamp(0, 64) as u32),
            "compression" => spec.set_compression(whole(value)?),
            "dither_method" => {
                spec.dither_method =
                    DitherMethod::parse(value).map_err(|e| format!("{body}: {e}"))?
            }
            _ => return Ok(false),
        }
    } else if let Some(method) = upper.strip_prefix("TH") {
        spec.dither = on;
        if !method.is_empty() {
            spec.dither_method = DitherMethod::parse(method).map_err(|e| format!("{opt}: {e}"))?;
        }
    } else if let Some(rest) = upper.strip_prefix('F') {
        out.to_file = on;
        let mut chars = rest.chars();
        if let Some(letter) = chars.next() {
            spec.file_type = FileType::from_letter(letter).map_err(|e| format!("{opt}: {e}"))?;
            out.type_given = true;
            let bits = chars.as_str();
            if !bits.is_empty() {
                let n: u32 = bits.parse().map_err(|_| {
                    format!("{opt}: expected the bits per colour after the type, as in +FN16")
                })?;
                spec.set_bits(n);
            }
        }
    } else {
        return Ok(false);
    }
    Ok(true)
}

fn apply_pov_option(
    opt: &str,
    s: &mut RenderSettings,
    a: &mut RenderArgs,
    out: &mut OutputOpts,
    warnings: &mut Vec<String>,
) -> Result<(), String> {
    if apply_output_option(opt, out)? {
        return Ok(());
    }
    let on = opt.starts_with('+');
    let body = &opt[1..];
    let upper = body.to_ascii_uppercase();
    let num = |t: &str| -> Result<f64, String> {
        t.parse::<f64>()
            .map_err(|_| format!("bad number in option {opt}"))
    };
    // Memory (+MI), render order (+RP +RS), bounding (+B +BM) and warning-level (+WL)
    // options do not change the picture. Field rendering (+UF +UO) is accepted and ignored by
    // povray 3.7 as well: its frames are whole pictures either way (checked).
    if let Some(rest) = upper.strip_prefix("BS") {
        // POV-Ray takes at least 4 (its manual).
        s.aa_block = (num(rest)? as u32).max(4);
        return Ok(());
    }
    if ["MI", "RP", "RS", "WL", "UF", "UO", "B"]
        .iter()
        .any(|p| upper.starts_with(p))
    {
        return Ok(());
    }
    if let Some(rest) = upper.strip_prefix("AM") {
        s.sampling_method = match num(rest)? {
            m if m == 1.0 || m == 2.0 => m as u32,
            m => return Err(format!("{opt}: the sampling method is 1 or 2, not {m}")),
        };
    } else if let Some(rest) = upper.strip_prefix("AG") {
        s.aa_gamma = match num(rest)? {
            g if g > 0.0 => g,
            g => {
                return Err(format!(
                    "{opt}: the anti-aliasing gamma must be positive, not {g}"
                ))
            }
        };
    } else if upper == "RVP" || upper == "HR" {
        // Radiosity's vain pretrace only shapes povray's preview, and lancer's radiosity is
        // reproducible for any thread count without asking (docs/radiosity.md).
    } else if upper.starts_with("RF") {
        warnings.push(format!(
            "option {opt} (radiosity cache files) is not supported by lancer yet and is ignored"
        ));
    } else if upper == "UA" {
        s.alpha = on;
    } else if let Some(rest) = upper.strip_prefix('Q') {
        // POV-Ray clips the level to 0..=11.
        s.quality = num(rest)?.clamp(0.0, 11.0) as u32;
    } else if upper.starts_with("WT") {
        a.threads = Some(num(&body[2..])? as usize);
    } else if let Some(rest) = upper.strip_prefix('W') {
        s.width = num(rest)? as u32;
    } else if let Some(rest) = upper.strip_prefix('H') {
        s.height = num(rest)? as u32;
    } else if let Some(rest) = upper.strip_prefix('A') {
        s.antialias = if on {
            Some(if rest.is_empty() { 0.3 } else { num(rest)? })
        } else {
            None
        };
    } else if let Some(rest) = upper.strip_prefix('R') {
        s.aa_depth = num(rest)? as u32;
    } else if let Some(rest) = upper.strip_prefix('J') {
        s.jitter = if on {
            if rest.is_empty() {
                1.0
            } else {
                num(rest)?
            }
        } else {
            0.0
        };
    } else if upper.starts_with('O') {
        if body.len() > 1 {
            a.output = Some(PathBuf::from(&body[1..]));
        }
    } else if upper.starts_with('I') {
        a.scene = Some(PathBuf::from(&body[1..]));
    } else if upper.starts_with('L') {
        a.library_path.push(PathBuf::from(&body[1..]));
    } else if matches!(
        upper.as_str(),
        "D" | "V" | "P" | "X" | "GA" | "GS" | "GR" | "GD" | "GF" | "GW" | "GP"
    ) || upper.starts_with('D')
    {
        // Display, verbosity, pause and stream options do not change the picture.
    } else {
        warnings.push(format!(
            "option {opt} is not supported by lancer yet and is ignored"
        ));
    }
    Ok(())
}
