//! The one recursive-descent parser, and the token stream it reads from.
//!
//! Tokens come from a stack of frames (the scene file, include files, macro bodies) over cached
//! token vectors. Directives are executed as the parser meets them (`peek`/`next`), because
//! POV-Ray's language is not context-free: a `#while` may wrap half an object and a macro call
//! may stand in the middle of one. Loops rewind a frame's position; nothing is re-read from
//! disk. Grammar areas live in sibling files as further `impl Parser` blocks.

use std::cell::RefCell;
use std::collections::{HashMap, HashSet};

use rustc_hash::FxHashMap;
use std::path::{Path, PathBuf};
use std::rc::Rc;

use crate::diag::{ChainLink, Diagnostic};
use crate::scene::desc::SceneDesc;

use super::lexer::{Sym, Tok, Token};
use super::source::{Sources, Span};
use super::value::Value;

mod files;
pub(super) use files::utf8_text;
use files::CachedFile;
pub use files::Lexed;
mod options;
pub use options::{ParseOptions, SYSTEM_INCLUDE_DIRS};

pub type PResult<T> = Result<T, Box<Diagnostic>>;

/// Limits that turn runaway scenes into errors instead of hangs or stack overflows.
const MAX_FRAME_DEPTH: usize = 200;
/// How deeply expressions, objects and function bodies may nest (see `Parser::nested`). A level
/// of the recursive descent takes up to about 5.5 KB of stack in a release build, so 256 levels
/// fit even the 2 MB stack of a spawned thread (tests, library users); POV-Ray itself gives up
/// at about 100 nested macro calls, and hand-written scenes nest far less.
const MAX_NESTING: u32 = 256;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum FrameKind {
    File,
    Include,
    Macro,
}

pub(super) struct Frame {
    pub tokens: Rc<Vec<Token>>,
    pub pos: usize,
    pub end: usize,
    pub kind: FrameKind,
    /// Where the include directive or macro call stood, for error chains.
    pub call_site: Option<(Span, Rc<str>)>,
    /// Whether entering this frame pushed a symbol table (include files and macro calls do).
    pub scope: bool,
}

#[derive(Clone, Debug)]
pub(super) enum Cond {
    /// Inside a taken `#if`/`#else` branch: a later `#else`/`#elseif` skips to `#end`.
    If { frame: usize },
    /// Inside a `#while` body: `#end` rewinds to the condition.
    While { frame: usize, cond_pos: usize },
    /// Inside a `#for` body: `#end` steps the counter and rewinds.
    For {
        frame: usize,
        body_pos: usize,
        var: Rc<str>,
        end: f64,
        step: f64,
    },
    /// Inside a `#switch`: `matched` once a clause was true (later clauses fall through).
    Switch {
        frame: usize,
        value: f64,
        matched: bool,
    },
}

pub struct Parser {
    pub sources: Sources,
    pub(super) frames: Vec<Frame>,
    pub(super) conds: Vec<Cond>,
    /// Symbol tables; [0] is global, one more per include file and macro call.
    /// FxHash: identifiers are looked up on every token, and SipHash's DoS resistance buys
    /// nothing against a scene that can loop forever anyway.
    pub(super) scopes: Vec<FxHashMap<Rc<str>, Value>>,
    /// The token position (frame count, position, token list) last found by `peek` to be a
    /// plain identifier, so peeking it again skips the macro and array lookups.
    plain_ident_at: Option<(usize, usize, usize)>,
    /// What the look-up at `plain_ident_at` found, so the operand reader need not look the
    /// identifier up a second time.
    pub(super) plain_ident: IdentClass,
    file_cache: HashMap<PathBuf, CachedFile>,
    /// Every name the lexer has read this parse, shared by all the files (`lexer::Names`).
    names: crate::sdl::lexer::Names,
    pub options: ParseOptions,
    pub(super) scene_dir: PathBuf,
    pub scene: SceneDesc,
    pub warnings: Vec<Diagnostic>,
    warned: HashSet<(Rc<str>, Span)>,
    /// Warnings raised while reading a declaration, held back until the identifier is used: an
    /// include file declaring something lancer cannot render yet (shapes.inc's quadrics) must
    /// not warn in every scene that includes it. Interior mutability because `lookup` is `&self`.
    deferred: RefCell<FxHashMap<Rc<str>, Vec<Diagnostic>>>,
    /// Deferred warnings whose identifier has been used, waiting to join `warnings`.
    released: RefCell<Vec<Diagnostic>>,
    /// Inside `( )`, where comparisons, logic and `? :` are read (see `parse_binary`).
    pub(super) rel_ok: bool,
    pub(super) last_span: Span,
    /// States of the random streams `seed()` made, indexed by what it returned.
    pub(super) rand_streams: Vec<u32>,
    /// The array element most recently resolved and the token positions it spanned, so a
    /// macro argument that is a lone element can be bound by reference.
    pub(super) last_element: Option<super::array::LastElement>,
    pub(super) files: super::fileio::Files,
    pub(super) deprecated: super::deprecated::Deprecations,
    /// How many times `trace()` ran, to warn once a scene leans on it heavily.
    pub(super) trace_calls: u32,
    /// Objects built for `trace()` and its kin, per identifier.
    pub(super) built_objects: super::built_objects::BuiltObjects,
    /// `#while`/`#for` iterations so far, against `ParseOptions::max_loop_iterations`.
    pub(super) loop_iterations: u64,
    /// Current depth of `nested` calls.
    nesting: u32,
    /// `global_settings { charset utf8 }` (or `sys`) seen: text objects read strings as
    /// Unicode; POV-Ray's default, ascii, has only codes 0 to 127.
    pub(super) utf8_strings: bool,
    /// Inside a media's `density { }`: a pigment body read as a density (white by default,
    /// a grey ramp as its default map, `density` items and `density_map`).
    pub(super) in_density: bool,
}

/// What an identifier found plain by `ready` stands for.
#[derive(Clone, Copy, Debug)]
pub(super) enum IdentClass {
    /// No symbol table has it: a keyword or built-in name, or an undeclared identifier.
    Undeclared,
    /// A declared float (the loop counters and constants of big loops), its value.
    Float(f64),
    /// Anything else declared.
    Declared,
}

impl Parser {
    pub fn new(options: ParseOptions) -> Parser {
        let mut globals = FxHashMap::default();
        for (name, v) in &options.declares {
            globals.insert(Rc::from(name.as_str()), Value::Float(*v));
        }
        Parser {
            sources: Sources::default(),
            frames: Vec::new(),
            conds: Vec::new(),
            scopes: vec![globals],
            plain_ident_at: None,
            plain_ident: IdentClass::Declared,
            file_cache: HashMap::new(),
            names: Default::default(),
            options,
            scene_dir: PathBuf::from("."),
            scene: super::default_scene(),
            warnings: Vec::new(),
            warned: HashSet::new(),
            deferred: RefCell::default(),
            released: RefCell::default(),
            rel_ok: false,
            last_span: Span::default(),
            rand_streams: Vec::new(),
            last_element: None,
            files: Default::default(),
            deprecated: Default::default(),
            trace_calls: 0,
            built_objects: Default::default(),
            loop_iterations: 0,
            nesting: 0,
            utf8_strings: false,
            in_density: false,
        }
    }

    /// Parses a whole scene file. Errors carry spans into `self.sources`.
    pub fn parse_file(&mut self, path: &Path) -> PResult<()> {
        self.scene_dir = path
            .parent()
            .map(Path::to_path_buf)
            .unwrap_or_else(|| PathBuf::from("."));
        let (_, tokens) = self.load(path, None)?;
        self.push_frame(tokens, FrameKind::File, None, false)?;
        if let Some(v) = self.options.version {
            self.scene.version = Some(v);
        }
        if let Some(name) = self.options.include_header.clone() {
            self.include_header(&name)?;
        }
        let r = self.parse_scene_items();
        self.flush_released();
        r
    }

    /// Parses scene text given directly (tests, snippets).
    pub fn parse_str(&mut self, name: &str, text: &str) -> PResult<()> {
        let id = self.sources.add(name.to_string(), text.to_string());
        let tokens = self.lex_file(id)?;
        self.push_frame(tokens, FrameKind::File, None, false)?;
        let r = self.parse_scene_items();
        self.flush_released();
        r
    }

    /// Moves the warnings of declarations used so far into `warnings`.
    pub(super) fn flush_released(&mut self) {
        let released = std::mem::take(self.released.get_mut());
        self.warnings.extend(released);
    }

    /// Holds back the "not supported" warnings from `from` on (those raised while reading the
    /// declaration of `name`) until `name` is looked up. Warnings about values computed now
    /// (`trace` of something lancer cannot render, a function it cannot evaluate) stay: the
    /// value is wrong whether or not the identifier is used later.
    pub(super) fn defer_warnings(&mut self, name: &Rc<str>, from: usize) {
        if self.warnings.len() > from {
            let (held, kept): (Vec<Diagnostic>, Vec<Diagnostic>) =
                self.warnings.drain(from..).partition(|d| d.deferrable);
            self.warnings.extend(kept);
            if !held.is_empty() {
                self.deferred
                    .get_mut()
                    .entry(name.clone())
                    .or_default()
                    .extend(held);
            }
        }
    }

    pub(super) fn push_frame(
        &mut self,
        tokens: Rc<Vec<Token>>,
        kind: FrameKind,
        call_site: Option<(Span, Rc<str>)>,
        scope: bool,
    ) -> PResult<()> {
        if self.frames.len() >= MAX_FRAME_DEPTH {
            let span = call_site.as_ref().map(|c| c.0).unwrap_or(self.last_span);
            return Err(self.error_at(span, format!("too many nested macro calls (more than {MAX_FRAME_DEPTH}; POV-Ray says \"Too many nested symbol tables\"): is a macro calling itself without end?")));
        }
        let end = tokens.len();
        self.push_frame_range(tokens, 0, end, kind, call_site, scope);
        Ok(())
    }

    pub(super) fn push_frame_range(
        &mut self,
        tokens: Rc<Vec<Token>>,
        pos: usize,
        end: usize,
        kind: FrameKind,
        call_site: Option<(Span, Rc<str>)>,
        scope: bool,
    ) {
        self.frames.push(Frame {
            tokens,
            pos,
            end,
            kind,
            call_site,
            scope,
        });
        if scope {
            self.scopes.push(FxHashMap::default());
        }
    }

    /// The token at the position in the innermost frame, if that frame has one left.
    pub(super) fn current_token(&self) -> Option<&Token> {
        let f = self.frames.last()?;
        (f.pos < f.end).then(|| &f.tokens[f.pos])
    }

    /// The next token without executing directives or macro calls; pops finished frames.
    pub(super) fn raw_peek(&mut self) -> PResult<Option<Token>> {
        Ok(if self.raw_ready()? {
            self.current_token().cloned()
        } else {
            None
        })
    }

    /// `raw_peek` without the copy: whether a token is left, which is then `current_token()`.
    fn raw_ready(&mut self) -> PResult<bool> {
        loop {
            let Some(f) = self.frames.last() else {
                return Ok(false);
            };
            if f.pos < f.end {
                self.last_span = f.tokens[f.pos].span;
                return Ok(true);
            }
            if self.frames.len() == 1 {
                self.check_conds_closed()?;
                return Ok(false);
            }
            self.check_conds_closed()?;
            if self.frames.pop().is_some_and(|f| f.scope) {
                self.scopes.pop();
                self.built_objects.scopes_left(self.scopes.len());
            }
        }
    }

    /// A `#if` or `#while` still open when its file or macro body ends is an error at the
    /// directive, as POV-Ray reports it.
    fn check_conds_closed(&mut self) -> PResult<()> {
        let depth = self.frames.len() - 1;
        let open = match self.conds.last() {
            Some(Cond::If { frame })
            | Some(Cond::While { frame, .. })
            | Some(Cond::For { frame, .. })
            | Some(Cond::Switch { frame, .. }) => *frame == depth,
            None => false,
        };
        if open {
            let span = self.last_span;
            return Err(self.error_at(span, "missing #end: a #if, #while or #for opened in this file or macro is not closed before it ends"));
        }
        Ok(())
    }

    /// Span of the token just consumed, for messages about the value that ended there.
    pub(super) fn cur_span(&self) -> Span {
        self.frames
            .last()
            .and_then(|f| f.tokens.get(f.pos.saturating_sub(1)))
            .map(|t| t.span)
            .unwrap_or_default()
    }

    /// Runs one level of a recursive grammar rule, refusing to go deeper than `MAX_NESTING`:
    /// `((((...` or `union { union { ...` thousands deep would otherwise overflow the stack
    /// and abort the process instead of reporting an error.
    pub(super) fn nested<T>(&mut self, f: impl FnOnce(&mut Self) -> PResult<T>) -> PResult<T> {
        if self.nesting >= MAX_NESTING {
            let span = self.last_span;
            return Err(self.error_at(
                span,
                format!(
                    "expressions, objects or function bodies nested more than {MAX_NESTING} deep"
                ),
            ));
        }
        self.nesting += 1;
        let r = f(self);
        self.nesting -= 1;
        r
    }

    /// Runs `f` with comparisons, `&`, `|` and `? :` read (`ok`) or not. POV-Ray reads them
    /// only inside parentheses; vector literals, call arguments, subscripts and `matrix`
    /// values start a context where they are not, so `max(1 > 0, 2)` is an error there too.
    pub(super) fn with_rel<T>(
        &mut self,
        ok: bool,
        f: impl FnOnce(&mut Self) -> PResult<T>,
    ) -> PResult<T> {
        let saved = std::mem::replace(&mut self.rel_ok, ok);
        let r = f(self);
        self.rel_ok = saved;
        r
    }

    pub(super) fn advance(&mut self) {
        self.plain_ident_at = None;
        if let Some(f) = self.frames.last_mut() {
            f.pos += 1;
        }
    }

    /// The next token after executing any directives and macro calls in the way.
    pub fn peek(&mut self) -> PResult<Option<Token>> {
        Ok(if self.ready()? {
            self.current_token().cloned()
        } else {
            None
        })
    }

    /// `peek` without copying the token out (a token holding an `Rc` costs a count up and
    /// down, and returning one through `PResult<Option<Token>>` a 40-byte copy): runs the
    /// directives and macro calls in the way and says whether a token is left; it is then
    /// `current_token()`. The grammar's hot paths (operands, symbols, keywords) read it there.
    #[inline]
    pub(super) fn ready(&mut self) -> PResult<bool> {
        // Fast path, kept small so it inlines: literals, symbols and identifiers already
        // known to be plain need no directive or macro handling.
        if let Some(t) = self.current_token() {
            let plain = match &t.tok {
                Tok::Num(_) | Tok::Sym(_) | Tok::Str(_) | Tok::Bulk(_) => true,
                Tok::Ident(_) => self.plain_ident_at == Some(self.position_key()),
                Tok::Directive(_) => false,
            };
            if plain {
                self.last_span = t.span;
                return Ok(true);
            }
        }
        self.ready_slow()
    }

    #[inline(never)]
    fn ready_slow(&mut self) -> PResult<bool> {
        loop {
            if !self.raw_ready()? {
                return Ok(false);
            }
            let Some(t) = self.current_token() else {
                return Ok(false);
            };
            let span = t.span;
            match &t.tok {
                Tok::Directive(d) => {
                    let d = d.clone();
                    self.advance();
                    self.directive(&d, span)?;
                }
                Tok::Ident(name) => {
                    // Nothing can change what an identifier means between two peeks at the same
                    // token without advancing (a directive would advance), so the answer is
                    // kept until the next `advance`.
                    let at = self.position_key();
                    if self.plain_ident_at == Some(at) {
                        return Ok(true);
                    }
                    if self.has_deprecations() {
                        let name = name.clone();
                        self.check_deprecated(&name, span);
                    }
                    let Some(Tok::Ident(name)) = self.current_token().map(|t| &t.tok) else {
                        unreachable!("the token at the position did not change");
                    };
                    match self.lookup(name) {
                        Some(Value::Macro(m)) => {
                            let m = m.clone();
                            self.advance();
                            self.invoke_macro(&m, span)?;
                        }
                        Some(Value::Array(_)) if self.at_subscript() => {
                            let name = name.clone();
                            self.advance();
                            self.push_element(name, span)?;
                        }
                        found => {
                            self.plain_ident = match found {
                                None => IdentClass::Undeclared,
                                Some(Value::Float(f)) => IdentClass::Float(*f),
                                Some(_) => IdentClass::Declared,
                            };
                            self.plain_ident_at = Some(at);
                            return Ok(true);
                        }
                    }
                }
                _ => return Ok(true),
            }
        }
    }

    /// What the identifier at the current token stands for, when `ready` has just found
    /// it plain (`None` otherwise).
    pub(super) fn plain_ident_class(&self) -> Option<IdentClass> {
        (self.plain_ident_at == Some(self.position_key())).then_some(self.plain_ident)
    }

    /// Where the token stream stands: frame count, position in the innermost frame, and that
    /// frame's token list (two frames at the same depth and position are told apart by it).
    fn position_key(&self) -> (usize, usize, usize) {
        match self.frames.last() {
            Some(f) => (self.frames.len(), f.pos, f.tokens.as_ptr() as usize),
            None => (0, 0, 0),
        }
    }

    pub fn next_tok(&mut self) -> PResult<Token> {
        match self.peek()? {
            Some(t) => {
                self.advance();
                Ok(t)
            }
            None => Err(self.eof_error()),
        }
    }

    pub(super) fn eof_error(&self) -> Box<Diagnostic> {
        self.error_at(
            self.last_span,
            "unexpected end of file: a '{' or '(' is probably not closed",
        )
    }

    pub(super) fn peek_sym(&mut self) -> PResult<Option<Sym>> {
        // Symbols and literals are never directives or macro calls: no need for `peek`.
        if let Some(t) = self.current_token() {
            let span = t.span;
            let known = match t.tok {
                Tok::Sym(s) => Some(Some(s)),
                Tok::Num(_) | Tok::Str(_) => Some(None),
                _ => None,
            };
            if let Some(sym) = known {
                self.last_span = span;
                return Ok(sym);
            }
        }
        if !self.ready()? {
            return Ok(None);
        }
        Ok(match self.current_token() {
            Some(Token {
                tok: Tok::Sym(s), ..
            }) => Some(*s),
            _ => None,
        })
    }

    /// The next symbol without executing directives: used for operator look-ahead, so that a
    /// directive after an expression (`#declare A = 1 #end`) ends the expression rather than
    /// running inside it.
    pub(super) fn raw_peek_sym(&mut self) -> PResult<Option<Sym>> {
        // Operator look-ahead runs at every precedence level for every operand; reading the
        // token in place spares the clone.
        if let Some(t) = self.current_token() {
            let (span, sym) = match t.tok {
                Tok::Sym(s) => (t.span, Some(s)),
                _ => (t.span, None),
            };
            let directive = matches!(t.tok, Tok::Directive(_));
            self.last_span = span;
            if !directive {
                return Ok(sym);
            }
        }
        loop {
            return Ok(match self.raw_peek()? {
                Some(Token {
                    tok: Tok::Sym(s), ..
                }) => Some(s),
                // In a macro body, the `#end` or `#else` of a conditional (which only closes it
                // or skips the untaken branch, never rewinds) is run in place as povray does, so
                // a macro whose value ends inside `#if ... #end` (arrays.inc's
                // Rand_Array_Item) can be followed by an operator. Elsewhere a directive ends
                // the expression first: `#declare A = 1 #end` before a loop rewinds, an
                // `#include "f" #end` before the file is entered.
                Some(Token {
                    tok: Tok::Directive(d),
                    span,
                }) if matches!(&*d, "end" | "else" | "elseif") && self.in_macro_if() => {
                    self.advance();
                    self.directive(&d, span)?;
                    continue;
                }
                _ => None,
            });
        }
    }

    /// Whether the innermost frame is a macro body inside one of its own `#if` branches.
    fn in_macro_if(&self) -> bool {
        let depth = self.frames.len() - 1;
        self.frames
            .last()
            .is_some_and(|f| f.kind == FrameKind::Macro)
            && matches!(self.conds.last(), Some(Cond::If { frame }) if *frame == depth)
    }

    pub(super) fn peek_ident(&mut self) -> PResult<Option<Rc<str>>> {
        Ok(self.peek_keyword()?.cloned())
    }

    /// The next token's identifier, read in place (`peek_ident` without the copy).
    pub(super) fn peek_keyword(&mut self) -> PResult<Option<&Rc<str>>> {
        if !self.ready()? {
            return Ok(None);
        }
        Ok(match self.current_token() {
            Some(Token {
                tok: Tok::Ident(s), ..
            }) => Some(s),
            _ => None,
        })
    }

    pub(super) fn eat_sym(&mut self, s: Sym) -> PResult<bool> {
        if self.peek_sym()? == Some(s) {
            self.advance();
            return Ok(true);
        }
        Ok(false)
    }

    pub(super) fn expect_sym(&mut self, s: Sym, context: &str) -> PResult<Span> {
        self.expect_sym_with(s, || context.to_string())
    }

    /// `expect_sym` with the context made only when it is needed.
    pub(super) fn expect_sym_with(
        &mut self,
        s: Sym,
        context: impl FnOnce() -> String,
    ) -> PResult<Span> {
        if self.peek_sym()? == Some(s) {
            // `peek_sym` left the symbol's span in `last_span`.
            let span = self.last_span;
            self.advance();
            return Ok(span);
        }
        let t = self.next_tok()?;
        if t.tok == Tok::Sym(s) {
            return Ok(t.span);
        }
        Err(self.error_at(
            t.span,
            format!("expected '{}' {}, found {}", s.text(), context(), t.tok),
        ))
    }

    pub(super) fn eat_keyword(&mut self, k: &str) -> PResult<bool> {
        if self.peek_keyword()?.is_some_and(|s| **s == *k) {
            self.advance();
            return Ok(true);
        }
        Ok(false)
    }

    pub(super) fn skip_optional_comma(&mut self) -> PResult<()> {
        self.eat_sym(Sym::Comma)?;
        Ok(())
    }

    pub fn lookup(&self, name: &str) -> Option<&Value> {
        if !self.deferred.borrow().is_empty() {
            if let Some(held) = self.deferred.borrow_mut().remove(name) {
                self.released.borrow_mut().extend(held);
            }
        }
        self.lookup_quiet(name)
    }

    /// `lookup` without counting as a use: `#ifdef`/`defined()` test a name, they do not use it.
    pub(super) fn lookup_quiet(&self, name: &str) -> Option<&Value> {
        match self.scopes.iter().rev().find_map(|s| s.get(name)) {
            Some(Value::Ref(r)) => self.value_at(r),
            v => v,
        }
    }

    /// An error at `span` with the include/macro chain of the current frames.
    pub fn error_at(&self, span: Span, message: impl Into<String>) -> Box<Diagnostic> {
        let mut d = Diagnostic::error(message, Some(span));
        d.chain = self.chain();
        Box::new(d)
    }

    fn chain(&self) -> Vec<ChainLink> {
        self.frames
            .iter()
            .rev()
            .filter_map(|f| f.call_site.as_ref())
            .map(|(span, what)| ChainLink {
                what: what.to_string(),
                span: *span,
            })
            .collect()
    }

    /// Warns once per place about a keyword lancer reads but does not render yet. Inside a
    /// declaration the warning waits until the identifier is used.
    pub fn unsupported(&mut self, keyword: &str, span: Span) {
        self.unsupported_warning(keyword, span, true);
    }

    /// Like `unsupported`, for a value computed now without the feature (a function lancer
    /// cannot evaluate gives 0): said at once, used or not.
    pub fn unsupported_now(&mut self, keyword: &str, span: Span) {
        self.unsupported_warning(keyword, span, false);
    }

    fn unsupported_warning(&mut self, keyword: &str, span: Span, deferrable: bool) {
        if self.warned.insert((keyword.into(), span)) {
            let mut d = Diagnostic::warning(format!("'{keyword}' is not supported by lancer yet and is ignored; the picture will differ from POV-Ray's"), Some(span));
            d.chain = self.chain();
            d.deferrable = deferrable;
            self.warnings.push(d);
        }
    }

    /// A warning at `span`, once: a macro called 400 times says it once, not 400 times.
    pub fn warn(&mut self, span: Span, message: impl Into<String>) {
        self.warn_with(span, message.into(), false);
    }

    /// `warn` about how a declared thing looks (a finish's `crand`, a light's `jitter`): held
    /// back, like "not supported" warnings, until the declaration is used. An include file's
    /// unused textures say nothing.
    pub fn warn_if_used(&mut self, span: Span, message: impl Into<String>) {
        self.warn_with(span, message.into(), true);
    }

    fn warn_with(&mut self, span: Span, message: String, deferrable: bool) {
        if !self.warned.insert((message.as_str().into(), span)) {
            return;
        }
        let mut d = Diagnostic::warning(message, Some(span));
        d.chain = self.chain();
        d.deferrable = deferrable;
        self.warnings.push(d);
    }

    /// Skips a balanced `{ ... }` block (used for blocks of unsupported features).
    pub(super) fn skip_block(&mut self) -> PResult<()> {
        let open = self.expect_sym(Sym::LBrace, "to open the block")?;
        let mut depth = 1;
        while depth > 0 {
            // Directives and macro calls inside still run, as in POV-Ray: braces may sit in
            // #if branches (shapes.inc's mesh2 macros), and declarations must happen.
            let Some(t) = self.peek()? else {
                return Err(self.error_at(open, "this '{' is never closed"));
            };
            self.advance();
            match t.tok {
                Tok::Sym(Sym::LBrace) => depth += 1,
                Tok::Sym(Sym::RBrace) => depth -= 1,
                _ => {}
            }
        }
        Ok(())
    }
}
