//! `texture { ... }` blocks: plain textures (pigment, finish, normal), and patterned ones —
//! a block pattern with listed textures, `texture_map`, or the old `tiles`.

use std::sync::Arc;

use crate::scene::desc::{Texture, TextureEntries, TexturePattern};
use crate::scene::pattern::{Pattern, PatternKind};

use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};
use super::pattern::is_pattern_keyword;
use super::source::Span;
use super::value::Value;

impl Parser {
    pub(super) fn parse_texture_block(&mut self) -> PResult<Texture> {
        self.open_brace("texture")?;
        self.parse_texture_body(Sym::RBrace)
    }

    /// `parse_texture_block` for an object: `texture { T }` with nothing more gives the
    /// declared texture itself, shared, so a loop placing a million objects with it holds
    /// one texture, not a million copies.
    pub(super) fn parse_texture_block_shared(&mut self) -> PResult<Arc<Texture>> {
        self.open_brace("texture")?;
        if let Some(k) = self.peek_ident()? {
            if let Some(Value::Texture(id)) = self.lookup(&k) {
                let id = id.clone();
                self.advance();
                if self.eat_sym(Sym::RBrace)? {
                    return Ok(id);
                }
                return self
                    .parse_texture_rest(Arc::unwrap_or_clone(id), Sym::RBrace)
                    .map(Arc::new);
            }
        }
        let tex = self.scene.default_texture.clone();
        self.parse_texture_rest(tex, Sym::RBrace).map(Arc::new)
    }

    /// The inside of a texture up to and including `close` (`}`, or `]` in a texture map).
    fn parse_texture_body(&mut self, close: Sym) -> PResult<Texture> {
        let mut tex = self.scene.default_texture.clone();
        if let Some(k) = self.peek_ident()? {
            if let Some(Value::Texture(id)) = self.lookup(&k) {
                tex = (**id).clone();
                self.advance();
            }
        }
        self.parse_texture_rest(tex, close)
    }

    /// A texture's items after its optional identifier, up to and including `close`.
    fn parse_texture_rest(&mut self, mut tex: Texture, close: Sym) -> PResult<Texture> {
        loop {
            let t = self.next_tok()?;
            let Tok::Ident(k) = &t.tok else {
                if t.tok == Tok::Sym(close) {
                    break;
                }
                return Err(self.unexpected(&t, "in texture"));
            };
            if let Some(tr) = self.transform_item(k)? {
                tex.apply_transform(&tr);
                continue;
            }
            if let Some(tp) = &mut tex.pattern {
                let space = tp.transform;
                if self.pattern_modifier(k, t.span, &mut tp.pattern, &space)? {
                    continue;
                }
            }
            match &**k {
                "pigment" => tex.pigment = self.parse_pigment_block(Some(tex.pigment.clone()))?,
                "finish" => tex.finish = self.parse_finish_block(Some(tex.finish.clone()))?,
                "normal" => {
                    let base = tex.normal.take().map(|n| *n);
                    tex.normal = Some(Box::new(self.parse_normal_block_over(base)?));
                }
                "uv_mapping" => tex.uv_mapping = true,
                "texture_map" => {
                    let weights_optional = tex
                        .pattern
                        .as_ref()
                        .is_some_and(|tp| matches!(tp.pattern.kind, PatternKind::Average));
                    let map = self.parse_texture_map_entries(weights_optional)?;
                    match &mut tex.pattern {
                        Some(tp) => tp.entries = TextureEntries::Map(map),
                        None => {
                            // A map with no pattern follows POV-Ray's default gradient x.
                            tex.pattern = Some(Box::new(TexturePattern {
                                pattern: Pattern::new(PatternKind::Gradient(crate::math::DVec3::X)),
                                transform: Default::default(),
                                entries: TextureEntries::Map(map),
                            }))
                        }
                    }
                }
                "tiles" => {
                    // The old form of a checker of two textures, `tiles { T1 tile2 T2 }`, with
                    // T2 where checker puts its first item (measured with povray).
                    self.open_brace("tiles")?;
                    let a = self.parse_tile_textures(true)?;
                    let b = self.parse_tile_textures(false)?;
                    let mut pattern = Pattern::new(PatternKind::Checker);
                    pattern.noise_generator = 0;
                    tex.pattern = Some(Box::new(TexturePattern {
                        pattern,
                        transform: Default::default(),
                        entries: TextureEntries::List(vec![b, a]),
                    }));
                }
                k if is_pattern_keyword(k) => {
                    let Some(kind) = self.pattern_keyword(k, t.span)? else {
                        return Err(self.error_at(t.span, format!("unexpected '{k}' in texture")));
                    };
                    if matches!(kind, PatternKind::Unsupported) {
                        // Already warned about; the texture stays as it was.
                        self.skip_texture_pattern()?;
                        continue;
                    }
                    let mut pattern = Pattern::new(kind);
                    pattern.noise_generator = 0;
                    let entries = if pattern.is_block() {
                        let items = self.parse_texture_items()?;
                        self.close_object_pattern(&pattern.kind)?;
                        TextureEntries::List(items)
                    } else {
                        TextureEntries::Map(Vec::new())
                    };
                    tex.pattern = Some(Box::new(TexturePattern {
                        pattern,
                        transform: Default::default(),
                        entries,
                    }));
                }
                "material_map" => {
                    if let Some(tp) = self.parse_material_map(t.span)? {
                        tex.pattern = Some(Box::new(tp));
                    }
                }
                _ => return Err(self.error_at(t.span, format!("unexpected '{k}' in texture"))),
            }
        }
        if let Some(tp) = &tex.pattern {
            let empty = match &tp.entries {
                TextureEntries::List(l) => l.is_empty(),
                TextureEntries::Map(m) => m.is_empty(),
            };
            if empty {
                // POV-Ray requires a texture_map here; keep the plain texture.
                tex.pattern = None;
            }
        }
        Ok(tex)
    }

    /// The textures listed after a block pattern in a texture (`texture {..}` or declared
    /// texture identifiers, commas optional).
    fn parse_texture_items(&mut self) -> PResult<Vec<Texture>> {
        self.parse_item_list(
            "texture",
            |v| match v {
                Value::Texture(t) => Some((**t).clone()),
                _ => None,
            },
            |p| p.parse_texture_block(),
        )
    }

    /// The items listed after a block pattern: `KEYWORD {..}` blocks (read by `block`) or
    /// declared identifiers of the kind (`declared`), commas optional.
    pub(super) fn parse_item_list<T>(
        &mut self,
        keyword: &str,
        declared: impl Fn(&Value) -> Option<T>,
        mut block: impl FnMut(&mut Parser) -> PResult<T>,
    ) -> PResult<Vec<T>> {
        let mut items = Vec::new();
        loop {
            if self.eat_keyword(keyword)? {
                items.push(block(self)?);
            } else if let Some(k) = self.peek_ident()? {
                match self.lookup(&k).and_then(&declared) {
                    Some(item) => {
                        items.push(item);
                        self.advance();
                    }
                    None => break,
                }
            } else {
                break;
            }
            self.skip_optional_comma()?;
        }
        Ok(items)
    }

    /// One side of `tiles`: texture blocks (layered) up to `tile2` (first side) or the
    /// closing brace (second side), which are read too.
    fn parse_tile_textures(&mut self, first: bool) -> PResult<Texture> {
        let mut layers: Option<Texture> = None;
        loop {
            let done = if first {
                self.eat_keyword("tile2")?
            } else {
                self.eat_sym(Sym::RBrace)?
            };
            if done {
                return Ok(layers.unwrap_or_else(|| self.scene.default_texture.clone()));
            }
            if self.eat_keyword("texture")? {
                let t = self.parse_texture_block()?;
                layers = Some(match layers {
                    Some(below) => t.over(below),
                    None => t,
                });
            } else {
                let t = self.next_tok()?;
                return Err(self.unexpected(&t, "in tiles; expected 'texture'"));
            }
        }
    }

    /// `texture_map { [v TEXTURE_BODY] ... }` after the keyword, or a declared one.
    pub(super) fn parse_texture_map(&mut self) -> PResult<Vec<(f64, Texture)>> {
        self.parse_texture_map_entries(false)
    }

    /// `weights_optional`: `average`'s entries may leave out their weight (1).
    fn parse_texture_map_entries(
        &mut self,
        weights_optional: bool,
    ) -> PResult<Vec<(f64, Texture)>> {
        self.parse_map_entries(
            "texture_map",
            weights_optional,
            true,
            |v| match v {
                Value::TextureMap(m) => Some((**m).clone()),
                _ => None,
            },
            |p| p.parse_texture_body(Sym::RBracket),
        )
    }

    /// `material_map { TYPE "file" [map_type N] [once] [interpolate N] TEXTURE... }` (povray
    /// 3.7 rejects transforms inside, though the manual lists them)
    /// after the keyword: a texture list picked by the palette index of the image's pixel.
    /// None (after a warning) for an image without a palette, whose rule is not measured.
    fn parse_material_map(&mut self, span: Span) -> PResult<Option<TexturePattern>> {
        self.open_brace("material_map")?;
        let (_, name_span, name) = self.image_file_name()?;
        let mut im = crate::scene::desc::ImageMap::new(true);
        let mut items = Vec::new();
        loop {
            items.extend(self.parse_texture_items()?);
            let t = self.next_tok()?;
            let Tok::Ident(k) = &t.tok else {
                if t.tok == Tok::Sym(Sym::RBrace) {
                    break;
                }
                return Err(self.unexpected(&t, "in material_map"));
            };
            match &**k {
                "map_type" => im.map_type = self.parse_float()? as u32,
                "once" => im.once = true,
                "interpolate" => {
                    // The manual: the index is interpolated before the texture is chosen,
                    // "no useful purpose"; lancer takes the nearest pixel.
                    self.parse_float()?;
                    self.unsupported(
                        "interpolate (in material_map; the nearest pixel is used)",
                        t.span,
                    );
                }
                _ => return Err(self.error_at(t.span, format!("unexpected '{k}' in material_map"))),
            }
        }
        let Some(path) = self.find_file(&name) else {
            return Err(self.error_at(name_span, format!("cannot find image file \"{name}\" (searched the scene directory and the library path)")));
        };
        let Some(indices) = crate::scene::image::palette_indices(&path) else {
            self.unsupported("material_map (with an image without a palette)", span);
            return Ok(None);
        };
        crate::scene::image::load_image_map(&path, &mut im)
            .map_err(|e| self.error_at(name_span, e))?;
        if indices.len() != im.pixels.len() || items.is_empty() {
            self.unsupported("material_map (image or texture list unreadable)", span);
            return Ok(None);
        }
        im.path = path;
        // Measured (tests/probes/material_map): an index past the list's end wraps around it.
        let n = items.len();
        let indices: Vec<u8> = indices.iter().map(|&i| (i as usize % n) as u8).collect();
        let mut pattern = Pattern::new(PatternKind::MaterialMap(
            std::sync::Arc::new(im),
            std::sync::Arc::new(indices),
        ));
        pattern.noise_generator = 0;
        Ok(Some(TexturePattern {
            pattern,
            transform: Default::default(),
            entries: TextureEntries::List(items),
        }))
    }

    fn skip_texture_pattern(&mut self) -> PResult<()> {
        let mut depth = 0;
        loop {
            let t = self.peek()?.ok_or_else(|| self.eof_error())?;
            match t.tok {
                Tok::Sym(Sym::LBrace) | Tok::Sym(Sym::LBracket) => depth += 1,
                Tok::Sym(Sym::RBrace) | Tok::Sym(Sym::RBracket) if depth == 0 => return Ok(()),
                Tok::Sym(Sym::RBrace) | Tok::Sym(Sym::RBracket) => depth -= 1,
                _ => {}
            }
            self.advance();
        }
    }
}
