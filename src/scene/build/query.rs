//! The built scene's queries: the nearest crossing along a ray, the objects a ray may meet
//! (for shadow rays), and which solids hold a point. The walks over the BVH and the
//! unbounded objects live here; building the scene is in the parent module.

use std::sync::Arc;

use crate::geom::bvh::{Avx, Lanes, Recip, Sse};
use crate::geom::plane::Plane;
use crate::geom::sphere::Sphere;
use crate::geom::Hit;
use crate::math::{Aabb, DVec3, Ray};
use crate::scene::children::{fresh_copy, fresh_hit};
use crate::scene::object::{ObjKind, Object, Scratch, SurfaceHit};
use glam::DVec4;

use super::moved::{moved_ray, only_moved};
use super::Scene;

/// A BVH primitive's name (`Bvh::rename`) has this bit set when its object is an
/// untransformed, unclipped sphere, whose crossings the walks then ask inline; the bits
/// below `MOVED` are the object's index in `Scene::objects`.
const SPHERE: u32 = 1 << 31;

/// Or this bit, for an unclipped sphere that is only moved (`moved::only_moved`), asked inline
/// on the object-space ray `moved::moved_ray` makes. A bit apart from `SPHERE` and tested
/// after it, so that a plain sphere's leaf costs no more than before (its own bit, `SPHERE`
/// and `MOVED` together cost two instructions a plain sphere in mirror_spheres).
const MOVED: u32 = 1 << 30;

/// The name of `objects[obj]` as a BVH primitive: its index, with `SPHERE` for a plain sphere
/// (a shape that is one, `Shape::as_sphere`, whose `Arc` holds that very sphere), `MOVED`
/// for such a sphere whose transform only moves it.
pub(super) fn leaf_name(objects: &[Object], obj: usize) -> u32 {
    let name = u32::try_from(obj)
        .ok()
        .filter(|&n| n < MOVED)
        .expect("fewer than 2^30 objects");
    let o = &objects[obj];
    let sphere = match (&o.kind, o.clip.is_empty()) {
        (ObjKind::Shape(shape, _), true) => shape
            .as_sphere()
            .is_some_and(|s| std::ptr::addr_eq(s, Arc::as_ptr(shape))),
        _ => false,
    };
    match &o.transform {
        _ if !sphere => name,
        None => name | SPHERE,
        Some(t) if only_moved(t) => name | MOVED,
        Some(_) => name,
    }
}

/// An object a walk offers (`Scene::for_each_candidate_recip`), and whether the BVH named it
/// a sphere asked inline (`leaf_name`: `SPHERE` or `MOVED`), which its `sphere` then gives.
#[derive(Clone, Copy)]
pub struct Candidate<'a> {
    pub obj: &'a Object,
    sphere: bool,
    moved: bool,
}

impl<'a> Candidate<'a> {
    /// The object's sphere when it is a plain or moved one. Asked where it is needed (after
    /// the cheap tests of the object's flags), so the walk branches on the name's bits only
    /// there.
    #[inline(always)]
    pub fn sphere(self) -> Option<SphereAt<'a>> {
        // Each case makes its own answer, `moved` a constant in it: LLVM then keeps the plain
        // sphere's path apart from the moved one's (through one `Option` of the offset, both
        // went through a test of it: ~4 instructions a plain sphere).
        if self.sphere {
            Some(SphereAt {
                sphere: self.shape_sphere(),
                obj: self.obj,
                moved: false,
            })
        } else if self.moved {
            Some(SphereAt {
                sphere: self.shape_sphere(),
                obj: self.obj,
                moved: true,
            })
        } else {
            None
        }
    }

    /// The sphere of an object `leaf_name` named `SPHERE` or `MOVED`.
    #[inline(always)]
    fn shape_sphere(self) -> &'a Sphere {
        let ObjKind::Shape(shape, _) = &self.obj.kind else {
            // SAFETY: `leaf_name` names only shapes `SPHERE` or `MOVED`, and objects are not
            // replaced once the scene is built.
            unsafe { std::hint::unreachable_unchecked() }
        };
        debug_assert!(shape
            .as_sphere()
            .is_some_and(|s| std::ptr::addr_eq(s, Arc::as_ptr(shape))));
        // SAFETY: `leaf_name` named `SPHERE` or `MOVED` only objects whose shape's `Arc` holds
        // a `Sphere` at this address (`as_sphere` answered with it); an `Arc`'s value never
        // changes.
        unsafe { &*(Arc::as_ptr(shape) as *const Sphere) }
    }
}

/// A sphere the walks ask inline, its object, and whether the object moves it (`MOVED`: then
/// asked on the object-space ray, `moved::moved_ray`).
#[derive(Clone, Copy)]
pub struct SphereAt<'a> {
    sphere: &'a Sphere,
    obj: &'a Object,
    moved: bool,
}

impl SphereAt<'_> {
    /// The object's `first_hit` crossing: `Sphere::intersect_first` on the object-space ray,
    /// which for a moved sphere `moved_ray` makes as `Object::local_ray` does.
    #[inline(always)]
    pub fn first_t(self, ray: &Ray, tmax: f64) -> Option<f64> {
        if self.moved {
            moved_first_t(self.sphere, self.obj, ray, tmax)
        } else {
            self.sphere.first_t(ray, tmax)
        }
    }

    /// The object's `any_hit`: `Sphere::any_hit` on the object-space ray.
    #[inline(always)]
    pub fn blocks(self, ray: &Ray, tmax: f64) -> bool {
        if self.moved {
            moved_blocks(self.sphere, self.obj, ray, tmax)
        } else {
            self.sphere.blocks(ray, tmax)
        }
    }
}

/// The inverse transform's offset of an object `leaf_name` named `MOVED`.
#[inline(always)]
fn offset(obj: &Object) -> &DVec4 {
    let Some(t) = &obj.transform else {
        // SAFETY: `leaf_name` names `MOVED` only objects with a transform, and objects are
        // not replaced once the scene is built.
        unsafe { std::hint::unreachable_unchecked() }
    };
    debug_assert!(only_moved(t));
    &t.inv.w_axis
}

/// `SphereAt::first_t` of a moved sphere, out of line: inlined, the moved ray's values (and
/// the registers they took) cost every ray of a scene without moved spheres ~4 instructions
/// of set-up and each plain sphere ~1 (mirror_spheres +0.3 %); a call here is ~10 where the
/// object's general path was ~130.
#[inline(never)]
fn moved_first_t(sphere: &Sphere, obj: &Object, ray: &Ray, tmax: f64) -> Option<f64> {
    sphere.first_t(&moved_ray(ray, offset(obj)), tmax)
}

/// `SphereAt::blocks` of a moved sphere, out of line as `moved_first_t` is.
#[inline(never)]
fn moved_blocks(sphere: &Sphere, obj: &Object, ray: &Ray, tmax: f64) -> bool {
    sphere.blocks(&moved_ray(ray, offset(obj)), tmax)
}

/// An object outside the BVH (unbounded: planes, quadrics, their CSG), tested by every ray
/// before the walk.
pub(super) struct Unbounded {
    /// Its index in `Scene::objects`.
    obj: usize,
    /// A box holding all its crossings and its inside, when one is known
    /// (`scene::cull::object_cull`): rays and points outside skip the object.
    cull: Option<Aabb>,
    /// The plane, for an untransformed, unclipped shape that is one: its crossing is asked
    /// inline, where the call through the shape's table (and, for shadow rays, the caller's
    /// closure) cost ~30 instructions a camera ray and ~80 a shadow ray in mirror_spheres,
    /// whose floor every ray asks.
    plane: Option<Plane>,
}

impl Unbounded {
    /// Object `obj` of `objects`. A shape's `half_space` is its own plane (only `Plane` has
    /// one, and `scene::faces` answers for such a shape with `Plane`'s arithmetic already).
    pub(super) fn of(objects: &[Object], obj: usize) -> Unbounded {
        let o = &objects[obj];
        let plane = match (&o.kind, o.clip.is_empty(), &o.transform) {
            (ObjKind::Shape(shape, _), true, None) => {
                shape.half_space().map(Plane::from_half_space)
            }
            _ => None,
        };
        Unbounded {
            obj,
            cull: crate::scene::cull::object_cull(o),
            plane,
        }
    }

    /// Whether the segment (0, tmax) surely meets none of the object's crossings: outside its
    /// cull box, or a plane it does not cross there (`Plane::hit_t`, which is what its
    /// `intersect_first`, `any_hit` and `intersect_all` report).
    #[inline(always)]
    fn missed(&self, ray: &Ray, r: &Recip, tmax: f64) -> bool {
        self.cull
            .is_some_and(|c| c.hit(ray.origin, r.inv, tmax).is_none())
            || self
                .plane
                .is_some_and(|p| p.hit_t(ray).is_none_or(|t| t >= tmax))
    }
}

impl Scene {
    /// Nearest crossing along the ray closer than `tmax`: the copy compiled with AVX where the
    /// CPU has it (`first_hit_avx`), else the build's own (x86-64-v2), chosen by the flag the
    /// scene read once (`avx`). Inlined: a function asking the CPU and calling the copy cost
    /// ~20 instructions a ray (its frame and the 56-byte answer passed through).
    #[inline(always)]
    pub fn first_hit<'a>(
        &'a self,
        ray: &Ray,
        tmax: f64,
        scratch: &mut Scratch<'a>,
    ) -> Option<SurfaceHit<'a>> {
        #[cfg(target_arch = "x86_64")]
        if self.avx {
            // SAFETY: the scene found that the CPU has AVX.
            return unsafe { self.first_hit_avx(ray, tmax, scratch) };
        }
        self.first_hit_base(ray, tmax, scratch)
    }

    /// Whether the CPU has AVX, as `math::has_avx` said when the scene was built: callers
    /// with copies of their own (the shadow rays') choose by it without asking the CPU.
    #[inline(always)]
    pub fn avx(&self) -> bool {
        self.avx
    }

    /// `first_hit_in` in three-operand AVX encodings, no other change (no fused multiply-add:
    /// the same operations, so the same bits). The walk's node test holds six broadcast
    /// vectors, the distance limit and a zero across the loop; with SSE's two-operand forms
    /// some were spilled and reloaded every node, and each minimum and maximum needed a copy
    /// (`Plain2` also reads each face straight into the subtraction).
    ///
    /// # Safety
    /// The CPU must have AVX.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    unsafe fn first_hit_avx<'a>(
        &'a self,
        ray: &Ray,
        tmax: f64,
        scratch: &mut Scratch<'a>,
    ) -> Option<SurfaceHit<'a>> {
        // SAFETY: the caller says the CPU has AVX.
        self.first_hit_in(unsafe { Avx::new() }, ray, tmax, scratch)
    }

    /// `first_hit_in` for CPUs without AVX.
    #[inline(never)]
    fn first_hit_base<'a>(
        &'a self,
        ray: &Ray,
        tmax: f64,
        scratch: &mut Scratch<'a>,
    ) -> Option<SurfaceHit<'a>> {
        self.first_hit_in(Sse, ray, tmax, scratch)
    }

    /// The object a BVH primitive's name (`leaf_name`) stands for, and whether it is a
    /// sphere asked inline.
    #[inline(always)]
    fn leaf(&self, name: usize) -> Candidate<'_> {
        Candidate {
            obj: &self.objects[name & !((SPHERE | MOVED) as usize)],
            sphere: name & SPHERE as usize != 0,
            moved: name & MOVED as usize != 0,
        }
    }

    /// `first_hit`'s work, inlined into each of its copies (`lanes`: the walk's node test).
    #[inline(always)]
    fn first_hit_in<'a>(
        &'a self,
        lanes: impl Lanes,
        ray: &Ray,
        tmax: f64,
        scratch: &mut Scratch<'a>,
    ) -> Option<SurfaceHit<'a>> {
        // Nothing to hit (a scene of sky, background or fog only): no reciprocal of the
        // direction, whose three divisions were a tenth of such a scene's time.
        if self.unbounded.is_empty() && self.bvh.is_empty() {
            return None;
        }
        let mut best: Option<SurfaceHit<'a>> = None;
        let mut tmax = tmax;
        let r = Recip::of(ray);
        for u in &self.unbounded {
            if u.cull
                .is_some_and(|c| c.hit(ray.origin, r.inv, tmax).is_none())
            {
                continue;
            }
            let obj = &self.objects[u.obj];
            // A plane's `leaf_first_hit` (its `intersect_first`), inline.
            // Each kind's answer is written into `best` where it is made: through one
            // `Option` for both, it was built and then copied (~20 instructions a crossing).
            match &u.plane {
                Some(p) => {
                    if let Some(t) = p.hit_t(ray).filter(|&t| t < tmax) {
                        tmax = t;
                        best = Some(SurfaceHit {
                            t,
                            obj,
                            hit: Hit::new(t),
                            flip: obj.inverse,
                        });
                    }
                }
                None => {
                    if let Some(h) = leaf_first_hit(obj, ray, tmax, scratch) {
                        tmax = h.t;
                        best = Some(h);
                    }
                }
            }
        }
        // Inlined into the walk, which LLVM stopped doing once the walk had two copies (one
        // for rays with a flat axis): a call per leaf otherwise.
        self.bvh.traverse_recip(
            lanes,
            ray,
            &r,
            tmax,
            #[inline(always)]
            |prim, tmax| {
                let c = self.leaf(prim);
                let obj = c.obj;
                match c.sphere() {
                    // `Sphere::intersect_first`, inline.
                    Some(s) => {
                        if let Some(t) = s.first_t(ray, *tmax) {
                            *tmax = t;
                            best = Some(SurfaceHit {
                                t,
                                obj,
                                hit: Hit::new(t),
                                flip: obj.inverse,
                            });
                        }
                    }
                    None => {
                        if let Some(h) = leaf_first_hit(obj, ray, *tmax, scratch) {
                            *tmax = h.t;
                            best = Some(h);
                        }
                    }
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
        let mut f = f;
        self.for_each_candidate_recip(Sse, ray, &Recip::of(ray), tmax, |c| f(c.obj));
    }

    /// `for_each_candidate` with the ray's `Recip` already worked out: a shadow ray's caller
    /// has it for its cached blocker's box. Always inlined, so that the shadow ray's AVX copy
    /// walks in AVX and its callback is not called out of line (`lanes`: see
    /// `Bvh::traverse_recip`). `f` gets each object as a `Candidate`, which tells a plain
    /// sphere (an untransformed, unclipped one, whose `any_hit` is `Sphere::blocks`).
    #[inline(always)]
    pub fn for_each_candidate_recip<'a>(
        &'a self,
        lanes: impl Lanes,
        ray: &Ray,
        r: &Recip,
        tmax: f64,
        mut f: impl FnMut(Candidate<'a>) -> bool,
    ) {
        for u in &self.unbounded {
            // An object the ray misses adds nothing, opaque or not: no crossing of it within
            // tmax to block or filter the light.
            if !u.missed(ray, r, tmax)
                && f(Candidate {
                    obj: &self.objects[u.obj],
                    sphere: false,
                    moved: false,
                })
            {
                return;
            }
        }
        self.bvh.traverse_recip(
            lanes,
            ray,
            r,
            tmax,
            #[inline(always)]
            |prim, _| f(self.leaf(prim)),
        );
    }

    /// Whether any top-level object that may hold `p` (the unbounded ones past their cull
    /// boxes, the bounded ones by the BVH's point query) satisfies `test`.
    fn any_object_at(&self, p: DVec3, test: impl Fn(&Object) -> bool) -> bool {
        if self
            .unbounded
            .iter()
            .any(|u| u.cull.is_none_or(|c| c.contains(p)) && test(&self.objects[u.obj]))
        {
            return true;
        }
        let mut found = false;
        self.bvh.visit_point(p, |k| {
            found = test(self.leaf(k).obj);
            found
        });
        found
    }

    /// Calls `f` with every top-level object whose bounds hold `p` (it decides itself
    /// whether `p` is inside).
    pub fn each_object_at<'s>(&'s self, p: DVec3, mut f: impl FnMut(&'s Object)) {
        for u in &self.unbounded {
            if u.cull.is_none_or(|c| c.contains(p)) {
                f(&self.objects[u.obj]);
            }
        }
        self.bvh.visit_point(p, |k| {
            f(self.leaf(k).obj);
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
    // Both answers are read field by field (`fresh_hit`, `fresh_copy`): the callee has just
    // stored them so, and the walk's copy of the whole read `Hit`'s t and u as one 16-byte
    // load and the padding after `flip` as two overlapping 4-byte pieces, neither of which
    // the store buffer forwards (4-5 % of `first_hit_avx`'s samples on camera/cylinder3 and
    // advanced/cliche/sign). Built from fields, the walk's `best` holds no padding to copy.
    match (&obj.kind, obj.clip.is_empty(), &obj.transform) {
        (ObjKind::Shape(shape, _), true, None) => shape
            .intersect_first(ray, tmax, &mut scratch.hits)
            .as_ref()
            .map(|hit| {
                let hit = fresh_hit(hit);
                SurfaceHit {
                    t: hit.t,
                    obj,
                    hit,
                    flip: obj.inverse,
                }
            }),
        _ => obj.first_hit(ray, tmax, scratch).as_ref().map(fresh_copy),
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
        // A clipped shape without a window, as `Object::any_hit` would ask it after its tests
        // for unions and CSG nodes.
        (ObjKind::Shape(shape, None), false, _) => {
            obj.clipped_leaf_any_hit(&**shape, ray, tmax, scratch)
        }
        _ => obj.any_hit(ray, tmax, scratch),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::test_rng::Lcg;

    /// Planes of every kind beside a few bounded objects: plain, `inverse`, tilted and far,
    /// no_shadow, filtering, turned and clipped ones.
    const SCENE: &str = r#"
        plane { y, 0 pigment { rgb 1 } }
        plane { -z, -4 inverse pigment { rgb 1 } }
        plane { <1, 2, 3>, 1e6 pigment { rgb 1 } }
        plane { x, 2 no_shadow pigment { rgb 1 } }
        plane { <0, 1, -1>, 0.5 pigment { rgbf <1, 1, 1, 0.5> } }
        plane { y, 1 rotate 20*x translate 3*z pigment { rgb 1 } }
        plane { x, -3 clipped_by { sphere { 0, 20 } } pigment { rgb 1 } }
        sphere { <0, 1, 2>, 1 pigment { rgb 1 } }
        box { -1, 1 translate <2, 2, 5> pigment { rgb 1 } }
    "#;

    fn scene() -> Scene {
        crate::scene::csg_hit::tests::built(SCENE)
    }

    /// A plane asked inline (`Unbounded::plane`) answers as its object does: `first_hit`'s
    /// crossing bit for bit, and where `missed` says so, no crossing for `any_hit` or
    /// `all_hits`; the scene's `first_hit` is the nearest of every object's, bit for bit.
    /// Rays from anywhere (on the planes too), some along the axes, `tmax` finite and not.
    #[test]
    fn inline_planes_answer_as_their_objects() {
        let scene = scene();
        let inline = scene.unbounded.iter().filter(|u| u.plane.is_some()).count();
        // The clipped plane is bounded by its clipping sphere (in the BVH); the turned one
        // keeps its transform and is asked through its object.
        assert_eq!((scene.unbounded.len(), inline), (6, 5));
        let mut rng = Lcg(17);
        let mut s = Scratch::default();
        let (mut crossed, mut missed) = (0, 0);
        for k in 0..20_000usize {
            let mut origin = rng.vec(10.0);
            if k % 4 == 0 {
                origin.y = 0.0;
            }
            let mut dir = rng.vec(2.0);
            match k % 7 {
                0 => dir = DVec3::new(0.0, -1.0, 0.0),
                1 => dir.x = 0.0,
                _ => {}
            }
            let ray = Ray::new(origin, dir);
            let r = Recip::of(&ray);
            let tmax = if k % 3 == 0 {
                f64::INFINITY
            } else {
                rng.next() * 20.0
            };
            for u in &scene.unbounded {
                let obj = &scene.objects[u.obj];
                if let Some(p) = &u.plane {
                    let want = obj.first_hit(&ray, tmax, &mut s).map(|h| h.t.to_bits());
                    let got = p.hit_t(&ray).filter(|&t| t < tmax).map(f64::to_bits);
                    assert_eq!(want, got, "k={k}");
                }
                if u.missed(&ray, &r, tmax) {
                    assert!(!obj.any_hit(&ray, tmax, &mut s), "k={k}");
                    obj.all_hits(&ray, tmax, &mut s);
                    assert!(s.surface.is_empty(), "k={k}");
                    missed += 1;
                } else {
                    crossed += 1;
                }
            }
            let mut want: Option<(f64, *const Object)> = None;
            for o in &scene.objects {
                if let Some(h) = o.first_hit(&ray, tmax, &mut s) {
                    if want.is_none_or(|w| h.t < w.0) {
                        want = Some((h.t, o));
                    }
                }
            }
            let got = scene
                .first_hit(&ray, tmax, &mut s)
                .map(|h| (h.t, h.obj as *const Object));
            assert_eq!(
                want.map(|w| (w.0.to_bits(), w.1)),
                got.map(|g| (g.0.to_bits(), g.1)),
                "k={k}"
            );
        }
        assert!(crossed > 10_000 && missed > 10_000, "{crossed} {missed}");
    }

    /// Only unclipped spheres, untransformed or only moved, are named `SPHERE` or `MOVED`; the walks' inline sphere tests answer as the objects do: the scene's
    /// `first_hit` is the nearest of every object's (bit for bit), and each candidate's
    /// `sphere().blocks` is its `any_hit`. Some rays have signed zeros in their origin and
    /// direction, which the moved spheres' object-space rays must keep as the matrix does.
    #[test]
    fn plain_spheres_answer_as_their_objects() {
        let scene = crate::scene::csg_hit::tests::built(
            r#"
            sphere { <0, 1, 2>, 1 pigment { rgb 1 } }
            sphere { <2, 0, 1>, 0.5 inverse pigment { rgb 1 } }
            sphere { 0, 1 scale <1, 2, 1> translate <-2, 0, 0> pigment { rgb 1 } }
            sphere { 0, 1 translate <0, -2, 0> pigment { rgb 1 } }
            sphere { <1, 1, -2>, 1 clipped_by { plane { y, 1 } } pigment { rgb 1 } }
            union { sphere { <3, 3, 3>, 1 } box { 2, 4 } pigment { rgb 1 } }
            box { -1, 1 translate <-3, 2, 4> pigment { rgb 1 } }
            sphere { <-1, -1, -1>, 0.7 pigment { rgbf <1, 1, 1, 0.5> } }
            sphere { <0.5, 0, 0>, 0.8 translate <1, 0, -3> translate <0, 0.1, 0> inverse
                pigment { rgb 1 } }
            sphere { <0, 0, 0.3>, 0.6 translate <-1.3, 2.7, -0.4> pigment { rgbf 0.5 } }
        "#,
        );
        let named: Vec<u32> = (0..scene.objects.len())
            .map(|i| leaf_name(&scene.objects, i) >> 30)
            .collect();
        // A stretched sphere keeps its transform: asked through its object, as are clipped
        // ones and CSG members. 2 is `SPHERE`, 1 `MOVED`.
        assert_eq!(named, [2, 2, 0, 1, 0, 0, 0, 2, 1, 1], "{named:?}");
        let moved: Vec<*const Object> = (0..scene.objects.len())
            .filter(|&i| named[i] == 1)
            .map(|i| &scene.objects[i] as *const Object)
            .collect();
        let mut rng = Lcg(29);
        let mut s = Scratch::default();
        let (mut hits, mut blocked, mut moved_hits) = (0, 0, 0);
        for k in 0..20_000usize {
            let mut origin = rng.vec(6.0);
            let mut dir = rng.vec(2.0);
            if k % 9 == 0 {
                dir.y = 0.0;
            }
            match k % 5 {
                1 => (origin.x, dir.z) = (-0.0, -0.0),
                2 => (origin.y, dir.x) = (0.0, -0.0),
                3 => (origin.z, dir.y) = (-0.0, 0.0),
                _ => {}
            }
            let ray = Ray::new(origin, dir);
            let tmax = if k % 3 == 0 {
                f64::INFINITY
            } else {
                rng.next() * 8.0
            };
            let mut want: Option<(f64, *const Object, bool)> = None;
            for o in &scene.objects {
                if let Some(h) = o.first_hit(&ray, tmax, &mut s) {
                    if want.is_none_or(|w| h.t < w.0) {
                        want = Some((h.t, h.obj, h.flip));
                    }
                }
            }
            let got = scene
                .first_hit(&ray, tmax, &mut s)
                .map(|h| (h.t.to_bits(), h.obj as *const Object, h.flip));
            assert_eq!(want.map(|w| (w.0.to_bits(), w.1, w.2)), got, "k={k}");
            hits += usize::from(got.is_some());
            moved_hits += usize::from(got.is_some_and(|g| moved.contains(&g.1)));
            let r = Recip::of(&ray);
            scene.for_each_candidate_recip(Sse, &ray, &r, tmax, |c| {
                if let Some(sp) = c.sphere() {
                    let any = c.obj.any_hit(&ray, tmax, &mut s);
                    assert_eq!(sp.blocks(&ray, tmax), any, "k={k}");
                    blocked += usize::from(any);
                }
                false
            });
        }
        assert!(hits > 2_000 && blocked > 1_000, "{hits} {blocked}");
        assert!(moved_hits > 500, "{moved_hits}");
    }
}
