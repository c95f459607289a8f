//! Escape-time fractal patterns (`mandel`, `julia`, `magnet`): the orbit loops, the z² + c
//! loop and the orbits stepped several at a time for a normal's samples (the same bits per
//! lane as one orbit alone), and the interior and exterior value types.

use crate::scene::pattern::Fractal;

/// Escape-time fractals. From z = c (mandel) or z = p (julia), z ← zⁿ + c; leaving the
/// radius-2 disc at step k (from 0) gives the exterior value (type 1: k/N, measured), staying
/// in for N steps the interior value (type 0: 1). Other types read the orbit as the manual
/// lists them, scaled by their factor (checked against povray for types 1 to 8).
pub(super) fn fractal(f: &Fractal, p: (f64, f64)) -> f64 {
    if f.magnet != 0 {
        return magnet(f, p);
    }
    match (f.exponent, f.interior.0) {
        // Only interior type 1 reads the orbit's smallest point; the loop without it is
        // shorter (same values either way).
        (2, 1) => fractal2::<true>(f, p),
        (2, _) => fractal2::<false>(f, p),
        _ => fractal_n(f, p),
    }
}

/// `fractal` for any exponent (zⁿ by `cpow`).
fn fractal_n(f: &Fractal, p: (f64, f64)) -> f64 {
    let c = f.julia.unwrap_or(p);
    let (mut zr, mut zi) = p;
    let n = f.iterations;
    // The orbit's smallest point counts the starting point too (measured: interior 1).
    let mut min_abs2 = zr * zr + zi * zi;
    for k in 0..n {
        (zr, zi) = cpow(zr, zi, f.exponent);
        zr += c.0;
        zi += c.1;
        let a2 = zr * zr + zi * zi;
        if a2 > 4.0 {
            let (t, factor) = f.exterior;
            return match t {
                1 => k as f64 / n as f64,
                7 if factor != 0.0 => (k as f64 % factor) / factor,
                8 if factor != 0.0 => (k as f64 % (factor + 1.0)) / factor,
                6 => (zr * zr + zi * zi).sqrt() * factor,
                _ => orbit_value(t, zr, zi, min_abs2) * factor,
            };
        }
        min_abs2 = min_abs2.min(a2);
    }
    let (t, factor) = f.interior;
    orbit_value(t, zr, zi, min_abs2) * factor
}

/// `fractal` for z² + c, the arithmetic of the general loop with `cpow(z, 2)` written out:
/// z·z's products zr·zr and zi·zi are the ones the escape test of the step before summed, so
/// each is computed once, and zr·zi + zi·zr is zr·zi + zr·zi (the same product twice). The
/// orbit is the same to the bit; the loop is about a sixth shorter. `MIN`: whether to keep
/// the orbit's smallest |z|² (interior type 1 alone reads it).
#[inline(always)]
fn fractal2<const MIN: bool>(f: &Fractal, p: (f64, f64)) -> f64 {
    let c = f.julia.unwrap_or(p);
    let (mut zr, mut zi) = p;
    let (mut rr, mut ii) = (zr * zr, zi * zi);
    let n = f.iterations;
    let mut min_abs2 = rr + ii;
    for k in 0..n {
        let ri = zr * zi;
        zr = (rr - ii) + c.0;
        zi = (ri + ri) + c.1;
        rr = zr * zr;
        ii = zi * zi;
        let a2 = rr + ii;
        if a2 > 4.0 {
            return exterior_value(f, k, zr, zi, a2, min_abs2);
        }
        if MIN {
            min_abs2 = min_abs2.min(a2);
        }
    }
    let (t, factor) = f.interior;
    orbit_value(t, zr, zi, min_abs2) * factor
}

/// A z² + c fractal's value at the points of `ps` (a normal's samples), each lane the same
/// arithmetic as `fractal2` at its point. One orbit is bound by the latency of its steps;
/// L orbits stepped together overlap. Lanes that have left go on stepping (their values
/// are kept from the step they left and what they compute after is never read).
#[inline(always)]
pub(super) fn fractal2_lanes<const MIN: bool, const L: usize>(
    f: &Fractal,
    ps: [(f64, f64); L],
) -> [f64; L] {
    let c = ps.map(|p| f.julia.unwrap_or(p));
    let (mut zr, mut zi) = (ps.map(|p| p.0), ps.map(|p| p.1));
    let (mut rr, mut ii) = (zr.map(|x| x * x), zi.map(|y| y * y));
    let mut min_abs2: [f64; L] = std::array::from_fn(|l| rr[l] + ii[l]);
    let mut out = [0.0; L];
    let mut live = [true; L];
    let n = f.iterations;
    for k in 0..n {
        for l in 0..L {
            let ri = zr[l] * zi[l];
            zr[l] = (rr[l] - ii[l]) + c[l].0;
            zi[l] = (ri + ri) + c[l].1;
            rr[l] = zr[l] * zr[l];
            ii[l] = zi[l] * zi[l];
            let a2 = rr[l] + ii[l];
            if live[l] && a2 > 4.0 {
                out[l] = exterior_value(f, k, zr[l], zi[l], a2, min_abs2[l]);
                live[l] = false;
            }
            if MIN {
                min_abs2[l] = min_abs2[l].min(a2);
            }
        }
        if live.iter().all(|&x| !x) {
            return out;
        }
    }
    let (t, factor) = f.interior;
    for l in 0..L {
        if live[l] {
            out[l] = orbit_value(t, zr[l], zi[l], min_abs2[l]) * factor;
        }
    }
    out
}

/// The value of an orbit that left the radius-2 disc at step k (from 0) at z, |z|² = a2.
#[inline(always)]
fn exterior_value(f: &Fractal, k: u32, zr: f64, zi: f64, a2: f64, min_abs2: f64) -> f64 {
    let n = f.iterations;
    let (t, factor) = f.exterior;
    match t {
        1 => k as f64 / n as f64,
        7 if factor != 0.0 => (k as f64 % factor) / factor,
        8 if factor != 0.0 => (k as f64 % (factor + 1.0)) / factor,
        6 => a2.sqrt() * factor,
        _ => orbit_value(t, zr, zi, min_abs2) * factor,
    }
}

/// The magnet fractals (fractint's magnet 1 and 2): z ← ((z² + c − 1)/(2z + c − 2))² or
/// z ← ((z³ + 3(c−1)z + (c−1)(c−2))/(3z² + 3(c−2)z + (c−1)(c−2) + 1))², from z = 0 with c = p
/// (mandel) or z = p (julia). Step k (from 0) ends the orbit, as exterior, when |z|² > 10⁴ or
/// |z − 1|² < 10⁻⁴: both bounds measured with scripts/measure_pattern.py, 800 points matching.
fn magnet(f: &Fractal, p: (f64, f64)) -> f64 {
    let (c1, c2, mut z, mut min_abs2) = magnet_start(f, p);
    for k in 0..f.iterations {
        z = magnet_step(f.magnet, z, c1, c2);
        let a2 = z.0 * z.0 + z.1 * z.1;
        let d1 = (z.0 - 1.0) * (z.0 - 1.0) + z.1 * z.1;
        if a2 > 1e4 || d1 < 1e-4 {
            return exterior_value(f, k, z.0, z.1, a2, min_abs2);
        }
        min_abs2 = min_abs2.min(a2);
    }
    let (t, factor) = f.interior;
    orbit_value(t, z.0, z.1, min_abs2) * factor
}

/// A magnet orbit's c − 1, c − 2, starting z and starting smallest |z|² at `p`. The smallest
/// point (interior 1) counts the starting point for julia but not the mandel form's 0
/// (measured).
#[inline(always)]
fn magnet_start(f: &Fractal, p: (f64, f64)) -> (Complex, Complex, Complex, f64) {
    let (c, z, min_abs2) = match f.julia {
        Some(c) => (c, p, p.0 * p.0 + p.1 * p.1),
        None => (p, (0.0, 0.0), f64::INFINITY),
    };
    ((c.0 - 1.0, c.1), (c.0 - 2.0, c.1), z, min_abs2)
}

/// A complex number as (real, imaginary).
type Complex = (f64, f64);

/// One step of magnet `kind` (1 or 2) from z, with c1 = c − 1 and c2 = c − 2.
#[inline(always)]
fn magnet_step(kind: u8, z: Complex, c1: Complex, c2: Complex) -> Complex {
    let mul = |a: (f64, f64), b: (f64, f64)| (a.0 * b.0 - a.1 * b.1, a.0 * b.1 + a.1 * b.0);
    let div = |a: (f64, f64), b: (f64, f64)| {
        let d = b.0 * b.0 + b.1 * b.1;
        ((a.0 * b.0 + a.1 * b.1) / d, (a.1 * b.0 - a.0 * b.1) / d)
    };
    let q = if kind == 1 {
        let num = mul(z, z);
        div(
            (num.0 + c1.0, num.1 + c1.1),
            (2.0 * z.0 + c2.0, 2.0 * z.1 + c2.1),
        )
    } else {
        let z2 = mul(z, z);
        let z3 = mul(z2, z);
        let cc = mul(c1, c2);
        let a = mul((3.0 * c1.0, 3.0 * c1.1), z);
        let b = mul((3.0 * c2.0, 3.0 * c2.1), z);
        div(
            (z3.0 + a.0 + cc.0, z3.1 + a.1 + cc.1),
            (3.0 * z2.0 + b.0 + cc.0 + 1.0, 3.0 * z2.1 + b.1 + cc.1),
        )
    };
    mul(q, q)
}

/// `magnet` at the points of `ps` (a normal's samples) with the orbits stepped together, as
/// `fractal2_lanes` does for z² + c; each lane the same arithmetic as `magnet` at its point.
#[inline(always)]
pub(super) fn magnet_lanes<const L: usize>(f: &Fractal, ps: [(f64, f64); L]) -> [f64; L] {
    let start = ps.map(|p| magnet_start(f, p));
    let mut z = start.map(|s| s.2);
    let mut min_abs2 = start.map(|s| s.3);
    let mut out = [0.0; L];
    let mut live = [true; L];
    for k in 0..f.iterations {
        for l in 0..L {
            z[l] = magnet_step(f.magnet, z[l], start[l].0, start[l].1);
            let (zr, zi) = z[l];
            let a2 = zr * zr + zi * zi;
            let d1 = (zr - 1.0) * (zr - 1.0) + zi * zi;
            if live[l] && (a2 > 1e4 || d1 < 1e-4) {
                out[l] = exterior_value(f, k, zr, zi, a2, min_abs2[l]);
                live[l] = false;
            }
            min_abs2[l] = min_abs2[l].min(a2);
        }
        if live.iter().all(|&x| !x) {
            return out;
        }
    }
    let (t, factor) = f.interior;
    for l in 0..L {
        if live[l] {
            out[l] = orbit_value(t, z[l].0, z[l].1, min_abs2[l]) * factor;
        }
    }
    out
}

/// Types 0 and 2 to 6 (and interior 1): what of the orbit a fractal's value reports. Type 6,
/// the manual's "absolute value", is the squared modulus inside and the modulus outside in
/// POV-Ray 3.7 (measured).
fn orbit_value(t: u8, zr: f64, zi: f64, min_abs2: f64) -> f64 {
    match t {
        1 => min_abs2.sqrt(),
        2 => zr,
        3 => zi,
        4 => zr * zr,
        5 => zi * zi,
        6 => zr * zr + zi * zi,
        _ => 1.0,
    }
}

/// zⁿ for a small integer n ≥ 2 by repeated multiplication.
fn cpow(zr: f64, zi: f64, n: u32) -> (f64, f64) {
    let (mut r, mut i) = (zr, zi);
    for _ in 1..n.max(2) {
        (r, i) = (r * zr - i * zi, r * zi + i * zr);
    }
    (r, i)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The magnet orbits stepped four at a time are each lane's own orbit to the bit.
    #[test]
    fn magnet_lanes_are_the_single_orbit() {
        for kind in [1, 2] {
            for julia in [None, Some((0.3, 0.44))] {
                for (interior, exterior) in [
                    ((1, 200.0), (5, 1.0)),
                    ((0, 1.0), (1, 1.0)),
                    ((6, 1.0), (6, 0.5)),
                ] {
                    let f = Fractal {
                        julia,
                        iterations: 50,
                        exponent: 2,
                        magnet: kind,
                        interior,
                        exterior,
                    };
                    for n in 0..300 {
                        let t = n as f64 * 0.0917;
                        let p = (2.5 * (t * 1.1).sin(), 2.0 * (t * 0.6).cos());
                        let ps = [p, (1.01, 0.02), (-0.3, 0.2), (p.1, p.0)];
                        let got = magnet_lanes(&f, ps);
                        for (g, q) in got.iter().zip(ps) {
                            assert_eq!(g.to_bits(), magnet(&f, q).to_bits(), "{q:?}");
                        }
                    }
                }
            }
        }
    }

    /// The z² + c loop is the general loop's orbit to the bit, for every interior and
    /// exterior type, mandel and julia, inside and outside the set.
    #[test]
    fn squaring_fractal_is_the_general_loop() {
        for julia in [None, Some((0.3, 0.44)), Some((-0.75, 0.11))] {
            for interior in [
                (0, 1.0),
                (1, 200.0),
                (2, 1.0),
                (3, 0.5),
                (4, 1.0),
                (5, 1.0),
                (6, 2.0),
            ] {
                for exterior in [
                    (1, 1.0),
                    (0, 1.0),
                    (2, 1.0),
                    (5, 1.0),
                    (6, 0.3),
                    (7, 5.0),
                    (8, 3.0),
                ] {
                    let f = Fractal {
                        julia,
                        iterations: 60,
                        exponent: 2,
                        magnet: 0,
                        interior,
                        exterior,
                    };
                    for n in 0..400 {
                        let t = n as f64 * 0.0731;
                        let p = (1.6 * (t * 1.3).sin() - 0.4, 1.2 * (t * 0.7).cos());
                        let (a, b) = (fractal(&f, p), fractal_n(&f, p));
                        assert_eq!(a.to_bits(), b.to_bits(), "{p:?} {interior:?} {exterior:?}");
                        // Four lanes: this point beside three others that leave at other
                        // steps (or stay in).
                        let others = [(0.25, 0.1), (-0.74, 0.12), (1.5, 1.5)];
                        for lane in 0..4 {
                            let mut ps = others.to_vec();
                            ps.insert(lane, p);
                            let ps: [(f64, f64); 4] = ps.try_into().unwrap();
                            let got = if interior.0 == 1 {
                                fractal2_lanes::<true, 4>(&f, ps)
                            } else {
                                fractal2_lanes::<false, 4>(&f, ps)
                            };
                            for (g, q) in got.iter().zip(ps) {
                                assert_eq!(g.to_bits(), fractal_n(&f, q).to_bits(), "{q:?}");
                            }
                        }
                    }
                }
            }
        }
    }
}
