//! POV-Ray `mesh` / `mesh2`: many flat and smooth triangles behind one BVH.
//!
//! The triangle data stays shared in the `Arc<MeshData>` (every copy of a declared mesh points
//! at it); a `Mesh` adds only edge vectors for the intersection test and the hierarchy.
//! `Hit::part` is the index into `MeshData::triangles`, `Hit::uv` the barycentrics.

use std::sync::Arc;

use crate::geom::bvh::Bvh;
use crate::geom::triangle::{smooth_normal, TriGeom};
use crate::geom::{Hit, Shape};
use crate::math::{Aabb, DVec3, Ray, EPSILON};
use crate::scene::desc::{MeshData, MeshTriangle, Triangles};

pub struct Mesh {
    data: Arc<MeshData>,
    /// Per triangle: false for degenerate ones and ones with out-of-range vertex indices.
    /// The corner and edge vectors are computed from the vertices at each test rather than
    /// kept (72 bytes a triangle, 80 MB for a million): the same subtractions give the same
    /// bits, and the vertices are shared between neighbouring triangles in the cache.
    valid: Vec<bool>,
    /// `data.normals` made unit length once, not on every hit.
    unit_normals: Vec<DVec3>,
    bvh: Bvh,
}

impl std::fmt::Debug for Mesh {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Mesh")
            .field("triangles", &self.valid.len())
            .field("bounds", &self.bvh.bounds())
            .finish()
    }
}

impl Mesh {
    pub fn new(data: Arc<MeshData>) -> Mesh {
        let geom = |c: [u32; 3]| {
            let v = c.map(|i| data.vertices.get(i as usize).copied());
            TriGeom::new([v[0]?, v[1]?, v[2]?])
        };
        let n = data.triangles.len();
        let unit_normals = data.normals.iter().map(|n| n.normalize_or_zero()).collect();
        if let Some((nu, nv)) = grid_cells(&data) {
            // Each triangle's validity is decided where the grid build asks its box, from
            // the corners loaded once for both (a pass of its own loaded them a second time).
            let mut valid = vec![false; n];
            let bvh = Bvh::build_grid(nu, nv, |i| {
                let c = data.triangles.corners(i);
                let v = c.map(|k| data.vertices.get(k as usize).copied());
                let [Some(p0), Some(p1), Some(p2)] = v else {
                    return Aabb::EMPTY;
                };
                if !surely_valid([p0, p1, p2]) && TriGeom::new([p0, p1, p2]).is_none() {
                    return Aabb::EMPTY;
                }
                valid[i] = true;
                // The box of `tri`'s corner and edges.
                valid_bounds(p0, p1 - p0, p2 - p0)
            });
            return Mesh {
                data,
                valid,
                unit_normals,
                bvh,
            };
        }
        let mut valid = Vec::with_capacity(n);
        let mut boxes = Vec::with_capacity(n);
        for i in 0..n {
            let g = geom(data.triangles.corners(i));
            valid.push(g.is_some());
            boxes.push(g.map_or(Aabb::EMPTY, |g| g.bounds()));
        }
        Mesh {
            data,
            valid,
            unit_normals,
            bvh: Bvh::build(&boxes),
        }
    }

    /// Triangle `i`'s corner and edges, bit for bit what `TriGeom::new` made at the build.
    #[inline]
    fn tri(&self, i: usize) -> Option<TriGeom> {
        if !*self.valid.get(i)? {
            return None;
        }
        let v = self.data.triangles.corners(i);
        let p = |k: usize| self.data.vertices[v[k] as usize];
        let p0 = p(0);
        Some(TriGeom {
            p0,
            e1: p(1) - p0,
            e2: p(2) - p0,
        })
    }

    /// The per-triangle texture index (into `MeshData::textures`) of the triangle in
    /// `Hit::part`, if the mesh gave it one.
    pub fn triangle_texture(&self, part: u32) -> Option<u32> {
        self.data.triangles.get(part as usize)?.texture
    }

    /// Vertex normals of a smooth triangle, when all its normal indices are valid.
    fn vertex_normals(&self, i: usize) -> Option<[DVec3; 3]> {
        let n = self.data.triangles.get(i)?.n?;
        let get = |k: u32| self.unit_normals.get(k as usize).copied();
        Some([get(n[0])?, get(n[1])?, get(n[2])?])
    }
}

impl Shape for Mesh {
    fn bounds(&self) -> Aabb {
        self.bvh.bounds()
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        self.bvh.traverse(ray, f64::INFINITY, |i, _| {
            if let Some((t, u, v)) = self.tri(i).and_then(|g| g.intersect(ray, f64::INFINITY)) {
                out.push(Hit {
                    t,
                    part: i as u32,
                    uv: [u, v],
                });
            }
            false
        });
    }

    fn intersect_first(&self, ray: &Ray, tmax: f64, _scratch: &mut Vec<Hit>) -> Option<Hit> {
        let mut best = None;
        self.bvh.traverse(ray, tmax, |i, tmax| {
            if let Some((t, u, v)) = self.tri(i).and_then(|g| g.intersect(ray, *tmax)) {
                *tmax = t;
                best = Some(Hit {
                    t,
                    part: i as u32,
                    uv: [u, v],
                });
            }
            false
        });
        best
    }

    /// Without `inside_vector` a mesh has no inside; with it, a point is inside when the ray
    /// from it along that vector crosses an odd number of triangles.
    fn inside(&self, p: DVec3) -> bool {
        let Some(v) = self.data.inside_vector else {
            return false;
        };
        let mut hits = Vec::new();
        self.intersect_all(&Ray::new(p, v), &mut hits);
        hits.iter().filter(|h| h.t > EPSILON).count() % 2 == 1
    }

    fn normal(&self, _p: DVec3, hit: &Hit) -> DVec3 {
        let i = hit.part as usize;
        let Some(g) = self.tri(i) else {
            return DVec3::Y;
        };
        let geometric = g.geometric_normal();
        match self.vertex_normals(i) {
            Some(n) => smooth_normal(&n, hit.uv, geometric),
            None => geometric,
        }
    }

    /// The triangle's uv_vectors interpolated by the hit's barycentrics.
    fn uv(&self, _p: DVec3, hit: &Hit) -> Option<[f64; 2]> {
        let t = self.data.triangles.get(hit.part as usize)?;
        let get = |k: u32| self.data.uvs.get(k as usize).copied();
        let idx = t.uv?;
        let (a, b, c) = (get(idx[0])?, get(idx[1])?, get(idx[2])?);
        let [u, v] = hit.uv;
        let w = 1.0 - u - v;
        Some([
            a[0] * w + b[0] * u + c[0] * v,
            a[1] * w + b[1] * u + c[1] * v,
        ])
    }
}

/// True only where `TriGeom::new` gives a triangle, decided without its three square roots:
/// the squared test with a factor 4 of margin (2 on the lengths, against a few roundings of
/// 1e-16 each), on squares far from overflow and underflow. Anything else (false) is left to
/// `TriGeom::new` itself.
fn surely_valid(p: [DVec3; 3]) -> bool {
    let (e1, e2) = (p[1] - p[0], p[2] - p[0]);
    let n2 = e1.cross(e2).length_squared();
    let l = e1.length_squared() * e2.length_squared();
    p[0].is_finite() && l > 1e-250 && l < 1e250 && n2 > 4e-28 * l
}

/// `TriGeom { p0, e1, e2 }.bounds()` for a valid triangle, bit for bit, with plain
/// comparisons: a valid triangle's corner and edges are finite, so no NaN reaches the
/// minima and maxima, and where they hold none `f64::min(a, b)` is `if b < a { b } else { a }`
/// (the first operand on a tie of zeros, as its NaN-aware lowering gives). The NaN-aware
/// form's extra instructions were a tenth of a grid mesh's build.
#[inline(always)]
fn valid_bounds(p0: DVec3, e1: DVec3, e2: DVec3) -> Aabb {
    let (p1, p2) = (p0 + e1, p0 + e2);
    let lo = |a: f64, b: f64| if b < a { b } else { a };
    let hi = |a: f64, b: f64| if b > a { b } else { a };
    let min = |a: DVec3, b: DVec3| DVec3::new(lo(a.x, b.x), lo(a.y, b.y), lo(a.z, b.z));
    let max = |a: DVec3, b: DVec3| DVec3::new(hi(a.x, b.x), hi(a.y, b.y), hi(a.z, b.z));
    Aabb::new(min(min(p0, p1), p2), max(max(p0, p1), p2))
}

/// `(nu, nv)` when the triangles are exactly `grid_mesh`'s for an `nu` × `nv` grid (corner
/// indices only: normals and uvs do not shape the hierarchy), so `Bvh::build_grid` can build
/// the hierarchy from the layout.
fn grid_cells(data: &MeshData) -> Option<(usize, usize)> {
    let tris = &data.triangles;
    if tris.is_empty() {
        return None;
    }
    let nu = (tris.corners(0)[2] as usize).checked_sub(2)?;
    if nu == 0 || !tris.len().is_multiple_of(2 * nu) {
        return None;
    }
    let nv = tris.len() / (2 * nu);
    if data.vertices.len() != (nu + 1) * (nv + 1) {
        return None;
    }
    let mut k = 0;
    let same = each_grid_triangle(nu, nv, |t| {
        k += 1;
        tris.corners(k - 1) == t
    });
    same.then_some((nu, nv))
}

/// Calls `f` with the corner indices of `grid_mesh`'s triangles for an `nu` × `nv` grid, in
/// its order (row by row, two triangles a cell), until `f` says stop; whether it went
/// through. A loop rather than an iterator: a nested `flat_map` made objects/bezier's
/// start-up 2-5 ms slower.
fn each_grid_triangle(nu: usize, nv: usize, mut f: impl FnMut([u32; 3]) -> bool) -> bool {
    let idx = |i: usize, j: usize| (j * (nu + 1) + i) as u32;
    for j in 0..nv {
        for i in 0..nu {
            let (a, b, c, d) = (idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1));
            if !f([a, b, c]) || !f([a, c, d]) {
                return false;
            }
        }
    }
    true
}

/// A surface sampled on a regular grid of `nu` × `nv` cells as smooth triangles (bicubic
/// patches, parametric surfaces): `sample(i, j)` gives grid point (i, j)'s position, normal
/// and uv. Triangles with a non-finite corner are left out, and those with a zero corner
/// normal (a pole) are drawn flat.
pub fn grid_mesh(
    nu: usize,
    nv: usize,
    mut sample: impl FnMut(usize, usize) -> (DVec3, DVec3, [f64; 2]),
) -> MeshData {
    let points = (nu + 1) * (nv + 1);
    let mut vertices = Vec::with_capacity(points);
    let mut normals = Vec::with_capacity(points);
    let mut uvs = Vec::with_capacity(points);
    for j in 0..=nv {
        for i in 0..=nu {
            let (p, n, uv) = sample(i, j);
            vertices.push(p);
            normals.push(n);
            uvs.push(uv);
        }
    }
    grid_mesh_of(nu, nv, vertices, normals, uvs)
}

/// `grid_mesh` from its samples, taken row by row (`(nu + 1) × (nv + 1)` of each).
pub fn grid_mesh_of(
    nu: usize,
    nv: usize,
    vertices: Vec<DVec3>,
    normals: Vec<DVec3>,
    uvs: Vec<[f64; 2]>,
) -> MeshData {
    // Where every point is finite and every normal nonzero, every cell gives both triangles,
    // smooth: their normal and uv indices are their corners, stored once for all.
    let triangles =
        if vertices.iter().all(|p| p.is_finite()) && normals.iter().all(|&n| n != DVec3::ZERO) {
            let mut corners = Vec::with_capacity(nu * nv * 2);
            each_grid_triangle(nu, nv, |t| {
                corners.push(t);
                true
            });
            Triangles::same_as_corners(corners)
        } else {
            // Pushed as they come rather than collected and converted: a patch's list of
            // `MeshTriangle`s was 7 MB of fresh pages written once and read once.
            let mut triangles = Triangles::with_capacity(nu * nv * 2);
            each_grid_triangle(nu, nv, |t| {
                if t.iter().all(|&k| vertices[k as usize].is_finite()) {
                    let smooth = t.iter().all(|&k| normals[k as usize] != DVec3::ZERO);
                    triangles.push(MeshTriangle {
                        v: t,
                        n: smooth.then_some(t),
                        texture: None,
                        uv: Some(t),
                    });
                }
                true
            });
            triangles
        };
    MeshData {
        vertices,
        normals,
        triangles,
        uvs,
        textures: Vec::new(),
        inside_vector: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::triangle::Triangle;
    use crate::scene::desc::MeshTriangle;

    /// An icosphere of radius 1 with per-vertex normals, `levels` times subdivided.
    fn icosphere(levels: u32, smooth: bool) -> MeshData {
        let g = (1.0 + 5f64.sqrt()) / 2.0;
        let mut v: Vec<DVec3> = [
            (-1.0, g, 0.0),
            (1.0, g, 0.0),
            (-1.0, -g, 0.0),
            (1.0, -g, 0.0),
            (0.0, -1.0, g),
            (0.0, 1.0, g),
            (0.0, -1.0, -g),
            (0.0, 1.0, -g),
            (g, 0.0, -1.0),
            (g, 0.0, 1.0),
            (-g, 0.0, -1.0),
            (-g, 0.0, 1.0),
        ]
        .iter()
        .map(|&(x, y, z)| DVec3::new(x, y, z).normalize())
        .collect();
        let mut f: Vec<[u32; 3]> = vec![
            [0, 11, 5],
            [0, 5, 1],
            [0, 1, 7],
            [0, 7, 10],
            [0, 10, 11],
            [1, 5, 9],
            [5, 11, 4],
            [11, 10, 2],
            [10, 7, 6],
            [7, 1, 8],
            [3, 9, 4],
            [3, 4, 2],
            [3, 2, 6],
            [3, 6, 8],
            [3, 8, 9],
            [4, 9, 5],
            [2, 4, 11],
            [6, 2, 10],
            [8, 6, 7],
            [9, 8, 1],
        ];
        for _ in 0..levels {
            let mut cache = std::collections::HashMap::new();
            let mut mid = |a: u32, b: u32, v: &mut Vec<DVec3>| {
                *cache.entry((a.min(b), a.max(b))).or_insert_with(|| {
                    v.push((v[a as usize] + v[b as usize]).normalize());
                    v.len() as u32 - 1
                })
            };
            let mut nf = Vec::new();
            for [a, b, c] in f {
                let (ab, bc, ca) = (mid(a, b, &mut v), mid(b, c, &mut v), mid(c, a, &mut v));
                nf.extend([[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
            }
            f = nf;
        }
        let triangles = f.iter().enumerate().map(|(i, &t)| MeshTriangle {
            v: t,
            n: smooth.then_some(t),
            texture: Some(i as u32 % 3),
            uv: None,
        });
        MeshData {
            normals: if smooth { v.clone() } else { vec![] },
            vertices: v,
            triangles: triangles.collect(),
            textures: vec![],
            uvs: vec![],
            inside_vector: None,
        }
    }

    use crate::geom::test_rng::Lcg;

    #[test]
    fn matches_brute_force_over_triangles() {
        let data = Arc::new(icosphere(3, true));
        let mesh = Mesh::new(data.clone());
        assert_eq!(data.triangles.len(), 1280);
        let tris: Vec<Triangle> = data
            .triangles
            .iter()
            .map(|t| Triangle::new(t.v.map(|i| data.vertices[i as usize])))
            .collect();
        let mut rng = Lcg(3);
        let mut scratch = Vec::new();
        let mut hits = 0;
        for _ in 0..3000 {
            let o = rng.vec(6.0);
            let ray = Ray::new(o, rng.vec(2.5) - o);
            let brute = tris
                .iter()
                .enumerate()
                .filter_map(|(i, t)| {
                    t.intersect_first(&ray, f64::INFINITY, &mut scratch)
                        .map(|h| (i, h.t))
                })
                .min_by(|a, b| a.1.total_cmp(&b.1));
            let got = mesh.intersect_first(&ray, f64::INFINITY, &mut scratch);
            assert_eq!(brute.map(|b| b.0 as u32), got.map(|h| h.part));
            let mut all = Vec::new();
            mesh.intersect_all(&ray, &mut all);
            let count = tris
                .iter()
                .filter(|t| {
                    t.intersect_first(&ray, f64::INFINITY, &mut scratch)
                        .is_some()
                })
                .count();
            assert_eq!(all.len(), count);
            hits += count;
        }
        assert!(hits > 1000);
    }

    #[test]
    fn smooth_normals_and_textures() {
        let mesh = Mesh::new(Arc::new(icosphere(2, true)));
        let r = Ray::new(DVec3::new(0.3, 0.2, -5.0), DVec3::Z);
        let h = mesh
            .intersect_first(&r, f64::INFINITY, &mut Vec::new())
            .unwrap();
        let p = r.at(h.t);
        let n = mesh.normal(p, &h).normalize();
        // Interpolated normals of an icosphere approximate the sphere's normal at the point.
        assert!(
            (n - p.normalize()).length() < 0.02,
            "{n} vs {}",
            p.normalize()
        );
        assert_eq!(mesh.triangle_texture(h.part), Some(h.part % 3));
        assert_eq!(mesh.triangle_texture(1_000_000), None);
        let flat = Mesh::new(Arc::new(icosphere(2, false)));
        let h = flat
            .intersect_first(&r, f64::INFINITY, &mut Vec::new())
            .unwrap();
        let p = r.at(h.t);
        assert!(flat.normal(p, &h).normalize().dot(p.normalize()).abs() > 0.98);
        assert!(!flat.inside(DVec3::ZERO));
        let b = flat.bounds();
        assert!(
            (b.max - DVec3::ONE).abs().max_element() < 1e-12
                && (b.min + DVec3::ONE).abs().max_element() < 1e-12
        );
    }

    #[test]
    fn degenerate_meshes() {
        let r = Ray::new(DVec3::new(0.1, 0.1, -5.0), DVec3::Z);
        let empty = Mesh::new(Arc::new(MeshData::default()));
        assert!(empty
            .intersect_first(&r, f64::INFINITY, &mut Vec::new())
            .is_none());
        assert!(empty.bounds().is_empty());
        let bad = MeshData {
            vertices: vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::X * 2.0],
            normals: vec![DVec3::Z],
            triangles: vec![
                MeshTriangle {
                    v: [0, 1, 3],
                    n: None,
                    texture: None,
                    uv: None,
                },
                MeshTriangle {
                    v: [0, 1, 9],
                    n: None,
                    texture: None,
                    uv: None,
                },
                MeshTriangle {
                    v: [0, 1, 2],
                    n: Some([0, 0, 7]),
                    texture: None,
                    uv: None,
                },
            ]
            .into(),
            textures: vec![],
            uvs: vec![],
            inside_vector: None,
        };
        let mesh = Mesh::new(Arc::new(bad));
        let h = mesh
            .intersect_first(&r, f64::INFINITY, &mut Vec::new())
            .unwrap();
        assert_eq!(h.part, 2);
        // Out-of-range normal index: flat shading instead of a panic.
        assert_eq!(mesh.normal(r.at(h.t), &h).normalize(), DVec3::Z);
        assert_eq!(mesh.normal(DVec3::ZERO, &Hit::with_part(1.0, 99)), DVec3::Y);
    }

    /// A wavy 12 × 7 grid with a pole along its first row (degenerate triangles).
    fn wavy_grid(pole: bool) -> MeshData {
        grid_mesh(12, 7, |i, j| {
            let (x, y) = (i as f64 * 0.3, j as f64 * 0.4);
            let x = if pole && j == 0 { 1.8 } else { x };
            let p = DVec3::new(x, y, (3.0 * x).sin() * (2.0 * y).cos());
            (p, DVec3::Z, [x, y])
        })
    }

    /// The grid hierarchy finds the nearest crossing the whole triangle list gives: the same
    /// triangle at the same `t`, bit for bit, for rays from all sides (no two triangles of
    /// this surface meet a ray at one `t` except on shared edges, which the rays avoid by
    /// chance).
    #[test]
    fn grid_hierarchy_finds_the_nearest_triangle() {
        let mut rng = crate::geom::test_rng::Lcg(7);
        for pole in [false, true] {
            let data = Arc::new(wavy_grid(pole));
            assert_eq!(grid_cells(&data), Some((12, 7)));
            let mesh = Mesh::new(data.clone());
            let all: Vec<TriGeom> = (0..data.triangles.len())
                .filter_map(|i| mesh.tri(i))
                .collect();
            assert_eq!(all.len() < data.triangles.len(), pole);
            for _ in 0..2000 {
                let o = DVec3::new(1.8, 1.4, 0.0) + rng.vec(8.0);
                let target = DVec3::new(1.8, 1.4, 0.0) + rng.vec(3.0);
                let ray = Ray::new(o, target - o);
                let brute = (0..data.triangles.len())
                    .filter_map(|i| Some((mesh.tri(i)?.intersect(&ray, f64::INFINITY)?.0, i)))
                    .min_by(|a, b| a.0.total_cmp(&b.0));
                let got = mesh.intersect_first(&ray, f64::INFINITY, &mut Vec::new());
                assert_eq!(
                    got.map(|h| (h.t.to_bits(), h.part as usize)),
                    brute.map(|(t, i)| (t.to_bits(), i))
                );
            }
        }
    }

    /// `valid_bounds` is `TriGeom::bounds` to the bit on finite corners and edges, zeros of
    /// both signs, ties and overflow to infinity among them.
    #[test]
    fn valid_bounds_are_trigeoms() {
        let mut rng = Lcg(23);
        let pick = |rng: &mut Lcg| -> f64 {
            let r = rng.next();
            match (r * 10.0) as u32 {
                0 => 0.0,
                1 => -0.0,
                2 => 1.0,
                3 => -1.0,
                4 => 1e308 * (rng.next() - 0.5).signum(),
                _ => (rng.next() - 0.5) * 8.0,
            }
        };
        for _ in 0..200_000 {
            let v = |rng: &mut Lcg| DVec3::new(pick(rng), pick(rng), pick(rng));
            let (p0, e1, e2) = (v(&mut rng), v(&mut rng), v(&mut rng));
            let want = TriGeom { p0, e1, e2 }.bounds();
            let got = valid_bounds(p0, e1, e2);
            let bits = |b: Aabb| [b.min, b.max].map(|p| p.to_array().map(f64::to_bits));
            assert_eq!(bits(got), bits(want), "{p0} {e1} {e2}");
        }
    }

    #[test]
    fn only_grid_layouts_take_the_grid_hierarchy() {
        let mut data = wavy_grid(false);
        assert_eq!(grid_cells(&icosphere(1, true)), None);
        assert_eq!(grid_cells(&MeshData::default()), None);
        // One triangle's corners swapped: no longer the layout.
        let mut tris: Vec<MeshTriangle> = data.triangles.iter().collect();
        tris[5].v.swap(1, 2);
        data.triangles = tris.into();
        assert_eq!(grid_cells(&data), None);
    }

    /// Throughput on the 20480-triangle icosphere: `cargo test --release -- --ignored --nocapture mesh_speed`.
    #[test]
    #[ignore]
    fn mesh_speed() {
        let mesh = Mesh::new(Arc::new(icosphere(5, true)));
        assert_eq!(mesh.valid.len(), 20480);
        let n = 1000;
        let mut scratch = Vec::new();
        let start = std::time::Instant::now();
        let mut hits = 0;
        for j in 0..n {
            for i in 0..n {
                let target = DVec3::new(
                    i as f64 / n as f64 * 2.4 - 1.2,
                    j as f64 / n as f64 * 2.4 - 1.2,
                    0.0,
                );
                let o = DVec3::new(0.0, 0.0, -5.0);
                hits += mesh
                    .intersect_first(&Ray::new(o, target - o), f64::INFINITY, &mut scratch)
                    .is_some() as u32;
            }
        }
        let dt = start.elapsed().as_secs_f64();
        eprintln!(
            "{} rays, {hits} hits, {:.1} Mrays/s, depth {}",
            n * n,
            (n * n) as f64 / dt / 1e6,
            mesh.bvh.depth()
        );
    }
}
