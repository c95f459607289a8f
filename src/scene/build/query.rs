//! The built scene's queries: the nearest crossing along a ray, the objects a ray may meet
//! (for shadow rays), and which solids hold a point. The walks over the BVH and the
//! unbounded objects live here; building the scene is in the parent module.

use crate::math::{DVec3, Ray};
use crate::scene::object::{ObjKind, Object, Scratch, SurfaceHit};

use super::Scene;

impl Scene {
    /// Nearest crossing along the ray closer than `tmax`.
    pub fn first_hit<'a>(
        &'a self,
        ray: &Ray,
        tmax: f64,
        scratch: &mut Scratch<'a>,
    ) -> Option<SurfaceHit<'a>> {
        // Nothing to hit (a scene of sky, background or fog only): no reciprocal of the
        // direction, whose three divisions were a tenth of such a scene's time.
        if self.unbounded.is_empty() && self.bounded.is_empty() {
            return None;
        }
        let mut best: Option<SurfaceHit<'a>> = None;
        let mut tmax = tmax;
        let inv_dir = crate::geom::bvh::ray_recip(ray);
        for (&i, cull) in self.unbounded.iter().zip(&self.unbounded_cull) {
            if cull.is_some_and(|c| c.hit(ray.origin, inv_dir, tmax).is_none()) {
                continue;
            }
            if let Some(h) = leaf_first_hit(&self.objects[i], ray, tmax, scratch) {
                tmax = h.t;
                best = Some(h);
            }
        }
        // Inlined into the walk, which LLVM stopped doing once the walk had two copies (one
        // for rays with a flat axis): a call per leaf otherwise.
        self.bvh.traverse_inv(
            ray,
            inv_dir,
            tmax,
            #[inline(always)]
            |prim, tmax| {
                if let Some(h) =
                    leaf_first_hit(&self.objects[self.bounded[prim]], ray, *tmax, scratch)
                {
                    *tmax = h.t;
                    best = Some(h);
                }
                false
            },
        );
        best
    }

    /// Calls `f` for every object whose bounds the segment (0, tmax) may cross; `f` returns
    /// true to stop (an opaque blocker was found).
    pub fn for_each_candidate<'a>(
        &'a self,
        ray: &Ray,
        tmax: f64,
        f: impl FnMut(&'a Object) -> bool,
    ) {
        self.for_each_candidate_inv(ray, crate::geom::bvh::ray_recip(ray), tmax, f);
    }

    /// `for_each_candidate` with the ray's reciprocal direction (`ray_recip`) already
    /// computed: a shadow ray's caller has it for its cached blocker's box.
    pub fn for_each_candidate_inv<'a>(
        &'a self,
        ray: &Ray,
        inv_dir: DVec3,
        tmax: f64,
        mut f: impl FnMut(&'a Object) -> bool,
    ) {
        for (&i, cull) in self.unbounded.iter().zip(&self.unbounded_cull) {
            // An object the ray misses adds nothing, opaque or not.
            let missed = cull.is_some_and(|c| c.hit(ray.origin, inv_dir, tmax).is_none());
            if !missed && f(&self.objects[i]) {
                return;
            }
        }
        self.bvh.traverse_inv(ray, inv_dir, tmax, |prim, _| {
            f(&self.objects[self.bounded[prim]])
        });
    }

    /// Whether any top-level object that may hold `p` (the unbounded ones past their cull
    /// boxes, the bounded ones by the BVH's point query) satisfies `test`.
    fn any_object_at(&self, p: DVec3, test: impl Fn(&Object) -> bool) -> bool {
        if self
            .unbounded
            .iter()
            .zip(&self.unbounded_cull)
            .any(|(&i, cull)| cull.is_none_or(|c| c.contains(p)) && test(&self.objects[i]))
        {
            return true;
        }
        let mut found = false;
        self.bvh.visit_point(p, |k| {
            found = test(&self.objects[self.bounded[k]]);
            found
        });
        found
    }

    /// Calls `f` with every top-level object whose bounds hold `p` (it decides itself
    /// whether `p` is inside).
    pub fn each_object_at<'s>(&'s self, p: DVec3, mut f: impl FnMut(&'s Object)) {
        for (&i, cull) in self.unbounded.iter().zip(&self.unbounded_cull) {
            if cull.is_none_or(|c| c.contains(p)) {
                f(&self.objects[i]);
            }
        }
        self.bvh.visit_point(p, |k| {
            f(&self.objects[self.bounded[k]]);
            false
        });
    }

    /// Whether `p` is inside an object that is not `hollow`, where POV-Ray computes no
    /// atmosphere.
    pub fn inside_solid(&self, p: DVec3) -> bool {
        self.any_object_at(p, |o| o.solid_at(p))
    }

    /// Whether `p` is inside any object other than `leaf` (CSG nodes holding `leaf` are
    /// judged by their other members): `Object::inside_without` over every object, with the
    /// tree holding `leaf` found through the parent table and the others through the BVH.
    pub fn inside_other(&self, p: DVec3, leaf: &Object) -> bool {
        // `leaf` and its nodes up to the top-level object holding it.
        let mut chain = vec![leaf as *const Object as usize];
        loop {
            let at = *chain.last().unwrap_or(&0);
            match self.parents.binary_search_by(|e| e.0.cmp(&at)) {
                Ok(k) => chain.push(self.parents[k].1),
                Err(_) => break,
            }
        }
        let root = *chain.last().unwrap_or(&0);
        let is_root = |o: &Object| o as *const Object as usize == root;
        // Outside the tree holding `leaf`, inside_without is inside; it is false outside a
        // bounded object's box, so the BVH's point query finds every object that can say yes.
        if self.any_object_at(p, |o| !is_root(o) && o.inside(p)) {
            return true;
        }
        match self.objects.iter().find(|o| is_root(o)) {
            Some(o) => o.inside_without_chain(p, &chain),
            None => false,
        }
    }
}

/// `Object::first_hit` with the case of nearly every top-level object inlined into the walks:
/// an untransformed, unclipped shape, whose first crossing is its shape's. The call and the
/// checks of the general function (CSG, clipping, the object-space ray) cost ~45
/// instructions an object (mirror_spheres' camera and reflected rays each ask its floor
/// plane and ~0.6 spheres).
#[inline(always)]
fn leaf_first_hit<'a>(
    obj: &'a Object,
    ray: &Ray,
    tmax: f64,
    scratch: &mut Scratch<'a>,
) -> Option<SurfaceHit<'a>> {
    match (&obj.kind, obj.clip.is_empty(), &obj.transform) {
        (ObjKind::Shape(shape, _), true, None) => shape
            .intersect_first(ray, tmax, &mut scratch.hits)
            .map(|hit| SurfaceHit {
                t: hit.t,
                obj,
                hit,
                flip: obj.inverse,
            }),
        _ => obj.first_hit(ray, tmax, scratch),
    }
}

/// `Object::any_hit`, likewise with an untransformed, unclipped shape's case inlined (shadow
/// rays): the shape's own `any_hit`, which is what the general function asks of it.
#[inline(always)]
pub(crate) fn leaf_any_hit<'a>(
    obj: &'a Object,
    ray: &Ray,
    tmax: f64,
    scratch: &mut Scratch<'a>,
) -> bool {
    match (&obj.kind, obj.clip.is_empty(), &obj.transform) {
        (ObjKind::Shape(shape, _), true, None) => shape.any_hit(ray, tmax, &mut scratch.hits),
        _ => obj.any_hit(ray, tmax, scratch),
    }
}
