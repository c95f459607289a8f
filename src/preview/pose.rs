//! The preview camera's pose: where the camera stands and where its axes point, the moves the
//! keyboard and mouse make (all in the camera's own frame, so "forward" is where it looks),
//! and the `camera { }` block that reproduces the current view in a scene file.

use crate::math::DVec3;
use crate::render::camera::Camera;

/// A camera's location and axes, with their lengths (they set the field of view), and the
/// point the mouse orbits around.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    pub location: DVec3,
    pub direction: DVec3,
    pub right: DVec3,
    pub up: DVec3,
    /// The orbit centre: the scene's look_at point, carried along by translations.
    pub pivot: DVec3,
    /// Not a plain perspective camera: what it is (see `Camera::unusual_kind`).
    pub unusual: Option<&'static str>,
}

/// A turn of `angle` radians around unit `axis` (Rodrigues' formula): around +y a positive
/// angle takes +z towards +x, which in POV-Ray's left-handed frame (x right, z ahead) is a
/// turn to the right.
fn turn(v: DVec3, axis: DVec3, angle: f64) -> DVec3 {
    let (s, c) = angle.sin_cos();
    v * c + axis.cross(v) * s + axis * axis.dot(v) * (1.0 - c)
}

impl Pose {
    /// The pose of a built camera; the pivot is ahead at `reach` (the distance to the scene's
    /// look_at point, when it gave one), else at ten times the direction's length.
    pub fn of(camera: &Camera, reach: Option<f64>) -> Pose {
        let reach = reach
            .filter(|r| *r > 1e-9)
            .unwrap_or(10.0 * camera.direction.length());
        let pivot = camera.location + camera.direction.normalize_or(DVec3::Z) * reach;
        Pose {
            location: camera.location,
            direction: camera.direction,
            right: camera.right,
            up: camera.up,
            pivot,
            unusual: camera.unusual_kind(),
        }
    }

    /// Distance from the camera to the pivot: the scale of the scene for movement speeds.
    pub fn reach(&self) -> f64 {
        (self.pivot - self.location).length().max(1e-3)
    }

    /// Moves by `forward`, `sideways` (towards +right) and `lift` (towards +up), in scene
    /// units along the camera's own unit axes.
    pub fn translate(&mut self, forward: f64, sideways: f64, lift: f64) {
        let d = self.direction.normalize_or(DVec3::Z) * forward
            + self.right.normalize_or(DVec3::X) * sideways
            + self.up.normalize_or(DVec3::Y) * lift;
        self.location += d;
        self.pivot += d;
    }

    /// Turns the camera in place: `yaw` radians around its up axis (positive turns right),
    /// `pitch` around its right axis (positive turns up). The pivot turns with the view and
    /// keeps its distance.
    pub fn rotate(&mut self, yaw: f64, pitch: f64) {
        let reach = self.reach();
        let handed = self.handedness();
        let up = self.up.normalize_or(DVec3::Y);
        self.direction = turn(self.direction, up, yaw * handed);
        self.right = turn(self.right, up, yaw * handed);
        let right = self.right.normalize_or(DVec3::X);
        self.direction = turn(self.direction, right, -pitch * handed);
        self.up = turn(self.up, right, -pitch * handed);
        self.pivot = self.location + self.direction.normalize_or(DVec3::Z) * reach;
    }

    /// Orbits the camera around the pivot: `yaw` radians around the camera's up axis through
    /// the pivot, `pitch` around its right axis, always facing the pivot.
    pub fn orbit(&mut self, yaw: f64, pitch: f64) {
        let handed = self.handedness();
        let up = self.up.normalize_or(DVec3::Y);
        let spin = |v: DVec3, axis: DVec3, a: f64| turn(v, axis, a);
        let mut offset = self.location - self.pivot;
        offset = spin(offset, up, yaw * handed);
        self.direction = spin(self.direction, up, yaw * handed);
        self.right = spin(self.right, up, yaw * handed);
        let right = self.right.normalize_or(DVec3::X);
        offset = spin(offset, right, -pitch * handed);
        self.direction = spin(self.direction, right, -pitch * handed);
        self.up = spin(self.up, right, -pitch * handed);
        self.location = self.pivot + offset;
    }

    /// +1 for POV-Ray's usual left-handed camera (right = up × direction), −1 for a mirrored
    /// one, so that the keys turn the view the way they say either way.
    fn handedness(&self) -> f64 {
        if self.up.cross(self.direction).dot(self.right) >= 0.0 {
            1.0
        } else {
            -1.0
        }
    }

    /// The camera with this pose.
    pub fn apply(&self, camera: &Camera) -> Camera {
        camera.posed(self.location, self.direction, self.right, self.up)
    }

    /// The horizontal field of view in degrees, as POV-Ray's `angle`.
    pub fn angle(&self) -> f64 {
        2.0 * (0.5 * self.right.length() / self.direction.length().max(1e-12))
            .atan()
            .to_degrees()
    }

    /// A `camera { }` block giving this view: `right` and `up` carry the lengths and the
    /// handedness, `sky` the up direction, `angle` the field of view and `look_at` the pivot
    /// (POV-Ray applies angle, then look_at with sky, whatever order they are written in).
    pub fn camera_block(&self) -> String {
        let v = |v: DVec3| format!("<{}, {}, {}>", fmt(v.x), fmt(v.y), fmt(v.z));
        if let Some(kind) = self.unusual {
            // angle and look_at mean other things there: the axes as they are, with a note.
            return format!(
                "// the scene's camera is {kind}: add its projection keyword and items; this gives the view's place and axes\ncamera {{\n  location {}\n  right {}\n  up {}\n  direction {}\n}}\n",
                v(self.location),
                v(self.right),
                v(self.up),
                v(self.direction),
            );
        }
        let look = self.location + self.direction.normalize_or(DVec3::Z) * self.reach();
        format!(
            "camera {{\n  perspective\n  location {}\n  right {}\n  up {}\n  sky {}\n  angle {}\n  look_at {}\n}}\n",
            v(self.location),
            v(self.right),
            v(self.up),
            v(self.up.normalize_or(DVec3::Y)),
            fmt(self.angle()),
            v(look),
        )
    }
}

/// The distance from a camera to its look_at point, when the scene gave one.
pub fn look_reach(desc: &crate::scene::desc::CameraDesc) -> Option<f64> {
    desc.look_at.map(|l| (l - desc.location).length())
}

/// Enough digits to reproduce the view, without float noise such as 0.30000000000000004.
fn fmt(x: f64) -> String {
    let s = format!("{x:.9}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.into()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::desc::CameraDesc;

    fn close(a: DVec3, b: DVec3) -> bool {
        (a - b).length() < 1e-6
    }

    fn camera(text: &str) -> (Camera, Option<f64>) {
        let mut p = crate::sdl::Parser::new(crate::sdl::ParseOptions::default());
        p.parse_str("t.pov", text).expect("parses");
        let desc: &CameraDesc = &p.scene.camera;
        (Camera::new(desc, 320, 240), look_reach(desc))
    }

    #[test]
    fn moves_follow_the_camera_axes() {
        let (c, look) = camera("camera { location <0, 0, -5> look_at 0 }");
        let mut p = Pose::of(&c, look);
        assert!(close(p.pivot, DVec3::ZERO));
        p.translate(1.0, 0.0, 0.0);
        assert!(close(p.location, DVec3::new(0.0, 0.0, -4.0)));
        p.translate(0.0, 2.0, 3.0);
        assert!(close(p.location, DVec3::new(2.0, 3.0, -4.0)));
        // Turning right by 90° looks along +x in the left-handed frame.
        let mut q = Pose::of(&c, look);
        q.rotate(std::f64::consts::FRAC_PI_2, 0.0);
        assert!(close(q.direction.normalize(), DVec3::X));
        assert!(close(q.right.normalize(), -DVec3::Z));
        // Turning up by 90° looks along +y.
        let mut q = Pose::of(&c, look);
        q.rotate(0.0, std::f64::consts::FRAC_PI_2);
        assert!(close(q.direction.normalize(), DVec3::Y));
        // Orbiting keeps the distance to the pivot and faces it.
        let mut q = Pose::of(&c, look);
        q.orbit(0.7, 0.3);
        assert!((q.reach() - 5.0).abs() < 1e-9);
        assert!(close(
            q.direction.normalize(),
            (q.pivot - q.location).normalize()
        ));
    }

    #[test]
    fn unusual_cameras_get_their_axes_and_a_note() {
        let (c, look) = camera("camera { orthographic location <0, 0, -5> look_at 0 }");
        let block = Pose::of(&c, look).camera_block();
        assert!(
            block.starts_with("// the scene's camera is orthographic"),
            "{block}"
        );
        assert!(block.contains("direction") && !block.contains("angle"));
    }

    #[test]
    fn camera_block_reproduces_the_view() {
        let (c, look) = camera("camera { location <1, 2, -5> look_at <0, 1, 0> angle 50 }");
        let mut p = Pose::of(&c, look);
        p.rotate(0.4, -0.2);
        p.translate(0.5, -1.0, 0.25);
        let (again, look2) = camera(&p.camera_block());
        let q = Pose::of(&again, look2);
        for (a, b) in [
            (q.location, p.location),
            (q.direction, p.direction),
            (q.right, p.right),
            (q.up, p.up),
        ] {
            assert!((a - b).length() < 1e-6, "{a} vs {b}\n{}", p.camera_block());
        }
    }
}
