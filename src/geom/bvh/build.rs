//! Building the BVH: the binned surface-area heuristic over the primitives' boxes (clamped so
//! infinite and NaN-free arithmetic holds), splitting large subtrees in parallel, and the
//! partition that reads the bins the SAH search computed.

use std::borrow::Cow;

use crate::math::{Aabb, DVec3};

use super::*;

/// Subtrees with at least this many primitives build their two halves in parallel.
pub(super) const PARALLEL_MIN: usize = 16 * 1024;

pub(super) struct Builder<'a> {
    pub(super) bounds: &'a [Aabb],
    pub(super) clamped: Cow<'a, [Aabb]>,
    pub(super) centroids: Vec<DVec3>,
}

pub(super) fn clamp_box(b: &Aabb) -> Aabb {
    let lo = DVec3::splat(-BIG);
    let hi = DVec3::splat(BIG);
    let (min, max) = (b.min.clamp(lo, hi), b.max.clamp(lo, hi));
    // NaN survives clamp; such a box is as good as empty.
    if min.is_nan() || max.is_nan() {
        Aabb::new(DVec3::ZERO, DVec3::ZERO)
    } else {
        Aabb::new(min, max)
    }
}

/// `Aabb::union` for boxes with no NaN in them (the clamped boxes the heuristic bins; the grid
/// builder's boxes, which its callers promise hold none): where no operand is NaN,
/// `f64::min(x, y)` is `if y < x { y } else { x }` and `max` likewise (the first operand on a
/// tie of zeros), without the NaN tests' several instructions a component; this union ran
/// three times per primitive per tree level. Only the heuristic's areas come from the binned
/// boxes, and a tie between 0 and -0 (the one case where the result may differ) gives the same
/// area, so the tree is the same.
#[inline(always)]
pub(super) fn union_no_nan(a: &Aabb, b: &Aabb) -> Aabb {
    let lo = |x: f64, y: f64| if y < x { y } else { x };
    let hi = |x: f64, y: f64| if y > x { y } else { x };
    Aabb {
        min: DVec3::new(
            lo(a.min.x, b.min.x),
            lo(a.min.y, b.min.y),
            lo(a.min.z, b.min.z),
        ),
        max: DVec3::new(
            hi(a.max.x, b.max.x),
            hi(a.max.y, b.max.y),
            hi(a.max.z, b.max.z),
        ),
    }
}

pub(super) fn centroid(b: &Aabb) -> DVec3 {
    if b.is_empty() {
        DVec3::ZERO
    } else {
        b.center()
    }
}

impl Builder<'_> {
    fn leaf_or_pending(&self, prims: &[u32], first: usize) -> BinNode {
        let bounds = prims
            .iter()
            .fold(Aabb::EMPTY, |b, &p| b.union(&self.bounds[p as usize]));
        BinNode {
            bounds,
            index: first as u32,
            count: prims.len() as u32,
        }
    }

    /// Appends the subtree over `prims` (which start at `first` in the final order) to
    /// `nodes` in depth-first order; interior nodes' indices count from `nodes`' start.
    pub(super) fn node(
        &self,
        prims: &mut [u32],
        first: usize,
        depth: u32,
        nodes: &mut Vec<BinNode>,
    ) -> u32 {
        let idx = nodes.len();
        nodes.push(self.leaf_or_pending(prims, first));
        if let Some(mid) = self.split(prims, depth) {
            let (left, right) = prims.split_at_mut(mid);
            self.node(left, first, depth + 1, nodes);
            let second = self.node(right, first + mid, depth + 1, nodes);
            nodes[idx].index = second;
            nodes[idx].count = 0;
        }
        idx as u32
    }

    /// `node` for a whole subtree, appended to `nodes`, building big halves on two threads.
    /// The nodes come out exactly as the serial build lays them out: the parent, the left
    /// subtree (built in place), then the right one (built apart, then moved in with its
    /// interior indices shifted past the left's).
    pub(super) fn subtree(
        &self,
        prims: &mut [u32],
        first: usize,
        depth: u32,
        nodes: &mut Vec<BinNode>,
    ) {
        if prims.len() < PARALLEL_MIN {
            self.node(prims, first, depth, nodes);
            return;
        }
        let idx = nodes.len();
        nodes.push(self.leaf_or_pending(prims, first));
        if let Some(mid) = self.split(prims, depth) {
            let (left, right) = prims.split_at_mut(mid);
            let ((), r) = rayon::join(
                || self.subtree(left, first, depth + 1, nodes),
                || {
                    let mut r = Vec::with_capacity(2 * right.len());
                    self.subtree(right, first + mid, depth + 1, &mut r);
                    r
                },
            );
            let second = nodes.len() as u32;
            nodes[idx].index = second;
            nodes[idx].count = 0;
            nodes.extend(r.into_iter().map(|mut n| {
                if n.count == 0 {
                    n.index += second;
                }
                n
            }));
        }
    }

    /// Reorders `prims` and returns the split position, or `None` for a leaf.
    fn split(&self, prims: &mut [u32], depth: u32) -> Option<usize> {
        let n = prims.len();
        if n <= 1 {
            return None;
        }
        // The centroids hold no NaN (those of the clamped boxes, which have none), so
        // `union_no_nan` is `Aabb::grow` here, up to the sign of a zero, which changes no bin
        // (`bin_of`'s difference and the extents are the same numbers).
        let cb = prims.iter().fold(Aabb::EMPTY, |b, &p| {
            let c = self.centroids[p as usize];
            union_no_nan(&b, &Aabb { min: c, max: c })
        });
        let extent = cb.max - cb.min;
        if depth < SAH_DEPTH {
            let found = BINS_SCRATCH.with_borrow_mut(|bins| {
                let (cost, axis, bin) = self.best_sah(prims, &cb, bins)?;
                if n <= MAX_LEAF && cost >= n as f64 {
                    return Some(None);
                }
                // `partition` looks at each position once, before any swap has moved it, so
                // the bins `best_sah` stored in the original order decide as `bin_of` would.
                let mid = partition_by_bins(prims, bins, axis, bin as u8);
                (mid > 0 && mid < n).then_some(Some(mid))
            });
            if let Some(split) = found {
                return split;
            }
        }
        if n <= MAX_LEAF {
            return None;
        }
        // Median split: on the widest centroid axis, or by position when all centroids coincide.
        let mid = n / 2;
        let axis = if extent.x >= extent.y && extent.x >= extent.z {
            0
        } else if extent.y >= extent.z {
            1
        } else {
            2
        };
        if extent[axis] > 0.0 {
            prims.select_nth_unstable_by(mid, |a, b| {
                self.centroids[*a as usize][axis].total_cmp(&self.centroids[*b as usize][axis])
            });
        }
        Some(mid)
    }

    fn bin_of(&self, p: u32, axis: usize, cb: &Aabb) -> usize {
        let c = self.centroids[p as usize][axis];
        let f = (c - cb.min[axis]) / (cb.max[axis] - cb.min[axis]);
        ((f * BINS as f64) as usize).min(BINS - 1)
    }

    /// Cheapest binned split as (cost, axis, last bin of the left side); `bins` receives each
    /// primitive's bin on every live axis, in the order of `prims`.
    fn best_sah(
        &self,
        prims: &[u32],
        cb: &Aabb,
        bins: &mut Vec<[u8; 3]>,
    ) -> Option<(f64, usize, usize)> {
        // One pass over the primitives bins all three axes and takes the parent's box: each
        // primitive's data is fetched once instead of four times (the arithmetic and the
        // order of the unions are the serial passes', so the tree is the same).
        // A NaN extent is binned, as the per-axis passes did (they skipped only `<= 0`).
        let live = [0, 1, 2].map(|axis| {
            let extent = cb.max[axis] - cb.min[axis];
            extent > 0.0 || extent.is_nan()
        });
        let mut parent = Aabb::EMPTY;
        let mut all_boxes = [[Aabb::EMPTY; BINS]; 3];
        let mut all_counts = [[0usize; BINS]; 3];
        bins.clear();
        bins.reserve(prims.len());
        for &p in prims {
            let b = &self.clamped[p as usize];
            parent = union_no_nan(&parent, b);
            let mut ks = [0u8; 3];
            for axis in 0..3 {
                if live[axis] {
                    let k = self.bin_of(p, axis, cb);
                    ks[axis] = k as u8;
                    all_boxes[axis][k] = union_no_nan(&all_boxes[axis][k], b);
                    all_counts[axis][k] += 1;
                }
            }
            bins.push(ks);
        }
        let parent_area = parent.surface_area();
        if parent_area <= 0.0 || !parent_area.is_finite() {
            return None;
        }
        let mut best: Option<(f64, usize, usize)> = None;
        for axis in 0..3 {
            if !live[axis] {
                continue;
            }
            let (boxes, counts) = (&all_boxes[axis], &all_counts[axis]);
            // Right-to-left sweep stores the right side's area*count for each split position.
            let mut right_cost = [0.0; BINS];
            let (mut acc, mut cnt) = (Aabb::EMPTY, 0);
            // An empty bin (its box `EMPTY`, its count 0) leaves `acc` and `cnt` as they
            // were, so its position's numbers are the last position's: copied, not computed.
            // Small nodes fill a few of the sixteen bins, and these sweeps were most of a
            // split's cost (abyss: 71,129 splits).
            for i in (1..BINS).rev() {
                if counts[i] == 0 {
                    right_cost[i - 1] = right_cost[i];
                    continue;
                }
                acc = union_no_nan(&acc, &boxes[i]);
                cnt += counts[i];
                right_cost[i - 1] = acc.surface_area() * cnt as f64;
            }
            let (mut acc, mut cnt) = (Aabb::EMPTY, 0);
            for i in 0..BINS - 1 {
                // Past an empty bin the cost is the last position's to the bit (both sides
                // unchanged), which the strict `<` below would not take: skipped.
                if counts[i] == 0 {
                    continue;
                }
                acc = union_no_nan(&acc, &boxes[i]);
                cnt += counts[i];
                if cnt == 0 || cnt == prims.len() {
                    continue;
                }
                let cost = TRAVERSAL_COST
                    + (acc.surface_area() * cnt as f64 + right_cost[i]) / parent_area;
                if best.is_none_or(|b| cost < b.0) {
                    best = Some((cost, axis, i));
                }
            }
        }
        best
    }
}

thread_local! {
    /// `best_sah`'s bins per primitive, kept for the partition that follows it (one buffer a
    /// thread: `split` never runs inside another `split`).
    static BINS_SCRATCH: std::cell::RefCell<Vec<[u8; 3]>> = const { std::cell::RefCell::new(Vec::new()) };
}

/// In-place partition of `v` putting first the elements whose bin on `axis` (`bins[j]` for
/// the element at position `j` before the partition) is at most `last`; returns how many.
/// Position `j` is read before any swap reaches it (swaps exchange it only with positions
/// already passed), so its element is still the one `bins[j]` belongs to.
fn partition_by_bins(v: &mut [u32], bins: &[[u8; 3]], axis: usize, last: u8) -> usize {
    let mut i = 0;
    for (j, ks) in bins[..v.len()].iter().enumerate() {
        if ks[axis] <= last {
            v.swap(i, j);
            i += 1;
        }
    }
    i
}
