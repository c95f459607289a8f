//! `interior { ior fade_distance fade_power fade_color ... }`.

use crate::scene::desc::Interior;

use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};
use super::value::Value;

impl Parser {
    pub(super) fn parse_interior_block(&mut self) -> PResult<Interior> {
        self.open_brace("interior")?;
        let mut int = Interior::default();
        loop {
            let t = self.next_tok()?;
            let Tok::Ident(k) = &t.tok else {
                if t.tok == Tok::Sym(Sym::RBrace) {
                    return Ok(int);
                }
                return Err(self.unexpected(&t, "in interior"));
            };
            if let Some(Value::Interior(id)) = self.lookup(k) {
                int = (**id).clone();
                continue;
            }
            match &**k {
                "ior" => int.ior = self.parse_float()?,
                "caustics" => int.caustics = self.parse_float()? as f32,
                "fade_distance" => int.fade_distance = self.parse_float()?,
                "fade_power" => int.fade_power = self.parse_float()?,
                "fade_color" | "fade_colour" => int.fade_color = self.parse_color()?.rgb,
                "dispersion" => int.dispersion = self.parse_float()? as f32,
                "dispersion_samples" => {
                    int.dispersion_samples = self.parse_float()?.clamp(2.0, 65535.0) as u16;
                }
                "media" => {
                    let m = self.parse_media_block()?;
                    std::sync::Arc::make_mut(&mut int.media).push(m);
                }
                _ => return Err(self.error_at(t.span, format!("unexpected '{k}' in interior"))),
            }
        }
    }
}
