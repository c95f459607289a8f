//! Image comparison for checking lancer's renders against POV-Ray's.
//!
//! Two renders of the same scene never agree pixel for pixel: the renderers
//! sample differently, round differently and may anti-alias differently. A
//! per-pixel difference would flag all of that noise, so the regression check
//! uses the structural similarity index (SSIM) of Wang et al. 2004, which
//! rewards matching local structure and forgives small, uncorrelated errors.
//!
//! The numbers are meant to agree with scikit-image's
//! `structural_similarity(a, b, gaussian_weights=True, sigma=1.5,
//! use_sample_covariance=False, data_range=1.0, channel_axis=2)`, so that a
//! threshold chosen by looking at images in Python means the same thing here.
//! `scripts/ssim_check.py` computes the reference values; `docs/ssim.md`
//! records how closely the two agree.

use std::path::Path;

/// A picture as linear arrays of f32 channel values in [0,1], RGB, row-major, row 0 at top.
#[derive(Clone, Debug, PartialEq)]
pub struct Picture {
    pub width: u32,
    pub height: u32,
    pub rgb: Vec<f32>,
}

/// Side of the Gaussian window: scipy's `gaussian_filter` with σ = 1.5 and
/// scikit-image's `truncate = 3.5` has radius `int(3.5 * 1.5 + 0.5)` = 5.
pub const WINDOW: u32 = 11;

/// Pixels dropped from each edge before averaging the SSIM map, as
/// scikit-image does, because near the border the window sees mirrored data.
pub const BORDER: u32 = (WINDOW - 1) / 2;

const RADIUS: usize = BORDER as usize;
const SIGMA: f64 = 1.5;
const K1: f64 = 0.01;
const K2: f64 = 0.03;
// Data range L = 1 because channel values are normalised to [0,1].
const C1: f64 = (K1 * 1.0) * (K1 * 1.0);
const C2: f64 = (K2 * 1.0) * (K2 * 1.0);

impl Picture {
    /// Reads PNG (8- or 16-bit, gray/RGB/RGBA, alpha dropped) or OpenEXR. Raw stored values:
    /// gAMA/sRGB chunks are ignored (POV-Ray writes a gAMA chunk; we compare raw pixel values).
    /// EXR values are used as stored (clamped to [0,1]).
    pub fn load(path: &Path) -> Result<Picture, String> {
        let err = |e: &dyn std::fmt::Display| format!("{}: {e}", path.display());
        let img = image::ImageReader::open(path)
            .map_err(|e| err(&e))?
            .with_guessed_format()
            .map_err(|e| err(&e))?
            .decode()
            .map_err(|e| err(&e))?;
        let (width, height) = (img.width(), img.height());
        // The samples are read straight from the decoded buffers rather than
        // through `to_rgb32f()` and friends: in image 0.25 those go through
        // colour-space-aware casts, and we want the stored numbers untouched.
        use image::DynamicImage as D;
        let rgb = match &img {
            D::ImageLuma8(b) => expand(b.as_raw(), 1, |v| f32::from(v) / 255.0),
            D::ImageLumaA8(b) => expand(b.as_raw(), 2, |v| f32::from(v) / 255.0),
            D::ImageRgb8(b) => expand(b.as_raw(), 3, |v| f32::from(v) / 255.0),
            D::ImageRgba8(b) => expand(b.as_raw(), 4, |v| f32::from(v) / 255.0),
            D::ImageLuma16(b) => expand(b.as_raw(), 1, |v| f32::from(v) / 65535.0),
            D::ImageLumaA16(b) => expand(b.as_raw(), 2, |v| f32::from(v) / 65535.0),
            D::ImageRgb16(b) => expand(b.as_raw(), 3, |v| f32::from(v) / 65535.0),
            D::ImageRgba16(b) => expand(b.as_raw(), 4, |v| f32::from(v) / 65535.0),
            D::ImageRgb32F(b) => expand(b.as_raw(), 3, clamp01),
            D::ImageRgba32F(b) => expand(b.as_raw(), 4, clamp01),
            other => {
                return Err(format!(
                    "{}: unsupported pixel format {:?}",
                    path.display(),
                    other.color()
                ))
            }
        };
        Ok(Picture { width, height, rgb })
    }

    /// Wraps 8-bit RGB bytes (`width × height × 3`, row 0 at top), e.g. a
    /// render still in memory. Panics if the length does not match.
    pub fn from_rgb8(width: u32, height: u32, data: &[u8]) -> Picture {
        assert_eq!(
            data.len(),
            width as usize * height as usize * 3,
            "from_rgb8: data length does not match {width}x{height} RGB"
        );
        Picture {
            width,
            height,
            rgb: data.iter().map(|&v| f32::from(v) / 255.0).collect(),
        }
    }
}

/// Turns interleaved samples with `channels` channels into RGB. Alpha is
/// dropped: the comparison is about the colours the renderers computed, and
/// gray is replicated so a gray file compares like the RGB picture it shows.
fn expand<T: Copy>(raw: &[T], channels: usize, conv: impl Fn(T) -> f32) -> Vec<f32> {
    let mut out = Vec::with_capacity(raw.len() / channels * 3);
    for px in raw.chunks_exact(channels) {
        if channels < 3 {
            let g = conv(px[0]);
            out.extend_from_slice(&[g, g, g]);
        } else {
            out.extend(px[..3].iter().map(|&v| conv(v)));
        }
    }
    out
}

/// EXR can hold anything, including NaN from a broken render; NaN becomes 0
/// so that it shows up as a difference instead of poisoning every mean.
fn clamp01(v: f32) -> f32 {
    if v.is_nan() {
        0.0
    } else {
        v.clamp(0.0, 1.0)
    }
}

/// Standard SSIM of Wang et al. 2004: Gaussian window 11×11, σ = 1.5, K1 = 0.01, K2 = 0.03,
/// data range L = 1, computed per channel with scikit-image's border treatment (mirror-reflect
/// filtering, then `BORDER` = 5 pixels cropped from each edge), mean over pixels then over
/// channels.
///
/// Errors if the sizes differ or either side is smaller than the 11-pixel window (scikit-image
/// refuses those too).
pub fn ssim(a: &Picture, b: &Picture) -> Result<f64, String> {
    let (w, h) = check(a, b)?;
    Ok(mean_ssim(&channel_maps(a, b, w, h), w, h))
}

/// The SSIM and the per-pixel map together, computing the expensive channel maps once.
pub fn ssim_and_map(a: &Picture, b: &Picture) -> Result<(f64, SsimMap), String> {
    let (w, h) = check(a, b)?;
    let maps = channel_maps(a, b, w, h);
    Ok((
        mean_ssim(&maps, w, h),
        (a.width, a.height, average_map(&maps)),
    ))
}

/// Mean over channels of each map's mean away from the border (scikit-image's cropping).
fn mean_ssim(maps: &[Vec<f64>; 3], w: usize, h: usize) -> f64 {
    let m = RADIUS;
    let count = ((w - 2 * m) * (h - 2 * m)) as f64;
    let mut total = 0.0;
    for map in maps {
        let sum: f64 = (m..h - m)
            .map(|y| map[y * w + m..y * w + w - m].iter().sum::<f64>())
            .sum();
        total += sum / count;
    }
    total / 3.0
}

/// The channel maps averaged pixel by pixel.
fn average_map([m0, m1, m2]: &[Vec<f64>; 3]) -> Vec<f32> {
    m0.iter()
        .zip(m1)
        .zip(m2)
        .map(|((x, y), z)| ((x + y + z) / 3.0) as f32)
        .collect()
}

/// Width, height and the per-pixel SSIM values, row-major.
pub type SsimMap = (u32, u32, Vec<f32>);

/// Per-pixel SSIM map (mean over channels), for heat maps and worst-tile reports.
///
/// The map has the picture's full size, border included (scikit-image's `full=True` output
/// averaged over channels), so it overlays the image pixel for pixel; `ssim` averages only the
/// part at least `BORDER` pixels from every edge.
pub fn ssim_map(a: &Picture, b: &Picture) -> Result<SsimMap, String> {
    let (w, h) = check(a, b)?;
    Ok((a.width, a.height, average_map(&channel_maps(a, b, w, h))))
}

/// Mean SSIM of the worst 16×16 tile, or `tile`×`tile` for another `tile`.
///
/// A low global SSIM says something is wrong; this says how wrong the worst spot
/// is, which catches a small missing object that the global mean would dilute.
pub fn worst_tile(map: &(u32, u32, Vec<f32>), tile: u32) -> f64 {
    worst_tile_at(map, tile).2
}

/// Like [`worst_tile`], but also returns the tile's top-left corner `(x, y, mean)`.
///
/// Tiles lie on a grid from the top-left corner; where the size is not a multiple
/// of `tile`, the last column and row of tiles are moved in to end at the edge, so
/// every tile has the same number of pixels and a sliver at the edge cannot score
/// as a whole tile. An empty map gives `(0, 0, NaN)`.
pub fn worst_tile_at(map: &(u32, u32, Vec<f32>), tile: u32) -> (u32, u32, f64) {
    let (w, h, values) = map;
    let (w, h) = (*w as usize, *h as usize);
    assert_eq!(
        values.len(),
        w * h,
        "worst_tile: map length does not match its size"
    );
    if w == 0 || h == 0 {
        return (0, 0, f64::NAN);
    }
    let tw = (tile.max(1) as usize).min(w);
    let th = (tile.max(1) as usize).min(h);
    let starts = |n: usize, t: usize| (0..n.div_ceil(t)).map(move |i| (i * t).min(n - t));
    let mut worst = (0, 0, f64::INFINITY);
    for y0 in starts(h, th) {
        for x0 in starts(w, tw) {
            let sum: f64 = (y0..y0 + th)
                .flat_map(|y| &values[y * w + x0..y * w + x0 + tw])
                .map(|&v| f64::from(v))
                .sum();
            let mean = sum / (tw * th) as f64;
            if mean < worst.2 {
                worst = (x0 as u32, y0 as u32, mean);
            }
        }
    }
    worst
}

/// Peak signal-to-noise ratio in dB with peak 1, over all channels (scikit-image's
/// `peak_signal_noise_ratio(a, b, data_range=1.0)`). Identical pictures give +∞.
pub fn psnr(a: &Picture, b: &Picture) -> Result<f64, String> {
    check_sizes(a, b)?;
    if a.rgb.is_empty() {
        return Err("psnr: pictures are empty".into());
    }
    let se: f64 = a
        .rgb
        .iter()
        .zip(&b.rgb)
        .map(|(&x, &y)| (f64::from(x) - f64::from(y)).powi(2))
        .sum();
    let mse = se / a.rgb.len() as f64;
    Ok(if mse == 0.0 {
        f64::INFINITY
    } else {
        -10.0 * mse.log10()
    })
}

/// Writes an SSIM map as a grayscale PNG: white where the pictures agree, black
/// where SSIM ≤ 0. Handy next to the two renders when a regression test fails.
pub fn write_map_png(map: &(u32, u32, Vec<f32>), path: &Path) -> Result<(), String> {
    let (w, h, values) = map;
    let bytes: Vec<u8> = values
        .iter()
        .map(|&v| (clamp01(v) * 255.0).round() as u8)
        .collect();
    image::save_buffer(path, &bytes, *w, *h, image::ExtendedColorType::L8)
        .map_err(|e| format!("{}: {e}", path.display()))
}

fn check_sizes(a: &Picture, b: &Picture) -> Result<(), String> {
    for p in [a, b] {
        if p.rgb.len() != p.width as usize * p.height as usize * 3 {
            return Err(format!(
                "picture claims {}x{} but holds {} values, not {}",
                p.width,
                p.height,
                p.rgb.len(),
                p.width as usize * p.height as usize * 3
            ));
        }
    }
    if (a.width, a.height) != (b.width, b.height) {
        return Err(format!(
            "picture sizes differ: {}x{} vs {}x{}",
            a.width, a.height, b.width, b.height
        ));
    }
    Ok(())
}

fn check(a: &Picture, b: &Picture) -> Result<(usize, usize), String> {
    check_sizes(a, b)?;
    if a.width < WINDOW || a.height < WINDOW {
        return Err(format!(
            "picture is {}x{}; SSIM needs at least {WINDOW}x{WINDOW}",
            a.width, a.height
        ));
    }
    Ok((a.width as usize, a.height as usize))
}

/// scipy's `_gaussian_kernel1d`: sampled, not integrated, then normalised.
fn kernel() -> [f64; WINDOW as usize] {
    let mut k = [0.0; WINDOW as usize];
    for (i, v) in k.iter_mut().enumerate() {
        let x = i as f64 - RADIUS as f64;
        *v = (-0.5 / (SIGMA * SIGMA) * x * x).exp();
    }
    let sum: f64 = k.iter().sum();
    k.iter_mut().for_each(|v| *v /= sum);
    k
}

/// scipy's `mode='reflect'` (d c b a | a b c d | d c b a): the edge sample is
/// repeated. Folding repeatedly keeps it right even when the window is wider
/// than the picture.
fn reflect(i: isize, n: usize) -> usize {
    let n = n as isize;
    let m = i.rem_euclid(2 * n);
    (if m >= n { 2 * n - 1 - m } else { m }) as usize
}

/// Full-size SSIM map of each channel.
///
/// Everything is f64: the variances are differences of nearly equal filtered
/// values, which f32 would round away on flat regions. The five filtered
/// quantities (x, y, x², y², xy) are produced one output row at a time, so the
/// intermediate data stays in cache and no full-size temporary planes are needed.
fn channel_maps(a: &Picture, b: &Picture, w: usize, h: usize) -> [Vec<f64>; 3] {
    let k = kernel();
    std::array::from_fn(|c| {
        let plane = |p: &Picture| -> Vec<f64> {
            p.rgb.chunks_exact(3).map(|px| f64::from(px[c])).collect()
        };
        let (x, y) = (plane(a), plane(b));
        let mut map = vec![0.0; w * h];
        // Column-filtered rows, padded by RADIUS on each side for the row pass.
        let mut cols: [Vec<f64>; 5] = std::array::from_fn(|_| vec![0.0; w + 2 * RADIUS]);
        let mut filt: [Vec<f64>; 5] = std::array::from_fn(|_| vec![0.0; w]);
        for (row, out) in map.chunks_exact_mut(w).enumerate() {
            filter_columns(&x, &y, w, h, row, &k, &mut cols);
            for (p, f) in cols.iter_mut().zip(filt.iter_mut()) {
                filter_row(p, w, &k, f);
            }
            let [ux, uy, uxx, uyy, uxy] = &filt;
            for (i, s) in out.iter_mut().enumerate() {
                *s = ssim_formula(ux[i], uy[i], uxx[i], uyy[i], uxy[i]);
            }
        }
        map
    })
}

/// The vertical pass (scipy filters axis 0 first) for output row `row`: the
/// Gaussian-weighted sums of x, y, x², y² and xy down each column, written into
/// the middle of the padded buffers in `cols`.
///
/// All taps of a column are summed in one go, so the five sums stay in
/// registers instead of going through memory once per tap.
fn filter_columns(
    x: &[f64],
    y: &[f64],
    w: usize,
    h: usize,
    row: usize,
    k: &[f64; WINDOW as usize],
    cols: &mut [Vec<f64>; 5],
) {
    let start: [usize; WINDOW as usize] =
        std::array::from_fn(|t| reflect(row as isize + t as isize - RADIUS as isize, h) * w);
    let xr: [&[f64]; WINDOW as usize] = std::array::from_fn(|t| &x[start[t]..start[t] + w]);
    let yr: [&[f64]; WINDOW as usize] = std::array::from_fn(|t| &y[start[t]..start[t] + w]);
    let [cx, cy, cxx, cyy, cxy] = cols;
    let (cx, cy) = (&mut cx[RADIUS..RADIUS + w], &mut cy[RADIUS..RADIUS + w]);
    let (cxx, cyy) = (&mut cxx[RADIUS..RADIUS + w], &mut cyy[RADIUS..RADIUS + w]);
    let cxy = &mut cxy[RADIUS..RADIUS + w];
    for i in 0..w {
        let mut s = [0.0; 5];
        for t in 0..WINDOW as usize {
            let (xs, ys, kt) = (xr[t][i], yr[t][i], k[t]);
            s[0] += kt * xs;
            s[1] += kt * ys;
            s[2] += kt * (xs * xs);
            s[3] += kt * (ys * ys);
            // x·y before weighting keeps swapped inputs bit-identical.
            s[4] += kt * (xs * ys);
        }
        (cx[i], cy[i], cxx[i], cyy[i], cxy[i]) = (s[0], s[1], s[2], s[3], s[4]);
    }
}

/// The horizontal pass: mirror the `w` values in the middle of `p` into its
/// padding, then filter, pairing taps that share a weight.
fn filter_row(p: &mut [f64], w: usize, k: &[f64; WINDOW as usize], out: &mut [f64]) {
    for j in 0..RADIUS {
        p[j] = p[RADIUS + reflect(j as isize - RADIUS as isize, w)];
        p[RADIUS + w + j] = p[RADIUS + reflect((w + j) as isize, w)];
    }
    let mut i = 0;
    while i + LANES <= w {
        out[i..i + LANES].copy_from_slice(&row_sums::<LANES>(p, k, i));
        i += LANES;
    }
    for (l, o) in out[i..w].iter_mut().enumerate() {
        *o = row_sums::<1>(p, k, i + l)[0];
    }
}

/// Outputs computed together: small fixed-size blocks keep the sums in
/// registers, which measured faster here than either one output at a time or
/// whole-row passes per tap.
const LANES: usize = 4;

/// Filtered values for outputs `i..i + N` of a padded row.
#[inline(always)]
fn row_sums<const N: usize>(p: &[f64], k: &[f64; WINDOW as usize], i: usize) -> [f64; N] {
    let window: &[f64] = &p[i..i + N + 2 * RADIUS];
    let mut s = [0.0; N];
    for l in 0..N {
        s[l] = k[RADIUS] * window[l + RADIUS];
    }
    for d in 1..=RADIUS {
        for l in 0..N {
            s[l] += k[RADIUS + d] * (window[l + RADIUS - d] + window[l + RADIUS + d]);
        }
    }
    s
}

/// Wang et al.'s formula from the local (weighted) moments, written exactly as
/// scikit-image evaluates it so the rounding matches as well as possible.
fn ssim_formula(ux: f64, uy: f64, uxx: f64, uyy: f64, uxy: f64) -> f64 {
    let vx = uxx - ux * ux;
    let vy = uyy - uy * uy;
    let vxy = uxy - ux * uy;
    let a1 = 2.0 * ux * uy + C1;
    let a2 = 2.0 * vxy + C2;
    let b1 = ux * ux + uy * uy + C1;
    let b2 = vx + vy + C2;
    (a1 * a2) / (b1 * b2)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn constant(w: u32, h: u32, v: f32) -> Picture {
        Picture {
            width: w,
            height: h,
            rgb: vec![v; (w * h * 3) as usize],
        }
    }

    /// Integer patterns that `scripts/ssim_check.py --synthetic` rebuilds in
    /// numpy, so the reference numbers below can be regenerated.
    fn synthetic(w: u32, h: u32, which: u32) -> Picture {
        let mut data = Vec::with_capacity((w * h * 3) as usize);
        for y in 0..h {
            for x in 0..w {
                for c in 0..3 {
                    let v = if which == 0 {
                        (x * 11 + y * 7 + c * 50) % 256
                    } else {
                        (x * x + 3 * y + c * 29 + (x * y) % 17) % 256
                    };
                    data.push(v as u8);
                }
            }
        }
        Picture::from_rgb8(w, h, &data)
    }

    #[test]
    fn identical_pictures_score_one() {
        let a = synthetic(40, 30, 1);
        assert_eq!(ssim(&a, &a).unwrap(), 1.0);
        let (_, _, map) = ssim_map(&a, &a).unwrap();
        assert!(map.iter().all(|&v| v == 1.0));
        assert_eq!(psnr(&a, &a).unwrap(), f64::INFINITY);
    }

    #[test]
    fn constant_pictures_have_closed_form() {
        // Variances vanish, so SSIM reduces to the luminance term
        // (2·μa·μb + C1) / (μa² + μb² + C1).
        let (a, b) = (constant(16, 12, 0.5), constant(16, 12, 0.25));
        let (ma, mb) = (f64::from(0.5f32), f64::from(0.25f32));
        let expect = (2.0 * ma * mb + C1) / (ma * ma + mb * mb + C1);
        assert!((ssim(&a, &b).unwrap() - expect).abs() < 1e-12);
        assert!((psnr(&a, &b).unwrap() - 10.0 * 16f64.log10()).abs() < 1e-9);
    }

    // From `python3 scripts/ssim_check.py --synthetic` (scikit-image 0.26.0).
    const SYNTHETIC_SKIMAGE: f64 = 0.25885892910226116;
    const SYNTHETIC_PSNR: f64 = 8.501229955585856;

    #[test]
    fn matches_scikit_image_on_synthetic_pair() {
        let (a, b) = (synthetic(24, 20, 0), synthetic(24, 20, 1));
        let got = ssim(&a, &b).unwrap();
        assert!((got - SYNTHETIC_SKIMAGE).abs() < 1e-9, "{got}");
        let got = psnr(&a, &b).unwrap();
        assert!((got - SYNTHETIC_PSNR).abs() < 1e-6, "{got}");
    }

    #[test]
    fn map_border_excluded_mean_is_ssim() {
        let (a, b) = (synthetic(30, 25, 0), synthetic(30, 25, 1));
        let (w, h, map) = ssim_map(&a, &b).unwrap();
        assert_eq!((w, h, map.len()), (30, 25, 750));
        let m = BORDER as usize;
        let inner: Vec<f64> = (m..25 - m)
            .flat_map(|y| &map[y * 30 + m..y * 30 + 30 - m])
            .map(|&v| f64::from(v))
            .collect();
        let mean = inner.iter().sum::<f64>() / inner.len() as f64;
        assert!((mean - ssim(&a, &b).unwrap()).abs() < 1e-6);
    }

    #[test]
    fn symmetric() {
        let (a, b) = (synthetic(30, 25, 0), synthetic(30, 25, 1));
        assert_eq!(ssim(&a, &b).unwrap(), ssim(&b, &a).unwrap());
        assert_eq!(ssim_map(&a, &b).unwrap(), ssim_map(&b, &a).unwrap());
    }

    #[test]
    fn size_mismatch_and_tiny_pictures_are_errors() {
        let a = constant(20, 20, 0.5);
        assert!(ssim(&a, &constant(20, 21, 0.5)).is_err());
        assert!(ssim_map(&a, &constant(21, 20, 0.5)).is_err());
        assert!(psnr(&a, &constant(21, 20, 0.5)).is_err());
        let tiny = constant(10, 20, 0.5);
        assert!(ssim(&tiny, &tiny).is_err());
        let bad = Picture {
            width: 20,
            height: 20,
            rgb: vec![0.0; 5],
        };
        assert!(ssim(&bad, &bad).is_err());
    }

    #[test]
    fn reflect_matches_scipy() {
        // scipy.ndimage 'reflect' on n = 4: ... 1 0 | 0 1 2 3 | 3 2 ...
        let got: Vec<usize> = (-5..10).map(|i| reflect(i, 4)).collect();
        assert_eq!(got, [3, 3, 2, 1, 0, 0, 1, 2, 3, 3, 2, 1, 0, 0, 1]);
        assert_eq!(reflect(-3, 1), 0);
    }

    #[test]
    fn kernel_is_normalised_and_symmetric() {
        let k = kernel();
        assert!((k.iter().sum::<f64>() - 1.0).abs() < 1e-15);
        for i in 0..RADIUS {
            assert_eq!(k[i], k[WINDOW as usize - 1 - i]);
        }
    }

    #[test]
    fn worst_tile_finds_the_damage() {
        let a = constant(64, 48, 0.5);
        let mut b = a.clone();
        // A bright square inside the tile whose corner is (32, 16).
        for y in 20..28 {
            for x in 36..44 {
                for c in 0..3 {
                    b.rgb[(y * 64 + x) * 3 + c] = 1.0;
                }
            }
        }
        let map = ssim_map(&a, &b).unwrap();
        let (x, y, worst) = worst_tile_at(&map, 16);
        assert_eq!((x, y), (32, 16));
        assert!(worst < 0.9);
        assert_eq!(worst_tile(&map, 16), worst);
        assert!(worst < ssim(&a, &b).unwrap());
        // Sizes that are not multiples of the tile still use full tiles.
        let odd = (20, 20, vec![1.0f32; 400]);
        assert_eq!(worst_tile_at(&odd, 16), (0, 0, 1.0));
        assert!(worst_tile(&(0, 0, vec![]), 16).is_nan());
    }

    fn temp_path(name: &str) -> std::path::PathBuf {
        std::env::temp_dir().join(format!("lancer-ssim-{}-{name}", std::process::id()))
    }

    #[test]
    fn load_png_16_bit_and_alpha_keep_raw_values() {
        let path = temp_path("rgba16.png");
        let raw: Vec<u16> = vec![0, 1, 65535, 7, 30000, 40000, 50000, 0];
        let buf = image::ImageBuffer::<image::Rgba<u16>, _>::from_raw(2, 1, raw).unwrap();
        buf.save(&path).unwrap();
        let p = Picture::load(&path).unwrap();
        std::fs::remove_file(&path).ok();
        assert_eq!((p.width, p.height), (2, 1));
        let expect = [
            0.0,
            1.0 / 65535.0,
            1.0,
            30000.0 / 65535.0,
            40000.0 / 65535.0,
            50000.0 / 65535.0,
        ];
        for (g, e) in p.rgb.iter().zip(expect) {
            assert!((f64::from(*g) - e).abs() < 1e-7, "{g} vs {e}");
        }
    }

    #[test]
    fn load_gray_png_replicates() {
        let path = temp_path("gray8.png");
        image::GrayImage::from_raw(3, 1, vec![0, 128, 255])
            .unwrap()
            .save(&path)
            .unwrap();
        let p = Picture::load(&path).unwrap();
        std::fs::remove_file(&path).ok();
        let expect = Picture::from_rgb8(3, 1, &[0, 0, 0, 128, 128, 128, 255, 255, 255]);
        assert_eq!(p, expect);
    }

    #[test]
    fn load_exr_clamps() {
        let path = temp_path("clamp.exr");
        let raw = vec![-1.0f32, 0.25, 3.0, 0.5, 1.0, 0.0];
        image::Rgb32FImage::from_raw(2, 1, raw)
            .unwrap()
            .save(&path)
            .unwrap();
        let p = Picture::load(&path).unwrap();
        std::fs::remove_file(&path).ok();
        assert_eq!(p.rgb, vec![0.0, 0.25, 1.0, 0.5, 1.0, 0.0]);
    }

    #[test]
    fn heat_map_png_round_trips() {
        let path = temp_path("map.png");
        let map = (2, 2, vec![1.0f32, 0.5, 0.0, -0.3]);
        write_map_png(&map, &path).unwrap();
        let p = Picture::load(&path).unwrap();
        std::fs::remove_file(&path).ok();
        let g: Vec<f32> = p.rgb.iter().step_by(3).copied().collect();
        assert_eq!(g, vec![1.0, 128.0 / 255.0, 0.0, 0.0]);
    }

    #[test]
    fn load_missing_file_is_an_error() {
        assert!(Picture::load(Path::new("/nonexistent/lancer.png")).is_err());
    }

    /// Prints SSIM and PSNR for pairs of files named in `LANCER_SSIM_PAIRS`
    /// (paths joined like `PATH`), for `scripts/ssim_check.py --rust`.
    #[test]
    #[ignore]
    fn pairs_from_env() {
        let Some(list) = std::env::var_os("LANCER_SSIM_PAIRS") else {
            return;
        };
        let paths: Vec<_> = std::env::split_paths(&list).collect();
        for pair in paths.chunks(2) {
            let [pa, pb] = pair else {
                panic!("LANCER_SSIM_PAIRS needs an even number of paths");
            };
            let a = Picture::load(pa).unwrap();
            let b = Picture::load(pb).unwrap();
            println!(
                "LANCER_SSIM\t{:.10}\t{:.6}\t{}\t{}",
                ssim(&a, &b).unwrap(),
                psnr(&a, &b).unwrap(),
                pa.display(),
                pb.display()
            );
        }
    }
}
