//! Spline evaluation, shared by the scene language (`S(t [, type])`, read in `sdl::spline`)
//! and spline functions (`function { spline { ... } }`), which render threads may call.
//!
//! POV-Ray 3.7 knows linear_spline (the default), quadratic_spline, cubic_spline and
//! natural_spline here. The formulas below were fitted to POV-Ray 3.7.0's `#debug` output to
//! 1e-9 (see tests/sdl_lang.rs):
//! - linear: straight segments; before the first / after the last point, the end points.
//! - quadratic: on segment [t_i, t_i+1], the parabola through points i-1, i, i+1 (points 0, 1, 2
//!   on the first segment), in the knots' own spacing.
//! - cubic: Hermite segments whose tangent at a point is the mean of the slopes of the chords
//!   on either side; only valid from the second to the next-to-last point and held constant
//!   outside. With two points POV-Ray returns their midpoint everywhere.
//! - natural: the interpolating cubic spline with zero second derivative at both ends.
//!
//! Quadratic and natural splines with two points are linear. Points are sorted by parameter;
//! a repeated parameter replaces the earlier point. The result has as many components as the
//! longest vector given (2 to 5); a shorter vector takes its missing components from the point
//! written before it (zeros for the first), as POV-Ray's parser leaves them.

use std::sync::OnceLock;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SplineKind {
    Linear,
    Quadratic,
    Cubic,
    Natural,
}

impl SplineKind {
    pub fn from_keyword(k: &str) -> Option<SplineKind> {
        Some(match k {
            "linear_spline" => SplineKind::Linear,
            "quadratic_spline" => SplineKind::Quadratic,
            "cubic_spline" => SplineKind::Cubic,
            "natural_spline" => SplineKind::Natural,
            _ => return None,
        })
    }
}

#[derive(Debug)]
pub struct SplineDef {
    pub kind: SplineKind,
    /// Sorted by parameter, parameters distinct.
    pub points: Vec<(f64, [f64; 5])>,
    /// Components of the result, 2 to 5.
    pub dim: u8,
    /// The natural spline's second derivatives at each point, solved once on first use (a
    /// camera path is evaluated once per frame, a #while may evaluate it thousands of times).
    natural_m: OnceLock<Vec<P>>,
}

impl Clone for SplineDef {
    /// A copy (`spline { S ... }`) may get more points, so the solved system stays behind.
    fn clone(&self) -> Self {
        SplineDef {
            kind: self.kind,
            points: self.points.clone(),
            dim: self.dim,
            natural_m: OnceLock::new(),
        }
    }
}

type P = [f64; 5];

fn lerp(a: &P, b: &P, s: f64) -> P {
    std::array::from_fn(|k| a[k] + (b[k] - a[k]) * s)
}

impl SplineDef {
    /// A spline of `kind` without points; `dim` starts at 2, the fewest components a result has.
    pub fn new(kind: SplineKind) -> SplineDef {
        SplineDef {
            kind,
            points: Vec::new(),
            dim: 2,
            natural_m: OnceLock::new(),
        }
    }

    /// Adds a point, replacing one with the same parameter.
    pub fn insert(&mut self, t: f64, v: P, n: u8) {
        self.natural_m = OnceLock::new();
        self.dim = self.dim.max(n);
        match self.points.binary_search_by(|p| p.0.total_cmp(&t)) {
            Ok(i) => self.points[i].1 = v,
            Err(i) => self.points.insert(i, (t, v)),
        }
    }

    /// The segment `i` with t_i <= t < t_i+1, limited to `lo..=hi`.
    fn segment(&self, t: f64, lo: usize, hi: usize) -> usize {
        let i = self.points.partition_point(|p| p.0 <= t);
        i.saturating_sub(1).clamp(lo, hi)
    }

    pub fn eval(&self, t: f64, kind: SplineKind) -> P {
        let pts = &self.points;
        let n = pts.len();
        if n == 0 {
            return [0.0; 5];
        }
        if n == 1 {
            return pts[0].1;
        }
        if kind == SplineKind::Cubic {
            return self.cubic(t);
        }
        if t <= pts[0].0 {
            return pts[0].1;
        }
        if t >= pts[n - 1].0 {
            return pts[n - 1].1;
        }
        let i = self.segment(t, 0, n - 2);
        match kind {
            _ if n == 2 => linear_in(pts, i, t),
            SplineKind::Linear => linear_in(pts, i, t),
            SplineKind::Quadratic => {
                let a = i.saturating_sub(1).min(n - 3);
                let idx = [a, a + 1, a + 2];
                let mut out = [0.0; 5];
                for &j in &idx {
                    let mut l = 1.0;
                    for &k in &idx {
                        if k != j {
                            l *= (t - pts[k].0) / (pts[j].0 - pts[k].0);
                        }
                    }
                    for (o, p) in out.iter_mut().zip(pts[j].1) {
                        *o += l * p;
                    }
                }
                out
            }
            SplineKind::Natural => {
                let m = self
                    .natural_m
                    .get_or_init(|| natural_second_derivatives(pts));
                natural(pts, m, i, t)
            }
            SplineKind::Cubic => unreachable!("handled above"),
        }
    }

    fn cubic(&self, t: f64) -> P {
        let pts = &self.points;
        let n = pts.len();
        if n == 2 {
            return lerp(&pts[0].1, &pts[1].1, 0.5);
        }
        if t <= pts[1].0 {
            return pts[1].1;
        }
        if t >= pts[n - 2].0 {
            return pts[n - 2].1;
        }
        let i = self.segment(t, 1, n - 3);
        let slope = |a: usize, b: usize| -> P {
            std::array::from_fn(|k| (pts[b].1[k] - pts[a].1[k]) / (pts[b].0 - pts[a].0))
        };
        let tangent = |j: usize| -> P {
            let (l, r) = (slope(j - 1, j), slope(j, j + 1));
            std::array::from_fn(|k| 0.5 * (l[k] + r[k]))
        };
        let (m0, m1) = (tangent(i), tangent(i + 1));
        let h = pts[i + 1].0 - pts[i].0;
        let s = (t - pts[i].0) / h;
        let (s2, s3) = (s * s, s * s * s);
        let h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
        let h10 = s3 - 2.0 * s2 + s;
        let h01 = -2.0 * s3 + 3.0 * s2;
        let h11 = s3 - s2;
        std::array::from_fn(|k| {
            h00 * pts[i].1[k] + h10 * h * m0[k] + h01 * pts[i + 1].1[k] + h11 * h * m1[k]
        })
    }
}

fn linear_in(pts: &[(f64, P)], i: usize, t: f64) -> P {
    let s = (t - pts[i].0) / (pts[i + 1].0 - pts[i].0);
    lerp(&pts[i].1, &pts[i + 1].1, s)
}

/// The natural cubic spline's second derivatives at every point: the tridiagonal system with
/// zero end conditions, solved per component (Thomas algorithm).
fn natural_second_derivatives(pts: &[(f64, P)]) -> Vec<P> {
    let n = pts.len();
    let mut mm = vec![[0.0; 5]; n];
    if n < 3 {
        return mm;
    }
    let h: Vec<f64> = (0..n - 1).map(|j| pts[j + 1].0 - pts[j].0).collect();
    // Unknowns M_1..M_{n-2}; M_0 = M_{n-1} = 0.
    let m = n - 2;
    let (mut diag, mut rhs) = (vec![0.0; m], vec![0.0; m]);
    // `k` is a component index into every point's array, not a walk over one slice.
    #[allow(clippy::needless_range_loop)]
    for k in 0..5 {
        let y = |j: usize| pts[j].1[k];
        for r in 0..m {
            let j = r + 1;
            diag[r] = 2.0 * (h[j - 1] + h[j]);
            rhs[r] = 6.0 * ((y(j + 1) - y(j)) / h[j] - (y(j) - y(j - 1)) / h[j - 1]);
        }
        // Sub-diagonal h[r] (row r+1), super-diagonal h[r+1] (row r).
        for r in 1..m {
            let w = h[r] / diag[r - 1];
            diag[r] -= w * h[r];
            rhs[r] -= w * rhs[r - 1];
        }
        for r in (0..m).rev() {
            let next = if r + 1 < m { mm[r + 2][k] } else { 0.0 };
            mm[r + 1][k] = (rhs[r] - h[r + 1] * next) / diag[r];
        }
    }
    mm
}

/// The natural cubic spline on segment `i`, from the second derivatives `mm`.
fn natural(pts: &[(f64, P)], mm: &[P], i: usize, t: f64) -> P {
    let (a, b) = (pts[i].0, pts[i + 1].0);
    let hi = b - a;
    let (da, db) = (b - t, t - a);
    std::array::from_fn(|k| {
        let (y0, y1) = (pts[i].1[k], pts[i + 1].1[k]);
        let (m0, m1) = (mm[i][k], mm[i + 1][k]);
        m0 * da.powi(3) / (6.0 * hi)
            + m1 * db.powi(3) / (6.0 * hi)
            + (y0 / hi - m0 * hi / 6.0) * da
            + (y1 / hi - m1 * hi / 6.0) * db
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spline(kind: SplineKind, pts: &[(f64, f64)]) -> SplineDef {
        let mut s = SplineDef::new(kind);
        for &(t, x) in pts {
            s.insert(t, [x, 0.0, 0.0, 0.0, 0.0], 2);
        }
        s
    }

    #[test]
    fn natural_spline_through_a_line_is_the_line() {
        let s = spline(SplineKind::Natural, &[(0.0, 0.0), (1.0, 2.0), (3.0, 6.0)]);
        assert!((s.eval(2.0, SplineKind::Natural)[0] - 4.0).abs() < 1e-12);
    }

    #[test]
    fn duplicates_replace_and_points_sort() {
        let s = spline(SplineKind::Linear, &[(3.0, 3.0), (1.0, 1.0), (1.0, 5.0)]);
        assert_eq!(s.points.len(), 2);
        assert_eq!(s.eval(0.0, SplineKind::Linear)[0], 5.0);
        assert_eq!(s.eval(2.0, SplineKind::Linear)[0], 4.0);
    }

    #[test]
    fn quadratic_reproduces_a_parabola() {
        let s = spline(
            SplineKind::Quadratic,
            &[(0.0, 0.0), (1.0, 1.0), (2.5, 6.25), (4.0, 16.0)],
        );
        for t in [0.3, 1.7, 3.2] {
            assert!((s.eval(t, SplineKind::Quadratic)[0] - t * t).abs() < 1e-12);
        }
    }
}
