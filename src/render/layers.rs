//! A hit's texture layers, top down: each layer's (or each weighted part's) own light,
//! its reflection's share and tint, and what passes through it, summed into `LayerSum` for
//! `Tracer::shade` (trace.rs), which then traces the reflected and transmitted rays.
//!
//! Split from trace.rs. The per-hit values every part reads travel in one `HitView` and the
//! sums in one `LayerSum`, so that a part is one call with a few pointers: as a closure
//! capturing each of them by reference, a hit stored ~26 pointers per layer before any
//! shading (ray21's finding, ~51 instructions a hit on mirror_spheres).

use crate::color::Rgbft;
use crate::math::{by_coordinates, DVec3, Transform};
use crate::scene::desc::{PigmentKind, Reflection, Texture};
use crate::scene::object::Object;

use super::lighting::{SpecMemo, SPEC_MEMO_START};
use super::trace::{fresnel, reflect, Path, TraceCtx, Tracer};
use super::{normal, texture_map};

/// What every layer of one hit shares, set once per hit.
pub(super) struct HitView<'h, 'a> {
    pub p: DVec3,
    /// The ray's unit direction.
    pub dir: DVec3,
    /// The surface normal facing the ray.
    pub nf: DVec3,
    /// `dir` reflected about `nf`.
    pub mirror: DVec3,
    /// −dir·nf, clamped to [0, 1].
    pub cos_i: f64,
    /// The iors on the ray's side and on the far side.
    pub n1: f64,
    pub n2: f64,
    pub entering: bool,
    pub obj: &'h Object,
    /// By reference: copied into the view, the option's 8-byte tag store was read back
    /// by a 16-byte load (a store-forwarding stall on every hit, ~2 % of mirror_spheres).
    pub uv: &'h Option<DVec3>,
    pub path: Path<'a>,
}

/// What the layers add up to. Measured with povray 3.7 (tests/probes/layered_*): each layer
/// lights its own colour weighted by what the layers above let through and by its own
/// opacity; its highlights only by what the layers above let through; reflections of all
/// layers add up unweighted; what passes every layer goes on through the object.
pub(super) struct LayerSum {
    /// The sums `Tracer::shade` traces on from.
    pub out: Layered,
    /// Reflections off perturbed normals go their own ways: (direction, tint·amount).
    /// Inline for the few a hit has: a heap Vec cost an allocation per such hit.
    pub bent: smallvec::SmallVec<[(DVec3, DVec3); 4]>,
    /// Radiosity's light at this point, gathered at most once (per normal with
    /// `normal on`), and only if some layer is diffuse.
    irr: Option<DVec3>,
    /// The current layer's colour, its parts' weighted sum.
    layer_c: [f64; 5],
    /// The layers' half vectors and highlight powers per light (`lighting::SpecMemo`).
    spec: SpecMemo,
}

impl LayerSum {
    pub(super) fn new() -> LayerSum {
        LayerSum {
            out: Layered::START,
            bent: smallvec::SmallVec::new(),
            irr: None,
            layer_c: [0.0; 5],
            spec: SPEC_MEMO_START,
        }
    }
}

/// What `Tracer::shade` traces the reflected and transmitted rays from: `LayerSum` without
/// the bent reflections (read from it in place) and the layer loop's own working values.
#[derive(Clone, Copy)]
pub(super) struct Layered {
    pub col: DVec3,
    pub through: DVec3,
    pub refl_amount: DVec3,
    pub refl_tinted: DVec3,
    /// Every reflection's tinted share, bent or not: what conserve_energy takes away.
    pub refl_all_tinted: DVec3,
    pub last: Rgbft,
    pub conserve: bool,
    /// `exponent`: what a reflection brings back is raised to this power first.
    pub refl_power: Option<f64>,
    /// The first perturbed normal met decides refraction.
    pub refract_n: Option<DVec3>,
}

impl Layered {
    /// Before any layer: nothing lit, everything let through.
    const START: Layered = Layered {
        col: DVec3::ZERO,
        through: DVec3::ONE,
        refl_amount: DVec3::ZERO,
        refl_tinted: DVec3::ZERO,
        refl_all_tinted: DVec3::ZERO,
        last: Rgbft::BLACK,
        conserve: false,
        refl_power: None,
        refract_n: None,
    };
}

/// Whether `shade_single` serves a hit on `top`: one plain layer that does not perturb the
/// normal (`bumpy`: some part of the texture does), and a mirror direction without NaN
/// (which equals nothing, so the general loop counts it a bent reflection). With radiosity
/// the one layer asks the irradiance at the unperturbed normal, as the loop's first part
/// would.
#[inline(always)]
pub(super) fn single_plain(top: &Texture, bumpy: bool, mirror: DVec3) -> bool {
    top.under.is_none() && top.pattern.is_none() && !bumpy && !mirror.is_nan()
}

impl<'a> Tracer<'a> {
    /// Every layer of `top` at the hit `hv`, into `sum` (fresh from `LayerSum::new`).
    pub(super) fn shade_layers(
        &self,
        top: &Texture,
        hv: &HitView<'_, 'a>,
        sum: &mut LayerSum,
        ctx: &mut TraceCtx<'a>,
    ) {
        let q = self.quality;
        for tex in top.layers() {
            // Under an opaque layer a layer's light and colour count nothing (`through` is
            // zero; transmission, `last` and `conserve` are only read when it is not), only
            // its reflection does: a layer that cannot reflect is not evaluated. Radiosity's
            // gathering has effects beyond this point, so it keeps every layer.
            if sum.out.through == DVec3::ZERO
                && self.rad.is_none()
                && !(q.reflection && texture_map::may_reflect(tex))
            {
                continue;
            }
            // A patterned texture is shaded as the plain textures it is made of here, each
            // weighted (texture_map blends); a plain one is itself with weight 1.
            sum.layer_c = [0.0; 5];
            // A plain layer (most are) is its own only part: called directly, not through
            // `blend`'s dynamic callback, so that `shade_part` is inlined for it.
            if tex.pattern.is_none() {
                let c = self.plain_layer_colour(tex, hv);
                self.shade_part(hv, sum, c, tex, &crate::math::IDENTITY, 1.0, ctx);
            } else {
                texture_map::blend(
                    tex,
                    hv.p,
                    *hv.uv,
                    q.quick_colors,
                    1.0,
                    &mut |c, part, space, w| self.shade_part(hv, sum, c, part, space, w, ctx),
                );
            }
            let c = Rgbft::from_array(sum.layer_c);
            sum.out.through *= c.transmitted();
            sum.out.last = c;
        }
    }

    /// A texture of one plain layer (no pattern, no layer under it, no normal perturbation)
    /// on a hit whose mirror direction is a number: `shade_layers` and
    /// `shade_part` with the weight 1 and nothing above the layer, written out with the
    /// sums in locals. In `LayerSum` (passed by reference, with its `SmallVec` of bent
    /// reflections) every sum lived in memory, initialised and read back on every hit.
    /// The same operations in the same order; products by the constant 1 and 1·x are
    /// folded by the compiler, which IEEE arithmetic allows (x·1 is x to the bit).
    /// The caller's test: `single_plain`.
    ///
    /// `direct`: the lights are not gathered yet, and are found and added here in one loop
    /// (`layer_light_direct`), `gathering` as `gather_lights` takes it. Only without
    /// radiosity: with it the caller gathers the lights first, and the irradiance is asked
    /// between them and their sum, as the layer loop asks it.
    #[inline(always)]
    pub(super) fn shade_single(
        &self,
        tex: &Texture,
        hv: &HitView<'_, 'a>,
        direct: Option<bool>,
        ctx: &mut TraceCtx<'a>,
    ) -> Layered {
        let q = self.quality;
        let fin = &tex.finish;
        let (w, through) = (1.0, DVec3::ONE);
        // A solid colour is read where the texture holds it: copied out, the copy's 16+16+8
        // byte stores were read back by the lighting's 8+16 byte loads (a store-forwarding
        // stall on every hit).
        let made;
        let c: &Rgbft = match &tex.pigment.kind {
            PigmentKind::Solid(c) if !q.quick_colors => c,
            _ => {
                made = self.plain_layer_colour(tex, hv);
                &made
            }
        };
        let light = match direct {
            Some(gathering) => self.layer_light_direct(
                c,
                fin,
                hv.p,
                hv.dir,
                hv.nf,
                hv.mirror,
                (hv.obj, gathering),
                ctx,
            ),
            None => {
                // `shade_part`'s choice with the normal unperturbed: with `normal on` or off
                // the irradiance is asked at `nf`, after the colour and before the lights, as
                // there.
                let indirect = match self.rad {
                    None => None,
                    Some(_) if fin.diffuse <= 0.0 => Some(DVec3::ZERO),
                    Some(_) => Some(self.indirect(hv.p, hv.nf, hv.path, ctx)),
                };
                self.layer_light(c, fin, hv.p, hv.dir, hv.nf, hv.mirror, indirect, ctx, None)
            }
        };
        let col = DVec3::ZERO + through * w * light;
        let mut out = Layered {
            col,
            through,
            conserve: fin.conserve_energy,
            ..Layered::START
        };
        let refl = &fin.reflection;
        if !refl.is_zero() && q.reflection {
            out.refl_power = refl.power();
            let (amount, tinted) = self.reflection_share(hv, refl, c.rgb, hv.cos_i, w);
            out.refl_all_tinted += tinted;
            out.refl_amount += amount;
            // The mirror direction is the unperturbed one and a number: never bent.
            out.refl_tinted += tinted;
        }
        let mut layer_c = [0.0; 5];
        for (l, v) in layer_c.iter_mut().zip(c.to_array()) {
            *l += v * w;
        }
        let c = Rgbft::from_array(layer_c);
        out.through *= c.transmitted();
        out.last = c;
        out
    }

    /// `plain_colour` of a plain layer at the hit. A solid colour (most pigments) is that
    /// answer itself: it takes the quick colour only with `quick_colors` and reads the
    /// surface or the point only for a patterned pigment. Without the call, its frame and
    /// the uv passed by reference (~50 instructions a hit).
    #[inline(always)]
    fn plain_layer_colour(&self, tex: &Texture, hv: &HitView<'_, 'a>) -> Rgbft {
        let quick = self.quality.quick_colors;
        match &tex.pigment.kind {
            PigmentKind::Solid(c) if !quick => *c,
            _ => texture_map::plain_colour(tex, hv.p, hv.uv, &crate::math::IDENTITY, quick),
        }
    }

    /// A reflection's share at a part of colour `rgb` and weight `w` whose normal meets the
    /// ray at cosine `pcos`: (amount, amount tinted by `metallic`).
    #[inline(always)]
    fn reflection_share(
        &self,
        hv: &HitView<'_, 'a>,
        refl: &Reflection,
        rgb: DVec3,
        pcos: f64,
        w: f64,
    ) -> (DVec3, DVec3) {
        // Where a ray leaves an object at a point still inside another object (a wall
        // plane whose inside holds the camera, say), POV-Ray takes the leaving object's
        // ior for both sides of the Fresnel term, which makes it zero; elsewhere the exit
        // is an ordinary glass-to-air interface. Measured: tests/probes.
        let f = if refl.min == refl.max {
            // The blend factor does not matter; skip the powf on this per-hit path.
            0.0
        } else if !refl.fresnel {
            (1.0 - pcos).powf(refl.falloff)
        } else if hv.entering || !self.scene.inside_other(hv.p, hv.obj) {
            fresnel(pcos, hv.n1, hv.n2)
        } else {
            0.0
        };
        let amount = (refl.min + (refl.max - refl.min) * f) * w;
        // Measured: the tint fades to white at glancing angles (render::metallic). Without
        // `metallic` the tint is white and amount·1 is amount to the bit.
        let tinted = if refl.metallic == 0.0 {
            amount
        } else {
            amount * super::metallic::tint(rgb, refl.metallic, pcos)
        };
        (amount, tinted)
    }

    /// One plain part of a layer, colour `c` with weight `w` (1 for a plain layer).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn shade_part(
        &self,
        hv: &HitView<'_, 'a>,
        sum: &mut LayerSum,
        c: Rgbft,
        part: &Texture,
        space: &Transform,
        w: f64,
        ctx: &mut TraceCtx<'a>,
    ) {
        let fin = &part.finish;
        // By coordinates: `shade` writes the view's vectors from their spill slots 8 bytes at
        // a time just before the layer loop, and `dir` and `nf` loaded as 16-byte pairs could
        // not be forwarded (2-2.5 % of normmap, densfile and slopemap on the first one).
        let (dir, nf) = (by_coordinates(&hv.dir), by_coordinates(&hv.nf));
        let (pn, pmirror, pcos) = match &part.normal {
            Some(nd) if normal::perturbs(part.normal.as_deref()) => {
                let pn = normal::perturb_in(nd, space, hv.p, nf);
                sum.out.refract_n.get_or_insert(pn);
                (pn, reflect(dir, pn), (-dir.dot(pn)).clamp(0.0, 1.0))
            }
            _ => (nf, hv.mirror, hv.cos_i),
        };
        let indirect = match self.rad {
            None => None,
            Some(_) if fin.diffuse <= 0.0 => Some(DVec3::ZERO),
            Some(r) if r.set.normal => Some(self.indirect(hv.p, pn, hv.path, ctx)),
            Some(_) => Some(
                *sum.irr
                    .get_or_insert_with(|| self.indirect(hv.p, nf, hv.path, ctx)),
            ),
        };
        let light = self.layer_light(
            &c,
            fin,
            hv.p,
            dir,
            pn,
            pmirror,
            indirect,
            ctx,
            Some(&mut sum.spec),
        );
        sum.out.col += sum.out.through * w * light;
        let refl = &fin.reflection;
        if !refl.is_zero() && self.quality.reflection {
            sum.out.refl_power = refl.power().or(sum.out.refl_power);
            let (amount, tinted) = self.reflection_share(hv, refl, c.rgb, pcos, w);
            sum.out.refl_all_tinted += tinted;
            sum.out.refl_amount += amount;
            if pmirror == hv.mirror {
                sum.out.refl_tinted += tinted;
            } else {
                // Measured (a sky coloured by direction seen in a plane with a steep normal
                // pattern, tests/probes/reflect_below_surface.pov): where the perturbed
                // normal faces away from the ray the reflection is the true surface's; a
                // perturbed reflection that would go into the surface is mirrored back out
                // across it.
                let below = pmirror.dot(nf);
                let d = if dir.dot(pn) >= 0.0 {
                    hv.mirror
                } else if below < 0.0 {
                    pmirror - nf * (2.0 * below)
                } else {
                    pmirror
                };
                sum.bent.push((d, tinted));
            }
        }
        for (l, v) in sum.layer_c.iter_mut().zip(c.to_array()) {
            *l += v * w;
        }
        sum.out.conserve = fin.conserve_energy;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::test_rng::Lcg;
    use crate::math::Ray;
    use crate::render::camera::Camera;
    use crate::render::trace::{Path, Quality};
    use crate::scene::build::{build, Scene};
    use crate::sdl::{ParseOptions, Parser};

    fn scene(text: &str) -> Scene {
        let mut p = Parser::new(ParseOptions::default());
        p.parse_str("test.pov", text).expect("test scene parses");
        build(&p.scene, 64, 48).scene
    }

    /// Single plain textures of every kind `shade_single` meets: reflections plain, with
    /// falloff, fresnel (from inside too) and metallic, conserve_energy, filter and transmit,
    /// phong, specular, brilliance and crand; a shadowless light, a shadowed one and an
    /// area light lighting from each of its points; a double-illuminated box.
    const SCENE: &str = "#version 3.7; global_settings { assumed_gamma 1.0 }
        camera { location <0, 2, -8> look_at 0 }
        light_source { <-6, 9, -7> rgb <1, 0.97, 0.92> }
        light_source { <7, 5, -3> rgb 0.3 shadowless }
        light_source { <1, 6, -2> rgb 0.4 area_light x, z, 3, 3 area_illumination on }
        plane { y, -1 pigment { checker rgb 0.8 rgb 0.1 } finish { reflection 0.08 } }
        sphere { <-2, 0, 0>, 1 pigment { rgbf <0.9, 0.9, 1, 0.8> }
          finish { reflection { 0.1, 0.9 fresnel on } conserve_energy phong 0.6 }
          interior { ior 1.5 } }
        sphere { <0, 0, 0>, 1 pigment { rgb <0.8, 0.6, 0.2> }
          finish { reflection { 0.5 metallic } phong 0.5 phong_size 40 metallic } }
        sphere { <2, 0, 0>, 1 pigment { rgbt <0.2, 0.5, 0.9, 0.3> }
          finish { specular 0.6 roughness 0.01 reflection { 0.2, 0.6 falloff 2 } } }
        box { <-3, -1, 2>, <3, 2, 3> pigment { rgb 0.5 }
          finish { brilliance 2 crand 0.2 diffuse 0.7 ambient 0.2 } double_illuminate }";

    fn bits(v: DVec3) -> [u64; 3] {
        v.to_array().map(f64::to_bits)
    }

    #[test]
    fn one_plain_layer_is_the_layer_loop() {
        let s = scene(SCENE);
        let camera = Camera::of_scene(&s);
        let tracer = Tracer::new(&s, &camera, false, Quality::level(9));
        let mut ctx = TraceCtx::default();
        let mut rng = Lcg(5);
        let mut checked = 0;
        for case in 0..6000 {
            // Rays from around the camera, and every third from inside the scene (some
            // from inside the glass sphere, leaving it).
            let origin = if case % 3 == 0 {
                rng.vec(4.0)
            } else {
                DVec3::new(0.0, 2.0, -8.0) + rng.vec(1.0)
            };
            let ray = Ray::new(origin, (rng.vec(2.0) + DVec3::new(0.0, -0.1, 0.9)) * 3.0);
            let Some(h) = s.first_hit(&ray, f64::INFINITY, &mut ctx) else {
                continue;
            };
            let p = ray.at(h.t);
            let dir = ray.dir.normalize();
            let n = h.obj.normal(p, &h);
            let entering = n.dot(dir) < 0.0;
            let nf = if entering { n } else { -n };
            let top = h.obj.texture_facing(&h, !entering);
            let mirror = reflect(dir, nf);
            let bumpy = normal::texture_perturbs(top);
            if !single_plain(top, bumpy, mirror) || top.uses_uv() {
                continue;
            }
            let (n1, n2) = if entering {
                (1.0, h.obj.ior)
            } else {
                (h.obj.ior, 1.0)
            };
            let hv = HitView {
                p,
                dir,
                nf,
                mirror,
                cos_i: (-dir.dot(nf)).clamp(0.0, 1.0),
                n1,
                n2,
                entering,
                obj: h.obj,
                uv: &None,
                path: Path::CAMERA,
            };
            tracer.gather_lights(p, nf, bumpy, h.obj, false, &mut ctx);
            let one = tracer.shade_single(top, &hv, None, &mut ctx);
            // The lights found and added in one loop: the same bits.
            let direct = tracer.shade_single(top, &hv, Some(false), &mut ctx);
            assert_eq!(bits(direct.col), bits(one.col), "case {case}");
            let mut sum = LayerSum::new();
            tracer.shade_layers(top, &hv, &mut sum, &mut ctx);
            assert!(sum.bent.is_empty(), "case {case}");
            let all = sum.out;
            for (a, b) in [
                (one.col, all.col),
                (one.through, all.through),
                (one.refl_amount, all.refl_amount),
                (one.refl_tinted, all.refl_tinted),
                (one.refl_all_tinted, all.refl_all_tinted),
            ] {
                assert_eq!(bits(a), bits(b), "case {case}");
            }
            let last = |c: Rgbft| c.to_array().map(f64::to_bits);
            assert_eq!(last(one.last), last(all.last), "case {case}");
            assert_eq!(one.conserve, all.conserve);
            assert_eq!(
                one.refl_power.map(f64::to_bits),
                all.refl_power.map(f64::to_bits)
            );
            assert!(one.refract_n.is_none() && all.refract_n.is_none());
            checked += 1;
        }
        assert!(checked > 2000, "{checked} hits checked");
    }
}
