//! `media { }`: particles in an object's interior or in the atmosphere that absorb, emit and
//! scatter light along the rays crossing them (manual 3.4.8 "Media").
//!
//! The numbers here were measured with povray 3.7 (tests/probes/media_*.pov and
//! scripts/measure_media.sh): the scattering phase functions' scale, the number of samples
//! `samples` stands for.

use std::sync::{Arc, LazyLock};

use crate::color::Rgbft;
use crate::math::{DVec3, Transform};
use crate::scene::desc::{Pigment, PigmentKind};
use crate::scene::pattern::PatternKind;

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
    /// How the densities' product may be cut short (`Media::ready`).
    pub plan: DensityPlan,
}

/// Where a density product may stop early: once one factor is zero in every channel, the
/// product is ±0 in every channel when the other factors are finite, and ±0 densities add
/// nothing anywhere they are used (render::media skips them, with finite coefficients).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DensityPlan {
    /// Every factor is provably finite and the media's coefficients are finite, so a zero
    /// factor ends the product.
    pub cut_on_zero: bool,
    /// The factor looked at first (a cheap one; the product itself keeps the written order).
    pub first: usize,
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
            plan: DensityPlan::default(),
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

    /// Plans the density product once the densities are final (scene build).
    pub fn ready(&mut self) {
        let coefficients = [self.absorption, self.emission]
            .into_iter()
            .chain(self.scattering.map(|s| s.color * s.extinction))
            .all(|v| v.is_finite());
        let cut_on_zero =
            self.density.len() > 1 && coefficients && self.density.iter().all(bounded);
        // A factor cheaper than the first is looked at first where there is one.
        let first = if cut_on_zero {
            self.density.iter().position(cheap).unwrap_or(0)
        } else {
            0
        };
        self.plan = DensityPlan { cut_on_zero, first };
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

/// Whether a density's colour is finite wherever it is evaluated: a finite solid colour, or a
/// colour map of finite entries, whose lookups are the entries or a blend a + (b − a)·t of
/// two neighbours with t in [0, 1] (entries far from overflow, so b − a stays finite).
fn bounded(p: &Pigment) -> bool {
    const LIMIT: f64 = 1e300;
    // Written so that NaN fails every test.
    let small = |x: f64| x.abs() < LIMIT;
    let colour = |c: &Rgbft| {
        small(c.rgb.x) && small(c.rgb.y) && small(c.rgb.z) && small(c.filter) && small(c.transmit)
    };
    match &p.kind {
        PigmentKind::Solid(c) => colour(c),
        // Finite entry values too: the blend's t is (v − a)/(b − a).
        PigmentKind::Mapped { map, .. } => map.iter().all(|(v, c)| small(*v) && colour(c)),
        _ => false,
    }
}

/// Whether a density's pattern costs a few arithmetic operations (no noise, no turbulence).
fn cheap(p: &Pigment) -> bool {
    match &p.kind {
        PigmentKind::Solid(_) => true,
        PigmentKind::Mapped { pattern, .. } => {
            pattern.turbulence.is_none()
                && pattern.warps.is_empty()
                && matches!(
                    pattern.kind,
                    PatternKind::Gradient(..)
                        | PatternKind::Onion
                        | PatternKind::Spherical
                        | PatternKind::Cylindrical
                        | PatternKind::Boxed
                        | PatternKind::Planar
                )
        }
        _ => false,
    }
}

/// The empty media list every interior without media shares (no allocation per object).
pub fn no_media() -> Arc<Vec<Media>> {
    static EMPTY: LazyLock<Arc<Vec<Media>>> = LazyLock::new(|| Arc::new(Vec::new()));
    EMPTY.clone()
}
