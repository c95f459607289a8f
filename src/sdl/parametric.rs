//! Reading `parametric { }`: a surface x(u,v), y(u,v), z(u,v) over a (u, v) rectangle, kept
//! inside its container. lancer draws it as a fine smooth mesh carrying (u, v) for
//! uv_mapping, clipped by the container, where POV-Ray subdivides (u, v) space per ray; the
//! two agree to well under a pixel at ordinary sizes.

use std::sync::Arc;

use crate::func::Function;
use crate::geom::isosurface::Container;
use crate::math::DVec3;
use crate::scene::desc::{MeshData, MeshTriangle, ObjectDesc, ShapeDesc};

use super::lexer::{Sym, Tok};
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
        loop {
            let Some(t) = self.peek()? else {
                return Err(self.error_at(open, "this '{' is never closed"));
            };
            let k = match &t.tok {
                Tok::Sym(Sym::RBrace) => {
                    self.advance();
                    break;
                }
                Tok::Ident(k) => k.clone(),
                _ => {
                    return Err(self.unexpected(
                        &t,
                        "in the parametric; expected a parametric item, a modifier or '}'",
                    ))
                }
            };
            self.advance();
            match &*k {
                "contained_by" => container = self.iso_container()?,
                // POV-Ray's subdivision settings; the mesh does not need them.
                "max_gradient" | "accuracy" => {
                    self.parse_float()?;
                }
                "precompute" => {
                    self.parse_float()?;
                    loop {
                        self.skip_optional_comma()?;
                        match self.peek_ident()?.as_deref() {
                            Some("x" | "y" | "z") => self.advance(),
                            _ => break,
                        }
                    }
                }
                _ => {
                    if !self.object_modifier(&mut obj, &k, t.span)? {
                        return Err(self.error_at(
                            t.span,
                            format!("'{k}' is not a parametric item or an object modifier"),
                        ));
                    }
                }
            }
        }
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
    let n = CELLS;
    let (du, dv) = ((hi[0] - lo[0]) / n as f64, (hi[1] - lo[1]) / n as f64);
    let mut vertices = Vec::with_capacity((n + 1) * (n + 1));
    let mut normals = Vec::with_capacity((n + 1) * (n + 1));
    let mut uvs = Vec::with_capacity((n + 1) * (n + 1));
    for j in 0..=n {
        let v = lo[1] + dv * j as f64;
        for i in 0..=n {
            let u = lo[0] + du * i as f64;
            let p = point(f, u, v);
            let (hu, hv) = (du * 1e-3, dv * 1e-3);
            let pu = point(f, u + hu, v) - point(f, u - hu, v);
            let pv = point(f, u, v + hv) - point(f, u, v - hv);
            vertices.push(p);
            normals.push(pu.cross(pv).normalize_or_zero());
            uvs.push([u, v]);
        }
    }
    let idx = |i: usize, j: usize| (j * (n + 1) + i) as u32;
    let finite = |k: u32| vertices[k as usize].is_finite();
    let mut triangles = Vec::with_capacity(n * n * 2);
    for j in 0..n {
        for i in 0..n {
            let (a, b, c, d) = (idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1));
            for t in [[a, b, c], [a, c, d]] {
                if !t.iter().all(|&k| finite(k)) {
                    continue;
                }
                // Where the derivatives vanish (a pole) the triangle is drawn flat.
                let smooth = t.iter().all(|&k| normals[k as usize] != DVec3::ZERO);
                triangles.push(MeshTriangle {
                    v: t,
                    n: smooth.then_some(t),
                    texture: None,
                    uv: Some(t),
                });
            }
        }
    }
    MeshData {
        vertices,
        normals,
        triangles,
        uvs,
        textures: Vec::new(),
    }
}
