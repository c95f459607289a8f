//! `media { }` and its `density { }` blocks (manual 3.4.8), in interiors and at the top
//! level (atmospheric media).

use crate::color::Rgbft;
use crate::math::DVec3;
use crate::scene::desc::Pigment;
use crate::scene::media::{Media, Scattering};

use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};
use super::value::Value;

impl Parser {
    /// `media { [MEDIA_IDENTIFIER] items }` after the keyword.
    pub(super) fn parse_media_block(&mut self) -> PResult<Media> {
        self.open_brace("media")?;
        let mut m = Media::default();
        if let Some(k) = self.peek_ident()? {
            if let Some(Value::Media(id)) = self.lookup(&k) {
                m = (**id).clone();
                self.advance();
            }
        }
        loop {
            let t = self.next_tok()?;
            let Tok::Ident(k) = &t.tok else {
                if t.tok == Tok::Sym(Sym::RBrace) {
                    return Ok(m);
                }
                return Err(self.unexpected(&t, "in media"));
            };
            if let Some(tr) = self.transform_item(k)? {
                m.apply_transform(&tr);
                continue;
            }
            match &**k {
                "method" => m.method = self.parse_float()?.round().clamp(1.0, 3.0) as u32,
                "intervals" => m.intervals = self.parse_float()?.round().max(1.0) as u32,
                "samples" => {
                    let lo = self.parse_float()?.round().max(1.0) as u32;
                    let hi = if self.eat_sym(Sym::Comma)? {
                        self.parse_float()?.round().max(1.0) as u32
                    } else {
                        lo
                    };
                    m.samples = (lo, hi.max(lo));
                }
                "aa_level" => {
                    let v = self.parse_float()?;
                    if v < 1.0 {
                        // As povray: "aa_level in media must be at least one."
                        return Err(self.error_at(t.span, "aa_level in media must be at least 1"));
                    }
                    m.aa_level = v as u32;
                }
                "aa_threshold" => m.aa_threshold = self.parse_float()?,
                "jitter" => m.jitter = self.parse_float()?,
                "confidence" | "variance" | "ratio" => {
                    // Methods 1 and 2's statistics; lancer samples every method evenly.
                    self.parse_float()?;
                }
                "absorption" => m.absorption = self.parse_color()?.rgb,
                "emission" => m.emission = self.parse_color()?.rgb,
                "scattering" => m.scattering = Some(self.parse_scattering()?),
                "density" => {
                    let d = self.parse_density_block()?;
                    m.density.push(d);
                }
                _ => return Err(self.error_at(t.span, format!("unexpected '{k}' in media"))),
            }
        }
    }

    /// `scattering { type, COLOR [eccentricity e] [extinction x] }` after the keyword.
    fn parse_scattering(&mut self) -> PResult<Scattering> {
        let open = self.open_brace("scattering")?;
        let kind = self.parse_float()?.round();
        if !(1.0..=5.0).contains(&kind) {
            return Err(self.error_at(open, format!("scattering type {kind} is not 1 to 5")));
        }
        self.skip_optional_comma()?;
        let color = self.parse_color()?.rgb;
        let mut s = Scattering {
            kind: kind as u32,
            color,
            eccentricity: 0.0,
            extinction: 1.0,
        };
        loop {
            let t = self.next_tok()?;
            match &t.tok {
                Tok::Sym(Sym::RBrace) => return Ok(s),
                Tok::Ident(k) if &**k == "eccentricity" => {
                    if s.kind != 5 {
                        // povray refuses it too ("Eccentricity cannot be used with this
                        // scattering type").
                        return Err(self.error_at(
                            t.span,
                            "eccentricity is only for scattering type 5 (Henyey-Greenstein)",
                        ));
                    }
                    s.eccentricity = self.parse_float()?;
                }
                Tok::Ident(k) if &**k == "extinction" => s.extinction = self.parse_float()?,
                _ => return Err(self.unexpected(&t, "in scattering")),
            }
        }
    }

    /// `density { [DENSITY_IDENTIFIER] [PATTERN] modifiers }` after the keyword: read as a
    /// pigment whose colour is the density, white (1) when nothing is given.
    pub(super) fn parse_density_block(&mut self) -> PResult<Pigment> {
        let outer = std::mem::replace(&mut self.in_density, true);
        let base = Pigment::solid(Rgbft::rgb(DVec3::ONE));
        let d = self.parse_pigment_block(Some(base));
        self.in_density = outer;
        d
    }
}
