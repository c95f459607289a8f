//! Reading POV-Ray's algebraic surfaces: `quadric`, `cubic`, `quartic`, `poly` and
//! `polynomial`, all into one term list (see `geom::algebraic`).

use crate::geom::algebraic::{pov_term_order, MAX_ORDER};
use crate::scene::desc::{ObjectDesc, ShapeDesc};

use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};
use super::source::Span;

impl Parser {
    /// `quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }`: Ax² + By² + Cz² + Dxy + Exz + Fyz + Gx +
    /// Hy + Iz + J.
    pub(super) fn quadric(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("quadric")?;
        let a = self.parse_vector()?;
        self.skip_optional_comma()?;
        let b = self.parse_vector()?;
        self.skip_optional_comma()?;
        let c = self.parse_vector()?;
        self.skip_optional_comma()?;
        let j = self.parse_float()?;
        let terms = vec![
            ([2, 0, 0], a.x),
            ([0, 2, 0], a.y),
            ([0, 0, 2], a.z),
            ([1, 1, 0], b.x),
            ([1, 0, 1], b.y),
            ([0, 1, 1], b.z),
            ([1, 0, 0], c.x),
            ([0, 1, 0], c.y),
            ([0, 0, 1], c.z),
            ([0, 0, 0], j),
        ];
        self.algebraic(2, terms, open)
    }

    /// `cubic { <A1..A20> }` and `quartic { <A1..A35> }`.
    pub(super) fn poly_fixed(&mut self, order: usize, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace(if order == 3 { "cubic" } else { "quartic" })?;
        self.poly_coefficients(order, open)
    }

    /// `poly { Order, <A1..An> }`.
    pub(super) fn poly(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("poly")?;
        let order = self.poly_order()?;
        self.skip_optional_comma()?;
        self.poly_coefficients(order, open)
    }

    /// `polynomial { Order, xyz(i,j,k):value, ... }`: a later term with the same powers
    /// replaces an earlier one.
    pub(super) fn polynomial(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("polynomial")?;
        let order = self.poly_order()?;
        self.skip_optional_comma()?;
        let mut terms: Vec<([u8; 3], f64)> = Vec::new();
        while self.peek_ident()?.as_deref() == Some("xyz") {
            let span = self.next_span()?;
            self.advance();
            self.expect_sym(Sym::LParen, "after 'xyz'")?;
            let mut pw = [0u8; 3];
            for (i, p) in pw.iter_mut().enumerate() {
                if i > 0 {
                    self.expect_sym(Sym::Comma, "between the powers of xyz(...)")?;
                }
                let v = self.parse_float()?;
                if !(0.0..=order as f64).contains(&v) {
                    return Err(self.error_at(
                        span,
                        format!("xyz power {v} is outside 0..{order} for this polynomial"),
                    ));
                }
                *p = v as u8;
            }
            self.expect_sym(Sym::RParen, "to close xyz(...)")?;
            self.expect_sym(Sym::Colon, "after xyz(...)")?;
            let c = self.parse_float()?;
            self.skip_optional_comma()?;
            terms.retain(|(p, _)| *p != pw);
            terms.push((pw, c));
        }
        self.algebraic(order, terms, open)
    }

    fn poly_order(&mut self) -> PResult<usize> {
        let span = self.next_span()?;
        let v = self.parse_float()?;
        if !(2.0..=MAX_ORDER as f64).contains(&v) {
            return Err(self.error_at(
                span,
                format!("the order of a poly must be 2 to {MAX_ORDER} (POV-Ray allows up to 35; lancer stops at {MAX_ORDER}), not {v}"),
            ));
        }
        Ok(v as usize)
    }

    /// `<A1, A2, ...>` with exactly as many coefficients as the order has terms.
    fn poly_coefficients(&mut self, order: usize, open: Span) -> PResult<ObjectDesc> {
        let order_terms = pov_term_order(order);
        let span = self.next_span()?;
        self.expect_sym(Sym::Lt, "to start the coefficient list")?;
        let mut coeffs = Vec::with_capacity(order_terms.len());
        loop {
            if matches!(self.peek()?.map(|t| t.tok), Some(Tok::Sym(Sym::Gt))) {
                self.advance();
                break;
            }
            coeffs.push(self.parse_float()?);
            self.skip_optional_comma()?;
        }
        if coeffs.len() != order_terms.len() {
            return Err(self.error_at(
                span,
                format!(
                    "an order-{order} polynomial needs {} coefficients, this list has {}",
                    order_terms.len(),
                    coeffs.len()
                ),
            ));
        }
        let terms = order_terms.into_iter().zip(coeffs).collect();
        self.algebraic(order, terms, open)
    }

    fn algebraic(
        &mut self,
        order: usize,
        terms: Vec<([u8; 3], f64)>,
        open: Span,
    ) -> PResult<ObjectDesc> {
        let obj = ObjectDesc::new(ShapeDesc::Algebraic {
            order,
            terms,
            sturm: false,
        });
        self.finish_object(obj, open)
    }
}
