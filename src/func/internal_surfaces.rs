//! The helix, spiral, lathe-like, hexagonal and crossed-ellipsoid surfaces among POV-Ray's
//! internal functions (`f_helix1`, `f_helix2`, `f_spiral`, `f_poly4`, `f_hex_x`, `f_hex_y`,
//! `f_cross_ellipsoids`, `f_isect_ellipsoids`, `f_quantum` of `functions.inc`).
//!
//! Fitted black-box to the `povray` binary: scripts/measure_internal_functions.py prints a
//! function at chosen points, and every formula here reproduces those values to ~1e-15
//! (hundreds of random points and parameter sets; the table test in `internal.rs` keeps a
//! sample). What the manual leaves unsaid and the measures showed is written beside each.

use std::f64::consts::PI;

/// The manual's "cross section type" `c` applied to an offset (a, b) from a tube's centre
/// line: 0 a square, 1 a circle, 2 a diamond, 3 a concave diamond. Measured to be the
/// p-norm with p = 2/c (the maximum for c = 0).
fn cross_section(a: f64, b: f64, c: f64) -> f64 {
    let (a, b) = (a.abs(), b.abs());
    if c == 0.0 {
        a.max(b)
    } else {
        let p = 2.0 / c;
        (a.powf(p) + b.powf(p)).powf(1.0 / p)
    }
}

/// `f_helix1(x, y, z, helixes, period, minor, major, shape, cross section, angle)`.
///
/// In the half plane through the y axis at the point's angle θ = atan2(z, x), the n helixes
/// cross at heights where n·(−period·y − θ) ≡ π (mod 2π); the offset from the nearest
/// crossing is measured vertically (divided by `shape`), the radial one is r − major, the
/// pair is turned by −angle degrees before the cross section is applied, and the distance
/// is capped by r + major (what povray gives far from every crossing). `helixes` may be
/// fractional: povray uses it as a real number.
pub fn helix1(x: f64, y: f64, z: f64, p: [f64; 7]) -> f64 {
    let [n, period, minor, major, shape, section, angle] = p;
    let r = x.hypot(z);
    let th = if r == 0.0 { 0.0 } else { z.atan2(x) };
    let spacing = 2.0 * PI / n;
    let mut u = (-period * y - th - PI / n).rem_euclid(spacing);
    if u > spacing / 2.0 {
        u -= spacing;
    }
    let along = u / period / shape;
    let dr = r - major;
    let (s, c) = (-angle.to_radians()).sin_cos();
    let d = cross_section(dr * c - along * s, dr * s + along * c, section);
    d.min(r + major) - minor
}

/// `f_helix2(x, y, z, _, period, minor, major, _, cross section, _)`: the tube's centre at
/// height y is (major·cos(period·y), major·sin(period·y)) in the xz plane, and the cross
/// section is taken in that plane in a frame turning with the centre. The rotation angle
/// the manual lists (7th parameter) changes nothing in povray (measured: 0, 25, −40 and 90
/// degrees give the same values), nor do the two "not used" ones.
pub fn helix2(x: f64, y: f64, z: f64, p: [f64; 7]) -> f64 {
    let [_, period, minor, major, _, section, _] = p;
    let (s, c) = (period * y).sin_cos();
    let (dx, dz) = (x - major * c, z - major * s);
    cross_section(dx * c + dz * s, -dx * s + dz * c, section) - minor
}

/// `f_spiral(x, y, z, spacing, thickness, outer radius, _, _, cross section)`: a flat
/// spiral in the xz plane, r = spacing·(θ/2π + ½) with θ = atan2(−z, x), its cross section
/// taken in (radial offset to the nearest winding, y). Measured too: the centre is a ball
/// of radius `thickness` (the minimum with |p| − thickness, whatever the cross section),
/// the whole is cut by the sphere of radius `outer` (the maximum with |p| − outer), and
/// r = 0 reads as 1e-6.
pub fn spiral(x: f64, y: f64, z: f64, p: [f64; 6]) -> f64 {
    let [spacing, thickness, outer, _, _, section] = p;
    let mut r = x.hypot(z);
    if r == 0.0 {
        r = 1e-6;
    }
    let th = (-z).atan2(x);
    let mut u = (r - spacing * (th / (2.0 * PI) + 0.5)).rem_euclid(spacing);
    if u > spacing / 2.0 {
        u -= spacing;
    }
    let len = (r * r + y * y).sqrt();
    let d = (cross_section(u, y, section) - thickness).min(len - thickness);
    d.max(len - outer)
}

/// `f_poly4(x, y, z, c0, c1, c2, c3, c4)`: the surface of revolution about y whose radius at
/// height y is c0 + c1·y + c2·y² + c3·y³ + c4·y⁴; measured: the radius is kept at −5 or
/// above (c0 = −20 gives r + 5), never capped above.
pub fn poly4(x: f64, y: f64, z: f64, c: [f64; 5]) -> f64 {
    let radius = c.iter().rev().fold(0.0, |acc, &ci| acc * y + ci);
    x.hypot(z) - radius.max(-5.0)
}

/// The hexagonal lattice of `f_hex_x` and `f_hex_y`: centres √3 apart along x in rows 1.5
/// apart along y, every other row shifted by √3/2 (measured: `f_hex_x` is 0.866 = √3/2 at
/// (0, 1.5) and 0.232 at (1.5, 0)).
const HEX_ROW: f64 = 1.5;

/// `f_hex_x(x, y, z, unused)`: the hexagon norm max(|dx|, |dx/2 ± dy·√3/2|) of the offset
/// to the nearest lattice centre: hexagonal prisms along z whose flat sides face ±x, touching
/// at 0.866. Checked at random points against povray (exact to ~1e-15).
pub fn hex_x(x: f64, y: f64) -> f64 {
    let s3 = 3f64.sqrt();
    let norm = |dx: f64, dy: f64| {
        let (a, b) = (dx / 2.0, dy * s3 / 2.0);
        dx.abs().max((a + b).abs()).max((a - b).abs())
    };
    let j0 = (y / HEX_ROW).floor();
    let mut best = f64::INFINITY;
    for j in [j0 - 1.0, j0, j0 + 1.0, j0 + 2.0] {
        let shift = if j.rem_euclid(2.0) == 1.0 {
            s3 / 2.0
        } else {
            0.0
        };
        let i0 = ((x - shift) / s3).round();
        for i in [i0 - 1.0, i0, i0 + 1.0] {
            best = best.min(norm(x - (s3 * i + shift), y - HEX_ROW * j));
        }
    }
    best
}

/// `f_hex_y(x, y, z, unused)`: the distance to the nearest line of the triangular grid
/// through the same lattice's centres (lines along x and at ±60° to it, 1.5 apart): thin
/// walls between the cells, "boxes rotated 60 degrees" in the manual's words.
pub fn hex_y(x: f64, y: f64) -> f64 {
    let s3 = 3f64.sqrt();
    let off = |t: f64| (t - HEX_ROW * (t / HEX_ROW).round()).abs();
    off(y)
        .min(off(y / 2.0 + x * s3 / 2.0))
        .min(off(y / 2.0 - x * s3 / 2.0))
}

/// `f_cross_ellipsoids` (`union` true) and `f_isect_ellipsoids`: threshold − diameter ·
/// field, the field the largest (union) or smallest (intersection) of exp(−k·q) over three
/// ellipsoids, one along each axis, q = c² + e·(the other two coordinates squared) for the
/// axis coordinate c. `p` is (eccentricity e, inverse size k, diameter, threshold).
/// Measured: 150 random points and parameter sets (negative k too, where the larger q
/// wins the union) against povray, exact to ~1e-15.
pub fn crossed_ellipsoids(x: f64, y: f64, z: f64, p: [f64; 4], union: bool) -> f64 {
    let [e, k, diameter, threshold] = p;
    let (xx, yy, zz) = (x * x, y * y, z * z);
    let fields =
        [xx + e * (yy + zz), yy + e * (xx + zz), zz + e * (xx + yy)].map(|q| (-k * q).exp());
    let field = if union {
        fields[0].max(fields[1]).max(fields[2])
    } else {
        fields[0].min(fields[1]).min(fields[2])
    };
    threshold - diameter * field
}

/// `f_quantum(x, y, z, unused)`: 1.2 − 1.6·(3y² − r²)²·e^(−k·r), a d orbital's density
/// (the r⁴·(3cos²θ − 1)² lobes about the y axis). Fitted to povray's values along x (least
/// squares over r = 0.25..6: 1.6 and k = 1.33333332, not 4/3: with 4/3 the values differ in
/// the 8th digit); then 150 random points agree to 1e-12.
pub fn quantum(x: f64, y: f64, z: f64) -> f64 {
    let rr = x * x + y * y + z * z;
    let lobes = 3.0 * y * y - rr;
    1.2 - 1.6 * lobes * lobes * (-1.33333332 * rr.sqrt()).exp()
}

#[cfg(test)]
// The expected values are kept exactly as POV-Ray printed them.
#[allow(clippy::excessive_precision)]
mod tests {
    use crate::func::internal::{check_printed, Internal};

    /// Values printed by POV-Ray 3.7 (scripts/measure_internal_functions.py, its default
    /// points) for `f_helix1`, `f_helix2` and `f_spiral`; 1e-12 absolute, as printed
    /// with 15 decimals.
    #[test]
    fn matches_povray_at_sample_points() {
        #[rustfmt::skip]
        let cases: &[(Internal, &[f64], [f64; 6])] = &[
            // advanced/abyss.pov's mine cable (rFil = 1).
            (Internal::Helix1, &[3.0, 35.0, 0.35, 0.55, 2.0, 1.0, 0.0], [2.262317316715959, -0.337460979787727, -0.171982670064513, -0.199813615336382, -0.138421647290644, 0.353033544279221]),
            (Internal::Helix1, &[2.5, 1.3, 0.2, 1.0, 1.2, 0.7, 10.0], [1.928133038095337, 0.350728504933456, 0.224148786777295, 0.426830277405075, 0.421251841037569, 0.320674482431709]),
            (Internal::Helix1, &[1.0, 0.7, 0.25, 0.9, 1.5, 3.0, -35.0], [3.812277660168379, 0.348105079055630, 1.378010988928052, 1.050000000000000, 1.411577310586391, 1.381552112272132]),
            (Internal::Helix2, &[0.0, 1.4, 0.2, 0.8, 0.0, 2.6, -40.0], [4.364040337822884, 1.662327265208788, 1.699219598191358, 1.257954637525288, 0.452478187505320, 2.230413374097425]),
            (Internal::Helix2, &[0.0, 2.3, 0.3, 0.7, 0.0, 0.0, 0.0], [3.493225537835448, 0.658315571054160, 0.427681052757699, 0.400000000000000, 0.151684184976244, 1.477495939812274]),
            (Internal::Spiral, &[0.5, 0.1, 2.0, 0.0, 0.0, 1.0], [1.900034067737354, 0.200113051987741, 1.402178113427381, 0.125000000000000, 0.002108430359606, 0.395438738625047]),
            (Internal::Spiral, &[0.45, 0.12, 2.2, 0.0, 0.0, 2.7], [2.230125461656047, 0.311191566810149, 1.547333200053306, 0.042500000000000, 0.078926108183655, 0.473942512004740]),
            (Internal::Spiral, &[0.3, 0.05, 1.7, 0.0, 0.0, 0.0], [2.041657386773942, 0.250000000000000, 1.450000000000000, -0.025000000000000, 0.050000000000000, 0.400000000000000]),
            (Internal::Poly4, &[1.0, -0.5, 0.3, 0.2, -0.1], [1.962277660168380, -0.343073519286549, -0.515739011071948, -0.600000000000000, -0.191612689413609, 0.403122033614167]),
            (Internal::Poly4, &[-2.0, -1.0, 2.0, 0.5, -0.3], [-0.037722339831621, 2.647446480713450, -0.065739011071948, 2.400000000000000, 2.841107310586391, 3.264735783614167]),
        ];
        for (f, extra, want) in cases {
            check_printed(*f, extra, want);
        }
        // Special points measured apart: the axis, and the spiral's centre read as r = 1e-6.
        let sp = [0.5, 0.1, 2.0, 0.0, 0.0, 1.0];
        let at = |p: [f64; 3]| Internal::Spiral.eval(&[&p[..], &sp[..]].concat());
        assert!((at([0.0, 0.0, 0.0]) - -0.099999).abs() < 1e-15);
        assert!((at([1e-7, 0.0, 0.0]) - -0.0999999).abs() < 1e-15);
        assert!((at([-2.0, 0.0, 0.0])).abs() < 1e-15);
        let p4 =
            |p: [f64; 3]| Internal::Poly4.eval(&[&p[..], &[-20.0, 0.0, 0.0, 0.0, 0.0]].concat());
        assert!((p4([0.3, 0.5, 0.4]) - 5.5).abs() < 1e-15);
        assert!((p4([3.0, 0.0, 4.0]) - 10.0).abs() < 1e-15);
        let h = [0.0, 0.3, 0.0, 1.0, 1.0, 0.2, 1.0, 1.0, 1.0, 0.0];
        assert!((Internal::Helix1.eval(&h) - 0.8).abs() < 1e-15);
    }
}
