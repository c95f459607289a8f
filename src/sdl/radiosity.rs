//! `global_settings { radiosity { ... } }` and an object's `radiosity { importance }`: every
//! item of POV-Ray 3.7's radiosity block (manual 3.4.4.3), defaults in `RadiositySettings`.

use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};

impl Parser {
    pub(super) fn parse_global_radiosity(&mut self) -> PResult<()> {
        self.expect_sym(Sym::LBrace, "after 'radiosity'")?;
        let mut r = self.scene.global.radiosity.clone().unwrap_or_default();
        loop {
            let t = self.next_tok()?;
            let Tok::Ident(k) = &t.tok else {
                if t.tok == Tok::Sym(Sym::RBrace) {
                    break;
                }
                return Err(self.unexpected(&t, "in radiosity"));
            };
            match &**k {
                "adc_bailout" => r.adc_bailout = self.parse_float()?,
                "always_sample" => r.always_sample = self.optional_bool()?,
                "brightness" => r.brightness = self.parse_float()?,
                "count" => {
                    r.count = self.parse_float()?.max(1.0) as u32;
                    r.count_pool = r.count;
                    if self.eat_sym(Sym::Comma)? {
                        r.count_pool = (self.parse_float()?.max(1.0) as u32).max(r.count);
                    }
                }
                "error_bound" => r.error_bound = self.parse_float()?,
                "gray_threshold" => r.gray_threshold = self.parse_float()?.clamp(0.0, 1.0),
                "low_error_factor" => r.low_error_factor = self.parse_float()?,
                "max_sample" => r.max_sample = self.parse_float()?,
                "maximum_reuse" => r.maximum_reuse = self.parse_float()?,
                "minimum_reuse" => r.minimum_reuse = self.parse_float()?,
                "nearest_count" => {
                    r.nearest_count = self.parse_float()?.clamp(1.0, 20.0) as u32;
                    if self.eat_sym(Sym::Comma)? {
                        // The adaptive pretrace's stopping rule: lancer's pretrace always
                        // runs every pass, which only costs time.
                        self.parse_float()?;
                        self.unsupported("radiosity nearest_count's second value", t.span);
                    }
                }
                "normal" => r.normal = self.optional_bool()?,
                "pretrace_start" => r.pretrace_start = self.parse_float()?,
                "pretrace_end" => r.pretrace_end = self.parse_float()?,
                "recursion_limit" => {
                    r.recursion_limit = self.parse_float()?.clamp(1.0, 20.0) as u32
                }
                "media" | "subsurface" => {
                    if self.optional_bool()? {
                        self.unsupported(&format!("radiosity {k} on"), t.span);
                    }
                }
                "save_file" | "load_file" => {
                    // Replaced by the +RF options in 3.7.
                    self.parse_expr()?;
                    self.unsupported(&format!("radiosity {k}"), t.span);
                }
                // Deprecated 3.6 items 3.7 still reads and ignores.
                "distance_maximum" => {
                    self.parse_float()?;
                }
                _ => return Err(self.error_at(t.span, format!("unexpected '{k}' in radiosity"))),
            }
        }
        self.scene.global.radiosity = Some(r);
        Ok(())
    }

    /// An object's `radiosity { importance F }`: the importance, when written (the manual's
    /// range, above 0 and at most 1; values outside are clamped into it with a warning).
    pub(super) fn parse_object_radiosity(&mut self) -> PResult<Option<f32>> {
        self.expect_sym(Sym::LBrace, "after 'radiosity'")?;
        let mut importance = None;
        loop {
            let t = self.next_tok()?;
            match &t.tok {
                Tok::Sym(Sym::RBrace) => return Ok(importance),
                Tok::Ident(k) if &**k == "importance" => {
                    let v = self.parse_float()?;
                    if !(v > 0.0 && v <= 1.0) {
                        self.warn(
                            t.span,
                            format!("radiosity importance {v} is outside (0, 1]; clamped"),
                        );
                    }
                    importance = Some(v.clamp(1e-6, 1.0) as f32);
                }
                _ => return Err(self.unexpected(&t, "in an object's radiosity block")),
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::scene::desc::SceneDesc;
    use crate::sdl::{ParseOptions, Parser};

    fn parse_str(src: &str) -> Result<SceneDesc, ()> {
        let mut p = Parser::new(ParseOptions::default());
        p.parse_str("t.pov", src).map_err(|_| ())?;
        Ok(p.scene)
    }

    #[test]
    fn importance_is_inherited_and_defaulted() {
        let d = parse_str(
            "default { radiosity { importance 0.5 } }
             union { sphere { 0, 1 } sphere { x, 1 radiosity { importance 0.75 } }
                     radiosity { importance 0.25 } }
             sphere { 0, 1 }",
        )
        .unwrap();
        let imp = |o: &crate::scene::desc::ObjectDesc| o.rad_importance;
        let crate::scene::desc::ShapeDesc::Csg { children, .. } = &d.objects[0].shape else {
            panic!("union expected");
        };
        assert_eq!(imp(&d.objects[0]), 0.25);
        assert_eq!(imp(&children[0]), 0.25);
        assert_eq!(imp(&children[1]), 0.75);
        assert_eq!(imp(&d.objects[1]), 0.5);
    }

    #[test]
    fn defaults_and_items() {
        let d = parse_str("global_settings { radiosity { } }").unwrap();
        assert_eq!(d.global.radiosity, Some(Default::default()));
        let d = parse_str(
            "global_settings { radiosity { count 100, 400 brightness 0.5 recursion_limit 1 normal on } }",
        )
        .unwrap();
        let r = d.global.radiosity.unwrap();
        assert_eq!((r.count, r.count_pool), (100, 400));
        assert_eq!(r.brightness, 0.5);
        assert_eq!(r.recursion_limit, 1);
        assert!(r.normal);
    }
}
