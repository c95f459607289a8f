//! Command-line options: clap long options, and POV-Ray's `+W640 -A +Oout.png` options accepted
//! verbatim so `povray` can be swapped for `lancer` in an existing script.

use std::path::PathBuf;

use clap::{Args, Parser as ClapParser, Subcommand};

use crate::output::OutputSpec;
use crate::render::RenderSettings;

mod job;
pub use job::{make_job, make_job_with};

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::{DitherMethod, FileGamma, FileType};

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
