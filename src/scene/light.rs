//! Light sources as the renderer uses them: point, spot and cylinder lights, parallel lights
//! and area lights, resolved from the scene description into world space.
//!
//! The spot and cylinder falloff curves were measured with povray 3.7 on a plane lit from
//! above (tests/probes/light_*.pov): full intensity inside `radius`, a smoothstep down to zero
//! at `falloff`, times cos(angle)^tightness for spotlights and (1 − distance/falloff)^tightness
//! for cylinders. A cylinder light shines along its axis, like a parallel light.

use crate::math::{DVec3, Transform};
use crate::scene::desc::{AreaLightDesc, LightDesc, LightKind};

#[derive(Clone, Debug)]
pub struct Light {
    pub position: DVec3,
    pub color: DVec3,
    pub shadowless: bool,
    pub fade_distance: Option<f64>,
    pub fade_power: f64,
    pub cone: Cone,
    /// Unit direction the light travels, for parallel and cylinder lights.
    pub parallel: Option<DVec3>,
    /// An array of point lights for soft shadows (axes in world space); lighting itself
    /// comes from the centre.
    pub area: Option<AreaLightDesc>,
    /// `projected_through`: light arrives only along paths that cross this object (not part
    /// of the scene), and only objects between the point and it cast shadows.
    pub projected: Option<Projected>,
    /// The `light_group` it belongs to (0: none, it lights everything outside groups).
    pub group: u16,
    pub media_interaction: bool,
    pub media_attenuation: bool,
    /// Whether it shoots photons that refract and reflect (with global photons on).
    pub photons: crate::scene::photon::LightPhotons,
}

/// A `projected_through` object, shared by copies of the light.
#[derive(Clone)]
pub struct Projected(pub std::sync::Arc<crate::scene::object::Object>);

impl std::fmt::Debug for Projected {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Projected(..)")
    }
}

/// The shape of a light's beam.
#[derive(Clone, Copy, Debug)]
pub enum Cone {
    Point,
    Spot {
        axis: DVec3,
        cos_radius: f64,
        cos_falloff: f64,
        tightness: f64,
    },
    Cylinder {
        axis: DVec3,
        radius: f64,
        falloff: f64,
        tightness: f64,
    },
}

/// How a light reaches a point.
#[derive(Clone, Copy, Debug)]
pub struct Incidence {
    /// Unit vector from the point towards the light.
    pub l: DVec3,
    /// Length of the shadow ray; None where the point gets light without shadows (above a
    /// parallel light's plane).
    pub shadow_dist: Option<f64>,
    /// Distance for fading, always to the light's location.
    pub dist: f64,
    /// The beam's share at this point (1 outside spot and cylinder lights).
    pub beam: f64,
}

impl Light {
    pub fn new(d: &LightDesc, t: &Transform) -> Light {
        let position = t.point(d.position);
        let point_at = t.point(d.point_at);
        let axis = (point_at - position).normalize_or(DVec3::Z);
        let cone = match d.kind {
            LightKind::Point => Cone::Point,
            LightKind::Spot => {
                let radius = d.radius.unwrap_or(30.0);
                // A falloff inside the hot-spot makes a hard edge at the radius.
                let falloff = d.falloff.unwrap_or(45.0).max(radius);
                Cone::Spot {
                    axis,
                    cos_radius: radius.to_radians().cos(),
                    cos_falloff: falloff.to_radians().cos(),
                    tightness: d.tightness,
                }
            }
            LightKind::Cylinder => {
                let radius = d.radius.unwrap_or(0.75);
                Cone::Cylinder {
                    axis,
                    radius,
                    falloff: d.falloff.unwrap_or(1.0).max(radius),
                    tightness: d.tightness,
                }
            }
        };
        let parallel = (d.parallel || d.kind == LightKind::Cylinder).then_some(axis);
        Light {
            position,
            color: d.color,
            shadowless: d.shadowless,
            fade_distance: d.fade_distance,
            fade_power: d.fade_power,
            cone,
            parallel,
            area: d.area.as_ref().map(|a| AreaLightDesc {
                axis1: t.vector(a.axis1),
                axis2: t.vector(a.axis2),
                ..a.clone()
            }),
            projected: None,
            group: 0,
            media_interaction: d.media_interaction,
            media_attenuation: d.media_attenuation,
            photons: d.photons,
        }
    }

    /// `fade_distance`/`fade_power`: 2/(1 + (d/fade_distance)^fade_power), full strength at
    /// the fade distance.
    pub fn fade(&self, dist: f64) -> f64 {
        match self.fade_distance {
            Some(fd) if fd > 0.0 && self.fade_power > 0.0 => {
                let x = dist / fd;
                // powf is a libm call; 2 and 1 are the common powers. x·x is the correctly
                // rounded square; glibc's pow(x, 2) is one ulp off it for ~0.08% of x
                // (measured), which moved no picture of scripts/identical_check.sh.
                let xp = if self.fade_power == 2.0 {
                    x * x
                } else if self.fade_power == 1.0 {
                    x
                } else {
                    x.powf(self.fade_power)
                };
                2.0 / (1.0 + xp)
            }
            _ => 1.0,
        }
    }

    /// How this light reaches `p`, or None where it does not (outside the beam, or at the
    /// light itself).
    pub fn incidence(&self, p: DVec3) -> Option<Incidence> {
        let to_light = self.position - p;
        let dist = to_light.length();
        if dist <= 0.0 {
            return None;
        }
        // p − position is −to_light, whose length is `dist` to the bit.
        let beam = self.beam_from(p - self.position, dist);
        if beam <= 0.0 {
            return None;
        }
        let (l, shadow_dist) = match self.parallel {
            Some(dir) => {
                // Shadow rays go back along the beam to the plane through the light's
                // location; points beyond that plane are lit but unshadowed.
                let along = to_light.dot(-dir);
                (-dir, (along > 0.0).then_some(along))
            }
            None => (to_light / dist, Some(dist)),
        };
        Some(Incidence {
            l,
            shadow_dist,
            dist,
            beam,
        })
    }

    pub fn beam(&self, p: DVec3) -> f64 {
        let w = p - self.position;
        self.beam_from(w, w.length())
    }

    /// `beam` at the point `w` from the light, `len` = |w| (so callers that know it save a
    /// square root): the same arithmetic as `beam`, bit for bit.
    fn beam_from(&self, w: DVec3, len: f64) -> f64 {
        match self.cone {
            Cone::Point => 1.0,
            Cone::Spot {
                axis,
                cos_radius,
                cos_falloff,
                tightness,
            } => {
                // glam's normalize_or_zero, with the length already known. `w` was just
                // stored by the caller (a third of this function's samples on cornell waited
                // on it before `by_coordinates`).
                let DVec3 { x, y, z } = crate::math::by_coordinates(&w);
                let rcp = 1.0 / len;
                let unit = if rcp.is_finite() && rcp > 0.0 {
                    DVec3::new(x * rcp, y * rcp, z * rcp)
                } else {
                    DVec3::ZERO
                };
                let c = unit.dot(axis);
                if c <= cos_falloff {
                    return 0.0;
                }
                let edge = if c >= cos_radius || cos_radius <= cos_falloff {
                    1.0
                } else {
                    smoothstep((c - cos_falloff) / (cos_radius - cos_falloff))
                };
                if tightness == 1.0 {
                    // powf(c, 1) is c exactly, without the libm call.
                    edge * c
                } else if tightness != 0.0 {
                    edge * c.powf(tightness)
                } else {
                    edge
                }
            }
            Cone::Cylinder {
                axis,
                radius,
                falloff,
                tightness,
            } => {
                let v = w;
                if v.dot(axis) <= 0.0 {
                    return 0.0;
                }
                let d = (v - axis * v.dot(axis)).length();
                if d >= falloff {
                    return 0.0;
                }
                let edge = if d <= radius || falloff <= radius {
                    1.0
                } else {
                    smoothstep((falloff - d) / (falloff - radius))
                };
                if tightness != 0.0 {
                    edge * (1.0 - d / falloff).powf(tightness)
                } else {
                    edge
                }
            }
        }
    }
}

fn smoothstep(t: f64) -> f64 {
    let t = t.clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

impl AreaLightDesc {
    /// The array point (i, j) relative to the light's centre, for a light seen from `from`
    /// (unit vector from the light towards the shaded point, used by `orient`). `jitter` is a
    /// pair in [-0.5, 0.5) moving the point within its cell.
    pub fn point(&self, i: u32, j: u32, from: DVec3, jitter: (f64, f64)) -> DVec3 {
        self.point_on(i, j, self.axes(from), jitter)
    }

    /// The array's axes as seen from direction `from` (turned to face it with `orient`): the
    /// same for every point of the array, so a shaded point asks once.
    pub fn axes(&self, from: DVec3) -> (DVec3, DVec3) {
        if self.orient {
            orient_axes(self.axis1, self.axis2, from)
        } else {
            (self.axis1, self.axis2)
        }
    }

    /// `point` with the axes `axes` gave.
    pub fn point_on(&self, i: u32, j: u32, axes: (DVec3, DVec3), jitter: (f64, f64)) -> DVec3 {
        self.grid(axes).point(i, j, jitter)
    }

    /// The array with the axes `axes` gave, its cell sizes worked out once for all of its
    /// points (a shaded point asks for up to size1·size2 of them).
    pub fn grid(&self, axes: (DVec3, DVec3)) -> AreaGrid {
        let cell = |n: u32| if n <= 1 { 0.0 } else { 1.0 / (n - 1) as f64 };
        AreaGrid {
            axes,
            cells: (cell(self.size1), cell(self.size2)),
            sizes: (self.size1, self.size2),
            circular: self.circular,
        }
    }
}

/// An area light's array as one shaded point sees it: `AreaLightDesc::grid`.
#[derive(Clone, Copy, Debug)]
pub struct AreaGrid {
    axes: (DVec3, DVec3),
    /// 1/(size − 1) along each axis (unused for a size of 1).
    cells: (f64, f64),
    sizes: (u32, u32),
    circular: bool,
}

impl AreaGrid {
    /// The array point (i, j) relative to the light's centre; `jitter` is a pair in
    /// [-0.5, 0.5) moving the point within its cell.
    #[inline]
    pub fn point(&self, i: u32, j: u32, jitter: (f64, f64)) -> DVec3 {
        let frac = |k: u32, n: u32, cell: f64, jit: f64| {
            if n <= 1 {
                0.0
            } else {
                (k as f64 * cell - 0.5 + jit * cell).clamp(-0.5, 0.5)
            }
        };
        let mut u = frac(i, self.sizes.0, self.cells.0, jitter.0);
        let mut v = frac(j, self.sizes.1, self.cells.1, jitter.1);
        if self.circular {
            (u, v) = square_to_disc(u * 2.0, v * 2.0);
            u *= 0.5;
            v *= 0.5;
        }
        let (a1, a2) = self.axes;
        a1 * u + a2 * v
    }
}

/// [-1, 1]² onto the unit disc, each point pulled in along its ray from the centre so the
/// square's rings become circles (closest to povray of the mappings tried: concentric and
/// elliptical-grid were further off).
fn square_to_disc(a: f64, b: f64) -> (f64, f64) {
    let len = (a * a + b * b).sqrt();
    if len == 0.0 {
        return (0.0, 0.0);
    }
    let k = a.abs().max(b.abs()) / len;
    (a * k, b * k)
}

/// Axes of the same lengths turned to face along `from`, the first kept as close to its
/// own direction as it can be.
fn orient_axes(a1: DVec3, a2: DVec3, from: DVec3) -> (DVec3, DVec3) {
    let n = from.normalize_or(DVec3::Z);
    let mut u = a1 - n * a1.dot(n);
    if u.length_squared() < 1e-12 {
        u = a2 - n * a2.dot(n);
    }
    if u.length_squared() < 1e-12 {
        u = n.any_orthonormal_vector();
    }
    let u = u.normalize();
    let v = n.cross(u);
    (u * a1.length(), v * a2.length())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn light(kind: LightKind, radius: f64, falloff: f64, tightness: f64) -> Light {
        let mut d = LightDesc::at(DVec3::new(0.0, 10.0, 0.0));
        d.kind = kind;
        d.point_at = DVec3::ZERO;
        d.radius = Some(radius);
        d.falloff = Some(falloff);
        d.tightness = tightness;
        Light::new(&d, &Transform::IDENTITY)
    }

    #[test]
    fn spot_falloff_matches_povray_samples() {
        // Intensities povray 3.7 gave on a plane 10 below the light (divided by cos θ).
        let s = light(LightKind::Spot, 10.0, 30.0, 0.0);
        let at = |x: f64| s.beam(DVec3::new(x, 0.0, 0.0));
        assert!((at(1.0) - 1.0).abs() < 1e-9);
        assert!((at(3.99) - 0.54262).abs() < 2e-3);
        assert!((at(2.79) - 0.91232).abs() < 2e-3);
        assert_eq!(at(6.0), 0.0);
        let t = light(LightKind::Spot, 10.0, 30.0, 10.0);
        assert!((t.beam(DVec3::new(2.39, 0.0, 0.0)) - 0.73419).abs() < 3e-3);
    }

    #[test]
    fn cylinder_falloff_matches_povray_samples() {
        let c = light(LightKind::Cylinder, 2.0, 4.0, 0.0);
        let at = |x: f64| c.beam(DVec3::new(x, 0.0, 0.0));
        assert_eq!(at(1.9), 1.0);
        assert!((at(3.19) - 0.35775).abs() < 5e-3);
        assert_eq!(at(4.1), 0.0);
        let t = light(LightKind::Cylinder, 2.0, 4.0, 10.0);
        assert!((t.beam(DVec3::new(0.8, 0.0, 0.0)) - 0.10804).abs() < 2e-3);
        // Cylinder light shines straight down its axis.
        let i = c.incidence(DVec3::new(1.0, 0.0, 0.0)).unwrap();
        assert!((i.l - DVec3::Y).length() < 1e-12);
        assert!((i.shadow_dist.unwrap() - 10.0).abs() < 1e-12);
    }

    #[test]
    fn area_points_span_the_axes() {
        let a = AreaLightDesc {
            axis1: DVec3::X * 2.0,
            axis2: DVec3::Z * 2.0,
            size1: 3,
            size2: 3,
            adaptive: None,
            jitter: false,
            circular: false,
            orient: false,
            illumination: false,
        };
        assert_eq!(
            a.point(0, 0, DVec3::Y, (0.0, 0.0)),
            DVec3::new(-1.0, 0.0, -1.0)
        );
        assert_eq!(a.point(1, 1, DVec3::Y, (0.0, 0.0)), DVec3::ZERO);
        assert_eq!(
            a.point(2, 0, DVec3::Y, (0.0, 0.0)),
            DVec3::new(1.0, 0.0, -1.0)
        );
    }

    /// The grid's points are the array points as each was computed on its own before the
    /// cell sizes were shared (`1/(n − 1)` per point), to the bit.
    #[test]
    fn grid_points_match_per_point_arithmetic() {
        let frac = |k: u32, n: u32, jit: f64| {
            if n <= 1 {
                0.0
            } else {
                let cell = 1.0 / (n - 1) as f64;
                (k as f64 * cell - 0.5 + jit * cell).clamp(-0.5, 0.5)
            }
        };
        let axes = (DVec3::new(4.0, 0.1, 0.0), DVec3::new(0.0, 0.3, 7.0));
        for (n1, n2, circular) in [(10, 10, false), (9, 7, true), (1, 5, false), (3, 1, true)] {
            let a = AreaLightDesc {
                axis1: axes.0,
                axis2: axes.1,
                size1: n1,
                size2: n2,
                circular,
                ..AreaLightDesc::default()
            };
            let grid = a.grid(axes);
            for i in 0..n1 {
                for j in 0..n2 {
                    for jit in [(0.0, 0.0), (0.37, -0.21), (-0.5, 0.49)] {
                        let (mut u, mut v) = (frac(i, n1, jit.0), frac(j, n2, jit.1));
                        if circular {
                            (u, v) = square_to_disc(u * 2.0, v * 2.0);
                            u *= 0.5;
                            v *= 0.5;
                        }
                        let bits = |p: DVec3| p.to_array().map(f64::to_bits);
                        let want = bits(axes.0 * u + axes.1 * v);
                        assert_eq!(bits(grid.point(i, j, jit)), want);
                        assert_eq!(bits(a.point_on(i, j, axes, jit)), want);
                    }
                }
            }
        }
    }
}
