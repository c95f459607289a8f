//! POV-Ray 3.7's mesh camera (manual 3.4.2.2.3): each pixel's rays start on faces of meshes
//! given in the camera block and leave along the face normals, for texture baking and cameras
//! of any shape. Distributions 0 to 3 choose the faces; `location`'s z moves the origins
//! along the normals and a negative `direction` z reverses the rays.

use std::sync::Arc;

use glam::DVec2;

use crate::math::{DVec3, Ray, Transform};
use crate::scene::desc::MeshData;

/// The camera as written: the meshes with the transforms given inside the camera block.
#[derive(Clone, Debug)]
pub struct MeshCameraDesc {
    pub rays_per_pixel: u32,
    pub distribution: u32,
    pub meshes: Vec<(Arc<MeshData>, Transform)>,
    /// `smooth`: distribution 3 interpolates the vertex normals.
    pub smooth: bool,
}

/// A face's ray in world space.
#[derive(Clone, Copy, Debug)]
struct Face {
    centroid: DVec3,
    normal: DVec3,
}

/// A face of the first mesh for distribution 3: its place in uv space and in the world.
#[derive(Clone, Debug)]
struct UvFace {
    uv: [DVec2; 3],
    p: [DVec3; 3],
    /// Vertex normals (world, unit) for `smooth`; the face normal otherwise.
    n: [DVec3; 3],
}

/// Faces worked out together by distribution 0 before their rays are traced.
const BATCH: usize = 16;

/// Cells per side of the uv grid that finds distribution 3's face for a pixel.
const GRID: usize = 64;

#[derive(Debug)]
pub struct MeshCamera {
    rays_per_pixel: u32,
    distribution: u32,
    /// The meshes as written, each face's ray worked out when a ray needs it. Stored faces
    /// (48 bytes each) were 368 MB on ess-ortho-camera (a hundred meshes of a face per
    /// pixel): their build and page faults took ~12 % of its time, and a pixel's hundred
    /// reads, one from each mesh's array, missed the cache another ~15 %. The meshes share
    /// their data, so a pixel's corners stay in cache from ray to ray.
    meshes: Vec<(Arc<MeshData>, Transform)>,
    /// Distribution 1's index of each mesh's first face in the summed list.
    starts: Vec<usize>,
    uv_faces: Vec<UvFace>,
    /// Indices into `uv_faces` of the faces whose uv box overlaps each grid cell, in face order.
    uv_grid: Vec<Vec<u32>>,
    offset: f64,
    reverse: bool,
    width: u32,
    height: u32,
}

/// POV-Ray's face normal: the ess sample cameras, whose triangles are written counter-clockwise
/// seen from the scene, shoot towards +z with it.
fn face_normal(p: &[DVec3; 3]) -> DVec3 {
    (p[2] - p[0]).cross(p[1] - p[0]).normalize_or_zero()
}

impl MeshCamera {
    /// `offset` is the camera's `location` z, `reverse` whether its `direction` z is negative.
    pub fn new(
        d: &MeshCameraDesc,
        offset: f64,
        reverse: bool,
        width: u32,
        height: u32,
    ) -> MeshCamera {
        let smooth = d.smooth;
        let corners =
            |m: &MeshData, t: &Transform, v: [u32; 3]| v.map(|i| t.point(m.vertices[i as usize]));
        let starts = d
            .meshes
            .iter()
            .scan(0, |n, (m, _)| {
                let start = *n;
                *n += m.triangles.len();
                Some(start)
            })
            .collect();
        let mut uv_faces = Vec::new();
        if d.distribution == 3 {
            if let Some((m, t)) = d.meshes.first() {
                for tri in m.triangles.iter() {
                    let Some(uvi) = tri.uv else { continue };
                    let p = corners(m, t, tri.v);
                    let geo = face_normal(&p);
                    let n = match tri.n {
                        // The vertex normals point the way the face normal does.
                        Some(ni) if smooth => ni.map(|i| {
                            let n = t.normal(m.normals[i as usize]).normalize_or_zero();
                            if n.dot(geo) < 0.0 {
                                -n
                            } else {
                                n
                            }
                        }),
                        _ => [geo; 3],
                    };
                    let uv = uvi.map(|i| {
                        let [u, v] = m.uvs[i as usize];
                        DVec2::new(u, v)
                    });
                    uv_faces.push(UvFace { uv, p, n });
                }
            }
        }
        let mut uv_grid = vec![Vec::new(); GRID * GRID];
        let cell = |x: f64| ((x * GRID as f64).floor().max(0.0) as usize).min(GRID - 1);
        for (i, f) in uv_faces.iter().enumerate() {
            let lo = f.uv[0].min(f.uv[1]).min(f.uv[2]);
            let hi = f.uv[0].max(f.uv[1]).max(f.uv[2]);
            if hi.x < 0.0 || hi.y < 0.0 || lo.x > 1.0 || lo.y > 1.0 {
                continue;
            }
            for gy in cell(lo.y)..=cell(hi.y) {
                for gx in cell(lo.x)..=cell(hi.x) {
                    uv_grid[gy * GRID + gx].push(i as u32);
                }
            }
        }
        MeshCamera {
            rays_per_pixel: d.rays_per_pixel.max(1),
            distribution: d.distribution,
            meshes: d.meshes.clone(),
            starts,
            uv_faces,
            uv_grid,
            offset,
            reverse,
            width,
            height,
        }
    }

    /// Face `i` of mesh `m` in world space, when it exists.
    #[inline]
    fn face(&self, m: usize, i: usize) -> Option<Face> {
        let (data, t) = self.meshes.get(m)?;
        if i >= data.triangles.len() {
            return None;
        }
        // Written out: `array::map` here stayed an out-of-line `try_map` call per ray.
        let [a, b, c] = data.triangles.corners(i);
        let v = &data.vertices;
        let p = [
            t.point(v[a as usize]),
            t.point(v[b as usize]),
            t.point(v[c as usize]),
        ];
        Some(Face {
            centroid: (p[0] + p[1] + p[2]) / 3.0,
            normal: face_normal(&p),
        })
    }

    /// Face `k` of the meshes' faces in order, as one list.
    fn summed_face(&self, k: usize) -> Option<Face> {
        let m = self.starts.partition_point(|&s| s <= k).checked_sub(1)?;
        self.face(m, k - self.starts[m])
    }

    fn face_ray(&self, origin: DVec3, normal: DVec3) -> Ray {
        let dir = if self.reverse { -normal } else { normal };
        Ray::new(origin + normal * self.offset, dir)
    }

    /// Calls `f` with each ray of image position (px, py) (pixels from the top-left corner).
    /// A ray whose face does not exist is not shot (the manual: it does not count in the
    /// pixel's average); a pixel without any ray stays black.
    pub fn for_each_ray(&self, px: f64, py: f64, mut f: impl FnMut(Ray)) {
        let (w, h) = (self.width as usize, self.height as usize);
        // povray places a pixel's ray at its corner (x, y), except that the top row is taken
        // at y = 0.5; the face row is y - 1 truncated towards zero, so pixel rows 0 and 1 both
        // take the first row of faces. Measured with one face per pixel (distributions 0-2)
        // and a uv square (distribution 3): tests/probes/mesh_camera*.pov.
        let (xp, yp) = (px - 0.5, (py - 0.5).max(0.5));
        let (x, y) = (
            xp.trunc().max(0.0) as usize,
            (yp - 1.0).trunc().max(0.0) as usize,
        );
        let pixel = w * y + x;
        match self.distribution {
            0 => {
                // A batch of faces worked out before any of their rays is traced: each face's
                // normal ends in a square root and a division, ~40 cycles of latency that a
                // trace in between kept from overlapping with the next face's.
                let mut batch = [Face {
                    centroid: DVec3::ZERO,
                    normal: DVec3::ZERO,
                }; BATCH];
                let rays = self.rays_per_pixel as usize;
                for first in (0..rays).step_by(BATCH) {
                    let mut n = 0;
                    for r in first..rays.min(first + BATCH) {
                        if let Some(face) = self.face(r, pixel) {
                            batch[n] = face;
                            n += 1;
                        }
                    }
                    for face in &batch[..n] {
                        f(self.face_ray(face.centroid, face.normal));
                    }
                }
            }
            1 => {
                for r in 0..self.rays_per_pixel as usize {
                    match self.summed_face(w * h * r + pixel) {
                        Some(face) => f(self.face_ray(face.centroid, face.normal)),
                        None => break,
                    }
                }
            }
            2 => {
                let n = self.meshes.len().max(1);
                let block = (w / n).max(1);
                let m = (x / block).min(n - 1);
                // The face is block width * row + x with x counted from the image's left
                // edge, not the block's: measured (tests/probes/mesh_camera_2.pov).
                let local = block * y + x;
                if let Some(face) = self.face(m, local) {
                    f(self.face_ray(face.centroid, face.normal));
                }
            }
            _ => {
                // Here the right-most column is taken at x = width - 1.5 (measured, as above).
                let xp = xp.min(w as f64 - 1.5);
                let uv = DVec2::new(xp / w as f64, 1.0 - yp / h as f64);
                if let Some((face, b)) = self.uv_face(uv) {
                    let origin = face.p[0] * b.x + face.p[1] * b.y + face.p[2] * b.z;
                    let n =
                        (face.n[0] * b.x + face.n[1] * b.y + face.n[2] * b.z).normalize_or_zero();
                    f(self.face_ray(origin, n));
                }
            }
        }
    }

    /// The first face (in mesh order) whose uv triangle holds `uv`, with its barycentrics.
    fn uv_face(&self, uv: DVec2) -> Option<(&UvFace, DVec3)> {
        if !(0.0..=1.0).contains(&uv.x) || !(0.0..=1.0).contains(&uv.y) {
            return None;
        }
        let cell = |x: f64| ((x * GRID as f64) as usize).min(GRID - 1);
        self.uv_grid[cell(uv.y) * GRID + cell(uv.x)]
            .iter()
            .map(|&i| &self.uv_faces[i as usize])
            .find_map(|face| barycentric(&face.uv, uv).map(|b| (face, b)))
    }
}

/// Barycentric weights of `p` in the triangle `t`, when it lies inside (edges included).
fn barycentric(t: &[DVec2; 3], p: DVec2) -> Option<DVec3> {
    let (e1, e2, d) = (t[1] - t[0], t[2] - t[0], p - t[0]);
    let den = e1.perp_dot(e2);
    if den.abs() < 1e-300 {
        return None;
    }
    let b1 = d.perp_dot(e2) / den;
    let b2 = e1.perp_dot(d) / den;
    let b0 = 1.0 - b1 - b2;
    const EPS: f64 = -1e-12;
    (b0 >= EPS && b1 >= EPS && b2 >= EPS).then_some(DVec3::new(b0, b1, b2))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::desc::MeshTriangle;

    /// Two faces side by side, the second with its corners in the other order.
    fn two_faces() -> Arc<MeshData> {
        Arc::new(MeshData {
            vertices: vec![
                DVec3::ZERO,
                DVec3::new(1.0, 1.0, 0.0),
                DVec3::X,
                DVec3::new(2.0, 0.0, 0.0),
            ],
            normals: Vec::new(),
            triangles: vec![
                MeshTriangle {
                    v: [0, 1, 2],
                    n: None,
                    texture: None,
                    uv: Some([0, 1, 2]),
                },
                MeshTriangle {
                    v: [2, 3, 1],
                    n: None,
                    texture: None,
                    uv: Some([2, 3, 1]),
                },
            ]
            .into(),
            uvs: vec![[0.0, 0.0], [0.5, 1.0], [0.5, 0.0], [1.0, 0.0]],
            textures: Vec::new(),
            inside_vector: None,
        })
    }

    fn rays(cam: &MeshCamera, px: f64, py: f64) -> Vec<Ray> {
        let mut v = Vec::new();
        cam.for_each_ray(px, py, |r| v.push(r));
        v
    }

    #[test]
    fn distribution_0_takes_face_by_pixel_number_and_mesh_by_ray() {
        let m = two_faces();
        let d = MeshCameraDesc {
            rays_per_pixel: 2,
            distribution: 0,
            meshes: vec![
                (m.clone(), Transform::IDENTITY),
                (m, Transform::translate(DVec3::Y)),
            ],
            smooth: false,
        };
        let cam = MeshCamera::new(&d, 0.5, false, 2, 1);
        let r = rays(&cam, 0.5, 1.5);
        assert_eq!(r.len(), 2);
        assert!((r[0].dir - DVec3::Z).length() < 1e-12, "{:?}", r[0].dir);
        let c = DVec3::new(2.0 / 3.0, 1.0 / 3.0, 0.5);
        assert!((r[0].origin - c).length() < 1e-12);
        assert!((r[1].origin - c - DVec3::Y).length() < 1e-12);
        // The second face is wound the other way: its normal faces -z.
        assert!((rays(&cam, 1.5, 0.5)[0].dir + DVec3::Z).length() < 1e-12);
        // Beyond the faces, no ray.
        let cam = MeshCamera::new(&d, 0.0, true, 3, 1);
        assert!(rays(&cam, 2.5, 0.5).is_empty());
        assert!((rays(&cam, 0.5, 0.5)[0].dir + DVec3::Z).length() < 1e-12);
    }

    /// The faces worked out per ray are the stored faces of before, bit for bit: each
    /// mesh's faces in order, distribution 1 summing them across meshes (an empty mesh
    /// among them).
    #[test]
    fn faces_per_ray_match_stored_faces() {
        let m = two_faces();
        let empty = Arc::new(MeshData {
            triangles: Vec::<MeshTriangle>::new().into(),
            ..(*m).clone()
        });
        let meshes = vec![
            (m.clone(), Transform::rotate(DVec3::new(10.0, 20.0, 30.0))),
            (empty, Transform::IDENTITY),
            (
                m,
                Transform::translate(DVec3::new(0.1, -0.3, 7.0))
                    .then(&Transform::scale(DVec3::new(1.0, 3.0, 0.5))),
            ),
        ];
        let stored: Vec<Face> = meshes
            .iter()
            .flat_map(|(m, t)| {
                m.triangles.iter().map(move |tri| {
                    let p = tri.v.map(|i| t.point(m.vertices[i as usize]));
                    Face {
                        centroid: (p[0] + p[1] + p[2]) / 3.0,
                        normal: face_normal(&p),
                    }
                })
            })
            .collect();
        let d = MeshCameraDesc {
            rays_per_pixel: 4,
            distribution: 1,
            meshes,
            smooth: false,
        };
        let cam = MeshCamera::new(&d, 0.25, false, 1, 1);
        let bits =
            |f: &Face| [f.centroid.to_array(), f.normal.to_array()].map(|a| a.map(f64::to_bits));
        for (k, f) in stored.iter().enumerate() {
            assert_eq!(bits(&cam.summed_face(k).unwrap()), bits(f), "face {k}");
        }
        assert!(cam.summed_face(stored.len()).is_none());
        assert_eq!(bits(&cam.face(2, 1).unwrap()), bits(&stored[3]));
        assert!(cam.face(1, 0).is_none() && cam.face(3, 0).is_none());
        let r = rays(&cam, 0.5, 0.5);
        assert_eq!(r.len(), 4);
        assert_eq!(r[3].origin, stored[3].centroid + stored[3].normal * 0.25);
    }

    #[test]
    fn distribution_1_sums_meshes_and_3_maps_uv() {
        let m = two_faces();
        let d = MeshCameraDesc {
            rays_per_pixel: 2,
            distribution: 1,
            meshes: vec![(m.clone(), Transform::IDENTITY)],
            smooth: false,
        };
        let cam = MeshCamera::new(&d, 0.0, false, 1, 1);
        assert_eq!(rays(&cam, 0.5, 0.5).len(), 2);
        let d = MeshCameraDesc {
            rays_per_pixel: 1,
            distribution: 3,
            meshes: vec![(m, Transform::IDENTITY)],
            smooth: false,
        };
        let cam = MeshCamera::new(&d, 0.0, false, 4, 4);
        // The pixel at corner (0.5, 3.5) is uv (0.125, 0.125): inside the first face at
        // (0.25, 0.125, 0).
        let r = rays(&cam, 1.0, 4.0);
        assert!(
            (r[0].origin - DVec3::new(0.25, 0.125, 0.0)).length() < 1e-12,
            "{r:?}"
        );
        // uv (0.625, 0.875) (the right-most column is taken at x = 2.5) is outside both.
        assert!(rays(&cam, 3.5, 0.5).is_empty());
    }
}
