//! Reading `mesh2 { vertex_vectors normal_vectors uv_vectors texture_list face_indices
//! normal_indices uv_indices }` into the same triangle data as `mesh`.

use std::rc::Rc;
use std::sync::Arc;

use crate::math::DVec3;
use crate::scene::desc::{MeshData, MeshTriangle, ObjectDesc, ShapeDesc};

use super::bulk::Bulk;
use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};
use super::source::Span;

impl Parser {
    pub(super) fn mesh2(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("mesh2")?;
        let mut data = MeshData::default();
        let mut faces: Vec<([u32; 3], Option<u32>)> = Vec::new();
        let mut normal_idx: Option<Vec<[u32; 3]>> = None;
        let mut uv_idx: Option<Vec<[u32; 3]>> = None;
        let mut face_span = open;
        while let Some(k) = self.peek_ident()? {
            let span = self.next_span()?;
            match &*k {
                "vertex_vectors" => {
                    self.advance();
                    data.vertices = self.vector_list("vertex_vectors")?;
                }
                "normal_vectors" => {
                    self.advance();
                    data.normals = self.vector_list("normal_vectors")?;
                }
                "uv_vectors" => {
                    self.advance();
                    data.uvs = self
                        .vector_list("uv_vectors")?
                        .into_iter()
                        .map(|v| [v.x, v.y])
                        .collect();
                }
                "uv_indices" => {
                    self.advance();
                    let list = self.index_list("uv_indices", false)?;
                    uv_idx = Some(list.into_iter().map(|(v, _)| v).collect());
                }
                "texture_list" => {
                    self.advance();
                    self.open_brace("texture_list")?;
                    let n = self.parse_float()?.max(0.0) as usize;
                    for _ in 0..n {
                        self.skip_optional_comma()?;
                        if !self.eat_keyword("texture")? {
                            return Err(self.error_at(span, "texture_list: expected a texture"));
                        }
                        data.textures.push(self.parse_texture_block()?);
                    }
                    self.skip_optional_comma()?;
                    self.expect_sym(Sym::RBrace, "to close texture_list")?;
                }
                "face_indices" => {
                    self.advance();
                    face_span = span;
                    faces = self.index_list("face_indices", true)?;
                }
                "normal_indices" => {
                    self.advance();
                    let list = self.index_list("normal_indices", false)?;
                    normal_idx = Some(list.into_iter().map(|(v, _)| v).collect());
                }
                "inside_vector" => {
                    self.advance();
                    data.inside_vector = Some(self.parse_vector()?);
                }
                _ => break,
            }
        }
        let nv = data.vertices.len() as u32;
        let nn = data.normals.len() as u32;
        let nt = data.textures.len() as u32;
        for (i, (v, tex)) in faces.iter().enumerate() {
            if v.iter().any(|&k| k >= nv) {
                return Err(self.error_at(
                    face_span,
                    format!("face {i} uses vertex {v:?} but the mesh2 has {nv} vertices"),
                ));
            }
            if tex.is_some_and(|t| t >= nt) {
                return Err(self.error_at(
                    face_span,
                    format!(
                        "face {i} uses texture {} but texture_list has {nt}",
                        tex.unwrap()
                    ),
                ));
            }
            // Normals follow normal_indices when given, else the face's own vertex indices.
            let n = match &normal_idx {
                Some(list) => list.get(i).copied(),
                None if nn > 0 => Some(*v),
                None => None,
            }
            .filter(|n| n.iter().all(|&k| k < nn));
            // Texture coordinates likewise follow uv_indices, else the vertex indices.
            let nu = data.uvs.len() as u32;
            let uv = match &uv_idx {
                Some(list) => list.get(i).copied(),
                None if nu > 0 => Some(*v),
                None => None,
            }
            .filter(|u| u.iter().all(|&k| k < nu));
            data.triangles.push(MeshTriangle {
                v: *v,
                n,
                texture: *tex,
                uv,
            });
        }
        self.finish_object(ObjectDesc::new(ShapeDesc::Mesh(Arc::new(data))), open)
    }

    /// The entries of a list the lexer stored in bulk (`super::bulk`), with its closing brace.
    fn bulk_list(&mut self, what: &str) -> PResult<Option<Rc<Bulk>>> {
        let Some(Tok::Bulk(b)) = self.peek()?.map(|t| t.tok) else {
            return Ok(None);
        };
        self.advance();
        let n = b.vectors.len();
        self.expect_sym_with(Sym::RBrace, || {
            format!("to close {what} (after {n} entries)")
        })?;
        Ok(Some(b))
    }

    /// `{ N, <v>, <v>, ... }`.
    fn vector_list(&mut self, what: &str) -> PResult<Vec<DVec3>> {
        self.open_brace(what)?;
        if let Some(b) = self.bulk_list(what)? {
            return Ok(b.vectors.iter().map(|&v| DVec3::from_array(v)).collect());
        }
        let n = self.parse_float()?.max(0.0) as usize;
        let mut v = Vec::with_capacity(n.min(1 << 20));
        for _ in 0..n {
            self.skip_optional_comma()?;
            v.push(self.parse_vector()?);
        }
        self.skip_optional_comma()?;
        self.expect_sym_with(Sym::RBrace, || {
            format!("to close {what} (after {n} entries)")
        })?;
        Ok(v)
    }

    /// `{ N, <a,b,c> [, t | , t1, t2, t3], ... }`: texture indices only in face_indices. Of
    /// three per-vertex textures the first is used (POV-Ray blends them).
    fn index_list(&mut self, what: &str, textures: bool) -> PResult<Vec<([u32; 3], Option<u32>)>> {
        self.open_brace(what)?;
        let idx = |x: f64| x.max(0.0) as u32;
        if let Some(b) = self.bulk_list(what)? {
            let tex = |i: usize| {
                b.first_texture
                    .get(i)
                    .filter(|t| !t.is_nan())
                    .map(|&t| idx(t))
            };
            return Ok(b
                .vectors
                .iter()
                .enumerate()
                .map(|(i, v)| ([idx(v[0]), idx(v[1]), idx(v[2])], tex(i)))
                .collect());
        }
        let n = self.parse_float()?.max(0.0) as usize;
        let mut out = Vec::with_capacity(n.min(1 << 20));
        for _ in 0..n {
            self.skip_optional_comma()?;
            let v = self.parse_vector()?;
            let mut tex = None;
            if textures {
                let mut given = Vec::new();
                while given.len() < 3 {
                    let comma = self.eat_sym(Sym::Comma)?;
                    if comma && matches!(self.peek()?.map(|t| t.tok), Some(Tok::Sym(Sym::Lt))) {
                        // The comma belonged to the next face.
                        break;
                    }
                    if !(comma || given.is_empty() && self.starts_float()?)
                        || !self.starts_float()?
                    {
                        break;
                    }
                    given.push(self.parse_float()?);
                }
                tex = given.first().map(|&t| idx(t));
            }
            out.push(([idx(v.x), idx(v.y), idx(v.z)], tex));
        }
        self.skip_optional_comma()?;
        self.expect_sym_with(Sym::RBrace, || {
            format!("to close {what} (after {n} entries)")
        })?;
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use crate::scene::desc::{MeshData, ShapeDesc};
    use crate::sdl::parser::{ParseOptions, Parser};

    fn mesh(text: &str) -> MeshData {
        let mut p = Parser::new(ParseOptions::default());
        p.parse_str("t.pov", text).unwrap();
        match &p.scene.objects[0].shape {
            ShapeDesc::Mesh(m) => (**m).clone(),
            _ => panic!("not a mesh"),
        }
    }

    /// A literal list stored in bulk by the lexer reads as the same mesh as the same entries
    /// read by expressions (forced here by a `+0` in the first entry of each list).
    #[test]
    fn bulk_lists_read_as_expressions_do() {
        let lists = |z: &str| {
            format!(
                "mesh2 {{ vertex_vectors {{ 4, <0,0,0{z}>, <1,0,-0>, <1,1,.5>, <0,1,-2.5e-1> }}
                 normal_vectors {{ 2, <0,0,-1{z}>, <0,1,-1> }}
                 uv_vectors {{ 3, <0,0{z}>, <1,0>, <0.5,1> }}
                 texture_list {{ 2, texture {{ pigment {{ rgb 1 }} }} texture {{ pigment {{ rgb 0 }} }} }}
                 face_indices {{ 3, <0,1,2{z}>, 1, <0,2,3>, <1,2,3>, 0, 1, 1 }}
                 normal_indices {{ 3, <0,1,1{z}>, <1,1,0>, <0,0,0> }}
                 uv_indices {{ 3, <0,1,2{z}>, <2,1,0>, <0,0,1>, }} }}"
            )
        };
        let (a, b) = (mesh(&lists("")), mesh(&lists("+0")));
        assert_eq!(a.vertices, b.vertices);
        assert_eq!(a.normals, b.normals);
        assert_eq!(a.uvs, b.uvs);
        let (ta, tb): (Vec<_>, Vec<_>) =
            (a.triangles.iter().collect(), b.triangles.iter().collect());
        assert_eq!(ta, tb);
        assert_eq!(ta[0].texture, Some(1));
        assert_eq!(ta[1].texture, None);
        assert_eq!(ta[2].texture, Some(0));
        assert_eq!(ta[1].n, Some([1, 1, 0]));
        assert_eq!(ta[2].uv, Some([0, 0, 1]));
    }
}
