//! POV-Ray `superellipsoid { <e, n> }`: the points where
//! `(|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1`, inside the box from -1 to 1.
//!
//! The field is no polynomial, so crossings are found numerically: the ray's stretch inside the
//! box is cut where it meets the planes the field is not smooth across (x = 0, y = 0, z = 0) and
//! the symmetry planes between the axes (x = ±y, x = ±z, y = ±z), each piece is sampled a few
//! times for changes of sign, and each change is narrowed down to a root by regula falsi kept
//! honest by bisection. Within such a piece the field varies slowly enough that two crossings
//! closer than a sample step only happen where the ray grazes the surface.
//!
//! Small exponents make powers of numbers below one underflow and above one overflow; the
//! field is therefore evaluated as `m^(2/n) · (1 + (min/max)^(2/e))^(e/n)` with `m` the larger
//! of |x| and |y|, and the gradient in logarithms.

mod intpow;
mod linear;
mod near;

use crate::geom::{Hit, Shape};
use crate::math::{Aabb, DVec3, Ray, EPSILON};
use intpow::IntPow;
use linear::LinConsts;
use near::Series;

/// Widening of the box searched, so a crossing on the box's faces (e or n near zero) is kept.
const MARGIN: f64 = 1e-6;
/// Samples per piece between breakpoints.
const SAMPLES: usize = 4;

/// Table steps on [0, 1] for the bounds of the samples' powers (a power of two, so that
/// `x * STEPS` and its floor are exact). 512 rather than 128: a sample the tables leave
/// undecided costs two to four `pow` calls, and with large exponents (|z|^20 for n = 0.1)
/// one step of 128 near 1 spans a seventh of the field. The tables cost ~1,500 powers per
/// shape; 1024 steps decided a little more and cost more than they saved (superel2).
const STEPS: usize = 512;

#[derive(Clone, Debug)]
pub struct Superellipsoid {
    /// 2/e, the exponent of |x| and |y|.
    a: Power,
    /// e/n, the exponent of their sum.
    b: Power,
    /// 2/n, the exponent of |z|.
    c: Power,
    /// 2^(e/n): the largest `(1 + r^a)^b` can be (r <= 1), for `sign`.
    top: f64,
    /// `x^c` at `x = i / STEPS`: with `x^c` increasing, the two entries around `x` bound it.
    pow_c: [f64; STEPS + 1],
    /// `(1 + r^a)^b` at `r = i / STEPS`, increasing in `r` like `pow_c`.
    pow_ab: [f64; STEPS + 1],
    /// The binomial series of `a`, `b` and `c`, for values near a known one (`near`).
    sa: Series,
    sb: Series,
    sc: Series,
    /// The first-order model's bound constants (`linear`).
    lin: LinConsts,
}

/// A fixed exponent. `powf` with exponent 1, 2 or 1/2 gives exactly `x`, `x * x` and
/// `x.sqrt()` (the correctly rounded results; unit test `special_powers_are_exact`), at a
/// fraction of the cost: these exponents come from round shapes' `e` or `n` of 1 or 2.
/// Other whole and half-whole exponents have their own form with the same bits (`intpow`).
#[derive(Clone, Copy, Debug)]
enum Power {
    One,
    Two,
    Half,
    Whole(IntPow),
    Other(f64),
}

impl Power {
    fn new(k: f64) -> Power {
        if k == 1.0 {
            Power::One
        } else if k == 2.0 {
            Power::Two
        } else if k == 0.5 {
            Power::Half
        } else if let Some(p) = IntPow::new(k) {
            Power::Whole(p)
        } else {
            Power::Other(k)
        }
    }

    /// `x.powf(k)` to the bit, for `x >= 0` (the field's arguments are absolute values).
    #[inline]
    fn of(self, x: f64) -> f64 {
        match self {
            Power::One => x,
            Power::Two => x * x,
            Power::Half => x.sqrt(),
            Power::Whole(p) => p.of(x),
            Power::Other(k) => x.powf(k),
        }
    }

    fn exponent(self) -> f64 {
        match self {
            Power::One => 1.0,
            Power::Two => 2.0,
            Power::Half => 0.5,
            Power::Whole(p) => p.exponent(),
            Power::Other(k) => k,
        }
    }
}

/// The two table entries around `x` in `[0, 1]` (None outside, or NaN).
#[inline]
fn around(table: &[f64; STEPS + 1], x: f64) -> Option<(f64, f64)> {
    if x > 1.0 || x.is_nan() {
        return None;
    }
    // SAFETY: `x` is an absolute value or a ratio of them (not negative), not NaN and at most
    // 1 here, so `x * STEPS` is in [0, STEPS] and its truncation fits a u32. (The checked
    // float-to-usize cast was a tenth of the samples' cost.)
    let i = unsafe { (x * STEPS as f64).to_int_unchecked::<u32>() } as usize;
    let i = i.min(STEPS - 1);
    Some((table[i], table[i + 1]))
}

/// A point's field value, or only its sign when that is certain without the whole value.
/// A struct of a float and a flag, not an enum: `crossings` copies the last sample's `Field`
/// each step, and the enum's copy went through odd stack offsets whose 8-byte reload of the
/// value could not be forwarded from the stores (a stall on every sample).
#[derive(Clone, Copy)]
struct Field {
    /// The value when `exact`; otherwise -1 or 1, carrying only the sign.
    v: f64,
    exact: bool,
}

impl Field {
    #[inline(always)]
    fn value(v: f64) -> Field {
        Field { v, exact: true }
    }

    #[inline(always)]
    fn sign(negative: bool) -> Field {
        Field {
            v: if negative { -1.0 } else { 1.0 },
            exact: false,
        }
    }

    /// `v < 0.0` for a value (false for NaN, as before), the sign otherwise.
    #[inline(always)]
    fn negative(self) -> bool {
        self.v < 0.0
    }
}

impl Superellipsoid {
    /// Exponents must be positive and finite; callers clamp (the parser warns).
    pub fn new(e: f64, n: f64) -> Superellipsoid {
        let (a, b, c) = (Power::new(2.0 / e), Power::new(e / n), Power::new(2.0 / n));
        let at = |i: usize| i as f64 / STEPS as f64;
        Superellipsoid {
            a,
            b,
            c,
            top: 2f64.powf(e / n),
            pow_c: std::array::from_fn(|i| c.of(at(i))),
            pow_ab: std::array::from_fn(|i| b.of(1.0 + a.of(at(i)))),
            sa: Series::new(a.exponent()),
            sb: Series::new(b.exponent()),
            sc: Series::new(c.exponent()),
            lin: LinConsts::new(a.exponent(), b.exponent(), c.exponent()),
        }
    }

    /// Negative inside, zero on the surface.
    pub fn value(&self, p: DVec3) -> f64 {
        let (x, y, z) = (p.x.abs(), p.y.abs(), p.z.abs());
        let m = x.max(y);
        let xy = if m > 0.0 {
            let r = x.min(y) / m;
            self.c.of(m) * self.b.of(1.0 + self.a.of(r))
        } else {
            0.0
        };
        xy + self.c.of(z) - 1.0
    }

    /// `value`, or its sign alone when the two powers of `m` and `|z|` settle it: the field
    /// is `m^c·(1 + r^a)^b + |z|^c − 1` with `1 <= (1 + r^a)^b <= 2^b`, so far enough from
    /// the surface the two other powers are not needed. When they are, the value is finished
    /// from the same powers, so it is `value`'s to the bit.
    ///
    /// Inlined into the sample loop (most samples end at the box test or the tables, ~40
    /// instructions, which the call's overhead grew by a third); the powers are `field_powers`.
    #[inline(always)]
    fn field(&self, p: DVec3) -> Field {
        let (x, y, z) = (p.x.abs(), p.y.abs(), p.z.abs());
        let m = x.max(y);
        // Outside the unit box (the samples at the ray's entry into the searched box and at
        // its exit lie on its faces, 1 + MARGIN out): `value` is not negative, without a
        // power. With m > 1 (or |z| > 1) and an exponent k > 0, m^k is above 1, so its
        // faithfully rounded power (glibc's, as `Power::of` and `near` assume) is at least 1,
        // as are the other factor `(1 + r^a)^b` and their rounded product; the sum with the
        // other, non-negative power is then at least 1, and less 1 at least 0. NaN compares
        // false here and goes on as before. The tables (`around`) leave such points to the
        // exact powers, two `pow` calls each.
        if m > 1.0 || z > 1.0 {
            return Field::sign(false);
        }
        if m <= 0.0 || m.is_nan() {
            return self.field_powers(p, m, 0.0);
        }
        let r = x.min(y) / m;
        // Bounds from the tables first (no power at all): the field is increasing in `m`, `r`
        // and `|z|`, and the margins are far above the tables' and these sums' rounding.
        if let (Some((mc0, mc1)), Some((g0, g1)), Some((zc0, zc1))) = (
            around(&self.pow_c, m),
            around(&self.pow_ab, r),
            around(&self.pow_c, z),
        ) {
            if mc0 * g0 + zc0 > 1.0 + 1e-9 {
                return Field::sign(false);
            }
            if mc1 * g1 + zc1 < 1.0 - 1e-9 {
                return Field::sign(true);
            }
        }
        self.field_powers(p, m, r)
    }

    /// `field`'s end where the tables do not settle the sign: `m` is max(|x|, |y|) and `r`
    /// min/max (not read when `m` is not positive, where `value` decides).
    #[inline(never)]
    fn field_powers(&self, p: DVec3, m: f64, r: f64) -> Field {
        if m <= 0.0 || m.is_nan() {
            return Field::value(self.value(p));
        }
        let z = p.z.abs();
        let (mc, zc) = (self.c.of(m), self.c.of(z));
        // Margins far above the rounding of these few operations.
        if mc + zc > 1.0 + 1e-9 {
            return Field::sign(false);
        }
        if mc * self.top + zc < 1.0 - 1e-9 {
            return Field::sign(true);
        }
        let xy = mc * self.b.of(1.0 + self.a.of(r));
        Field::value(xy + zc - 1.0)
    }

    /// Crossings as distances along the unit direction `u` from `o`, within `[0, hi]`,
    /// increasing. Each change of sign between samples `s0 < s1` is first put to `bracket`
    /// (the root lies in `[s0, s1]`): refined, passed over, or the end of the search with
    /// its answer; the search also stops after the first root `last` accepts.
    fn crossings(
        &self,
        o: DVec3,
        u: DVec3,
        hi: f64,
        out: &mut impl FnMut(f64),
        mut bracket: impl FnMut(f64, f64) -> Bracket,
        last: impl Fn(f64) -> bool,
    ) -> Option<bool> {
        let lo = 0.0;
        // Breakpoints: where the ray meets each plane n·p = 0.
        const PLANES: [[f64; 3]; 9] = [
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
            [1.0, 1.0, 0.0],
            [1.0, -1.0, 0.0],
            [1.0, 0.0, 1.0],
            [1.0, 0.0, -1.0],
            [0.0, 1.0, 1.0],
            [0.0, 1.0, -1.0],
        ];
        let mut cuts = [0.0f64; PLANES.len() + 2];
        let mut nc = 0;
        cuts[nc] = lo;
        nc += 1;
        for pl in PLANES {
            let nv = DVec3::from_array(pl);
            let den = nv.dot(u);
            if den != 0.0 {
                let s = -nv.dot(o) / den;
                if s > lo && s < hi {
                    cuts[nc] = s;
                    nc += 1;
                }
            }
        }
        cuts[nc] = hi;
        nc += 1;
        let cuts = &mut cuts[..nc];
        cuts.sort_by(f64::total_cmp);

        let f = |s: f64| self.value(o + u * s);
        // Samples need only their sign; the two ends of a change of sign get their values
        // (as `value` gives them) for the refinement.
        let exact = |s: f64, v: Field| if v.exact { v.v } else { f(s) };
        let (mut s0, mut f0) = (lo, self.field(o + u * lo));
        for w in cuts.windows(2) {
            let (a, b) = (w[0], w[1]);
            if b <= a {
                continue;
            }
            for k in 1..=SAMPLES {
                let s1 = if k == SAMPLES {
                    b
                } else {
                    a + (b - a) * k as f64 / SAMPLES as f64
                };
                let mut f1 = self.field(o + u * s1);
                if f0.negative() != f1.negative() {
                    match bracket(s0, s1) {
                        Bracket::Refine => {
                            let (v0, v1) = (exact(s0, f0), exact(s1, f1));
                            let root = near::refine(self, o, u, s0, v0, s1, v1);
                            out(root);
                            if last(root) {
                                return None;
                            }
                            f1 = Field::value(v1);
                        }
                        Bracket::Pass => {}
                        Bracket::Answer(hit) => return Some(hit),
                    }
                }
                (s0, f0) = (s1, f1);
            }
        }
        None
    }
}

/// What `crossings` does with a change of sign.
enum Bracket {
    /// Refine the root.
    Refine,
    /// Go on without it (its root cannot count).
    Pass,
    /// Stop the search: whether a crossing counting as a hit is there is already known.
    Answer(bool),
}

/// Which crossings `hits` is asked for.
#[derive(Clone, Copy)]
enum Want {
    All,
    /// The nearest with `EPSILON < t < tmax`.
    First(f64),
    /// Only whether there is one with `EPSILON < t < tmax` (shadow rays): a change of sign
    /// whose whole bracket maps inside or beyond that range answers without its root.
    Any(f64),
}

impl Superellipsoid {
    /// The crossings with `t > EPSILON`, increasing (`Want::All`), or the nearest; for
    /// `Want::Any` the answer when it is known without a root, else as for `First`.
    fn hits(&self, ray: &Ray, out: &mut Vec<Hit>, want: Want) -> Option<bool> {
        let len = ray.dir.length();
        if !(len > 0.0 && len.is_finite()) {
            return None;
        }
        let u = ray.dir / len;
        let (lo, hi) = box_interval(ray.origin, u, 1.0 + MARGIN)?;
        let lo = lo.max(EPSILON * len);
        if lo >= hi || lo.is_nan() || hi.is_nan() {
            return None;
        }
        // Distances are measured from the box entry so the samples keep their digits.
        let o = ray.origin + u * lo;
        // Increasing in `s` (a sum and a division by a positive number, each rounded
        // monotonically), so a root in `[s0, s1]` has its `t` in `[to_t(s0), to_t(s1)]`.
        let to_t = |s: f64| (s + lo) / len;
        let first_only = !matches!(want, Want::All);
        self.crossings(
            o,
            u,
            hi - lo,
            &mut |s| {
                let t = to_t(s);
                if t > EPSILON {
                    out.push(Hit::new(t));
                }
            },
            |s0, s1| match want {
                Want::All => Bracket::Refine,
                // The first root past EPSILON is the one asked for; beyond `tmax` it is none.
                Want::First(tmax) => {
                    let t0 = to_t(s0);
                    if t0 > EPSILON && t0 >= tmax {
                        Bracket::Answer(false)
                    } else {
                        Bracket::Refine
                    }
                }
                Want::Any(tmax) => {
                    let (t0, t1) = (to_t(s0), to_t(s1));
                    if t1 <= EPSILON {
                        Bracket::Pass
                    } else if t0 > EPSILON && t1 < tmax {
                        Bracket::Answer(true)
                    } else if t0 > EPSILON && t0 >= tmax {
                        Bracket::Answer(false)
                    } else {
                        Bracket::Refine
                    }
                }
            },
            |s| first_only && to_t(s) > EPSILON,
        )
    }
}

/// The stretch of the ray `o + s u` inside the box |x|, |y|, |z| <= r, or None.
fn box_interval(o: DVec3, u: DVec3, r: f64) -> Option<(f64, f64)> {
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    for i in 0..3 {
        if u[i] != 0.0 {
            let (a, b) = ((-r - o[i]) / u[i], (r - o[i]) / u[i]);
            lo = lo.max(a.min(b));
            hi = hi.min(a.max(b));
        } else if o[i].abs() > r {
            return None;
        }
    }
    (lo <= hi).then_some((lo, hi))
}

impl Shape for Superellipsoid {
    fn bounds(&self) -> Aabb {
        Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0))
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        self.hits(ray, out, Want::All);
    }

    /// Only the first crossing is refined: the `t` are increasing in the crossings, so the
    /// first whose `t` passes `EPSILON` is the nearest.
    fn intersect_first(&self, ray: &Ray, tmax: f64, scratch: &mut Vec<Hit>) -> Option<Hit> {
        scratch.clear();
        if self.hits(ray, scratch, Want::First(tmax)) == Some(false) {
            return None;
        }
        scratch.first().filter(|h| h.t < tmax).copied()
    }

    fn any_hit(&self, ray: &Ray, tmax: f64, scratch: &mut Vec<Hit>) -> bool {
        scratch.clear();
        match self.hits(ray, scratch, Want::Any(tmax)) {
            Some(hit) => hit,
            None => scratch.first().is_some_and(|h| h.t < tmax),
        }
    }

    fn inside(&self, p: DVec3) -> bool {
        self.value(p) < 0.0
    }

    fn normal(&self, p: DVec3, _hit: &Hit) -> DVec3 {
        // Gradient components (2/n)·S^(e/n - 1)·|x|^(2/e - 1) for x and y, with S the sum of
        // their powers, and (2/n)·|z|^(2/n - 1) for z; as logarithms, scaled by the largest.
        let (x, y, z) = (p.x.abs(), p.y.abs(), p.z.abs());
        let m = x.max(y);
        let ln_s = if m > 0.0 {
            let r = x.min(y) / m;
            self.a.exponent() * m.ln() + (1.0 + self.a.of(r)).ln()
        } else {
            f64::NEG_INFINITY
        };
        let part = |v: f64, k: f64| if k == 0.0 { 0.0 } else { k * v.ln() };
        let (a, b, c) = (self.a.exponent(), self.b.exponent(), self.c.exponent());
        let lx = (b - 1.0) * ln_s + part(x, a - 1.0);
        let ly = (b - 1.0) * ln_s + part(y, a - 1.0);
        let lz = part(z, c - 1.0);
        let l = [lx, ly, lz];
        let top = l
            .iter()
            .copied()
            .filter(|v| !v.is_nan())
            .fold(f64::NEG_INFINITY, f64::max);
        let mag = |li: f64| {
            if top == f64::INFINITY {
                if li == f64::INFINITY {
                    1.0
                } else {
                    0.0
                }
            } else if li.is_nan() || top == f64::NEG_INFINITY {
                0.0
            } else {
                (li - top).exp()
            }
        };
        let n = DVec3::new(
            mag(lx).copysign(p.x),
            mag(ly).copysign(p.y),
            mag(lz).copysign(p.z),
        );
        if n == DVec3::ZERO {
            p
        } else {
            n
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hits(s: &Superellipsoid, o: DVec3, d: DVec3) -> Vec<f64> {
        let mut v = Vec::new();
        s.intersect_all(&Ray::new(o, d), &mut v);
        let mut t: Vec<f64> = v.iter().map(|h| h.t).collect();
        t.sort_by(f64::total_cmp);
        t
    }

    #[test]
    fn sphere_case() {
        let s = Superellipsoid::new(1.0, 1.0);
        let t = hits(&s, DVec3::new(0.3, 0.2, -5.0), DVec3::Z * 2.0);
        let h = (1.0f64 - 0.13).sqrt();
        assert_eq!(t.len(), 2);
        assert!((t[0] - (5.0 - h) / 2.0).abs() < 1e-12, "{t:?}");
        assert!((t[1] - (5.0 + h) / 2.0).abs() < 1e-12);
        let p = DVec3::new(0.3, 0.2, -h);
        let n = s.normal(p, &Hit::new(0.0)).normalize();
        assert!((n - p.normalize()).length() < 1e-12, "{n}");
        assert!(s.inside(DVec3::splat(0.5)) && !s.inside(DVec3::splat(0.6)));
    }

    #[test]
    fn boxy_and_pinched() {
        // Nearly a box: crossings at the faces.
        let s = Superellipsoid::new(0.01, 0.01);
        let t = hits(&s, DVec3::new(0.2, -0.3, -3.0), DVec3::Z);
        assert_eq!(t.len(), 2);
        assert!(
            (t[0] - 2.0).abs() < 1e-3 && (t[1] - 4.0).abs() < 1e-3,
            "{t:?}"
        );
        let n = s.normal(DVec3::new(0.2, -0.3, -0.999), &Hit::new(0.0));
        assert!((n.normalize() - DVec3::NEG_Z).length() < 1e-9, "{n}");
        // A star (e = n = 3) hit along a diagonal: |x| = |y| = |z| = k with 2^(3/2)... solve.
        let s = Superellipsoid::new(3.0, 3.0);
        let d = DVec3::ONE.normalize();
        let t = hits(&s, -d * 4.0, d);
        // (2 k^(2/3))^(1) + k^(2/3) = 1  =>  k = 3^(-3/2); the distance is sqrt(3) k.
        let r = 3f64.sqrt() * 3f64.powf(-1.5);
        assert_eq!(t.len(), 2);
        assert!((t[0] - (4.0 - r)).abs() < 1e-10, "{t:?}");
        // Normals at the cusps stay finite.
        for p in [DVec3::X, DVec3::Y, DVec3::Z, DVec3::ZERO] {
            let n = s.normal(p, &Hit::new(0.0));
            assert!(n.is_finite() && n != DVec3::ZERO, "{p} {n}");
        }
    }

    /// `Power` relies on these being `powf`'s results to the bit (they are its correctly rounded
    /// results; LLVM makes the same replacements for constant exponents).
    #[test]
    fn special_powers_are_exact() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        for i in 0..200_000 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            // Uniform in [0, 2), then spread over many binades.
            let u = f64::from_bits((state >> 12) | 0x3ff0_0000_0000_0000) - 1.0;
            let x = std::hint::black_box(u * 2f64.powi((i % 64) - 40));
            assert_eq!(
                Power::new(2.0).of(x).to_bits(),
                x.powf(2.0).to_bits(),
                "{x}"
            );
            assert_eq!(
                Power::new(0.5).of(x).to_bits(),
                x.powf(0.5).to_bits(),
                "{x}"
            );
            assert_eq!(
                Power::new(1.0).of(x).to_bits(),
                x.powf(1.0).to_bits(),
                "{x}"
            );
        }
        for x in [0.0, f64::INFINITY, f64::NAN, f64::MIN_POSITIVE, 5e-324] {
            for k in [0.5, 1.0, 2.0] {
                let (p, q) = (Power::new(k).of(x), x.powf(k));
                assert!(
                    p.to_bits() == q.to_bits() || (p.is_nan() && q.is_nan()),
                    "{x} {k}"
                );
            }
        }
    }

    /// The samples' sign from the tables (or the two cheap powers) is the sign of `value`.
    #[test]
    fn field_sign_is_the_value_sign() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            f64::from_bits((state >> 12) | 0x3ff0_0000_0000_0000) - 1.0
        };
        let exps = [0.1, 0.3, 0.5, 1.0, 2.0, 3.0];
        for &e in &exps {
            for &n in &exps {
                let s = Superellipsoid::new(e, n);
                for _ in 0..20_000 {
                    let p = DVec3::new(next(), next(), next()) * 2.0 - DVec3::ONE;
                    // Half the points pulled onto the surface, where the sign is close; some
                    // put on a face of the searched box (1 + MARGIN out), where samples start
                    // and end.
                    let p = if next() < 0.5 {
                        super::near::tests::on_surface(&s, p)
                    } else if next() < 0.2 {
                        let mut q = p.to_array();
                        let k = (next() * 3.0) as usize % 3;
                        q[k] = (1.0 + MARGIN).copysign(q[k]);
                        DVec3::from_array(q)
                    } else {
                        p
                    };
                    let v = s.value(p);
                    let f = s.field(p);
                    if f.exact {
                        assert_eq!(f.v.to_bits(), v.to_bits(), "{e} {n} {p}");
                    } else {
                        assert_eq!(f.negative(), v < 0.0, "{e} {n} {p}");
                    }
                }
            }
        }
    }

    /// The nearest crossing alone is `intersect_all`'s nearest, to the bit.
    #[test]
    fn first_crossing_is_the_nearest_of_all() {
        let mut rng = crate::geom::test_rng::Lcg(5);
        for (e, n) in [(0.3, 0.3), (1.0, 0.1), (2.0, 0.5), (3.0, 3.0), (1.0, 1.0)] {
            let s = Superellipsoid::new(e, n);
            for _ in 0..3000 {
                let o = rng.vec(5.0);
                let ray = Ray::new(o, rng.vec(1.0).normalize() * 1.7 - o * 0.1 * rng.next());
                let tmax = if rng.next() < 0.3 { 2.0 } else { f64::INFINITY };
                let want =
                    crate::geom::test_rng::nearest_of_all(&s, &ray, tmax).map(|h| h.t.to_bits());
                let got = s.intersect_first(&ray, tmax, &mut Vec::new());
                assert_eq!(want, got.map(|h| h.t.to_bits()), "{e} {n} {ray:?}");
            }
        }
    }

    /// `any_hit` answers as `intersect_first` does, also for rays leaving the surface (shadow
    /// rays) and for `tmax` within a sample step of the crossing.
    #[test]
    fn any_hit_is_whether_there_is_a_first() {
        let mut rng = crate::geom::test_rng::Lcg(7);
        let mut hits = 0;
        for (e, n) in [
            (0.3, 0.3),
            (1.0, 0.1),
            (1.0, 0.5),
            (2.0, 0.5),
            (3.0, 3.0),
            (1.0, 1.0),
        ] {
            let s = Superellipsoid::new(e, n);
            for i in 0..3000 {
                let o = rng.vec(3.0);
                let d = rng.vec(1.0).normalize() * 1.3 - o * 0.2 * rng.next();
                let mut ray = Ray::new(o, d);
                // Every other ray starts on the surface, as a shadow ray does.
                if i % 2 == 1 {
                    if let Some(h) = s.intersect_first(&ray, f64::INFINITY, &mut Vec::new()) {
                        ray = Ray::new(ray.at(h.t), rng.vec(1.0));
                    }
                }
                let first = s.intersect_first(&ray, f64::INFINITY, &mut Vec::new());
                let near = first.map_or(1.0, |h| h.t);
                for tmax in [
                    f64::INFINITY,
                    near,
                    near * (1.0 + 1e-9),
                    near * 0.999,
                    0.5,
                    3.0,
                ] {
                    let want = s.intersect_first(&ray, tmax, &mut Vec::new()).is_some();
                    assert_eq!(
                        s.any_hit(&ray, tmax, &mut Vec::new()),
                        want,
                        "{e} {n} {ray:?}"
                    );
                    hits += want as usize;
                }
            }
        }
        assert!(hits > 5000, "{hits}");
    }

    #[test]
    fn odd_rays() {
        let s = Superellipsoid::new(0.5, 2.0);
        assert!(hits(&s, DVec3::ZERO, DVec3::ZERO).is_empty());
        assert!(hits(&s, DVec3::splat(f64::NAN), DVec3::X).is_empty());
        assert!(hits(&s, DVec3::new(0.0, 5.0, 0.0), DVec3::X).is_empty());
        // From inside: one crossing.
        assert_eq!(hits(&s, DVec3::ZERO, DVec3::new(0.3, 0.1, 0.2)).len(), 1);
    }
}
