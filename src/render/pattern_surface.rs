//! The surface the normal-dependent patterns read (slope, aoi): a per-thread record of the
//! point, normal and ray a texture is being evaluated for, and slope's formula.

use std::cell::Cell;
use std::f64::consts::PI;

use crate::math::DVec3;
use crate::scene::pattern::{Pattern, PatternKind, Slope};

/// The surface a texture is being evaluated on, for the normal-dependent patterns (slope, aoi).
#[derive(Clone, Copy, Debug)]
pub struct Surface {
    /// World point.
    pub point: DVec3,
    /// Unit normal in world space, turned to face the ray and perturbed by the texture's
    /// normal where it has one (measured).
    pub normal: DVec3,
    /// Unit ray direction.
    pub ray: DVec3,
}

thread_local! {
    // A thread-local rather than an argument: slope and aoi are rare, and every pattern,
    // pigment and texture evaluation would otherwise carry a surface it does not use.
    static SURFACE: Cell<Option<Surface>> = const { Cell::new(None) };
}

/// Sets the surface the next pattern evaluations on this thread are for (None: no surface,
/// as in functions, where slope and aoi are 0).
pub fn set_surface(s: Option<Surface>) {
    SURFACE.with(|c| c.set(s));
}

/// The surface set by `set_surface`.
pub fn surface() -> Option<Surface> {
    SURFACE.with(|c| c.get())
}

/// Whether a pattern reads the surface normal (slope, aoi).
pub fn uses_surface(pat: &Pattern) -> bool {
    matches!(pat.kind, PatternKind::Slope(_) | PatternKind::Aoi)
}

/// 1 where a unit normal's cosine with a direction is 1, 0.5 at right angles, 0 opposite:
/// linear in the angle (measured; not in the cosine).
pub(super) fn angle_value(cos: f64) -> f64 {
    1.0 - cos.clamp(-1.0, 1.0).acos() / PI
}

/// Slope: the angle value of the surface normal against the direction (world space), scaled
/// so `lo` gives 0 and `hi` 1 (not clipped: the usual wrap follows); with `altitude` mixed
/// with the gradient `(q·â − lo)/(hi − lo)` in pattern space, the two weighted by the lengths
/// of the direction and the altitude vector. All measured with scripts/measure_slope.py.
pub(super) fn slope(sl: &Slope, q: DVec3) -> f64 {
    let Some(s) = surface() else {
        return 0.0;
    };
    // `dir`'s unit vector and the weights are the pattern's constants (`Slope::new`); only
    // `point_at`'s direction depends on the point.
    let unit = if sl.point_at {
        (sl.dir - s.point).normalize_or_zero()
    } else {
        sl.unit_dir
    };
    let span = |v: f64, lo: f64, hi: f64| {
        if hi == lo {
            0.0
        } else {
            (v - lo) / (hi - lo)
        }
    };
    let v = span(angle_value(s.normal.dot(unit)), sl.lo, sl.hi);
    match sl.altitude {
        Some((_, lo, hi)) if !sl.point_at => {
            let (wd, wa) = sl.weights;
            let g = span(q.dot(sl.unit_altitude), lo, hi);
            if wd + wa == 0.0 {
                0.0
            } else {
                (wd * v + wa * g) / (wd + wa)
            }
        }
        _ => v,
    }
}
