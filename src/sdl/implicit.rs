//! Reading POV-Ray's implicit and field objects: `superellipsoid`, `blob`, `isosurface` and
//! `height_field` (the geometry is in `geom::superellipsoid`, `geom::blob`, ...).

use std::sync::Arc;

use crate::func::{FnKind, Function};
use crate::geom::blob::{BlobData, Component, ComponentKind};
use crate::geom::height_field::HeightData;
use crate::geom::isosurface::{Container, IsoData};
use crate::math::{DVec3, Transform};
use crate::scene::desc::{CsgOp, ObjectDesc, ShapeDesc, Texture};
use crate::scene::height_image::{load_heights, HfGamma, MAX_PIXELS};

use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};
use super::source::Span;
use super::value::Value;

/// The exponent a superellipsoid gets instead of a zero, negative or non-finite one: small
/// enough to look like POV-Ray's sharp-edged box for tiny exponents.
const MIN_EXPONENT: f64 = 1e-5;

impl Parser {
    /// `superellipsoid { <e, n> modifiers }`.
    pub(super) fn superellipsoid(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("superellipsoid")?;
        let span = self.next_span()?;
        let v = self.parse_vector()?;
        let mut fix = |x: f64, which: &str| {
            if x > 0.0 && x.is_finite() {
                x
            } else {
                self.warn(
                    span,
                    format!("superellipsoid exponent {which} = {x} must be greater than zero; {MIN_EXPONENT} is used"),
                );
                MIN_EXPONENT
            }
        };
        let e = fix(v.x, "e");
        let n = fix(v.y, "n");
        self.finish_object(ObjectDesc::new(ShapeDesc::Superellipsoid { e, n }), open)
    }
}

impl Parser {
    /// `blob { threshold T  sphere {...}  cylinder {...}  component S, R, <C>  sturm
    /// hierarchy  modifiers }`; items and modifiers may come in any order.
    pub(super) fn blob(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("blob")?;
        let mut obj = ObjectDesc::new(ShapeDesc::Blob {
            data: Arc::new(BlobData {
                components: Vec::new(),
                threshold: 1.0,
                sturm: false,
            }),
            textures: Vec::new(),
        });
        loop {
            let Some(t) = self.peek()? else {
                return Err(self.error_at(open, "this '{' is never closed"));
            };
            let k = match &t.tok {
                Tok::Sym(Sym::RBrace) => {
                    self.advance();
                    break;
                }
                Tok::Ident(k) => k.clone(),
                _ => {
                    return Err(
                        self.unexpected(&t, "in the blob; expected a component, a modifier or '}'")
                    )
                }
            };
            self.advance();
            let ShapeDesc::Blob { data, textures } = &mut obj.shape else {
                unreachable!("the blob's shape is set above")
            };
            match &*k {
                "threshold" => {
                    let v = self.parse_float()?;
                    if v.is_nan() || v <= 0.0 {
                        self.warn(t.span, format!("a blob's threshold must be positive, not {v}; the blob may fill all space"));
                    }
                    Arc::make_mut(data).threshold = v;
                }
                "sphere" | "cylinder" => {
                    let (c, tex) = self.blob_component(&k)?;
                    Arc::make_mut(data).components.push(c);
                    textures.push(tex);
                }
                "component" => {
                    // The obsolete form: strength, radius, centre.
                    let strength = self.parse_float()?;
                    self.skip_optional_comma()?;
                    let radius = self.parse_float()?;
                    self.skip_optional_comma()?;
                    let center = self.parse_vector()?;
                    Arc::make_mut(data).components.push(Component {
                        kind: ComponentKind::Sphere { center },
                        radius,
                        strength,
                        transform: Transform::IDENTITY,
                    });
                    textures.push(None);
                }
                "sturm" => {
                    let on = self.optional_bool()?;
                    Arc::make_mut(data).sturm = on;
                }
                // A bounding hierarchy is always used.
                "hierarchy" => {
                    self.optional_bool()?;
                }
                _ => {
                    if !self.object_modifier(&mut obj, &k, t.span)? {
                        return Err(self.error_at(
                            t.span,
                            format!("'{k}' is not a blob component or an object modifier"),
                        ));
                    }
                }
            }
        }
        if let ShapeDesc::Blob { data, .. } = &obj.shape {
            if data.components.is_empty() {
                return Err(self.error_at(open, "a blob needs at least one component"));
            }
        }
        Ok(obj)
    }

    /// `sphere { <C>, R, [strength] S  modifiers }` or `cylinder { <A>, <B>, R, [strength] S
    /// modifiers }` inside a blob, the keyword just read; the modifiers are transforms and
    /// texture items.
    fn blob_component(&mut self, k: &str) -> PResult<(Component, Option<Texture>)> {
        let open = self.open_brace(k)?;
        let kind = if k == "sphere" {
            ComponentKind::Sphere {
                center: self.parse_vector()?,
            }
        } else {
            let a = self.parse_vector()?;
            self.skip_optional_comma()?;
            let b = self.parse_vector()?;
            ComponentKind::Cylinder { a, b }
        };
        self.skip_optional_comma()?;
        let radius = self.parse_float()?;
        self.skip_optional_comma()?;
        self.eat_keyword("strength")?;
        let strength = self.parse_float()?;
        // The component's transforms and texture, collected on a stand-in object so they
        // follow the usual rules (a texture given before a transform moves with it).
        let mut holder = ObjectDesc::new(ShapeDesc::Sphere {
            center: Default::default(),
            radius: 0.0,
        });
        loop {
            let t = self.next_tok()?;
            match &t.tok {
                Tok::Sym(Sym::RBrace) => break,
                Tok::Ident(m)
                    if matches!(
                        &**m,
                        "texture"
                            | "pigment"
                            | "normal"
                            | "finish"
                            | "translate"
                            | "rotate"
                            | "scale"
                            | "matrix"
                            | "transform"
                    ) =>
                {
                    let m = m.clone();
                    self.object_modifier(&mut holder, &m, t.span)?;
                }
                _ => {
                    return Err(self.unexpected(
                        &t,
                        &format!("in a blob {k}; expected a texture, a transform or '}}'"),
                    ))
                }
            }
        }
        let _ = open;
        Ok((
            Component {
                kind,
                radius,
                strength,
                transform: *holder.transform,
            },
            holder.texture.map(Arc::unwrap_or_clone),
        ))
    }
}

impl Parser {
    /// `isosurface { function { ... } [contained_by { box {...} | sphere {...} }]
    /// [threshold T] [accuracy A] [max_gradient G] [evaluate P0, P1, P2] [open]
    /// [max_trace N | all_intersections] modifiers }`.
    pub(super) fn isosurface(&mut self, s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("isosurface")?;
        let fspan = self.next_span()?;
        if !self.eat_keyword("function")? {
            return Err(self.error_at(fspan, "an isosurface starts with its function { ... }"));
        }
        // A function lancer cannot read or evaluate: the rest of the isosurface is of no use
        // and is read past, as lancer reads past objects it does not render (its modifiers
        // may use what lancer cannot parse either).
        let why = match self.function_body(fspan)? {
            Ok(f) => match &f.unsupported {
                None => Ok(f),
                Some(why) => Err(why.clone()),
            },
            Err(why) => Err(why),
        };
        let function = match why {
            Ok(f) => f,
            Err(why) => {
                self.warn(
                    fspan,
                    format!("this isosurface is not rendered: {why}; the picture will differ from POV-Ray's"),
                );
                self.skip_to_close()?;
                let _ = open;
                return Ok(ObjectDesc::new(ShapeDesc::Csg {
                    op: CsgOp::Union,
                    children: Vec::new(),
                }));
            }
        };
        let mut data = IsoData {
            function,
            container: Container::Box {
                min: DVec3::splat(-1.0),
                max: DVec3::splat(1.0),
            },
            threshold: 0.0,
            accuracy: 0.001,
            max_gradient: 1.1,
            evaluate: None,
            open: false,
            max_trace: Some(1),
        };
        // A stand-in shape while the modifiers are read (a CSG one would not keep transforms).
        let mut obj = ObjectDesc::new(ShapeDesc::Sphere {
            center: DVec3::ZERO,
            radius: 0.0,
        });
        self.special_items(&mut obj, open, "isosurface", |p, k, span| {
            match k {
                "contained_by" => data.container = p.iso_container()?,
                "threshold" => data.threshold = p.parse_float()?,
                "accuracy" => {
                    let v = p.parse_float()?;
                    if v.is_nan() || v <= 0.0 {
                        p.warn(
                            span,
                            format!(
                                "isosurface accuracy must be positive, not {v}; 0.000001 is used"
                            ),
                        );
                    }
                    data.accuracy = v;
                }
                "max_gradient" => {
                    let v = p.parse_float()?;
                    if v.is_nan() || v <= 0.0 {
                        p.warn(
                            span,
                            format!(
                                "isosurface max_gradient must be positive, not {v}; 1.1 is used"
                            ),
                        );
                    }
                    data.max_gradient = v;
                }
                "evaluate" => {
                    let mut e = [0.0; 3];
                    for (i, v) in e.iter_mut().enumerate() {
                        if i > 0 {
                            p.skip_optional_comma()?;
                        }
                        *v = p.parse_float()?;
                    }
                    data.evaluate = Some(e);
                }
                "open" => data.open = p.optional_bool()?,
                "max_trace" => {
                    let v = p.parse_float()?;
                    data.max_trace = Some(v.clamp(1.0, u32::MAX as f64) as u32);
                }
                "all_intersections" => data.max_trace = None,
                // POV-Ray 3.5's solver choice; 3.7 reads and ignores it.
                "method" => {
                    p.parse_float()?;
                }
                _ => return Ok(false),
            }
            Ok(true)
        })?;
        let _ = s;
        obj.shape = ShapeDesc::Isosurface(Arc::new(data));
        Ok(obj)
    }

    /// The function after `isosurface { function` or `height_field { function W, H`. A body lancer cannot read (a call lancer's
    /// function language does not have yet) is skipped and its error message returned as the
    /// reason, so the scene still renders without the isosurface; that is possible only when
    /// the error left the token stream in the same file or macro body, which is then rewound.
    pub(super) fn function_body(&mut self, fspan: Span) -> PResult<Result<Arc<Function>, String>> {
        let frames = self.frames.len();
        let at = self.frames.last().map(|f| (f.pos, f.tokens.as_ptr()));
        let conds = self.conds.len();
        match self.parse_function_literal(fspan) {
            Ok(Value::Function(f)) => Ok(Ok(f)),
            Ok(_) => unreachable!("parse_function_literal makes functions"),
            Err(e) => {
                let same = self.frames.len() == frames
                    && self.conds.len() == conds
                    && self.frames.last().map(|f| f.tokens.as_ptr()) == at.map(|a| a.1);
                let (Some((pos, _)), true) = (at, same) else {
                    return Err(e);
                };
                if let Some(f) = self.frames.last_mut() {
                    f.pos = pos;
                }
                if self.peek_sym()? != Some(Sym::LBrace) {
                    return Err(e);
                }
                self.skip_block()?;
                Ok(Err(e.message))
            }
        }
    }

    /// Reads past the rest of an object whose '{' is open, up to its '}' (directives inside
    /// still run).
    pub(super) fn skip_to_close(&mut self) -> PResult<()> {
        let mut depth = 1;
        while depth > 0 {
            match self.next_tok()?.tok {
                Tok::Sym(Sym::LBrace) => depth += 1,
                Tok::Sym(Sym::RBrace) => depth -= 1,
                _ => {}
            }
        }
        Ok(())
    }

    /// `{ box { A, B } }` or `{ sphere { C, R } }` after `contained_by`.
    pub(super) fn iso_container(&mut self) -> PResult<Container> {
        let open = self.open_brace("contained_by")?;
        let span = self.next_span()?;
        let Some(o) = self.parse_object()? else {
            return Err(self.error_at(span, "contained_by takes a box or a sphere"));
        };
        if !o.transform.is_identity() {
            self.warn(span, "transforms of an isosurface's container are ignored (POV-Ray ignores them too); transform the isosurface");
        }
        let c = match o.shape {
            ShapeDesc::Box { corner1, corner2 } => Container::Box {
                min: corner1.min(corner2),
                max: corner1.max(corner2),
            },
            ShapeDesc::Sphere { center, radius } => Container::Sphere {
                center,
                radius: radius.abs(),
            },
            _ => return Err(self.error_at(span, "contained_by takes a box or a sphere")),
        };
        self.expect_sym(Sym::RBrace, "to close contained_by")?;
        let _ = open;
        Ok(c)
    }
}

/// Image types POV-Ray reads for height fields that lancer cannot decode.
const HF_UNREADABLE: &[&str] = &["iff", "sys", "tiff"];

impl Parser {
    /// `height_field { [type] "file" [gamma G] [premultiplied B] | function W, H { ... }
    /// [smooth] [water_level L] [hierarchy B] modifiers }`.
    pub(super) fn height_field(&mut self, kw: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("height_field")?;
        let span = self.next_span()?;
        let grid = if self.eat_keyword("function")? {
            self.hf_function(span)?
        } else {
            self.hf_image(span)?
        };
        // Not rendered (already warned about): read past the rest, as for isosurfaces.
        let Some((width, depth, heights)) = grid else {
            self.skip_to_close()?;
            return Ok(ObjectDesc::new(ShapeDesc::Csg {
                op: CsgOp::Union,
                children: Vec::new(),
            }));
        };
        let mut data = HeightData::new(width, depth, heights);
        // A stand-in shape while the modifiers are read (a CSG one would not keep transforms).
        let mut obj = ObjectDesc::new(ShapeDesc::Sphere {
            center: DVec3::ZERO,
            radius: 0.0,
        });
        self.special_items(&mut obj, open, "height_field", |p, k, _| {
            match k {
                "smooth" => data.smooth = p.optional_bool()?,
                "water_level" => data.water_level = p.parse_float()?,
                "hierarchy" => {
                    p.optional_bool()?;
                }
                _ => return Ok(false),
            }
            Ok(true)
        })?;
        // Turned upside down, a height field's solid side (below its surface) faces up, and
        // rays from above meet its surface from inside without crossing a wall. POV-Ray then
        // refracts as a ray entering the glass (it goes by the interiors the ray is in);
        // lancer goes by the side of the normal and refracts as one leaving (measured with
        // a flat glass field scaled <12, -0.5, 12>: 0.75 SSIM; advanced/glasschess).
        if obj.transform.normal(DVec3::Y).y < 0.0
            && obj.interior.as_ref().is_some_and(|i| i.ior != 1.0)
        {
            self.warn(
                kw,
                "'height_field' is not supported by lancer yet: turned upside down with an ior, its glass is met from the solid side, where lancer refracts as leaving and POV-Ray as entering",
            );
        }
        obj.shape = ShapeDesc::HeightField(Arc::new(data));
        Ok(obj)
    }

    /// `[type] "file" [gamma G | gamma srgb] [premultiplied B]`: the grid, j from z = 0.
    fn hf_image(&mut self, span: Span) -> PResult<Option<(usize, usize, Vec<u16>)>> {
        let mut kind = None;
        if let Some(k) = self.peek_ident()? {
            // An image map's types, and POV-Ray's `pot` (16-bit heights) for height fields.
            if super::texture::IMAGE_TYPES.contains(&&*k) || &*k == "pot" {
                self.advance();
                kind = Some(k);
            }
        }
        let name_span = self.next_span()?;
        let name = self.parse_string()?;
        let mut gamma = None;
        loop {
            if self.eat_keyword("gamma")? {
                gamma = Some(if self.eat_keyword("srgb")? {
                    HfGamma::Srgb
                } else {
                    let g = self.parse_float()?;
                    if g > 0.0 && g.is_finite() {
                        HfGamma::Power(g)
                    } else {
                        self.warn(name_span, format!("gamma {g} is not positive; ignored"));
                        continue;
                    }
                });
            } else if self.eat_keyword("premultiplied")? {
                // Alpha does not make heights.
                self.optional_bool()?;
            } else {
                break;
            }
        }
        if let Some(k) = &kind {
            if HF_UNREADABLE.contains(&&**k) {
                self.unsupported(&format!("height_field {k} files (png, gif, pot, tga, ppm, pgm, bmp, jpeg, hdr and exr are read)"), span);
                return Ok(None);
            }
        }
        let Some(path) = self.find_file(&name) else {
            return Err(self.error_at(
                name_span,
                format!("cannot find height field image \"{name}\" (searched the scene directory and the library path)"),
            ));
        };
        let pot = kind.as_deref() == Some("pot");
        let img = load_heights(&path, gamma, pot).map_err(|e| self.error_at(name_span, e))?;
        // Image rows run from the top (z = 1) down.
        let (w, h) = (img.width, img.height);
        let mut grid = vec![0u16; w * h];
        for r in 0..h {
            let j = h - 1 - r;
            grid[j * w..(j + 1) * w].copy_from_slice(&img.heights[r * w..(r + 1) * w]);
        }
        Ok(Some((w, h, grid)))
    }

    /// `W, H { body }` after `function`: the body sampled as a W×H image, x and y from 0 to
    /// 1 across and down it. Values are kept as POV-Ray keeps them: times 65535, truncated and
    /// wrapped to 16 bits (measured: -0.3 gives 0.7, 1.5 gives 0.5).
    fn hf_function(&mut self, span: Span) -> PResult<Option<(usize, usize, Vec<u16>)>> {
        let w = self.parse_float()?;
        self.skip_optional_comma()?;
        let h = self.parse_float()?;
        if !(w >= 2.0 && h >= 2.0) || w * h > MAX_PIXELS as f64 {
            return Err(self.error_at(
                span,
                format!("a height_field function's resolution must be at least 2×2 and at most {MAX_PIXELS} points, not {w}×{h}"),
            ));
        }
        let (w, h) = (w as usize, h as usize);
        let fspan = self.next_span()?;
        let f = match self.function_body(fspan)? {
            Ok(f) => f,
            Err(why) => {
                self.warn(fspan, format!("this height_field is not rendered: {why}; the picture will differ from POV-Ray's"));
                return Ok(None);
            }
        };
        if let Some(why) = &f.unsupported {
            self.warn(fspan, format!("this height_field is not rendered: {why}; the picture will differ from POV-Ray's"));
            return Ok(None);
        }
        // Measured (trace() onto `function 8, 8 { pigment { rgb C } }`): a pigment function's
        // height is its grey, 0.297 r + 0.589 g + 0.114 b; filter and transmit do not count.
        let f = if matches!(f.kind, FnKind::Pigment(..)) {
            Arc::new(Function::component(f, 5))
        } else {
            f
        };
        let mut grid = vec![0u16; w * h];
        for r in 0..h {
            let y = r as f64 / (h - 1) as f64;
            let j = h - 1 - r;
            for i in 0..w {
                let x = i as f64 / (w - 1) as f64;
                let v = f.eval(&[x, y, 0.0]);
                // NaN becomes 0 in the cast.
                grid[j * w + i] = ((v * 65535.0).trunc() as i64).rem_euclid(65536) as u16;
            }
        }
        Ok(Some((w, h, grid)))
    }
}
