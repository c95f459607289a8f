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
    let (cx, cz) = if px.abs() < NEAR && pz.abs() < NEAR {
        nearest_centre(px, pz, |t, c| t * (1.0 / c))
    } else {
        nearest_centre(px, pz, |t, c| t / c)
    };
    let (rx, rz) = (px - cx, pz - cz);
    let kind = rhombus(rx, rz);
    // Distances to the rhombus's two pairs of parallel edges, √3/2 apart.
    let h = SQRT3 / 2.0;
    let [(s0, c0), (s1, c1)] = edge_normals()[kind];
    let (a, b) = ((c0 * rz - s0 * rx).abs(), (c1 * rz - s1 * rx).abs());
    let edge = a.min(h - a).min(b).min(h - b);
    (kind as f64 + 1.0 - edge / (h / 2.0)) / 3.0
}

/// Offsets up to this size find their windows of candidate centres by multiplying by the
/// reciprocal (see `nearest_centre`); farther ones (and NaN) divide, as the windows were first
/// found.
const NEAR: f64 = 1e9;

/// The centre (cx, cz) of the hexagon nearest the offset (px, pz): of the nine centres in
/// columns m0 − 1..=m0 + 1 (m0 the nearest column index) and rows k0 − 1..=k0 + 1 of each
/// (k0 the nearest row of the column), the least squared distance, ties to the larger cz,
/// then to the first column. `per(t, c)` is t/c or t·(1/c), which only choose the windows:
/// the nearest centre (and any tied with it) lies within 1 of the point (the hexagons'
/// circumradius), so within 2/3 of px/1.5 in columns and within 1/√3 of its row's quotient,
/// and a window whose middle is off by one (the product rounding to the other side of a
/// half) still holds it. The distances and the choice are the same operations either way.
/// The divisions were ~4 of the pattern's ~15 dependent steps (tiling: 27 % of the render).
#[inline(always)]
fn nearest_centre(px: f64, pz: f64, per: impl Fn(f64, f64) -> f64) -> (f64, f64) {
    let m0 = per(px, 1.5).round();
    let mut best = (f64::INFINITY, 0.0, 0.0);
    for m in [m0 - 1.0, m0, m0 + 1.0] {
        let cx = m * 1.5;
        let k0 = per(pz - m * SQRT3 / 2.0, SQRT3).round();
        for k in [k0 - 1.0, k0, k0 + 1.0] {
            let cz = m * SQRT3 / 2.0 + k * SQRT3;
            let d = (px - cx).powi(2) + (pz - cz).powi(2);
            if d < best.0 || (d == best.0 && cz > best.2) {
                best = (d, cx, cz);
            }
        }
    }
    (best.1, best.2)
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

    /// The windows found by the reciprocal give the offsets from the centre (what the
    /// pattern reads) that the divisions give, bit for bit, and so the same value: on a grid
    /// through many hexagons, on the column and row half-way lines (where the windows' middles
    /// can differ), at the hexagons' edges and corners, and far out. (At a corner the two may
    /// name one centre as m = −0, k = −0 and m = −0, k = +0, a cz of −0 or +0; px and pz are
    /// never −0, being differences x − ½ and z − √3/2, so the offsets agree.)
    #[test]
    fn reciprocal_windows_give_the_divisions_centres() {
        let by_division = |px: f64, pz: f64| {
            let (cx, cz) = nearest_centre(px, pz, |t, c| t / c);
            (px - cx, pz - cz)
        };
        let by_product = |px: f64, pz: f64| {
            let (cx, cz) = nearest_centre(px, pz, |t, c| t * (1.0 / c));
            (px - cx, pz - cz)
        };
        let mut pts = vec![];
        for i in -300..300 {
            for j in -300..300 {
                pts.push((i as f64 * 0.0371 + 0.001, j as f64 * 0.0293 - 0.002));
            }
        }
        // Half-way lines of the columns (px/1.5 = m + 1/2) and rows, and the centres' own
        // coordinates, each with its neighbouring doubles.
        for m in -60..60 {
            for k in -60..60 {
                let (m, k) = (m as f64, k as f64);
                let xs = [(m + 0.5) * 1.5, m * 1.5, m * 1.5 + 1.0, m * 1.5 + 0.5];
                for x in xs {
                    let zs = [
                        (k + 0.5) * SQRT3 + x / 1.5 * SQRT3 / 2.0,
                        m * SQRT3 / 2.0 + k * SQRT3,
                        m * SQRT3 / 2.0 + (k + 0.5) * SQRT3,
                        (m + 1.0) * SQRT3 / 2.0 + (k + 0.5) * SQRT3,
                    ];
                    for z in zs {
                        for dx in -2i64..=2 {
                            for dz in -2i64..=2 {
                                pts.push((
                                    f64::from_bits(x.to_bits().wrapping_add(dx as u64)),
                                    f64::from_bits(z.to_bits().wrapping_add(dz as u64)),
                                ));
                            }
                        }
                    }
                }
            }
        }
        let mut x = 0x9E37_79B9_7F4A_7C15u64;
        for _ in 0..200_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let scale = 10f64.powi((x % 10) as i32 - 1);
            let a = ((x >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * scale;
            let b = ((x.rotate_left(29) >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * scale;
            pts.push((a, b));
        }
        pts.extend([(0.0, 0.0), (NEAR * 0.999, -NEAR * 0.999)]);
        for (px, pz) in pts {
            let (a, b) = (by_division(px, pz), by_product(px, pz));
            assert_eq!(
                (a.0.to_bits(), a.1.to_bits()),
                (b.0.to_bits(), b.1.to_bits()),
                "({px:e}, {pz:e})"
            );
            let (x, z) = (px + 0.5, pz + SQRT3 / 2.0);
            assert_eq!(
                rhombille(x, z).to_bits(),
                rhombille_by_division(x, z).to_bits(),
                "({x:e}, {z:e})"
            );
        }
    }

    /// `rhombille` as it was before the reciprocal windows, for the test above.
    fn rhombille_by_division(x: f64, z: f64) -> f64 {
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
        let h = SQRT3 / 2.0;
        let [(s0, c0), (s1, c1)] = edge_normals()[kind];
        let (a, b) = ((c0 * rz - s0 * rx).abs(), (c1 * rz - s1 * rx).abs());
        let edge = a.min(h - a).min(b).min(h - b);
        (kind as f64 + 1.0 - edge / (h / 2.0)) / 3.0
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
