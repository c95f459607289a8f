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
    let kind = rhombus(rx, rz);
    // Distances to the rhombus's two pairs of parallel edges, √3/2 apart.
    let h = SQRT3 / 2.0;
    let [(s0, c0), (s1, c1)] = edge_normals()[kind];
    let (a, b) = ((c0 * rz - s0 * rx).abs(), (c1 * rz - s1 * rx).abs());
    let edge = a.min(h - a).min(b).min(h - b);
    (kind as f64 + 1.0 - edge / (h / 2.0)) / 3.0
}

/// Which rhombus of its hexagon the offset (rx, rz) from the centre lies in: 1 for the
/// directions from 120° to 240°, 0 from 240° on, 2 below 120°, by the angle
/// `rem_euclid(atan2(rz, rx) in degrees, 360)`. Directions clearly off the 120° and 240° lines
/// (|rz| = √3·|rx| on the −x side) and off both axes are told by signs alone; the angle's
/// rounding (a few ulps of 360) cannot move them across.
fn rhombus(rx: f64, rz: f64) -> usize {
    let size = rx.abs() + rz.abs();
    let g = SQRT3 * rx.abs() - rz.abs();
    if rx != 0.0 && rz != 0.0 && size > 1e-200 && g.abs() > 1e-9 * size {
        return if rx < 0.0 && g > 0.0 {
            1
        } else if rz < 0.0 {
            0
        } else {
            2
        };
    }
    let angle = rem_euclid(rz.atan2(rx).to_degrees(), 360.0);
    if (120.0..=240.0).contains(&angle) {
        1
    } else if angle >= 240.0 {
        0
    } else {
        2
    }
}

/// (sin, cos) of the directions 60° either side of each rhombus's middle direction (300°,
/// 180° and 60° for kinds 0, 1, 2), computed once as `sin_cos` of the degrees in radians.
fn edge_normals() -> &'static [[(f64, f64); 2]; 3] {
    static TABLE: std::sync::OnceLock<[[(f64, f64); 2]; 3]> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        [300.0_f64, 180.0, 60.0].map(|middle: f64| {
            [middle - 60.0, middle + 60.0].map(|deg: f64| deg.to_radians().sin_cos())
        })
    })
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

    /// The rhombus told by signs is the one the angle gives, on and near the 120° and 240°
    /// lines, on the axes (both zeros) and elsewhere.
    #[test]
    fn rhombus_by_signs_is_the_angles() {
        let by_angle = |rx: f64, rz: f64| {
            let angle = rem_euclid(rz.atan2(rx).to_degrees(), 360.0);
            if (120.0..=240.0).contains(&angle) {
                1
            } else if angle >= 240.0 {
                0
            } else {
                2
            }
        };
        let mut pts = vec![];
        for i in 0..20_000 {
            let t = i as f64 * 0.000_314_159_7;
            let r = 0.9 * ((i % 97) as f64 + 1.0) / 97.0;
            pts.push((r * t.cos(), r * t.sin()));
        }
        for deg in [0.0_f64, 60.0, 90.0, 120.0, 180.0, 240.0, 270.0, 300.0] {
            let (s, c) = deg.to_radians().sin_cos();
            for r in [1e-300, 1e-12, 0.3, 0.8660254037844386] {
                let (x, z) = (r * c, r * s);
                for k in -40i64..=40 {
                    let e = k as f64 * 1e-17;
                    pts.push((x + e, z));
                    pts.push((x, z + e));
                    pts.push((f64::from_bits(x.to_bits().wrapping_add(k as u64)), z));
                    pts.push((x, f64::from_bits(z.to_bits().wrapping_add(k as u64))));
                }
            }
        }
        for z in [0.0, -0.0] {
            for x in [0.0, -0.0, 0.5, -0.5] {
                pts.push((x, z));
                pts.push((z, x));
            }
        }
        for (rx, rz) in pts {
            assert_eq!(rhombus(rx, rz), by_angle(rx, rz), "({rx:e}, {rz:e})");
        }
    }
}
