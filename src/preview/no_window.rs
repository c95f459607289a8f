//! `+D` in a lancer built without the `preview` feature (the Python module's build): there
//! is no window to show the picture in, so the render goes on without one after a warning.

use crate::render::{Film, RenderSettings};
use crate::scene::build::Scene;

/// Never made without the window: a render is never shown.
pub enum Feed {}

impl Feed {
    pub fn render(&self, _scene: &Scene, _s: &RenderSettings) -> Film {
        match *self {}
    }
}

/// Runs `body` without a window; `+D` only warns.
pub fn run<T>(
    display: bool,
    _pause: bool,
    _size: (u32, u32),
    body: impl FnOnce(Option<Feed>) -> T,
) -> T {
    if display {
        eprintln!("warning: +D: this lancer was built without the preview window (cargo feature `preview`); rendering without showing the picture");
    }
    body(None)
}
