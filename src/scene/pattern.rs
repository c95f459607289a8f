//! Pattern descriptions: which scalar field a pigment (and later a normal or texture) follows,
//! and the modifiers POV-Ray applies around it (turbulence, warps, frequency, phase, wave type,
//! noise generator). Evaluation is in `render::pattern`; this is plain data the parser builds.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

use crate::func::Function;
use crate::math::{DVec3, Transform};
use crate::scene::desc::{Pigment, PigmentKind};

/// Whether a pattern that reads the surface being shaded (slope, aoi: the callers of
/// `render::pattern::surface`; a new one must be noted too) has been made in this process:
/// until one has, shading need not record the surface (a thread-local write per hit). Set by
/// the parser where it makes one, never cleared: a scene parsed later, or at the same time on
/// another thread, can only keep it set, which costs time, not pictures.
static SURFACE_PATTERNS: AtomicBool = AtomicBool::new(false);

/// Notes that a slope or aoi pattern exists (see `SURFACE_PATTERNS`).
pub fn note_surface_pattern() {
    SURFACE_PATTERNS.store(true, Ordering::Relaxed);
}

/// Whether some slope or aoi pattern may be evaluated (see `SURFACE_PATTERNS`).
pub fn surface_patterns_made() -> bool {
    SURFACE_PATTERNS.load(Ordering::Relaxed)
}

#[derive(Clone, Debug)]
pub struct Pattern {
    pub kind: PatternKind,
    pub wave: Wave,
    pub frequency: f64,
    pub phase: f64,
    /// Turbulence written outside a warp: applied to the point before everything else
    /// (innermost), whatever its position among the transforms.
    pub turbulence: Option<Turbulence>,
    /// Warps in the order written; each keeps the pattern transform in force when it was read.
    pub warps: Vec<Warp>,
    /// 1, 2 or 3: which noise function the noise-based patterns and turbulence use.
    pub noise_generator: u8,
}

impl Pattern {
    /// Whether this pattern, or a pigment inside it (`pigment_pattern`), named no noise
    /// generator (0) and so waits for the scene's.
    pub fn needs_generator(&self) -> bool {
        self.noise_generator == 0
            || matches!(&self.kind, PatternKind::PigmentPattern(p) if p.needs_generator())
    }

    /// Gives the scene's noise generator to this pattern and the pigments inside it that named
    /// none. Measured: `pigment_pattern { agate }` under `noise_generator 1` is generator 1's
    /// agate, as are `function { pattern { agate } }` and `function { pigment { agate } }`.
    pub fn take_generator(&mut self, gen: u8) {
        if self.noise_generator == 0 {
            self.noise_generator = gen;
        }
        if let PatternKind::PigmentPattern(p) = &mut self.kind {
            p.take_generator(gen);
        }
    }

    pub fn new(kind: PatternKind) -> Pattern {
        // Wood, marble and the spirals are triangle waves unless told otherwise.
        let wave = match kind {
            PatternKind::Marble
            | PatternKind::Wood
            | PatternKind::Spiral1(_)
            | PatternKind::Spiral2(_) => Wave::Triangle,
            _ => Wave::Ramp,
        };
        Pattern {
            kind,
            wave,
            frequency: 1.0,
            phase: 0.0,
            turbulence: None,
            warps: Vec::new(),
            noise_generator: 2,
        }
    }

    /// Block patterns (checker, hexagon, brick, square, triangular, cubic) choose among listed
    /// items instead of reading a map.
    pub fn is_block(&self) -> bool {
        matches!(
            self.kind,
            PatternKind::Checker
                | PatternKind::Hexagon
                | PatternKind::Brick { .. }
                | PatternKind::Square
                | PatternKind::Triangular
                | PatternKind::Cubic
                | PatternKind::Object(_)
                | PatternKind::MaterialMap(..)
        )
    }
}

/// The `tiling` numbers lancer draws (the others are warned about).
pub const TILINGS_MEASURED: &[u32] = &[5];

#[derive(Clone, Debug)]
pub enum PatternKind {
    Checker,
    /// `gradient <v>`: the fractional part of p · v, v of unit length.
    Gradient(DVec3),
    Onion,
    Radial,
    Spherical,
    Cylindrical,
    Boxed,
    Planar,
    Leopard,
    Marble,
    Wood,
    /// `spiral1 arms`.
    Spiral1(f64),
    /// `spiral2 arms`: spiral1's value through a triangle wave plus the radius's.
    Spiral2(f64),
    Brick {
        size: DVec3,
        mortar: f64,
    },
    Hexagon,
    /// Unit squares in the x-z plane, four items.
    Square,
    /// Triangles of side 1 in the x-z plane, six items.
    Triangular,
    /// The six pyramids around the half-axes (+x, +y, +z, -x, -y, -z), six items.
    Cubic,
    /// `pigment_pattern { ... }`: the pigment's grey (0.297 r + 0.589 g + 0.114 b).
    PigmentPattern(Box<crate::scene::desc::Pigment>),
    /// `image_pattern { ... }`: the image's grey (file values), or with `use_alpha` its
    /// transparency (1 − alpha).
    ImagePattern(Arc<crate::scene::desc::ImageMap>),
    /// `slope { ... }`: the angle between the surface normal and a direction (or the way to a
    /// point), optionally mixed with a gradient (`altitude`).
    Slope(Box<Slope>),
    /// `aoi`: the angle between the surface normal and the ray.
    Aoi,
    /// bozo: one octave of noise.
    Bozo,
    /// spotted and (as a pigment) bumps: bozo's values with a grey default map.
    Spotted,
    Granite,
    Agate {
        turb: f64,
    },
    Wrinkles,
    Dents,
    /// Ripples and waves from the first N (`number_of_waves`, at most 10) wave sources.
    Ripples(u8),
    Waves(u8),
    Crackle {
        form: DVec3,
        metric: f64,
        offset: f64,
        solid: bool,
    },
    Cells,
    /// `quilted`: each unit cube a cushion whose seam's cross-section is a cubic Bézier with
    /// inner control points `control0` and `control1` (default 1, 1); see
    /// `render::pattern::quilted_vector`.
    Quilted {
        c0: f64,
        c1: f64,
    },
    /// `material_map { png "file" ... }`: the palette index of the image's pixel (planar,
    /// spherical, cylindrical or torus mapping like an image map), which picks a listed texture.
    MaterialMap(Arc<crate::scene::desc::ImageMap>, Arc<Vec<u8>>),
    /// `tiling N`, one of `TILINGS_MEASURED` (render::tiling).
    Tiling(u32),
    /// `mandel N` (`julia` None) or `julia <c>, N`: iterations of zⁿ + c from z = c = x + iy
    /// (mandel) or from z = x + iy (julia).
    Fractal(Box<Fractal>),
    /// `average`: the map's entries mixed by their weights, not chosen by a value.
    Average,
    /// `function { ... }` of x, y, z.
    Function(Arc<Function>),
    /// `object { OBJECT A, B }`: B inside the object, A outside.
    Object(Arc<ObjectPattern>),
    /// `density_file df3 "file"`: a voxel grid over the unit cube.
    DensityFile(Arc<crate::scene::df3::Df3>),
    /// A pattern lancer does not evaluate yet (already warned about): the middle of its map.
    Unsupported,
}

/// A slope pattern's parameters (measured: docs/povray-behaviour.md, Patterns). `dir` and
/// `point_at` are in world space: pattern transforms do not move them.
#[derive(Clone, Debug, PartialEq)]
pub struct Slope {
    /// The direction as written (its length weighs the slope against the altitude), or the
    /// reference point with `point_at`.
    pub dir: DVec3,
    pub point_at: bool,
    /// The slope values that give 0 and 1 (default 0, 1).
    pub lo: f64,
    pub hi: f64,
    /// `altitude <a>, lo, hi`: a gradient along a (pattern space) from lo to hi.
    pub altitude: Option<(DVec3, f64, f64)>,
    /// Made by [`Slope::new`] from the fields above, so every hit does not redo them (four
    /// square roots and three divisions a slope value): `dir`'s unit vector (unused with
    /// `point_at`), the altitude's unit vector, and the lengths of `dir` and the altitude
    /// that weigh the two.
    pub unit_dir: DVec3,
    pub unit_altitude: DVec3,
    pub weights: (f64, f64),
}

impl Slope {
    /// The slope with its derived fields, computed by the very operations the pattern used
    /// to do per hit (`normalize_or_zero`, `length`), so the values keep their bits.
    pub fn new(
        dir: DVec3,
        point_at: bool,
        lo: f64,
        hi: f64,
        altitude: Option<(DVec3, f64, f64)>,
    ) -> Slope {
        let a = altitude.map_or(DVec3::ZERO, |(a, _, _)| a);
        Slope {
            dir,
            point_at,
            lo,
            hi,
            altitude,
            unit_dir: dir.normalize_or_zero(),
            unit_altitude: a.normalize_or_zero(),
            weights: (dir.length(), a.length()),
        }
    }
}

#[derive(Clone, Debug)]
pub struct Fractal {
    /// The constant of a julia set; None for the Mandelbrot set.
    pub julia: Option<(f64, f64)>,
    pub iterations: u32,
    /// 2 to 33.
    pub exponent: u32,
    /// 0 for zⁿ + c; 1 or 2 for the magnet fractals, which start at z = 0 (mandel) or z = p
    /// (julia) and stop when z leaves radius 100 or comes within 0.01 of 1 (measured).
    pub magnet: u8,
    /// `interior type, factor` (default 0, 1) and `exterior type, factor` (default 1, 1).
    pub interior: (u8, f64),
    pub exterior: (u8, f64),
}

/// How the pattern's value (after frequency and phase) is shaped before the map lookup.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Wave {
    Ramp,
    Triangle,
    Sine,
    Scallop,
    Cubic,
    Poly(f64),
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Turbulence {
    pub amount: DVec3,
    pub octaves: u32,
    pub omega: f64,
    pub lambda: f64,
}

impl Default for Turbulence {
    fn default() -> Self {
        Turbulence {
            amount: DVec3::ZERO,
            octaves: 6,
            omega: 0.5,
            lambda: 2.0,
        }
    }
}

#[derive(Clone, Debug)]
pub struct Warp {
    /// The pattern's transform when the warp was read: the warp acts in that space.
    pub space: Transform,
    pub kind: WarpKind,
}

#[derive(Clone, Debug)]
pub enum WarpKind {
    /// `planar n, d`: the point's (x, y) read on another plane, p′ = x·e1 + y·e2 + d·e3
    /// (measured for the six axis normals; see `sdl::pattern::planar_frame`).
    Planar {
        e1: DVec3,
        e2: DVec3,
        e3: DVec3,
        d: f64,
    },
    Turbulence(Turbulence),
    /// `cylindrical` / `spherical` (measured with scripts/measure_pattern.py, see
    /// render::warp::wrap): the point as (angle around y in turns, height or latitude,
    /// distance), the angle (and a sphere's latitude) times distance^dist_exp, the triple
    /// turned so the distance runs along `orientation` (an axis).
    Wrap {
        spherical: bool,
        orientation: u8,
        dist_exp: f64,
    },
    Repeat {
        /// The repeat vector (one non-zero component).
        dir: DVec3,
        offset: DVec3,
        flip: DVec3,
    },
    BlackHole {
        center: DVec3,
        radius: f64,
        strength: f64,
        falloff: f64,
        inverse: bool,
        repeat: DVec3,
        turbulence: DVec3,
    },
}

/// The scene's noise generator handed down to a pigment's patterns (here beside
/// [`Pattern::take_generator`], which it recurses into).
impl Pigment {
    /// Whether any pattern in this pigment waits for the scene's noise generator.
    pub fn needs_generator(&self) -> bool {
        match &self.kind {
            PigmentKind::Solid(_) | PigmentKind::ImageMap(_, None) => false,
            PigmentKind::ImageMap(_, Some(pattern)) | PigmentKind::Mapped { pattern, .. } => {
                pattern.needs_generator()
            }
            PigmentKind::List { pattern, items } => {
                pattern.needs_generator() || items.iter().any(Pigment::needs_generator)
            }
            PigmentKind::PigmentMap { pattern, map } => {
                pattern.needs_generator() || map.iter().any(|(_, p)| p.needs_generator())
            }
        }
    }

    /// Gives the scene's noise generator to every pattern in this pigment that named none.
    pub fn take_generator(&mut self, gen: u8) {
        match &mut self.kind {
            PigmentKind::Solid(_) | PigmentKind::ImageMap(_, None) => {}
            PigmentKind::ImageMap(_, Some(pattern)) | PigmentKind::Mapped { pattern, .. } => {
                pattern.take_generator(gen)
            }
            PigmentKind::List { pattern, items } => {
                pattern.take_generator(gen);
                items.iter_mut().for_each(|p| p.take_generator(gen));
            }
            PigmentKind::PigmentMap { pattern, map } => {
                pattern.take_generator(gen);
                map.iter_mut().for_each(|(_, p)| p.take_generator(gen));
            }
        }
    }
}

/// The object of an `object` pattern: its description, built into a renderable object the
/// first time the pattern is evaluated (by any thread; the result is the same).
pub struct ObjectPattern {
    pub desc: crate::scene::desc::ObjectDesc,
    pub built: std::sync::OnceLock<Option<crate::scene::object::Object>>,
}

impl std::fmt::Debug for ObjectPattern {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ObjectPattern")
            .field("desc", &self.desc)
            .finish()
    }
}

impl ObjectPattern {
    pub fn new(desc: crate::scene::desc::ObjectDesc) -> ObjectPattern {
        ObjectPattern {
            desc,
            built: std::sync::OnceLock::new(),
        }
    }

    /// Whether `p` (pattern space) is inside the object.
    pub fn inside(&self, p: crate::math::DVec3) -> bool {
        self.built
            .get_or_init(|| crate::scene::build::standalone_object(&self.desc))
            .as_ref()
            .is_some_and(|o| o.inside(p))
    }
}
