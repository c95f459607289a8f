//! The `lancer` command: renders POV-Ray scenes. Exit codes: 0 success, 1 scene or output
//! error, 2 usage error.

use std::process::ExitCode;
use std::time::Instant;

use clap::Parser as _;
use indicatif::{ProgressBar, ProgressStyle};

use lancer::cli::{make_job, split_args, Cli, Command};
use lancer::sdl::ParseOptions;

mod commands;

fn main() -> ExitCode {
    let (clap_args, pov) = split_args(std::env::args().collect());
    let cli = match Cli::try_parse_from(clap_args) {
        Ok(c) => c,
        Err(e) => {
            let code = if e.use_stderr() { 2 } else { 0 };
            let _ = e.print();
            return ExitCode::from(code);
        }
    };
    match cli.command {
        Command::Render(args) => match make_job(args, &pov) {
            Ok(job) => render(job),
            Err(e) => {
                eprintln!("lancer: {e}");
                ExitCode::from(2)
            }
        },
        Command::Compare(args) => commands::compare(args),
        Command::Check(args) => commands::check(args, &pov),
        Command::Conformance(args) => commands::conformance(args),
    }
}

fn render(job: lancer::cli::Job) -> ExitCode {
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
    let start = Instant::now();
    let mut opts = ParseOptions {
        library_paths: job.library_paths.clone(),
        image_width: job.settings.width,
        image_height: job.settings.height,
        ..ParseOptions::default()
    };
    job.safety.apply(&mut opts);
    let parsed = lancer::api::parse_file(&job.scene, opts);
    let sources = &parsed.parser.sources;
    for w in &parsed.parser.warnings {
        w.emit_stderr(sources);
    }
    if let Some(e) = &parsed.error {
        e.emit_stderr(sources);
        return ExitCode::from(1);
    }
    let parse_time = start.elapsed();
    let built = lancer::scene::build::build(
        &parsed.parser.scene,
        job.settings.width,
        job.settings.height,
    );
    for w in &built.warnings {
        eprintln!("warning: {w}");
    }
    let show = !job.quiet && std::io::IsTerminal::is_terminal(&std::io::stderr());
    let bar = if show {
        ProgressBar::new(job.settings.height as u64)
    } else {
        ProgressBar::hidden()
    };
    bar.set_style(
        ProgressStyle::with_template("{spinner} rendering [{bar:40}] {pos}/{len} rows, {eta} left")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    let trace_start = Instant::now();
    let film = lancer::render::render(&built.scene, &job.settings, &|n| bar.inc(n));
    bar.finish_and_clear();
    if let Err(e) = lancer::output::write(&film, &job.output, job.format) {
        eprintln!("lancer: {e}");
        return ExitCode::from(1);
    }
    if !job.quiet {
        eprintln!(
            "lancer: wrote {} ({}x{}) — parse {:.3}s, render {:.3}s",
            job.output.display(),
            job.settings.width,
            job.settings.height,
            parse_time.as_secs_f64(),
            trace_start.elapsed().as_secs_f64()
        );
    }
    ExitCode::SUCCESS
}
