//! A certificate that a ray misses a quadric without cross terms, decided before the ray's
//! direction is normalised: most rays of an unbounded scene miss most of its quadric
//! cylinders, and the certificate skips the square root, the divisions and the expansion in
//! the unit direction that [`super::Algebraic`]'s quadratic formula would run to find no root.

use crate::math::DVec3;

/// `Σ sq_i x_i² + Σ lin_i x_i + k`, the quadric's diagonal form.
#[derive(Clone, Copy, Debug)]
pub(super) struct Diagonal {
    pub sq: [f64; 3],
    pub lin: [f64; 3],
    pub k: f64,
    /// The terms in the shape's order (sums depend on it): which power (`SQ + axis`,
    /// `LIN + axis`, `CONST`) and its coefficient; `n` of them.
    pub terms: [(u8, f64); 7],
    pub n: usize,
    /// Whether the terms come in kind order (x², y², z², x, y, z, constant: a `quadric`'s
    /// order, zero coefficients left out), and then each kind's coefficient and whether the
    /// shape has it: `along` and `value` are then written out in that order, without the
    /// loop over the terms and its dispatch on their kinds.
    pub in_order: bool,
    pub coef: [f64; 7],
    pub has: [bool; 7],
}

/// Kinds of a diagonal term.
pub(super) const SQ: u8 = 0;
pub(super) const LIN: u8 = 3;
pub(super) const CONST: u8 = 6;

/// `acc[a] += c·p[a]` for the nonzero `p[a]`, as `Diagonal::along` adds an x or y term.
#[inline(always)]
fn add_nonzero<const N: usize>(acc: &mut [f64; 3], c: f64, p: [f64; N]) {
    for a in 0..N {
        let v = 0.0 + p[a];
        if v != 0.0 {
            acc[a] += c * v;
        }
    }
}

/// `acc[b] += c·p[b]` for every `p[b]`, as `Diagonal::along` adds a z term.
#[inline(always)]
fn add_all<const N: usize>(acc: &mut [f64; 3], c: f64, p: [f64; N]) {
    for b in 0..N {
        acc[b] += c * p[b];
    }
}

impl Diagonal {
    /// The diagonal form of `terms` (powers distinct, at most order 2, no cross terms).
    pub fn new(sq: [f64; 3], lin: [f64; 3], k: f64, terms: &[([u8; 3], f64)]) -> Diagonal {
        let mut d = Diagonal {
            sq,
            lin,
            k,
            terms: [(CONST, 0.0); 7],
            n: 0,
            in_order: true,
            coef: [0.0; 7],
            has: [false; 7],
        };
        for (p, c) in terms.iter().take(7) {
            let kind = match *p {
                [2, 0, 0] => SQ,
                [0, 2, 0] => SQ + 1,
                [0, 0, 2] => SQ + 2,
                [1, 0, 0] => LIN,
                [0, 1, 0] => LIN + 1,
                [0, 0, 1] => LIN + 2,
                [0, 0, 0] => CONST,
                _ => unreachable!("a cross term in a diagonal quadric"),
            };
            d.terms[d.n] = (kind, *c);
            d.n += 1;
        }
        for (k, &(kind, c)) in d.terms[..d.n].iter().enumerate() {
            d.in_order &= k == 0 || d.terms[k - 1].0 < kind;
            d.coef[kind as usize] = c;
            d.has[kind as usize] = true;
        }
        d
    }

    /// `Algebraic::along_quadric` for these terms, with the same operations in the same
    /// order left after its multiplications by the constant 1 (exact): the powers of each
    /// axis as `powers_unrolled` sums them from zero, then each term added to the
    /// coefficients in the shape's order, the x and y terms skipping zero powers as
    /// `add_term` skips a zero `xy`, the z terms and the constant not (their `xy` is 1).
    #[inline(always)]
    pub fn along(&self, o: DVec3, d: DVec3) -> [f64; 3] {
        let p1 = |o: f64, d: f64| [0.0 + o, 0.0 + d];
        let p2 = |q: [f64; 2], o: f64, d: f64| {
            [0.0 + q[0] * o, (0.0 + q[0] * d) + q[1] * o, 0.0 + q[1] * d]
        };
        let (x1, y1, z1) = (p1(o.x, d.x), p1(o.y, d.y), p1(o.z, d.z));
        let (x2, y2, z2) = (p2(x1, o.x, d.x), p2(y1, o.y, d.y), p2(z1, o.z, d.z));
        let mut acc = [0.0f64; 3];
        if self.in_order {
            // The loop below for terms in kind order: the same additions in the same order.
            let (c, has) = (&self.coef, &self.has);
            if has[0] {
                add_nonzero(&mut acc, c[0], x2);
            }
            if has[1] {
                add_nonzero(&mut acc, c[1], y2);
            }
            if has[2] {
                add_all(&mut acc, c[2], z2);
            }
            if has[3] {
                add_nonzero(&mut acc, c[3], x1);
            }
            if has[4] {
                add_nonzero(&mut acc, c[4], y1);
            }
            if has[5] {
                add_all(&mut acc, c[5], z1);
            }
            if has[6] {
                acc[0] += c[6];
            }
            return acc;
        }
        for &(kind, c) in &self.terms[..self.n] {
            match kind {
                0 => add_nonzero(&mut acc, c, x2),
                1 => add_nonzero(&mut acc, c, y2),
                2 => add_all(&mut acc, c, z2),
                3 => add_nonzero(&mut acc, c, x1),
                4 => add_nonzero(&mut acc, c, y1),
                5 => add_all(&mut acc, c, z1),
                _ => acc[0] += c,
            }
        }
        acc
    }

    /// `Algebraic::value` for these terms: each term `c·x^i·y^j·z^k` with powers from
    /// `powi_table` (1, v, v·v) is `c` times its one power (the products by 1 are exact),
    /// summed in the shape's order by the same `sum`.
    #[inline(always)]
    pub fn value(&self, p: DVec3) -> f64 {
        let sq = [p.x * p.x, p.y * p.y, p.z * p.z];
        let lin = [p.x, p.y, p.z];
        if self.in_order {
            // The sum below for terms in kind order, from the same neutral element (`sum`'s
            // own, whose sign decides a lone term's zero).
            let (c, has) = (&self.coef, &self.has);
            let mut s: f64 = std::iter::empty::<f64>().sum();
            for (k, v) in [sq[0], sq[1], sq[2], lin[0], lin[1], lin[2]]
                .into_iter()
                .enumerate()
            {
                if has[k] {
                    s += c[k] * v;
                }
            }
            if has[6] {
                s += c[6];
            }
            return s;
        }
        self.terms[..self.n]
            .iter()
            .map(|&(kind, c)| match kind {
                0..=2 => c * sq[kind as usize],
                3..=5 => c * lin[kind as usize - 3],
                _ => c,
            })
            .sum()
    }

    /// Whether the quadratic along `origin + t·dir` surely has a negative discriminant as
    /// `low_roots_in` computes it from the polynomial in the unit direction (so it finds no
    /// root, and the quadric no crossing).
    ///
    /// Why a margin of 1e-12 of `T = m1² + 4·m2·m0` is safe: `m2`, `m1`, `m0` bound the sums
    /// of the coefficients' terms in absolute value along `dir`, and scale by `1/|dir|²`,
    /// `1/|dir|`, 1 in the unit direction. Every rounding that separates the discriminant
    /// computed there from `|dir|⁻²` times the exact discriminant along `dir` (the unit
    /// direction's components, each within a few units in the last place of `dir/|dir|`; the
    /// expansion's products and sums; `b² − 4ac`) is at most a few dozen units in the last
    /// place (2^-53) of `T/|dir|²`, and so is the rounding of the sums here: under 1e-14 of
    /// `T` together, far below the margin. The scales are bounded so that nothing overflows
    /// and underflow's absolute errors are negligible beside the margin. NaN or infinite
    /// input fails the comparisons and certifies nothing.
    #[inline(always)]
    pub fn surely_misses(&self, origin: DVec3, dir: DVec3) -> bool {
        let ([a0, a1, a2], [l0, l1, l2]) = (self.sq, self.lin);
        let (ax, ay, az) = (a0 * origin.x, a1 * origin.y, a2 * origin.z);
        let c2 = a0 * dir.x * dir.x + a1 * dir.y * dir.y + a2 * dir.z * dir.z;
        let c1 = (2.0 * ax + l0) * dir.x + (2.0 * ay + l1) * dir.y + (2.0 * az + l2) * dir.z;
        let c0 = (ax + l0) * origin.x + (ay + l1) * origin.y + (az + l2) * origin.z + self.k;
        let disc = c1 * c1 - 4.0 * c2 * c0;
        // Most quadric tests that fail here are hits: the bounds only when it can pass (NaN
        // fails too).
        disc < 0.0 && {
            let (ax, ay, az) = (ax.abs(), ay.abs(), az.abs());
            let (l0, l1, l2) = (l0.abs(), l1.abs(), l2.abs());
            let (o, d) = (origin.abs(), dir.abs());
            let m2 = a0.abs() * d.x * d.x + a1.abs() * d.y * d.y + a2.abs() * d.z * d.z;
            let m1 = (2.0 * ax + l0) * d.x + (2.0 * ay + l1) * d.y + (2.0 * az + l2) * d.z;
            let m0 = (ax + l0) * o.x + (ay + l1) * o.y + (az + l2) * o.z + self.k.abs();
            let scale = m1 * m1 + 4.0 * m2 * m0;
            let len2 = dir.length_squared();
            disc < -1e-12 * scale && scale > 1e-150 && scale < 1e150 && len2 > 1e-50 && len2 < 1e50
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::Algebraic;
    use crate::math::{DVec3, Ray};

    /// The diagonal form's expansion along a ray and its value equal the general ones bit
    /// for bit: terms in every order, coefficients and coordinates with zeros of both signs,
    /// tiny, huge, infinite and NaN values.
    #[test]
    fn diagonal_along_and_value_match_the_general_ones() {
        let mut rnd = crate::math::xorshift_unit(0x9e37_79b9_7f4a_7c15u64);
        let special = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            0.5,
            1e-300,
            -1e300,
            f64::INFINITY,
            f64::NAN,
        ];
        let mut pick = move || -> f64 {
            if rnd() < 0.3 {
                special[(rnd() * special.len() as f64) as usize % special.len()]
            } else {
                (rnd() - 0.5) * 10f64.powi((rnd() * 12.0) as i32 - 6)
            }
        };
        let powers: [[u8; 3]; 7] = [
            [2, 0, 0],
            [0, 2, 0],
            [0, 0, 2],
            [1, 0, 0],
            [0, 1, 0],
            [0, 0, 1],
            [0, 0, 0],
        ];
        let same = |a: f64, b: f64| a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan());
        let (mut checked, mut in_order) = (0, 0);
        for case in 0..200_000usize {
            // A random subset of the powers in a random order, with random coefficients.
            let mut terms: Vec<([u8; 3], f64)> = powers.iter().map(|p| (*p, 0.0)).collect();
            for i in (1..terms.len()).rev() {
                let j = (pick().abs() * 1e6) as usize % (i + 1);
                terms.swap(i, j);
            }
            terms.truncate(1 + case % 7);
            if case % 3 == 0 {
                // A `quadric`'s order (kind order), which takes the written-out sums.
                terms.sort_by_key(|t| powers.iter().position(|p| *p == t.0));
            }
            for t in terms.iter_mut() {
                t.1 = pick();
            }
            let q = Algebraic::new(2, &terms, false);
            let Some(diag) = q.diagonal else {
                continue;
            };
            let o = DVec3::new(pick(), pick(), pick());
            let d = DVec3::new(pick(), pick(), pick());
            let (a, b) = (diag.along(o, d), q.along_quadric(o, d));
            for k in 0..3 {
                assert!(same(a[k], b[k]), "{terms:?} {o:?} {d:?}: {a:?} {b:?}");
            }
            assert!(same(diag.value(o), q.value_n::<3>(o)), "{terms:?} {o:?}");
            checked += 1;
            in_order += diag.in_order as usize;
        }
        assert!(checked > 100_000, "{checked}");
        assert!(
            in_order > 60_000 && in_order < checked - 60_000,
            "{in_order}"
        );
    }

    /// Where the certificate holds, the quadratic formula in the unit direction finds no
    /// root, for quadrics of shapes.inc's kinds at many scales and rays grazing them.
    #[test]
    fn certified_misses_have_no_root() {
        let mut rnd = crate::math::xorshift_unit(0x2545_f491_4f6c_dd1du64);
        let (mut certified, mut total) = (0, 0);
        for case in 0..40_000 {
            let pick = |r: f64| [-1.0, 0.0, 1.0, 0.5, -3.0][(r * 5.0) as usize];
            let scale = 10f64.powi((rnd() * 8.0) as i32 - 4);
            let sq = [pick(rnd()), pick(rnd()), pick(rnd())];
            let lin = [pick(rnd()) * (rnd() < 0.3) as u8 as f64, 0.0, pick(rnd())];
            let k = pick(rnd()) * scale;
            let mut terms = vec![];
            for (i, p) in [[2, 0, 0], [0, 2, 0], [0, 0, 2]].into_iter().enumerate() {
                terms.push((p, sq[i]));
            }
            for (i, p) in [[1, 0, 0], [0, 1, 0], [0, 0, 1]].into_iter().enumerate() {
                terms.push((p, lin[i]));
            }
            terms.push(([0, 0, 0], k));
            let q = Algebraic::new(2, &terms, false);
            let Some(diag) = q.diagonal else {
                continue;
            };
            let mut v = |s: f64| DVec3::new(rnd() - 0.5, rnd() - 0.5, rnd() - 0.5) * s;
            let mut origin = v(20.0 * scale.sqrt());
            let dir_scale = 10f64.powi((case % 7) - 3);
            let mut dir = v(dir_scale);
            let r = v(1.0).x + 0.5;
            if case % 2 == 0 {
                // Grazing: a direction nearly perpendicular to the gradient at the origin,
                // moved onto the surface along the gradient's line when it can be.
                let g = DVec3::new(
                    2.0 * sq[0] * origin.x + lin[0],
                    2.0 * sq[1] * origin.y + lin[1],
                    2.0 * sq[2] * origin.z + lin[2],
                );
                if g.length_squared() > 0.0 {
                    dir = dir - g * (dir.dot(g) / g.length_squared()) * (1.0 - 1e-9 * r);
                    origin += g * (-q.value(origin) / g.length_squared());
                }
            }
            total += 1;
            let ray = Ray::new(origin, dir);
            if diag.surely_misses(ray.origin, ray.dir) {
                certified += 1;
                assert!(
                    q.low_order_solved(&ray).is_none_or(|(_, n, _)| n == 0),
                    "certified {sq:?} {lin:?} {k} {origin:?} {dir:?}"
                );
                // The discriminant itself is negative, whatever the interval.
                let len = dir.length();
                let c = q.along_quadric(origin, dir / len);
                assert!(c[1] * c[1] - 4.0 * c[2] * c[0] < 0.0);
            }
        }
        assert!(certified > total / 10, "{certified} of {total}");
    }
}
