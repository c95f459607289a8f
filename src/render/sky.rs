//! The sky_sphere's colour of a ray that reaches it: most skies are one plain colour or one
//! gradient under a small colour map, and the latter is evaluated here in one piece instead of
//! through `pigment::eval`'s calls to the pattern's function, its wave and the map lookup
//! (~100 instructions a ray of call overhead and results passed through memory).
//!
//! The fused path does exactly the general path's arithmetic in the same order: the sky
//! direction, the pigment's inverse transform, gradient's value, frequency, phase and wave,
//! then the colour map's entry pair and lerp, so the colour is the same to the bit.

use crate::color::Rgbft;
use crate::math::{by_coordinates, DVec3, Transform};
use crate::scene::desc::{ColorMap, Pigment, PigmentKind};
use crate::scene::pattern::{Pattern, PatternKind};

use super::{pattern, pigment};

/// The sky's direction of a ray. Not inlined into the plain colour's path: inlined there, the
/// compiler computed its square root and division for every ray before looking at the layers,
/// plain colours too (most skies).
#[inline(never)]
fn unit_sky(dir: DVec3) -> DVec3 {
    dir.normalize_or_zero()
}

/// The colour of a sky_sphere's only layer for a ray going `dir`, handed to `f` (the
/// background's blend) where it is made: a colour-map entry by reference to the map, not
/// through a joined stack copy. Apart from `layer_colour`: in the layers' loop the direction
/// is loop-invariant, and the compiler hoisted its square root and division above the plain
/// colour's test.
///
/// `dir` by reference: the gradient reads it by coordinates. It is the ray's own, which the
/// camera has just stored as an x-y pair and z; read whole, LLVM loaded x and a y-z pair,
/// which the store buffer cannot forward (the normalisation waited on it: ~10 % of
/// templates/Basic_Scenes/DarkBlueSky_Axes). The other paths copy it as before: `unit_sky`
/// takes its copy through memory, and a copy made of three loads was stored so that it read
/// a pair across two stores again (a pigment-mapped sky 4 % slower, legacy_sky's 10 %).
#[inline(always)]
pub(super) fn only_layer_with<R>(layer: &Pigment, dir: &DVec3, f: impl FnOnce(&Rgbft) -> R) -> R {
    match &layer.kind {
        PigmentKind::Solid(c) => f(c),
        PigmentKind::Mapped { pattern: pat, map } => match plain_gradient(pat) {
            Some(a) => mapped_gradient(
                layer,
                pat,
                a,
                map,
                by_coordinates(dir).normalize_or_zero(),
                f,
            ),
            None => f(&pigment::eval(layer, unit_sky(*dir))),
        },
        _ => f(&pigment::eval(layer, unit_sky(*dir))),
    }
}

/// One sky_sphere layer's colour for a ray going `dir`; `d`, the sky direction, is worked out
/// at most once per ray and only for a layer that is not a plain colour.
#[inline(always)]
pub(super) fn layer_colour(layer: &Pigment, dir: DVec3, d: &mut Option<DVec3>) -> Rgbft {
    match &layer.kind {
        PigmentKind::Solid(c) => *c,
        PigmentKind::Mapped { pattern: pat, map } => match plain_gradient(pat) {
            Some(a) => {
                let w = sky_direction(dir, d);
                mapped_gradient(layer, pat, a, map, w, |c| *c)
            }
            None => pigment::eval(layer, sky_direction(dir, d)),
        },
        _ => pigment::eval(layer, sky_direction(dir, d)),
    }
}

/// The sky direction `d` remembers for the ray, worked out on first use. Read by
/// coordinates: `unit_sky` returns it through memory as an x-y pair and z, and LLVM read it
/// back as x and a y-z pair, a load the store buffer cannot forward (29 % of `legacy_sky`'s
/// samples on interior/skysph1 sat right after it).
#[inline(always)]
fn sky_direction(dir: DVec3, d: &mut Option<DVec3>) -> DVec3 {
    by_coordinates(d.get_or_insert_with(|| unit_sky(dir)))
}

/// The axis of a gradient pattern that leaves its point where it is (no warps, no
/// turbulence: `pattern::warped`'s first test).
#[inline(always)]
fn plain_gradient(pat: &Pattern) -> Option<DVec3> {
    match pat.kind {
        PatternKind::Gradient(a) if pat.warps.is_empty() && pat.turbulence.is_none() => Some(a),
        _ => None,
    }
}

/// `pigment::eval` of a colour-mapped `plain_gradient` pigment at unit direction `w`, its
/// steps in the same order: the pigment's point, gradient's value, frequency, phase and wave,
/// the map's lookup.
#[inline(always)]
fn mapped_gradient<R>(
    layer: &Pigment,
    pat: &Pattern,
    a: DVec3,
    map: &ColorMap,
    w: DVec3,
    f: impl FnOnce(&Rgbft) -> R,
) -> R {
    let lp = if layer.transform.is_identity() {
        w
    } else {
        inv_point(&layer.transform, w)
    };
    let v = pattern::shape_inline(pat, pattern::gradient(lp, a));
    pigment::lookup_with(map, v, f)
}

/// `Transform::inv_point` written out: as a call, with the point and result passed through
/// memory, it was ~20 instructions a ray. The products and sums of glam's
/// `DMat4::transform_point3` in its order, lane for lane, so the same bits.
#[inline(always)]
fn inv_point(t: &Transform, p: DVec3) -> DVec3 {
    let m = &t.inv;
    let mut r = m.x_axis.truncate() * p.x;
    r = m.y_axis.truncate() * p.y + r;
    r = m.z_axis.truncate() * p.z + r;
    m.w_axis.truncate() + r
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::color::Rgbft;

    fn bits(c: Rgbft) -> [u64; 5] {
        c.to_array().map(f64::to_bits)
    }

    /// Directions all round, a few exactly on the axes.
    fn directions() -> Vec<DVec3> {
        let mut out = vec![DVec3::X, DVec3::Y, -DVec3::Y, DVec3::Z, DVec3::ZERO];
        for i in 0..400 {
            let (a, b) = (i as f64 * 0.37, i as f64 * 0.113);
            out.push(DVec3::new(
                a.cos() * b.sin(),
                b.cos() * 3.0,
                a.sin() * b.sin() * 0.5,
            ));
        }
        out
    }

    #[test]
    fn written_out_inverse_is_the_transforms() {
        let t = Transform::scale(DVec3::new(2.0, 3.0, 0.7))
            .then(&Transform::rotate(DVec3::new(10.0, -35.0, 71.0)))
            .then(&Transform::translate(DVec3::new(0.3, -1.0, 2.5)));
        for p in directions() {
            let (a, b) = (inv_point(&t, p), t.inv_point(p));
            assert_eq!(
                a.to_array().map(f64::to_bits),
                b.to_array().map(f64::to_bits)
            );
        }
    }

    #[test]
    fn gradient_skies_are_the_pigments() {
        use crate::scene::pattern::Wave;
        let c = |r: f64, g: f64, b: f64| Rgbft::rgb(DVec3::new(r, g, b));
        let maps: Vec<ColorMap> = vec![
            vec![
                (0.0, c(0.75, 0.8, 0.9)),
                (0.5, c(0.75, 0.8, 0.9)),
                (1.0, c(0.15, 0.3, 0.65)),
            ],
            vec![
                (0.0, c(1.0, 1.0, 1.0)),
                (0.4, c(0.1, 0.1, 0.5)),
                (0.6, c(0.1, 0.1, 0.5)),
                (1.0, c(1.0, 1.0, 1.0)),
            ],
            vec![
                (0.2, c(0.0, 0.0, 0.0)),
                (0.2, c(1.0, 0.0, 0.0)),
                (0.9, Rgbft::new(0.0, 1.0, 0.0, 0.3, 0.2)),
            ],
            vec![(0.5, c(0.3, 0.2, 0.1))],
        ];
        let xforms = [
            None,
            Some(Transform::scale(DVec3::splat(2.0)).then(&Transform::translate(-DVec3::Y))),
            Some(Transform::rotate(DVec3::new(30.0, 0.0, 12.0))),
        ];
        for map in &maps {
            for x in &xforms {
                for (freq, phase, wave) in [
                    (1.0, 0.0, Wave::Ramp),
                    (3.0, 0.25, Wave::Triangle),
                    (-1.5, 0.0, Wave::Sine),
                ] {
                    let mut pat = Pattern::new(PatternKind::Gradient(DVec3::new(0.0, 1.0, 0.2)));
                    pat.frequency = freq;
                    pat.phase = phase;
                    pat.wave = wave;
                    let mut layer = Pigment {
                        kind: PigmentKind::Mapped {
                            pattern: Box::new(pat),
                            map: map.clone(),
                        },
                        ..Pigment::solid(Rgbft::BLACK)
                    };
                    if let Some(t) = x {
                        layer.apply_transform(t);
                    }
                    for dir in directions() {
                        let want = pigment::eval(&layer, dir.normalize_or_zero());
                        assert_eq!(
                            bits(only_layer_with(&layer, &dir, |c| *c)),
                            bits(want),
                            "{dir}"
                        );
                        let mut d = None;
                        assert_eq!(bits(layer_colour(&layer, dir, &mut d)), bits(want), "{dir}");
                    }
                }
            }
        }
    }
}
