//! Builds the runtime scene from the description: resolves textures (CSG children inherit
//! their parent's, POV-Ray's post-processing), creates shapes, computes world bounds, builds the
//! BVH over bounded objects, and settles the gamma mode.

use std::collections::HashMap;
use std::sync::Arc;

use crate::color::Rgbft;
use crate::geom::blob::{Blob, BlobData};
use crate::geom::bvh::Bvh;
use crate::geom::text::TextData;
use crate::geom::Shape;
use crate::math::{Aabb, DVec3, Transform};
use crate::scene::desc::{
    CameraDesc, FogDesc, ImageMap, Interior, MeshData, ObjectDesc, Pigment, PigmentKind,
    RadiositySettings, SceneDesc, ShapeDesc, Texture, TextureEntries,
};
use crate::scene::light_group::LightSet;
use crate::scene::media::Media;
use crate::scene::object::{ObjKind, Object};
use crate::scene::shapes::make_shape;

pub use super::light::Light;

mod moved;
mod query;
pub(crate) use query::leaf_any_hit;

/// How working values become file values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum GammaMode {
    /// Shading in a space of this gamma (1.0 = linear); output encoded as sRGB.
    Corrected(f64),
    /// Pre-3.7 scene without assumed_gamma: values go to the file unchanged.
    None,
}

pub struct Scene {
    /// The camera as the scene describes it, for a picture of `size` pixels: the renderer
    /// makes its rays (`render::camera::Camera::of_scene`), since a camera `normal` and a
    /// focal-blur bokeh are patterns only the renderer evaluates.
    pub camera: CameraDesc,
    pub size: (u32, u32),
    pub lights: Vec<Light>,
    /// Which lights light which objects (`Object::light_set`); one entry when the scene has
    /// no `light_group`.
    pub light_sets: Vec<LightSet>,
    pub objects: Vec<Object>,
    /// Over the bounded objects; its primitives are named by `query::leaf_name` (the object's
    /// index, and whether it is a plain sphere).
    bvh: Bvh,
    /// Whether the CPU has AVX (`math::has_avx`), asked once: `first_hit` and the renderer's
    /// shadow rays choose their walk's copy by it (`Scene::avx`), where every call asked the
    /// CPU (~20 instructions a ray with the frame around the choice).
    avx: bool,
    /// The objects outside the BVH.
    unbounded: Vec<query::Unbounded>,
    /// (address of a CSG member, address of its node), sorted: the way up from a leaf for
    /// `inside_other`, which would otherwise search every object tree for the leaf.
    parents: Vec<(usize, usize)>,
    pub background: Rgbft,
    pub sky: Vec<Pigment>,
    /// Scenes before `#version 3.7` (or with none): a filtering sky_sphere layer passes the
    /// layers below it untinted (measured; render::trace background).
    pub legacy_sky_filter: bool,
    pub max_trace_level: u32,
    pub adc_bailout: f64,
    pub ambient_light: DVec3,
    pub gamma: GammaMode,
    /// Fog layers with a distance (POV-Ray treats distance 0 as no fog), up made unit.
    pub fogs: Vec<FogDesc>,
    /// `global_settings { radiosity {} }`: indirect light from an irradiance cache.
    pub radiosity: Option<crate::scene::desc::RadiositySettings>,
    /// Atmospheric media, densities readied.
    pub media: Vec<Media>,
    /// Whether any object's interior holds media.
    pub object_media: bool,
    /// `global_settings { photons {} }`: caustics from a photon map.
    pub photons: Option<crate::scene::photon::PhotonSettings>,
}

pub struct BuildOutput {
    pub scene: Scene,
    pub warnings: Vec<String>,
}

pub fn build(desc: &SceneDesc, width: u32, height: u32) -> BuildOutput {
    build_from(desc, desc.objects.iter(), width, height)
}

/// `build` that takes the objects out of the description, freeing each one's description
/// as soon as its runtime object exists: a million-object scene's descriptions (hundreds of
/// megabytes) are gone before the BVH is built, which keeps the peak memory down. The
/// description keeps everything else.
pub fn build_consuming(desc: &mut SceneDesc, width: u32, height: u32) -> BuildOutput {
    let objects = std::mem::take(&mut desc.objects);
    build_from(desc, objects.into_iter(), width, height)
}

fn build_from<O: std::borrow::Borrow<ObjectDesc>>(
    desc: &SceneDesc,
    descs: impl ExactSizeIterator<Item = O>,
    width: u32,
    height: u32,
) -> BuildOutput {
    let mut warnings = Vec::new();
    let gamma = match (desc.global.assumed_gamma, desc.version) {
        (Some(g), _) => GammaMode::Corrected(if g > 0.0 { g } else { 1.0 }),
        (None, Some(v)) if v < 3.7 => GammaMode::None,
        // No `#version` anywhere (an included file's counts) and no `+MV`: povray 3.7 takes the
        // scene for a pre-3.7 one and leaves gamma alone (measured: tests/probes/no_version).
        (None, None) => {
            warnings.push("the scene has no #version directive and sets no assumed_gamma: gamma correction is off, as POV-Ray 3.7 does for pre-3.7 scenes (start the scene with #version 3.7; and set global_settings { assumed_gamma 1.0 })".to_string());
            GammaMode::None
        }
        (None, Some(_)) => {
            warnings.push("the scene sets no assumed_gamma; taking 1.0 as POV-Ray 3.7 does (add global_settings { assumed_gamma 1.0 })".to_string());
            GammaMode::Corrected(1.0)
        }
    };
    let mut ctx = Ctx::new(gamma, desc.global.noise_generator);
    let default_texture = Arc::new(desc.default_texture.clone());
    let mut objects = Vec::with_capacity(descs.len());
    for o in descs {
        if let Some(obj) = ctx.object(o.borrow(), None, None, &default_texture) {
            objects.push(obj);
        }
    }
    for o in &mut objects {
        crate::scene::children::attach(o, false);
        if desc.global.photons.is_some() {
            inherit_photon_flags(o, 0);
        }
    }
    let mut bounded = Vec::new();
    let mut unbounded = Vec::new();
    for (i, o) in objects.iter().enumerate() {
        if o.bounds.is_finite() {
            bounded.push(i);
        } else {
            unbounded.push(i);
        }
    }
    let boxes: Vec<Aabb> = bounded.iter().map(|&i| objects[i].bounds).collect();
    let unbounded = unbounded
        .into_iter()
        .map(|i| query::Unbounded::of(&objects, i))
        .collect();
    let mut bvh = Bvh::build(&boxes);
    bvh.rename(|k| query::leaf_name(&objects, bounded[k as usize]));
    drop(bounded);
    let mut sky = desc.sky_sphere.clone().unwrap_or_default();
    for p in &mut sky {
        ctx.pigment(p);
    }
    let mut media = desc.media.clone();
    ctx.ready_media(&mut media);
    let object_media = objects.iter().any(has_media);
    let mut scene = Scene {
        camera: desc.camera.clone(),
        size: (width, height),
        lights: ctx.lights,
        light_sets: ctx.light_sets,
        objects,
        bvh,
        avx: crate::math::has_avx(),
        unbounded,
        parents: Vec::new(),
        background: desc.background,
        sky,
        legacy_sky_filter: desc.version.is_none_or(|v| v < 3.7),
        max_trace_level: desc.global.max_trace_level,
        adc_bailout: desc.global.adc_bailout,
        ambient_light: desc.global.ambient_light,
        radiosity: desc.global.radiosity.clone().map(|r| RadiositySettings {
            keep_ambient: desc.version.is_some_and(|v| v < 3.7),
            ..r
        }),
        photons: desc.global.photons.clone(),
        gamma,
        media,
        object_media,
        fogs: desc
            .fogs
            .iter()
            .filter(|f| f.distance > 0.0)
            .map(|f| {
                let mut f = FogDesc {
                    up: f.up.normalize_or(DVec3::Y),
                    ..f.clone()
                };
                if let Some(tb) = &mut f.turbulence {
                    tb.noise_generator = desc.global.noise_generator;
                    tb.set_reach();
                }
                // A rainbow's direction unit, its up perpendicular to it and its band, once per scene.
                if let Some(rb) = &mut f.rainbow {
                    let d = rb.direction.normalize_or(DVec3::Z);
                    rb.direction = d;
                    rb.up = (rb.up - d * rb.up.dot(d)).normalize_or_zero();
                    rb.set_band();
                }
                f
            })
            .collect(),
    };
    // Addresses are final: the objects' buffers do not move again.
    scene.parents = parent_table(&scene.objects);
    BuildOutput { scene, warnings }
}

/// One object built on its own, for an `object` pattern: no lights, no scene-wide state.
pub fn standalone_object(o: &ObjectDesc) -> Option<Object> {
    // Only the object's shape matters to the pattern: gamma and noise do not.
    let mut ctx = Ctx::new(GammaMode::Corrected(1.0), 2);
    let default_texture = Arc::new(Texture::default());
    let mut obj = ctx.object(o, None, None, &default_texture)?;
    crate::scene::children::attach(&mut obj, false);
    Some(obj)
}

fn has_media(o: &Object) -> bool {
    o.interior.as_ref().is_some_and(|i| i.has_media())
        || match &o.kind {
            ObjKind::Csg { children, .. } => children.iter().any(has_media),
            _ => false,
        }
}

fn parent_table(objects: &[Object]) -> Vec<(usize, usize)> {
    fn walk(o: &Object, out: &mut Vec<(usize, usize)>) {
        if let ObjKind::Csg { children, .. } = &o.kind {
            for c in children {
                out.push((c as *const Object as usize, o as *const Object as usize));
                walk(c, out);
            }
        }
    }
    let mut out = Vec::new();
    objects.iter().for_each(|o| walk(o, &mut out));
    out.sort_unstable();
    out
}

struct Ctx {
    /// One runtime mesh (with its BVH) per `#declare`d mesh, shared by every copy.
    meshes: HashMap<*const MeshData, Arc<dyn Shape>>,
    /// Likewise one runtime text (with its glyph BVH) per `#declare`d text.
    texts: HashMap<*const TextData, Arc<dyn Shape>>,
    /// Likewise one runtime blob (prepared components and their BVH) per `#declare`d blob:
    /// biscuit's icing logo, hundreds of spheres, was prepared again for each of its 21
    /// copies (a fifth of the run at 320x240).
    blobs: HashMap<*const BlobData, Arc<Blob>>,
    /// Each image map converted to the working gamma once, with whether any pixel lets light
    /// through, however many objects use it. Keyed by the description's image.
    images: HashMap<*const ImageMap, (Arc<ImageMap>, bool)>,
    /// Textures the description shares between objects (a CSG's inherited one, the default),
    /// readied once. Keyed by address: the description keeps them alive while building.
    shared_textures: HashMap<*const Texture, (Arc<Texture>, bool)>,
    /// Each interior's media readied once, so CSG members sharing an interior keep sharing
    /// one list (render counts a list once where members overlap).
    media: HashMap<*const Vec<Media>, Arc<Vec<Media>>>,
    lights: Vec<Light>,
    gamma: GammaMode,
    noise_generator: u8,
    /// The light sets of `light_group`s met so far (0: outside every group), the set and
    /// group of the objects and lights being built, and the last group number given.
    light_sets: Vec<LightSet>,
    current_set: u16,
    current_group: u16,
    /// The `hollow` of the CSG being built, which its members take unless they say their own
    /// (manual, "Hollow Object Modifier").
    hollow_default: bool,
    groups: u16,
}

impl Ctx {
    /// The runtime blob of `data`, prepared once however many objects copy it.
    fn blob(&mut self, data: &Arc<BlobData>) -> Arc<Blob> {
        self.blobs
            .entry(Arc::as_ptr(data))
            .or_insert_with(|| Arc::new(Blob::new(data)))
            .clone()
    }

    fn new(gamma: GammaMode, noise_generator: u8) -> Ctx {
        Ctx {
            meshes: HashMap::new(),
            texts: HashMap::new(),
            blobs: HashMap::new(),
            images: HashMap::new(),
            shared_textures: HashMap::new(),
            media: HashMap::new(),
            lights: Vec::new(),
            gamma,
            noise_generator,
            light_sets: vec![LightSet::outside()],
            current_set: 0,
            current_group: 0,
            hollow_default: false,
            groups: 0,
        }
    }

    /// Scene colours are already in working space; image maps were decoded to linear light
    /// on load and need converting only when the working gamma is not 1.
    fn image(&mut self, im: &Arc<ImageMap>) -> (Arc<ImageMap>, bool) {
        let gamma = match self.gamma {
            GammaMode::Corrected(g) if g != 1.0 => Some(g),
            _ => None,
        };
        self.images
            .entry(Arc::as_ptr(im))
            .or_insert_with(|| {
                let mut converted = im.clone();
                if let Some(g) = gamma {
                    Arc::make_mut(&mut converted)
                        .pixels
                        .map_values(|px| px.rgb = px.rgb.powf(1.0 / g));
                }
                let transparent = converted.pixels.any(|c| !c.is_opaque());
                (converted, transparent)
            })
            .clone()
    }

    /// An interior with its media's densities readied (noise generator, images), shared
    /// between the objects that share the description's list.
    fn interior(&mut self, int: &Interior) -> Interior {
        if !int.has_media() {
            return int.clone();
        }
        let desc = &int.media;
        let key = Arc::as_ptr(desc);
        let media = match self.media.get(&key) {
            Some(m) => m.clone(),
            None => {
                let mut all = (**desc).clone();
                self.ready_media(&mut all);
                let ready = Arc::new(all);
                self.media.insert(key, ready.clone());
                ready
            }
        };
        Interior {
            media,
            ..int.clone()
        }
    }

    /// Media densities readied like any pigment (the scene's noise generator, images).
    fn ready_media(&mut self, media: &mut [Media]) {
        for m in media.iter_mut() {
            for d in m.density.iter_mut() {
                self.pigment(d);
            }
            m.ready();
        }
    }

    /// Converts a pigment's images to working space; returns whether it may let light through.
    fn pigment(&mut self, p: &mut Pigment) -> bool {
        // Patterns that named no noise generator use the scene's.
        let gen = self.noise_generator;
        p.take_generator(gen);
        match &mut p.kind {
            PigmentKind::Solid(c) => !c.is_opaque(),
            PigmentKind::Mapped { map, .. } => map.iter().any(|(_, c)| !c.is_opaque()),
            PigmentKind::List { items, .. } => {
                items.iter_mut().fold(false, |t, i| self.pigment(i) | t)
            }
            PigmentKind::PigmentMap { map, .. } => {
                map.iter_mut().fold(false, |t, (_, i)| self.pigment(i) | t)
            }
            PigmentKind::ImageMap(im, _) => {
                let (converted, transparent) = self.image(im);
                *im = converted;
                transparent
            }
        }
    }

    /// The texture ready to render, and whether light can pass through it: through every
    /// layer of a layered one.
    fn texture(&mut self, t: &Texture) -> (Arc<Texture>, bool) {
        let mut t = t.clone();
        let transparent = self.prepare_texture(&mut t);
        (Arc::new(t), transparent)
    }

    /// An object's texture ready to render, and whether light can pass through it. The
    /// description's own `Arc` is kept when readying changes nothing (the common case), so a
    /// million objects do not mean a million texture copies.
    fn object_texture(&mut self, t: &Arc<Texture>) -> (Arc<Texture>, bool) {
        let shared = Arc::strong_count(t) > 1;
        if shared {
            if let Some(hit) = self.shared_textures.get(&Arc::as_ptr(t)) {
                return hit.clone();
            }
        }
        let unchanged = !self.texture_needs_readying(t);
        let (ready, transparent) = if unchanged {
            let transparent = self.prepare_texture(&mut (**t).clone());
            (t.clone(), transparent)
        } else {
            self.texture(t)
        };
        if shared {
            self.shared_textures
                .insert(Arc::as_ptr(t), (ready.clone(), transparent));
        }
        (ready, transparent)
    }

    /// Whether `prepare_texture` would change `t`: a pattern (of a pigment, a normal or the
    /// texture) that takes the scene's noise generator, or an image map to convert to a
    /// working gamma other than 1. Must answer true for everything `prepare_texture` changes.
    fn texture_needs_readying(&self, t: &Texture) -> bool {
        t.layers().any(|l| {
            self.pigment_needs_readying(&l.pigment)
                || l.normal.as_deref().is_some_and(normal_needs_generator)
                || l.pattern.as_ref().is_some_and(|tp| {
                    tp.pattern.needs_generator()
                        || match &tp.entries {
                            TextureEntries::List(items) => {
                                items.iter().any(|e| self.texture_needs_readying(e))
                            }
                            TextureEntries::Map(map) => {
                                map.iter().any(|(_, e)| self.texture_needs_readying(e))
                            }
                        }
                })
        })
    }

    fn pigment_needs_readying(&self, p: &Pigment) -> bool {
        if p.needs_generator() {
            return true;
        }
        match &p.kind {
            PigmentKind::Solid(_) | PigmentKind::Mapped { .. } => false,
            PigmentKind::List { items, .. } => items.iter().any(|i| self.pigment_needs_readying(i)),
            PigmentKind::PigmentMap { map, .. } => {
                map.iter().any(|(_, i)| self.pigment_needs_readying(i))
            }
            PigmentKind::ImageMap(..) => {
                matches!(self.gamma, GammaMode::Corrected(g) if g != 1.0)
            }
        }
    }

    /// Readies a texture's pigments and normals (patterned ones' entries too); whether light
    /// may pass. `texture_needs_readying` must know every change made here.
    fn prepare_texture(&mut self, t: &mut Texture) -> bool {
        let mut transparent = true;
        let mut layer = Some(t);
        while let Some(l) = layer {
            if let Some(n) = &mut l.normal {
                normal_generator(n, self.noise_generator);
            }
            let mut this = self.pigment(&mut l.pigment);
            if let Some(tp) = &mut l.pattern {
                tp.pattern.take_generator(self.noise_generator);
                // Light may pass where any of the textures lets it.
                this = match &mut tp.entries {
                    TextureEntries::List(items) => items
                        .iter_mut()
                        .fold(false, |a, e| self.prepare_texture(e) | a),
                    TextureEntries::Map(map) => map
                        .iter_mut()
                        .fold(false, |a, (_, e)| self.prepare_texture(e) | a),
                };
            }
            transparent &= this;
            layer = l.under.as_deref_mut();
        }
        transparent
    }

    fn object(
        &mut self,
        o: &ObjectDesc,
        parent_tex: Option<&Arc<Texture>>,
        parent_int: Option<&Interior>,
        default: &Arc<Texture>,
    ) -> Option<Object> {
        self.object_in(o, parent_tex, None, parent_int, default)
    }

    /// `object` with the interior texture a CSG parent passes down (to members without a
    /// texture of their own), in its light group.
    fn object_in(
        &mut self,
        o: &ObjectDesc,
        parent_tex: Option<&Arc<Texture>>,
        parent_itex: Option<&Arc<Texture>>,
        parent_int: Option<&Interior>,
        default: &Arc<Texture>,
    ) -> Option<Object> {
        let Some(global) = o.light_group else {
            return self.object_in_group(o, parent_tex, parent_itex, parent_int, default);
        };
        let saved = (self.current_set, self.current_group);
        if self.groups == u16::MAX || self.light_sets.len() > u16::MAX as usize {
            // More groups than lancer numbers: the rest share the last one's lights.
            return self.object_in_group(o, parent_tex, parent_itex, parent_int, default);
        }
        self.groups += 1;
        // Measured with povray 3.7.0 (tests/probes/light_group.pov), against the manual's
        // word on nesting: an object in nested groups is lit by its innermost group's lights
        // only, and the outermost group's `global_lights` decides for all of them.
        let outer = &self.light_sets[self.current_set as usize];
        let global = if self.current_set == 0 {
            global
        } else {
            outer.global
        };
        self.light_sets.push(LightSet {
            group: self.groups,
            global,
        });
        self.current_set = (self.light_sets.len() - 1) as u16;
        self.current_group = self.groups;
        let built = self.object_in_group(o, parent_tex, parent_itex, parent_int, default);
        (self.current_set, self.current_group) = saved;
        built
    }

    /// An object (a light group's contents included) in the light group being built.
    fn object_in_group(
        &mut self,
        o: &ObjectDesc,
        parent_tex: Option<&Arc<Texture>>,
        parent_itex: Option<&Arc<Texture>>,
        parent_int: Option<&Interior>,
        default: &Arc<Texture>,
    ) -> Option<Object> {
        let tex_desc = o.texture.as_ref().or(parent_tex);
        let itex_desc = o
            .interior_texture
            .as_ref()
            .or(parent_itex.filter(|_| o.texture.is_none()));
        let int = o.interior.as_ref().or(parent_int);
        let (texture, mut transparent) = self.object_texture(tex_desc.unwrap_or(default));
        let ior = int.map_or(1.0, |i| i.ior);
        let interior_texture = itex_desc.map(|t| {
            let (t, tr) = self.object_texture(t);
            transparent |= tr;
            t
        });
        let mut blob = None;
        // Measured: a union of `no_shadow` objects casts no shadow though the union does not
        // say so (incdemo/woods: rows of no_shadow boxes, each row a union); shadow rays test
        // a CSG as a whole, so the flag goes up to it when every member has it.
        let mut no_shadow = o.no_shadow;
        let (kind, bounds, mesh) = match &o.shape {
            ShapeDesc::Light(l) => {
                let mut light = Light::new(l, &o.transform);
                light.group = self.current_group;
                if let Some(through) = &l.projected_through {
                    // Its textures and interiors are stripped: only its surface matters.
                    let mut shape = (**through).clone();
                    shape.apply_transform(&o.transform);
                    light.projected = self
                        .object(&shape, None, None, default)
                        .map(|obj| crate::scene::light::Projected(Arc::new(obj)));
                }
                self.lights.push(light);
                // `looks_like` is drawn at the light's location and casts no shadow.
                let shape = l.looks_like.as_ref()?;
                let mut shape = (**shape).clone();
                shape.apply_transform(&Transform::translate(l.position).then(&o.transform));
                shape.no_shadow = true;
                return self.object_in(&shape, parent_tex, parent_itex, parent_int, default);
            }
            ShapeDesc::Csg { op, children } => {
                let outer_hollow = self.hollow_default;
                self.hollow_default = o.hollow.unwrap_or(outer_hollow);
                let kids: Vec<Object> = children
                    .iter()
                    .filter_map(|c| self.object_in(c, tex_desc, itex_desc, int, default))
                    .collect();
                self.hollow_default = outer_hollow;
                if kids.is_empty() {
                    return None;
                }
                no_shadow |= matches!(op, crate::scene::desc::CsgOp::Union)
                    && kids.iter().all(|k| k.no_shadow);
                // Shadow rays must look at the surfaces of a CSG whose members can let light through.
                transparent = kids.iter().any(|k| k.transparent);
                let bounds = csg_bounds(*op, &kids);
                (
                    ObjKind::Csg {
                        op: *op,
                        index: None,
                        cull: None,
                        children: kids,
                    },
                    bounds,
                    None,
                )
            }
            shape => {
                let s: Arc<dyn Shape> = match shape {
                    ShapeDesc::Mesh(data) => {
                        let key = Arc::as_ptr(data);
                        self.meshes
                            .entry(key)
                            .or_insert_with(|| make_shape(shape))
                            .clone()
                    }
                    ShapeDesc::Text(data) => self
                        .texts
                        .entry(Arc::as_ptr(data))
                        .or_insert_with(|| make_shape(shape))
                        .clone(),
                    ShapeDesc::Blob { data, textures } if textures.iter().any(Option::is_some) => {
                        let shape = self.blob(data);
                        let mut texes = Vec::with_capacity(textures.len());
                        for t in textures {
                            let (tex, tr) = match t {
                                Some(t) => self.texture(t),
                                None => (texture.clone(), false),
                            };
                            transparent |= tr;
                            texes.push(tex);
                        }
                        blob = Some(Box::new((shape.clone(), texes)));
                        shape
                    }
                    ShapeDesc::Blob { data, .. } => self.blob(data),
                    _ => make_shape(shape),
                };
                let b = s.bounds();
                let bounds = if o.transform.is_identity() {
                    b
                } else {
                    b.transformed(&o.transform)
                };
                let mesh = match shape {
                    ShapeDesc::Mesh(data) if !data.textures.is_empty() => {
                        let mut texes = Vec::with_capacity(data.textures.len());
                        for t in &data.textures {
                            let (tex, tr) = self.texture(t);
                            transparent |= tr;
                            texes.push(tex);
                        }
                        Some(Box::new((data.clone(), texes)))
                    }
                    _ => None,
                };
                (ObjKind::Shape(s, None), bounds, mesh)
            }
        };
        let clip: Vec<Object> = o
            .clipped_by
            .iter()
            .filter_map(|c| self.object(c, None, None, default))
            .collect();
        // Only what lies inside every clipping object is left.
        let bounds = clip.iter().fold(bounds, |b, c| b.intersection(&c.bounds));
        let bounds = if o.inverse { Aabb::INFINITE } else { bounds };
        Some(Object {
            kind,
            transform: (!o.transform.is_identity()).then(|| Box::new(*o.transform)),
            texture,
            interior_texture,
            mesh,
            blob,
            ior,
            no_shadow,
            no_image: o.no_image,
            no_reflection: o.no_reflection,
            no_radiosity: o.no_radiosity,
            importance: if o.rad_importance > 0.0 {
                (f64::from(o.rad_importance) * 255.0).round().max(1.0) as u8
            } else {
                u8::MAX
            },
            double_illuminate: o.double_illuminate,
            light_set: self.current_set,
            hollow: o.hollow.unwrap_or(self.hollow_default),
            inverse: o.inverse,
            bounds,
            transparent,
            clip,
            interior: int
                .filter(|i| i.fades() || i.has_media() || i.dispersion != 1.0 || i.caustics > 0.0)
                .map(|i| Box::new(self.interior(i))),
            photons: object_photon_flags(o),
            photon_mult: o.photons.spacing_mult(),
        })
    }
}

/// An object's photon flags: `no_shadow` makes it `pass_through` unless that is turned off
/// (manual 3.4.4.4.4).
fn object_photon_flags(o: &ObjectDesc) -> u8 {
    use crate::scene::photon::flags::*;
    let f = o.photons.flags;
    if o.no_shadow && f & PASS_THROUGH_OFF == 0 {
        f | PASS_THROUGH
    } else {
        f
    }
}

/// Gives a CSG's photon flags to its members (they are what rays and photons meet), keeping
/// flags the members set themselves.
pub(crate) fn inherit_photon_flags(o: &mut Object, from: u8) {
    o.photons |= from;
    let f = o.photons;
    if let ObjKind::Csg { children, .. } = &mut o.kind {
        for c in children {
            inherit_photon_flags(c, f);
        }
    }
}

fn csg_bounds(op: crate::scene::desc::CsgOp, kids: &[Object]) -> Aabb {
    use crate::scene::desc::CsgOp::*;
    match op {
        Union | Merge => kids.iter().fold(Aabb::EMPTY, |a, k| a.union(&k.bounds)),
        Intersection => kids
            .iter()
            .fold(Aabb::INFINITE, |a, k| a.intersection(&k.bounds)),
        Difference => kids[0].bounds,
    }
}

/// Normal patterns that named no noise generator use the scene's.
/// Whether `normal_generator` would change `n`.
fn normal_needs_generator(n: &crate::scene::desc::Normal) -> bool {
    use crate::scene::desc::NormalKind;
    match &n.kind {
        NormalKind::Pattern { pattern, .. } => pattern.needs_generator(),
        NormalKind::List { pattern, items } => {
            pattern.needs_generator() || items.iter().any(normal_needs_generator)
        }
        NormalKind::Map { pattern, map } => {
            pattern.needs_generator() || map.iter().any(|(_, i)| normal_needs_generator(i))
        }
        NormalKind::Flat | NormalKind::BumpMap(_) | NormalKind::Facets { .. } => false,
    }
}

fn normal_generator(n: &mut crate::scene::desc::Normal, gen: u8) {
    use crate::scene::desc::NormalKind;
    match &mut n.kind {
        NormalKind::Pattern { pattern, .. } => {
            pattern.take_generator(gen);
        }
        NormalKind::List { pattern, items } => {
            pattern.take_generator(gen);
            for i in items {
                normal_generator(i, gen);
            }
        }
        NormalKind::Map { pattern, map } => {
            pattern.take_generator(gen);
            for (_, i) in map {
                normal_generator(i, gen);
            }
        }
        NormalKind::Flat | NormalKind::BumpMap(_) | NormalKind::Facets { .. } => {}
    }
}
