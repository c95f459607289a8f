//! Image tests: every row of reference/manifest.tsv is rendered by lancer with the row's
//! POV-Ray options and compared with POV-Ray's picture by SSIM; each row states its own
//! tolerance and why. One test renders all rows so a failure shows the whole table.

use std::path::{Path, PathBuf};

use lancer::cli::{make_job, split_args, Cli, Command};
use lancer::ssim::{ssim, Picture};

use clap::Parser as _;

struct Row {
    scene: String,
    options: String,
    reference: String,
    min_ssim: f64,
}

fn manifest() -> Vec<Row> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join("reference/manifest.tsv"))
        .expect("reference/manifest.tsv");
    text.lines()
        .skip(1)
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let f: Vec<&str> = l.split('\t').collect();
            Row {
                scene: f[0].into(),
                options: f[1].into(),
                reference: f[2].into(),
                min_ssim: f[3].parse().expect("min_ssim"),
            }
        })
        .collect()
}

fn render_row(row: &Row) -> Result<Picture, String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let scene: PathBuf = root.join("scenes").join(&row.scene);
    let mut args = vec!["lancer".to_string(), scene.display().to_string()];
    args.extend(row.options.split_whitespace().map(String::from));
    let (c, pov) = split_args(args);
    let Command::Render(r) = Cli::try_parse_from(c).map_err(|e| e.to_string())?.command else {
        return Err(format!(
            "manifest options for {} are not a render",
            row.scene
        ));
    };
    let job = make_job(r, &pov)?;
    let film = lancer::api::render_file(&job.scene, &job.library_paths, &job.settings)?;
    Ok(Picture::from_rgb8(
        film.width,
        film.height,
        &lancer::output::to_rgb8(&film),
    ))
}

#[test]
fn scenes_match_povray_references() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut failures = Vec::new();
    let mut table = String::from("\nscene                 options              ssim    min\n");
    for row in manifest() {
        let reference =
            Picture::load(&root.join("reference").join(&row.reference)).expect("reference picture");
        let start = std::time::Instant::now();
        let result = render_row(&row).and_then(|p| ssim(&p, &reference));
        let secs = start.elapsed().as_secs_f64();
        match result {
            Ok(s) => {
                table += &format!(
                    "{:<21} {:<20} {:.4}  {:.2}  ({secs:.2}s)\n",
                    row.scene, row.options, s, row.min_ssim
                );
                if s < row.min_ssim {
                    failures.push(format!(
                        "{} {}: SSIM {s:.4} < {}",
                        row.scene, row.options, row.min_ssim
                    ));
                }
            }
            Err(e) => failures.push(format!("{} {}: {e}", row.scene, row.options)),
        }
    }
    eprintln!("{table}");
    assert!(failures.is_empty(), "{}\n{table}", failures.join("\n"));
}
