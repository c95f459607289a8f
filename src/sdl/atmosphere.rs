//! Atmospheric scene items: `fog { ... }` (constant and ground fog) and `rainbow { ... }`,
//! each read into a `FogDesc`.

use crate::scene::desc::{FogDesc, RainbowDesc};

use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};
use super::value::Value;

impl Parser {
    /// `fog { [FOG_IDENTIFIER] items }` after the keyword.
    pub(super) fn parse_fog_block(&mut self) -> PResult<FogDesc> {
        let open = self.expect_sym(Sym::LBrace, "after 'fog'")?;
        let mut fog = FogDesc::default();
        if let Some(k) = self.peek_ident()? {
            if let Some(Value::Fog(f)) = self.lookup(&k) {
                fog = (**f).clone();
                self.advance();
            }
        }
        loop {
            let t = self
                .peek()?
                .ok_or_else(|| self.error_at(open, "this '{' is never closed"))?;
            match &t.tok {
                Tok::Sym(Sym::RBrace) => {
                    self.advance();
                    return Ok(fog);
                }
                Tok::Ident(_) if self.starts_color()? => fog.color = self.parse_color()?,
                Tok::Ident(k) => {
                    let k = k.clone();
                    self.advance();
                    match &*k {
                        "fog_type" => fog.ground = self.parse_float()? >= 1.5,
                        "distance" => fog.distance = self.parse_float()?,
                        "fog_offset" => fog.offset = self.parse_float()?,
                        "fog_alt" => fog.alt = self.parse_float()?,
                        "up" => fog.up = self.parse_vector()?,
                        "turbulence" => {
                            let amount = self.parse_vector()?;
                            let tb = fog.turbulence.get_or_insert_default();
                            (tb.on, tb.amount) = (true, amount);
                        }
                        "turb_depth" | "omega" | "lambda" | "octaves" => {
                            // Kept, though without `turbulence` they change nothing.
                            let v = self.parse_float()?;
                            let tb = fog.turbulence.get_or_insert_default();
                            match &*k {
                                "turb_depth" => tb.depth = v,
                                "omega" => tb.omega = v,
                                "lambda" => tb.lambda = v,
                                _ => tb.octaves = v.max(1.0) as u32,
                            }
                        }
                        other => match self.transform_item(other)? {
                            // Only the up direction turns with the fog; translation does
                            // nothing to it.
                            Some(tr) => fog.up = tr.vector(fog.up),
                            None => {
                                return Err(
                                    self.error_at(t.span, format!("unexpected '{other}' in fog"))
                                )
                            }
                        },
                    }
                }
                _ => fog.color = self.parse_color()?,
            }
        }
    }
}

impl Parser {
    /// `rainbow { ... }` after the keyword: a fog whose colour comes from its map by the ray's
    /// angle to `direction`.
    pub(super) fn parse_rainbow_block(&mut self) -> PResult<FogDesc> {
        let open = self.expect_sym(Sym::LBrace, "after 'rainbow'")?;
        let mut rb = RainbowDesc::default();
        // Without `distance` the rainbow is never seen on objects (manual 3.4.3.5).
        let mut distance = 1e30;
        let mut falloff = None;
        if let Some(k) = self.peek_ident()? {
            if let Some(Value::Fog(f)) = self.lookup(&k) {
                if let Some(r) = &f.rainbow {
                    rb = (**r).clone();
                    distance = f.distance;
                    falloff = Some(rb.falloff_angle);
                    self.advance();
                }
            }
        }
        loop {
            let t = self
                .peek()?
                .ok_or_else(|| self.error_at(open, "this '{' is never closed"))?;
            let Tok::Ident(k) = &t.tok else {
                if t.tok == Tok::Sym(Sym::RBrace) {
                    self.advance();
                    break;
                }
                return Err(self.unexpected(&t, "in rainbow"));
            };
            let k = k.clone();
            self.advance();
            match &*k {
                "direction" => rb.direction = self.parse_vector()?,
                "angle" => rb.angle = self.parse_float()?,
                "width" => rb.width = self.parse_float()?,
                "distance" => distance = self.parse_float()?,
                "up" => rb.up = self.parse_vector()?,
                "arc_angle" => rb.arc_angle = self.parse_float()?.clamp(0.0, 360.0),
                "falloff_angle" => falloff = Some(self.parse_float()?.clamp(0.0, 360.0)),
                "jitter" => {
                    rb.jitter = self.parse_float()?;
                    if rb.jitter != 0.0 {
                        self.warn_if_used(t.span, "'jitter' (in rainbow) is random in POV-Ray: lancer adds noise of the same size to the rainbow's index, the same for any thread count, but not povray's pixels");
                    }
                }
                "color_map" | "colour_map" => rb.color_map = self.parse_color_map()?,
                other => match self.transform_item(other)? {
                    Some(tr) => {
                        rb.direction = tr.vector(rb.direction);
                        rb.up = tr.vector(rb.up);
                    }
                    None => {
                        return Err(
                            self.error_at(t.span, format!("unexpected '{other}' in rainbow"))
                        )
                    }
                },
            }
        }
        rb.falloff_angle = falloff.unwrap_or(rb.arc_angle).min(rb.arc_angle);
        Ok(FogDesc {
            distance,
            rainbow: Some(Box::new(rb)),
            ..FogDesc::default()
        })
    }
}
