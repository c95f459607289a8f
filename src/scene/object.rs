//! Runtime objects: a shape placed in the world with its texture and flags, or a CSG node.
//!
//! Only leaves carry transforms (CSG transforms were pushed down to the leaves by the parser),
//! so every CSG inside test and hit filter works in world space.

use std::sync::Arc;

use crate::geom::{Hit, Shape};
use crate::math::{Aabb, DVec3, Ray, Transform};
use crate::scene::desc::{CsgOp, MeshData, Texture};

pub enum ObjKind {
    Shape(Arc<dyn Shape>),
    Csg { op: CsgOp, children: Vec<Object> },
}

pub struct Object {
    pub kind: ObjKind,
    /// Object to world; `None` when identity, to skip two matrix products per ray.
    pub transform: Option<Transform>,
    pub texture: Arc<Texture>,
    /// Per-triangle textures of a mesh, indexed by `MeshData::triangles[i].texture`.
    pub mesh: Option<(Arc<MeshData>, Vec<Arc<Texture>>)>,
    pub ior: f64,
    pub no_shadow: bool,
    pub inverse: bool,
    /// World-space bounds (`Aabb::INFINITE` for unbounded objects).
    pub bounds: Aabb,
    /// Whether any colour of the texture has filter or transmit, so shadow rays must look at
    /// the surface colour instead of stopping at the first crossing.
    pub transparent: bool,
}

/// A crossing of a ray with a leaf object.
#[derive(Clone, Copy)]
pub struct SurfaceHit<'a> {
    pub t: f64,
    pub obj: &'a Object,
    pub hit: Hit,
    /// The surface belongs to a subtracted CSG operand, so its normal points inwards.
    pub flip: bool,
}

impl Object {
    fn local_ray(&self, ray: &Ray) -> Ray {
        match &self.transform {
            Some(t) => t.inv_ray(ray),
            None => *ray,
        }
    }

    /// Nearest crossing with `t` in (EPSILON, tmax).
    pub fn first_hit<'a>(
        &'a self,
        ray: &Ray,
        tmax: f64,
        scratch: &mut Vec<Hit>,
    ) -> Option<SurfaceHit<'a>> {
        match &self.kind {
            ObjKind::Shape(s) => {
                let r = self.local_ray(ray);
                s.intersect_first(&r, tmax, scratch).map(|hit| SurfaceHit {
                    t: hit.t,
                    obj: self,
                    hit,
                    flip: self.inverse,
                })
            }
            ObjKind::Csg {
                op: CsgOp::Union,
                children,
            } => {
                let mut best: Option<SurfaceHit<'a>> = None;
                let mut tmax = tmax;
                for c in children {
                    if c.bounds.hit(ray.origin, ray.dir.recip(), tmax).is_none() {
                        continue;
                    }
                    if let Some(h) = c.first_hit(ray, tmax, scratch) {
                        tmax = h.t;
                        best = Some(h);
                    }
                }
                best
            }
            ObjKind::Csg { .. } => {
                let mut all = Vec::new();
                self.all_hits(ray, &mut all, scratch);
                all.into_iter()
                    .filter(|h| h.t < tmax)
                    .min_by(|a, b| a.t.total_cmp(&b.t))
            }
        }
    }

    /// Every crossing with t > EPSILON, in no particular order.
    pub fn all_hits<'a>(
        &'a self,
        ray: &Ray,
        out: &mut Vec<SurfaceHit<'a>>,
        scratch: &mut Vec<Hit>,
    ) {
        match &self.kind {
            ObjKind::Shape(s) => {
                let r = self.local_ray(ray);
                scratch.clear();
                s.intersect_all(&r, scratch);
                out.extend(scratch.iter().map(|&hit| SurfaceHit {
                    t: hit.t,
                    obj: self,
                    hit,
                    flip: self.inverse,
                }));
            }
            ObjKind::Csg { op, children } => {
                let mut mine: Vec<SurfaceHit<'a>> = Vec::new();
                for (i, c) in children.iter().enumerate() {
                    let start = mine.len();
                    c.all_hits(ray, &mut mine, scratch);
                    let keep_from = start;
                    let mut k = keep_from;
                    for j in keep_from..mine.len() {
                        let h = mine[j];
                        let p = ray.at(h.t);
                        let others = children.iter().enumerate().filter(|(o, _)| *o != i);
                        let keep = match op {
                            CsgOp::Union => true,
                            CsgOp::Merge => others.clone().all(|(_, o)| !o.inside(p)),
                            CsgOp::Intersection => others.clone().all(|(_, o)| o.inside(p)),
                            CsgOp::Difference => {
                                if i == 0 {
                                    others.clone().all(|(_, o)| !o.inside(p))
                                } else {
                                    children[0].inside(p)
                                        && others
                                            .clone()
                                            .filter(|(o, _)| *o != 0)
                                            .all(|(_, o)| !o.inside(p))
                                }
                            }
                        };
                        if keep {
                            let mut h = h;
                            if *op == CsgOp::Difference && i > 0 {
                                h.flip = !h.flip;
                            }
                            mine[k] = h;
                            k += 1;
                        }
                    }
                    mine.truncate(k);
                }
                if self.inverse {
                    for h in &mut mine {
                        h.flip = !h.flip;
                    }
                }
                out.extend(mine);
            }
        }
    }

    pub fn inside(&self, p: DVec3) -> bool {
        let r = match &self.kind {
            ObjKind::Shape(s) => {
                let lp = match &self.transform {
                    Some(t) => t.inv_point(p),
                    None => p,
                };
                s.inside(lp)
            }
            ObjKind::Csg { op, children } => match op {
                CsgOp::Union | CsgOp::Merge => children.iter().any(|c| c.inside(p)),
                CsgOp::Intersection => !children.is_empty() && children.iter().all(|c| c.inside(p)),
                CsgOp::Difference => {
                    children.first().is_some_and(|c| c.inside(p))
                        && !children[1..].iter().any(|c| c.inside(p))
                }
            },
        };
        // A shape's own `inverse` is folded in here; CSG nodes likewise.
        r != self.inverse
    }

    /// Like `inside`, but as if `leaf` were not part of this object.
    pub fn inside_without(&self, p: DVec3, leaf: &Object) -> bool {
        if std::ptr::eq(self, leaf) {
            return false;
        }
        match &self.kind {
            ObjKind::Csg {
                op: CsgOp::Union | CsgOp::Merge,
                children,
            } if self.contains(leaf) => {
                children.iter().any(|c| c.inside_without(p, leaf)) != self.inverse
            }
            _ if self.contains(leaf) => false,
            _ => self.inside(p),
        }
    }

    fn contains(&self, leaf: &Object) -> bool {
        std::ptr::eq(self, leaf)
            || match &self.kind {
                ObjKind::Csg { children, .. } => children.iter().any(|c| c.contains(leaf)),
                ObjKind::Shape(_) => false,
            }
    }

    /// Unit world-space normal at a hit on this leaf, outward (before face-forwarding).
    pub fn normal(&self, p: DVec3, h: &SurfaceHit) -> DVec3 {
        let ObjKind::Shape(s) = &self.kind else {
            return DVec3::Z;
        };
        let n = match &self.transform {
            Some(t) => t.normal(s.normal(t.inv_point(p), &h.hit)),
            None => s.normal(p, &h.hit),
        };
        let n = n.normalize_or_zero();
        if h.flip {
            -n
        } else {
            n
        }
    }

    /// The texture at a hit: a mesh triangle's own texture, else the object's.
    pub fn texture_at(&self, h: &SurfaceHit) -> &Texture {
        if let Some((data, texes)) = &self.mesh {
            if let Some(ti) = data
                .triangles
                .get(h.hit.part as usize)
                .and_then(|t| t.texture)
            {
                if let Some(t) = texes.get(ti as usize) {
                    return t;
                }
            }
        }
        &self.texture
    }
}
