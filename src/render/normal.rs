//! Perturbed surface normals (`normal { ... }`), as POV-Ray 3.7 computes them. Measured with the
//! `povray` binary by scripts/measure_normals.py (a white plane under coloured parallel lights
//! gives the perturbed normal per pixel) and checked by tests/probes/normal_*.pov:
//!
//! - The surface normal goes into the pattern's space as a normal (Mᵀ·n) and is made unit length
//!   there unless `no_bump_scale` is given; it is perturbed there and brought back (M⁻ᵀ), then
//!   normalised. So a uniform `scale` keeps the bump slopes and a stretch tilts them; with
//!   `no_bump_scale` a pattern twice as large has slopes half as steep.
//! - Any pattern other than the classic bump patterns perturbs by the slope of its value (after
//!   the slope map, if any): n − (2/15)·amount·∇h, where ∇h comes from the value at four
//!   points at distance `accuracy` (0.02) around the point, the corners of a regular
//!   tetrahedron with one corner along +y (found by scanning a step function's edge across
//!   them). Four values fix a linear function exactly, so the slope is exact for linear
//!   patterns and smoothed over `accuracy` at edges.
//! - A slope map makes the height a cubic Hermite spline of the value through its entries'
//!   heights with their slopes, each slope taken over its segment (measured on `gradient x`
//!   with constant-height maps and a triangle-wave map).

use std::f64::consts::TAU;

use crate::math::{by_coordinates, DVec3, Transform};
use crate::scene::desc::{ImageMap, Normal, NormalKind, Special, Texture, TextureEntries};
use crate::scene::pattern::{Pattern, PatternKind};

use super::{noise, noise_lattice, pattern};

/// Tilt per unit of value slope and of amount (measured: `gradient x 1` tilts by 2/15).
const SLOPE_SCALE: f64 = 2.0 / 15.0;

/// The corners of the sampling tetrahedron: one along +y, three below it at y = −1/3.
const TETRA: [DVec3; 4] = [
    DVec3::new(0.0, 1.0, 0.0),
    DVec3::new(0.942_809_041_582_063_4, -1.0 / 3.0, 0.0),
    DVec3::new(-0.471_404_520_791_031_7, -1.0 / 3.0, 0.816_496_580_927_726),
    DVec3::new(-0.471_404_520_791_031_7, -1.0 / 3.0, -0.816_496_580_927_726),
];

/// Whether any part of a texture (layers, patterned entries) perturbs the normal.
pub fn texture_perturbs(t: &Texture) -> bool {
    t.layers().any(|l| {
        perturbs(l.normal.as_deref())
            || l.pattern.as_ref().is_some_and(|tp| match &tp.entries {
                TextureEntries::List(items) => items.iter().any(texture_perturbs),
                TextureEntries::Map(map) => map.iter().any(|(_, t)| texture_perturbs(t)),
            })
    })
}

/// Whether a normal changes anything.
pub fn perturbs(n: Option<&Normal>) -> bool {
    n.is_some_and(|n| !matches!(n.kind, NormalKind::Flat))
}

/// The perturbed unit normal at `p` for the unit surface normal `n`, both in the space `nd`'s
/// transform maps to (`space` takes that space on to the world; `p` and `n` are world).
pub fn perturb_in(nd: &Normal, space: &Transform, p: DVec3, n: DVec3) -> DVec3 {
    if space.is_identity() {
        perturb(nd, p, n)
    } else {
        let t = nd.transform.then(space);
        perturb_with(nd, &t, p, n)
    }
}

/// The perturbed unit normal at `p` for the unit surface normal `n` (both in the normal's
/// parent space).
pub fn perturb(nd: &Normal, p: DVec3, n: DVec3) -> DVec3 {
    perturb_with(nd, &nd.transform, p, n)
}

fn perturb_with(nd: &Normal, t: &Transform, p: DVec3, n: DVec3) -> DVec3 {
    if matches!(nd.kind, NormalKind::Flat) {
        return n;
    }
    // By coordinates too: `normal_map`'s nested calls store their normal as three 8-byte
    // stores, and the transformed branch loaded its x-y pair as 16 bytes.
    let n = by_coordinates(&n);
    let identity = t.is_identity();
    let (lp, ln) = if identity {
        (p, n)
    } else {
        (t.inv_point(p), t.m.transpose().transform_vector3(n))
    };
    // Read by coordinates: the two branches meet in one stack slot, which the transformed
    // branch fills by three 8-byte stores (three dot products), and a 16-byte load of x-y
    // spanning two of them cannot be forwarded from the store buffer (a tenth of this
    // function's samples on normavg, on the instruction after that load).
    let mut ln = by_coordinates(&ln);
    if !nd.no_bump_scale {
        ln = unit_or_zero(ln);
    }
    // By coordinates: `local`'s arms (inlined) leave their result in one stack slot by
    // three 8-byte stores, and the merge loaded its x-y pair as 16 bytes, which the store
    // buffer cannot forward (a tenth of this function's samples on slopemap, next to it).
    let out = by_coordinates(&local(nd, lp, ln));
    let out = if identity { out } else { t.normal(out) };
    let out = out.normalize_or_zero();
    if out == DVec3::ZERO {
        n
    } else {
        out
    }
}

/// `v.normalize_or_zero()`, bit for bit, without its square root and division where |v|² is
/// exactly 1: then the length is √1 = 1, its reciprocal 1, and v·1 is v (−0 included). The
/// normal going into a pattern is mostly unit already (a plane's or box's axis, the normal
/// `normal_map` made unit before each entry normalises it again), and the two were a
/// dependent chain of a `sqrtsd` and a `divsd` on every perturbed normal.
#[inline(always)]
fn unit_or_zero(v: DVec3) -> DVec3 {
    if v.dot(v) == 1.0 {
        v
    } else {
        v.normalize_or_zero()
    }
}

/// The perturbed (not normalised) normal in the pattern's own space.
fn local(nd: &Normal, lp: DVec3, ln: DVec3) -> DVec3 {
    let amount = nd.amount;
    match &nd.kind {
        NormalKind::Flat => ln,
        NormalKind::Pattern {
            pattern: pat,
            special,
            slope_map,
        } => match special {
            Special::Slope => {
                // By coordinates: `slope` returns its vector stored as x (8 bytes) and y-z
                // (16), and the x-y pair loaded as 16 bytes here could not be forwarded.
                let g = by_coordinates(&slope(pat, slope_map.as_deref(), lp, nd.accuracy));
                ln - g * (SLOPE_SCALE * amount)
            }
            Special::Bumps => {
                ln + noise::dnoise(pattern::warped(pat, lp), pat.noise_generator) * amount
            }
            Special::Dents => dents(pat, lp, ln, amount),
            Special::Quilted => match pat.kind {
                PatternKind::Quilted { c0, c1 } => {
                    ln + pattern::quilted_vector(pattern::warped(pat, lp), c0, c1) * amount
                }
                _ => ln,
            },
            Special::Wrinkles => wrinkles(pat, lp, ln, amount),
            Special::Ripples | Special::Waves => waves(pat, *special, lp, ln, amount),
        },
        NormalKind::List {
            pattern: pat,
            items,
        } => {
            // The entries see the warped point (measured: see `pattern::warped`).
            let q = pattern::warped(pat, lp);
            let i = pattern::index_warped(pat, q).min(items.len().saturating_sub(1));
            match items.get(i) {
                Some(item) => perturb(item, q, unit_or_zero(ln)),
                None => ln,
            }
        }
        NormalKind::Map { pattern: pat, map } => normal_map(pat, map, lp, ln),
        NormalKind::BumpMap(im) => bump_map(im, lp, ln, amount),
        NormalKind::Facets { .. } => ln,
    }
}

/// The value's height (through the slope map) and its slope at `lp` from four samples.
fn slope(pat: &Pattern, map: Option<&[(f64, f64, f64)]>, lp: DVec3, accuracy: f64) -> DVec3 {
    // Warps and turbulence move the point once; the samples sit around the moved point.
    let centre = pattern::warped(pat, lp);
    // The four samples' values together: a fractal steps their orbits at once. By
    // reference: passed by value, the array was copied in 16-byte pieces that straddled
    // the points' 16 + 8-byte stores just made here, store-forwarding stalls (mist's brick).
    let vs = pattern::values_warped4(pat, &TETRA.map(|u| centre + ((lp + u * accuracy) - lp)));
    // Each value by its own 8-byte load: the four are returned through memory, stored one
    // at a time, and a 16-byte load of two of them could not be forwarded (two fifths of
    // this function's samples on normavg, after the call).
    // SAFETY: reads of initialised doubles through references.
    let vs = unsafe { [0, 1, 2, 3].map(|k| std::ptr::read_volatile(&vs[k])) };
    // For a regular tetrahedron Σ uuᵀ = (4/3)·I, so this is the linear fit's gradient.
    let mut g = DVec3::ZERO;
    for (u, v) in TETRA.into_iter().zip(vs) {
        let h = match map {
            Some(m) => slope_height(m, v),
            None => v,
        };
        g += u * h;
    }
    g * (0.75 / accuracy)
}

/// The height a slope map gives value `v`: a cubic Hermite spline through the entries'
/// heights with their slopes, flat outside them. The slopes are per segment, not per unit of
/// value (measured: `[0 <0,1>] [0.5 <1,1>]` rises in a straight line).
pub fn slope_height(map: &[(f64, f64, f64)], v: f64) -> f64 {
    let (Some(first), Some(last)) = (map.first(), map.last()) else {
        return v;
    };
    if v <= first.0 {
        return first.1;
    }
    if v >= last.0 {
        return last.1;
    }
    for w in map.windows(2) {
        let ((v0, h0, s0), (v1, h1, s1)) = (w[0], w[1]);
        if v <= v1 {
            let d = v1 - v0;
            if d <= 0.0 {
                return h1;
            }
            let t = (v - v0) / d;
            let (t2, t3) = (t * t, t * t * t);
            return h0 * (2.0 * t3 - 3.0 * t2 + 1.0)
                + h1 * (3.0 * t2 - 2.0 * t3)
                + s0 * (t3 - 2.0 * t2 + t)
                + s1 * (t3 - t2);
        }
    }
    last.1
}

/// Dents: bumps whose depth is the cube of the noise, so most of the surface stays smooth.
/// Equals povray's normals to one 16-bit step for all three noise generators.
fn dents(pat: &Pattern, lp: DVec3, ln: DVec3, amount: f64) -> DVec3 {
    let q = pattern::warped(pat, lp);
    let (v, d) = noise::noise_and_dnoise(q, pat.noise_generator);
    ln + d * (amount * v * v * v)
}

/// Wrinkles: ten octaves of vector noise, each twice as fine and half as strong (equal to
/// povray's normals to one 16-bit step, probe `normal_noise`).
fn wrinkles(pat: &Pattern, lp: DVec3, ln: DVec3, amount: f64) -> DVec3 {
    let q = pattern::warped(pat, lp);
    ln + noise_lattice::abs_octaves(q) * amount
}

/// Ripples and waves: each wave source tilts the normal along the direction from it by the
/// wave's value there, the sources' tilts averaged. Measured with `number_of_waves 1`:
/// n + amount·(p − c)/|p − c|·sin(2π·|p − c|) for ripples, the same with sin(2π·f·|p − c|)/f
/// and the source's own frequency f for waves; with all ten sources, frequency and phase,
/// lancer's normals equal povray's to the 16-bit step (scripts/measure_waves.py).
///
/// Every source's offset, distance and sine argument first, then the sines, then the sum (in
/// source order, the same operations): with the libm call inside one loop, the loop saved and
/// restored its live values around every `sin` (~13 of ~60 instructions a source; arches).
fn waves(pat: &Pattern, special: Special, lp: DVec3, ln: DVec3, amount: f64) -> DVec3 {
    let q = pattern::warped(pat, lp);
    let sources = &pattern::WAVE_SOURCES[..pattern::wave_count(pat)];
    let n = sources.len() as f64;
    let mut d = [DVec3::ZERO; pattern::WAVE_SOURCES.len()];
    let mut len = [0.0; pattern::WAVE_SOURCES.len()];
    let mut s = [0.0; pattern::WAVE_SOURCES.len()];
    for (k, &(c, f)) in sources.iter().enumerate() {
        d[k] = q - c;
        len[k] = d[k].length();
        s[k] = match special {
            Special::Ripples => TAU * (len[k] * pat.frequency + pat.phase),
            _ => TAU * (len[k] * pat.frequency * f + pat.phase),
        };
    }
    // A source at the point (length 0) adds nothing; its sine is taken and dropped.
    for x in &mut s[..sources.len()] {
        *x = x.sin();
    }
    let mut sum = DVec3::ZERO;
    for (k, &(_, f)) in sources.iter().enumerate() {
        if len[k] == 0.0 {
            continue;
        }
        let s = match special {
            Special::Ripples => s[k],
            _ => s[k] / f,
        };
        sum += d[k] * (s / len[k]);
    }
    ln + sum * (amount / n)
}

/// `normal_map`: the normals around the pattern's value, blended by their weights; `average`
/// blends all of them.
fn normal_map(pat: &Pattern, map: &[(f64, Normal)], lp: DVec3, ln: DVec3) -> DVec3 {
    let n = unit_or_zero(ln);
    if matches!(pat.kind, PatternKind::Average) {
        let q = pattern::warped(pat, lp);
        let total: f64 = map.iter().map(|e| e.0).sum();
        if total == 0.0 {
            return ln;
        }
        return map
            .iter()
            .fold(DVec3::ZERO, |s, (w, m)| s + perturb(m, q, n) * (w / total));
    }
    // The entries see the warped point (measured: see `pattern::warped`).
    let q = pattern::warped(pat, lp);
    let v = pattern::value_warped(pat, q);
    let lp = q;
    let (Some(first), Some(last)) = (map.first(), map.last()) else {
        return ln;
    };
    if v <= first.0 {
        return perturb(&first.1, lp, n);
    }
    for w in map.windows(2) {
        let ((va, na), (vb, nb)) = (&w[0], &w[1]);
        if v <= *vb {
            let span = vb - va;
            if span <= 0.0 {
                return perturb(nb, lp, n);
            }
            let t = (v - va) / span;
            return perturb(na, lp, n) * (1.0 - t) + perturb(nb, lp, n) * t;
        }
    }
    perturb(&last.1, lp, n)
}

/// `bump_map`: the image's grey as a height over the x-y plane, its slope from the
/// neighbouring pixels.
fn bump_map(im: &ImageMap, lp: DVec3, ln: DVec3, amount: f64) -> DVec3 {
    if im.width == 0 || im.height == 0 {
        return ln;
    }
    let grey = |x: i64, y: i64| {
        let xi = x.rem_euclid(im.width as i64) as usize;
        let yi = y.rem_euclid(im.height as i64) as usize;
        let c = im.pixels.get(yi * im.width as usize + xi);
        0.297 * c.rgb.x + 0.589 * c.rgb.y + 0.114 * c.rgb.z
    };
    let (u, v) = (lp.x - lp.x.floor(), lp.y - lp.y.floor());
    if im.once && !((0.0..1.0).contains(&lp.x) && (0.0..1.0).contains(&lp.y)) {
        return ln;
    }
    let x = (u * im.width as f64) as i64;
    let y = ((1.0 - v) * im.height as f64) as i64;
    let h = grey(x, y);
    let dx = grey(x + 1, y) - h;
    let dy = h - grey(x, y + 1);
    ln - DVec3::new(dx, dy, 0.0) * amount
}

#[cfg(test)]
mod tests {
    use super::*;

    fn gradient_x(amount: f64) -> Normal {
        let mut n = Normal::new(NormalKind::Pattern {
            pattern: Box::new(Pattern::new(PatternKind::Gradient(DVec3::X))),
            special: Special::Slope,
            slope_map: None,
        });
        n.amount = amount;
        n
    }

    /// Measured with scripts/measure_normals.py: `gradient x 1` on a plane facing -z tilts the
    /// normal by 2/15 towards -x, whatever the point and the pattern's uniform scale.
    #[test]
    fn gradient_tilts_by_two_fifteenths() {
        let n = perturb(&gradient_x(1.0), DVec3::new(0.3, 0.2, 0.0), -DVec3::Z);
        assert!((n.x / n.z - 2.0 / 15.0).abs() < 1e-9, "{n}");
        let mut scaled = gradient_x(1.0);
        scaled.apply_transform(&Transform::scale(DVec3::splat(2.0)));
        let m = perturb(&scaled, DVec3::new(0.3, 0.2, 0.0), -DVec3::Z);
        assert!((m - n).length() < 1e-9);
        scaled.no_bump_scale = true;
        let h = perturb(&scaled, DVec3::new(0.3, 0.2, 0.0), -DVec3::Z);
        assert!((h.x / h.z - 1.0 / 15.0).abs() < 1e-9, "{h}");
    }

    /// `waves` (its sines taken apart from the sums) is the one-loop form, bit for bit, for
    /// ripples and waves with every source count, frequency and phase, at points that
    /// include a source itself (its length-0 term skipped).
    #[test]
    fn waves_are_the_one_loop_sum() {
        fn one_loop(pat: &Pattern, special: Special, lp: DVec3, ln: DVec3, amount: f64) -> DVec3 {
            let q = pattern::warped(pat, lp);
            let sources = &pattern::WAVE_SOURCES[..pattern::wave_count(pat)];
            let n = sources.len() as f64;
            let mut sum = DVec3::ZERO;
            for &(c, f) in sources {
                let d = q - c;
                let len = d.length();
                if len == 0.0 {
                    continue;
                }
                let s = match special {
                    Special::Ripples => (TAU * (len * pat.frequency + pat.phase)).sin(),
                    _ => (TAU * (len * pat.frequency * f + pat.phase)).sin() / f,
                };
                sum += d * (s / len);
            }
            ln + sum * (amount / n)
        }
        let ln = DVec3::new(0.2, 0.9, -0.1);
        for count in [1, 3, 10, 12] {
            for (kind, special) in [
                (PatternKind::Ripples(count), Special::Ripples),
                (PatternKind::Waves(count), Special::Waves),
            ] {
                let mut pat = Pattern::new(kind);
                for (freq, phase) in [(1.0, 0.0), (5000.0, 0.25), (0.3, -1.5)] {
                    pat.frequency = freq;
                    pat.phase = phase;
                    let mut points = vec![pattern::WAVE_SOURCES[0].0, pattern::WAVE_SOURCES[9].0];
                    for k in 0..200 {
                        let t = k as f64 * 0.37;
                        points.push(DVec3::new(t.sin() * 3.0, t * 0.05 - 4.0, (t * 0.7).cos()));
                    }
                    for p in points {
                        let a = waves(&pat, special, p, ln, 0.4);
                        let b = one_loop(&pat, special, p, ln, 0.4);
                        assert_eq!(
                            a.to_array().map(f64::to_bits),
                            b.to_array().map(f64::to_bits)
                        );
                    }
                }
            }
        }
    }

    /// `unit_or_zero` is glam's `normalize_or_zero` to the bit: axes and their negatives,
    /// vectors made unit once and twice (most of those have |v|² = 1, the rest not), tiny,
    /// huge, zero, −0, infinite and NaN components.
    #[test]
    fn unit_or_zero_is_normalize_or_zero() {
        use crate::geom::test_rng::Lcg;
        let bits = |v: DVec3| v.to_array().map(f64::to_bits);
        let mut cases = vec![
            DVec3::ZERO,
            -DVec3::ZERO,
            DVec3::new(-0.0, 1.0, 0.0),
            DVec3::new(0.0, -0.0, -1.0),
            DVec3::new(1e-300, 0.0, 0.0),
            DVec3::new(1e300, 1e300, 0.0),
            DVec3::new(f64::INFINITY, 0.0, 0.0),
            DVec3::new(f64::NAN, 1.0, 0.0),
            DVec3::new(f64::MIN_POSITIVE, -f64::MIN_POSITIVE, 0.0),
            DVec3::new(1.0 + f64::EPSILON, 0.0, 0.0),
            DVec3::new(1.0 - f64::EPSILON / 2.0, 0.0, 0.0),
        ];
        for a in [DVec3::X, DVec3::Y, DVec3::Z] {
            cases.push(a);
            cases.push(-a);
        }
        let mut rng = Lcg(36);
        for k in 0..200_000 {
            let v = rng.vec(10f64.powi(k % 7 - 3));
            let u = v.normalize_or_zero();
            cases.extend([v, u, u.normalize_or_zero(), u * (1.0 + f64::EPSILON)]);
        }
        let mut exact = 0;
        for v in cases {
            exact += (v.dot(v) == 1.0) as usize;
            assert_eq!(bits(unit_or_zero(v)), bits(v.normalize_or_zero()), "{v:?}");
        }
        // The short way is taken for many of them (the test would prove little otherwise).
        assert!(exact > 100_000, "{exact}");
    }

    #[test]
    fn slope_map_is_a_hermite_spline_per_segment() {
        let tri = [
            (0.0, 0.0, 1.0),
            (0.5, 1.0, 1.0),
            (0.5, 1.0, -1.0),
            (1.0, 0.0, -1.0),
        ];
        assert!((slope_height(&tri, 0.25) - 0.5).abs() < 1e-12);
        assert!((slope_height(&tri, 0.75) - 0.5).abs() < 1e-12);
        let s = [(0.0, 0.0, 0.0), (1.0, 1.0, 0.0)];
        assert!((slope_height(&s, 0.4) - (3.0 * 0.16 - 2.0 * 0.064)).abs() < 1e-12);
    }
}
