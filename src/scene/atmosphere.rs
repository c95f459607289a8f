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
    /// max(1, |depth|·`turbulence_bound(octaves, omega)`): the most |min(depth·T, 1)| can be,
    /// T the fog's turbulence anywhere (render::fog::stirred skips T where this times the
    /// ray's fall-off is negligible). Set by the scene build (`set_reach`) once the other
    /// fields are final; infinite, which never skips, until then.
    pub reach: f64,
}

impl FogTurbulence {
    /// Fills `reach` from the other fields (once per fog, when the scene is built, rather
    /// than on every far ray).
    pub fn set_reach(&mut self) {
        self.reach = (self.depth.abs() * turbulence_bound(self.octaves, self.omega)).max(1.0);
    }
}

/// The most one octave after the first of scalar turbulence can be in magnitude, before its
/// weight: generator 2's map of the lattice noise's bound, 2·(a + b·(1/2 + bound)) + 1/2,
/// which also covers generator 1's [0, 1] and generator 3's [−1/2, 3/2]. A number here so
/// that the scene layer can bound a fog's turbulence without the renderer's tables;
/// render::noise asserts at compile time that it is that value computed from the lattice's
/// table (noise_lattice::SCALAR_BOUND), to the bit.
pub const TURBULENCE_OCTAVE_BOUND: f64 = 48.24161077991952;

/// A bound on |turbulence(p, octaves, omega, _, generator)| (render::noise) over every point,
/// for any lambda and generator: the first octave is clipped to [0, 1], every other one is at
/// most `TURBULENCE_OCTAVE_BOUND` times its weight |ω|^i; doubled for rounding. Infinite or
/// NaN for an infinite or NaN omega.
pub fn turbulence_bound(octaves: u32, omega: f64) -> f64 {
    let omega = (omega as f32 as f64).abs();
    let (mut sum, mut weight) = (1.0, 1.0);
    for _ in 1..octaves.clamp(1, 10) {
        weight *= omega;
        sum += weight * TURBULENCE_OCTAVE_BOUND;
    }
    2.0 * sum
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
            reach: f64::INFINITY,
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
    /// `cos_band`'s (c_hi, c_lo), set once per scene by `set_band` when the scene is built;
    /// the default (−inf, inf) skips no ray.
    pub band: (f64, f64),
}

impl RainbowDesc {
    /// Cosines (c_hi, c_lo) of the angle to `direction` outside which a ray certainly misses
    /// the rainbow: render::fog asks `acos` only for dir·direction in [c_hi, c_lo].
    ///
    /// The rainbow shows where index = (angle − (angle₀ − width/2))/max(width, 1e-12) +
    /// jitter·(u − 1/2), u in [0, 1), lies in [0, 1], so only for angles in
    /// [s − w·|jitter|/2, s + w·(1 + |jitter|/2)] (s the inner edge, w the width). That
    /// range is widened by δ = 1e-6·(1 + |s| + w·(1 + |jitter|)) degrees, orders above the
    /// rounding of index's few operations (about 1e-16 of those magnitudes), and its cosines
    /// by 1e-12 more, above the error of libm's `cos`, `acos` and the degree conversions
    /// (|acos'| >= 1, so a cosine 1e-12 past an edge is an angle at least 1e-12 rad past it).
    /// Numbers that are not finite and moderate give (−inf, inf): no ray is skipped.
    pub fn cos_band(&self) -> (f64, f64) {
        self.band
    }

    /// Works out `cos_band` from angle, width and jitter (once per scene, after parsing).
    pub fn set_band(&mut self) {
        self.band = self.band_of();
    }

    fn band_of(&self) -> (f64, f64) {
        let never = (f64::NEG_INFINITY, f64::INFINITY);
        let w = self.width.max(1e-12);
        let s = self.angle - self.width * 0.5;
        let j = self.jitter.abs();
        if ![self.angle, self.width, j, s, w]
            .iter()
            .all(|v| v.abs() < 1e100)
        {
            return never;
        }
        let delta = 1e-6 * (1.0 + s.abs() + w * (1.0 + j));
        let lo = s - w * (0.5 * j) - delta;
        let hi = s + w * (1.0 + 0.5 * j) + delta;
        // Below 0 or above 180 degrees no ray's angle lies past that edge.
        let c_lo = if lo > 0.0 {
            lo.to_radians().cos() + 1e-12
        } else {
            f64::INFINITY
        };
        let c_hi = if hi < 180.0 {
            hi.to_radians().cos() - 1e-12
        } else {
            f64::NEG_INFINITY
        };
        (c_hi, c_lo)
    }
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
            band: (f64::NEG_INFINITY, f64::INFINITY),
        }
    }
}
