//! Command-line options: clap long options, and POV-Ray's `+W640 -A +Oout.png` options accepted
//! verbatim so `povray` can be swapped for `lancer` in an existing script.

use std::path::PathBuf;

use clap::{Args, Parser as ClapParser, Subcommand};

use crate::output::{DitherMethod, FileGamma, FileType, OutputSpec};
use crate::render::RenderSettings;

#[derive(ClapParser, Debug)]
#[command(
    name = "lancer",
    version,
    about = "A fast ray tracer for POV-Ray 3.7 scenes",
    disable_version_flag = true
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
    /// Print the version.
    #[arg(long, action = clap::ArgAction::Version)]
    version: Option<bool>,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Render a scene (the default when no subcommand is given).
    Render(RenderArgs),
    /// Compare two pictures: SSIM, worst 16x16 tile and PSNR. Exit 1 below --min-ssim, 2 when a
    /// picture is unreadable or the sizes differ.
    Compare(CompareArgs),
    /// Parse scenes without rendering and print their diagnostics (exit 1 on errors).
    Check(CheckArgs),
    /// Render a directory of scenes with povray and lancer and report how they compare.
    #[command(hide = true)]
    Conformance(ConformanceArgs),
    /// Open a scene in a window: the picture refines while nothing changes, the keyboard and
    /// mouse move the camera, a toolbox switches effects. Takes the render's options.
    Preview(PreviewArgs),
}

#[derive(Args, Debug)]
pub struct PreviewArgs {
    #[command(flatten)]
    pub render: RenderArgs,
    /// Write a screenshot of the window (PNG) once the first view is refined.
    #[arg(long, value_name = "PNG")]
    pub screenshot: Option<PathBuf>,
    /// Close the window once the screenshot is written.
    #[arg(long, requires = "screenshot")]
    pub exit_after_screenshot: bool,
    /// Orbit the camera for SECONDS, print the frame rate and close (benchmarks).
    #[arg(long, value_name = "SECONDS")]
    pub bench: Option<f64>,
    /// Render every view at full resolution, without the coarse levels.
    #[arg(long)]
    pub full_resolution: bool,
}

#[derive(Args, Debug)]
pub struct CompareArgs {
    /// The first picture (PNG 8/16-bit or EXR); the heat map is drawn over it.
    pub a: PathBuf,
    /// The second picture.
    pub b: PathBuf,
    /// Exit with status 1 when the SSIM is below this.
    #[arg(long, value_name = "S")]
    pub min_ssim: Option<f64>,
    /// Write a heat map of where the pictures differ (PNG).
    #[arg(long, value_name = "PNG")]
    pub diff: Option<PathBuf>,
    /// Write an HTML page (one file) with both pictures, the heat map and the numbers.
    #[arg(long, value_name = "HTML")]
    pub html: Option<PathBuf>,
}

#[derive(Args, Debug)]
pub struct CheckArgs {
    /// Scene or include files to parse.
    #[arg(required = true)]
    pub files: Vec<PathBuf>,
    /// Directory searched for include files (repeatable).
    #[arg(long = "library-path", value_name = "DIR")]
    pub library_path: Vec<PathBuf>,
    /// Print only errors, not warnings. POV-Ray style `+Ldir` options add library paths.
    #[arg(short, long)]
    pub quiet: bool,
    #[command(flatten)]
    pub safety: SafetyArgs,
}

#[derive(Args, Debug)]
pub struct ConformanceArgs {
    /// Directory of scenes (default: POV-Ray's sample scenes).
    #[arg(long, default_value = crate::conformance::DEFAULT_SCENES)]
    pub scenes: PathBuf,
    /// Only the scenes listed in this file; its `min_good N` line makes the run fail when fewer
    /// than N reach SSIM 0.95.
    #[arg(long)]
    pub subset: Option<PathBuf>,
    /// Write the report to PREFIX.md, PREFIX.tsv and PREFIX.html (pictures in PREFIX_files/).
    #[arg(long, value_name = "PREFIX")]
    pub report: Option<PathBuf>,
    /// Write a subset file for CI: the scenes at SSIM ≥ 0.95 that POV-Ray renders within
    /// --subset-seconds, with their count as the ratchet. Refuses to lower an existing ratchet.
    #[arg(long, value_name = "FILE")]
    pub write_subset: Option<PathBuf>,
    /// POV-Ray wall time up to which a good scene is cheap enough for the CI subset.
    #[arg(long, default_value_t = 3.0)]
    pub subset_seconds: f64,
    /// Cache of POV-Ray's renders (default: ~/.cache/lancer/conformance).
    #[arg(long)]
    pub cache: Option<PathBuf>,
    /// Known differences (`scene<TAB>reason` per line): the report names the reason beside
    /// each such scene below SSIM 0.95 and lists the ones left unexplained.
    #[arg(long, value_name = "FILE")]
    pub known: Option<PathBuf>,
    /// Scenes rendered at once.
    #[arg(long, default_value_t = 2)]
    pub jobs: usize,
    #[arg(long, default_value_t = 160)]
    pub width: u32,
    #[arg(long, default_value_t = 120)]
    pub height: u32,
    /// Seconds POV-Ray may take per scene.
    #[arg(long, default_value_t = 120)]
    pub povray_timeout: u64,
    /// Seconds lancer may take per scene.
    #[arg(long, default_value_t = 60)]
    pub lancer_timeout: u64,
    /// The POV-Ray binary.
    #[arg(long, default_value = "povray")]
    pub povray: PathBuf,
    #[arg(short, long)]
    pub quiet: bool,
}

#[derive(Args, Debug, Default)]
pub struct RenderArgs {
    /// The .pov scene file.
    pub scene: Option<PathBuf>,
    /// Output file; default: the scene name with the file type's extension, in the current
    /// directory. Without a file type option the extension picks it (.png .ppm .tga .bmp .jpg
    /// .hdr .exr).
    #[arg(short = 'o', long)]
    pub output: Option<PathBuf>,
    #[arg(long)]
    pub width: Option<u32>,
    #[arg(long)]
    pub height: Option<u32>,
    /// Anti-aliasing threshold (POV-Ray's +A; 0.3 is its default).
    #[arg(long, value_name = "THRESHOLD")]
    pub antialias: Option<f64>,
    #[arg(long)]
    pub no_antialias: bool,
    /// Supersampling grid size for anti-aliasing (POV-Ray's +R).
    #[arg(long)]
    pub aa_depth: Option<u32>,
    /// Do not jitter anti-aliasing samples (POV-Ray's -J).
    #[arg(long)]
    pub no_jitter: bool,
    /// Worker threads (default: all cores). The picture is the same for any count.
    #[arg(long)]
    pub threads: Option<usize>,
    /// Directory searched for include files and images (repeatable).
    #[arg(long = "library-path", value_name = "DIR")]
    pub library_path: Vec<PathBuf>,
    /// png, png16, ppm, ppm16, tga, tga-rle, bmp, jpeg, hdr or exr (default: from the output
    /// name). POV-Ray's +F<type><bits> does the same.
    #[arg(long)]
    pub format: Option<String>,
    /// No progress bar or statistics.
    #[arg(short, long)]
    pub quiet: bool,
    /// Also print the lines POV-Ray prints on stderr (`File '...' line N: Parse Error: ...`,
    /// the statistics with `Render Time`), as when lancer is invoked as `povray`.
    #[arg(long)]
    pub povray_messages: bool,
    #[command(flatten)]
    pub safety: SafetyArgs,
    /// POV-Ray style options (+W640 +H480 -A +A0.3 +R3 -J +Oout.png +Iscene.pov +Ldir +FN16 +FE
    /// +FT +THfs).
    #[arg(hide = true)]
    pub pov: Vec<String>,
}

/// Limits for scenes from untrusted sources, shared by `render` and `check`.
#[derive(Args, Debug, Default, Clone)]
pub struct SafetyArgs {
    /// Stop with an error after this many #while/#for iterations in all (off by default, as in
    /// POV-Ray; set it for scenes you do not trust).
    #[arg(long, value_name = "N")]
    pub max_loop_iterations: Option<u64>,
    /// Let #fopen read and write below DIR as well as the scene's and the current directory
    /// (repeatable).
    #[arg(long = "allow-io", value_name = "DIR")]
    pub allow_io: Vec<PathBuf>,
    /// Let #fopen read and write anywhere.
    #[arg(long)]
    pub io_unrestricted: bool,
    /// Read no povray.ini or povray.conf (POV-Ray's configuration files, read by default as
    /// povray reads them), for runs that must not depend on the machine. LANCER_NO_CONFIG=1
    /// does the same.
    #[arg(long)]
    pub no_config: bool,
    /// povray.conf's I/O restrictions, when configuration files are read.
    #[arg(skip)]
    pub conf: Option<crate::config::IoConf>,
}

impl SafetyArgs {
    pub fn apply(&self, o: &mut crate::sdl::ParseOptions) {
        o.max_loop_iterations = self.max_loop_iterations;
        o.io_allowed_dirs.extend(self.allow_io.iter().cloned());
        o.io_unrestricted |= self.io_unrestricted;
        if let Some(c) = &self.conf {
            use crate::config::IoSecurity;
            o.io_unrestricted |= c.security == IoSecurity::None;
            o.io_read_anywhere |= c.security == IoSecurity::ReadOnly;
            o.io_permits.extend(c.permits.iter().cloned());
        }
    }
}

/// Everything a render needs, after clap and POV-Ray options are merged (POV-Ray's later wins).
#[derive(Debug)]
pub struct Job {
    pub scene: PathBuf,
    pub output: PathBuf,
    /// File type, bits, file gamma, dithering, JPEG quality.
    pub output_spec: OutputSpec,
    pub settings: RenderSettings,
    pub library_paths: Vec<PathBuf>,
    pub threads: Option<usize>,
    pub quiet: bool,
    pub safety: SafetyArgs,
    pub animation: crate::anim::Animation,
    /// `Declare=Name=Value`: floats the scene finds declared.
    pub declares: Vec<(String, f64)>,
    /// `-F` / `Output_To_File=off`: render without writing a file (timing runs).
    pub write_output: bool,
    /// `+C`: skip frames whose picture already exists, so an interrupted animation resumes.
    pub continue_trace: bool,
    /// `+MV` / `Version=`: the language version a scene starts in.
    pub version: Option<f64>,
    /// `+HI` / `Include_Header=`: a file included before the scene.
    pub include_header: Option<String>,
    /// `+D`: show the picture in a window as it is drawn; `+P`: keep it open at the end.
    pub display: bool,
    pub pause: bool,
    pub warnings: Vec<String>,
}

impl Job {
    /// What the parser needs from the options, for `frame` of the run (the still picture's
    /// frame when not animating): one place for render and check alike.
    pub fn parse_options(&self, frame: &crate::anim::Frame) -> crate::sdl::ParseOptions {
        let mut o = crate::sdl::ParseOptions {
            library_paths: self.library_paths.clone(),
            image_width: self.settings.width,
            image_height: self.settings.height,
            declares: self.declares.clone(),
            version: self.version,
            include_header: self.include_header.clone(),
            ..crate::sdl::ParseOptions::default()
        };
        self.safety.apply(&mut o);
        let animated = self.animation.is_animation();
        frame.apply(&mut o, animated || self.animation.clock.is_some());
        o
    }
}

/// Splits POV-Ray style arguments from the rest so clap never sees them: anything starting
/// with '+', and single-dash arguments other than lancer's own `-o`, `-q`, `-h`.
pub fn split_args(args: Vec<String>) -> (Vec<String>, Vec<String>) {
    let mut clap_args = Vec::new();
    let mut pov = Vec::new();
    let mut iter = args.into_iter();
    if let Some(prog) = iter.next() {
        clap_args.push(prog);
    }
    let rest: Vec<String> = iter.collect();
    let mut i = 0;
    while i < rest.len() {
        let a = &rest[i];
        let is_pov = a.starts_with('+')
            || (a.starts_with('-')
                && !a.starts_with("--")
                && a.len() > 1
                && !matches!(a.as_str(), "-o" | "-q" | "-h"));
        if is_pov {
            pov.push(a.clone());
        } else {
            clap_args.push(a.clone());
            if matches!(a.as_str(), "-o") && i + 1 < rest.len() {
                i += 1;
                clap_args.push(rest[i].clone());
            }
        }
        i += 1;
    }
    // `lancer scene.pov ...` means `lancer render scene.pov ...`.
    let known = [
        "render",
        "help",
        "compare",
        "check",
        "conformance",
        "preview",
    ];
    if clap_args.len() == 1
        || !known.contains(&clap_args[1].as_str()) && !clap_args[1].starts_with("--")
        || clap_args
            .get(1)
            .is_some_and(|a| a.starts_with("--") && a != "--help" && a != "--version")
    {
        clap_args.insert(1, "render".into());
    }
    (clap_args, pov)
}

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

#[cfg(test)]
mod tests {
    use super::*;

    fn job(args: &[&str]) -> Result<Job, String> {
        let (c, pov) = split_args(args.iter().map(|s| s.to_string()).collect());
        let cli = Cli::try_parse_from(c).map_err(|e| e.to_string())?;
        match cli.command {
            Command::Render(r) => make_job(r, &pov),
            other => Err(format!("not a render: {other:?}")),
        }
    }

    #[test]
    fn clap_definition_is_consistent() {
        use clap::CommandFactory;
        Cli::command().debug_assert();
    }

    #[test]
    fn pov_options_verbatim() {
        let j = job(&[
            "lancer",
            "scenes/a.pov",
            "+W640",
            "+H480",
            "+A0.3",
            "+Omirror.png",
            "+L/some/dir",
            "-J",
        ])
        .unwrap();
        assert_eq!((j.settings.width, j.settings.height), (640, 480));
        assert_eq!(j.settings.antialias, Some(0.3));
        assert_eq!(j.settings.jitter, 0.0);
        assert_eq!(j.output, PathBuf::from("mirror.png"));
        assert_eq!(j.library_paths, vec![PathBuf::from("/some/dir")]);
    }

    #[test]
    fn long_options_with_subcommand() {
        let j = job(&[
            "lancer",
            "render",
            "--width",
            "320",
            "--height",
            "240",
            "--no-antialias",
            "--threads",
            "2",
            "-o",
            "out.exr",
            "scene.pov",
        ])
        .unwrap();
        assert_eq!(j.settings.antialias, None);
        assert_eq!(j.threads, Some(2));
        assert_eq!(j.output_spec.file_type, FileType::Exr);
        assert_eq!(j.scene, PathBuf::from("scene.pov"));
    }

    #[test]
    fn partial_render_windows_as_povray_reads_them() {
        // The pixels povray 3.7 rendered for these options at 32x24 (all else black).
        let w = |opts: &[&str]| {
            let mut args = vec!["lancer", "a.pov", "+W32", "+H24"];
            args.extend_from_slice(opts);
            job(&args).unwrap().settings.window.unwrap()
        };
        let r = w(&["+SR0.5", "+ER0.75", "+SC8", "+EC20"]);
        assert_eq!((r.y0, r.y1, r.x0, r.x1), (12, 18, 7, 20));
        let r = w(&["+SR3", "+ER5", "+SC1", "+EC4"]);
        assert_eq!((r.y0, r.y1, r.x0, r.x1), (2, 5, 0, 4));
        let r = w(&["+SR0.1", "+ER0.2"]);
        assert_eq!((r.y0, r.y1, r.x0, r.x1), (2, 4, 0, 32));
        let r = w(&["+SC1.0", "+EC1"]);
        assert_eq!((r.x0, r.x1), (0, 32));
        assert!(job(&["lancer", "a.pov", "+W32", "+H24", "+SR0.5", "+ER0.2"]).is_err());
    }

    #[test]
    fn animation_options() {
        let j = job(&[
            "lancer", "a.pov", "+KFI1", "+KFF24", "+KI0", "+KF2", "+KC", "+SF5", "+EF8", "+C",
        ])
        .unwrap();
        let a = &j.animation;
        assert_eq!((a.initial_frame, a.final_frame), (Some(1), Some(24)));
        assert_eq!((a.initial_clock, a.final_clock), (Some(0.0), Some(2.0)));
        assert!(a.cyclic && j.continue_trace);
        assert_eq!((a.subset_start, a.subset_end), (Some(5.0), Some(8.0)));
        let j = job(&["lancer", "a.pov", "+K0.5"]).unwrap();
        assert_eq!(j.animation.clock, Some(0.5));
    }

    #[test]
    fn input_option_and_16_bit() {
        let j = job(&["lancer", "+Iscene.pov", "+FN16", "-A"]).unwrap();
        assert_eq!(j.scene, PathBuf::from("scene.pov"));
        assert_eq!(j.output_spec.file_type, FileType::Png);
        assert_eq!(j.output_spec.bits, 16);
        assert_eq!(j.output, PathBuf::from("scene.png"));
    }

    #[test]
    fn file_output_options_as_povray_reads_them() {
        let spec = |opts: &[&str]| {
            let mut args = vec!["lancer", "a.pov"];
            args.extend_from_slice(opts);
            job(&args).unwrap()
        };
        // Bits stay when only the type changes; other types than PNG and PPM write 8.
        let j = spec(&["+FN12", "+FP"]);
        assert_eq!(j.output_spec.file_type, FileType::Ppm);
        assert_eq!(j.output_spec.effective_bits(), 12);
        assert_eq!(j.output, PathBuf::from("a.ppm"));
        let j = spec(&["+FN12", "+FC"]);
        assert_eq!(j.output_spec.effective_bits(), 8);
        assert_eq!(j.output, PathBuf::from("a.tga"));
        assert_eq!(spec(&["+FN3"]).output_spec.bits, 5);
        assert_eq!(spec(&["+FN17"]).output_spec.bits, 16);
        // -F<type> turns file output off and keeps the type; +F turns it on again.
        let j = spec(&["-FJ"]);
        assert!(!j.write_output);
        assert_eq!(j.output, PathBuf::from("a.jpg"));
        assert!(spec(&["-FB", "+F"]).write_output);
        // The output name picks the type when no option does.
        assert_eq!(spec(&["+Oout.bmp"]).output_spec.file_type, FileType::Bmp);
        assert_eq!(spec(&["+Oout.hdr"]).output_spec.file_type, FileType::Hdr);
        assert_eq!(
            spec(&["+FT", "+Oout.png"]).output_spec.file_type,
            FileType::Tga
        );
        // +TH alone keeps the method set before; -THxx sets it with dithering off.
        let j = spec(&["-THb2", "+TH"]);
        assert!(j.output_spec.dither);
        assert_eq!(j.output_spec.dither_method, DitherMethod::Bayer2);
        let j = spec(&["+TH"]);
        assert_eq!(j.output_spec.dither_method, DitherMethod::FloydSteinberg);
        assert!(!spec(&["+THd1", "-TH"]).output_spec.dither);
        // INI-only keys, as ini.rs passes them on.
        let j = spec(&[
            "+File_Gamma=2.2",
            "+Bits_Per_Color=10",
            "+Dither_Method=b4",
            "+Compression=1",
        ]);
        assert_eq!(j.output_spec.file_gamma, FileGamma::Power(2.2));
        assert_eq!(j.output_spec.bits, 10);
        assert_eq!(j.output_spec.dither_method, DitherMethod::Bayer4);
        assert!(!j.output_spec.dither);
        assert_eq!(j.output_spec.jpeg_quality, 85);
        assert_eq!(
            spec(&["--format", "tga-rle"]).output_spec.file_type,
            FileType::TgaRle
        );
        // Alpha with a type that cannot hold it: a warning, as POV-Ray gives.
        assert!(spec(&["+UA", "+FP"])
            .warnings
            .iter()
            .any(|w| w.contains("alpha")));
        assert!(spec(&["+UA", "+FN"]).warnings.is_empty());
    }

    #[test]
    fn bad_file_output_options_name_themselves() {
        let err = |opts: &[&str]| {
            let mut args = vec!["lancer", "a.pov"];
            args.extend_from_slice(opts);
            job(&args).unwrap_err()
        };
        let e = err(&["+FS"]);
        assert!(e.contains("+FS") && e.contains("+FN"), "{e}");
        assert!(err(&["+FX"]).contains("+FX"));
        assert!(err(&["+FNx"]).contains("+FNx"));
        assert!(err(&["+THq"]).contains("+THq"));
        assert!(err(&["+File_Gamma=-1"]).contains("File_Gamma"));
        assert!(err(&["+Bits_Per_Color=many"]).contains("Bits_Per_Color"));
        assert!(err(&["--format", "gif"]).contains("gif"));
    }

    #[test]
    fn display_and_pause_options() {
        let j = job(&["lancer", "s.pov", "+D", "+P"]).unwrap();
        assert!(j.display && j.pause);
        let j = job(&["lancer", "s.pov", "+D0", "-P"]).unwrap();
        assert!(j.display && !j.pause);
        let j = job(&["lancer", "s.pov", "+D", "-D", "+Dither_Method=b4"]).unwrap();
        assert!(!j.display);
        let j = job(&["lancer", "preview", "s.pov", "+W64"]);
        assert!(j.is_err(), "preview is its own command");
    }
}
