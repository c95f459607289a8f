//! lancer: a fast ray tracer that reads POV-Ray 3.7 scene files and writes the pictures
//! POV-Ray would write.
//!
//! Pipeline: `sdl` (lexer → token stream → parser executing directives) produces a
//! `scene::desc::SceneDesc`; `scene::build` turns it into a runtime scene with a BVH; `render`
//! traces it into a film; `output` writes PNG/EXR.

pub mod anim;
pub mod api;
pub mod app;
pub mod cli;
pub mod color;
pub mod compare;
pub mod config;
pub mod conformance;
pub mod cpu;
pub mod diag;
pub mod func;
pub mod geom;
pub mod html_report;
pub mod ini;
pub mod math;
pub mod output;
pub mod preview;
pub mod render;
pub mod scene;
pub mod sdl;
pub mod ssim;
pub mod stats;
