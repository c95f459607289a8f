//! Object statements: the keyword table, each primitive's parameters, CSG, meshes and the
//! modifiers every object accepts.

use std::sync::Arc;

use crate::math::{DVec3, Transform};
use crate::scene::desc::{
    CsgOp, Interior, MeshData, MeshTriangle, ObjectDesc, ShapeDesc, SmoothTriangleDesc, Texture,
};

use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};
use super::source::Span;
use super::value::Value;

type ObjectFn = fn(&mut Parser, Span) -> PResult<ObjectDesc>;

/// Objects POV-Ray 3.7 has that lancer reads past (with a warning) but does not render yet.
const UNSUPPORTED_OBJECTS: &[&str] = &["lemon"];

impl Parser {
    pub(super) fn object_parser(k: &str) -> Option<ObjectFn> {
        Some(match k {
            "sphere" => Parser::sphere,
            "plane" => Parser::plane,
            "box" => Parser::box_object,
            "cylinder" => Parser::cylinder,
            "cone" => Parser::cone,
            "disc" => Parser::disc,
            "torus" => Parser::torus,
            "triangle" => Parser::triangle,
            "smooth_triangle" => Parser::smooth_triangle,
            "mesh" => Parser::mesh,
            "mesh2" => Parser::mesh2,
            "quadric" => Parser::quadric,
            "cubic" => |p, s| p.poly_fixed(3, s),
            "quartic" => |p, s| p.poly_fixed(4, s),
            "poly" => Parser::poly,
            "polynomial" => Parser::polynomial,
            "text" => Parser::text_object,
            "prism" => Parser::prism,
            "lathe" => Parser::lathe,
            "sor" => Parser::sor,
            "polygon" => Parser::polygon,
            "sphere_sweep" => Parser::sphere_sweep,
            "superellipsoid" => Parser::superellipsoid,
            "blob" => Parser::blob,
            "isosurface" => Parser::isosurface,
            "height_field" => Parser::height_field,
            "bicubic_patch" => Parser::bicubic_patch,
            "julia_fractal" => Parser::julia_fractal,
            "ovus" => Parser::ovus,
            "parametric" => Parser::parametric,
            "union" => |p, s| p.csg(CsgOp::Union, s),
            "light_group" => Parser::light_group,
            "merge" => |p, s| p.csg(CsgOp::Merge, s),
            "intersection" => |p, s| p.csg(CsgOp::Intersection, s),
            "difference" => |p, s| p.csg(CsgOp::Difference, s),
            "object" => Parser::object_ref,
            "light_source" => Parser::light_source,
            k if UNSUPPORTED_OBJECTS.contains(&k) => Parser::unsupported_object,
            _ => return None,
        })
    }

    /// Parses an object if the next token starts one.
    pub fn parse_object(&mut self) -> PResult<Option<ObjectDesc>> {
        let Some(t) = self.peek()? else {
            return Ok(None);
        };
        let Tok::Ident(k) = &t.tok else {
            return Ok(None);
        };
        let Some(f) = Self::object_parser(k) else {
            return Ok(None);
        };
        self.advance();
        // CSG and `object { object { ...` recurse through here.
        self.nested(|p| f(p, t.span)).map(Some)
    }

    pub(super) fn open_brace(&mut self, what: &str) -> PResult<Span> {
        self.expect_sym_with(Sym::LBrace, || format!("after '{what}'"))
    }

    /// Parses modifiers up to and including the closing brace.
    pub(super) fn finish_object(&mut self, mut obj: ObjectDesc, open: Span) -> PResult<ObjectDesc> {
        // `uv_mapping` among the modifiers maps the textures given after it (measured:
        // povray draws `sphere { 0, 1 uv_mapping texture { T } }` as `texture { uv_mapping T }`
        // and refuses it after the texture).
        let mut uv = false;
        loop {
            let Some(t) = self.peek()? else {
                return Err(self.error_at(open, "this '{' is never closed"));
            };
            match &t.tok {
                Tok::Sym(Sym::RBrace) => {
                    self.advance();
                    if uv {
                        if let Some(tex) = &mut obj.texture {
                            Arc::make_mut(tex).uv_mapping = true;
                        }
                    }
                    self.warn_uv_without_coordinates(&obj, open);
                    return Ok(obj);
                }
                Tok::Ident(k) if &**k == "uv_mapping" => {
                    self.advance();
                    if obj.texture.is_some() {
                        return Err(self
                            .error_at(t.span, "uv_mapping must come before the object's texture"));
                    }
                    uv = true;
                }
                Tok::Ident(k) => {
                    let k = k.clone();
                    self.advance();
                    if !self.object_modifier(&mut obj, &k, t.span)? {
                        return Err(self.error_at(
                            t.span,
                            format!("'{k}' is not an object modifier; expected a modifier or '}}'"),
                        ));
                    }
                    // Marked as soon as it is given: a uv-mapped texture does not follow
                    // the object's later transforms (measured: `sphere { 0, 0.5 uv_mapping
                    // texture { T } scale 2 }` shows as many checks as the unit sphere).
                    if uv {
                        if let Some(tex) = obj.texture.as_mut().filter(|t| !t.uv_mapping) {
                            Arc::make_mut(tex).uv_mapping = true;
                        }
                    }
                }
                _ => return Err(self.unexpected(&t, "in the object; expected a modifier or '}'")),
            }
        }
    }

    /// A uv-mapped texture on a shape lancer has no uv coordinates for is drawn at the 3D
    /// point instead: said, never silent.
    fn warn_uv_without_coordinates(&mut self, obj: &ObjectDesc, open: Span) {
        if !obj.texture.as_ref().is_some_and(|t| t.uses_uv()) {
            return;
        }
        if let Some(shape) = obj.shape.first_without_uv() {
            self.warn(open, format!("'uv_mapping on {shape}' is not supported by lancer yet: the pattern is evaluated at the 3D point, so the picture will differ from POV-Ray's"));
        }
    }

    fn texture_mut(&mut self, obj: &mut ObjectDesc) -> Texture {
        obj.texture
            .take()
            .map(Arc::unwrap_or_clone)
            .unwrap_or_else(|| self.scene.default_texture.clone())
    }

    /// One object modifier whose keyword was just consumed; false when `k` is not one.
    pub(super) fn object_modifier(
        &mut self,
        obj: &mut ObjectDesc,
        k: &str,
        span: Span,
    ) -> PResult<bool> {
        if let Some(t) = self.transform_item(k)? {
            obj.apply_transform(&t);
            return Ok(true);
        }
        match k {
            "texture" => {
                let t = self.parse_texture_block_shared()?;
                obj.texture = Some(match obj.texture.take() {
                    Some(below) => {
                        Arc::new(Arc::unwrap_or_clone(t).over(Arc::unwrap_or_clone(below)))
                    }
                    None => t,
                });
            }
            "pigment" => {
                let mut tex = self.texture_mut(obj);
                tex.pigment = self.parse_pigment_block(Some(tex.pigment.clone()))?;
                obj.texture = Some(Arc::new(tex));
            }
            "finish" => {
                let mut tex = self.texture_mut(obj);
                tex.finish = self.parse_finish_block(Some(tex.finish.clone()))?;
                obj.texture = Some(Arc::new(tex));
            }
            "normal" => {
                let mut tex = self.texture_mut(obj);
                let base = tex.normal.take().map(|n| *n);
                tex.normal = Some(Box::new(self.parse_normal_block_over(base)?));
                obj.texture = Some(Arc::new(tex));
            }
            "interior" => obj.interior = Some(self.parse_interior_block()?),
            "material" => self.material(obj)?,
            "no_shadow" => obj.no_shadow = true,
            // Only meaningful in a light_group (elsewhere povray reads it and does nothing).
            "global_lights" => {
                let on = self.optional_bool()?;
                if obj.light_group.is_some() {
                    obj.light_group = Some(on);
                }
            }
            "inverse" => obj.inverse = !obj.inverse,
            "hollow" => obj.hollow = Some(self.optional_bool()?),
            "open" => match &mut obj.shape {
                ShapeDesc::Cylinder { open, .. } | ShapeDesc::Cone { open, .. } => *open = true,
                _ => self.warn(span, "'open' only applies to cylinders and cones; ignored"),
            },
            "sturm" => {
                if let ShapeDesc::Torus { sturm, .. } | ShapeDesc::Algebraic { sturm, .. } =
                    &mut obj.shape
                {
                    *sturm = self.optional_bool()?;
                }
            }
            // Bounding only speeds POV-Ray up; lancer builds its own bounds.
            "bounded_by" => self.skip_block()?,
            "no_image" | "no_reflection" | "double_illuminate" | "no_radiosity" => {
                let on = self.optional_bool()?;
                // On a CSG object it holds for every member, which are what rays meet.
                set_deep(obj, &|o: &mut ObjectDesc| match k {
                    "no_image" => o.no_image = on,
                    "no_reflection" => o.no_reflection = on,
                    "no_radiosity" => o.no_radiosity = on,
                    _ => o.double_illuminate = on,
                });
            }
            "split_union" => {
                self.optional_bool()?;
            }
            "photons" => obj.photons = self.parse_object_photons(obj.photons)?,
            "radiosity" => {
                if let Some(v) = self.parse_object_radiosity()? {
                    // CSG members without their own take their parent's.
                    inherit_importance(obj, v);
                    obj.rad_importance = v;
                }
            }
            "clipped_by" => {
                let open = self.open_brace("clipped_by")?;
                let mut clips = Vec::new();
                loop {
                    if let Some(o) = self.parse_object()? {
                        clips.push(o);
                        continue;
                    }
                    let t = self.next_tok()?;
                    match &t.tok {
                        Tok::Sym(Sym::RBrace) => break,
                        // `clipped_by { bounded_by }`: clip by the bounding objects, which
                        // lancer does not keep (it bounds objects itself).
                        Tok::Ident(k) if &**k == "bounded_by" => {
                            self.unsupported("clipped_by { bounded_by }", t.span)
                        }
                        _ => {
                            return Err(
                                self.unexpected(&t, "in clipped_by; expected objects or '}'")
                            )
                        }
                    }
                }
                let _ = open;
                obj.clipped_by.extend(clips);
            }
            "interior_texture" => {
                obj.interior_texture = Some(self.parse_texture_block_shared()?);
            }
            "uv_mapping" => self.unsupported(k, span),
            _ => return Ok(false),
        }
        Ok(true)
    }

    /// `on`/`off`/a float after a flag keyword, or true when nothing numeric follows.
    /// A flag keyword's optional value (`hollow`, `hollow off`, `hollow F`, `hollow (1)`): any
    /// float expression may follow, as in POV-Ray; nothing means on.
    pub(super) fn optional_bool(&mut self) -> PResult<bool> {
        if self.starts_float()? {
            Ok(self.parse_float()? != 0.0)
        } else {
            Ok(true)
        }
    }

    fn material(&mut self, obj: &mut ObjectDesc) -> PResult<()> {
        let (texture, interior) = self.parse_material_block()?;
        if let Some(t) = texture {
            obj.texture = Some(Arc::new(t));
        }
        if interior.is_some() {
            obj.interior = interior;
        }
        Ok(())
    }

    /// `material { [Identifier] texture {...} interior {...} transforms }` after the keyword.
    pub(super) fn parse_material_block(&mut self) -> PResult<(Option<Texture>, Option<Interior>)> {
        let open = self.open_brace("material")?;
        let (mut texture, mut interior) = (None, None);
        loop {
            let t = self.next_tok()?;
            match &t.tok {
                Tok::Sym(Sym::RBrace) => return Ok((texture, interior)),
                Tok::Ident(k) if &**k == "texture" => texture = Some(self.parse_texture_block()?),
                Tok::Ident(k) if &**k == "interior" => {
                    interior = Some(self.parse_interior_block()?)
                }
                Tok::Ident(k) => {
                    if let Some(tr) = self.transform_item(k)? {
                        if let Some(tex) = &mut texture {
                            tex.apply_transform(&tr);
                        }
                        if let Some(int) = &mut interior {
                            int.apply_transform(&tr);
                        }
                    } else {
                        match self.lookup(k) {
                            Some(Value::Material(m)) => (texture, interior) = (**m).clone(),
                            Some(Value::Texture(tex)) => texture = Some((**tex).clone()),
                            _ => {
                                return Err(
                                    self.error_at(t.span, format!("unexpected '{k}' in material"))
                                )
                            }
                        }
                    }
                }
                _ => return Err(self.error_at(open, format!("unexpected {} in material", t.tok))),
            }
        }
    }

    /// A transformation keyword just consumed: translate, rotate, scale, matrix, transform.
    pub(super) fn transform_item(&mut self, k: &str) -> PResult<Option<Transform>> {
        Ok(Some(match k {
            "translate" => Transform::translate(self.parse_vector()?),
            "rotate" => Transform::rotate(self.parse_vector()?),
            "scale" => {
                let span = self.next_span()?;
                let v = self.parse_vector()?;
                if v.x == 0.0 || v.y == 0.0 || v.z == 0.0 {
                    self.warn(span, "scale by 0 is changed to 1, as POV-Ray does");
                }
                Transform::scale(v)
            }
            "matrix" => {
                self.expect_sym(Sym::Lt, "after 'matrix'")?;
                let v = self.with_rel(false, |p| {
                    let mut v = [0.0; 12];
                    for (i, x) in v.iter_mut().enumerate() {
                        if i > 0 {
                            p.skip_optional_comma()?;
                        }
                        *x = p.parse_float()?;
                    }
                    Ok(v)
                })?;
                self.expect_sym(Sym::Gt, "to close the matrix")?;
                Transform::pov_matrix(&v)
            }
            "transform" => {
                if self.peek_sym()? == Some(Sym::LBrace) {
                    self.parse_transform_block()?
                } else {
                    let t = self.next_tok()?;
                    match &t.tok {
                        Tok::Ident(n) => match self.lookup(n) {
                            Some(Value::Transform(tr)) => **tr,
                            _ => {
                                return Err(
                                    self.error_at(t.span, format!("'{n}' is not a transform"))
                                )
                            }
                        },
                        _ => return Err(self.unexpected(&t, "after 'transform'")),
                    }
                }
            }
            _ => return Ok(None),
        }))
    }

    pub(super) fn parse_transform_block(&mut self) -> PResult<Transform> {
        self.open_brace("transform")?;
        let mut acc = Transform::IDENTITY;
        loop {
            let t = self.next_tok()?;
            match &t.tok {
                Tok::Sym(Sym::RBrace) => return Ok(acc),
                Tok::Ident(k) if &**k == "inverse" => acc = acc.inverse(),
                Tok::Ident(k) => {
                    if let Some(Value::Transform(tr)) = self.lookup(k) {
                        acc = acc.then(tr);
                    } else if let Some(tr) = self.transform_item(k)? {
                        acc = acc.then(&tr);
                    } else {
                        return Err(self.unexpected(&t, "in transform"));
                    }
                }
                _ => return Err(self.unexpected(&t, "in transform")),
            }
        }
    }

    fn sphere(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("sphere")?;
        let center = self.parse_vector()?;
        self.skip_optional_comma()?;
        let radius = self.parse_float()?;
        self.finish_object(ObjectDesc::new(ShapeDesc::Sphere { center, radius }), open)
    }

    fn plane(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("plane")?;
        let normal = self.parse_vector()?;
        self.skip_optional_comma()?;
        let distance = self.parse_float()?;
        self.finish_object(ObjectDesc::new(ShapeDesc::Plane { normal, distance }), open)
    }

    fn box_object(&mut self, kw: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("box")?;
        let corner1 = self.parse_vector()?;
        self.skip_optional_comma()?;
        let corner2 = self.parse_vector()?;
        let obj = self.finish_object(ObjectDesc::new(ShapeDesc::Box { corner1, corner2 }), open)?;
        // Measured (textures/finishes/var_reflection): a flat glass box shows no_reflection
        // objects in lancer's reflections and not in POV-Ray's; 0.05 thick, the two agree.
        if (corner1 - corner2).abs().min_element() == 0.0
            && obj.interior.as_ref().is_some_and(|i| i.ior != 1.0)
        {
            self.warn(kw, "'box' is not supported by lancer yet: a box of zero thickness with an ior meets its two faces at one point, and lancer's glass there differs from POV-Ray's");
        }
        Ok(obj)
    }

    fn cylinder(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open_b = self.open_brace("cylinder")?;
        let base = self.parse_vector()?;
        self.skip_optional_comma()?;
        let cap = self.parse_vector()?;
        self.skip_optional_comma()?;
        let radius = self.parse_float()?;
        self.finish_object(
            ObjectDesc::new(ShapeDesc::Cylinder {
                base,
                cap,
                radius,
                open: false,
            }),
            open_b,
        )
    }

    fn cone(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open_b = self.open_brace("cone")?;
        let base = self.parse_vector()?;
        self.skip_optional_comma()?;
        let base_radius = self.parse_float()?;
        self.skip_optional_comma()?;
        let cap = self.parse_vector()?;
        self.skip_optional_comma()?;
        let cap_radius = self.parse_float()?;
        self.finish_object(
            ObjectDesc::new(ShapeDesc::Cone {
                base,
                base_radius,
                cap,
                cap_radius,
                open: false,
            }),
            open_b,
        )
    }

    fn disc(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("disc")?;
        let center = self.parse_vector()?;
        self.skip_optional_comma()?;
        let normal = self.parse_vector()?;
        self.skip_optional_comma()?;
        let radius = self.parse_float()?;
        let hole_radius = if self.eat_sym(Sym::Comma)? {
            self.parse_float()?
        } else {
            0.0
        };
        self.finish_object(
            ObjectDesc::new(ShapeDesc::Disc {
                center,
                normal,
                radius,
                hole_radius,
            }),
            open,
        )
    }

    fn torus(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("torus")?;
        let major = self.parse_float()?;
        self.skip_optional_comma()?;
        let minor = self.parse_float()?;
        self.finish_object(
            ObjectDesc::new(ShapeDesc::Torus {
                major,
                minor,
                sturm: false,
            }),
            open,
        )
    }

    fn three_points(&mut self, with_normals: bool) -> PResult<([DVec3; 3], [DVec3; 3])> {
        let mut p = [DVec3::ZERO; 3];
        let mut n = [DVec3::ZERO; 3];
        for i in 0..3 {
            if i > 0 {
                self.skip_optional_comma()?;
            }
            p[i] = self.parse_vector()?;
            if with_normals {
                self.skip_optional_comma()?;
                n[i] = self.parse_vector()?;
            }
        }
        Ok((p, n))
    }

    fn triangle(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("triangle")?;
        let (p, _) = self.three_points(false)?;
        self.finish_object(ObjectDesc::new(ShapeDesc::Triangle { p }), open)
    }

    fn smooth_triangle(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("smooth_triangle")?;
        let (p, n) = self.three_points(true)?;
        self.finish_object(
            ObjectDesc::new(ShapeDesc::SmoothTriangle(Box::new(SmoothTriangleDesc {
                p,
                n,
            }))),
            open,
        )
    }

    fn mesh(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("mesh")?;
        // `mesh { DeclaredMesh modifiers }` (camera/mesh_camera) starts from a declared mesh.
        if let Some(k) = self.peek_ident()? {
            if let Some(Value::Object(o)) = self.lookup(&k) {
                if matches!(o.shape, ShapeDesc::Mesh(_)) {
                    let base = (**o).clone();
                    self.advance();
                    return self.finish_object(base, open);
                }
            }
        }
        let mut data = MeshData::default();
        loop {
            let Some(t) = self.peek()? else {
                return Err(self.error_at(open, "this '{' is never closed"));
            };
            let smooth = match &t.tok {
                Tok::Ident(k) if &**k == "triangle" => false,
                Tok::Ident(k) if &**k == "smooth_triangle" => true,
                Tok::Ident(k) if &**k == "inside_vector" => {
                    self.advance();
                    data.inside_vector = Some(self.parse_vector()?);
                    continue;
                }
                // A bounding hierarchy is always used.
                Tok::Ident(k) if &**k == "hierarchy" => {
                    self.advance();
                    self.optional_bool()?;
                    continue;
                }
                _ => break,
            };
            self.advance();
            let inner = self.open_brace(if smooth {
                "smooth_triangle"
            } else {
                "triangle"
            })?;
            let (p, n) = self.three_points(smooth)?;
            let base = data.vertices.len() as u32;
            data.vertices.extend_from_slice(&p);
            let normals = smooth.then(|| {
                let nb = data.normals.len() as u32;
                data.normals.extend_from_slice(&n);
                [nb, nb + 1, nb + 2]
            });
            let mut texture = None;
            let mut uv = None;
            loop {
                let t = self.next_tok()?;
                match &t.tok {
                    Tok::Sym(Sym::RBrace) => break,
                    Tok::Ident(k) if &**k == "texture" => {
                        data.textures.push(self.parse_texture_block()?);
                        texture = Some(data.textures.len() as u32 - 1);
                    }
                    Tok::Ident(k) if &**k == "uv_vectors" => {
                        let ub = data.uvs.len() as u32;
                        for i in 0..3 {
                            if i > 0 {
                                self.skip_optional_comma()?;
                            }
                            let v = self.parse_vector()?;
                            data.uvs.push([v.x, v.y]);
                        }
                        uv = Some([ub, ub + 1, ub + 2]);
                    }
                    _ => {
                        return Err(self
                            .error_at(inner, format!("unexpected {} in a mesh triangle", t.tok)))
                    }
                }
            }
            data.triangles.push(MeshTriangle {
                v: [base, base + 1, base + 2],
                n: normals,
                texture,
                uv,
            });
        }
        self.finish_object(ObjectDesc::new(ShapeDesc::Mesh(Arc::new(data))), open)
    }

    fn csg(&mut self, op: CsgOp, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("CSG")?;
        let mut children = Vec::new();
        while let Some(o) = self.parse_object()? {
            children.push(o);
        }
        self.finish_object(ObjectDesc::new(ShapeDesc::Csg { op, children }), open)
    }

    pub(super) fn object_ref(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("object")?;
        if let Some(o) = self.parse_object()? {
            return self.finish_object(o, open);
        }
        let t = self.next_tok()?;
        let obj = match &t.tok {
            Tok::Ident(n) => match self.lookup(n) {
                Some(Value::Object(o)) => (**o).clone(),
                Some(v) => {
                    return Err(self.error_at(
                        t.span,
                        format!("'{n}' holds a {}, not an object", v.type_name()),
                    ))
                }
                None => return Err(self.error_at(t.span, format!("undeclared identifier '{n}'"))),
            },
            _ => return Err(self.unexpected(&t, "in object { }; expected an object identifier")),
        };
        self.finish_object(obj, open)
    }

    fn unsupported_object(&mut self, span: Span) -> PResult<ObjectDesc> {
        let name = self
            .frames
            .last()
            .and_then(|f| f.tokens.get(f.pos.saturating_sub(1)))
            .map(|t| t.tok.to_string())
            .unwrap_or_default();
        self.unsupported(name.trim_matches('\''), span);
        self.skip_block()?;
        // An empty union renders as nothing but keeps `#declare X = blob {...}` usable.
        Ok(ObjectDesc::new(ShapeDesc::Csg {
            op: CsgOp::Union,
            children: Vec::new(),
        }))
    }
}

/// Applies `f` to an object and, for CSG, to every member at any depth.
/// Gives `obj` and its CSG members that have no `radiosity { importance }` of their own
/// importance `v`.
pub(super) fn inherit_importance(obj: &mut ObjectDesc, v: f32) {
    set_deep(obj, &|o: &mut ObjectDesc| {
        if o.rad_importance == 0.0 {
            o.rad_importance = v;
        }
    });
}

fn set_deep(obj: &mut ObjectDesc, f: &dyn Fn(&mut ObjectDesc)) {
    f(obj);
    if let ShapeDesc::Csg { children, .. } = &mut obj.shape {
        for c in children {
            set_deep(c, f);
        }
    }
}
