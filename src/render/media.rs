//! Media along a ray: what the particles of object and atmospheric `media` absorb, emit and
//! scatter between the ray's start and the surface it meets.
//!
//! Measured with povray 3.7 (tests/probes/media_*.pov, scripts/measure_media.sh):
//! - absorption a over a length d keeps exp(−a·d) of what lies behind, exactly;
//! - emission e over d adds e·d, each sample dimmed by what lies before it;
//! - on constant media, `samples` S behaves as S/2 + 1 equal steps, each step's emission
//!   dimmed by the steps in front of it (e over d with absorption a gives
//!   e·d/n · Σ exp(−a·d·i/n), i < n, to five digits for every S tried);
//! - scattering adds, per step, the light arriving there times the phase function
//!   (`Scattering::phase`) times the scattering colour, and dims like absorption times
//!   `extinction`.
//!
//! Samples are evenly spaced and never jittered: the same bytes for any thread count.

use crate::math::{DVec3, Ray};
use crate::scene::media::{Media, Scattering};
use crate::scene::object::{ObjKind, Object};

use super::media_beam::{beam_cuts, lit_span};
use super::pigment;
use super::trace::{Seen, TraceCtx, Tracer};

/// Media found along one stretch of a ray: each list once (CSG members share theirs).
pub type MediaSet<'a> = Vec<&'a [Media]>;

/// The media lists of the objects around `p` (innermost CSG members holding their own).
pub fn containing<'a>(tracer: &Tracer<'a>, p: DVec3, out: &mut MediaSet<'a>) {
    fn walk<'a>(o: &'a Object, p: DVec3, out: &mut MediaSet<'a>) {
        if !o.inside(p) {
            return;
        }
        match o.interior.as_deref() {
            Some(int) if int.has_media() => {
                let m: &'a [Media] = int.media();
                if !out.iter().any(|x| std::ptr::eq(*x, m)) {
                    out.push(m);
                }
            }
            _ => {
                if let ObjKind::Csg { children, .. } = &o.kind {
                    for c in children.iter() {
                        walk(c, p, out);
                    }
                }
            }
        }
    }
    tracer.scene.each_object_at(p, |o| walk(o, p, out));
}

/// The optical depth per unit length at `p`: absorption plus scattering's extinction, each
/// times its density.
fn extinction_at(media: &[&[Media]], p: DVec3) -> DVec3 {
    let mut sum = DVec3::ZERO;
    for m in media.iter().flat_map(|l| l.iter()) {
        let mut k = m.absorption;
        if let Some(s) = &m.scattering {
            k += s.color * s.extinction;
        }
        if k != DVec3::ZERO {
            // Where `density` answers ZERO early, k is finite and the product it stands for
            // ±0: k·(±0) is ±0, and adding ±0 to a sum that starts at +0 changes nothing.
            sum += k * density(m, p);
        }
    }
    sum
}

/// The product of the media's densities at `p`. Where the plan allows (`DensityPlan`), a
/// factor zero in every channel answers ZERO at once: the whole product would be ±0 in every
/// channel, which every caller treats as ZERO (with finite coefficients ±0 adds nothing), so
/// the costly factors are skipped where a cheap one is zero.
#[inline]
fn density(m: &Media, p: DVec3) -> DVec3 {
    if m.density.is_empty() {
        return DVec3::ONE;
    }
    if !m.plan.cut_on_zero {
        return m
            .density
            .iter()
            .fold(DVec3::ONE, |a, d| a * pigment::eval(d, p).rgb);
    }
    density_cut(m, p)
}

/// `density` under a plan that may stop at a zero factor.
#[inline(never)]
fn density_cut(m: &Media, p: DVec3) -> DVec3 {
    let plan = m.plan;
    let first = pigment::eval(&m.density[plan.first], p).rgb;
    if first == DVec3::ZERO {
        return DVec3::ZERO;
    }
    // The product in the written order, as without the plan (1·x is x, so starting from the
    // first factor's value is the same fold).
    let mut a = DVec3::ONE;
    for (i, d) in m.density.iter().enumerate() {
        a *= if i == plan.first {
            first
        } else {
            pigment::eval(d, p).rgb
        };
        if a == DVec3::ZERO {
            return DVec3::ZERO;
        }
    }
    a
}

/// The media whose sampling settings the whole stretch follows: the first one (measured:
/// an interior holding `media { samples 5 }` then `media { }` (samples 10) samples both in
/// three steps, and in six when the two are swapped).
fn leader<'m>(media: &[&'m [Media]]) -> Option<&'m Media> {
    media.iter().flat_map(|l| l.iter()).next()
}

/// How a stretch is sampled: in how many equal intervals, each taken in how many steps
/// (measured: `intervals 2` samples each half of a box as `intervals 1` samples the whole,
/// its own last h unsampled).
fn steps(media: &[&[Media]]) -> (u32, u32) {
    leader(media).map_or((1, 1), |m| (m.intervals.max(1), m.steps()))
}

/// What a light crossing `ray` from `t0` to `t1` (ray units) keeps through `media`.
///
/// Measured with a step of absorbing density moved through a box between a parallel light
/// and a wall (scripts/measure_media_shadow.sh): a shadow ray's stretch is sampled as a
/// viewing ray's is, from the shadowed point towards the light: n steps each weighing L/n,
/// step j the mean of the samples at j·h, (j + ½)·h and (j + 1)·h with h = L/(n + 1), so the
/// last h before the light is never sampled; absorption alone never splits a step.
pub fn transmittance(media: &[&[Media]], ray: &Ray, t0: f64, t1: f64) -> DVec3 {
    if !media
        .iter()
        .flat_map(|l| l.iter())
        .any(|m| m.extinguishes())
    {
        return DVec3::ONE;
    }
    let (intervals, n) = steps(media);
    let len = ray.dir.length();
    let span = (t1 - t0) / intervals as f64;
    let h = span / (n + 1) as f64;
    // Media without densities (fog-like atmospheres) have the same extinction everywhere:
    // asked once, then summed exactly as the samples would be.
    let uniform = media
        .iter()
        .flat_map(|l| l.iter())
        .all(|m| m.density.is_empty())
        .then(|| extinction_at(media, ray.origin));
    let mut depth = DVec3::ZERO;
    for i in 0..intervals {
        let start = t0 + span * i as f64;
        let at = |k: u32| {
            uniform.unwrap_or_else(|| extinction_at(media, ray.at(start + 0.5 * h * k as f64)))
        };
        // Ends shared by neighbouring steps count twice, middles once.
        depth += at(0) + at(2 * n);
        for j in 0..n {
            depth += at(2 * j + 1);
            if j > 0 {
                depth += 2.0 * at(2 * j);
            }
        }
    }
    exp3(-depth * (span * len / (3.0 * n as f64)))
}

/// `v.exp()`, with one `exp` where the channels are equal (grey media): the same argument
/// gives the same bits (±0 both give 1; NaN is never equal, so takes the three).
fn exp3(v: DVec3) -> DVec3 {
    if v.x == v.y && v.y == v.z {
        DVec3::splat(v.x.exp())
    } else {
        v.exp()
    }
}

impl<'a> Tracer<'a> {
    /// `seen` at distance `t` along `ray` (ray units, finite) as it arrives through `media`.
    pub(super) fn through_media(
        &self,
        media: &[&[Media]],
        ray: &Ray,
        t: f64,
        seen: Seen,
        ctx: &mut TraceCtx<'a>,
    ) -> Seen {
        let (intervals, n) = steps(media);
        let len = ray.dir.length();
        let dir = ray.dir / len;
        let scatters = media
            .iter()
            .flat_map(|l| l.iter())
            .any(|m| m.scattering.is_some_and(|s| s.color != DVec3::ZERO));
        // The stretch is cut where it enters and leaves spotlight and cylinder beams, each
        // piece sampled on its own (manual: lit intervals are sampled apart from unlit ones),
        // so that a narrow beam is not missed between samples.
        // The lights that may scatter here, each with the part of the stretch outside which
        // its beam is provably zero: a piece's samples ask only the lights whose part it
        // meets (media_beam; the others would answer zero, so no picture changes).
        let mut cuts = std::mem::take(&mut ctx.media_cuts);
        let mut lights = std::mem::take(&mut ctx.media_lights);
        let mut piece = std::mem::take(&mut ctx.media_piece);
        cuts.clear();
        cuts.extend([0.0, t * len]);
        lights.clear();
        if scatters {
            for (slot, light) in self.scene.lights.iter().enumerate() {
                // Measured: a shadowless light scatters nothing in media (a box of scattering
                // media lit only by one stays black; scripts/measure_media_shadow.sh).
                if light.media_interaction && !light.shadowless {
                    beam_cuts(light, ray.origin, dir, t * len, &mut cuts);
                    if let Some((lo, hi)) = lit_span(light, ray.origin, dir, t * len) {
                        lights.push((slot, lo, hi));
                    }
                }
            }
            cuts.sort_by(f64::total_cmp);
        }
        // Adaptive sampling (method 3) only from 3 samples up (manual); `aa_level` L splits a
        // step L - 1 times at most (measured: aa_level 1 never splits, the default 3 twice).
        let (levels, aa_threshold) = leader(media).map_or((0, 0.0), |m| {
            let adaptive = m.samples.0 >= 3;
            (
                if adaptive {
                    m.aa_level.saturating_sub(1)
                } else {
                    0
                },
                m.aa_threshold,
            )
        });
        let mut dimmed = (DVec3::ZERO, DVec3::ONE);
        let mut acc = Composite {
            kept: DVec3::ONE,
            added: DVec3::ZERO,
        };
        // Measured with a thin bump and a step of density moved through a box
        // (docs/media.md): a stretch is cut into `intervals` equal parts; each of a part's n
        // steps weighs L/n (L the part's length), but its samples lie at j·h, (j + 1/2)·h
        // and (j + 1)·h with h = L/(n + 1), so the last h of the part is never sampled; a
        // step is the mean of its three samples, or, where neighbouring samples' light
        // (summed over the channels) times L differs by more than aa_threshold, the mean of
        // its two halves sampled likewise.
        // The scatter list is taken from `ctx` once per stretch, not once per sample (a
        // take and a put back of three words around every sample). A nested stretch (none
        // today: shadow rays ask `transmittance`) would find an empty list and grow its own.
        let mut scatter = std::mem::take(&mut ctx.media_scatter);
        for w in cuts.windows(2).filter(|w| w[1] > w[0]) {
            let span = (w[1] - w[0]) / intervals as f64;
            let h = span / (n + 1) as f64;
            let weight = span / n as f64;
            let threshold = aa_threshold / span;
            piece.clear();
            // Samples reach no further than w[1] − h (the last h is never sampled).
            let last = w[1] - 0.5 * h;
            piece.extend(
                lights
                    .iter()
                    .filter(|&&(_, lo, hi)| last >= lo && w[0] <= hi)
                    .map(|&(slot, _, _)| slot),
            );
            let mut sample = |s: f64, ctx: &mut TraceCtx<'a>| {
                let p = ray.origin + dir * s;
                let mut sigma = DVec3::ZERO;
                let mut glow = DVec3::ZERO;
                // Each density is evaluated once here, also for the lights' scattering below.
                // The first scattering media stays out of the list (most samples meet one):
                // no copy of its settings per sample.
                let mut first: Option<(DVec3, &Scattering)> = None;
                scatter.clear();
                for m in media.iter().flat_map(|l| l.iter()) {
                    let rho = density(m, p);
                    if rho == DVec3::ZERO {
                        continue;
                    }
                    sigma += m.absorption * rho;
                    glow += m.emission * rho;
                    if let Some(sc) = &m.scattering {
                        sigma += sc.color * sc.extinction * rho;
                        if sc.color != DVec3::ZERO {
                            if first.is_none() {
                                first = Some((rho, sc));
                            } else {
                                scatter.push((rho, *sc));
                            }
                        }
                    }
                }
                if let Some(first) = first {
                    glow += self.in_scattered(first, &scatter, &piece, p, dir, ctx);
                }
                Sample::new(sigma, glow)
            };
            for i in 0..intervals {
                let start = w[0] + span * i as f64;
                let mut left = sample(start, ctx);
                for j in 0..n {
                    let a = start + h * j as f64;
                    let mid = sample(a + 0.5 * h, ctx);
                    let right = sample(a + h, ctx);
                    let step = refine(
                        a,
                        h,
                        [&left, &mid, &right],
                        levels,
                        threshold,
                        &mut sample,
                        ctx,
                    );
                    acc.added += acc.kept * step.glow() * weight;
                    // Uniform media give every step of a piece the same extinction: exp is
                    // asked once for it (the same argument gives the same bits).
                    let arg = -step.sigma() * weight;
                    if arg != dimmed.0 {
                        dimmed = (arg, exp3(arg));
                    }
                    acc.kept *= dimmed.1;
                    left = right;
                }
            }
        }
        ctx.media_scatter = scatter;
        ctx.media_cuts = cuts;
        ctx.media_lights = lights;
        ctx.media_piece = piece;
        let Composite { kept, added } = acc;
        Seen {
            rgb: seen.rgb * kept + added,
            clear: seen.clear * kept.max_element(),
        }
    }

    /// The light the media's scattering sends from `p` towards the viewer (the ray goes
    /// `dir` from the viewer): every light of `lights` (slots; the others give nothing here)
    /// reaching `p`, shadows included, times each
    /// scattering media's phase function, colour and density (`scatter`).
    fn in_scattered(
        &self,
        first: (DVec3, &Scattering),
        rest: &[(DVec3, Scattering)],
        lights: &[usize],
        p: DVec3,
        dir: DVec3,
        ctx: &mut TraceCtx<'a>,
    ) -> DVec3 {
        let mut out = DVec3::ZERO;
        for &slot in lights {
            let light = &self.scene.lights[slot];
            let Some(inc) = light.incidence(p) else {
                continue;
            };
            let mut lc = light.color * (light.fade(inc.dist) * inc.beam);
            if self.quality.shadows {
                if let Some(dist) = inc.shadow_dist {
                    lc *= self.light_seen(p, (slot, light), inc.l, dist, false, ctx);
                }
            }
            if lc == DVec3::ZERO {
                continue;
            }
            // The light travels along −l; the viewer lies along −dir.
            let cos = inc.l.dot(dir);
            let (rho, s) = first;
            out += lc * s.color * rho * s.phase(cos);
            for (rho, s) in rest {
                out += lc * s.color * *rho * s.phase(cos);
            }
        }
        out
    }
}

impl<'a> Tracer<'a> {
    /// `seen` after the stretch of `ray` up to `t` (outside solid objects): through the
    /// media of the objects around it and the atmosphere's.
    pub(super) fn media_segment(
        &self,
        ray: &Ray,
        t: f64,
        seen: Seen,
        ctx: &mut TraceCtx<'a>,
    ) -> Seen {
        let mut set = std::mem::take(&mut ctx.media_lists);
        set.clear();
        if self.scene.object_media {
            // The stretch crosses no surface: one point tells which objects hold it.
            containing(self, ray.at(t * 0.5), &mut set);
        }
        if !self.scene.media.is_empty() {
            set.push(&self.scene.media);
        }
        let out = if set.is_empty() {
            seen
        } else {
            self.through_media(&set, ray, t, seen, ctx)
        };
        ctx.media_lists = set;
        out
    }
}

/// What one sample of the media gives: extinction and light sent towards the viewer, both
/// per unit length.
///
/// Each vector sits in its own 32-byte slot. Packed (glow at byte 24), the sample closure
/// stored a `Sample` as 16 + 8 + 16 + 8 bytes and the settled step read `sigma.z` with a
/// 16-byte load at byte 16 that straddled two of those stores: a store-forwarding stall on
/// every sample. Apart, no load can cover two stores.
#[derive(Clone, Copy)]
struct Sample {
    sigma: Slot,
    glow: Slot,
}

/// A `DVec3` padded to 32 bytes (see `Sample`).
#[derive(Clone, Copy)]
#[repr(align(16))]
struct Slot(DVec3);

impl Sample {
    #[inline(always)]
    fn new(sigma: DVec3, glow: DVec3) -> Sample {
        Sample {
            sigma: Slot(sigma),
            glow: Slot(glow),
        }
    }

    #[inline(always)]
    fn sigma(&self) -> DVec3 {
        self.sigma.0
    }

    #[inline(always)]
    fn glow(&self) -> DVec3 {
        self.glow.0
    }
}

/// Front-to-back compositing of the steps along a stretch.
struct Composite {
    kept: DVec3,
    added: DVec3,
}

/// The mean light and extinction of a step [a, a + h] from its samples at its ends and
/// middle, halved while neighbouring samples' light differs by more than `threshold` and
/// `levels` remain.
///
/// Inlined, with the samples by reference: most steps are settled at once, and the caller
/// then reads the samples' fields as the sample closure stored them and keeps the mean in
/// registers. Copying a `Sample` by value moved it in 16-byte loads that straddled the
/// closure's 8- and 16-byte stores (a store-forwarding stall per sample).
#[inline(always)]
fn refine<'a, F: FnMut(f64, &mut TraceCtx<'a>) -> Sample>(
    a: f64,
    h: f64,
    [l, m, r]: [&Sample; 3],
    levels: u32,
    threshold: f64,
    sample: &mut F,
    ctx: &mut TraceCtx<'a>,
) -> Sample {
    let differ = |x: &Sample, y: &Sample| (x.glow() - y.glow()).abs().element_sum() > threshold;
    if levels == 0 || !(differ(l, m) || differ(m, r)) {
        return Sample::new(
            (l.sigma() + m.sigma() + r.sigma()) / 3.0,
            (l.glow() + m.glow() + r.glow()) / 3.0,
        );
    }
    halve(a, h, [l, m, r], levels, threshold, sample, ctx)
}

/// `refine`'s unsettled step: two more samples, each half refined on its own.
#[inline(never)]
fn halve<'a, F: FnMut(f64, &mut TraceCtx<'a>) -> Sample>(
    a: f64,
    h: f64,
    [l, m, r]: [&Sample; 3],
    levels: u32,
    threshold: f64,
    sample: &mut F,
    ctx: &mut TraceCtx<'a>,
) -> Sample {
    let half = 0.5 * h;
    let lm = sample(a + 0.25 * h, ctx);
    let mr = sample(a + 0.75 * h, ctx);
    let x = refine(a, half, [l, &lm, m], levels - 1, threshold, sample, ctx);
    let y = refine(
        a + half,
        half,
        [m, &mr, r],
        levels - 1,
        threshold,
        sample,
        ctx,
    );
    Sample::new((x.sigma() + y.sigma()) * 0.5, (x.glow() + y.glow()) * 0.5)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::color::Rgbft;
    use crate::scene::desc::{Pigment, PigmentKind};
    use crate::scene::media::DensityPlan;
    use crate::scene::pattern::{Pattern, PatternKind};

    fn mapped(kind: PatternKind, map: &[(f64, f64)]) -> Pigment {
        let mut p = Pigment::solid(Rgbft::BLACK);
        p.kind = PigmentKind::Mapped {
            pattern: Box::new(Pattern::new(kind)),
            map: map
                .iter()
                .map(|&(v, c)| (v, Rgbft::rgb(DVec3::new(c, 0.5 * c, -c))))
                .collect(),
        };
        p.take_generator(2);
        p
    }

    fn media(density: Vec<Pigment>) -> Media {
        let mut m = Media {
            absorption: DVec3::new(0.3, 0.2, 0.1),
            density,
            ..Media::default()
        };
        m.ready();
        m
    }

    /// The plan's early ZERO stands only where the written product is ±0 in every channel,
    /// and elsewhere gives the same bits; extinction sums are the same bits either way.
    #[test]
    fn density_cut_matches_the_full_product() {
        let m = media(vec![
            mapped(
                PatternKind::Wrinkles,
                &[(0.0, 0.0), (0.4, 0.0), (0.6, 1.0), (1.0, 2.0)],
            ),
            mapped(
                PatternKind::Spherical,
                &[(0.0, 0.0), (0.4, 1.0), (1.0, 1.0)],
            ),
            mapped(PatternKind::Bozo, &[(0.0, -1.0), (1.0, 1.0)]),
        ]);
        assert_eq!(
            m.plan,
            DensityPlan {
                cut_on_zero: true,
                first: 1
            }
        );
        let mut plain = m.clone();
        plain.plan = DensityPlan::default();
        let mut cut = 0;
        for i in 0..20_000u32 {
            let f = |k: u32| ((i.wrapping_mul(k) % 1000) as f64 / 1000.0 - 0.5) * 3.0;
            let p = DVec3::new(f(7919), f(104_729), f(15_485_863));
            let (a, b) = (density(&m, p), density(&plain, p));
            if a == DVec3::ZERO {
                assert_eq!(b, DVec3::ZERO, "at {p}");
                cut += 1;
            } else {
                assert_eq!(
                    a.to_array().map(f64::to_bits),
                    b.to_array().map(f64::to_bits)
                );
            }
            let (x, y) = (
                extinction_at(&[std::slice::from_ref(&m)], p),
                extinction_at(&[std::slice::from_ref(&plain)], p),
            );
            assert_eq!(
                x.to_array().map(f64::to_bits),
                y.to_array().map(f64::to_bits)
            );
        }
        assert!(cut > 1000, "{cut}");
    }

    /// A factor that may not be finite (a NaN or huge entry, an image) keeps the full product.
    #[test]
    fn density_plan_needs_finite_factors() {
        let sphere = || mapped(PatternKind::Spherical, &[(0.0, 0.0), (1.0, 1.0)]);
        for bad in [f64::NAN, 1e301, f64::INFINITY] {
            let m = media(vec![
                mapped(PatternKind::Bozo, &[(0.0, bad), (1.0, 1.0)]),
                sphere(),
            ]);
            assert!(!m.plan.cut_on_zero);
            let m = media(vec![
                mapped(PatternKind::Bozo, &[(bad, 0.0), (1.0, 1.0)]),
                sphere(),
            ]);
            assert!(!m.plan.cut_on_zero);
        }
        let mut m = media(vec![sphere(), sphere()]);
        assert!(m.plan.cut_on_zero);
        m.absorption = DVec3::new(f64::INFINITY, 0.0, 0.0);
        m.ready();
        assert!(!m.plan.cut_on_zero);
        // One density alone has nothing to skip.
        assert!(!media(vec![sphere()]).plan.cut_on_zero);
    }
}
