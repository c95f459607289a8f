//! The preview's render thread: parses and builds the scene when its file, frame or size
//! changes, and renders each view the window asks for coarse to fine with the batch renderer
//! (`render::progressive`), dropping a view as soon as a newer one is asked for. It knows
//! nothing of the window: it reads `Wanted`, writes `Shown` and calls `repaint`.

use std::path::PathBuf;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Condvar, Mutex};
use std::time::Instant;

use super::pose::{look_reach, Pose};
use crate::cli::Job;
use crate::render::camera::Camera;
use crate::render::photons::PhotonMap;
use crate::render::progressive::{self, Switches};
use crate::render::{Film, RenderSettings};
use crate::scene::build::Scene;

/// What the window wants rendered.
#[derive(Clone, Debug)]
pub struct Wanted {
    pub scene: PathBuf,
    /// Index into the job's frames (the clock slider).
    pub frame: usize,
    /// Bumped when a watched file changed, to parse again.
    pub reload: u64,
    pub settings: RenderSettings,
    pub switches: Switches,
    /// None: the scene's own `max_trace_level`.
    pub max_trace_level: Option<u32>,
    pub threads: usize,
    /// None: the scene's camera.
    pub pose: Option<Pose>,
    /// Start every view at full resolution (no coarse levels).
    pub full_only: bool,
    pub quit: bool,
}

/// What the worker last produced.
#[derive(Default)]
pub struct Shown {
    /// 8-bit RGB, `width`×`height`.
    pub rgb8: Vec<u8>,
    pub width: u32,
    pub height: u32,
    /// Block size of the level shown (1: every pixel traced).
    pub block: usize,
    /// The finished picture, anti-aliased, when the view is refined to the end.
    pub film: Option<Arc<Film>>,
    /// The request generation the picture belongs to.
    pub generation: u64,
    /// Counts every picture published, for the fps counter.
    pub pictures: u64,
    /// Seconds from the view's request to this picture, and rays traced for it so far.
    pub seconds: f64,
    pub rays: u64,
    /// The last parse or build error (file:line: message); the last good picture stays.
    pub error: Option<String>,
    pub warnings: Vec<String>,
    /// After each successful load: the scene camera's pose and the files read, and a counter
    /// the window watches for a new load.
    pub scene_pose: Option<Pose>,
    pub files: Vec<PathBuf>,
    pub loads: u64,
    pub scene_max_trace_level: u32,
    /// Whether the loaded scene has radiosity or photons (for the toolbox).
    pub has_radiosity: bool,
    pub has_photons: bool,
}

/// The channel between window and worker.
pub struct Shared {
    pub wanted: Mutex<Wanted>,
    pub generation: AtomicU64,
    pub wake: Condvar,
    pub shown: Mutex<Shown>,
}

impl Shared {
    pub fn new(wanted: Wanted) -> Arc<Shared> {
        Arc::new(Shared {
            wanted: Mutex::new(wanted),
            generation: AtomicU64::new(1),
            wake: Condvar::new(),
            shown: Mutex::new(Shown::default()),
        })
    }

    /// Changes what is wanted and wakes the worker (the view being rendered is dropped).
    pub fn ask(&self, f: impl FnOnce(&mut Wanted)) {
        let mut w = self.wanted.lock().unwrap_or_else(|e| e.into_inner());
        f(&mut w);
        self.generation.fetch_add(1, Ordering::SeqCst);
        self.wake.notify_all();
    }
}

/// The loaded scene and what it was loaded from.
struct Loaded {
    key: (PathBuf, usize, u64, u32, u32),
    scene: Scene,
    camera: Camera,
    max_trace_level: u32,
    photons: Option<PhotonMap>,
    /// Distance from the scene's camera to its look_at point.
    reach: Option<f64>,
}

/// Time a first level may take while the camera moves: about a 30 fps frame.
const FIRST_LEVEL_SECONDS: f64 = 0.03;

pub fn run(job: Arc<Job>, shared: Arc<Shared>, repaint: Arc<dyn Fn() + Send + Sync>) {
    let frames = job.animation.frames(&job.output).unwrap_or_default();
    let mut loaded: Option<Loaded> = None;
    let mut tried: Option<(PathBuf, usize, u64, u32, u32)> = None;
    let mut seen = 0;
    let mut pool: Option<(usize, rayon::ThreadPool)> = None;
    // Seconds per traced pixel, measured on the last level: picks the first level's block.
    let mut per_pixel: Option<f64> = None;
    loop {
        let wanted = {
            let mut w = shared.wanted.lock().unwrap_or_else(|e| e.into_inner());
            while shared.generation.load(Ordering::SeqCst) == seen && !w.quit {
                w = shared.wake.wait(w).unwrap_or_else(|e| e.into_inner());
            }
            w.clone()
        };
        if wanted.quit {
            return;
        }
        let generation = shared.generation.load(Ordering::SeqCst);
        seen = generation;
        let asked = Instant::now();
        let s = &wanted.settings;
        let key = (
            wanted.scene.clone(),
            wanted.frame,
            wanted.reload,
            s.width,
            s.height,
        );
        if tried.as_ref() != Some(&key) {
            tried = Some(key.clone());
            let frame = frames.get(wanted.frame).or(frames.first());
            match load(&job, &wanted, frame, key) {
                Ok((l, files, warnings)) => {
                    let mut sh = shared.shown.lock().unwrap_or_else(|e| e.into_inner());
                    sh.error = None;
                    sh.warnings = warnings;
                    sh.files = files;
                    sh.scene_pose = Some(Pose::of(&l.camera, l.reach));
                    sh.scene_max_trace_level = l.max_trace_level;
                    sh.has_radiosity = l.scene.radiosity.is_some();
                    sh.has_photons = l.scene.photons.is_some();
                    sh.loads += 1;
                    loaded = Some(l);
                }
                Err((e, files)) => {
                    let mut sh = shared.shown.lock().unwrap_or_else(|e| e.into_inner());
                    sh.error = Some(e);
                    if !files.is_empty() {
                        sh.files = files;
                    }
                    sh.loads += 1;
                }
            }
            repaint();
            // A new load re-asks with the scene's camera when the window wants it.
            if shared.generation.load(Ordering::SeqCst) != generation {
                continue;
            }
        }
        let Some(l) = loaded.as_mut() else { continue };
        if (l.key.3, l.key.4) != (s.width, s.height) {
            // The size changed but the scene failed to load at it: show the old size.
            continue;
        }
        let camera = match &wanted.pose {
            Some(p) => p.apply(&l.camera),
            None => l.camera.clone(),
        };
        l.scene.max_trace_level = wanted.max_trace_level.unwrap_or(l.max_trace_level);
        let threads = wanted.threads.max(1);
        if pool.as_ref().is_none_or(|(n, _)| *n != threads) {
            pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .ok()
                .map(|p| (threads, p));
        }
        let cancel = || shared.generation.load(Ordering::SeqCst) != generation;
        let pixels = (s.width as f64) * (s.height as f64);
        let first = if wanted.full_only {
            1
        } else {
            first_block(pixels, per_pixel)
        };
        let scene = &l.scene;
        let photons = l.photons.as_ref();
        let publish = |rgb8: Vec<u8>, block: usize, film: Option<Film>, rays: u64| {
            let mut sh = shared.shown.lock().unwrap_or_else(|e| e.into_inner());
            sh.rgb8 = rgb8;
            sh.width = s.width;
            sh.height = s.height;
            sh.block = block;
            sh.film = film.map(Arc::new);
            sh.generation = generation;
            sh.pictures += 1;
            sh.seconds = asked.elapsed().as_secs_f64();
            sh.rays = rays;
            drop(sh);
            repaint();
        };
        let mut work = || {
            progressive::with_view(scene, &camera, s, &wanted.switches, photons, |view| {
                let mut p = view.start();
                for (i, b) in progressive::levels(first).enumerate() {
                    let t = Instant::now();
                    let before = p.camera_rays;
                    // The first level always finishes, so that a camera moving faster than
                    // views render still shows every view's first picture.
                    let never = || false;
                    let stop: &(dyn Fn() -> bool + Sync) = if i == 0 { &never } else { &cancel };
                    if !view.level(&mut p, b, stop) {
                        return;
                    }
                    let traced = (p.camera_rays - before).max(1) as f64;
                    per_pixel = Some(t.elapsed().as_secs_f64() / traced);
                    if b == 1 {
                        let film = view.finish(p);
                        let rgb8 = crate::output::to_rgb8(&film);
                        let rays = film.rays;
                        publish(rgb8, 1, Some(film), rays);
                        return;
                    }
                    publish(view.preview_rgb8(&p), b, None, p.rays);
                    if cancel() {
                        return;
                    }
                }
            })
        };
        match &pool {
            Some((_, pool)) => pool.install(work),
            None => work(),
        }
    }
}

/// The coarsest block size needed for a first level within `FIRST_LEVEL_SECONDS`, given the
/// measured seconds per traced pixel (16 before anything is measured).
fn first_block(pixels: f64, per_pixel: Option<f64>) -> usize {
    let Some(t) = per_pixel else { return 16 };
    let mut b = 1usize;
    while b < 64 && pixels / (b * b) as f64 * t > FIRST_LEVEL_SECONDS {
        b *= 2;
    }
    b
}

/// Parses and builds the scene for `frame`; errors as `file:line:col: message`, with the
/// files read so far (still watched, so fixing an include file re-parses).
#[allow(clippy::type_complexity)]
fn load(
    job: &Job,
    wanted: &Wanted,
    frame: Option<&crate::anim::Frame>,
    key: (PathBuf, usize, u64, u32, u32),
) -> Result<(Loaded, Vec<PathBuf>, Vec<String>), (String, Vec<PathBuf>)> {
    let s = &wanted.settings;
    let mut opts = match frame {
        Some(f) => job.parse_options(f),
        None => crate::sdl::ParseOptions {
            library_paths: job.library_paths.clone(),
            ..Default::default()
        },
    };
    opts.image_width = s.width;
    opts.image_height = s.height;
    let parsed = crate::api::parse_file(&wanted.scene, opts);
    let sources = &parsed.parser.sources;
    let files: Vec<PathBuf> = (0..sources.count())
        .map(|i| PathBuf::from(sources.name(i as u32)))
        .filter(|p| p.is_file())
        .collect();
    if let Some(e) = &parsed.error {
        return Err((e.one_line(sources), files));
    }
    let mut warnings: Vec<String> = parsed
        .parser
        .warnings
        .iter()
        .map(|w| w.one_line(sources))
        .collect();
    let reach = look_reach(&parsed.parser.scene.camera);
    let built = crate::scene::build::build(&parsed.parser.scene, s.width, s.height);
    warnings.extend(built.warnings);
    let scene = built.scene;
    let photons = progressive::shoot_photons(&scene);
    Ok((
        Loaded {
            key,
            camera: Camera::of_scene(&scene),
            max_trace_level: scene.max_trace_level,
            scene,
            photons,
            reach,
        },
        files,
        warnings,
    ))
}
