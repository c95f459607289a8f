//! The scalar noise at two to four points at once (the octaves of granite, wrinkles and
//! scalar turbulence, a normal's four samples): every point's hash walk first, then the
//! arithmetic with one point per lane. Split from noise_lattice.rs (its parent module) to
//! keep that file under 800 lines.

use std::arch::x86_64::*;
use std::mem::MaybeUninit;

use crate::math::DVec3;

use super::super::noise_data::{GEN2_A, GEN2_B};
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
    // SAFETY: the caller guarantees AVX.
    unsafe {
        let acc = sum_avx4(cells);
        if let Ok(o) = <&mut [f64; 4]>::try_from(&mut *out) {
            // Four points (most chunks): one store, where the copy of a slice of variable
            // length was a call to memcpy.
            _mm256_storeu_pd(o.as_mut_ptr(), acc);
        } else {
            let mut res = [0.0; 4];
            _mm256_storeu_pd(res.as_mut_ptr(), acc);
            out.copy_from_slice(&res[..cells.len()]);
        }
    }
}

/// `scalar_avx4`'s sums left in their lanes (lane l for `cells[l]`; missing lanes repeat
/// the last point), for callers that map them further in the lanes.
///
/// # Safety
/// The CPU must have AVX.
#[inline(always)]
unsafe fn sum_avx4(cells: &[Corners]) -> __m256d {
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
        acc
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
    // SAFETY: the caller guarantees AVX.
    unsafe { _mm_storeu_pd(out.as_mut_ptr(), sum_avx2(&cells[0], &cells[1])) };
}

/// `scalar_avx2`'s sums left in their lanes (lane 0 for `a`, lane 1 for `b`).
///
/// # Safety
/// The CPU must have AVX (the caller's target feature; SSE2 would do).
#[inline(always)]
unsafe fn sum_avx2(a: &Corners, b: &Corners) -> __m128d {
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
        acc
    }
}

/// Granite's six octaves at `p` (generators 1 and 2; `gen1` picks the first): `noise::granite`'s
/// value without its points, values and mapping going through memory. The octaves' points
/// are `p·f` as there, their walks and sums `scalar_into_avx`'s (four points in
/// `sum_avx4`, the last two in `sum_avx2`), and each lane maps its sum with the scalar
/// code's operations in its order: the generator's value (`sum_noise`), the clamp to
/// [0, 1], then |v − ½|·4/f; the six terms are added to 0 in octave order, as there.
///
/// # Safety
/// The CPU must have AVX.
#[target_feature(enable = "avx")]
pub(super) fn granite_avx(p: DVec3, gen1: bool) -> f64 {
    const FREQS: [f64; 6] = [4.0, 8.0, 16.0, 32.0, 64.0, 128.0];
    let mut cells = [const { MaybeUninit::<Corners>::uninit() }; 6];
    for (c, f) in cells.iter_mut().zip(FREQS) {
        // SAFETY: this function only runs with AVX enabled.
        c.write(unsafe { corners_avx(p * f) });
    }
    // SAFETY: all six were written just above; Corners is Copy.
    let cells = unsafe { &*(cells.as_ptr() as *const [Corners; 6]) };
    // SAFETY: this function only runs with AVX enabled.
    unsafe {
        let lo = granite_terms4(sum_avx4(&cells[..4]), gen1, _mm256_loadu_pd(FREQS.as_ptr()));
        let hi = granite_terms2(
            sum_avx2(&cells[4], &cells[5]),
            gen1,
            _mm_loadu_pd(FREQS[4..].as_ptr()),
        );
        let (mut a, mut b) = ([0.0; 4], [0.0; 2]);
        _mm256_storeu_pd(a.as_mut_ptr(), lo);
        _mm_storeu_pd(b.as_mut_ptr(), hi);
        let mut sum = 0.0;
        for t in a.into_iter().chain(b) {
            sum += t;
        }
        sum
    }
}

/// `x.clamp(0.0, 1.0)` in lanes, NaN and −0 included: `max(0, x)` answers its second
/// operand x for a NaN and for two zeros, and `min(1, y)` likewise.
macro_rules! clamp01 {
    ($max:ident, $min:ident, $set1:ident, $x:expr) => {
        $min($set1(1.0), $max($set1(0.0), $x))
    };
}

/// `noise::sum_noise` of generator 1 (`gen1`) or 2 per lane from the lattice sums `s`, with
/// its operations in its order.
///
/// # Safety
/// The CPU must have AVX.
#[inline(always)]
unsafe fn sum_noise4(s: __m256d, gen1: bool) -> __m256d {
    // SAFETY: the caller guarantees AVX.
    unsafe {
        let c = _mm256_set1_pd;
        let u = _mm256_add_pd(c(0.5), s);
        if gen1 {
            clamp01!(_mm256_max_pd, _mm256_min_pd, _mm256_set1_pd, u)
        } else {
            let g = _mm256_add_pd(c(GEN2_A), _mm256_mul_pd(c(GEN2_B), u));
            _mm256_sub_pd(_mm256_mul_pd(c(2.0), g), c(0.5))
        }
    }
}

/// `sum_noise4` in the two lanes of a 128-bit register.
///
/// # Safety
/// The CPU must have AVX (SSE2 would do).
#[inline(always)]
unsafe fn sum_noise2(s: __m128d, gen1: bool) -> __m128d {
    // SAFETY: the caller guarantees AVX.
    unsafe {
        let c = _mm_set1_pd;
        let u = _mm_add_pd(c(0.5), s);
        if gen1 {
            clamp01!(_mm_max_pd, _mm_min_pd, _mm_set1_pd, u)
        } else {
            let g = _mm_add_pd(c(GEN2_A), _mm_mul_pd(c(GEN2_B), u));
            _mm_sub_pd(_mm_mul_pd(c(2.0), g), c(0.5))
        }
    }
}

/// One octave's granite term per lane from the lattice sums `s` (see `granite_avx`).
///
/// # Safety
/// The CPU must have AVX.
#[inline(always)]
unsafe fn granite_terms4(s: __m256d, gen1: bool, f: __m256d) -> __m256d {
    // SAFETY: the caller guarantees AVX.
    unsafe {
        let c = _mm256_set1_pd;
        let v = clamp01!(
            _mm256_max_pd,
            _mm256_min_pd,
            _mm256_set1_pd,
            sum_noise4(s, gen1)
        );
        let d = _mm256_andnot_pd(c(-0.0), _mm256_sub_pd(v, c(0.5)));
        _mm256_div_pd(_mm256_mul_pd(d, c(4.0)), f)
    }
}

/// `granite_terms4` in the two lanes of a 128-bit register.
///
/// # Safety
/// The CPU must have AVX (SSE2 would do).
#[inline(always)]
unsafe fn granite_terms2(s: __m128d, gen1: bool, f: __m128d) -> __m128d {
    // SAFETY: the caller guarantees AVX.
    unsafe {
        let c = _mm_set1_pd;
        let v = clamp01!(_mm_max_pd, _mm_min_pd, _mm_set1_pd, sum_noise2(s, gen1));
        let d = _mm_andnot_pd(c(-0.0), _mm_sub_pd(v, c(0.5)));
        _mm_div_pd(_mm_mul_pd(d, c(4.0)), f)
    }
}

/// Scalar turbulence's `n` octaves (1 to 10) at `p`, generators 1 and 2 (`gen1`: the
/// first): `noise::turbulence`'s value with the octaves' points and values kept out of
/// zeroed arrays and the generator's map done in lanes. The points are `p·scale` with
/// scale multiplied by `lambda` per octave as there; the octaves go through
/// `scalar_into_avx`'s kernels in its chunks (four points in `sum_avx4`, a last chunk of
/// three too, of two in `sum_avx2`, of one, or one point alone, in `scalar_avx`), and the
/// sum is the first value clamped plus each next one times omega's running product, in
/// octave order.
///
/// # Safety
/// The CPU must have AVX.
#[target_feature(enable = "avx")]
pub(super) fn turbulence_avx(p: DVec3, n: usize, omega: f64, lambda: f64, gen1: bool) -> f64 {
    let n = n.clamp(1, 10);
    let mut pts = [const { MaybeUninit::<DVec3>::uninit() }; 10];
    let mut cells = [const { MaybeUninit::<Corners>::uninit() }; 10];
    let mut scale = 1.0;
    for k in 0..n {
        let q = if k == 0 {
            p
        } else {
            scale *= lambda;
            p * scale
        };
        pts[k].write(q);
        // SAFETY: this function only runs with AVX enabled.
        cells[k].write(unsafe { corners_avx(q) });
    }
    // SAFETY: the first n of each were written just above; both types are Copy.
    let (pts, cells) = unsafe {
        (
            std::slice::from_raw_parts(pts.as_ptr() as *const DVec3, n),
            std::slice::from_raw_parts(cells.as_ptr() as *const Corners, n),
        )
    };
    let mut v = [0.0; 12];
    let mut k = 0;
    // SAFETY: this function only runs with AVX enabled.
    unsafe {
        if n == 1 {
            v[0] = one_value(pts[0], gen1);
        }
        while n > 1 && k < n {
            let m = (n - k).min(4);
            if m == 1 {
                v[k] = one_value(pts[k], gen1);
            } else if m == 2 {
                let s = sum_noise2(sum_avx2(&cells[k], &cells[k + 1]), gen1);
                _mm_storeu_pd(v[k..].as_mut_ptr(), s);
            } else {
                let s = sum_noise4(sum_avx4(&cells[k..k + m]), gen1);
                _mm256_storeu_pd(v[k..].as_mut_ptr(), s);
            }
            k += m;
        }
    }
    crate::render::noise::octave_sum(&v[..n], omega)
}

/// One point's `sum_noise` through `scalar_avx`, as `scalar_into_avx` takes a lone point.
///
/// # Safety
/// The CPU must have AVX.
#[inline(always)]
unsafe fn one_value(p: DVec3, gen1: bool) -> f64 {
    // SAFETY: the caller guarantees AVX.
    unsafe {
        let s = scalar_avx(&cell_avx(p));
        if gen1 {
            (0.5 + s).clamp(0.0, 1.0)
        } else {
            2.0 * (GEN2_A + GEN2_B * (0.5 + s)) - 0.5
        }
    }
}

/// Wrinkles' ten octaves at `p` (generators 1 and 2; `gen1` picks the first):
/// `noise::wrinkles`' value without its points and values going through memory. The
/// octaves' points are `p·2ᵏ` as there, their walks and sums `scalar_into_avx`'s chunks
/// (four, four and two points), and each lane maps its sum with the scalar code's
/// operations in its order: the generator's value (`sum_noise`), the clamp to [0, 1], times
/// the octave's weight 2⁻ᵏ⁻¹; the ten terms are added to 0 in octave order, as there.
///
/// # Safety
/// The CPU must have AVX.
#[target_feature(enable = "avx")]
pub(super) fn wrinkles_avx(p: DVec3, gen1: bool) -> f64 {
    const WEIGHTS: [f64; 10] = [
        0.5,
        0.25,
        0.125,
        0.0625,
        0.03125,
        0.015625,
        0.0078125,
        0.00390625,
        0.001953125,
        0.0009765625,
    ];
    let mut cells = [const { MaybeUninit::<Corners>::uninit() }; 10];
    let mut f = 1.0;
    for c in cells.iter_mut() {
        // SAFETY: this function only runs with AVX enabled.
        c.write(unsafe { corners_avx(p * f) });
        f *= 2.0;
    }
    // SAFETY: all ten were written just above; Corners is Copy.
    let cells = unsafe { &*(cells.as_ptr() as *const [Corners; 10]) };
    // SAFETY: this function only runs with AVX enabled.
    unsafe {
        let term4 = |s: __m256d, w: &[f64]| {
            let v = clamp01!(
                _mm256_max_pd,
                _mm256_min_pd,
                _mm256_set1_pd,
                sum_noise4(s, gen1)
            );
            _mm256_mul_pd(_mm256_loadu_pd(w.as_ptr()), v)
        };
        let a = term4(sum_avx4(&cells[..4]), &WEIGHTS[..4]);
        let b = term4(sum_avx4(&cells[4..8]), &WEIGHTS[4..8]);
        let v = clamp01!(
            _mm_max_pd,
            _mm_min_pd,
            _mm_set1_pd,
            sum_noise2(sum_avx2(&cells[8], &cells[9]), gen1)
        );
        let c = _mm_mul_pd(_mm_loadu_pd(WEIGHTS[8..].as_ptr()), v);
        let mut t = [0.0; 10];
        _mm256_storeu_pd(t.as_mut_ptr(), a);
        _mm256_storeu_pd(t[4..].as_mut_ptr(), b);
        _mm_storeu_pd(t[8..].as_mut_ptr(), c);
        let mut sum = 0.0;
        for x in t {
            sum += x;
        }
        sum
    }
}
