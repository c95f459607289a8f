//! POV-Ray's cameras: the items resolved in its fixed order (angle, then look_at with sky,
//! then transforms) and primary rays through pixel positions for each projection
//! (perspective, orthographic, fisheye, ultra wide angle, panoramic, spherical, cylinder 1–4).

use std::f64::consts::PI;

use std::sync::Arc;

use crate::math::{DVec3, Ray};
use crate::scene::desc::{CameraDesc, Normal, Projection};
use crate::scene::mesh_camera::MeshCamera;

#[derive(Clone, Debug)]
pub struct Camera {
    pub location: DVec3,
    pub direction: DVec3,
    pub right: DVec3,
    pub up: DVec3,
    /// Parallel rays from points spread over right × up around the location.
    orthographic: bool,
    projection: Projection,
    /// Horizontal and vertical viewing angles (radians) of the angular projections.
    h_angle: f64,
    v_angle: f64,
    width: f64,
    height: f64,
    /// `normal { ... }` in the camera: bends every ray.
    normal: Option<Normal>,
    /// A mesh camera replaces the projection: `ray` is not used then.
    mesh: Option<Arc<MeshCamera>>,
    /// Focal blur: None for a pinhole camera.
    lens: Option<super::focal::Lens>,
    /// Unit direction, right and up (`normalize_or` of Z, X, Y) and the lengths of right and
    /// up, for the angular projections: once per camera, not per ray (`with_axes`).
    unit: [DVec3; 3],
    right_len: f64,
    up_len: f64,
    /// A cylinder camera's (position, sin, cos) of its angle at each pixel centre along the
    /// axis the angle runs (x for cylinders 1 and 3, y for 2 and 4): rays through a pixel's
    /// centre take them from here instead of a `sin_cos` each (the same expressions, so the
    /// same bits); other positions (anti-aliasing's samples) compute their own.
    turns: Arc<[(f64, f64, f64)]>,
}

impl Camera {
    /// This camera moved to `location` with new axes (the preview window's camera): the same
    /// projection; a focal-blur lens turns with the view.
    pub fn posed(&self, location: DVec3, direction: DVec3, right: DVec3, up: DVec3) -> Camera {
        let frame = |d: DVec3, r: DVec3, u: DVec3| {
            glam::DMat3::from_cols(
                r.normalize_or(DVec3::X),
                u.normalize_or(DVec3::Y),
                d.normalize_or(DVec3::Z),
            )
        };
        // The turn taking the old axes to the new ones (both frames orthonormal up to
        // lengths, so the inverse of the old is its transpose).
        let turn =
            frame(direction, right, up) * frame(self.direction, self.right, self.up).transpose();
        Camera {
            location,
            direction,
            right,
            up,
            lens: self.lens.as_ref().map(|l| l.turned(|v| turn * v)),
            ..self.clone()
        }
        .with_axes()
    }

    /// The camera with `unit`, `right_len` and `up_len` made from its vectors.
    fn with_axes(self) -> Camera {
        Camera {
            unit: [
                self.direction.normalize_or(DVec3::Z),
                self.right.normalize_or(DVec3::X),
                self.up.normalize_or(DVec3::Y),
            ],
            right_len: self.right.length(),
            up_len: self.up.length(),
            ..self
        }
    }

    /// The camera of a built scene, for the picture size it was built for.
    pub fn of_scene(scene: &crate::scene::build::Scene) -> Camera {
        Camera::new(&scene.camera, scene.size.0, scene.size.1)
    }

    pub fn new(d: &CameraDesc, width: u32, height: u32) -> Camera {
        let mut dir = d.direction;
        let mut right = d.right;
        let mut up = d.up;
        // The angular projections take the angle as it is (when none is given, 360° for the
        // spherical camera and 90° for the others, as povray does); the perspective one turns
        // it into the direction's length.
        let default = if d.projection == Projection::Spherical {
            360.0
        } else {
            90.0
        };
        let h_angle = d.angle.unwrap_or(default).to_radians();
        let v_angle = d.v_angle.map(f64::to_radians).unwrap_or(h_angle * 0.5);
        if let (Some(angle), Projection::Perspective) = (d.angle, d.projection) {
            let a = angle.clamp(1e-6, 179.999).to_radians();
            dir = dir.normalize_or(DVec3::Z) * (0.5 * right.length() / (a * 0.5).tan());
        }
        if let Some(look) = d.look_at {
            // Keep the handedness the vectors had (right = -x cameras stay mirrored). When up
            // and direction are parallel (`up z` with the default direction, sample scenes
            // objects/prism3*.pov) the test gives zero, which POV-Ray takes as right-handed:
            // its pictures of those scenes are mirrored.
            let left_handed = up.cross(dir).dot(right) > 0.0;
            let dl = dir.length();
            let new_dir = (look - d.location).normalize_or(dir.normalize_or(DVec3::Z));
            let mut r = d.sky.cross(new_dir);
            if r.length_squared() < 1e-20 {
                // Looking straight along the sky vector: POV-Ray keeps the old right vector.
                r = right;
            }
            let rl = right.length();
            right = r.normalize() * rl;
            if !left_handed {
                right = -right;
            }
            dir = new_dir * dl;
            let ul = up.length();
            up = dir.cross(right).normalize_or(DVec3::Y) * ul;
            if !left_handed {
                up = -up;
            }
        }
        if d.orthographic && (!d.sized || d.angle_given) {
            // The view area of the perspective camera this one replaces, taken at the look_at
            // point: objects there keep their size (manual 3.4.2.2.2). Without look_at POV-Ray
            // measures to its default look_at, <0,0,1> (checked with povray 3.7).
            let dist = (d.look_at.unwrap_or(DVec3::Z) - d.location).length();
            let k = dist / dir.length().max(1e-12);
            right *= k;
            up *= k;
        }
        let t = &d.transform;
        let lens = super::focal::Lens::new(
            &d.blur,
            d.location,
            t.vector(right),
            t.vector(up),
            t.vector(dir),
        );
        Camera {
            lens,
            orthographic: d.orthographic,
            projection: d.projection,
            h_angle,
            v_angle,
            location: t.point(d.location),
            direction: t.vector(dir),
            right: t.vector(right),
            up: t.vector(up),
            width: width as f64,
            height: height as f64,
            normal: d
                .normal
                .clone()
                .filter(|n| super::normal::perturbs(Some(n))),
            mesh: d.mesh.as_ref().map(|m| {
                Arc::new(MeshCamera::new(
                    m,
                    d.location.z,
                    d.direction.z < -1e-10,
                    width,
                    height,
                ))
            }),
            unit: [DVec3::Z, DVec3::X, DVec3::Y],
            right_len: 1.0,
            up_len: 1.0,
            turns: Arc::new([]),
        }
        .with_axes()
        .with_turns(width, height)
    }

    fn with_turns(self, width: u32, height: u32) -> Camera {
        let Projection::Cylinder(kind) = self.projection else {
            return self;
        };
        let along_x = kind == 1 || kind == 3;
        let n = if along_x { width } else { height };
        let turns = (0..n)
            .map(|i| {
                let pos = i as f64 + 0.5;
                let a = self.cylinder_angle(along_x, pos);
                (pos, a.sin(), a.cos())
            })
            .collect();
        Camera { turns, ..self }
    }

    /// A cylinder camera's angle at picture position `pos` along x (`along_x`) or y.
    #[inline]
    fn cylinder_angle(&self, along_x: bool, pos: f64) -> f64 {
        if along_x {
            (pos / self.width - 0.5) * self.h_angle
        } else {
            (0.5 - pos / self.height) * self.h_angle
        }
    }

    /// (sin, cos) of a cylinder camera's angle at picture position `pos`.
    #[inline]
    fn cylinder_turn(&self, along_x: bool, pos: f64) -> (f64, f64) {
        match self.turns.get(pos as usize) {
            Some(&(at, s, c)) if at.to_bits() == pos.to_bits() => (s, c),
            _ => {
                let a = self.cylinder_angle(along_x, pos);
                (a.sin(), a.cos())
            }
        }
    }

    /// The mesh camera, when the scene has one: its pixels take several rays or none.
    /// What kind of camera this is when it is not a plain perspective one (the preview's
    /// copied camera block cannot say everything about those).
    pub fn unusual_kind(&self) -> Option<&'static str> {
        if self.mesh.is_some() {
            return Some("a mesh camera");
        }
        if self.orthographic {
            return Some("orthographic");
        }
        match self.projection {
            Projection::Perspective => None,
            Projection::Fisheye => Some("fisheye"),
            Projection::UltraWideAngle => Some("ultra_wide_angle"),
            Projection::Omnimax => Some("omnimax"),
            Projection::Panoramic => Some("panoramic"),
            Projection::Spherical => Some("spherical"),
            Projection::Cylinder(_) => Some("cylinder"),
        }
    }

    pub fn mesh(&self) -> Option<&MeshCamera> {
        self.mesh.as_deref()
    }

    /// The focal-blur lens, when the camera has one.
    pub fn lens(&self) -> Option<&super::focal::Lens> {
        self.lens.as_ref()
    }

    /// Ray through image position (px, py) in pixels from the top-left corner; pixel centres
    /// are at +0.5. None where the projection shows nothing (outside a fisheye's circle).
    #[inline]
    pub fn ray(&self, px: f64, py: f64) -> Option<Ray> {
        if self.plain() {
            return Some(self.plain_ray(px, py));
        }
        self.bent_ray(px, py)
    }

    /// A perspective camera without a `normal`: `plain_ray` is its `ray`.
    #[inline]
    pub fn plain(&self) -> bool {
        self.normal.is_none() && !self.orthographic && self.projection == Projection::Perspective
    }

    /// `ray` of a `plain` camera, inline in the caller's pixel loop: the ray is built where
    /// the caller keeps it instead of being copied out of a returned Option (whose copy's
    /// misaligned loads of the just-stored values stalled every pixel), and the other
    /// projections stay out of the loop.
    #[inline]
    pub fn plain_ray(&self, px: f64, py: f64) -> Ray {
        let dx = px / self.width - 0.5;
        let dy = 0.5 - py / self.height;
        Ray::new(
            self.location,
            self.direction + self.right * dx + self.up * dy,
        )
    }

    /// `ray` for every camera but the plain perspective one.
    #[inline(never)]
    fn bent_ray(&self, px: f64, py: f64) -> Option<Ray> {
        let ray = self.straight_ray(px, py)?;
        let Some(n) = &self.normal else {
            return Some(ray);
        };
        // The pattern is evaluated at the pixel's place in the picture, (u, v, 0) with u and v
        // from -1/2 to 1/2 across its width and height (v up), whatever the lengths of right
        // and up, and perturbs the unit direction. Measured: `gradient x` / `gradient y`
        // camera normals at scale 0.37 put their jumps every 0.37 of the picture's width and
        // height under right 4/3 or 2 and up 1 or 3 (tests/probes/camera_normal_plane.pov).
        let d = ray.dir.normalize_or(DVec3::Z);
        let at = DVec3::new(px / self.width - 0.5, 0.5 - py / self.height, 0.0);
        Some(Ray::new(ray.origin, super::normal::perturb(n, at, d)))
    }

    fn straight_ray(&self, px: f64, py: f64) -> Option<Ray> {
        let dx = px / self.width - 0.5;
        let dy = 0.5 - py / self.height;
        if self.orthographic {
            return Some(Ray::new(
                self.location + self.right * dx + self.up * dy,
                self.direction,
            ));
        }
        // The unit axes once per camera: three square roots and divisions a ray were a
        // twentieth of a small scene's time.
        let [d, r, u] = self.unit;
        let dir = match self.projection {
            Projection::Perspective => self.direction + self.right * dx + self.up * dy,
            Projection::Fisheye => {
                // A circle filling the height; the right/up lengths keep it round.
                let x = 2.0 * dx * self.right_len / self.up_len.max(1e-12);
                let y = 2.0 * dy;
                let rad = (x * x + y * y).sqrt();
                if rad > 1.0 {
                    return None;
                }
                let theta = rad * self.h_angle * 0.5;
                let phi = y.atan2(x);
                d * theta.cos() + (r * phi.cos() + u * phi.sin()) * theta.sin()
            }
            Projection::Omnimax => {
                let aspect = self.right_len / self.up_len.max(1e-12);
                let (x, y) = omnimax_disc(dx, dy, aspect);
                let rad = (x * x + y * y).sqrt();
                if rad > 1.0 {
                    return None;
                }
                let theta = omnimax_theta(rad);
                let phi = y.atan2(x);
                let (st, ct) = theta.sin_cos();
                // The dome's lower edge: nothing more than 45° below the view axis.
                if st * phi.sin() + ct < 0.0 {
                    return None;
                }
                d * ct + (r * phi.cos() + u * phi.sin()) * st
            }
            Projection::UltraWideAngle => {
                let v = self.h_angle * self.up_len / self.right_len.max(1e-12);
                let (xa, ya) = (dx * self.h_angle, dy * v);
                r * xa.sin() + u * ya.sin() + d * (xa.cos() * ya.cos())
            }
            Projection::Panoramic => {
                // The vectors' own lengths shape the view (manual 3.4.2.2.7).
                let (xa, ya) = (dx * PI, dy * PI);
                (self.direction * xa.cos() + self.right * xa.sin()) * ya.cos() + self.up * ya.sin()
            }
            Projection::Spherical => {
                let (xa, ya) = (dx * self.h_angle, dy * self.v_angle);
                (d * xa.cos() + r * xa.sin()) * ya.cos() + u * ya.sin()
            }
            Projection::Cylinder(kind) => {
                let along_x = kind == 1 || kind == 3;
                let (s, c) = self.cylinder_turn(along_x, if along_x { px } else { py });
                return Some(match kind {
                    1 => Ray::new(self.location, d * c + r * s + self.up * dy),
                    2 => Ray::new(self.location, d * c + u * s + self.right * dx),
                    3 => Ray::new(self.location + self.up * dy, d * c + r * s),
                    _ => Ray::new(self.location + self.right * dx, d * c + u * s),
                });
            }
        };
        Some(Ray::new(self.location, dir))
    }
}

/// Where picture position (dx, dy) (each from -1/2 to 1/2, y up) lies on the omnimax disc,
/// whose unit circle is the dome's 180° rim; measured from `povray` by
/// scripts/measure_omnimax.sh (docs/povray-behaviour.md). The disc's top touches the picture's
/// top; for a right/up ratio `aspect` above 1 the disc's centre moves down until the
/// picture's bottom reaches the dome's lower edge (at `aspect` = OMNIMAX_FULL), beyond which
/// wider pictures only widen the view.
fn omnimax_disc(dx: f64, dy: f64, aspect: f64) -> (f64, f64) {
    let a = aspect.min(OMNIMAX_FULL);
    let sy = 2.0 / a;
    let centre = -(a - 1.0).max(0.0) * 0.5;
    (sy * aspect * dx, sy * (dy - centre))
}

/// The aspect at which the omnimax picture's bottom edge reaches the dome's lower edge:
/// 2 / (1 + r) where `omnimax_theta(r)` is 45°.
const OMNIMAX_FULL: f64 = 1.283_457_7;

/// The angle from the view axis of a point `rad` from the omnimax disc's centre: an odd
/// quintic, fitted to 4096 directions `povray` traces along a picture row (residual 2e-5
/// radians, the 16-bit measurement's own noise).
fn omnimax_theta(rad: f64) -> f64 {
    let r2 = rad * rad;
    rad * (1.411_270_4 + r2 * (-0.094_396_01 + r2 * 0.256_745_57))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_camera_looks_down_z() {
        let c = Camera::new(&CameraDesc::default(), 4, 3);
        let r = c.ray(2.0, 1.5).unwrap();
        assert!((r.dir - DVec3::Z).length() < 1e-12);
    }

    /// Rays through pixel centres from the table are the rays computed afresh, bit for bit,
    /// and positions off the centres (or off the picture) compute their own.
    #[test]
    fn cylinder_turns_are_the_computed_ones() {
        for kind in 1..=4 {
            let d = CameraDesc {
                projection: Projection::Cylinder(kind),
                angle: Some(200.0),
                location: DVec3::new(8.0, 10.0, 5.0),
                look_at: Some(DVec3::new(0.0, 10.0, 0.0)),
                ..CameraDesc::default()
            };
            let cam = Camera::new(&d, 37, 23);
            assert_eq!(cam.turns.len(), if kind % 2 == 1 { 37 } else { 23 });
            let fresh = Camera {
                turns: Arc::new([]),
                ..cam.clone()
            };
            let bits = |r: Ray| [r.origin, r.dir].map(|v| v.to_array().map(f64::to_bits));
            for y in -1..25 {
                for x in -1..39 {
                    for (dx, dy) in [(0.5, 0.5), (0.25, 0.5), (0.5, 0.75), (0.0, 0.0)] {
                        let (px, py) = (x as f64 + dx, y as f64 + dy);
                        let (a, b) = (cam.ray(px, py).unwrap(), fresh.ray(px, py).unwrap());
                        assert_eq!(bits(a), bits(b), "cylinder {kind} at ({px}, {py})");
                    }
                }
            }
        }
    }

    #[test]
    fn look_at_keeps_lengths_and_sky() {
        let d = CameraDesc {
            location: DVec3::new(0.0, 0.0, -5.0),
            look_at: Some(DVec3::new(5.0, 0.0, 0.0)),
            ..CameraDesc::default()
        };
        let c = Camera::new(&d, 4, 3);
        assert!((c.direction.length() - 1.0).abs() < 1e-12);
        assert!((c.right.length() - 1.33).abs() < 1e-12);
        assert!(c.up.dot(DVec3::Y) > 0.999);
        assert!(
            c.right.cross(c.up).dot(c.direction) > 0.0,
            "same frame orientation as the default camera"
        );
    }
}
