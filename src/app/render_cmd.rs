//! `lancer render` (the default command): a still picture, or an animation frame by frame with
//! the scene parsed anew for each frame, as POV-Ray does. Part of the `lancer` command (app).

use std::collections::HashSet;
use std::process::ExitCode;
use std::time::Instant;

use indicatif::{MultiProgress, ProgressBar, ProgressStyle};

use crate::anim::Frame;
use crate::cli::Job;
use crate::preview::display::Feed;

use super::povray_msgs;

/// Renders the job; with `feed` (`+D`) each picture is also shown as it is drawn.
pub fn render(job: Job, feed: Option<Feed>) -> ExitCode {
    for w in &job.warnings {
        eprintln!("warning: {w}");
    }
    if job.threads == Some(1) && super::OWN_PROCESS.load(std::sync::atomic::Ordering::Relaxed) {
        // One thread: this thread is the pool's only worker, so no thread is started and none
        // spins waiting while the scene is parsed and written (a tenth of a one-pixel
        // render's CPU time). The pool is left behind at exit (rayon cannot take a current
        // thread back out of a pool), which is why only the `lancer` command does this, not
        // the Python module that calls `run` again; any other thread (the +D window) still
        // finds rayon's global pool.
        if let Ok(pool) = rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .use_current_thread()
            .build()
        {
            return pool.install(|| render_frames(job, feed));
        }
    }
    if let Some(n) = job.threads {
        if let Err(e) = rayon::ThreadPoolBuilder::new()
            .num_threads(n.max(1))
            .build_global()
        {
            eprintln!("warning: cannot set the thread count: {e}");
        }
    }
    render_frames(job, feed)
}

/// `render`'s frames, in whichever thread pool it chose.
fn render_frames(job: Job, feed: Option<Feed>) -> ExitCode {
    let frames = match job.animation.frames(&job.output) {
        Ok(f) => f,
        Err(e) => {
            eprintln!("lancer: {e}");
            return ExitCode::from(2);
        }
    };
    let plan = match plan(&job) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("lancer: {e}");
            povray_msgs::render_failed();
            return ExitCode::from(1);
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
        let code = render_frame(
            &job,
            f,
            animated,
            last,
            plan,
            &mut said,
            &mut lexed,
            &row_bar,
            feed.as_ref(),
        );
        row_bar.finish_and_clear();
        bars.remove(&row_bar);
        if code != ExitCode::SUCCESS {
            return code;
        }
        frame_bar.inc(1);
    }
    frame_bar.finish_and_clear();
    // The lexed files are freed by the exit that follows.
    crate::stats::dispose(lexed, true);
    if animated && !job.quiet {
        eprintln!(
            "lancer: {} frames in {:.2}s",
            frames.len(),
            start.elapsed().as_secs_f64()
        );
    }
    ExitCode::SUCCESS
}

/// How the picture is held: whole, or rendered and written band by band.
#[derive(Clone, Copy)]
enum Plan {
    Whole,
    /// Rows a band.
    Banded(usize),
}

/// Above this a picture is rendered band by band when its file type allows; below it the
/// whole-picture path keeps today's files byte for byte (a streamed PNG's compressed data is
/// split into other chunks). 4K pictures (3840×2160) stay below.
const BAND_ABOVE: u64 = 2 << 30;

/// Decides, before any work, how the picture is held; a picture that can neither be banded
/// nor fit in the memory available is refused with what it needs and how to avoid it.
fn plan(job: &Job) -> Result<Plan, String> {
    use crate::render::band;
    let s = &job.settings;
    let need = band::whole_picture_bytes(s);
    if need <= BAND_ABOVE {
        return Ok(Plan::Whole);
    }
    let why_not = if !band::can_band(s) {
        Some("anti-aliasing method 2 (+AM2) needs the whole picture".to_string())
    } else if job.write_output {
        crate::output::why_not_streamable(&job.output_spec)
    } else {
        None
    };
    let Some(why) = why_not else {
        return Ok(Plan::Banded(band::band_rows(s)));
    };
    let available = crate::stats::available_memory_bytes();
    if available.is_none_or(|a| need < a) {
        return Ok(Plan::Whole);
    }
    let gb = |b: u64| b as f64 / (1u64 << 30) as f64;
    Err(format!(
        "a {}x{} picture needs about {:.1} GB of memory to render whole ({why}), and {:.1} GB \
         are available; lancer renders PNG and PPM pictures band by band in bounded memory: \
         write PNG (+FN) or PPM (+FP), without dithering, with anti-aliasing method 1 (+AM1) \
         or none (-A)",
        s.width,
        s.height,
        gb(need),
        gb(available.unwrap_or(0)),
    ))
}

/// The most bytes of tokens the last frame leaves unfreed for the exit to take back.
const LEAVE_TOKENS_UP_TO: usize = 32 << 20;

#[allow(clippy::too_many_arguments)]
fn render_frame(
    job: &Job,
    f: &Frame,
    animated: bool,
    last: bool,
    plan: Plan,
    said: &mut HashSet<String>,
    lexed: &mut Option<crate::sdl::parser::Lexed>,
    bar: &ProgressBar,
    feed: Option<&Feed>,
) -> ExitCode {
    let start = Instant::now();
    let opts = job.parse_options(f);
    let mut parsed = crate::api::parse_file_with(&job.scene, opts, lexed.take());
    let sources = &parsed.parser.sources;
    for w in &parsed.parser.warnings {
        if said.insert(w.one_line(sources)) {
            w.emit_stderr(sources);
        }
    }
    if let Some(e) = &parsed.error {
        e.emit_stderr(sources);
        if !job.scene.is_file() {
            povray_msgs::missing_input(&job.scene.display().to_string());
        } else {
            let place = crate::api::ErrorPlace::of(e, sources);
            povray_msgs::parse_error(place.file.as_deref(), place.line, &e.message);
        }
        return ExitCode::from(1);
    }
    let parse_time = start.elapsed();
    let files = parsed.parser.take_lexed();
    let build_start = Instant::now();
    if last {
        // No later frame needs the tokens: a big mesh2 file's are hundreds of megabytes,
        // freed before the build adds its own. A few megabytes are left to the exit, as the
        // scene is: freeing them token by token was ~3 % of a small scene's process (the
        // include files of textures/pigments/mappr2 at 1x1).
        let small = files.token_bytes() <= LEAVE_TOKENS_UP_TO;
        let exiting = small && super::OWN_PROCESS.load(std::sync::atomic::Ordering::Relaxed);
        crate::stats::dispose(files, exiting);
    } else {
        *lexed = Some(files);
    }
    let built = crate::scene::build::build_consuming(
        &mut parsed.parser.scene,
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
    let (w, h) = (job.settings.width, job.settings.height);
    let progress = |n| bar.inc(n);
    let trace_start = Instant::now();
    let (rays, camera_rays, timing) = match plan {
        Plan::Whole => {
            // Without anti-aliasing, a display or a float file, each pixel is quantised as it
            // is traced: no film to fill and read back.
            let direct = (feed.is_none() && job.write_output && job.settings.antialias.is_none())
                .then(|| {
                    crate::output::Quantised::new(
                        &job.output_spec,
                        built.scene.gamma,
                        w,
                        h,
                        job.settings.alpha,
                    )
                })
                .flatten();
            let (rays, camera_rays, render_time, written) = if let Some(mut pic) = direct {
                let (samples, q) = pic.samples();
                let (rays, camera_rays) = crate::render::render_into(
                    &built.scene,
                    &job.settings,
                    &progress,
                    samples,
                    q.channels,
                    |seen, px| {
                        let c = seen.rgb;
                        q.put(c.x, c.y, c.z, 1.0 - seen.clear, px)
                    },
                );
                let render_time = trace_start.elapsed().as_secs_f64();
                let written = pic.write(&f.output, &job.output_spec);
                (rays, camera_rays, render_time, written)
            } else {
                let film = match feed {
                    Some(feed) => feed.render(&built.scene, &job.settings),
                    None => crate::render::render(&built.scene, &job.settings, &progress),
                };
                let render_time = trace_start.elapsed().as_secs_f64();
                let written = if job.write_output {
                    crate::output::write(&film, &f.output, &job.output_spec)
                } else {
                    Ok(())
                };
                (film.rays, film.camera_rays, render_time, written)
            };
            if let Err(e) = written {
                eprintln!("lancer: {e}");
                povray_msgs::render_failed();
                return ExitCode::from(1);
            }
            let timing = if job.write_output {
                let write = trace_start.elapsed().as_secs_f64() - render_time;
                format!("render {render_time:.3}s, write {write:.3}s")
            } else {
                format!("render {render_time:.3}s")
            };
            (rays, camera_rays, timing)
        }
        Plan::Banded(rows) => {
            use crate::render::band::render_bands;
            if feed.is_some() {
                eprintln!("warning: +D: a picture rendered band by band is not shown");
            }
            let scene = &built.scene;
            let s = &job.settings;
            let counts = if job.write_output {
                crate::output::write_banded(&f.output, &job.output_spec, w, h, |sink| {
                    render_bands(scene, s, rows, &progress, sink)
                })
            } else {
                render_bands(scene, s, rows, &progress, &mut |_| Ok(()))
            };
            let (rays, camera_rays) = match counts {
                Ok(c) => c,
                Err(e) => {
                    eprintln!("lancer: {e}");
                    povray_msgs::render_failed();
                    return ExitCode::from(1);
                }
            };
            let t = trace_start.elapsed().as_secs_f64();
            let what = if job.write_output {
                "render and write"
            } else {
                "render"
            };
            (
                rays,
                camera_rays,
                format!("{what} {t:.3}s in bands of {rows} rows"),
            )
        }
    };
    povray_msgs::statistics(
        &povray_msgs::Stats {
            width: w,
            height: h,
            parse_seconds: parse_time.as_secs_f64(),
            build_seconds: build_time.as_secs_f64(),
            trace_seconds: trace_start.elapsed().as_secs_f64(),
            rays,
            camera_rays,
            threads: rayon::current_num_threads(),
        },
        last,
    );
    if !job.quiet {
        let peak = crate::stats::peak_rss_bytes()
            .map_or(String::new(), |b| format!(", peak {} MB", b / (1 << 20)));
        let phases = format!(
            "parse {:.3}s, build {:.3}s, {timing}{peak}",
            parse_time.as_secs_f64(),
            build_time.as_secs_f64(),
        );
        if job.write_output {
            let frame = if animated {
                format!("frame {} (clock {}): ", f.number, f.clock)
            } else {
                String::new()
            };
            eprintln!(
                "lancer: {frame}wrote {} ({w}x{h}) — {phases}, {rays} rays ({camera_rays} camera)",
                f.output.display(),
            );
        } else {
            eprintln!(
                "lancer: rendered frame {} without writing it (Output_To_File=off / -F) — {phases}",
                f.number,
            );
        }
    }
    crate::stats::dispose(built.scene, last);
    ExitCode::SUCCESS
}
