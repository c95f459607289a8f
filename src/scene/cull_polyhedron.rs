//! The bounding box of a convex polyhedron given by half-spaces (`polyhedron_box`), for the
//! culls of `scene::cull`: the box of its vertices, each the common point of three planes,
//! found by trying every three planes (cubic in their number), or for planes that are all
//! axes (members' world boxes) per axis, with the same result to the bit.

use crate::math::{Aabb, DVec3};

/// Far beyond any scene: a polyhedron reaching this far is open on that side.
const FAR: f64 = 1e9;
/// More half-spaces than this and the vertex search (cubic in their number) is not tried.
const MAX_PLANES: usize = 48;

/// The bounding box of {p : n·p <= d for every half-space}, padded; `None` when it cannot be
/// found (too many planes, nothing finite, no vertex).
pub(super) fn polyhedron_box(planes: &[(DVec3, f64)]) -> Option<Aabb> {
    polyhedron_box_by(planes, |hs, tol, b| {
        if !axis_vertices(hs, tol, b) {
            vertex_search(hs, tol, b);
        }
    })
}

/// `polyhedron_box` with `vertices` growing the box by the kept vertices of the normalised
/// half-spaces (`vertex_search`, or `axis_vertices` where it applies).
fn polyhedron_box_by(
    planes: &[(DVec3, f64)],
    vertices: impl Fn(&[(DVec3, f64)], f64, &mut Aabb),
) -> Option<Aabb> {
    if planes.is_empty() || planes.len() > MAX_PLANES {
        return None;
    }
    // Normalised, so one tolerance fits every plane; a far cube closes open polyhedra.
    let mut hs: Vec<(DVec3, f64)> = planes
        .iter()
        .map(|&(n, d)| {
            let l = n.length();
            (n / l, d / l)
        })
        .collect();
    for n in [DVec3::X, DVec3::Y, DVec3::Z] {
        hs.push((n, FAR));
        hs.push((-n, FAR));
    }
    let scale = hs[..planes.len()]
        .iter()
        .map(|h| h.1.abs())
        .fold(1.0, f64::max);
    let tol = 1e-9 * scale;
    let mut b = Aabb::EMPTY;
    vertices(&hs, tol, &mut b);
    if b.is_empty() {
        return None;
    }
    let pad = DVec3::splat(1e-6 * scale) + (b.max - b.min) * 1e-6;
    let (mut lo, mut hi) = (b.min - pad, b.max + pad);
    // A side reaching the far cube is open.
    for a in 0..3 {
        if lo[a] < -0.5 * FAR {
            lo[a] = f64::NEG_INFINITY;
        }
        if hi[a] > 0.5 * FAR {
            hi[a] = f64::INFINITY;
        }
    }
    Some(Aabb::new(lo, hi))
}

/// The vertex search of `polyhedron_box`: every three planes' common point, kept when it lies
/// inside every half-space (within `tol`), grows `b`.
fn vertex_search(hs: &[(DVec3, f64)], tol: f64, b: &mut Aabb) {
    let m = hs.len();
    for i in 0..m {
        for j in i + 1..m {
            let nij = hs[i].0.cross(hs[j].0);
            for k in j + 1..m {
                let det = nij.dot(hs[k].0);
                if det.abs() < 1e-12 {
                    continue;
                }
                // Cramer's rule for the point on all three planes.
                let v = (hs[j].0.cross(hs[k].0) * hs[i].1
                    + hs[k].0.cross(hs[i].0) * hs[j].1
                    + nij * hs[k].1)
                    / det;
                if v.is_finite() && hs.iter().all(|&(n, d)| n.dot(v) <= d + tol) {
                    *b = b.grow(v);
                }
            }
        }
    }
}

/// `vertex_search` when every normal is an axis (±x, ±y, ±z exactly): the half-spaces of
/// members' world boxes, as an intersection of bounded members gives (advanced/whiltile's
/// 289 tiles: 18 planes and the far cube's 6, 2,024 triples each). Returns false, leaving `b`
/// alone, for any other normal. The same box, bit for bit, in time linear per axis: a
/// vertex's coordinate on each axis is one of that axis's planes' `d / n[a]` (Cramer's rule
/// with axis normals: crosses, `det` = ±1 and the sums are exact, the other terms zeros),
/// triples of two planes on one axis have `det` = 0 and are skipped, and a plane's test
/// `n·v <= d + tol` reads only its own axis's coordinate (the other products are zeros, which
/// change neither the sum nor the comparison). So the kept vertices are every combination of
/// each axis's coordinates that pass that axis's tests, and their box is, per axis, the least
/// and greatest passing coordinate (zeros' signs aside: the padding's subtraction and
/// addition make the same bits of either).
fn axis_vertices(hs: &[(DVec3, f64)], tol: f64, b: &mut Aabb) -> bool {
    // Each plane's axis (`polyhedron_box` takes at most `MAX_PLANES` and the far cube's 6).
    let mut axes = [0usize; MAX_PLANES + 6];
    for (axis, &(n, _)) in axes.iter_mut().zip(hs) {
        let a = n.abs();
        *axis = match (a.x, a.y, a.z) {
            (1.0, 0.0, 0.0) => 0,
            (0.0, 1.0, 0.0) => 1,
            (0.0, 0.0, 1.0) => 2,
            _ => return false,
        };
    }
    let axes = &axes[..hs.len()];
    let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
    for (&(n, d), &a) in hs.iter().zip(axes) {
        // This plane's coordinate on its axis, where its vertices lie (non-finite:
        // `vertex_search` drops such vertices).
        let x = d / n[a];
        let kept = x.is_finite()
            && hs
                .iter()
                .zip(axes)
                .all(|(&(m, e), &c)| c != a || m[a] * x <= e + tol);
        if kept {
            lo[a] = lo[a].min(x);
            hi[a] = hi[a].max(x);
        }
    }
    // A vertex needs a kept coordinate on every axis.
    if (0..3).all(|a| lo[a] <= hi[a]) {
        *b = Aabb::new(lo, hi);
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cube_and_open_slab() {
        let mut planes = Vec::new();
        for n in [DVec3::X, DVec3::Y, DVec3::Z] {
            planes.push((n, 1.0));
            planes.push((-n, 1.0));
        }
        let b = polyhedron_box(&planes).unwrap();
        assert!((b.max - DVec3::ONE).abs().max_element() < 1e-5);
        assert!(b.contains(DVec3::ONE) && b.contains(-DVec3::ONE));
        // Only x is closed.
        let b = polyhedron_box(&planes[..2]).unwrap();
        assert!(b.max.x < 1.1 && b.min.x > -1.1);
        assert!(b.max.y == f64::INFINITY && b.min.z == f64::NEG_INFINITY);
        // Empty: x <= -1 and x >= 1.
        assert!(polyhedron_box(&[(DVec3::X, -1.0), (-DVec3::X, -1.0)]).is_none());
    }

    /// Axis planes' boxes (`axis_vertices`) are the vertex search's, bit for bit: boxes of
    /// members with coincident, nearly coincident (within the tolerance and just beyond), zero
    /// and unnormalised planes, open sides and empty sets, at scales from 1e-3 to 1e7.
    #[test]
    fn axis_planes_match_the_vertex_search() {
        let mut unit = crate::math::xorshift_unit(0x2545_f491_4f6c_dd1d);
        let bits =
            |b: Option<Aabb>| b.map(|b| [b.min, b.max].map(|v| v.to_array().map(f64::to_bits)));
        let (mut some, mut none) = (0, 0);
        for case in 0..20000 {
            let scale = [1e-3, 1.0, 3.0, 1e4, 1e7][case % 5];
            let mut planes = Vec::new();
            for _ in 0..1 + (unit() * 20.0) as usize {
                let a = (unit() * 3.0) as usize % 3;
                let sign = if unit() < 0.5 { -1.0 } else { 1.0 };
                let len = [1.0, 2.0, 0.3][(unit() * 3.0) as usize % 3];
                let mut n = DVec3::ZERO;
                n[a] = sign * len;
                let d = match (unit() * 6.0) as usize {
                    0 => 0.0,
                    1 => -0.0,
                    2 => scale * (1.0 + 1e-10 * (unit() - 0.5)),
                    3 => -scale * (0.5 + unit()) * 0.01,
                    _ => scale * (unit() - 0.3),
                } * len;
                planes.push((n, d));
            }
            let got = polyhedron_box(&planes);
            let want = polyhedron_box_by(&planes, vertex_search);
            assert_eq!(bits(got), bits(want), "case {case}: {planes:?}");
            if got.is_some() {
                some += 1;
            } else {
                none += 1;
            }
        }
        assert!(some > 1000 && none > 1000, "{some} {none}");
    }

    #[test]
    fn tetrahedron_from_rotated_planes() {
        // x, y, z >= 0 and x + y + z <= 1.
        let planes = [
            (-DVec3::X, 0.0),
            (-DVec3::Y, 0.0),
            (-DVec3::Z, 0.0),
            (DVec3::ONE, 1.0),
        ];
        let b = polyhedron_box(&planes).unwrap();
        assert!((b.max - DVec3::ONE).abs().max_element() < 1e-5);
        assert!(b.min.abs().max_element() < 1e-5);
    }
}
