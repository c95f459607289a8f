//! Reading POV-Ray's implicit and field objects: `superellipsoid`, `blob`, `isosurface` and
//! `height_field` (the geometry is in `geom::superellipsoid`, `geom::blob`, ...).

use crate::scene::desc::{ObjectDesc, ShapeDesc};

use super::parser::{PResult, Parser};
use super::source::Span;

/// The exponent a superellipsoid gets instead of a zero, negative or non-finite one: small
/// enough to look like POV-Ray's sharp-edged box for tiny exponents.
const MIN_EXPONENT: f64 = 1e-5;

impl Parser {
    /// `superellipsoid { <e, n> modifiers }`.
    pub(super) fn superellipsoid(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("superellipsoid")?;
        let span = self.next_span()?;
        let v = self.parse_vector()?;
        let mut fix = |x: f64, which: &str| {
            if x > 0.0 && x.is_finite() {
                x
            } else {
                self.warn(
                    span,
                    format!("superellipsoid exponent {which} = {x} must be greater than zero; {MIN_EXPONENT} is used"),
                );
                MIN_EXPONENT
            }
        };
        let e = fix(v.x, "e");
        let n = fix(v.y, "n");
        self.finish_object(ObjectDesc::new(ShapeDesc::Superellipsoid { e, n }), open)
    }
}
