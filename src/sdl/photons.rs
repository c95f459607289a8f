//! The three `photons { }` blocks: in global_settings, in an object, in a light_source.

use crate::scene::photon::{flags, LightPhotons, ObjectPhotons, PhotonSettings};

use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};

impl Parser {
    /// `photons { spacing | count, gather, media, jitter, ... }` in global_settings.
    pub(super) fn parse_global_photons(&mut self) -> PResult<PhotonSettings> {
        self.open_brace("photons")?;
        let mut p = PhotonSettings::default();
        loop {
            let t = self.next_tok()?;
            let Tok::Ident(k) = &t.tok else {
                if t.tok == Tok::Sym(Sym::RBrace) {
                    break;
                }
                return Err(self.unexpected(&t, "in photons"));
            };
            match &**k {
                "spacing" => p.spacing = Some(self.parse_float()?),
                "count" => p.count = Some(self.parse_float()?),
                "gather" => {
                    p.gather_min = self.parse_float()?.max(0.0) as u32;
                    self.skip_optional_comma()?;
                    p.gather_max = self.parse_float()?.max(1.0) as u32;
                }
                "media" => {
                    self.unsupported("media (photons in media)", t.span);
                    self.parse_float()?;
                    if self.eat_sym(Sym::Comma)? {
                        self.parse_float()?;
                    }
                }
                "jitter" => p.jitter = self.parse_float()?,
                "max_trace_level" => p.max_trace_level = Some(self.parse_float()?.max(1.0) as u32),
                "adc_bailout" => p.adc_bailout = Some(self.parse_float()?),
                "autostop" => p.autostop = self.parse_float()?.clamp(0.0, 1.0),
                "expand_thresholds" => {
                    self.warn(t.span, "expand_thresholds is read but not used: lancer always takes the widened photon search, which matches povray's pictures better (docs/photons.md)");
                    p.expand_increase = self.parse_float()?;
                    self.skip_optional_comma()?;
                    p.expand_min = self.parse_float()?.max(0.0) as u32;
                }
                "radius" => self.parse_photon_radius(&mut p)?,
                "save_file" => p.save_file = Some(self.parse_string()?),
                "load_file" => p.load_file = Some(self.parse_string()?),
                _ => return Err(self.error_at(t.span, format!("unexpected '{k}' in photons"))),
            }
        }
        if p.spacing.is_none() && p.count.is_none() {
            // POV-Ray requires one of them; without either, a count gives some photons.
            p.count = Some(20000.0);
        }
        Ok(p)
    }

    /// `radius [gather_radius] [, multiplier [, media_radius [, media_multiplier]]]`, every
    /// part optional.
    fn parse_photon_radius(&mut self, p: &mut PhotonSettings) -> PResult<()> {
        let mut slot = 0;
        loop {
            if self.starts_float()? {
                let v = self.parse_float()?;
                match slot {
                    0 => p.radius = (v > 0.0).then_some(v),
                    1 => p.radius_mult = if v > 0.0 { v } else { 1.0 },
                    // Media radii: photons in media are not built.
                    _ => {}
                }
            }
            if slot >= 3 || !self.eat_sym(Sym::Comma)? {
                return Ok(());
            }
            slot += 1;
        }
    }

    /// An object's `photons { target [mult], refraction, reflection, collect, pass_through }`.
    pub(super) fn parse_object_photons(&mut self, mut p: ObjectPhotons) -> PResult<ObjectPhotons> {
        self.open_brace("photons")?;
        loop {
            let t = self.next_tok()?;
            let Tok::Ident(k) = &t.tok else {
                if t.tok == Tok::Sym(Sym::RBrace) {
                    return Ok(p);
                }
                return Err(self.unexpected(&t, "in the object's photons"));
            };
            let mut set = |bit: u8, on: bool| {
                if on {
                    p.flags |= bit;
                } else {
                    p.flags &= !bit;
                }
            };
            match &**k {
                "target" => {
                    set(flags::TARGET, true);
                    if self.starts_float()? {
                        let m = self.parse_float()?;
                        p.set_spacing_mult(m);
                    }
                }
                "refraction" => set(flags::REFRACTION, self.optional_bool()?),
                "reflection" => set(flags::REFLECTION, self.optional_bool()?),
                "collect" => set(flags::NO_COLLECT, !self.optional_bool()?),
                "pass_through" => {
                    let on = self.optional_bool()?;
                    set(flags::PASS_THROUGH, on);
                    set(flags::PASS_THROUGH_OFF, !on);
                }
                "split_union" => {
                    // lancer shoots at a union's bounds as a whole: the same as `off`.
                    self.optional_bool()?;
                }
                _ => {
                    return Err(
                        self.error_at(t.span, format!("unexpected '{k}' in the object's photons"))
                    )
                }
            }
        }
    }

    /// A light's `photons { refraction, reflection, area_light }`.
    pub(super) fn parse_light_photons(&mut self) -> PResult<LightPhotons> {
        self.open_brace("photons")?;
        // Measured: `photons { reflection off }` still refracts, `photons { refraction off }`
        // does not: what the block does not name keeps the default, on.
        let mut p = LightPhotons::default();
        loop {
            let t = self.next_tok()?;
            let Tok::Ident(k) = &t.tok else {
                if t.tok == Tok::Sym(Sym::RBrace) {
                    return Ok(p);
                }
                return Err(self.unexpected(&t, "in the light's photons"));
            };
            match &**k {
                "refraction" => p.refraction = self.optional_bool()?,
                "reflection" => p.reflection = self.optional_bool()?,
                "area_light" => {
                    p.area_light = self.optional_bool()?;
                    if p.area_light {
                        self.unsupported(
                            "area_light (photons are shot from the light's centre)",
                            t.span,
                        );
                    }
                }
                _ => {
                    return Err(
                        self.error_at(t.span, format!("unexpected '{k}' in the light's photons"))
                    )
                }
            }
        }
    }
}
