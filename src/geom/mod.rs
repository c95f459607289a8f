//! Shapes in their own canonical space, and the contract the renderer and CSG rely on.
//!
//! A shape reports *every* crossing of a ray (CSG needs all of them, not just the first), can
//! say whether a point is inside it, and gives the normal at a crossing it reported. Placement
//! in the world (transform), textures and flags belong to `scene::Object`, not to shapes.

use crate::math::{Aabb, DVec3, Ray};

/// One crossing of a ray with a surface.
#[derive(Clone, Copy, Debug)]
pub struct Hit {
    /// Distance along the ray in units of the ray's direction (unnormalised).
    pub t: f64,
    /// Shape-specific data needed later for the normal: a face index for boxes, a triangle index
    /// for meshes, which sub-surface of a cylinder or cone was hit, ...
    pub part: u32,
    /// Barycentric (u, v) for triangles, so smooth normals need no second intersection.
    pub uv: [f64; 2],
}

impl Hit {
    pub fn new(t: f64) -> Hit {
        Hit {
            t,
            part: 0,
            uv: [0.0; 2],
        }
    }
    pub fn with_part(t: f64, part: u32) -> Hit {
        Hit {
            t,
            part,
            uv: [0.0; 2],
        }
    }
}

pub trait Shape: Send + Sync + std::fmt::Debug {
    /// Bounds in the shape's own space; `Aabb::INFINITE` for unbounded shapes (planes).
    fn bounds(&self) -> Aabb;
    /// Appends every crossing with `t > EPSILON` (in any order) to `out`.
    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>);
    /// Nearest crossing with `EPSILON < t < tmax`. Shapes override when they can do better.
    fn intersect_first(&self, ray: &Ray, tmax: f64, scratch: &mut Vec<Hit>) -> Option<Hit> {
        scratch.clear();
        self.intersect_all(ray, scratch);
        scratch
            .iter()
            .filter(|h| h.t > crate::math::EPSILON && h.t < tmax)
            .min_by(|a, b| a.t.total_cmp(&b.t))
            .copied()
    }
    /// A CSG search's listing (`csg_first_hit`): appends to `out` crossings `intersect_all`
    /// lists, as it lists them (the same bits, in its order), among them the first by `t`,
    /// then by place in that list, of those with `t < tmax` that `keep` holds for, if any.
    /// The search takes the least kept crossing over all members, so the others cannot matter.
    /// The default lists them all; shapes that find their nearest crossings first may append
    /// that one alone. `keep` has no side effect on the answer; `scratch` is the shape's.
    fn gather_kept(
        &self,
        ray: &Ray,
        _tmax: f64,
        out: &mut Vec<Hit>,
        _scratch: &mut Vec<Hit>,
        _keep: &mut dyn FnMut(f64) -> bool,
    ) {
        self.intersect_all(ray, out)
    }
    /// `intersect_first(..).is_some()` (shadow rays), for shapes that can tell sooner.
    fn any_hit(&self, ray: &Ray, tmax: f64, scratch: &mut Vec<Hit>) -> bool {
        self.intersect_first(ray, tmax, scratch).is_some()
    }
    /// Whether `keep` holds for the `t` of some crossing `intersect_all` lists with
    /// `t < tmax` (CSG and clipped shadow rays: is any crossing on the surface). Which
    /// crossings are asked, and in what order, is the shape's choice: `keep` has no side
    /// effect on the answer. Shapes that find their crossings one at a time stop at the first
    /// kept one.
    fn any_kept(
        &self,
        ray: &Ray,
        tmax: f64,
        scratch: &mut Vec<Hit>,
        keep: &mut dyn FnMut(f64) -> bool,
    ) -> bool {
        any_listed_kept(self, ray, tmax, scratch, keep)
    }
    /// `intersect_all`, but crossings with `t` outside `[lo, hi]` may be left out (a clipped
    /// object's crossings outside its clipping box): those inside come out exactly as
    /// `intersect_all` gives them.
    fn intersect_all_within(&self, ray: &Ray, _lo: f64, _hi: f64, out: &mut Vec<Hit>) {
        self.intersect_all(ray, out)
    }
    /// `intersect_all`, but crossings with `t` at or past `tmax`, or at most `EPSILON`, may be
    /// left out (the caller drops them): a sphere's shadow ray with both ends well inside it.
    fn intersect_all_before(&self, ray: &Ray, _tmax: f64, out: &mut Vec<Hit>) {
        self.intersect_all(ray, out)
    }
    /// Whether `intersect_all_within` saves work (the scene then finds the boxes for it).
    fn windowed(&self) -> bool {
        false
    }
    /// Whether `p` lies inside the shape (POV-Ray's "inside" test, used by CSG and interiors).
    fn inside(&self, p: DVec3) -> bool;
    /// Outward normal at a point the shape reported, not necessarily unit length.
    fn normal(&self, p: DVec3, hit: &Hit) -> DVec3;
    /// A half-space `n·p <= d` holding the solid, for shapes that are one (planes): CSG
    /// intersections of them get finite boxes from it, and `scene::faces` answers for such a
    /// shape with `Plane`'s arithmetic.
    fn half_space(&self) -> Option<(DVec3, f64)> {
        None
    }
    /// A ball `(centre, radius)` holding the solid, for shapes that are one (spheres): an
    /// intersection's other members are asked only for crossings on the ray's chord of it.
    fn ball(&self) -> Option<(DVec3, f64)> {
        None
    }
    /// This shape as a `Sphere` (only `Sphere` answers): the scene's walks ask an untransformed
    /// sphere's crossings inline (`scene::build::query`), without the call through the table.
    fn as_sphere(&self) -> Option<&sphere::Sphere> {
        None
    }
    /// This shape as an `Algebraic` (only `Algebraic` answers): a CSG node of quadrics asks
    /// its members' crossings four at a time (`algebraic::crossings_lanes`).
    fn as_algebraic(&self) -> Option<&algebraic::Algebraic> {
        None
    }
    /// Whether `inside` says yes only within `bounds` (up to the rounding of its own test):
    /// true for the shapes whose test is a few products and comparisons that cannot stray
    /// (boxes, cylinders), so that a CSG node may reason with their local bounds in
    /// another member's space (`scene::csg_lead::shut_of`).
    fn inside_bounded(&self) -> bool {
        false
    }
    /// This shape as a box (`BoxShape`, not empty), so that a CSG node may ask its box
    /// members with the box's own code and no dispatch (`scene::csg_boxes`).
    fn solid_box(&self) -> Option<boxes::BoxShape> {
        None
    }
    /// Bounds of the solid on the axes where it has them (infinite on the others), for
    /// unbounded shapes that are bounded across some axes (a quadric cylinder): clipping by
    /// them gives finite boxes. Only used to skip work, never as `bounds`.
    fn slab_bounds(&self) -> Aabb {
        self.bounds()
    }
    /// Bounds of the part of the solid inside `b` (both in the shape's space), for the same
    /// use as `slab_bounds`: a hyperboloid between two planes is bounded across them although
    /// it has no slab of its own.
    fn slab_bounds_within(&self, b: &Aabb) -> Aabb {
        self.slab_bounds().intersection(b)
    }
    /// The surface's (u, v) texture coordinates at a point it reported, for `uv_mapping`;
    /// None for shapes POV-Ray 3.7 gives no uv coordinates.
    fn uv(&self, _p: DVec3, _hit: &Hit) -> Option<[f64; 2]> {
        None
    }
}

/// `Shape::any_kept` from the full list of crossings: the default, and the fallback of shapes
/// whose lazy walk does not apply to every ray or setting (a `sturm` blob).
pub fn any_listed_kept<S: Shape + ?Sized>(
    shape: &S,
    ray: &Ray,
    tmax: f64,
    scratch: &mut Vec<Hit>,
    keep: &mut dyn FnMut(f64) -> bool,
) -> bool {
    scratch.clear();
    shape.intersect_all(ray, scratch);
    scratch.iter().any(|h| h.t < tmax && keep(h.t))
}

pub mod algebraic;
pub mod bernstein;
pub mod bicubic;
pub mod blob;
pub mod boxes;
pub mod bvh;
pub mod cone;
pub mod cylinder;
pub mod disc;
pub mod font;
pub mod glyph_bands;
pub mod height_field;
pub mod isosurface;
pub mod julia;
pub mod lathe;
pub mod mesh;
pub mod ovus;
pub mod plane;
pub mod poly;
pub mod polygon;
pub mod prism;
pub mod sor;
pub mod sphere;
pub mod sphere_sweep;
pub mod spline2d;
pub mod superellipsoid;
pub mod text;
pub mod torus;
pub mod triangle;

/// Helpers for the geometry tests: a small deterministic generator (no extra crates) and
/// polynomials built from their roots.
#[cfg(test)]
pub(crate) mod test_rng {
    use crate::math::DVec3;

    pub struct Lcg(pub u64);

    impl Lcg {
        pub fn next(&mut self) -> f64 {
            self.0 = self
                .0
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (self.0 >> 11) as f64 / (1u64 << 53) as f64
        }
        pub fn vec(&mut self, s: f64) -> DVec3 {
            DVec3::new(self.next() - 0.5, self.next() - 0.5, self.next() - 0.5) * s
        }
    }

    /// Expands `prod (x - r_i)` into ascending coefficients.
    pub fn from_roots(roots: &[f64]) -> Vec<f64> {
        let mut c = vec![1.0];
        for &r in roots {
            let mut n = vec![0.0; c.len() + 1];
            for (i, &ci) in c.iter().enumerate() {
                n[i + 1] += ci;
                n[i] -= r * ci;
            }
            c = n;
        }
        c
    }

    /// Asserts that `first(cut)` is the first of `all` above `cut`, bit for bit, with no cut
    /// and with three cuts drawn in (lo, hi): a root finder that stops at the first root a
    /// caller keeps must agree with the one that finds them all.
    pub fn check_first_root(
        rng: &mut Lcg,
        all: &[f64],
        (lo, hi): (f64, f64),
        first: impl Fn(f64) -> Option<f64>,
        what: &str,
    ) {
        for k in 0..4 {
            let cut = if k == 0 {
                f64::NEG_INFINITY
            } else {
                lo + (hi - lo) * rng.next()
            };
            let want = all.iter().copied().find(|&x| x > cut);
            assert_eq!(
                want.map(f64::to_bits),
                first(cut).map(f64::to_bits),
                "{what} {lo} {hi} {cut}"
            );
        }
    }

    /// Asserts that a window's roots `part` are roots of `all` and hold every one of `all`
    /// in [wlo, whi].
    pub fn check_window(all: &[f64], part: &[f64], (wlo, whi): (f64, f64), what: &str) {
        for r in part {
            assert!(all.contains(r), "{what}: {r} not in {all:?}");
        }
        for r in all.iter().filter(|&&r| r >= wlo && r <= whi) {
            assert!(
                part.contains(r),
                "{what} [{wlo}, {whi}]: {r} lost, {part:?}"
            );
        }
    }

    /// The nearest of all a shape's crossings in (EPSILON, tmax): what `intersect_first` must
    /// answer, bit for bit, for the solvers that find it without every crossing.
    pub fn nearest_of_all<S: super::Shape + ?Sized>(
        shape: &S,
        ray: &crate::math::Ray,
        tmax: f64,
    ) -> Option<super::Hit> {
        let mut all = Vec::new();
        shape.intersect_all(ray, &mut all);
        all.into_iter()
            .filter(|h| h.t > crate::math::EPSILON && h.t < tmax)
            .min_by(|a, b| a.t.total_cmp(&b.t))
    }
}
