//! The scalar noise at two to four points at once (the octaves of granite, wrinkles and
//! scalar turbulence, a normal's four samples): every point's hash walk first, then the
//! arithmetic with one point per lane. Split from noise_lattice.rs (its parent module) to
//! keep that file under 800 lines.

use std::arch::x86_64::*;
use std::mem::MaybeUninit;

use crate::math::DVec3;

use super::{cell, cell_avx, entries_avx, floor_lanes, scalar_avx, HASH_Z32, MAX_POINTS, ROWS};

/// What `scalar_avx4` reads of a cell: the fractional position and the corners' rows
/// (`Cell` without the weights, which the four-point lanes compute themselves). `row` holds
/// each corner's byte offset into `ROWS` (`HASH_Z32`, 32 times `Cell`'s entry): the loads
/// then add it to the table's address as it is, where an index took a shift per corner and
/// point (4 of the ~30 instructions of a corner of four points).
#[derive(Clone, Copy)]
pub(super) struct Corners {
    pub t: [f64; 3],
    pub row: [u32; 8],
}

/// The `ROWS` row at byte offset `off` (a `Corners::row`) as a pointer to its four numbers.
///
/// # Safety
/// `off` must be 32·k for some k < 256 (every `HASH_Z32` value is: HASH_Z's are below 256).
#[inline(always)]
unsafe fn row_at(off: u32) -> *const f64 {
    // SAFETY: the caller guarantees `off` is the start of row k < 256 of ROWS, whose rows
    // are 32 bytes each.
    unsafe { ROWS.as_ptr().cast::<u8>().add(off as usize).cast::<f64>() }
}

/// `cell_avx`'s fractional position and hash walk without its weights: the batched scalar
/// noise (wrinkles' ten octaves, granite's, a normal's four samples) computed and stored
/// the weights of every point only for `scalar_avx4` to compute them again in its lanes.
/// Coordinates outside the i32 range (and NaN) take `cell`, as `cell_avx` does.
///
/// # Safety
/// The CPU must have AVX.
#[inline(always)]
pub(super) unsafe fn corners_avx(p: DVec3) -> Corners {
    // SAFETY: the caller guarantees AVX.
    unsafe {
        let Some((v, f)) = floor_lanes(p) else {
            let c = cell(p);
            return Corners {
                t: c.t,
                row: c.entry.map(|e| e * 32),
            };
        };
        let mut ta = [0.0; 4];
        _mm256_storeu_pd(ta.as_mut_ptr(), _mm256_sub_pd(v, f));
        Corners {
            t: [ta[0], ta[1], ta[2]],
            row: entries_avx(f, &HASH_Z32),
        }
    }
}

#[target_feature(enable = "avx")]
pub(super) fn scalar_into_avx(ps: &[DVec3], out: &mut [f64]) {
    let n = ps.len().min(out.len()).min(MAX_POINTS);
    if n == 1 {
        // SAFETY: this function only runs with AVX enabled.
        out[0] = unsafe { scalar_avx(&cell_avx(ps[0])) };
        return;
    }
    // Every hash walk first (as `scalar_into_with`), without initialising the unused cells.
    let mut buf = [const { MaybeUninit::<Corners>::uninit() }; MAX_POINTS];
    for (b, &p) in buf.iter_mut().zip(&ps[..n]) {
        // SAFETY: this function only runs with AVX enabled.
        b.write(unsafe { corners_avx(p) });
    }
    // SAFETY: the first n cells were written just above; Corners is Copy (nothing to drop).
    let cells = unsafe { std::slice::from_raw_parts(buf.as_ptr() as *const Corners, n) };
    for ((c, o), p) in cells
        .chunks(4)
        .zip(out[..n].chunks_mut(4))
        .zip(ps.chunks(4))
    {
        if c.len() == 1 {
            // A lone last point (5 or 9 octaves) takes the one-point lanes, which need the
            // weights: its whole cell again.
            // SAFETY: as above.
            o[0] = unsafe { scalar_avx(&cell_avx(p[0])) };
        } else if c.len() == 2 {
            // SAFETY: as above.
            unsafe { scalar_avx2(c, o) };
        } else {
            // SAFETY: as above.
            unsafe { scalar_avx4(c, o) };
        }
    }
}

/// `scalar`'s arithmetic for two to four points at once (octaves of one sum), lane l for
/// point l: each lane computes every corner's term as the scalar code does and adds them in
/// corner order, so the eight-term sum is vertical instead of a horizontal chain per point.
/// The weights are computed in the lanes from the fractional positions with the scalar
/// code's operations (`cell`).
///
/// # Safety
/// The CPU must have AVX.
#[inline(always)]
unsafe fn scalar_avx4(cells: &[Corners], out: &mut [f64]) {
    let n = cells.len();
    // Missing lanes repeat the last point; their results are dropped.
    let lane = |l: usize| &cells[l.min(n - 1)];
    // SAFETY: the caller guarantees AVX; every `row` is a row's offset (`corners_avx`),
    // and ROWS' rows are 32-byte aligned.
    unsafe {
        let v = |a: usize| _mm256_setr_pd(lane(0).t[a], lane(1).t[a], lane(2).t[a], lane(3).t[a]);
        let (tx, ty, tz) = (v(0), v(1), v(2));
        let one = _mm256_set1_pd(1.0);
        let s_curve = |t: __m256d| {
            _mm256_mul_pd(
                _mm256_mul_pd(t, t),
                _mm256_sub_pd(_mm256_set1_pd(3.0), _mm256_mul_pd(_mm256_set1_pd(2.0), t)),
            )
        };
        let (sx, sy, sz) = (s_curve(tx), s_curve(ty), s_curve(tz));
        let (wx, wy) = ([_mm256_sub_pd(one, sx), sx], [_mm256_sub_pd(one, sy), sy]);
        let wxy = [
            _mm256_mul_pd(wx[0], wy[0]),
            _mm256_mul_pd(wx[1], wy[0]),
            _mm256_mul_pd(wx[0], wy[1]),
            _mm256_mul_pd(wx[1], wy[1]),
        ];
        let wz = [_mm256_sub_pd(one, sz), sz];
        let dx = [tx, _mm256_sub_pd(tx, one)];
        let dy = [ty, _mm256_sub_pd(ty, one)];
        let dz = [tz, _mm256_sub_pd(tz, one)];
        let mut acc = _mm256_setzero_pd();
        // Written out per corner (a macro, not a loop): rolled, the loop kept its operands on
        // the stack and computed each one's offset from k, ~14 of its ~47 instructions a
        // corner.
        macro_rules! corner {
            ($k:literal) => {{
                let row = |l: usize| _mm256_load_pd(row_at(lane(l).row[$k]));
                let [e0, e1, e2, e3] = transposed!(row(0), row(1), row(2), row(3));
                let mut t = _mm256_add_pd(e0, _mm256_mul_pd(e1, dx[$k & 1]));
                t = _mm256_add_pd(t, _mm256_mul_pd(e2, dy[($k >> 1) & 1]));
                t = _mm256_add_pd(t, _mm256_mul_pd(e3, dz[$k >> 2]));
                let w = _mm256_mul_pd(wxy[$k & 3], wz[$k >> 2]);
                acc = _mm256_add_pd(acc, _mm256_mul_pd(w, t));
            }};
        }
        corner!(0);
        corner!(1);
        corner!(2);
        corner!(3);
        corner!(4);
        corner!(5);
        corner!(6);
        corner!(7);
        if let Ok(o) = <&mut [f64; 4]>::try_from(&mut *out) {
            // Four points (most chunks): one store, where the copy of a slice of variable
            // length was a call to memcpy.
            _mm256_storeu_pd(o.as_mut_ptr(), acc);
        } else {
            let mut res = [0.0; 4];
            _mm256_storeu_pd(res.as_mut_ptr(), acc);
            out.copy_from_slice(&res[..n]);
        }
    }
}

/// `scalar_avx4` for two points in the two lanes of a 128-bit register: the last two of ten
/// octaves (wrinkles, granite) took a four-lane pass of which half was thrown away. Each
/// lane does `scalar_avx4`'s operations in its order (the accumulator starting at +0 too),
/// so the bits are the same.
///
/// # Safety
/// The CPU must have AVX (the caller's target feature; SSE2 would do).
#[inline(always)]
unsafe fn scalar_avx2(cells: &[Corners], out: &mut [f64]) {
    let (a, b) = (&cells[0], &cells[1]);
    // SAFETY: the caller guarantees AVX; every `row` is a row's offset (`corners_avx`),
    // and ROWS' rows are 32-byte aligned, so both their halves are 16-byte aligned, as the
    // aligned loads need.
    unsafe {
        let v = |i: usize| _mm_setr_pd(a.t[i], b.t[i]);
        let (tx, ty, tz) = (v(0), v(1), v(2));
        let one = _mm_set1_pd(1.0);
        let s_curve = |t: __m128d| {
            _mm_mul_pd(
                _mm_mul_pd(t, t),
                _mm_sub_pd(_mm_set1_pd(3.0), _mm_mul_pd(_mm_set1_pd(2.0), t)),
            )
        };
        let (sx, sy, sz) = (s_curve(tx), s_curve(ty), s_curve(tz));
        let (wx, wy) = ([_mm_sub_pd(one, sx), sx], [_mm_sub_pd(one, sy), sy]);
        let wxy = [
            _mm_mul_pd(wx[0], wy[0]),
            _mm_mul_pd(wx[1], wy[0]),
            _mm_mul_pd(wx[0], wy[1]),
            _mm_mul_pd(wx[1], wy[1]),
        ];
        let wz = [_mm_sub_pd(one, sz), sz];
        let dx = [tx, _mm_sub_pd(tx, one)];
        let dy = [ty, _mm_sub_pd(ty, one)];
        let dz = [tz, _mm_sub_pd(tz, one)];
        let mut acc = _mm_setzero_pd();
        for k in 0..8 {
            let (ra, rb) = (row_at(a.row[k]), row_at(b.row[k]));
            let (alo, ahi) = (_mm_load_pd(ra), _mm_load_pd(ra.add(2)));
            let (blo, bhi) = (_mm_load_pd(rb), _mm_load_pd(rb.add(2)));
            let (e0, e1) = (_mm_unpacklo_pd(alo, blo), _mm_unpackhi_pd(alo, blo));
            let (e2, e3) = (_mm_unpacklo_pd(ahi, bhi), _mm_unpackhi_pd(ahi, bhi));
            let mut t = _mm_add_pd(e0, _mm_mul_pd(e1, dx[k & 1]));
            t = _mm_add_pd(t, _mm_mul_pd(e2, dy[(k >> 1) & 1]));
            t = _mm_add_pd(t, _mm_mul_pd(e3, dz[k >> 2]));
            let w = _mm_mul_pd(wxy[k & 3], wz[k >> 2]);
            acc = _mm_add_pd(acc, _mm_mul_pd(w, t));
        }
        _mm_storeu_pd(out.as_mut_ptr(), acc);
    }
}
