//! Atmospheric scene items: `fog { ... }` (constant and ground fog), read into a `FogDesc`.

use crate::scene::desc::FogDesc;

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
                            self.unsupported("turbulence (in fog)", t.span);
                            self.parse_vector()?;
                        }
                        "turb_depth" | "omega" | "lambda" | "octaves" => {
                            self.parse_float()?;
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
