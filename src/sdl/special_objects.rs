//! Reading POV-Ray's `bicubic_patch`, `julia_fractal` and `ovus` (the geometry is in
//! `geom::bicubic`, `geom::julia` and `geom::ovus`).

use std::sync::Arc;

use crate::geom::bicubic::{tessellate, MAX_STEPS};
use crate::geom::julia::{Algebra, Julia, JuliaFn};
use crate::geom::ovus::Ovus;
use crate::math::DVec3;
use crate::scene::desc::{ObjectDesc, ShapeDesc};

use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};
use super::source::Span;
use super::value::Value;

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
        let a = if what.starts_with(['a', 'e', 'i', 'o', 'u']) {
            "an"
        } else {
            "a"
        };
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
                        &format!("in the {what}; expected {a} {what} item, a modifier or '}}'"),
                    ))
                }
            };
            self.advance();
            if !item(self, &k, t.span)? && !self.object_modifier(obj, &k, t.span)? {
                return Err(self.error_at(
                    t.span,
                    format!("'{k}' is not {a} {what} item or an object modifier"),
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

    /// The four corners' `uv_vectors` of a patch, read and not applied: the tessellation
    /// carries the patch's own (u, v), POV-Ray's default corners.
    fn patch_uv_vectors(&mut self) -> PResult<()> {
        for i in 0..4 {
            if i > 0 {
                self.skip_optional_comma()?;
            }
            self.parse_vector()?;
        }
        Ok(())
    }

    /// A 4-vector where the grammar wants one (a float fills all four).
    fn parse_vector4(&mut self) -> PResult<[f64; 4]> {
        let span = self.next_span()?;
        match self.parse_expr()? {
            Value::Float(f) => Ok([f; 4]),
            Value::Vector(c, n) => {
                let c = super::expr::pad((c, n));
                Ok([c[0], c[1], c[2], c[3]])
            }
            other => Err(self.error_at(
                span,
                format!("expected a 4-D vector, found a {}", other.type_name()),
            )),
        }
    }

    /// `julia_fractal { <P> [quaternion | hypercomplex] [sqr | cube | exp | ... | pwr(X, Y)]
    /// [max_iteration N] [precision P] [slice <N>, D] modifiers }`.
    pub(super) fn julia_fractal(&mut self, kw: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("julia_fractal")?;
        let param = self.parse_vector4()?;
        let mut algebra = Algebra::Quaternion;
        let mut func = (JuliaFn::Sqr, Span::default());
        let mut max_iteration = 20u32;
        let mut precision = 20.0;
        let mut slice = ([0.0, 0.0, 0.0, 1.0], 0.0);
        // A stand-in shape while the modifiers are read (a CSG one would not keep transforms).
        let mut obj = ObjectDesc::new(ShapeDesc::Sphere {
            center: DVec3::ZERO,
            radius: 0.0,
        });
        self.special_items(&mut obj, open, "julia_fractal", |p, k, span| {
            let f = match k {
                "quaternion" => {
                    algebra = Algebra::Quaternion;
                    return Ok(true);
                }
                "hypercomplex" => {
                    algebra = Algebra::Hypercomplex;
                    return Ok(true);
                }
                "max_iteration" => {
                    max_iteration = p.parse_float()?.clamp(0.0, 1e6) as u32;
                    return Ok(true);
                }
                "precision" => {
                    precision = p.parse_float()?;
                    return Ok(true);
                }
                "slice" => {
                    let n = p.parse_vector4()?;
                    p.skip_optional_comma()?;
                    let d = p.parse_float()?;
                    if n[3] == 0.0 || n.iter().all(|&x| x == 0.0) {
                        p.warn(span, "a julia_fractal slice normal must have a non-zero 4th component; <0,0,0,1>, 0 is used");
                    }
                    slice = (n, d);
                    return Ok(true);
                }
                "sqr" => JuliaFn::Sqr,
                "cube" => JuliaFn::Cube,
                "exp" => JuliaFn::Exp,
                "reciprocal" => JuliaFn::Reciprocal,
                "sin" => JuliaFn::Sin,
                "asin" => JuliaFn::Asin,
                "sinh" => JuliaFn::Sinh,
                "asinh" => JuliaFn::Asinh,
                "cos" => JuliaFn::Cos,
                "acos" => JuliaFn::Acos,
                "cosh" => JuliaFn::Cosh,
                "acosh" => JuliaFn::Acosh,
                "tan" => JuliaFn::Tan,
                "atan" => JuliaFn::Atan,
                "tanh" => JuliaFn::Tanh,
                "atanh" => JuliaFn::Atanh,
                "ln" => JuliaFn::Ln,
                "pwr" => {
                    p.expect_sym(Sym::LParen, "after 'pwr'")?;
                    let x = p.parse_float()?;
                    p.skip_optional_comma()?;
                    let y = p.parse_float()?;
                    p.expect_sym(Sym::RParen, "to close pwr(")?;
                    JuliaFn::Pwr(x, y)
                }
                _ => return Ok(false),
            };
            func = (f, span);
            Ok(true)
        })?;
        if algebra == Algebra::Quaternion && !matches!(func.0, JuliaFn::Sqr | JuliaFn::Cube) {
            // POV-Ray refuses this; lancer draws the quaternion square instead of stopping.
            self.warn(
                func.1,
                "only sqr and cube work with quaternion julia_fractals (add hypercomplex); sqr is used",
            );
            func.0 = JuliaFn::Sqr;
        }
        // docs/implicit-objects.md: quaternions follow POV-Ray's measured march exactly;
        // the hypercomplex march is not recovered yet.
        if algebra == Algebra::Hypercomplex {
            self.warn(
                kw,
                "'julia_fractal' hypercomplex is not fully supported by lancer yet: its inside test matches POV-Ray but the ray march does not, so thin parts and edges differ",
            );
        }
        obj.shape = ShapeDesc::Prebuilt(Arc::new(Julia::new(
            param,
            algebra,
            func.0,
            max_iteration,
            precision,
            slice,
        )));
        Ok(obj)
    }

    /// `ovus { Bottom_radius, Top_radius modifiers }`.
    pub(super) fn ovus(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("ovus")?;
        let span = self.next_span()?;
        let bottom = self.parse_float()?;
        self.skip_optional_comma()?;
        let top = self.parse_float()?;
        if top.abs() >= 2.0 * bottom.abs() {
            // povray's own warning, word for word but for its spelling.
            self.warn(
                span,
                "ovus second radius should be less than twice first radius; substituting a sphere, as it would be identical and simpler",
            );
        }
        let shape = ShapeDesc::Prebuilt(Arc::new(Ovus::new(bottom, top)));
        self.finish_object(ObjectDesc::new(shape), open)
    }
}
