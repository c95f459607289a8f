//! Tight boxes for CSG intersections (and differences of them) that a box per member cannot
//! give: a polyhedron cut from rotated planes (shapes2.inc's dodecahedron, say) has members
//! that are all unbounded, so its `bounds` stay infinite and every ray would test every face.
//!
//! The box is the bounding box of the polyhedron cut by the members' planes and the finite
//! members' boxes (its vertices, from every three planes), padded. It is only a test a ray or a
//! point must pass before the usual work: it never changes an answer (a crossing of an
//! intersection lies on one member and inside all the others, so inside every half-space), and
//! it leaves `bounds`, and so the scene's BVH, as they were.
//!
//! The same half-spaces (and a sphere member's ball) give windowed shapes (quartics) their
//! [`Window`]: the stretch of each ray where their crossings can survive the clipping or the
//! intersection, so the root finder polishes nothing outside it.

use crate::math::{Aabb, DMat4, DVec3, Ray};
use crate::scene::desc::CsgOp;
use crate::scene::object::{ObjKind, Object};
use polyhedron::polyhedron_box;

/// More half-spaces than this and a window is kept as a box (each plane costs a division per
/// ray).
const MAX_WINDOW_PLANES: usize = 12;

/// A box holding every crossing of a top-level object whose `bounds` are not finite, from its
/// own planes and slabs and its clipping objects' (a crossing must lie inside all of them);
/// `None` when nothing finite comes of it. Not for inverted objects (their solid is outside).
pub fn object_cull(o: &Object) -> Option<Aabb> {
    if o.inverse {
        return None;
    }
    let mut planes = Vec::new();
    half_spaces(o, &mut planes);
    for c in &o.clip {
        half_spaces(c, &mut planes);
    }
    let mut b = polyhedron_box(&planes).unwrap_or(Aabb::INFINITE);
    if let ObjKind::Csg { cull: Some(c), .. } = &o.kind {
        if let Some(a) = &c.aabb {
            b = b.intersection(a);
        }
    }
    let b = b.intersection(&o.bounds);
    (b != Aabb::INFINITE && (b.is_finite() || b.min.is_finite() || b.max.is_finite())).then_some(b)
}

/// Where a windowed shape's crossings can survive its clipping (`ObjKind::Shape`'s window): a
/// box, or when its clipping gives no box with a finite corner (a slab of two planes, turned)
/// the clipping's half-spaces themselves, each padded as `polyhedron_box` pads its box.
#[derive(Clone)]
pub struct Window {
    edges: Edges,
    /// A ball holding the solid of a member or clipping object (a sphere), in its own space.
    ball: Option<Ball>,
}

#[derive(Clone)]
enum Edges {
    /// None: the ball alone bounds the window.
    Whole,
    Box(Aabb),
    Planes(Planes),
}

/// Turned half-spaces: those paired with an opposite face (a turned box's six faces are three
/// slabs) and the others.
#[derive(Clone)]
struct Planes {
    /// `(n, hi, lo)`: `lo <= n·p <= hi`.
    slabs: Vec<(DVec3, f64, f64)>,
    /// `(n, d)`: `n·p <= d`.
    single: Vec<(DVec3, f64)>,
}

impl Planes {
    /// The padded half-spaces, each face paired with one whose normal is its exact opposite.
    fn paired(planes: &[(DVec3, f64)]) -> Planes {
        let mut used = vec![false; planes.len()];
        let (mut slabs, mut single) = (Vec::new(), Vec::new());
        for i in 0..planes.len() {
            if used[i] {
                continue;
            }
            used[i] = true;
            let (n, d) = planes[i];
            match (i + 1..planes.len()).find(|&j| !used[j] && planes[j].0 == -n) {
                Some(j) => {
                    used[j] = true;
                    slabs.push((n, d, -planes[j].1));
                }
                None => single.push((n, d)),
            }
        }
        Planes { slabs, single }
    }
}

#[derive(Clone)]
struct Ball {
    /// World to the sphere's space (`None`: the same).
    inv: Option<DMat4>,
    centre: DVec3,
    /// The radius, padded by 1e-6 of itself.
    radius: f64,
}

impl Window {
    /// The window of a clipped shape, when its clipping gives one: the half-spaces when some
    /// is turned off the axes (their box would be looser), else the box.
    pub fn of(o: &Object) -> Option<Window> {
        let boxed = object_cull(o);
        if o.inverse {
            return boxed.map(|b| Window {
                edges: Edges::Box(b),
                ball: None,
            });
        }
        let mut planes = Vec::new();
        window_half_spaces(o, &mut planes);
        let ball = o
            .clip
            .iter()
            .enumerate()
            .find_map(|(k, c)| Some((k, ball_of(c)?)));
        for (k, c) in o.clip.iter().enumerate() {
            // With a box to fall back on, the ball's own faces are left out: see `within`.
            if boxed.is_none() || ball.as_ref().is_none_or(|b| b.0 != k) {
                window_half_spaces(c, &mut planes);
            }
        }
        Window::choose(boxed, &planes).map(|w| w.with_ball(ball.map(|b| b.1)))
    }

    /// The window of an `intersection`'s member: every crossing the node keeps lies inside all
    /// its members, so inside their half-spaces, and inside the node's box `bx`.
    pub fn within(children: &[Object], bx: Aabb) -> Option<Window> {
        let ball = children
            .iter()
            .enumerate()
            .find_map(|(k, c)| Some((k, ball_of(c)?)));
        let mut planes = Vec::new();
        for (k, c) in children.iter().enumerate() {
            // The ball's own member adds nothing but its box's faces (six turned planes when
            // it is turned: folium's and witch's spheres), which hold the ball and so cut no
            // chord shorter: a division and a mispredicted branch per face and ray, saved.
            // Only the window's padding differs, and any window holding every crossing the
            // node keeps gives the same kept roots (`roots_in_window`).
            if ball.as_ref().is_none_or(|b| b.0 != k) {
                window_half_spaces(c, &mut planes);
            }
        }
        // Nothing else bounds the node and its box holds the whole ball: the box cuts no chord
        // shorter either, so only the ball is asked.
        if let Some((_, b)) = &ball {
            if planes.is_empty() && b.inv.is_none() && {
                let wb = b.world_box();
                bx.min.cmple(wb.min).all() && bx.max.cmpge(wb.max).all()
            } {
                return Some(Window {
                    edges: Edges::Whole,
                    ball: ball.map(|b| b.1),
                });
            }
        }
        Window::choose(Some(bx), &planes).map(|w| w.with_ball(ball.map(|b| b.1)))
    }

    fn with_ball(self, ball: Option<Ball>) -> Window {
        Window { ball, ..self }
    }

    /// The half-spaces (normalised and padded as `polyhedron_box` pads its box: by 1e-6 of the
    /// largest offset, far above the rounding of the inside tests and of a ray's distances to
    /// the planes) when the box is missing or some plane is turned, else the box.
    fn choose(boxed: Option<Aabb>, planes: &[(DVec3, f64)]) -> Option<Window> {
        let planes: Vec<(DVec3, f64)> = planes
            .iter()
            .map(|&(n, d)| {
                let l = n.length();
                (n / l, d / l)
            })
            .filter(|(n, d)| n.is_finite() && d.is_finite())
            .collect();
        let turned = planes
            .iter()
            .any(|(n, _)| n.to_array().iter().filter(|v| **v != 0.0).count() > 1);
        let edges = if planes.is_empty()
            || planes.len() > MAX_WINDOW_PLANES
            || (boxed.is_some() && !turned)
        {
            Edges::Box(boxed?)
        } else {
            let scale = planes.iter().map(|h| h.1.abs()).fold(1.0, f64::max);
            let pad = 1e-6 * scale;
            let padded: Vec<_> = planes.iter().map(|&(n, d)| (n, d + pad)).collect();
            Edges::Planes(Planes::paired(&padded))
        };
        Some(Window { edges, ball: None })
    }

    /// The stretch of `origin + t·dir` (the `t` of the world ray, which a shape's own ray
    /// shares) holding every crossing the clipping keeps, padded against rounding.
    #[inline]
    pub fn range(&self, ray: &Ray) -> Range {
        if let (Edges::Whole, Some(ball)) = (&self.edges, &self.ball) {
            return match ball.chord(ray) {
                Some((b0, b1)) if b0.is_finite() && b1.is_finite() => Range::Within(b0, b1),
                Some(_) => Range::All,
                None => Range::Empty,
            };
        }
        let range = self.edge_range(ray);
        match (&self.ball, range) {
            (Some(ball), Range::Within(lo, hi)) if !lo.is_nan() && !hi.is_nan() => {
                match ball.chord(ray) {
                    Some((b0, b1)) => {
                        let (lo, hi) = (lo.max(b0), hi.min(b1));
                        if lo <= hi {
                            Range::Within(lo, hi)
                        } else {
                            Range::Empty
                        }
                    }
                    None => Range::Empty,
                }
            }
            _ => range,
        }
    }

    /// `range` from the box or the planes alone.
    #[inline]
    fn edge_range(&self, ray: &Ray) -> Range {
        let (lo, hi) = match &self.edges {
            Edges::Whole => return Range::All,
            Edges::Box(b) => {
                let inv = ray.dir.recip();
                let (t0, t1) = ((b.min - ray.origin) * inv, (b.max - ray.origin) * inv);
                let lo = t0.min(t1).max_element();
                let hi = t0.max(t1).min_element();
                let pad = 1e-7 * (lo.abs().max(hi.abs()) + 1.0);
                // NaN (a ray in a face's plane) asks for everything: the shape's window
                // search takes a NaN edge as none.
                return if lo <= hi || lo.is_nan() || hi.is_nan() {
                    Range::Within(lo - pad, hi + pad)
                } else {
                    Range::Empty
                };
            }
            Edges::Planes(planes) => {
                let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
                // A slab's two faces share the products with the ray and one reciprocal, and
                // its entry and exit come from a min and a max, not from branches on the
                // direction's side (mispredicted on a third of trough's faces). The products by
                // the reciprocal round once more than the quotients: a few ulps of `t`, far
                // below the final padding (1e-7 of the reach), so the window still holds every
                // kept crossing, which is all it must do (`roots_in_window`).
                let mut nan = false;
                for &(n, top, bottom) in &planes.slabs {
                    let (nd, no) = (n.dot(ray.dir), n.dot(ray.origin));
                    if nd == 0.0 {
                        // Parallel: left unbounded, as by each face alone.
                        continue;
                    }
                    let r = 1.0 / nd;
                    let (ta, tb) = ((top - no) * r, (bottom - no) * r);
                    nan |= ta.is_nan() | tb.is_nan();
                    lo = lo.max(ta.min(tb));
                    hi = hi.min(ta.max(tb));
                }
                if nan {
                    return Range::All;
                }
                for &(n, d) in &planes.single {
                    // n·(o + t·dir) <= d; a ray parallel to a plane is left unbounded by it.
                    let (nd, no) = (n.dot(ray.dir), n.dot(ray.origin));
                    let t = (d - no) / nd;
                    if nd > 0.0 {
                        hi = hi.min(t);
                    } else if nd < 0.0 {
                        lo = lo.max(t);
                    } else if nd.is_nan() {
                        return Range::All;
                    }
                    if t.is_nan() && nd != 0.0 {
                        return Range::All;
                    }
                }
                (lo, hi)
            }
        };
        let reach = match (lo.is_finite(), hi.is_finite()) {
            (true, true) => lo.abs().max(hi.abs()),
            (true, false) => lo.abs(),
            (false, true) => hi.abs(),
            (false, false) => return Range::All,
        };
        if lo > hi {
            return Range::Empty;
        }
        let pad = 1e-7 * (reach + 1.0);
        Range::Within(lo - pad, hi + pad)
    }
}

/// The ball of a member or clipping object that is a sphere (not inverted), padded.
fn ball_of(o: &Object) -> Option<Ball> {
    let ObjKind::Shape(s, _) = &o.kind else {
        return None;
    };
    if o.inverse {
        return None;
    }
    let (centre, r) = s.ball()?;
    if !(r > 0.0 && r.is_finite() && centre.is_finite()) {
        return None;
    }
    let radius = r * (1.0 + 1e-6);
    Some(match &o.transform {
        None => Ball {
            inv: None,
            centre,
            radius,
        },
        Some(t) => world_ball(&t.m, centre, radius).unwrap_or(Ball {
            inv: Some(t.inv),
            centre,
            radius,
        }),
    })
}

/// The ball of `centre` and `radius` through `m` as a ball in world space, when `m` turns,
/// moves and scales evenly (up to 1e-6): the ray then needs no map into the sphere's space,
/// a matrix product at the head of `chord`'s chain of dependent steps on every ray.
///
/// It holds the mapped ball: a point `c + v` (`|v| <= radius`) maps to `m(c) + Mv`, and
/// `|Mv| <= σ·|v|` with `σ²` the largest eigenvalue of `MᵀM`, at most the largest row sum
/// of its absolute values (Gershgorin): `s2 + off` below. The roundings of those sums and of
/// `m(c)` (a few ulps of `|M||c| + |m(0)|`) are covered by the padding.
fn world_ball(m: &DMat4, centre: DVec3, radius: f64) -> Option<Ball> {
    let cols = [
        m.x_axis.truncate(),
        m.y_axis.truncate(),
        m.z_axis.truncate(),
    ];
    let len2 = cols.map(|c| c.length_squared());
    let s2 = len2[0].max(len2[1]).max(len2[2]);
    let off = (0..3)
        .map(|i| {
            (0..3)
                .filter(|&j| j != i)
                .map(|j| cols[i].dot(cols[j]).abs())
                .sum::<f64>()
        })
        .fold(0.0, f64::max);
    let low = len2[0].min(len2[1]).min(len2[2]);
    if !(s2.is_finite() && low > 0.0 && low >= s2 * (1.0 - 1e-6) && off <= 1e-6 * s2) {
        return None;
    }
    let world = m.transform_point3(centre);
    let reach = s2.sqrt() * centre.abs().element_sum() + m.w_axis.truncate().abs().element_sum();
    let radius = radius * ((s2 + off) * (1.0 + 1e-12)).sqrt() * (1.0 + 1e-9) + 1e-12 * reach;
    (world.is_finite() && radius.is_finite()).then_some(Ball {
        inv: None,
        centre: world,
        radius,
    })
}

impl Ball {
    /// The box of the (world) ball.
    fn world_box(&self) -> Aabb {
        Aabb::new(self.centre - self.radius, self.centre + self.radius)
    }

    /// The stretch of the ray (world `t`) inside the padded ball, itself padded by 1e-7 of
    /// its ends as boxes are; `None` when the ray misses it. From the point of the line
    /// nearest the centre (no cancellation between `b²` and `4ac`): every rounding here is a
    /// few ulps of the distances involved, and the padding (1e-6 of the radius) is far above
    /// them as long as the ray starts within 1e5 radii of the centre; farther away the ball
    /// says nothing (the whole line).
    #[inline]
    fn chord(&self, ray: &Ray) -> Option<(f64, f64)> {
        let (o, d) = match &self.inv {
            Some(m) => (m.transform_point3(ray.origin), m.transform_vector3(ray.dir)),
            None => (ray.origin, ray.dir),
        };
        let oc = o - self.centre;
        let r2 = self.radius * self.radius;
        let a = d.length_squared();
        // False for NaN too: the whole line then.
        let near = a > 0.0 && a.is_finite() && oc.length_squared() < 1e10 * r2;
        if !near {
            return Some((f64::NEG_INFINITY, f64::INFINITY));
        }
        // One division, beside the dot product rather than after it: the two quotients by `a`
        // of the chain become products, a rounding each more, far below the padding.
        let inv_a = 1.0 / a;
        let tm = -oc.dot(d) * inv_a;
        let h = oc + d * tm;
        let gap = r2 - h.length_squared();
        if gap < 0.0 {
            return None;
        }
        if gap.is_nan() {
            return Some((f64::NEG_INFINITY, f64::INFINITY));
        }
        let half = (gap * inv_a).sqrt();
        let (b0, b1) = (tm - half, tm + half);
        let pad = 1e-7 * (b0.abs().max(b1.abs()) + 1.0);
        Some((b0 - pad, b1 + pad))
    }
}

/// What a [`Window`] leaves of a ray.
#[derive(Clone, Copy, Debug)]
pub enum Range {
    /// Every crossing (the window says nothing for this ray).
    All,
    /// No crossing survives the clipping.
    Empty,
    /// Only crossings with `t` in `[lo, hi]` may survive (NaN ends: every crossing).
    Within(f64, f64),
}

/// A finite box holding an object's solid and crossings: its bounds, or when they are not
/// finite the box its planes, clipping and CSG cull give (`object_cull`).
pub fn solid_box(o: &Object) -> Option<Aabb> {
    let finite = |b: &Aabb| b.is_finite() && !b.is_empty();
    if finite(&o.bounds) {
        return Some(o.bounds);
    }
    object_cull(o).filter(finite)
}

/// The tight box of a CSG node, when it is finite on some side and tighter than `bounds`.
pub fn cull_box(op: CsgOp, children: &[Object], bounds: &Aabb) -> Option<Aabb> {
    let b = match op {
        CsgOp::Intersection => {
            let mut planes = Vec::new();
            for c in children {
                half_spaces(c, &mut planes);
            }
            let mut b = polyhedron_box(&planes).unwrap_or(Aabb::INFINITE);
            // Members bounded only within what the others close (a hyperboloid between two
            // planes, chess2's pieces); twice, so two such members can close each other.
            for _ in 0..2 {
                for c in children {
                    if let Some(m) = member_box_within(c, &b) {
                        b = b.intersection(&m);
                    }
                }
            }
            if b == Aabb::INFINITE {
                return None;
            }
            b
        }
        // A difference lies inside its first member, and outside every subtracted member that
        // is a half-space (a plane): advanced/abyss's hull is a blob less three planes, an
        // octant of the blob's box.
        CsgOp::Difference => {
            let first = member_box(&children[0])?;
            let mut planes = Vec::new();
            half_spaces(&children[0], &mut planes);
            let own = planes.len();
            planes.extend(children[1..].iter().filter_map(complement));
            if planes.len() > own {
                polyhedron_box(&planes).map_or(first, |b| b.intersection(&first))
            } else {
                first
            }
        }
        // A union of members that are each finite (some only by their own cull: chess2's
        // pieces, a hyperboloid between planes beside spheres) lies in their boxes' union.
        CsgOp::Union | CsgOp::Merge => {
            let mut b = Aabb::EMPTY;
            for c in children {
                if c.bounds.is_empty() {
                    continue;
                }
                b = b.union(&solid_box(c)?);
            }
            if b.is_empty() {
                return None;
            }
            b
        }
    };
    let b = b.intersection(bounds);
    (b.min.cmpgt(bounds.min).any() || b.max.cmplt(bounds.max).any()).then_some(b)
}

/// A box holding an object's solid (before `inverse`), from its own bounds or planes.
fn member_box(o: &Object) -> Option<Aabb> {
    if o.inverse {
        return None;
    }
    let mut planes = Vec::new();
    half_spaces(o, &mut planes);
    polyhedron_box(&planes)
}

/// A box holding the part of a shape member's solid inside `b` (before any clipping, which
/// only takes away), from the shape's `slab_bounds_within` in its own space.
fn member_box_within(o: &Object, b: &Aabb) -> Option<Aabb> {
    let ObjKind::Shape(s, _) = &o.kind else {
        return None;
    };
    if o.inverse {
        return None;
    }
    match &o.transform {
        None => Some(s.slab_bounds_within(b)),
        Some(t) => {
            let local = map_box(b, &t.inv)?;
            map_box(&s.slab_bounds_within(&local), &t.m)
        }
    }
}

/// A box through an affine map: per axis when the map only scales and moves (so open sides
/// stay open), by its corners when the box is finite; `None` otherwise.
fn map_box(b: &Aabb, m: &DMat4) -> Option<Aabb> {
    if b.is_empty() {
        return Some(*b);
    }
    let axis_aligned = (0..3).all(|c| (0..3).all(|r| r == c || m.col(c)[r] == 0.0));
    if axis_aligned {
        let (mut lo, mut hi) = (DVec3::ZERO, DVec3::ZERO);
        for a in 0..3 {
            let (s, t) = (m.col(a)[a], m.w_axis[a]);
            let (p, q) = (s * b.min[a] + t, s * b.max[a] + t);
            lo[a] = p.min(q);
            hi[a] = p.max(q);
        }
        let out = Aabb::new(lo, hi);
        return (!lo.is_nan() && !hi.is_nan()).then_some(out);
    }
    b.is_finite().then(|| b.corners_mapped(m))
}

/// Half-spaces n·p <= d holding the object's solid: a plane's own, its box's faces, those of
/// a nested intersection's members.
fn half_spaces(o: &Object, out: &mut Vec<(DVec3, f64)>) {
    if o.bounds.is_finite() && !o.bounds.is_empty() {
        let (lo, hi) = (o.bounds.min, o.bounds.max);
        for (axis, n) in [DVec3::X, DVec3::Y, DVec3::Z].into_iter().enumerate() {
            out.push((n, hi[axis]));
            out.push((-n, -lo[axis]));
        }
        return;
    }
    match &o.kind {
        ObjKind::Shape(s, _) => {
            // In the shape's space: its own half-space, or the finite sides of its slabs
            // (these only for a solid that is not inverted).
            let mut local = Vec::new();
            if let Some(h) = s.half_space() {
                local.push(if o.inverse { (-h.0, -h.1) } else { h });
            } else if !o.inverse {
                let b = s.slab_bounds();
                for (axis, n) in [DVec3::X, DVec3::Y, DVec3::Z].into_iter().enumerate() {
                    if b.max[axis].is_finite() && b.min[axis].is_finite() {
                        local.push((n, b.max[axis]));
                        local.push((-n, -b.min[axis]));
                    }
                }
            }
            for (n, d) in local {
                let (n, d) = match &o.transform {
                    Some(t) => (t.normal(n), d - n.dot(t.inv_point(DVec3::ZERO))),
                    None => (n, d),
                };
                if n.is_finite() && d.is_finite() && n != DVec3::ZERO {
                    out.push((n, d));
                }
            }
        }
        ObjKind::Csg {
            op: CsgOp::Intersection,
            children,
            ..
        } if !o.inverse => children.iter().for_each(|c| half_spaces(c, out)),
        _ => {}
    }
}

/// `half_spaces` for a window: a bounded shape turned off the axes gives the faces of its own
/// box turned into world planes rather than its world bounds' faces (the box of the turned box,
/// up to 1.7 times wider on each axis). objects/quartic/trough's saddle inside its rotated
/// `UnitBox` is then solved only where the box is, not across the corners of its world box.
/// Not shared with the culls' `half_spaces`: their vertex search wants few, axis planes.
fn window_half_spaces(o: &Object, out: &mut Vec<(DVec3, f64)>) {
    if let (ObjKind::Shape(s, _), Some(t)) = (&o.kind, &o.transform) {
        let turned = (0..3).any(|c| (0..3).any(|r| r != c && t.m.col(c)[r] != 0.0));
        let local = s.bounds();
        if turned
            && !o.inverse
            && o.bounds.is_finite()
            && !o.bounds.is_empty()
            && local.is_finite()
            && !local.is_empty()
        {
            // Each face n·q <= d of the local box, with q = inv(p): (invᵀn)·p <= d − n·inv(0).
            for (axis, n) in [DVec3::X, DVec3::Y, DVec3::Z].into_iter().enumerate() {
                for (n, d) in [(n, local.max[axis]), (-n, -local.min[axis])] {
                    let (n, d) = (t.normal(n), d - n.dot(t.inv_point(DVec3::ZERO)));
                    if n.is_finite() && d.is_finite() && n != DVec3::ZERO {
                        out.push((n, d));
                    }
                }
            }
            return;
        }
    }
    half_spaces(o, out)
}

/// The half-space n·p <= d holding what a subtracted member leaves, when the member's solid is
/// itself a half-space (a plane, not clipped): a plane's inside is n·p < d (`geom::plane`),
/// so what lies outside it is n·p >= d, and the padded box holds that closed side.
fn complement(o: &Object) -> Option<(DVec3, f64)> {
    let ObjKind::Shape(s, _) = &o.kind else {
        return None;
    };
    if !o.clip.is_empty() || o.bounds.is_finite() {
        return None;
    }
    let h = s.half_space()?;
    let (n, d) = if o.inverse { (-h.0, -h.1) } else { h };
    let (n, d) = match &o.transform {
        Some(t) => (t.normal(n), d - n.dot(t.inv_point(DVec3::ZERO))),
        None => (n, d),
    };
    (n.is_finite() && d.is_finite() && n != DVec3::ZERO).then_some((-n, -d))
}

#[cfg(test)]
#[path = "cull_tests.rs"]
mod tests;

#[path = "cull_polyhedron.rs"]
mod polyhedron;

#[path = "cull_local.rs"]
mod local;
pub use local::LocalBox;

#[cfg(test)]
#[path = "cull_window_tests.rs"]
mod window_tests;
