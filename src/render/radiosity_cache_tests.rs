//! Tests of the irradiance cache (radiosity_cache.rs): lookups find every sample in reach, the
//! memo's lookups blend as the plain ones do, and new samples are all tested.

use super::*;
use crate::render::radiosity::mix;

/// Numbers in [0, 1) from `mix` chained from `seed`.
fn unit_rng(seed: u64) -> impl FnMut() -> f64 {
    let mut h = seed;
    move || {
        h = mix(h);
        (h >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The grids filed for a lowered bound, and filed again for the final one, list every
/// sample whose reach covers a point, each once.
#[test]
fn near_finds_every_sample_in_reach() {
    let mut cache = Cache::default();
    let mut rnd = unit_rng(1);
    for i in 0..400 {
        let p = DVec3::new(rnd(), rnd(), rnd()) * 10.0;
        cache.samples.push(Sample {
            p,
            n: DVec3::Z,
            irr: DVec3::ONE,
            r: 0.05 + 2.0 * rnd() * rnd(),
            level: 1 + i % 3,
        });
    }
    // Far apart, in cells of one key (2^21 cells of 0.5 apart at coarser 0, 2^20 at 1),
    // with reaches spanning several cells.
    for j in 0..6 {
        cache.samples.push(Sample {
            p: DVec3::new(5.2 + f64::from(j) * 1048576.0, 5.1, 4.9),
            n: DVec3::Z,
            irr: DVec3::ONE,
            r: 1.9,
            level: 1,
        });
    }
    for (bound, coarser) in [(0.25, 0), (0.5, 0), (0.25, 2), (0.5, 1)] {
        if coarser != cache.coarser {
            // A new cell size: the grids are filed from scratch.
            cache.scales.clear();
            cache.filed = 0;
            cache.coarser = coarser;
        }
        cache.file_new(bound, 0.5);
        for k in 0..200 {
            let mut p = DVec3::new(rnd(), rnd(), rnd()) * 10.0;
            if k % 4 == 0 {
                p.x += f64::from(k % 3) * 1048576.0;
            }
            let from = (rnd() * 100.0) as usize;
            let mut found = Vec::new();
            cache.near(p, bound, 3, from, |i, _| found.push(i));
            let mut seen = Vec::new();
            cache.near_while(p, bound, 3, |i, _| {
                seen.push(i);
                true
            });
            seen.retain(|&i| i >= from);
            assert_eq!(seen, found, "near_while lists what near does");
            let mut want: Vec<usize> = (from..cache.samples.len())
                .filter(|&i| {
                    let s = &cache.samples[i];
                    (p - s.p).length_squared() < (s.r * bound) * (s.r * bound)
                })
                .collect();
            // A lookup of level 1 reads the cells' level-1 lists: the level-1 samples of
            // the full ones, in the same order.
            let mut ones = Vec::new();
            cache.near(p, bound, 1, from, |i, _| ones.push(i));
            let mut all = found.clone();
            all.retain(|&i| cache.samples[i].level == 1);
            assert_eq!(ones, all, "level-1 lists at {p}");
            found.sort_unstable();
            want.sort_unstable();
            assert_eq!(found, want, "bound {bound} coarser {coarser} at {p}");
        }
    }
}

/// `near_memo` blends the samples `near` lists and `weight` takes, in the same order, to
/// the bit: for runs of lookups sharing a normal (listing cells in the memo and reading
/// the lists) and lookups with a fresh normal or level between them.
#[test]
fn near_memo_blends_as_near() {
    let mut cache = Cache::with_pool(Vec::new(), 1);
    let mut rnd = unit_rng(11);
    let facings = [
        DVec3::Z,
        DVec3::X,
        -DVec3::Y,
        DVec3::new(0.6, 0.0, 0.8),
        DVec3::new(1.0, 1.0, 0.2).normalize(),
    ];
    for i in 0..500 {
        let p = DVec3::new(rnd(), rnd(), rnd()) * 6.0;
        let n = if i % 3 == 0 {
            DVec3::new(rnd() - 0.5, rnd() - 0.5, rnd() - 0.5).normalize()
        } else {
            facings[i % facings.len()]
        };
        cache.samples.push(Sample {
            p,
            n,
            irr: DVec3::new(rnd(), rnd(), rnd()),
            r: 0.05 + rnd() * rnd() * 1.5,
            level: 1 + (i % 4 == 0) as u32,
        });
    }
    let mut memo = RadiosityMemo::default();
    for (bound, last) in [(0.9, 1.8), (1.8, 1.8)] {
        cache.file_new(bound, last);
        let mut p = DVec3::new(3.0, 3.0, 3.0);
        for k in 0..3000 {
            // Runs of a few dozen lookups creeping over one facing, now and then another
            // facing or level in between.
            if k % 37 == 0 {
                p = DVec3::new(rnd(), rnd(), rnd()) * 6.0;
            }
            p += DVec3::new(rnd() - 0.5, rnd() - 0.5, rnd() - 0.5) * 0.05;
            let n = if k % 11 == 5 {
                DVec3::new(rnd() - 0.5, rnd() - 0.5, rnd() - 0.5).normalize()
            } else {
                facings[(k / 37) % facings.len()]
            };
            let level = if k % 13 == 7 { 2 } else { 1 };
            let (mut want, mut got) = (Blend::default(), Blend::default());
            cache.near(p, bound, level, 0, |i, s| {
                want.add(s, cache.irr[i], p, n, level, bound);
            });
            cache.near_memo(p, n, bound, level, &mut memo, &mut got);
            assert_eq!(got.count, want.count);
            assert_eq!(got.weight.to_bits(), want.weight.to_bits());
            assert_eq!(
                got.sum.to_array().map(f64::to_bits),
                want.sum.to_array().map(f64::to_bits)
            );
        }
    }
    let listed: usize = memo.entries.iter().map(|e| e.lists.len()).sum();
    assert!(listed > 1, "the lists were used");
}

/// `near_enough` with a thread's memo of the last cells blends what the plain walk of the
/// cells (`near_while`) blends and stops where it stops, to the bit: runs of probes creeping
/// through the same cells, jumps, NaN points, stops at an early scale (later scales' copies
/// left behind), and the grids filed again (another stamp) between runs.
#[test]
fn near_enough_memo_reads_as_the_cells() {
    let mut cache = Cache::with_pool(Vec::new(), 2);
    let mut rnd = unit_rng(23);
    let mut memo = ProbeMemo::default();
    let mut stops = 0;
    for round in 0..4 {
        for i in 0..150 {
            let p = DVec3::new(rnd(), rnd(), rnd()) * 6.0;
            let n = if i % 2 == 0 {
                DVec3::Z
            } else {
                DVec3::new(rnd() - 0.5, rnd() - 0.5, rnd() + 0.2).normalize()
            };
            cache.samples.push(Sample {
                p,
                n,
                irr: DVec3::new(rnd(), rnd(), rnd()),
                r: 0.05 + rnd() * rnd() * 2.0,
                level: 1 + (i % 5 == 0) as u32,
            });
        }
        let bound = if round % 2 == 0 { 0.9 } else { 1.8 };
        cache.file_new(bound, 1.8);
        let mut p = DVec3::new(3.0, 3.0, 3.0);
        for k in 0..1500 {
            if k % 29 == 0 {
                p = DVec3::new(rnd(), rnd(), rnd()) * 6.0;
            }
            p += DVec3::new(rnd() - 0.5, rnd() - 0.5, rnd() - 0.5) * 0.04;
            let at = if k % 97 == 13 {
                DVec3::new(f64::NAN, p.y, p.z)
            } else {
                p
            };
            let n = if k % 3 == 0 {
                DVec3::new(rnd() - 0.5, rnd() - 0.5, rnd() + 0.2).normalize()
            } else {
                DVec3::Z
            };
            let need = 1 + (k % 7) as u32;
            let mut want = Blend::default();
            let want_all = cache.near_while(at, bound, 1, |i, s| {
                want.add(s, cache.irr[i], at, n, 1, bound);
                !enough(&want, need)
            });
            let mut got = Blend::default();
            let got_all = cache.near_enough(at, n, bound, need, &mut memo, &mut got);
            assert_eq!(got_all, want_all, "stopped at the same sample");
            stops += usize::from(!got_all);
            assert_eq!(got.count, want.count);
            assert_eq!(got.weight.to_bits(), want.weight.to_bits());
            assert_eq!(
                got.sum.to_array().map(f64::to_bits),
                want.sum.to_array().map(f64::to_bits)
            );
        }
    }
    assert!(stops > 100, "probes stopped early: {stops}");
}

/// Filing again with nothing new and the same bound keeps the stamp (the threads' memos stay
/// valid) and the grids; a new sample or another bound makes a new stamp, and a memo made
/// before reads the grids afresh, finding the new sample.
#[test]
fn filing_nothing_new_keeps_the_stamp() {
    let mut cache = Cache::with_pool(Vec::new(), 1);
    let sample = |x: f64| Sample {
        p: DVec3::new(x, 0.0, 0.0),
        n: DVec3::Z,
        irr: DVec3::ONE,
        r: 1.0,
        level: 1,
    };
    cache.file_new(0.5, 1.0);
    let empty = cache.stamp;
    assert_ne!(empty, 0, "an empty cache filed has a stamp");
    cache.samples.push(sample(0.0));
    cache.file_new(0.5, 1.0);
    let one = cache.stamp;
    assert_ne!(one, empty);
    cache.file_new(0.5, 1.0);
    assert_eq!(cache.stamp, one, "nothing new");
    let mut memo = ProbeMemo::default();
    let lookup = |cache: &Cache, memo: &mut ProbeMemo| {
        let mut b = Blend::default();
        cache.near_enough(DVec3::new(0.1, 0.0, 0.0), DVec3::Z, 0.5, 9, memo, &mut b);
        b.count
    };
    assert_eq!(lookup(&cache, &mut memo), 1);
    cache.samples.push(sample(0.2));
    cache.file_new(0.5, 1.0);
    assert_ne!(cache.stamp, one, "a new sample");
    assert_eq!(
        lookup(&cache, &mut memo),
        2,
        "the memo was of the old grids"
    );
    let two = cache.stamp;
    cache.file_new(1.0, 1.0);
    assert_ne!(cache.stamp, two, "another bound");
    assert_eq!(lookup(&cache, &mut memo), 2);
}

/// The fold check's `any_valid` answers as testing every sample from `from` on would,
/// whether it tests the few new samples directly or reads the grids.
#[test]
fn any_valid_tests_every_new_sample() {
    let mut cache = Cache::with_pool(Vec::new(), 1);
    let mut rnd = unit_rng(7);
    for i in 0..300 {
        let p = DVec3::new(rnd(), rnd(), rnd()) * 4.0;
        let n = DVec3::new(rnd() - 0.5, rnd() - 0.5, 1.0).normalize();
        cache.samples.push(Sample {
            p,
            n,
            irr: DVec3::ONE,
            r: 0.05 + rnd(),
            level: 1 + i % 2,
        });
    }
    let bound = 0.5;
    cache.file_new(bound, bound);
    for k in 0..400 {
        let p = DVec3::new(rnd(), rnd(), rnd()) * 4.0;
        let n = DVec3::new(rnd() - 0.5, rnd() - 0.5, 1.0).normalize();
        // Both sides of FEW_NEW, and past the end.
        let from = [0, 100, 280, 290, 299, 300, 400][k % 7];
        let want = cache.samples[from.min(300)..]
            .iter()
            .any(|s| weight(&s.footprint(), p, n, 1, bound).is_some());
        assert_eq!(cache.any_valid(p, n, bound, from), want, "{p} from {from}");
    }
}

/// A key from the floors (`floors_key`) is `pack` of the cell's coordinates as `cell_of`
/// makes them, for points near and far, on both sides of zero, beyond the clamp, infinite
/// and NaN.
#[test]
fn floors_key_is_the_packed_cell() {
    let mut rnd = unit_rng(9);
    let scale = Scale {
        exp: 0,
        cell: 0.25,
        inv_cell: 4.0,
        level: 1,
        grid: FxHashMap::default(),
        grid1: FxHashMap::default(),
    };
    let mut specials = vec![
        0.0,
        -0.0,
        1e-300,
        -1e-300,
        0.2499999,
        -0.25,
        1e14,
        -1e14,
        2.5e14,
        -2.5e14,
        1e300,
        -1e300,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
    ];
    for _ in 0..3000 {
        let m = 10f64.powf(rnd() * 30.0 - 10.0);
        specials.push((rnd() - 0.5) * m);
    }
    for (k, &x) in specials.iter().enumerate() {
        let y = specials[(k * 7 + 3) % specials.len()];
        let z = specials[(k * 13 + 5) % specials.len()];
        let p = DVec3::new(x, y, z);
        let (cx, cy, cz) = scale.cell_of(p);
        assert_eq!(scale.key(p), pack(cx, cy, cz), "{p}");
        assert_eq!(floors_key(scale.floors(p)), pack(cx, cy, cz), "{p}");
    }
}
