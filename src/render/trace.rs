//! Whitted ray tracing with POV-Ray 3.7's shading rules.
//!
//! Measured against the `povray` binary on minimal scenes (see tests/shading.rs): the surface's
//! own light (ambient, diffuse) is weighted by 1 − filter − transmit while highlights are not;
//! light passing through is rgb·filter + transmit of the traced colour; shadow rays are filtered
//! at every surface crossing; shadowless lights make no highlights; rays past max_trace_level
//! return black.

use crate::math::{DVec3, Ray};
use crate::scene::build::Scene;
use crate::scene::desc::{Interior, Texture};
use crate::scene::object::{Scratch, SurfaceHit};
pub use crate::scene::scratch::LitBy;
use crate::scene::scratch::SkyKey;

use super::camera::Camera;
use super::layers::{single_plain, HitView, LayerSum, Layered};
use super::{normal, texture_map};

/// Per-thread scratch buffers so tracing allocates nothing per ray.
pub type TraceCtx<'a> = Scratch<'a>;

#[derive(Clone)]
pub struct Tracer<'a> {
    pub scene: &'a Scene,
    pub camera: &'a Camera,
    /// Radiosity's cache and settings for this pass; None without radiosity.
    pub rad: Option<super::radiosity::RadTrace<'a>>,
    /// `+UA`: the output keeps the background's share of each pixel in an alpha channel.
    pub alpha: bool,
    pub quality: Quality,
    /// The photon map, when the scene shoots photons.
    pub photons: Option<&'a super::photons::PhotonMap>,
    /// The scene has no fog, no atmospheric media and no object with media: what a ray
    /// brings back is what it meets (`seen_past`'s four tests a ray, asked once).
    pub clear_air: bool,
}

/// What POV-Ray's `+Q0..11` levels switch on (manual 3.2.8.3, each level checked against
/// `povray` in tests/options.rs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Quality {
    /// Below 2 a surface shows its pigment colour unlit.
    pub lighting: bool,
    pub shadows: bool,
    /// Level 4 shadows treat area lights as points.
    pub area_lights: bool,
    /// Below 6 a pigment's `quick_color` stands in for it, and nothing is seen through.
    pub quick_colors: bool,
    pub transmission: bool,
    pub reflection: bool,
}

impl Quality {
    pub fn level(q: u32) -> Quality {
        Quality {
            lighting: q >= 2,
            shadows: q >= 4,
            area_lights: q >= 5,
            quick_colors: q <= 5,
            transmission: q >= 6,
            reflection: q >= 8,
        }
    }
}

impl Default for Quality {
    fn default() -> Self {
        Quality::level(9)
    }
}

/// Where a ray is in the tree of rays from the camera.
#[derive(Clone, Copy)]
pub struct Path<'a> {
    /// 1 for camera rays.
    pub(super) depth: u32,
    /// The ray's share of the pixel, for adaptive depth control.
    weight: f64,
    /// The camera ray continued through transparent surfaces only (see `trace_seen`).
    pub(super) straight: bool,
    /// The fading interior the ray travels in, if any.
    medium: Option<&'a Interior>,
    /// Whether the ray runs inside a solid (not `hollow`) object, where there is no fog:
    /// known for reflected rays (their incident ray's), found by looking otherwise.
    in_solid: Option<bool>,
    /// 0 on the camera's tree of rays; n below a radiosity sample of level n.
    pub(super) rad_level: u32,
    /// The ray's place in the spectrum (0 red to 1 violet) once a dispersing object split it.
    wave: Option<f32>,
}

impl<'a> Path<'a> {
    pub(super) const CAMERA: Path<'static> = Path {
        depth: 1,
        weight: 1.0,
        straight: true,
        medium: None,
        in_solid: None,
        rad_level: 0,
        wave: None,
    };

    fn next(self, weight: f64, straight: bool, medium: Option<&'a Interior>) -> Path<'a> {
        Path {
            depth: self.depth + 1,
            weight,
            straight,
            medium,
            in_solid: self.in_solid,
            rad_level: self.rad_level,
            wave: self.wave,
        }
    }

    /// A gathering ray of a radiosity sample of level `level`.
    pub(super) fn gathering(self, level: u32) -> Path<'a> {
        Path {
            depth: self.depth + 1,
            weight: 1.0,
            straight: false,
            medium: None,
            in_solid: None,
            rad_level: level,
            wave: None,
        }
    }
}

/// What a ray brings back: colour, and with `+UA` how much of the background shows through
/// along it (1 where it reaches the background unobstructed).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Seen {
    pub rgb: DVec3,
    pub clear: f64,
}

/// POV-Ray's grey of a filter colour when it reduces filtering to one number for the alpha
/// channel (the classic NTSC-like weights; measured: a yellow rgbf pane, tests/options.rs).
#[inline]
pub(super) fn grey(c: DVec3) -> f64 {
    0.297 * c.x + 0.589 * c.y + 0.114 * c.z
}

/// Whether the crossing `h` is invisible to the ray (`first_visible`'s rules).
#[inline(always)]
fn hidden(h: &SurfaceHit, straight: bool, gather: bool) -> bool {
    if gather {
        h.obj.no_radiosity
    } else if straight {
        h.obj.no_image
    } else {
        h.obj.no_reflection
    }
}

/// The direction a ray going `dir` takes through a surface with normal `nf` (facing the ray,
/// `cos_i` = −dir·nf) from ior n1 into n2; None on total internal reflection.
pub(super) fn refract(dir: DVec3, nf: DVec3, cos_i: f64, n1: f64, n2: f64) -> Option<DVec3> {
    let eta = n1 / n2;
    let k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
    (k >= 0.0).then(|| dir * eta + nf * (eta * cos_i - k.sqrt()))
}

pub(super) fn reflect(d: DVec3, n: DVec3) -> DVec3 {
    d - n * (2.0 * d.dot(n))
}

/// Exact dielectric Fresnel reflectance for unpolarised light going from ior n1 into n2.
pub fn fresnel(cos_i: f64, n1: f64, n2: f64) -> f64 {
    let eta = n1 / n2;
    let sin_t2 = eta * eta * (1.0 - cos_i * cos_i);
    if sin_t2 >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin_t2).sqrt();
    let rs = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
    let rp = (n1 * cos_t - n2 * cos_i) / (n1 * cos_t + n2 * cos_i);
    0.5 * (rs * rs + rp * rp)
}

impl<'a> Tracer<'a> {
    pub fn new(scene: &'a Scene, camera: &'a Camera, alpha: bool, quality: Quality) -> Tracer<'a> {
        Tracer {
            scene,
            camera,
            rad: None,
            alpha,
            quality,
            photons: None,
            clear_air: scene.fogs.is_empty() && scene.media.is_empty() && !scene.object_media,
        }
    }

    /// A camera ray: colour in the scene's working space, and the background's share. No ray
    /// (outside a fisheye's circle) is black.
    pub fn trace_camera(&self, ray: Option<Ray>, ctx: &mut TraceCtx<'a>) -> Seen {
        // Radiosity samples the final trace had to gather serve this camera sample only, so
        // that no pixel depends on which pixels the thread traced before.
        ctx.rad_local.clear();
        self.trace_pretrace(ray, ctx)
    }

    /// A camera ray keeping the radiosity samples gathered before it in `ctx.rad_local`.
    pub(super) fn trace_pretrace(&self, ray: Option<Ray>, ctx: &mut TraceCtx<'a>) -> Seen {
        // By reference into the option: moved out, the ray was copied in 16-byte pieces
        // (origin.z with dir.x, then dir.y-z) straddling the camera's x-y pair and z stores,
        // two store-forwarding stalls a camera ray (nearly three fifths of
        // `trace_camera_at`'s samples on sign's orthographic camera).
        match &ray {
            Some(ray) => self.trace_seen(ray, Path::CAMERA, ctx),
            None => Seen::default(),
        }
    }

    /// What the camera sees at image position (px, py): one ray through the projection, or a
    /// mesh camera's rays averaged (none: black).
    pub fn trace_camera_at(&self, px: f64, py: f64, ctx: &mut TraceCtx<'a>) -> Seen {
        let cam = self.camera;
        if cam.plain() && cam.mesh().is_none() && cam.lens().is_none() {
            // `trace_camera` without its `Option<Ray>`: see `Camera::plain_ray`.
            ctx.rad_local.clear();
            let ray = cam.plain_ray(px, py);
            return self.trace_seen(&ray, Path::CAMERA, ctx);
        }
        let Some(mesh) = cam.mesh() else {
            if let Some(lens) = cam.lens() {
                return super::focal::trace(self, cam, lens, px, py, ctx);
            }
            return self.trace_camera(cam.ray(px, py), ctx);
        };
        // As in `trace_camera`: the radiosity samples this position gathers serve it alone
        // (they were kept from pixel to pixel, so the picture depended on the thread count).
        ctx.rad_local.clear();
        let mut sum = Seen::default();
        let mut n = 0u32;
        mesh.for_each_ray(px, py, |ray| {
            let s = self.trace_seen(&ray, Path::CAMERA, ctx);
            sum.rgb += s.rgb;
            sum.clear += s.clear;
            n += 1;
        });
        if n > 1 {
            sum.rgb /= n as f64;
            sum.clear /= n as f64;
        }
        sum
    }

    /// `path.straight`: the ray continues the camera ray through transparent surfaces only, so the
    /// background it reaches counts towards the pixel's transparency.
    fn trace_seen(&self, ray: &Ray, path: Path<'a>, ctx: &mut TraceCtx<'a>) -> Seen {
        ctx.rays += 1;
        if path.depth > self.scene.max_trace_level {
            return Seen::default();
        }
        // `first_visible` written out so that the hit stays where `first_hit` put it: a
        // `match` of the two sources of its answer copied the 56-byte hit on every ray.
        let mut hit = self.scene.first_hit(ray, f64::INFINITY, ctx);
        if let Some(h) = hit {
            if hidden(&h, path.straight, false) {
                hit = self.visible_past(ray, h, path.straight, false, ctx);
            }
        }
        self.seen_past(ray, hit, path, ctx)
    }

    /// `trace_seen` past finding the ray's first visible crossing `hit`.
    #[inline(always)]
    pub(super) fn seen_past(
        &self,
        ray: &Ray,
        hit: Option<SurfaceHit<'a>>,
        path: Path<'a>,
        ctx: &mut TraceCtx<'a>,
    ) -> Seen {
        if self.clear_air {
            // What the general path below does without fog and media: no inside test, the
            // ray in no solid, nothing applied after.
            let mut path = path;
            path.in_solid = Some(false);
            return self.seen_of(ray, &hit, path, ctx);
        }
        let t = hit.as_ref().map_or(f64::INFINITY, |h| h.t);
        // No atmosphere and no media inside solid (not `hollow`) objects, povray's rule
        // (measured: a camera inside plane { z, 10 } sees the plane unfogged; a media box,
        // hollow or not, shows nothing inside a solid plane, tests/probes/media_*). A ray that crossed no
        // surface to get here is looked up at a point of its segment (which crosses none);
        // a reflected ray stays where its incident ray was, whichever way it turns
        // (measured: rays reflected from a rippled floor into the floor's half-space are
        // fogged, advanced/mist.pov).
        let media = !self.scene.media.is_empty() || self.scene.object_media;
        // A radiosity pretrace pass keeps the samples its camera rays' trees gather, not their
        // colour, which is all fog changes: no fog there, nor the inside test it needs.
        let fog = match self.rad {
            Some(r) if r.probe && path.rad_level == 0 => false,
            _ => !self.scene.fogs.is_empty(),
        };
        let solid = (fog || media)
            && path.in_solid.unwrap_or_else(|| {
                let mid = if t.is_finite() { t * 0.5 } else { 1.0 };
                self.scene.inside_solid(ray.at(mid))
            });
        // Set in place: a new `Path` from `..path` was a 14-instruction copy on every ray.
        let mut path = path;
        path.in_solid = Some(solid);
        let mut seen = self.seen_of(ray, &hit, path, ctx);
        if t.is_finite() && !solid && media {
            seen = self.media_segment(ray, t, seen, ctx);
        }
        if !fog || solid {
            seen
        } else {
            super::fog::apply(&self.scene.fogs, ray, t, seen)
        }
    }

    /// The colour of the ray's first visible crossing `hit`, or of the background.
    #[inline(always)]
    fn seen_of(
        &self,
        ray: &Ray,
        hit: &Option<SurfaceHit<'a>>,
        path: Path<'a>,
        ctx: &mut TraceCtx<'a>,
    ) -> Seen {
        match hit {
            // Blobs with textured components aside, straight to `shade` (not through
            // `shade_blended`'s frame).
            Some(h) if h.obj.blob.is_none() => self.shade(ray, h, path, ctx),
            Some(h) => self.shade_blended(ray, h, path, ctx),
            None => self.background(ray.dir, path.straight),
        }
    }

    /// A radiosity gathering ray: what it brings back, and how far it went (infinite to the
    /// background). It passes through `no_radiosity` objects.
    ///
    /// `share`: the ray's place in its sample's sequence (index / count). An object of
    /// `radiosity { importance I }` is followed only by the first I of the sequence, which
    /// count 1/I times to make up for the others (manual 3.4.4.3.4.1).
    ///
    /// `sky`: the ray's frame and place in it, where the background it may reach is
    /// remembered (`SkyMemo`).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn trace_gather(
        &self,
        ray: &Ray,
        path: Path<'a>,
        share: f64,
        sky: Option<(&SkyKey, usize)>,
        ctx: &mut TraceCtx<'a>,
    ) -> (DVec3, f64) {
        ctx.rays += 1;
        if path.depth > self.scene.max_trace_level {
            return (DVec3::ZERO, f64::INFINITY);
        }
        let (seen, t) = match self.first_visible(ray, false, true, ctx) {
            Some(h) if h.obj.importance < u8::MAX => {
                let imp = f64::from(h.obj.importance) / 255.0;
                if share >= imp {
                    return (DVec3::ZERO, h.t * ray.dir.length());
                }
                let mut s = self.shade_blended(ray, &h, path, ctx);
                s.rgb /= imp;
                (s, h.t)
            }
            Some(h) => (self.shade_blended(ray, &h, path, ctx), h.t),
            None => {
                let bg = || {
                    let s = self.background(ray.dir, false);
                    (s.rgb, s.clear)
                };
                let (rgb, clear) = match sky {
                    Some((key, i)) => ctx.rad_sky.seen(key, i, bg),
                    None => bg(),
                };
                (Seen { rgb, clear }, f64::INFINITY)
            }
        };
        if self.scene.fogs.is_empty() {
            // The colour by coordinates: copied whole, `shade_blended`'s answer was read back
            // as 16-byte halves, and the (z, clear) half spans two of its 8-byte stores, a
            // store-forwarding stall per gathering ray that hits (rad35: ~0.6 % of radiosity2).
            return (crate::math::by_coordinates(&seen.rgb), t * ray.dir.length());
        }
        let seen = super::fog::apply(&self.scene.fogs, ray, t, seen);
        (seen.rgb, t * ray.dir.length())
    }

    /// The first crossing the ray can see: camera rays and their transmitted continuations
    /// (`straight`) pass through `no_image` objects, reflected rays through `no_reflection`
    /// ones (measured with povray: a no_image sphere is missing through glass too, and shows
    /// in a mirror), radiosity's gathering rays (`gather`) through `no_radiosity` ones. `t`
    /// stays measured along `ray`.
    pub(super) fn first_visible(
        &self,
        ray: &Ray,
        straight: bool,
        gather: bool,
        ctx: &mut TraceCtx<'a>,
    ) -> Option<SurfaceHit<'a>> {
        // Nearly every first crossing is visible: the loop past hidden objects (and its
        // set-up, hoisted before this test when it was one loop) is out of line. The
        // `Option` is passed on as it came: taken apart with `?` and wrapped again in
        // `Some`, the 56-byte hit was copied twice on every ray.
        match self.scene.first_hit(ray, f64::INFINITY, ctx) {
            Some(h) if hidden(&h, straight, gather) => {
                self.visible_past(ray, h, straight, gather, ctx)
            }
            hit => hit,
        }
    }

    /// `first_visible` past a first crossing `h` that is hidden.
    #[inline(never)]
    fn visible_past(
        &self,
        ray: &Ray,
        mut h: SurfaceHit<'a>,
        straight: bool,
        gather: bool,
        ctx: &mut TraceCtx<'a>,
    ) -> Option<SurfaceHit<'a>> {
        let mut offset = 0.0;
        // Bounded so that a ray grazing along a hidden surface cannot loop for ever.
        for _ in 0..256 {
            if !hidden(&h, straight, gather) {
                h.t += offset;
                return Some(h);
            }
            offset += h.t;
            h = self
                .scene
                .first_hit(&Ray::new(ray.at(offset), ray.dir), f64::INFINITY, ctx)?;
        }
        None
    }

    /// `shade`, except on a blob whose components have textures: POV-Ray shades the point with
    /// the texture of each component reaching it and averages the colours, weighted by the
    /// magnitude of each component's field there (measured: negative components count by
    /// their size, components without a texture bring the blob's). Like any ray, a texture
    /// whose share of the pixel is below adc_bailout is not shaded at all: measured with
    /// povray, components under 1/255 of the sum leave no trace.
    fn shade_blended(
        &self,
        ray: &Ray,
        h: &SurfaceHit<'a>,
        path: Path<'a>,
        ctx: &mut TraceCtx<'a>,
    ) -> Seen {
        let Some((blob, _)) = h.obj.blob.as_deref() else {
            return self.shade(ray, h, path, ctx);
        };
        let p = ray.at(h.t);
        let local = h.obj.transform.as_ref().map_or(p, |t| t.inv_point(p));
        // The buffer is taken out while the parts are shaded: their rays may meet blobs too.
        let mut weights = std::mem::take(&mut ctx.blob_weights);
        blob.densities(local, &mut weights);
        let total: f64 = weights.iter().map(|(_, d)| d.abs()).sum();
        if total.is_nan() || total <= 0.0 {
            ctx.blob_weights = weights;
            return self.shade(ray, h, path, ctx);
        }
        let mut out = Seen::default();
        for &(i, d) in &weights {
            let w = d.abs() / total;
            if path.weight * w < self.scene.adc_bailout {
                continue;
            }
            let mut hi = *h;
            hi.hit.part = i as u32;
            let part = Path {
                weight: path.weight * w,
                ..path
            };
            let s = self.shade(ray, &hi, part, ctx);
            out.rgb += s.rgb * w;
            out.clear += s.clear * w;
        }
        ctx.blob_weights = weights;
        out
    }

    fn shade(&self, ray: &Ray, h: &SurfaceHit<'a>, path: Path<'a>, ctx: &mut TraceCtx<'a>) -> Seen {
        let s = self.scene;
        let q = self.quality;
        let obj = h.obj;
        let p = ray.at(h.t);
        let dir = ray.dir.normalize();
        // One coordinate at a time: `Object::normal` returns through memory and some of its
        // paths store x and y 8 bytes each, which the x-y pair load LLVM read it back with
        // could not be forwarded from (a tenth of `shade`'s samples on mirror_spheres).
        let n = crate::math::by_coordinates(&obj.normal(p, h));
        let entering = n.dot(dir) < 0.0;
        let nf = if entering { n } else { -n };
        // Only slope and aoi read the surface: without them the thread-local write is skipped.
        if crate::scene::pattern::surface_patterns_made() {
            super::pattern::set_surface(Some(super::pattern::Surface {
                point: p,
                normal: nf,
                ray: dir,
            }));
        }
        let top = obj.texture_facing(h, !entering);
        let [uses_uv, bumpy, lit] = texture_facts(top, ctx);
        let uv = if uses_uv { obj.uv_point(p, h) } else { None };
        if !q.lighting {
            return Seen {
                rgb: texture_map::color_at(top, p, uv, q.quick_colors).rgb,
                clear: 0.0,
            };
        }
        // Per hit, not per layer or light. The `HitView` is made after the lights, in each
        // branch: the one-layer path takes it apart again (its values stay in registers and
        // their spill slots), where a view made before the lights, whose address the layer
        // loop takes, was 34 copies a hit from those slots into it.
        let mirror = reflect(dir, nf);
        let cos_i = (-dir.dot(nf)).clamp(0.0, 1.0);
        // Undispersed light (nearly every ray) takes the object's ior without looking at
        // its interior.
        let ior = match path.wave {
            None => obj.ior,
            wave => super::dispersion::ior(obj, wave),
        };
        let (n1, n2) = if entering { (1.0, ior) } else { (ior, 1.0) };
        let uv = &uv;
        let view = move || HitView {
            p,
            dir,
            nf,
            mirror,
            cos_i,
            n1,
            n2,
            entering,
            obj,
            uv,
            path,
        };
        // A perturbed normal may face lights the surface itself turns away from; POV-Ray
        // lights them (measured: a light just behind a plane whose normal leans towards it):
        // `bumpy`, whether any part of the texture perturbs the normal.
        // Most hits are on one plain layer: its sums in locals, `LayerSum` not made, and
        // when lights reach it and radiosity is off, each added as its shadow ray answers
        // (`layer_light_direct`). With radiosity the lights are gathered here first (or
        // cleared for a pretrace's probe) and the irradiance asked between them and their
        // sum, as the layer loop does.
        let single = single_plain(top, bumpy, mirror);
        let direct = single && lit && self.rad.is_none();
        if direct {
            // `shade_single` gathers the lights itself.
        } else if self.rad.is_some_and(|r| r.probe) && path.rad_level == 0 {
            // A radiosity pretrace pass keeps the samples its camera rays gather, not their
            // colour: the lights of what they meet do not matter.
            ctx.lit.clear();
        } else if !lit {
            // No layer would add anything per light (a sky dome's `diffuse 0`): no shadow
            // rays. Nothing but `layer_light` reads the gathered lights, this hit's layers
            // only (`irradiance` keeps them from the gathering rays' hits).
            ctx.lit.clear();
        } else {
            self.gather_lights(p, nf, bumpy, obj, path.rad_level > 0, ctx);
        }
        let mut sum;
        let (lay, bent): (Layered, &[(DVec3, DVec3)]) = if single {
            let direct = direct.then_some(path.rad_level > 0);
            (self.shade_single(top, &view(), direct, ctx), &[])
        } else {
            sum = LayerSum::new();
            self.shade_layers(top, &view(), &mut sum, ctx);
            (sum.out, &sum.bent)
        };
        let Layered {
            mut col,
            through,
            refl_amount,
            refl_tinted,
            refl_all_tinted,
            last,
            conserve,
            refl_power,
            refract_n,
        } = lay;
        if refl_amount != DVec3::ZERO {
            let w = path.weight * refl_amount.max_element();
            if w > s.adc_bailout {
                // A reflection stays on the side the ray came from, in its medium.
                if refl_tinted != DVec3::ZERO || bent.is_empty() {
                    // One coordinate at a time: `shade` and `background` write the colour as
                    // a pair and a double in different orders, and a pair's load spanning two
                    // stores waited for them (3 % of `shade`'s samples on mirror_spheres).
                    let rc = crate::math::by_coordinates(
                        &self
                            .trace_seen(&Ray::new(p, mirror), path.next(w, false, path.medium), ctx)
                            .rgb,
                    );
                    col += powered(rc, refl_power) * refl_tinted;
                }
                // By reference: iterating the SmallVec by value copied its ~200 bytes for
                // every reflecting hit, bent or not (ray16: 140,900 `memcpy`s on
                // mirror_spheres).
                for &(d, tinted) in bent.iter() {
                    let wb = path.weight * tinted.max_element();
                    if wb > s.adc_bailout {
                        let rc = self
                            .trace_seen(&Ray::new(p, d), path.next(wb, false, path.medium), ctx)
                            .rgb;
                        col += powered(rc, refl_power) * tinted;
                    }
                }
            }
        }

        let mut clear = 0.0;
        if (last.filter > 0.0 || last.transmit > 0.0) && through != DVec3::ZERO && q.transmission {
            let mut tcol = through;
            if conserve {
                // Measured: a metallic reflection tinted green takes only green from what
                // passes (tests/probes/conserve_metallic.pov); untinted it is the amount.
                tcol *= DVec3::ONE - refl_all_tinted;
            }
            let w = path.weight * tcol.max_element();
            if w > s.adc_bailout {
                let (nf, cos_i) = match refract_n {
                    Some(pn) => (pn, (-dir.dot(pn)).clamp(0.0, 1.0)),
                    None => (nf, cos_i),
                };
                // Total internal reflection sends the transmitted share back inside.
                let bend = |n1: f64, n2: f64| {
                    if n1 == n2 {
                        return dir;
                    }
                    refract(dir, nf, cos_i, n1, n2).unwrap_or(mirror)
                };
                // Into the object's interior, or back out (into air: nested interiors are
                // not tracked).
                let inside = if entering {
                    obj.interior.as_deref()
                } else {
                    None
                };
                // The transmitted ray crosses the surface: whether it is in a solid is looked
                // up afresh.
                let onward = Path {
                    in_solid: None,
                    ..path.next(w, path.straight, inside)
                };
                let split = match path.wave {
                    None if entering => super::dispersion::of(obj),
                    _ => None,
                };
                let tc = match split {
                    None => self.trace_seen(&Ray::new(p, bend(n1, n2)), onward, ctx),
                    Some((_, count)) => {
                        // Light entering a dispersing object goes on as `count` colours.
                        let mut sum = Seen::default();
                        for (t, c) in super::dispersion::samples(count) {
                            let n2 = super::dispersion::ior(obj, Some(t));
                            let part = Path {
                                wave: Some(t),
                                ..onward
                            };
                            let s = self.trace_seen(&Ray::new(p, bend(n1, n2)), part, ctx);
                            sum.rgb += s.rgb * c;
                            sum.clear += s.clear / count as f64;
                        }
                        sum
                    }
                };
                // Light coming in through the far side of a fading interior is dimmed by the
                // stretch the ray spent inside; the far surface's own light is not (measured:
                // ambient on both faces of a fading slab).
                let fade = match path.medium {
                    Some(int) if !entering => int.fade(h.t * ray.dir.length()),
                    _ => DVec3::ONE,
                };
                col += tc.rgb * tcol * fade;
                clear = tc.clear * grey(through);
            }
        }
        Seen { rgb: col, clear }
    }
}

/// Three facts about a texture that each walk all its layers and entries: whether any part
/// is uv-mapped, perturbs the normal, and takes light from light sources
/// (`texture_map::lit_by_lights`). Remembered for the last four textures shaded in `ctx`:
/// most hits in a row are on one texture or a few (a reflection's), and a big texture_map's
/// walks were a fifth of textures/pigments/skies/stars. Facts of the same texture are the
/// same wherever they were found.
fn texture_facts<'a>(top: &'a Texture, ctx: &mut TraceCtx<'a>) -> [bool; 3] {
    let seen = &mut ctx.last_textures;
    for &(t, facts) in seen.iter().flatten() {
        if std::ptr::eq(t, top) {
            return facts;
        }
    }
    let facts = [
        top.uses_uv(),
        normal::texture_perturbs(top),
        texture_map::lit_by_lights(top),
    ];
    // Newest first; the oldest drops out.
    seen.rotate_right(1);
    seen[0] = Some((top, facts));
    facts
}

/// A reflected colour raised to a reflection `exponent`'s power (per channel, negative
/// values left alone).
fn powered(c: DVec3, power: Option<f64>) -> DVec3 {
    match power {
        Some(k) => DVec3::new(
            c.x.max(0.0).powf(k),
            c.y.max(0.0).powf(k),
            c.z.max(0.0).powf(k),
        ),
        None => c,
    }
}

/// A seed from a point's exact coordinates, so random-looking choices made there are the
/// same on every run and for any thread count.
pub(super) fn point_seed(p: DVec3) -> u32 {
    let h = p.x.to_bits() ^ p.y.to_bits().rotate_left(21) ^ p.z.to_bits().rotate_left(42);
    (h ^ (h >> 32)) as u32
}

/// A well-mixed value in [0, 1) from a point seed and a light's index.
pub(super) fn grain(seed: u32, light: u32) -> f64 {
    let mut h = seed ^ light.wrapping_mul(0x9e37_79b9);
    h ^= h >> 16;
    h = h.wrapping_mul(0x7feb_352d);
    h ^= h >> 15;
    h = h.wrapping_mul(0x846c_a68b);
    h ^= h >> 16;
    (h >> 8) as f64 / (1u32 << 24) as f64
}
