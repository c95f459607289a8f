//! Top-level scene items: camera, background, sky_sphere, global_settings and the loop that
//! reads a whole scene.

use crate::color::Rgbft;
use std::sync::Arc;

use crate::scene::desc::{CameraDesc, Pigment, Projection, ShapeDesc};
use crate::scene::mesh_camera::MeshCameraDesc;

use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};
use super::value::Value;

/// Atmospheric and global effects POV-Ray renders that lancer reads past with a warning.
const UNSUPPORTED_BLOCKS: &[&str] = &["photons", "radiosity"];

impl Parser {
    pub(super) fn parse_scene_items(&mut self) -> PResult<()> {
        loop {
            if let Some(mut obj) = self.parse_object()? {
                if let Some(v) = self.scene.default_importance {
                    super::object::inherit_importance(&mut obj, v);
                }
                self.scene.objects.push(obj);
                continue;
            }
            let Some(t) = self.peek()? else { return Ok(()) };
            self.advance();
            let Tok::Ident(k) = &t.tok else {
                return Err(self.unexpected(&t, "at the top level of the scene; expected an object, camera, light_source or setting"));
            };
            match &**k {
                "camera" => self.scene.camera = self.parse_camera_block()?,
                "background" => {
                    self.expect_sym(Sym::LBrace, "after 'background'")?;
                    self.scene.background = self.parse_color()?;
                    self.expect_sym(Sym::RBrace, "to close background")?;
                }
                "sky_sphere" => self.parse_sky_sphere()?,
                "fog" => {
                    let fog = self.parse_fog_block()?;
                    self.scene.fogs.push(fog);
                }
                "media" => {
                    let m = self.parse_media_block()?;
                    self.scene.media.push(m);
                }
                "rainbow" => {
                    let rainbow = self.parse_rainbow_block()?;
                    self.scene.fogs.push(rainbow);
                }
                // `default { ... }` without the `#` is the old spelling, still read by 3.7.
                "default" => self.default_directive()?,
                "global_settings" => self.parse_global_settings()?,
                k if UNSUPPORTED_BLOCKS.contains(&k) => {
                    self.unsupported(k, t.span);
                    self.skip_block()?;
                }
                _ => {
                    let msg = match self.lookup(k) {
                        Some(Value::Object(_)) => format!("'{k}' is an object identifier; write object {{ {k} }} to place it"),
                        Some(v) => format!("a {} identifier ('{k}') cannot stand alone in a scene", v.type_name()),
                        None => format!("unexpected '{k}' at the top level of the scene; expected an object, camera, light_source or setting"),
                    };
                    return Err(self.error_at(t.span, msg));
                }
            }
        }
    }

    fn parse_sky_sphere(&mut self) -> PResult<()> {
        let layers = self.parse_sky_sphere_block()?;
        self.scene.sky_sphere = Some(layers);
        Ok(())
    }

    /// `sky_sphere { [Identifier] pigment {...}... transforms }` after the keyword.
    pub(super) fn parse_sky_sphere_block(&mut self) -> PResult<Vec<Pigment>> {
        self.expect_sym(Sym::LBrace, "after 'sky_sphere'")?;
        let mut layers: Vec<Pigment> = Vec::new();
        loop {
            let t = self.next_tok()?;
            match &t.tok {
                Tok::Sym(Sym::RBrace) => break,
                Tok::Ident(k) if &**k == "pigment" => layers.push(self.parse_pigment_block(None)?),
                Tok::Ident(k) if &**k == "emission" => {
                    self.unsupported("emission (in sky_sphere)", t.span);
                    self.parse_color()?;
                }
                Tok::Ident(k) => {
                    if let Some(tr) = self.transform_item(k)? {
                        for p in &mut layers {
                            p.apply_transform(&tr);
                        }
                    } else if let Some(Value::SkySphere(s)) = self.lookup(k) {
                        layers = (**s).clone();
                    } else {
                        return Err(
                            self.error_at(t.span, format!("unexpected '{k}' in sky_sphere"))
                        );
                    }
                }
                _ => return Err(self.unexpected(&t, "in sky_sphere")),
            }
        }
        Ok(layers)
    }

    fn parse_global_settings(&mut self) -> PResult<()> {
        self.expect_sym(Sym::LBrace, "after 'global_settings'")?;
        loop {
            let t = self.next_tok()?;
            let Tok::Ident(k) = &t.tok else {
                if t.tok == Tok::Sym(Sym::RBrace) {
                    return Ok(());
                }
                return Err(self.unexpected(&t, "in global_settings"));
            };
            match &**k {
                "assumed_gamma" => {
                    let v = self.parse_float()?;
                    self.scene.global.assumed_gamma = Some(v);
                }
                "max_trace_level" => {
                    let v = self.parse_float()?;
                    self.scene.global.max_trace_level = v.max(1.0) as u32;
                }
                "adc_bailout" => {
                    let v = self.parse_float()?;
                    self.scene.global.adc_bailout = v;
                }
                "ambient_light" => {
                    let c = self.parse_color()?;
                    self.scene.global.ambient_light = c.rgb;
                }
                "charset" => {
                    let t = self.next_tok()?;
                    match &t.tok {
                        Tok::Ident(c) if &**c == "ascii" => self.utf8_strings = false,
                        // sys is the system's character set, UTF-8 on the systems lancer
                        // runs on.
                        Tok::Ident(c) if &**c == "utf8" || &**c == "sys" => {
                            self.utf8_strings = true
                        }
                        _ => {
                            return Err(
                                self.unexpected(&t, "after charset; expected ascii, utf8 or sys")
                            )
                        }
                    }
                }
                "hf_gray_16" => {
                    // Only changes height-field output, which lancer does not write.
                    self.optional_bool()?;
                }
                "noise_generator" => {
                    let v = self.parse_float()?;
                    self.scene.global.noise_generator = (v as i64).clamp(1, 3) as u8;
                }
                "number_of_waves" => {
                    let v = self.parse_float()?;
                    if v > 10.0 {
                        self.unsupported("number_of_waves above 10 (10 are used)", t.span);
                    }
                    self.scene.global.number_of_waves = v.clamp(1.0, 10.0) as u8;
                }
                "max_intersections" | "mm_per_unit" | "subsurface" => {
                    if self.peek_sym()? == Some(Sym::LBrace) {
                        self.skip_block()?;
                    } else {
                        // Read past: none of these changes what lancer renders today.
                        self.parse_expr()?;
                    }
                }
                "irid_wavelength" => {
                    self.parse_color()?;
                    // Measured only for the default (docs/textures.md, irid).
                    self.unsupported(
                        "irid_wavelength (the default's measured wavelengths are used)",
                        t.span,
                    );
                }
                "radiosity" => self.parse_global_radiosity()?,
                "photons" => {
                    let p = self.parse_global_photons()?;
                    self.scene.global.photons = Some(p);
                }
                _ => {
                    return Err(
                        self.error_at(t.span, format!("unexpected '{k}' in global_settings"))
                    )
                }
            }
        }
    }

    pub(super) fn parse_camera_block(&mut self) -> PResult<CameraDesc> {
        self.expect_sym(Sym::LBrace, "after 'camera'")?;
        let mut cam = CameraDesc::default();
        if let Some(k) = self.peek_ident()? {
            if let Some(Value::Camera(c)) = self.lookup(&k) {
                cam = (**c).clone();
                self.advance();
            }
        }
        loop {
            let t = self.next_tok()?;
            let Tok::Ident(k) = &t.tok else {
                if t.tok == Tok::Sym(Sym::RBrace) {
                    return Ok(cam);
                }
                return Err(self.unexpected(&t, "in camera"));
            };
            if let Some(tr) = self.transform_item(k)? {
                cam.transform = cam.transform.then(&tr);
                continue;
            }
            match &**k {
                "perspective" | "orthographic" | "fisheye" | "ultra_wide_angle" | "omnimax"
                | "panoramic" | "spherical" | "cylinder" => {
                    cam.orthographic = &**k == "orthographic";
                    cam.projection = match &**k {
                        "fisheye" => Projection::Fisheye,
                        "ultra_wide_angle" => Projection::UltraWideAngle,
                        "omnimax" => Projection::Omnimax,
                        "panoramic" => Projection::Panoramic,
                        "spherical" => Projection::Spherical,
                        "cylinder" => {
                            let n = self.parse_float()?;
                            if !(1.0..=4.0).contains(&n) {
                                return Err(self.error_at(
                                    t.span,
                                    format!("the cylinder camera type must be 1 to 4, not {n}"),
                                ));
                            }
                            Projection::Cylinder(n as u8)
                        }
                        _ => Projection::Perspective,
                    };
                }
                "mesh_camera" => cam.mesh = Some(Arc::new(self.parse_mesh_camera(t.span)?)),
                "location" => cam.location = self.parse_vector()?,
                "look_at" => cam.look_at = Some(self.parse_vector()?),
                "right" => {
                    cam.right = self.parse_vector()?;
                    cam.sized = true;
                }
                "up" => {
                    cam.up = self.parse_vector()?;
                    cam.sized = true;
                }
                "direction" => cam.direction = self.parse_vector()?,
                "sky" => cam.sky = self.parse_vector()?,
                "angle" => {
                    cam.angle_given = true;
                    // An orthographic camera's angle may come without a value.
                    if cam.orthographic && !self.starts_float()? {
                        continue;
                    }
                    cam.angle = Some(self.parse_float()?);
                    let comma = self.eat_sym(Sym::Comma)?;
                    if comma || self.starts_number()? {
                        let v = self.parse_float()?;
                        if cam.projection == Projection::Spherical {
                            cam.v_angle = Some(v);
                        } else {
                            self.unsupported(
                                "angle (vertical angle, spherical cameras only)",
                                t.span,
                            );
                        }
                    }
                }
                "aperture" => cam.blur.aperture = self.parse_float()?,
                "blur_samples" => {
                    let a = self.parse_float()?;
                    if self.eat_sym(Sym::Comma)? {
                        let b = self.parse_float()?;
                        cam.blur.min_samples = Some(a.max(1.0) as u32);
                        cam.blur.max_samples = b.max(0.0) as u32;
                    } else {
                        cam.blur.max_samples = a.max(0.0) as u32;
                    }
                }
                "focal_point" => cam.blur.focal_point = self.parse_vector()?,
                "confidence" => cam.blur.confidence = self.parse_float()?.clamp(0.0, 0.999_999),
                "variance" => {
                    let v = self.parse_float()?;
                    if v >= 1.0 {
                        // The manual: "If 1 is used POV-Ray will issue a warning and then use
                        // the default instead." Measured: `variance 0` is taken as written
                        // (every pixel takes the most samples), without a warning.
                        self.warn(
                            t.span,
                            "focal blur variance must be below 1; the default 1/128 is used",
                        );
                    } else {
                        cam.blur.variance = v.max(0.0);
                    }
                }
                "normal" => {
                    cam.normal = Some(self.parse_normal_block(t.span)?);
                }
                "bokeh" => {
                    self.expect_sym(Sym::LBrace, "after 'bokeh'")?;
                    let pig = self.next_tok()?;
                    if !matches!(&pig.tok, Tok::Ident(k) if &**k == "pigment") {
                        return Err(self.error_at(pig.span, "expected 'pigment' in bokeh"));
                    }
                    cam.blur.bokeh = Some(Box::new(self.parse_pigment_block(None)?));
                    self.expect_sym(Sym::RBrace, "to close 'bokeh'")?;
                }
                _ => return Err(self.error_at(t.span, format!("unexpected '{k}' in camera"))),
            }
        }
    }

    /// `mesh_camera { rays distribution [max_distance] mesh {..}... }` after the keyword.
    fn parse_mesh_camera(&mut self, at: super::source::Span) -> PResult<MeshCameraDesc> {
        self.expect_sym(Sym::LBrace, "after 'mesh_camera'")?;
        let rays = self.parse_float()?;
        self.skip_optional_comma()?;
        let dist_span = self.peek()?.map_or(at, |t| t.span);
        let distribution = self.parse_float()?;
        self.skip_optional_comma()?;
        if rays.is_nan() || rays < 1.0 {
            return Err(self.error_at(
                at,
                format!("mesh_camera needs at least 1 ray per pixel, not {rays}"),
            ));
        }
        if !(0.0..=3.0).contains(&distribution) || distribution.fract() != 0.0 {
            return Err(self.error_at(
                dist_span,
                format!(
                    "the mesh_camera distribution type must be 0, 1, 2 or 3, not {distribution}"
                ),
            ));
        }
        if self.starts_float()? {
            let span = self.peek()?.map_or(at, |t| t.span);
            let max = self.parse_float()?;
            self.skip_optional_comma()?;
            if max > 1e-10 {
                self.unsupported("mesh_camera max distance (rays go on for ever)", span);
            }
        }
        let mut meshes = Vec::new();
        let mut smooth = false;
        loop {
            let Some(t) = self.peek()? else {
                return Err(self.error_at(at, "this mesh_camera is never closed"));
            };
            match &t.tok {
                Tok::Sym(Sym::RBrace) => {
                    self.advance();
                    break;
                }
                Tok::Ident(k) if &**k == "smooth" => {
                    if distribution != 3.0 {
                        // povray: "Smooth can only be used with distribution 3".
                        return Err(self.error_at(
                            t.span,
                            format!("'smooth' needs mesh_camera distribution 3 (this one is {distribution}), as in POV-Ray"),
                        ));
                    }
                    self.advance();
                    smooth = true;
                }
                Tok::Ident(k) if matches!(&**k, "mesh" | "mesh2") => {
                    let Some(obj) = self.parse_object()? else {
                        return Err(self.error_at(t.span, "expected a mesh"));
                    };
                    let ShapeDesc::Mesh(data) = &obj.shape else {
                        return Err(
                            self.error_at(t.span, "a mesh_camera takes mesh or mesh2 objects")
                        );
                    };
                    meshes.push((data.clone(), *obj.transform.get()));
                }
                _ => {
                    return Err(self
                        .unexpected(&t, "in mesh_camera; expected a mesh, mesh2, smooth or '}'"))
                }
            }
        }
        if meshes.is_empty() {
            return Err(self.error_at(at, "a mesh_camera needs at least one mesh"));
        }
        if distribution == 0.0 && (meshes.len() as f64) < rays {
            return Err(self.error_at(at, format!("mesh_camera distribution 0 needs a mesh per ray: {rays} rays per pixel but {} meshes", meshes.len())));
        }
        if distribution >= 2.0 && rays > 1.0 {
            self.warn(at, format!("mesh_camera distribution {distribution} shoots one ray per pixel; POV-Ray 3.7 allows no more"));
        }
        Ok(MeshCameraDesc {
            rays_per_pixel: rays as u32,
            distribution: distribution as u32,
            meshes,
            smooth,
        })
    }

    fn starts_number(&mut self) -> PResult<bool> {
        Ok(matches!(self.peek()?.map(|t| t.tok), Some(Tok::Num(_))))
    }
}

/// Background colour when a scene sets none.
/// Black and fully transmitting: the same black without alpha, and transparent with `+UA`
/// (povray writes alpha 0 where a scene without `background` shows it).
pub const DEFAULT_BACKGROUND: Rgbft = Rgbft {
    rgb: crate::math::DVec3::ZERO,
    filter: 0.0,
    transmit: 1.0,
};
