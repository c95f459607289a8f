//! Escape-time fractal patterns (`mandel`, `julia`, `magnet`): the orbit loops, the z² + c
//! loop and the orbits stepped several at a time for a normal's samples (the same bits per
//! lane as one orbit alone), and the interior and exterior value types.

use crate::scene::pattern::Fractal;

mod ahead;
#[cfg(target_arch = "x86_64")]
mod magnet_avx;

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
        (2, 1) => ahead::fractal2_ahead::<true>(f, p),
        (2, _) => ahead::fractal2_ahead::<false>(f, p),
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
/// the orbit's smallest |z|² (interior type 1 alone reads it). `fractal` asks it through
/// `ahead`, which steps the same orbit beside the ones the next calls are likely to ask.
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

/// `fractal2_lanes` at four points, with AVX where the CPU has it (as `magnet_lanes4`).
pub(super) fn fractal2_lanes4<const MIN: bool>(f: &Fractal, ps: [(f64, f64); 4]) -> [f64; 4] {
    #[cfg(target_arch = "x86_64")]
    if crate::math::has_avx() {
        // SAFETY: the CPU has AVX (checked just above).
        return unsafe { fractal2_4_avx::<MIN>(f, ps) };
    }
    fractal2_lanes::<MIN, 4>(f, ps)
}

/// `fractal2_lanes` for four lanes with AVX: `ahead`'s steps written with intrinsics, run
/// until each lane has left or reached `iterations`. Left to the vectoriser, the lane
/// arrays' code changed width with how the crate was split into codegen units (textures/
/// patterns/fractals2 5 % slower after an unrelated change); the intrinsics fix it. The same
/// IEEE operations lane by lane in the same order (nothing fused), so the same bits as the
/// SSE2 build.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
unsafe fn fractal2_4_avx<const MIN: bool>(f: &Fractal, ps: [(f64, f64); 4]) -> [f64; 4] {
    let c = ps.map(|p| f.julia.unwrap_or(p));
    let (cr, ci) = (Lanes(c.map(|c| c.0)), Lanes(c.map(|c| c.1)));
    let (zr, zi) = (Lanes(ps.map(|p| p.0)), Lanes(ps.map(|p| p.1)));
    let (rr, ii) = (zr * zr, zi * zi);
    let min_abs2 = rr + ii;
    let mut s = ahead::State {
        zr,
        zi,
        rr,
        ii,
        min_abs2,
    };
    let n = f.iterations;
    let mut out = [0.0; 4];
    let mut ended = 0u32;
    let mut done = 0;
    while done < n {
        let (m, new, a2) = ahead::steps_avx::<MIN>(&mut s, (cr, ci), !ended & 0b1111, n - done);
        done += m;
        if new != 0 {
            for l in (0..4).filter(|&l| new >> l & 1 != 0) {
                let (zr, zi, min) = (s.zr.0[l], s.zi.0[l], s.min_abs2.0[l]);
                out[l] = exterior_value(f, done - 1, zr, zi, a2.0[l], min);
            }
            ended |= new;
            if ended == 0b1111 {
                return out;
            }
            if MIN {
                s.min_abs2 = s.min_abs2.zip(a2, f64::min);
            }
        }
    }
    let (t, factor) = f.interior;
    for l in (0..4).filter(|&l| ended >> l & 1 == 0) {
        out[l] = orbit_value(t, s.zr.0[l], s.zi.0[l], s.min_abs2.0[l]) * factor;
    }
    out
}

/// A z² + c fractal's value at the points of `ps` (a normal's samples), each lane the same
/// arithmetic as `fractal2` at its point. One orbit is bound by the latency of its steps;
/// L orbits stepped together overlap. The step has no branch inside (a lane's leaving is a
/// mask, its value taken after the step), so the lanes stay in vector registers. Lanes that
/// have left go on stepping (their values are kept from the step they left and what they
/// compute after is never read).
#[inline(always)]
fn fractal2_lanes<const MIN: bool, const L: usize>(f: &Fractal, ps: [(f64, f64); L]) -> [f64; L] {
    let c = ps.map(|p| f.julia.unwrap_or(p));
    let (cr, ci) = (Lanes(c.map(|c| c.0)), Lanes(c.map(|c| c.1)));
    let (mut zr, mut zi) = (Lanes(ps.map(|p| p.0)), Lanes(ps.map(|p| p.1)));
    let (mut rr, mut ii) = (zr * zr, zi * zi);
    let mut min_abs2 = rr + ii;
    let mut out = [0.0; L];
    let all = (1u32 << L) - 1;
    let mut ended = 0u32;
    for k in 0..f.iterations {
        let ri = zr * zi;
        zr = (rr - ii) + cr;
        zi = (ri + ri) + ci;
        rr = zr * zr;
        ii = zi * zi;
        let a2 = rr + ii;
        let new = a2.mask(|x| x > 4.0) & !ended;
        if new != 0 {
            for l in (0..L).filter(|&l| new >> l & 1 != 0) {
                out[l] = exterior_value(f, k, zr.0[l], zi.0[l], a2.0[l], min_abs2.0[l]);
            }
            ended |= new;
            if ended == all {
                return out;
            }
        }
        if MIN {
            min_abs2 = min_abs2.zip(a2, f64::min);
        }
    }
    let (t, factor) = f.interior;
    for l in (0..L).filter(|&l| ended >> l & 1 == 0) {
        out[l] = orbit_value(t, zr.0[l], zi.0[l], min_abs2.0[l]) * factor;
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
        // Kept as two scalars: the vectoriser packed z's parts into one register, with
        // shuffles (haddpd, addsubpd, unpck) on the orbit's chain.
        z = (crate::math::opaque(z.0), crate::math::opaque(z.1));
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

/// One step of magnet `kind` (1 or 2) from z, with c1 = c − 1 and c2 = c − 2: for one orbit
/// (`f64`) or a lane per orbit (`Lanes`), the same operations in the same order.
#[inline(always)]
fn magnet_step<T: Num>(kind: u8, z: (T, T), c1: (T, T), c2: (T, T)) -> (T, T) {
    let mul = |a: (T, T), b: (T, T)| (a.0 * b.0 - a.1 * b.1, a.0 * b.1 + a.1 * b.0);
    let div = |a: (T, T), b: (T, T)| {
        let d = b.0 * b.0 + b.1 * b.1;
        ((a.0 * b.0 + a.1 * b.1) / d, (a.1 * b.0 - a.0 * b.1) / d)
    };
    let (two, three) = (T::splat(2.0), T::splat(3.0));
    let q = if kind == 1 {
        let num = mul(z, z);
        div(
            (num.0 + c1.0, num.1 + c1.1),
            (two * z.0 + c2.0, two * z.1 + c2.1),
        )
    } else {
        let z2 = mul(z, z);
        let z3 = mul(z2, z);
        let cc = mul(c1, c2);
        let a = mul((three * c1.0, three * c1.1), z);
        let b = mul((three * c2.0, three * c2.1), z);
        div(
            (z3.0 + a.0 + cc.0, z3.1 + a.1 + cc.1),
            (
                three * z2.0 + b.0 + cc.0 + T::splat(1.0),
                three * z2.1 + b.1 + cc.1,
            ),
        )
    };
    mul(q, q)
}

/// The arithmetic a fractal step needs, for one orbit (`f64`) or several (`Lanes`).
trait Num:
    Copy
    + std::ops::Add<Output = Self>
    + std::ops::Sub<Output = Self>
    + std::ops::Mul<Output = Self>
    + std::ops::Div<Output = Self>
{
    fn splat(x: f64) -> Self;
}

impl Num for f64 {
    #[inline(always)]
    fn splat(x: f64) -> f64 {
        x
    }
}

/// One number per orbit. Every operation is lane by lane on the whole array, so the
/// compiler keeps the L orbits in one vector register each (a 256-bit one for four lanes
/// with AVX) instead of vectorising within one orbit's complex pairs, which it did with the
/// orbits written lane after lane (385 instructions per four-lane magnet step, measured).
/// (geom::julia_pair has the same kind of lanes for the quaternion orbits.)
#[derive(Clone, Copy)]
struct Lanes<const L: usize>([f64; L]);

impl<const L: usize> Lanes<L> {
    #[inline(always)]
    fn zip(self, o: Self, f: impl Fn(f64, f64) -> f64) -> Self {
        Lanes(std::array::from_fn(|i| f(self.0[i], o.0[i])))
    }

    /// Lane bits (bit l for lane l) of `f` over the lanes.
    #[inline(always)]
    fn mask(self, f: impl Fn(f64) -> bool) -> u32 {
        (0..L).fold(0, |m, i| m | u32::from(f(self.0[i])) << i)
    }
}

impl<const L: usize> Num for Lanes<L> {
    #[inline(always)]
    fn splat(x: f64) -> Self {
        Lanes([x; L])
    }
}

impl<const L: usize> std::ops::Add for Lanes<L> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        self.zip(o, |a, b| a + b)
    }
}

impl<const L: usize> std::ops::Sub for Lanes<L> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        self.zip(o, |a, b| a - b)
    }
}

impl<const L: usize> std::ops::Mul for Lanes<L> {
    type Output = Self;
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        self.zip(o, |a, b| a * b)
    }
}

impl<const L: usize> std::ops::Div for Lanes<L> {
    type Output = Self;
    #[inline(always)]
    fn div(self, o: Self) -> Self {
        self.zip(o, |a, b| a / b)
    }
}

/// `magnet` at the points of `ps` (a normal's samples) with the orbits stepped together, as
/// `fractal2_lanes` does for z² + c; each lane the same arithmetic as `magnet` at its point.
/// Four lanes run with AVX where the CPU has it (`magnet_avx`, written with intrinsics).
pub(super) fn magnet_lanes4(f: &Fractal, ps: [(f64, f64); 4]) -> [f64; 4] {
    #[cfg(target_arch = "x86_64")]
    if crate::math::has_avx() {
        // SAFETY: the CPU has AVX (checked just above).
        return unsafe { magnet_avx::magnet4_avx(f, ps) };
    }
    magnet_lanes(f, ps)
}

/// `magnet` at the points of `ps`, the orbits stepped together. Each step is `Lanes`
/// arithmetic with no branch inside (whether a lane ends is a mask, its rare value taken
/// after the step), so the L orbits stay in vector registers: one magnet step is two
/// divisions and a dozen products on a dependent chain, and L chains overlap. Lanes that
/// have ended go on stepping unread (they may overflow, harmlessly).
#[inline(always)]
fn magnet_lanes<const L: usize>(f: &Fractal, ps: [(f64, f64); L]) -> [f64; L] {
    if f.magnet == 1 {
        magnet_lanes_k::<1, L>(f, ps)
    } else {
        magnet_lanes_k::<2, L>(f, ps)
    }
}

/// `magnet_lanes` for magnet `KIND`.
#[inline(always)]
fn magnet_lanes_k<const KIND: u8, const L: usize>(f: &Fractal, ps: [(f64, f64); L]) -> [f64; L] {
    let start = ps.map(|p| magnet_start(f, p));
    let c1 = (Lanes(start.map(|s| s.0 .0)), Lanes(start.map(|s| s.0 .1)));
    let c2 = (Lanes(start.map(|s| s.1 .0)), Lanes(start.map(|s| s.1 .1)));
    let mut z = (Lanes(start.map(|s| s.2 .0)), Lanes(start.map(|s| s.2 .1)));
    let mut min_abs2 = Lanes(start.map(|s| s.3));
    let mut out = [0.0; L];
    let all = (1u32 << L) - 1;
    let mut ended = 0u32;
    let one = Lanes::splat(1.0);
    for k in 0..f.iterations {
        z = magnet_step(KIND, z, c1, c2);
        let a2 = z.0 * z.0 + z.1 * z.1;
        let d1 = (z.0 - one) * (z.0 - one) + z.1 * z.1;
        let ends = a2.mask(|x| x > 1e4) | d1.mask(|x| x < 1e-4);
        let new = ends & !ended;
        if new != 0 {
            for l in (0..L).filter(|&l| new >> l & 1 != 0) {
                out[l] = exterior_value(f, k, z.0 .0[l], z.1 .0[l], a2.0[l], min_abs2.0[l]);
            }
            ended |= new;
            if ended == all {
                return out;
            }
        }
        min_abs2 = min_abs2.zip(a2, f64::min);
    }
    let (t, factor) = f.interior;
    for l in (0..L).filter(|&l| ended >> l & 1 == 0) {
        out[l] = orbit_value(t, z.0 .0[l], z.1 .0[l], min_abs2.0[l]) * factor;
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
                        let got4 = magnet_lanes4(&f, ps);
                        for ((g, g4), q) in got.iter().zip(got4).zip(ps) {
                            assert_eq!(g.to_bits(), magnet(&f, q).to_bits(), "{q:?}");
                            assert_eq!(g4.to_bits(), magnet(&f, q).to_bits(), "{q:?}");
                        }
                    }
                }
            }
        }
    }

    /// Edge points in the AVX lanes: zero denominators (0/0 and x/0 orbits that never end),
    /// NaN and infinite points, signed zeros, the fixed point 1 and far points; each lane
    /// beside every other, for both kinds, mandel and julia (whose smallest |z|² starts NaN
    /// at a NaN point). A NaN's sign follows the compiler's operand order for commutative
    /// operations, not IEEE's rules (the lanes written as `Lanes` arrays differ there from
    /// the one orbit too), so any NaN matches any NaN.
    #[test]
    fn magnet_lanes_at_edge_points() {
        let edges = [
            (2.0, 0.0),
            (1.0, 0.0),
            (0.0, 0.0),
            (-0.0, -0.0),
            (f64::NAN, 0.5),
            (0.5, f64::NAN),
            (f64::INFINITY, 0.0),
            (f64::NEG_INFINITY, f64::INFINITY),
            (1e300, -1e300),
            (1e-300, 1.0 + 1e-12),
            (0.5, 0.0),
            (-1.0, 1.0),
        ];
        for kind in [1, 2] {
            for julia in [
                None,
                Some((0.3, 0.44)),
                Some((2.0, 0.0)),
                Some((f64::NAN, 0.0)),
            ] {
                for (interior, exterior) in [((1, 200.0), (5, 1.0)), ((6, 1.0), (6, 0.5))] {
                    let f = Fractal {
                        julia,
                        iterations: 30,
                        exponent: 2,
                        magnet: kind,
                        interior,
                        exterior,
                    };
                    for (i, &a) in edges.iter().enumerate() {
                        for &b in &edges[i..] {
                            let ps = [a, b, (b.1, a.0), (0.3, 0.2)];
                            for (g, q) in magnet_lanes4(&f, ps).iter().zip(ps) {
                                let want = magnet(&f, q);
                                let nans = g.is_nan() && want.is_nan();
                                assert!(nans || g.to_bits() == want.to_bits(), "{q:?}");
                            }
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
                            let (got, got4) = if interior.0 == 1 {
                                (
                                    fractal2_lanes::<true, 4>(&f, ps),
                                    fractal2_lanes4::<true>(&f, ps),
                                )
                            } else {
                                (
                                    fractal2_lanes::<false, 4>(&f, ps),
                                    fractal2_lanes4::<false>(&f, ps),
                                )
                            };
                            for ((g, g4), q) in got.iter().zip(got4).zip(ps) {
                                assert_eq!(g.to_bits(), fractal_n(&f, q).to_bits(), "{q:?}");
                                assert_eq!(g4.to_bits(), fractal_n(&f, q).to_bits(), "{q:?}");
                            }
                        }
                    }
                }
            }
        }
    }
}
