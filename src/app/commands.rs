//! The `compare`, `check` and `conformance` subcommands of the `lancer` command (rendering
//! lives in render_cmd.rs). Each returns the process exit code.

use std::process::ExitCode;
use std::time::Duration;

use crate::cli::{make_job_with, CheckArgs, CompareArgs, ConformanceArgs, RenderArgs};
use crate::conformance::{self, report, Options};

pub fn compare(a: CompareArgs) -> ExitCode {
    let (c, base) = match crate::compare::compare_files(&a.a, &a.b) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("lancer compare: {}", e.0);
            return ExitCode::from(2);
        }
    };
    // A closed pipe (`lancer compare a b | head -1`) is not an error worth a panic.
    let _ = std::io::Write::write_all(&mut std::io::stdout(), c.report().as_bytes());
    if let Some(path) = &a.diff {
        if let Err(e) = c.write_heat_map(&base, path) {
            eprintln!("lancer compare: cannot write the heat map: {e}");
            return ExitCode::from(2);
        }
    }
    if let Some(path) = &a.html {
        let page = (|| -> Result<String, String> {
            let pb = crate::ssim::Picture::load(&a.b)?;
            Ok(crate::html_report::compare_page(
                &a.a.display().to_string(),
                &a.b.display().to_string(),
                &crate::compare::picture_png(&base)?,
                &crate::compare::picture_png(&pb)?,
                &c.heat_map_png(&base)?,
                &c,
            ))
        })();
        let written = page.and_then(|p| {
            crate::output::write_atomic(path, |tmp| {
                std::fs::write(tmp, p.as_bytes()).map_err(|e| e.to_string())
            })
        });
        if let Err(e) = written {
            eprintln!("lancer compare: cannot write the HTML page: {e}");
            return ExitCode::from(2);
        }
    }
    match a.min_ssim {
        Some(min) if c.ssim < min => {
            eprintln!(
                "lancer compare: SSIM {:.6} is below the minimum {min}",
                c.ssim
            );
            ExitCode::from(1)
        }
        _ => ExitCode::SUCCESS,
    }
}

pub fn check(a: CheckArgs, config: &crate::config::Config, pov: &[String]) -> ExitCode {
    let mut failed = 0;
    for file in &a.files {
        // The same options as a render of the file would get (+L, +W/+H, Declare=, +K, ...).
        let args = RenderArgs {
            scene: Some(file.clone()),
            library_path: a.library_path.clone(),
            safety: a.safety.clone(),
            ..RenderArgs::default()
        };
        let job = match make_job_with(args, config, pov) {
            Ok(j) => j,
            Err(e) => {
                eprintln!("lancer check: {e}");
                return ExitCode::from(2);
            }
        };
        let frame = match job.animation.frames(&job.output) {
            Ok(f) => f.into_iter().next().expect("at least one frame"),
            Err(e) => {
                eprintln!("lancer check: {e}");
                return ExitCode::from(2);
            }
        };
        if file == &a.files[0] && !a.quiet {
            for w in &job.warnings {
                eprintln!("warning: {w}");
            }
        }
        let opts = job.parse_options(&frame);
        let parsed = crate::api::parse_file(file, opts);
        let sources = &parsed.parser.sources;
        if !a.quiet {
            for w in &parsed.parser.warnings {
                w.emit_stderr(sources);
            }
        }
        match &parsed.error {
            Some(e) => {
                e.emit_stderr(sources);
                failed += 1;
            }
            None if !a.quiet => eprintln!(
                "{}: ok ({} warning{})",
                file.display(),
                parsed.parser.warnings.len(),
                if parsed.parser.warnings.len() == 1 {
                    ""
                } else {
                    "s"
                }
            ),
            None => {}
        }
    }
    if a.files.len() > 1 {
        eprintln!(
            "lancer check: {} of {} files parsed without errors",
            a.files.len() - failed,
            a.files.len()
        );
    }
    if failed > 0 {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

pub fn conformance(a: ConformanceArgs) -> ExitCode {
    match run_conformance(a) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("lancer conformance: {e}");
            ExitCode::from(2)
        }
    }
}

fn run_conformance(a: ConformanceArgs) -> Result<ExitCode, String> {
    let subset = a
        .subset
        .as_deref()
        .map(conformance::read_subset)
        .transpose()?;
    if !a.scenes.is_dir() {
        return Err(format!(
            "no scenes at {} (apt-get install povray-examples, or give --scenes DIR)",
            a.scenes.display()
        ));
    }
    let lancer = std::env::current_exe().map_err(|e| format!("cannot find lancer itself: {e}"))?;
    let o = Options {
        root: a.scenes.clone(),
        only: subset.as_ref().map(|s| s.scenes.clone()),
        cache: a
            .cache
            .clone()
            .unwrap_or_else(conformance::cache::default_dir),
        jobs: a.jobs,
        width: a.width,
        height: a.height,
        pov_limit: Duration::from_secs(a.povray_timeout),
        lancer_limit: Duration::from_secs(a.lancer_timeout),
        povray: a.povray.clone(),
        lancer,
        verbose: !a.quiet,
        pictures: a.report.as_ref().map(|p| files_dir(p)),
    };
    if let Some(d) = &o.pictures {
        std::fs::create_dir_all(d).map_err(|e| format!("cannot create {}: {e}", d.display()))?;
    }
    let results = conformance::run(&o)?;
    let summary = report::summarize(&results);
    println!("{}", summary.line());
    if let Some(prefix) = &a.report {
        let header = format!(
            "Generated by `lancer conformance` (lancer {}) over `{}`: {}×{}, no anti-aliasing, one thread, POV-Ray limited to {} s and lancer to {} s per scene. POV-Ray's renders are cached by scene content and options.",
            env!("CARGO_PKG_VERSION"),
            a.scenes.display(),
            a.width,
            a.height,
            a.povray_timeout,
            a.lancer_timeout
        );
        let known = a
            .known
            .as_deref()
            .map(report::read_known)
            .transpose()?
            .unwrap_or_default();
        let md = report::markdown(&results, &header, &known);
        crate::output::write_text_atomic(&prefix.with_extension("md"), &md)?;
        crate::output::write_text_atomic(
            &prefix.with_extension("tsv"),
            &report::tsv(&results, &known),
        )?;
        let dir = files_dir(prefix);
        let rel = dir.file_name().map(|n| n.to_string_lossy().into_owned());
        let pictures: Vec<_> = results
            .iter()
            .map(|r| {
                let names = conformance::picture_names(&r.name);
                let at = |n: &String| format!("{}/{n}", rel.clone().unwrap_or_default());
                dir.join(&names[2])
                    .exists()
                    .then(|| crate::html_report::ScenePictures {
                        povray: at(&names[0]),
                        lancer: at(&names[1]),
                        diff: at(&names[2]),
                    })
            })
            .collect();
        let page = crate::html_report::conformance_page(
            "lancer conformance",
            &format!("{}. {header}", summary.line()),
            &results,
            &pictures,
            a.width,
        );
        crate::output::write_text_atomic(&prefix.with_extension("html"), &page)?;
    }
    if let Some(path) = &a.write_subset {
        write_subset(path, &results, a.subset_seconds)?;
    }
    if let Some(min) = subset.and_then(|s| s.min_good) {
        if summary.good < min {
            eprintln!(
                "lancer conformance: ratchet failed: {} scenes at SSIM ≥ 0.95, the committed count is {min}",
                summary.good
            );
            return Ok(ExitCode::from(1));
        }
        println!(
            "ratchet ok: {} scenes at SSIM ≥ 0.95 (at least {min} required)",
            summary.good
        );
    }
    Ok(ExitCode::SUCCESS)
}

/// Where the HTML report's pictures go: `PREFIX_files` beside `PREFIX.html`.
fn files_dir(prefix: &std::path::Path) -> std::path::PathBuf {
    let mut name = prefix.file_name().unwrap_or_default().to_os_string();
    name.push("_files");
    prefix.with_file_name(name)
}

/// The CI subset: every good scene POV-Ray renders quickly, so CI can afford to render them
/// again on a clean machine; their count is the ratchet.
fn write_subset(
    path: &std::path::Path,
    results: &[conformance::SceneResult],
    max_seconds: f64,
) -> Result<(), String> {
    let good: Vec<&str> = results
        .iter()
        .filter(|r| r.class == conformance::Class::Good && r.pov.seconds <= max_seconds)
        .map(|r| r.name.as_str())
        .collect();
    if path.exists() {
        let old = conformance::read_subset(path)?;
        if let Some(min) = old.min_good.filter(|&m| m > good.len()) {
            return Err(format!(
                "the ratchet in {} would go down from {min} to {}; fix the regression, or edit the file by hand and say why there",
                path.display(),
                good.len()
            ));
        }
    }
    let mut text = format!(
        "# Scenes CI renders with povray and lancer (written by `lancer conformance --write-subset`):\n\
# the sample scenes at SSIM >= 0.95 that POV-Ray renders within {max_seconds} s.\n\
# .ci/run fails when fewer than min_good of them reach SSIM 0.95.\n\
min_good {}\n",
        good.len()
    );
    for g in good {
        text.push_str(g);
        text.push('\n');
    }
    crate::output::write_text_atomic(path, &text)
}
