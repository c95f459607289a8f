//! Reading POV-Ray's `bicubic_patch`, `julia_fractal`, `parametric` and `ovus` (the geometry
//! is in `geom::bicubic`, `geom::julia`, `geom::parametric` and `geom::ovus`).

use std::sync::Arc;

use crate::geom::bicubic::{tessellate, MAX_STEPS};
use crate::math::DVec3;
use crate::scene::desc::{ObjectDesc, ShapeDesc};

use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};
use super::source::Span;

impl Parser {
    /// Reads an object's modifiers up to its '}', handing keywords `item` does not take
    /// (it returns false) to the ordinary object modifiers.
    pub(super) fn special_items(
        &mut self,
        obj: &mut ObjectDesc,
        open: Span,
        what: &str,
        mut item: impl FnMut(&mut Parser, &str, Span) -> PResult<bool>,
    ) -> PResult<()> {
        loop {
            let Some(t) = self.peek()? else {
                return Err(self.error_at(open, "this '{' is never closed"));
            };
            let k = match &t.tok {
                Tok::Sym(Sym::RBrace) => {
                    self.advance();
                    return Ok(());
                }
                Tok::Ident(k) => k.clone(),
                _ => {
                    return Err(self.unexpected(
                        &t,
                        &format!("in the {what}; expected a {what} item, a modifier or '}}'"),
                    ))
                }
            };
            self.advance();
            if !item(self, &k, t.span)? && !self.object_modifier(obj, &k, t.span)? {
                return Err(self.error_at(
                    t.span,
                    format!("'{k}' is not a {what} item or an object modifier"),
                ));
            }
        }
    }

    /// `bicubic_patch { type T [flatness F] [u_steps U] [v_steps V] P1, ..., P16
    /// [uv_vectors UV1, UV2, UV3, UV4] modifiers }`.
    pub(super) fn bicubic_patch(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("bicubic_patch")?;
        let (mut u_steps, mut v_steps) = (0u32, 0u32);
        loop {
            let span = self.next_span()?;
            let steps = |p: &mut Parser, which: &str| -> PResult<u32> {
                let v = p.parse_float()?;
                if v > MAX_STEPS as f64 {
                    p.warn(
                        span,
                        format!("bicubic_patch {which} {v} is more than lancer subdivides; {MAX_STEPS} is used"),
                    );
                }
                Ok(v.clamp(0.0, MAX_STEPS as f64) as u32)
            };
            if self.eat_keyword("type")? || self.eat_keyword("flatness")? {
                // The type only trades memory for speed in POV-Ray, and lancer always
                // subdivides fully, so neither changes the picture.
                self.parse_float()?;
            } else if self.eat_keyword("u_steps")? {
                u_steps = steps(self, "u_steps")?;
            } else if self.eat_keyword("v_steps")? {
                v_steps = steps(self, "v_steps")?;
            } else if self.eat_keyword("uv_vectors")? {
                self.patch_uv_vectors()?;
            } else if self.eat_keyword("accuracy")? {
                // Read by POV-Ray 3.7 for old scenes, not used.
                self.parse_float()?;
            } else if !self.eat_sym(Sym::Comma)? {
                // POV-Ray takes a comma after each item (objects/primitiv.pov has one).
                break;
            }
        }
        let mut p = [DVec3::ZERO; 16];
        for (i, q) in p.iter_mut().enumerate() {
            if i > 0 {
                self.skip_optional_comma()?;
            }
            *q = self.parse_vector()?;
        }
        let mut obj = ObjectDesc::new(ShapeDesc::Mesh(Arc::new(tessellate(&p, u_steps, v_steps))));
        self.special_items(&mut obj, open, "bicubic_patch", |p, k, _| {
            if k != "uv_vectors" {
                return Ok(false);
            }
            p.patch_uv_vectors()?;
            Ok(true)
        })?;
        Ok(obj)
    }

    /// The four corners' `uv_vectors` of a patch. Texture coordinates serve uv_mapping, which
    /// lancer does not do yet (that keyword warns where it is used).
    fn patch_uv_vectors(&mut self) -> PResult<()> {
        for i in 0..4 {
            if i > 0 {
                self.skip_optional_comma()?;
            }
            self.parse_vector()?;
        }
        Ok(())
    }
}
