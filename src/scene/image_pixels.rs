//! An image map's decoded pixels, kept compact: most images have few distinct colours (a
//! palette PNG has at most 256), so each pixel is an index into a table of the distinct
//! decoded `Rgbft` values. The table holds the very values a full decode gives (the same
//! code computes them), so lookups answer bit for bit what a `Vec<Rgbft>` would, while the
//! image takes 1 or 2 bytes a pixel instead of 40 and stays in the caches.

use rustc_hash::FxHashMap;

use crate::color::Rgbft;

/// More distinct colours than this and the pixels are kept whole (an index table would be
/// nearly as big as the pixels).
const MAX_TABLE: usize = 1 << 16;

#[derive(Clone, Debug)]
enum Store {
    /// Up to 256 distinct colours: one byte a pixel.
    Table8 { table: Vec<Rgbft>, idx: Vec<u8> },
    /// Up to 65536 distinct colours: two bytes a pixel.
    Table16 { table: Vec<Rgbft>, idx: Vec<u16> },
    /// Every pixel's value.
    Full(Vec<Rgbft>),
}

/// The pixels of an image, row 0 at the top; `get(i)` is pixel `i` in row-major order.
#[derive(Clone, Debug)]
pub struct ImagePixels {
    store: Store,
}

impl Default for ImagePixels {
    fn default() -> Self {
        ImagePixels {
            store: Store::Full(Vec::new()),
        }
    }
}

fn bits(c: &Rgbft) -> [u64; 5] {
    [
        c.rgb.x.to_bits(),
        c.rgb.y.to_bits(),
        c.rgb.z.to_bits(),
        c.filter.to_bits(),
        c.transmit.to_bits(),
    ]
}

impl ImagePixels {
    /// Pixels given as keys (for instance a pixel's raw file samples) and the decode of a key;
    /// `decode` is called once for each distinct key. Equal keys must decode to equal values.
    pub fn from_keys<K, I, F>(n: usize, keys: I, mut decode: F) -> ImagePixels
    where
        K: std::hash::Hash + Eq + Copy,
        I: Iterator<Item = K> + Clone,
        F: FnMut(K) -> Rgbft,
    {
        let mut seen: FxHashMap<K, u16> = FxHashMap::default();
        let mut table = Vec::new();
        let mut idx: Vec<u16> = Vec::with_capacity(n);
        // Neighbouring pixels are often alike: skip the map for a repeat of the last key.
        let mut last: Option<(K, u16)> = None;
        for k in keys.clone() {
            if let Some((lk, li)) = last {
                if lk == k {
                    idx.push(li);
                    continue;
                }
            }
            let i = match seen.get(&k) {
                Some(&i) => i,
                None => {
                    if table.len() == MAX_TABLE {
                        return ImagePixels {
                            store: Store::Full(keys.map(decode).collect()),
                        };
                    }
                    let i = table.len() as u16;
                    table.push(decode(k));
                    seen.insert(k, i);
                    i
                }
            };
            last = Some((k, i));
            idx.push(i);
        }
        Self::tabled(table, idx)
    }

    /// Pixels given as palette indices and the decode of an index; `decode` is called once
    /// for each index used, and the table holds only those (every entry is some pixel's
    /// value, as `any` needs).
    pub fn from_indices(mut idx: Vec<u8>, mut decode: impl FnMut(u8) -> Rgbft) -> ImagePixels {
        const UNSEEN: u16 = u16::MAX;
        let mut slot = [UNSEEN; 256];
        let mut table = Vec::new();
        for i in idx.iter_mut() {
            let s = &mut slot[*i as usize];
            if *s == UNSEEN {
                *s = table.len() as u16;
                table.push(decode(*i));
            }
            // At most 256 entries: every slot fits a byte.
            *i = *s as u8;
        }
        ImagePixels {
            store: Store::Table8 { table, idx },
        }
    }

    /// Compacts whole pixels (distinct by their bits).
    pub fn from_vec(v: Vec<Rgbft>) -> ImagePixels {
        let mut seen: FxHashMap<[u64; 5], u16> = FxHashMap::default();
        let mut table = Vec::new();
        let mut idx: Vec<u16> = Vec::with_capacity(v.len());
        for c in &v {
            let i = match seen.get(&bits(c)) {
                Some(&i) => i,
                None => {
                    if table.len() == MAX_TABLE {
                        return ImagePixels {
                            store: Store::Full(v),
                        };
                    }
                    let i = table.len() as u16;
                    table.push(*c);
                    seen.insert(bits(c), i);
                    i
                }
            };
            idx.push(i);
        }
        Self::tabled(table, idx)
    }

    fn tabled(table: Vec<Rgbft>, idx: Vec<u16>) -> ImagePixels {
        let store = if table.len() <= 256 {
            Store::Table8 {
                table,
                idx: idx.into_iter().map(|i| i as u8).collect(),
            }
        } else {
            Store::Table16 { table, idx }
        };
        ImagePixels { store }
    }

    /// Pixel `i` (row-major, row 0 at the top).
    #[inline]
    pub fn get(&self, i: usize) -> Rgbft {
        match &self.store {
            Store::Table8 { table, idx } => table[idx[i] as usize],
            Store::Table16 { table, idx } => table[idx[i] as usize],
            Store::Full(v) => v[i],
        }
    }

    pub fn len(&self) -> usize {
        match &self.store {
            Store::Table8 { idx, .. } => idx.len(),
            Store::Table16 { idx, .. } => idx.len(),
            Store::Full(v) => v.len(),
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Every pixel, row-major.
    pub fn to_vec(&self) -> Vec<Rgbft> {
        (0..self.len()).map(|i| self.get(i)).collect()
    }

    /// Replaces every pixel's value by `f` of it (a function of the value alone, so a table's
    /// entries can be mapped in place of the pixels).
    pub fn map_values(&mut self, mut f: impl FnMut(&mut Rgbft)) {
        match &mut self.store {
            Store::Table8 { table, .. } | Store::Table16 { table, .. } => {
                table.iter_mut().for_each(f)
            }
            Store::Full(v) => v.iter_mut().for_each(&mut f),
        }
    }

    /// Whether some pixel's value satisfies `f`.
    pub fn any(&self, f: impl FnMut(&Rgbft) -> bool) -> bool {
        // Every table entry is some pixel's value.
        match &self.store {
            Store::Table8 { table, .. } | Store::Table16 { table, .. } => table.iter().any(f),
            Store::Full(v) => v.iter().any(f),
        }
    }

    /// Bytes the pixels take (for reports and tests).
    pub fn heap_bytes(&self) -> usize {
        let rgbft = std::mem::size_of::<Rgbft>();
        match &self.store {
            Store::Table8 { table, idx } => table.len() * rgbft + idx.len(),
            Store::Table16 { table, idx } => table.len() * rgbft + idx.len() * 2,
            Store::Full(v) => v.len() * rgbft,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grey(v: f64) -> Rgbft {
        Rgbft::new(v, v, v, 0.0, 0.0)
    }

    #[test]
    fn tabled_pixels_read_back_as_given() {
        let v: Vec<Rgbft> = (0..1000).map(|i| grey((i % 7) as f64 / 7.0)).collect();
        let p = ImagePixels::from_vec(v.clone());
        assert_eq!(p.len(), 1000);
        assert_eq!(p.heap_bytes(), 1000 + 7 * 40);
        assert_eq!(p.to_vec(), v);
    }

    #[test]
    fn many_colours_use_wider_indices_or_whole_pixels() {
        let v: Vec<Rgbft> = (0..70000).map(|i| grey(i as f64)).collect();
        let p = ImagePixels::from_vec(v.clone());
        assert_eq!(p.to_vec(), v);
        let v: Vec<Rgbft> = (0..3000).map(|i| grey(i as f64)).collect();
        let p = ImagePixels::from_keys(v.len(), 0..3000u32, |k| grey(k as f64));
        assert_eq!(p.heap_bytes(), 3000 * 40 + 3000 * 2);
        assert_eq!(p.to_vec(), v);
    }

    #[test]
    fn indexed_pixels_read_back_as_their_keys_decode() {
        let keys: Vec<u8> = (0..5000u32).map(|i| ((i * 37) % 251) as u8).collect();
        let decode = |k: u8| grey(k as f64 / 3.0);
        let by_key = ImagePixels::from_keys(keys.len(), keys.iter().copied(), decode);
        let by_index = ImagePixels::from_indices(keys.clone(), decode);
        assert_eq!(by_index.len(), keys.len());
        assert_eq!(by_index.to_vec(), by_key.to_vec());
        assert_eq!(by_index.heap_bytes(), by_key.heap_bytes());
        let empty = ImagePixels::from_indices(Vec::new(), decode);
        assert!(empty.is_empty() && !empty.any(|_| true));
        let all: Vec<u8> = (0..=255u8).rev().collect();
        let p = ImagePixels::from_indices(all.clone(), decode);
        assert_eq!(
            p.to_vec(),
            all.iter().map(|&k| decode(k)).collect::<Vec<_>>()
        );
    }

    #[test]
    fn mapping_values_maps_every_pixel() {
        let v: Vec<Rgbft> = (0..100).map(|i| grey((i % 3) as f64)).collect();
        let mut p = ImagePixels::from_vec(v.clone());
        p.map_values(|c| c.transmit = 0.5);
        assert!(p.to_vec().iter().all(|c| c.transmit == 0.5));
        assert!(p.any(|c| c.rgb.x == 2.0));
    }
}
