//! Pattern evaluation: the scalar value (or block index) of a pattern at a point in its own
//! space, independent of what the value then selects (colours, pigments, and later normals).
//!
//! Order, as POV-Ray 3.7 does it: warps from the last written to the first, then classic
//! turbulence (always innermost), then the pattern's function, then frequency and phase
//! (`fmod(v·f + phase, 1.00001)`, plus 1 when negative; the period just over 1 keeps a value of
//! exactly 1, such as `spherical` at its centre, at the top of the map), then the wave type.
//! The formulas of the deterministic patterns were measured against the `povray` binary with
//! 16-bit renders of each pattern on a plane (see tests/probes/pattern_*.pov).

use std::cell::Cell;
use std::f64::consts::{PI, TAU};

use crate::math::DVec3;
use crate::scene::pattern::{Pattern, PatternKind, Slope, Wave};

use super::fractal::{fractal, fractal2_lanes4, magnet_lanes4};
use super::noise;
use super::pattern_wrap::{fmod, rem_euclid};
use super::warp;

/// Keeps points that sit exactly on a checker boundary (a plane at y = 0 computed as -1e-17)
/// on the same side every time.
const CHECKER_EPS: f64 = 1e-9;

/// POV-Ray's period for frequency and phase: a hair over 1 (measured: `spherical frequency 2`
/// keeps the centre at the top of the map).
const WRAP: f64 = 1.00001;

/// The surface a texture is being evaluated on, for the normal-dependent patterns (slope, aoi).
#[derive(Clone, Copy, Debug)]
pub struct Surface {
    /// World point.
    pub point: DVec3,
    /// Unit normal in world space, turned to face the ray and perturbed by the texture's
    /// normal where it has one (measured).
    pub normal: DVec3,
    /// Unit ray direction.
    pub ray: DVec3,
}

thread_local! {
    // A thread-local rather than an argument: slope and aoi are rare, and every pattern,
    // pigment and texture evaluation would otherwise carry a surface it does not use.
    static SURFACE: Cell<Option<Surface>> = const { Cell::new(None) };
}

/// Sets the surface the next pattern evaluations on this thread are for (None: no surface,
/// as in functions, where slope and aoi are 0).
pub fn set_surface(s: Option<Surface>) {
    SURFACE.with(|c| c.set(s));
}

/// The surface set by `set_surface`.
pub fn surface() -> Option<Surface> {
    SURFACE.with(|c| c.get())
}

/// Whether a pattern reads the surface normal (slope, aoi).
pub fn uses_surface(pat: &Pattern) -> bool {
    matches!(pat.kind, PatternKind::Slope(_) | PatternKind::Aoi)
}

/// The pattern's value in [0, 1] at `p` (pattern space, before warps), ready for a map lookup.
pub fn value(pat: &Pattern, p: DVec3) -> f64 {
    let q = warped(pat, p);
    let v = raw(pat, q);
    shape(pat, v)
}

/// Which listed item a block pattern (checker, hexagon, brick) picks at `p`; for other
/// patterns, whether the value is in the upper half.
pub fn index(pat: &Pattern, p: DVec3) -> usize {
    index_warped(pat, warped(pat, p))
}

/// The pattern's value at a point `warped` has already moved (maps and lists evaluate their
/// entries there too).
pub fn value_warped(pat: &Pattern, q: DVec3) -> f64 {
    shape(pat, raw(pat, q))
}

/// `index` at a point `warped` has already moved.
pub fn index_warped(pat: &Pattern, q: DVec3) -> usize {
    match &pat.kind {
        PatternKind::Checker => checker(q),
        PatternKind::Hexagon => hexagon(q),
        PatternKind::Brick { size, mortar } => brick(q, *size, *mortar),
        PatternKind::Square => square(q),
        PatternKind::Triangular => triangular(q),
        PatternKind::Cubic => cubic(q),
        PatternKind::MaterialMap(im, indices) => material_index(im, indices, q),
        _ => (shape(pat, raw(pat, q)) >= 0.5) as usize,
    }
}

/// The point after warps and turbulence: where the entries of a map or list are evaluated
/// (measured: a `pigment_map`, pigment list, `texture_map`, texture list or `normal_map` of
/// `gradient z` stripes under `warp { turbulence }` or plain turbulence shows wavy stripes in
/// povray; marble's and wood's own turbulence, which is not a warp, leaves them straight).
/// Inlined for its first test (no warps, and no turbulence or marble's and wood's own: the
/// point stays), which spares most patterns a ~30-instruction call.
#[inline]
pub fn warped(pat: &Pattern, p: DVec3) -> DVec3 {
    if pat.warps.is_empty()
        && (pat.turbulence.is_none() || matches!(pat.kind, PatternKind::Marble | PatternKind::Wood))
    {
        p
    } else {
        warped_moved(pat, p)
    }
}

/// `warped` of a pattern with warps or turbulence.
#[inline(never)]
fn warped_moved(pat: &Pattern, p: DVec3) -> DVec3 {
    let mut q = p;
    for w in pat.warps.iter().rev() {
        q = warp::apply(w, q, pat.noise_generator);
    }
    if let Some(t) = &pat.turbulence {
        // Marble and wood use their turbulence in their own formulas instead (see `raw`).
        if !matches!(pat.kind, PatternKind::Marble | PatternKind::Wood) && t.amount != DVec3::ZERO {
            q += t.amount
                * noise::turbulence_vec(q, t.octaves, t.omega, t.lambda, pat.noise_generator);
        }
    }
    q
}

/// Frequency, phase and wave type.
fn shape(pat: &Pattern, v: f64) -> f64 {
    shape_inline(pat, v)
}

/// `shape` written into its caller: a normal's four samples (gradient, radial, the noises)
/// paid its call and an array `map` on each (~30 instructions a sample on normavg).
#[inline(always)]
pub(super) fn shape_inline(pat: &Pattern, v: f64) -> f64 {
    if pat.is_block() {
        return v;
    }
    let x = v * pat.frequency + pat.phase;
    // Inside the period fmod's own first exit answers x, here before its call (not inlined).
    let mut v = if x.abs() < WRAP { x } else { fmod(x, WRAP) };
    if v < 0.0 {
        // Measured: gradient x at x = -0.3 gives 0.7, so negatives wrap by 1, not WRAP.
        v += 1.0;
    }
    if !v.is_finite() {
        v = 0.0;
    }
    match pat.wave {
        Wave::Ramp => v,
        Wave::Triangle => {
            if v < 0.5 {
                2.0 * v
            } else {
                2.0 - 2.0 * v
            }
        }
        Wave::Sine => 0.5 + 0.5 * (TAU * v).sin(),
        Wave::Scallop => (PI * v).sin().abs(),
        Wave::Cubic => v * v * (3.0 - 2.0 * v),
        Wave::Poly(e) => v.max(0.0).powf(e),
    }
}

/// The pattern's own function before frequency, phase and wave.
fn raw(pat: &Pattern, q: DVec3) -> f64 {
    let gen = pat.noise_generator;
    match &pat.kind {
        PatternKind::Checker => checker(q) as f64,
        PatternKind::Hexagon => hexagon(q) as f64 / 2.0,
        PatternKind::Brick { size, mortar } => brick(q, *size, *mortar) as f64,
        PatternKind::Square => square(q) as f64,
        PatternKind::Triangular => triangular(q) as f64,
        PatternKind::Cubic => cubic(q) as f64,
        PatternKind::ImagePattern(im) => {
            let c = super::pigment::image(im, q);
            if im.use_alpha {
                // Measured: opaque pixels give 0, so the value is the transparency.
                c.transmit
            } else {
                0.297 * c.rgb.x + 0.589 * c.rgb.y + 0.114 * c.rgb.z
            }
        }
        PatternKind::PigmentPattern(p) => {
            let c = super::pigment::eval(p, q);
            0.297 * c.rgb.x + 0.589 * c.rgb.y + 0.114 * c.rgb.z
        }
        PatternKind::Gradient(a) => gradient(q, *a),
        PatternKind::Onion => fmod(q.length(), 1.0),
        PatternKind::Radial => radial(q),
        PatternKind::Spherical => 1.0 - q.length().min(1.0),
        PatternKind::Cylindrical => 1.0 - (q.x * q.x + q.z * q.z).sqrt().min(1.0),
        PatternKind::Boxed => 1.0 - q.x.abs().max(q.y.abs()).max(q.z.abs()).min(1.0),
        PatternKind::Planar => 1.0 - q.y.abs().min(1.0),
        PatternKind::Leopard => {
            let s = (q.x.sin() + q.y.sin() + q.z.sin()) / 3.0;
            s * s
        }
        PatternKind::Marble => {
            let t = pat.turbulence.map_or(0.0, |t| {
                t.amount.x * noise::turbulence(q, t.octaves, t.omega, t.lambda, gen)
            });
            q.x + t
        }
        PatternKind::Wood => match &pat.turbulence {
            Some(t) if t.amount != DVec3::ZERO => {
                // Not through turbulence_vec's per-thread cache, which a wood's point almost
                // never hits (a pigment read three times through functions, as the `_37`
                // woods' gamma correction does, is remembered whole by `pigment::eval_memo`).
                let tv = noise::turbulence_vec_uncached(q, t.octaves, t.omega, t.lambda);
                wood(q, t.amount, tv)
            }
            _ => (q.x * q.x + q.y * q.y).sqrt(),
        },
        PatternKind::Spiral1(arms) => {
            let r = (q.x * q.x + q.y * q.y).sqrt();
            if r == 0.0 {
                q.z
            } else {
                r + q.z + arms * (q.y.atan2(q.x) / TAU + 0.25)
            }
        }
        // Measured (scripts/measure_pattern.py): spiral1's value through an exact triangle wave
        // plus the radius's, so 0 to 2 before the pattern's own wave. The manual's "two
        // spirals twisting in opposite directions" is not what 3.7 computes.
        PatternKind::Spiral2(arms) => {
            let r = (q.x * q.x + q.y * q.y).sqrt();
            let s = if r == 0.0 {
                q.z
            } else {
                r + q.z + arms * (q.y.atan2(q.x) / TAU + 0.25)
            };
            tri(s) + tri(r)
        }
        PatternKind::Slope(sl) => slope(sl, q),
        PatternKind::Aoi => surface().map_or(0.0, |s| angle_value(-s.normal.dot(s.ray))),
        PatternKind::Bozo | PatternKind::Spotted => noise::noise(q, gen),
        PatternKind::Granite => noise::granite(q, gen),
        PatternKind::Agate { turb } => {
            let t = pat.turbulence.unwrap_or_default();
            agate(
                *turb,
                q,
                noise::turbulence(q, t.octaves, t.omega, t.lambda, gen),
            )
        }
        PatternKind::Wrinkles => noise::wrinkles(q, gen),
        PatternKind::Dents => noise::noise(q, gen).powi(3),
        PatternKind::Ripples(_) | PatternKind::Waves(_) => waves(pat, q),
        PatternKind::Crackle {
            form,
            metric,
            offset,
            solid,
        } => super::crackle::crackle(q, *form, *metric, *offset, *solid, gen),
        PatternKind::Cells => {
            noise::cell_value(q.x.floor() as i64, q.y.floor() as i64, q.z.floor() as i64)
        }
        PatternKind::MaterialMap(im, indices) => material_index(im, indices, q) as f64,
        PatternKind::Tiling(n) => super::tiling::value(*n, q),
        PatternKind::Quilted { c0, c1 } => {
            // Measured: a third of the cushion vector's component magnitudes.
            let v = quilted_vector(q, *c0, *c1);
            (v.x.abs() + v.y.abs() + v.z.abs()) / 3.0
        }
        PatternKind::Fractal(f) => fractal(f, (q.x, q.y)),
        PatternKind::DensityFile(d) => d.eval(q),
        PatternKind::Object(o) => o.inside(q) as u8 as f64,
        // Measured as gradient's: values above 1 are reduced first (2 and 3 give 0, 2.5 gives
        // 0.5, 1 stays 1; a density of 3 is no media at all).
        PatternKind::Function(f) => {
            if f.unsupported.is_some() {
                0.0
            } else {
                let v = f.eval(&[q.x, q.y, q.z]);
                if v > 1.0 {
                    fmod(v, 1.0)
                } else {
                    v
                }
            }
        }
        // Maps handle `average` themselves; as a plain value it is the middle.
        PatternKind::Unsupported | PatternKind::Average => 0.5,
    }
}

/// Radial's value before the wave: the angle about y from +x, in turns.
#[inline(always)]
fn radial(q: DVec3) -> f64 {
    let a = (-q.z).atan2(q.x) / TAU;
    a - a.floor()
}

/// Gradient's value before the wave. Measured: gradient x gives 0.3 at x = 1.3, 1 at 1, 0 at
/// 2, but 0.80009 at -9.2 (only values above 1 are reduced before the 1.00001 wrap).
#[inline(always)]
pub(super) fn gradient(q: DVec3, a: DVec3) -> f64 {
    let v = q.dot(a);
    if v > 1.0 && v < 2.0 {
        // fmod's exact result here (Sterbenz: v − 1 is exact for v in [1, 2]).
        v - 1.0
    } else if v > 1.0 {
        fmod(v, 1.0)
    } else {
        v
    }
}

/// A material map's palette index at `q` (0 off a `once` image).
fn material_index(im: &crate::scene::desc::ImageMap, indices: &[u8], q: DVec3) -> usize {
    super::pigment::image_pixel(im, q)
        .and_then(|i| indices.get(i))
        .map_or(0, |&i| i as usize)
}

/// Quilted's cushion vector at `q`: the offset d from the centre of q's unit cube times
/// (2/√3)·B(|d|), B the cubic Bézier through 0, `c0`, `c1`, 1. Measured with
/// scripts/measure_pattern.py and scripts/measure_normals.py (docs/textures.md): the pattern
/// value is a third of the vector's |x| + |y| + |z| and the normal is n + amount·vector, both
/// to the printed precision at random points in ±3 for several control pairs.
pub fn quilted_vector(q: DVec3, c0: f64, c1: f64) -> DVec3 {
    let d = q - q.floor() - DVec3::splat(0.5);
    let t = d.length();
    let s = 1.0 - t;
    let b = 3.0 * s * s * t * c0 + 3.0 * s * t * t * c1 + t * t * t;
    d * (b * 2.0 / 3f64.sqrt())
}

/// 1 where a unit normal's cosine with a direction is 1, 0.5 at right angles, 0 opposite:
/// linear in the angle (measured; not in the cosine).
fn angle_value(cos: f64) -> f64 {
    1.0 - cos.clamp(-1.0, 1.0).acos() / PI
}

/// Slope: the angle value of the surface normal against the direction (world space), scaled
/// so `lo` gives 0 and `hi` 1 (not clipped: the usual wrap follows); with `altitude` mixed
/// with the gradient `(q·â − lo)/(hi − lo)` in pattern space, the two weighted by the lengths
/// of the direction and the altitude vector. All measured with scripts/measure_slope.py.
fn slope(sl: &Slope, q: DVec3) -> f64 {
    let Some(s) = surface() else {
        return 0.0;
    };
    let d = if sl.point_at {
        sl.dir - s.point
    } else {
        sl.dir
    };
    let span = |v: f64, lo: f64, hi: f64| {
        if hi == lo {
            0.0
        } else {
            (v - lo) / (hi - lo)
        }
    };
    let v = span(
        angle_value(s.normal.dot(d.normalize_or_zero())),
        sl.lo,
        sl.hi,
    );
    match sl.altitude {
        Some((a, lo, hi)) if !sl.point_at => {
            let (wd, wa) = (sl.dir.length(), a.length());
            let g = span(q.dot(a.normalize_or_zero()), lo, hi);
            if wd + wa == 0.0 {
                0.0
            } else {
                (wd * v + wa * g) / (wd + wa)
            }
        }
        _ => v,
    }
}

/// Wood's rings under turbulence `amount`, v the vector turbulence at q. Measured: the rings'
/// x and y are x + sin(2π a.x (x + v.x)) and y + sin(2π a.y (y + v.y)).
fn wood(q: DVec3, amount: DVec3, v: DVec3) -> f64 {
    let x = q.x + (TAU * amount.x * (q.x + v.x)).sin();
    let y = q.y + (TAU * amount.y * (q.y + v.y)).sin();
    (x * x + y * y).sqrt()
}

/// Agate from the scalar turbulence t at q. Measured: (1/2 + sin(2π(1.1 z + 1.3 agate_turb
/// t))/2)^0.77, t with the pattern's octaves, omega and lambda.
fn agate(turb: f64, q: DVec3, t: f64) -> f64 {
    (0.5 + 0.5 * (TAU * (1.1 * q.z + 1.3 * (turb as f32 as f64) * t)).sin()).powf(0.77)
}

/// `values_warped4` of the noise patterns, whose samples' lattice walks go together; None
/// for the others. Always inlined: its one caller's other checks had it moved out of line.
#[inline(always)]
fn noise_values4(pat: &Pattern, qs: &[DVec3; 4]) -> Option<[f64; 4]> {
    let gen = pat.noise_generator;
    let raw = match &pat.kind {
        PatternKind::Bozo | PatternKind::Spotted => noise::noise4(*qs, gen),
        PatternKind::Dents => noise::noise4(*qs, gen).map(|v| v.powi(3)),
        PatternKind::Granite => noise::granite4(*qs, gen),
        PatternKind::Agate { turb } => {
            let t = pat.turbulence.unwrap_or_default();
            let ts = noise::turbulence4(*qs, t.octaves, t.omega, t.lambda, gen);
            std::array::from_fn(|k| agate(*turb, qs[k], ts[k]))
        }
        PatternKind::Wood => match &pat.turbulence {
            Some(t) if t.amount != DVec3::ZERO => {
                let vs = noise::turbulence_vec4(*qs, t.octaves, t.omega, t.lambda);
                std::array::from_fn(|k| wood(qs[k], t.amount, vs[k]))
            }
            _ => return None,
        },
        PatternKind::Marble => {
            let t = pat.turbulence?;
            let ts = noise::turbulence4(*qs, t.octaves, t.omega, t.lambda, gen);
            std::array::from_fn(|k| qs[k].x + t.amount.x * ts[k])
        }
        _ => return None,
    };
    let mut out = [0.0; 4];
    for (o, v) in out.iter_mut().zip(raw) {
        *o = shape_inline(pat, v);
    }
    Some(out)
}

/// A triangle wave of period 1 from 0 (at integers) to 1 (at half-integers).
fn tri(v: f64) -> f64 {
    let f = v - v.floor();
    if f < 0.5 {
        2.0 * f
    } else {
        2.0 - 2.0 * f
    }
}

/// `value_warped` at four points (a normal's samples): the same values, with z² + c
/// fractals' orbits stepped together (`fractal2_lanes`).
pub fn values_warped4(pat: &Pattern, qs: &[DVec3; 4]) -> [f64; 4] {
    if let PatternKind::Fractal(f) = &pat.kind {
        if f.magnet != 0 {
            return magnet_lanes4(f, qs.map(|q| (q.x, q.y))).map(|v| shape(pat, v));
        }
        if f.exponent == 2 {
            let ps = qs.map(|q| (q.x, q.y));
            let raw = if f.interior.0 == 1 {
                fractal2_lanes4::<true>(f, ps)
            } else {
                fractal2_lanes4::<false>(f, ps)
            };
            return raw.map(|v| shape(pat, v));
        }
    }
    if let Some(vs) = noise_values4(pat, qs) {
        return vs;
    }
    // Gradient normals (normal maps of gradients, slope maps) read four samples of a dot
    // product: `raw`'s call and dispatch per sample cost more than the pattern. Radial's
    // samples, likewise, are `raw`'s angle and `shape`.
    let mut out = [0.0; 4];
    match &pat.kind {
        PatternKind::Gradient(a) => {
            for (o, &q) in out.iter_mut().zip(qs) {
                *o = shape_inline(pat, gradient(q, *a));
            }
        }
        PatternKind::Radial => {
            for (o, &q) in out.iter_mut().zip(qs) {
                *o = shape_inline(pat, radial(q));
            }
        }
        _ => {
            for (o, &q) in out.iter_mut().zip(qs) {
                *o = value_warped(pat, q);
            }
        }
    }
    out
}

fn checker(q: DVec3) -> usize {
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
fn hexagon(q: DVec3) -> usize {
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
fn square(q: DVec3) -> usize {
    let ix = rem_euclid(q.x.floor(), 2.0) as usize;
    let iz = rem_euclid(q.z.floor(), 2.0) as usize;
    [[0, 3], [1, 2]][iz][ix]
}

/// Triangles of side 1 in the x-z plane, one side along x. In the skewed coordinates
/// u = x − z/√3, w = 2z/√3 each unit cell holds a lower and an upper triangle; the item depends
/// on (⌊w⌋ − ⌊u⌋) mod 3 and which half (measured: six items around every vertex).
fn triangular(q: DVec3) -> usize {
    let s3 = 3f64.sqrt();
    let u = q.x - q.z / s3;
    let w = 2.0 * q.z / s3;
    let (iu, iw) = (u.floor(), w.floor());
    let upper = (u - iu) + (w - iw) > 1.0;
    let d = rem_euclid(iw - iu, 3.0) as usize;
    [[0, 3], [2, 1], [4, 5]][d.min(2)][upper as usize]
}

/// The half-axis the point is nearest: +x, +y, +z, −x, −y, −z give items 0 to 5.
fn cubic(q: DVec3) -> usize {
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
fn brick(q: DVec3, size: DVec3, mortar: f64) -> usize {
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

/// POV-Ray's ten wave sources (points on the unit sphere) that ripples and waves spread from,
/// with each source's frequency in waves. Measured by scripts/measure_waves.py: with
/// `number_of_waves N` the pigment adds source N, whose own field (N·v_N − (N−1)·v_(N−1)) fits
/// sin(2π·d) for ripples and (0.4/f)·sin(2π·f·d) for waves with rms error below 1e-4.
pub const WAVE_SOURCES: [(DVec3, f64); 10] = [
    (DVec3::new(-0.60437, 0.49205, -0.62658), 0.91912),
    (DVec3::new(-0.55258, -0.24607, -0.79631), 0.96004),
    (DVec3::new(-0.44454, 0.62333, 0.64330), 0.43317),
    (DVec3::new(0.49659, 0.66894, 0.55309), 0.70930),
    (DVec3::new(-0.06437, -0.80595, -0.58848), 0.68919),
    (DVec3::new(0.24619, -0.91456, -0.32090), 0.99144),
    (DVec3::new(-0.66610, -0.59187, -0.45387), 0.78297),
    (DVec3::new(-0.52050, -0.38602, -0.76162), 0.40067),
    (DVec3::new(0.13794, -0.70465, -0.69602), 0.22967),
    (DVec3::new(0.56490, 0.72204, -0.39943), 0.16851),
];

/// Ripples and waves: the mean of circular waves from the ten sources. Frequency and phase
/// act inside the waves and then once more on the value like any pattern's (measured: both
/// match povray's 16-bit values only so).
fn waves(pat: &Pattern, q: DVec3) -> f64 {
    let sources = &WAVE_SOURCES[..wave_count(pat)];
    let mut sum = 0.0;
    for &(c, f) in sources {
        let d = (q - c).length();
        sum += match pat.kind {
            PatternKind::Ripples(_) => (TAU * (d * pat.frequency + pat.phase)).sin(),
            _ => 0.4 / f * (TAU * (f * d * pat.frequency + pat.phase)).sin(),
        };
    }
    0.5 + 0.5 * sum / sources.len() as f64
}

/// How many wave sources a ripples or waves pattern uses (`number_of_waves`).
pub fn wave_count(pat: &Pattern) -> usize {
    match pat.kind {
        PatternKind::Ripples(n) | PatternKind::Waves(n) => {
            (n as usize).clamp(1, WAVE_SOURCES.len())
        }
        _ => WAVE_SOURCES.len(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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

    fn pat(kind: PatternKind) -> Pattern {
        Pattern::new(kind)
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

    #[test]
    fn frequency_keeps_one_at_the_top_and_wraps_negatives() {
        let mut p = pat(PatternKind::Spherical);
        p.frequency = 2.0;
        assert!(value(&p, DVec3::ZERO) > 0.999);
        let mut g = pat(PatternKind::Gradient(DVec3::X));
        g.frequency = -1.5;
        g.phase = 0.3;
        // Measured with povray: gradient x, frequency -1.5, phase 0.3 at x = 1.4125.
        assert!((value(&g, DVec3::new(1.4125, 0.0, 0.0)) - 0.68125).abs() < 1e-4);
    }

    #[test]
    fn spiral2_matches_povray() {
        // scripts/measure_pattern.py 'spiral2 2.5' and 'spiral2 2.5 ramp_wave frequency 0.3
        // phase 0.1' at these points; 1e-6 is the 12 digits printed less rounding slack.
        let pts = [
            (DVec3::new(-0.7, 0.4, 1.3), 0.538982638, 0.480850412),
            (DVec3::new(0.3, -1.2, -0.45), 0.511916522, 0.323212532),
            (DVec3::new(0.0, 0.0, -0.35), 0.6, 0.310000010),
            (DVec3::new(1.7, 0.1, 0.2), 0.874790237, 0.531221554),
        ];
        // The parser truncates the arms as povray does.
        let tri = pat(PatternKind::Spiral2(2.0));
        let mut ramp = pat(PatternKind::Spiral2(2.0));
        ramp.wave = Wave::Ramp;
        ramp.frequency = 0.3;
        ramp.phase = 0.1;
        for (p, a, b) in pts {
            assert!((value(&tri, p) - a).abs() < 1e-6, "{p}: {}", value(&tri, p));
            assert!(
                (value(&ramp, p) - b).abs() < 1e-6,
                "{p}: {}",
                value(&ramp, p)
            );
        }
    }

    /// The noise patterns' four samples together are their values one at a time.
    #[test]
    fn noise_samples_together_are_the_values() {
        use crate::scene::pattern::Turbulence;
        let turb = Turbulence {
            amount: DVec3::new(0.7, 0.2, 0.1),
            ..Default::default()
        };
        let kinds = [
            PatternKind::Bozo,
            PatternKind::Spotted,
            PatternKind::Dents,
            PatternKind::Granite,
            PatternKind::Agate { turb: 1.6 },
            PatternKind::Marble,
            PatternKind::Wood,
            // Not noise, but with their own four-sample paths (`shape_inline`).
            PatternKind::Gradient(DVec3::new(0.3, 1.0, -0.7)),
            PatternKind::Radial,
        ];
        for kind in kinds {
            for (gen, turbulence, wave) in [
                (2, None, Wave::Ramp),
                (1, Some(turb), Wave::Sine),
                (3, Some(turb), Wave::Triangle),
            ] {
                let mut p = pat(kind.clone());
                (p.noise_generator, p.turbulence, p.wave) = (gen, turbulence, wave);
                p.frequency = 1.3;
                for n in 0..500 {
                    let t = n as f64 * 0.71;
                    let c = DVec3::new(t.sin() * 3.0, t * 0.01, t.cos() - 2.0);
                    let qs = [0.0, 0.003, -0.004, 0.2].map(|d| c + DVec3::new(d, 2.0 * d, -d));
                    let want = qs.map(|q| value_warped(&p, q).to_bits());
                    assert_eq!(values_warped4(&p, &qs).map(f64::to_bits), want, "{kind:?}");
                }
            }
        }
    }

    /// `warped`'s inline test keeps the point only where the whole warp would: no warps, and
    /// no turbulence or marble's and wood's own (zero turbulence too, which leaves it).
    #[test]
    fn warped_test_is_the_whole_warp() {
        use crate::scene::pattern::Turbulence;
        let turb = Turbulence {
            amount: DVec3::new(0.7, 0.2, 0.1),
            ..Default::default()
        };
        let still = Turbulence {
            amount: DVec3::ZERO,
            ..Default::default()
        };
        let kinds = [
            PatternKind::Wood,
            PatternKind::Marble,
            PatternKind::Granite,
            PatternKind::Agate { turb: 1.6 },
            PatternKind::Gradient(DVec3::X),
        ];
        for kind in kinds {
            for turbulence in [None, Some(turb), Some(still)] {
                let mut p = pat(kind.clone());
                p.turbulence = turbulence;
                for n in 0..200 {
                    let t = n as f64 * 0.37;
                    let q = DVec3::new(t.sin() * 5.0, t * 0.03 - 2.0, t.cos());
                    let bits = |v: DVec3| v.to_array().map(f64::to_bits);
                    assert_eq!(bits(warped(&p, q)), bits(warped_moved(&p, q)), "{kind:?}");
                }
            }
        }
    }

    #[test]
    fn waves_shape_the_value() {
        let mut g = pat(PatternKind::Gradient(DVec3::X));
        g.wave = Wave::Triangle;
        assert!((value(&g, DVec3::new(0.75, 0.0, 0.0)) - 0.5).abs() < 1e-9);
        g.wave = Wave::Scallop;
        assert!((value(&g, DVec3::new(0.5, 0.0, 0.0)) - 1.0).abs() < 1e-9);
        g.wave = Wave::Poly(2.0);
        assert!((value(&g, DVec3::new(0.5, 0.0, 0.0)) - 0.25).abs() < 1e-9);
    }
}
