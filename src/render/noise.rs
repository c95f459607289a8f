//! Noise and turbulence for the noise-based patterns (bozo, granite, agate, wrinkles, ...) and
//! for the turbulence warp: POV-Ray 3.7's own functions, with its tables measured from the
//! `povray` binary (scripts/measure_noise.py, docs/noise.md; the tables are in `noise_data`).
//!
//! Generators 1 and 2 are one lattice noise: each integer lattice point picks, through a
//! three-stage 12-bit hash, a position i in a table of 267 numbers; its value is ENTRY[i]/2
//! and its gradient ENTRY[i+1..i+4]; the eight corners are blended with the cubic s-curve.
//! Generator 1 clips that to [0, 1]; generator 2 maps it affinely into [0, 1]. Crackle's
//! points and cells' values come from a second hash of the same kind (`cells_data`).
//! Generator 3 is a gradient-only lattice noise of its own: the point moved by a constant,
//! unit gradients from a table of 2048 chosen by an additive 11-bit hash (`noise3_data`).
//! Everything here is a pure function of the point: no tables built at run time, no
//! allocation (turbulence keeps its last result per thread, which changes no value). The
//! lattice itself is in `noise_lattice`.

use std::cell::Cell;

use crate::math::DVec3;

use super::cells_data::{
    CELL_HASH_OFFSET, CELL_HASH_X, CELL_HASH_Y, CELL_HASH_Z, CELL_POINT, CELL_VALUE,
};
use super::noise3_data::{GEN3_A, GEN3_B, GEN3_GRAD, GEN3_PERM, GEN3_SHIFT};
use super::noise_data::{GEN2_A, GEN2_B};
use super::noise_lattice;

#[inline]
fn s_curve(t: f64) -> f64 {
    t * t * (3.0 - 2.0 * t)
}

/// Generator 3's unclipped value (measured, docs/noise.md): each coordinate plus GEN3_SHIFT
/// (about 1e7, so the sum keeps 29 fraction bits, as POV-Ray's does) is floored; the
/// corners' unit gradients come from an additive hash of the 11-bit lattice coordinates and
/// are blended with the cubic s-curve.
fn gradient_noise(p: DVec3) -> f64 {
    let t = [p.x + GEN3_SHIFT, p.y + GEN3_SHIFT, p.z + GEN3_SHIFT];
    let fl = [t[0].floor(), t[1].floor(), t[2].floor()];
    let f = [t[0] - fl[0], t[1] - fl[1], t[2] - fl[2]];
    let i = fl.map(|c| (c as i64 & 2047) as usize);
    let s = f.map(s_curve);
    let perm = |k: usize| GEN3_PERM[k & 2047] as usize;
    let mut sum = 0.0;
    for corner in 0..8 {
        let d = [corner & 1, (corner >> 1) & 1, (corner >> 2) & 1];
        let h = perm(perm(i[0] + d[0]) + ((i[1] + d[1]) & 2047));
        let g = &GEN3_GRAD[(h + ((i[2] + d[2]) & 2047)) & 2047];
        let w = (0..3)
            .map(|a| if d[a] == 1 { s[a] } else { 1.0 - s[a] })
            .product::<f64>();
        sum += w
            * (g[0] * (f[0] - d[0] as f64)
                + g[1] * (f[1] - d[1] as f64)
                + g[2] * (f[2] - d[2] as f64));
    }
    GEN3_A + GEN3_B * sum
}

/// The entry of unit cube (x, y, z) in the cells tables: the same kind of three-stage 12-bit
/// hash as the noise's, with its own tables (measured with the `cells` pattern).
#[inline]
fn cell_entry(x: i64, y: i64, z: i64) -> usize {
    let m = |c: i64| (c.wrapping_add(CELL_HASH_OFFSET) & 4095) as usize;
    CELL_HASH_Z[CELL_HASH_Y[CELL_HASH_X[m(x)] as usize ^ m(y)] as usize ^ m(z)] as usize
}

/// Crackle's random point in unit cube (x, y, z), as POV-Ray places it.
#[inline]
pub fn cell_point(x: i64, y: i64, z: i64) -> DVec3 {
    let p = CELL_POINT[cell_entry(x, y, z)];
    DVec3::new(x as f64 + p[0], y as f64 + p[1], z as f64 + p[2])
}

/// The `cells` pattern's value of unit cube (x, y, z).
#[inline]
pub fn cell_value(x: i64, y: i64, z: i64) -> f64 {
    CELL_VALUE[cell_entry(x, y, z)]
}

/// A well-mixed 32-bit hash of a lattice point and a salt (for lancer's own noise, crackle
/// points and cell values).
#[inline]
pub fn hash3(x: i64, y: i64, z: i64, salt: u32) -> u32 {
    let mut h = (x as u32).wrapping_mul(0x8da6_b343)
        ^ (y as u32).wrapping_mul(0xd816_3841)
        ^ (z as u32).wrapping_mul(0xcb1a_b31f)
        ^ salt.wrapping_mul(0x9e37_79b9);
    h ^= h >> 16;
    h = h.wrapping_mul(0x7feb_352d);
    h ^= h >> 15;
    h = h.wrapping_mul(0x846c_a68b);
    h ^ (h >> 16)
}

/// A float in [0, 1) from a hash.
#[inline]
pub fn unit(h: u32) -> f64 {
    (h >> 8) as f64 / (1u32 << 24) as f64
}

/// The noise value in [0, 1] that bozo, granite and turbulence build on.
pub fn noise(p: DVec3, generator: u8) -> f64 {
    match generator {
        3 => gradient_noise(p).clamp(0.0, 1.0),
        _ => lattice_value(noise_lattice::scalar(p), generator),
    }
}

/// Generator 1's or 2's noise value from the lattice's sum at the point.
#[inline(always)]
fn lattice_value(sum: f64, generator: u8) -> f64 {
    match generator {
        1 => (0.5 + sum).clamp(0.0, 1.0),
        _ => (GEN2_A + GEN2_B * (0.5 + sum)).clamp(0.0, 1.0),
    }
}

/// POV-Ray's vector noise ("DNoise", what `vturbulence` and turbulence sum): three lattice
/// noises on entries 0, 4 and 8 places apart, each in about [-0.5, 0.5]. The same for every
/// noise_generator (measured: `gradient x turbulence 0.1 noise_generator 3` moves the point
/// exactly as generator 2 does).
pub fn dnoise(p: DVec3, _generator: u8) -> DVec3 {
    noise_lattice::vector(p)
}

/// `dnoise` at up to ten points, their lattice hash walks together (the same values).
pub fn dnoise_many<const N: usize>(ps: &[DVec3; N], out: &mut [DVec3; N]) {
    noise_lattice::vector_many(ps, out)
}

/// `noise(p, generator)` and `dnoise(p, generator)` from one lattice walk: for generators 1
/// and 2 the scalar noise is the vector noise's first component, bit for bit (both sum the
/// same corner terms in the same order).
pub fn noise_and_dnoise(p: DVec3, generator: u8) -> (f64, DVec3) {
    let d = noise_lattice::vector(p);
    let v = match generator {
        3 => noise(p, 3),
        _ => lattice_value(d.x, generator),
    };
    (v, d)
}

/// The displacement of turbulence: octaves of vector noise, each `lambda` times finer and
/// `omega` times weaker than the one before. POV-Ray keeps lambda and omega in single
/// precision (measured: vturbulence(2.7, 0.6, ...) matches only with both rounded to f32).
///
/// The last result is kept per thread: layers of one texture or sky (S_Cloud5's three cloud
/// layers, a wood's layers) often stir the same point with the same octaves, omega and lambda
/// and differ only in the amount, which the caller applies.
pub fn turbulence_vec(p: DVec3, octaves: u32, omega: f64, lambda: f64, _generator: u8) -> DVec3 {
    let (omega, lambda) = (omega as f32 as f64, lambda as f32 as f64);
    // POV-Ray stops at 10 octaves (measured: vturbulence with 12 or 20 equals 10).
    let octaves = octaves.clamp(1, 10);
    let key = [
        p.x.to_bits(),
        p.y.to_bits(),
        p.z.to_bits(),
        octaves as u64,
        omega.to_bits(),
        lambda.to_bits(),
    ];
    // The last key is read out here and compared where `key` is still in registers: a
    // closure doing both stayed an out-of-line `LocalKey::with` that read `key` back from the
    // caller's stack in 16-byte loads over its 8-byte stores, a store-forwarding stall.
    let (k, v) = LAST_TURBULENCE.with(|last| (last.key.get(), last.value.get()));
    // Not `k == key`: that is a call to memcmp (1-4 % of a wood).
    if k.iter().zip(&key).fold(0, |acc, (a, b)| acc | (a ^ b)) == 0 {
        return v;
    }
    let v = noise_lattice::vector_octaves(p, octaves, omega, lambda);
    LAST_TURBULENCE.with(|last| {
        last.key.set(key);
        last.value.set(v);
    });
    v
}

/// `turbulence_vec` without its per-thread cache (the same value), for callers whose points
/// rarely repeat, where the cache's key compare and store are pure cost.
pub fn turbulence_vec_uncached(p: DVec3, octaves: u32, omega: f64, lambda: f64) -> DVec3 {
    let (omega, lambda) = (omega as f32 as f64, lambda as f32 as f64);
    noise_lattice::vector_octaves(p, octaves.clamp(1, 10), omega, lambda)
}

/// `turbulence_vec` at a normal's four samples, all their octaves' lattice walks together
/// (the per-thread last result is neither read nor changed).
pub fn turbulence_vec4(ps: [DVec3; 4], octaves: u32, omega: f64, lambda: f64) -> [DVec3; 4] {
    let (omega, lambda) = (omega as f32 as f64, lambda as f32 as f64);
    noise_lattice::vector_octaves4(ps, octaves.clamp(1, 10), omega, lambda)
}

/// `turbulence_vec`'s last key (the point's and parameters' bits) and result, each read and
/// written in place: as one `Cell<Option<(key, value)>>` the pair was copied whole through
/// the stack on every call (~40 instructions a call; most calls miss: stones1's warps never
/// hit, sky layers do).
struct LastTurbulence {
    key: Cell<[u64; 6]>,
    value: Cell<DVec3>,
}

thread_local! {
    /// Its first key's octave count, 0, matches no call (every call clamps it to 1..=10).
    static LAST_TURBULENCE: LastTurbulence = const {
        LastTurbulence {
            key: Cell::new([0; 6]),
            value: Cell::new(DVec3::ZERO),
        }
    };
}

/// The noise the patterns' own sums (turbulence, granite, wrinkles) are built on, per
/// generator (measured): generator 1's clipped value, or generator 2's value n mapped to
/// 2n - 1/2, which may leave [0, 1].
#[inline]
fn sum_noise(p: DVec3, generator: u8) -> f64 {
    match generator {
        1 => (0.5 + noise_lattice::scalar(p)).clamp(0.0, 1.0),
        3 => 2.0 * noise(p, 3) - 0.5,
        _ => 2.0 * (GEN2_A + GEN2_B * (0.5 + noise_lattice::scalar(p))) - 0.5,
    }
}

/// `sum_noise` clipped to [0, 1]: one octave of granite or wrinkles, or turbulence's first.
#[inline]
pub fn clipped_noise(p: DVec3, generator: u8) -> f64 {
    sum_noise(p, generator).clamp(0.0, 1.0)
}

/// `sum_noise` at up to 40 points into `out` (the octaves of one sum or of four, whose
/// lattice hash walks `noise_lattice::scalar_into` overlaps).
fn sum_noise_into(ps: &[DVec3], generator: u8, out: &mut [f64]) {
    match generator {
        3 => {
            for (o, &p) in out.iter_mut().zip(ps) {
                *o = sum_noise(p, 3);
            }
        }
        1 => {
            noise_lattice::scalar_into(ps, out);
            for o in out.iter_mut() {
                *o = (0.5 + *o).clamp(0.0, 1.0);
            }
        }
        _ => {
            noise_lattice::scalar_into(ps, out);
            for o in out.iter_mut() {
                *o = 2.0 * (GEN2_A + GEN2_B * (0.5 + *o)) - 0.5;
            }
        }
    }
}

/// Scalar turbulence (marble's and agate's): the first octave clipped to [0, 1], the others
/// added unclipped, each `lambda` times finer and `omega` times weaker (lambda and omega in
/// single precision, as POV-Ray keeps them). Measured: `marble turbulence t ramp_wave` is
/// x + t·this.
pub fn turbulence(p: DVec3, octaves: u32, omega: f64, lambda: f64, generator: u8) -> f64 {
    let (omega, lambda) = (omega as f32 as f64, lambda as f32 as f64);
    let n = octaves.clamp(1, 10) as usize;
    // Generators 1 and 2 with AVX: the same sum without the zeroed arrays of points and
    // values and with the generator's map in lanes.
    if generator != 3 {
        if let Some(v) = noise_lattice::turbulence(p, n, omega, lambda, generator == 1) {
            return v;
        }
    }
    turbulence_plain(p, n, omega, lambda, generator)
}

/// `turbulence` through `sum_noise_into` (omega and lambda rounded, n clamped): generator 3,
/// and any generator without AVX.
fn turbulence_plain(p: DVec3, n: usize, omega: f64, lambda: f64, generator: u8) -> f64 {
    let mut ps = [p; 10];
    let mut scale = 1.0;
    for q in &mut ps[1..n] {
        scale *= lambda;
        *q = p * scale;
    }
    let mut v = [0.0; 10];
    sum_noise_into(&ps[..n], generator, &mut v[..n]);
    octave_sum(&v[..n], omega)
}

/// Turbulence's sum of its octaves' noise values `v` (at least one): the first clamped to
/// [0, 1], each later one weighted by the next power of `omega`, added in octave order.
#[inline(always)]
pub(super) fn octave_sum(v: &[f64], omega: f64) -> f64 {
    let mut sum = v[0].clamp(0.0, 1.0);
    let mut weight = 1.0;
    for &x in &v[1..] {
        weight *= omega;
        sum += weight * x;
    }
    sum
}

pub use crate::scene::atmosphere::turbulence_bound;

// The scene layer's octave bound (`turbulence_bound`'s) is generator 2's map of the lattice's
// bound computed from the table, to the bit.
const _: () = assert!(
    2.0 * (GEN2_A + GEN2_B * (0.5 + noise_lattice::SCALAR_BOUND)) + 0.5
        == crate::scene::atmosphere::TURBULENCE_OCTAVE_BOUND
);

/// `turbulence` at a normal's four samples, the lattice walks of all their octaves together
/// (the same values: each sum in the same order).
pub fn turbulence4(
    ps: [DVec3; 4],
    octaves: u32,
    omega: f64,
    lambda: f64,
    generator: u8,
) -> [f64; 4] {
    let (omega, lambda) = (omega as f32 as f64, lambda as f32 as f64);
    let n = octaves.clamp(1, 10) as usize;
    let mut qs = [DVec3::ZERO; 40];
    for (p, q) in ps.iter().zip(qs.chunks_mut(n)) {
        q[0] = *p;
        let mut scale = 1.0;
        for q in &mut q[1..] {
            scale *= lambda;
            *q = *p * scale;
        }
    }
    let mut v = [0.0; 40];
    sum_noise_into(&qs[..4 * n], generator, &mut v[..4 * n]);
    let mut out = [0.0; 4];
    for (o, v) in out.iter_mut().zip(v.chunks(n)) {
        *o = octave_sum(v, omega);
    }
    out
}

/// `noise` at a normal's four samples, their lattice walks together.
pub fn noise4(ps: [DVec3; 4], generator: u8) -> [f64; 4] {
    if generator == 3 {
        return ps.map(|p| noise(p, 3));
    }
    let mut v = [0.0; 4];
    noise_lattice::scalar_into(&ps, &mut v);
    v.map(|s| match generator {
        1 => (0.5 + s).clamp(0.0, 1.0),
        _ => (GEN2_A + GEN2_B * (0.5 + s)).clamp(0.0, 1.0),
    })
}

/// `granite` at a normal's four samples, their lattice walks together.
pub fn granite4(ps: [DVec3; 4], generator: u8) -> [f64; 4] {
    let freqs = [4.0, 8.0, 16.0, 32.0, 64.0, 128.0];
    let mut qs = [DVec3::ZERO; 24];
    for (p, q) in ps.iter().zip(qs.chunks_mut(6)) {
        for (q, f) in q.iter_mut().zip(freqs) {
            *q = *p * f;
        }
    }
    let mut v = [0.0; 24];
    sum_noise_into(&qs, generator, &mut v);
    let mut out = [0.0; 4];
    for (o, v) in out.iter_mut().zip(v.chunks(6)) {
        let mut sum = 0.0;
        for (&x, f) in v.iter().zip(freqs) {
            sum += (x.clamp(0.0, 1.0) - 0.5).abs() * 4.0 / f;
        }
        *o = sum;
    }
    out
}

/// Granite: six octaves from four times the point's frequency, each |noise - 1/2| halving in
/// weight.
pub fn granite(p: DVec3, generator: u8) -> f64 {
    // Generators 1 and 2 with AVX: the same operations with the octaves' values kept in
    // lanes (~180 instructions a call went to their copies and the loops around the lattice).
    if generator != 3 {
        if let Some(v) = noise_lattice::granite(p, generator == 1) {
            return v;
        }
    }
    granite_plain(p, generator)
}

/// `granite` through `sum_noise_into`: generator 3, and any generator without AVX.
fn granite_plain(p: DVec3, generator: u8) -> f64 {
    let freqs = [4.0, 8.0, 16.0, 32.0, 64.0, 128.0];
    let mut v = [0.0; 6];
    sum_noise_into(&scaled(p, freqs), generator, &mut v);
    let mut sum = 0.0;
    for (x, f) in v.into_iter().zip(freqs) {
        sum += (x.clamp(0.0, 1.0) - 0.5).abs() * 4.0 / f;
    }
    sum
}

/// `p` times each frequency. A loop: `freqs.map(|f| p * f)` stayed a call to
/// `array::try_map` that copied the points out through memory.
#[inline(always)]
fn scaled<const N: usize>(p: DVec3, freqs: [f64; N]) -> [DVec3; N] {
    let mut ps = [DVec3::ZERO; N];
    for (q, f) in ps.iter_mut().zip(freqs) {
        *q = p * f;
    }
    ps
}

/// Wrinkles: ten octaves of the clipped noise, weights 1/2, 1/4, ...
pub fn wrinkles(p: DVec3, generator: u8) -> f64 {
    // Generators 1 and 2 with AVX: the same operations with the octaves' values kept in
    // lanes, as granite's (arches' sky: ~1,750 instructions a call, ~230 of them the
    // values' copies through `sum_noise_into` and the loops around the lattice).
    if generator != 3 {
        if let Some(v) = noise_lattice::wrinkles(p, generator == 1) {
            return v;
        }
    }
    wrinkles_plain(p, generator)
}

/// `wrinkles` through `sum_noise_into`: generator 3, and any generator without AVX.
fn wrinkles_plain(p: DVec3, generator: u8) -> f64 {
    let mut freqs = [1.0; 10];
    for k in 1..10 {
        freqs[k] = freqs[k - 1] * 2.0;
    }
    let mut v = [0.0; 10];
    sum_noise_into(&scaled(p, freqs), generator, &mut v);
    let mut sum = 0.0;
    let mut weight = 0.5;
    for x in v {
        sum += weight * x.clamp(0.0, 1.0);
        weight *= 0.5;
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Generator 3 is GEN3_A at every lattice point, which sits at k - frac(GEN3_SHIFT).
    #[test]
    fn generator_3_is_flat_at_lattice_points() {
        let k = |c: f64| c - GEN3_SHIFT.fract();
        for (x, y, z) in [(0.0, 0.0, 0.0), (3.0, -7.0, 12.0), (-400.0, 9.0, 1500.0)] {
            assert_eq!(noise(DVec3::new(k(x), k(y), k(z)), 3), GEN3_A);
        }
    }

    /// Values POV-Ray printed (`f_noise_generator`, `vturbulence`); tests/noise_probes.rs checks
    /// many more at held-out points.
    #[test]
    fn generators_match_povray() {
        let p = DVec3::new(0.0, 0.0, 0.0);
        assert!((noise(p, 1) - 0.0565805).abs() < 1e-12);
        assert!((noise(p, 2) - 0.2983224393079099).abs() < 1e-12);
        // f_noise_generator(0, 0, 0, 3) and (0.5, 0.5, 0.5, 3)
        assert!((noise(p, 3) - 0.5113543053730359).abs() < 1e-12);
        assert!((noise(DVec3::splat(0.5), 3) - 0.6721038435526576).abs() < 1e-12);
        let d = dnoise(DVec3::new(1.0, 0.0, 1.0), 2);
        assert!(
            (d - DVec3::new(-0.448821, -0.4434195, 0.3610055))
                .abs()
                .max_element()
                < 1e-12
        );
    }

    /// Asserts that a pattern's lanes (`lanes`) give `plain`'s bits, for both generators, at
    /// ordinary points, lattice points and halves, points whose higher octaves leave the i32
    /// range (the walk's fallback), infinities and NaN (any NaN matches any NaN).
    fn same_as_plain(lanes: fn(DVec3, u8) -> f64, plain: fn(DVec3, u8) -> f64) {
        let mut points: Vec<DVec3> = (0..20_000)
            .map(|n| {
                let t = n as f64 * 0.0917;
                DVec3::new(t.sin() * 300.0, t * 0.013 - 40.0, (t * 0.3).cos() * 7.0)
            })
            .collect();
        for c in [
            0.0, -0.0, 0.5, -0.5, 1.0, -1.0, 3.25, 1.6e7, -1.7e7, 2e9, 1e300,
        ] {
            points.push(DVec3::splat(c));
            points.push(DVec3::new(c, 0.25, -c));
        }
        for c in [f64::NAN, f64::INFINITY, -f64::INFINITY] {
            points.push(DVec3::new(c, 1.0, 2.0));
            points.push(DVec3::new(0.3, 1.0, c));
        }
        for p in points {
            for g in [1, 2] {
                let (a, b) = (lanes(p, g), plain(p, g));
                assert!(
                    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()),
                    "{p} generator {g}: {a:e} against {b:e}"
                );
            }
        }
    }

    /// Granite's lanes (AVX, generators 1 and 2) are `sum_noise_into`'s values mapped in
    /// memory, bit for bit, at `same_as_plain`'s points.
    #[test]
    fn granite_lanes_are_the_plain_granite() {
        same_as_plain(granite, granite_plain);
    }

    /// Wrinkles' lanes are `sum_noise_into`'s values summed from memory, bit for bit, at
    /// `same_as_plain`'s points and both generators.
    #[test]
    fn wrinkles_lanes_are_the_plain_wrinkles() {
        same_as_plain(wrinkles, wrinkles_plain);
    }

    /// Scalar turbulence's lanes are `sum_noise_into`'s values summed from memory, bit for
    /// bit, for every octave count (each chunking of the octaves) and both generators.
    #[test]
    fn turbulence_lanes_are_the_plain_turbulence() {
        let mut points: Vec<DVec3> = (0..3_000)
            .map(|n| {
                let t = n as f64 * 0.0917;
                DVec3::new(t.sin() * 300.0, t * 0.013 - 40.0, (t * 0.3).cos() * 7.0)
            })
            .collect();
        for c in [0.0, -0.0, 0.5, -1.0, 1.6e7, -1.7e7, 2e9, 1e300] {
            points.push(DVec3::new(c, 0.25, -c));
        }
        for c in [f64::NAN, f64::INFINITY] {
            points.push(DVec3::new(0.3, c, 2.0));
        }
        for p in points {
            for g in [1, 2] {
                for n in 1..=10 {
                    for (om, la) in [(0.5, 2.0), (0.7, 3.0), (0.6f32 as f64, 2.7f32 as f64)] {
                        let a = noise_lattice::turbulence(p, n, om, la, g == 1);
                        let b = turbulence_plain(p, n, om, la, g);
                        let a = a.unwrap_or(b);
                        assert!(
                            a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()),
                            "{p} generator {g}, {n} octaves: {a:e} against {b:e}"
                        );
                    }
                }
            }
        }
    }

    /// The four-sample forms are the one-point functions, bit for bit, for every generator.
    #[test]
    fn four_samples_are_four_points() {
        for n in 0..3_000 {
            let t = n as f64 * 0.217;
            let p = DVec3::new(t.sin() * 30.0, t * 0.13 - 40.0, (t * 0.3).cos() * 7.0);
            let ps = [0.0, 0.01, -0.02, 0.5].map(|d| p + DVec3::new(d, -d, 2.0 * d));
            let bits = |v: [f64; 4]| v.map(f64::to_bits);
            for g in [0, 1, 2, 3] {
                assert_eq!(bits(noise4(ps, g)), bits(ps.map(|p| noise(p, g))));
                assert_eq!(bits(granite4(ps, g)), bits(ps.map(|p| granite(p, g))));
                for (oct, om, la) in [(6, 0.5, 2.0), (1, 0.7, 3.0), (10, 0.6, 2.7), (3, 0.45, 1.9)]
                {
                    assert_eq!(
                        bits(turbulence4(ps, oct, om, la, g)),
                        bits(ps.map(|p| turbulence(p, oct, om, la, g)))
                    );
                }
            }
        }
    }

    #[test]
    fn noise_and_dnoise_together_are_each() {
        for n in 0..5_000 {
            let t = n as f64 * 0.173;
            let p = DVec3::new(t.cos() * 90.0, t * 0.07 - 3.0, (t * 0.4).sin() * 15.0);
            for g in [0, 1, 2, 3] {
                let (v, d) = noise_and_dnoise(p, g);
                assert_eq!(v.to_bits(), noise(p, g).to_bits());
                assert_eq!(
                    d.to_array().map(f64::to_bits),
                    dnoise(p, g).to_array().map(f64::to_bits)
                );
            }
        }
    }

    /// The cached turbulence is the uncached one, bit for bit, on repeats (of point and
    /// parameters), on a changed parameter at the same point and at the origin, whose key's
    /// point bits are the fresh cache's.
    #[test]
    fn cached_turbulence_is_the_turbulence() {
        let bits = |v: DVec3| v.to_array().map(f64::to_bits);
        let p = DVec3::new(0.3, -1.7, 2.25);
        for (q, oct, om, la) in [
            (DVec3::ZERO, 1, 0.0, 0.0),
            (DVec3::ZERO, 6, 0.5, 2.0),
            (p, 6, 0.5, 2.0),
            (p, 6, 0.5, 2.0),
            (p, 7, 0.5, 2.0),
            (p, 7, 0.6, 2.0),
            (p, 7, 0.6, 2.5),
            (p, 0, 0.6, 2.5),
            (-p, 0, 0.6, 2.5),
            (p, 0, 0.6, 2.5),
        ] {
            assert_eq!(
                bits(turbulence_vec(q, oct, om, la, 2)),
                bits(turbulence_vec_uncached(q, oct, om, la))
            );
        }
    }

    /// `turbulence_bound` bounds scalar turbulence at scattered points for every generator,
    /// octave count and a spread of omegas (the lattice's own bound is checked at its extreme
    /// corners in noise_lattice's tests).
    #[test]
    fn turbulence_stays_within_its_bound() {
        for n in 0..4_000 {
            let t = n as f64 * 0.377;
            let p = DVec3::new(t.sin() * 300.0, t * 0.91 - 700.0, (t * 0.3).cos() * 70.0);
            for g in [1, 2, 3] {
                for (oct, om) in [
                    (1, 0.5),
                    (6, 0.5),
                    (10, 0.9),
                    (4, 1.25),
                    (10, 3.0),
                    (7, -2.0),
                ] {
                    let v = turbulence(p, oct, om, 2.0, g);
                    assert!(
                        v.abs() <= turbulence_bound(oct, om),
                        "{v} at {p} {g} {oct} {om}"
                    );
                }
            }
        }
        assert!(turbulence_bound(6, f64::NAN).is_nan());
        assert!(turbulence_bound(6, 1e300).is_infinite());
    }

    #[test]
    fn noise_values_stay_in_unit_range() {
        for g in 1..=3 {
            for i in 0..500 {
                let t = i as f64 * 0.31;
                let n = noise(DVec3::new(t, -t * 0.5, t * 0.25 + 0.1), g);
                assert!((0.0..=1.0).contains(&n));
            }
        }
    }
}
