//! Fog: colour added along every ray by the distance it travels, constant or thinning with
//! height above `fog_offset` (ground fog).
//!
//! Measured with povray 3.7 (tests/probes/fog_*.pov): a ray `d` long keeps
//! a = max(exp(−optical/distance), transmit) of what it saw, filtered by
//! 1 − filter + filter·fog colour, and gains (1 − a)·fog colour. Several fogs multiply what
//! is seen through them and add their colours, each unattenuated by the others (measured:
//! two constant fogs over one wall).

use std::cell::Cell;

use crate::color::Rgbft;
use crate::math::{DVec3, Ray};
use crate::scene::atmosphere::FogTurbulence;
use crate::scene::desc::{FogDesc, RainbowDesc};

use super::trace::Seen;

/// How far a ray that hits nothing runs through fog: povray's background is 2e10 away
/// (measured: a white fog of distance 1e10 over a black background gives 1 − e⁻² = 0.8647,
/// and 1.0 for every distance up to 1e9).
const FAR: f64 = 2e10;

/// `seen` along `ray` up to distance `t` (in units of the ray's direction; infinite for the
/// background), after every fog layer.
///
/// Inlined, with the colour handed on as four numbers: `Seen` by value went through a copy the
/// caller made with 16-byte loads, and the one of (rgb.z, clear) straddled the two 8-byte
/// stores that `shade` or the background had just made, a store-forwarding stall on every
/// fogged ray (half of `trace_seen`'s samples on fog_f). Scalars are loaded one by one.
#[inline(always)]
pub fn apply(fogs: &[FogDesc], ray: &Ray, t: f64, seen: Seen) -> Seen {
    apply_parts(fogs, ray, t, seen.rgb.x, seen.rgb.y, seen.rgb.z, seen.clear)
}

/// `apply` of the colour (r, g, b) with clearness `clear`.
#[inline(never)]
fn apply_parts(fogs: &[FogDesc], ray: &Ray, t: f64, r: f64, g: f64, b: f64, clear: f64) -> Seen {
    let len = ray.dir.length();
    let d = if t.is_finite() { t * len } else { FAR };
    // The unit direction only for the fogs that ask for it (rainbows, ground fog,
    // turbulence): a plain fog needs the length alone, and the three divisions were made for
    // every fogged ray. The same quotients whenever they are made.
    let mut unit = None;
    let mut dir = || *unit.get_or_insert_with(|| ray.dir / len);
    let mut added = DVec3::ZERO;
    // The rainbows' jitter depends on the direction only: hashed once per ray, by the first
    // rainbow with jitter (rainbow1's two rainbows hashed it twice).
    let mut jitter = None;
    // The colour and clearness in locals, the result built from them at the end: updated in
    // `seen` (passed and returned through memory), z's 8-byte store was read back at once by
    // the 16-byte copy of (z, clear) into the result, a store-forwarding stall (~20 % of
    // this function's time on nufog2).
    let (mut rgb, mut clear) = (DVec3::new(r, g, b), clear);
    for f in fogs {
        let color = match &f.rainbow {
            Some(rb) => match rainbow_color(rb, dir(), &mut jitter) {
                Some(c) => c,
                None => continue,
            },
            None => f.color,
        };
        let optical = depth_along(f, ray.origin, &mut dir, d);
        let optical = stirred(f, ray.origin, &mut dir, d, optical);
        let a = fade(-optical / f.distance).max(color.transmit);
        let fc = color.rgb;
        let mut filter = DVec3::splat(1.0 - color.filter) + fc * color.filter;
        if f.rainbow.is_some() {
            // A rainbow filters only by its own share (measured: an rgbf <1,0,0,0.8> rainbow
            // over a white wall leaves green a·(a + (1 − a)·0.2), where a fog leaves a·0.2).
            filter = DVec3::splat(a) + filter * (1.0 - a);
        }
        rgb *= filter * a;
        added += fc * (1.0 - a);
        clear *= a;
    }
    Seen {
        rgb: rgb + added,
        clear,
    }
}

/// What light travelling `d` along `ray` (unit direction) keeps through the fogs (not
/// rainbows): their `a` of `apply`, multiplied.
pub fn kept(fogs: &[FogDesc], ray: &Ray, d: f64) -> f64 {
    fogs.iter()
        .filter(|f| f.rainbow.is_none())
        .map(|f| {
            let optical = stirred(
                f,
                ray.origin,
                || ray.dir,
                d,
                depth_along(f, ray.origin, || ray.dir, d),
            );
            fade(-optical / f.distance).max(f.color.transmit)
        })
        .product()
}

/// `x.exp()`, without the call where it is exactly 0: every ray to the background of a
/// fog thinner than FAR/746 (below −745.14 the exponential is under half the least
/// subnormal and rounds to 0).
fn fade(x: f64) -> f64 {
    if x < -746.0 {
        0.0
    } else {
        x.exp()
    }
}

/// The fog a ray `d` long meets, before turbulence: its length, or for ground fog its
/// length times the mean density. Inlined: called, it read `dir`'s (y, z) as 16 bytes that
/// `apply` had just stored as (x, y) and z, a store-forwarding stall (nufog2). `dir` gives the
/// ray's unit direction, asked only for ground fog.
#[inline(always)]
fn depth_along(f: &FogDesc, origin: DVec3, dir: impl FnOnce() -> DVec3, d: f64) -> f64 {
    if f.ground {
        ground_depth(f, origin, dir(), d)
    } else {
        d
    }
}

/// The fog's depth `optical` along a ray `d` long after its turbulence. Measured (constant
/// and ground fog over a black wall, 16-bit, probe fog_turbulence): the depth shrinks by the
/// factor 1 − min(turb_depth·T, 1)·exp(−d/distance), T the scalar turbulence (marble's) at
/// turbulence ⊙ (the ray's midpoint); turb_depth scales the effect, it does not move the
/// point. Without the keyword nothing changes; with it, even <0,0,0> (T at the origin) does.
///
/// Far along a ray the factor is exactly 1 and T is not computed: |min(turb_depth·T, 1)| is
/// at most the fog's `reach` (max(1, |turb_depth|·`noise::turbulence_bound`), computed once
/// per fog when the scene is built), so when reach·exp(−d/distance) is at most 2^-55 the
/// rounded product is too, and 1 minus a number that small rounds to 1 (a sky plane 10000
/// away under a fog of distance 50: exp(−200)). An infinite reach fails the test and takes
/// the full formula; a NaN bound leaves reach 1, which still bounds min(NaN·…, 1) = 1.
///
/// `dir` gives the ray's unit direction, asked only where the fog has turbulence.
#[inline(always)]
fn stirred(f: &FogDesc, origin: DVec3, dir: impl FnOnce() -> DVec3, d: f64, optical: f64) -> f64 {
    let Some(tb) = f.turbulence.as_deref().filter(|t| t.on) else {
        return optical;
    };
    stir(tb, f.distance, origin, dir(), d, optical)
}

/// `stirred` of a fog with turbulence. Out of line: inlined into `apply`, its midpoint's
/// arithmetic was hoisted above the loop over the fogs and paid by every fogged ray.
#[inline(never)]
fn stir(tb: &FogTurbulence, distance: f64, origin: DVec3, dir: DVec3, d: f64, optical: f64) -> f64 {
    if !d.is_finite() || d >= FAR {
        return optical;
    }
    let fall = (-d / distance).exp();
    if tb.reach * fall <= NEGLIGIBLE {
        return optical;
    }
    let p = tb.amount * (origin + dir * (d * 0.5));
    let t = super::noise::turbulence(p, tb.octaves, tb.omega, tb.lambda, tb.noise_generator);
    optical * (1.0 - (tb.depth * t).min(1.0) * fall)
}

/// 2^-55: 1 − x and 1 + x round to 1 for any |x| up to here (half an ulp of 1 from below
/// is 2^-54).
const NEGLIGIBLE: f64 = 1.0 / (1u64 << 55) as f64;

/// A rainbow's colour for a ray going `dir` (unit); None where the ray misses the rainbow.
/// Out of line: inlined into `apply`, its jitter's hash of the direction was hoisted above the
/// loop over the fogs and computed for every fogged ray, rainbow or not (radiosity_37: ~80
/// instructions of each of its 127 k fogged rays).
///
/// Rays whose cosine to the rainbow's direction lies outside `cos_band` are certainly outside
/// its band, jitter included, and get None without the `acos` (most of rainbow1's rays).
#[inline(never)]
fn rainbow_color(rb: &RainbowDesc, dir: DVec3, jitter: &mut Option<f64>) -> Option<Rgbft> {
    let c = dir.dot(rb.direction).clamp(-1.0, 1.0);
    let (c_hi, c_lo) = rb.cos_band();
    if c < c_hi || c > c_lo {
        return None;
    }
    rainbow_color_at(rb, c, dir, jitter)
}

/// `rainbow_color` for a ray whose cosine to the direction is `c`, without the band test.
fn rainbow_color_at(
    rb: &RainbowDesc,
    c: f64,
    dir: DVec3,
    jitter: &mut Option<f64>,
) -> Option<Rgbft> {
    // Unit, and `up` perpendicular to it, since the scene was built.
    let d = rb.direction;
    let angle = c.acos().to_degrees();
    let mut index = (angle - (rb.angle - rb.width * 0.5)) / rb.width.max(1e-12);
    if rb.jitter != 0.0 {
        index += rb.jitter * (*jitter.get_or_insert_with(|| jitter_noise(dir)) - 0.5);
    }
    if !(0.0..=1.0).contains(&index) {
        return None;
    }
    let mut weight = 1.0;
    if rb.arc_angle < 360.0 {
        // The angle about the direction from `up`.
        let up = rb.up;
        let side = d.cross(up);
        let p = dir - d * dir.dot(d);
        let phi = p.dot(side).atan2(p.dot(up)).to_degrees().abs();
        let (arc, fall) = (rb.arc_angle * 0.5, rb.falloff_angle * 0.5);
        if phi > arc {
            return None;
        }
        if phi > fall {
            // A smoothstep over the soft end (measured: a white rainbow with arc_angle 180
            // and falloff_angle 0 shows 3t² − 2t³ of it, t = (arc − φ)/(arc − falloff)).
            let t = (arc - phi) / (arc - fall).max(1e-12);
            weight = t * t * (3.0 - 2.0 * t);
        }
    }
    // The soft ends raise the colour's transmit towards 1 (measured on a wall and on the
    // background: transmit' = 1 − w·(1 − transmit), w the smoothstep below).
    let mut c = super::pigment::lookup(&rb.color_map, index);
    c.transmit = 1.0 - weight * (1.0 - c.transmit);
    Some(c)
}

/// A number in [0, 1) from a direction, standing in for POV-Ray's random rainbow jitter.
fn jitter_noise(dir: DVec3) -> f64 {
    let q = |v: f64| ((v * 1e6).round() as i64) as u64;
    let mut h = q(dir.x) ^ q(dir.y).rotate_left(21) ^ q(dir.z).rotate_left(42);
    h = (h ^ (h >> 33)).wrapping_mul(0xff51_afd7_ed55_8ccd);
    h = (h ^ (h >> 33)).wrapping_mul(0xc4ce_b9fe_1a85_ec53);
    ((h ^ (h >> 33)) >> 11) as f64 / (1u64 << 53) as f64
}

/// The fog a ray meets: its length times the mean density between the heights it spans.
/// Density is 1 up to `fog_offset` and 1/(1 + ((h − offset)/alt)²) above: measured with
/// povray on level rays at many heights (the manual's 1/(1 + (h − offset)/alt)² is not what
/// it draws).
fn ground_depth(f: &FogDesc, origin: DVec3, dir: DVec3, d: f64) -> f64 {
    let h0 = origin.dot(f.up);
    let h1 = h0 + dir.dot(f.up) * d;
    let alt = f.alt.max(1e-10);
    // The density integrated from -∞ (up to a constant) to height h.
    let integral = |h: f64| {
        if h <= f.offset {
            h
        } else {
            f.offset + alt * ((h - f.offset) / alt).atan()
        }
    };
    if (h1 - h0).abs() < 1e-9 {
        let density = if h0 <= f.offset {
            1.0
        } else {
            let x = (h0 - f.offset) / alt;
            1.0 / (1.0 + x * x)
        };
        return d * density;
    }
    d * (integral(h1) - start_integral(h0, f.offset, alt, integral)) / (h1 - h0)
}

thread_local! {
    /// The last `integral(h0)` above the offset, keyed by the bits of (h0, offset, alt): all
    /// the gathering rays of a radiosity sample start at its point, and all camera rays at
    /// the camera, so their starting height repeats ray after ray (radiosity_37: 108 k
    /// gathering rays, 2 k samples). A key of zeros never matches (`alt` is at least 1e-10).
    static START: Cell<([u64; 3], f64)> = const { Cell::new(([0; 3], 0.0)) };
}

/// `integral(h0)`, its `atan` computed again only when the starting height or the fog
/// changed since the last ray: the same call on the same numbers, so the same bits.
#[inline(always)]
fn start_integral(h0: f64, offset: f64, alt: f64, integral: impl Fn(f64) -> f64) -> f64 {
    if h0 <= offset {
        return h0;
    }
    let key = [h0.to_bits(), offset.to_bits(), alt.to_bits()];
    START.with(|c| {
        let (k, v) = c.get();
        // Word by word: `k == key` compared the key's first 16 bytes in one load just after
        // they were stored 8 bytes at a time, a store-forwarding stall (~20 % of the ground
        // fog's time on nufog2).
        if (k[0] ^ key[0]) | (k[1] ^ key[1]) | (k[2] ^ key[2]) == 0 {
            return v;
        }
        let v = integral(h0);
        c.set((key, v));
        v
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The formula `stirred` skips the turbulence of, computed in full.
    fn stirred_in_full(f: &FogDesc, origin: DVec3, dir: DVec3, d: f64, optical: f64) -> f64 {
        let tb = f.turbulence.as_deref().unwrap();
        let p = tb.amount * (origin + dir * (d * 0.5));
        let t = crate::render::noise::turbulence(
            p,
            tb.octaves,
            tb.omega,
            tb.lambda,
            tb.noise_generator,
        );
        optical * (1.0 - (tb.depth * t).min(1.0) * (-d / f.distance).exp())
    }

    /// Far rays, whose turbulence is not computed, and near ones get the full formula's bits,
    /// for depths and omegas of both signs and large, every generator and a fog distance
    /// around the point where the shortcut starts.
    #[test]
    fn far_fog_without_turbulence_is_the_formula() {
        let mut skipped = 0;
        for (depth, omega, octaves, g) in [
            (0.5, 0.5, 6, 2),
            (-3.0, 0.7, 10, 1),
            (40.0, 2.5, 10, 3),
            (1e6, 1.3, 4, 2),
            (0.0, 0.5, 6, 2),
        ] {
            let mut tb = FogTurbulence {
                on: true,
                amount: DVec3::new(1.8, 1.8, 1.8),
                depth,
                octaves,
                omega,
                lambda: 2.0,
                noise_generator: g,
                reach: f64::INFINITY,
            };
            tb.set_reach();
            let f = FogDesc {
                distance: 50.0,
                turbulence: Some(Box::new(tb)),
                ..FogDesc::default()
            };
            for n in 0..3_000 {
                let t = n as f64 * 0.731;
                let origin = DVec3::new(t.sin() * 3.0, 1.0, t.cos() * 2.0 - 3.0);
                let dir = DVec3::new((t * 0.3).sin(), (t * 0.7).cos(), 0.5).normalize();
                // From 1 to about 10^5: across exp(-d/50) ~ 2^-55 and far beyond.
                let d = 10f64.powf(n as f64 / 600.0);
                let optical = d * 0.37;
                let full = stirred_in_full(&f, origin, dir, d, optical);
                let got = stirred(&f, origin, || dir, d, optical);
                assert_eq!(
                    got.to_bits(),
                    full.to_bits(),
                    "d {d} depth {depth} omega {omega}"
                );
                let reach = f.turbulence.as_deref().unwrap().reach;
                skipped += usize::from(reach * (-d / f.distance).exp() <= NEGLIGIBLE);
            }
        }
        // The shortcut is taken for a good share of the rays.
        assert!(skipped > 3_000, "{skipped}");
    }

    /// `rainbow_color`'s band test never changes an answer: against `rainbow_color_at` (the
    /// `acos` for every ray) bit for bit, for rainbows with odd angles, widths and jitters
    /// (zero, negative, huge, NaN, infinite), arcs, and rays spread over the sphere and
    /// packed close to each band edge.
    #[test]
    fn rainbow_band_test_is_the_full_colour() {
        let map = vec![
            (0.0, Rgbft::new(1.0, 0.5, 1.0, 1.0, 0.0)),
            (0.45, Rgbft::new(0.2, 1.0, 0.2, 0.8, 0.1)),
            (0.9, Rgbft::new(1.0, 0.2, 0.2, 1.0, 0.0)),
        ];
        let bits = |c: Option<Rgbft>| {
            c.map(|c| [c.rgb.x, c.rgb.y, c.rgb.z, c.filter, c.transmit].map(f64::to_bits))
        };
        let angles = [
            42.5,
            37.0,
            0.0,
            2.0,
            90.0,
            178.0,
            180.0,
            200.0,
            -5.0,
            f64::NAN,
            1e200,
        ];
        let widths = [5.0, 0.0, 1e-12, 40.0, -3.0, 400.0, f64::NAN, f64::INFINITY];
        let jitters = [0.0, 0.01, 1.0, 50.0, -0.3, f64::NAN, f64::INFINITY];
        let (mut skipped, mut shown) = (0, 0);
        for (k, &angle) in angles.iter().enumerate() {
            for &width in &widths {
                for &jitter in &jitters {
                    let direction = DVec3::new(-0.2, -0.2, 1.0).normalize();
                    let up = (DVec3::Y - direction * DVec3::Y.dot(direction)).normalize();
                    let mut rb = RainbowDesc {
                        direction,
                        angle,
                        width,
                        up,
                        arc_angle: if k % 2 == 0 { 360.0 } else { 200.0 },
                        falloff_angle: 120.0,
                        jitter,
                        color_map: map.clone(),
                        ..RainbowDesc::default()
                    };
                    rb.set_band();
                    // Angles to the direction: spread, and within 1e-6 degree of each edge.
                    let mut thetas: Vec<f64> = (0..400).map(|n| n as f64 * 0.45).collect();
                    let (w, s) = (width.max(1e-12), angle - width * 0.5);
                    for edge in [
                        s,
                        s + w,
                        s - w * jitter.abs() * 0.5,
                        s + w + w * jitter.abs() * 0.5,
                    ] {
                        for n in -50..=50 {
                            thetas.push(edge + n as f64 * 2e-8);
                        }
                    }
                    let side = direction.cross(up);
                    for (n, th) in thetas.into_iter().enumerate() {
                        let (th, phi) = (th.to_radians(), n as f64 * 0.37);
                        let dir =
                            direction * th.cos() + (up * phi.cos() + side * phi.sin()) * th.sin();
                        let c = dir.dot(rb.direction).clamp(-1.0, 1.0);
                        let want = rainbow_color_at(&rb, c, dir, &mut None);
                        let got = rainbow_color(&rb, dir, &mut None);
                        assert_eq!(
                            bits(got),
                            bits(want),
                            "angle {angle} width {width} jitter {jitter} theta {th}"
                        );
                        let (c_hi, c_lo) = rb.cos_band();
                        if c < c_hi || c > c_lo {
                            skipped += 1;
                        }
                        shown += usize::from(want.is_some());
                    }
                }
            }
        }
        // Both the shortcut and the colour are exercised.
        assert!(skipped > 50_000 && shown > 10_000, "{skipped} {shown}");
    }

    /// `ground_depth` with its remembered starting integral against the formula in full, for
    /// rays that share a start (as a sample's gathering rays do) and rays that do not, two
    /// fogs taking turns, heights below and above the offset.
    #[test]
    fn a_remembered_start_is_the_formula() {
        let fog = |offset: f64, alt: f64| FogDesc {
            ground: true,
            offset,
            alt,
            up: DVec3::Y,
            ..FogDesc::default()
        };
        let fogs = [fog(0.0, 1.3), fog(0.5, 0.7)];
        let full = |f: &FogDesc, origin: DVec3, dir: DVec3, d: f64| {
            let (h0, alt) = (origin.dot(f.up), f.alt.max(1e-10));
            let h1 = h0 + dir.dot(f.up) * d;
            let integral = |h: f64| {
                if h <= f.offset {
                    h
                } else {
                    f.offset + alt * ((h - f.offset) / alt).atan()
                }
            };
            d * (integral(h1) - integral(h0)) / (h1 - h0)
        };
        for n in 0..2_000 {
            let t = n as f64 * 0.613;
            // Five rays from each start, then a new one; the fogs alternate every ray.
            let s = (n / 5) as f64;
            let origin = DVec3::new(s.sin(), 1.2 * s.cos() + 0.4, s * 0.1);
            let dir = DVec3::new(t.sin(), (t * 1.7).cos(), 0.3).normalize();
            let f = &fogs[n % 2];
            let d = 0.5 + (t * 0.37).sin().abs() * 20.0;
            let want = full(f, origin, dir, d);
            if (dir.dot(f.up) * d).abs() >= 1e-9 {
                assert_eq!(ground_depth(f, origin, dir, d).to_bits(), want.to_bits());
            }
        }
    }
}
