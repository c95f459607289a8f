//! `lancer render` (the default command): a still picture, or an animation frame by frame with
//! the scene parsed anew for each frame, as POV-Ray does. Part of the binary.

use std::collections::HashSet;
use std::process::ExitCode;
use std::time::Instant;

use indicatif::{MultiProgress, ProgressBar, ProgressStyle};

use lancer::anim::Frame;
use lancer::cli::Job;

pub fn render(job: Job) -> ExitCode {
    for w in &job.warnings {
        eprintln!("warning: {w}");
    }
    if let Some(n) = job.threads {
        if let Err(e) = rayon::ThreadPoolBuilder::new()
            .num_threads(n.max(1))
            .build_global()
        {
            eprintln!("warning: cannot set the thread count: {e}");
        }
    }
    let frames = match job.animation.frames(&job.output) {
        Ok(f) => f,
        Err(e) => {
            eprintln!("lancer: {e}");
            return ExitCode::from(2);
        }
    };
    let animated = job.animation.is_animation();
    let show = !job.quiet && std::io::IsTerminal::is_terminal(&std::io::stderr());
    let bars = MultiProgress::new();
    let frame_bar = if show && animated {
        bars.add(ProgressBar::new(frames.len() as u64))
    } else {
        ProgressBar::hidden()
    };
    frame_bar.set_style(
        ProgressStyle::with_template("animation [{bar:40}] {pos}/{len} frames, {eta} left")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    // The scene is parsed for every frame; its warnings are the same each time, and the files
    // it reads are lexed once and handed from frame to frame.
    let mut said = HashSet::new();
    let mut lexed = None;
    let start = Instant::now();
    for f in &frames {
        if job.continue_trace && f.output.exists() {
            if !job.quiet {
                eprintln!(
                    "lancer: frame {} done already ({}), skipped",
                    f.number,
                    f.output.display()
                );
            }
            frame_bar.inc(1);
            continue;
        }
        let row_bar = if show {
            bars.add(ProgressBar::new(job.settings.height as u64))
        } else {
            ProgressBar::hidden()
        };
        let last = std::ptr::eq(f, frames.last().unwrap_or(f));
        let code = render_frame(&job, f, animated, last, &mut said, &mut lexed, &row_bar);
        row_bar.finish_and_clear();
        bars.remove(&row_bar);
        if code != ExitCode::SUCCESS {
            return code;
        }
        frame_bar.inc(1);
    }
    frame_bar.finish_and_clear();
    // The lexed files are freed by the exit that follows.
    lancer::stats::dispose(lexed, true);
    if animated && !job.quiet {
        eprintln!(
            "lancer: {} frames in {:.2}s",
            frames.len(),
            start.elapsed().as_secs_f64()
        );
    }
    ExitCode::SUCCESS
}

fn render_frame(
    job: &Job,
    f: &Frame,
    animated: bool,
    last: bool,
    said: &mut HashSet<String>,
    lexed: &mut Option<lancer::sdl::parser::Lexed>,
    bar: &ProgressBar,
) -> ExitCode {
    let start = Instant::now();
    let opts = job.parse_options(f);
    let mut parsed = lancer::api::parse_file_with(&job.scene, opts, lexed.take());
    let sources = &parsed.parser.sources;
    for w in &parsed.parser.warnings {
        if said.insert(w.one_line(sources)) {
            w.emit_stderr(sources);
        }
    }
    if let Some(e) = &parsed.error {
        e.emit_stderr(sources);
        return ExitCode::from(1);
    }
    let parse_time = start.elapsed();
    let files = parsed.parser.take_lexed();
    let build_start = Instant::now();
    if last {
        // No later frame needs the tokens: a big mesh2 file's are hundreds of megabytes,
        // freed before the build adds its own.
        drop(files);
    } else {
        *lexed = Some(files);
    }
    let built = lancer::scene::build::build(
        &parsed.parser.scene,
        job.settings.width,
        job.settings.height,
    );
    // The description is no longer needed; freeing it is part of the build's time.
    drop(parsed);
    let build_time = build_start.elapsed();
    for w in &built.warnings {
        if said.insert(w.clone()) {
            eprintln!("warning: {w}");
        }
    }
    bar.set_style(
        ProgressStyle::with_template("{spinner} rendering [{bar:40}] {pos}/{len} rows, {eta} left")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    let trace_start = Instant::now();
    let film = lancer::render::render(&built.scene, &job.settings, &|n| bar.inc(n));
    let render_time = trace_start.elapsed();
    let phases = |write: Option<f64>| {
        let write = write.map_or(String::new(), |w| format!(", write {w:.3}s"));
        let peak = lancer::stats::peak_rss_bytes()
            .map_or(String::new(), |b| format!(", peak {} MB", b / (1 << 20)));
        format!(
            "parse {:.3}s, build {:.3}s, render {:.3}s{write}{peak}",
            parse_time.as_secs_f64(),
            build_time.as_secs_f64(),
            render_time.as_secs_f64(),
        )
    };
    if !job.write_output {
        if !job.quiet {
            eprintln!(
                "lancer: rendered frame {} without writing it (Output_To_File=off / -F) — {}",
                f.number,
                phases(None)
            );
        }
        lancer::stats::dispose(built.scene, last);
        return ExitCode::SUCCESS;
    }
    let write_start = Instant::now();
    if let Err(e) = lancer::output::write(&film, &f.output, &job.output_spec) {
        eprintln!("lancer: {e}");
        return ExitCode::from(1);
    }
    let write_time = write_start.elapsed();
    if !job.quiet {
        let frame = if animated {
            format!("frame {} (clock {}): ", f.number, f.clock)
        } else {
            String::new()
        };
        eprintln!(
            "lancer: {frame}wrote {} ({}x{}) — {}, {} rays ({} camera)",
            f.output.display(),
            job.settings.width,
            job.settings.height,
            phases(Some(write_time.as_secs_f64())),
            film.rays,
            film.camera_rays
        );
    }
    lancer::stats::dispose(built.scene, last);
    ExitCode::SUCCESS
}
