//! The conformance runner (`lancer conformance`): renders a directory of scenes with `povray`
//! and with lancer under the same canonical options, compares the pictures with SSIM, and
//! writes the report that says how compatible lancer is and which missing keywords block the
//! most scenes. With a subset file it is also CI's ratchet.

pub mod cache;
pub mod process;
pub mod report;

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::Duration;

use cache::{Cache, PovResult, PovStatus};

/// Where Debian's povray-examples puts POV-Ray 3.7's sample scenes (a symlink into
/// /usr/share/doc, hence the link-following walk).
pub const DEFAULT_SCENES: &str = "/usr/share/povray-3.7/scenes";
pub const SYSTEM_INCLUDE: &str = "/usr/share/povray-3.7/include";

/// SSIM at or above which a scene counts as matching POV-Ray.
pub const GOOD: f64 = 0.95;
/// SSIM at or above which a scene is close: the same picture with details wrong.
pub const CLOSE: f64 = 0.80;

pub struct Options {
    /// The directory scenes are found in and named relative to.
    pub root: PathBuf,
    /// Only these scenes (relative to `root`), from a subset file; all `.pov` files otherwise.
    pub only: Option<Vec<String>>,
    pub cache: PathBuf,
    pub jobs: usize,
    pub width: u32,
    pub height: u32,
    pub pov_limit: Duration,
    pub lancer_limit: Duration,
    pub povray: PathBuf,
    pub lancer: PathBuf,
    /// Print one line per scene as it finishes.
    pub verbose: bool,
    /// Keep each scene's pictures here (POV-Ray's, lancer's and the heat map, named by
    /// `picture_names`) for the HTML report.
    pub pictures: Option<PathBuf>,
}

/// The file names of a scene's pictures in `Options::pictures`: POV-Ray's, lancer's, the
/// heat map.
pub fn picture_names(scene: &str) -> [String; 3] {
    let stem = scene.trim_end_matches(".pov").replace(['/', '\\'], "__");
    ["povray", "lancer", "diff"].map(|k| format!("{stem}-{k}.png"))
}

/// How lancer did on one scene, relative to POV-Ray.
#[derive(Clone, Debug, PartialEq)]
pub enum Class {
    Good,
    Close,
    Low,
    /// lancer exited with an error; the first error message.
    Error(String),
    Panic(String),
    Timeout,
    /// POV-Ray itself failed or timed out: listed, not counted.
    PovFailed(String),
}

impl Class {
    pub fn label(&self) -> &'static str {
        match self {
            Class::Good => "ssim>=0.95",
            Class::Close => "ssim>=0.80",
            Class::Low => "ssim<0.80",
            Class::Error(_) => "error",
            Class::Panic(_) => "panic",
            Class::Timeout => "timeout",
            Class::PovFailed(_) => "povray-failed",
        }
    }
}

pub struct SceneResult {
    pub name: String,
    pub class: Class,
    pub ssim: Option<f64>,
    pub lancer_seconds: f64,
    pub pov: PovResult,
    /// Keywords lancer warned it does not support, in first-seen order.
    pub missing: Vec<String>,
}

/// Every `.pov` file below `root`, following symbolic links, as sorted relative names.
pub fn find_scenes(root: &Path) -> Result<Vec<String>, String> {
    let mut out = Vec::new();
    let mut stack = vec![root.to_path_buf()];
    let mut seen = std::collections::HashSet::new();
    while let Some(dir) = stack.pop() {
        let canon = std::fs::canonicalize(&dir).unwrap_or(dir.clone());
        if !seen.insert(canon) {
            continue;
        }
        let entries =
            std::fs::read_dir(&dir).map_err(|e| format!("cannot read {}: {e}", dir.display()))?;
        for e in entries.flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|x| x.eq_ignore_ascii_case("pov")) {
                if let Ok(rel) = p.strip_prefix(root) {
                    out.push(rel.to_string_lossy().into_owned());
                }
            }
        }
    }
    out.sort();
    Ok(out)
}

/// Copies a directory tree, following symbolic links (the sample scenes are a link farm).
fn copy_tree(from: &Path, to: &Path) -> Result<(), String> {
    std::fs::create_dir_all(to).map_err(|e| format!("cannot create {}: {e}", to.display()))?;
    let entries =
        std::fs::read_dir(from).map_err(|e| format!("cannot read {}: {e}", from.display()))?;
    for e in entries.flatten() {
        let (src, dst) = (e.path(), to.join(e.file_name()));
        if src.is_dir() {
            copy_tree(&src, &dst)?;
        } else {
            std::fs::copy(&src, &dst).map_err(|e| format!("cannot copy {}: {e}", src.display()))?;
        }
    }
    Ok(())
}

/// The options both renderers get: POV-Ray's canonical ones from DESIGN.md (every option
/// explicit, because Debian's povray.ini would otherwise open a display at 800×600).
fn canonical_args(o: &Options, scene: &Path, out: &Path) -> Vec<String> {
    let dir = scene.parent().unwrap_or(Path::new("."));
    vec![
        "-D".into(),
        "-V".into(),
        "+FN8".into(),
        "-A".into(),
        format!("+W{}", o.width),
        format!("+H{}", o.height),
        "+WT1".into(),
        format!("+L{}", dir.display()),
        format!("+L{SYSTEM_INCLUDE}"),
        format!("+I{}", scene.display()),
        format!("+O{}", out.display()),
    ]
}

/// Runs every scene, `jobs` at a time, and returns the results in scene order.
pub fn run(o: &Options) -> Result<Vec<SceneResult>, String> {
    let names = match &o.only {
        Some(list) => list.clone(),
        None => find_scenes(&o.root)?,
    };
    let cache = Cache::new(o.cache.clone())?;
    let scratch = std::env::temp_dir().join(format!("lancer-conformance-{}", std::process::id()));
    std::fs::create_dir_all(&scratch)
        .map_err(|e| format!("cannot create {}: {e}", scratch.display()))?;
    // Some scenes write files (#fopen ... write) that others then read: both renderers work
    // in a fresh copy, so the run neither changes the installed scenes nor depends on what an
    // earlier run left there.
    let copy = scratch.join("scenes");
    copy_tree(&o.root, &copy)?;
    let o = &Options {
        root: copy,
        only: o.only.clone(),
        cache: o.cache.clone(),
        povray: o.povray.clone(),
        lancer: o.lancer.clone(),
        pictures: o.pictures.clone(),
        ..*o
    };
    let next = AtomicUsize::new(0);
    let results: Mutex<Vec<Option<SceneResult>>> =
        Mutex::new((0..names.len()).map(|_| None).collect());
    let failure: Mutex<Option<String>> = Mutex::new(None);
    std::thread::scope(|s| {
        for _ in 0..o.jobs.max(1) {
            s.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::SeqCst);
                if i >= names.len() {
                    break;
                }
                match run_one(o, &cache, &scratch, &names[i], i) {
                    Ok(r) => {
                        if o.verbose {
                            eprintln!("[{}/{}] {}", i + 1, names.len(), report::progress_line(&r));
                        }
                        results.lock().unwrap()[i] = Some(r);
                    }
                    Err(e) => {
                        *failure.lock().unwrap() = Some(e);
                        next.store(names.len(), Ordering::SeqCst);
                    }
                }
            });
        }
    });
    let _ = std::fs::remove_dir_all(&scratch);
    if let Some(e) = failure.into_inner().unwrap() {
        return Err(e);
    }
    Ok(results
        .into_inner()
        .unwrap()
        .into_iter()
        .flatten()
        .collect())
}

fn run_one(
    o: &Options,
    cache: &Cache,
    scratch: &Path,
    name: &str,
    index: usize,
) -> Result<SceneResult, String> {
    let scene = o.root.join(name);
    let dir = scene.parent().unwrap_or(Path::new(".")).to_path_buf();
    let content =
        std::fs::read(&scene).map_err(|e| format!("cannot read {}: {e}", scene.display()))?;
    // The options POV-Ray gets, less the paths (which change with every run's scratch copy),
    // so that changing `canonical_args` can never reuse a stale picture.
    let options: String = canonical_args(o, &scene, Path::new(""))
        .into_iter()
        .filter(|a| !a.starts_with("+L") && !a.starts_with("+I") && !a.starts_with("+O"))
        .collect::<Vec<_>>()
        .join(" ");
    let key = cache::fnv64(&[&content, options.as_bytes(), b"povray-3.7", name.as_bytes()]);
    let pov = match cache.get(key) {
        Some(r) => r,
        None => {
            let r = run_povray(o, &scene, &dir, &cache.picture(key))?;
            cache.put(key, &r)?;
            r
        }
    };
    let out = scratch.join(format!("{index}.png"));
    let mut args = vec!["-q".to_string()];
    args.extend(canonical_args(o, &scene, &out));
    let run = process::run(&o.lancer, &args, &dir, o.lancer_limit)?;
    let missing = report::missing_keywords(&run.stderr);
    let mut ssim = None;
    let class = if pov.status != PovStatus::Ok {
        Class::PovFailed(if pov.status == PovStatus::TimedOut {
            format!("timed out after {} s", o.pov_limit.as_secs())
        } else {
            pov.message.clone()
        })
    } else if run.timed_out {
        Class::Timeout
    } else if run.code == Some(101) || run.code.is_none() {
        Class::Panic(report::panic_message(&run.stderr, run.code))
    } else if run.code != Some(0) {
        Class::Error(report::first_error(&run.stderr))
    } else {
        // Only the score is reported here: no map, tile or PSNR to compute.
        let score = crate::ssim::Picture::load(&out).and_then(|mine| {
            let theirs = crate::ssim::Picture::load(&cache.picture(key))?;
            crate::ssim::ssim(&mine, &theirs)
        });
        match score {
            Ok(s) => {
                ssim = Some(s);
                if s >= GOOD {
                    Class::Good
                } else if s >= CLOSE {
                    Class::Close
                } else {
                    Class::Low
                }
            }
            Err(e) => Class::Error(format!("cannot compare the pictures: {e}")),
        }
    };
    if let (Some(dir), true) = (&o.pictures, ssim.is_some()) {
        keep_pictures(dir, name, &cache.picture(key), &out)?;
    }
    let _ = std::fs::remove_file(&out);
    Ok(SceneResult {
        name: name.to_string(),
        class,
        ssim,
        lancer_seconds: run.seconds,
        pov,
        missing,
    })
}

/// Copies both pictures into `dir` and draws the heat map of their differences.
fn keep_pictures(dir: &Path, name: &str, povray: &Path, lancer: &Path) -> Result<(), String> {
    let [p, l, d] = picture_names(name).map(|n| dir.join(n));
    let copy = |from: &Path, to: &Path| {
        std::fs::copy(from, to)
            .map(|_| ())
            .map_err(|e| format!("cannot copy {} to {}: {e}", from.display(), to.display()))
    };
    copy(povray, &p)?;
    copy(lancer, &l)?;
    let (c, base) = crate::compare::compare_files(povray, lancer).map_err(|e| e.0)?;
    c.write_heat_map(&base, &d)
}

fn run_povray(o: &Options, scene: &Path, dir: &Path, out: &Path) -> Result<PovResult, String> {
    let run = process::run(&o.povray, &canonical_args(o, scene, out), dir, o.pov_limit)?;
    let work_seconds = report::pov_work_seconds(&run.stderr);
    let (status, message) = if run.timed_out {
        let _ = std::fs::remove_file(out);
        (PovStatus::TimedOut, String::new())
    } else if run.code == Some(0) && out.exists() {
        (PovStatus::Ok, String::new())
    } else {
        (PovStatus::Failed, report::pov_error(&run.stderr))
    };
    Ok(PovResult {
        status,
        seconds: run.seconds,
        work_seconds,
        message,
    })
}

/// A subset file: one scene name per line (relative to the scenes directory), `#` comments,
/// and a `min_good N` line giving the ratchet — the number of them that must stay at
/// SSIM ≥ 0.95.
pub struct Subset {
    pub scenes: Vec<String>,
    pub min_good: Option<usize>,
}

pub fn read_subset(path: &Path) -> Result<Subset, String> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read the subset file {}: {e}", path.display()))?;
    let mut scenes = Vec::new();
    let mut min_good = None;
    for (n, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        if let Some(v) = line.strip_prefix("min_good") {
            min_good = Some(v.trim().parse().map_err(|_| {
                format!(
                    "{}:{}: min_good needs a whole number",
                    path.display(),
                    n + 1
                )
            })?);
        } else {
            scenes.push(line.to_string());
        }
    }
    Ok(Subset { scenes, min_good })
}
