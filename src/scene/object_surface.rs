//! What a hit on a leaf's surface shows: its world-space normal, its uv point and its
//! texture (a mesh triangle's or blob component's own, the interior texture from inside).
//!
//! Moved out of object.rs unchanged (it had grown past 800 lines): the search code stays
//! there, the per-hit surface questions the shading asks are here.

use crate::math::{by_coordinates, DVec3};
use crate::scene::desc::Texture;
use crate::scene::object::{ObjKind, Object, SurfaceHit};

impl Object {
    /// Unit world-space normal at a hit on this leaf, outward (before face-forwarding).
    pub fn normal(&self, p: DVec3, h: &SurfaceHit) -> DVec3 {
        let ObjKind::Shape(s, _) = &self.kind else {
            return DVec3::Z;
        };
        // The shape's answer read one coordinate at a time: shapes return it through memory,
        // often stored 8 bytes at a time, and the 16-byte load of x-y LLVM read it back with
        // could not be forwarded from those stores (a fifth to a third of this function's
        // samples on camera/panoramic, camera/shear and advanced/bwstripe).
        let n = match &self.transform {
            Some(t) => t.normal(by_coordinates(&s.normal(t.inv_point(p), &h.hit))),
            None => by_coordinates(&s.normal(p, &h.hit)),
        };
        // A normal of exactly unit squared length (a box's faces, a plane given as x, y or z,
        // untransformed or moved and turned by quarter turns) is what `normalize_or_zero`
        // would return to the bit: its length is sqrt(1) = 1 and 1/1 = 1, and n·1 is n. The
        // square root and the division are skipped, a dependent chain of ~40 cycles on
        // every hit of such a surface (perf: this function's share of the time was 2.5 times
        // its share of the instructions on incdemo/debug).
        let n = if n.length_squared() == 1.0 {
            n
        } else {
            n.normalize_or_zero()
        };
        if h.flip {
            -n
        } else {
            n
        }
    }

    /// The shape's (u, v, 0) at a hit for `uv_mapping`, or None where the shape has no uv
    /// coordinates.
    pub fn uv_point(&self, p: DVec3, h: &SurfaceHit) -> Option<DVec3> {
        let ObjKind::Shape(s, _) = &self.kind else {
            return None;
        };
        let local = self.transform.as_ref().map_or(p, |t| t.inv_point(p));
        s.uv(local, &h.hit).map(|[u, v]| DVec3::new(u, v, 0.0))
    }

    /// The texture of the surface at a hit, `inside` when the ray meets it from inside the
    /// object (its normal points away from the ray): the `interior_texture` there, if any.
    pub fn texture_facing(&self, h: &SurfaceHit, inside: bool) -> &Texture {
        match &self.interior_texture {
            Some(t) if inside => t,
            _ => self.texture_at(h),
        }
    }

    /// The texture at a hit: a mesh triangle's own texture, a blob component's, else the
    /// object's.
    pub fn texture_at(&self, h: &SurfaceHit) -> &Texture {
        if let Some(t) = self
            .blob
            .as_ref()
            .and_then(|b| b.1.get(h.hit.part as usize))
        {
            return t;
        }
        if let Some((data, texes)) = self.mesh.as_deref() {
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
