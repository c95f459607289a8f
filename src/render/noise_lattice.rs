//! The lattice noise of generators 1 and 2 and of POV-Ray's vector noise, the hot loop of
//! every noise-textured scene (skies, woods, granite: 20-70% of their time).
//!
//! One corner's contribution to one component is `w·(½e0 + e1·dx + e2·dy + e3·dz)`, e the four
//! ENTRY values at the corner's hashed position moved 0, 4 or 8 places on for the x, y and z
//! components. `PACKED` lays those twelve numbers out per position as four rows of (x, y, z,
//! unused) lanes, with ½e0 already halved (exact: a power of two), so the three components are
//! one 4-lane multiply-add chain per corner. Every lane does the scalar code's operations in
//! the scalar code's order, and nothing here is contracted to FMA, so the results are the
//! scalar code's bits (unit test `packed_lattice_is_the_scalar_lattice`, tests/noise_probes.rs).
//! With AVX (detected at run time; the build targets x86-64-v2) the lanes are one 256-bit
//! register; without it the same lanes are plain arrays. The scalar noise (bozo, granite,
//! wrinkles) puts four corners in the lanes instead and sums their terms in corner order.

use crate::math::{has_avx, DVec3};

use super::cell_list::CellList;
use super::noise_data::{ENTRY, HASH_OFFSET, HASH_X, HASH_Y, HASH_Z};

#[inline(always)]
fn s_curve(t: f64) -> f64 {
    t * t * (3.0 - 2.0 * t)
}

/// Twelve ENTRY values of one hashed position as four 32-byte rows: row j holds entry j of
/// the x, y and z components (positions i+j, i+j+4, i+j+8), row 0 halved.
#[repr(C, align(32))]
#[derive(Clone, Copy)]
struct Packed([[f64; 4]; 4]);

const fn pack() -> [Packed; 256] {
    let mut t = [Packed([[0.0; 4]; 4]); 256];
    let mut i = 0;
    while i < 256 {
        let mut j = 0;
        while j < 4 {
            let mut c = 0;
            while c < 3 {
                let v = ENTRY[i + j + 4 * c];
                t[i].0[j][c] = if j == 0 { 0.5 * v } else { v };
                c += 1;
            }
            j += 1;
        }
        i += 1;
    }
    t
}

/// HASH_Z's values are below 256, so 256 positions cover every corner.
static PACKED: [Packed; 256] = pack();

/// Component 0's four numbers per position (½e0, e1, e2, e3) as one 32-byte row, for the
/// scalar noise, which takes four corners' rows at once and transposes them into lanes.
#[repr(C, align(32))]
#[derive(Clone, Copy)]
struct Row([f64; 4]);

const fn rows() -> [Row; 256] {
    let mut t = [Row([0.0; 4]); 256];
    let mut i = 0;
    while i < 256 {
        t[i] = Row([0.5 * ENTRY[i], ENTRY[i + 1], ENTRY[i + 2], ENTRY[i + 3]]);
        i += 1;
    }
    t
}

static ROWS: [Row; 256] = rows();

/// HASH_Z's values times 32: the byte offset of each corner's row in `ROWS` (and a quarter
/// of it in `PACKED`, whose rows are 128 bytes: an address's scale of 4). The lanes' cells
/// keep these, so reading a row adds the offset to the table's address, where an index
/// took a shift first (one instruction per corner and point).
static HASH_Z32: [u16; 4096] = hash_z32();

const fn hash_z32() -> [u16; 4096] {
    let mut t = [0u16; 4096];
    let mut i = 0;
    while i < 4096 {
        t[i] = HASH_Z[i] as u16 * 32;
        i += 1;
    }
    t
}

/// What the eight corners share: the fractional position, the x·y weights of the four
/// (dx, dy) columns, the z weights, and each corner's ENTRY position (corner = dx + 2dy + 4dz;
/// below 256, as HASH_Z's values are: the readers mask it with 255, which spares the bounds
/// checks; 32 bits measured faster than bytes or 64 bits in a standalone loop).
#[derive(Clone, Copy)]
struct Cell {
    t: [f64; 3],
    wxy: [f64; 4],
    wz: [f64; 2],
    entry: [u32; 8],
}

#[inline(always)]
fn cell(p: DVec3) -> Cell {
    let (fx, fy, fz) = (p.x.floor(), p.y.floor(), p.z.floor());
    let (ix, iy, iz) = (fx as i64, fy as i64, fz as i64);
    let (tx, ty, tz) = (p.x - fx, p.y - fy, p.z - fz);
    let (sx, sy, sz) = (s_curve(tx), s_curve(ty), s_curve(tz));
    let (wx, wy) = ([1.0 - sx, sx], [1.0 - sy, sy]);
    // The scalar weight is (wx·wy)·wz: the first product is shared by the two z layers.
    let wxy = [wx[0] * wy[0], wx[1] * wy[0], wx[0] * wy[1], wx[1] * wy[1]];
    // Each corner's position in ENTRY: a three-stage hash of its coordinates, the first
    // stages shared between corners (14 table reads instead of 24).
    let m = |c: i64| (c.wrapping_add(HASH_OFFSET) & 4095) as usize;
    // Wrapping: a coordinate beyond i64 saturates to i64::MAX, whose neighbour wraps (as a
    // release build always did; a debug build stopped on the overflow).
    let next = |c: i64| m(c.wrapping_add(1));
    let hx = [HASH_X[m(ix)] as usize, HASH_X[next(ix)] as usize];
    let (my, mz) = ([m(iy), next(iy)], [m(iz), next(iz)]);
    let mut hxy = [0usize; 4];
    for (k, h) in hxy.iter_mut().enumerate() {
        // The mask changes nothing (both sides are below 4096) but spares a bounds check.
        *h = HASH_Y[(hx[k & 1] ^ my[k >> 1]) & 4095] as usize;
    }
    let mut entry = [0u32; 8];
    for (c, e) in entry.iter_mut().enumerate() {
        *e = u32::from(HASH_Z[(hxy[c & 3] ^ mz[c >> 2]) & 4095]);
    }
    Cell {
        t: [tx, ty, tz],
        wxy,
        wz: [1.0 - sz, sz],
        entry,
    }
}

/// Whether every lane of the comparison mask `m` is set: one `vtestpd` of its sign bits
/// against all ones (`_mm256_movemask_pd(m) == 0b1111` compiled to seven instructions, an
/// extract, two 64-bit compares, an or and a test, on every point of every noise).
///
/// # Safety
/// The CPU must have AVX.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn all_lanes(m: std::arch::x86_64::__m256d) -> bool {
    use std::arch::x86_64::*;
    // SAFETY: the caller guarantees AVX.
    unsafe { _mm256_testc_pd(m, _mm256_castsi256_pd(_mm256_set1_epi64x(-1))) != 0 }
}

/// A cell's set-up in AVX lanes (x, y, z, unused), shared by `cell_avx` and the octaves'
/// `lane_cell`: the floors `f`, the offsets `t = p − f`, the s-curves `s` and `o = 1 − s`,
/// and the four wx·wy of `cell` in its order (wx in lanes (1 − sx, sx, 1 − sx, sx), wy in
/// (1 − sy, 1 − sy, sy, sy), multiplied lane-wise). `None` where a floor is outside the i32
/// range (or NaN): those points take `cell`, whose saturating conversion they need.
#[cfg(target_arch = "x86_64")]
pub(super) struct CellLanes {
    pub f: std::arch::x86_64::__m256d,
    pub t: std::arch::x86_64::__m256d,
    pub s: std::arch::x86_64::__m256d,
    pub o: std::arch::x86_64::__m256d,
    pub wxy: std::arch::x86_64::__m256d,
}

/// The point `p` in lanes (x, y, z, 0) and its floors; `None` where a floor is outside the
/// i32 range (or NaN): those points take `cell`, whose saturating conversion they need.
///
/// # Safety
/// The CPU must have AVX.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(super) unsafe fn floor_lanes(
    p: DVec3,
) -> Option<(std::arch::x86_64::__m256d, std::arch::x86_64::__m256d)> {
    use std::arch::x86_64::*;
    // SAFETY: the caller guarantees AVX.
    unsafe {
        let v = _mm256_setr_pd(p.x, p.y, p.z, 0.0);
        let f = _mm256_round_pd::<{ _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC }>(v);
        let abs = _mm256_andnot_pd(_mm256_set1_pd(-0.0), f);
        let inside = _mm256_cmp_pd::<_CMP_LT_OQ>(abs, _mm256_set1_pd(2147483648.0));
        all_lanes(inside).then_some((v, f))
    }
}

/// `CellLanes` of the point `p`.
///
/// # Safety
/// The CPU must have AVX.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(super) unsafe fn cell_lanes(p: DVec3) -> Option<CellLanes> {
    use std::arch::x86_64::*;
    // SAFETY: the caller guarantees AVX.
    unsafe {
        let (v, f) = floor_lanes(p)?;
        let t = _mm256_sub_pd(v, f);
        let s = _mm256_mul_pd(
            _mm256_mul_pd(t, t),
            _mm256_sub_pd(_mm256_set1_pd(3.0), _mm256_mul_pd(_mm256_set1_pd(2.0), t)),
        );
        let o = _mm256_sub_pd(_mm256_set1_pd(1.0), s);
        let xo = _mm256_unpacklo_pd(o, s);
        let wx = _mm256_permute2f128_pd::<0x00>(xo, xo);
        let wy = _mm256_permute2f128_pd::<0x20>(_mm256_unpackhi_pd(o, o), _mm256_unpackhi_pd(s, s));
        let wxy = _mm256_mul_pd(wx, wy);
        Some(CellLanes { f, t, s, o, wxy })
    }
}

/// `cell` with the three coordinates in the lanes of one AVX register: one rounding, one
/// conversion and one s-curve for the three axes instead of three scalar ones (each scalar
/// `as i64` is a conversion plus its saturation and NaN checks). The same operations per
/// lane, so the same bits; coordinates whose floor is outside the i32 range (and NaN) take
/// `cell`, whose saturating conversion they need.
///
/// # Safety
/// The CPU must have AVX.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn cell_avx(p: DVec3) -> Cell {
    use std::arch::x86_64::*;
    // SAFETY: the caller guarantees AVX.
    unsafe {
        let Some(CellLanes {
            f,
            t,
            s,
            o,
            wxy: wxy_lanes,
        }) = cell_lanes(p)
        else {
            return cell(p);
        };
        let mut wxy = [0.0; 4];
        _mm256_storeu_pd(wxy.as_mut_ptr(), wxy_lanes);
        let (mut ta, mut sa, mut oa) = ([0.0; 4], [0.0; 4], [0.0; 4]);
        _mm256_storeu_pd(ta.as_mut_ptr(), t);
        _mm256_storeu_pd(sa.as_mut_ptr(), s);
        _mm256_storeu_pd(oa.as_mut_ptr(), o);
        let entry = entries_avx(f, &HASH_Z);
        Cell {
            t: [ta[0], ta[1], ta[2]],
            wxy,
            wz: [oa[2], sa[2]],
            entry,
        }
    }
}

/// The eight corners' ENTRY positions of the cell whose floors are `f`'s lanes (x, y, z,
/// unused): `cell`'s hash walk, its last stage read from `last` (HASH_Z, or `HASH_Z32` for
/// the rows' byte offsets). The floors must be integers inside the i32 range (the
/// callers check): converted exactly, and the hash's wrapping add and 12-bit mask see the
/// same low bits as in i64.
///
/// # Safety
/// The CPU must have AVX.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn entries_avx<T: Copy + Into<u32>>(
    f: std::arch::x86_64::__m256d,
    last: &[T; 4096],
) -> [u32; 8] {
    use std::arch::x86_64::*;
    // SAFETY: the caller guarantees AVX.
    unsafe {
        let m0 = _mm_add_epi32(_mm256_cvttpd_epi32(f), _mm_set1_epi32(HASH_OFFSET as i32));
        let m1 = _mm_add_epi32(m0, _mm_set1_epi32(1));
        let mask = _mm_set1_epi32(4095);
        let (mut a0, mut a1) = ([0u32; 4], [0u32; 4]);
        _mm_storeu_si128(a0.as_mut_ptr() as *mut __m128i, _mm_and_si128(m0, mask));
        _mm_storeu_si128(a1.as_mut_ptr() as *mut __m128i, _mm_and_si128(m1, mask));
        let hx = [
            HASH_X[a0[0] as usize & 4095] as usize,
            HASH_X[a1[0] as usize & 4095] as usize,
        ];
        let (my, mz) = (
            [a0[1] as usize, a1[1] as usize],
            [a0[2] as usize, a1[2] as usize],
        );
        // Unchecked reads: `cell`'s `& 4095` on each index changes nothing (both sides of
        // every xor are below 4096) but was an instruction on six of the walk's reads.
        let mut hxy = [0usize; 4];
        for (k, h) in hxy.iter_mut().enumerate() {
            // SAFETY: HASH_X's values are below 4096 (asserted at compile time below)
            // and `my` is masked to 12 bits, so the xor is below 4096, HASH_Y's length.
            *h = *HASH_Y.get_unchecked(hx[k & 1] ^ my[k >> 1]) as usize;
        }
        let mut entry = [0u32; 8];
        for (c, e) in entry.iter_mut().enumerate() {
            // SAFETY: as above, with HASH_Y's values (asserted) and `mz`: below `last`'s 4096.
            *e = (*last.get_unchecked(hxy[c & 3] ^ mz[c >> 2])).into();
        }
        entry
    }
}

/// Whether every value of a hash stage indexes the next stage's 4096 entries (noise's
/// stages here, and crackle's cells stages, whose unchecked reads rely on it too).
pub(super) const fn all_below_4096(t: &[u16; 4096]) -> bool {
    let mut i = 0;
    while i < 4096 {
        if t[i] >= 4096 {
            return false;
        }
        i += 1;
    }
    true
}

// `entries_avx`'s unchecked reads rely on this (an unnamed constant is always evaluated).
const _: () = assert!(all_below_4096(&HASH_X) && all_below_4096(&HASH_Y));

/// A bound on |`scalar(p)`| for every point (a NaN or infinite point gives NaN): each of the
/// eight corner terms is a weight in [0, 1] times ½e0 + e1·dx + e2·dy + e3·dz with every
/// |d| ≤ 1, so the sum is at most 8 times the largest row's Σ|e|; doubled for rounding.
/// Callers use it to prove that a noise cannot change a result (`fog::stirred`).
pub const SCALAR_BOUND: f64 = scalar_bound();

const fn scalar_bound() -> f64 {
    let rows = rows();
    let mut most = 0.0;
    let mut i = 0;
    while i < 256 {
        let r = &rows[i].0;
        let s = r[0].abs() + r[1].abs() + r[2].abs() + r[3].abs();
        if s > most {
            most = s;
        }
        i += 1;
    }
    16.0 * most
}

/// The lattice noise of component 0 (the scalar noise), in about [-0.5, 0.5]; 0.5 plus it
/// is generator 1's unclipped value.
#[inline]
pub fn scalar(p: DVec3) -> f64 {
    scalar_many([p])[0]
}

/// The most points `scalar_into` takes: ten octaves at each of a normal's four samples.
pub const MAX_POINTS: usize = 40;

/// `scalar` at up to `MAX_POINTS` points (the octaves of granite, wrinkles and scalar
/// turbulence, at one point or a normal's four) into `out`: every point's hash walk first,
/// then the arithmetic, so that the walks' dependent table reads overlap instead of each
/// waiting for the one before.
#[inline]
pub fn scalar_into(ps: &[DVec3], out: &mut [f64]) {
    #[cfg(target_arch = "x86_64")]
    if has_avx() {
        // SAFETY: AVX was detected.
        return unsafe { scalar_into_avx(ps, out) };
    }
    scalar_into_with(ps, out, scalar_lanes)
}

#[inline(always)]
fn scalar_into_with(ps: &[DVec3], out: &mut [f64], terms: impl Fn(&Cell) -> f64) {
    let mut cells = CellList::<Cell, MAX_POINTS>::new();
    for &p in ps.iter().take(MAX_POINTS) {
        cells.push(cell(p));
    }
    for (o, c) in out.iter_mut().zip(cells.as_slice()) {
        *o = terms(c);
    }
}

/// Four rows of `ROWS` (four corners' or four points' (value, x, y, z) entries, each an AVX
/// register) transposed, so that each of the four results holds one field of all four: a
/// macro, not a function, so the shuffles stay in the AVX callers' registers.
#[cfg(target_arch = "x86_64")]
macro_rules! transposed {
    ($r0:expr, $r1:expr, $r2:expr, $r3:expr) => {{
        let (r0, r1, r2, r3) = ($r0, $r1, $r2, $r3);
        let (t0, t1) = (_mm256_unpacklo_pd(r0, r1), _mm256_unpackhi_pd(r0, r1));
        let (t2, t3) = (_mm256_unpacklo_pd(r2, r3), _mm256_unpackhi_pd(r2, r3));
        [
            _mm256_permute2f128_pd(t0, t2, 0x20),
            _mm256_permute2f128_pd(t1, t3, 0x20),
            _mm256_permute2f128_pd(t0, t2, 0x31),
            _mm256_permute2f128_pd(t1, t3, 0x31),
        ]
    }};
}

/// `scalar_into` for a fixed number of points.
#[inline]
pub fn scalar_many<const N: usize>(ps: [DVec3; N]) -> [f64; N] {
    let mut out = [0.0; N];
    scalar_into(&ps, &mut out);
    out
}

/// `scalar`'s arithmetic one corner at a time.
#[inline(always)]
fn scalar_lanes(c: &Cell) -> f64 {
    let mut out = 0.0;
    for (k, &i) in c.entry.iter().enumerate() {
        let e = &PACKED[i as usize & 255].0;
        let (dx, dy, dz) = (k & 1, (k >> 1) & 1, k >> 2);
        let (ddx, ddy, ddz) = (c.t[0] - dx as f64, c.t[1] - dy as f64, c.t[2] - dz as f64);
        let w = c.wxy[k & 3] * c.wz[dz];
        out += w * (e[0][0] + e[1][0] * ddx + e[2][0] * ddy + e[3][0] * ddz);
    }
    out
}

// The batched scalar noise's walk and lanes (`scalar_into_avx`), after `transposed!`.
#[cfg(target_arch = "x86_64")]
#[path = "noise_scalar.rs"]
mod scalar_lanes;
#[cfg(target_arch = "x86_64")]
use scalar_lanes::{granite_avx, scalar_into_avx, turbulence_avx, wrinkles_avx};

/// Granite's sum for generators 1 and 2 (`gen1`: the first) mapped in the lanes, or None
/// without AVX (the caller then takes `scalar_into`'s values through memory).
#[inline]
pub fn granite(p: DVec3, gen1: bool) -> Option<f64> {
    #[cfg(target_arch = "x86_64")]
    if has_avx() {
        // SAFETY: AVX was detected.
        return Some(unsafe { granite_avx(p, gen1) });
    }
    None
}

/// Wrinkles' sum for generators 1 and 2 (`gen1`: the first) mapped in the lanes, or None
/// without AVX (the caller then takes `scalar_into`'s values through memory).
#[inline]
pub fn wrinkles(p: DVec3, gen1: bool) -> Option<f64> {
    #[cfg(target_arch = "x86_64")]
    if has_avx() {
        // SAFETY: AVX was detected.
        return Some(unsafe { wrinkles_avx(p, gen1) });
    }
    None
}

/// Scalar turbulence's sum of `n` octaves (1 to 10; lambda and omega already rounded) for
/// generators 1 and 2 (`gen1`: the first) mapped in the lanes, or None without AVX.
#[inline]
pub fn turbulence(p: DVec3, n: usize, omega: f64, lambda: f64, gen1: bool) -> Option<f64> {
    #[cfg(target_arch = "x86_64")]
    if has_avx() {
        // SAFETY: AVX was detected.
        return Some(unsafe { turbulence_avx(p, n, omega, lambda, gen1) });
    }
    None
}

/// `scalar`'s arithmetic with the four corners of each z layer as the lanes of one AVX
/// register: their rows are transposed so that lane k holds corner k's numbers, each lane
/// computes its corner's term as the scalar code does, and the eight terms are summed in
/// corner order.
///
/// # Safety
/// The CPU must have AVX.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn scalar_avx(c: &Cell) -> f64 {
    use std::arch::x86_64::*;
    let [tx, ty, tz] = c.t;
    // SAFETY: the caller guarantees AVX; ROWS' rows are 32-byte aligned.
    unsafe {
        let dx = _mm256_setr_pd(tx, tx - 1.0, tx, tx - 1.0);
        let dy = _mm256_setr_pd(ty, ty, ty - 1.0, ty - 1.0);
        let wxy = _mm256_loadu_pd(c.wxy.as_ptr());
        let mut out = 0.0;
        for (z, entry) in c.entry.chunks_exact(4).enumerate() {
            let row = |k: usize| _mm256_load_pd(ROWS[entry[k] as usize & 255].0.as_ptr());
            let [e0, e1, e2, e3] = transposed!(row(0), row(1), row(2), row(3));
            let dz = _mm256_set1_pd(tz - z as f64);
            let mut t = _mm256_add_pd(e0, _mm256_mul_pd(e1, dx));
            t = _mm256_add_pd(t, _mm256_mul_pd(e2, dy));
            t = _mm256_add_pd(t, _mm256_mul_pd(e3, dz));
            let w = _mm256_mul_pd(wxy, _mm256_set1_pd(c.wz[z]));
            let mut terms = [0.0; 4];
            _mm256_storeu_pd(terms.as_mut_ptr(), _mm256_mul_pd(w, t));
            for v in terms {
                out += v;
            }
        }
        out
    }
}

/// The three components of the vector noise with plain arrays as lanes.
#[inline(always)]
fn vector_lanes(c: &Cell) -> [f64; 3] {
    let mut out = [0.0; 4];
    for (k, &i) in c.entry.iter().enumerate() {
        let e = &PACKED[i as usize & 255].0;
        let (dx, dy, dz) = (k & 1, (k >> 1) & 1, k >> 2);
        let (ddx, ddy, ddz) = (c.t[0] - dx as f64, c.t[1] - dy as f64, c.t[2] - dz as f64);
        let w = c.wxy[k & 3] * c.wz[dz];
        for (l, o) in out.iter_mut().enumerate() {
            *o += w * (e[0][l] + e[1][l] * ddx + e[2][l] * ddy + e[3][l] * ddz);
        }
    }
    [out[0], out[1], out[2]]
}

/// POV-Ray's vector noise: the lattice noise of components 0, 4 and 8 places on.
#[inline]
pub fn vector(p: DVec3) -> DVec3 {
    #[cfg(target_arch = "x86_64")]
    if has_avx() {
        // SAFETY: AVX was detected.
        return unsafe { octaves_lanes::vector(p) };
    }
    DVec3::from_array(vector_lanes(&cell(p)))
}

/// `vector` at up to ten points (the wrinkles normal's octaves): every hash walk first, as in
/// `scalar_into`, then each point's arithmetic as `vector` does it. (Plain loops: the
/// arrays' `map` was left as calls that copied the cells, slower than the walks it saved.)
#[inline]
pub fn vector_many<const N: usize>(ps: &[DVec3; N], out: &mut [DVec3; N]) {
    #[cfg(target_arch = "x86_64")]
    if has_avx() {
        // SAFETY: AVX was detected.
        return unsafe { octaves_lanes::vector_many(ps, out) };
    }
    vector_many_with(ps, out, cell, vector_lanes)
}

#[inline(always)]
fn vector_many_with<const N: usize>(
    ps: &[DVec3; N],
    out: &mut [DVec3; N],
    cell: impl Fn(DVec3) -> Cell,
    terms: impl Fn(&Cell) -> [f64; 3],
) {
    let mut cells = CellList::<Cell, N>::new();
    for &p in ps {
        cells.push(cell(p));
    }
    for (o, c) in out.iter_mut().zip(cells.as_slice()) {
        *o = DVec3::from_array(terms(c));
    }
}

/// The wrinkles normal's tilt: Σ |`vector`(p·2ᵏ)| / 2ᵏ for k = 0..10, summed in that order,
/// the ten lattice walks first.
#[inline]
pub fn abs_octaves(p: DVec3) -> DVec3 {
    #[cfg(target_arch = "x86_64")]
    if has_avx() {
        // SAFETY: AVX was detected.
        return unsafe { octaves_lanes::abs_octaves(p) };
    }
    abs_octaves_plain(p)
}

fn abs_octaves_plain(p: DVec3) -> DVec3 {
    let mut scales = [1.0; 10];
    let mut ps = [p; 10];
    for k in 1..10 {
        scales[k] = scales[k - 1] * 2.0;
        ps[k] = p * scales[k];
    }
    let mut ds = [DVec3::ZERO; 10];
    vector_many_with(&ps, &mut ds, cell, vector_lanes);
    let mut sum = DVec3::ZERO;
    for k in 0..10 {
        sum += ds[k].abs() / scales[k];
    }
    sum
}

/// Octaves of vector noise, each `lambda` times finer and `omega` times weaker than the one
/// before, summed (turbulence's displacement; lambda and omega already as POV-Ray rounds
/// them; at most 10 octaves). Every octave's hash walk comes first, as in `scalar_many`.
#[inline(always)]
fn octaves_with(
    p: DVec3,
    octaves: u32,
    omega: f64,
    lambda: f64,
    cell: impl Fn(DVec3) -> Cell,
    terms: impl Fn(&Cell) -> [f64; 3],
) -> DVec3 {
    let n = octaves.min(10) as usize;
    let mut cells = CellList::<Cell, 10>::new();
    let mut scale = 1.0;
    for _ in 0..n {
        cells.push(cell(p * scale));
        scale *= lambda;
    }
    let mut sum = DVec3::ZERO;
    let mut weight = 1.0;
    for c in cells.as_slice() {
        sum += weight * DVec3::from_array(terms(c));
        weight *= omega;
    }
    sum
}

/// `octaves_with` at a normal's four samples: all their octaves' hash walks first.
#[inline(always)]
fn octaves4_with(
    ps: [DVec3; 4],
    octaves: u32,
    omega: f64,
    lambda: f64,
    cell: impl Fn(DVec3) -> Cell,
    terms: impl Fn(&Cell) -> [f64; 3],
) -> [DVec3; 4] {
    let n = octaves.clamp(1, 10) as usize;
    let mut cells = CellList::<Cell, MAX_POINTS>::new();
    for p in &ps {
        let mut scale = 1.0;
        for _ in 0..n {
            cells.push(cell(*p * scale));
            scale *= lambda;
        }
    }
    let mut out = [DVec3::ZERO; 4];
    for (o, cs) in out.iter_mut().zip(cells.as_slice().chunks(n)) {
        let mut weight = 1.0;
        for c in cs {
            *o += weight * DVec3::from_array(terms(c));
            weight *= omega;
        }
    }
    out
}

/// `vector_octaves` at four points (1 to 10 octaves).
pub fn vector_octaves4(ps: [DVec3; 4], octaves: u32, omega: f64, lambda: f64) -> [DVec3; 4] {
    #[cfg(target_arch = "x86_64")]
    if has_avx() {
        // SAFETY: AVX was detected.
        return unsafe { octaves_lanes::octaves4(ps, octaves, omega, lambda) };
    }
    octaves4_with(ps, octaves, omega, lambda, cell, vector_lanes)
}

/// `octaves` octaves (at most 10) of vector noise from `p`. Inlined, so that the turbulence
/// calls the AVX octaves directly.
#[inline]
pub fn vector_octaves(p: DVec3, octaves: u32, omega: f64, lambda: f64) -> DVec3 {
    #[cfg(target_arch = "x86_64")]
    if has_avx() {
        // SAFETY: AVX was detected.
        return unsafe { octaves_lanes::octaves(p, octaves, omega, lambda) };
    }
    octaves_plain(p, octaves, omega, lambda)
}

/// `vector_octaves` without AVX, out of line: inlined, its ten cells made the callers' stack
/// frames 1.4 KB and their prologues longer on every call.
#[cold]
#[inline(never)]
fn octaves_plain(p: DVec3, octaves: u32, omega: f64, lambda: f64) -> DVec3 {
    octaves_with(p, octaves, omega, lambda, cell, vector_lanes)
}

// The AVX forms of `octaves_with`, `octaves4_with`, `vector`, `vector_many` and
// `abs_octaves_plain`, with cells laid out for the lanes.
#[cfg(target_arch = "x86_64")]
#[path = "noise_octaves.rs"]
mod octaves_lanes;

#[cfg(test)]
#[path = "noise_lattice_tests.rs"]
mod tests;
