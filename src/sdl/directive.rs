//! Directives, executed the moment the token stream meets them, and macro invocation.

use std::rc::Rc;

use super::lexer::{Sym, Tok, Token};
use super::parser::{Cond, FrameKind, PResult, Parser};
use super::source::Span;
use super::value::{MacroDef, Value};

/// Whether a `#for` loop runs again with its variable at `v`.
fn for_continues(v: f64, end: f64, step: f64) -> bool {
    if step > 0.0 {
        v <= end
    } else {
        v >= end
    }
}

/// Where a skip over inactive tokens stopped.
enum SkipStop {
    Else,
    ElseIf,
    End,
}

impl Parser {
    pub(super) fn directive(&mut self, d: &str, span: Span) -> PResult<()> {
        match d {
            "declare" => self.declare(false, span),
            "local" => self.declare(true, span),
            "undef" => {
                let (name, elem) = self.raw_ident_or_element("after #undef")?;
                if let Some(p) = elem {
                    return self.set_element(&p, None);
                }
                self.built_objects.forget(&name);
                for s in self.scopes.iter_mut().rev() {
                    if s.remove(&*name).is_some() {
                        break;
                    }
                }
                Ok(())
            }
            "include" => {
                let name = self.parse_string()?;
                self.include(&name, span)
            }
            "version" => {
                let v = self.parse_float()?;
                self.eat_sym(Sym::Semi)?;
                self.scene.version = Some(v);
                Ok(())
            }
            "if" => {
                let c = self.parse_float()?;
                self.enter_if(c != 0.0, span)
            }
            "ifdef" | "ifndef" => {
                self.expect_sym_with(Sym::LParen, || format!("after #{d}"))?;
                let (name, elem) = self.raw_ident_or_element(&format!("in #{d}"))?;
                self.expect_sym_with(Sym::RParen, || format!("to close #{d}"))?;
                let defined = self.is_defined(&name, &elem);
                self.enter_if(defined == (d == "ifdef"), span)
            }
            "else" | "elseif" => match self.conds.pop() {
                Some(Cond::If { .. }) => self.skip_inactive(span, false).map(|_| ()),
                Some(c @ Cond::Switch { .. }) if d == "else" => {
                    self.conds.push(c);
                    self.switch_else();
                    Ok(())
                }
                _ => Err(self.error_at(span, format!("#{d} without a matching #if"))),
            },
            "end" => self.end_directive(span),
            "while" => {
                let cond_pos = self.frames.last().map_or(0, |f| f.pos);
                let c = self.parse_float()?;
                if c != 0.0 {
                    let frame = self.frames.len() - 1;
                    self.conds.push(Cond::While { frame, cond_pos });
                    Ok(())
                } else {
                    self.skip_inactive(span, false).map(|_| ())
                }
            }
            "for" => self.for_directive(span),
            "macro" => self.define_macro(span),
            "default" => self.default_directive(),
            "debug" | "warning" | "error" => {
                let msg = self.parse_string()?;
                match d {
                    "debug" => eprint!("{msg}"),
                    "warning" => self.warn(span, format!("#warning: {msg}")),
                    _ => return Err(self.error_at(span, format!("#error: {msg}"))),
                }
                Ok(())
            }
            "switch" => self.switch_directive(span),
            "case" | "range" => self.case_directive(d, span),
            "break" => self.break_directive(span),
            "fopen" => self.fopen_directive(span),
            "fclose" => self.fclose_directive(span),
            "read" => self.read_directive(span),
            "write" => self.write_directive(span),
            _ => Err(self.error_at(span, format!("unknown directive #{d}"))),
        }
    }

    /// An identifier read without expanding it (directive names, declared names).
    pub(super) fn raw_ident(&mut self, context: &str) -> PResult<Rc<str>> {
        let t = self.raw_peek()?.ok_or_else(|| self.eof_error())?;
        if let Tok::Ident(n) = &t.tok {
            self.advance();
            return Ok(n.clone());
        }
        Err(self.error_at(
            t.span,
            format!("expected an identifier {context}, found {}", t.tok),
        ))
    }

    fn enter_if(&mut self, taken: bool, span: Span) -> PResult<()> {
        let frame = self.frames.len() - 1;
        if taken {
            self.conds.push(Cond::If { frame });
            return Ok(());
        }
        loop {
            match self.skip_inactive(span, true)? {
                SkipStop::Else => {
                    self.conds.push(Cond::If { frame });
                    return Ok(());
                }
                SkipStop::ElseIf => {
                    if self.parse_float()? != 0.0 {
                        self.conds.push(Cond::If { frame });
                        return Ok(());
                    }
                }
                SkipStop::End => return Ok(()),
            }
        }
    }

    /// Skips raw tokens of an inactive branch or loop body up to the matching `#end` (or
    /// `#else`/`#elseif` when `stop_at_else`), consuming the directive it stops at.
    fn skip_inactive(&mut self, open: Span, stop_at_else: bool) -> PResult<SkipStop> {
        let stops: &[&str] = if stop_at_else {
            &["else", "elseif"]
        } else {
            &[]
        };
        Ok(match &*self.skip_to_directive(open, 0, stops)? {
            "else" => SkipStop::Else,
            "elseif" => SkipStop::ElseIf,
            _ => SkipStop::End,
        })
    }

    fn end_directive(&mut self, span: Span) -> PResult<()> {
        let depth = self.frames.len() - 1;
        match self.conds.pop() {
            Some(Cond::If { frame }) | Some(Cond::Switch { frame, .. }) if frame == depth => Ok(()),
            Some(Cond::While { frame, cond_pos }) if frame == depth => {
                self.count_loop_iteration(span)?;
                self.frames[frame].pos = cond_pos;
                if self.parse_float()? != 0.0 {
                    self.conds.push(Cond::While { frame, cond_pos });
                    Ok(())
                } else {
                    self.skip_inactive(span, false).map(|_| ())
                }
            }
            Some(Cond::For {
                frame,
                body_pos,
                var,
                end,
                step,
            }) if frame == depth => {
                self.count_loop_iteration(span)?;
                let v = match self.lookup(&var) {
                    Some(Value::Float(v)) => *v + step,
                    _ => return Err(self.error_at(span, format!("the #for loop variable '{var}' was changed to a non-float inside the loop"))),
                };
                self.assign_var(var.clone(), Value::Float(v), true)?;
                if for_continues(v, end, step) {
                    self.frames[frame].pos = body_pos;
                    self.conds.push(Cond::For {
                        frame,
                        body_pos,
                        var,
                        end,
                        step,
                    });
                }
                Ok(())
            }
            Some(c) => {
                self.conds.push(c);
                Err(self.error_at(
                    span,
                    "#end does not match a #if, #while or #for opened in this file or macro",
                ))
            }
            None => Err(self.error_at(span, "#end without a matching #if, #while, #for or #macro")),
        }
    }

    fn for_directive(&mut self, span: Span) -> PResult<()> {
        self.expect_sym(Sym::LParen, "after #for")?;
        let var = self.raw_ident("as the #for loop variable")?;
        self.expect_sym(Sym::Comma, "after the #for variable")?;
        let start = self.parse_float()?;
        self.expect_sym(Sym::Comma, "after the #for start value")?;
        let end = self.parse_float()?;
        let step = if self.eat_sym(Sym::Comma)? {
            self.parse_float()?
        } else {
            1.0
        };
        self.expect_sym(Sym::RParen, "to close #for")?;
        if step == 0.0 {
            return Err(self.error_at(span, "#for step is zero: the loop would never end"));
        }
        self.assign_var(var.clone(), Value::Float(start), true)?;
        if !for_continues(start, end, step) {
            return self.skip_inactive(span, false).map(|_| ());
        }
        let frame = self.frames.len() - 1;
        let body_pos = self.frames[frame].pos;
        self.conds.push(Cond::For {
            frame,
            body_pos,
            var,
            end,
            step,
        });
        Ok(())
    }

    fn declare(&mut self, local: bool, _span: Span) -> PResult<()> {
        let deprecation = self.parse_deprecation()?;
        let name = self.raw_ident(if local {
            "after #local"
        } else {
            "after #declare"
        })?;
        if let Some(d) = deprecation {
            self.mark_deprecated(name.clone(), d);
        }
        if self.raw_peek_sym()? == Some(Sym::LBracket) {
            return self.declare_element(name, _span);
        }
        self.expect_sym_with(Sym::Eq, || format!("after '{name}' in the declaration"))?;
        // Warnings from identifiers used before this declaration belong where they were used.
        self.flush_released();
        let target = self.assign_target(&name, local);
        let first_warning = self.warnings.len();
        let v = self.parse_rvalue()?;
        self.flush_released();
        self.defer_warnings(&name, first_warning);
        // The semicolon is optional for objects and required by POV-Ray for numbers; accept it
        // either way.
        if self.raw_peek_sym()? == Some(Sym::Semi) {
            self.advance();
        }
        self.assign_to(target, name, v)
    }

    /// The right-hand side of a declaration or a macro argument: anything an identifier can hold.
    pub(super) fn parse_rvalue(&mut self) -> PResult<Value> {
        let t = self.peek()?.ok_or_else(|| self.eof_error())?;
        let Tok::Ident(k) = &t.tok else {
            return self.parse_expr();
        };
        if Self::object_parser(k).is_some() {
            return Ok(Value::Object(Box::new(
                self.parse_object()?.expect("object keyword"),
            )));
        }
        match &**k {
            "pigment" => {
                self.advance();
                Ok(Value::Pigment(Box::new(self.parse_pigment_block(None)?)))
            }
            "finish" => {
                self.advance();
                Ok(Value::Finish(Box::new(self.parse_finish_block(None)?)))
            }
            "normal" => {
                self.advance();
                Ok(Value::Normal(Box::new(self.parse_normal_block(t.span)?)))
            }
            "texture" => {
                self.advance();
                let mut tex = self.parse_texture_block()?;
                // `#declare T = texture {...} texture {...}` declares a layered texture. Raw
                // look-ahead: a directive after the declaration must not run before it ends.
                while matches!(self.raw_peek()?, Some(Token { tok: Tok::Ident(ref k), .. }) if &**k == "texture")
                {
                    self.advance();
                    tex = self.parse_texture_block()?.over(tex);
                }
                Ok(Value::Texture(std::sync::Arc::new(tex)))
            }
            "interior" => {
                self.advance();
                Ok(Value::Interior(Box::new(self.parse_interior_block()?)))
            }
            "camera" => {
                self.advance();
                Ok(Value::Camera(Box::new(self.parse_camera_block()?)))
            }
            "transform" => {
                self.advance();
                Ok(Value::Transform(Box::new(self.parse_transform_block()?)))
            }
            "color_map" | "colour_map" => {
                self.advance();
                Ok(Value::ColorMap(Box::new(self.parse_color_map()?)))
            }
            "material" => {
                self.advance();
                Ok(Value::Material(Box::new(self.parse_material_block()?)))
            }
            "sky_sphere" => {
                self.advance();
                Ok(Value::SkySphere(Box::new(self.parse_sky_sphere_block()?)))
            }
            "fog" => {
                self.advance();
                Ok(Value::Fog(Box::new(self.parse_fog_block()?)))
            }
            "rainbow" => {
                self.advance();
                Ok(Value::Fog(Box::new(self.parse_rainbow_block()?)))
            }
            "pigment_map" => {
                self.advance();
                Ok(Value::PigmentMap(Box::new(self.parse_pigment_map()?)))
            }
            "texture_map" => {
                self.advance();
                Ok(Value::TextureMap(Box::new(self.parse_texture_map()?)))
            }
            "normal_map" => {
                self.advance();
                Ok(Value::NormalMap(Box::new(self.parse_normal_map()?)))
            }
            "slope_map" => {
                self.advance();
                Ok(Value::SlopeMap(Box::new(self.parse_slope_map()?)))
            }
            "media" => {
                self.advance();
                Ok(Value::Media(Box::new(self.parse_media_block()?)))
            }
            "density" => {
                self.advance();
                Ok(Value::Pigment(Box::new(self.parse_density_block()?)))
            }
            "density_map" => {
                self.advance();
                let outer = std::mem::replace(&mut self.in_density, true);
                let map = self.parse_pigment_map();
                self.in_density = outer;
                Ok(Value::PigmentMap(Box::new(map?)))
            }
            "array" => {
                self.advance();
                self.parse_array(t.span)
            }
            "spline" => {
                self.advance();
                self.parse_spline(t.span)
            }
            _ => match self.lookup(k) {
                Some(
                    v @ (Value::Object(_)
                    | Value::Pigment(_)
                    | Value::Finish(_)
                    | Value::Normal(_)
                    | Value::Texture(_)
                    | Value::Interior(_)
                    | Value::Camera(_)
                    | Value::Transform(_)
                    | Value::ColorMap(_)
                    | Value::PigmentMap(_)
                    | Value::TextureMap(_)
                    | Value::NormalMap(_)
                    | Value::SlopeMap(_)
                    | Value::Material(_)
                    | Value::SkySphere(_)
                    | Value::Fog(_)
                    | Value::Skipped(_)),
                ) => {
                    let v = v.clone();
                    self.advance();
                    Ok(v)
                }
                _ => self.parse_expr(),
            },
        }
    }

    fn define_macro(&mut self, span: Span) -> PResult<()> {
        let name = self.raw_ident("after #macro")?;
        self.expect_sym(Sym::LParen, "after the macro name")?;
        let mut params = Vec::new();
        loop {
            let t = self.raw_peek()?.ok_or_else(|| self.eof_error())?;
            self.advance();
            match &t.tok {
                Tok::Sym(Sym::RParen) => break,
                Tok::Sym(Sym::Comma) => {}
                Tok::Ident(k) if &**k == "optional" => {
                    let p = self.raw_ident("after 'optional'")?;
                    params.push((p.to_string(), true));
                }
                Tok::Ident(p) => params.push((p.to_string(), false)),
                other => {
                    return Err(self.error_at(
                        t.span,
                        format!("expected a parameter name in #macro {name}, found {other}"),
                    ))
                }
            }
        }
        let f = self.frames.last().expect("a frame");
        let (tokens, body_start) = (f.tokens.clone(), f.pos);
        self.skip_inactive(span, false)?;
        let body_end = self.frames.last().expect("a frame").pos - 1;
        let def = MacroDef {
            name: name.to_string(),
            params,
            tokens,
            body_start,
            body_end,
        };
        self.assign_var(name, Value::Macro(Rc::new(def)), false)?;
        Ok(())
    }

    pub(super) fn invoke_macro(&mut self, m: &Rc<MacroDef>, span: Span) -> PResult<()> {
        self.expect_sym_with(Sym::LParen, || format!("after the macro name {}", m.name))?;
        let mut args = Vec::new();
        if !self.eat_sym(Sym::RParen)? {
            loop {
                // An empty argument leaves an optional parameter undefined.
                if matches!(self.peek_sym()?, Some(Sym::Comma) | Some(Sym::RParen)) {
                    args.push(None);
                } else {
                    args.push(Some(self.parse_macro_arg()?));
                }
                if self.eat_sym(Sym::RParen)? {
                    break;
                }
                // POV-Ray lets the comma go after an argument that is not a plain expression
                // (`Align_Object(Center_Object(...), x) -y, ...)` in incdemo/shapes.pov).
                self.skip_optional_comma()?;
            }
        }
        if args.len() > m.params.len() || m.params[args.len()..].iter().any(|p| !p.1) {
            return Err(self.error_at(
                span,
                format!(
                    "macro {} takes {} parameters, {} given",
                    m.name,
                    m.params.len(),
                    args.len()
                ),
            ));
        }
        self.push_frame_range(
            m.tokens.clone(),
            m.body_start,
            m.body_end,
            FrameKind::Macro,
            Some((span, format!("in macro {} called from here", m.name).into())),
            true,
        );
        if self.frames.len() > 200 {
            return Err(self.error_at(
                span,
                format!(
                    "too many nested macro calls (more than 200; POV-Ray says \"Too many nested symbol tables\"): does {} call itself without end?",
                    m.name
                ),
            ));
        }
        // The macro's table is new, so nothing built can be read from it yet; the parameters
        // are forgotten anyway so no name bound here can ever be answered from before.
        for (p, _) in &m.params {
            self.built_objects.forget(p);
        }
        let scope = self.scopes.last_mut().expect("macro scope");
        for ((p, _), a) in m.params.iter().zip(args) {
            if let Some(a) = a {
                scope.insert(p.as_str().into(), a);
            }
        }
        Ok(())
    }

    /// `#default { texture/pigment/finish }` changes what later objects start from.
    pub(super) fn default_directive(&mut self) -> PResult<()> {
        self.expect_sym(Sym::LBrace, "after #default")?;
        loop {
            let t = self.next_tok()?;
            match &t.tok {
                Tok::Sym(Sym::RBrace) => return Ok(()),
                Tok::Ident(k) if &**k == "pigment" => {
                    let base = self.scene.default_texture.pigment.clone();
                    self.scene.default_texture.pigment = self.parse_pigment_block(Some(base))?;
                }
                Tok::Ident(k) if &**k == "finish" => {
                    let base = self.scene.default_texture.finish.clone();
                    self.scene.default_texture.finish = self.parse_finish_block(Some(base))?;
                }
                Tok::Ident(k) if &**k == "texture" => {
                    self.scene.default_texture = self.parse_texture_block()?
                }
                Tok::Ident(k) if &**k == "normal" => {
                    let n = self.parse_normal_block(t.span)?;
                    self.scene.default_texture.normal = Some(Box::new(n));
                }
                Tok::Ident(k) if &**k == "radiosity" => {
                    if let Some(v) = self.parse_object_radiosity()? {
                        self.scene.default_importance = Some(v);
                    }
                }
                _ => return Err(self.unexpected(&t, "in #default")),
            }
        }
    }

    pub(super) fn unexpected(&self, t: &Token, context: &str) -> Box<crate::diag::Diagnostic> {
        self.error_at(t.span, format!("unexpected {} {context}", t.tok))
    }
}
