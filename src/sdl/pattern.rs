//! Pattern keywords and pattern modifiers, shared by everything patterned (pigments today;
//! normals and textures can reuse them): which pattern, its arguments, frequency, phase, wave
//! types, turbulence, warps and noise generator. Colour maps and pigment maps are in texture.rs.

use crate::color::Rgbft;
use crate::math::{DVec3, Transform};
use crate::scene::pattern::{
    Fractal, Pattern, PatternKind, Slope, Turbulence, Warp, WarpKind, Wave,
};

use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};
use super::source::Span;
use super::value::Value;

/// Pattern keywords POV-Ray 3.7 has that lancer does not evaluate yet.
pub(super) const UNSUPPORTED_PATTERNS: &[&str] = &["facets", "pavement", "proportion"];

/// Pattern keywords lancer evaluates (see `pattern_keyword`).
const PATTERNS: &[&str] = &[
    "density_file",
    "object",
    "checker",
    "gradient",
    "onion",
    "radial",
    "spherical",
    "cylindrical",
    "boxed",
    "planar",
    "leopard",
    "marble",
    "wood",
    "spiral1",
    "spiral2",
    "brick",
    "hexagon",
    "bozo",
    "spotted",
    "bumps",
    "granite",
    "agate",
    "wrinkles",
    "dents",
    "ripples",
    "waves",
    "crackle",
    "cells",
    "quilted",
    "tiling",
    "function",
    "mandel",
    "julia",
    "magnet",
    "average",
    "square",
    "triangular",
    "cubic",
    "pigment_pattern",
    "image_pattern",
    "slope",
    "aoi",
];

/// Whether `k` names a pattern of POV-Ray 3.7, evaluated by lancer or not.
pub(super) fn is_pattern_keyword(k: &str) -> bool {
    PATTERNS.contains(&k) || UNSUPPORTED_PATTERNS.contains(&k)
}

/// Modifiers of patterns lancer does not evaluate, read past with a warning (one value each).
const UNSUPPORTED_MODIFIERS: &[&str] = &["orientation", "dist_exp", "strength"];

/// Where `warp { planar n, d }` puts a point's x, y and the distance d: POV-Ray's frame for
/// the six axis normals, measured with scripts/measure_pattern.py (`function { 0.5+0.1*x }
/// warp { planar ... }` and the same for y and z). For other normals povray's frame is not
/// orthonormal (n = <1,1,0> gives e1 = (1,0,−1)/√2, e2 = (0,1,1)/√2, e3 = (1,−1,0)/√2) and its
/// rule is not recovered yet: None.
fn planar_frame(n: DVec3) -> Option<(DVec3, DVec3, DVec3)> {
    let n = n.normalize_or_zero();
    let (x, y, z) = (DVec3::X, DVec3::Y, DVec3::Z);
    let axes = [
        (z, (x, y, z)),
        (-z, (-x, -y, -z)),
        (y, (x, z, -y)),
        (-y, (-x, -z, y)),
        (x, (-z, y, x)),
        (-x, (z, -y, -x)),
    ];
    axes.iter()
        .find(|(a, _)| (n - *a).length() < 1e-12)
        .map(|(_, f)| *f)
}

/// The colours a pattern uses when no map or list is given (measured with povray).
pub fn default_map(kind: &PatternKind) -> Vec<(f64, Rgbft)> {
    let c = |r: f64, g: f64, b: f64| Rgbft::rgb(DVec3::new(r, g, b));
    match kind {
        PatternKind::Bozo => vec![
            (0.4, c(1.0, 1.0, 1.0)),
            (0.4, c(0.0, 1.0, 0.0)),
            (0.6, c(0.0, 1.0, 0.0)),
            (0.6, c(0.0, 0.0, 1.0)),
            (0.8, c(0.0, 0.0, 1.0)),
            (0.8, c(1.0, 0.0, 0.0)),
        ],
        PatternKind::Marble => vec![
            (0.0, c(0.9, 0.8, 0.8)),
            (0.9, c(0.9, 0.08, 0.08)),
            (0.9, c(0.0, 0.0, 0.0)),
        ],
        PatternKind::Wood => vec![(0.6, c(0.666, 0.312, 0.2)), (0.6, c(0.4, 0.1333, 0.066))],
        PatternKind::Radial => vec![
            (0.0, c(0.0, 1.0, 1.0)),
            (1.0 / 3.0, c(1.0, 1.0, 0.0)),
            (2.0 / 3.0, c(1.0, 0.0, 1.0)),
            (1.0, c(0.0, 1.0, 1.0)),
        ],
        // Only the Mandelbrot set of exponent 2 has one (julia and higher exponents ramp black
        // to white like most patterns).
        PatternKind::Fractal(f) if f.julia.is_none() && f.exponent == 2 => vec![
            (0.0, c(0.0, 0.0, 0.0)),
            (0.001, c(0.0, 0.0, 0.0)),
            (0.001, c(0.0, 1.0, 1.0)),
            (0.012, c(1.0, 1.0, 0.0)),
            (0.015, c(1.0, 0.0, 1.0)),
            (0.1, c(0.0, 1.0, 1.0)),
        ],
        PatternKind::Agate { .. } => vec![
            (0.0, c(1.0, 1.0, 1.0)),
            (0.5, c(0.95, 0.75, 0.5)),
            (0.5, c(0.9, 0.7, 0.5)),
            (0.6, c(0.9, 0.7, 0.4)),
            (0.6, c(1.0, 0.7, 0.4)),
            (1.0, c(0.6, 0.3, 0.0)),
        ],
        _ => vec![(0.0, Rgbft::BLACK), (1.0, c(1.0, 1.0, 1.0))],
    }
}

/// The items a block pattern uses when none are listed.
pub fn default_items(kind: &PatternKind) -> Vec<Rgbft> {
    let c = |r: f64, g: f64, b: f64| Rgbft::rgb(DVec3::new(r, g, b));
    match kind {
        PatternKind::Hexagon => vec![c(0.0, 0.0, 1.0), c(0.0, 1.0, 0.0), c(1.0, 0.0, 0.0)],
        PatternKind::Brick { .. } => vec![c(0.5, 0.5, 0.5), c(0.6, 0.15, 0.15)],
        PatternKind::Square => vec![
            c(1.0, 0.0, 0.0),
            c(0.0, 1.0, 0.0),
            c(0.0, 0.0, 1.0),
            c(1.0, 1.0, 0.0),
        ],
        PatternKind::Triangular | PatternKind::Cubic => vec![
            c(1.0, 0.0, 0.0),
            c(0.0, 1.0, 0.0),
            c(0.0, 0.0, 1.0),
            c(1.0, 1.0, 0.0),
            c(0.0, 1.0, 1.0),
            c(1.0, 0.0, 1.0),
        ],
        _ => vec![c(0.0, 0.0, 1.0), c(0.0, 1.0, 0.0)],
    }
}

impl Parser {
    /// The pattern a keyword just read names, with its arguments; None when `k` is not a
    /// pattern lancer evaluates. Unsupported patterns give `PatternKind::Unsupported` after a
    /// warning.
    pub(super) fn pattern_keyword(&mut self, k: &str, span: Span) -> PResult<Option<PatternKind>> {
        Ok(Some(match k {
            "checker" => PatternKind::Checker,
            // POV-Ray uses only the direction: `gradient 2*x` repeats every unit too.
            "gradient" => PatternKind::Gradient(self.parse_vector()?.normalize_or_zero()),
            "onion" => PatternKind::Onion,
            "radial" => PatternKind::Radial,
            "spherical" => PatternKind::Spherical,
            "cylindrical" => PatternKind::Cylindrical,
            "boxed" => PatternKind::Boxed,
            "planar" => PatternKind::Planar,
            "leopard" => PatternKind::Leopard,
            "marble" => PatternKind::Marble,
            "wood" => PatternKind::Wood,
            // Measured: the number of arms is truncated to an integer (2.5 draws 2, -1.5 -1).
            "spiral1" => PatternKind::Spiral1(self.parse_float()?.trunc()),
            "spiral2" => PatternKind::Spiral2(self.parse_float()?.trunc()),
            "brick" => PatternKind::Brick {
                size: DVec3::new(8.0, 3.0, 4.5),
                mortar: 0.5,
            },
            "hexagon" => PatternKind::Hexagon,
            "bozo" => PatternKind::Bozo,
            "spotted" | "bumps" => PatternKind::Spotted,
            "granite" => PatternKind::Granite,
            "agate" => PatternKind::Agate { turb: 1.0 },
            "wrinkles" => PatternKind::Wrinkles,
            "dents" => PatternKind::Dents,
            "ripples" => PatternKind::Ripples(self.scene.global.number_of_waves),
            "waves" => PatternKind::Waves(self.scene.global.number_of_waves),
            "crackle" => PatternKind::Crackle {
                form: DVec3::new(-1.0, 1.0, 0.0),
                metric: 2.0,
                offset: 0.0,
                solid: false,
            },
            "cells" => PatternKind::Cells,
            // The manual: both controls default to 1.
            "quilted" => PatternKind::Quilted { c0: 1.0, c1: 1.0 },
            "tiling" => {
                let n = self.parse_float()?;
                let n = if n >= 1.0 { n as u32 } else { 0 };
                if crate::scene::pattern::TILINGS_MEASURED.contains(&n) {
                    PatternKind::Tiling(n)
                } else {
                    self.unsupported(&format!("tiling {n} (lancer draws tiling 5 only)"), span);
                    PatternKind::Unsupported
                }
            }
            "square" => PatternKind::Square,
            "triangular" => PatternKind::Triangular,
            "cubic" => PatternKind::Cubic,
            "image_pattern" => {
                let mut im = self.parse_image_map(span)?;
                crate::scene::image::to_file_values(&mut im);
                PatternKind::ImagePattern(std::sync::Arc::new(im))
            }
            "pigment_pattern" => {
                self.open_brace("pigment_pattern")?;
                PatternKind::PigmentPattern(Box::new(self.parse_pigment_body_in_braces()?))
            }
            "object" => {
                // `object { OBJECT A, B }`: the list items follow the object inside the
                // braces; `close_object_pattern` reads the closing brace after them.
                self.open_brace("object")?;
                let desc = match self.parse_object()? {
                    Some(o) => o,
                    None => {
                        let t = self.next_tok()?;
                        match &t.tok {
                            super::lexer::Tok::Ident(n) => match self.lookup(n) {
                                Some(Value::Object(o)) => (**o).clone(),
                                _ => {
                                    return Err(self.error_at(
                                        t.span,
                                        format!("'{n}' is not an object identifier"),
                                    ))
                                }
                            },
                            _ => {
                                return Err(
                                    self.unexpected(&t, "in an object pattern; expected an object")
                                )
                            }
                        }
                    }
                };
                PatternKind::Object(std::sync::Arc::new(
                    crate::scene::pattern::ObjectPattern::new(desc),
                ))
            }
            "density_file" => {
                let fmt = self.next_tok()?;
                if !matches!(&fmt.tok, super::lexer::Tok::Ident(k) if &**k == "df3") {
                    return Err(self.unexpected(&fmt, "after density_file (expected df3)"));
                }
                let name_span = self.next_span()?;
                let name = self.parse_string()?;
                let interpolate = if self.eat_keyword("interpolate")? {
                    self.parse_float()?.round().max(0.0) as u32
                } else {
                    0
                };
                let Some(path) = self.find_file(&name) else {
                    return Err(self.error_at(name_span, format!("cannot find density file \"{name}\" (searched the scene directory and the library path)")));
                };
                let d = crate::scene::df3::Df3::load(&path, interpolate)
                    .map_err(|e| self.error_at(name_span, e))?;
                PatternKind::DensityFile(std::sync::Arc::new(d))
            }
            "average" => PatternKind::Average,
            // Shading records the surface for these only once one exists.
            "aoi" => {
                crate::scene::pattern::note_surface_pattern();
                PatternKind::Aoi
            }
            "slope" => {
                crate::scene::pattern::note_surface_pattern();
                PatternKind::Slope(Box::new(self.parse_slope()?))
            }
            "magnet" => {
                // magnet 1|2 mandel N, or magnet 1|2 julia <c>, N
                let t = self.parse_float()?;
                let julia = self.eat_keyword("julia")?;
                if !julia {
                    self.eat_keyword("mandel")?;
                }
                self.parse_fractal(julia, if t >= 2.0 { 2 } else { 1 })?
            }
            "mandel" | "julia" => self.parse_fractal(k == "julia", 0)?,
            "function" => {
                let v = self.parse_function_literal(span)?;
                match v {
                    Value::Function(f) if f.is_float() && f.unsupported.is_none() => {
                        PatternKind::Function(f)
                    }
                    Value::Function(f) => {
                        let why = f
                            .unsupported
                            .clone()
                            .unwrap_or_else(|| "function pattern of this kind".into());
                        self.warn(span, format!("this function pattern is not supported by lancer yet: {why}; it shows the middle of its map and the picture will differ from POV-Ray's"));
                        PatternKind::Unsupported
                    }
                    _ => PatternKind::Unsupported,
                }
            }
            k if UNSUPPORTED_PATTERNS.contains(&k) => {
                self.unsupported(&format!("{k} pattern"), span);
                PatternKind::Unsupported
            }
            _ => return Ok(None),
        }))
    }

    /// A fractal pattern's `[<c>,] N` after its keywords: a julia set's constant, then the
    /// iterations.
    fn parse_fractal(&mut self, julia: bool, magnet: u8) -> PResult<PatternKind> {
        let julia = if julia {
            let c = self.parse_vector()?;
            self.skip_optional_comma()?;
            Some((c.x, c.y))
        } else {
            None
        };
        let iterations = self.parse_float()?.clamp(0.0, 1e6) as u32;
        Ok(PatternKind::Fractal(Box::new(Fractal {
            julia,
            iterations,
            exponent: 2,
            magnet,
            interior: (0, 1.0),
            exterior: (1, 1.0),
        })))
    }

    /// After an `object` pattern's list items: its closing brace.
    pub(super) fn close_object_pattern(&mut self, kind: &PatternKind) -> PResult<()> {
        if matches!(kind, PatternKind::Object(_)) {
            self.expect_sym(Sym::RBrace, "to close the object pattern")?;
        }
        Ok(())
    }

    /// `slope { <dir> [, lo, hi] [altitude <a> [, lo, hi]] }` or `slope { point_at <p> [, lo,
    /// hi] }` after the keyword.
    fn parse_slope(&mut self) -> PResult<Slope> {
        if !self.eat_sym(Sym::LBrace)? {
            // The old form without braces, `slope -z` (advanced/balcony/terrain.inc).
            return Ok(Slope::new(self.parse_vector()?, false, 0.0, 1.0, None));
        }
        let point_at = self.eat_keyword("point_at")?;
        let dir = self.parse_vector()?;
        let (mut lo, mut hi) = (0.0, 1.0);
        if self.eat_sym(Sym::Comma)? {
            lo = self.parse_float()?;
            self.skip_optional_comma()?;
            hi = self.parse_float()?;
        }
        let mut altitude = None;
        if !point_at && self.eat_keyword("altitude")? {
            let a = self.parse_vector()?;
            let (mut lo, mut hi) = (0.0, 1.0);
            if self.eat_sym(Sym::Comma)? {
                lo = self.parse_float()?;
                self.skip_optional_comma()?;
                hi = self.parse_float()?;
            }
            altitude = Some((a, lo, hi));
        }
        self.expect_sym(Sym::RBrace, "slope")?;
        Ok(Slope::new(dir, point_at, lo, hi, altitude))
    }

    /// A pattern modifier just read as keyword `k`; false when `k` is not one. `space` is the
    /// pattern's transform so far, which a warp keeps.
    pub(super) fn pattern_modifier(
        &mut self,
        k: &str,
        span: Span,
        pat: &mut Pattern,
        space: &Transform,
    ) -> PResult<bool> {
        if k == "interpolate" {
            // A density file's (read after its file name too, as densfile.pov writes it).
            let n = self.parse_float()?.round().max(0.0) as u32;
            match &mut pat.kind {
                PatternKind::DensityFile(d) => {
                    if let Some(d) = std::sync::Arc::get_mut(d) {
                        d.interpolate = n;
                    } else {
                        let mut copy = crate::scene::df3::Df3::clone(d);
                        copy.interpolate = n;
                        *d = std::sync::Arc::new(copy);
                    }
                }
                _ => self.unsupported("interpolate (outside density_file)", span),
            }
            return Ok(true);
        }
        match k {
            "frequency" => {
                pat.frequency = self.parse_float()?;
                // lancer's wave sources are POV-Ray's measured to about 1e-6; a high frequency
                // (water normals use 100000 at scale 100000) turns that into other waves.
                // Measured: `ripples scale 100 frequency 100` already differs by 0.1-0.9.
                if matches!(pat.kind, PatternKind::Ripples(_) | PatternKind::Waves(_))
                    && pat.frequency.abs() >= 50.0
                {
                    self.warn(span, "'frequency' is not supported by lancer yet: ripples and waves at a frequency this high magnify the 1e-6 error of lancer's measured wave sources, so the waves will differ from POV-Ray's");
                }
            }
            "phase" => pat.phase = self.parse_float()?,
            "ramp_wave" => pat.wave = Wave::Ramp,
            "triangle_wave" => pat.wave = Wave::Triangle,
            "sine_wave" => pat.wave = Wave::Sine,
            "scallop_wave" => pat.wave = Wave::Scallop,
            "cubic_wave" => pat.wave = Wave::Cubic,
            "poly_wave" => {
                let e = if self.starts_float()? {
                    self.parse_float()?
                } else {
                    1.0
                };
                pat.wave = Wave::Poly(e);
            }
            "turbulence" => {
                let amount = self.parse_vector()?;
                pat.turbulence
                    .get_or_insert_with(Turbulence::default)
                    .amount = amount;
            }
            "octaves" | "omega" | "lambda" => {
                let v = self.parse_float()?;
                let t = pat.turbulence.get_or_insert_with(Turbulence::default);
                set_turb_param(t, k, v);
            }
            "noise_generator" => {
                pat.noise_generator = (self.parse_float()? as i64).clamp(1, 3) as u8;
            }
            "agate_turb" => {
                let v = self.parse_float()?;
                if let PatternKind::Agate { turb } = &mut pat.kind {
                    *turb = v;
                }
            }
            "brick_size" | "mortar" => {
                let v = self.parse_vector()?;
                if let PatternKind::Brick { size, mortar } = &mut pat.kind {
                    if k == "mortar" {
                        *mortar = v.x;
                    } else {
                        *size = v;
                    }
                }
            }
            "exponent" => {
                let e = self.parse_float()?;
                if let PatternKind::Fractal(f) = &mut pat.kind {
                    f.exponent = (e as i64).clamp(2, 33) as u32;
                }
            }
            "interior" | "exterior" => {
                // A fractal's colouring: type, factor.
                let t = self.parse_float()?;
                self.skip_optional_comma()?;
                let factor = self.parse_float()?;
                match &mut pat.kind {
                    PatternKind::Fractal(f) => {
                        let v = ((t as i64).clamp(0, 8) as u8, factor);
                        if k == "interior" {
                            f.interior = v;
                        } else {
                            f.exterior = v;
                        }
                    }
                    _ => self.unsupported(k, span),
                }
            }
            "form" | "metric" | "offset" | "solid" => {
                let v = if k == "solid" {
                    DVec3::ONE
                } else if k == "form" {
                    self.parse_vector()?
                } else {
                    DVec3::splat(self.parse_float()?)
                };
                if let PatternKind::Crackle {
                    form,
                    metric,
                    offset,
                    solid,
                } = &mut pat.kind
                {
                    match k {
                        "form" => *form = v,
                        "metric" => *metric = v.x,
                        "offset" => *offset = v.x,
                        _ => *solid = true,
                    }
                }
            }
            "control0" | "control1" => {
                let v = self.parse_float()?;
                match &mut pat.kind {
                    PatternKind::Quilted { c0, .. } if k == "control0" => *c0 = v,
                    PatternKind::Quilted { c1, .. } => *c1 = v,
                    _ => self.unsupported(&format!("{k} (outside quilted)"), span),
                }
            }
            "warp" => {
                if let Some(kind) = self.parse_warp_block(span)? {
                    pat.warps.push(Warp {
                        space: *space,
                        kind,
                    });
                }
            }
            k if UNSUPPORTED_MODIFIERS.contains(&k) => {
                self.unsupported(k, span);
                self.parse_expr()?;
            }
            _ => return Ok(false),
        }
        Ok(true)
    }

    /// `warp { ... }` after the keyword; None (after a warning) for warps lancer lacks.
    fn parse_warp_block(&mut self, span: Span) -> PResult<Option<WarpKind>> {
        self.open_brace("warp")?;
        let t = self.next_tok()?;
        let Tok::Ident(k) = &t.tok else {
            return Err(self.unexpected(&t, "in warp"));
        };
        let mut kind = match &**k {
            "turbulence" => WarpKind::Turbulence(Turbulence {
                amount: self.parse_vector()?,
                ..Turbulence::default()
            }),
            "repeat" => WarpKind::Repeat {
                dir: self.parse_vector()?,
                offset: DVec3::ZERO,
                flip: DVec3::ZERO,
            },
            "black_hole" => {
                let center = self.parse_vector()?;
                self.skip_optional_comma()?;
                WarpKind::BlackHole {
                    center,
                    radius: self.parse_float()?,
                    strength: 1.0,
                    falloff: 2.0,
                    inverse: false,
                    repeat: DVec3::ZERO,
                    turbulence: DVec3::ZERO,
                }
            }
            "cylindrical" | "spherical" => WarpKind::Wrap {
                spherical: &**k == "spherical",
                orientation: 2,
                dist_exp: 0.0,
            },
            "planar" => {
                let (mut n, mut d) = (DVec3::Z, 0.0);
                if self.peek_sym()? != Some(Sym::RBrace) {
                    n = self.parse_vector()?;
                    self.skip_optional_comma()?;
                    d = self.parse_float()?;
                }
                match planar_frame(n) {
                    Some((e1, e2, e3)) => WarpKind::Planar { e1, e2, e3, d },
                    None => {
                        self.unsupported("warp planar (with a normal not along an axis)", span);
                        self.skip_rest_of_block()?;
                        return Ok(None);
                    }
                }
            }
            other => {
                self.unsupported(&format!("warp {other}"), span);
                self.skip_rest_of_block()?;
                return Ok(None);
            }
        };
        loop {
            let t = self.next_tok()?;
            let Tok::Ident(m) = &t.tok else {
                if t.tok == Tok::Sym(Sym::RBrace) {
                    fix_repeated_black_hole(&mut kind);
                    return Ok(Some(kind));
                }
                return Err(self.unexpected(&t, "in warp"));
            };
            match (&mut kind, &**m) {
                (WarpKind::Turbulence(tb), "octaves" | "omega" | "lambda") => {
                    let v = self.parse_float()?;
                    set_turb_param(tb, m, v);
                }
                (WarpKind::Wrap { dist_exp, .. }, "dist_exp") => *dist_exp = self.parse_float()?,
                (WarpKind::Wrap { orientation, .. }, "orientation") => {
                    let v = self.parse_vector()?;
                    let axis = [DVec3::X, DVec3::Y, DVec3::Z]
                        .iter()
                        .position(|a| v.normalize_or_zero() == *a);
                    match axis {
                        Some(i) => *orientation = i as u8,
                        None => self.unsupported("warp orientation (other than x, y or z)", t.span),
                    }
                }
                (WarpKind::Repeat { offset, .. }, "offset") => *offset = self.parse_vector()?,
                (WarpKind::Repeat { flip, .. }, "flip") => *flip = self.parse_vector()?,
                (
                    WarpKind::BlackHole {
                        strength,
                        falloff,
                        inverse,
                        repeat,
                        turbulence,
                        ..
                    },
                    key,
                ) if matches!(
                    key,
                    "strength" | "falloff" | "inverse" | "repeat" | "turbulence" | "type"
                ) =>
                {
                    match key {
                        "strength" => *strength = self.parse_float()?,
                        "falloff" => *falloff = self.parse_float()?,
                        "inverse" => *inverse = true,
                        "repeat" => *repeat = self.parse_vector()?,
                        "turbulence" => *turbulence = self.parse_vector()?,
                        _ => {
                            self.parse_float()?;
                        }
                    }
                }
                _ => return Err(self.error_at(t.span, format!("unexpected '{m}' in warp"))),
            }
        }
    }

    /// Reads to the closing brace of a block whose opening brace was already read.
    fn skip_rest_of_block(&mut self) -> PResult<()> {
        let mut depth = 1;
        while depth > 0 {
            let t = self.next_tok()?;
            match t.tok {
                Tok::Sym(Sym::LBrace) => depth += 1,
                Tok::Sym(Sym::RBrace) => depth -= 1,
                _ => {}
            }
        }
        Ok(())
    }
}

/// A repeated black hole must fit inside its block: on each repeated axis POV-Ray moves a
/// centre closer to the block's edge than the radius out to the radius, and widens a block too
/// narrow for centre + radius (measured: a hole at the origin repeats as one at the radius).
fn fix_repeated_black_hole(kind: &mut WarpKind) {
    if let WarpKind::BlackHole {
        center,
        radius,
        repeat,
        ..
    } = kind
    {
        for k in 0..3 {
            if repeat[k] != 0.0 {
                center[k] = center[k].max(*radius);
                repeat[k] = repeat[k].max(center[k] + *radius);
            }
        }
    }
}

fn set_turb_param(t: &mut Turbulence, k: &str, v: f64) {
    match k {
        "octaves" => t.octaves = (v as i64).clamp(1, 10) as u32,
        "omega" => t.omega = v,
        _ => t.lambda = v,
    }
}
