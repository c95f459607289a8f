//! The `lancer` command: renders POV-Ray scenes. Exit codes: 0 success, 1 scene or output
//! error, 2 usage error. Reads POV-Ray's povray.ini and povray.conf as povray does unless
//! `--no-config` / `LANCER_NO_CONFIG=1` (config.rs).

use std::process::ExitCode;

use clap::Parser as _;

use lancer::cli::{make_job_with, split_args, Cli, Command};

mod commands;
mod render_cmd;

fn main() -> ExitCode {
    // INI files on the command line become the switches they hold, where they stand.
    let mut ini_warnings = Vec::new();
    let raw: Vec<String> = std::env::args().collect();
    let hermetic = lancer::config::disabled(&raw);
    let args = match lancer::ini::expand(raw, &mut ini_warnings) {
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
    let config = || {
        if hermetic {
            return Ok(lancer::config::Config::default());
        }
        let mut w = Vec::new();
        let c = lancer::config::load(&lancer::config::Places::from_env(), &mut w);
        for w in &w {
            eprintln!("warning: {w}");
        }
        c
    };
    let config = match &cli.command {
        Command::Render(_) | Command::Check(_) => match config() {
            Ok(c) => c,
            Err(e) => {
                eprintln!("lancer: {e}");
                return ExitCode::from(2);
            }
        },
        _ => lancer::config::Config::default(),
    };
    match cli.command {
        Command::Render(args) => match make_job_with(args, &config, &pov) {
            Ok(job) => render_cmd::render(job),
            Err(e) => {
                eprintln!("lancer: {e}");
                ExitCode::from(2)
            }
        },
        Command::Compare(args) => commands::compare(args),
        Command::Check(args) => commands::check(args, &config, &pov),
        Command::Conformance(args) => commands::conformance(args),
    }
}
