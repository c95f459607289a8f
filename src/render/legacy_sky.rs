//! POV-Ray's pre-3.7 composition of a sky_sphere's filtering layers over the background,
//! kept apart from the tracer: only `Tracer::background` asks it, and only for old scenes.

use crate::color::Rgbft;
use crate::math::DVec3;

/// A sky_sphere's layers over the background as POV-Ray composes them before `#version 3.7`
/// when some layer filters (measured, probe sky_sphere_filter_36): each layer's own colour
/// (rgb·(1 − f − t)) reaches the eye times Πf + Πt over the layers above it (untinted; the top
/// layer's times 1), the background times Π(f·rgb) + Πt over all layers. From 3.7 on, each
/// layer lets f·rgb + t of everything below it through. Fed bottom layer first: `filtered`
/// sums the layers below the current top weighted by the products of their filters above
/// them, `transmitted` likewise by the transmits, so each layer is evaluated once.
pub(super) struct LegacySky {
    background: DVec3,
    top: DVec3,
    filtered: DVec3,
    transmitted: DVec3,
    tint: DVec3,
    transmit: f64,
    any_filter: bool,
}

impl LegacySky {
    pub(super) fn new(background: DVec3) -> Self {
        LegacySky {
            background,
            top: DVec3::ZERO,
            filtered: DVec3::ZERO,
            transmitted: DVec3::ZERO,
            tint: DVec3::ONE,
            transmit: 1.0,
            any_filter: false,
        }
    }

    pub(super) fn add(&mut self, c: &Rgbft) {
        let own = c.rgb * c.opacity();
        self.top = own + self.filtered * c.filter + self.transmitted * c.transmit;
        self.filtered = own + self.filtered * c.filter;
        self.transmitted = own + self.transmitted * c.transmit;
        self.tint *= c.filter * c.rgb;
        self.transmit *= c.transmit;
        self.any_filter |= c.filter > 0.0;
    }

    /// The composed colour, when some layer filtered (otherwise the 3.7 rule gives the same).
    pub(super) fn filtered_rgb(&self) -> Option<DVec3> {
        self.any_filter
            .then(|| self.top + self.background * (self.tint + DVec3::splat(self.transmit)))
    }
}
