//! `media { }`: particles in an object's interior or in the atmosphere that absorb, emit and
//! scatter light along the rays crossing them (manual 3.4.8 "Media").
//!
//! The numbers here were measured with povray 3.7 (tests/probes/media_*.pov and
//! scripts/measure_media.sh): the scattering phase functions' scale, the number of samples
//! `samples` stands for.

use std::sync::{Arc, LazyLock};

use crate::math::{DVec3, Transform};
use crate::scene::desc::Pigment;

#[derive(Clone, Debug)]
pub struct Media {
    pub method: u32,
    pub intervals: u32,
    /// `samples min, max`.
    pub samples: (u32, u32),
    pub aa_level: u32,
    pub aa_threshold: f64,
    pub jitter: f64,
    pub absorption: DVec3,
    pub emission: DVec3,
    pub scattering: Option<Scattering>,
    /// `density { }` blocks, multiplied together; none is density 1 everywhere.
    pub density: Vec<Pigment>,
}

impl Default for Media {
    fn default() -> Self {
        // povray 3.7's defaults as measured (the manual's "samples 1, 1" is not what it
        // does: a media without `samples` renders exactly as one with `samples 10`).
        Media {
            method: 3,
            intervals: 1,
            samples: (10, 10),
            aa_level: 3,
            aa_threshold: 0.1,
            jitter: 0.0,
            absorption: DVec3::ZERO,
            emission: DVec3::ZERO,
            scattering: None,
            density: Vec::new(),
        }
    }
}

#[derive(Clone, Copy, Debug)]
pub struct Scattering {
    /// 1 isotropic, 2 Mie haze, 3 Mie murky, 4 Rayleigh, 5 Henyey-Greenstein.
    pub kind: u32,
    pub color: DVec3,
    pub eccentricity: f64,
    pub extinction: f64,
}

impl Scattering {
    /// How much of a light's colour is scattered towards the viewer, per unit of
    /// `color`·density·length; `cos` is the cosine between the light's direction of travel
    /// and the direction towards the viewer (1: the light shines straight at the viewer).
    /// Measured against povray (scripts/measure_media.sh, tests/probes/media_scattering.pov): isotropic is 1,
    /// Henyey-Greenstein is the textbook (1 − g²)/(1 + g² − 2g·cos)^1.5, the others are the
    /// textbook shapes times the factors below.
    pub fn phase(&self, cos: f64) -> f64 {
        match self.kind {
            2 => 1.1533 * (0.5 + 4.5 * ((1.0 + cos) * 0.5).powi(8)),
            3 => 0.9916 * (0.5 + 25.0 * ((1.0 + cos) * 0.5).powi(32)),
            4 => 0.79935 * (1.0 + cos * cos),
            5 => {
                let g = self.eccentricity;
                (1.0 - g * g) / (1.0 + g * g - 2.0 * g * cos).max(1e-12).powf(1.5)
            }
            _ => 1.0,
        }
    }
}

impl Media {
    /// Transforms apply to the densities given so far (manual: "Transformations apply only
    /// to the density statements which have been already specified").
    pub fn apply_transform(&mut self, t: &Transform) {
        for d in &mut self.density {
            d.apply_transform(t);
        }
    }

    /// Whether light crossing this media is dimmed (emission alone never is).
    pub fn extinguishes(&self) -> bool {
        self.absorption != DVec3::ZERO
            || self
                .scattering
                .is_some_and(|s| s.extinction != 0.0 && s.color != DVec3::ZERO)
    }

    /// The sub-intervals the `samples` setting stands for along one interval: measured on
    /// constant media, `samples` S behaves as S/2 + 1 equal steps (at least 2).
    pub fn steps(&self) -> u32 {
        self.samples.0.max(2) / 2 + 1
    }
}

/// The empty media list every interior without media shares (no allocation per object).
pub fn no_media() -> Arc<Vec<Media>> {
    static EMPTY: LazyLock<Arc<Vec<Media>>> = LazyLock::new(|| Arc::new(Vec::new()));
    EMPTY.clone()
}
