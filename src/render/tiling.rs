//! The `tiling` pattern: tiles in the x-z plane, each tile type's value running from
//! type/N at the tile's middle to (type+1)/N at its edge (the manual's "bevel"), N the
//! pattern's number of tile types. Measured with scripts/measure_tiling.py (docs/textures.md);
//! only the tilings measured so far are here.

use crate::math::DVec3;

use super::pattern_wrap::rem_euclid;

const SQRT3: f64 = 1.732_050_807_568_877_2;

/// The value of `tiling n` at `p` (0 for tilings not in
/// `scene::pattern::TILINGS_MEASURED`).
pub fn value(n: u32, p: DVec3) -> f64 {
    match n {
        5 => rhombille(p.x, p.z),
        _ => 0.0,
    }
}

/// Tiling 5: each hexagon of side 1 (flat top and bottom, centred at (1/2, √3/2) plus
/// m·(3/2, √3/2) plus k·(0, √3)) cut into three rhombi of side 1 meeting at its centre: type 1
/// to its −x side, type 0 below (−z, right), type 2 above (+z, right). The bevel is linear in
/// the distance to the nearest edge, 0 at the rhombus's inradius √3/4. A point on a boundary
/// between two hexagons belongs to the one with the larger z (measured along z = 0).
fn rhombille(x: f64, z: f64) -> f64 {
    let (px, pz) = (x - 0.5, z - SQRT3 / 2.0);
    let m0 = (px / 1.5).round();
    let mut best = (f64::INFINITY, 0.0, 0.0);
    for m in [m0 - 1.0, m0, m0 + 1.0] {
        let cx = m * 1.5;
        let k0 = ((pz - m * SQRT3 / 2.0) / SQRT3).round();
        for k in [k0 - 1.0, k0, k0 + 1.0] {
            let cz = m * SQRT3 / 2.0 + k * SQRT3;
            let d = (px - cx).powi(2) + (pz - cz).powi(2);
            if d < best.0 || (d == best.0 && cz > best.2) {
                best = (d, cx, cz);
            }
        }
    }
    let (rx, rz) = (px - best.1, pz - best.2);
    let angle = rem_euclid(rz.atan2(rx).to_degrees(), 360.0);
    let (kind, middle) = if (120.0..=240.0).contains(&angle) {
        (1.0, 180.0_f64)
    } else if angle >= 240.0 {
        (0.0, 300.0)
    } else {
        (2.0, 60.0)
    };
    // Distances to the rhombus's two pairs of parallel edges, √3/2 apart.
    let h = SQRT3 / 2.0;
    let across = |deg: f64| {
        let (s, c) = deg.to_radians().sin_cos();
        (c * rz - s * rx).abs()
    };
    let (a, b) = (across(middle - 60.0), across(middle + 60.0));
    let edge = a.min(h - a).min(b).min(h - b);
    (kind + 1.0 - edge / (h / 2.0)) / 3.0
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Values povray printed (scripts/measure_tiling.py 5); they are single precision there.
    #[test]
    fn rhombille_matches_povray() {
        let cases = [
            (0.1, 0.1, 0.305156678),
            (0.4, 0.4, 0.220626742),
            (0.9, 0.9, 0.973846316),
            (0.0, 0.9, 0.346410155),
            (0.5, 0.7, 0.269430131),
            (0.3, 0.0, 0.333333343),
            (0.0, 0.0, 0.666666687),
        ];
        for (x, z, v) in cases {
            let got = value(5, DVec3::new(x, 0.0, z));
            assert!((got - v).abs() < 1e-6, "({x}, {z}): {got} vs {v}");
        }
    }
}
