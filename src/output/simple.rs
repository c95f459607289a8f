//! The byte-simple formats, written by hand so their layout is POV-Ray's: binary PPM (P6,
//! maxval 2ⁿ−1, two bytes a sample above 8 bits), Targa (top-down, BGR(A), straight alpha,
//! RLE packets split as POV-Ray splits them, a TGA 2.0 extension area recording the gamma
//! and whether alpha is meaningful) and BMP (bottom-up BGR rows padded to four bytes, or
//! BGRA with straight alpha; BITMAPINFOHEADER, as POV-Ray writes even 32-bit files).
//! Unlike POV-Ray no render date is written, so the same frame gives the same bytes.

use std::io::Write;

use super::pixels::Plane;

fn io(e: std::io::Error) -> String {
    e.to_string()
}

pub(crate) fn write_ppm(plane: &Plane, mut out: impl Write) -> Result<(), String> {
    out.write_all(&ppm_header(plane, plane.height))
        .map_err(io)?;
    write_ppm_samples(plane, &mut out).map_err(io)?;
    out.flush().map_err(io)
}

/// A PPM header for a picture `height` rows high of `plane`'s width and depth.
pub(crate) fn ppm_header(plane: &Plane, height: u32) -> Vec<u8> {
    let max = (1u32 << plane.bits) - 1;
    format!("P6\n{} {}\n{max}\n", plane.width, height).into_bytes()
}

/// Writes the samples as a PPM stores them: one byte each, or two big-endian above 8 bits.
/// A piece at a time through one small buffer: a buffer of the whole picture's bytes cost
/// more in page faults than its conversion.
pub(crate) fn write_ppm_samples(plane: &Plane, out: &mut impl Write) -> std::io::Result<()> {
    const PIECE: usize = 16 * 1024;
    let mut bytes = Vec::with_capacity(2 * PIECE);
    for piece in plane.data.chunks(PIECE) {
        bytes.clear();
        if plane.bits > 8 {
            bytes.extend(piece.iter().flat_map(|q| q.to_be_bytes()));
        } else {
            bytes.extend(piece.iter().map(|&q| q as u8));
        }
        out.write_all(&bytes)?;
    }
    Ok(())
}

/// One pixel in file order (blue, green, red, then alpha when there is one).
fn bgra(plane: &Plane, x: u32, y: u32) -> [u8; 4] {
    let p = plane.pixel(x, y);
    [
        p[2] as u8,
        p[1] as u8,
        p[0] as u8,
        *p.get(3).unwrap_or(&0) as u8,
    ]
}

pub(crate) fn write_tga(
    plane: &Plane,
    rle: bool,
    gamma: f64,
    mut out: impl Write,
) -> Result<(), String> {
    let (w, h) = (plane.width, plane.height);
    let (w16, h16) = match (u16::try_from(w), u16::try_from(h)) {
        (Ok(a), Ok(b)) => (a, b),
        _ => {
            return Err(format!(
                "Targa files hold at most 65535x65535 pixels, not {w}x{h}"
            ))
        }
    };
    let alpha = plane.channels == 4;
    let n = if alpha { 4 } else { 3 };
    let mut buf = Vec::with_capacity(18 + (w * h) as usize * n + 600);
    buf.extend_from_slice(&[0, 0, if rle { 10 } else { 2 }, 0, 0, 0, 0, 0, 0, 0, 0, 0]);
    buf.extend_from_slice(&w16.to_le_bytes());
    buf.extend_from_slice(&h16.to_le_bytes());
    // Bits per pixel; descriptor: rows top to bottom (bit 5) and the alpha bits.
    buf.push(8 * n as u8);
    buf.push(0x20 | if alpha { 8 } else { 0 });
    for y in 0..h {
        let row: Vec<[u8; 4]> = (0..w).map(|x| bgra(plane, x, y)).collect();
        if rle {
            rle_row(&row, n, &mut buf);
        } else {
            row.iter().for_each(|p| buf.extend_from_slice(&p[..n]));
        }
    }
    let extension_at = buf.len() as u32;
    extension_area(&mut buf, gamma, alpha);
    buf.extend_from_slice(&extension_at.to_le_bytes());
    buf.extend_from_slice(&0u32.to_le_bytes());
    buf.extend_from_slice(b"TRUEVISION-XFILE.\0");
    out.write_all(&buf).map_err(io)?;
    out.flush().map_err(io)
}

/// Packs one row as POV-Ray does (its files re-encode byte for byte): a pixel equal to the
/// next starts a run packet of up to 128; otherwise a literal packet gathers pixels up to
/// the next such pair; a packet that would start on the row's last pixel is a run of one.
/// Packets never cross rows.
fn rle_row(row: &[[u8; 4]], n: usize, buf: &mut Vec<u8>) {
    let w = row.len();
    let mut i = 0;
    while i < w {
        if i + 1 == w || row[i] == row[i + 1] {
            let mut len = 1;
            while i + len < w && len < 128 && row[i + len] == row[i] {
                len += 1;
            }
            buf.push(0x80 | (len - 1) as u8);
            buf.extend_from_slice(&row[i][..n]);
            i += len;
        } else {
            let mut j = i;
            while j < w && j - i < 128 && !(j + 1 < w && row[j] == row[j + 1]) {
                j += 1;
            }
            buf.push((j - i - 1) as u8);
            row[i..j]
                .iter()
                .for_each(|p| buf.extend_from_slice(&p[..n]));
            i = j;
        }
    }
}

/// The 495-byte TGA 2.0 extension area: software, gamma as POV-Ray records it (the ratio
/// gamma·6553 / 6553, truncated), attributes type 3 when the alpha channel holds real data.
fn extension_area(buf: &mut Vec<u8>, gamma: f64, alpha: bool) {
    let start = buf.len();
    buf.extend_from_slice(&495u16.to_le_bytes());
    // Author name (41), comments (4 × 81), date (6 × 2), job name (41), job time (3 × 2).
    buf.resize(start + 426, 0);
    let mut software = format!("lancer {}", env!("CARGO_PKG_VERSION")).into_bytes();
    software.resize(41, 0);
    buf.extend_from_slice(&software);
    // Software version (3), key colour (4), pixel aspect ratio (4).
    buf.resize(start + 478, 0);
    let num = (gamma * 6553.0).clamp(0.0, 65535.0) as u16;
    buf.extend_from_slice(&num.to_le_bytes());
    buf.extend_from_slice(&6553u16.to_le_bytes());
    // Colour correction, postage stamp and scan line table offsets: none.
    buf.resize(start + 494, 0);
    buf.push(if alpha { 3 } else { 0 });
}

pub(crate) fn write_bmp(plane: &Plane, mut out: impl Write) -> Result<(), String> {
    let (w, h) = (plane.width as usize, plane.height as usize);
    let n = plane.channels.min(4);
    let stride = (w * n).div_ceil(4) * 4;
    let size = stride * h;
    let total = u32::try_from(54 + size).map_err(|_| "picture too large for BMP".to_string())?;
    let mut buf = Vec::with_capacity(54 + size);
    buf.extend_from_slice(b"BM");
    buf.extend_from_slice(&total.to_le_bytes());
    buf.extend_from_slice(&0u32.to_le_bytes());
    buf.extend_from_slice(&54u32.to_le_bytes());
    buf.extend_from_slice(&40u32.to_le_bytes());
    buf.extend_from_slice(&(w as i32).to_le_bytes());
    // Positive height: rows bottom to top.
    buf.extend_from_slice(&(h as i32).to_le_bytes());
    buf.extend_from_slice(&1u16.to_le_bytes());
    buf.extend_from_slice(&(8 * n as u16).to_le_bytes());
    buf.extend_from_slice(&0u32.to_le_bytes());
    buf.extend_from_slice(&(size as u32).to_le_bytes());
    buf.extend_from_slice(&[0; 16]);
    for y in (0..h as u32).rev() {
        let row_start = buf.len();
        for x in 0..w as u32 {
            buf.extend_from_slice(&bgra(plane, x, y)[..n]);
        }
        buf.resize(row_start + stride, 0);
    }
    out.write_all(&buf).map_err(io)?;
    out.flush().map_err(io)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rle(pixels: &[u8]) -> Vec<u8> {
        let row: Vec<[u8; 4]> = pixels.iter().map(|&v| [v, v, v, 0]).collect();
        let mut buf = Vec::new();
        rle_row(&row, 3, &mut buf);
        buf
    }

    #[test]
    fn rle_packets_split_as_povray_splits_them() {
        // A pair is a run; a lone pixel between runs is a literal of one, but a lone last
        // pixel is a run of one.
        assert_eq!(
            rle(&[1, 2, 3, 3, 4, 5, 5, 6]),
            vec![1, 1, 1, 1, 2, 2, 2, 0x81, 3, 3, 3, 0, 4, 4, 4, 0x81, 5, 5, 5, 0x80, 6, 6, 6]
        );
        assert_eq!(rle(&[7, 8]), vec![1, 7, 7, 7, 8, 8, 8]);
        // Runs stop at 128.
        let long = rle(&[9; 300]);
        assert_eq!(long[0], 0xFF);
        assert_eq!(long[4], 0xFF);
        assert_eq!(long[8], 0x80 | 43);
        // Literals stop at 128 too.
        let distinct: Vec<u8> = (0..255).collect();
        let lit = rle(&distinct);
        assert_eq!(lit[0], 127);
        assert_eq!(lit[1 + 128 * 3], 126);
        assert_eq!(lit.len(), 2 + 255 * 3);
    }

    #[test]
    fn bmp_rows_are_padded_and_bottom_up() {
        let plane = Plane {
            width: 1,
            height: 2,
            channels: 3,
            bits: 8,
            data: vec![1, 2, 3, 4, 5, 6],
        };
        let mut out = Vec::new();
        write_bmp(&plane, &mut out).unwrap();
        assert_eq!(out.len(), 54 + 8);
        assert_eq!(&out[54..], &[6, 5, 4, 0, 3, 2, 1, 0]);
    }

    #[test]
    fn ppm_above_8_bits_is_big_endian() {
        let plane = Plane {
            width: 1,
            height: 1,
            channels: 3,
            bits: 12,
            data: vec![4095, 256, 1],
        };
        let mut out = Vec::new();
        write_ppm(&plane, &mut out).unwrap();
        assert_eq!(out, b"P6\n1 1\n4095\n\x0f\xff\x01\x00\x00\x01".to_vec());
    }
}
