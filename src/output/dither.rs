//! Output dithering (`+TH`, `Dither_Method`), reconstructed from what povray 3.7 writes (its
//! 16-bit output taken as the unquantised value, its dithered 5- and 8-bit files as the
//! answer):
//!
//! - Bayer (`b2`, `b3`, `b4`): q = min(floor(e·max + k/n²), max) on the encoded value e, k
//!   from the matrices below (1..=n², so black becomes 1 where k = n², as in POV-Ray's files).
//! - Error diffusion (`d1`, `d2`, `fs`) works in linear light: the target is the pixel's
//!   linear value plus the error it received, clipped to [0, 1]; q rounds its encoding; the
//!   error passed on is the target minus the linear value of q. Pixels go in raster order.
//!   `d1` hands the whole error to the next pixel, running on from the end of one row into
//!   the next; `d2` gives 1/2 right, 1/4 down and 1/4 down-right; `fs` is Floyd–Steinberg
//!   (7/16 right, 3/16 down-left, 5/16 down, 1/16 down-right, not serpentine). In `d2` and
//!   `fs` what would fall off the picture is dropped.
//!
//! An alpha channel is dithered alongside the colour, on its own value (POV-Ray's Bayer-dithered
//! RGBA files show the same offsets in alpha).

use super::pixels::Curve;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DitherMethod {
    Bayer2,
    Bayer3,
    Bayer4,
    Diffuse1,
    Diffuse2,
    FloydSteinberg,
}

impl DitherMethod {
    /// `b2`, `b3`, `b4`, `d1`, `d2` or `fs`, in any case.
    pub fn parse(s: &str) -> Result<DitherMethod, String> {
        Ok(match s.to_ascii_lowercase().as_str() {
            "b2" => DitherMethod::Bayer2,
            "b3" => DitherMethod::Bayer3,
            "b4" => DitherMethod::Bayer4,
            "d1" => DitherMethod::Diffuse1,
            "d2" => DitherMethod::Diffuse2,
            "fs" => DitherMethod::FloydSteinberg,
            _ => {
                return Err(format!(
                    "unknown dither method '{s}' (b2, b3, b4, d1, d2 or fs)"
                ))
            }
        })
    }
}

/// Thresholds k by [y mod n][x mod n]; the offset added before flooring is k / n².
const BAYER2: [[u8; 2]; 2] = [[1, 4], [3, 2]];
const BAYER3: [[u8; 3]; 3] = [[3, 6, 2], [7, 1, 8], [4, 9, 5]];
const BAYER4: [[u8; 4]; 4] = [
    [1, 13, 4, 16],
    [9, 5, 12, 8],
    [3, 15, 2, 14],
    [11, 7, 10, 6],
];

/// The samples of one pixel: colour in linear light, then alpha when there is one.
pub(crate) type Px = [f64; 4];

/// Quantises pixels (row-major, `width` per row) to 0..=max with dithering; `curves` encodes
/// each channel (colour with the file's curve, alpha as it is).
pub(crate) fn quantise(
    lin: &[Px],
    width: usize,
    max: f64,
    curve: [Curve; 4],
    method: DitherMethod,
) -> Vec<[u16; 4]> {
    match method {
        DitherMethod::Bayer2 => bayer(lin, width, max, curve, |x, y| BAYER2[y % 2][x % 2], 2),
        DitherMethod::Bayer3 => bayer(lin, width, max, curve, |x, y| BAYER3[y % 3][x % 3], 3),
        DitherMethod::Bayer4 => bayer(lin, width, max, curve, |x, y| BAYER4[y % 4][x % 4], 4),
        DitherMethod::Diffuse1 => diffuse_serial(lin, max, curve),
        DitherMethod::Diffuse2 => diffuse(lin, width, max, curve, 0.5, &[(0, 0.25), (1, 0.25)]),
        DitherMethod::FloydSteinberg => diffuse(
            lin,
            width,
            max,
            curve,
            7.0 / 16.0,
            &[(-1, 3.0 / 16.0), (0, 5.0 / 16.0), (1, 1.0 / 16.0)],
        ),
    }
}

fn bayer(
    lin: &[Px],
    width: usize,
    max: f64,
    curve: [Curve; 4],
    k: impl Fn(usize, usize) -> u8,
    n: usize,
) -> Vec<[u16; 4]> {
    let cells = (n * n) as f64;
    lin.iter()
        .enumerate()
        .map(|(i, l)| {
            let off = k(i % width, i / width) as f64 / cells;
            std::array::from_fn(|c| (curve[c].encode(l[c]) * max + off).floor().min(max) as u16)
        })
        .collect()
}

/// One error-diffusion step: the sample for a target and the linear error it leaves.
fn step(target: f64, max: f64, curve: Curve) -> (u16, f64) {
    let t = target.clamp(0.0, 1.0);
    let q = (curve.encode(t) * max + 0.5).floor();
    (q as u16, t - curve.decode(q / max))
}

fn diffuse_serial(lin: &[Px], max: f64, curve: [Curve; 4]) -> Vec<[u16; 4]> {
    let mut err = [0.0; 4];
    lin.iter()
        .map(|l| {
            let mut out = [0; 4];
            for c in 0..4 {
                let (q, e) = step(l[c] + err[c], max, curve[c]);
                out[c] = q;
                err[c] = e;
            }
            out
        })
        .collect()
}

/// Error diffusion to the right (`right` of the error) and to the row below (`(dx, share)`).
fn diffuse(
    lin: &[Px],
    width: usize,
    max: f64,
    curve: [Curve; 4],
    right: f64,
    below: &[(isize, f64)],
) -> Vec<[u16; 4]> {
    let mut out = Vec::with_capacity(lin.len());
    // Errors received by the current and the next row.
    let mut this_row = vec![[0.0; 4]; width];
    let mut next_row = vec![[0.0; 4]; width];
    for row in lin.chunks(width.max(1)) {
        let mut carry = [0.0; 4];
        for (x, l) in row.iter().enumerate() {
            let mut px = [0; 4];
            for c in 0..4 {
                let (q, e) = step(l[c] + this_row[x][c] + carry[c], max, curve[c]);
                px[c] = q;
                carry[c] = e * right;
                for &(dx, share) in below {
                    let nx = x as isize + dx;
                    if (0..width as isize).contains(&nx) {
                        next_row[nx as usize][c] += e * share;
                    }
                }
            }
            out.push(px);
        }
        std::mem::swap(&mut this_row, &mut next_row);
        next_row.iter_mut().for_each(|e| *e = [0.0; 4]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    const SRGB: [Curve; 4] = [Curve::Srgb, Curve::Srgb, Curve::Srgb, Curve::Identity];

    fn one_channel(out: &[[u16; 4]]) -> Vec<u16> {
        out.iter().map(|p| p[0]).collect()
    }

    #[test]
    fn bayer_offsets_and_black() {
        // POV-Ray's 4x4 black picture with +FN5 +THb2: 1 where the threshold is n².
        let black = vec![[0.0; 4]; 16];
        let q = quantise(&black, 4, 31.0, SRGB, DitherMethod::Bayer2);
        assert_eq!(
            one_channel(&q),
            vec![0, 1, 0, 1, 0, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0]
        );
        let q = quantise(&black, 4, 255.0, SRGB, DitherMethod::Bayer4);
        assert_eq!(one_channel(&q).iter().filter(|&&v| v == 1).count(), 1);
        assert_eq!(q[3][0], 1);
        // White stays at the top.
        let white = vec![[1.0; 4]; 9];
        let q = quantise(&white, 3, 31.0, SRGB, DitherMethod::Bayer3);
        assert!(one_channel(&q).iter().all(|&v| v == 31));
        for m in [BAYER3.concat(), BAYER4.concat()] {
            let mut k = m.clone();
            k.sort();
            assert_eq!(k, (1..=m.len() as u8).collect::<Vec<_>>());
        }
    }

    #[test]
    fn error_diffusion_keeps_the_mean() {
        // A flat level a quarter of the way between two steps: a quarter of the pixels go up.
        let e = 20.25 / 31.0;
        let l = Curve::Srgb.decode(e);
        let flat = vec![[l; 4]; 12 * 6];
        for m in [
            DitherMethod::Diffuse1,
            DitherMethod::Diffuse2,
            DitherMethod::FloydSteinberg,
        ] {
            let q = quantise(&flat, 12, 31.0, SRGB, m);
            let ups = one_channel(&q).iter().filter(|&&v| v == 21).count();
            assert!(one_channel(&q).iter().all(|&v| v == 20 || v == 21));
            assert!((16..=20).contains(&ups), "{m:?}: {ups} of 72 up");
        }
    }

    #[test]
    fn d1_runs_on_across_rows_and_fs_does_not() {
        // As in POV-Ray's 12x6 pictures of a flat level with +THd1, the pattern runs on from
        // one row into the next: a fifth of a step goes up every fifth pixel.
        let l = Curve::Srgb.decode(20.2 / 31.0);
        let flat = vec![[l; 4]; 12 * 2];
        let q = quantise(&flat, 12, 31.0, SRGB, DitherMethod::Diffuse1);
        let ups: Vec<usize> = (0..24).filter(|&i| q[i][0] == 21).collect();
        assert_eq!(ups[..4], [2, 7, 12, 17]);
        // +THfs at a quarter step: the first row never goes up, the second alternates.
        let l = Curve::Srgb.decode(20.25 / 31.0);
        let flat = vec![[l; 4]; 12 * 2];
        let q = quantise(&flat, 12, 31.0, SRGB, DitherMethod::FloydSteinberg);
        assert!(q[..12].iter().all(|p| p[0] == 20));
        let second: Vec<u16> = q[12..].iter().map(|p| p[0] - 20).collect();
        assert_eq!(second, vec![0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1]);
    }

    #[test]
    fn methods_parse() {
        assert_eq!(
            DitherMethod::parse("FS").unwrap(),
            DitherMethod::FloydSteinberg
        );
        assert_eq!(DitherMethod::parse("b3").unwrap(), DitherMethod::Bayer3);
        assert!(DitherMethod::parse("b5").is_err());
    }
}
