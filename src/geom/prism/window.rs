//! Per-ray prunes of a prism's outline pieces: which pieces can hold a wall crossing the
//! heights keep (`Window`), and the `t` a linear sweep's crossing must have (`Keep`).

use super::Prism;
use crate::geom::spline2d::{Piece, P2};
use crate::math::DVec3;

/// The `t` a linear sweep's wall crossing must have for the caller: within `[lo, hi]` and
/// below `before`; `inv_dd` as in `Prism::wall_t_range`.
#[derive(Clone, Copy)]
pub(super) struct Keep {
    pub(super) lo: f64,
    pub(super) hi: f64,
    pub(super) before: f64,
    pub(super) inv_dd: f64,
}

/// Which outline pieces can hold a wall crossing that `wall_t` keeps (within the heights),
/// for one ray: a cheap test before the crossings are solved and refined.
pub(super) enum Window {
    All,
    /// Linear sweep: the piece's range of `t` (`Prism::wall_t_range`) must meet the
    /// heights' (`Prism::height_t_range`).
    Linear {
        o: DVec3,
        d: DVec3,
        inv_dd: f64,
        y_lo: f64,
        y_hi: f64,
    },
    /// Conic sweep: the piece's box must meet the box of the ray's stretch between the
    /// heights projected onto the outline's plane (widened for rounding).
    Conic {
        lo: P2,
        hi: P2,
    },
}

impl Window {
    /// The crossings a linear sweep keeps: those within the heights.
    pub(super) fn keep(&self) -> Option<Keep> {
        match *self {
            Window::Linear {
                inv_dd, y_lo, y_hi, ..
            } => Some(Keep {
                lo: y_lo,
                hi: y_hi,
                before: f64::INFINITY,
                inv_dd,
            }),
            _ => None,
        }
    }

    pub(super) fn may_hold(&self, pc: &Piece) -> bool {
        match *self {
            Window::All => true,
            Window::Linear {
                o,
                d,
                inv_dd,
                y_lo,
                y_hi,
            } => {
                let (floor, ceil) = Prism::wall_t_range(pc, o, d, inv_dd);
                !(floor > y_hi || ceil < y_lo)
            }
            Window::Conic { lo, hi } => {
                !(pc.hi[0] < lo[0] || pc.lo[0] > hi[0] || pc.hi[1] < lo[1] || pc.lo[1] > hi[1])
            }
        }
    }
}
