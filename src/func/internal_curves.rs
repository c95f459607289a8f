//! POV-Ray's 2-d curve internal functions (`f_devils_curve_2d`, `f_witch_of_agnesi_2d`, ...
//! of `functions.inc`): a polynomial of the curve's plane times a field strength, extruded
//! along z or turned about the y axis by the three "SOR" parameters that follow the curve's
//! own (switch, offset, angle).
//!
//! Found from the `povray` binary alone (scripts/fit_internal_curves.py): with the switch
//! off (≤ 0) the curve is Q(x, y) and z is unused; with it on, r = hypot(x, z) − offset and
//! the pair (r, y) is turned by the angle in degrees before Q is applied (measured on
//! `f_witch_of_agnesi_2d`: 80 random cases with switches 0, 0.5, 1, 2 and −1). Q's terms
//! were fitted by least squares with the switch off and then checked with random SOR
//! parameters and field strengths (largest difference ~1e-14 of the value). The value is
//! kept within ±10 like the 3-d polynomial surfaces.

use super::internal_polynomials::{self as poly, Terms};

/// The curve polynomial of internal function `id` (terms in X, Y and the parameters after
/// the field strength) and how many parameters it has before the three SOR ones.
pub fn terms(id: u32) -> Option<(Terms, usize)> {
    Some(match id {
        15 => (DEVILS_CURVE_2D, 2),
        21 => (FOLIUM_SURFACE_2D, 2),
        34 => (KAMPYLE_OF_EUDOXUS_2D, 2),
        39 => (LEMNISCATE_OF_GERONO_2D, 2),
        67 => (STROPHOID_2D, 3),
        75 => (WITCH_OF_AGNESI_2D, 2),
        _ => return None,
    })
}

/// `a` holds x, y, z, the field strength, the curve's `k` parameters and the SOR switch,
/// offset and angle (missing ones read as zero).
pub fn eval(t: Terms, k: usize, a: &[f64]) -> f64 {
    let g = |i: usize| a.get(i).copied().unwrap_or(0.0);
    let (x, y, z) = (g(0), g(1), g(2));
    let (switch, offset, angle) = (g(4 + k), g(5 + k), g(6 + k));
    let (cx, cy) = if switch > 0.0 {
        let r = x.hypot(z) - offset;
        let (s, c) = angle.to_radians().sin_cos();
        (r * c - y * s, r * s + y * c)
    } else {
        (x, y)
    };
    let mut args = [0.0; 7];
    args[0] = cx;
    args[1] = cy;
    for (i, v) in args.iter_mut().enumerate().skip(3).take(1 + k) {
        *v = g(i);
    }
    poly::eval(t, &args)
}

/// `f_devils_curve_2d` (internal 15): P1 the x factor, P2 the y factor.
const DEVILS_CURVE_2D: Terms = &[
    (-1.0, [0, 2, 0, 0, 2, 0]),
    (1.0, [0, 4, 0, 0, 0, 0]),
    (1.0, [2, 0, 0, 2, 0, 0]),
    (-1.0, [4, 0, 0, 0, 0, 0]),
];
/// `f_witch_of_agnesi_2d` (internal 75): P1 the spike's size, P2 its height.
const WITCH_OF_AGNESI_2D: Terms = &[
    (1.0, [0, 0, 0, 0, 1, 0]),
    (-1.0, [0, 1, 0, 2, 0, 0]),
    (-1.0, [2, 1, 0, 0, 0, 0]),
];
/// `f_folium_surface_2d` (internal 21): P1 the neck width factor, P2 the divergence.
const FOLIUM_SURFACE_2D: Terms = &[
    (-1.0, [0, 2, 0, 0, 0, 0]),
    (-1.0, [1, 2, 0, 0, 1, 0]),
    (4.0, [1, 2, 0, 1, 0, 0]),
    (-1.0, [2, 0, 0, 0, 0, 0]),
    (-1.0, [2, 0, 0, 0, 1, 0]),
];
/// `f_kampyle_of_eudoxus_2d` (internal 34): P1 the dimple, P2 the closeness.
const KAMPYLE_OF_EUDOXUS_2D: Terms = &[
    (-1.0, [0, 2, 0, 0, 0, 0]),
    (-1.0, [2, 0, 0, 1, 3, 0]),
    (1.0, [4, 0, 0, 0, 2, 0]),
];
/// `f_lemniscate_of_gerono_2d` (internal 39): P1 the size, P2 the width.
const LEMNISCATE_OF_GERONO_2D: Terms = &[
    (-1.0, [0, 2, 0, 0, 0, 0]),
    (1.0, [2, 0, 0, 2, 2, 0]),
    (-1.0, [4, 0, 0, 0, 2, 0]),
];
/// `f_strophoid_2d` (internal 67): P1 the bulb's size, P2 the sharpness, P3 the fatness.
const STROPHOID_2D: Terms = &[
    (-1.0, [0, 2, 0, 0, 1, 0]),
    (1.0, [1, 2, 0, 0, 0, 0]),
    (1.0, [2, 0, 0, 1, 0, 2]),
    (1.0, [3, 0, 0, 0, 0, 2]),
];
