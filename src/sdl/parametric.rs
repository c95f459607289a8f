//! Reading `parametric { }`: a surface x(u,v), y(u,v), z(u,v) over a (u, v) rectangle, kept
//! inside its container. lancer draws it as a fine smooth mesh carrying (u, v) for
//! uv_mapping, clipped by the container, where POV-Ray subdivides (u, v) space per ray; the
//! two agree to well under a pixel at ordinary sizes.

use std::sync::Arc;

use crate::func::Function;
use crate::geom::isosurface::Container;
use crate::math::DVec3;
use crate::scene::desc::{MeshData, ObjectDesc, ShapeDesc};

use super::parser::{PResult, Parser};
use super::source::Span;

/// Grid cells along u and along v.
const CELLS: usize = 256;

impl Parser {
    /// `parametric { function {x} function {y} function {z} <u1,v1>, <u2,v2>
    /// [contained_by {..}] [max_gradient G] [accuracy A] [precompute D, vars] modifiers }`.
    pub(super) fn parametric(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("parametric")?;
        let mut functions = Vec::new();
        for _ in 0..3 {
            self.skip_optional_comma()?;
            let fspan = self.next_span()?;
            if !self.eat_keyword("function")? {
                return Err(self.error_at(fspan, "a parametric starts with three function { ... }"));
            }
            match self.function_body(fspan)? {
                Ok(f) if f.unsupported.is_none() => functions.push(f),
                Ok(f) => {
                    let why = f.unsupported.clone().unwrap_or_default();
                    return self.skip_parametric(fspan, &why);
                }
                Err(why) => return self.skip_parametric(fspan, &why),
            }
        }
        self.skip_optional_comma()?;
        let lo = self.parse_vector()?;
        self.skip_optional_comma()?;
        let hi = self.parse_vector()?;
        let mut container = Container::Box {
            min: DVec3::splat(-1.0),
            max: DVec3::splat(1.0),
        };
        // A stand-in shape while the modifiers are read.
        let mut obj = ObjectDesc::new(ShapeDesc::Sphere {
            center: DVec3::ZERO,
            radius: 0.0,
        });
        self.special_items(&mut obj, open, "parametric", |p, k, _| {
            match k {
                "contained_by" => container = p.iso_container()?,
                // POV-Ray's subdivision settings; the mesh does not need them.
                "max_gradient" | "accuracy" => {
                    p.parse_float()?;
                }
                "precompute" => {
                    p.parse_float()?;
                    loop {
                        p.skip_optional_comma()?;
                        match p.peek_ident()?.as_deref() {
                            Some("x" | "y" | "z") => p.advance(),
                            _ => break,
                        }
                    }
                }
                _ => return Ok(false),
            }
            Ok(true)
        })?;
        let f: [&Function; 3] = [&functions[0], &functions[1], &functions[2]];
        let mesh = tessellate(f, [lo.x, lo.y], [hi.x, hi.y]);
        // The container clips the surface in the parametric's own space: it takes the
        // transforms the object got.
        let mut clip = ObjectDesc::new(match container {
            Container::Box { min, max } => ShapeDesc::Box {
                corner1: min,
                corner2: max,
            },
            Container::Sphere { center, radius } => ShapeDesc::Sphere { center, radius },
        });
        clip.transform = obj.transform.clone();
        obj.clipped_by.insert(0, clip);
        obj.shape = ShapeDesc::Mesh(Arc::new(mesh));
        Ok(obj)
    }

    fn skip_parametric(&mut self, at: Span, why: &str) -> PResult<ObjectDesc> {
        self.warn(
            at,
            format!(
                "this parametric is not rendered: {why}; the picture will differ from POV-Ray's"
            ),
        );
        self.skip_to_close()?;
        Ok(ObjectDesc::new(ShapeDesc::Csg {
            op: crate::scene::desc::CsgOp::Union,
            children: Vec::new(),
        }))
    }
}

fn point(f: [&Function; 3], u: f64, v: f64) -> DVec3 {
    let a = [u, v, 0.0];
    DVec3::new(f[0].eval(&a), f[1].eval(&a), f[2].eval(&a))
}

/// The surface as a smooth mesh on a regular (u, v) grid, normals from the partial
/// derivatives, (u, v) as texture coordinates.
fn tessellate(f: [&Function; 3], lo: [f64; 2], hi: [f64; 2]) -> MeshData {
    let (du, dv) = (
        (hi[0] - lo[0]) / CELLS as f64,
        (hi[1] - lo[1]) / CELLS as f64,
    );
    crate::geom::mesh::grid_mesh(CELLS, CELLS, |i, j| {
        let (u, v) = (lo[0] + du * i as f64, lo[1] + dv * j as f64);
        let (hu, hv) = (du * 1e-3, dv * 1e-3);
        let pu = point(f, u + hu, v) - point(f, u - hu, v);
        let pv = point(f, u, v + hv) - point(f, u, v - hv);
        (point(f, u, v), pu.cross(pv).normalize_or_zero(), [u, v])
    })
}
