//! Texture statements: pigment (colours, patterns, colour maps, pigment maps, image maps),
//! finish, normal and interior blocks. Texture blocks are in texture_block.rs.

use std::rc::Rc;
use std::sync::Arc;

use crate::color::Rgbft;
use crate::math::DVec3;
use crate::scene::desc::{ColorMap, Finish, ImageMap, Pattern, Pigment, PigmentKind, Reflection};
use crate::scene::pattern::PatternKind;

use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};
use super::pattern::{default_items, default_map};
use super::source::Span;
use super::value::Value;

/// Keywords that start a colour expression.
const COLOR_KEYWORDS: &[&str] = &[
    "color", "colour", "rgb", "rgbf", "rgbt", "rgbft", "srgb", "srgbf", "srgbt", "srgbft", "red",
    "green", "blue",
];

/// What a pigment body has said so far besides its pattern.
enum Form {
    Solid(Rgbft),
    /// An explicit colour map (None: the pattern's default).
    Colors(Option<ColorMap>),
    Items(Vec<Pigment>),
    Pigments(Vec<(f64, Pigment)>),
    Image(Arc<ImageMap>),
}

/// The file type keywords an image map may start with (POV-Ray 3.7's list).
pub(super) const IMAGE_TYPES: &[&str] = &[
    "png", "gif", "tga", "iff", "ppm", "pgm", "sys", "jpeg", "tiff", "exr", "hdr", "bmp",
];
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
        self.parse_pigment_body(base, Sym::RBrace)
    }

    /// A pigment body whose opening brace was just read, up to its closing brace.
    pub(super) fn parse_pigment_body_in_braces(&mut self) -> PResult<Pigment> {
        self.parse_pigment_body(None, Sym::RBrace)
    }

    /// The inside of a pigment up to and including `close` (`}` for a block, `]` for a
    /// pigment map entry).
    fn parse_pigment_body(&mut self, base: Option<Pigment>, close: Sym) -> PResult<Pigment> {
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
        let (mut pat, mut form) = split_pigment(p.kind);
        p.kind = PigmentKind::Solid(Rgbft::BLACK);
        loop {
            if let Some(k) = self.peek_ident()? {
                if COLOR_KEYWORDS.contains(&&*k) {
                    // A colour after other items (`pigment { P1 color Red }`) replaces them.
                    form = Form::Solid(self.parse_color()?);
                    pat = None;
                    continue;
                }
            }
            let t = self.next_tok()?;
            let Tok::Ident(k) = &t.tok else {
                if t.tok == Tok::Sym(close) {
                    break;
                }
                return Err(self.unexpected(&t, "in pigment"));
            };
            if let Some(tr) = self.transform_item(k)? {
                // Listed and mapped pigments are evaluated in this pigment's space, so they
                // follow its transforms without being changed themselves.
                p.apply_transform(&tr);
                continue;
            }
            if let Some(kind) = self.pattern_keyword(k, t.span)? {
                let mut np = Pattern::new(kind);
                if let Some(old) = pat.take() {
                    // Modifiers written before the pattern keyword still count.
                    np.turbulence = old.turbulence;
                    np.warps = old.warps;
                    np.frequency = old.frequency;
                    np.phase = old.phase;
                    np.noise_generator = old.noise_generator;
                } else {
                    np.noise_generator = 0;
                }
                if np.is_block() {
                    form = Form::Items(self.parse_pattern_items(&np.kind)?);
                    self.close_object_pattern(&np.kind)?;
                } else if !matches!(form, Form::Colors(Some(_)) | Form::Pigments(_)) {
                    form = Form::Colors(None);
                }
                pat = Some(np);
                continue;
            }
            let space = *p.transform;
            let pm = pat.get_or_insert_with(|| {
                let mut u = Pattern::new(PatternKind::Unsupported);
                u.noise_generator = 0;
                u
            });
            if self.pattern_modifier(k, t.span, pm, &space)? {
                continue;
            }
            match &**k {
                "color_map" | "colour_map" => form = Form::Colors(Some(self.parse_color_map()?)),
                "pigment_map" | "density_map" => {
                    if pat
                        .as_ref()
                        .is_some_and(|q| matches!(q.kind, PatternKind::Unsupported))
                    {
                        // The entries of an unsupported pattern (`average`'s weights) may not
                        // follow the usual form; the pattern was already warned about.
                        self.skip_block()?;
                    } else {
                        let weights_optional = pat
                            .as_ref()
                            .is_some_and(|q| matches!(q.kind, PatternKind::Average));
                        form = Form::Pigments(self.parse_pigment_map_entries(weights_optional)?);
                    }
                }
                "image_map" => form = Form::Image(Arc::new(self.parse_image_map(t.span)?)),
                "quick_color" | "quick_colour" => {
                    p.quick = Some(self.parse_color()?);
                }
                "color_map_entries" => {
                    self.unsupported(k, t.span);
                    self.skip_block()?;
                }
                "uv_mapping" => p.uv_mapping = true,
                _ => return Err(self.error_at(t.span, format!("unexpected '{k}' in pigment"))),
            }
        }
        if self.in_density && matches!(form, Form::Colors(None)) {
            // A density's pattern value is its density: grey from 0 to 1.
            form = Form::Colors(Some(vec![
                (0.0, Rgbft::BLACK),
                (1.0, Rgbft::rgb(DVec3::ONE)),
            ]));
        }
        p.kind = join_pigment(pat, form);
        Ok(p)
    }

    /// The colours or pigments listed after a block pattern's keyword, defaults filling in.
    fn parse_pattern_items(&mut self, kind: &PatternKind) -> PResult<Vec<Pigment>> {
        let mut items: Vec<Pigment> = default_items(kind)
            .into_iter()
            .map(Pigment::solid)
            .collect();
        for item in items.iter_mut() {
            if self.eat_keyword(if self.in_density {
                "density"
            } else {
                "pigment"
            })? {
                *item = self.parse_pigment_block(None)?;
            } else if self.starts_color()? {
                *item = Pigment::solid(self.parse_color()?);
            } else {
                break;
            }
            self.skip_optional_comma()?;
        }
        Ok(items)
    }

    /// `pigment_map { [v PIGMENT_BODY] ... }` after the keyword, or a declared one.
    pub(super) fn parse_pigment_map(&mut self) -> PResult<Vec<(f64, Pigment)>> {
        self.parse_pigment_map_entries(false)
    }

    /// `weights_optional`: `average`'s entries may leave out their weight (1).
    fn parse_pigment_map_entries(
        &mut self,
        weights_optional: bool,
    ) -> PResult<Vec<(f64, Pigment)>> {
        self.parse_map_entries(
            "pigment_map",
            weights_optional,
            true,
            |v| match v {
                Value::PigmentMap(m) => Some((**m).clone()),
                _ => None,
            },
            |p| p.parse_pigment_body(None, Sym::RBracket),
        )
    }

    /// `NAME { [v ENTRY] ... }` after the keyword: entries read by `entry` up to their ']',
    /// a declared map of the same kind taken whole (`declared`), sorted by value when
    /// `sorted`. `weights_optional`: `average`'s entries may leave out their weight (1).
    pub(super) fn parse_map_entries<T>(
        &mut self,
        name: &str,
        weights_optional: bool,
        sorted: bool,
        declared: impl Fn(&Value) -> Option<Vec<(f64, T)>>,
        mut entry: impl FnMut(&mut Parser) -> PResult<T>,
    ) -> PResult<Vec<(f64, T)>> {
        self.open_brace(name)?;
        let mut map = Vec::new();
        loop {
            let t = self.next_tok()?;
            match &t.tok {
                Tok::Sym(Sym::RBrace) => break,
                Tok::Sym(Sym::LBracket) => {
                    let v = if weights_optional && !self.starts_float()? {
                        1.0
                    } else {
                        self.parse_float()?
                    };
                    self.skip_optional_comma()?;
                    map.push((v, entry(self)?));
                }
                Tok::Ident(k) => match self.lookup(k).and_then(&declared) {
                    Some(m) => map = m,
                    None => return Err(self.unexpected(&t, &format!("in {name}"))),
                },
                _ => {
                    let what = name.trim_end_matches("_map");
                    let msg = format!("in {name}; expected '[value {what}]'");
                    return Err(self.unexpected(&t, &msg));
                }
            }
        }
        if sorted {
            map.sort_by(|a, b| a.0.total_cmp(&b.0));
        }
        Ok(map)
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

    /// An image map's optional file type keyword and its file name (and where the name is).
    pub(super) fn image_file_name(&mut self) -> PResult<(Option<Rc<str>>, Span, String)> {
        let mut kind = None;
        if let Some(k) = self.peek_ident()? {
            if IMAGE_TYPES.contains(&&*k) {
                self.advance();
                kind = Some(k);
            }
        }
        let name_span = self.next_span()?;
        Ok((kind, name_span, self.parse_string()?))
    }

    pub(super) fn parse_image_map(&mut self, span: Span) -> PResult<ImageMap> {
        self.open_brace("image_map")?;
        let (kind, name_span, name) = self.image_file_name()?;
        let mut map = ImageMap::new(false);
        let (mut filter_all, mut transmit_all) = (None, None);
        // `filter N, v` / `transmit N, v`: for the pixels of palette index N.
        let mut by_index = Vec::new();
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
                            let index = self.parse_float()?;
                            self.skip_optional_comma()?;
                            let v = self.parse_float()?;
                            by_index.push((&**k == "filter", index, v, t.span));
                        }
                    }
                    "gamma" => {
                        self.unsupported("gamma (in image_map)", t.span);
                        self.parse_float()?;
                    }
                    "use_alpha" => map.use_alpha = true,
                    "use_color" | "use_colour" => map.use_index = false,
                    "use_index" => map.use_index = true,
                    "bump_size" => map.bump_size = Some(self.parse_float()?),
                    _ => {
                        return Err(self.error_at(t.span, format!("unexpected '{k}' in image_map")))
                    }
                },
                _ => return Err(self.unexpected(&t, "in image_map")),
            }
        }
        if map.map_type > 2 && map.map_type != 5 {
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
        if !by_index.is_empty() {
            match crate::scene::image::palette_indices(&path) {
                Some(indices) if indices.len() == map.pixels.len() => {
                    // By palette index, not by colour: two entries may share a colour.
                    let mut pixels = map.pixels.to_vec();
                    for (filter, index, v, _) in by_index {
                        for (px, &i) in pixels.iter_mut().zip(&indices) {
                            if i as f64 == index {
                                if filter {
                                    px.filter = v;
                                } else {
                                    px.transmit = v;
                                }
                            }
                        }
                    }
                    map.pixels = crate::scene::image_pixels::ImagePixels::from_vec(pixels);
                }
                _ => {
                    let span = by_index[0].3;
                    self.warn(
                        span,
                        format!(
                            "{name} has no palette: filter/transmit for a palette index do nothing"
                        ),
                    );
                }
            }
        }
        if filter_all.is_some() || transmit_all.is_some() {
            map.pixels.map_values(|px| {
                px.filter = filter_all.unwrap_or(px.filter);
                px.transmit = transmit_all.unwrap_or(px.transmit);
            });
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
                "reflection_exponent" => f.reflection.exponent = self.parse_exponent(t.span)?,
                "conserve_energy" => f.conserve_energy = self.optional_bool()?,
                "crand" => {
                    f.crand = self.parse_float()?;
                    self.warn_if_used(t.span, "'crand' is random in POV-Ray (its pixels change with the thread count): lancer's graininess has the same distribution (measured) but not the same pixels, and is the same for any thread count");
                }
                "irid" => f.irid = Some(Box::new(self.parse_irid(t.span)?)),
                "subsurface" => {
                    self.unsupported(k, t.span);
                    self.skip_block()?;
                }
                _ => return Err(self.error_at(t.span, format!("unexpected '{k}' in finish"))),
            }
        }
    }

    /// `irid { amount [thickness t] [turbulence u] }` after the keyword.
    fn parse_irid(&mut self, span: Span) -> PResult<crate::scene::desc::Irid> {
        self.open_brace("irid")?;
        let mut irid = crate::scene::desc::Irid {
            amount: self.parse_float()?,
            thickness: 0.0,
            turbulence: 0.0,
        };
        loop {
            let t = self.next_tok()?;
            match &t.tok {
                Tok::Sym(Sym::RBrace) => break,
                Tok::Ident(k) if &**k == "thickness" => irid.thickness = self.parse_float()?,
                Tok::Ident(k) if &**k == "turbulence" => {
                    irid.turbulence = self.parse_vector()?.x;
                }
                _ => return Err(self.unexpected(&t, "in irid")),
            }
        }
        if irid.turbulence != 0.0 {
            self.warn(span, "'turbulence' in irid is not supported exactly by lancer yet: the film thickness varies by a fit of POV-Ray's noise (within about 0.15 times the thickness times the turbulence), so the colours drift from POV-Ray's where the turbulence is large");
        }
        Ok(irid)
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

    /// A reflection exponent, which must be positive.
    fn parse_exponent(&mut self, span: Span) -> PResult<f32> {
        let e = self.parse_float()?;
        if e <= 0.0 {
            return Err(self.error_at(
                span,
                format!("the reflection exponent must be positive, not {e}"),
            ));
        }
        Ok(e as f32)
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
                exponent: f.reflection.exponent,
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
                    "exponent" => r.exponent = self.parse_exponent(t.span)?,
                    "metallic" => {
                        r.metallic = if self.starts_float()? {
                            self.parse_float()?
                        } else {
                            1.0
                        };
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
}

/// A pigment's pattern and the rest, so a body can modify a declared pigment.
fn split_pigment(kind: PigmentKind) -> (Option<Pattern>, Form) {
    match kind {
        PigmentKind::Solid(c) => (None, Form::Solid(c)),
        PigmentKind::Mapped { pattern, map } => (Some(*pattern), Form::Colors(Some(map))),
        PigmentKind::List { pattern, items } => (Some(*pattern), Form::Items(items)),
        PigmentKind::PigmentMap { pattern, map } => (Some(*pattern), Form::Pigments(map)),
        PigmentKind::ImageMap(im, pat) => (pat.map(|p| *p), Form::Image(im)),
    }
}

fn join_pigment(pat: Option<Pattern>, form: Form) -> PigmentKind {
    let Some(pattern) = pat else {
        return match form {
            Form::Solid(c) => PigmentKind::Solid(c),
            Form::Image(im) => PigmentKind::ImageMap(im, None),
            // A map with no pattern ramps along x, as POV-Ray's default gradient does.
            Form::Colors(map) => PigmentKind::Mapped {
                pattern: Box::new(Pattern::new(PatternKind::Gradient(DVec3::X))),
                map: map.unwrap_or_else(|| default_map(&PatternKind::Gradient(DVec3::X))),
            },
            Form::Items(items) => PigmentKind::List {
                pattern: Box::new(Pattern::new(PatternKind::Checker)),
                items,
            },
            Form::Pigments(map) => PigmentKind::PigmentMap {
                pattern: Box::new(Pattern::new(PatternKind::Gradient(DVec3::X))),
                map,
            },
        };
    };
    let pattern = Box::new(pattern);
    if pattern.is_block() {
        let items = match form {
            Form::Items(items) => items,
            _ => default_items(&pattern.kind)
                .into_iter()
                .map(Pigment::solid)
                .collect(),
        };
        return PigmentKind::List { pattern, items };
    }
    match form {
        Form::Image(im) => {
            let warped = pattern.turbulence.is_some_and(|t| t.amount != DVec3::ZERO)
                || !pattern.warps.is_empty();
            PigmentKind::ImageMap(im, warped.then_some(pattern))
        }
        // Only modifiers were given to a plain colour: it stays plain.
        Form::Solid(c) if matches!(pattern.kind, PatternKind::Unsupported) => PigmentKind::Solid(c),
        Form::Pigments(map) => PigmentKind::PigmentMap { pattern, map },
        Form::Colors(Some(map)) => PigmentKind::Mapped { pattern, map },
        Form::Colors(None) | Form::Items(_) | Form::Solid(_) => {
            let map = default_map(&pattern.kind);
            PigmentKind::Mapped { pattern, map }
        }
    }
}
