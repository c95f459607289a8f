//! The vector noise in AVX lanes: the turbulence's octaves (the displacement of every
//! turbulent wood, granite and sky) and the bumps, dents and wrinkles normals' single points,
//! `vector_lanes(&cell(p))`'s values bit for bit, with each cell laid out as the lanes read it.
//!
//! `Cell` keeps the s-curve weights as x·y products and two z weights, and the fractional
//! position as three scalars; the arithmetic then made the eight corner weights and the six
//! offset broadcasts (t and t − 1 per axis) with shuffles and scalar subtractions, about 30
//! instructions an octave. Here the hash-walk phase, which has the values in lanes anyway,
//! stores the eight weights (the same wxy·wz products) and both offset rows (the same
//! t − 1.0), so every corner reads its weight with one broadcast from memory; and the octaves'
//! sum stays in a register instead of three scalars that were spilled to the stack.

use std::arch::x86_64::*;
use std::mem::MaybeUninit;

use crate::math::DVec3;

use super::{
    cell, cell_lanes, entries_avx, Cell, CellLanes, CellList, HASH_Z32, MAX_POINTS, PACKED,
};

/// One octave's cell for the lanes: the fractional position's lanes (x, y, z, 0) and the
/// same minus one (each corner's offsets), the eight corners' weights in corner order
/// (corner = dx + 2dy + 4dz), and their rows in `PACKED` as `HASH_Z32`'s offsets (32 times
/// the ENTRY position; 4 times that is the row's byte offset, which the address's scale
/// makes: an index took a shift per corner).
#[derive(Clone, Copy)]
#[repr(C, align(32))]
struct LaneCell {
    d: [[f64; 4]; 2],
    w: [f64; 8],
    packed: [u32; 8],
}

/// The `PACKED` row at `HASH_Z32` offset `off` (a `LaneCell::packed`) as a pointer to its
/// sixteen numbers.
///
/// # Safety
/// `off` must be 32·k for some k < 256 (every `HASH_Z32` value is: HASH_Z's are below 256).
#[inline(always)]
unsafe fn packed_at(off: u32) -> *const f64 {
    // SAFETY: the caller guarantees 4·off = 128·k is the start of PACKED[k], k < 256.
    unsafe {
        PACKED
            .as_ptr()
            .cast::<u8>()
            .add(off as usize * 4)
            .cast::<f64>()
    }
}

/// `LaneCell` from a `Cell` (points whose floors leave the i32 range, and NaN): the
/// products and differences `vector_lanes` forms from it.
fn from_cell(c: &Cell) -> LaneCell {
    let [tx, ty, tz] = c.t;
    LaneCell {
        d: [[tx, ty, tz, 0.0], [tx - 1.0, ty - 1.0, tz - 1.0, -1.0]],
        w: std::array::from_fn(|k| c.wxy[k & 3] * c.wz[k >> 2]),
        packed: c.entry.map(|e| e * 32),
    }
}

/// `cell_avx`'s operations, then the weights' and offsets' last steps in the lanes.
///
/// # Safety
/// The CPU must have AVX.
#[inline(always)]
unsafe fn lane_cell(p: DVec3) -> LaneCell {
    // SAFETY: the caller guarantees AVX; the stores go to 32-byte aligned fields of a
    // `repr(C, align(32))` struct at offsets 0, 32, 64 and 96.
    unsafe {
        let Some(CellLanes { f, t, s, o, wxy }) = cell_lanes(p) else {
            return from_cell(&cell(p));
        };
        // Each z weight (1 − sz, sz) broadcast from lane 2, to multiply wx·wy by:
        // `vector_lanes`' wxy·wz products, four at a time.
        let oz = _mm256_permute_pd::<0>(_mm256_permute2f128_pd::<0x11>(o, o));
        let sz = _mm256_permute_pd::<0>(_mm256_permute2f128_pd::<0x11>(s, s));
        let mut c = LaneCell {
            d: [[0.0; 4]; 2],
            w: [0.0; 8],
            packed: entries_avx(f, &HASH_Z32),
        };
        _mm256_store_pd(c.d[0].as_mut_ptr(), t);
        _mm256_store_pd(c.d[1].as_mut_ptr(), _mm256_sub_pd(t, _mm256_set1_pd(1.0)));
        _mm256_store_pd(c.w.as_mut_ptr(), _mm256_mul_pd(wxy, oz));
        _mm256_store_pd(c.w.as_mut_ptr().add(4), _mm256_mul_pd(wxy, sz));
        c
    }
}

/// `vector_lanes`' sum over the eight corners (x, y, z in lanes 0-2), in corner order.
///
/// # Safety
/// The CPU must have AVX.
#[inline(always)]
unsafe fn lane_terms(c: &LaneCell) -> __m256d {
    // SAFETY: the caller guarantees AVX; every `packed` is a row's offset (`lane_cell`,
    // `from_cell`), and PACKED's rows are 32-byte aligned, as the aligned loads need.
    unsafe {
        let dx = [
            _mm256_broadcast_sd(&c.d[0][0]),
            _mm256_broadcast_sd(&c.d[1][0]),
        ];
        let dy = [
            _mm256_broadcast_sd(&c.d[0][1]),
            _mm256_broadcast_sd(&c.d[1][1]),
        ];
        let dz = [
            _mm256_broadcast_sd(&c.d[0][2]),
            _mm256_broadcast_sd(&c.d[1][2]),
        ];
        let mut acc = _mm256_setzero_pd();
        for (k, &off) in c.packed.iter().enumerate() {
            let e = packed_at(off);
            let w = _mm256_broadcast_sd(&c.w[k]);
            let mut t = _mm256_add_pd(
                _mm256_load_pd(e),
                _mm256_mul_pd(_mm256_load_pd(e.add(4)), dx[k & 1]),
            );
            t = _mm256_add_pd(t, _mm256_mul_pd(_mm256_load_pd(e.add(8)), dy[(k >> 1) & 1]));
            t = _mm256_add_pd(t, _mm256_mul_pd(_mm256_load_pd(e.add(12)), dz[k >> 2]));
            acc = _mm256_add_pd(acc, _mm256_mul_pd(w, t));
        }
        acc
    }
}

/// The lanes' x, y and z.
///
/// # Safety
/// The CPU must have AVX.
#[inline(always)]
unsafe fn to_dvec3(v: __m256d) -> DVec3 {
    let mut out = [0.0; 4];
    // SAFETY: the caller guarantees AVX; `out` has the four lanes' room.
    unsafe { _mm256_storeu_pd(out.as_mut_ptr(), v) };
    DVec3::new(out[0], out[1], out[2])
}

/// `vector_lanes(&cell(p))`, the vector noise of a bumps or dents normal. Through `Cell`
/// (`cell_avx`, then the AVX sum) the walk stored t, s and 1 − s as scalars and the sum
/// rebuilt the weights and offsets from them; the lanes' cell keeps them as the sum reads them.
#[target_feature(enable = "avx")]
pub(super) fn vector(p: DVec3) -> DVec3 {
    // SAFETY: this function only runs with AVX enabled.
    unsafe { to_dvec3(lane_terms(&lane_cell(p))) }
}

/// `vector` at up to ten points (the wrinkles normal's octaves): every hash walk first.
#[target_feature(enable = "avx")]
pub(super) fn vector_many<const N: usize>(ps: &[DVec3; N], out: &mut [DVec3; N]) {
    let mut cells = CellList::<LaneCell, N>::new();
    for &p in ps {
        // SAFETY: this function only runs with AVX enabled.
        cells.push(unsafe { lane_cell(p) });
    }
    for (o, c) in out.iter_mut().zip(cells.as_slice()) {
        // SAFETY: as above.
        *o = unsafe { to_dvec3(lane_terms(c)) };
    }
}

/// `noise_lattice::abs_octaves_plain(p)`, the wrinkles normal's ten octaves: the octaves'
/// values stay in the lanes for the sum instead of going out as `DVec3`s and coming back.
/// Each |value| is cleared of its sign as `f64::abs` does, and multiplied by 2⁻ᵏ where the
/// plain sum divides by 2ᵏ: both round the same exact quotient, so the bits are the same.
#[target_feature(enable = "avx")]
pub(super) fn abs_octaves(p: DVec3) -> DVec3 {
    let mut cells = CellList::<LaneCell, 10>::new();
    // SAFETY: this function only runs with AVX enabled.
    cells.push(unsafe { lane_cell(p) });
    let mut scale = 1.0;
    for _ in 1..10 {
        scale *= 2.0;
        // SAFETY: as above.
        cells.push(unsafe { lane_cell(p * scale) });
    }
    // SAFETY: as above.
    unsafe {
        let sign = _mm256_set1_pd(-0.0);
        let mut sum = _mm256_setzero_pd();
        let mut inv = 1.0;
        for c in cells.as_slice() {
            let a = _mm256_andnot_pd(sign, lane_terms(c));
            sum = _mm256_add_pd(sum, _mm256_mul_pd(a, _mm256_set1_pd(inv)));
            inv *= 0.5;
        }
        to_dvec3(sum)
    }
}

/// The octaves' weighted sum of `cells` (each octave's terms times 1, ω, ω², ...): `sum +=
/// weight·terms` lane by lane, as `octaves_with` adds its three components.
///
/// # Safety
/// The CPU must have AVX.
#[inline(always)]
unsafe fn weighted(cells: &[LaneCell], omega: f64) -> DVec3 {
    // SAFETY: the caller guarantees AVX.
    unsafe {
        let mut sum = _mm256_setzero_pd();
        let mut weight = 1.0;
        for c in cells {
            sum = _mm256_add_pd(sum, _mm256_mul_pd(_mm256_set1_pd(weight), lane_terms(c)));
            weight *= omega;
        }
        to_dvec3(sum)
    }
}

/// `octaves_with(p, .., cell, vector_lanes)`: every octave's hash walk first, then the
/// arithmetic.
///
/// The cells go to a plain array by the loop's own index: through `CellList` the list's
/// length went to memory and back with a bounds check on every octave (~5 instructions of
/// ~185), the stores through its buffer being able to alias it.
#[target_feature(enable = "avx")]
pub(super) fn octaves(p: DVec3, octaves: u32, omega: f64, lambda: f64) -> DVec3 {
    let n = octaves.min(10) as usize;
    let mut buf = [const { MaybeUninit::<LaneCell>::uninit() }; 10];
    let mut scale = 1.0;
    for cell in &mut buf[..n] {
        // SAFETY: this function only runs with AVX enabled.
        cell.write(unsafe { lane_cell(p * scale) });
        scale *= lambda;
    }
    // SAFETY: the first n cells were written just above (n <= 10, the slice's bound);
    // `MaybeUninit<LaneCell>` has `LaneCell`'s layout and LaneCell is Copy (nothing to drop).
    unsafe {
        let cells = std::slice::from_raw_parts(buf.as_ptr().cast::<LaneCell>(), n);
        weighted(cells, omega)
    }
}

/// `octaves4_with(ps, .., cell, vector_lanes)`: all four points' hash walks first.
#[target_feature(enable = "avx")]
pub(super) fn octaves4(ps: [DVec3; 4], octaves: u32, omega: f64, lambda: f64) -> [DVec3; 4] {
    let n = octaves.clamp(1, 10) as usize;
    let mut cells = CellList::<LaneCell, MAX_POINTS>::new();
    for p in &ps {
        let mut scale = 1.0;
        for _ in 0..n {
            // SAFETY: this function only runs with AVX enabled.
            cells.push(unsafe { lane_cell(*p * scale) });
            scale *= lambda;
        }
    }
    let mut out = [DVec3::ZERO; 4];
    for (o, cs) in out.iter_mut().zip(cells.as_slice().chunks(n)) {
        // SAFETY: as above.
        *o = unsafe { weighted(cs, omega) };
    }
    out
}
