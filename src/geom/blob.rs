//! POV-Ray `blob`: the surface where a sum of component fields equals the threshold.
//!
//! Each component (a sphere, or a cylinder with hemispherical caps, possibly transformed on
//! its own) adds `strength · (1 − d²/r²)²` within radius `r` of its centre or axis, nothing
//! beyond. Along a ray d² is a quadratic in the ray parameter, so each component's field is a
//! quartic on the stretch of the ray inside it (a cylinder gives up to three: cap, body, cap,
//! cut where the ray crosses the planes through the ends). The ray is cut at every place a
//! component's stretch starts or ends; between two cuts the field is one quartic, the sum of
//! the components present, and its roots at the threshold are the crossings. Strengths may be
//! negative (components that dent the others).
//!
//! The crossings are computed from the ray's entry into the first component it meets and with
//! a unit direction, so the quartics are never evaluated far from where they matter (as for
//! the torus). A bounding-volume hierarchy over the components keeps blobs with many
//! components fast.

use std::cell::RefCell;

use crate::geom::bernstein::surely_no_root;
use crate::geom::bvh::Bvh;
use crate::geom::poly::{first_root_in, first_root_with, roots_in, sturm_roots_in, Candidate};
use crate::geom::{Hit, Shape};
use crate::math::{Aabb, DMat4, DVec3, Ray, Transform, EPSILON};

/// The `Hit::part` of blob crossings. The renderer shades a blob whose components have textures
/// once per component reaching the hit, setting `part` to the component; a crossing still
/// carrying this value (a shadow ray's) takes the blob's own texture.
pub const PART_BLENDED: u32 = u32::MAX;

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ComponentKind {
    Sphere {
        center: DVec3,
    },
    /// From `a` to `b`, with hemispherical caps.
    Cylinder {
        a: DVec3,
        b: DVec3,
    },
}

/// One blob component as written.
#[derive(Clone, Copy, Debug)]
pub struct Component {
    pub kind: ComponentKind,
    pub radius: f64,
    pub strength: f64,
    /// Component space to blob space (the component's own transforms).
    pub transform: Transform,
}

/// The blob as the parser reads it; shared by every copy of a `#declare`d blob.
#[derive(Clone, Debug)]
pub struct BlobData {
    pub components: Vec<Component>,
    pub threshold: f64,
    pub sturm: bool,
}

/// A component prepared for tracing: in its own space, the field depends only on the squared
/// distance to a point or a segment.
#[derive(Clone, Copy, Debug)]
struct Prepared {
    /// Segment start (the centre for spheres), unit axis and length (0 for spheres).
    a: DVec3,
    axis: DVec3,
    len: f64,
    r2: f64,
    /// `1 / r2`, the same quotient `push` formed for every stretch.
    inv_r2: f64,
    strength: f64,
    /// None when the component has no transform of its own.
    transform: Option<Transform>,
    /// Position in `BlobData::components`, which per-component textures are indexed by.
    index: usize,
}

impl Prepared {
    fn local_point(&self, p: DVec3) -> DVec3 {
        self.transform.map_or(p, |t| t.inv_point(p))
    }

    /// Vector from the nearest point of the segment to the local point `q`.
    fn offset(&self, q: DVec3) -> DVec3 {
        let d = q - self.a;
        if self.len == 0.0 {
            return d;
        }
        let h = d.dot(self.axis).clamp(0.0, self.len);
        d - self.axis * h
    }

    /// The component's field at a blob-space point.
    fn density(&self, p: DVec3) -> f64 {
        let d2 = self.offset(self.local_point(p)).length_squared();
        if d2 < self.r2 {
            let w = 1.0 - d2 / self.r2;
            self.strength * w * w
        } else {
            0.0
        }
    }

    /// Appends the stretches of the local ray `q0 + s v` inside the component, each with its
    /// field as a quartic in s (ascending coefficients), those ending at or before `min_s`
    /// left out (`crossings` would drop them).
    fn pieces(&self, q0: DVec3, v: DVec3, min_s: f64, out: &mut Vec<Piece>) {
        // Squared distance to a point c: |q0 - c|² + 2 s (q0 - c)·v + s² v·v.
        let to_point = |c: DVec3| {
            let d = q0 - c;
            [d.length_squared(), 2.0 * d.dot(v), v.length_squared()]
        };
        if self.len == 0.0 {
            self.push(
                to_point(self.a),
                f64::NEG_INFINITY,
                f64::INFINITY,
                min_s,
                out,
            );
            return;
        }
        // Height along the axis, h0 + s h1; the body lies where 0 <= h <= len.
        let d = q0 - self.a;
        let (h0, h1) = (d.dot(self.axis), v.dot(self.axis));
        let pa = to_point(self.a);
        let b = self.a + self.axis * self.len;
        let pb = to_point(b);
        let body = [pa[0] - h0 * h0, pa[1] - 2.0 * h0 * h1, pa[2] - h1 * h1];
        // A ray wide of the body's and both caps' spheres (`push` would return at each one's
        // discriminant) pushes nothing: leave before the end planes' two quotients.
        if self.wide(body) && self.wide(pa) && self.wide(pb) {
            return;
        }
        let (s_lo, s_hi) = if h1 != 0.0 {
            let (s0, s1) = (-h0 / h1, (self.len - h0) / h1);
            (s0.min(s1), s0.max(s1))
        } else if (0.0..=self.len).contains(&h0) {
            (f64::NEG_INFINITY, f64::INFINITY)
        } else {
            (f64::NAN, f64::NAN)
        };
        if !s_lo.is_nan() {
            self.push(body, s_lo, s_hi, min_s, out);
        }
        // The caps: before the body and after it along the ray; which end is which depends on
        // the ray's direction along the axis.
        let (first, last) = if h1 >= 0.0 { (pa, pb) } else { (pb, pa) };
        if s_lo.is_nan() {
            // Parallel to the end planes, outside the body: only one cap can be reached.
            let end = if h0 < 0.0 { pa } else { pb };
            self.push(end, f64::NEG_INFINITY, f64::INFINITY, min_s, out);
        } else {
            self.push(first, f64::NEG_INFINITY, s_lo, min_s, out);
            self.push(last, s_hi, f64::INFINITY, min_s, out);
        }
    }

    /// Whether `push` returns at the discriminant of the quadratic distance `d2` (the same
    /// operations), whatever the stretch it is given.
    #[inline(always)]
    fn wide(&self, d2: [f64; 3]) -> bool {
        let [c, b, a] = d2;
        a > 0.0 && b * b - 4.0 * a * (c - self.r2) <= 0.0
    }

    /// The stretch where the quadratic distance `d2` is below r², clipped to [lo, hi], unless
    /// it ends at or before `min_s`. Inlined into `pieces`, where the distances of a cap
    /// that ends behind the ray's start are then never formed.
    #[inline(always)]
    fn push(&self, d2: [f64; 3], lo: f64, hi: f64, min_s: f64, out: &mut Vec<Piece>) {
        // The clipped end is at most `hi`: a cap wholly behind the ray's start (a shadow
        // ray's) needs neither its square root nor its quotients.
        if hi <= min_s {
            return;
        }
        let [c, b, a] = d2;
        let (c0, c1) = if a > 0.0 {
            let disc = b * b - 4.0 * a * (c - self.r2);
            if disc <= 0.0 {
                return;
            }
            let q = -0.5 * (b + b.signum() * disc.sqrt());
            let (x, y) = (q / a, if q != 0.0 { (c - self.r2) / q } else { q / a });
            (x.min(y), x.max(y))
        } else if c < self.r2 {
            (f64::NEG_INFINITY, f64::INFINITY)
        } else {
            return;
        };
        let (lo, hi) = (lo.max(c0), hi.min(c1));
        if !lo.is_finite() || !hi.is_finite() || lo >= hi || hi <= min_s {
            return;
        }
        // strength · (1 - d2/r²)², with w = 1 - d2/r² a quadratic.
        let k = self.inv_r2;
        let w = [1.0 - c * k, -b * k, -a * k];
        let s = self.strength;
        out.push(Piece {
            lo,
            hi,
            c: [
                s * w[0] * w[0],
                s * 2.0 * w[0] * w[1],
                s * (w[1] * w[1] + 2.0 * w[0] * w[2]),
                s * 2.0 * w[1] * w[2],
                s * w[2] * w[2],
            ],
        });
    }
}

/// A stretch of the ray with one component's field as a quartic.
#[derive(Clone, Copy, Debug)]
struct Piece {
    lo: f64,
    hi: f64,
    c: [f64; 5],
}

/// Work of `crossings` (nearest crossing only) left undone because its roots all map to
/// `t <= EPSILON`, where `keep` rejects them whatever their bits: only their effect on the
/// deduplication's `last` is unknown, and that matters only when a later root lies within
/// the deduplication tolerance of them (see `Backlog::settle`).
#[derive(Clone, Copy, Debug)]
enum Deferred {
    /// A whole stretch: `first_root_in` on it, every root rejected.
    Stretch { c: [f64; 5], lo: f64, hi: f64 },
    /// One root's bracket, unpolished: `c[..n]` is the polynomial `Candidate::c`.
    Root {
        c: [f64; 5],
        n: usize,
        a: f64,
        b: f64,
        neg_at_a: bool,
    },
}

#[derive(Default)]
struct Work {
    pieces: Vec<Piece>,
    cuts: Vec<f64>,
    deferred: Vec<Deferred>,
}

/// `crossings`' test of a root `s` against the previous one it took, `last`: a root on a cut
/// is found from both sides. Updates `last` for a root it takes; true when its `t` counts.
#[inline]
fn keep_root(s: f64, last: &mut f64, shift: f64, len: f64) -> bool {
    if s - *last <= 1e-12 * (1.0 + s.abs()) {
        return false;
    }
    *last = s;
    (s + shift) / len > EPSILON
}

/// The deferred work since `last` was last known for sure, and the largest root it can
/// hold (every root of a stretch lies in it, a polished root in its bracket).
struct Backlog<'a> {
    items: &'a mut Vec<Deferred>,
    bound: f64,
}

impl Backlog<'_> {
    fn defer(&mut self, item: Deferred, bound: f64) {
        self.items.push(item);
        self.bound = self.bound.max(bound);
    }

    /// Brings `last` up to date before the root `x` is tested against it. The deferred work
    /// leaves `last` either as it was or at one of its roots, all at most `bound`; when `x`
    /// passes the test against both (`x - y` only grows as `y` falls, in rounded arithmetic
    /// too), `x` is taken and replaces `last` whichever it was, so the work is dropped.
    /// Otherwise it is done now, in order, exactly as it would have been.
    fn settle(&mut self, x: f64, last: &mut f64, shift: f64, len: f64) {
        if self.items.is_empty() {
            return;
        }
        let tol = 1e-12 * (1.0 + x.abs());
        if x - self.bound <= tol || x - *last <= tol {
            for item in self.items.iter() {
                match *item {
                    Deferred::Stretch { c, lo, hi } => {
                        let found = first_root_in(&c, lo, hi, |s| keep_root(s, last, shift, len));
                        debug_assert!(found.is_none());
                    }
                    Deferred::Root {
                        c,
                        n,
                        a,
                        b,
                        neg_at_a,
                    } => {
                        let s = Candidate {
                            c: &c[..n],
                            a,
                            b,
                            neg_at_a,
                        }
                        .root();
                        let kept = keep_root(s, last, shift, len);
                        debug_assert!(!kept);
                    }
                }
            }
        }
        self.items.clear();
        self.bound = f64::NEG_INFINITY;
    }
}

thread_local! {
    static WORK: RefCell<Work> = RefCell::new(Work::default());
}

#[derive(Debug)]
pub struct Blob {
    comps: Vec<Prepared>,
    /// Blob-space bounds of each component, for the hierarchy.
    bvh: Bvh,
    bounds: Aabb,
    threshold: f64,
    sturm: bool,
    /// How far beyond its box a component's field may be found, by rounding: the normal and
    /// field of a point ask only the components whose box so grown holds it (`each_near`).
    /// None asks every component: few of them, or one whose box or transform is not finite.
    near_pad: Option<f64>,
}

/// Below this many components the normal and field scan them all: the walk to find the
/// near ones costs about what a few components' distances do.
const NEAR_MIN: usize = 8;

/// The room `each_near` leaves around a component's blob-space box `b`. The box and a point's
/// distance to the component are each a few roundings from exact, relative to the
/// coordinates, and a transform scales that by at most its condition number (bounded by the
/// product of the Frobenius norms of its matrix and inverse); 1e-9 is millions of units in
/// the last place above it. Not finite when the box or transform is not.
fn near_pad(b: &Aabb, transform: Option<&Transform>) -> f64 {
    let frobenius = |m: &DMat4| {
        (m.x_axis.truncate().length_squared()
            + m.y_axis.truncate().length_squared()
            + m.z_axis.truncate().length_squared())
        .sqrt()
    };
    let cond = transform.map_or(1.0, |t| {
        if t.m.is_finite() && t.inv.is_finite() {
            frobenius(&t.m) * frobenius(&t.inv)
        } else {
            f64::INFINITY
        }
    });
    let size = b.min.abs().max(b.max.abs()).max_element();
    let pad = 1e-9 * cond.max(1.0) * (1.0 + size);
    if pad.is_nan() {
        f64::INFINITY
    } else {
        pad
    }
}

impl Blob {
    pub fn new(data: &BlobData) -> Blob {
        let mut comps = Vec::new();
        let mut boxes = Vec::new();
        for (index, c) in data.components.iter().enumerate() {
            let r = c.radius.abs();
            if !(r > 0.0 && r.is_finite() && c.strength.is_finite()) || c.strength == 0.0 {
                continue;
            }
            let (a, axis, len) = match c.kind {
                ComponentKind::Sphere { center } => (center, DVec3::X, 0.0),
                ComponentKind::Cylinder { a, b } => {
                    let d = b - a;
                    let len = d.length();
                    if len > 0.0 && len.is_finite() {
                        (a, d / len, len)
                    } else {
                        (a, DVec3::X, 0.0)
                    }
                }
            };
            let end = a + axis * len;
            let local = Aabb::new(a.min(end) - DVec3::splat(r), a.max(end) + DVec3::splat(r));
            let tf = (!c.transform.is_identity()).then_some(c.transform);
            boxes.push(tf.map_or(local, |t| local.transformed(&t)));
            comps.push(Prepared {
                a,
                axis,
                len,
                r2: r * r,
                inv_r2: 1.0 / (r * r),
                strength: c.strength,
                transform: tf,
                index,
            });
        }
        // Only components adding to the field can hold surface when the threshold is positive.
        let bounds = if data.threshold > 0.0 {
            comps
                .iter()
                .zip(&boxes)
                .filter(|(c, _)| c.strength > 0.0)
                .fold(Aabb::EMPTY, |acc, (_, b)| acc.union(b))
        } else {
            Aabb::INFINITE
        };
        let pad = comps
            .iter()
            .zip(&boxes)
            .map(|(c, b)| {
                let ok = b.is_finite() && c.r2.is_finite() && c.inv_r2.is_finite();
                if ok {
                    near_pad(b, c.transform.as_ref())
                } else {
                    f64::INFINITY
                }
            })
            .fold(0.0, f64::max);
        Blob {
            bvh: Bvh::build(&boxes),
            near_pad: (comps.len() >= NEAR_MIN && pad.is_finite()).then_some(pad),
            comps,
            bounds,
            threshold: data.threshold,
            sturm: data.sturm,
        }
    }

    /// Calls `f` on the components in their order, leaving out only ones whose field is
    /// zero at `p` (`d2 >= r2`: `density` gives +0 and `normal` skips them), so sums over
    /// what it gives are the full loop's bits. A point beyond a component's box by more than
    /// `near_pad` is beyond its radius whatever the rounding (see `near_pad`).
    #[inline]
    fn each_near(&self, p: DVec3, mut f: impl FnMut(&Prepared)) {
        match self.near_pad {
            Some(pad) if p.is_finite() => {
                let mut near: smallvec::SmallVec<[u32; 32]> = smallvec::SmallVec::new();
                self.bvh.visit_near(p, pad, |i| near.push(i as u32));
                near.sort_unstable();
                for &i in &near {
                    f(&self.comps[i as usize]);
                }
            }
            _ => self.comps.iter().for_each(f),
        }
    }

    /// The summed field at a blob-space point. The components left out add +0, which can
    /// only turn a -0 sum into +0; `inside` compares it with the threshold, where the two
    /// zeros are one.
    pub fn field(&self, p: DVec3) -> f64 {
        let mut sum = -0.0;
        self.each_near(p, |c| sum += c.density(p));
        sum
    }

    /// The components whose field reaches `p`, as (index in `BlobData::components`, field).
    pub fn densities(&self, p: DVec3, out: &mut Vec<(usize, f64)>) {
        out.clear();
        self.each_near(p, |c| {
            let d = c.density(p);
            if d != 0.0 {
                out.push((c.index, d));
            }
        });
    }

    /// The crossings, or with `first_only` only the nearest (`first_root_in`: the roots
    /// beyond it are not polished), the same bits. With `first_only` the stretches starting
    /// at or beyond `tmax` are not searched: a root s in [lo, hi] gives t = (s + shift) / len,
    /// and rounding keeps that order, so t >= tmax for every such root, which
    /// `intersect_first` drops anyway. With `SETTLE` (and `first_only`, `accept` always
    /// true) a bracket that surely holds a counted crossing is pushed as its lower end's `t`
    /// unpolished: for `any_hit`, which asks only whether there is one.
    ///
    /// With `first_only`, `accept` is asked in increasing order about each crossing's `t`
    /// the full list holds (it never sees a `t <= EPSILON`) and the walk stops at the first it
    /// accepts, which is the one pushed: `intersect_first` accepts the first, `any_kept` the
    /// first its caller keeps or the first at or beyond `tmax`. Without `first_only` it is
    /// not asked.
    fn crossings<const SETTLE: bool>(
        &self,
        ray: &Ray,
        w: &mut Work,
        out: &mut Vec<Hit>,
        first_only: bool,
        tmax: f64,
        mut accept: impl FnMut(f64) -> bool,
    ) {
        let len = ray.dir.length();
        if !(len > 0.0 && len.is_finite() && ray.origin.is_finite()) {
            return;
        }
        let u = ray.dir / len;
        let unit = Ray::new(ray.origin, u);
        // Stretches ending at or before `t = EPSILON` hold no crossing that counts.
        let min_s = EPSILON * len;
        w.pieces.clear();
        self.bvh.traverse(&unit, f64::INFINITY, |i, _| {
            let c = &self.comps[i];
            let (q0, v) = match &c.transform {
                Some(t) => (t.inv_point(ray.origin), t.inv_vector(u)),
                None => (ray.origin, u),
            };
            c.pieces(q0, v, min_s, &mut w.pieces);
            false
        });
        if w.pieces.is_empty() {
            return;
        }
        // Re-centre every quartic on the first entry so they are evaluated near their roots.
        let shift = w
            .pieces
            .iter()
            .map(|p| p.lo)
            .fold(f64::INFINITY, f64::min)
            .max(0.0);
        w.cuts.clear();
        // A ray starting inside a component (shadow and reflected rays) has `shift == 0`, where
        // the Taylor shift only adds `0·c` terms to finite coefficients: they change at most
        // the sign of a zero coefficient, which the sums below never see (each starts at +0 or
        // at `-threshold`, nonzero, so no partial sum is -0, and adding ±0 to anything else
        // leaves it as it is).
        let unshifted = shift == 0.0 && self.threshold != 0.0;
        for p in &mut w.pieces {
            if !(unshifted && p.c.iter().all(|x| x.is_finite())) {
                p.c = shifted(&p.c, shift);
            }
            p.lo -= shift;
            p.hi -= shift;
            w.cuts.push(p.lo);
            w.cuts.push(p.hi);
        }
        // `total_cmp` holds two cuts equal only when their bits are, so the unstable sort
        // leaves them in the one order a stable sort would.
        w.cuts.sort_unstable_by(f64::total_cmp);
        w.cuts.dedup();
        let Work {
            pieces,
            cuts,
            deferred,
        } = w;
        deferred.clear();
        let mut backlog = Backlog {
            items: deferred,
            bound: f64::NEG_INFINITY,
        };
        let mut last = f64::NEG_INFINITY;
        for k in 0..cuts.len().saturating_sub(1) {
            let (lo, hi) = (cuts[k], cuts[k + 1]);
            if first_only && (lo + shift) / len >= tmax {
                return;
            }
            let mid = 0.5 * (lo + hi);
            let mut sum = [-self.threshold, 0.0, 0.0, 0.0, 0.0];
            let mut any = false;
            for p in pieces.iter().filter(|p| p.lo <= mid && mid < p.hi) {
                for (s, c) in sum.iter_mut().zip(p.c) {
                    *s += c;
                }
                any = true;
            }
            if !any {
                continue;
            }
            if first_only && !self.sturm {
                // Roots at or below `hi` (a polished root lies in its bracket) give
                // `t <= EPSILON` when `hi` does (rounding keeps the order), and `keep_root`
                // rejects them: such a stretch or bracket (shadow rays leaving the surface)
                // is deferred rather than searched or polished, see `Backlog::settle`.
                let behind = |s: f64| (s + shift) / len <= EPSILON;
                if behind(hi) {
                    backlog.defer(Deferred::Stretch { c: sum, lo, hi }, hi);
                    continue;
                }
                let take = |cand: Candidate| {
                    // A bracket reaching past `t = EPSILON` (the root at a shadow ray's
                    // origin) whose root surely lies behind it is deferred as well.
                    let bound = if behind(cand.b) {
                        Some(cand.b)
                    } else if behind(cand.a) {
                        root_surely_behind(&cand, shift, len)
                    } else {
                        None
                    };
                    if let Some(bound) = bound {
                        let mut c = [0.0; 5];
                        c[..cand.c.len()].copy_from_slice(cand.c);
                        let item = Deferred::Root {
                            c,
                            n: cand.c.len(),
                            a: cand.a,
                            b: cand.b,
                            neg_at_a: cand.neg_at_a,
                        };
                        backlog.defer(item, bound);
                        return None;
                    }
                    if SETTLE {
                        // Whatever the polished root `s` in `[a, b]`: `s - last` is at
                        // least `a - prior` and the tolerance at most the one of the larger
                        // end (rounding keeps both orders), so `Backlog::settle` drops its
                        // work and `keep_root` takes `s`; its `t` lies in the ends' `t`s,
                        // above `EPSILON` and below `tmax`. So the walk would push a crossing
                        // that counts: a caller asking only whether there is one is answered
                        // without the polish (shadow rays).
                        let (a, b) = (cand.a, cand.b);
                        let prior = last.max(backlog.bound);
                        if (a + shift) / len > EPSILON
                            && (b + shift) / len < tmax
                            && a - prior > 1e-12 * (1.0 + a.abs().max(b.abs()))
                        {
                            return Some(a);
                        }
                    }
                    let s = cand.root();
                    backlog.settle(s, &mut last, shift, len);
                    // `keep_root` first: it moves `last` for every root the list would hold.
                    (keep_root(s, &mut last, shift, len) && accept((s + shift) / len)).then_some(s)
                };
                if let Some(s) = first_root_with(&sum, lo, hi, take) {
                    out.push(Hit::with_part((s + shift) / len, PART_BLENDED));
                    return;
                }
                continue;
            }
            let roots = if self.sturm {
                sturm_roots_in(&sum, lo, hi)
            } else {
                roots_in(&sum, lo, hi)
            };
            for &s in roots.iter() {
                // A root on a cut is found from both sides.
                if s - last <= 1e-12 * (1.0 + s.abs()) {
                    continue;
                }
                last = s;
                let t = (s + shift) / len;
                if t > EPSILON {
                    // No component chosen yet: see `PART_BLENDED`.
                    out.push(Hit::with_part(t, PART_BLENDED));
                }
            }
        }
    }
}

/// For a sign change's bracket `[a, b]` with `a` behind `t = EPSILON` and `b` beyond it (the
/// root at a shadow ray's origin): a bound on the polished root whose `t` is at most
/// `EPSILON`, when its sign settles that the root lies behind, so `keep_root` would reject it.
///
/// Why: `surely_no_root` on `[w, b]` (w between the root's expected place, the ray's start,
/// and `t = EPSILON`) certifies that every evaluation at a point there has `b`'s sign, which
/// is not `a`'s (the bracket is a change of sign). So every step of `polish` that evaluates a
/// point `x >= w` moves the bracket's upper end to `x`, and its lower end stays below `w`.
/// `polish` then returns an exact zero found below `w`, or a point within its tolerance
/// (`2·2^-52·|r| + MIN_POSITIVE`, `|r| <= max(|a|, |b|)`) of a point evaluated below `w`
/// or of its lower end: a Newton step from an `x >= w` is at least `1e-11·T / (4T/x)`
/// (`|f| > 1e-11·T`, `|f'(x)| <= 4·T/x` with `T = Σ|c_j|·b^j`, the certificate's bound),
/// far above that tolerance. So the root is below `w + 1e-14·max(|a|, |b|) + 1e-300`
/// (given that `polish` converges within its 100 steps, as `window::edge_rules_out` assumes
/// too), and rounding keeps the order through `(s + shift) / len`.
#[inline]
fn root_surely_behind(cand: &Candidate, shift: f64, len: f64) -> Option<f64> {
    let (a, b) = (cand.a, cand.b);
    let w = 0.5 * ((EPSILON * len - shift) + a.max(-shift));
    let bound = w + 1e-14 * a.abs().max(b.abs()) + 1e-300;
    let sure = w > a
        && w < b
        && w > 1e-290
        && (bound + shift) / len <= EPSILON
        && surely_no_root(cand.c, w, b);
    sure.then_some(bound)
}

/// The quartic `c` in s re-expressed in s' = s − shift.
fn shifted(c: &[f64; 5], shift: f64) -> [f64; 5] {
    // Taylor expansion at `shift`: coefficient k is p^(k)(shift) / k!.
    let mut out = *c;
    for k in 0..5 {
        for j in (k..4).rev() {
            out[j] += shift * out[j + 1];
        }
    }
    out
}

impl Shape for Blob {
    fn bounds(&self) -> Aabb {
        self.bounds
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        WORK.with(|w| match w.try_borrow_mut() {
            Ok(mut w) => self.crossings::<false>(ray, &mut w, out, false, f64::INFINITY, |_| true),
            // Never re-entered in practice; a fresh buffer keeps it correct if it were.
            Err(_) => self.crossings::<false>(
                ray,
                &mut Work::default(),
                out,
                false,
                f64::INFINITY,
                |_| true,
            ),
        });
    }

    fn intersect_first(&self, ray: &Ray, tmax: f64, scratch: &mut Vec<Hit>) -> Option<Hit> {
        scratch.clear();
        WORK.with(|w| match w.try_borrow_mut() {
            Ok(mut w) => self.crossings::<false>(ray, &mut w, scratch, true, tmax, |_| true),
            Err(_) => {
                self.crossings::<false>(ray, &mut Work::default(), scratch, true, tmax, |_| true)
            }
        });
        // With `sturm` every crossing is there; without, only the nearest.
        scratch
            .iter()
            .filter(|h| h.t > EPSILON && h.t < tmax)
            .min_by(|a, b| a.t.total_cmp(&b.t))
            .copied()
    }

    /// `intersect_first(..).is_some()`, a root's polish left out where its bracket settles
    /// the answer (`crossings`' `SETTLE`): shadow rays. `sturm` blobs list.
    fn any_hit(&self, ray: &Ray, tmax: f64, scratch: &mut Vec<Hit>) -> bool {
        if self.sturm {
            return self.intersect_first(ray, tmax, scratch).is_some();
        }
        scratch.clear();
        WORK.with(|w| match w.try_borrow_mut() {
            Ok(mut w) => self.crossings::<true>(ray, &mut w, scratch, true, tmax, |_| true),
            Err(_) => {
                self.crossings::<true>(ray, &mut Work::default(), scratch, true, tmax, |_| true)
            }
        });
        scratch.iter().any(|h| h.t > EPSILON && h.t < tmax)
    }

    /// The crossings nearest first (`crossings`' walk for `intersect_first`: the same roots,
    /// bit for bit, each polished only when reached), stopping at the first `keep` holds for
    /// or the first at or beyond `tmax` (`t` grows with the root). `sturm` blobs list.
    fn any_kept(
        &self,
        ray: &Ray,
        tmax: f64,
        scratch: &mut Vec<Hit>,
        keep: &mut dyn FnMut(f64) -> bool,
    ) -> bool {
        if self.sturm {
            return super::any_listed_kept(self, ray, tmax, scratch, keep);
        }
        scratch.clear();
        let accept = |t: f64| t >= tmax || keep(t);
        WORK.with(|w| match w.try_borrow_mut() {
            Ok(mut w) => self.crossings::<false>(ray, &mut w, scratch, true, tmax, accept),
            Err(_) => {
                self.crossings::<false>(ray, &mut Work::default(), scratch, true, tmax, accept)
            }
        });
        scratch.first().is_some_and(|h| h.t < tmax)
    }

    /// The listing's least kept crossing below `tmax` alone (`any_kept`'s walk: crossings
    /// nearest first, the same bits and part, each polished only when reached): the CSG
    /// search takes a member's least kept crossing, so the others cannot change its answer.
    /// `sturm` blobs list.
    fn gather_kept(
        &self,
        ray: &Ray,
        tmax: f64,
        out: &mut Vec<Hit>,
        scratch: &mut Vec<Hit>,
        keep: &mut dyn FnMut(f64) -> bool,
    ) {
        if self.sturm {
            return self.intersect_all(ray, out);
        }
        scratch.clear();
        let accept = |t: f64| t >= tmax || keep(t);
        WORK.with(|w| match w.try_borrow_mut() {
            Ok(mut w) => self.crossings::<false>(ray, &mut w, scratch, true, tmax, accept),
            Err(_) => {
                self.crossings::<false>(ray, &mut Work::default(), scratch, true, tmax, accept)
            }
        });
        out.extend(scratch.first().filter(|h| h.t < tmax));
    }

    fn inside(&self, p: DVec3) -> bool {
        self.field(p) > self.threshold
    }

    fn normal(&self, p: DVec3, _hit: &Hit) -> DVec3 {
        // Minus the field's gradient: each component contributes
        // 4·strength·(1 − d²/r²)/r² times the offset from its centre or axis, taken back to
        // blob space by the inverse transpose of its transform.
        let mut n = DVec3::ZERO;
        self.each_near(p, |c| {
            let q = c.local_point(p);
            let off = c.offset(q);
            let d2 = off.length_squared();
            if d2 >= c.r2 {
                return;
            }
            let g = off * (4.0 * c.strength * (1.0 - d2 / c.r2) / c.r2);
            n += match &c.transform {
                Some(t) => t.normal(g),
                None => g,
            };
        });
        n
    }
}

#[cfg(test)]
#[path = "blob_tests.rs"]
mod tests;
