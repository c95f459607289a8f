//! Limits that turn runaway scenes into clear errors instead of hangs or exhausted memory.
//!
//! POV-Ray 3.7.0 stops at 31 nested include files ("Too many nested include files") and at
//! about 56 nested macro calls ("Too many nested symbol tables"); lancer stops includes at the
//! same depth and macro calls later (see parser.rs `MAX_FRAME_DEPTH`), so every scene POV-Ray
//! accepts still parses. Loops are unbounded unless `ParseOptions::max_loop_iterations` is set.
//! Array and string sizes are bounded in array.rs and strings.rs.

use super::parser::{FrameKind, PResult, Parser};
use super::source::Span;

/// Include files open at once, not counting the scene file (POV-Ray's limit).
pub const MAX_INCLUDE_DEPTH: usize = 31;

impl Parser {
    /// Called before entering another include file.
    pub(super) fn check_include_depth(&self, site: Span) -> PResult<()> {
        let open = self
            .frames
            .iter()
            .filter(|f| f.kind == FrameKind::Include)
            .count();
        if open >= MAX_INCLUDE_DEPTH {
            return Err(self.error_at(
                site,
                format!("too many nested include files (more than {MAX_INCLUDE_DEPTH}, POV-Ray's limit too): does an include file include itself?"),
            ));
        }
        Ok(())
    }

    /// Called each time a `#while` or `#for` loop goes round again.
    pub(super) fn count_loop_iteration(&mut self, span: Span) -> PResult<()> {
        self.loop_iterations += 1;
        match self.options.max_loop_iterations {
            Some(max) if self.loop_iterations > max => Err(self.error_at(
                span,
                format!("more than {max} #while/#for iterations in this parse (the configured limit); is this loop's condition ever false?"),
            )),
            _ => Ok(()),
        }
    }
}
