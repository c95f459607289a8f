//! The camera's focal blur settings as written (`aperture`, `blur_samples`, `focal_point`,
//! `confidence`, `variance`, `bokeh`), with POV-Ray's defaults; render::focal traces with them.

use crate::math::DVec3;
use crate::scene::desc::Pigment;

#[derive(Clone, Debug)]
pub struct FocalDesc {
    pub aperture: f64,
    /// `blur_samples [min,] max`: the minimum when written.
    pub min_samples: Option<u32>,
    pub max_samples: u32,
    pub focal_point: DVec3,
    pub confidence: f64,
    pub variance: f64,
    /// `bokeh { pigment }`: the aperture's shape and weight, the pigment's brightness over
    /// the unit square <0,0,0>..<1,1,0> (None: the round lens).
    pub bokeh: Option<Box<Pigment>>,
}

impl Default for FocalDesc {
    fn default() -> Self {
        FocalDesc {
            aperture: 0.0,
            min_samples: None,
            max_samples: 0,
            focal_point: DVec3::ZERO,
            confidence: 0.9,
            variance: 1.0 / 128.0,
            bokeh: None,
        }
    }
}

impl FocalDesc {
    /// Focal blur is on only with both an aperture and samples (manual 3.4.2.3).
    pub fn active(&self) -> bool {
        self.aperture > 0.0 && self.max_samples > 0
    }

    /// The manual's default minimum: 4 below 7 samples, 7 otherwise.
    pub fn min(&self) -> u32 {
        let d = if self.max_samples < 7 { 4 } else { 7 };
        self.min_samples
            .unwrap_or(d)
            .clamp(1, self.max_samples.max(1))
    }
}
