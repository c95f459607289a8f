//! Focal blur: many camera rays per pixel from points on a lens disc, all aimed at the point
//! where the pixel's own ray meets the plane of sharpness, averaged until the samples agree
//! (POV-Ray's `confidence` / `variance`) or `blur_samples` is reached.
//!
//! Measured with povray 3.7 (scripts/focal_blur_geometry.sh): the lens is a disc of radius
//! aperture / 4 in world units across the camera's unit right and up vectors, whatever the
//! lengths of right, up and direction; the plane of sharpness is perpendicular to the viewing
//! direction at the straight-line distance from the camera to `focal_point` (a focal point off
//! the axis puts the plane nearer than its depth along the axis); a point on that plane off
//! the axis is sharp. Each sample is also jittered within the pixel.
//!
//! POV-Ray draws its lens points from a Halton sequence; its pixels cannot be matched sample
//! for sample. lancer uses Halton points too, shifted per pixel by a hash of the pixel's
//! position (never thread state), so the picture is the same for any thread count or split.

use crate::math::{DVec3, Ray};
use crate::scene::focal::FocalDesc;

use super::camera::Camera;
use super::trace::{Seen, TraceCtx, Tracer};

/// The lens of a focal-blur camera, in world space.
#[derive(Clone, Debug)]
pub struct Lens {
    radius: f64,
    focal_dist: f64,
    right: DVec3,
    up: DVec3,
    forward: DVec3,
    min: u32,
    max: u32,
    /// Squared normal quantile of the confidence: how many standard errors must fit in the
    /// tolerance before sampling stops.
    z2: f64,
    variance: f64,
    bokeh: Option<Bokeh>,
}

impl Lens {
    /// The lens of a camera turned by `turn` (the preview window's camera moves).
    pub fn turned(&self, turn: impl Fn(DVec3) -> DVec3) -> Lens {
        Lens {
            right: turn(self.right),
            up: turn(self.up),
            forward: turn(self.forward),
            ..self.clone()
        }
    }

    /// The lens for a camera at `location` (before the camera's transforms, like
    /// `focal_point`) whose world-space axes are given.
    pub fn new(
        d: &FocalDesc,
        location: DVec3,
        right: DVec3,
        up: DVec3,
        dir: DVec3,
    ) -> Option<Lens> {
        if !d.active() {
            return None;
        }
        let z = normal_quantile(0.5 + 0.5 * d.confidence);
        Some(Lens {
            radius: d.aperture * 0.25,
            focal_dist: (d.focal_point - location).length(),
            right: right.normalize_or(DVec3::X),
            up: up.normalize_or(DVec3::Y),
            forward: dir.normalize_or(DVec3::Z),
            min: d.min(),
            max: d.max_samples.max(1),
            z2: z * z,
            variance: d.variance,
            bokeh: d.bokeh.as_deref().map(Bokeh::new),
        })
    }

    /// `straight` (the pinhole ray through a point of the pixel) from lens point (lx, ly) of
    /// the unit disc instead.
    fn bend(&self, straight: Ray, lx: f64, ly: f64) -> Ray {
        let along = straight.dir.dot(self.forward);
        if along <= 1e-12 {
            return straight;
        }
        let focus = straight.origin + straight.dir * (self.focal_dist / along);
        let origin = straight.origin + (self.right * lx + self.up * ly) * self.radius;
        let dir = (focus - origin).normalize_or(straight.dir) * straight.dir.length();
        Ray::new(origin, dir)
    }
}

/// The blurred colour at image position (px, py).
pub fn trace<'a>(
    tracer: &Tracer<'a>,
    cam: &Camera,
    lens: &Lens,
    px: f64,
    py: f64,
    ctx: &mut TraceCtx<'a>,
) -> Seen {
    let seed = mix(px.to_bits() ^ py.to_bits().rotate_left(29));
    let shift = [
        unit(mix(seed ^ 1)),
        unit(mix(seed ^ 2)),
        unit(mix(seed ^ 3)),
        unit(mix(seed ^ 4)),
    ];
    let mut sum = DVec3::ZERO;
    let mut sum2 = DVec3::ZERO;
    let mut clear = 0.0;
    let mut n = 0u32;
    for i in 1..=lens.max {
        let a = (halton(i, 2) + shift[0]).fract();
        let b = (halton(i, 3) + shift[1]).fract();
        let jx = (halton(i, 5) + shift[2]).fract() - 0.5;
        let jy = (halton(i, 7) + shift[3]).fract() - 0.5;
        let (lx, ly) = match &lens.bokeh {
            Some(bokeh) => bokeh.point(a, b),
            None => {
                // Uniform over the disc.
                let (r, phi) = (a.sqrt(), b * std::f64::consts::TAU);
                (r * phi.cos(), r * phi.sin())
            }
        };
        let ray = cam.ray(px + jx, py + jy).map(|s| lens.bend(s, lx, ly));
        let s = tracer.trace_camera(ray, ctx);
        sum += s.rgb;
        let c = s.rgb.clamp(DVec3::ZERO, DVec3::ONE);
        sum2 += c * c;
        clear += s.clear;
        n += 1;
        if n >= lens.min && n >= 2 && settled(lens, sum, sum2, n) {
            break;
        }
    }
    let k = 1.0 / n as f64;
    Seen {
        rgb: sum * k,
        clear: clear * k,
    }
}

/// A `bokeh` aperture: lens points drawn with density proportional to the pigment's
/// brightness (grey 0.297 r + 0.589 g + 0.114 b) over the unit square, which spans the round
/// lens's bounding square (measured with povray: a white bokeh blurs a point into a square as
/// wide as the round lens's disc; a point behind the plane of sharpness lit through pigment
/// x < 1/2 only blurs into the left half of its spot, through y > 1/2 the lower half: as
/// lens points with x < 0 and y < 0 do).
#[derive(Clone, Debug)]
struct Bokeh {
    /// Cumulative weight of the rows (y) up to and including each.
    rows: Vec<f64>,
    /// Per row, the cumulative weight of its cells (x) up to and including each.
    cells: Vec<f64>,
}

/// Cells per side of the grid the bokeh pigment is sampled on.
const BOKEH_GRID: usize = 64;

impl Bokeh {
    fn new(p: &crate::scene::desc::Pigment) -> Bokeh {
        let n = BOKEH_GRID;
        let mut cells = vec![0.0; n * n];
        let mut rows = vec![0.0; n];
        let mut total = 0.0;
        for j in 0..n {
            let mut acc = 0.0;
            for i in 0..n {
                let at = DVec3::new(
                    (i as f64 + 0.5) / n as f64,
                    (j as f64 + 0.5) / n as f64,
                    0.0,
                );
                let c = super::pigment::eval(p, at).rgb;
                acc += (0.297 * c.x + 0.589 * c.y + 0.114 * c.z).max(0.0);
                cells[j * n + i] = acc;
            }
            total += acc;
            rows[j] = total;
        }
        if total <= 0.0 {
            // A black bokeh lets no light through anywhere; POV-Ray's picture is then
            // undefined, so fall back to a uniform square.
            for j in 0..n {
                rows[j] = (j + 1) as f64;
                for i in 0..n {
                    cells[j * n + i] = (i + 1) as f64;
                }
            }
        }
        Bokeh { rows, cells }
    }

    /// The lens point (from -1 to 1 on each axis) for uniform numbers a, b in [0, 1).
    fn point(&self, a: f64, b: f64) -> (f64, f64) {
        let n = BOKEH_GRID;
        let (j, fy) = invert(&self.rows, a);
        let (i, fx) = invert(&self.cells[j * n..(j + 1) * n], b);
        let x = (i as f64 + fx) / n as f64;
        let y = (j as f64 + fy) / n as f64;
        (2.0 * x - 1.0, 1.0 - 2.0 * y)
    }
}

/// The cell of cumulative weights `cum` that uniform `u` falls in, and where inside it.
fn invert(cum: &[f64], u: f64) -> (usize, f64) {
    let total = *cum.last().unwrap_or(&1.0);
    let target = u * total;
    let k = cum.partition_point(|&c| c <= target).min(cum.len() - 1);
    let lo = if k == 0 { 0.0 } else { cum[k - 1] };
    let w = cum[k] - lo;
    let f = if w > 0.0 {
        ((target - lo) / w).clamp(0.0, 1.0)
    } else {
        0.5
    };
    (k, f)
}

/// Whether the mean of `n` samples is within the variance tolerance at the confidence asked:
/// z² · s² / n ≤ variance in every channel.
fn settled(lens: &Lens, sum: DVec3, sum2: DVec3, n: u32) -> bool {
    let nf = n as f64;
    let mean = (sum / nf).clamp(DVec3::ZERO, DVec3::ONE);
    let var = ((sum2 - mean * mean * nf) / (nf - 1.0)).max(DVec3::ZERO);
    (var * (lens.z2 / nf)).max_element() <= lens.variance
}

/// The radical inverse of `i` in base `b`.
fn halton(mut i: u32, b: u32) -> f64 {
    let mut f = 1.0;
    let mut r = 0.0;
    let inv = 1.0 / b as f64;
    while i > 0 {
        f *= inv;
        r += f * (i % b) as f64;
        i /= b;
    }
    r
}

fn mix(mut h: u64) -> u64 {
    h = h.wrapping_mul(0x9E37_79B9_7F4A_7C15);
    h ^= h >> 31;
    h = h.wrapping_mul(0xBF58_476D_1CE4_E5B9);
    h ^= h >> 29;
    h = h.wrapping_mul(0x94D0_49BB_1331_11EB);
    h ^ (h >> 32)
}

fn unit(h: u64) -> f64 {
    (h >> 11) as f64 / (1u64 << 53) as f64
}

/// The standard normal quantile at probability p in (0, 1), by bisection on the error function.
fn normal_quantile(p: f64) -> f64 {
    let p = p.clamp(1e-9, 1.0 - 1e-9);
    let (mut lo, mut hi) = (-10.0, 10.0);
    for _ in 0..80 {
        let mid = 0.5 * (lo + hi);
        if normal_cdf(mid) < p {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

fn normal_cdf(x: f64) -> f64 {
    0.5 * (1.0 + erf(x / std::f64::consts::SQRT_2))
}

/// Abramowitz and Stegun 7.1.26 (absolute error below 1.5e-7: plenty for a stopping rule).
fn erf(x: f64) -> f64 {
    let s = x.signum();
    let x = x.abs();
    let t = 1.0 / (1.0 + 0.327_591_1 * x);
    let y = 1.0
        - (((((1.061_405_429 * t - 1.453_152_027) * t) + 1.421_413_741) * t - 0.284_496_736) * t
            + 0.254_829_592)
            * t
            * (-x * x).exp();
    s * y
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quantile_of_ninety_percent_two_sided() {
        assert!((normal_quantile(0.95) - 1.6449).abs() < 1e-3);
        assert!(normal_quantile(0.5).abs() < 1e-6);
    }

    #[test]
    fn halton_base_two() {
        assert_eq!(halton(1, 2), 0.5);
        assert_eq!(halton(2, 2), 0.25);
        assert_eq!(halton(3, 2), 0.75);
    }

    #[test]
    fn focal_plane_point_is_sharp() {
        let d = FocalDesc {
            aperture: 4.0,
            max_samples: 10,
            focal_point: DVec3::new(0.0, 0.0, 5.0),
            ..FocalDesc::default()
        };
        let lens = Lens::new(&d, DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z).unwrap();
        let straight = Ray::new(DVec3::ZERO, DVec3::new(0.3, 0.1, 1.0));
        let target = straight.at(5.0);
        for (lx, ly) in [(1.0, 0.0), (0.0, -1.0), (0.6, 0.6)] {
            let r = lens.bend(straight, lx, ly);
            assert!((r.origin.length() - (lx * lx + ly * ly).sqrt()).abs() < 1e-12);
            let t = (target - r.origin).dot(r.dir) / r.dir.length_squared();
            assert!((r.at(t) - target).length() < 1e-9);
        }
    }
}
