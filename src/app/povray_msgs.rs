//! The message lines POV-Ray 3.7 writes on stderr, for programs that read them: printed, beside
//! lancer's own diagnostics, when lancer is invoked as `povray` (a symlink) or with
//! `--povray-messages`. The lines are those Debian's povray 3.7.0.10 prints with `-V`
//! (measured by tests/povray_mode.rs when povray is installed):
//!
//! ```text
//! File 'bad.pov' line 4: Parse Error: No matching } in 'sphere', box found instead
//! Fatal error in parser: Cannot parse input.
//! Render failed
//! ```
//!
//! and after a render the statistics block ending in `Render Time:` ... `POV-Ray finished`.
//!
//! Exit codes, in every mode, as povray's: 1 for a parse error, a missing scene or an output
//! that cannot be written; 2 for a user abort (SIGINT, SIGTERM). A usage error is 1 as
//! `povray` and 2 as `lancer`.

use std::sync::atomic::{AtomicBool, Ordering};

static POVRAY_MODE: AtomicBool = AtomicBool::new(false);

/// Whether the program name asks for POV-Ray's messages (`povray`, `povray3.7`, ...).
pub fn invoked_as_povray(argv0: &str) -> bool {
    std::path::Path::new(argv0)
        .file_name()
        .is_some_and(|n| n.to_string_lossy().starts_with("povray"))
}

pub fn set(on: bool) {
    POVRAY_MODE.store(on, Ordering::Relaxed);
}

pub fn on() -> bool {
    POVRAY_MODE.load(Ordering::Relaxed)
}

/// A parse error: `file` as the scene named it, `line` 1-based.
pub fn parse_error(file: Option<&str>, line: Option<usize>, message: &str) {
    if !on() {
        return;
    }
    match (file, line) {
        (Some(f), Some(l)) => eprintln!("File '{f}' line {l}: Parse Error: {message}"),
        _ => eprintln!("Parse Error: {message}"),
    }
    eprintln!("Fatal error in parser: Cannot parse input.");
    eprintln!("Render failed");
}

/// The scene file cannot be opened.
pub fn missing_input(name: &str) {
    if !on() {
        return;
    }
    eprintln!(
        "Possible Parse Error: Cannot find file '{name}', even after trying to append file type extension."
    );
    eprintln!("Parse Error: Cannot open input file.");
    eprintln!("Fatal error in parser: Cannot parse input.");
    eprintln!("Render failed");
}

/// Any other failure (the output cannot be written, ...).
pub fn render_failed() {
    if on() {
        eprintln!("Render failed");
    }
}

/// What a user abort prints; the process then exits with 2.
pub fn aborted_text(signal: &str) -> String {
    if on() {
        format!(
            "povray: received signal {signal}; requested render cancel\n\
             Fatal error in renderer: Frontend halted render.\n\
             Render cancelled by user\n"
        )
    } else {
        format!("lancer: interrupted ({signal}); nothing written\n")
    }
}

/// `0 hours  0 minutes  1 seconds (1.234 seconds)`.
fn duration(label: &str, secs: f64) -> String {
    let whole = secs.max(0.0) as u64;
    format!(
        "  {label:<18}{} hours {:>2} minutes {:>2} seconds ({secs:.3} seconds)",
        whole / 3600,
        whole / 60 % 60,
        whole % 60
    )
}

/// The process's CPU time so far (user + system), from /proc on Linux.
fn cpu_seconds() -> f64 {
    let Ok(stat) = std::fs::read_to_string("/proc/self/stat") else {
        return 0.0;
    };
    // Fields after the command name in parentheses; utime and stime are the 14th and 15th.
    let rest = stat.rsplit_once(')').map_or("", |(_, r)| r);
    let f: Vec<&str> = rest.split_whitespace().collect();
    let ticks = |i: usize| f.get(i).and_then(|v| v.parse::<f64>().ok()).unwrap_or(0.0);
    (ticks(11) + ticks(12)) / 100.0
}

pub struct Stats {
    pub width: u32,
    pub height: u32,
    pub parse_seconds: f64,
    pub build_seconds: f64,
    pub trace_seconds: f64,
    pub rays: u64,
    pub camera_rays: u64,
    pub threads: usize,
}

const RULE: &str = "----------------------------------------------------------------------------";

/// The statistics POV-Ray prints after a frame, ending in `POV-Ray finished` after the last.
pub fn statistics(s: &Stats, last: bool) {
    if !on() {
        return;
    }
    let using = |t: usize| {
        format!(
            "              using {t} thread(s) with {:.3} CPU-seconds total",
            cpu_seconds()
        )
    };
    let pixels = s.width as u64 * s.height as u64;
    let mut out = vec![
        "Parser Time".to_string(),
        duration("Parse Time:", s.parse_seconds),
        using(1),
        duration("Bounding Time:", s.build_seconds),
        using(1),
        RULE.into(),
        "Render Statistics".into(),
        format!("Image Resolution {} x {}", s.width, s.height),
        RULE.into(),
        format!(
            "Pixels:      {pixels:>10}   Samples:     {:>10}   Smpls/Pxl: {:.2}",
            s.camera_rays.saturating_sub(pixels),
            s.camera_rays.saturating_sub(pixels) as f64 / pixels.max(1) as f64
        ),
        format!("Rays:        {:>10}", s.rays),
        RULE.into(),
        "Render Time:".into(),
        "  Photon Time:      No photons".into(),
        "  Radiosity Time:   No radiosity".into(),
        duration("Trace Time:", s.trace_seconds),
        using(s.threads),
    ];
    if last {
        out.push("POV-Ray finished".into());
    }
    eprintln!("{}", out.join("\n"));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn program_names() {
        assert!(invoked_as_povray("/usr/local/bin/povray"));
        assert!(invoked_as_povray("povray3.7"));
        assert!(!invoked_as_povray("/usr/bin/lancer"));
    }

    #[test]
    fn durations_as_povray_prints_them() {
        assert_eq!(
            duration("Trace Time:", 0.0),
            "  Trace Time:       0 hours  0 minutes  0 seconds (0.000 seconds)"
        );
        assert_eq!(
            duration("Parse Time:", 3725.5),
            "  Parse Time:       1 hours  2 minutes  5 seconds (3725.500 seconds)"
        );
    }
}
