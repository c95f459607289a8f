//! `normal { ... }` blocks: a pattern and its strength (`bumps 0.5`), `bump_map`, normal lists
//! of block patterns, `normal_map`, `slope_map`, `bump_size`, `accuracy`, `no_bump_scale` and
//! the pattern modifiers shared with pigments. Evaluation is in render::normal.

use std::sync::Arc;

use crate::scene::desc::{Normal, NormalKind, SlopeMap, Special};
use crate::scene::pattern::{Pattern, PatternKind};

use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};
use super::source::Span;
use super::value::Value;

/// What a normal body has said so far besides its pattern.
enum Form {
    Plain(Option<SlopeMap>),
    Items(Vec<Normal>),
    Map(Vec<(f64, Normal)>),
}

impl Parser {
    /// `normal { ... }` after the keyword.
    pub(super) fn parse_normal_block(&mut self, _span: Span) -> PResult<Normal> {
        self.open_brace("normal")?;
        self.parse_normal_body(None, Sym::RBrace)
    }

    /// A normal modified in place: `normal { ... }` after an object's or texture's normal.
    pub(super) fn parse_normal_block_over(&mut self, base: Option<Normal>) -> PResult<Normal> {
        self.open_brace("normal")?;
        self.parse_normal_body(base, Sym::RBrace)
    }

    /// The inside of a normal up to and including `close` (`}`, or `]` in a normal map).
    fn parse_normal_body(&mut self, base: Option<Normal>, close: Sym) -> PResult<Normal> {
        let mut n = base.unwrap_or_else(|| Normal::new(NormalKind::Flat));
        if let Some(k) = self.peek_ident()? {
            if let Some(Value::Normal(id)) = self.lookup(&k) {
                n = (**id).clone();
                self.advance();
            }
        }
        let kind = std::mem::replace(&mut n.kind, NormalKind::Flat);
        // A declared bump map or facets normal keeps its kind under new modifiers.
        let mut other = matches!(kind, NormalKind::BumpMap(_) | NormalKind::Facets { .. })
            .then_some(kind.clone());
        let (mut pat, mut special, mut form) = split(kind);
        loop {
            let t = self.next_tok()?;
            let Tok::Ident(k) = &t.tok else {
                if t.tok == Tok::Sym(close) {
                    break;
                }
                return Err(self.unexpected(&t, "in normal"));
            };
            if let Some(tr) = self.transform_item(k)? {
                n.apply_transform(&tr);
                continue;
            }
            match &**k {
                "bump_size" => {
                    n.amount = self.parse_float()?;
                    continue;
                }
                "accuracy" => {
                    n.accuracy = self.parse_float()?;
                    continue;
                }
                "no_bump_scale" => {
                    n.no_bump_scale = self.optional_bool()?;
                    continue;
                }
                "bump_map" => {
                    let mut im = self.parse_image_map(t.span)?;
                    crate::scene::image::to_file_values(&mut im);
                    if im.use_index {
                        self.unsupported("use_index (in bump_map; the grey is used)", t.span);
                    }
                    if let Some(b) = im.bump_size {
                        n.amount = b;
                    }
                    other = Some(NormalKind::BumpMap(Arc::new(im)));
                    pat = None;
                    continue;
                }
                "facets" => {
                    self.unsupported("facets (normal pattern; the normal is left flat)", t.span);
                    let (mut coords, mut size) = (0.0, 0.1);
                    loop {
                        if self.eat_keyword("coords")? {
                            coords = self.parse_float()?;
                        } else if self.eat_keyword("size")? {
                            size = self.parse_float()?;
                        } else {
                            break;
                        }
                    }
                    self.normal_amount(&mut n)?;
                    other = Some(NormalKind::Facets { coords, size });
                    pat = None;
                    continue;
                }
                _ => {}
            }
            let sp = match &**k {
                "bumps" => Some(Special::Bumps),
                "dents" => Some(Special::Dents),
                "ripples" => Some(Special::Ripples),
                "waves" => Some(Special::Waves),
                "wrinkles" => Some(Special::Wrinkles),
                "quilted" => Some(Special::Quilted),
                _ => None,
            };
            if let Some(kind) = self.pattern_keyword(k, t.span)? {
                let mut np = Pattern::new(kind);
                match pat.take() {
                    // Modifiers written before the pattern keyword still count.
                    Some(old) => {
                        np.turbulence = old.turbulence;
                        np.warps = old.warps;
                        np.frequency = old.frequency;
                        np.phase = old.phase;
                        np.noise_generator = old.noise_generator;
                    }
                    None => np.noise_generator = 0,
                }
                special = sp.unwrap_or(Special::Slope);
                other = None;
                if np.is_block() {
                    self.skip_optional_comma()?;
                    let items = self.parse_normal_items()?;
                    self.close_object_pattern(&np.kind)?;
                    form = if items.is_empty() {
                        Form::Plain(None)
                    } else {
                        Form::Items(items)
                    };
                } else if matches!(form, Form::Items(_)) {
                    form = Form::Plain(None);
                }
                if !matches!(form, Form::Items(_)) {
                    self.normal_amount(&mut n)?;
                }
                pat = Some(np);
                continue;
            }
            match &**k {
                "normal_map" => {
                    let weights_optional = pat
                        .as_ref()
                        .is_some_and(|q| matches!(q.kind, PatternKind::Average));
                    form = Form::Map(self.parse_normal_map_entries(weights_optional)?);
                    continue;
                }
                "slope_map" => {
                    form = Form::Plain(Some(self.parse_slope_map()?));
                    continue;
                }
                _ => {}
            }
            let space = n.transform;
            let pm = pat.get_or_insert_with(|| {
                let mut u = Pattern::new(PatternKind::Unsupported);
                u.noise_generator = 0;
                u
            });
            if self.pattern_modifier(k, t.span, pm, &space)? {
                continue;
            }
            return Err(self.error_at(t.span, format!("unexpected '{k}' in normal")));
        }
        n.kind = match (other, pat) {
            (Some(kind), _) => kind,
            (None, None) => NormalKind::Flat,
            (None, Some(p)) if matches!(p.kind, PatternKind::Unsupported) => NormalKind::Flat,
            (None, Some(p)) => join(p, special, form),
        };
        Ok(n)
    }

    /// The optional strength after a pattern keyword (`bumps 0.5`, `gradient x, 2`).
    fn normal_amount(&mut self, n: &mut Normal) -> PResult<()> {
        let comma = self.eat_sym(Sym::Comma)?;
        if comma || self.starts_float()? {
            n.amount = self.parse_float()?;
        }
        Ok(())
    }

    /// What a normal inside a map or a block pattern's list starts from: a flat normal with
    /// the `#default` normal's `bump_size` (measured: under `#default { normal { bump_size
    /// 1.5 } }` the entries of a normal_map perturb as with `1.5`, textures/normals/normmap).
    fn default_normal_base(&self) -> Option<Normal> {
        let d = self.scene.default_texture.normal.as_deref()?;
        let mut n = Normal::new(NormalKind::Flat);
        n.amount = d.amount;
        Some(n)
    }

    /// The normals listed after a block pattern: `normal { ... }` blocks or identifiers.
    fn parse_normal_items(&mut self) -> PResult<Vec<Normal>> {
        self.parse_item_list(
            "normal",
            |v| match v {
                Value::Normal(n) => Some((**n).clone()),
                _ => None,
            },
            |p| {
                let base = p.default_normal_base();
                p.parse_normal_block_over(base)
            },
        )
    }

    /// `normal_map { [v NORMAL_BODY] ... }` after the keyword, or a declared one.
    pub(super) fn parse_normal_map(&mut self) -> PResult<Vec<(f64, Normal)>> {
        self.parse_normal_map_entries(false)
    }

    fn parse_normal_map_entries(&mut self, weights_optional: bool) -> PResult<Vec<(f64, Normal)>> {
        self.parse_map_entries(
            "normal_map",
            weights_optional,
            !weights_optional,
            |v| match v {
                Value::NormalMap(m) => Some((**m).clone()),
                _ => None,
            },
            |p| {
                let base = p.default_normal_base();
                p.parse_normal_body(base, Sym::RBracket)
            },
        )
    }

    /// `slope_map { [v, <height, slope>] ... }` after the keyword, or a declared one.
    pub(super) fn parse_slope_map(&mut self) -> PResult<SlopeMap> {
        self.open_brace("slope_map")?;
        let mut map = Vec::new();
        loop {
            let t = self.next_tok()?;
            match &t.tok {
                Tok::Sym(Sym::RBrace) => break,
                Tok::Sym(Sym::LBracket) => {
                    let v = self.parse_float()?;
                    self.skip_optional_comma()?;
                    let hs = self.parse_vector()?;
                    self.expect_sym(Sym::RBracket, "to close the slope map entry")?;
                    map.push((v, hs.x, hs.y));
                }
                Tok::Ident(k) => match self.lookup(k) {
                    Some(Value::SlopeMap(m)) => map = (**m).clone(),
                    _ => return Err(self.unexpected(&t, "in slope_map")),
                },
                _ => return Err(self.unexpected(&t, "in slope_map; expected '[value, <h, s>]'")),
            }
        }
        // A stable sort: equal values keep their order (a jump in height or slope).
        map.sort_by(|a, b| a.0.total_cmp(&b.0));
        Ok(map)
    }
}

/// A normal's pattern and the rest, so a body can modify a declared normal.
fn split(kind: NormalKind) -> (Option<Pattern>, Special, Form) {
    match kind {
        NormalKind::Flat | NormalKind::BumpMap(_) | NormalKind::Facets { .. } => {
            (None, Special::Slope, Form::Plain(None))
        }
        NormalKind::Pattern {
            pattern,
            special,
            slope_map,
        } => (Some(*pattern), special, Form::Plain(slope_map)),
        NormalKind::List { pattern, items } => (Some(*pattern), Special::Slope, Form::Items(items)),
        NormalKind::Map { pattern, map } => (Some(*pattern), Special::Slope, Form::Map(map)),
    }
}

fn join(pattern: Pattern, special: Special, form: Form) -> NormalKind {
    let pattern = Box::new(pattern);
    match form {
        Form::Items(items) => NormalKind::List { pattern, items },
        Form::Map(map) => NormalKind::Map { pattern, map },
        Form::Plain(slope_map) => NormalKind::Pattern {
            pattern,
            special,
            slope_map,
        },
    }
}
