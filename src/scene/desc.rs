//! The declarative scene description: plain, clonable values produced by the parser.
//!
//! This is what `#declare` stores and what snippet tests inspect. Transforms applied to an
//! object are applied at once to its shape transform and to every texture already attached
//! (POV-Ray's semantics: a texture given before a `translate` moves with the object, one given
//! after does not). CSG children without a texture inherit their parent's texture only when the
//! scene is built, as POV-Ray's post-processing does, so later modifiers on the parent count.

use std::sync::Arc;

use crate::color::Rgbft;
use crate::math::{DVec3, Transform, Xform};
pub use crate::scene::atmosphere::{FogDesc, RainbowDesc};
pub use crate::scene::pattern::Pattern;

#[derive(Clone, Debug)]
pub struct SceneDesc {
    pub camera: CameraDesc,
    pub lights: Vec<LightDesc>,
    pub objects: Vec<ObjectDesc>,
    pub background: Rgbft,
    pub sky_sphere: Option<Vec<Pigment>>,
    pub global: GlobalSettings,
    /// The texture given to objects that have none (`#default`).
    /// `default { radiosity { importance } }`: the importance of objects without their own.
    pub default_importance: Option<f32>,
    pub default_texture: Texture,
    /// `#version` in force at the end of parsing, if the scene set one.
    pub version: Option<f64>,
    /// Fog layers, applied in the order given.
    pub fogs: Vec<FogDesc>,
    /// Atmospheric `media { }`, outside every solid object.
    pub media: Vec<crate::scene::media::Media>,
}

#[derive(Clone, Debug)]
pub struct GlobalSettings {
    /// None when the scene did not say; the builder decides (3.7 rules) and warns.
    pub assumed_gamma: Option<f64>,
    pub max_trace_level: u32,
    pub adc_bailout: f64,
    pub ambient_light: DVec3,
    /// `noise_generator` for patterns that do not name their own.
    pub noise_generator: u8,
    /// `number_of_waves`: how many wave sources ripples and waves read after it (1 to 10).
    pub number_of_waves: u8,
    /// `radiosity { ... }`: present turns radiosity on.
    pub radiosity: Option<RadiositySettings>,
    /// `photons { ... }`: present turns photons on.
    pub photons: Option<crate::scene::photon::PhotonSettings>,
}

/// `global_settings { radiosity { ... } }` with POV-Ray 3.7's defaults (manual 3.4.1).
#[derive(Clone, Debug, PartialEq)]
pub struct RadiositySettings {
    pub adc_bailout: f64,
    pub always_sample: bool,
    pub brightness: f64,
    pub count: u32,
    /// `count`'s second value: the pool of directions the rays are drawn from.
    pub count_pool: u32,
    pub error_bound: f64,
    pub gray_threshold: f64,
    pub low_error_factor: f64,
    /// Non-positive: no limit.
    pub max_sample: f64,
    pub maximum_reuse: f64,
    pub minimum_reuse: f64,
    pub nearest_count: u32,
    pub normal: bool,
    pub pretrace_start: f64,
    pub pretrace_end: f64,
    pub recursion_limit: u32,
    /// Scenes for POV-Ray before 3.7 keep their `ambient` beside radiosity's light (set by
    /// the scene builder from `#version`; measured, docs/povray-behaviour.md).
    pub keep_ambient: bool,
}

impl Default for RadiositySettings {
    fn default() -> Self {
        RadiositySettings {
            adc_bailout: 0.01,
            always_sample: false,
            brightness: 1.0,
            count: 35,
            count_pool: 35,
            error_bound: 1.8,
            gray_threshold: 0.0,
            low_error_factor: 0.5,
            max_sample: -1.0,
            maximum_reuse: 0.2,
            minimum_reuse: 0.015,
            nearest_count: 5,
            normal: false,
            pretrace_start: 0.08,
            pretrace_end: 0.04,
            recursion_limit: 2,
            keep_ambient: false,
        }
    }
}

impl Default for GlobalSettings {
    fn default() -> Self {
        GlobalSettings {
            assumed_gamma: None,
            max_trace_level: 5,
            adc_bailout: 1.0 / 255.0,
            ambient_light: DVec3::ONE,
            noise_generator: 2,
            number_of_waves: 10,
            radiosity: None,
            photons: None,
        }
    }
}

/// Camera items as written; `CameraDesc::resolve` applies them in POV-Ray's fixed order.
#[derive(Clone, Debug)]
pub struct CameraDesc {
    pub location: DVec3,
    pub direction: DVec3,
    pub right: DVec3,
    pub up: DVec3,
    pub sky: DVec3,
    pub look_at: Option<DVec3>,
    pub angle: Option<f64>,
    /// Transforms written inside the camera block, applied after everything else.
    pub transform: Transform,
    pub orthographic: bool,
    /// Projections other than perspective and orthographic.
    pub projection: Projection,
    /// `angle H, V`: the vertical angle of a spherical camera.
    pub v_angle: Option<f64>,
    /// `right` or `up` written in the block: an orthographic camera then takes its view size
    /// from them, otherwise from the perspective view it replaces.
    pub sized: bool,
    /// `angle` written (with or without a value).
    pub angle_given: bool,
    /// `normal { ... }`: perturbs every camera ray's direction.
    pub normal: Option<Normal>,
    /// `mesh_camera { }`: rays from mesh faces instead of a projection.
    pub mesh: Option<Arc<crate::scene::mesh_camera::MeshCameraDesc>>,
    /// Focal blur (inactive without both `aperture` and `blur_samples`).
    pub blur: crate::scene::focal::FocalDesc,
}

impl Default for CameraDesc {
    fn default() -> Self {
        CameraDesc {
            location: DVec3::ZERO,
            direction: DVec3::Z,
            right: DVec3::new(1.33, 0.0, 0.0),
            up: DVec3::Y,
            sky: DVec3::Y,
            look_at: None,
            angle: None,
            transform: Transform::IDENTITY,
            orthographic: false,
            projection: Projection::Perspective,
            v_angle: None,
            sized: false,
            angle_given: false,
            normal: None,
            mesh: None,
            blur: Default::default(),
        }
    }
}

/// POV-Ray's camera projections (orthographic is a flag of its own, `CameraDesc::orthographic`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Projection {
    Perspective,
    Fisheye,
    UltraWideAngle,
    Omnimax,
    Panoramic,
    Spherical,
    /// `cylinder 1..4`.
    Cylinder(u8),
}

#[derive(Clone, Debug)]
pub struct LightDesc {
    pub position: DVec3,
    pub color: DVec3,
    pub shadowless: bool,
    pub fade_distance: Option<f64>,
    pub fade_power: f64,
    pub kind: LightKind,
    /// Where a spotlight, cylinder or parallel light points (POV-Ray's default <0,0,1>).
    pub point_at: DVec3,
    /// Hot-spot and edge: degrees for spotlights, distances from the axis for cylinders;
    /// None takes the kind's default.
    pub radius: Option<f64>,
    pub falloff: Option<f64>,
    pub tightness: f64,
    pub parallel: bool,
    pub area: Option<AreaLightDesc>,
    /// `looks_like`: an object drawn at the light (placed at its location), casting no shadow.
    pub looks_like: Option<Box<ObjectDesc>>,
    /// `projected_through`: only light whose path crosses this object arrives.
    pub projected_through: Option<Box<ObjectDesc>>,
    /// `media_interaction` (on by default): scattering media scatter this light.
    pub media_interaction: bool,
    /// `media_attenuation` (off by default): media dim this light on its way.
    pub media_attenuation: bool,
    pub photons: crate::scene::photon::LightPhotons,
}

impl LightDesc {
    pub fn at(position: DVec3) -> LightDesc {
        LightDesc {
            position,
            color: DVec3::ONE,
            shadowless: false,
            fade_distance: None,
            fade_power: 0.0,
            kind: LightKind::Point,
            point_at: DVec3::Z,
            radius: None,
            falloff: None,
            tightness: 0.0,
            parallel: false,
            area: None,
            looks_like: None,
            projected_through: None,
            media_interaction: true,
            media_attenuation: false,
            photons: Default::default(),
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightKind {
    Point,
    Spot,
    Cylinder,
}

/// `area_light <axis1>, <axis2>, size1, size2` and its modifiers.
#[derive(Clone, Debug)]
pub struct AreaLightDesc {
    pub axis1: DVec3,
    pub axis2: DVec3,
    pub size1: u32,
    pub size2: u32,
    pub adaptive: Option<u32>,
    pub jitter: bool,
    pub circular: bool,
    pub orient: bool,
    /// `area_illumination`: each point of the array lights the surface from its own
    /// direction (diffuse and highlights), not only shadows it.
    pub illumination: bool,
}

/// A 1×1 array: holds the modifiers of an area light given before its `area_light` line.
impl Default for AreaLightDesc {
    fn default() -> AreaLightDesc {
        AreaLightDesc {
            axis1: DVec3::ZERO,
            axis2: DVec3::ZERO,
            size1: 1,
            size2: 1,
            adaptive: None,
            jitter: false,
            circular: false,
            orient: false,
            illumination: false,
        }
    }
}

#[derive(Clone, Debug)]
pub struct ObjectDesc {
    pub shape: ShapeDesc,
    /// Object space to world space.
    pub transform: Xform,
    /// Shared with the runtime object (and between CSG members that inherit it), not copied.
    pub texture: Option<Arc<Texture>>,
    /// `interior_texture`: the texture of the surface seen from inside (where its normal
    /// points away from the ray).
    pub interior_texture: Option<Arc<Texture>>,
    pub interior: Option<Interior>,
    pub no_shadow: bool,
    /// `no_image`: unseen by camera rays and their transmitted continuations.
    pub no_image: bool,
    /// `no_reflection`: unseen by reflected rays.
    pub no_reflection: bool,
    /// `no_radiosity`: unseen by radiosity's gathering rays.
    pub no_radiosity: bool,
    /// `radiosity { importance }`: the share of radiosity's gathering rays that meet it and
    /// are followed, above 0 (0: not written; CSG members inherit their parent's). Not an
    /// Option: that would grow every object description by 8 bytes.
    pub rad_importance: f32,
    /// `double_illuminate`: lit by lights behind its surface too (diffuse only).
    pub double_illuminate: bool,
    pub hollow: Option<bool>,
    pub inverse: bool,
    /// A `light_group` (read as a union) and its `global_lights` setting: its lights light
    /// only its objects, which the scene's other lights light only with `global_lights on`.
    pub light_group: Option<bool>,
    /// `clipped_by { ... }`: only the surface inside all of these is kept.
    pub clipped_by: Vec<ObjectDesc>,
    pub photons: crate::scene::photon::ObjectPhotons,
}

impl ObjectDesc {
    pub fn new(shape: ShapeDesc) -> ObjectDesc {
        ObjectDesc {
            shape,
            transform: Xform::IDENTITY,
            texture: None,
            interior_texture: None,
            interior: None,
            no_shadow: false,
            no_image: false,
            no_reflection: false,
            no_radiosity: false,
            rad_importance: 0.0,
            double_illuminate: false,
            hollow: None,
            inverse: false,
            light_group: None,
            clipped_by: Vec::new(),
            photons: Default::default(),
        }
    }

    /// Applies a transform to the object, its attached texture and, for CSG, every child.
    pub fn apply_transform(&mut self, t: &Transform) {
        if let Some(tex) = &mut self.texture {
            Arc::make_mut(tex).apply_object_transform(t);
        }
        if let Some(tex) = &mut self.interior_texture {
            Arc::make_mut(tex).apply_object_transform(t);
        }
        if let Some(int) = &mut self.interior {
            int.apply_transform(t);
        }
        for c in &mut self.clipped_by {
            c.apply_transform(t);
        }
        match &mut self.shape {
            ShapeDesc::Csg { children, .. } => {
                for c in children {
                    c.apply_transform(t);
                }
            }
            ShapeDesc::Blob { textures, .. } => {
                for tex in textures.iter_mut().flatten() {
                    tex.apply_object_transform(t);
                }
                self.transform.apply(t);
            }
            _ => self.transform.apply(t),
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CsgOp {
    Union,
    Merge,
    Intersection,
    Difference,
}

#[derive(Clone, Debug)]
pub enum ShapeDesc {
    Sphere {
        center: DVec3,
        radius: f64,
    },
    /// Points p with `normal · p = distance` (normal as written, not normalised).
    Plane {
        normal: DVec3,
        distance: f64,
    },
    Box {
        corner1: DVec3,
        corner2: DVec3,
    },
    Cylinder {
        base: DVec3,
        cap: DVec3,
        radius: f64,
        open: bool,
    },
    Cone {
        base: DVec3,
        base_radius: f64,
        cap: DVec3,
        cap_radius: f64,
        open: bool,
    },
    Disc {
        center: DVec3,
        normal: DVec3,
        radius: f64,
        hole_radius: f64,
    },
    Torus {
        major: f64,
        minor: f64,
        sturm: bool,
    },
    Triangle {
        p: [DVec3; 3],
    },
    SmoothTriangle(Box<SmoothTriangleDesc>),
    Mesh(Arc<MeshData>),
    /// `quadric`, `cubic`, `quartic`, `poly`, `polynomial`: zero set of a polynomial.
    Algebraic {
        order: usize,
        /// (powers of x, y, z; coefficient).
        terms: Vec<([u8; 3], f64)>,
        sturm: bool,
    },
    /// Laid-out glyphs shared by every copy of a `#declare`d text.
    Text(Arc<crate::geom::text::TextData>),
    /// Spline-swept objects and polygons, built when parsed (see `sdl::sweep`).
    Prism(Arc<crate::geom::prism::Prism>),
    Lathe(Arc<crate::geom::lathe::Lathe>),
    Sor(Arc<crate::geom::sor::Sor>),
    Polygon(Arc<crate::geom::polygon::Polygon>),
    SphereSweep(Arc<crate::geom::sphere_sweep::SphereSweep>),
    /// `superellipsoid { <e, n> }`, exponents already clamped to be positive.
    Superellipsoid {
        e: f64,
        n: f64,
    },
    /// `height_field { ... }` from an image or a function.
    HeightField(Arc<crate::geom::height_field::HeightData>),
    /// `isosurface { ... }`.
    Isosurface(Arc<crate::geom::isosurface::IsoData>),
    /// `blob { ... }`, with each component's own texture (None: the blob's).
    Blob {
        data: Arc<crate::geom::blob::BlobData>,
        textures: Vec<Option<Texture>>,
    },
    /// Shapes the parser builds whole (`julia_fractal`, `ovus`, ...): nothing is left to
    /// decide when the scene is built.
    Prebuilt(Arc<dyn crate::geom::Shape>),
    Csg {
        op: CsgOp,
        children: Vec<ObjectDesc>,
    },
    /// A light source is an object in POV-Ray: it may sit inside CSG and move with it.
    /// Boxed, as the rarer large variants are, to keep every object description small.
    Light(Box<LightDesc>),
}

/// A smooth triangle's corners and their normals.
#[derive(Clone, Debug)]
pub struct SmoothTriangleDesc {
    pub p: [DVec3; 3],
    pub n: [DVec3; 3],
}

/// Triangle soup shared by every copy of a `#declare`d mesh.
#[derive(Clone, Debug, Default)]
pub struct MeshData {
    pub vertices: Vec<DVec3>,
    /// Per-vertex normals for smooth triangles; empty when the mesh is flat.
    pub normals: Vec<DVec3>,
    pub triangles: Triangles,
    /// Texture coordinates (`uv_vectors`) for uv_mapping.
    pub uvs: Vec<[f64; 2]>,
    /// Textures named inside the mesh per triangle (index into this list).
    pub textures: Vec<Texture>,
    /// `inside_vector`: the mesh is a solid, a point inside when a ray from it along this
    /// direction crosses an odd number of triangles (manual 3.4.5.2.3).
    pub inside_vector: Option<DVec3>,
}

pub use super::mesh_triangles::{MeshTriangle, Triangles};

mod surface;
pub use surface::*;
