//! The POV-Ray scene description language: lexer, token stream and the one parser that
//! executes directives as it reads.

pub mod algebraic;
pub mod array;
pub mod atmosphere;
mod built_objects;
pub mod builtins_math;
pub mod bulk;
pub mod byref;
pub mod camera;
pub mod deprecated;
pub mod directive;
pub mod expr;
pub mod fileio;
pub mod function_parse;
pub mod implicit;
pub mod interior;
pub mod lexer;
pub mod light;
pub mod limits;
pub mod media;
pub mod mesh2;
pub mod normal;
pub mod object;
pub mod parametric;
pub mod parser;
pub mod pattern;
mod photons;
pub mod radiosity;
pub mod source;
pub mod special_objects;
pub mod spline;
pub mod strings;
pub mod sweep;
pub mod switch;
pub mod text;
pub mod texture;
pub mod texture_block;
pub mod value;

use crate::scene::desc::{CameraDesc, GlobalSettings, SceneDesc, Texture};

pub use parser::{ParseOptions, Parser};

pub fn default_scene() -> SceneDesc {
    SceneDesc {
        camera: CameraDesc::default(),
        lights: Vec::new(),
        objects: Vec::new(),
        background: camera::DEFAULT_BACKGROUND,
        sky_sphere: None,
        global: GlobalSettings::default(),
        default_texture: Texture::default(),
        default_importance: None,
        version: None,
        fogs: Vec::new(),
        media: Vec::new(),
    }
}
