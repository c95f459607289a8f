//! Horizontal bands over a glyph's outline pieces, so that a point-in-glyph test and a ray's
//! side-wall search look only at the pieces whose height range can matter.
//!
//! A glyph has tens of pieces (cyrvetic's digits about forty), and `Glyph::contains` asked every
//! one of them for its winding number at every cap crossing: that loop was most of a text
//! object's cost. Each band keeps a bit set of the pieces whose y range meets it; a query takes
//! the union of its bands' sets and visits the set bits in ascending order, which is the order
//! of the piece list, each piece once. The answers are unchanged: a piece outside the visited
//! bands is one the full scan would have skipped (its y range misses the query's), and the
//! pieces that are visited are visited in the same order, so sums and first-found ties are the
//! same.
//!
//! Band membership uses one monotone function of y (`band`), for the pieces' ranges when the
//! index is built and for the queries: `y0 <= y1` gives `band(y0) <= band(y1)` whatever the
//! rounding, so a piece whose range [min, max] meets the query's [y0, y1] has a band range that
//! meets the query's band range.

use super::font::Piece;

/// Most bands a glyph gets; a piece set per band is one 64-bit word for up to 64 pieces.
const MAX_BANDS: usize = 32;

/// The band index of one glyph. `Default` (no bands) means "no index": queries visit every
/// piece.
#[derive(Clone, Debug, Default)]
pub struct Bands {
    /// Bottom of the lowest band.
    lo: f64,
    /// Bands per unit of height.
    scale: f64,
    count: usize,
    /// Words per band's bit set.
    words: usize,
    /// `count` bit sets of `words` words each, band after band.
    bits: Vec<u64>,
}

impl Bands {
    /// The index of `pieces`, whose y values lie within [lo, hi].
    pub fn new(pieces: &[Piece], lo: f64, hi: f64) -> Bands {
        let height = hi - lo;
        let count = if height > 0.0 && height.is_finite() {
            (pieces.len() / 2).clamp(1, MAX_BANDS)
        } else {
            1
        };
        let words = pieces.len().div_ceil(64);
        let mut b = Bands {
            lo,
            scale: if count > 1 {
                count as f64 / height
            } else {
                0.0
            },
            count,
            words,
            bits: vec![0; count * words],
        };
        for (i, p) in pieces.iter().enumerate() {
            let (b0, b1) = (b.band(p.min.y), b.band(p.max.y));
            for band in b0..=b1 {
                b.bits[band * words + i / 64] |= 1 << (i % 64);
            }
        }
        b
    }

    /// The band holding height `y`: non-decreasing in y, clamped to the bands (NaN gives the
    /// lowest; callers treat NaN queries apart).
    #[inline]
    fn band(&self, y: f64) -> usize {
        if self.count <= 1 {
            return 0;
        }
        let f = ((y - self.lo) * self.scale).floor();
        if f >= (self.count - 1) as f64 {
            self.count - 1
        } else if f > 0.0 {
            f as usize
        } else {
            0
        }
    }

    /// Calls `f` with the index of every piece of the `n` pieces that may meet heights
    /// [y0, y1], ascending, each once: every piece whose y range meets [y0, y1] is among them.
    /// Without an index, or for a NaN bound, every piece.
    #[inline]
    pub fn each_in(&self, n: usize, y0: f64, y1: f64, mut f: impl FnMut(usize)) {
        if self.count == 0 || y0.is_nan() || y1.is_nan() {
            (0..n).for_each(f);
            return;
        }
        let (b0, b1) = (self.band(y0), self.band(y1));
        for w in 0..self.words {
            let mut m = 0u64;
            for band in b0..=b1 {
                m |= self.bits[band * self.words + w];
            }
            while m != 0 {
                f(w * 64 + m.trailing_zeros() as usize);
                m &= m - 1;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::test_rng::Lcg;
    use glam::DVec2;

    fn piece(y0: f64, y1: f64) -> Piece {
        let (a, b) = (DVec2::new(0.0, y0), DVec2::new(1.0, y1));
        Piece {
            p0: a,
            c: (a + b) * 0.5,
            p1: b,
            min: a.min(b),
            max: a.max(b),
        }
    }

    #[test]
    fn visits_every_piece_a_full_scan_keeps_in_order() {
        let mut rng = Lcg(7);
        let mut range = |lo: f64, hi: f64| lo + (hi - lo) * rng.next();
        for n in [1usize, 3, 40, 64, 65, 150] {
            let pieces: Vec<Piece> = (0..n)
                .map(|_| piece(range(-1.0, 2.0), range(-1.0, 2.0)))
                .collect();
            let lo = pieces.iter().map(|p| p.min.y).fold(f64::INFINITY, f64::min);
            let hi = pieces
                .iter()
                .map(|p| p.max.y)
                .fold(f64::NEG_INFINITY, f64::max);
            let bands = Bands::new(&pieces, lo, hi);
            for _ in 0..500 {
                let a = range(-1.5, 2.5);
                let (y0, y1) = if range(0.0, 1.0) < 0.5 {
                    (a, a)
                } else {
                    let b = range(-1.5, 2.5);
                    (a.min(b), a.max(b))
                };
                let mut seen = Vec::new();
                bands.each_in(n, y0, y1, |i| seen.push(i));
                assert!(seen.windows(2).all(|w| w[0] < w[1]), "ascending, each once");
                for (i, p) in pieces.iter().enumerate() {
                    if p.max.y >= y0 && p.min.y <= y1 {
                        assert!(
                            seen.contains(&i),
                            "piece {i} [{}, {}] for [{y0}, {y1}]",
                            p.min.y,
                            p.max.y
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn flat_glyphs_nan_and_no_index_visit_everything() {
        let pieces = vec![piece(0.5, 0.5), piece(0.5, 0.5), piece(0.5, 0.5)];
        let flat = Bands::new(&pieces, 0.5, 0.5);
        let mut seen = Vec::new();
        flat.each_in(3, 0.5, 0.5, |i| seen.push(i));
        assert_eq!(seen, [0, 1, 2]);
        let tall = Bands::new(
            &[
                piece(0.0, 1.0),
                piece(0.0, 0.1),
                piece(0.9, 1.0),
                piece(0.0, 0.1),
            ],
            0.0,
            1.0,
        );
        seen.clear();
        tall.each_in(4, f64::NAN, 0.5, |i| seen.push(i));
        assert_eq!(seen, [0, 1, 2, 3]);
        seen.clear();
        Bands::default().each_in(2, 0.0, 0.0, |i| seen.push(i));
        assert_eq!(seen, [0, 1]);
        seen.clear();
        tall.each_in(4, 0.95, f64::INFINITY, |i| seen.push(i));
        assert_eq!(seen, [0, 2]);
    }
}
