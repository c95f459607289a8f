//! The crackle pattern: distances from a point to the nearest three of one random point per
//! unit cube (POV-Ray's points, measured: see docs/noise.md).
//!
//! The 27 cubes around the point are walked in a fixed order and the three smallest sums of
//! |d|^metric kept; the cubes whose sum cannot be among those three are skipped without
//! hashing their point or taking their powers (`nearest3`), or, inside the i32 range, all
//! 27 points are hashed and only the cubes whose sums may be among the three smallest by
//! cheap bounds take their exact powers (`nearest3_bounded`): either gives the walk's own
//! answer bit for bit.

mod bounds;

use crate::math::DVec3;

use super::cells_data::{CELL_HASH_OFFSET, CELL_HASH_X, CELL_HASH_Y, CELL_HASH_Z, CELL_POINT};
use super::noise;
use super::noise_lattice::all_below_4096;

/// Crackle: `form` weighs the distances to the nearest three points, the result clipped to
/// [0, 1]; `offset` enters each distance as (Σ|d|^metric + offset^metric)^(1/metric). `solid`
/// gives each cell the noise value at its point. All measured with `function { pattern {
/// crackle ... } }`.
pub fn crackle(q: DVec3, form: DVec3, metric: f64, offset: f64, solid: bool, gen: u8) -> f64 {
    let (d, nearest) = nearest3(q, metric);
    if solid {
        return noise::noise(nearest, gen);
    }
    let off = if offset == 0.0 {
        0.0
    } else {
        offset.abs().powf(metric)
    };
    let root = |s: f64| {
        if metric == 2.0 {
            (s + off).sqrt()
        } else if metric == 1.0 {
            s + off
        } else {
            (s + off).powf(1.0 / metric)
        }
    };
    let v = form.x * root(d[0]) + form.y * root(d[1]) + form.z * root(d[2]);
    v.clamp(0.0, 1.0)
}

/// Σ|v|^metric of one offset (v's components are not negative).
#[inline(always)]
fn metric_sum(v: DVec3, metric: f64) -> f64 {
    if metric == 2.0 {
        v.length_squared()
    } else if metric == 1.0 {
        v.x + v.y + v.z
    } else {
        v.x.powf(metric) + v.y.powf(metric) + v.z.powf(metric)
    }
}

/// The point of the cube at offset (dx, dy, dz) from q's and the point's sum.
#[inline(always)]
fn cube_at(q: DVec3, base: DVec3, metric: f64, dx: i64, dy: i64, dz: i64) -> (f64, DVec3) {
    // Wrapping as release builds do (huge coordinates saturate the casts), not a debug panic.
    let (cx, cy, cz) = (
        (base.x as i64).wrapping_add(dx),
        (base.y as i64).wrapping_add(dy),
        (base.z as i64).wrapping_add(dz),
    );
    let pt = noise::cell_point(cx, cy, cz);
    (metric_sum((pt - q).abs(), metric), pt)
}

/// Cube k of the 27 (k = 9(dz + 1) + 3(dy + 1) + dx + 1).
#[inline(always)]
fn cube(q: DVec3, base: DVec3, metric: f64, k: usize) -> (f64, DVec3) {
    let (dx, dy, dz) = (
        (k % 3) as i64 - 1,
        ((k / 3) % 3) as i64 - 1,
        (k / 9) as i64 - 1,
    );
    cube_at(q, base, metric, dx, dy, dz)
}

/// Keeps the three smallest sums in `d` (sorted) and the point of the first smallest. The
/// third is asked first: d is sorted and never NaN, so a sum not below it is below neither
/// of the others, and most cubes are that far (one test instead of three).
#[inline(always)]
fn insert(d: &mut [f64; 3], nearest: &mut DVec3, sum: f64, pt: DVec3) {
    if sum < d[2] {
        if sum < d[0] {
            *d = [sum, d[0], d[1]];
            *nearest = pt;
        } else if sum < d[1] {
            *d = [d[0], sum, d[1]];
        } else {
            d[2] = sum;
        }
    }
}

/// The plain walk of all 27 cubes: the three smallest sums and the nearest point.
fn walk(q: DVec3, metric: f64) -> ([f64; 3], DVec3) {
    // Inside the i32 range (not NaN), the cubes' coordinates convert exactly either way.
    let inside = |c: f64| c.abs() < 2147483648.0;
    if inside(q.x) && inside(q.y) && inside(q.z) {
        return walk_shared(q, metric);
    }
    walk_each(q, metric)
}

/// The first stages of `walk_shared`'s hash: the nine (x, y) columns' HASH_Y values (x
/// fastest), the three z stage inputs, and the cubes' coordinates as floats per axis.
#[inline(always)]
fn shared_stages(base: DVec3) -> ([usize; 9], [usize; 3], [[f64; 3]; 3]) {
    let (bx, by, bz) = (base.x as i64, base.y as i64, base.z as i64);
    let m = |c: i64| (c.wrapping_add(CELL_HASH_OFFSET) & 4095) as usize;
    let three = |b: i64| [m(b - 1), m(b), m(b + 1)];
    let coords = |b: i64| [(b - 1) as f64, b as f64, (b + 1) as f64];
    let my = three(by);
    let hx = three(bx).map(|i| CELL_HASH_X[i] as usize);
    let mut hxy = [0usize; 9];
    for (k, h) in hxy.iter_mut().enumerate() {
        *h = CELL_HASH_Y[(hx[k % 3] ^ my[k / 3]) & 4095] as usize;
    }
    (hxy, three(bz), [coords(bx), coords(by), coords(bz)])
}

/// `walk_each` for a point whose floors are inside the i32 range, where every cube's
/// coordinate c (floor ± 1) and `c as f64` are exact: the cubes' three-stage hash shares its
/// first stages (3 x and 9 (x, y) reads instead of 27 of each, with masks where each cube
/// had bounds checks), and each cube's point and sum are `cube_at`'s operations on the same
/// values, visited in the same order.
fn walk_shared(q: DVec3, metric: f64) -> ([f64; 3], DVec3) {
    let (hxy, mz, [fx, fy, fz]) = shared_stages(q.floor());
    let mut d = [f64::INFINITY; 3];
    let mut nearest = DVec3::ZERO;
    for (dz, &mz) in mz.iter().enumerate() {
        for (k, &h) in hxy.iter().enumerate() {
            // SAFETY: h and mz are below 4096 (CELL_HASH_Y's values, asserted below, and a
            // 12-bit mask), so their xor indexes CELL_HASH_Z, whose values (asserted) index
            // CELL_POINT: a mask or a bounds check on each was an instruction or two a cube.
            let p = unsafe {
                let e = *CELL_HASH_Z.get_unchecked(h ^ mz) as usize;
                *CELL_POINT.get_unchecked(e)
            };
            let pt = DVec3::new(fx[k % 3] + p[0], fy[k / 3] + p[1], fz[dz] + p[2]);
            insert(&mut d, &mut nearest, metric_sum((pt - q).abs(), metric), pt);
        }
    }
    (d, nearest)
}

// `walk_shared`'s unchecked reads rely on this (an unnamed constant is always evaluated).
const _: () = assert!(all_below_4096(&CELL_HASH_Y) && all_below_4096(&CELL_HASH_Z));

/// The walk of all 27 cubes, each hashed whole (any point).
fn walk_each(q: DVec3, metric: f64) -> ([f64; 3], DVec3) {
    let base = q.floor();
    let mut d = [f64::INFINITY; 3];
    let mut nearest = DVec3::ZERO;
    for dz in -1..=1 {
        for dy in -1..=1 {
            for dx in -1..=1 {
                let (sum, pt) = cube_at(q, base, metric, dx, dy, dz);
                insert(&mut d, &mut nearest, sum, pt);
            }
        }
    }
    (d, nearest)
}

/// The centre cube and its six face neighbours, visited first to learn a bound.
const FACES: [usize; 7] = [13, 4, 10, 12, 14, 16, 22];

/// `walk`'s answer, skipping the cubes that cannot change it when the metric takes powers
/// (for metrics 1 and 2 a cube costs less than the unpredictable branch that would skip it:
/// crackle_form 146 -> 208 ms, crackle1 56 -> 69 with every metric skipping). The centre and
/// face cubes are
/// summed first; their third smallest sum t bounds the answer's third (three sums at most t
/// exist). A cube whose sum is surely above t is then neither among the three smallest nor
/// the nearest, so leaving it out of the walk (kept in its order) changes nothing. Its sum is
/// bounded from below without its point: the point lies in its own cube, so along each axis
/// it is at least as far as that cube's face is from q, and rounding, the powers and the sum
/// are monotonic (the powers given a margin for libm's last bit).
fn nearest3(q: DVec3, metric: f64) -> ([f64; 3], DVec3) {
    // Far from the origin the cube's corner is not exact; NaN fails the comparisons. The
    // bounds need powers that grow with the distance.
    let small = |c: f64| c.abs() < 1e15;
    let powers = metric != 2.0 && metric != 1.0 && metric > 0.0 && metric.is_finite();
    if !(powers && small(q.x) && small(q.y) && small(q.z)) {
        return walk(q, metric);
    }
    let inside = |c: f64| c.abs() < 2147483648.0;
    if bounds::metric_in_range(metric) && inside(q.x) && inside(q.y) && inside(q.z) {
        return nearest3_bounded(q, metric);
    }
    let base = q.floor();
    let mut sums = [0.0; 27];
    let mut pts = [DVec3::ZERO; 27];
    let mut d = [f64::INFINITY; 3];
    let mut nearest = DVec3::ZERO;
    for k in FACES {
        (sums[k], pts[k]) = cube(q, base, metric, k);
        insert(&mut d, &mut nearest, sums[k], pts[k]);
    }
    let t = d[2];
    // Per axis, the least |d|^metric for the cube below, the same and the one above.
    let power = |b: f64| {
        // Two libm results may be out of order by an ulp; tiny ones are given up on.
        let p = b.powf(metric);
        if p < 1e-290 {
            0.0
        } else {
            p * (1.0 - 1.0 / (1u64 << 40) as f64)
        }
    };
    let axis = |c: f64, b: f64| [power(c - b), 0.0, power((b + 1.0) - c)];
    let (bx, by, bz) = (axis(q.x, base.x), axis(q.y, base.y), axis(q.z, base.z));
    d = [f64::INFINITY; 3];
    nearest = DVec3::ZERO;
    for k in 0..27 {
        let (sum, pt) = if FACES.contains(&k) {
            (sums[k], pts[k])
        } else {
            let bound = bx[k % 3] + by[(k / 3) % 3] + bz[k / 9];
            if bound > t {
                continue;
            }
            cube(q, base, metric, k)
        };
        insert(&mut d, &mut nearest, sum, pt);
    }
    (d, nearest)
}

/// `walk_shared`'s answer (q inside the i32 range, the metric in `bounds::metric_in_range`)
/// with the exact powers taken only where they may matter. Every cube's point is hashed (a
/// few table reads) and its sum bounded by `bounds::sum_bounds`; at least three cubes have
/// sums at most the third smallest upper bound u, so the third smallest sum is at most u,
/// and a cube whose lower bound is above u has a sum above it: it is neither among the three
/// smallest nor the nearest, and the walk, kept in its order, leaves it out. The cubes that
/// remain (about three) are summed and inserted as `walk_shared` does, on the same values.
fn nearest3_bounded(q: DVec3, metric: f64) -> ([f64; 3], DVec3) {
    let (hxy, mz, [fx, fy, fz]) = shared_stages(q.floor());
    // Built element by element (arrays zeroed first cost a memset per evaluation).
    let pts: [DVec3; 27] = std::array::from_fn(|i| {
        let (dz, k) = (i / 9, i % 9);
        // SAFETY: as in `walk_shared` (hxy's and mz's values below 4096, CELL_HASH_Z's too).
        let p = unsafe {
            let e = *CELL_HASH_Z.get_unchecked(hxy[k] ^ mz[dz]) as usize;
            *CELL_POINT.get_unchecked(e)
        };
        DVec3::new(fx[k % 3] + p[0], fy[k / 3] + p[1], fz[dz] + p[2])
    });
    // The differences by axis ((pt - q).abs()'s components), a 28th cube's as a pad for the
    // bounds' lanes.
    let diff: [[f64; 28]; 3] = std::array::from_fn(|a| {
        std::array::from_fn(|i| {
            if i < 27 {
                (pts[i][a] - q[a]).abs()
            } else {
                1.0
            }
        })
    });
    let (low, high) = bounds::sum_bounds(&diff, metric);
    // The three smallest upper bounds, sorted, by selects (no NaN here).
    let mut u = [f64::INFINITY; 3];
    for &h in &high[..27] {
        u = [u[0].min(h), u[1].min(u[0].max(h)), u[2].min(u[1].max(h))];
    }
    let mut d = [f64::INFINITY; 3];
    let mut nearest = DVec3::ZERO;
    for i in 0..27 {
        if low[i] <= u[2] {
            let a = DVec3::new(diff[0][i], diff[1][i], diff[2][i]);
            insert(&mut d, &mut nearest, metric_sum(a, metric), pts[i]);
        }
    }
    (d, nearest)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::test_rng::Lcg;

    #[test]
    fn cell_points_lie_in_their_cubes() {
        for x in -3..3 {
            for y in -3..3 {
                for z in -3..3 {
                    let p = noise::cell_point(x, y, z) - DVec3::new(x as f64, y as f64, z as f64);
                    assert!(p.min_element() >= 0.0 && p.max_element() < 1.0, "{p}");
                }
            }
        }
    }

    /// The skipping walk gives the full walk's sums and nearest point bit for bit.
    #[test]
    fn skipping_cubes_is_the_full_walk() {
        let bits =
            |(d, p): ([f64; 3], DVec3)| (d.map(f64::to_bits), p.to_array().map(f64::to_bits));
        let mut rng = Lcg(7);
        let metrics = [
            2.0,
            1.0,
            2.5,
            4.0,
            6.0,
            0.5,
            1.0 / 3.0,
            3.0,
            1.6,
            40.0,
            0.0,
            -1.0,
        ];
        let mut points = Vec::new();
        for n in 0..6_000 {
            let scale = [1.0, 10.0, 1e3, 1e6, 1e14, 1e16][n % 6];
            points.push(rng.vec(2.0 * scale));
        }
        // Lattice points, faces and half-way points, where sums tie.
        for i in -4..4 {
            for h in [0.0, 0.5, 1e-17, -1e-17, 0.25] {
                let c = i as f64 + h;
                points.push(DVec3::new(c, c, c));
                points.push(DVec3::new(c, 0.5, -c));
            }
        }
        points.extend([
            DVec3::splat(f64::NAN),
            DVec3::new(f64::INFINITY, 0.0, 0.0),
            DVec3::new(0.3, f64::NEG_INFINITY, 0.0),
        ]);
        for &p in &points {
            for m in metrics {
                assert_eq!(bits(nearest3(p, m)), bits(walk(p, m)), "{p} {m}");
            }
        }
    }

    /// The walk that takes exact powers only where the bounds allow is the full walk bit for
    /// bit: random points at several scales up to the i32 edges, lattice points, faces and
    /// half-way points (ties between cubes), every scene's metric and the range's ends.
    #[test]
    fn bounded_walk_is_the_full_walk() {
        let bits =
            |(d, p): ([f64; 3], DVec3)| (d.map(f64::to_bits), p.to_array().map(f64::to_bits));
        let mut rng = Lcg(13);
        let mut metrics = vec![0.25, 16.0, 1.5, 2.2, 2.5, 3.0, 0.5, 1.6, 4.0, 1.0 / 3.0];
        for _ in 0..6 {
            metrics.push(0.25 + 15.75 * rng.next());
        }
        let mut points = Vec::new();
        for n in 0..6_000 {
            let scale = [1.0, 10.0, 1e3, 1e6, 4e9, 1e-3][n % 6];
            points.push(rng.vec(scale));
        }
        for i in -4..4 {
            for h in [0.0, 0.5, 1e-17, -1e-17, 0.25, 1e-300] {
                let c = i as f64 + h;
                points.push(DVec3::new(c, c, c));
                points.push(DVec3::new(c, 0.5, -c));
                points.push(DVec3::new(0.5, 0.5, c));
            }
        }
        for c in [-2147483647.0, 2147483647.5, -2147483648.0 + 1e-6, -0.0] {
            points.push(DVec3::new(c, 0.25, -c));
        }
        // Cube points themselves (a difference of 0 on every axis) and points near them.
        for x in -2..2 {
            for y in -2..2 {
                let p = noise::cell_point(x, y, 1);
                points.extend([p, p + DVec3::splat(1e-12), p - DVec3::new(0.0, 1e-20, 0.0)]);
            }
        }
        for &p in &points {
            for &m in &metrics {
                assert_eq!(bits(nearest3(p, m)), bits(walk(p, m)), "{p} {m}");
            }
        }
    }

    /// The walk with shared hash stages is the walk that hashes every cube, bit for bit,
    /// from tiny coordinates to the edges of the i32 range, on lattice points and halves.
    #[test]
    fn shared_walk_is_the_walk() {
        let bits =
            |(d, p): ([f64; 3], DVec3)| (d.map(f64::to_bits), p.to_array().map(f64::to_bits));
        let mut rng = Lcg(11);
        let mut points = Vec::new();
        for n in 0..8_000 {
            let scale = [1.0, 10.0, 1e3, 1e6, 2e9, 1e-3][n % 6];
            points.push(rng.vec(scale));
        }
        let edge = 2147483647.0;
        for c in [
            -edge,
            edge,
            -edge + 0.5,
            edge - 0.5,
            -2147483648.0 + 1e-6,
            0.0,
            -0.0,
        ] {
            points.push(DVec3::new(c, 0.25, -c));
            points.push(DVec3::new(0.5, c, c));
        }
        for i in -4..4 {
            for h in [0.0, 0.5, 1e-17, -1e-17, 0.25] {
                let c = i as f64 + h;
                points.push(DVec3::new(c, c, c));
            }
        }
        for &p in &points {
            for m in [2.0, 1.0, 2.5, 0.5] {
                assert_eq!(bits(walk_shared(p, m)), bits(walk_each(p, m)), "{p} {m}");
            }
        }
    }
}
