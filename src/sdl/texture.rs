//! Texture statements: pigment (colours, patterns, colour maps, image maps), finish, normal,
//! texture and interior blocks.

use std::sync::Arc;

use crate::color::Rgbft;
use crate::math::DVec3;
use crate::scene::desc::{
    ColorMap, Finish, ImageMap, Normal, NormalKind, Pattern, Pigment, PigmentKind, Reflection,
    Texture,
};

use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};
use super::source::Span;
use super::value::Value;

/// Pattern keywords POV-Ray 3.7 has that lancer does not evaluate yet.
const UNSUPPORTED_PATTERNS: &[&str] = &[
    "agate",
    "image_pattern",
    "aoi",
    "average",
    "boxed",
    "bozo",
    "brick",
    "bumps",
    "cells",
    "crackle",
    "cubic",
    "cylindrical",
    "density_file",
    "dents",
    "facets",
    "function",
    "gradient_x",
    "granite",
    "hexagon",
    "julia",
    "leopard",
    "magnet",
    "mandel",
    "marble",
    "object",
    "onion",
    "pavement",
    "pigment_pattern",
    "planar",
    "quilted",
    "radial",
    "ripples",
    "slope",
    "spherical",
    "spiral1",
    "spiral2",
    "spotted",
    "square",
    "tiling",
    "triangular",
    "waves",
    "wood",
    "wrinkles",
    "proportion",
];

/// Pattern modifiers that change the picture and that lancer reads past with a warning.
/// Pattern modifiers followed by one value.
const UNSUPPORTED_MODIFIERS: &[&str] = &[
    "turbulence",
    "octaves",
    "omega",
    "lambda",
    "noise_generator",
    "agate_turb",
    "metric",
    "offset",
    "form",
    "control0",
    "control1",
    "interpolate",
    "orientation",
    "dist_exp",
    "strength",
    "mortar",
    "brick_size",
    "exponent",
];

/// Keywords that start a colour expression.
const COLOR_KEYWORDS: &[&str] = &[
    "color", "colour", "rgb", "rgbf", "rgbt", "rgbft", "srgb", "srgbf", "srgbt", "srgbft", "red",
    "green", "blue",
];

/// Pattern modifiers that stand alone.
const UNSUPPORTED_FLAGS: &[&str] = &["uv_mapping", "solid"];

impl Parser {
    /// Whether the next token starts a colour (so `pigment { Red }` is a solid colour): a colour
    /// keyword, a number, `<`, `(`, or an identifier holding a colour, vector or float.
    pub(super) fn starts_color(&mut self) -> PResult<bool> {
        Ok(match self.peek()?.map(|t| t.tok) {
            Some(Tok::Ident(k)) => {
                COLOR_KEYWORDS.contains(&&*k)
                    || matches!(
                        self.lookup(&k),
                        Some(Value::Color(_) | Value::Float(_) | Value::Vector(..))
                    )
            }
            Some(Tok::Sym(Sym::Lt)) | Some(Tok::Num(_)) | Some(Tok::Sym(Sym::LParen)) => true,
            _ => false,
        })
    }

    /// `pigment { ... }` after the keyword. `base` is the pigment being modified, if any.
    pub(super) fn parse_pigment_block(&mut self, base: Option<Pigment>) -> PResult<Pigment> {
        self.open_brace("pigment")?;
        let mut p = base.unwrap_or_else(|| Pigment::solid(Rgbft::BLACK));
        if let Some(k) = self.peek_ident()? {
            if let Some(Value::Pigment(id)) = self.lookup(&k) {
                p = (**id).clone();
                self.advance();
            }
        }
        if self.starts_color()? {
            p = Pigment::solid(self.parse_color()?);
        }
        let mut freq_phase = (1.0, 0.0);
        loop {
            let t = self.next_tok()?;
            let Tok::Ident(k) = &t.tok else {
                if t.tok == Tok::Sym(Sym::RBrace) {
                    break;
                }
                return Err(self.unexpected(&t, "in pigment"));
            };
            if let Some(tr) = self.transform_item(k)? {
                p.apply_transform(&tr);
                continue;
            }
            match &**k {
                "checker" => {
                    let mut items = vec![
                        Pigment::solid(Rgbft::rgb(DVec3::new(0.0, 0.0, 1.0))),
                        Pigment::solid(Rgbft::rgb(DVec3::new(0.0, 1.0, 0.0))),
                    ];
                    for item in items.iter_mut() {
                        if self.eat_keyword("pigment")? {
                            *item = self.parse_pigment_block(None)?;
                        } else if self.starts_color()? {
                            *item = Pigment::solid(self.parse_color()?);
                        } else {
                            break;
                        }
                        self.skip_optional_comma()?;
                    }
                    p.kind = PigmentKind::List {
                        pattern: Pattern::Checker,
                        items,
                    };
                }
                "gradient" => {
                    let axis = self.parse_vector()?;
                    p.kind = PigmentKind::Mapped {
                        pattern: Pattern::Gradient(axis),
                        map: self.current_map(&p),
                    };
                }
                "color_map" | "colour_map" => {
                    let map = self.parse_color_map()?;
                    match &mut p.kind {
                        PigmentKind::Mapped { map: m, .. } => *m = map,
                        _ => {
                            p.kind = PigmentKind::Mapped {
                                pattern: Pattern::Gradient(DVec3::X),
                                map,
                            }
                        }
                    }
                }
                "image_map" => {
                    p.kind = PigmentKind::ImageMap(Arc::new(self.parse_image_map(t.span)?))
                }
                "frequency" => freq_phase.0 = self.parse_float()?,
                "phase" => freq_phase.1 = self.parse_float()?,
                "quick_color" | "quick_colour" => {
                    p.quick = Some(self.parse_color()?);
                }
                "warp" => {
                    self.unsupported("warp", t.span);
                    self.skip_block()?;
                }
                "pigment_map" | "color_map_entries" => {
                    self.unsupported(k, t.span);
                    self.skip_block()?;
                }
                "ramp_wave" | "sine_wave" | "triangle_wave" | "scallop_wave" | "cubic_wave" => {
                    if &**k != "ramp_wave" {
                        self.unsupported(k, t.span);
                    }
                }
                "poly_wave" => {
                    self.unsupported(k, t.span);
                    self.parse_float()?;
                }
                k if UNSUPPORTED_MODIFIERS.contains(&k) => {
                    self.unsupported(k, t.span);
                    self.parse_expr()?;
                }
                k if UNSUPPORTED_FLAGS.contains(&k) => self.unsupported(k, t.span),
                "interior" | "exterior" => {
                    // Fractal patterns' inside and outside colouring: type, factor.
                    self.unsupported(k, t.span);
                    self.parse_float()?;
                    self.skip_optional_comma()?;
                    self.parse_float()?;
                }
                k if UNSUPPORTED_PATTERNS.contains(&k) => {
                    self.unsupported(&format!("{k} pattern"), t.span);
                    self.skip_pattern_args(k)?;
                    p.kind = PigmentKind::Mapped {
                        pattern: Pattern::Unsupported,
                        map: self.current_map(&p),
                    };
                }
                _ => return Err(self.error_at(t.span, format!("unexpected '{k}' in pigment"))),
            }
        }
        if freq_phase != (1.0, 0.0) {
            if let PigmentKind::Mapped {
                pattern: Pattern::Gradient(a),
                ..
            } = &mut p.kind
            {
                // gradient with frequency f is the same ramp over a vector f times as long.
                *a *= freq_phase.0;
            }
            if freq_phase.1 != 0.0 {
                let span = self.cur_span();
                self.unsupported("phase", span);
            }
        }
        Ok(p)
    }

    fn current_map(&self, p: &Pigment) -> ColorMap {
        match &p.kind {
            PigmentKind::Mapped { map, .. } => map.clone(),
            // POV-Ray's default map for most patterns is a black-to-white ramp.
            _ => vec![(0.0, Rgbft::BLACK), (1.0, Rgbft::rgb(DVec3::ONE))],
        }
    }

    fn skip_pattern_args(&mut self, k: &str) -> PResult<()> {
        match k {
            "brick" | "hexagon" | "cubic" | "square" | "triangular" => {
                while self.starts_color()? {
                    self.parse_color()?;
                    self.skip_optional_comma()?;
                }
            }
            "function" | "pigment_pattern" | "object" | "density_file" | "image_pattern" => {
                if k == "density_file" {
                    self.next_tok()?;
                    self.next_tok()?;
                } else {
                    self.skip_block()?;
                }
            }
            "julia" => {
                // julia <complex>, iterations
                self.parse_vector()?;
                self.skip_optional_comma()?;
                self.parse_float()?;
            }
            "mandel" | "magnet" | "tiling" | "spiral1" | "spiral2" => {
                self.parse_expr()?;
            }
            _ => {}
        }
        Ok(())
    }

    pub(super) fn parse_color_map(&mut self) -> PResult<ColorMap> {
        self.open_brace("color_map")?;
        let mut map: ColorMap = Vec::new();
        if let Some(k) = self.peek_ident()? {
            match self.lookup(&k) {
                Some(Value::ColorMap(m)) => {
                    map = (**m).clone();
                    self.advance();
                }
                Some(Value::Pigment(p)) => {
                    if let PigmentKind::Mapped { map: m, .. } = &p.kind {
                        map = m.clone();
                    }
                }
                _ => {}
            }
        }
        loop {
            let t = self.next_tok()?;
            match &t.tok {
                Tok::Sym(Sym::RBrace) => break,
                Tok::Sym(Sym::LBracket) => {
                    let v = self.parse_float()?;
                    self.skip_optional_comma()?;
                    // The old form `[v1, v2 color c1 color c2]` gives two entries.
                    if !self.starts_color()?
                        || matches!(self.peek()?.map(|t| t.tok), Some(Tok::Num(_)))
                    {
                        let v2 = self.parse_float()?;
                        let c1 = self.parse_color()?;
                        let c2 = self.parse_color()?;
                        map.push((v, c1));
                        map.push((v2, c2));
                    } else {
                        let c = self.parse_color()?;
                        map.push((v, c));
                    }
                    self.expect_sym(Sym::RBracket, "to close the colour map entry")?;
                }
                Tok::Ident(k) if matches!(self.lookup(k), Some(Value::Pigment(_))) => {}
                _ => return Err(self.unexpected(&t, "in color_map; expected '[value colour]'")),
            }
        }
        map.sort_by(|a, b| a.0.total_cmp(&b.0));
        Ok(map)
    }

    fn parse_image_map(&mut self, span: Span) -> PResult<ImageMap> {
        self.open_brace("image_map")?;
        let mut kind = None;
        if let Some(k) = self.peek_ident()? {
            if matches!(
                &*k,
                "png"
                    | "gif"
                    | "tga"
                    | "iff"
                    | "ppm"
                    | "pgm"
                    | "sys"
                    | "jpeg"
                    | "tiff"
                    | "exr"
                    | "hdr"
                    | "bmp"
            ) {
                self.advance();
                kind = Some(k);
            }
        }
        let name_span = self.next_span()?;
        let name = self.parse_string()?;
        let mut map = ImageMap {
            path: Default::default(),
            map_type: 0,
            once: false,
            interpolate: 0,
            width: 0,
            height: 0,
            pixels: Vec::new(),
        };
        let (mut filter_all, mut transmit_all) = (None, None);
        loop {
            let t = self.next_tok()?;
            match &t.tok {
                Tok::Sym(Sym::RBrace) => break,
                Tok::Ident(k) => match &**k {
                    "map_type" => map.map_type = self.parse_float()? as u32,
                    "once" => map.once = true,
                    "interpolate" => map.interpolate = self.parse_float()? as u32,
                    "filter" | "transmit" => {
                        if self.eat_keyword("all")? {
                            let v = Some(self.parse_float()?);
                            if &**k == "filter" {
                                filter_all = v
                            } else {
                                transmit_all = v
                            }
                        } else {
                            self.unsupported(&format!("{k} on a palette index"), t.span);
                            self.parse_float()?;
                            self.skip_optional_comma()?;
                            self.parse_float()?;
                        }
                    }
                    "gamma" => {
                        self.unsupported("gamma (in image_map)", t.span);
                        self.parse_float()?;
                    }
                    "use_color" | "use_colour" | "use_index" | "use_alpha" => {}
                    _ => {
                        return Err(self.error_at(t.span, format!("unexpected '{k}' in image_map")))
                    }
                },
                _ => return Err(self.unexpected(&t, "in image_map")),
            }
        }
        if map.map_type > 2 {
            self.unsupported(&format!("map_type {} (in image_map)", map.map_type), span);
        }
        let Some(path) = self.find_file(&name) else {
            return Err(self.error_at(name_span, format!("cannot find image file \"{name}\" (searched the scene directory and the library path)")));
        };
        if let Some(k) = kind {
            if !matches!(&*k, "png" | "exr") {
                return Err(self.error_at(
                    span,
                    format!(
                        "image_map {k} files are not supported by lancer yet (png and exr are)"
                    ),
                ));
            }
        }
        crate::scene::image::load_image_map(&path, &mut map)
            .map_err(|e| self.error_at(name_span, e))?;
        if filter_all.is_some() || transmit_all.is_some() {
            for px in &mut map.pixels {
                px.filter = filter_all.unwrap_or(px.filter);
                px.transmit = transmit_all.unwrap_or(px.transmit);
            }
        }
        map.path = path;
        Ok(map)
    }

    pub(super) fn parse_finish_block(&mut self, base: Option<Finish>) -> PResult<Finish> {
        self.open_brace("finish")?;
        let mut f = base.unwrap_or_default();
        loop {
            let t = self.next_tok()?;
            let Tok::Ident(k) = &t.tok else {
                if t.tok == Tok::Sym(Sym::RBrace) {
                    return Ok(f);
                }
                return Err(self.unexpected(&t, "in finish"));
            };
            if let Some(Value::Finish(id)) = self.lookup(k) {
                f = (**id).clone();
                continue;
            }
            match &**k {
                "ambient" => f.ambient = self.parse_color()?.rgb,
                "emission" => f.emission = self.parse_color()?.rgb,
                "diffuse" => {
                    self.eat_keyword("albedo")?;
                    f.diffuse = self.parse_float()?;
                    if self.eat_sym(Sym::Comma)? {
                        self.unsupported("diffuse (backside value)", t.span);
                        self.parse_float()?;
                    }
                }
                "brilliance" => f.brilliance = self.parse_float()?,
                "phong" => {
                    self.eat_keyword("albedo")?;
                    f.phong = self.parse_float()?;
                }
                "phong_size" => f.phong_size = self.parse_float()?,
                "specular" => {
                    self.eat_keyword("albedo")?;
                    f.specular = self.parse_float()?;
                }
                "roughness" => f.roughness = self.parse_float()?,
                "metallic" => {
                    f.metallic = if self.starts_float()? {
                        self.parse_float()?
                    } else {
                        1.0
                    };
                }
                "reflection" => self.parse_reflection(&mut f)?,
                "reflection_exponent" => {
                    self.unsupported(k, t.span);
                    self.parse_float()?;
                }
                "conserve_energy" => f.conserve_energy = self.optional_bool()?,
                "crand" => {
                    self.unsupported(k, t.span);
                    self.parse_float()?;
                }
                "irid" | "subsurface" => {
                    self.unsupported(k, t.span);
                    self.skip_block()?;
                }
                _ => return Err(self.error_at(t.span, format!("unexpected '{k}' in finish"))),
            }
        }
    }

    pub(super) fn starts_float(&mut self) -> PResult<bool> {
        Ok(match self.peek()?.map(|t| t.tok) {
            Some(Tok::Num(_)) | Some(Tok::Sym(Sym::LParen)) | Some(Tok::Sym(Sym::Minus)) => true,
            Some(Tok::Ident(k)) => {
                matches!(self.lookup(&k), Some(Value::Float(_)))
                    || matches!(&*k, "on" | "off" | "true" | "false" | "yes" | "no")
            }
            _ => false,
        })
    }

    /// `reflection 0.3`, `reflection rgb <..>` or `reflection { [min,] max fresnel falloff ... }`.
    fn parse_reflection(&mut self, f: &mut Finish) -> PResult<()> {
        if !self.eat_sym(Sym::LBrace)? {
            let c = self.parse_color()?.rgb;
            f.reflection = Reflection {
                min: c,
                max: c,
                falloff: 1.0,
                fresnel: false,
                metallic: 0.0,
            };
            return Ok(());
        }
        let mut r = Reflection {
            falloff: 1.0,
            ..Reflection::default()
        };
        let first = self.parse_color()?.rgb;
        if self.eat_sym(Sym::Comma)? || self.starts_color()? {
            r.min = first;
            r.max = self.parse_color()?.rgb;
        } else {
            r.min = first;
            r.max = first;
        }
        loop {
            let t = self.next_tok()?;
            match &t.tok {
                Tok::Sym(Sym::RBrace) => break,
                Tok::Ident(k) => match &**k {
                    "fresnel" => r.fresnel = self.optional_bool()?,
                    "falloff" => r.falloff = self.parse_float()?,
                    "exponent" => {
                        self.unsupported("exponent (in reflection)", t.span);
                        self.parse_float()?;
                    }
                    "metallic" => {
                        r.metallic = if self.starts_float()? {
                            self.parse_float()?
                        } else {
                            1.0
                        }
                    }
                    _ => {
                        return Err(self.error_at(t.span, format!("unexpected '{k}' in reflection")))
                    }
                },
                _ => return Err(self.unexpected(&t, "in reflection")),
            }
        }
        f.reflection = r;
        Ok(())
    }

    /// Normal blocks are read past: lancer does not perturb normals yet.
    pub(super) fn parse_normal_block(&mut self, span: Span) -> PResult<Normal> {
        self.unsupported("normal (surface perturbation)", span);
        self.skip_block()?;
        Ok(Normal {
            kind: NormalKind::Unsupported,
            amount: 0.0,
            transform: Default::default(),
        })
    }

    pub(super) fn parse_texture_block(&mut self) -> PResult<Texture> {
        self.open_brace("texture")?;
        let mut tex = self.scene.default_texture.clone();
        if let Some(k) = self.peek_ident()? {
            if let Some(Value::Texture(id)) = self.lookup(&k) {
                tex = (**id).clone();
                self.advance();
            }
        }
        loop {
            let t = self.next_tok()?;
            let Tok::Ident(k) = &t.tok else {
                if t.tok == Tok::Sym(Sym::RBrace) {
                    return Ok(tex);
                }
                return Err(self.unexpected(&t, "in texture"));
            };
            if let Some(tr) = self.transform_item(k)? {
                tex.apply_transform(&tr);
                continue;
            }
            match &**k {
                "pigment" => tex.pigment = self.parse_pigment_block(Some(tex.pigment.clone()))?,
                "finish" => tex.finish = self.parse_finish_block(Some(tex.finish.clone()))?,
                "normal" => tex.normal = Some(self.parse_normal_block(t.span)?),
                "uv_mapping" => self.unsupported(k, t.span),
                k if UNSUPPORTED_PATTERNS.contains(&k)
                    || matches!(
                        k,
                        "checker"
                            | "gradient"
                            | "material_map"
                            | "tiles"
                            | "texture_map"
                            | "image_pattern"
                            | "object"
                            | "slope"
                    ) =>
                {
                    self.unsupported(&format!("{k} (patterned texture)"), t.span);
                    self.skip_texture_pattern()?;
                }
                _ => return Err(self.error_at(t.span, format!("unexpected '{k}' in texture"))),
            }
        }
    }

    /// Reads past the rest of a patterned texture up to (not including) its closing brace.
    fn skip_texture_pattern(&mut self) -> PResult<()> {
        let mut depth = 0;
        loop {
            let t = self.peek()?.ok_or_else(|| self.eof_error())?;
            match t.tok {
                Tok::Sym(Sym::LBrace) => depth += 1,
                Tok::Sym(Sym::RBrace) if depth == 0 => return Ok(()),
                Tok::Sym(Sym::RBrace) => depth -= 1,
                _ => {}
            }
            self.advance();
        }
    }
}
