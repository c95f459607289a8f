//! `lancer preview scene.pov [POV-Ray options]`: an interactive window over the batch
//! renderer. The picture refines coarse to fine while nothing changes (`worker`, over
//! `render::progressive`), the keyboard and mouse move the camera (`pose`), a toolbox switches
//! effects, and the scene's files are watched for live editing (`watch`). `display` serves
//! POV-Ray's `+D`/`+P` for batch renders. The window is eframe/egui on OpenGL (glow), loaded
//! at run time: building needs no system libraries, running needs a display and libGL.

#[cfg(feature = "preview")]
pub mod app;
#[cfg(feature = "preview")]
pub mod display;
#[cfg(not(feature = "preview"))]
#[path = "no_window.rs"]
pub mod display;
pub mod pose;
#[cfg(feature = "preview")]
pub mod watch;
#[cfg(feature = "preview")]
pub mod worker;

use std::path::PathBuf;

use crate::cli::Job;

/// Options of `lancer preview` beyond the render's own.
#[derive(Clone, Debug, Default)]
pub struct Options {
    /// Write a screenshot of the whole window (PNG) once the first view is refined.
    pub screenshot: Option<PathBuf>,
    /// Close the window once that screenshot is written.
    pub screenshot_exit: bool,
    /// Orbit the camera for this many seconds, print the frame rate and close.
    pub bench: Option<f64>,
    /// Start with "full resolution only" on: no coarse levels.
    pub full_resolution: bool,
    /// A newly opened scene shows its own camera (always, except in tests that keep a pose).
    pub follow_scene_camera: bool,
}

/// Why no window can be opened here, when that is known before trying.
pub fn no_display() -> Option<String> {
    if cfg!(target_os = "linux") {
        let set = |v: &str| std::env::var_os(v).is_some_and(|x| !x.is_empty());
        if !set("DISPLAY") && !set("WAYLAND_DISPLAY") {
            return Some(
                "no display: neither DISPLAY nor WAYLAND_DISPLAY is set (run it in a desktop \
                 session, or under xvfb-run; batch renders need no display: lancer scene.pov)"
                    .into(),
            );
        }
    }
    None
}

/// Opens the preview window for `job` and returns the exit code: 0 when the window is
/// closed, 1 when it cannot be opened.
pub fn run(job: Job, options: Options) -> u8 {
    #[cfg(not(feature = "preview"))]
    {
        let _ = (job, options);
        eprintln!(
            "lancer preview: this lancer was built without the preview window (cargo feature \
             `preview`)"
        );
        1
    }
    #[cfg(feature = "preview")]
    window(job, options)
}

#[cfg(feature = "preview")]
fn window(job: Job, options: Options) -> u8 {
    use std::sync::Arc;
    if let Some(why) = no_display() {
        eprintln!("lancer preview: {why}");
        return 1;
    }
    for w in &job.warnings {
        eprintln!("warning: {w}");
    }
    let threads = job.threads.unwrap_or_else(|| {
        std::thread::available_parallelism()
            .map(|n| n.get())
            .unwrap_or(1)
    });
    let wanted = worker::Wanted {
        scene: job.scene.clone(),
        frame: 0,
        reload: 0,
        settings: job.settings.clone(),
        switches: crate::render::progressive::Switches::of(&job.settings),
        max_trace_level: None,
        threads,
        pose: None,
        full_only: options.full_resolution,
        quit: false,
    };
    let (w, h) = (job.settings.width as f32, job.settings.height as f32);
    let job = Arc::new(job);
    let shared = worker::Shared::new(wanted);
    let title = format!("lancer preview — {}", job.scene.display());
    let native = eframe::NativeOptions {
        viewport: eframe::egui::ViewportBuilder::default()
            .with_title(title)
            .with_inner_size([
                (w + 400.0).clamp(900.0, 1800.0),
                (h + 80.0).clamp(560.0, 1100.0),
            ])
            .with_drag_and_drop(true),
        ..Default::default()
    };
    let started = {
        let (job, shared) = (job.clone(), shared.clone());
        eframe::run_native(
            "lancer preview",
            native,
            Box::new(move |cc| {
                let ctx = cc.egui_ctx.clone();
                let repaint: Arc<dyn Fn() + Send + Sync> = Arc::new(move || ctx.request_repaint());
                let (j, s) = (job.clone(), shared.clone());
                std::thread::Builder::new()
                    .name("lancer-preview-render".into())
                    .spawn(move || worker::run(j, s, repaint))?;
                Ok(Box::new(app::App::new(job, shared, options)))
            }),
        )
    };
    shared.ask(|w| w.quit = true);
    match started {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("lancer preview: cannot open a window: {e}");
            1
        }
    }
}
