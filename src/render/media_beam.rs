//! Light beams along a media stretch: where a ray crosses the edge of a spotlight's cone or a
//! cylinder light's tube (so that lit and unlit pieces are sampled apart), and which lights are
//! certainly dark on a piece, so that its samples need not ask them.
//!
//! The second is for speed only and must never change a picture: a light is left out of a
//! piece only where `Light::beam` is provably zero at every point of it, with a margin far
//! above the rounding of the sample points and of `beam`'s own arithmetic. Where that cannot
//! be shown (rays grazing a cone, the apex on the ray, cones wider than a half-space) the light
//! is kept and asked at every sample, as before.

use crate::math::DVec3;
use crate::scene::light::{Cone, Light};

/// Where the ray `origin + s·dir` (dir unit, 0 < s < len) crosses the edge of `light`'s
/// beam, if it has one.
pub(super) fn beam_cuts(light: &Light, origin: DVec3, dir: DVec3, len: f64, out: &mut Vec<f64>) {
    let v = origin - light.position;
    let (a, b, c, axis, spot) = match light.cone {
        Cone::Point => return,
        Cone::Spot {
            axis, cos_falloff, ..
        } => {
            let (ua, va) = (dir.dot(axis), v.dot(axis));
            let c2 = cos_falloff * cos_falloff;
            (
                ua * ua - c2,
                2.0 * (va * ua - c2 * v.dot(dir)),
                va * va - c2 * v.length_squared(),
                axis,
                true,
            )
        }
        Cone::Cylinder { axis, falloff, .. } => {
            let up = dir - axis * dir.dot(axis);
            let vp = v - axis * v.dot(axis);
            (
                up.length_squared(),
                2.0 * up.dot(vp),
                vp.length_squared() - falloff * falloff,
                axis,
                false,
            )
        }
    };
    if a.abs() < 1e-12 {
        return;
    }
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return;
    }
    let r = disc.sqrt();
    for s in [(-b - r) / (2.0 * a), (-b + r) / (2.0 * a)] {
        // A spotlight's cone has one nappe, in front of the light.
        if s > 0.0 && s < len && (!spot || (v + dir * s).dot(axis) > 0.0) {
            out.push(s);
        }
    }
}

/// The part `[lo, hi]` of the stretch `origin + s·dir`, `0 <= s <= len`, outside which
/// `light`'s beam is certainly zero (`dark_on` has proven both sides), or None where it is
/// zero on the whole stretch. Found from the beam's edge widened a little (so that the true
/// edge lies inside with room for rounding), then proven; where the proof fails the whole
/// stretch is returned, which only costs time.
pub(super) fn lit_span(light: &Light, origin: DVec3, dir: DVec3, len: f64) -> Option<(f64, f64)> {
    let whole = Some((0.0, len));
    let v = origin - light.position;
    // The roots of the widened edge's quadratic a·s² + b·s + c, and which side of them is
    // inside: between them, or from the first on, or up to the second.
    let (a, b, c, inside) = match light.cone {
        Cone::Point => return whole,
        Cone::Spot {
            axis, cos_falloff, ..
        } => {
            let cw = cos_falloff - WIDEN;
            if cw.is_nan() || cw <= 0.0 {
                return whole;
            }
            let (ua, va) = (dir.dot(axis), v.dot(axis));
            let c2 = cw * cw;
            let a = ua * ua - c2;
            let b = 2.0 * (va * ua - c2 * v.dot(dir));
            let c = va * va - c2 * v.length_squared();
            // Most rays miss most cones (media2: 36 spotlights): settled from the quadratic
            // alone, without `Line::new`'s and `spot_dark`'s three roots and two divisions.
            if a < -1e-9 && misses_cone(a, b, c, c2, v, origin, light.position, len) {
                return None;
            }
            // a > 0: the ray runs within the cone's angle, inside the front nappe from the
            // second root on (ua > 0) or up to the first (ua < 0).
            let side = if a < 0.0 {
                Side::Between
            } else if ua > 0.0 {
                Side::After
            } else {
                Side::Before
            };
            (a, b, c, side)
        }
        Cone::Cylinder { axis, falloff, .. } => {
            let up = dir - axis * dir.dot(axis);
            let vp = v - axis * v.dot(axis);
            let r = falloff * (1.0 + WIDEN) + WIDEN;
            (
                up.length_squared(),
                2.0 * up.dot(vp),
                vp.length_squared() - r * r,
                Side::Between,
            )
        }
    };
    let disc = b * b - 4.0 * a * c;
    let (lo, hi) = if a.abs() < 1e-9 || !disc.is_finite() {
        (0.0, len)
    } else if disc < 0.0 {
        // No edge crossing: inside everywhere or nowhere.
        match inside {
            Side::Between => (1.0, 0.0),
            _ => (0.0, len),
        }
    } else {
        let r = disc.sqrt();
        let (r1, r2) = {
            let (x, y) = ((-b - r) / (2.0 * a), (-b + r) / (2.0 * a));
            (x.min(y), x.max(y))
        };
        match inside {
            Side::Between => (r1, r2),
            Side::After => (r2, len),
            Side::Before => (0.0, r1),
        }
    };
    let (lo, hi) = (lo.max(0.0), hi.min(len));
    let line = Line::new(light, origin, dir);
    if lo.is_nan() || hi.is_nan() || lo > hi {
        return (!line.dark_on(0.0, len)).then_some((0.0, len));
    }
    let proven = (lo <= 0.0 || line.dark_on(0.0, lo)) && (hi >= len || line.dark_on(hi, len));
    if proven {
        Some((lo, hi))
    } else {
        whole
    }
}

/// Whether the widened cone's quadratic proves the beam zero on the whole stretch: a ray
/// steeper than the cone (`a < 0`, a = ua² − c2 with c2 = cw², cw the widened cosine) whose
/// quadratic Q(s) = ((v + s·dir)·axis)² − c2·|v + s·dir|² = a·s² + b·s + c stays below −E
/// everywhere, so |cos(angle to the axis)| < cw = cos_falloff − WIDEN at every point of the
/// line, both nappes. For speed only: a wrong "true" would change a picture, "false" costs
/// the longer proof (`Line::dark_on`).
///
/// Rounding: with V = Σ|v_i| >= |v| and dir, axis unit, |a| <= 1, |b| <= 4V, |c| <= 2V², and
/// a, b, c, b² − 4ac each carry at most ~600u·V² of error (u = 2^-53) against the exact
/// values of the same rounded v, dir, axis, c2; `slop` = 1e-11·V² is ~75 times that. The
/// code's a takes |dir|² as 1 (it is 1 ± 4u), which moves Q by at most 5u·len² on the
/// stretch: E's 1e-14·S² term (S >= len) covers it. a < −1e-9 keeps the exact a negative and
/// within a factor 2 of the rounded one, so disc + slop < −8|a|·E gives an exact maximum
/// −disc/(4a) < −E. Then c2·|w|² >= E' (E less the |dir| term) >= 1e-16·c2·S², so every
/// point is at least 1e-8·S from the light, where the sample points' rounding (within
/// ~7u·S of the line) turns the cosine by under 1e-7, well inside WIDEN.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn misses_cone(
    a: f64,
    b: f64,
    c: f64,
    c2: f64,
    v: DVec3,
    origin: DVec3,
    light: DVec3,
    len: f64,
) -> bool {
    let size = |u: DVec3| u.abs().element_sum();
    let vs = size(v);
    let scale = size(origin) + size(light) + len.abs() + vs;
    // A normal E (S > 1e-100) and finite slop and E; NaN fails every comparison.
    if !(scale > 1e-100 && scale < 1e100) {
        return false;
    }
    let e = (1e-14 + 1e-16 * c2) * scale * scale;
    let slop = 1e-11 * vs * vs;
    let disc = b * b - 4.0 * a * c;
    disc.is_finite() && disc + slop + 8.0 * a.abs() * e < 0.0
}

/// `s0 <= s1`, both numbers (NaN makes no claim).
fn ordered(s0: f64, s1: f64) -> bool {
    s0.partial_cmp(&s1).is_some_and(|o| o.is_le())
}

#[derive(Clone, Copy)]
enum Side {
    Between,
    After,
    Before,
}

/// How far `lit_span` widens a beam before proving its outside dark: a cosine 1e-6 lower, a
/// cylinder 1e-6 (relative and absolute) wider; far above `dark_on`'s margin, so the proof
/// holds at the widened edge except very near the light.
const WIDEN: f64 = 1e-6;

/// Relative margin of the darkness tests: the sample points and `beam` round at about 1e-16 of
/// the coordinates, so a point proven this far outside a beam is outside it in any rounding.
const MARGIN: f64 = 1e-9;

/// Whether `light`'s beam is certainly zero at every point `origin + s·dir` (dir unit) with
/// `s0 <= s <= s1`. False means "perhaps lit", never "lit".
#[cfg(test)]
fn dark_on(light: &Light, origin: DVec3, dir: DVec3, s0: f64, s1: f64) -> bool {
    Line::new(light, origin, dir).dark_on(s0, s1)
}

/// A ray against one light's beam, with what all its pieces share worked out once.
struct Line<'l> {
    light: &'l Light,
    origin: DVec3,
    dir: DVec3,
    /// origin − the light's position.
    v: DVec3,
    /// Where along the line the beam's edge function peaks (spotlights: f below, the least
    /// distance from the axis for cylinders); ±infinity where it only rises or falls.
    peak: f64,
}

impl<'l> Line<'l> {
    fn new(light: &'l Light, origin: DVec3, dir: DVec3) -> Line<'l> {
        let v = origin - light.position;
        let peak = match light.cone {
            Cone::Point => f64::NAN,
            Cone::Spot {
                axis, cos_falloff, ..
            } => {
                let k = dir.dot(axis) / cos_falloff;
                if k >= 1.0 {
                    f64::INFINITY
                } else if k <= -1.0 {
                    f64::NEG_INFINITY
                } else {
                    let p = v.dot(dir);
                    let q = (v.length_squared() - p * p).max(0.0).sqrt();
                    -p + k * q / (1.0 - k * k).sqrt()
                }
            }
            Cone::Cylinder { axis, .. } => {
                let up = dir - axis * dir.dot(axis);
                let vp = v - axis * v.dot(axis);
                let a = up.length_squared();
                if a > 1e-12 {
                    -up.dot(vp) / a
                } else {
                    f64::NAN
                }
            }
        };
        Line {
            light,
            origin,
            dir,
            v,
            peak,
        }
    }

    /// `dark_on` for this line. Inlined into `lit_span`: called out of line, its 16-byte loads
    /// of the line's fields straddled the 8-byte stores `Line::new` had just made (a
    /// store-forwarding stall, a fifth of this function's samples in media2).
    #[inline(always)]
    fn dark_on(&self, s0: f64, s1: f64) -> bool {
        if !ordered(s0, s1) {
            return false;
        }
        let (v, dir) = (self.v, self.dir);
        // Absolute rounding scale of everything computed below and of the sample points (sums
        // of the coordinates' magnitudes, which bound the lengths without square roots).
        let size = |u: DVec3| u.abs().element_sum();
        let scale = MARGIN
            * (size(self.origin)
                + size(self.light.position)
                + s0.abs()
                + s1.abs()
                + size(v + dir * s0)
                + size(v + dir * s1));
        match self.light.cone {
            Cone::Point => false,
            Cone::Spot {
                axis, cos_falloff, ..
            } => spot_dark(v, dir, axis, cos_falloff, self.peak.clamp(s0, s1), scale),
            Cone::Cylinder { axis, falloff, .. } => {
                cylinder_dark(v, dir, axis, falloff, (s0, s1), self.peak, scale)
            }
        }
    }
}

/// A spotlight gives nothing where cos(angle to its axis) <= cos_falloff. With
/// f(s) = w·axis − cos_falloff·|w| (w = v + s·dir, the point relative to the light), that is
/// f <= 0 (which also covers the rear nappe). For cos_falloff > 0, f is concave (a linear
/// function minus a multiple of a norm), so its greatest value on [s0, s1] is where f' = 0,
/// clamped to the piece (`top`): with x = s + v·dir and q the line's distance from the
/// light, f'(s) = dir·axis − cos_falloff·x/√(x² + q²) vanishes at x = k·q/√(1 − k²),
/// k = dir·axis / cos_falloff (for |k| < 1; otherwise f is monotonic). f is flat there, so
/// placing that point a little wrong changes the value found by far less than the margin;
/// near the light's apex f is near 0 and nothing is claimed.
fn spot_dark(v: DVec3, dir: DVec3, axis: DVec3, cf: f64, top: f64, m: f64) -> bool {
    if cf.is_nan() || cf <= 0.0 || top.is_nan() {
        return false;
    }
    let w = v + dir * top;
    let bound = w.dot(axis) - cf * w.length();
    // beam() compares cos(angle) = f/|w| + cf with cf; the margin `m` is at least MARGIN·|w|
    // anywhere on the piece (|w| is largest at an end), which keeps the cosine MARGIN below
    // cf, far beyond rounding.
    bound.is_finite() && bound < -m
}

/// A cylinder light gives nothing behind its plane or at distance >= falloff from its axis.
/// The distance from the axis is a convex function of s: its least value on [s0, s1] is at
/// the clamped vertex of its square, and it changes by at most |dir across the axis| per unit
/// of s, which bounds the error of placing that vertex.
fn cylinder_dark(
    v: DVec3,
    dir: DVec3,
    axis: DVec3,
    falloff: f64,
    (s0, s1): (f64, f64),
    vertex: f64,
    m: f64,
) -> bool {
    // Behind the light's plane at both ends, so everywhere between.
    if (v + dir * s0).dot(axis) < -m && (v + dir * s1).dot(axis) < -m {
        return true;
    }
    let up = dir - axis * dir.dot(axis);
    let vp = v - axis * v.dot(axis);
    let at = |s: f64| (vp + up * s).length();
    // The distance is Lipschitz with constant |up|: a vertex misplaced by ds costs at most
    // |up|·ds; where there is no vertex (the ray along the axis) the whole piece's change
    // is bounded the same way.
    let least = if vertex.is_nan() {
        at(s0) - up.length() * (s1 - s0) - m
    } else {
        at(vertex.clamp(s0, s1)) - m
    };
    least.is_finite() && least > falloff + m
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Transform;
    use crate::scene::desc::{LightDesc, LightKind};

    fn light(kind: LightKind, pos: DVec3, at: DVec3, radius: f64, falloff: f64) -> Light {
        let d = LightDesc {
            kind,
            point_at: at,
            radius: Some(radius),
            falloff: Some(falloff),
            ..LightDesc::at(pos)
        };
        Light::new(&d, &Transform::IDENTITY)
    }

    use crate::geom::test_rng::Lcg;

    /// Case `case` of the property tests: a spot (or, every third, a cylinder) light of random
    /// place, aim, radius and falloff, and a ray of random length from a random point, from
    /// the light itself (every fifth) or beyond its aim point (every fifth), running down the
    /// axis every seventh and, with `backwards`, up it the next.
    fn random_case(rng: &mut Lcg, case: u32, backwards: bool) -> (Light, DVec3, DVec3, f64) {
        let kind = if case % 3 == 2 {
            LightKind::Cylinder
        } else {
            LightKind::Spot
        };
        let pos = rng.vec(40.0);
        let at = pos + rng.vec(10.0);
        let radius = rng.next() * 3.0;
        let falloff = radius + rng.next() * 20.0;
        let l = light(kind, pos, at, radius, falloff);
        let origin = match case % 5 {
            0 => pos,
            1 => pos + (at - pos) * 3.0,
            _ => rng.vec(60.0),
        };
        let dir = match case % 7 {
            0 => (at - pos).normalize(),
            1 if backwards => -(at - pos).normalize(),
            _ => rng.vec(2.0).normalize(),
        };
        let len = rng.next() * 80.0;
        (l, origin, dir, len)
    }

    /// Every piece called dark has zero beam at each of many points along it (and the
    /// points exactly at its ends), over random spot and cylinder lights and rays, including
    /// rays through the apex and along the axis. Exact: a dark claim that is wrong anywhere
    /// would change a picture. Also checks that the test is not vacuous.
    #[test]
    fn dark_pieces_have_no_beam() {
        let mut rng = Lcg(7);
        let mut dark = 0;
        let mut total = 0;
        for case in 0..4000 {
            let (l, origin, dir, len) = random_case(&mut rng, case, false);
            let mut cuts = vec![0.0, len];
            beam_cuts(&l, origin, dir, len, &mut cuts);
            cuts.sort_by(f64::total_cmp);
            for w in cuts.windows(2) {
                total += 1;
                if !dark_on(&l, origin, dir, w[0], w[1]) {
                    continue;
                }
                dark += 1;
                for k in 0..=64 {
                    let s = w[0] + (w[1] - w[0]) * k as f64 / 64.0;
                    assert_eq!(l.beam(origin + dir * s), 0.0, "case {case} s {s}");
                }
                assert_eq!(l.beam(origin + dir * w[1]), 0.0, "case {case}");
            }
        }
        assert!(dark * 4 > total, "{dark} of {total} pieces dark");
    }

    /// Every point outside a light's `lit_span` has zero beam (exact: a wrong claim would
    /// change a picture), and the span is usually narrower than the stretch.
    #[test]
    fn beam_is_zero_outside_lit_span() {
        let mut rng = Lcg(11);
        let mut narrowed = 0;
        for case in 0..4000 {
            let (l, origin, dir, len) = random_case(&mut rng, case, true);
            let span = lit_span(&l, origin, dir, len);
            if span.is_none_or(|(lo, hi)| hi - lo < len) {
                narrowed += 1;
            }
            for k in 0..=400 {
                let s = len * (k as f64 / 400.0);
                let lit = span.is_some_and(|(lo, hi)| s >= lo && s <= hi);
                if !lit {
                    assert_eq!(l.beam(origin + dir * s), 0.0, "case {case} s {s} {span:?}");
                }
            }
        }
        assert!(narrowed > 2000, "{narrowed} spans narrowed");
    }

    /// `misses_cone` against the beam itself on the hardest rays: lines tangent to a
    /// spotlight's true cone (in the cone's tangent plane, so outside the nappe but for the
    /// touching point), moved out (or in) by relative gaps from 1e-13 to 1e-2, over random
    /// lights, distances from the apex of 1e-6 to 1e4 and tilts toward the generator. Every
    /// claim must leave the beam zero at the touching point and at many points around it and
    /// along the stretch, and `lit_span` must agree (None). Also not vacuous: clear misses
    /// are claimed.
    #[test]
    fn misses_cone_claims_only_dark_lines() {
        let mut rng = Lcg(23);
        let (mut claimed, mut clear) = (0, 0);
        let gaps = [
            -1e-3, -1e-7, 0.0, 1e-13, 1e-10, 1e-8, 1e-7, 1e-6, 2e-6, 1e-5, 1e-3, 1e-2,
        ];
        for case in 0..3000 {
            let pos = rng.vec(40.0);
            let aim = rng.vec(2.0).normalize();
            let falloff = 1.0 + rng.next() * 80.0;
            let l = light(LightKind::Spot, pos, pos + aim, falloff * 0.5, falloff);
            let Cone::Spot {
                axis, cos_falloff, ..
            } = l.cone
            else {
                unreachable!()
            };
            let sin_f = (1.0 - cos_falloff * cos_falloff).sqrt();
            // A unit normal to the axis: a generator g = cos·axis + sin·n, the cone's outward
            // normal across it, and the circumferential direction t.
            let n = axis.cross(rng.vec(2.0)).normalize();
            let t = axis.cross(n);
            let g = axis * cos_falloff + n * sin_f;
            let out = n * cos_falloff - axis * sin_f;
            let r = 10f64.powf(rng.next() * 10.0 - 6.0);
            let phi = (rng.next() * 2.0 - 1.0) * 1.5;
            let dir = (t * phi.cos() + g * phi.sin()).normalize();
            let gap = gaps[case % gaps.len()];
            let touch = pos + g * r + out * (gap * r);
            let back = rng.next() * 3.0 * r;
            let len = back + rng.next() * 3.0 * r;
            let origin = touch - dir * back;
            let v = origin - pos;
            let cw = cos_falloff - WIDEN;
            let (ua, va) = (dir.dot(axis), v.dot(axis));
            let c2 = cw * cw;
            let a = ua * ua - c2;
            let b = 2.0 * (va * ua - c2 * v.dot(dir));
            let c = va * va - c2 * v.length_squared();
            if gap >= 1e-3 && a < -1e-3 {
                clear += 1;
            }
            if !(a < -1e-9 && misses_cone(a, b, c, c2, v, origin, pos, len)) {
                continue;
            }
            claimed += 1;
            assert!(lit_span(&l, origin, dir, len).is_none(), "case {case}");
            assert_eq!(l.beam(touch), 0.0, "case {case} gap {gap}");
            for k in 0..=200 {
                let s = len * (k as f64 / 200.0);
                assert_eq!(l.beam(origin + dir * s), 0.0, "case {case} s {s}");
                let near = back + r * 1e-3 * (k as f64 / 100.0 - 1.0);
                assert_eq!(l.beam(origin + dir * near), 0.0, "case {case} near {near}");
            }
        }
        assert!(
            claimed * 4 > clear && clear > 300,
            "{claimed} claimed, {clear} clear"
        );
    }

    #[test]
    fn lit_pieces_are_not_dark() {
        let l = light(
            LightKind::Spot,
            DVec3::new(0.0, 10.0, 0.0),
            DVec3::ZERO,
            5.0,
            10.0,
        );
        // Down the axis: lit all the way.
        assert!(!dark_on(&l, DVec3::new(0.0, 5.0, 0.0), -DVec3::Y, 0.0, 4.0));
        // Across the cone below the light: lit in the middle only.
        assert!(!dark_on(
            &l,
            DVec3::new(-5.0, 0.0, 0.0),
            DVec3::X,
            0.0,
            10.0
        ));
        // Beside it and well away: dark.
        assert!(dark_on(&l, DVec3::new(-5.0, 0.0, 0.0), DVec3::X, 0.0, 3.0));
        // Behind the light (the rear nappe): dark.
        assert!(dark_on(&l, DVec3::new(0.0, 12.0, 0.0), DVec3::Y, 0.0, 10.0));
    }
}
