//! POV-Ray's `+D` for batch renders: the picture shown in a window as it is drawn (coarse to
//! fine, with the preview's progressive renderer, whose finished picture is the batch one),
//! and `+P`: the window stays open at the end until it is closed. Without a display the render
//! goes on without a window, after a warning, as POV-Ray does.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};

use eframe::egui;

use crate::render::progressive::{levels, shoot_photons, with_view, Switches};
use crate::render::{Film, RenderSettings};
use crate::scene::build::Scene;

/// The last picture drawn, for the window.
#[derive(Default)]
struct Picture {
    rgb8: Vec<u8>,
    width: u32,
    height: u32,
    count: u64,
}

/// Where a batch render shows its pictures.
#[derive(Clone)]
pub struct Feed {
    picture: Arc<Mutex<Picture>>,
    ctx: Arc<Mutex<Option<egui::Context>>>,
    done: Arc<AtomicBool>,
}

impl Feed {
    fn show(&self, rgb8: Vec<u8>, width: u32, height: u32) {
        let mut p = self.picture.lock().unwrap_or_else(|e| e.into_inner());
        *p = Picture {
            rgb8,
            width,
            height,
            count: p.count + 1,
        };
        drop(p);
        if let Some(ctx) = &*self.ctx.lock().unwrap_or_else(|e| e.into_inner()) {
            ctx.request_repaint();
        }
    }

    /// Renders as `render::render` does, showing each level as it is drawn; the film is the
    /// batch render's.
    pub fn render(&self, scene: &Scene, s: &RenderSettings) -> Film {
        let photons = shoot_photons(scene);
        let camera = crate::render::camera::Camera::of_scene(scene);
        with_view(
            scene,
            &camera,
            s,
            &Switches::of(s),
            photons.as_ref(),
            |view| {
                let mut p = view.start();
                for b in levels(16) {
                    view.level(&mut p, b, &|| false);
                    if b > 1 {
                        self.show(view.preview_rgb8(&p), s.width, s.height);
                    }
                }
                let film = view.finish(p);
                self.show(crate::output::to_rgb8(&film), s.width, s.height);
                film
            },
        )
    }
}

struct DisplayApp {
    feed: Feed,
    pause: bool,
    texture: Option<egui::TextureHandle>,
    shown: u64,
}

impl eframe::App for DisplayApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        let ctx = ui.ctx().clone();
        let p = self.feed.picture.lock().unwrap_or_else(|e| e.into_inner());
        if p.count != self.shown && !p.rgb8.is_empty() {
            self.shown = p.count;
            let image = egui::ColorImage::from_rgb([p.width as usize, p.height as usize], &p.rgb8);
            let opts = egui::TextureOptions::NEAREST;
            match &mut self.texture {
                Some(t) => t.set(image, opts),
                None => self.texture = Some(ctx.load_texture("render", image, opts)),
            }
        }
        drop(p);
        let done = self.feed.done.load(Ordering::SeqCst);
        egui::CentralPanel::no_frame().show(ui, |ui| {
            if let Some(t) = &self.texture {
                let avail = ui.available_size();
                let size = t.size_vec2();
                let scale = (avail.x / size.x).min(avail.y / size.y);
                ui.centered_and_justified(|ui| {
                    ui.image(egui::load::SizedTexture::new(t.id(), size * scale));
                });
            }
        });
        if done && !self.pause {
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
        }
        if !done {
            // The render thread wakes the window; this only catches its end.
            ctx.request_repaint_after(std::time::Duration::from_millis(100));
        }
    }
}

/// Runs `body` (the batch render) with a window showing what it draws when `display` is on
/// and a display is there; the window closes when `body` returns, unless `pause`. Returns
/// what `body` returns.
pub fn run<T: Send + 'static>(
    display: bool,
    pause: bool,
    size: (u32, u32),
    body: impl FnOnce(Option<Feed>) -> T + Send + 'static,
) -> T {
    if !display {
        return body(None);
    }
    if let Some(why) = super::no_display() {
        eprintln!("warning: +D: {why}; rendering without showing the picture");
        return body(None);
    }
    let feed = Feed {
        picture: Arc::default(),
        ctx: Arc::default(),
        done: Arc::default(),
    };
    let worker_feed = feed.clone();
    let handle = std::thread::spawn(move || {
        let out = body(Some(worker_feed.clone()));
        worker_feed.done.store(true, Ordering::SeqCst);
        if let Some(ctx) = &*worker_feed.ctx.lock().unwrap_or_else(|e| e.into_inner()) {
            ctx.request_repaint();
        }
        out
    });
    let (w, h) = (size.0 as f32, size.1 as f32);
    let native = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("lancer")
            .with_inner_size([w.clamp(160.0, 1600.0), h.clamp(120.0, 1000.0)]),
        ..Default::default()
    };
    let app_feed = feed.clone();
    let shown = eframe::run_native(
        "lancer",
        native,
        Box::new(move |cc| {
            *app_feed.ctx.lock().unwrap_or_else(|e| e.into_inner()) = Some(cc.egui_ctx.clone());
            Ok(Box::new(DisplayApp {
                feed: app_feed,
                pause,
                texture: None,
                shown: 0,
            }))
        }),
    );
    if let Err(e) = shown {
        eprintln!("warning: +D: cannot open a window ({e}); rendering without it");
    }
    // Closing the window early does not stop the render: the file is still written.
    match handle.join() {
        Ok(out) => out,
        Err(panic) => std::panic::resume_unwind(panic),
    }
}
