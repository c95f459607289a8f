//! The irradiance cache of radiosity: the samples gathered so far, the grids over their reach
//! that lookups read (one per power-of-two scale), and Ward's weighted blend of the samples
//! valid at a point. Filled by the passes of `radiosity` (gathering, pretrace), read by
//! every shading of a diffuse surface while radiosity is on.

use std::sync::atomic::{AtomicU64, Ordering};

use rustc_hash::FxHashMap;
use smallvec::SmallVec;

use crate::math::DVec3;
use crate::scene::scratch::{MemoEntry, ProbeMemo, RadiosityMemo};

pub use crate::scene::scratch::RadiositySample as Sample;

/// The stamp of the last filing of any cache (`Cache::stamp`).
static STAMPS: AtomicU64 = AtomicU64::new(0);

impl Sample {
    pub(super) fn footprint(&self) -> Footprint {
        Footprint {
            p: self.p,
            r: self.r,
            n: self.n,
            level: self.level,
        }
    }
}

/// Where a sample is valid: what `weight` reads of it, in one aligned cache line.
#[derive(Clone, Copy)]
#[repr(C, align(64))]
pub(super) struct Footprint {
    pub(super) p: DVec3,
    pub(super) r: f64,
    pub(super) n: DVec3,
    pub(super) level: u32,
}

/// The samples gathered so far, with grids over their reach for lookups.
#[derive(Default)]
pub struct Cache {
    pub(super) samples: Vec<Sample>,
    /// What the lookups test of each filed sample, one cache line each (a `Sample` is 88
    /// bytes, two lines for most), and what they blend of it: most of the samples a cell
    /// lists are turned away by the first and never read in the second.
    foot: Vec<Footprint>,
    pub(super) irr: Vec<DVec3>,
    /// One grid per scale: samples whose reach at the final error bound is in [2^k, 2^(k+1))
    /// are filed under every cell their reach at the bound in force touches, the cells'
    /// size that reach's power of two, so a lookup reads one cell per scale and meets few
    /// samples that cannot reach it (one grid for all reaches filed each sample under tens of
    /// cells or none, and every lookup read the wide ones). The scales keep the order the
    /// final bound gives them whatever bound they are filed for: the blend's sums follow it.
    pub(super) scales: Vec<Scale>,
    /// How many of `samples` are filed in `scales`.
    filed: usize,
    /// Unique to each filing of each cache (0: never filed): what a thread's `RadiosityMemo`
    /// was taken from.
    stamp: u64,
    /// The error bound the grids are filed for: the pretrace's (lowered by
    /// `low_error_factor`) until its last pass, then the final one. Filed for the final bound
    /// throughout, a pretrace lookup met about three times the samples its own bound lets
    /// reach it (cornell: 145 read per lookup, 10 within reach; 33 read filed at its bound).
    filed_bound: f64,
    /// The cells are 2^coarser times the power of two of their scale's reach. Whatever their
    /// size, a lookup reads one cell per scale and meets the samples within reach in the
    /// same order (their number's), so this is a matter of speed only: larger cells file a
    /// sample under fewer of them (8-27 at 1, 1-8 at 2, 27-125 at 0) and give lookups more
    /// samples out of reach to turn away.
    pub(super) coarser: i32,
    /// Unit-disc points of the gathering directions (`direction_pool`).
    pub(super) pool: Vec<(f64, f64)>,
    /// Whether the CPU has AVX: lookups then read a listed cell's samples four at a time
    /// (`lanes::blend_listed`).
    lanes: bool,
    /// Rays the pretrace traced, for the statistics line.
    pub rays: u64,
    /// First-pass colours (one ray at each pixel's centre, row by row) the last completion
    /// pass lit exactly as the final trace would (`fold` in `pretrace`).
    pub first_pass: Option<super::radiosity::FirstPass>,
}

/// The samples a cell lists, in number order. Most cells list a few (stackernight, whose
/// `error_bound 0.01` files each sample under about 64 cells of its own, lists one in each of
/// its 729402 cells): held in place, as large as a `Vec`, they cost no allocation each.
pub(super) type Ids = SmallVec<[u32; 4]>;

pub(super) struct Scale {
    /// The scale's power of two at the final error bound (its identity and place in order).
    exp: i32,
    /// The size of its cells at the bound filed for, a power of two, and its inverse (exact:
    /// a coordinate times it is the coordinate divided by the size, to the bit).
    cell: f64,
    inv_cell: f64,
    /// The lowest level of its samples: a lookup of a lower level finds none valid in it
    /// and skips the scale (deeper samples reach farther, so the widest scales hold only
    /// them).
    level: u32,
    /// Cells by `pack`ed coordinates.
    pub(super) grid: FxHashMap<u64, Ids>,
    /// The same cells listing only the samples of level 1, for the lookups of level 1 (camera
    /// rays), which take no deeper sample: in `grid` they met them (deeper samples are a third
    /// to half of all, filed at their own reach's scale beside those of level 1) and turned
    /// each away. The level-1 samples of a cell keep their order, so the blend's sums do.
    grid1: FxHashMap<u64, Ids>,
}

impl Scale {
    fn cell_of(&self, p: DVec3) -> (i64, i64, i64) {
        let k = |v: f64| (v * self.inv_cell).floor().clamp(-1e15, 1e15) as i64;
        (k(p.x), k(p.y), k(p.z))
    }

    /// `pack(cell_of(p))`, by `floors_key`.
    #[cfg(test)]
    fn key(&self, p: DVec3) -> u64 {
        floors_key(self.floors(p))
    }

    /// `cell_of` before its clamp and conversion: equal floors give equal keys (`floors_key`),
    /// and a memo asks them first (the conversion's saturation took most of a scale's visit).
    #[inline(always)]
    fn floors(&self, p: DVec3) -> [f64; 3] {
        [p.x, p.y, p.z].map(|v| (v * self.inv_cell).floor())
    }

    /// `floors` in sub-cells, `SPLIT` to a cell's side (the point lies in
    /// [f·sub, (f + 1)·sub) on each axis, `sub` the cell's size over `SPLIT`: both powers of
    /// two, so the products are exact). Equal sub-floors, equal floors.
    #[inline(always)]
    fn sub_floors(&self, p: DVec3) -> [f64; 3] {
        let inv = self.inv_cell * SPLIT;
        [p.x, p.y, p.z].map(|v| (v * inv).floor())
    }
}

/// Sub-cells to a cell's side for the copies of a cell's list that lookups reading whole cells
/// keep (`sift::sift`, `Cache::sub_cell`): a sample is filed under every cell its reach touches, and a point of
/// the cell is in reach of a few in ten of them (radiosity2: 84 % out of reach).
const SPLIT: f64 = 4.0;

/// `pack` of `cell_of`'s coordinates from their `floors`, to the bit. The clamped floor
/// is a whole number below 2^51 in size, so adding 1.5 * 2^52 to it is exact and leaves it
/// in the low bits as two's complement plus 2^51, whose low 21 bits are `as i64`'s: `pack`
/// keeps only those. This instead of the saturating conversion, whose range checks were
/// half of a key's instructions; a NaN is 0, as `as i64` makes it.
#[inline(always)]
fn floors_key(f: [f64; 3]) -> u64 {
    const WHOLE: f64 = 6_755_399_441_055_744.0;
    let k = |v: f64| {
        let c = v.clamp(-1e15, 1e15);
        if c.is_nan() {
            0
        } else {
            (c + WHOLE).to_bits()
        }
    };
    pack_bits(k(f[0]), k(f[1]), k(f[2]))
}

/// A cell's key: its coordinates modulo 2^21, in one word (a bucket of 32 bytes instead of
/// 48, one multiply to hash instead of three). Cells 2^21 apart share a key and so a list;
/// that only adds samples out of reach, which lookups turn away (`within`), and a sample
/// filed under two cells of one key is listed once (`file_new`), so lookups meet the same
/// samples in the same order.
#[inline(always)]
fn pack(x: i64, y: i64, z: i64) -> u64 {
    pack_bits(x as u64, y as u64, z as u64)
}

/// `pack` of three words whose low 21 bits are the coordinates'.
#[inline(always)]
fn pack_bits(x: u64, y: u64, z: u64) -> u64 {
    const M: u64 = (1 << 21) - 1;
    ((x & M) << 42) | ((y & M) << 21) | (z & M)
}

impl Cache {
    /// An empty cache gathering along the directions of `pool` (`direction_pool`), its cells
    /// `coarser` (see the field).
    pub(super) fn with_pool(pool: Vec<(f64, f64)>, coarser: i32) -> Self {
        Cache {
            pool,
            coarser,
            lanes: crate::math::has_avx(),
            ..Cache::default()
        }
    }

    /// Files the samples added since the last call under their scale's cells, for lookups at
    /// error bound `bound` (a sample reaches `r * bound`); `last` is the final error bound,
    /// which orders the scales. Samples are only ever appended, so this gives the grids a
    /// filing from scratch would; a new `bound` files every sample again.
    pub(super) fn file_new(&mut self, bound: f64, last: f64) {
        // Grids filed again as they were keep their stamp, so the threads' memos of them stay
        // valid (the pretrace files at the start of every pass and after every phase that
        // added samples: its last passes mostly add none).
        if self.stamp != 0 && bound == self.filed_bound && self.filed == self.samples.len() {
            return;
        }
        for s in &self.samples[self.foot.len()..] {
            self.foot.push(s.footprint());
            self.irr.push(s.irr);
        }
        if bound != self.filed_bound {
            for scale in &mut self.scales {
                scale.grid.clear();
                scale.grid1.clear();
            }
            self.filed = 0;
            self.filed_bound = bound;
        }
        // Cells of the scale's power of two at `bound` (between a quarter of the reach and
        // the reach, as they were at the final bound: the ratio of the bounds is a power of
        // two for the default `low_error_factor`, 0.5), times 2^coarser.
        let shift = (bound / last).log2().floor().clamp(-60.0, 60.0) as i32 + self.coarser;
        for i in self.filed..self.samples.len() {
            let s = &self.samples[i];
            let e = (s.r * last).max(1e-9).log2().floor().clamp(-200.0, 200.0) as i32;
            let rr = (s.r * bound).max(1e-9);
            let at = match self.scales.iter().position(|g| g.exp == e) {
                Some(at) => at,
                None => {
                    self.scales.push(Scale {
                        exp: e,
                        cell: 0.0,
                        inv_cell: 0.0,
                        level: u32::MAX,
                        grid: FxHashMap::default(),
                        grid1: FxHashMap::default(),
                    });
                    self.scales.len() - 1
                }
            };
            let scale = &mut self.scales[at];
            scale.cell = 2f64.powi(e + shift);
            scale.inv_cell = 1.0 / scale.cell;
            scale.level = scale.level.min(s.level);
            let lo = scale.cell_of(s.p - DVec3::splat(rr));
            let hi = scale.cell_of(s.p + DVec3::splat(rr));
            for x in lo.0..=hi.0 {
                for y in lo.1..=hi.1 {
                    for z in lo.2..=hi.2 {
                        let key = pack(x, y, z);
                        let ids = scale.grid.entry(key).or_default();
                        // Listed already under a cell of the same key.
                        if ids.last() != Some(&(i as u32)) {
                            ids.push(i as u32);
                        }
                        if s.level == 1 {
                            let ids = scale.grid1.entry(key).or_default();
                            if ids.last() != Some(&(i as u32)) {
                                ids.push(i as u32);
                            }
                        }
                    }
                }
            }
        }
        self.filed = self.samples.len();
        self.stamp = STAMPS.fetch_add(1, Ordering::Relaxed) + 1;
    }

    /// Every sample from number `from` on whose reach at error bound `bound` covers `p`
    /// (`weight`'s distance test), each once, in the order of the scales and of their cells'
    /// lists (the blend's sums depend on it), leaving out scales holding no sample of level
    /// `level` or less (none of which `weight` takes). What the lookups read, for the tests.
    #[cfg(test)]
    pub(super) fn near(
        &self,
        p: DVec3,
        bound: f64,
        level: u32,
        from: usize,
        mut f: impl FnMut(usize, &Footprint),
    ) {
        let mut found: [&[u32]; GROUP] = [&[]; GROUP];
        for group in self.scales.chunks(GROUP) {
            self.cells(group, p, bound, level, &mut found);
            for ids in &found[..group.len()] {
                for &i in from_on(ids, from) {
                    let s = &self.foot[i as usize];
                    if within(s, p, bound) {
                        f(i as usize, s);
                    }
                }
            }
        }
    }

    /// Blends into `b` the samples `weight` takes at (p, n) for a lookup of `level`: `near`
    /// from the first sample on for a lookup facing `n`, leaving out besides samples
    /// that `weight` turns away whatever the point: of a level above `level`, or facing more
    /// than 60° from `n`. `memo` (the thread's) keeps per normal the cells read, each listed
    /// (the first time a lookup facing that way reads it, from the normal's second lookup on:
    /// see the probation entry below) with the samples that pass those two tests; lookups
    /// after it read the list, whenever they come back to the cell.
    /// Neighbouring pixels of a flat surface share their normal to the bit and their cells at
    /// every scale, and in a room about half of what a cell lists faces away (rad15's
    /// counts). Another normal taking an entry raises its epoch and drops its lists. (rad16
    /// listed a cell only when read twice in a row and kept one cell per scale: a cell left
    /// and come back to, as the next row of a floor does, was read whole again; listing a
    /// cell costs about what reading it whole does, the list's place and a map's insert.)
    /// The samples are blended in the order `near` gives them, so the blend's sums are the
    /// same to the bit. A sample of a list keeps its `normal_err` for this normal (the same
    /// bits for every lookup reading the list), which stands for `weight`'s level and normal
    /// tests and its first square root, and what else `weight` computes from the sample with
    /// the entry's normal and bound alone (`ListedQuad`); a list is kept four samples to a
    /// quad, field by field, and read a quad at a time where the CPU has AVX (`lanes`).
    #[inline]
    pub(super) fn near_memo(
        &self,
        p: DVec3,
        n: DVec3,
        bound: f64,
        level: u32,
        memo: &mut RadiosityMemo,
        b: &mut Blend,
    ) {
        let facing = [n.x.to_bits(), n.y.to_bits(), n.z.to_bits()];
        let RadiosityMemo { entries, whole } = memo;
        if entries.len() != MEMO_WAYS + 1 {
            entries.resize_with(MEMO_WAYS + 1, Default::default);
        }
        let hash = (facing[0] ^ facing[1].rotate_left(21) ^ facing[2].rotate_left(42))
            .wrapping_mul(0x9e37_79b9_7f4a_7c15);
        let slot = (hash >> 32) as usize & (MEMO_WAYS - 1);
        let holds = |e: &MemoEntry| {
            e.stamp == self.stamp && e.n == facing && e.level == level && e.bound == bound.to_bits()
        };
        // A normal no entry holds takes the last one, which lists nothing (a curved surface's
        // normals never come back); when its next lookup faces the same way it swaps into its
        // own entry, whose lists go. The normals of a room keep their lists through the
        // curved surfaces met between them. Lookups of deeper levels (the gathering rays'
        // hits, scattered over the scene) always take the probation entry and list nothing:
        // listing their cells cost more than reading the lists back saved (cornell, irr27:
        // 0.911 of the time by interleaved medians).
        let (ways, probation) = entries.split_at_mut(MEMO_WAYS);
        let probation = &mut probation[0];
        let fresh = if level == 1 && holds(&ways[slot]) {
            false
        } else if level == 1 && holds(probation) {
            std::mem::swap(&mut ways[slot], probation);
            false
        } else {
            probation.stamp = self.stamp;
            probation.n = facing;
            probation.level = level;
            probation.bound = bound.to_bits();
            probation.epoch += 1;
            // Emptied only when it holds something: clearing a map writes all its buckets.
            if !probation.lists.is_empty() {
                probation.lists.clear();
            }
            probation.listed.clear();
            true
        };
        if fresh && level == 1 {
            // A curved surface's camera rays: each scale's sub-cell from the thread's copy
            // (`sub_cell`), read whole in the scales' order, as below.
            self.sub_memo(whole, bound);
            for (scale, c) in self.scales.iter().zip(whole.cells.iter_mut()) {
                if scale.level > level {
                    continue;
                }
                self.sub_cell(scale, p, bound, c);
                lanes::blend_whole(self, &c.ids, (p, n), level, bound, b);
            }
            return;
        }
        let memo = if fresh { probation } else { &mut ways[slot] };
        if memo.cells.len() != self.scales.len() {
            memo.cells.resize_with(self.scales.len(), Default::default);
        }
        let epoch = memo.epoch;
        let MemoEntry {
            cells: memo_cells,
            lists,
            listed,
            ..
        } = memo;
        // Per scale of a group: the memo's list (`None`), or the cell to read, and whether to
        // list it.
        let mut found: [Option<&[u32]>; GROUP] = [None; GROUP];
        let mut list = [false; GROUP];
        for (g, group) in self.scales.chunks(GROUP).enumerate() {
            let cells = &mut memo_cells[g * GROUP..g * GROUP + group.len()];
            // As in `cells`: every cell is found before any is read.
            for (j, (scale, c)) in group.iter().zip(cells.iter_mut()).enumerate() {
                found[j] = Some(&[]);
                list[j] = false;
                if scale.level > level {
                    continue;
                }
                // The cell the last lookup read, by its floors (a NaN never equal: then by
                // the key below, whose list is found in `lists`). Its key is theirs.
                let floors = scale.floors(p);
                if c.epoch == epoch && c.floors == floors {
                    // Listed then.
                    prefetch(listed.as_ptr().wrapping_add(c.at.0 as usize));
                    found[j] = None;
                    continue;
                }
                let key = floors_key(floors);
                let grid = if level == 1 {
                    &scale.grid1
                } else {
                    &scale.grid
                };
                if fresh {
                    if let Some(ids) = grid.get(&key) {
                        prefetch(ids.as_ptr());
                        found[j] = Some(ids.as_slice());
                    }
                    continue;
                }
                c.key = key;
                c.floors = floors;
                c.epoch = epoch;
                // A cell listed before in this epoch, left since.
                if let Some(&at) = lists.get(&((g * GROUP + j) as u32, key)) {
                    prefetch(listed.as_ptr().wrapping_add(at.0 as usize));
                    c.at = at;
                    found[j] = None;
                    continue;
                }
                if let Some(ids) = grid.get(&key) {
                    prefetch(ids.as_ptr());
                    found[j] = Some(ids.as_slice());
                }
                // Listed once the whole cell has been read, while the entry's lists are few
                // enough: past that, read whole like a fresh normal's (the same samples in
                // the same order), and never taken for listed (no epoch is 0).
                if lists.len() < MEMO_CELLS && listed.len() < MEMO_QUADS {
                    list[j] = true;
                } else {
                    c.epoch = 0;
                }
            }
            for (j, c) in cells.iter_mut().enumerate() {
                match found[j] {
                    // An empty list (rad_def_test_37: 178 k of 413 k reads) costs no call.
                    None if c.at.1 == 0 => {}
                    None => {
                        let (at, len) = (c.at.0 as usize, c.at.1 as usize);
                        lanes::blend_listed(self, &listed[at..at + len], p, bound, b);
                    }
                    Some(ids) if list[j] => {
                        let start = listed.len();
                        let mut list = lanes::Listing {
                            quads: listed,
                            len: 0,
                        };
                        lanes::list_cell(self, ids, (p, n), level, bound, &mut list, b);
                        c.at = (start as u32, (listed.len() - start) as u32);
                        lists.insert(((g * GROUP + j) as u32, c.key), c.at);
                    }
                    Some(ids) => lanes::blend_whole(self, ids, (p, n), level, bound, b),
                }
            }
        }
    }

    /// Whether `need` samples of level 1 are valid at (p, n) at error bound `bound`, with some
    /// weight (`enough`): blends into `b` the samples `weight` takes in `near`'s
    /// order, stopping at the one that makes them enough (then false). `memo` (the thread's)
    /// keeps per scale the last cell read, found again by the floors of the point's
    /// coordinates (equal floors, equal key: `floors_key`): a probe then makes no key and asks
    /// no grid for the cells its neighbour read (rad_def_test_37: most of them), and reads the
    /// same list in the same order from the copy. A scale's cell is found only when the probe
    /// gets to it (stopped at an earlier one, the copies of later scales stay as they were).
    #[inline]
    pub(super) fn near_enough(
        &self,
        p: DVec3,
        n: DVec3,
        bound: f64,
        need: u32,
        memo: &mut ProbeMemo,
        b: &mut Blend,
    ) -> bool {
        debug_assert!(bound <= self.filed_bound, "grids filed for a smaller reach");
        if memo.stamp != self.stamp {
            memo.stamp = self.stamp;
            for c in &mut memo.cells {
                c.floors = [f64::NAN; 3];
            }
        }
        if memo.cells.len() < self.scales.len() {
            memo.cells.resize_with(self.scales.len(), Default::default);
        }
        for (scale, c) in self.scales.iter().zip(memo.cells.iter_mut()) {
            if scale.level > 1 {
                continue;
            }
            let floors = scale.floors(p);
            // A NaN is equal to nothing: a point or a memo cell with one asks the grid.
            if c.floors != floors {
                c.floors = floors;
                c.ids.clear();
                if let Some(ids) = scale.grid1.get(&floors_key(floors)) {
                    c.ids.extend_from_slice(ids);
                }
            }
            if !lanes::blend_until(self, &c.ids, (p, n), bound, need, b) {
                return false;
            }
        }
        true
    }

    /// `near` from the first sample on, stopping as soon as `f` returns false (then false):
    /// what `near_enough` reads, for the tests.
    #[cfg(test)]
    pub(super) fn near_while(
        &self,
        p: DVec3,
        bound: f64,
        level: u32,
        mut f: impl FnMut(usize, &Footprint) -> bool,
    ) -> bool {
        let mut found: [&[u32]; GROUP] = [&[]; GROUP];
        for group in self.scales.chunks(GROUP) {
            self.cells(group, p, bound, level, &mut found);
            for ids in &found[..group.len()] {
                for &i in ids.iter() {
                    let s = &self.foot[i as usize];
                    if within(s, p, bound) && !f(i as usize, s) {
                        return false;
                    }
                }
            }
        }
        true
    }

    /// Into `found`, the cell holding `p` of each scale of `group` (of `scales`, at most
    /// `GROUP`), empty for a scale without one or holding no sample of level `level` or less. The cells are
    /// all found first, then read: each is a cache miss (the grids are megabytes), and asked
    /// one after another the misses overlap instead of each waiting on the scan of the
    /// scale before (cornell: the lookup's share of the time 29% -> 23%).
    #[cfg(test)]
    fn cells<'s>(
        &'s self,
        group: &'s [Scale],
        p: DVec3,
        bound: f64,
        level: u32,
        found: &mut [&'s [u32]; GROUP],
    ) {
        debug_assert!(bound <= self.filed_bound, "grids filed for a smaller reach");
        for (scale, found) in group.iter().zip(found.iter_mut()) {
            *found = &[];
            if scale.level > level {
                continue;
            }
            let grid = if level == 1 {
                &scale.grid1
            } else {
                &scale.grid
            };
            if let Some(ids) = grid.get(&scale.key(p)) {
                prefetch(ids.as_ptr());
                *found = ids.as_slice();
            }
        }
    }

    /// Whether some sample from number `from` on is valid at (p, n) for a lookup of level 1
    /// at error bound `bound` (the fold check in `pretrace`). The few samples a last pass
    /// adds (none at all in most small scenes) are tested directly, not through the grids:
    /// which of them are asked, and in what order, does not change whether one is valid.
    /// The check itself asks `any_valid_memo` (radiosity_fold.rs); this is its reference.
    #[cfg(test)]
    pub(super) fn any_valid(&self, p: DVec3, n: DVec3, bound: f64, from: usize) -> bool {
        let new = &self.foot[from.min(self.foot.len())..];
        if new.len() <= FEW_NEW {
            return new.iter().any(|s| weight(s, p, n, 1, bound).is_some());
        }
        let mut valid = false;
        self.near(p, bound, 1, from, |_, s| {
            valid |= weight(s, p, n, 1, bound).is_some();
        });
        valid
    }

    pub fn len(&self) -> usize {
        self.samples.len()
    }

    pub fn is_empty(&self) -> bool {
        self.samples.is_empty()
    }
}

/// Up to this many new samples `any_valid` tests one by one rather than through the grids
/// (a hash probe per scale each).
const FEW_NEW: usize = 32;

/// Scales whose cells a lookup finds before reading any.
const GROUP: usize = 24;

/// Normals a thread's `RadiosityMemo` keeps cells for (a power of two).
const MEMO_WAYS: usize = 4;

/// The most cells, and quads of samples, a `MemoEntry` lists in an epoch: a lit pass of a
/// floor at 320x240 listed some hundred thousand, whose maps' growth by doubling (each a
/// fresh allocation, each page's first touch a fault) took ~9 % of radiosity3's time.
const MEMO_CELLS: usize = 8192;
const MEMO_QUADS: usize = 4096;

/// The ids of a cell's list from number `from` on (a cell lists its samples in the order
/// they were filed, which is their number's).
#[inline(always)]
fn from_on(ids: &[u32], from: usize) -> &[u32] {
    if from > 0 {
        &ids[ids.partition_point(|&i| (i as usize) < from)..]
    } else {
        ids
    }
}

/// Whether sample `s` reaches `p` at error bound `bound`: `weight`'s distance test (the same
/// arithmetic, so the same samples pass).
#[inline(always)]
fn within(s: &Footprint, p: DVec3, bound: f64) -> bool {
    let far = s.r * bound;
    (p - s.p).length_squared() < far * far
}

/// Asks for the cache line at `p` ahead of its use (no effect on the result).
#[inline(always)]
fn prefetch<T>(p: *const T) {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: a prefetch is only a hint; it reads nothing and cannot fault.
    unsafe {
        std::arch::x86_64::_mm_prefetch(p as *const i8, std::arch::x86_64::_MM_HINT_T0);
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = p;
}

/// Ward's interpolation of the samples valid at (p, n): weighted sum and count.
#[derive(Default)]
pub(super) struct Blend {
    pub(super) sum: DVec3,
    pub(super) weight: f64,
    pub(super) count: u32,
}

impl Blend {
    #[inline]
    pub(super) fn add(
        &mut self,
        s: &Footprint,
        irr: DVec3,
        p: DVec3,
        n: DVec3,
        level: u32,
        bound: f64,
    ) {
        self.take(irr, weight(s, p, n, level, bound));
    }

    /// `add` for a sample of a `near_memo` list, whose level and normal passed `weight`'s
    /// tests for this lookup's normal when listed, `nerr` its `normal_err` then.
    #[inline]
    pub(super) fn add_listed(
        &mut self,
        s: &Footprint,
        irr: DVec3,
        p: DVec3,
        n: DVec3,
        bound: f64,
        nerr: f64,
    ) {
        self.take(irr, weight_listed(s, p, n, bound, nerr));
    }

    /// Counts a sample of irradiance `irr` in with its weight, where it has one.
    #[inline(always)]
    fn take(&mut self, irr: DVec3, w: Option<f64>) {
        if let Some(w) = w {
            self.sum += irr * w;
            self.weight += w;
            self.count += 1;
        }
    }
}

/// Whether a blend has the `need` samples of some weight a probe's lookup asks for
/// (`enough_here`).
#[inline(always)]
pub(super) fn enough(b: &Blend, need: u32) -> bool {
    b.count >= need && b.weight > 0.0
}

/// The weight of sample `s` in the blend at (p, n) for a lookup of `level`, None where it is
/// not valid there.
#[inline]
pub(super) fn weight(s: &Footprint, p: DVec3, n: DVec3, level: u32, bound: f64) -> Option<f64> {
    if s.level > level {
        return None;
    }
    let d = p - s.p;
    let d2 = d.length_squared();
    let far = s.r * bound;
    if d2 >= far * far {
        return None;
    }
    let cos = n.dot(s.n);
    if cos < 0.5 {
        return None;
    }
    weight_tail(s, d, d2, n, bound, || normal_err(cos))
}

/// `weight` for a sample whose level and normal are known to pass its tests for normal `n`,
/// with `nerr` its `normal_err` for `n`: the same arithmetic, so the same bits.
#[inline]
pub(super) fn weight_listed(
    s: &Footprint,
    p: DVec3,
    n: DVec3,
    bound: f64,
    nerr: f64,
) -> Option<f64> {
    let d = p - s.p;
    let d2 = d.length_squared();
    let far = s.r * bound;
    if d2 >= far * far {
        return None;
    }
    weight_tail(s, d, d2, n, bound, || nerr)
}

/// The share of a sample's error from its normal's turn from the lookup's (`cos`, their dot
/// product): the same for every lookup facing the same way.
#[inline(always)]
fn normal_err(cos: f64) -> f64 {
    2.0 * (1.0 - cos).max(0.0).sqrt()
}

/// `weight` past its level, distance and normal tests (`d` from the sample to the point,
/// `d2` its squared length); `nerr` gives `normal_err`, asked only of samples not in front.
#[inline(always)]
fn weight_tail(
    s: &Footprint,
    d: DVec3,
    d2: f64,
    n: DVec3,
    bound: f64,
    nerr: impl FnOnce() -> f64,
) -> Option<f64> {
    let dist = d2.sqrt();
    // Samples in front of the point see a different neighbourhood (Ward's test).
    if d.dot(n + s.n) * 0.5 < -0.05 * s.r {
        return None;
    }
    let err = dist / s.r + nerr();
    if err >= bound {
        return None;
    }
    // Zero at the bound, so no seam where a sample stops counting; the square root keeps
    // the weight up over most of the reach (1/err - 1/bound peaked at the sample and left
    // each sample's blotch in the picture: radiosity_37 SSIM 0.896 -> 0.907,
    // radiosity_36 0.883 -> 0.901 against povray).
    Some((1.0 - err / bound).sqrt())
}

#[path = "radiosity_lanes.rs"]
mod lanes;

#[path = "radiosity_fold.rs"]
mod fold;

#[path = "radiosity_sift.rs"]
mod sift;

#[cfg(test)]
#[path = "radiosity_cache_tests.rs"]
mod tests;
