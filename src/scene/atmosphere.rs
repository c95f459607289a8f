//! Atmospheric effects as the scene describes them: fog layers and rainbows (a rainbow is a
//! fog whose colour depends on the ray's direction, so both share the fog's blending).

use crate::color::Rgbft;
use crate::math::DVec3;

use super::desc::ColorMap;

/// `fog { ... }`: constant (type 1) or ground fog (type 2); or a `rainbow { ... }`.
#[derive(Clone, Debug)]
pub struct FogDesc {
    pub ground: bool,
    pub distance: f64,
    pub color: Rgbft,
    pub offset: f64,
    pub alt: f64,
    /// The up direction of ground fog, transformed with the fog.
    pub up: DVec3,
    /// A rainbow takes its colour from its map by the ray's direction.
    pub rainbow: Option<Box<RainbowDesc>>,
    /// `turbulence` (present even as <0,0,0>: POV-Ray stirs the fog once the keyword is
    /// there) with its `turb_depth`, `octaves`, `omega`, `lambda` and the scene's noise
    /// generator.
    pub turbulence: Option<Box<FogTurbulence>>,
}

/// A fog's turbulence (render::fog::stirred).
#[derive(Clone, Debug)]
pub struct FogTurbulence {
    /// Whether `turbulence` was given (the other keywords alone do nothing).
    pub on: bool,
    pub amount: DVec3,
    pub depth: f64,
    pub octaves: u32,
    pub omega: f64,
    pub lambda: f64,
    pub noise_generator: u8,
}

impl Default for FogTurbulence {
    fn default() -> Self {
        FogTurbulence {
            on: false,
            amount: DVec3::ZERO,
            depth: 0.5,
            octaves: 6,
            omega: 0.5,
            lambda: 2.0,
            noise_generator: 2,
        }
    }
}

impl Default for FogDesc {
    fn default() -> Self {
        FogDesc {
            ground: false,
            distance: 0.0,
            color: Rgbft::BLACK,
            offset: 0.0,
            alt: 0.0,
            up: DVec3::Y,
            rainbow: None,
            turbulence: None,
        }
    }
}

/// `rainbow { ... }` (manual 3.4.3.5): rays at `angle` ± `width`/2 degrees from `direction`
/// see the colour map, inner edge 0 to outer edge 1, within `arc_angle` about `up`.
#[derive(Clone, Debug)]
pub struct RainbowDesc {
    pub direction: DVec3,
    pub angle: f64,
    pub width: f64,
    pub up: DVec3,
    pub arc_angle: f64,
    pub falloff_angle: f64,
    pub jitter: f64,
    pub color_map: ColorMap,
}

impl Default for RainbowDesc {
    fn default() -> Self {
        // A whole circle unless an arc is asked for (measured: the manual lists 180 as the
        // arc_angle default, but povray draws the full ring).
        RainbowDesc {
            direction: DVec3::Z,
            angle: 0.0,
            width: 0.0,
            up: DVec3::Y,
            arc_angle: 360.0,
            falloff_angle: 360.0,
            jitter: 0.0,
            color_map: ColorMap::new(),
        }
    }
}
