//! The preview window (eframe/egui): the picture the worker renders, the keyboard and mouse
//! camera, the toolbox, the status bar with fps and rays per second, and the actions (save,
//! copy camera, open, reload on file change, clock slider). Actions also print a line on
//! standard output, which the window tests and scripts read.

use std::collections::VecDeque;
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use eframe::egui;
use egui::{Key, TextureOptions};

use super::pose::Pose;
use super::watch::Watch;
use super::worker::{Shared, Wanted};
use super::Options;
use crate::cli::Job;
use crate::render::progressive::Switches;
use crate::render::trace::Quality;

pub struct App {
    job: Arc<Job>,
    shared: Arc<Shared>,
    options: Options,
    texture: Option<egui::TextureHandle>,
    /// `pictures` counter of the last picture uploaded.
    uploaded: u64,
    /// When pictures arrived, for the fps counter.
    arrivals: VecDeque<Instant>,
    /// The picture's generation, block and seconds, as shown in the status bar.
    status: (usize, f64, u64),
    stretch: bool,
    /// A save asked for before the view was refined: done when it is.
    save_pending: Option<PathBuf>,
    open_path: String,
    loads_seen: u64,
    watch: Option<Watch>,
    changed: Arc<AtomicBool>,
    playing: bool,
    frames: usize,
    /// Each frame's number and clock, for the slider's label.
    frame_clocks: Vec<(i64, f64)>,
    /// The scene's camera changed on a load: render it instead of the pose the keys made.
    follow: bool,
    /// The pose the keys and mouse move; None until the scene is loaded.
    pose: Option<Pose>,
    scene_pose: Option<Pose>,
    copied: Option<String>,
    /// --bench: when it started and the block sizes of the pictures shown since.
    bench: Option<(Instant, Vec<usize>)>,
    screenshot_taken: bool,
    screenshot_done: Arc<AtomicBool>,
}

impl App {
    pub fn new(job: Arc<Job>, shared: Arc<Shared>, options: Options) -> App {
        let frame_clocks: Vec<(i64, f64)> = job
            .animation
            .frames(&job.output)
            .map(|f| f.iter().map(|f| (f.number, f.clock)).collect())
            .unwrap_or_default();
        let frames = frame_clocks.len().max(1);
        let open_path = job.scene.display().to_string();
        App {
            job,
            shared,
            options,
            texture: None,
            uploaded: 0,
            arrivals: VecDeque::new(),
            status: (0, 0.0, 0),
            stretch: false,
            save_pending: None,
            open_path,
            loads_seen: 0,
            watch: None,
            changed: Arc::new(AtomicBool::new(false)),
            playing: false,
            frames,
            frame_clocks,
            follow: false,
            pose: None,
            scene_pose: None,
            copied: None,
            bench: None,
            screenshot_taken: false,
            screenshot_done: Arc::new(AtomicBool::new(false)),
        }
    }

    fn wanted(&self) -> Wanted {
        self.shared
            .wanted
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .clone()
    }

    /// Takes in what the worker produced: a new picture, a new load of the scene.
    fn receive(&mut self, ctx: &egui::Context) {
        let sh = self.shared.shown.lock().unwrap_or_else(|e| e.into_inner());
        if sh.loads != self.loads_seen {
            self.loads_seen = sh.loads;
            let new_scene = self.scene_pose.is_none()
                || sh.scene_pose.is_some_and(|p| Some(p) != self.scene_pose);
            if let Some(p) = sh.scene_pose {
                if self.pose.is_none() || new_scene && self.options.follow_scene_camera {
                    // The scene's camera changed (an edit, another frame of an animation, another
                    // scene): show it, leaving the pose the keys had made.
                    self.pose = Some(p);
                    if self.scene_pose.is_some() {
                        self.follow = true;
                    }
                }
                self.scene_pose = Some(p);
            }
            if let Some(e) = &sh.error {
                println!("lancer preview: error: {e}");
            }
            let files = sh.files.clone();
            let changed = self.changed.clone();
            let repaint = ctx.clone();
            self.watch = Watch::new(&files, move || {
                changed.store(true, Ordering::SeqCst);
                repaint.request_repaint();
            });
        }
        if std::mem::take(&mut self.follow) {
            drop(sh);
            self.shared.ask(|w| w.pose = None);
            return;
        }
        if sh.pictures == self.uploaded || sh.rgb8.is_empty() {
            return;
        }
        self.uploaded = sh.pictures;
        let image = egui::ColorImage::from_rgb([sh.width as usize, sh.height as usize], &sh.rgb8);
        // Nearest: the coarse levels' blocks stay blocks, and 1:1 pixels stay sharp.
        let opts = TextureOptions::NEAREST;
        match &mut self.texture {
            Some(t) => t.set(image, opts),
            None => self.texture = Some(ctx.load_texture("render", image, opts)),
        }
        self.status = (sh.block, sh.seconds, sh.rays);
        let now = Instant::now();
        self.arrivals.push_back(now);
        if let Some((_, blocks)) = &mut self.bench {
            blocks.push(sh.block);
        }
        let film = sh.film.clone();
        drop(sh);
        let Some(film) = film else { return };
        println!(
            "lancer preview: refined {}x{} in {:.3}s, {} rays",
            film.width, film.height, self.status.1, self.status.2
        );
        if let Some(path) = self.save_pending.take() {
            self.write(&film, &path);
        }
        if self.options.screenshot.is_some() && !self.screenshot_taken {
            self.screenshot_taken = true;
            let path = self.options.screenshot.clone().unwrap_or_default();
            let done = self.screenshot_done.clone();
            ctx.request_screenshot(move |img| {
                let (w, h) = (img.size[0] as u32, img.size[1] as u32);
                let rgba: Vec<u8> = img.pixels.iter().flat_map(|c| c.to_array()).collect();
                match image::RgbaImage::from_raw(w, h, rgba).map(|i| i.save(&path)) {
                    Some(Ok(())) => println!("lancer preview: screenshot {}", path.display()),
                    _ => println!("lancer preview: could not write {}", path.display()),
                }
                done.store(true, Ordering::SeqCst);
            });
            ctx.request_repaint();
        }
        if self.playing && self.frames > 1 {
            let next = (self.wanted().frame + 1) % self.frames;
            self.shared.ask(|w| w.frame = next);
        }
    }

    fn write(&self, film: &crate::render::Film, path: &std::path::Path) {
        match crate::output::write(film, path, &self.job.output_spec) {
            Ok(()) => println!("lancer preview: saved {}", path.display()),
            Err(e) => println!("lancer preview: could not save {}: {e}", path.display()),
        }
    }

    fn save(&mut self) {
        let path = self.job.output.clone();
        let sh = self.shared.shown.lock().unwrap_or_else(|e| e.into_inner());
        let current = sh.generation == self.shared.generation.load(Ordering::SeqCst);
        match sh.film.clone().filter(|_| current) {
            Some(film) => {
                drop(sh);
                self.write(&film, &path);
            }
            None => self.save_pending = Some(path),
        }
    }

    fn copy_camera(&mut self, ctx: &egui::Context) {
        if let Some(p) = self.pose {
            let block = p.camera_block();
            print!("{block}");
            ctx.copy_text(block.clone());
            self.copied = Some(block);
        }
    }

    /// Keyboard and mouse moves of the camera; true when the pose changed.
    fn steer(&mut self, ctx: &egui::Context, drag: egui::Vec2, scroll: f32) -> bool {
        let Some(mut pose) = self.pose else {
            return false;
        };
        let before = pose;
        // Ctrl+S saves and Ctrl+Q quits: with Ctrl held the letters do not move.
        let ctrl = ctx.input(|i| i.modifiers.ctrl || i.modifiers.command || i.modifiers.alt);
        if !ctx.egui_wants_keyboard_input() && !ctrl {
            let (dt, fast, down) = ctx.input(|i| {
                (
                    i.stable_dt.min(0.1) as f64,
                    i.modifiers.shift,
                    [
                        i.key_down(Key::W),
                        i.key_down(Key::S),
                        i.key_down(Key::A),
                        i.key_down(Key::D),
                        i.key_down(Key::R) || i.key_down(Key::PageUp),
                        i.key_down(Key::F) || i.key_down(Key::PageDown),
                        i.key_down(Key::ArrowLeft),
                        i.key_down(Key::ArrowRight),
                        i.key_down(Key::ArrowUp),
                        i.key_down(Key::ArrowDown),
                    ],
                )
            });
            let k = if fast { 4.0 } else { 1.0 };
            let step = pose.reach() * 0.5 * k * dt;
            let turn = 0.8 * k * dt;
            let axis = |plus: bool, minus: bool| f64::from(plus as u8) - f64::from(minus as u8);
            let (fwd, side, lift) = (
                axis(down[0], down[1]),
                axis(down[3], down[2]),
                axis(down[4], down[5]),
            );
            let (yaw, pitch) = (axis(down[7], down[6]), axis(down[8], down[9]));
            if fwd != 0.0 || side != 0.0 || lift != 0.0 {
                pose.translate(fwd * step, side * step, lift * step);
            }
            if yaw != 0.0 || pitch != 0.0 {
                pose.rotate(yaw * turn, pitch * turn);
            }
        }
        if drag != egui::Vec2::ZERO {
            pose.orbit(f64::from(drag.x) * 0.01, f64::from(drag.y) * 0.01);
        }
        if scroll != 0.0 {
            pose.translate(pose.reach() * f64::from(scroll) * 0.002, 0.0, 0.0);
        }
        if let (Some((start, _)), Some(from)) = (&self.bench, self.scene_pose) {
            // A steady orbit of 0.5 radian a second stands in for a mouse drag: the same
            // views each run, whatever the frame rate.
            pose = from;
            pose.orbit(0.5 * start.elapsed().as_secs_f64(), 0.0);
        }
        if pose == before {
            return false;
        }
        self.pose = Some(pose);
        true
    }

    fn toolbox(&mut self, ui: &mut egui::Ui, ctx: &egui::Context) {
        let mut w = self.wanted();
        let before = format!("{w:?}");
        let sh = self.shared.shown.lock().unwrap_or_else(|e| e.into_inner());
        let (has_rad, has_photons, scene_mtl) =
            (sh.has_radiosity, sh.has_photons, sh.scene_max_trace_level);
        drop(sh);
        ui.heading("Toolbox");
        let q = &mut w.switches.quality;
        ui.checkbox(&mut q.shadows, "Shadows (1)");
        ui.checkbox(&mut q.reflection, "Reflection (2)");
        ui.checkbox(&mut q.transmission, "Refraction / transmission (3)");
        ui.checkbox(&mut q.area_lights, "Area lights (4)");
        let mut textures = !q.quick_colors;
        ui.checkbox(&mut textures, "Textures (5; off: quick_color)");
        q.quick_colors = !textures;
        ui.checkbox(&mut q.lighting, "Lighting");
        ui.add_enabled(
            has_rad,
            egui::Checkbox::new(&mut w.switches.radiosity, "Radiosity"),
        );
        ui.add_enabled(
            has_photons,
            egui::Checkbox::new(&mut w.switches.photons, "Photons"),
        );
        let mut aa = w.settings.antialias.is_some();
        ui.checkbox(&mut aa, "Anti-aliasing (6)");
        let mut threshold = w.settings.antialias.unwrap_or(0.3);
        ui.add_enabled(
            aa,
            egui::Slider::new(&mut threshold, 0.0..=1.0).text("AA threshold"),
        );
        w.settings.antialias = aa.then_some(threshold);
        let mut level = w.settings.quality;
        if ui
            .add(egui::Slider::new(&mut level, 0..=11).text("Quality (+Q)"))
            .changed()
        {
            w.settings.quality = level;
            w.switches.quality = Quality::level(level);
        }
        let mut mtl = w.max_trace_level.unwrap_or(scene_mtl);
        if ui
            .add(egui::Slider::new(&mut mtl, 1..=64).text("Max trace level"))
            .changed()
        {
            w.max_trace_level = Some(mtl);
        }
        ui.separator();
        ui.horizontal(|ui| {
            ui.label("Size");
            ui.add(egui::DragValue::new(&mut w.settings.width).range(8..=8192));
            ui.label("×");
            ui.add(egui::DragValue::new(&mut w.settings.height).range(8..=8192));
        });
        ui.horizontal(|ui| {
            if ui.button("½").clicked() {
                w.settings.width = (w.settings.width / 2).max(8);
                w.settings.height = (w.settings.height / 2).max(8);
            }
            if ui.button("2×").clicked() {
                w.settings.width = (w.settings.width * 2).min(8192);
                w.settings.height = (w.settings.height * 2).min(8192);
            }
            ui.checkbox(&mut self.stretch, "Stretch to window (7)");
        });
        ui.add(egui::Slider::new(&mut w.threads, 1..=64).text("Threads"));
        ui.checkbox(&mut w.full_only, "Full resolution only (no coarse levels)");
        if self.frames > 1 {
            ui.separator();
            let mut f = w.frame;
            let (n, clock) = self.frame_clocks.get(f).copied().unwrap_or((0, 0.0));
            ui.add(
                egui::Slider::new(&mut f, 0..=self.frames - 1)
                    .show_value(false)
                    .text(format!("frame {n}, clock {clock:.3}")),
            );
            w.frame = f;
            ui.checkbox(&mut self.playing, "Play");
        }
        ui.separator();
        ui.horizontal(|ui| {
            if ui.button("Save (Ctrl+S)").clicked() {
                self.save();
            }
            if ui.button("Copy camera (C)").clicked() {
                self.copy_camera(ctx);
            }
        });
        if ui.button("Reset camera (Home)").clicked() {
            self.pose = self.scene_pose;
            w.pose = None;
        }
        ui.horizontal(|ui| {
            ui.text_edit_singleline(&mut self.open_path);
            if ui.button("Open").clicked() {
                w.scene = PathBuf::from(self.open_path.trim());
                w.pose = None;
                self.scene_pose = None;
                self.pose = None;
            }
        });
        if let Some(c) = &self.copied {
            ui.label(egui::RichText::new(c).monospace().small());
        }
        if format!("{w:?}") != before {
            self.shared.ask(|x| *x = w);
        }
    }

    /// Keys that toggle what the toolbox toggles, and the actions.
    fn shortcuts(&mut self, ctx: &egui::Context) {
        if ctx.egui_wants_keyboard_input() {
            return;
        }
        let (keys, ctrl) = ctx.input(|i| {
            let pressed = |k| i.key_pressed(k);
            (
                [
                    pressed(Key::Num1),
                    pressed(Key::Num2),
                    pressed(Key::Num3),
                    pressed(Key::Num4),
                    pressed(Key::Num5),
                    pressed(Key::Num6),
                    pressed(Key::Num7),
                    pressed(Key::C),
                    pressed(Key::Home),
                    pressed(Key::S),
                    pressed(Key::Q),
                ],
                i.modifiers.ctrl || i.modifiers.command,
            )
        });
        let mut w = self.wanted();
        let before = format!("{w:?}");
        let q = &mut w.switches.quality;
        let flip = |b: &mut bool, on: bool| *b ^= on;
        flip(&mut q.shadows, keys[0]);
        flip(&mut q.reflection, keys[1]);
        flip(&mut q.transmission, keys[2]);
        flip(&mut q.area_lights, keys[3]);
        flip(&mut q.quick_colors, keys[4]);
        if keys[5] {
            w.settings.antialias = match w.settings.antialias {
                Some(_) => None,
                None => Some(0.3),
            };
        }
        flip(&mut self.stretch, keys[6]);
        if keys[7] && !ctrl {
            self.copy_camera(ctx);
        }
        if keys[8] {
            self.pose = self.scene_pose;
            w.pose = None;
        }
        if keys[9] && ctrl {
            self.save();
        }
        if keys[10] && ctrl {
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
        }
        if format!("{w:?}") != before {
            self.shared.ask(|x| *x = w);
        }
    }

    fn status_bar(&mut self, ui: &mut egui::Ui) {
        let now = Instant::now();
        while self
            .arrivals
            .front()
            .is_some_and(|t| now - *t > Duration::from_secs(1))
        {
            self.arrivals.pop_front();
        }
        let (block, seconds, rays) = self.status;
        let sh = self.shared.shown.lock().unwrap_or_else(|e| e.into_inner());
        let error = sh.error.clone();
        let warnings = sh.warnings.len();
        let refined = sh.film.is_some();
        drop(sh);
        ui.horizontal_wrapped(|ui| {
            ui.monospace(format!("{:>3} fps", self.arrivals.len()));
            ui.separator();
            let what = if refined {
                "refined".to_string()
            } else {
                format!("1/{block} res")
            };
            ui.monospace(format!("{:.1} ms ({what})", seconds * 1e3));
            ui.separator();
            let rate = if seconds > 0.0 {
                rays as f64 / seconds / 1e6
            } else {
                0.0
            };
            ui.monospace(format!("{rate:.2} Mrays/s"));
            if let Some(p) = self.pose {
                ui.separator();
                let l = p.location;
                ui.monospace(format!("camera <{:.2}, {:.2}, {:.2}>", l.x, l.y, l.z));
            }
            if warnings > 0 {
                ui.separator();
                ui.label(format!("{warnings} warnings"));
            }
        });
        if let Some(e) = error {
            ui.colored_label(egui::Color32::LIGHT_RED, e);
        }
    }

    fn finish_bench(&mut self, ctx: &egui::Context) {
        let Some((start, blocks)) = &self.bench else {
            return;
        };
        let Some(seconds) = self.options.bench else {
            return;
        };
        let t = start.elapsed().as_secs_f64();
        if t < seconds {
            return;
        }
        let n = blocks.len();
        let full = blocks.iter().filter(|b| **b == 1).count();
        let mean = blocks.iter().sum::<usize>() as f64 / n.max(1) as f64;
        let w = self.wanted();
        println!(
            "lancer preview bench: {}x{} {} threads: {n} pictures in {t:.2}s = {:.1} fps \
             (mean block {mean:.2}; {full} at full resolution = {:.1} fps)",
            w.settings.width,
            w.settings.height,
            w.threads,
            n as f64 / t,
            full as f64 / t,
        );
        self.bench = None;
        ctx.send_viewport_cmd(egui::ViewportCommand::Close);
    }
}

impl eframe::App for App {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        let ctx = ui.ctx().clone();
        if self.options.bench.is_some() && self.bench.is_none() && self.uploaded > 0 {
            self.bench = Some((Instant::now(), Vec::new()));
        }
        self.receive(&ctx);
        if self.changed.swap(false, Ordering::SeqCst) {
            println!("lancer preview: a scene file changed, parsing again");
            self.shared.ask(|w| w.reload += 1);
        }
        let dropped: Vec<PathBuf> = ctx.input(|i| {
            i.raw
                .dropped_files
                .iter()
                .map(|f| f.path().to_path_buf())
                .filter(|p| !p.as_os_str().is_empty())
                .collect()
        });
        if let Some(p) = dropped.into_iter().next() {
            self.open_path = p.display().to_string();
            self.scene_pose = None;
            self.pose = None;
            self.shared.ask(|w| {
                w.scene = p;
                w.pose = None;
            });
        }
        self.shortcuts(&ctx);
        egui::Panel::left("toolbox").show(ui, |ui| {
            egui::ScrollArea::vertical().show(ui, |ui| self.toolbox(ui, &ctx));
        });
        egui::Panel::bottom("status").show(ui, |ui| self.status_bar(ui));
        let mut drag = egui::Vec2::ZERO;
        let mut scroll = 0.0;
        egui::CentralPanel::default().show(ui, |ui| {
            let Some(tex) = &self.texture else {
                ui.label("rendering…");
                return;
            };
            let avail = ui.available_size();
            let size = tex.size_vec2();
            let fit = (avail.x / size.x).min(avail.y / size.y);
            let scale = if self.stretch { fit } else { fit.min(1.0) };
            let r = ui.add(
                egui::Image::from_texture(egui::load::SizedTexture::new(tex.id(), size * scale))
                    .sense(egui::Sense::drag()),
            );
            if r.dragged() {
                drag = r.drag_delta();
            }
            if r.hovered() {
                scroll = ui.input(|i| i.smooth_scroll_delta.y);
            }
        });
        if self.steer(&ctx, drag, scroll) {
            let pose = self.pose;
            self.shared.ask(|w| w.pose = pose);
        }
        self.finish_bench(&ctx);
        if self.options.screenshot_exit && self.screenshot_done.load(Ordering::SeqCst) {
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
        }
        // Keep polling the keys while one is held (the worker's pictures wake the window
        // otherwise), 60 times a second as a mouse or key repeat would; each repaint costs
        // CPU the renderer shares (the window itself is drawn in software under Xvfb).
        let held = ctx.input(|i| !i.keys_down.is_empty() || i.pointer.any_down());
        if held || self.bench.is_some() || self.options.bench.is_some() {
            ctx.request_repaint_after(Duration::from_millis(16));
        }
    }

    fn on_exit(&mut self, _gl: Option<&eframe::glow::Context>) {
        self.shared.ask(|w| w.quit = true);
    }
}

/// The switches a job starts with.
pub fn switches(job: &Job) -> Switches {
    Switches::of(&job.settings)
}
