//! The fold check's lookups (`pretrace`'s last step): whether any sample filed since a
//! pixel's phase is valid where that pixel's lookups read the cache. A pixel's lookups and
//! its neighbours' fall in the same cells of most scales, so the check keeps, per scale, the
//! last cell it read, found again by the point's floors (as `ProbeMemo` does for a probe),
//! with its list already cut to the samples from `from` on: the key, the hash probe and the
//! binary search of `from_on` are made once per cell instead of once per lookup.

use super::{floors_key, from_on, weight, within, Cache, FEW_NEW};
use crate::math::DVec3;

/// Per scale, the floors of the last cell `any_valid_memo` read (NaN: none) and its samples
/// from `from` on. Borrows the cache: valid for one filing, which it keeps from changing.
pub(in crate::render) struct FoldMemo<'c> {
    from: usize,
    cells: Vec<([f64; 3], &'c [u32])>,
}

impl Cache {
    /// An empty `FoldMemo` of this cache.
    pub(in crate::render) fn fold_memo(&self) -> FoldMemo<'_> {
        FoldMemo {
            from: 0,
            cells: Vec::new(),
        }
    }

    /// `any_valid`, the same answer: it tests the same samples (each scale's cell holding
    /// `p`, from `from` on), with the cells found through `memo`. The answer is whether one
    /// is valid, so it stops at the first, and the order of the tests does not matter.
    pub(in crate::render) fn any_valid_memo<'c>(
        &'c self,
        p: DVec3,
        n: DVec3,
        bound: f64,
        from: usize,
        memo: &mut FoldMemo<'c>,
    ) -> bool {
        let new = &self.foot[from.min(self.foot.len())..];
        if new.len() <= FEW_NEW {
            return new.iter().any(|s| weight(s, p, n, 1, bound).is_some());
        }
        debug_assert!(bound <= self.filed_bound, "grids filed for a smaller reach");
        if memo.from != from || memo.cells.len() != self.scales.len() {
            memo.from = from;
            memo.cells.clear();
            memo.cells.resize(self.scales.len(), ([f64::NAN; 3], &[]));
        }
        for (scale, cell) in self.scales.iter().zip(memo.cells.iter_mut()) {
            // As in `cells`: a scale without samples of level 1 has none of these.
            if scale.level > 1 {
                continue;
            }
            let floors = scale.floors(p);
            // Equal floors, equal key (`floors_key`); a NaN floor equals nothing.
            if cell.0 != floors {
                let ids = scale.grid1.get(&floors_key(floors));
                *cell = (floors, ids.map_or(&[][..], |ids| from_on(ids, from)));
            }
            // `within` first, as `near` asks it: at a NaN point `weight`'s own distance test
            // (`>=`, false for a NaN) lets a sample through, and its weight is a NaN.
            if cell.1.iter().any(|&i| {
                let s = &self.foot[i as usize];
                within(s, p, bound) && weight(s, p, n, 1, bound).is_some()
            }) {
                return true;
            }
        }
        false
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Cache, Sample};
    use crate::math::DVec3;

    /// `any_valid_memo` answers as `any_valid` for one memo kept across lookups that creep
    /// (most cells found again), jump, come back, meet NaN and change `from` (both sides of
    /// `FEW_NEW`, and past the end).
    #[test]
    fn fold_memo_answers_as_any_valid() {
        let mut cache = Cache::with_pool(Vec::new(), 1);
        let mut h = 3u64;
        let mut rnd = move || {
            h = super::super::super::radiosity::mix(h);
            (h >> 11) as f64 / (1u64 << 53) as f64
        };
        // Normals near +z, so that about a third of the lookups find a valid sample.
        fn tilted(rnd: &mut impl FnMut() -> f64) -> DVec3 {
            DVec3::new(0.3 * (rnd() - 0.5), 0.3 * (rnd() - 0.5), 1.0).normalize()
        }
        for i in 0..400 {
            let p = DVec3::new(rnd(), rnd(), rnd()) * 2.0;
            let n = tilted(&mut rnd);
            cache.samples.push(Sample {
                p,
                n,
                irr: DVec3::ONE,
                r: 0.1 + 0.5 * rnd(),
                level: 1 + (i % 3 == 0) as u32,
            });
        }
        let bound = 1.0;
        cache.file_new(bound, bound);
        let mut memo = cache.fold_memo();
        let mut p = DVec3::splat(1.0);
        let (mut valid, mut checked) = (0, 0);
        for k in 0..6000 {
            p = match k % 97 {
                0 => DVec3::new(rnd(), rnd(), rnd()) * 2.0,
                13 => DVec3::new(f64::NAN, 1.0, 1.0),
                14 => DVec3::splat(1.0),
                _ if p.x.is_nan() => DVec3::splat(1.0),
                _ => p + (DVec3::new(rnd(), rnd(), rnd()) - 0.5) * 0.03,
            };
            let n = tilted(&mut rnd);
            let from = [0, 150, 300, 350, 370, 399, 400, 500][(k / 500) % 8];
            let want = cache.any_valid(p, n, bound, from);
            assert_eq!(
                cache.any_valid_memo(p, n, bound, from, &mut memo),
                want,
                "{k}: {p} from {from}"
            );
            valid += want as u32;
            checked += 1;
        }
        assert!(
            valid > 500 && valid < checked - 500,
            "{valid} of {checked} valid"
        );
    }
}
