//! CSG members that share one transform, asked with one ray in their space instead of one
//! per member: a node transformed as a whole (advanced/whiltile's tiles: a box and two
//! cylinders scaled, moved and turned together) carries the same inverse matrix in each
//! member, and its search transformed the ray (`local_ray`) once per member.
//!
//! A node without index (not a union) keeps, in its `Cull`, a class per member (`Shared`):
//! members that are leaves without clipping, window or face whose inverse matrices are the
//! same bit for bit are one class, named by its first member. Its `first_hit` runs an
//! instance of `csg_first_hit` that transforms the ray once per class (`shared_hits`). The
//! answer is the same bit for bit: the same matrix applied to the same ray gives the same
//! local ray, and every other step is `member_hits`' leaf path. The inside tests stay with
//! `csg_keeps`: a version that made each point in a class's space once per question
//! (`csg_keeps_shared`) cost more than it saved (most questions end at the first member
//! asked, the rejecter, so there was seldom a second member of the class to share with).

use crate::math::{Aabb, Ray};
use crate::scene::children::ChildIndex;
use crate::scene::desc::CsgOp;
use crate::scene::faces::Faces;
use crate::scene::object::{ObjKind, Object, Scratch, SurfaceHit};

/// Which search a node other than a union runs (`Object::node_search`), decided once the
/// indexes are attached (`children::attach_indexes`).
#[derive(Clone, Copy, PartialEq, Eq, Debug, Default)]
pub enum Search {
    /// `csg_first_hit` without folding, box members or classes.
    #[default]
    Plain,
    /// A member is folded (`Cull::folds`) and no member is a box.
    Folds,
    /// Some member is a box (`Cull::boxes`): `boxes_search`.
    Boxes,
    /// Members share transforms (`Cull::shared`).
    Shared,
}

/// A member outside every class: asked as before.
pub const NONE: u8 = u8::MAX;

/// The class of each member, by member number (`NONE` for members asked as before).
pub struct Shared {
    classes: Box<[u8]>,
}

impl Shared {
    /// The classes of `children` (with `faces`, the node's plane members), when at least two
    /// members share a transform.
    pub fn of(children: &[Object], faces: Option<&Faces>) -> Option<Shared> {
        if children.len() >= NONE as usize {
            return None;
        }
        // The leaves `member_hits` and `Object::inside` answer on their short path, with a
        // transform: the inverse matrix's bits.
        let key = |j: usize, c: &Object| match (&c.kind, &c.transform) {
            (ObjKind::Shape(_, None), Some(t))
                if c.clip.is_empty() && faces.and_then(|f| f.get(j)).is_none() =>
            {
                Some(t.inv.to_cols_array().map(f64::to_bits))
            }
            _ => None,
        };
        let keys: Vec<_> = children
            .iter()
            .enumerate()
            .map(|(j, c)| key(j, c))
            .collect();
        let mut classes = vec![NONE; children.len()].into_boxed_slice();
        let mut any = false;
        for j in 0..keys.len() {
            let Some(k) = &keys[j] else { continue };
            if let Some(first) = (0..j).find(|&m| keys[m].as_ref() == Some(k)) {
                classes[first] = first as u8;
                classes[j] = first as u8;
                any = true;
            }
        }
        any.then_some(Shared { classes })
    }

    /// Member `i`'s class (`NONE` if it has none).
    #[inline(always)]
    pub fn class(&self, i: usize) -> u8 {
        self.classes.get(i).copied().unwrap_or(NONE)
    }
}

/// The ray in a class's space, made for the last class asked.
pub(super) struct LocalRay {
    class: u8,
    ray: Ray,
}

impl LocalRay {
    pub(super) fn new(ray: &Ray) -> LocalRay {
        LocalRay {
            class: NONE,
            ray: *ray,
        }
    }
}

/// `member_hits(c, None, ray, tmax, s)` of a member `c` of class `class` (a leaf without
/// clipping, window or face, with a transform): the ray transformed once per class.
#[inline(always)]
pub(super) fn shared_hits<'a>(
    c: &'a Object,
    class: u8,
    local: &mut LocalRay,
    ray: &Ray,
    tmax: f64,
    s: &mut Scratch<'a>,
) {
    let (ObjKind::Shape(shape, _), Some(t)) = (&c.kind, &c.transform) else {
        unreachable!("classes hold transformed leaves")
    };
    if local.class != class {
        local.ray = t.inv_ray(ray);
        local.class = class;
    }
    s.hits.clear();
    shape.intersect_all(&local.ray, &mut s.hits);
    c.take_hits(tmax, s);
}

impl Object {
    /// `first_hit` of a node other than a union, past its polyhedron case: the search its
    /// `Cull::search` names, the folding, box and class code compiled out of the instances
    /// that have none (through the folding one, objects/csg/intee1 and cliptst2 cost 2-3 %
    /// more instructions).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    pub(super) fn node_search<'a>(
        &'a self,
        op: CsgOp,
        children: &'a [Object],
        index: Option<&ChildIndex>,
        culls: (Option<&Aabb>, Option<&Faces>),
        ray: &Ray,
        tmax: f64,
        s: &mut Scratch<'a>,
    ) -> Option<SurfaceHit<'a>> {
        let search = match &self.kind {
            ObjKind::Csg { cull: Some(c), .. } => c.search,
            _ => Search::Plain,
        };
        match search {
            // Box members without dispatch (`csg_boxes`); such nodes have no index.
            Search::Boxes => self.boxes_search(op, children, culls, ray, tmax, s),
            Search::Folds => {
                self.csg_first_hit::<true, false, false>(op, children, index, culls, ray, tmax, s)
            }
            // Nodes with classes have no index either.
            Search::Shared => {
                self.csg_first_hit::<false, false, true>(op, children, None, culls, ray, tmax, s)
            }
            Search::Plain => {
                self.csg_first_hit::<false, false, false>(op, children, index, culls, ray, tmax, s)
            }
        }
    }

    /// This node's member classes, if it has any (`Cull::shared`).
    #[inline(always)]
    pub(super) fn shared_members(&self) -> Option<&Shared> {
        match &self.kind {
            ObjKind::Csg { cull: Some(c), .. } => c.shared.as_ref(),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::test_rng::Lcg;
    use crate::math::EPSILON;
    use crate::scene::csg_hit::tests::built;

    /// Nodes whose members share transforms: whiltile's tile, a difference with an inverse
    /// member and a member of its own, a merge, a clipped intersection, and a node whose
    /// plane members are faces. Each gets its classes and the `Shared` search.
    const SCENE: &str = r#"
        intersection { box { -1, 1 } cylinder { -2*x, 2*x, 0.9 } cylinder { -2*z, 2*z, 0.9 }
                       sphere { 0, 2.0 translate 2.6*y inverse } scale <0.5, 0.2, 0.5>
                       translate <3, 0, -2> rotate y*30 }
        difference { sphere { 0, 1 } cylinder { -2*x, 2*x, 0.4 } cylinder { -2*y, 2*y, 0.4 inverse }
                     sphere { 0.5, 0.5 scale 2 } scale <1, 2, 0.7> rotate <10, 20, 30> translate 0.3 }
        merge { sphere { 0, 1 } cylinder { -2*x, 2*x, 0.5 } cone { -2*z, 0.6, 2*z, 0.1 }
                rotate <0, 45, 10> scale 1.5 }
        intersection { sphere { 0, 1 } cylinder { -2*x, 2*x, 0.8 } torus { 0.8, 0.3 }
                       clipped_by { plane { y, 0.3 } } rotate x*20 translate y }
        intersection { plane { y, 0.5 } plane { -y, 0.5 } sphere { 0, 1 } cylinder { -2*x, 2*x, 0.8 }
                       scale <1, 1, 2> rotate y*20 }
    "#;

    fn search(o: &Object) -> Search {
        match &o.kind {
            ObjKind::Csg { cull: Some(c), .. } => c.search,
            _ => Search::Plain,
        }
    }

    /// The classes hold exactly the transformed leaves that share their inverse matrix bit
    /// for bit: whiltile's box and cylinders, not its sphere (moved first).
    #[test]
    fn classes_are_the_shared_transforms() {
        let scene = built(SCENE);
        for (n, o) in scene.objects.iter().enumerate() {
            assert_eq!(search(o), Search::Shared, "object {n}");
        }
        let m = scene.objects[0].shared_members().unwrap();
        assert_eq!(
            (0..4).map(|j| m.class(j)).collect::<Vec<_>>(),
            [0, 0, 0, NONE]
        );
        let m = scene.objects[1].shared_members().unwrap();
        assert_eq!(
            (0..4).map(|j| m.class(j)).collect::<Vec<_>>(),
            [0, 0, 0, NONE]
        );
        // Untransformed members and nodes made of boxes keep their searches.
        let other = built(
            "intersection { sphere { 0, 1 } cylinder { -2*x, 2*x, 0.5 } }
             intersection { sphere { 0, 1 } cylinder { -2*x, 2*x, 0.5 rotate y*10 } rotate x*5 }",
        );
        assert!(other.objects.iter().all(|o| search(o) == Search::Plain));
    }

    /// The `Shared` search answers as `all_hits` and the plain search do, bit for bit (the
    /// same crossing, surface and side), with rays from inside, outside and along axes
    /// through the members.
    #[test]
    fn shared_search_matches_all_hits() {
        let scene = built(SCENE);
        let mut rng = Lcg(17);
        let (mut sa, mut sb) = (Scratch::default(), Scratch::default());
        let key = |h: Option<SurfaceHit>| {
            h.map(|h| (h.t.to_bits(), h.flip, h.obj as *const Object, h.hit.part))
        };
        for (n, o) in scene.objects.iter().enumerate() {
            let ObjKind::Csg {
                op,
                children,
                cull: Some(cull),
                ..
            } = &o.kind
            else {
                panic!("object {n} is not a node with a cull");
            };
            let centre = (o.bounds.min + o.bounds.max) * 0.5;
            let mut hits = 0;
            for k in 0..30_000 {
                let from = centre + rng.vec([1.0, 3.0, 8.0][k % 3]);
                let d = match k % 4 {
                    0 => [DVec3::X, DVec3::NEG_Y, DVec3::Z][k % 3],
                    1 => centre + rng.vec(0.5) - from,
                    _ => rng.vec(2.0),
                };
                let ray = Ray::new(from, d);
                let tmax = [f64::INFINITY, 3.0, rng.next() * 20.0][k % 3];
                sb.surface.clear();
                o.all_hits(&ray, tmax, &mut sb);
                let want = key(sb
                    .surface
                    .iter()
                    .filter(|h| o.clip.is_empty() || h.t > EPSILON)
                    .min_by(|a, b| a.t.total_cmp(&b.t))
                    .copied());
                sb.surface.clear();
                let culls = (cull.aabb.as_ref(), cull.faces.as_ref());
                let plain = o.csg_first_hit::<false, false, false>(
                    *op, children, None, culls, &ray, tmax, &mut sb,
                );
                assert_eq!(key(plain), want, "object {n}, ray {k}");
                let got = o.first_hit(&ray, tmax, &mut sa);
                assert_eq!(key(got), want, "object {n}, ray {k}");
                assert!(sa.surface.is_empty() && sa.csg_order.is_empty());
                hits += want.is_some() as usize;
            }
            assert!(hits > 3_000, "object {n}: {hits}");
        }
    }
}
