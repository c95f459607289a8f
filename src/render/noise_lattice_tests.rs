//! Tests of the noise lattice (noise_lattice.rs): every packed, batched and AVX form gives
//! the scalar reference's bits, and the scalar noise stays within its bound.

use super::*;

/// `SCALAR_BOUND` holds at random points and at the points where the s-curve weights sit
/// on one corner (integer coordinates and just below them), where a term is largest.
#[test]
fn scalar_noise_stays_within_its_bound() {
    let mut most: f64 = 0.0;
    for n in 0..200_000 {
        let t = n as f64 * 0.618_033_988_7;
        let p = DVec3::new(t.sin() * 900.0, t * 0.37 - 5_000.0, (t * 0.71).cos() * 40.0);
        most = most.max(scalar(p).abs());
        let k = p.floor();
        for q in [k, k - DVec3::splat(1e-9), k + DVec3::splat(0.5)] {
            most = most.max(scalar(q).abs());
        }
    }
    assert!(most <= SCALAR_BOUND, "{most} > {SCALAR_BOUND}");
    const { assert!(SCALAR_BOUND < 100.0) };
}

/// The original formulation: one scalar chain per corner and component, read straight
/// from ENTRY.
fn reference(p: DVec3, k: usize) -> f64 {
    let (fx, fy, fz) = (p.x.floor(), p.y.floor(), p.z.floor());
    let (ix, iy, iz) = (fx as i64, fy as i64, fz as i64);
    let t = [p.x - fx, p.y - fy, p.z - fz];
    let s = t.map(s_curve);
    let m = |c: i64| (c.wrapping_add(HASH_OFFSET) & 4095) as usize;
    let mut out = 0.0;
    for corner in 0..8usize {
        let d = [corner & 1, (corner >> 1) & 1, corner >> 2];
        let w: [f64; 3] = std::array::from_fn(|a| if d[a] == 1 { s[a] } else { 1.0 - s[a] });
        let hx = HASH_X[m(ix + d[0] as i64)] as usize;
        let hy = HASH_Y[hx ^ m(iy + d[1] as i64)] as usize;
        let i = HASH_Z[hy ^ m(iz + d[2] as i64)] as usize + k;
        let dd: [f64; 3] = std::array::from_fn(|a| t[a] - d[a] as f64);
        out += w[0]
            * w[1]
            * w[2]
            * (0.5 * ENTRY[i] + ENTRY[i + 1] * dd[0] + ENTRY[i + 2] * dd[1] + ENTRY[i + 3] * dd[2]);
    }
    out
}

#[test]
fn packed_lattice_is_the_scalar_lattice() {
    for n in 0..20_000 {
        let t = n as f64 * 0.0137;
        let p = DVec3::new(t.sin() * 50.0, t * 0.31 - 7.0, (t * 0.7).cos() * 33.0);
        let want = [reference(p, 0), reference(p, 4), reference(p, 8)];
        assert_eq!(scalar(p).to_bits(), want[0].to_bits(), "{p}");
        assert_eq!(scalar_lanes(&cell(p)).to_bits(), want[0].to_bits(), "{p}");
        assert_eq!(
            vector(p).to_array().map(f64::to_bits),
            want.map(f64::to_bits),
            "{p}"
        );
        assert_eq!(
            vector_lanes(&cell(p)).map(f64::to_bits),
            want.map(f64::to_bits),
            "{p}"
        );
    }
}

/// `cell_avx` is `cell` field for field, bit for bit (and `corners_avx` its position and
/// corners): every magnitude from tiny to past the i32 range (where both hand over to
/// `cell`), both signs, integers and their neighbours, signed zeros, infinities and NaN.
#[cfg(target_arch = "x86_64")]
#[test]
fn avx_cell_is_the_cell() {
    if !has_avx() {
        return;
    }
    let bits = |c: &Cell| {
        (
            c.t.map(f64::to_bits),
            c.wxy.map(f64::to_bits),
            c.wz.map(f64::to_bits),
            c.entry,
        )
    };
    let mut vals = vec![
        0.0,
        -0.0,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
        f64::MIN_POSITIVE,
        -f64::MIN_POSITIVE,
        2147483647.0,
        2147483647.5,
        2147483648.0,
        -2147483648.0,
        -2147483648.5,
        -2147483649.0,
        4503599627370496.0,
        -4503599627370497.0,
        1e300,
        -1e300,
    ];
    let mut x = 0x9E37_79B9_7F4A_7C15u64;
    for k in 0..4_000i32 {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        let m = (x >> 11) as f64 / (1u64 << 53) as f64;
        let e = k % 80 - 40;
        let v = m * 2f64.powi(e) * if x & 1 == 0 { 1.0 } else { -1.0 };
        vals.push(v);
        let n = (v * 7.0).round();
        vals.extend([
            n,
            f64::from_bits(n.to_bits() + 1),
            n.next_down(),
            n.next_up(),
        ]);
    }
    for (i, &a) in vals.iter().enumerate() {
        let (b, c) = (
            vals[(i * 7 + 3) % vals.len()],
            vals[(i * 13 + 5) % vals.len()],
        );
        for p in [
            DVec3::new(a, b, c),
            DVec3::new(c, a, b),
            DVec3::new(b, c, a),
        ] {
            // SAFETY: AVX was detected above.
            let got = unsafe { cell_avx(p) };
            let want = cell(p);
            assert_eq!(bits(&got), bits(&want), "{p:?}");
            // The weightless walk of the batched scalar noise: the same position and
            // corners, past the i32 range and at NaN too.
            // SAFETY: as above.
            let lean = unsafe { scalar_lanes::corners_avx(p) };
            assert_eq!(
                (lean.t.map(f64::to_bits), lean.row),
                (want.t.map(f64::to_bits), want.entry.map(|e| e * 32)),
                "{p:?}"
            );
        }
    }
}

#[test]
fn vectors_together_are_one_at_a_time() {
    for n in 0..2_000 {
        let t = n as f64 * 0.291;
        let p = DVec3::new(t.sin() * 70.0, t * 0.11 - 30.0, (t * 0.9).cos() * 12.0);
        let ps: [DVec3; 10] = std::array::from_fn(|k| p * (1u32 << k) as f64);
        let bits = |v: DVec3| v.to_array().map(f64::to_bits);
        let want = ps.map(|q| bits(vector(q)));
        let mut got = [DVec3::ZERO; 10];
        vector_many(&ps, &mut got);
        assert_eq!(got.map(bits), want);
        vector_many_with(&ps, &mut got, cell, vector_lanes);
        assert_eq!(got.map(bits), want);
        // Component 0 of the vector noise is the scalar noise, bit for bit (dents reads
        // both at one point from one walk).
        assert_eq!(want.map(|w| w[0]), ps.map(|q| scalar(q).to_bits()));
    }
}

#[test]
fn batched_scalar_is_the_scalar_lattice() {
    for n in 0..2_000 {
        let p = DVec3::new(n as f64 * 0.37 - 300.0, (n as f64).sqrt(), -0.01 * n as f64);
        let ps: [DVec3; MAX_POINTS] =
            std::array::from_fn(|k| p * (1 << (k % 10)) as f64 + DVec3::splat((k / 10) as f64));
        // Every batch size, as the AVX path groups the points by four.
        for m in 1..=MAX_POINTS {
            let mut got = [0.0; MAX_POINTS];
            scalar_into(&ps[..m], &mut got[..m]);
            // The path without AVX too (this machine may take the AVX one above).
            let mut lanes = [0.0; MAX_POINTS];
            scalar_into_with(&ps[..m], &mut lanes[..m], scalar_lanes);
            for (k, (v, l)) in got[..m].iter().zip(&lanes[..m]).enumerate() {
                let want = reference(ps[k], 0).to_bits();
                assert_eq!((v.to_bits(), l.to_bits()), (want, want), "{m} {k}");
            }
        }
    }
}

#[test]
fn octaves_are_the_scalar_lattice_octaves() {
    for n in 0..2_000 {
        let t = n as f64 * 0.173;
        let p = DVec3::new(t.cos() * 9.0, t * 0.05, t.sin() * 4.0 - 2.0);
        let a = vector_octaves(p, 10, 0.5, 2.5);
        let (mut b, mut scale, mut weight) = (DVec3::ZERO, 1.0, 1.0);
        for _ in 0..10 {
            let q = p * scale;
            b += weight * DVec3::new(reference(q, 0), reference(q, 4), reference(q, 8));
            scale *= 2.5;
            weight *= 0.5;
        }
        let lanes = octaves_with(p, 10, 0.5, 2.5, cell, vector_lanes);
        let bits = |v: DVec3| v.to_array().map(f64::to_bits);
        assert_eq!((bits(a), bits(lanes)), (bits(b), bits(b)));
        let ps = [0.0, 0.01, -0.03, 1.5].map(|d| p + DVec3::new(d, d, -d));
        for oct in [1, 3, 4, 10] {
            let one = ps.map(|p| bits(vector_octaves(p, oct, 0.5, 2.5)));
            let four = vector_octaves4(ps, oct, 0.5, 2.5).map(bits);
            let four_lanes = octaves4_with(ps, oct, 0.5, 2.5, cell, vector_lanes).map(bits);
            assert_eq!((four, four_lanes), (one, one));
        }
    }
}

/// The AVX octaves with lane-ready cells (`octaves_lanes`) are `octaves_with` and
/// `octaves4_with` over `cell` and `vector_lanes`, bit for bit (NaN for NaN), at every
/// magnitude: past the i32 range, where the cells come from `cell`, at integers and their
/// neighbours, signed zeros, infinities and NaN.
#[cfg(target_arch = "x86_64")]
#[test]
fn lane_octaves_are_the_octaves() {
    if !has_avx() {
        return;
    }
    let vals = edge_values();
    for (i, &a) in vals.iter().enumerate() {
        let (b, c) = (
            vals[(i * 7 + 3) % vals.len()],
            vals[(i * 13 + 5) % vals.len()],
        );
        let p = DVec3::new(a, b, c);
        for (oct, omega, lambda) in [(1, 0.5, 2.0), (3, 0.6, 2.7), (10, 0.5, 2.5), (0, 0.5, 2.0)] {
            // SAFETY: AVX was detected above.
            let got = unsafe { octaves_lanes::octaves(p, oct, omega, lambda) };
            let want = octaves_with(p, oct, omega, lambda, cell, vector_lanes);
            assert!(same(got, want), "{p:?} {oct}: {got:?} {want:?}");
            let ps = [p, DVec3::new(b, c, a), DVec3::new(c, a, b), p * 0.37];
            // SAFETY: as above.
            let got4 = unsafe { octaves_lanes::octaves4(ps, oct, omega, lambda) };
            let want4 = octaves4_with(ps, oct, omega, lambda, cell, vector_lanes);
            for (g, w) in got4.into_iter().zip(want4) {
                assert!(same(g, w), "{ps:?} {oct}: {g:?} {w:?}");
            }
        }
    }
}

/// The AVX vector noise (bumps, dents) and its batches (wrinkles' ten octaves) are
/// `vector_lanes(&cell(p))`, bit for bit (NaN for NaN), at the same values as the octaves.
#[cfg(target_arch = "x86_64")]
#[test]
fn lane_vectors_are_the_vectors() {
    if !has_avx() {
        return;
    }
    let vals = edge_values();
    for (i, &a) in vals.iter().enumerate() {
        let (b, c) = (
            vals[(i * 7 + 3) % vals.len()],
            vals[(i * 13 + 5) % vals.len()],
        );
        let p = DVec3::new(a, b, c);
        let want = DVec3::from_array(vector_lanes(&cell(p)));
        // SAFETY: AVX was detected above.
        let got = unsafe { octaves_lanes::vector(p) };
        assert!(same(got, want), "{p:?}: {got:?} {want:?}");
        let ps: [DVec3; 10] = std::array::from_fn(|k| p * (1u32 << k) as f64);
        let mut got10 = [DVec3::ZERO; 10];
        // SAFETY: as above.
        unsafe { octaves_lanes::vector_many(&ps, &mut got10) };
        for (g, q) in got10.into_iter().zip(ps) {
            let w = DVec3::from_array(vector_lanes(&cell(q)));
            assert!(same(g, w), "{q:?}: {g:?} {w:?}");
        }
    }
}

/// The wrinkles normal's octaves: the AVX lanes' sum is the plain one, and the plain one is
/// `vector` at each octave's point, |·| / 2ᵏ, summed (the normal's sum before it moved here).
#[cfg(target_arch = "x86_64")]
#[test]
fn abs_octaves_are_the_vectors_summed() {
    if !has_avx() {
        return;
    }
    let vals = edge_values();
    for (i, &a) in vals.iter().enumerate() {
        let (b, c) = (
            vals[(i * 11 + 1) % vals.len()],
            vals[(i * 5 + 9) % vals.len()],
        );
        let p = DVec3::new(a, b, c);
        let mut want = DVec3::ZERO;
        let mut scale = 1.0;
        for k in 0..10 {
            let q = if k == 0 { p } else { p * scale };
            want += DVec3::from_array(vector_lanes(&cell(q))).abs() / scale;
            scale *= 2.0;
        }
        let plain = abs_octaves_plain(p);
        // SAFETY: AVX was detected above.
        let got = unsafe { octaves_lanes::abs_octaves(p) };
        assert!(
            same(plain, want) && same(got, want),
            "{p:?}: {got:?} {plain:?} {want:?}"
        );
    }
}

/// Bit-for-bit equality, any NaN equal to any NaN.
fn same(a: DVec3, b: DVec3) -> bool {
    a.to_array()
        .into_iter()
        .zip(b.to_array())
        .all(|(x, y)| x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan()))
}

/// Signed zeros, infinities, NaN, values past the i32 range, and random magnitudes from 2⁻¹⁰
/// to 2²⁹ with their nearest integers and those integers' neighbours.
fn edge_values() -> Vec<f64> {
    let mut vals = vec![
        0.0,
        -0.0,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
        2147483647.5,
        -2147483648.5,
        1e300,
        -1e18,
    ];
    let mut x = 0x2545_F491_4F6C_DD1Du64;
    for k in 0..600i32 {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        let m = (x >> 11) as f64 / (1u64 << 53) as f64;
        let v = m * 2f64.powi(k % 40 - 10) * if x & 1 == 0 { 1.0 } else { -1.0 };
        let n = v.round();
        vals.extend([v, n, n.next_down(), n.next_up()]);
    }
    vals
}
