//! The `text` object: `text { ttf "font.ttf" "string" thickness, offset modifiers }` and
//! `text { internal N ... }`, with the font found like an include file.

use std::path::PathBuf;
use std::sync::Arc;

use glam::DVec2;

use crate::geom::font::Font;
use crate::geom::text::TextData;
use crate::scene::desc::{ObjectDesc, ShapeDesc};

use super::parser::{PResult, Parser};
use super::source::Span;

/// POV-Ray 3.7's built-in fonts by number. They are compiled into povray; lancer reads the
/// same fonts from the include directory (povray-includes ships them).
const INTERNAL_FONTS: [&str; 4] = ["povlogo.ttf", "timrom.ttf", "cyrvetic.ttf", "crystal.ttf"];

impl Parser {
    pub(super) fn text_object(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("text")?;
        let kind_span = self.next_span()?;
        let name = if self.eat_keyword("ttf")? {
            self.parse_string_term()?
        } else if self.eat_keyword("internal")? {
            let n = self.parse_float()?;
            // An out-of-range number means font 0, as the manual says.
            let i = if (0.0..4.0).contains(&n) {
                n as usize
            } else {
                0
            };
            INTERNAL_FONTS[i].to_string()
        } else {
            return Err(self.error_at(kind_span, "expected 'ttf' or 'internal' in text"));
        };
        let font = self.find_font(&name, kind_span)?;
        self.skip_optional_comma()?;
        let string_span = self.next_span()?;
        let string = self.parse_string_term()?;
        self.skip_optional_comma()?;
        let thickness = self.parse_float()?;
        self.skip_optional_comma()?;
        // A float offset is promoted to <f, f, f>: POV-Ray moves each glyph up by it too.
        let offset = self.parse_vector()?;
        let layout = font.layout(&string, DVec2::new(offset.x, offset.y), !self.utf8_strings);
        if !layout.missing.is_empty() {
            let mut chars: Vec<String> = layout
                .missing
                .iter()
                .map(|c| format!("{c:?} (U+{:04X})", *c as u32))
                .collect();
            chars.dedup();
            let mut msg = format!(
                "{} has no glyph for {}; drawn as its missing-glyph shape, as POV-Ray does",
                font.path.display(),
                chars.join(", ")
            );
            if !self.utf8_strings && layout.missing.iter().any(|c| !c.is_ascii()) {
                msg.push_str(" (with the default 'charset ascii' every character above 127 is missing; POV-Ray's own output for characters above 255 is unpredictable there; global_settings { charset utf8 } reads them as Unicode)");
            }
            self.warn(string_span, msg);
        }
        let data = TextData {
            glyphs: layout.glyphs,
            thickness,
        };
        self.finish_object(ObjectDesc::new(ShapeDesc::Text(Arc::new(data))), open)
    }

    /// The font file: as named, else with ".ttf" added (POV-Ray finds "cyrvetic" too), in
    /// the directories include files are looked for in.
    fn find_font(&mut self, name: &str, span: Span) -> PResult<Arc<Font>> {
        let path: Option<PathBuf> = self.find_file(name).or_else(|| {
            std::path::Path::new(name)
                .extension()
                .is_none()
                .then(|| self.find_file(&format!("{name}.ttf")))
                .flatten()
        });
        let Some(path) = path else {
            let d = self.error_at(span, format!("cannot find font file \"{name}\""));
            return Err(Box::new(
                d.with_note(self.searched_note())
                    .with_note("POV-Ray's fonts (timrom.ttf, cyrvetic.ttf, crystal.ttf, povlogo.ttf) come with Debian's povray-includes package; other directories can be added with +L<dir>"),
            ));
        };
        Font::load(&path).map_err(|e| self.error_at(span, e))
    }
}
