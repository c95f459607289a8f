//! What a ray that meets nothing brings back: the background colour, and the `sky_sphere`'s
//! layers over it (POV-Ray 3.7's rule, or the older one for `legacy_sky_filter` scenes).

use crate::math::DVec3;
use crate::scene::build::Scene;

use super::legacy_sky::LegacySky;
use super::sky;
use super::trace::{grey, Seen, Tracer};

/// A sky_sphere layer of colour `c` over what is `seen` below it (the 3.7 rule).
#[inline(always)]
fn over(seen: Seen, c: &crate::color::Rgbft) -> Seen {
    Seen {
        rgb: c.rgb * c.opacity() + seen.rgb * c.transmitted(),
        clear: seen.clear * (c.filter * grey(c.rgb) + c.transmit),
    }
}

/// `Tracer::background`'s sky for scenes older than 3.7 (`legacy_sky_filter`), out of the
/// common path: the same blending as the 3.7 rule, then `LegacySky`'s where a layer filters.
/// The colour below comes as numbers (a tuple went by reference) and is summed in locals:
/// built in `sky_over` as a `Seen` and passed by value, its four 8-byte stores were read back
/// as two 16-byte loads, and the result was copied out the same way (store-forwarding
/// stalls, 4 % of slopemt_36's samples on those loads).
#[inline(never)]
fn legacy_sky(s: &Scene, dir: DVec3, r: f64, g: f64, b: f64, clear: f64) -> Seen {
    let mut rgb = DVec3::new(r, g, b);
    let mut clear = clear;
    let mut d = None;
    let mut legacy = LegacySky::new(rgb);
    for layer in &s.sky {
        let c = sky::layer_colour(layer, dir, &mut d);
        legacy.add(&c);
        rgb = c.rgb * c.opacity() + rgb * c.transmitted();
        clear *= c.filter * grey(c.rgb) + c.transmit;
    }
    if let Some(filtered) = legacy.filtered_rgb() {
        rgb = filtered;
    }
    Seen { rgb, clear }
}

impl<'a> Tracer<'a> {
    /// POV-Ray 3.7 treats the background as a colour over black: its transmit darkens it
    /// (filter does nothing) unless the alpha channel is on, where a straight ray's background
    /// share goes to the alpha channel instead and reflections see the background's full colour.
    /// Inlined, and the sky apart: a ray that meets a plain background costs its caller a few
    /// products, not a call with a frame of six saved registers (and its colour stays in
    /// registers: built in memory and copied out, its z and clear were stored 8 bytes each and
    /// read back with one 16-byte load, a store-forwarding stall, 4 % of orngwood).
    #[inline(always)]
    pub fn background(&self, dir: DVec3, straight: bool) -> Seen {
        let s = self.scene;
        let bg = &s.background;
        let (rgb, clear) = match (self.alpha, straight) {
            (false, _) => (bg.rgb * (1.0 - bg.transmit), 0.0),
            (true, true) => (
                bg.rgb * bg.opacity(),
                bg.filter * grey(bg.rgb) + bg.transmit,
            ),
            (true, false) => (bg.rgb, 0.0),
        };
        if s.sky.is_empty() {
            return Seen { rgb, clear };
        }
        self.sky_over(rgb.x, rgb.y, rgb.z, clear, &dir)
    }

    /// The sky sphere over the background colour `(r, g, b)`, `clear`: passed as numbers so
    /// that they travel in registers.
    #[inline(never)]
    fn sky_over(&self, r: f64, g: f64, b: f64, clear: f64, dir: &DVec3) -> Seen {
        let s = self.scene;
        if s.legacy_sky_filter {
            return legacy_sky(s, *dir, r, g, b, clear);
        }
        let mut seen = Seen {
            rgb: DVec3::new(r, g, b),
            clear,
        };
        // Most skies are one layer: see `sky::only_layer_with` (which reads `dir` itself).
        if let [layer] = &s.sky[..] {
            return sky::only_layer_with(layer, dir, |c| over(seen, c));
        }
        let dir = *dir;
        // A plain colour needs no direction (most skies are one layer of one colour).
        let mut d = None;
        for layer in &s.sky {
            seen = over(seen, &sky::layer_colour(layer, dir, &mut d));
        }
        seen
    }
}
