//! POV-Ray 3.7's radiosity: diffuse inter-reflection from an irradiance cache (Ward's method),
//! filled by a pretrace over the picture at decreasing block sizes (`pretrace_start` down to
//! `pretrace_end`) and only read by the final trace.
//!
//! Determinism for any thread count and any split of the picture (docs/radiosity.md): the
//! cache is frozen during a pass; each pretrace sample position is traced against the frozen
//! cache plus the samples that same position has gathered so far (`Scratch::rad_local`), and
//! after the pass the new samples are appended in picture order. Gathering directions come
//! from a fixed Halton pool turned by a hash of the sample's position, never from a shared
//! random stream. The pretrace always covers the whole picture, whatever window is rendered,
//! and the final trace never adds to the cache: a point it finds no sample for gets one
//! computed for that camera sample only.

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;

use rayon::prelude::*;

use crate::math::{by_coordinates, DVec3, Ray};
use crate::scene::build::Scene;
use crate::scene::desc::RadiositySettings;
use crate::scene::object::{Scratch, SurfaceHit};
use crate::scene::scratch::{ProbeMemo, RadiosityMemo, SkyKey};

use smallvec::SmallVec;

use super::radiosity_cache::Blend;
pub use super::radiosity_cache::{Cache, Sample};
use super::trace::{point_seed, Path, Seen, TraceCtx, Tracer};
use super::RenderSettings;

/// What the tracer needs to look up and gather irradiance during one pass.
#[derive(Clone, Copy)]
pub struct RadTrace<'a> {
    pub set: &'a RadiositySettings,
    pub cache: &'a Cache,
    /// The error bound in force: lowered by `low_error_factor` during the pretrace.
    pub bound: f64,
    pub pretrace: bool,
    /// A pass of `pretrace` (seeding, pretrace or completion): only the samples its camera
    /// rays gather are kept, not their colour.
    pub probe: bool,
    /// Keep the points a camera ray's lookups read the cache at (`Scratch::rad_seen`).
    pub record: bool,
    /// Unit-disc points of the direction pool (cosine-weighted hemisphere once lifted).
    pub pool: &'a [(f64, f64)],
    pub eye: DVec3,
}

fn radical_inverse(mut i: u32, base: u32) -> f64 {
    let (mut f, mut r) = (1.0, 0.0);
    while i > 0 {
        f /= base as f64;
        r += f * (i % base) as f64;
        i /= base;
    }
    r
}

/// `n` Halton points mapped to the unit disc with equal area: lifted to the hemisphere they
/// are cosine-weighted, so the plain mean of what the rays see is the irradiance.
pub fn direction_pool(n: u32) -> Vec<(f64, f64)> {
    (1..=n)
        .map(|i| {
            let u = radical_inverse(i, 2);
            let phi = std::f64::consts::TAU * radical_inverse(i, 3);
            let r = u.sqrt();
            (r * phi.cos(), r * phi.sin())
        })
        .collect()
}

pub(super) fn mix(mut h: u64) -> u64 {
    h ^= h >> 33;
    h = h.wrapping_mul(0xff51_afd7_ed55_8ccd);
    h ^= h >> 33;
    h = h.wrapping_mul(0xc4ce_b9fe_1a85_ec53);
    h ^ (h >> 33)
}

impl<'a> Tracer<'a> {
    /// `irradiance`, its answer read back one coordinate at a time (`by_coordinates`): it is
    /// returned through memory, stored as an x-y pair and z, and its callers (`shade`'s
    /// layers, into which it is too large to be inlined) read it back as x and a y-z pair, a
    /// 16-byte load spanning both stores that cannot be forwarded from them (11 % of
    /// `shade`'s samples on raddem, on the instruction after that load). The same bits.
    #[inline(always)]
    pub(super) fn indirect(
        &self,
        p: DVec3,
        n: DVec3,
        path: Path<'a>,
        ctx: &mut Scratch<'a>,
    ) -> DVec3 {
        let irr = self.irradiance(p, n, path, ctx);
        crate::math::by_coordinates(&irr)
    }

    /// The irradiance at `p` (facing `n`) for a ray at `path`: from the cache where samples are
    /// valid there, otherwise gathered afresh. Zero past `recursion_limit`.
    pub(super) fn irradiance(
        &self,
        p: DVec3,
        n: DVec3,
        path: Path<'a>,
        ctx: &mut Scratch<'a>,
    ) -> DVec3 {
        let Some(rad) = self.rad.as_ref() else {
            return DVec3::ZERO;
        };
        let level = path.rad_level + 1;
        if level > rad.set.recursion_limit {
            return DVec3::ZERO;
        }
        // The point and normal by coordinates: the caller's copies are stored as x-y pairs and
        // z, and read whole they were loaded as x and a y-z pair (`near_memo`'s key of the
        // normal, the `rad_seen` entry built from them), stalls on the store buffer.
        let (p, n) = (by_coordinates(&p), by_coordinates(&n));
        // Deeper levels take one valid sample: asking nearest_count of them there multiplies
        // the samples gathered per ray tree beyond what povray's statistics show.
        let need = if level == 1 && (rad.pretrace || rad.set.always_sample) {
            rad.set.nearest_count
        } else {
            1
        };
        if rad.probe && path.rad_level == 0 {
            // A camera ray of a pretrace pass whose colour is not kept: only whether enough
            // samples are valid here matters (it decides whether to gather).
            if let Some(e) = enough_here(rad, p, n, need, ctx) {
                return e;
            }
        } else {
            let (cache, bound) = (rad.cache, rad.bound);
            let mut b = Blend::default();
            cache.near_memo(p, n, bound, level, &mut ctx.rad_memo, &mut b);
            for s in &ctx.rad_local {
                b.add(&s.footprint(), s.irr, p, n, level, bound);
            }
            if b.count >= need && b.weight > 0.0 {
                if rad.record {
                    ctx.rad_seen.push((p, n));
                }
                return b.sum / b.weight;
            }
        }
        // The point's own lights (`ctx.lit`, from `gather_lights`) are read by its layers
        // once this returns; the gathering rays light their own hits in a list of their own.
        // (They replaced the point's: a point that gathered was lit as the last gathering
        // ray's hit, from that hit's lights and without its own shadows.)
        // The same holds for the surface `slope` and `aoi` patterns read (a thread-local set
        // by each hit's `shade`): a later layer or part of the point's texture reads it.
        let surface = crate::scene::pattern::surface_patterns_made().then(super::pattern::surface);
        let spare = ctx.lit_spare.pop().unwrap_or_default();
        let own = std::mem::replace(&mut ctx.lit, spare);
        let s = self.gather(rad, p, n, level, path, ctx);
        let spare = std::mem::replace(&mut ctx.lit, own);
        ctx.lit_spare.push(spare);
        if let Some(surface) = surface {
            super::pattern::set_surface(surface);
        }
        ctx.rad_local.push(s);
        s.irr
    }

    fn gather(
        &self,
        rad: &RadTrace<'a>,
        p: DVec3,
        n: DVec3,
        level: u32,
        path: Path<'a>,
        ctx: &mut Scratch<'a>,
    ) -> Sample {
        let set = rad.set;
        // Every sample uses the same directions in its normal's frame, as POV-Ray does: errors
        // then vary smoothly from sample to sample instead of as noise. A pool larger than
        // `count` is drawn from at an offset hashed from the position (POV-Ray's round robin
        // would depend on the order samples are taken in).
        let h = mix(point_seed(p) as u64 ^ ((level as u64) << 40));
        let start = if rad.pool.len() > set.count as usize {
            (mix(h) % rad.pool.len() as u64) as usize
        } else {
            0
        };
        // Deeper samples shoot half as many rays per level (measured: povray's statistics
        // for cornell.pov, 200 rays at depth 0 and about 100 below).
        let count = (set.count >> (level - 1).min(31)).max(1) as usize;
        // A sky that depends on the direction alone is remembered along each frame's rays.
        let sky = (!self.scene.sky.is_empty() && !crate::scene::pattern::surface_patterns_made())
            .then(|| SkyKey {
                n: [n.x.to_bits(), n.y.to_bits(), n.z.to_bits()],
                pool: rad.pool.as_ptr() as usize,
                start: start as u32,
                count: count as u32,
            });
        if let Some(key) = sky {
            ctx.rad_sky.frame(key);
        }
        let (t1, t2) = frame(n);
        let ray_path = path.gathering(level);
        let mut sum = DVec3::ZERO;
        let mut inv_dist = 0.0;
        for i in 0..count {
            let (x, y) = rad.pool[(start + i) % rad.pool.len()];
            let z = (1.0 - x * x - y * y).max(0.0).sqrt();
            let dir = t1 * x + t2 * y + n * z;
            let share = i as f64 / count as f64;
            let sky = sky.as_ref().map(|k| (k, i));
            let (mut c, t) = self.trace_gather(&Ray::new(p, dir), ray_path, share, sky, ctx);
            if set.max_sample > 0.0 {
                let m = c.max_element();
                if m > set.max_sample {
                    c *= set.max_sample / m;
                }
            }
            sum += c;
            if t.is_finite() && t > 0.0 {
                inv_dist += 1.0 / t;
            }
        }
        let mut irr = sum / count as f64;
        if set.gray_threshold > 0.0 {
            let grey = (irr.x + irr.y + irr.z) / 3.0;
            irr = irr * (1.0 - set.gray_threshold) + DVec3::splat(grey * set.gray_threshold);
        }
        irr *= set.brightness;
        let eye = (p - rad.eye).length();
        let harmonic = if inv_dist > 0.0 {
            count as f64 / inv_dist
        } else {
            f64::INFINITY
        };
        // Deeper samples reach twice as far per level, both bounds (measured: the samples
        // povray saves with +RFO for the open box, recursion_limit 3, are clamped to
        // [0.015, 0.2], [0.03, 0.4] and [0.06, 0.8] times their distance from the camera).
        let scale = f64::from(1u32 << (level - 1).min(20));
        let r = harmonic
            .min(set.maximum_reuse * scale * eye)
            .max(set.minimum_reuse * scale * eye)
            .max(1e-9);
        Sample {
            p,
            n,
            irr,
            r,
            level,
        }
    }
}

/// Whether `need` samples are valid at (p, n) for a camera ray (level 1), with some weight:
/// then a blend of those found so far (not all of them), else None. The count and the weight
/// only grow, so the lookup stops once they are enough (raddem and rad_def_test, error_bound
/// 1.8: a hundred samples within reach of a lookup). Not inlined: in `irradiance` beside the
/// full lookup it made gamma_showcase's lookups 3% slower.
#[inline(never)]
fn enough_here(rad: &RadTrace, p: DVec3, n: DVec3, need: u32, ctx: &mut Scratch) -> Option<DVec3> {
    let (cache, bound) = (rad.cache, rad.bound);
    let mut b = Blend::default();
    let enough = |b: &Blend| super::radiosity_cache::enough(b, need);
    let mut done = !cache.near_enough(p, n, bound, need, &mut ctx.rad_probe, &mut b);
    for s in &ctx.rad_local {
        if done {
            break;
        }
        b.add(&s.footprint(), s.irr, p, n, 1, bound);
        done = enough(&b);
    }
    enough(&b).then(|| b.sum / b.weight)
}

/// Two unit vectors perpendicular to `n` and to each other, fixed by `n` alone.
fn frame(n: DVec3) -> (DVec3, DVec3) {
    let a = if n.x.abs() < 0.9 { DVec3::X } else { DVec3::Y };
    let t1 = n.cross(a).normalize();
    (t1, n.cross(t1))
}

/// The block sizes of the pretrace passes, in pixels: `pretrace_start` of the picture's
/// larger side, halved until `pretrace_end` (and never below a pixel).
pub fn pretrace_blocks(set: &RadiositySettings, width: u32, height: u32) -> Vec<f64> {
    halving(set.pretrace_start, set.pretrace_end, width, height)
}

/// After the pretrace, passes that take the samples the final trace would otherwise take
/// (POV-Ray takes them while tracing, in an order that depends on the threads): from the
/// pretrace's last block size halved down to a pixel, with the final error bound.
fn completion_blocks(set: &RadiositySettings, width: u32, height: u32) -> Vec<f64> {
    let side = width.max(height) as f64;
    let mut out = halving(set.pretrace_end, 0.0, width, height);
    out.remove(0);
    if out.is_empty() && set.pretrace_end * side > 1.0 {
        out.push(1.0);
    }
    out
}

fn halving(start: f64, end: f64, width: u32, height: u32) -> Vec<f64> {
    let side = width.max(height) as f64;
    let mut b = (start * side).max(1.0);
    let end = (end.min(start) * side).max(1.0);
    let mut out = vec![b];
    while b > end * 1.0001 && out.len() < 16 {
        b = (b * 0.5).max(end);
        out.push(b);
    }
    out
}

/// What a pass traced at one position: the samples it gathered, the colour (when lit) and
/// where its lookups read the cache.
/// Inline for the one point (or none) most positions look the cache up at: a `Vec` each cost
/// an allocation per lit pixel and kept its 192 bytes until the fold check.
/// Last, the camera ray's first crossing where a later completion pass traces the same pixel
/// (its index) and did not know it yet.
type Traced<'a> = (Vec<Sample>, Seen, Looked, Option<(usize, Hit<'a>)>);
type Hit<'a> = Option<SurfaceHit<'a>>;
type Looked = SmallVec<[(DVec3, DVec3); 1]>;

/// Positions of a phase traced between takings of their results (`pretrace`): a run's results
/// stay in the caches (~200 bytes a position).
const RUN: usize = 2048;

/// The order of a pass's four interleaved phases: (column, row) parity of the block.
const PHASES: [(usize, usize); 4] = [(0, 0), (1, 1), (1, 0), (0, 1)];

/// Fills the cache for the whole picture (not only a partial render's window, so that every
/// part of a split render sees the same cache). None without radiosity, or below `+Q9`
/// (measured: povray +Q8 renders a radiosity scene as without it).
pub fn pretrace(scene: &Scene, s: &RenderSettings, base: &Tracer) -> Option<Cache> {
    let set = scene.radiosity.as_ref().filter(|_| s.quality >= 9)?;
    // Cells twice the reach's power of two where gathering rays look the cache up (`count`
    // lookups per sample: cornell +2% at four times), four times where only camera rays do
    // (radiosity2 and radiosity3 -10%, stackernight -5% against the reach's own power of
    // two, whose 27-125 cells per sample were mostly filed and never read).
    let coarser = if set.recursion_limit > 1 { 1 } else { 2 };
    let mut cache = Cache::with_pool(direction_pool(set.count_pool.max(set.count)), coarser);
    let (w, h) = (s.width as f64, s.height as f64);
    // Seeding passes at coarser blocks come first: within a pass no position sees another's
    // new samples, so the first dense pass would otherwise gather every deeper level afresh
    // at each of its positions.
    let side = s.width.max(s.height) as f64;
    let mut blocks = halving(0.5, set.pretrace_start, s.width, s.height);
    blocks.pop();
    blocks.retain(|&b| b > set.pretrace_start * side * 1.5);
    blocks.extend(pretrace_blocks(set, s.width, s.height));
    let finishing = completion_blocks(set, s.width, s.height);
    let pretrace_passes = blocks.len();
    let passes = pretrace_passes + finishing.len();
    // The last completion pass at one-pixel blocks traces the final trace's first-pass rays
    // (one at each pixel's centre, as `trace_camera_at` does without a lens or mesh camera),
    // so it lights them too. A pixel of a phase after which the pass added no sample saw the
    // cache the final trace sees, and gathered nothing of its own: its colour is the final
    // trace's, which then need not trace it again (the same bytes). AA method 2 has no first
    // pass.
    let fold = finishing.last() == Some(&1.0)
        && base.camera.mesh().is_none()
        && base.camera.lens().is_none()
        && !(s.antialias.is_some() && s.sampling_method == 2);
    let mut first = if fold {
        FirstPass::new(s.width as usize * s.height as usize)
    } else {
        FirstPass::new(0)
    };
    // The points where the pixels the last pass lit looked the cache up, to be checked once
    // it is complete (`Check`); their colours wait in `first`. Room for one a pixel from the
    // start: grown by doubling, the list's copies faulted in fresh pages (with the entries'
    // own pages, a third of rad_def_test_37's faults); pages never written are never touched.
    let mut to_check: Vec<Check> = Vec::with_capacity(first.lit.len());
    // The completion passes trace pixel centres, and every later pass traces again the
    // pixels of those before it (the last traces them all): each camera ray's first crossing
    // is found once and kept, per pixel an index into `hits` (u32::MAX: none yet). Found with
    // `base`, whose borrows are the scene's, so a crossing outlives the pass's tracer and its
    // borrow of the cache (radiosity_37: 7,500 of 29,269 camera rays, ~9,500 instructions
    // each). A crossing depends on the ray alone, and the ray on the pixel.
    let reuse = finishing.len() > 1;
    let mut hit_at: Vec<u32> = if reuse {
        vec![u32::MAX; s.width as usize * s.height as usize]
    } else {
        Vec::new()
    };
    // Room for a crossing per pixel from the start: grown by doubling, the buffer's copies
    // faulted in their pages again (`memmove` 14 % of radiosity2's faults). Pages never
    // written are never touched.
    let mut hits: Vec<Hit> = Vec::with_capacity(hit_at.len());
    let rays = AtomicU64::new(0);
    let kept = Mutex::new(Vec::new());
    // A run's results (`RUN`), and a phase's new samples until the phase is done.
    let mut traced: Vec<Traced> = Vec::with_capacity(RUN);
    let mut gathered: Vec<Sample> = Vec::new();
    // The pretrace's samples are filed for its own error bound where its gathering rays look
    // them up (`count` lookups per sample, and a third of the samples read per lookup), and
    // filed again for the final bound after it. With `recursion_limit 1` only its camera rays
    // do, a few per sample, and filing twice cost more than it saved (radiosity3 +7%).
    let filing = |bound: f64| {
        if set.recursion_limit > 1 {
            bound
        } else {
            set.error_bound.max(bound)
        }
    };
    let mut positions: Vec<(usize, usize)> = Vec::new();
    for (pass, block) in blocks.into_iter().chain(finishing).enumerate() {
        let pretrace = pass < pretrace_passes;
        let last = fold && pass + 1 == passes;
        // Pixel centres whose crossings a later pass reads.
        let keep = reuse && !pretrace && pass + 1 < passes;
        let t0 = std::time::Instant::now();
        let nx = (w / block).ceil() as usize;
        let ny = (h / block).ceil() as usize;
        let bound = if pretrace {
            set.error_bound * set.low_error_factor
        } else {
            set.error_bound
        };
        cache.file_new(filing(bound), set.error_bound);
        // Four interleaved phases, each seeing the samples of those before: a position's
        // neighbours then reuse its new samples as in POV-Ray's one-by-one pretrace, rather
        // than each gathering its own copy (cornell: 3681 first-level samples instead of
        // 4579, povray takes 3463).
        for phase in PHASES {
            let lit = last;
            // The phase's positions in row order, stepped by parity (a division and a
            // filter per position were ~12 % of `pretrace`'s own samples), into one buffer.
            positions.clear();
            for iy in (phase.1..ny).step_by(2) {
                positions.extend((phase.0..nx).step_by(2).map(|ix| (ix, iy)));
            }
            let before = cache.samples.len();
            {
                let tracer = Tracer {
                    rad: Some(RadTrace {
                        set,
                        cache: &cache,
                        bound,
                        pretrace,
                        probe: !lit,
                        record: lit,
                        pool: &cache.pool,
                        eye: base.camera.location,
                    }),
                    ..base.clone()
                };
                // In runs of `RUN` positions, each run's results taken out of one buffer
                // before the next run: a phase's results at once were a fresh allocation each
                // phase (19,200 positions of ~200 bytes at 320x240), and the first touch of
                // each of its pages cost a fault (~2 us on this machine; with them, faults
                // were ~15 % of rad_def_test_37's time). Within a phase no position sees
                // another's results, so the runs give the same.
                for run in positions.chunks(RUN) {
                    let (hit_at_now, hits_now) = (&hit_at, &hits);
                    run.par_iter()
                        .map_init(
                            || Kept::take(&kept, &rays),
                            |kept, &(ix, iy)| {
                                let (ctx, own) = (&mut kept.pair.0, &mut kept.pair.1);
                                let mut x = ((ix as f64 + 0.5) * block).min(w - 0.5);
                                let mut y = ((iy as f64 + 0.5) * block).min(h - 0.5);
                                if !pretrace {
                                    // At a pixel's centre, where the final trace looks it
                                    // up: a sample whose reach is under a pixel then serves
                                    // that pixel (povray's final-trace samples lie at pixel
                                    // centres, measured from its +RFO file) instead of none.
                                    x = x.floor() + 0.5;
                                    y = y.floor() + 0.5;
                                }
                                ctx.rad_local.clear();
                                ctx.rad_seen.clear();
                                let ray = base.camera.ray(x, y);
                                let mut found = None;
                                // By reference into the option (as `trace_pretrace`
                                // reads it): moved out, the ray was copied in 16-byte
                                // pieces straddling the camera's stores (origin.z with
                                // dir.x, dir.y-z), two store-forwarding stalls a ray.
                                let seen = match &ray {
                                    Some(ray) if reuse && !pretrace => {
                                        let at = y as usize * s.width as usize + x as usize;
                                        let hit = match hit_at_now[at] {
                                            u32::MAX => {
                                                let hit = base.camera_hit(ray, own);
                                                found = keep.then_some((at, hit));
                                                hit
                                            }
                                            k => hits_now[k as usize],
                                        };
                                        tracer.trace_pretrace_hit(ray, hit, ctx)
                                    }
                                    _ => tracer.trace_pretrace(ray, ctx),
                                };
                                // Copied out, so the scratch keeps its buffers: most
                                // positions gather nothing, and an empty `Vec` costs no
                                // allocation.
                                (
                                    ctx.rad_local.to_vec(),
                                    seen,
                                    Looked::from_slice(&ctx.rad_seen),
                                    found,
                                )
                            },
                        )
                        .collect_into_vec(&mut traced);
                    for (&(ix, iy), (v, seen, looked, found)) in run.iter().zip(traced.drain(..)) {
                        if let Some((at, hit)) = found {
                            hit_at[at] = hits.len() as u32;
                            hits.push(hit);
                        }
                        // A pixel that gathered samples of its own is traced again by the
                        // final trace.
                        if lit && v.is_empty() {
                            let at = iy * s.width as usize + ix;
                            first.set(at, seen);
                            to_check
                                .extend(looked.iter().map(|&(p, n)| Check::new(at, p, n, before)));
                        }
                        gathered.extend(v);
                    }
                }
            }
            cache.samples.append(&mut gathered);
            if cache.samples.len() > before {
                cache.file_new(filing(bound), set.error_bound);
            }
        }
        if std::env::var_os("LANCER_RAD_STATS").is_some() {
            let mut levels = [0usize; 4];
            for smp in &cache.samples {
                levels[(smp.level as usize - 1).min(3)] += 1;
            }
            let cells: usize = cache
                .scales
                .iter()
                .map(|g| g.grid.values().map(|v| v.len()).sum::<usize>())
                .sum();
            let n: usize = cache.scales.iter().map(|g| g.grid.len()).sum();
            eprintln!(
                "grid {} scales, {} cells, {} entries",
                cache.scales.len(),
                n,
                cells
            );
            eprintln!(
                "radiosity pretrace block {block:.2}px: {} samples (by level {levels:?}), {} rays, {:.3}s",
                cache.len(),
                rays.load(Ordering::Relaxed),
                t0.elapsed().as_secs_f64()
            );
        }
    }
    if let Ok(path) = std::env::var("LANCER_RAD_DUMP") {
        let mut out = String::new();
        for smp in &cache.samples {
            out += &format!(
                "L{}\t{}\t{}\t{}\t{:.3} {:.3} {:.3}\t{:.4}\t{:.4}\t{:.4}\t{}\n",
                smp.level,
                smp.p.x,
                smp.p.y,
                smp.p.z,
                smp.n.x,
                smp.n.y,
                smp.n.z,
                smp.irr.x,
                smp.irr.y,
                smp.irr.z,
                smp.r
            );
        }
        std::fs::write(path, out).ok();
    }
    cache.rays = rays.into_inner();
    // The final trace looks up at the final bound.
    cache.file_new(set.error_bound, set.error_bound);
    // A lit pixel's colour is the final trace's when none of the samples added from its phase
    // on is valid where its lookups read the cache: they then saw the final cache's valid
    // samples, in its order.
    if fold {
        let mut memo = cache.fold_memo();
        for c in to_check {
            let at = c.at as usize;
            // A pixel's points in their order, up to the first where a new sample is valid.
            if first.lit[at]
                && cache.any_valid_memo(c.p, c.n, set.error_bound, c.before as usize, &mut memo)
            {
                first.lit[at] = false;
            }
        }
    }
    cache.first_pass = (!first.lit.is_empty()).then_some(first);
    Some(cache)
}

/// A point (`p`, facing `n`) where a pixel (`at`) the last completion pass lit looked the
/// cache up, with how many samples the cache held when the pixel's phase began (`before`):
/// the pixel keeps its colour if no sample added from then on is valid at any of its points.
/// One entry a point, the pixel's in their order; 56 bytes (as `(usize, Looked, usize)`, 72).
struct Check {
    at: u32,
    before: u32,
    p: DVec3,
    n: DVec3,
}

impl Check {
    fn new(at: usize, p: DVec3, n: DVec3, before: usize) -> Check {
        let id = |v: usize| u32::try_from(v).expect("pixels and samples are numbered in u32");
        Check {
            at: id(at),
            before: id(before),
            p,
            n,
        }
    }
}

/// First-pass colours the last completion pass lit (`fold` in `pretrace`), per pixel row by
/// row: the colour and alpha's clear as four doubles, and whether the pixel was lit. Both made
/// zeroed (`calloc`'s fresh pages, untouched until written) rather than a `Vec<Option<Seen>>`
/// of `None`s, whose 40 bytes a pixel were all written up front (a third of `pretrace`'s page
/// faults), then again where lit.
pub struct FirstPass {
    seen: Vec<[f64; 4]>,
    lit: Vec<bool>,
}

impl FirstPass {
    fn new(n: usize) -> Self {
        FirstPass {
            seen: vec![[0.0; 4]; n],
            lit: vec![false; n],
        }
    }

    fn set(&mut self, at: usize, seen: Seen) {
        self.seen[at] = [seen.rgb.x, seen.rgb.y, seen.rgb.z, seen.clear];
        self.lit[at] = true;
    }

    /// Pixel `at`'s colour when the last completion pass lit it.
    #[inline]
    pub fn get(&self, at: usize) -> Option<Seen> {
        self.lit[at].then(|| {
            let [x, y, z, clear] = self.seen[at];
            Seen {
                rgb: DVec3::new(x, y, z),
                clear,
            }
        })
    }
}

/// The radiosity memos a thread's lookups keep (`Cache::near_memo`'s, `near_enough`'s).
type Memos = (RadiosityMemo, ProbeMemo);

/// A pair of scratches (a position's, and its camera ray's crossing's) for a job of a
/// pretrace phase, the first with memos lent by the pool the phases share and given back
/// when the job is done: their lists of cells (valid while the cache is not filed anew, as
/// in the last passes, which add few samples or none) and their room outlive the phase. (The
/// scratches themselves cannot: they borrow the phase's tracer, which borrows the cache.) A
/// memo speeds the lookups and never changes what they find (so any split of the work among
/// threads gives the same bytes), so which job gets which memos does not matter.
/// The job's rays are counted in its scratch and added to the pass's count once, when the
/// job is done: a locked add per position drained the store buffer (a fifth of the pass
/// closure's own samples on rad_def_test_37 sat after it).
struct Kept<'p, 'a, 'b> {
    pair: (Scratch<'a>, Scratch<'b>),
    pool: &'p Mutex<Vec<Memos>>,
    rays: &'p AtomicU64,
}

impl<'p> Kept<'p, '_, '_> {
    fn take(pool: &'p Mutex<Vec<Memos>>, rays: &'p AtomicU64) -> Self {
        let mut pair = <(Scratch, Scratch)>::default();
        if let Some((memo, probe)) = pool.lock().ok().and_then(|mut v| v.pop()) {
            (pair.0.rad_memo, pair.0.rad_probe) = (memo, probe);
        }
        Kept { pair, pool, rays }
    }
}

impl Drop for Kept<'_, '_, '_> {
    fn drop(&mut self) {
        // The position's scratch alone, as before: the crossings' scratch counts no ray.
        self.rays.fetch_add(self.pair.0.rays, Ordering::Relaxed);
        if let Ok(mut v) = self.pool.lock() {
            let ctx = &mut self.pair.0;
            v.push((
                std::mem::take(&mut ctx.rad_memo),
                std::mem::take(&mut ctx.rad_probe),
            ));
        }
    }
}

/// The tracer of the final trace: reads `cache`, adds nothing to it.
pub fn final_tracer<'a>(
    base: &Tracer<'a>,
    set: &'a RadiositySettings,
    cache: &'a Cache,
) -> Tracer<'a> {
    Tracer {
        rad: Some(RadTrace {
            set,
            cache,
            bound: set.error_bound,
            pretrace: false,
            probe: false,
            record: false,
            pool: &cache.pool,
            eye: base.camera.location,
        }),
        ..base.clone()
    }
}

/// The camera rays of radiosity's completion passes, found once per pixel.
impl<'a> Tracer<'a> {
    /// A camera ray's first visible crossing, as `trace_seen` finds it: radiosity's completion
    /// passes keep it for the same pixel's ray in their later passes (`trace_pretrace_hit`).
    pub(super) fn camera_hit(&self, ray: &Ray, ctx: &mut TraceCtx<'a>) -> Option<SurfaceHit<'a>> {
        self.first_visible(ray, Path::CAMERA.straight, false, ctx)
    }

    /// `trace_pretrace` of a camera ray whose `camera_hit` is `hit`: the same colour, samples
    /// and ray count, without looking for the crossing again.
    pub(super) fn trace_pretrace_hit(
        &self,
        ray: &Ray,
        hit: Option<SurfaceHit<'a>>,
        ctx: &mut TraceCtx<'a>,
    ) -> Seen {
        ctx.rays += 1;
        if Path::CAMERA.depth > self.scene.max_trace_level {
            return Seen::default();
        }
        self.seen_past(ray, hit, Path::CAMERA, ctx)
    }
}

#[cfg(test)]
#[path = "radiosity_tests.rs"]
mod tests;
