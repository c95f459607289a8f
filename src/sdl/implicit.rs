//! Reading POV-Ray's implicit and field objects: `superellipsoid`, `blob`, `isosurface` and
//! `height_field` (the geometry is in `geom::superellipsoid`, `geom::blob`, ...).

use std::sync::Arc;

use crate::geom::blob::{BlobData, Component, ComponentKind};
use crate::math::Transform;
use crate::scene::desc::{ObjectDesc, ShapeDesc, Texture};

use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};
use super::source::Span;

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
                transform: holder.transform,
            },
            holder.texture,
        ))
    }
}
