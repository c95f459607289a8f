//! Evaluating pigments at a world point: colour maps, pigment lists, pigment maps and image
//! maps over the pattern values of `render::pattern`.

use std::cell::Cell;
use std::f64::consts::PI;
use std::sync::atomic::{AtomicU64, Ordering};

use crate::color::Rgbft;
use crate::math::DVec3;
use crate::scene::desc::{ColorMap, ImageMap, Pigment, PigmentKind};
use crate::scene::pattern::{Pattern, PatternKind};

use super::pattern;

pub fn eval(p: &Pigment, world: DVec3) -> Rgbft {
    // Most pigments are plain colours, which need no point in pattern space.
    if let PigmentKind::Solid(c) = &p.kind {
        return *c;
    }
    // No transform at all answers without the matrix; most others are a scale or a
    // rotation, whose first entry is not 1 (`Transform::is_identity`), where the whole
    // comparison took ~58 instructions a pigment (mirror_spheres' sky).
    let lp = if p.transform.is_identity() {
        world
    } else {
        p.transform.inv_point(world)
    };
    match &p.kind {
        PigmentKind::Solid(c) => *c, // answered above
        PigmentKind::Mapped { pattern: pat, map } => {
            lookup(map, pattern::value_warped(pat, pattern::warped(pat, lp)))
        }
        PigmentKind::List {
            pattern: pat,
            items,
        } => {
            // The entries see the warped point (measured: see `pattern::warped`).
            let q = pattern::warped(pat, lp);
            let i = pattern::index_warped(pat, q).min(items.len().saturating_sub(1));
            items.get(i).map_or(Rgbft::BLACK, |item| eval(item, q))
        }
        PigmentKind::PigmentMap { pattern: pat, map } => {
            let q = pattern::warped(pat, lp);
            if matches!(pat.kind, PatternKind::Average) {
                return average(map, q);
            }
            pigment_map(map, pattern::value_warped(pat, q), q)
        }
        // Turbulence and warps move the point the image is looked up at (measured: warp1.pov).
        PigmentKind::ImageMap(im, Some(pat)) => image(im, pattern::warped(pat, lp)),
        PigmentKind::ImageMap(im, None) => image(im, lp),
    }
}

/// A pigment function's key to the per-thread memo of its last value, or `NONE` when the
/// pigment's colour is not a function of the point alone.
///
/// `Correct_Pigment_Gamma` (cantelop, blkhole, warp2, the `_37` woods) reads one pigment
/// function three times at the same point, once per colour component; the memo makes the
/// second and third reads a compare. Keys are numbered once per process, so a key never
/// names another pigment (an animation's later frame may put a new pigment at an old one's
/// address).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Memo(u64);

impl Memo {
    pub const NONE: Memo = Memo(0);

    /// A fresh key for `p` if its colour depends on the point alone: no slope or aoi (which
    /// read the surface being shaded, a thread-local), and no function or object pattern
    /// (checking what a function calls is not worth it for a memo).
    pub fn for_pigment(p: &Pigment) -> Memo {
        static NEXT: AtomicU64 = AtomicU64::new(1);
        if point_alone(p) {
            Memo(NEXT.fetch_add(1, Ordering::Relaxed))
        } else {
            Memo::NONE
        }
    }
}

/// Whether `p`'s colour is a function of the point alone (see [`Memo::for_pigment`]).
fn point_alone(p: &Pigment) -> bool {
    let pattern_alone = |pat: &Pattern| match &pat.kind {
        PatternKind::Slope(_)
        | PatternKind::Aoi
        | PatternKind::Function(_)
        | PatternKind::Object(_) => false,
        PatternKind::PigmentPattern(inner) => point_alone(inner),
        _ => true,
    };
    match &p.kind {
        PigmentKind::Solid(_) | PigmentKind::ImageMap(_, None) => true,
        PigmentKind::ImageMap(_, Some(pat)) | PigmentKind::Mapped { pattern: pat, .. } => {
            pattern_alone(pat)
        }
        PigmentKind::List {
            pattern: pat,
            items,
        } => pattern_alone(pat) && items.iter().all(point_alone),
        PigmentKind::PigmentMap { pattern: pat, map } => {
            pattern_alone(pat) && map.iter().all(|(_, p)| point_alone(p))
        }
    }
}

thread_local! {
    /// The last memoised pigment function's key, point bits and colour.
    static LAST: Cell<(u64, [u64; 3], Rgbft)> = const {
        Cell::new((0, [0; 3], Rgbft::BLACK))
    };
}

/// `eval(p, world)`, remembered per thread under `memo` (the key of `p`, or `Memo::NONE`).
pub fn eval_memo(p: &Pigment, memo: Memo, world: DVec3) -> Rgbft {
    if memo == Memo::NONE {
        return eval(p, world);
    }
    let bits = world.to_array().map(f64::to_bits);
    let (k, b, c) = LAST.with(|l| l.get());
    if k == memo.0 && b == bits {
        return c;
    }
    // Evaluated before the store: a pigment function read inside `p` stores its own entry.
    let c = eval(p, world);
    LAST.with(|l| l.set((memo.0, bits, c)));
    c
}

/// Whether the pigment's own pattern reads the surface normal (slope, aoi), so the caller
/// hands it the perturbed one.
pub fn uses_surface(p: &Pigment) -> bool {
    match &p.kind {
        PigmentKind::Mapped { pattern: pat, .. }
        | PigmentKind::List { pattern: pat, .. }
        | PigmentKind::PigmentMap { pattern: pat, .. } => pattern::uses_surface(pat),
        _ => false,
    }
}

/// `average`: every entry's pigment weighted by its value.
fn average(map: &[(f64, Pigment)], lp: DVec3) -> Rgbft {
    let total: f64 = map.iter().map(|e| e.0).sum();
    if total == 0.0 {
        return Rgbft::BLACK;
    }
    let mut sum = [0.0; 5];
    for (w, p) in map {
        for (s, v) in sum.iter_mut().zip(eval(p, lp).to_array()) {
            *s += v * w / total;
        }
    }
    Rgbft::from_array(sum)
}

/// Pigment map lookup: like a colour map, but only the one or two pigments that the value
/// falls between are evaluated.
fn pigment_map(map: &[(f64, Pigment)], v: f64, lp: DVec3) -> Rgbft {
    let Some(first) = map.first() else {
        return Rgbft::BLACK;
    };
    if v <= first.0 {
        return eval(&first.1, lp);
    }
    // As in `lookup`: at or past the last entry's value, the last entry.
    if let Some(last) = map.last().filter(|l| v >= l.0) {
        return eval(&last.1, lp);
    }
    for w in map.windows(2) {
        let (a, b) = (&w[0], &w[1]);
        if v <= b.0 {
            let span = b.0 - a.0;
            if span <= 0.0 {
                return eval(&b.1, lp);
            }
            let t = (v - a.0) / span;
            return eval(&a.1, lp).lerp(eval(&b.1, lp), t);
        }
    }
    map.last().map_or(Rgbft::BLACK, |l| eval(&l.1, lp))
}

/// Colour map lookup: flat beyond the first and last entries, linear in between.
pub fn lookup(map: &ColorMap, v: f64) -> Rgbft {
    lookup_inline(map, v)
}

/// `lookup` written into its caller (the sky's gradient: the call and the colour passed back
/// through memory were ~25 instructions a ray).
#[inline(always)]
pub(super) fn lookup_inline(map: &ColorMap, v: f64) -> Rgbft {
    lookup_with(map, v, |c| *c)
}

/// `lookup_inline` handing its colour to `f` where each answer is made: the sky's caller
/// blends it in at once, so no join copies the 40-byte colour to a stack slot that `f`
/// then reads back in other-sized pieces (a store-forwarding stall, ~9 % of `background`).
#[inline(always)]
pub(super) fn lookup_with<R>(map: &ColorMap, v: f64, f: impl FnOnce(&Rgbft) -> R) -> R {
    let Some(first) = map.first() else {
        return f(&Rgbft::BLACK);
    };
    if v <= first.0 {
        return f(&first.1);
    }
    // Measured (`function { pigment { } }` at exact entry values): where entries share a
    // value the earlier one gives the colour there, except at or past the last entry's value,
    // where the last entry does (mandel's inside, value 1, under `[1 rgb x+y][1 rgb 0]`).
    let Some(last) = map.last() else {
        return f(&Rgbft::BLACK);
    };
    if v >= last.0 {
        return f(&last.1);
    }
    // The first entry after the first whose value is at or above v. The parser sorts colour
    // maps, so a search finds the same entry as a walk from the front; woods.inc's maps have
    // 256 entries, where the walk was 3-5 % of a wood scene. Small maps keep the walk, as
    // does a map ending in NaN (sorted last, it breaks the search's order; so does v NaN,
    // which no entry is at or above).
    let i = if map.len() > SMALL_MAP && !last.0.is_nan() && !v.is_nan() {
        if map.len() <= COUNT_MAP {
            below_count(map, v)
        } else {
            first_at_or_above(map, v)
        }
    } else {
        // A plain loop: `iter().skip(1).position(..)` stayed an out-of-line call (~40
        // instructions a lookup in a three-entry map).
        let mut i = 1;
        while i < map.len() && !at_or_above(v, map[i].0) {
            i += 1;
        }
        if i == map.len() {
            return f(&last.1);
        }
        i
    };
    let (a, b) = (&map[i - 1], &map[i]);
    let span = b.0 - a.0;
    if span <= 0.0 {
        f(&b.1)
    } else {
        f(&a.1.lerp(b.1, (v - a.0) / span))
    }
}

/// Colour maps up to this many entries are walked from the front rather than searched.
const SMALL_MAP: usize = 8;

/// Sorted maps up to this many entries are searched by `below_count`, longer ones by
/// `first_at_or_above`'s guess.
const COUNT_MAP: usize = 24;

/// `first_at_or_above` by counting: in a sorted map the entries after the first that lie
/// below v are the ones before the least i ≥ 1 with v ≤ `map[i]`'s value (no value is NaN:
/// sorted, a NaN would be last), so i is one plus their number. Without a branch: the
/// uneven maps of stones.inc (its `[a, b colour colour]` ranges, 10-20 entries) mostly
/// missed the guess, and the bisection after it, a chain of dependent loads and mispredicted
/// branches, took ~3 % of stones1.
#[inline(always)]
fn below_count(map: &ColorMap, v: f64) -> usize {
    let n = map.len();
    1 + map[1..n - 1]
        .iter()
        .map(|e| (e.0 < v) as usize)
        .sum::<usize>()
}

/// Whether a map value x is at or above v (a NaN value is not: the walk passes it).
fn at_or_above(v: f64, x: f64) -> bool {
    v <= x
}

/// The least i ≥ 1 with v ≤ `map[i]`'s value, in a sorted map whose last value is above v.
/// Most big maps are evenly spaced (woods.inc's steps of 1/255), so the guess by v's place
/// between the ends is the entry or the one before it; farther off, a bisection of the side
/// it lies on (a chain of dependent loads, which the guess avoids).
fn first_at_or_above(map: &ColorMap, v: f64) -> usize {
    debug_assert!(map.windows(2).all(|w| w[0].0 <= w[1].0 || w[0].0.is_nan()));
    let n = map.len();
    let at = |i: usize| at_or_above(v, map[i].0);
    let (lo, hi) = (map[0].0, map[n - 1].0);
    // Saturating: NaN (an infinite end) and negatives give 0, clamped to 1.
    let g = (((v - lo) / (hi - lo) * (n - 1) as f64) as usize).clamp(1, n - 1);
    if at(g) {
        if g == 1 || !at(g - 1) {
            return g;
        }
        // In 1..g-1, and g - 1 qualifies.
        1 + map[1..g - 1].partition_point(|e| !at_or_above(v, e.0))
    } else if at(g + 1) {
        // g < n - 1: the last entry qualifies and g does not.
        g + 1
    } else {
        // In g+2..n, and the last entry qualifies.
        g + 2 + map[g + 2..].partition_point(|e| !at_or_above(v, e.0))
    }
}

/// The image map's colour at pattern-space point `lp` (also what image patterns read).
pub fn image(im: &ImageMap, lp: DVec3) -> Rgbft {
    let Some((u, v)) = image_uv(im, lp) else {
        return Rgbft::BLACK;
    };
    // `once` leaves the rest of the plane (or cylinder) clear; it means nothing on a sphere.
    let inside = (0.0..1.0).contains(&u) && (0.0..1.0).contains(&v);
    if im.once && im.map_type != 1 && !inside {
        return Rgbft::new(0.0, 0.0, 0.0, 0.0, 1.0);
    }
    let u = u - u.floor();
    let v = v - v.floor();
    let (w, h) = (im.width as f64, im.height as f64);
    if im.width == 0 || im.height == 0 {
        return Rgbft::BLACK;
    }
    let fx = u * w;
    let fy = (1.0 - v) * h;
    if im.interpolate == 2 || im.interpolate == 3 || im.interpolate == 4 {
        let x0 = (fx - 0.5).floor();
        let y0 = (fy - 0.5).floor();
        let (tx, ty) = (fx - 0.5 - x0, fy - 0.5 - y0);
        // The two columns and two rows wrapped once each, not once per corner: the four
        // corners were an out-of-line closure (its colour returned through memory), each with
        // two 64-bit remainders (interp: ~11 % of the time in the closure and its caller).
        let (c0, c1) = (wrap(x0, im.width), wrap(x0 + 1.0, im.width));
        let w = im.width as usize;
        let (r0, r1) = (wrap(y0, im.height) * w, wrap(y0 + 1.0, im.height) * w);
        let top = im.pixels.get(r0 + c0).lerp(im.pixels.get(r0 + c1), tx);
        let bottom = im.pixels.get(r1 + c0).lerp(im.pixels.get(r1 + c1), tx);
        return top.lerp(bottom, ty);
    }
    let xi = (fx as usize).min(im.width as usize - 1);
    let yi = (fy as usize).min(im.height as usize - 1);
    im.pixels.get(yi * im.width as usize + xi)
}

/// `(x as i64).rem_euclid(n)`: the pixel index x (a whole number) wrapped into 0..n (n > 0).
/// Inside the picture, where nearly every index is, without the division.
#[inline(always)]
fn wrap(x: f64, n: u32) -> usize {
    let i = x as i64;
    if (i as u64) < n as u64 {
        i as usize
    } else {
        i.rem_euclid(n as i64) as usize
    }
}

/// The pixel (row 0 at the top) a `material_map` reads at `lp`: the image's nearest pixel,
/// as an uninterpolated image map picks it. None off a `once` image or where the mapping has
/// no direction.
pub fn image_pixel(im: &ImageMap, lp: DVec3) -> Option<usize> {
    let (u, v) = image_uv(im, lp)?;
    let inside = (0.0..1.0).contains(&u) && (0.0..1.0).contains(&v);
    if (im.once && im.map_type != 1 && !inside) || im.width == 0 || im.height == 0 {
        return None;
    }
    let (u, v) = (u - u.floor(), v - v.floor());
    let xi = ((u * im.width as f64) as usize).min(im.width as usize - 1);
    let yi = (((1.0 - v) * im.height as f64) as usize).min(im.height as usize - 1);
    Some(yi * im.width as usize + xi)
}

/// The image coordinates (u, v) of pattern-space point `lp` under the map type, before
/// wrapping; None where a spherical map has no direction.
fn image_uv(im: &ImageMap, lp: DVec3) -> Option<(f64, f64)> {
    Some(match im.map_type {
        1 => {
            // Spherical: u starts at +x and runs towards +z (a -y rotation); v = 1 at +y.
            let d = lp.normalize_or_zero();
            if d == DVec3::ZERO {
                return None;
            }
            let mut u = d.z.atan2(d.x) / (2.0 * PI);
            if u < 0.0 {
                u += 1.0;
            }
            (u, 1.0 - d.y.clamp(-1.0, 1.0).acos() / PI)
        }
        2 => {
            let mut u = lp.z.atan2(lp.x) / (2.0 * PI);
            if u < 0.0 {
                u += 1.0;
            }
            (u, lp.y)
        }
        5 => {
            // Torus of major radius 1 in the x-z plane: u as cylindrical; v the angle around
            // the tube, 0.5 on the outer equator, growing upwards, the seam on the inner rim
            // (measured: scripts/measure_map_type.sh, probe image_map_torus).
            let mut u = lp.z.atan2(lp.x) / (2.0 * PI);
            if u < 0.0 {
                u += 1.0;
            }
            let r = (lp.x * lp.x + lp.z * lp.z).sqrt() - 1.0;
            let v = 0.5 + lp.y.atan2(r) / (2.0 * PI);
            (u, v)
        }
        _ => (lp.x, lp.y),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn color_map_interpolates_and_clamps() {
        let map = vec![(0.25, Rgbft::BLACK), (0.75, Rgbft::rgb(DVec3::ONE))];
        assert_eq!(lookup(&map, 0.0).rgb, DVec3::ZERO);
        assert!((lookup(&map, 0.5).rgb - DVec3::splat(0.5)).length() < 1e-12);
        assert_eq!(lookup(&map, 1.0).rgb, DVec3::ONE);
    }

    /// The walk from the front that `lookup` bisects instead on big maps.
    fn walked(map: &ColorMap, v: f64) -> Rgbft {
        if v <= map[0].0 {
            return map[0].1;
        }
        if v >= map[map.len() - 1].0 {
            return map[map.len() - 1].1;
        }
        for w in map.windows(2) {
            if v <= w[1].0 {
                let span = w[1].0 - w[0].0;
                return if span <= 0.0 {
                    w[1].1
                } else {
                    w[0].1.lerp(w[1].1, (v - w[0].0) / span)
                };
            }
        }
        map[map.len() - 1].1
    }

    fn mapped(kind: PatternKind, map: ColorMap) -> Pigment {
        Pigment {
            kind: PigmentKind::Mapped {
                pattern: Box::new(Pattern::new(kind)),
                map,
            },
            ..Pigment::solid(Rgbft::BLACK)
        }
    }

    #[test]
    fn remembered_colours_are_the_pigments() {
        let bits = |c: Rgbft| c.to_array().map(f64::to_bits);
        let ramp = |a: f64, b: f64| {
            vec![
                (0.0, Rgbft::rgb(DVec3::new(a, 0.0, 1.0))),
                (1.0, Rgbft::rgb(DVec3::new(b, 1.0, 0.5))),
            ]
        };
        let onion = mapped(PatternKind::Onion, ramp(0.1, 0.9));
        let bozo = mapped(PatternKind::Bozo, ramp(0.7, 0.2));
        let (m1, m2) = (Memo::for_pigment(&onion), Memo::for_pigment(&bozo));
        assert!(m1 != Memo::NONE && m2 != Memo::NONE && m1 != m2);
        // Reads that repeat a point, alternate the pigments and differ in one bit (-0.0).
        let mut points: Vec<DVec3> = (0..50)
            .map(|i| DVec3::new(i as f64 * 0.137, -0.3 * i as f64, 1.0 / (i + 1) as f64))
            .collect();
        points.extend([DVec3::ZERO, DVec3::new(-0.0, 0.0, 0.0), DVec3::ZERO]);
        for &p in &points {
            for (pig, memo) in [(&onion, m1), (&onion, m1), (&bozo, m2), (&onion, m1)] {
                assert_eq!(bits(eval_memo(pig, memo, p)), bits(eval(pig, p)), "{p}");
            }
        }
        // A pigment that reads the surface being shaded is never remembered.
        let aoi = mapped(PatternKind::Aoi, ramp(0.0, 1.0));
        assert_eq!(Memo::for_pigment(&aoi), Memo::NONE);
        let mut nested = mapped(PatternKind::Onion, ramp(0.0, 1.0));
        nested.kind = PigmentKind::List {
            pattern: Box::new(Pattern::new(PatternKind::Checker)),
            items: vec![onion.clone(), aoi],
        };
        assert_eq!(Memo::for_pigment(&nested), Memo::NONE);
    }

    #[test]
    fn wrapped_indices_are_the_remainders() {
        let mut xs = vec![
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            1e300,
            -1e300,
            2f64.powi(63),
        ];
        xs.extend((-700..700).map(|i| i as f64));
        xs.extend([
            -2f64.powi(32),
            2f64.powi(32),
            2f64.powi(32) + 5.0,
            -2f64.powi(53),
        ]);
        for n in [1u32, 2, 7, 320, 65535, u32::MAX] {
            for &x in &xs {
                let want = (x as i64).rem_euclid(n as i64) as usize;
                assert_eq!(wrap(x, n), want, "{x} in {n}");
            }
        }
    }

    #[test]
    fn bisected_maps_give_the_walks_colours() {
        // Exact: the same entry pair and the same lerp, so bits compare equal (NaN aside).
        let bits = |c: Rgbft| c.to_array().map(f64::to_bits);
        for (n, p) in [
            (1, 1),
            (2, 1),
            (8, 1),
            (9, 1),
            (9, 3),
            (16, 2),
            (20, 3),
            (24, 1),
            (24, 4),
            (25, 2),
            (30, 1),
            (256, 1),
            (40, 3),
            (100, 5),
        ] {
            // From -0.1 in steps of 1/7 (to the power p: uneven), every third entry repeated
            // (zero spans).
            let mut map: ColorMap = Vec::new();
            for i in 0..n {
                let x = -0.1 + ((i / 3 * 2 + i % 3 / 2) as f64 / 7.0).powi(p);
                map.push((
                    x,
                    Rgbft::rgb(DVec3::new(i as f64, (i * i) as f64, 1.0 / (i + 1) as f64)),
                ));
            }
            let mut probes: Vec<f64> = map.iter().map(|e| e.0).collect();
            let top = map[n - 1].0 + 0.2;
            probes.extend((0..2000).map(|k| -0.3 + k as f64 * (top + 0.3) / 2000.0));
            for v in probes {
                assert_eq!(
                    bits(lookup(&map, v)),
                    bits(walked(&map, v)),
                    "{n} entries, {v}"
                );
            }
            let nan = lookup(&map, f64::NAN);
            assert_eq!(bits(nan), bits(walked(&map, f64::NAN)), "{n} entries, NaN");
        }
    }
}
