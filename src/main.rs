//! The `lancer` command: renders POV-Ray scenes. Exit codes: 0 success, 1 scene or output
//! error, 2 usage error.

use std::process::ExitCode;

use clap::Parser as _;

use lancer::cli::{make_job, split_args, Cli, Command};

mod commands;
mod render_cmd;

fn main() -> ExitCode {
    // INI files on the command line become the switches they hold, where they stand.
    let mut ini_warnings = Vec::new();
    let args = match lancer::ini::expand(std::env::args().collect(), &mut ini_warnings) {
        Ok(a) => a,
        Err(e) => {
            eprintln!("lancer: {e}");
            return ExitCode::from(2);
        }
    };
    for w in &ini_warnings {
        eprintln!("warning: {w}");
    }
    let (clap_args, pov) = split_args(args);
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
            Ok(job) => {
                let (display, pause) = (job.display, job.pause);
                let size = (job.settings.width, job.settings.height);
                lancer::preview::display::run(display, pause, size, move |feed| {
                    render_cmd::render(job, feed)
                })
            }
            Err(e) => {
                eprintln!("lancer: {e}");
                ExitCode::from(2)
            }
        },
        Command::Compare(args) => commands::compare(args),
        Command::Check(args) => commands::check(args, &pov),
        Command::Conformance(args) => commands::conformance(args),
        Command::Preview(args) => match make_job(args.render, &pov) {
            Ok(job) => {
                let options = lancer::preview::Options {
                    screenshot: args.screenshot,
                    screenshot_exit: args.exit_after_screenshot,
                    bench: args.bench,
                    full_resolution: args.full_resolution,
                    follow_scene_camera: true,
                };
                ExitCode::from(lancer::preview::run(job, options))
            }
            Err(e) => {
                eprintln!("lancer: {e}");
                ExitCode::from(2)
            }
        },
    }
}
