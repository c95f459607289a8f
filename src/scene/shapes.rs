//! Maps shape descriptions to the geometry module's shapes.

use std::sync::Arc;

use crate::geom::{
    algebraic::Algebraic, boxes::BoxShape, cone::Cone, cylinder::Cylinder, disc::Disc, mesh::Mesh,
    plane::Plane, sphere::Sphere, text::Text, torus::Torus, triangle::Triangle, Shape,
};
use crate::scene::desc::ShapeDesc;

/// A shape for a non-CSG, non-light description.
pub fn make_shape(d: &ShapeDesc) -> Arc<dyn Shape> {
    match d {
        ShapeDesc::Sphere { center, radius } => Arc::new(Sphere::new(*center, *radius)),
        ShapeDesc::Plane { normal, distance } => Arc::new(Plane::new(*normal, *distance)),
        ShapeDesc::Box { corner1, corner2 } => Arc::new(BoxShape::new(*corner1, *corner2)),
        ShapeDesc::Cylinder {
            base,
            cap,
            radius,
            open,
        } => Arc::new(Cylinder::new(*base, *cap, *radius, *open)),
        ShapeDesc::Cone {
            base,
            base_radius,
            cap,
            cap_radius,
            open,
        } => Arc::new(Cone::new(*base, *base_radius, *cap, *cap_radius, *open)),
        ShapeDesc::Disc {
            center,
            normal,
            radius,
            hole_radius,
        } => Arc::new(Disc::new(*center, *normal, *radius, *hole_radius)),
        ShapeDesc::Torus {
            major,
            minor,
            sturm,
        } => Arc::new(Torus::new(*major, *minor, *sturm)),
        ShapeDesc::Triangle { p } => Arc::new(Triangle::new(*p)),
        ShapeDesc::SmoothTriangle(t) => Arc::new(Triangle::smooth(t.p, t.n)),
        ShapeDesc::Mesh(data) => Arc::new(Mesh::new(data.clone())),
        ShapeDesc::Algebraic {
            order,
            terms,
            sturm,
        } => Arc::new(Algebraic::new(*order, terms, *sturm)),
        ShapeDesc::Text(data) => Arc::new(Text::new(data.clone())),
        ShapeDesc::Prism(s) => s.clone(),
        ShapeDesc::Lathe(s) => s.clone(),
        ShapeDesc::Sor(s) => s.clone(),
        ShapeDesc::Polygon(s) => s.clone(),
        ShapeDesc::SphereSweep(s) => s.clone(),
        ShapeDesc::Superellipsoid { e, n } => {
            Arc::new(crate::geom::superellipsoid::Superellipsoid::new(*e, *n))
        }
        ShapeDesc::Blob { data, .. } => Arc::new(crate::geom::blob::Blob::new(data)),
        ShapeDesc::HeightField(data) => {
            Arc::new(crate::geom::height_field::HeightField::new(data.clone()))
        }
        ShapeDesc::Isosurface(data) => Arc::new(crate::geom::isosurface::Isosurface::new(data)),
        ShapeDesc::Prebuilt(s) => s.clone(),
        ShapeDesc::Csg { .. } | ShapeDesc::Light(_) => {
            unreachable!("CSG and lights are built by scene::build")
        }
    }
}

impl ShapeDesc {
    /// The first shape under this one (CSG members without a texture of their own included)
    /// for which lancer has no uv coordinates, named as the scene language names it.
    pub fn first_without_uv(&self) -> Option<&'static str> {
        Some(match self {
            ShapeDesc::Sphere { .. } | ShapeDesc::Mesh(_) | ShapeDesc::Light(_) => return None,
            ShapeDesc::Csg { children, .. } => {
                return children
                    .iter()
                    .filter(|c| c.texture.is_none())
                    .find_map(|c| c.shape.first_without_uv())
            }
            ShapeDesc::Plane { .. } => "plane",
            ShapeDesc::Box { .. } => "box",
            ShapeDesc::Cylinder { .. } => "cylinder",
            ShapeDesc::Cone { .. } => "cone",
            ShapeDesc::Disc { .. } => "disc",
            ShapeDesc::Torus { .. } => "torus",
            ShapeDesc::Triangle { .. } | ShapeDesc::SmoothTriangle(_) => "triangle",
            ShapeDesc::Algebraic { .. } => "polynomial",
            ShapeDesc::Text(_) => "text",
            ShapeDesc::Prism(_) => "prism",
            ShapeDesc::Lathe(_) => "lathe",
            ShapeDesc::Sor(_) => "sor",
            ShapeDesc::Polygon(_) => "polygon",
            ShapeDesc::SphereSweep(_) => "sphere_sweep",
            ShapeDesc::Superellipsoid { .. } => "superellipsoid",
            ShapeDesc::HeightField(_) => "height_field",
            ShapeDesc::Isosurface(_) => "isosurface",
            ShapeDesc::Blob { .. } => "blob",
            ShapeDesc::Prebuilt(_) => "this object",
        })
    }
}
