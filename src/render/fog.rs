//! Fog: colour added along every ray by the distance it travels, constant or thinning with
//! height above `fog_offset` (ground fog).
//!
//! Measured with povray 3.7 (tests/probes/fog_*.pov): a ray `d` long keeps
//! a = max(exp(−optical/distance), transmit) of what it saw, filtered by
//! 1 − filter + filter·fog colour, and gains (1 − a)·fog colour. Several fogs multiply what
//! is seen through them and add their colours, each unattenuated by the others (measured:
//! two constant fogs over one wall).

use crate::math::{DVec3, Ray};
use crate::scene::desc::FogDesc;

use super::trace::Seen;

/// How far a ray that hits nothing runs through fog (POV-Ray, too, stops counting at a
/// large finite distance).
const FAR: f64 = 1e7;

/// `seen` along `ray` up to distance `t` (in units of the ray's direction; infinite for the
/// background), after every fog layer.
pub fn apply(fogs: &[FogDesc], ray: &Ray, t: f64, mut seen: Seen) -> Seen {
    let len = ray.dir.length();
    let d = if t.is_finite() { t * len } else { FAR };
    let dir = ray.dir / len;
    let mut added = DVec3::ZERO;
    for f in fogs {
        let optical = if f.ground {
            ground_depth(f, ray.origin, dir, d)
        } else {
            d
        };
        let a = (-optical / f.distance).exp().max(f.color.transmit);
        let fc = f.color.rgb;
        let filter = DVec3::splat(1.0 - f.color.filter) + fc * f.color.filter;
        seen.rgb *= filter * a;
        added += fc * (1.0 - a);
        seen.clear *= a;
    }
    seen.rgb += added;
    seen
}

/// The fog a ray meets: its length times the mean density between the heights it spans.
/// Density is 1 up to `fog_offset` and 1/(1 + ((h − offset)/alt)²) above: measured with
/// povray on level rays at many heights (the manual's 1/(1 + (h − offset)/alt)² is not what
/// it draws).
fn ground_depth(f: &FogDesc, origin: DVec3, dir: DVec3, d: f64) -> f64 {
    let h0 = origin.dot(f.up);
    let h1 = h0 + dir.dot(f.up) * d;
    let alt = f.alt.max(1e-10);
    // The density integrated from -∞ (up to a constant) to height h.
    let integral = |h: f64| {
        if h <= f.offset {
            h
        } else {
            f.offset + alt * ((h - f.offset) / alt).atan()
        }
    };
    if (h1 - h0).abs() < 1e-9 {
        let density = if h0 <= f.offset {
            1.0
        } else {
            let x = (h0 - f.offset) / alt;
            1.0 / (1.0 + x * x)
        };
        return d * density;
    }
    d * (integral(h1) - integral(h0)) / (h1 - h0)
}
