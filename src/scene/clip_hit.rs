//! Crossings of objects with `clipped_by` that are not CSG intersections, differences or
//! merges: a clipped leaf's or union's nearest crossing (`clipped_first_hit`) and a clipped
//! leaf's shadow test (`clipped_leaf_any_hit`). Split from csg_hit.rs, which searches the
//! CSG nodes.

use crate::geom::{Hit, Shape};
use crate::math::{Ray, Slabs, EPSILON};
use crate::scene::desc::CsgOp;
use crate::scene::faces;
use crate::scene::object::{each_member, member_hits, ObjKind, Object, Scratch, SurfaceHit};

impl Object {
    /// `any_hit` of a leaf `shape` (this object's) with `clipped_by` and without window:
    /// whether `clipped_first_hit` would find a crossing, that is whether any crossing
    /// `all_hits_unclipped` lists (the shape's `intersect_all` below `tmax`) has t > EPSILON
    /// and lies inside every clipping object. The shape asks them in its own order
    /// (`Shape::any_kept`): a clipped torus stops polishing at the first one kept.
    #[inline(never)]
    pub(crate) fn clipped_leaf_any_hit(
        &self,
        shape: &dyn Shape,
        ray: &Ray,
        tmax: f64,
        s: &mut Scratch<'_>,
    ) -> bool {
        let mut local = None;
        let r = self.local_ray(ray, &mut local);
        shape.any_kept(r, tmax, &mut s.hits, &mut |t| {
            t > EPSILON && self.clip.iter().all(|c| c.inside(ray.at(t)))
        })
    }

    /// `first_hit` of a leaf or union with `clipped_by`: the nearest of its crossings with
    /// t > EPSILON inside every clipping object (ties to the earlier in `all_hits`'s order, as
    /// `min_by` over it), asking the clip only about crossings that would be nearer. With
    /// `nearest` false, any such crossing (`any_hit`): a union's members are then asked one
    /// at a time, stopping at the first crossing the clip keeps.
    pub(super) fn clipped_first_hit<'a>(
        &'a self,
        ray: &Ray,
        tmax: f64,
        s: &mut Scratch<'a>,
        nearest: bool,
    ) -> Option<SurfaceHit<'a>> {
        let start = s.surface.len();
        let kept_t = |t: f64| t > EPSILON && self.clip.iter().all(|c| c.inside(ray.at(t)));
        let kept = |h: &SurfaceHit| kept_t(h.t);
        if let (ObjKind::Shape(shape, window), true) = (&self.kind, nearest) {
            // The running minimum below over the shape's own list, which `all_hits_unclipped`
            // would copy into surface hits (those below `tmax`, in order): the surface hit is
            // made only for the crossing kept (a clipped plane's camera rays pushed, read and
            // dropped one each).
            self.shape_hits(&**shape, window.as_deref(), ray, tmax, &mut s.hits);
            let mut best: Option<Hit> = None;
            for k in 0..s.hits.len() {
                let h = &s.hits[k];
                let t = h.t;
                if t < tmax && best.is_none_or(|b| t.total_cmp(&b.t).is_lt()) && kept_t(t) {
                    best = Some(Hit {
                        t,
                        part: h.part,
                        uv: h.uv,
                    });
                }
            }
            return best.map(|hit| SurfaceHit {
                t: hit.t,
                obj: self,
                hit,
                flip: self.inverse,
            });
        }
        if let ObjKind::Csg {
            op: CsgOp::Union,
            children,
            index,
            cull,
        } = &self.kind
        {
            if !nearest {
                // `all_hits_unclipped`'s tests of a union, member by member.
                let inv_dir = ray.dir.recip();
                if cull
                    .as_ref()
                    .and_then(|c| c.aabb.as_ref())
                    .is_some_and(|c| c.hit(ray.origin, inv_dir, tmax).is_none())
                {
                    return None;
                }
                let slabs = Slabs::new(ray.origin, inv_dir);
                // Plane members through their faces, as `all_hits_unclipped` asks them.
                let faces = cull.as_ref().and_then(|c| c.faces.as_ref());
                let ray_faces = faces.filter(|_| faces::ray_ok(ray));
                let mut found = None;
                each_member(children, index.as_deref(), ray, tmax, s, |c, i, s| {
                    if found.is_some() || !slabs.hits(&c.bounds, tmax) {
                        return;
                    }
                    let from = s.surface.len();
                    member_hits(c, ray_faces.and_then(|f| f.get(i)), ray, tmax, s);
                    found = s.surface[from..].iter().find(|h| kept(h)).copied();
                    s.surface.truncate(from);
                });
                return found;
            }
        }
        self.all_hits_unclipped(ray, tmax, s);
        let best = if nearest {
            // A running minimum that asks the clip only about crossings nearer than the best
            // so far: one that is not cannot become the minimum, kept or not, and the strict
            // comparison keeps the earliest of equal ones.
            let mut best: Option<SurfaceHit<'a>> = None;
            for h in &s.surface[start..] {
                if best.is_none_or(|b| h.t.total_cmp(&b.t).is_lt()) && kept(h) {
                    best = Some(*h);
                }
            }
            best
        } else {
            s.surface[start..].iter().find(|h| kept(h)).copied()
        };
        s.surface.truncate(start);
        best
    }
}
