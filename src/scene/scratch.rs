//! The per-thread scratch a ray's intersection and shading work in (so no ray allocates), and
//! the plain records the renderer keeps in it: the lights reaching a shaded point and the
//! radiosity samples gathered but not yet shared. The records are defined here, not in
//! render, so that the scene layer that owns the scratch does not depend on the renderer;
//! their behaviour (lighting, the irradiance cache) stays in render.

use crate::geom::Hit;
use crate::math::DVec3;
use crate::scene::desc::Texture;
use crate::scene::media::{Media, Scattering};
use crate::scene::object::{Object, SurfaceHit};

/// Per-thread buffers for intersection, so no ray allocates: shape crossings, and surface
/// crossings gathered for CSG filtering and shadow rays.
#[derive(Default)]
pub struct Scratch<'a> {
    pub hits: Vec<Hit>,
    pub surface: Vec<SurfaceHit<'a>>,
    /// Rays traced with this scratch (camera, reflected, refracted and shadow rays), for the
    /// statistics line.
    pub rays: u64,
    /// The lights reaching the point being shaded, shared by its texture layers.
    pub lit: Vec<LitBy>,
    /// Lists for `lit` while a radiosity sample is gathered below a shaded point: its
    /// gathering rays shade hits of their own, and the point's layers read its own list after.
    pub lit_spare: Vec<Vec<LitBy>>,
    /// Blob components reaching a shaded point, with their field (per-component textures).
    pub blob_weights: Vec<(usize, f64)>,
    /// Shadow samples of an area light's array already taken for the point being shaded.
    pub area_samples: Vec<Option<DVec3>>,
    /// CSG members a ray may meet, gathered from a node's index (a stack: nested nodes append
    /// after their parent's and truncate back).
    pub members: Vec<u32>,
    /// A CSG node's member crossings for `first_hit`, nearest first: (t's order key, where in
    /// `csg_hits`, member), packed as `csg_hit::order_entry`. A stack like `members`.
    pub csg_order: Vec<u128>,
    /// The crossings `csg_order` points at, as the shapes listed them (`csg_hit::gather_hits`):
    /// the search builds the surface hit of the kept one only. A stack like `members`.
    pub csg_hits: Vec<Hit>,
    /// Per light, the opaque object that last blocked a shadow ray to it (POV-Ray's shadow
    /// cache): asked first, since neighbouring points are mostly shadowed by the same object.
    pub blockers: Vec<Option<&'a Object>>,
    /// Per light, the leaf of an indexed union whose crossing last blocked a shadow ray to it
    /// (render::shadow): asked before the union, whose walk down to that leaf it saves.
    pub leaf_blockers: Vec<Option<&'a Object>>,
    /// Per light, the member of a transparent union (and that union, a top-level object)
    /// whose crossing last blocked a shadow ray to it, asked first likewise.
    pub member_blockers: Vec<Option<(&'a Object, &'a Object)>>,
    /// The light a shadow ray left after transparent crossings, when its test answers
    /// `Filtered` (render::shadow: the answer itself is a byte, returned in a register).
    pub shadow_att: DVec3,
    /// The members of a transparent union a shadow ray may cross (render::shadow).
    pub shadow_members: Vec<&'a Object>,
    /// Radiosity samples gathered while tracing the current camera sample, not yet in the
    /// shared cache (which is frozen during a pass, for determinism).
    pub rad_local: Vec<RadiositySample>,
    /// Where a camera ray's radiosity lookups read the cache: (point, normal).
    pub rad_seen: Vec<(DVec3, DVec3)>,
    /// The cells this thread's last radiosity lookups read, for the next lookup facing the
    /// same way (render::radiosity_cache).
    pub rad_memo: RadiosityMemo,
    /// The cells this thread's last probe lookup (a pretrace camera ray's) read, per scale.
    pub rad_probe: ProbeMemo,
    /// The background radiosity's gathering rays met, by their sample's frame of directions.
    pub rad_sky: SkyMemo,
    /// Photons found around the point being shaded: (squared distance, index).
    pub photon_found: Vec<(f32, u32)>,
    /// The media lists along the ray stretch being sampled (render::media).
    pub media_lists: Vec<&'a [Media]>,
    /// Where that stretch enters and leaves light beams.
    pub media_cuts: Vec<f64>,
    /// The lights that may scatter on that stretch (slot, and the part of the stretch outside
    /// which the light is dark), and those that may on the piece being sampled (slots).
    pub media_lights: Vec<(usize, f64, f64)>,
    pub media_piece: Vec<usize>,
    /// At one media sample: each scattering media's density, with its scattering.
    pub media_scatter: Vec<(DVec3, Scattering)>,
    /// The textures last shaded, newest first, with facts about them that walk their whole
    /// tree (render::trace's `texture_facts`): a star field's nested texture_maps cost two
    /// walks of every entry per hit otherwise. Four, for scenes whose rays go from one
    /// object to another and back (a mirror's reflections: with one, a fifth of
    /// mirror_spheres' hits walked their texture). Held by reference, so while the scene
    /// lives no other texture can have its address.
    pub last_textures: [Option<(&'a Texture, [bool; 3])>; 4],
}

/// A light reaching the point being shaded, after shadows.
pub struct LitBy {
    pub color: DVec3,
    pub l: DVec3,
    pub cos_n: f64,
    pub shadowless: bool,
    /// Behind the surface, lighting it through `double_illuminate`.
    pub back: bool,
    /// The light's index (`u32::MAX` for the photons' light): with the shaded point's seed it
    /// fixes `crand`'s random share (render::trace::grain), worked out only by finishes with
    /// `crand`, not for every light of every hit.
    pub slot: u32,
}

/// One cached irradiance value.
#[derive(Clone, Copy, Debug)]
pub struct RadiositySample {
    pub p: DVec3,
    pub n: DVec3,
    /// What the sample gathered, after `gray_threshold`, `max_sample` and `brightness`.
    pub irr: DVec3,
    /// Reuse radius: harmonic mean distance to what the rays met, clamped by
    /// `minimum_reuse` and `maximum_reuse` times the distance from the camera.
    pub r: f64,
    /// 1 for samples seen from camera rays, deeper for those of their gathering rays.
    pub level: u32,
}

/// For a few normals (a floor and what its reflections meet, a room's walls; each in the entry
/// its bits hash to, after a first lookup in the last, probation entry), the cells of the
/// irradiance cache lookups facing it read, each with its samples the normal and level tests
/// let through for that facing (render::radiosity_cache, `Cache::near_memo`).
#[derive(Default)]
pub struct RadiosityMemo {
    pub entries: Vec<MemoEntry>,
    /// Per scale, the sub-cell the last level-1 lookup of a fresh normal (a curved surface's)
    /// read whole, with its cell's level-1 samples that can reach it (`Cache::near_memo`).
    pub whole: ProbeMemo,
}

/// One normal's cells (`RadiosityMemo`).
#[derive(Default)]
pub struct MemoEntry {
    /// Which filing of which cache the cells are of (0: none).
    pub stamp: u64,
    /// The lookups' normal (bits), level and error bound (bits) the lists hold for.
    pub n: [u64; 3],
    pub level: u32,
    pub bound: u64,
    /// Raised whenever the entry takes another normal: cells of an older epoch hold nothing.
    pub epoch: u64,
    /// One per scale, in the cache's order.
    pub cells: Vec<MemoCell>,
    /// Every cell listed in this epoch, by (scale, key): its list's place in `listed`. A
    /// lookup coming back to a cell it left (the next row of a floor, the pass's next phase)
    /// reads the list again instead of the cell.
    pub lists: rustc_hash::FxHashMap<(u32, u64), (u32, u32)>,
    /// The lists, one after another, each in quads of four samples (the last padded with
    /// samples that reach nothing).
    pub listed: Vec<ListedQuad>,
}

/// Per scale, the cell a thread's last probe lookup read (render::radiosity_cache,
/// `Cache::near_enough`): the next probe, a neighbouring block's camera ray, mostly falls in
/// the same cells and reads this copy of their lists instead of making their keys and asking
/// the grids again.
#[derive(Default)]
pub struct ProbeMemo {
    /// Which filing of which cache the cells are of (0: none), for which error bound (bits:
    /// `RadiosityMemo::whole`'s only, whose copies depend on it).
    pub stamp: u64,
    pub bound: u64,
    pub cells: Vec<ProbeCell>,
}

/// A scale's cell in `ProbeMemo`: the floors of the point's coordinates in cells it was found
/// from (NaN, equal to nothing, until one is read), and a copy of the cell's level-1 list; in
/// `RadiosityMemo::whole`, the floors in sub-cells and the samples of the cell's list that can
/// reach a point of the sub-cell, in the list's order.
pub struct ProbeCell {
    pub floors: [f64; 3],
    pub ids: Vec<u32>,
}

impl Default for ProbeCell {
    fn default() -> Self {
        ProbeCell {
            floors: [f64::NAN; 3],
            ids: Vec::new(),
        }
    }
}

/// Four samples of a list of a `MemoEntry`, field by field, with what a lookup computes of
/// each that depends only on the entry's normal and bound: a lookup's lanes load each
/// quantity of the four at once (render::radiosity_lanes).
#[derive(Clone, Copy, Default)]
#[repr(C, align(32))]
pub struct ListedQuad {
    /// The samples' positions.
    pub px: [f64; 4],
    pub py: [f64; 4],
    pub pz: [f64; 4],
    /// The squared reach at the entry's bound, `(r * bound)²` (-1 in a padding lane).
    pub far2: [f64; 4],
    /// The harmonic distances, and -0.05 times them (Ward's front test).
    pub r: [f64; 4],
    pub front: [f64; 4],
    /// The entry's normal plus the sample's.
    pub mx: [f64; 4],
    pub my: [f64; 4],
    pub mz: [f64; 4],
    /// The share of the error from the sample's normal's turn from the entry's.
    pub nerr: [f64; 4],
    /// The samples' numbers.
    pub ids: [u32; 4],
}

/// A scale's last cell read (`MemoEntry`), valid in the entry's epoch: its key, the floors of
/// the point's coordinates in cells it was made from, and where its list is in the entry's
/// `listed` (first quad, number of quads).
#[derive(Default)]
pub struct MemoCell {
    pub key: u64,
    pub floors: [f64; 3],
    pub epoch: u64,
    pub at: (u32, u32),
}

/// What fixes the directions of a radiosity sample's gathering rays (render::radiosity's
/// `gather`): its normal's bits, the direction pool (its address), the first ray's place in
/// the pool and the number of rays. Ray i of two samples with one key has the same direction,
/// to the bit.
#[derive(Clone, Copy, PartialEq, Eq)]
pub struct SkyKey {
    pub n: [u64; 3],
    pub pool: usize,
    pub start: u32,
    pub count: u32,
}

/// The background's colour (and clear share) along the gathering rays of the last few
/// frames of directions (`SkyKey`), newest first: every sample facing one normal shoots the
/// same directions, so a floor's samples see the same sky along the rays that miss
/// everything, and the sky's colour depends on the direction alone (a sky that may read the
/// surface, `slope` or `aoi`, is not remembered: the caller's test).
#[derive(Default)]
pub struct SkyMemo {
    frames: Vec<SkyFrame>,
}

struct SkyFrame {
    key: SkyKey,
    seen: Vec<Option<(DVec3, f64)>>,
}

/// Frames kept: a floor's and those of the faces its neighbours' samples lie on.
const SKY_FRAMES: usize = 8;

impl SkyMemo {
    /// Makes `key`'s frame the newest; a frame not kept starts with nothing seen.
    pub fn frame(&mut self, key: SkyKey) {
        if let Some(i) = self.frames.iter().position(|f| f.key == key) {
            self.frames[..=i].rotate_right(1);
            return;
        }
        let mut f = if self.frames.len() < SKY_FRAMES {
            SkyFrame {
                key,
                seen: Vec::new(),
            }
        } else {
            self.frames.pop().expect("SKY_FRAMES frames")
        };
        f.key = key;
        f.seen.clear();
        f.seen.resize(key.count as usize, None);
        self.frames.insert(0, f);
    }

    /// What ray `i` of `key`'s frame sees of the background: remembered, or `f`'s answer
    /// (kept while the frame is; a deeper sample gathered meanwhile may have dropped it).
    #[inline]
    pub fn seen(
        &mut self,
        key: &SkyKey,
        i: usize,
        f: impl FnOnce() -> (DVec3, f64),
    ) -> (DVec3, f64) {
        match self.frames.iter_mut().find(|fr| fr.key == *key) {
            Some(fr) => *fr.seen[i].get_or_insert_with(f),
            None => f(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn key(k: u64) -> SkyKey {
        SkyKey {
            n: [k, 0, 0],
            pool: 0,
            start: 0,
            count: 3,
        }
    }

    #[test]
    fn a_sky_memo_answers_what_it_was_told_while_the_frame_is_kept() {
        let mut m = SkyMemo::default();
        let c = |v: f64| (DVec3::splat(v), v);
        m.frame(key(1));
        assert_eq!(m.seen(&key(1), 0, || c(1.0)), c(1.0));
        // Remembered: the closure is not asked again.
        assert_eq!(m.seen(&key(1), 0, || c(9.0)), c(1.0));
        // A frame not made newest (a deeper sample's, dropped meanwhile) is asked every time.
        assert_eq!(m.seen(&key(2), 0, || c(2.0)), c(2.0));
        assert_eq!(m.seen(&key(2), 0, || c(3.0)), c(3.0));
        // Frames beyond the kept number push the oldest out; the first is then empty again.
        for k in 2..=SKY_FRAMES as u64 + 1 {
            m.frame(key(k));
        }
        m.frame(key(1));
        assert_eq!(m.seen(&key(1), 0, || c(4.0)), c(4.0));
        m.frame(key(100));
        m.frame(key(2));
        assert_eq!(m.seen(&key(1), 0, || c(5.0)), c(4.0));
        assert_eq!(m.frames.len(), SKY_FRAMES);
    }
}
