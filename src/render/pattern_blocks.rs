//! The block patterns, which pick one of their listed items rather than a value: checker,
//! hexagon, square, triangular, cubic and brick (`pattern::index_warped`; their value is the
//! item as a number).

use crate::math::DVec3;

use super::pattern_wrap::rem_euclid;

/// Keeps points that sit exactly on a checker boundary (a plane at y = 0 computed as -1e-17)
/// on the same side every time.
const CHECKER_EPS: f64 = 1e-9;

pub(super) fn checker(q: DVec3) -> usize {
    let s = (q.x + CHECKER_EPS).floor() + (q.y + CHECKER_EPS).floor() + (q.z + CHECKER_EPS).floor();
    parity(s)
}

/// `s.rem_euclid(2.0) as usize` for a whole number `s` without the software fmod: its parity
/// as an integer. Beyond i64's range (and for NaN and infinities, which `rem_euclid` makes NaN)
/// the answer is 0, as there: doubles that large are even.
fn parity(s: f64) -> usize {
    if s.abs() < 9.0e18 {
        (s as i64 & 1) as usize
    } else {
        0
    }
}

/// Hexagons of side 1 in the x-z plane: the nearest centre of the lattice spanned by
/// (1.5, √3/2) and (0, √3), coloured so that no two neighbours share an item (item 0 at the
/// origin, item 1 at +z).
pub(super) fn hexagon(q: DVec3) -> usize {
    let s3 = 3f64.sqrt();
    let fi = q.x / 1.5;
    let fj = (q.z - fi * s3 / 2.0) / s3;
    let (i0, j0) = (fi.floor(), fj.floor());
    let mut best = (f64::INFINITY, 0.0, 0.0);
    // The basis vectors meet at 60°, so the nearest centre is a corner of the parallelogram.
    for (di, dj) in [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)] {
        let (i, j) = (i0 + di, j0 + dj);
        let (cx, cz) = (i * 1.5, i * s3 / 2.0 + j * s3);
        let d = (q.x - cx).powi(2) + (q.z - cz).powi(2);
        if d < best.0 {
            best = (d, i, j);
        }
    }
    rem_euclid(best.2 - best.1, 3.0) as usize
}

/// Unit squares in the x-z plane: items 0 and 3 alternate along x where floor(z) is even,
/// 1 and 2 where it is odd (measured).
pub(super) fn square(q: DVec3) -> usize {
    let ix = rem_euclid(q.x.floor(), 2.0) as usize;
    let iz = rem_euclid(q.z.floor(), 2.0) as usize;
    [[0, 3], [1, 2]][iz][ix]
}

/// Triangles of side 1 in the x-z plane, one side along x. In the skewed coordinates
/// u = x − z/√3, w = 2z/√3 each unit cell holds a lower and an upper triangle; the item depends
/// on (⌊w⌋ − ⌊u⌋) mod 3 and which half (measured: six items around every vertex).
pub(super) fn triangular(q: DVec3) -> usize {
    let s3 = 3f64.sqrt();
    let u = q.x - q.z / s3;
    let w = 2.0 * q.z / s3;
    let (iu, iw) = (u.floor(), w.floor());
    let upper = (u - iu) + (w - iw) > 1.0;
    let d = rem_euclid(iw - iu, 3.0) as usize;
    [[0, 3], [2, 1], [4, 5]][d.min(2)][upper as usize]
}

/// The half-axis the point is nearest: +x, +y, +z, −x, −y, −z give items 0 to 5.
pub(super) fn cubic(q: DVec3) -> usize {
    let a = q.abs();
    let (axis, v) = if a.x >= a.y && a.x >= a.z {
        (0, q.x)
    } else if a.y >= a.z {
        (1, q.y)
    } else {
        (2, q.z)
    };
    axis + if v < 0.0 { 3 } else { 0 }
}

/// Bricks of `size` (mortar included) with the mortar on the high side of each brick; odd
/// rows (in y) are shifted half a brick in x, even rows half a brick in z. Item 0 is the
/// mortar.
pub(super) fn brick(q: DVec3, size: DVec3, mortar: f64) -> usize {
    if size.min_element() <= 0.0 {
        return 1;
    }
    let row = (q.y / size.y).floor();
    // `rem_euclid(row, 2.0) != 0.0` for the whole number `row` without a remainder: its
    // integer parity, finite rows past 2^53 even (remainder 0), and NaN or infinite rows odd
    // (their remainder is NaN, which is not 0).
    let odd = if row.abs() < 9.0e18 {
        row as i64 & 1 != 0
    } else {
        !row.is_finite()
    };
    let x = if odd { q.x + size.x / 2.0 } else { q.x };
    let z = if odd { q.z } else { q.z + size.z / 2.0 };
    let xm = rem_euclid(x, size.x);
    let ym = rem_euclid(q.y, size.y);
    let zm = rem_euclid(z, size.z);
    let in_mortar = xm >= size.x - mortar || ym >= size.y - mortar || zm >= size.z - mortar;
    (!in_mortar) as usize
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::pattern::index;
    use crate::scene::pattern::{Pattern, PatternKind};

    fn pat(kind: PatternKind) -> Pattern {
        Pattern::new(kind)
    }

    #[test]
    fn parity_is_rem_euclid() {
        let mut vals = vec![
            0.0,
            -0.0,
            1.0,
            -1.0,
            2.0,
            -3.0,
            9.0e15,
            9.007_199_254_740_993e15,
        ];
        vals.extend([
            1e18,
            -1e18,
            1e19,
            -1e300,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ]);
        vals.extend(
            (-3000i32..3000)
                .map(|i| (i as f64) * 1.000_37_f64.powi(i.abs() / 10))
                .map(f64::floor),
        );
        for s in vals {
            assert_eq!(parity(s), s.rem_euclid(2.0) as usize, "{s}");
        }
    }

    #[test]
    fn checker_alternates_and_is_stable_at_zero() {
        let p = pat(PatternKind::Checker);
        assert_eq!(index(&p, DVec3::new(0.5, -1e-15, 0.5)), 0);
        assert_eq!(index(&p, DVec3::new(1.5, 0.0, 0.5)), 1);
        assert_eq!(index(&p, DVec3::new(-0.5, 0.0, 0.5)), 1);
    }

    #[test]
    fn hexagon_items_around_the_origin() {
        let p = pat(PatternKind::Hexagon);
        let s3 = 3f64.sqrt();
        assert_eq!(index(&p, DVec3::ZERO), 0);
        assert_eq!(index(&p, DVec3::new(0.0, 0.0, s3)), 1);
        assert_eq!(index(&p, DVec3::new(1.5, 0.0, s3 / 2.0)), 2);
    }
}
