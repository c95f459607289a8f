//! What an identifier can hold, and the arithmetic of POV-Ray's float/vector/colour values.

use std::rc::Rc;
use std::sync::Arc;

use crate::color::Rgbft;
use crate::math::{DVec3, Transform};
use crate::scene::desc::{
    CameraDesc, ColorMap, Finish, Interior, Normal, ObjectDesc, Pigment, Texture,
};

use super::lexer::Token;

#[derive(Clone, Debug)]
pub enum Value {
    Float(f64),
    /// A vector of 2 to 5 components (`<a,b>` … `<a,b,c,d,e>`), unused ones zero.
    Vector([f64; 5], u8),
    Color(Rgbft),
    Str(Rc<str>),
    Object(Box<ObjectDesc>),
    Pigment(Box<Pigment>),
    Finish(Box<Finish>),
    Normal(Box<Normal>),
    /// Shared: `texture { T }` hands every object the same one (copied only when changed).
    Texture(std::sync::Arc<Texture>),
    Interior(Box<Interior>),
    Camera(Box<CameraDesc>),
    Transform(Box<Transform>),
    Macro(Rc<MacroDef>),
    /// A `function { ... }`, shared with whatever evaluates it (Arc: render threads may).
    Function(Arc<crate::func::Function>),
    ColorMap(Box<ColorMap>),
    PigmentMap(Box<Vec<(f64, Pigment)>>),
    TextureMap(Box<Vec<(f64, Texture)>>),
    NormalMap(Box<Vec<(f64, Normal)>>),
    SlopeMap(Box<crate::scene::desc::SlopeMap>),
    /// `material { texture interior }`.
    Material(Box<(Option<Texture>, Option<Interior>)>),
    /// The pigment layers of a `sky_sphere`.
    SkySphere(Box<Vec<Pigment>>),
    Fog(Box<crate::scene::desc::FogDesc>),
    Media(Box<crate::scene::media::Media>),
    /// Something lancer reads but does not render yet (`media`, `fog`, `pigment_map`, ...),
    /// named by its keyword so it can still be declared, passed and used.
    Skipped(Rc<str>),
    Array(Rc<super::array::ArrayVal>),
    Spline(Rc<super::spline::SplineDef>),
    /// An open `#fopen` handle, by its identifier.
    File(Rc<str>),
    /// A macro parameter bound by reference to the caller's variable or array element.
    Ref(Rc<super::array::ElemPath>),
}

impl Value {
    pub fn type_name(&self) -> &'static str {
        match self {
            Value::Float(_) => "float",
            Value::Vector(..) => "vector",
            Value::Color(_) => "colour",
            Value::Str(_) => "string",
            Value::Object(_) => "object",
            Value::Pigment(_) => "pigment",
            Value::Finish(_) => "finish",
            Value::Normal(_) => "normal",
            Value::Texture(_) => "texture",
            Value::Interior(_) => "interior",
            Value::Camera(_) => "camera",
            Value::Transform(_) => "transform",
            Value::Macro(_) => "macro",
            Value::Function(_) => "function",
            Value::ColorMap(_) => "color_map",
            Value::PigmentMap(_) => "pigment_map",
            Value::TextureMap(_) => "texture_map",
            Value::NormalMap(_) => "normal_map",
            Value::SlopeMap(_) => "slope_map",
            Value::Material(_) => "material",
            Value::SkySphere(_) => "sky_sphere",
            Value::Fog(_) => "fog",
            Value::Media(_) => "media",
            Value::Skipped(_) => "unsupported item",
            Value::Array(_) => "array",
            Value::Spline(_) => "spline",
            Value::File(_) => "file handle",
            Value::Ref(_) => "reference",
        }
    }

    pub fn vec3(v: DVec3) -> Value {
        Value::Vector([v.x, v.y, v.z, 0.0, 0.0], 3)
    }

    /// Components and their count, for arithmetic; None for non-numeric values.
    pub fn components(&self) -> Option<([f64; 5], u8)> {
        match self {
            Value::Float(f) => Some(([*f; 5], 1)),
            Value::Vector(c, n) => Some((*c, *n)),
            Value::Color(c) => Some((c.to_array(), 5)),
            _ => None,
        }
    }
}

/// A `#macro`: its parameters and where its body lies in the defining file's tokens.
#[derive(Debug)]
pub struct MacroDef {
    pub name: String,
    pub params: Vec<(String, bool)>,
    pub tokens: Rc<Vec<Token>>,
    pub body_start: usize,
    pub body_end: usize,
}
