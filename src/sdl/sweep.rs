//! Reading POV-Ray's spline-swept objects and polygons: `prism`, `lathe`, `sor`, `polygon`
//! and `sphere_sweep`, with POV-Ray's refusals (too few points, unclosed outlines) as errors
//! at the object and its warnings where POV-Ray warns.

use std::sync::Arc;

use crate::geom::lathe::{profile, Lathe};
use crate::geom::polygon::{edges, Polygon};
use crate::geom::prism::{outline, Prism};
use crate::geom::sor::{check, Sor};
use crate::geom::sphere_sweep::{SphereSweep, SweepKind};
use crate::geom::spline2d::{SplineKind, P2};
use crate::geom::Shape;
use crate::math::DVec3;
use crate::scene::desc::{ObjectDesc, ShapeDesc};

use super::parser::{PResult, Parser};
use super::source::Span;

fn spline_kind(k: &str) -> Option<SplineKind> {
    Some(match k {
        "linear_spline" => SplineKind::Linear,
        "quadratic_spline" => SplineKind::Quadratic,
        "cubic_spline" => SplineKind::Cubic,
        "bezier_spline" => SplineKind::Bezier,
        _ => return None,
    })
}

impl Parser {
    /// `N, <p1>, <p2>, ...`: the count and that many vectors, commas optional.
    fn point_list(&mut self) -> PResult<Vec<DVec3>> {
        let n = self.parse_float()?;
        let n = if n.is_finite() && n > 0.0 {
            n as usize
        } else {
            0
        };
        let mut v = Vec::with_capacity(n.min(1 << 16));
        for _ in 0..n {
            self.skip_optional_comma()?;
            v.push(self.parse_vector()?);
        }
        Ok(v)
    }

    fn flat_points(&mut self) -> PResult<Vec<P2>> {
        Ok(self.point_list()?.iter().map(|p| [p.x, p.y]).collect())
    }

    /// The keywords that may follow the points: `open` (where allowed) and `sturm`.
    fn sweep_flags(&mut self, allow_open: bool) -> PResult<bool> {
        let mut open = false;
        while let Some(k) = self.peek_ident()? {
            match &*k {
                "open" if allow_open => open = true,
                // lancer's root isolation already finds every crossing POV-Ray's Sturm
                // solver is there to rescue.
                "sturm" => {}
                _ => break,
            }
            self.advance();
            if &*k == "sturm" {
                self.optional_bool()?;
            }
        }
        Ok(open)
    }

    pub(super) fn prism(&mut self, span: Span) -> PResult<ObjectDesc> {
        let open_b = self.open_brace("prism")?;
        let (mut kind, mut conic) = (SplineKind::Linear, false);
        while let Some(k) = self.peek_ident()? {
            if let Some(s) = spline_kind(&k) {
                kind = s;
            } else if &*k == "linear_sweep" || &*k == "conic_sweep" {
                conic = &*k == "conic_sweep";
            } else {
                break;
            }
            self.advance();
        }
        let h1 = self.parse_float()?;
        self.skip_optional_comma()?;
        let h2 = self.parse_float()?;
        self.skip_optional_comma()?;
        let points = self.flat_points()?;
        let o = outline(kind, &points).map_err(|e| self.error_at(span, e))?;
        if let Some(w) = o.warning {
            self.warn(span, w);
        }
        let open = self.sweep_flags(true)?;
        let shape = Prism::new(o.pieces, h1, h2, conic, open);
        self.finish_object(ObjectDesc::new(ShapeDesc::Prism(Arc::new(shape))), open_b)
    }

    pub(super) fn lathe(&mut self, span: Span) -> PResult<ObjectDesc> {
        let open_b = self.open_brace("lathe")?;
        let mut kind = SplineKind::Linear;
        while let Some(s) = self.peek_ident()?.and_then(|k| spline_kind(&k)) {
            kind = s;
            self.advance();
        }
        let points = self.flat_points()?;
        let pieces = profile(kind, &points).map_err(|e| self.error_at(span, e))?;
        self.sweep_flags(false)?;
        let shape = Lathe::new(pieces);
        self.finish_object(ObjectDesc::new(ShapeDesc::Lathe(Arc::new(shape))), open_b)
    }

    pub(super) fn sor(&mut self, span: Span) -> PResult<ObjectDesc> {
        let open_b = self.open_brace("sor")?;
        let points = self.flat_points()?;
        check(&points).map_err(|e| self.error_at(span, e))?;
        let open = self.sweep_flags(true)?;
        let shape = Sor::new(&points, open);
        self.finish_object(ObjectDesc::new(ShapeDesc::Sor(Arc::new(shape))), open_b)
    }

    pub(super) fn polygon(&mut self, span: Span) -> PResult<ObjectDesc> {
        let open_b = self.open_brace("polygon")?;
        let points = self.point_list()?;
        if points.len() < 3 {
            return Err(self.error_at(span, "Polygon needs at least three points."));
        }
        let (e, closed) = edges(&points);
        if closed {
            self.warn(span, "Polygon not closed. Closing it.");
        }
        let shape = Polygon::new(&e);
        if shape.bounds().is_empty() {
            self.warn(
                span,
                "the polygon's points are not all in one plane (or all on one line); \
                 POV-Ray draws nothing for it",
            );
        }
        self.finish_object(ObjectDesc::new(ShapeDesc::Polygon(Arc::new(shape))), open_b)
    }

    /// `sphere_sweep { linear_spline | b_spline | cubic_spline N, <c>, r, ... [tolerance t] }`.
    pub(super) fn sphere_sweep(&mut self, span: Span) -> PResult<ObjectDesc> {
        let open_b = self.open_brace("sphere_sweep")?;
        let kind_span = self.next_span()?;
        let kind = match self.peek_ident()?.as_deref() {
            Some("linear_spline") => SweepKind::Linear,
            Some("b_spline") => SweepKind::BSpline,
            Some("cubic_spline") => SweepKind::CatmullRom,
            _ => {
                return Err(self.error_at(
                    kind_span,
                    "sphere_sweep needs linear_spline, b_spline or cubic_spline first",
                ))
            }
        };
        self.advance();
        let n = self.parse_float()?;
        let n = if n.is_finite() && n > 0.0 {
            n as usize
        } else {
            0
        };
        let mut spheres = Vec::with_capacity(n.min(1 << 16));
        for _ in 0..n {
            self.skip_optional_comma()?;
            let c = self.parse_vector()?;
            self.skip_optional_comma()?;
            let r = self.parse_float()?;
            spheres.push((c, r));
        }
        let need = if kind == SweepKind::Linear { 2 } else { 4 };
        if spheres.len() < need {
            return Err(self.error_at(
                span,
                "Too few modeling spheres for interpolation type (linear_spline needs two, \
                 b_spline and cubic_spline four).",
            ));
        }
        self.skip_optional_comma()?;
        if self.eat_keyword("tolerance")? {
            self.parse_float()?;
        }
        let shape = SphereSweep::new(kind, &spheres);
        self.finish_object(
            ObjectDesc::new(ShapeDesc::SphereSweep(Arc::new(shape))),
            open_b,
        )
    }
}
