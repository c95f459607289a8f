//! A GIF decoder that keeps palette indices: height fields take a GIF's index as the height,
//! and Fractint's POT files (GIFs twice as wide, holding 16-bit heights) need the raw indices
//! too. Only the first image of the file is read; the `image` crate is built without GIF.
//! Rows stay in file order even in interlaced images, as povray reads them.

/// A GIF's first image as palette indices, row 0 at the top.
pub struct Indexed {
    pub width: usize,
    pub height: usize,
    pub pixels: Vec<u8>,
}

struct Bytes<'a> {
    data: &'a [u8],
    pos: usize,
}

impl Bytes<'_> {
    fn take(&mut self, n: usize) -> Result<&[u8], String> {
        let end = self.pos.checked_add(n).filter(|&e| e <= self.data.len());
        let Some(end) = end else {
            return Err("the GIF file ends early".into());
        };
        let s = &self.data[self.pos..end];
        self.pos = end;
        Ok(s)
    }
    fn u8(&mut self) -> Result<u8, String> {
        Ok(self.take(1)?[0])
    }
    fn u16(&mut self) -> Result<usize, String> {
        let b = self.take(2)?;
        Ok(u16::from_le_bytes([b[0], b[1]]) as usize)
    }
    /// Concatenated data sub-blocks up to the empty block.
    fn sub_blocks(&mut self) -> Result<Vec<u8>, String> {
        let mut out = Vec::new();
        loop {
            let n = self.u8()? as usize;
            if n == 0 {
                return Ok(out);
            }
            out.extend_from_slice(self.take(n)?);
        }
    }
}

/// Decodes the first image; `max_pixels` guards against absurd sizes.
pub fn decode(data: &[u8], max_pixels: u64) -> Result<Indexed, String> {
    let mut b = Bytes { data, pos: 0 };
    let sig = b.take(6)?;
    if sig != b"GIF87a" && sig != b"GIF89a" {
        return Err("not a GIF file".into());
    }
    b.take(4)?; // logical screen size
    let flags = b.u8()?;
    b.take(2)?; // background colour, aspect
    if flags & 0x80 != 0 {
        b.take(3 << ((flags & 7) + 1))?;
    }
    loop {
        match b.u8()? {
            0x21 => {
                b.u8()?; // extension label
                b.sub_blocks()?;
            }
            0x2C => break,
            0x3B => return Err("the GIF file holds no image".into()),
            x => return Err(format!("unexpected byte {x:#04x} in the GIF file")),
        }
    }
    b.take(4)?; // image position
    let (w, h) = (b.u16()?, b.u16()?);
    if w == 0 || h == 0 || (w as u64) * (h as u64) > max_pixels {
        return Err(format!("the GIF image is {w}×{h}"));
    }
    let flags = b.u8()?;
    if flags & 0x80 != 0 {
        b.take(3 << ((flags & 7) + 1))?;
    }
    let min_size = b.u8()? as u32;
    if !(1..=11).contains(&min_size) {
        return Err(format!("bad LZW code size {min_size} in the GIF file"));
    }
    let codes = b.sub_blocks()?;
    let mut out = lzw(&codes, min_size, w * h);
    out.resize(w * h, 0);
    // Interlaced images keep their rows in file order (every 8th row first, ...): povray
    // reads them so (measured with `trace` on an interlaced GIF), so lancer does too.
    Ok(Indexed {
        width: w,
        height: h,
        pixels: out,
    })
}

/// Variable-width LZW as GIF uses it; stops at the end code, at `limit` pixels or at bad data.
fn lzw(data: &[u8], min_size: u32, limit: usize) -> Vec<u8> {
    let clear = 1usize << min_size;
    let end = clear + 1;
    // Each code: (prefix code, last byte, length).
    let mut table: Vec<(usize, u8, usize)> = Vec::with_capacity(4096);
    let reset = |t: &mut Vec<(usize, u8, usize)>| {
        t.clear();
        t.extend((0..clear).map(|i| (usize::MAX, i as u8, 1)));
        t.push((usize::MAX, 0, 0));
        t.push((usize::MAX, 0, 0));
    };
    reset(&mut table);
    let mut size = min_size + 1;
    let mut out = Vec::with_capacity(limit);
    let (mut acc, mut nbits, mut pos) = (0u32, 0u32, 0usize);
    let mut prev: Option<usize> = None;
    let mut scratch = Vec::new();
    while out.len() < limit {
        while nbits < size {
            let Some(&byte) = data.get(pos) else {
                return out;
            };
            acc |= (byte as u32) << nbits;
            nbits += 8;
            pos += 1;
        }
        let code = (acc & ((1 << size) - 1)) as usize;
        acc >>= size;
        nbits -= size;
        if code == clear {
            reset(&mut table);
            size = min_size + 1;
            prev = None;
            continue;
        }
        if code == end {
            break;
        }
        // The string of `code`, or for the code not yet in the table, prev's string plus its
        // own first byte.
        let first_of = |t: &[(usize, u8, usize)], mut c: usize| {
            while t[c].0 != usize::MAX {
                c = t[c].0;
            }
            t[c].1
        };
        let known = code < table.len();
        let new_entry = match prev {
            Some(p) if known => Some((p, first_of(&table, code))),
            Some(p) if code == table.len() => Some((p, first_of(&table, p))),
            None if known => None,
            _ => return out,
        };
        if let Some((p, byte)) = new_entry {
            if table.len() < 4096 {
                let len = table[p].2 + 1;
                table.push((p, byte, len));
            }
        }
        scratch.clear();
        let mut c = code.min(table.len() - 1);
        loop {
            scratch.push(table[c].1);
            if table[c].0 == usize::MAX {
                break;
            }
            c = table[c].0;
        }
        out.extend(scratch.iter().rev());
        prev = Some(code);
        if table.len() == 1 << size && size < 12 {
            size += 1;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decodes_a_tiny_gif() {
        // A 3×2 GIF87a with a 4-colour palette, indices 0 1 2 / 3 0 1, min code size 2,
        // codes written by hand (clear, literals, end) at 3 bits, growing to 4 bits.
        let mut codes: Vec<(u32, u32)> = vec![(4, 3)];
        let mut size = 3;
        let mut next = 6;
        for (k, v) in [0u32, 1, 2, 3, 0, 1].into_iter().enumerate() {
            codes.push((v, size));
            if k > 0 {
                next += 1;
                if next == 1 << size {
                    size += 1;
                }
            }
        }
        codes.push((5, size));
        let (mut acc, mut n, mut bytes) = (0u64, 0, Vec::new());
        for (c, s) in codes {
            acc |= (c as u64) << n;
            n += s;
            while n >= 8 {
                bytes.push(acc as u8);
                acc >>= 8;
                n -= 8;
            }
        }
        if n > 0 {
            bytes.push(acc as u8);
        }
        let mut gif = b"GIF87a".to_vec();
        gif.extend([3, 0, 2, 0, 0x81, 0, 0]);
        gif.extend([0u8; 12]);
        gif.extend([0x2C, 0, 0, 0, 0, 3, 0, 2, 0, 0, 2, bytes.len() as u8]);
        gif.extend(&bytes);
        gif.extend([0, 0x3B]);
        let img = decode(&gif, 100).unwrap();
        assert_eq!((img.width, img.height), (3, 2));
        assert_eq!(img.pixels, vec![0, 1, 2, 3, 0, 1]);
        assert!(decode(&gif[..20], 100).is_err());
        assert!(decode(b"GIF89a", 100).is_err());
        assert!(decode(&gif, 4).is_err());
    }
}
