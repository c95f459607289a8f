//! What covers an object and fills it, as the parser produces them: textures (plain, layered,
//! patterned), pigments, normals, finishes and interiors. Part of the scene description
//! (`scene::desc` re-exports every item, so they are named `desc::Texture` and so on).

use std::path::PathBuf;
use std::sync::Arc;

use crate::color::Rgbft;
use crate::math::{DVec3, Transform, Xform};
use crate::scene::pattern::Pattern;

#[derive(Clone, Debug)]
pub struct Texture {
    pub pigment: Pigment,
    pub normal: Option<Box<Normal>>,
    pub finish: Finish,
    /// A layered texture's next layer down (`texture {A} texture {B}` puts B over A).
    pub under: Option<Box<Texture>>,
    /// A patterned texture (`texture { checker texture {..} texture {..} }`, `texture_map`):
    /// when set, it decides the pigment and finish and this layer's own are unused.
    pub pattern: Option<Box<TexturePattern>>,
    /// `uv_mapping` on the texture: all of it is evaluated at the surface's (u, v, 0).
    pub uv_mapping: bool,
}

/// The pattern of a patterned texture and the textures it chooses or blends between, which
/// are evaluated in the pattern's space.
#[derive(Clone, Debug)]
pub struct TexturePattern {
    pub pattern: Pattern,
    /// Pattern space to world space.
    pub transform: Transform,
    pub entries: TextureEntries,
}

#[derive(Clone, Debug)]
pub enum TextureEntries {
    /// A block pattern's listed textures.
    List(Vec<Texture>),
    /// `texture_map`, sorted by value.
    Map(Vec<(f64, Texture)>),
}

impl Default for Texture {
    fn default() -> Self {
        Texture {
            pigment: Pigment::solid(Rgbft::BLACK),
            normal: None,
            finish: Finish::default(),
            under: None,
            pattern: None,
            uv_mapping: false,
        }
    }
}

impl Texture {
    /// Whether any part of the texture (all its layers, map entries) is uv-mapped.
    pub fn uses_uv(&self) -> bool {
        self.layers().any(|t| {
            t.uv_mapping
                || t.pigment.uv_mapping
                || t.pattern.as_ref().is_some_and(|tp| match &tp.entries {
                    TextureEntries::List(items) => items.iter().any(Texture::uses_uv),
                    TextureEntries::Map(map) => map.iter().any(|(_, t)| t.uses_uv()),
                })
        })
    }

    pub fn apply_transform(&mut self, t: &Transform) {
        self.transform_layers(t, false);
    }

    /// The object's own transform, which moves its texture with it except where the texture
    /// is uv-mapped: uv coordinates travel with the surface already, and povray leaves a
    /// uv-mapped pattern unmoved by the object's transforms (measured: tests/probes/uv_*).
    pub fn apply_object_transform(&mut self, t: &Transform) {
        self.transform_layers(t, true);
    }

    /// Every layer's pigment, texture pattern and normal moved by `t`; with `keep_uv`, the
    /// uv-mapped ones stay.
    fn transform_layers(&mut self, t: &Transform, keep_uv: bool) {
        if !(keep_uv && self.uv_mapping) {
            if !(keep_uv && self.pigment.uv_mapping) {
                self.pigment.apply_transform(t);
            }
            if let Some(tp) = &mut self.pattern {
                tp.transform = tp.transform.then(t);
            }
            if let Some(n) = &mut self.normal {
                n.apply_transform(t);
            }
        }
        if let Some(u) = &mut self.under {
            u.transform_layers(t, keep_uv);
        }
    }

    /// This texture (itself possibly layered) laid over `below`.
    pub fn over(mut self, below: Texture) -> Texture {
        let mut bottom = &mut self;
        while bottom.under.is_some() {
            bottom = bottom.under.as_mut().unwrap();
        }
        bottom.under = Some(Box::new(below));
        self
    }

    /// The layers from the top down.
    pub fn layers(&self) -> impl Iterator<Item = &Texture> {
        std::iter::successors(Some(self), |t| t.under.as_deref())
    }
}

#[derive(Clone, Debug)]
pub struct Pigment {
    pub kind: PigmentKind,
    /// Pattern space to world space.
    pub transform: Xform,
    /// `quick_color`: what `+Q5` and below show instead of the pigment.
    pub quick: Option<Rgbft>,
    /// `uv_mapping`: the pattern is evaluated at the surface's (u, v, 0), not at the point.
    pub uv_mapping: bool,
}

impl Pigment {
    pub fn solid(c: Rgbft) -> Pigment {
        Pigment {
            kind: PigmentKind::Solid(c),
            transform: Xform::IDENTITY,
            quick: None,
            uv_mapping: false,
        }
    }
    pub fn apply_transform(&mut self, t: &Transform) {
        self.transform.apply(t);
        // Pigments nested in a list pattern are already in the outer pattern's space.
    }
}

#[derive(Clone, Debug)]
/// Patterns are boxed: pigments sit inside every object description, which the parser keeps
/// on the stack once per level of CSG nesting.
pub enum PigmentKind {
    Solid(Rgbft),
    /// A continuous pattern looked up in a colour map.
    Mapped {
        pattern: Box<Pattern>,
        map: ColorMap,
    },
    /// A discrete pattern choosing between whole pigments (checker, hexagon, brick).
    List {
        pattern: Box<Pattern>,
        items: Vec<Pigment>,
    },
    /// `pigment_map`: a continuous pattern blending whole pigments, sorted by value.
    PigmentMap {
        pattern: Box<Pattern>,
        map: Vec<(f64, Pigment)>,
    },
    /// An image, with the pattern that carries its turbulence and warps when it has any.
    ImageMap(Arc<ImageMap>, Option<Box<Pattern>>),
}

/// Colour map entries sorted by value, as POV-Ray's `color_map { [v colour] ... }`.
pub type ColorMap = Vec<(f64, Rgbft)>;

#[derive(Clone, Debug)]
pub struct ImageMap {
    pub path: PathBuf,
    /// 0 planar, 1 spherical (equirectangular), 2 cylindrical.
    pub map_type: u32,
    pub once: bool,
    pub interpolate: u32,
    pub width: u32,
    pub height: u32,
    /// Linear-light pixels, row 0 at the top (as stored in the file for an image pattern).
    pub pixels: crate::scene::image_pixels::ImagePixels,
    /// `use_alpha` (image patterns take their value from the alpha channel).
    pub use_alpha: bool,
    /// A bump map's `bump_size`, if it gave one.
    pub bump_size: Option<f64>,
    /// `use_index`: a bump map's height is the palette index, not the grey.
    pub use_index: bool,
}

impl ImageMap {
    /// An image map not yet loaded, with POV-Ray's defaults (planar, repeated, not
    /// interpolated); `use_index` as the map's kind takes it (a material map's texture is
    /// picked by palette index).
    pub fn new(use_index: bool) -> ImageMap {
        ImageMap {
            path: PathBuf::new(),
            map_type: 0,
            once: false,
            interpolate: 0,
            width: 0,
            height: 0,
            pixels: Default::default(),
            use_alpha: false,
            bump_size: None,
            use_index,
        }
    }
}

/// `normal { ... }`: how a texture perturbs the surface normal (evaluation in render::normal).
#[derive(Clone, Debug)]
pub struct Normal {
    pub kind: NormalKind,
    /// The pattern's strength (`bumps 0.5`, `bump_size`), POV-Ray's default 0.5.
    pub amount: f64,
    /// Pattern space to the parent's space (world for a texture's own normal).
    pub transform: Transform,
    /// Distance of the sample points of a sampled pattern's slope (`accuracy`, default 0.02).
    pub accuracy: f64,
    /// `no_bump_scale`: the bump depth follows the pattern's scaling.
    pub no_bump_scale: bool,
}

impl Normal {
    pub fn new(kind: NormalKind) -> Normal {
        Normal {
            kind,
            amount: 0.5,
            transform: Transform::IDENTITY,
            accuracy: 0.02,
            no_bump_scale: false,
        }
    }

    pub fn apply_transform(&mut self, t: &Transform) {
        self.transform = self.transform.then(t);
    }
}

/// A slope map entry: pattern value, then the height and slope there.
pub type SlopeMap = Vec<(f64, f64, f64)>;

/// The normal patterns of POV-Ray: the classic bump patterns with formulas of their own, any
/// other pattern by the slope of its value, lists and maps of whole normals, and image bumps.
#[derive(Clone, Debug)]
pub enum NormalKind {
    /// No pattern given: the surface normal stays as it is.
    Flat,
    /// bumps, dents, ripples, waves, wrinkles (their own formulas) or any pattern whose
    /// value's slope (through the slope map, if any) tilts the normal.
    Pattern {
        pattern: Box<Pattern>,
        special: Special,
        slope_map: Option<SlopeMap>,
    },
    /// A block pattern choosing whole normals (`checker normal {..} normal {..}`).
    List {
        pattern: Box<Pattern>,
        items: Vec<Normal>,
    },
    /// `normal_map` (and `average`): the normals around the pattern's value, blended.
    Map {
        pattern: Box<Pattern>,
        map: Vec<(f64, Normal)>,
    },
    /// `bump_map { ... }`: an image's grey (or palette index) as a height.
    BumpMap(Arc<ImageMap>),
    /// `facets`: flat facets from the cells of a crackle-like lattice (or of `coords`).
    Facets { coords: f64, size: f64 },
}

/// Which formula a pattern normal uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Special {
    /// The pattern's value, sampled around the point.
    Slope,
    Bumps,
    Dents,
    Ripples,
    Waves,
    Wrinkles,
    /// quilted: the cushion vector (`render::pattern::quilted_vector`) added to the normal.
    Quilted,
}

#[derive(Clone, Debug)]
pub struct Finish {
    pub ambient: DVec3,
    pub emission: DVec3,
    pub diffuse: f64,
    pub brilliance: f64,
    pub phong: f64,
    pub phong_size: f64,
    pub specular: f64,
    pub roughness: f64,
    pub metallic: f64,
    pub reflection: Reflection,
    pub conserve_energy: bool,
    /// `crand`: each light's diffuse term is scaled by 1 - crand·u, u uniform in [0, 1).
    pub crand: f64,
    /// `irid { amount thickness t turbulence u }` (boxed: rare, and textures stay small).
    pub irid: Option<Box<Irid>>,
}

/// Thin-film iridescence (render::irid).
#[derive(Clone, Debug, PartialEq)]
pub struct Irid {
    pub amount: f64,
    pub thickness: f64,
    pub turbulence: f64,
}

impl Default for Finish {
    fn default() -> Self {
        Finish {
            ambient: DVec3::splat(0.1),
            emission: DVec3::ZERO,
            diffuse: 0.6,
            brilliance: 1.0,
            phong: 0.0,
            phong_size: 40.0,
            specular: 0.0,
            roughness: 0.05,
            metallic: 0.0,
            reflection: Reflection::default(),
            conserve_energy: false,
            crand: 0.0,
            irid: None,
        }
    }
}

#[derive(Clone, Debug, Default)]
pub struct Reflection {
    /// Reflectivity facing the viewer (`reflection { min max }`: min).
    pub min: DVec3,
    /// Reflectivity at grazing angles.
    pub max: DVec3,
    pub falloff: f64,
    pub fresnel: bool,
    pub metallic: f64,
    /// `exponent`: the reflected colour is raised to 1/exponent before it is weighted
    /// (measured: reflection R of a background C shows R·C^(1/E)). 0 (unset) and 1 are linear.
    pub exponent: f32,
}

impl Reflection {
    pub fn is_zero(&self) -> bool {
        self.min == DVec3::ZERO && self.max == DVec3::ZERO
    }

    /// The power the reflected colour is raised to, when not 1.
    pub fn power(&self) -> Option<f64> {
        (self.exponent > 0.0 && self.exponent != 1.0).then(|| 1.0 / self.exponent as f64)
    }
}

#[derive(Clone, Debug)]
pub struct Interior {
    pub ior: f64,
    /// Light passing through fades to half over `fade_distance` (0: no fading).
    pub fade_distance: f64,
    pub fade_power: f64,
    /// What fully faded light keeps (black: nothing).
    pub fade_color: DVec3,
    /// `dispersion`: the ratio of the iors at the violet and red ends (1: none). f32 and u16:
    /// every object description holds an interior (tests/memory_layout.rs).
    pub dispersion: f32,
    /// `caustics`: shadow rays crossing the surface are brightened where it faces the light
    /// (0: off).
    pub caustics: f32,
    pub dispersion_samples: u16,
    /// `media { }` blocks, each computed on its own and added. Shared, so the members of a
    /// CSG that inherit one interior hold the same list (and it is counted once where they
    /// overlap).
    /// One pointer (every object description has room for an interior); interiors without
    /// media share one empty list.
    pub media: Arc<Vec<crate::scene::media::Media>>,
}

impl Default for Interior {
    fn default() -> Self {
        Interior {
            ior: 1.0,
            fade_distance: 0.0,
            fade_power: 0.0,
            fade_color: DVec3::ZERO,
            dispersion: 1.0,
            caustics: 0.0,
            dispersion_samples: 7,
            media: crate::scene::media::no_media(),
        }
    }
}

impl Interior {
    /// What a shadow ray's light is multiplied by where it crosses a surface of a `caustics`
    /// interior, `cos` the cosine between the (perturbed) normal and the light direction.
    /// Measured (scripts/measure_caustics.sh): 1 + |cos|^(45·caustics) per crossing, the
    /// same through both faces of a slab.
    pub fn caustic_gain(&self, cos: f64) -> f64 {
        if self.caustics <= 0.0 {
            1.0
        } else {
            1.0 + cos.abs().powf(45.0 * self.caustics as f64)
        }
    }

    /// What light keeps after `d` inside, per channel (measured with povray on fading
    /// slabs): a + (1 − a)·fade_color with a = 1/(1 + (d/fade_distance)^fade_power), or from
    /// fade_power 1000 on exp(−d/fade_distance · (1 − fade_color)).
    pub fn fade(&self, d: f64) -> DVec3 {
        if self.fade_distance <= 0.0 || self.fade_power <= 0.0 {
            return DVec3::ONE;
        }
        let x = d / self.fade_distance;
        if self.fade_power >= 1000.0 {
            let k = DVec3::ONE - self.fade_color;
            return DVec3::new((-x * k.x).exp(), (-x * k.y).exp(), (-x * k.z).exp());
        }
        let a = 1.0 / (1.0 + x.powf(self.fade_power));
        DVec3::splat(a) + (DVec3::ONE - a) * self.fade_color
    }

    /// The object's transforms move its media's densities with it.
    pub fn apply_transform(&mut self, t: &Transform) {
        if self.has_media() {
            for m in Arc::make_mut(&mut self.media) {
                m.apply_transform(t);
            }
        }
    }

    /// The `media { }` blocks, in order.
    pub fn media(&self) -> &[crate::scene::media::Media] {
        &self.media
    }

    pub fn has_media(&self) -> bool {
        !self.media.is_empty()
    }

    pub fn fades(&self) -> bool {
        self.fade_distance > 0.0 && self.fade_power > 0.0
    }
}
