//! Light statements: `light_source` with every light type and its area, and `light_group`
//! (lights that light only the objects grouped with them).

use crate::math::Transform;
use crate::scene::desc::{AreaLightDesc, CsgOp, LightDesc, LightKind, ObjectDesc, ShapeDesc};

use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};
use super::source::Span;
use super::value::Value;

impl Parser {
    /// `light_group { objects lights [global_lights] }`: a union whose lights light only its
    /// own objects (`global_lights` defaults to off).
    pub(super) fn light_group(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("light_group")?;
        let mut children = Vec::new();
        let mut global = false;
        loop {
            if let Some(o) = self.parse_object()? {
                children.push(o);
            } else if self.eat_keyword("global_lights")? {
                global = self.optional_bool()?;
            } else {
                break;
            }
        }
        let op = CsgOp::Union;
        let mut group = ObjectDesc::new(ShapeDesc::Csg { op, children });
        group.light_group = Some(global);
        self.finish_object(group, open)
    }

    pub(super) fn light_source(&mut self, _s: Span) -> PResult<ObjectDesc> {
        let open = self.open_brace("light_source")?;
        // `light_source { DeclaredLight modifiers }` starts from a declared light.
        let mut base: Option<ObjectDesc> = None;
        if let Some(k) = self.peek_ident()? {
            if let Some(Value::Object(o)) = self.lookup(&k) {
                if matches!(o.shape, ShapeDesc::Light(_)) {
                    base = Some((**o).clone());
                    self.advance();
                }
            }
        }
        let mut light = match &base {
            Some(ObjectDesc {
                shape: ShapeDesc::Light(l),
                ..
            }) => (**l).clone(),
            _ => {
                let position = self.parse_vector()?;
                self.skip_optional_comma()?;
                LightDesc::at(position)
            }
        };
        let mut obj_tf = Transform::IDENTITY;
        loop {
            let t = self
                .peek()?
                .ok_or_else(|| self.error_at(open, "this '{' is never closed"))?;
            match &t.tok {
                Tok::Sym(Sym::RBrace) => {
                    self.advance();
                    break;
                }
                // Any colour expression: a keyword (`srgbt` too), or an identifier starting
                // one (`White*2`).
                Tok::Ident(_) if self.starts_color()? => light.color = self.parse_color()?.rgb,
                Tok::Ident(k) => {
                    let k = k.clone();
                    self.advance();
                    match &*k {
                        "shadowless" => light.shadowless = true,
                        "fade_distance" => light.fade_distance = Some(self.parse_float()?),
                        "fade_power" => light.fade_power = self.parse_float()?,
                        "spotlight" => light.kind = LightKind::Spot,
                        "cylinder" => light.kind = LightKind::Cylinder,
                        "parallel" => light.parallel = true,
                        "point_at" => light.point_at = self.parse_vector()?,
                        "radius" => light.radius = Some(self.parse_float()?),
                        "falloff" => light.falloff = Some(self.parse_float()?),
                        "tightness" => light.tightness = self.parse_float()?,
                        "area_light" => {
                            let area = self.parse_area_light(light.area.take())?;
                            light.area = Some(area);
                        }
                        "adaptive" | "jitter" | "circular" | "orient" => {
                            let area = light.area.get_or_insert_default();
                            match &*k {
                                "adaptive" => {
                                    area.adaptive = Some(self.parse_float()?.max(0.0) as u32)
                                }
                                "jitter" => {
                                    area.jitter = true;
                                    self.warn_if_used(t.span, "'jitter' is random in POV-Ray (its pixels change with the thread count): soft shadow edges have the same grain as povray's but not the same pixels, and are the same for any thread count");
                                }
                                "circular" => area.circular = self.optional_bool()?,
                                _ => area.orient = self.optional_bool()?,
                            }
                        }
                        "looks_like" => {
                            let o = self.object_ref(t.span)?;
                            light.looks_like = Some(Box::new(o));
                        }
                        "projected_through" => {
                            let o = self.object_ref(t.span)?;
                            light.projected_through = Some(Box::new(o));
                        }
                        "area_illumination" => {
                            let on = self.optional_bool()?;
                            light.area.get_or_insert_default().illumination = on;
                        }
                        "media_interaction" => light.media_interaction = self.optional_bool()?,
                        "media_attenuation" => light.media_attenuation = self.optional_bool()?,
                        "photons" => light.photons = self.parse_light_photons()?,
                        other => {
                            if let Some(tr) = self.transform_item(other)? {
                                obj_tf = obj_tf.then(&tr);
                            } else {
                                return Err(self.error_at(
                                    t.span,
                                    format!("unexpected '{other}' in light_source"),
                                ));
                            }
                        }
                    }
                }
                _ => light.color = self.parse_color()?.rgb,
            }
        }
        let mut obj = match base {
            Some(mut b) => {
                b.shape = ShapeDesc::Light(Box::new(light));
                b
            }
            None => ObjectDesc::new(ShapeDesc::Light(Box::new(light))),
        };
        obj.apply_transform(&obj_tf);
        Ok(obj)
    }

    /// `area_light <axis1>, <axis2>, size1, size2`, keeping modifiers written before it.
    fn parse_area_light(&mut self, before: Option<AreaLightDesc>) -> PResult<AreaLightDesc> {
        let axis1 = self.parse_vector()?;
        self.skip_optional_comma()?;
        let axis2 = self.parse_vector()?;
        self.skip_optional_comma()?;
        let size1 = self.parse_float()?;
        self.skip_optional_comma()?;
        let size2 = self.parse_float()?;
        Ok(AreaLightDesc {
            axis1,
            axis2,
            size1: size1.max(1.0) as u32,
            size2: size2.max(1.0) as u32,
            ..before.unwrap_or_default()
        })
    }
}
