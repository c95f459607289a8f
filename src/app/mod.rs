//! The `lancer` command's work, in the library so that the binary and the Python module's
//! `lancer` command run the same code: INI expansion, configuration files, the subcommands.
//! Reads POV-Ray's povray.ini and povray.conf as povray does unless `--no-config` /
//! `LANCER_NO_CONFIG=1` (config.rs).

use std::process::ExitCode;

use clap::Parser as _;

use crate::cli::{make_job_with, split_args, Cli, Command};

mod commands;
pub mod povray_msgs;
mod render_cmd;

/// Set by `main`: the process is the `lancer` command, which exits after one `run`.
static OWN_PROCESS: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// `run` as the `lancer` command's whole life: what it sets up for one render need not be
/// undone for the next (see `render_cmd::render`).
pub fn run_main(args: Vec<String>) -> ExitCode {
    OWN_PROCESS.store(true, std::sync::atomic::Ordering::Relaxed);
    run(args)
}

/// Runs the `lancer` command with `args` (the program name first) and returns its exit code:
/// 0 success, 1 scene or output error, 2 usage error.
pub fn run(args: Vec<String>) -> ExitCode {
    // INI files on the command line become the switches they hold, where they stand.
    let mut ini_warnings = Vec::new();
    let raw = args;
    let hermetic = crate::config::disabled(&raw);
    let as_povray = raw
        .first()
        .is_some_and(|a| povray_msgs::invoked_as_povray(a));
    povray_msgs::set(as_povray || raw.iter().skip(1).any(|a| a == "--povray-messages"));
    // POV-Ray exits with 1 when it cannot read its options; lancer has kept 2.
    let usage = if as_povray { 1 } else { 2 };
    let args = match crate::ini::expand(raw, &mut ini_warnings) {
        Ok(a) => a,
        Err(e) => {
            eprintln!("lancer: {e}");
            return ExitCode::from(usage);
        }
    };
    for w in &ini_warnings {
        eprintln!("warning: {w}");
    }
    let (clap_args, pov) = split_args(args);
    let cli = match Cli::try_parse_from(clap_args) {
        Ok(c) => c,
        Err(e) => {
            let code = if e.use_stderr() { usage } else { 0 };
            let _ = e.print();
            return ExitCode::from(code);
        }
    };
    let config = || {
        if hermetic {
            return Ok(crate::config::Config::default());
        }
        let mut w = Vec::new();
        let c = crate::config::load(&crate::config::Places::from_env(), &mut w);
        for w in &w {
            eprintln!("warning: {w}");
        }
        c
    };
    let config = match &cli.command {
        Command::Render(_) | Command::Check(_) | Command::Preview(_) => match config() {
            Ok(c) => c,
            Err(e) => {
                eprintln!("lancer: {e}");
                return ExitCode::from(usage);
            }
        },
        _ => crate::config::Config::default(),
    };
    match cli.command {
        Command::Render(args) => match make_job_with(args, &config, &pov) {
            Ok(job) => {
                on_abort_exit();
                let (display, pause) = (job.display, job.pause);
                let size = (job.settings.width, job.settings.height);
                crate::preview::display::run(display, pause, size, move |feed| {
                    render_cmd::render(job, feed)
                })
            }
            Err(e) => {
                eprintln!("lancer: {e}");
                if povray_msgs::on() {
                    eprintln!("Failed to parse command-line option");
                }
                ExitCode::from(usage)
            }
        },
        Command::Compare(args) => commands::compare(args),
        Command::Check(args) => commands::check(args, &config, &pov),
        Command::Conformance(args) => commands::conformance(args),
        Command::Preview(args) => match make_job_with(args.render, &config, &pov) {
            Ok(job) => {
                let options = crate::preview::Options {
                    screenshot: args.screenshot,
                    screenshot_exit: args.exit_after_screenshot,
                    bench: args.bench,
                    full_resolution: args.full_resolution,
                    follow_scene_camera: true,
                };
                ExitCode::from(crate::preview::run(job, options))
            }
            Err(e) => {
                eprintln!("lancer: {e}");
                ExitCode::from(usage)
            }
        },
    }
}

/// A user abort (SIGINT, SIGTERM) ends a render at once with exit code 2, as povray's: no
/// picture is written (pictures are renamed into place only when complete).
/// The signal's own handler writes the message and exits: a thread waiting for the signal
/// (signal-hook's iterator: a socket pair, a thread and its malloc arena) cost about 0.1 ms
/// of every process's CPU time.
fn on_abort_exit() {
    use signal_hook::consts::{SIGINT, SIGTERM};
    use std::io::Write;
    use std::os::fd::FromRawFd;
    for (sig, name) in [
        (SIGINT, "SIGINT: Interrupt"),
        (SIGTERM, "SIGTERM: Termination"),
    ] {
        // Made now: the handler may not allocate.
        let text = povray_msgs::aborted_text(name);
        let action = move || {
            // SAFETY: fd 2 is the process's standard error, which this `File` borrows and
            // never closes (`ManuallyDrop`).
            let mut err = std::mem::ManuallyDrop::new(unsafe { std::fs::File::from_raw_fd(2) });
            let _ = err.write_all(text.as_bytes());
            signal_hook::low_level::exit(2);
        };
        // SAFETY: the action is async-signal-safe: write(2) of bytes made beforehand and
        // _exit(2); it allocates nothing and takes no lock.
        let _ = unsafe { signal_hook::low_level::register(sig, action) };
    }
}

/// `run`'s exit code as a number, for callers that are not a Rust `main` (the Python module).
pub fn run_status(args: Vec<String>) -> u8 {
    let code = run(args);
    (0..=255u8)
        .find(|&c| ExitCode::from(c) == code)
        .unwrap_or(1)
}
