//! The light a surface point receives and reflects: which lights reach it after shadows
//! (`gather_lights`, once per hit for all texture layers) and one layer's diffuse, phong and
//! specular share of them (`layer_light`). Split from trace.rs, which shades the hit.

use crate::color::Rgbft;
use crate::math::{DVec3, Ray};
use crate::scene::desc::Finish;
use crate::scene::light::{Cone, Incidence, Light};
use crate::scene::object::Object;

use super::trace::{grain, point_seed, LitBy, TraceCtx, Tracer};

impl<'a> Tracer<'a> {
    /// The lights reaching `p` (after shadows) into `ctx.lit`, once per hit for all layers;
    /// `all` keeps those behind the surface too, `double` lights the surface from behind
    /// (`double_illuminate`). `gathering`: `p` was met by a radiosity gathering ray.
    pub(super) fn gather_lights(
        &self,
        p: DVec3,
        nf: DVec3,
        all: bool,
        obj: &Object,
        gathering: bool,
        ctx: &mut TraceCtx<'a>,
    ) {
        // Pushed to in place: nothing the shadow rays do reads `ctx.lit` (taking the Vec out
        // and putting it back cost ~26 instructions a hit); only the area lights' closure,
        // which borrows `ctx` itself, takes it out.
        ctx.lit.clear();
        self.gather_each(p, nf, all, obj, gathering, ctx, |lit, lb| lit.push(lb));
    }

    /// `gather_lights`' work: each light reaching `p`, in order, handed to `put` with the
    /// list it would be pushed to (`ctx.lit`, or the area lights' own while `ctx` is lent
    /// to their shadow rays). Every entry's `cos_n` is `nf·l` to the bit.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn gather_each(
        &self,
        p: DVec3,
        nf: DVec3,
        all: bool,
        obj: &Object,
        gathering: bool,
        ctx: &mut TraceCtx<'a>,
        mut put: impl FnMut(&mut Vec<LitBy>, LitBy),
    ) {
        let double = obj.double_illuminate;
        let groups = self.scene.light_sets.len() > 1;
        let set = &self.scene.light_sets[obj.light_set as usize];
        let q = self.quality;
        for (slot, light) in self.scene.lights.iter().enumerate() {
            if groups && !set.sees(light.group) {
                continue;
            }
            let Some(inc) = incidence(light, p) else {
                continue;
            };
            let l = inc.l;
            let spread = light.area.as_ref().is_some_and(|a| a.illumination);
            if spread && !light.shadowless && q.shadows && self.samples_area(light, gathering) {
                if let Some(dist) = inc.shadow_dist {
                    // `area_illumination`: every point of the array lights the surface from
                    // its own direction, with its share of the light, even where the
                    // array's centre is below the surface's horizon.
                    let mut lit = std::mem::take(&mut ctx.lit);
                    self.area_each(p, (slot, light), l, dist, ctx, |dir, d, seen| {
                        let lc = light.color * (light.fade(d) * inc.beam);
                        let cos_n = nf.dot(dir);
                        let back = cos_n <= 0.0 && double;
                        if (cos_n > 0.0 || all || back) && seen != DVec3::ZERO {
                            put(
                                &mut lit,
                                LitBy {
                                    color: lc * seen,
                                    l: dir,
                                    cos_n,
                                    shadowless: false,
                                    back,
                                    slot: slot as u32,
                                },
                            );
                        }
                    });
                    ctx.lit = lit;
                    continue;
                }
            }
            let cos_n = nf.dot(l);

            let back = cos_n <= 0.0 && double;
            if cos_n <= 0.0 && !all && !back {
                continue;
            }
            let mut lc = light.color * (light.fade(inc.dist) * inc.beam);
            if light.projected.is_some() && (light.shadowless || !q.shadows) {
                let dist = inc.shadow_dist.unwrap_or(f64::INFINITY);
                if self
                    .projected_dist(&Ray::new(p, l), dist, slot, ctx)
                    .is_none()
                {
                    continue;
                }
            }
            if !light.shadowless && q.shadows {
                if let Some(dist) = inc.shadow_dist {
                    // `light_seen`'s own first test, asked here: a point light without media
                    // attenuation (nearly every light) sends its shadow ray without that
                    // call's frame and arguments (~25 instructions a shadow ray).
                    lc = if light.area.is_none() && !light.media_attenuation {
                        // `l` one coordinate at a time: `incidence` stored it as three
                        // doubles, and the call's copy of it read x-y as one 16-byte load
                        // spanning two of those stores, which waited for them to reach the
                        // cache (6.6 % of `shade`'s samples on textures/pigments/warp1).
                        let l = crate::math::by_coordinates(&l);
                        self.shadowed(lc, p, l, dist, slot, ctx)
                    } else {
                        lc * self.light_seen(p, (slot, light), l, dist, gathering, ctx)
                    };
                    if lc == DVec3::ZERO {
                        continue;
                    }
                }
            }
            put(
                &mut ctx.lit,
                LitBy {
                    color: lc,
                    l,
                    cos_n,
                    shadowless: light.shadowless,
                    back,
                    slot: slot as u32,
                },
            );
        }
        if let Some(map) = self.photons {
            if let Some(c) = map.caustic(p, nf, obj, &mut ctx.photon_found) {
                // The photons' own `cos_n` is 1, not `nf·nf`.
                let cos_n = nf.dot(c.l);
                put(&mut ctx.lit, LitBy { cos_n, ..c });
            }
        }
    }

    /// One texture layer's own light: ambient and diffuse weighted by its opacity,
    /// highlights not. With radiosity, `indirect` (the irradiance there) replaces ambient:
    /// POV-Ray 3.7 ignores `ambient` then (measured: docs/povray-behaviour.md).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    pub(super) fn layer_light(
        &self,
        c: &Rgbft,
        fin: &Finish,
        p: DVec3,
        dir: DVec3,
        nf: DVec3,
        mirror: DVec3,
        indirect: Option<DVec3>,
        ctx: &TraceCtx<'a>,
        memo: Option<&mut SpecMemo>,
    ) -> DVec3 {
        let mut col = self.own_light(c, fin, indirect);
        if ctx.lit.is_empty() {
            return col;
        }
        let f = Factors::new(c, fin, p, dir, nf, mirror);
        if f.plain() {
            lights_add::<true>(&f, &ctx.lit, &mut col, memo);
        } else {
            lights_add::<false>(&f, &ctx.lit, &mut col, memo);
        }
        col
    }

    /// `gather_lights` then `layer_light` (no radiosity) for a hit whose only layer has the
    /// unperturbed normal `nf`: each light's share is added as its shadow ray answers, in the
    /// order `ctx.lit` would have held it, so the list is neither written nor read again
    /// (~30 instructions a light). The layer's colour `c` is found before the shadow rays,
    /// which neither read nor change what it depends on (the surface a slope pigment reads
    /// is set before both, and `plain_colour` leaves it as it found it). `ctx.lit` is left as
    /// it was: nothing but `layer_light` reads it, always after filling it for its own hit.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    pub(super) fn layer_light_direct(
        &self,
        c: &Rgbft,
        fin: &Finish,
        p: DVec3,
        dir: DVec3,
        nf: DVec3,
        mirror: DVec3,
        (obj, gathering): (&Object, bool),
        ctx: &mut TraceCtx<'a>,
    ) -> DVec3 {
        let mut col = self.own_light(c, fin, None);
        let f = Factors::new(c, fin, p, dir, nf, mirror);
        // `all` is false: the normal is not perturbed (the caller's `single_plain`).
        if f.plain() {
            self.gather_each(
                p,
                nf,
                false,
                obj,
                gathering,
                ctx,
                #[inline(always)]
                |_, lb| light_add::<true>(&f, &lb, lb.cos_n, &mut col, None),
            );
        } else {
            self.gather_each(
                p,
                nf,
                false,
                obj,
                gathering,
                ctx,
                #[inline(always)]
                |_, lb| light_add::<false>(&f, &lb, lb.cos_n, &mut col, None),
            );
        }
        col
    }

    /// A layer's ambient (or radiosity's `indirect`) and emission, by its colour and opacity.
    #[inline(always)]
    fn own_light(&self, c: &Rgbft, fin: &Finish, indirect: Option<DVec3>) -> DVec3 {
        let opacity = c.opacity();
        let ambient = fin.ambient * self.scene.ambient_light;
        let own = match (indirect, &self.rad) {
            (Some(e), Some(r)) if r.set.keep_ambient => ambient + e * fin.diffuse,
            (Some(e), _) => e * fin.diffuse,
            (None, _) => ambient,
        };
        (own + fin.emission) * c.rgb * opacity
    }
}

/// `Light::incidence`, with a point light's (most lights') written out: its beam is 1
/// everywhere, so the out-of-line `beam_from` call and the spills around it go. The same
/// operations in the same order (unit test `point_lights_incidence_is_lights_own`).
#[inline(always)]
fn incidence(light: &Light, p: DVec3) -> Option<Incidence> {
    if !matches!(light.cone, Cone::Point) || light.parallel.is_some() {
        return light.incidence(p);
    }
    let to_light = light.position - p;
    let dist = to_light.length();
    if dist <= 0.0 {
        return None;
    }
    Some(Incidence {
        l: to_light / dist,
        shadow_dist: Some(dist),
        dist,
        beam: 1.0,
    })
}

/// A layer's per-light constants, for `lights_add`.
struct Factors<'f> {
    c: &'f Rgbft,
    fin: &'f Finish,
    p: DVec3,
    dir: DVec3,
    nf: DVec3,
    mirror: DVec3,
    opacity: f64,
    diffuse: bool,
    phong: bool,
    specular: bool,
    specular_exp: f64,
    metallic: bool,
}

impl<'f> Factors<'f> {
    /// Decided once per layer, not per light. A factor that is exactly one (no irid, no
    /// metallic, no crand) is left out rather than multiplied in: x·1 is x to the bit.
    #[inline(always)]
    fn new(
        c: &'f Rgbft,
        fin: &'f Finish,
        p: DVec3,
        dir: DVec3,
        nf: DVec3,
        mirror: DVec3,
    ) -> Factors<'f> {
        let phong = fin.phong > 0.0;
        let specular = fin.specular > 0.0;
        Factors {
            c,
            fin,
            p,
            dir,
            nf,
            mirror,
            opacity: c.opacity(),
            diffuse: fin.diffuse > 0.0,
            phong,
            specular,
            specular_exp: if specular {
                1.0 / fin.roughness.max(1e-6)
            } else {
                0.0
            },
            metallic: fin.metallic != 0.0 && (phong || specular),
        }
    }

    /// Most finishes have neither irid nor crand nor a metallic highlight and a brilliance
    /// of 1: their loop is compiled without those branches (and without the crand hash's
    /// point seed, which the compiler hoisted out of the loop for every light-lit layer).
    #[inline(always)]
    fn plain(&self) -> bool {
        let fin = self.fin;
        fin.irid.is_none() && fin.crand == 0.0 && !self.metallic && fin.brilliance == 1.0
    }
}

/// Each gathered light's diffuse and highlight terms of one layer, added to `col`. `PLAIN`:
/// the finish has no irid, no crand, no metallic highlight and brilliance 1 (the caller
/// checked), so those branches are compiled out; the arithmetic is the same either way.
/// `memo`: the layer loop's half vectors and highlight powers, one slot per light of the first
/// `SPEC_MEMO_LIGHTS`, shared by the hit's layers.
#[inline(always)]
fn lights_add<const PLAIN: bool>(
    f: &Factors,
    lit: &[LitBy],
    col: &mut DVec3,
    memo: Option<&mut SpecMemo>,
) {
    match memo {
        None => {
            for lb in lit {
                light_add::<PLAIN>(f, lb, f.nf.dot(lb.l), col, None);
            }
        }
        Some(m) => {
            let mut slots = m.iter_mut();
            for lb in lit {
                light_add::<PLAIN>(f, lb, f.nf.dot(lb.l), col, slots.next());
            }
        }
    }
}

/// How many lights of a hit have a slot in `SpecMemo`.
pub(super) const SPEC_MEMO_LIGHTS: usize = 4;

/// Per light: the last half vector's input `l - dir` (its bits) and the half vector, and
/// the last highlight cosine and exponent (their bits) and the cosine raised to that
/// exponent. The layers of one hit see the same light from the same ray, so each layer made
/// the same half vector (a square root and a division); under the same finish and an
/// unperturbed normal they raise the same cosine to the same power. `normalize_or_zero` and
/// `powf` are functions of their arguments' bits, so the answers kept are the answers they
/// would give again. The start's keys are answered right too: `l - dir` = +0 has the half
/// vector 0, and the cosine 0 is never looked up (only cosines above 0 are raised).
#[derive(Clone, Copy)]
pub(super) struct SpecSlot {
    half_key: [u64; 3],
    half: DVec3,
    power_key: [u64; 2],
    power: f64,
}

/// The memo's slots, one per light of the first `SPEC_MEMO_LIGHTS`.
pub(super) type SpecMemo = [SpecSlot; SPEC_MEMO_LIGHTS];

/// A memo with nothing kept.
pub(super) const SPEC_MEMO_START: SpecMemo = [SpecSlot {
    half_key: [0; 3],
    half: DVec3::ZERO,
    power_key: [0; 2],
    power: 0.0,
}; SPEC_MEMO_LIGHTS];

/// `d.normalize_or_zero()`, through `slot` when there is one.
#[inline(always)]
fn half_vector(d: DVec3, slot: Option<&mut SpecSlot>) -> DVec3 {
    match slot {
        None => d.normalize_or_zero(),
        Some(s) => {
            let key = [d.x.to_bits(), d.y.to_bits(), d.z.to_bits()];
            if s.half_key == key {
                s.half
            } else {
                let h = d.normalize_or_zero();
                s.half_key = key;
                s.half = h;
                h
            }
        }
    }
}

/// `cos_h.powf(exp)`, through `slot` when there is one.
#[inline(always)]
fn spec_power(cos_h: f64, exp: f64, slot: Option<&mut SpecSlot>) -> f64 {
    match slot {
        None => cos_h.powf(exp),
        Some(s) => {
            let key = [cos_h.to_bits(), exp.to_bits()];
            if s.power_key == key {
                s.power
            } else {
                let v = cos_h.powf(exp);
                s.power_key = key;
                s.power = v;
                v
            }
        }
    }
}

/// One light's diffuse and highlight terms (`lights_add`); `cos_n` is `nf·l`, which the
/// caller may have at hand.
#[inline(always)]
fn light_add<const PLAIN: bool>(
    f: &Factors,
    lb: &LitBy,
    cos_n: f64,
    col: &mut DVec3,
    mut slot: Option<&mut SpecSlot>,
) {
    let (fin, c, p, dir, nf) = (f.fin, f.c, f.p, f.dir, f.nf);
    let (lc, l) = (lb.color, lb.l);
    // Iridescence scales the light's diffuse and highlight terms alike (measured).
    let lc_irid = match &fin.irid {
        Some(irid) if !PLAIN => lc * super::irid::factor(irid, p, cos_n, -dir.dot(nf)),
        _ => lc,
    };
    if f.diffuse {
        // The same as lb.cos_n unless the normal was perturbed; a light behind a
        // double-illuminated surface lights it as if from the front.
        let cos_n = if lb.back { -cos_n } else { cos_n };
        if cos_n > 0.0 {
            let d = if PLAIN || fin.brilliance == 1.0 {
                cos_n
            } else {
                cos_n.powf(fin.brilliance)
            };
            // crand darkens each light's diffuse term by its own random share
            // (measured with povray: independent per light, uniform, ambient untouched).
            // The share's hash is made here, for the few finishes with crand, not
            // for every light of every hit as it once was (`gather_lights` shades the
            // same point `p`, so the same seed).
            let k = if !PLAIN && fin.crand != 0.0 {
                let g = grain(point_seed(p), lb.slot);
                fin.diffuse * d * f.opacity * (1.0 - fin.crand * g)
            } else {
                fin.diffuse * d * f.opacity
            };
            *col += lc_irid * c.rgb * k;
        }
    }
    // POV-Ray 3.7 gives shadowless lights no highlights (tests/probes/shadowless_*),
    // nor lights behind a double-illuminated surface (tests/probes/double_illuminate).
    if lb.shadowless || lb.back || !(f.phong || f.specular) {
        return;
    }
    // Highlights take the surface colour in proportion to `metallic`, less so as the
    // light grazes the surface (measured: render::metallic).
    let lc_tint = if !PLAIN && f.metallic {
        lc_irid * super::metallic::tint(c.rgb, fin.metallic, cos_n)
    } else {
        lc_irid
    };
    if f.phong {
        let cos_r = f.mirror.dot(l);
        if cos_r > 0.0 {
            *col += lc_tint * (fin.phong * cos_r.powf(fin.phong_size));
        }
    }
    if f.specular {
        let hv = half_vector(l - dir, slot.as_deref_mut());
        let cos_h = nf.dot(hv);
        if cos_h > 0.0 {
            *col += lc_tint * (fin.specular * spec_power(cos_h, f.specular_exp, slot));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Transform;
    use crate::scene::desc::LightDesc;

    use crate::geom::test_rng::Lcg;

    fn bits(v: DVec3) -> [u64; 3] {
        v.to_array().map(f64::to_bits)
    }

    #[test]
    fn point_lights_incidence_is_lights_own() {
        let mut rng = Lcg(7);
        for case in 0..20_000 {
            let scale = [1e-3, 1.0, 1e4][case % 3];
            let light = Light::new(&LightDesc::at(rng.vec(2.0 * scale)), &Transform::IDENTITY);
            // Every seventh point is the light's own place (no incidence).
            let p = if case % 7 == 0 {
                light.position
            } else {
                rng.vec(2.0 * scale)
            };
            match (incidence(&light, p), light.incidence(p)) {
                (None, None) => {}
                (Some(a), Some(b)) => {
                    assert_eq!(bits(a.l), bits(b.l));
                    assert_eq!(a.dist.to_bits(), b.dist.to_bits());
                    assert_eq!(a.beam.to_bits(), b.beam.to_bits());
                    assert_eq!(
                        a.shadow_dist.map(f64::to_bits),
                        b.shadow_dist.map(f64::to_bits)
                    );
                }
                (a, b) => panic!("case {case}: {a:?} against {b:?}"),
            }
        }
    }

    #[test]
    fn the_plain_loop_is_the_general_loop() {
        let mut rng = Lcg(11);
        for case in 0..5_000 {
            let fin = Finish {
                diffuse: [0.0, 0.6, rng.next()][case % 3],
                phong: [0.0, rng.next()][case % 2],
                phong_size: 1.0 + 80.0 * rng.next(),
                specular: [0.0, rng.next()][(case / 2) % 2],
                roughness: 0.001 + rng.next() * 0.1,
                ..Finish::default()
            };
            let c = Rgbft::new(rng.next(), rng.next(), rng.next(), rng.next() * 0.3, 0.0);
            let nf = rng.vec(2.0).normalize();
            let dir = rng.vec(2.0).normalize();
            let lit: Vec<LitBy> = (0..case % 4)
                .map(|i| {
                    let l = rng.vec(2.0).normalize();
                    LitBy {
                        color: rng.vec(2.0).abs(),
                        l,
                        cos_n: nf.dot(l),
                        shadowless: i == 2,
                        back: i == 3 && case % 5 == 0,
                        slot: i as u32,
                    }
                })
                .collect();
            let f = Factors {
                c: &c,
                fin: &fin,
                p: rng.vec(20.0),
                dir,
                nf,
                mirror: dir - nf * (2.0 * dir.dot(nf)),
                opacity: c.opacity(),
                diffuse: fin.diffuse > 0.0,
                phong: fin.phong > 0.0,
                specular: fin.specular > 0.0,
                specular_exp: 1.0 / fin.roughness,
                metallic: false,
            };
            let (mut plain, mut general) = (DVec3::splat(0.1), DVec3::splat(0.1));
            lights_add::<true>(&f, &lit, &mut plain, None);
            lights_add::<false>(&f, &lit, &mut general, None);
            assert_eq!(bits(plain), bits(general), "case {case}");
            // Through a memo: first filled, then read back (the same layer again), then
            // after another exponent, normal or ray direction has replaced some slots.
            let mut memo = SPEC_MEMO_START;
            for round in 0..3 {
                let other = Factors {
                    specular_exp: f.specular_exp * 1.5,
                    nf: if case % 2 == 0 { -nf } else { nf },
                    dir: if case % 3 == 0 { -dir } else { dir },
                    ..f
                };
                let g = if round == 1 { &other } else { &f };
                let (mut memoed, mut plain) = (DVec3::splat(0.1), DVec3::splat(0.1));
                lights_add::<true>(g, &lit, &mut memoed, Some(&mut memo));
                lights_add::<true>(g, &lit, &mut plain, None);
                assert_eq!(bits(memoed), bits(plain), "case {case} round {round}");
            }
        }
    }
}
