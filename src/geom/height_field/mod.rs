//! POV-Ray `height_field`: a grid of heights over the unit square, x and z from 0 to 1, each
//! grid cell split into two triangles.
//!
//! Vertex (i, j) sits at x = i/(W−1), z = j/(H−1) (j counts from z = 0; image files have their
//! top row at z = 1). Heights are 16-bit values over 65536, as POV-Ray keeps them. A cell's
//! diagonal runs from (i, j+1) to (i+1, j) (measured with povray's `trace`). There are no side
//! walls; `water_level` removes the surface below that height. Points over the square and below
//! the surface, however far below, are inside.
//!
//! Rays are traced through a min/max pyramid over the cells (each level halves the grid), so a
//! ray skips every block whose height range it passes above or below and only tests the
//! triangles of the cells it actually reaches, nearest first. When only the first crossing is
//! wanted (camera and shadow rays), the same cells are found in the same order by stepping
//! along the ray through blocks of 8×8 cells and the cells of the blocks it reaches (`cells`).
//!
//! `smooth` mixes the four corner normals of the cell bilinearly; the corner normals are made
//! and kept the way POV-Ray keeps them, as 16-bit integers in grid units, whose rounding tilts
//! them visibly on steep slopes (see `vertex_normal`).

mod cells;
mod walk;
#[cfg(target_arch = "x86_64")]
mod walk_avx;

use crate::geom::{Hit, Shape};
use crate::math::{Aabb, DVec3, Ray, EPSILON};

/// Heights as POV-Ray stores them: the 16-bit value over 65536.
const SCALE: f64 = 1.0 / 65536.0;

/// How far below y = 0 the solid reaches. POV-Ray counts every point under the surface as
/// inside, however deep (measured with `inside()`: CSG keeps a sphere's part below the field);
/// the bounds, which decide inside tests first, must reach down that far too.
const SOLID_DEPTH: f64 = 1e4;

/// The grid as read from an image or a function.
#[derive(Clone, Debug)]
pub struct HeightData {
    /// Vertices along x (image columns) and along z (image rows); both at least 2.
    pub width: usize,
    pub depth: usize,
    /// `heights[j * width + i]`, j from z = 0.
    pub heights: Vec<u16>,
    pub smooth: bool,
    pub water_level: f64,
    /// The min/max pyramid over `heights`, made by the first `HeightField` built on this grid
    /// and shared by the others: `trace()` and `inside()` in a scene's loops build the object
    /// anew for every call (advanced/landscape places 256 trees on a 500×500 field). It
    /// depends only on the grid, which is not changed once a shape uses it.
    pyramid: std::sync::OnceLock<std::sync::Arc<[Level]>>,
    /// Every vertex's corner normal, made on the first smooth normal asked for: a hit mixes
    /// four of them (see `CornerNormals`).
    normals: std::sync::OnceLock<CornerNormals>,
}

/// The grids up to this many vertices keep their corner normals in object units (24 bytes a
/// vertex: 24 MB at most); larger ones keep `vertex_normal`'s 6 bytes and take each corner to
/// object units per hit.
const UNIT_NORMALS_MAX: usize = 1 << 20;

/// Every vertex's `vertex_normal`, each the sum of four normalised cross products.
#[derive(Clone, Debug)]
enum CornerNormals {
    /// Taken to object units and normalised as a hit would (`HeightField::corner_unit`), the
    /// same bits made once: a hit saves four square roots and divisions.
    Unit(Box<[DVec3]>),
    /// As made: whole numbers within ±32767, so kept exactly as 16-bit integers.
    Grid(Box<[[i16; 3]]>),
}

impl HeightData {
    pub fn new(width: usize, depth: usize, heights: Vec<u16>) -> HeightData {
        HeightData {
            width,
            depth,
            heights,
            smooth: false,
            water_level: 0.0,
            pyramid: Default::default(),
            normals: Default::default(),
        }
    }

    fn h(&self, i: usize, j: usize) -> f64 {
        self.heights[j * self.width + i] as f64 * SCALE
    }
}

/// One pyramid level: the smallest and largest height under each block of cells.
#[derive(Debug)]
struct Level {
    nx: usize,
    nz: usize,
    /// Blocks along x of the level above (`nx` halved, rounded up): the width of `quads`.
    px: usize,
    /// The blocks' ranges by fours: the children of block (pi, pj) of the level above, in the
    /// order (0, 0), (1, 0), (0, 1), (1, 1), at `quads[pj * px + pi]`, so the walk's visit
    /// finds all four in one aligned 32 bytes. Children beyond the grid's edge are padding,
    /// never read as blocks.
    quads: Vec<Quad>,
}

/// Four blocks' smallest and largest heights in object units: a 16-bit value over 65536 is
/// an f32 exactly, so these are the same f64 values as `value as f64 * SCALE`.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(32))]
struct Quad([[f32; 2]; 4]);

impl Level {
    fn new(nx: usize, nz: usize, min: &[u16], max: &[u16]) -> Level {
        let (px, pz) = (nx.div_ceil(2), nz.div_ceil(2));
        let mut quads = vec![Quad([[0.0; 2]; 4]); px * pz];
        for j in 0..nz {
            for i in 0..nx {
                let k = j * nx + i;
                let range = [min[k], max[k]].map(|v| (v as f64 * SCALE) as f32);
                quads[(j / 2) * px + i / 2].0[(j % 2) * 2 + i % 2] = range;
            }
        }
        Level { nx, nz, px, quads }
    }

    /// The range of block (i, j), which lies within the level.
    #[inline(always)]
    fn range(&self, i: usize, j: usize) -> [f32; 2] {
        self.quads[(j / 2) * self.px + i / 2].0[(j % 2) * 2 + i % 2]
    }
}

#[derive(Debug)]
pub struct HeightField {
    data: std::sync::Arc<HeightData>,
    /// Level 0 has one block per cell; the last level has a single block.
    levels: std::sync::Arc<[Level]>,
    bounds: Aabb,
}

/// A ray in grid space (x and z in cell units, y in object units) and what its walk found.
struct GridRay<'a> {
    o: DVec3,
    d: DVec3,
    inv: DVec3,
    /// Only crossings before this; shrinks as crossings are found when `first`.
    tmax: f64,
    /// Crossings before this may be left out (a window's start; -inf for none): the pyramid
    /// walk skips the children the ray leaves along x or z before it.
    tmin: f64,
    first: bool,
    /// The crossings found, from `out[from]` on (what was there before is not this shape's).
    out: &'a mut Vec<Hit>,
    from: usize,
}

/// How `trace_by` walks a ray: along its cells (`walk_cells`, first crossings of rays with
/// `walk::Signs`), through the pyramid by `visit_signed` (rays with `Signs`), or by `visit`;
/// a ray the walk asked for does not allow takes the next.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Walk {
    Cells,
    #[cfg(test)]
    Signed,
    Pyramid,
}

/// The min/max pyramid of a grid of at least 2×2 vertices.
fn pyramid(data: &HeightData) -> std::sync::Arc<[Level]> {
    let w = data.width;
    let (nx, nz) = (w - 1, data.depth - 1);
    let mut min = vec![0u16; nx * nz];
    let mut max = vec![0u16; nx * nz];
    for j in 0..nz {
        for i in 0..nx {
            let c = [
                data.heights[j * w + i],
                data.heights[j * w + i + 1],
                data.heights[(j + 1) * w + i],
                data.heights[(j + 1) * w + i + 1],
            ];
            min[j * nx + i] = *c.iter().min().unwrap();
            max[j * nx + i] = *c.iter().max().unwrap();
        }
    }
    let mut levels = vec![Level::new(nx, nz, &min, &max)];
    let (mut lmin, mut lmax, mut lnx, mut lnz) = (min, max, nx, nz);
    while lnx > 1 || lnz > 1 {
        let (px, pz) = (lnx.div_ceil(2), lnz.div_ceil(2));
        let mut min = vec![u16::MAX; px * pz];
        let mut max = vec![0u16; px * pz];
        for j in 0..lnz {
            for i in 0..lnx {
                let k = (j / 2) * px + i / 2;
                min[k] = min[k].min(lmin[j * lnx + i]);
                max[k] = max[k].max(lmax[j * lnx + i]);
            }
        }
        levels.push(Level::new(px, pz, &min, &max));
        (lmin, lmax, lnx, lnz) = (min, max, px, pz);
    }
    levels.into()
}

impl HeightField {
    pub fn new(data: std::sync::Arc<HeightData>) -> HeightField {
        let (w, h) = (data.width, data.depth);
        let ok = w >= 2 && h >= 2 && data.heights.len() == w * h;
        let levels = if ok {
            data.pyramid.get_or_init(|| pyramid(&data)).clone()
        } else {
            std::sync::Arc::from([])
        };
        let top = levels.last().map_or(0.0, |l| l.range(0, 0)[1] as f64);
        let bounds = if ok && top >= data.water_level {
            Aabb::new(
                DVec3::new(0.0, -SOLID_DEPTH, 0.0),
                DVec3::new(1.0, top, 1.0),
            )
        } else {
            Aabb::EMPTY
        };
        HeightField {
            data,
            levels,
            bounds,
        }
    }

    fn cells(&self) -> (f64, f64) {
        ((self.data.width - 1) as f64, (self.data.depth - 1) as f64)
    }

    /// The x and z part of the slab test of block (bi, bj) of a level whose blocks are
    /// `span` cells wide: the entry distance (from 0) and the exit one (without `tmax`), or
    /// None when the ray runs along x or z outside the block.
    fn slab_xz(&self, r: &GridRay, span: f64, bi: usize, bj: usize) -> Option<(f64, f64)> {
        let (cx, cz) = self.cells();
        let mut t0 = 0.0f64;
        let mut t1 = f64::INFINITY;
        for (lo, hi, o, d, inv) in [
            (
                bi as f64 * span,
                ((bi + 1) as f64 * span).min(cx),
                r.o.x,
                r.d.x,
                r.inv.x,
            ),
            (
                bj as f64 * span,
                ((bj + 1) as f64 * span).min(cz),
                r.o.z,
                r.d.z,
                r.inv.z,
            ),
        ] {
            if d == 0.0 {
                if o < lo || o > hi {
                    return None;
                }
                continue;
            }
            let (u, v) = ((lo - o) * inv, (hi - o) * inv);
            t0 = t0.max(u.min(v));
            t1 = t1.min(u.max(v));
        }
        Some((t0, t1))
    }

    /// Whether the ray meets block (bi, bj) of `level` within `r.tmax`, its heights included,
    /// given the block's `slab_xz`. As `r.tmax` only shrinks, a block that fails here fails
    /// for the rest of the walk.
    ///
    /// `PLAIN` (see `visit`) takes `min` and `max` as single comparisons.
    #[inline(always)]
    fn reaches<const PLAIN: bool>(
        &self,
        r: &GridRay,
        l: &Level,
        bi: usize,
        bj: usize,
        xz: (f64, f64),
    ) -> bool {
        let [ylo, yhi] = l.range(bi, bj).map(f64::from);
        if yhi < self.data.water_level {
            return false;
        }
        let (mut t0, mut t1) = (xz.0, fmin::<PLAIN>(r.tmax, xz.1));
        if r.d.y == 0.0 {
            if r.o.y < ylo || r.o.y > yhi {
                return false;
            }
        } else {
            let (u, v) = ((ylo - r.o.y) * r.inv.y, (yhi - r.o.y) * r.inv.y);
            t0 = fmax::<PLAIN>(t0, fmin::<PLAIN>(u, v));
            t1 = fmin::<PLAIN>(t1, fmax::<PLAIN>(u, v));
        }
        slack_ok::<PLAIN>(t0, t1)
    }

    /// Visits the blocks the ray crosses, nearest first; `tmax` shrinks as hits are found
    /// when only the first is wanted. The caller has found that the ray `reaches` the block
    /// with the current `tmax`.
    ///
    /// The slab test is split in its x-and-z part and its y part, which are combined with
    /// `min` and `max` (exact, in any order): the same answers as `slab` over the block's box.
    ///
    /// With `PLAIN`, `min` and `max` are single comparisons instead of `f64::min` and
    /// `f64::max`, whose NaN handling was a quarter of the walk. `trace` asks for it only
    /// when no NaN can arise: origin, direction and `tmax` are not NaN and every `1 / d` the
    /// walk multiplies by is finite, so each distance is a finite difference times a finite
    /// number (infinite at worst, never NaN). Without NaN the two agree except, perhaps, on
    /// the sign of a zero, which the walk only compares (`<`, `<=`, and `abs`), except in
    /// the sort key of the children (their entry along x and z, compared with `total_cmp`):
    /// that key keeps `f64::max` and `f64::min`.
    fn visit<const PLAIN: bool>(&self, r: &mut GridRay, level: usize, bi: usize, bj: usize) {
        if level == 0 {
            self.cell_hits(r, bi, bj);
            return;
        }
        let below = &self.levels[level - 1];
        let mut kids = [((0.0, 0.0), 0usize, 0usize); 4];
        let mut n = 0;
        let s = (1usize << (level - 1)) as f64;
        // The children's boxes without their heights (`slab_xz` of each): the children share
        // their faces, so each face's distance is found once. A child that exists lies below
        // `cx` and `cz`, so its unclamped near face equals the clamped far face of the one
        // before.
        let (cx, cz) = self.cells();
        let axis = |b: usize, o: f64, d: f64, inv: f64, c: f64| {
            let f = [
                (b * 2) as f64 * s,
                fmin::<PLAIN>((b * 2 + 1) as f64 * s, c),
                fmin::<PLAIN>((b * 2 + 2) as f64 * s, c),
            ];
            // Per child: entry and exit along the axis, or None when the ray runs along
            // the axis outside the child.
            let one = |k: usize| {
                if d == 0.0 {
                    (o >= f[k] && o <= f[k + 1]).then_some((f64::NEG_INFINITY, f64::INFINITY))
                } else {
                    let (u, v) = ((f[k] - o) * inv, (f[k + 1] - o) * inv);
                    // The entry feeds the sort key: `f64::min` (see above).
                    Some((u.min(v), fmax::<PLAIN>(u, v)))
                }
            };
            [one(0), one(1)]
        };
        let xs = axis(bi, r.o.x, r.d.x, r.inv.x, cx);
        let zs = axis(bj, r.o.z, r.d.z, r.inv.z, cz);
        for (di, dj) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
            let (ci, cj) = (bi * 2 + di, bj * 2 + dj);
            if ci < below.nx && cj < below.nz {
                if let (Some(x), Some(z)) = (xs[di], zs[dj]) {
                    // As `slab_xz`: an axis the ray runs along adds nothing (max with -inf
                    // and min with +inf change no value).
                    let xz = (
                        0.0f64.max(x.0).max(z.0),
                        fmin::<PLAIN>(fmin::<PLAIN>(f64::INFINITY, x.1), z.1),
                    );
                    // A child the ray does not reach now is left out of the sort, which
                    // changes nothing: it would not be reached with the same or a smaller
                    // `tmax` on its turn, the others keep their order, and the loop below
                    // stops at the first child starting beyond `tmax` no later. A child
                    // kept is asked again only if `tmax` shrank before its turn.
                    if self.reaches::<PLAIN>(r, below, ci, cj, xz) {
                        kids[n] = (xz, ci, cj);
                        n += 1;
                    }
                }
            }
        }
        let kids = &mut kids[..n];
        if r.first {
            // Insertion sort: stable, as `sort_by`, without its call for four elements.
            for i in 1..kids.len() {
                let mut j = i;
                while j > 0 && kids[j - 1].0 .0.total_cmp(&kids[j].0 .0).is_gt() {
                    kids.swap(j - 1, j);
                    j -= 1;
                }
            }
        }
        let tmax = r.tmax;
        for &(xz, ci, cj) in kids.iter() {
            if r.first && xz.0 > r.tmax {
                break;
            }
            if r.tmax == tmax || self.reaches::<PLAIN>(r, below, ci, cj, xz) {
                self.visit::<PLAIN>(r, level - 1, ci, cj);
            }
        }
    }

    /// The two triangles of cell (i, j).
    fn cell_hits(&self, r: &mut GridRay, i: usize, j: usize) {
        let d = &self.data;
        let (h00, h10, h01, h11) = (d.h(i, j), d.h(i + 1, j), d.h(i, j + 1), d.h(i + 1, j + 1));
        // Local cell coordinates u = x - i, v = z - j along the ray.
        // Through i64: one conversion instruction, the same value (see `cells::Axis::face`).
        let (ou, ov) = (r.o.x - i as i64 as f64, r.o.z - j as i64 as f64);
        const TOL: f64 = 1e-9;
        for tri in 0..2u32 {
            // Height as a + b u + c v over the triangle.
            let (a, b, c) = if tri == 0 {
                (h00, h10 - h00, h01 - h00)
            } else {
                // h11 + (h01 - h11)(1 - u) + (h10 - h11)(1 - v)
                (h01 + h10 - h11, h11 - h01, h11 - h10)
            };
            // r.o.y + t d.y = a + b (ou + t du) + c (ov + t dv)
            let den = r.d.y - b * r.d.x - c * r.d.z;
            if den == 0.0 {
                continue;
            }
            let t = (a + b * ou + c * ov - r.o.y) / den;
            // Not `t >= tmax`: the other triangle of an edge must get its say (see below).
            if t.is_nan() || t <= EPSILON || t > r.tmax + 1e-12 * t.max(1.0) {
                continue;
            }
            let (u, v) = (ou + t * r.d.x, ov + t * r.d.z);
            let inside = if tri == 0 {
                u >= -TOL && v >= -TOL && u + v <= 1.0 + TOL
            } else {
                u <= 1.0 + TOL && v <= 1.0 + TOL && u + v >= 1.0 - TOL
            };
            if !inside || r.o.y + t * r.d.y < d.water_level {
                continue;
            }
            let cell = (j * (d.width - 1) + i) as u32;
            let hit = Hit {
                t,
                part: cell * 2 + tri,
                uv: [u.clamp(0.0, 1.0), v.clamp(0.0, 1.0)],
            };
            // A crossing on a shared edge is found from both sides: keep one, the second
            // triangle or the cell further along x or z, as povray's trace answers there.
            if let Some(h) = r.out[r.from..]
                .iter_mut()
                .find(|h| (h.t - t).abs() <= 1e-12 * t.max(1.0))
            {
                if hit.part > h.part {
                    *h = hit;
                }
                continue;
            }
            r.out.push(hit);
            if r.first {
                r.tmax = r.tmax.min(t);
            }
        }
    }

    fn trace(&self, ray: &Ray, tmax: f64, first: bool, out: &mut Vec<Hit>) {
        self.trace_by(ray, (f64::NEG_INFINITY, tmax), first, out, Walk::Cells);
    }

    /// `trace` by the given walk where the ray allows it (for the tests that show the walks
    /// find the same crossings).
    fn trace_by(
        &self,
        ray: &Ray,
        (tmin, tmax): (f64, f64),
        first: bool,
        out: &mut Vec<Hit>,
        walk: Walk,
    ) {
        if self.bounds.is_empty() {
            return;
        }
        let (cx, cz) = self.cells();
        let o = DVec3::new(ray.origin.x * cx, ray.origin.y, ray.origin.z * cz);
        let d = DVec3::new(ray.dir.x * cx, ray.dir.y, ray.dir.z * cz);
        if !o.is_finite() || !d.is_finite() || d == DVec3::ZERO {
            return;
        }
        let mut r = GridRay {
            o,
            d,
            inv: d.recip(),
            tmax,
            tmin,
            first,
            from: out.len(),
            out,
        };
        let top = self.levels.len() - 1;
        // No NaN in the walk (see `visit`): an axis the ray runs along is not divided by.
        let finite = |d: f64, inv: f64| d == 0.0 || inv.is_finite();
        let plain = !tmax.is_nan()
            && finite(r.d.x, r.inv.x)
            && finite(r.d.y, r.inv.y)
            && finite(r.d.z, r.inv.z);
        if plain && top > 0 && walk != Walk::Pyramid {
            if let Some(s) = walk::Signs::new(&r) {
                // Both make the root's test themselves.
                if !(first && walk == Walk::Cells && self.walk_cells(&mut r, &s)) {
                    self.walk_signed(&mut r, &s);
                }
                return;
            }
        }
        let Some(xz) = self.slab_xz(&r, (1usize << top) as f64, 0, 0) else {
            return;
        };
        let l = &self.levels[top];
        if plain {
            if self.reaches::<true>(&r, l, 0, 0, xz) {
                self.visit::<true>(&mut r, top, 0, 0);
            }
        } else if self.reaches::<false>(&r, l, 0, 0, xz) {
            self.visit::<false>(&mut r, top, 0, 0);
        }
    }

    /// Every vertex's corner normal, made on the first call.
    fn corner_normals(&self) -> &CornerNormals {
        let d = &self.data;
        d.normals.get_or_init(|| {
            let grid = (0..d.depth)
                .flat_map(|j| (0..d.width).map(move |i| (i, j)))
                .map(|(i, j)| self.vertex_normal(i, j).to_array().map(|c| c as i16));
            if d.width * d.depth <= UNIT_NORMALS_MAX {
                CornerNormals::Unit(grid.map(|n| self.corner_unit(n)).collect())
            } else {
                CornerNormals::Grid(grid.collect())
            }
        })
    }

    /// A vertex's `vertex_normal` (as kept) in object units, normalised.
    #[inline(always)]
    fn corner_unit(&self, n: [i16; 3]) -> DVec3 {
        let (cx, cz) = self.cells();
        let n = n.map(f64::from);
        DVec3::new(n[0] * cx, n[1] * 65536.0, n[2] * cz).normalize_or_zero()
    }

    /// The normal at vertex (i, j) as povray keeps it: in grid units (one per grid step, heights
    /// in 16-bit steps), the sum of the unit normals of the four triangles the vertex makes
    /// with its neighbours along x and z, normalised and truncated to 16-bit integers. Both
    /// details show: in those units slopes are large, so the sum weighs gentle sides more (a
    /// harmonic mean of the slopes), and the y component is a small integer whose truncation
    /// tilts the normal (measured with `trace`: a ramp rising d per vertex shows the slope
    /// (W-1) / (2 floor(32767 / d)), a parabola the harmonic mean of the slopes on either side,
    /// and random grids match to six digits).
    fn vertex_normal(&self, i: usize, j: usize) -> DVec3 {
        let d = &self.data;
        let raw = |i: usize, j: usize| d.heights[j * d.width + i] as f64;
        // The four triangles the vertex makes with its neighbours along x and z, taken in
        // turn (+x, +z), (+z, -x), (-x, -z), (-z, +x); at the edges the missing ones drop out.
        let p = |di: isize, dj: isize| -> Option<DVec3> {
            let (a, b) = (i as isize + di, j as isize + dj);
            (a >= 0 && b >= 0 && (a as usize) < d.width && (b as usize) < d.depth).then(|| {
                DVec3::new(
                    di as f64,
                    raw(a as usize, b as usize) - raw(i, j),
                    dj as f64,
                )
            })
        };
        let around = [p(1, 0), p(0, 1), p(-1, 0), p(0, -1)];
        let mut n = DVec3::ZERO;
        for k in 0..4 {
            if let (Some(a), Some(b)) = (around[k], around[(k + 1) % 4]) {
                let c = b.cross(a);
                n += if c.y < 0.0 { -c } else { c }.normalize();
            }
        }
        (n.normalize_or_zero() * 32767.0).trunc()
    }
}

/// Whether a slab test's entry `t0` and exit `t1` overlap, with a little slack so crossings
/// on block faces are not lost to rounding.
#[inline(always)]
fn slack_ok<const PLAIN: bool>(t0: f64, t1: f64) -> bool {
    t0 <= t1 + 1e-9 * fmax::<PLAIN>(t1.abs(), 1.0)
}

/// The corner normals of cell (i, j) mixed bilinearly at (u, v) within it.
#[inline(always)]
fn mix(
    (i, j): (usize, usize),
    (u, v): (f64, f64),
    corner: impl Fn(usize, usize) -> DVec3,
) -> DVec3 {
    corner(i, j) * ((1.0 - u) * (1.0 - v))
        + corner(i + 1, j) * (u * (1.0 - v))
        + corner(i, j + 1) * ((1.0 - u) * v)
        + corner(i + 1, j + 1) * (u * v)
}

/// `f64::min`, or with `PLAIN` one comparison: the same for numbers that are not NaN, but
/// for the sign of a zero (see `HeightField::visit`).
#[inline(always)]
fn fmin<const PLAIN: bool>(a: f64, b: f64) -> f64 {
    if !PLAIN {
        a.min(b)
    } else if b < a {
        b
    } else {
        a
    }
}

/// `f64::max`, or with `PLAIN` one comparison (as `fmin`).
#[inline(always)]
fn fmax<const PLAIN: bool>(a: f64, b: f64) -> f64 {
    if !PLAIN {
        a.max(b)
    } else if b > a {
        b
    } else {
        a
    }
}

impl Shape for HeightField {
    fn bounds(&self) -> Aabb {
        self.bounds
    }

    fn intersect_all(&self, ray: &Ray, out: &mut Vec<Hit>) {
        self.trace(ray, f64::INFINITY, false, out);
    }

    /// The all-crossings walk bounded by a `tmax` a little past `hi` and a `tmin` a little
    /// before `lo` (a clipped field's crossings outside its clipping box): it visits the
    /// blocks `intersect_all` visits, in the same order, less those the ray reaches only past
    /// that `tmax` or leaves along x or z before that `tmin`, so the crossings within the
    /// window come out the same and in the same order. The margins: 1e-6 of the reach, far
    /// above the slab tests' rounding and the edge merging's 1e-12 (no crossing in the window
    /// is merged with one left out), plus how far along the ray a cell's reported crossing
    /// may lie outside its cell (`cell_hits`' 1e-9 of a cell on each axis; the heights
    /// extrapolated that far change by as little): 1e-8 of the largest `1 / d` in grid units.
    /// A ray along an axis (an infinite `1 / d`) is not bounded.
    fn intersect_all_within(&self, ray: &Ray, lo: f64, hi: f64, out: &mut Vec<Hit>) {
        let (cx, cz) = self.cells();
        let grid = DVec3::new(ray.dir.x * cx, ray.dir.y, ray.dir.z * cz);
        let outside = 1e-8 * grid.recip().abs().max_element();
        let limit = hi + (1e-6 * (hi.abs() + 1.0) + outside);
        // A NaN end bounds nothing (NaN fails every comparison below).
        let start = lo - (1e-6 * (lo.abs() + 1.0) + outside);
        let start = if start > f64::NEG_INFINITY {
            start
        } else {
            f64::NEG_INFINITY
        };
        let limit = if limit < f64::INFINITY {
            limit
        } else {
            f64::INFINITY
        };
        self.trace_by(ray, (start, limit), false, out, Walk::Cells);
    }

    /// A clipped field's rays that miss its clipping box skip the walk, and those that
    /// cross it stop at its far side (`intersect_all_within`).
    fn windowed(&self) -> bool {
        true
    }

    fn intersect_first(&self, ray: &Ray, tmax: f64, scratch: &mut Vec<Hit>) -> Option<Hit> {
        scratch.clear();
        self.trace(ray, tmax, true, scratch);
        scratch
            .iter()
            .filter(|h| h.t < tmax)
            .min_by(|a, b| a.t.total_cmp(&b.t))
            .copied()
    }

    fn inside(&self, p: DVec3) -> bool {
        if self.bounds.is_empty() || !(0.0..=1.0).contains(&p.x) || !(0.0..=1.0).contains(&p.z) {
            return false;
        }
        let (cx, cz) = self.cells();
        let (gx, gz) = (p.x * cx, p.z * cz);
        let i = (gx.floor() as usize).min(self.data.width - 2);
        let j = (gz.floor() as usize).min(self.data.depth - 2);
        let (u, v) = (gx - i as f64, gz - j as f64);
        let d = &self.data;
        let h = if u + v <= 1.0 {
            d.h(i, j) + (d.h(i + 1, j) - d.h(i, j)) * u + (d.h(i, j + 1) - d.h(i, j)) * v
        } else {
            d.h(i + 1, j + 1)
                + (d.h(i, j + 1) - d.h(i + 1, j + 1)) * (1.0 - u)
                + (d.h(i + 1, j) - d.h(i + 1, j + 1)) * (1.0 - v)
        };
        p.y < h
    }

    fn normal(&self, _p: DVec3, hit: &Hit) -> DVec3 {
        let d = &self.data;
        let cell = (hit.part / 2) as usize;
        let tri = hit.part % 2;
        let (i, j) = (cell % (d.width - 1), cell / (d.width - 1));
        let (cx, cz) = self.cells();
        if d.smooth {
            // Each corner's normal taken to object units, then mixed bilinearly over the cell
            // (not by the triangle's barycentric weights): povray's trace() answers match this
            // exactly inside cells of a random grid.
            let [u, v] = hit.uv;
            let n = match self.corner_normals() {
                CornerNormals::Unit(n) => mix((i, j), (u, v), |a, b| n[b * d.width + a]),
                CornerNormals::Grid(n) => {
                    mix((i, j), (u, v), |a, b| self.corner_unit(n[b * d.width + a]))
                }
            };
            if n != DVec3::ZERO {
                return n;
            }
        }
        let (h00, h10, h01, h11) = (d.h(i, j), d.h(i + 1, j), d.h(i, j + 1), d.h(i + 1, j + 1));
        // Slopes per grid step, then per object unit.
        let (du, dv) = if tri == 0 {
            (h10 - h00, h01 - h00)
        } else {
            (h11 - h01, h11 - h10)
        };
        DVec3::new(-du * cx, 1.0, -dv * cz)
    }
}

#[cfg(test)]
mod tests;
