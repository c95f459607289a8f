//! Shadow rays: how much of a light reaches a point past the objects in between, for point
//! lights and for area lights (an array of points, sampled whole or adaptively).

use crate::math::{DVec3, Ray, Slabs};
use crate::scene::build::leaf_any_hit;
use crate::scene::light::Light;
use crate::scene::object::Object;

use super::texture_map;
use super::trace::{TraceCtx, Tracer};

/// Crossings this close to the light (along the shadow ray) do not shadow it.
const SHADOW_TOLERANCE: f64 = 2.9e-5;

impl<'a> Tracer<'a> {
    /// The light from `light` arriving at `p` along `l` (a shadow ray `dist` long), after
    /// shadows: an area light averages its array of points.
    pub(super) fn light_seen(
        &self,
        p: DVec3,
        (slot, light): (usize, &Light),
        l: DVec3,
        dist: f64,
        gathering: bool,
        ctx: &mut TraceCtx<'a>,
    ) -> DVec3 {
        // A point light without media attenuation (nearly every light): the shadow ray's
        // answer as it is, which `attenuated` returns unchanged, reached by a jump where the
        // general path below made a frame of its own (~40 instructions a shadow ray).
        if light.area.is_none() && !light.media_attenuation {
            return self.shadow(p, l, dist, slot, ctx);
        }
        let seen = match &light.area {
            Some(a) if self.samples_area(light, gathering) => {
                self.area_seen(p, (slot, light), a, ctx)
            }
            _ => self.shadow(p, l, dist, slot, ctx),
        };
        self.attenuated(seen, p, light, l, dist)
    }

    /// Whether `light`'s shadows come from its array of points rather than its centre.
    /// Radiosity's gathering rays see an area light as a point at its centre (measured:
    /// povray's shadow ray tests for a radiosity pass barely grow when a point light becomes
    /// a 4x4 area light, docs/radiosity.md).
    pub(super) fn samples_area(&self, light: &Light, gathering: bool) -> bool {
        light
            .area
            .as_ref()
            .is_some_and(|a| !gathering && self.quality.area_lights && a.size1 * a.size2 > 1)
            && light.parallel.is_none()
    }

    /// `area_illumination`: every point of the array lights `p` as a light of its own, each
    /// with an equal share, its own direction and its own shadow, whatever `adaptive` says
    /// (measured: under a 5x5 array 1 unit above a plane, povray's diffuse light is the mean
    /// of all 25 points' cosines, 0.3786 against 0.3757 computed, where the adaptive corners
    /// would give 0.465). `f` gets each point's unit direction and light after shadows.
    pub(super) fn area_each(
        &self,
        p: DVec3,
        (slot, light): (usize, &Light),
        l: DVec3,
        dist: f64,
        ctx: &mut TraceCtx<'a>,
        mut f: impl FnMut(DVec3, f64, DVec3),
    ) {
        let Some(a) = &light.area else {
            return;
        };
        let seen = self.area_seen(p, (slot, light), a, ctx);
        let share = self.attenuated(seen, p, light, l, dist) / (a.size1 * a.size2) as f64;
        let axes = a.axes((p - light.position).normalize_or_zero());
        for j in 0..a.size2 {
            for i in 0..a.size1 {
                let to = light.position + a.point_on(i, j, axes, (0.0, 0.0)) - p;
                let d = to.length();
                f(if d > 0.0 { to / d } else { l }, d, share);
            }
        }
    }

    /// `seen` after `media_attenuation`: the atmosphere's media and fog dim the light on its
    /// way (measured: interior/media/hollow1's light, 40000 units bright 800 units away
    /// through fog of distance 80, lights the scene as a light of about 2 would).
    fn attenuated(&self, seen: DVec3, p: DVec3, light: &Light, l: DVec3, dist: f64) -> DVec3 {
        if !light.media_attenuation || seen == DVec3::ZERO {
            return seen;
        }
        let ray = Ray::new(p, l);
        let mut seen = seen * super::fog::kept(&self.scene.fogs, &ray, dist);
        if !self.scene.media.is_empty() {
            seen *= super::media::transmittance(&[&self.scene.media], &ray, 0.0, dist);
        }
        seen
    }

    /// How far a shadow ray of light `slot` is tested: to its `projected_through` object's
    /// nearest crossing, None when it misses that object; `dist` for other lights.
    pub(super) fn projected_dist(
        &self,
        ray: &Ray,
        dist: f64,
        slot: usize,
        ctx: &mut TraceCtx<'a>,
    ) -> Option<f64> {
        match &self.scene.lights[slot].projected {
            Some(obj) => obj.0.first_hit(ray, dist, ctx).map(|h| h.t),
            None => Some(dist),
        }
    }

    /// Light reaching `p` from a light `dist` away in direction `l`: zero behind an opaque
    /// object, filtered by each crossing of a transparent one. `slot` is the light's number,
    /// for the cache of the last blocker.
    #[inline(always)]
    pub(super) fn shadow(
        &self,
        p: DVec3,
        l: DVec3,
        dist: f64,
        slot: usize,
        ctx: &mut TraceCtx<'a>,
    ) -> DVec3 {
        // `1 * x` is `x` to the bit: the answer itself.
        self.shadowed(DVec3::ONE, p, l, dist, slot, ctx)
    }

    /// `lc * self.shadow(..)`, to the bit, with the answer's three cases multiplied apart:
    /// joined first into one `DVec3`, the answer went through a stack slot written as an
    /// x-y pair and z and read as x and a y-z pair, which the store buffer cannot forward
    /// (`Shadowed`). Nothing in the way leaves `lc` as it is (`lc * 1` is `lc`).
    ///
    /// The shadow test is the copy compiled with AVX where the CPU has it, as
    /// `Scene::first_hit` (the walk's node test and the set-up around it in three-operand
    /// forms; the same operations, so the same bits). The choice is a flag the scene read
    /// once (`Scene::avx`), here inlined: a function asking the CPU at every shadow ray, with
    /// a frame for the call that asks it the first time, cost ~20 instructions a ray.
    #[inline(always)]
    pub(super) fn shadowed(
        &self,
        lc: DVec3,
        p: DVec3,
        l: DVec3,
        dist: f64,
        slot: usize,
        ctx: &mut TraceCtx<'a>,
    ) -> DVec3 {
        #[cfg(target_arch = "x86_64")]
        let answer = if self.scene.avx() {
            // SAFETY: the scene found that the CPU has AVX.
            unsafe { self.shadow_avx(p, l, dist, slot, ctx) }
        } else {
            self.shadow_base(p, l, dist, slot, ctx)
        };
        #[cfg(not(target_arch = "x86_64"))]
        let answer = self.shadow_base(p, l, dist, slot, ctx);
        match answer {
            Shadowed::Dark => lc * DVec3::ZERO,
            Shadowed::Lit => lc,
            Shadowed::Filtered => lc * ctx.shadow_att,
        }
    }

    /// `shadow` out of line, for the area lights' walk: inlined there, its two calls grew
    /// `AreaWalk::quad` (lights/soft +4.4 M instructions, more than the choice's call saves).
    #[inline(never)]
    pub(super) fn shadow_apart(
        &self,
        p: DVec3,
        l: DVec3,
        dist: f64,
        slot: usize,
        ctx: &mut TraceCtx<'a>,
    ) -> DVec3 {
        self.shadow(p, l, dist, slot, ctx)
    }

    /// # Safety
    /// The CPU must have AVX.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    #[inline(never)]
    unsafe fn shadow_avx(
        &self,
        p: DVec3,
        l: DVec3,
        dist: f64,
        slot: usize,
        ctx: &mut TraceCtx<'a>,
    ) -> Shadowed {
        // SAFETY: the caller says the CPU has AVX.
        self.shadow_in(
            unsafe { crate::geom::bvh::Avx::new() },
            p,
            l,
            dist,
            slot,
            ctx,
        )
    }

    /// `shadow_in` for CPUs without AVX.
    #[inline(never)]
    fn shadow_base(
        &self,
        p: DVec3,
        l: DVec3,
        dist: f64,
        slot: usize,
        ctx: &mut TraceCtx<'a>,
    ) -> Shadowed {
        self.shadow_in(crate::geom::bvh::Sse, p, l, dist, slot, ctx)
    }

    /// `shadow`'s work, inlined into each of its copies (`lanes`: the walk's node test).
    #[inline(always)]
    fn shadow_in(
        &self,
        lanes: impl crate::geom::bvh::Lanes,
        p: DVec3,
        l: DVec3,
        dist: f64,
        slot: usize,
        ctx: &mut TraceCtx<'a>,
    ) -> Shadowed {
        ctx.rays += 1;
        // Surfaces at the light itself do not shadow it (radiosity/cornell's lights sit on the
        // ceiling). Measured: a light up to 2.85e-5 above a disc facing away from the lit
        // wall is unshadowed, 2.9e-5 is shadowed, the same at every angle and scale tried.
        let dist = dist - SHADOW_TOLERANCE;
        if dist <= 0.0 {
            return Shadowed::Lit;
        }
        // The callers pass `p` and `l` through memory, `l` often stored as three doubles
        // just before the call; copied into the ray as an x-y pair and z, the pair's load
        // spanned two of those stores and waited for them to reach the cache (a tenth of
        // this function's samples on mirror_spheres, and the reciprocal's divisions after
        // it). Read one by one, and the ray written as the walks read it (`ray_at`); `l` is
        // `ray.dir` after, where a local copy of it for the closure was written as three
        // doubles and read back as a pair again.
        let (p, l) = (
            crate::math::by_coordinates(&p),
            crate::math::by_coordinates(&l),
        );
        let mut at = std::mem::MaybeUninit::uninit();
        let ray = ray_at(&mut at, p, l);
        // `projected_through`: no light unless the path crosses the object, and only what
        // lies between the point and that crossing casts a shadow (manual 3.4.4.1.8).
        let dist = match self.projected_dist(ray, dist, slot, ctx) {
            Some(d) => d,
            None => return Shadowed::Dark,
        };
        // Any opaque blocker makes the answer exactly zero, whatever else the ray crosses, so
        // the last one is tried first. Its box test is the one the BVH would have made.
        if ctx.blockers.len() <= slot {
            ctx.blockers.resize(slot + 1, None);
            ctx.leaf_blockers.resize(slot + 1, None);
        }
        // Once for the cached blocker's box and the walk (each took its own three divisions,
        // and its own tests of the ray for NaN-free slabs); the reciprocal is `recip` to the
        // bit, read so as to forward from the stores just made.
        let r = crate::geom::bvh::Recip::of(ray);
        // The cached boxes' tests are `Aabb::hit(..).is_some()`, through plain comparisons
        // where no slab distance can be NaN (`Slabs`): most cached blockers are not in the
        // way, and the NaN-aware test was ~75 instructions of every such shadow ray.
        // `Slabs::hits` read the just-built ray's origin as a (y, z) pair (a tenth of this
        // function's samples on cornell, a fifth on lights/arealit1, before the origin was
        // read one coordinate at a time): `p`, read so above.
        let slabs = crate::math::Slabs::known(p, r.inv, r.plain);
        // The leaf of an indexed union that blocked the last ray, before the union itself:
        // neighbouring samples of an area light are mostly blocked by the same torus or
        // cylinder, and the union's walk down to it cost more than the leaf's own test. A
        // leaf that blocks makes the union block (its box holds the leaf's), and the union
        // is a top-level object that the walk below would reach (as `member_blockers`).
        if let Some(leaf) = ctx.leaf_blockers[slot] {
            if slabs.hits(&leaf.bounds, dist) && leaf_any_hit(leaf, ray, dist, ctx) {
                return Shadowed::Dark;
            }
        }
        let mut tried = None;
        if let Some(b) = ctx.blockers[slot] {
            if slabs.hits(&b.bounds, dist) {
                if opaque_blocks(b, ray, &slabs, dist, slot, ctx) {
                    return Shadowed::Dark;
                }
                tried = Some(b);
            }
        }
        // With photons, light this light sends through refracting targets arrives as photons.
        let photons_only = self.photons.is_some() && self.scene.lights[slot].photons.refraction;
        // The member of a transparent union that blocked the last ray: asked as the union's
        // crossings would be (below), it answers only when it blocks, which the whole
        // traversal would also find (the union is a top-level object whose box holds the
        // member's, and a blocking crossing makes the answer exactly zero).
        if ctx.member_blockers.len() <= slot {
            ctx.member_blockers.resize(slot + 1, None);
        }
        // When asked and found not to block, the union's walk below would ask it again (its
        // two boxes are the tests that list it there): `through_transparent` takes this
        // answer instead, and whether it crossed the ray (advanced/abyss: the cached hull part
        // blocked 1 in 23 of the rays that asked it, and each of the others listed its blob's
        // crossings twice).
        let mut asked = None;
        if let Some((top, m)) = ctx.member_blockers[slot] {
            let start = ctx.surface.len();
            if slabs.hits(&top.bounds, dist) && slabs.hits(&m.bounds, dist) {
                if self.member_blocks(m, ray, ray.dir, dist, photons_only, ctx) {
                    return Shadowed::Dark;
                }
                asked = Some((top, m, ctx.surface.len() != start));
            }
            ctx.surface.truncate(start);
        }
        let mut att = DVec3::ONE;
        let mut blocker = None;
        // Whether a transparent candidate filtered `att`: until one does, it is all light.
        let mut filtered = false;
        // The opaque case inline (nearly every candidate: a sphere's or a plane's `any_hit`
        // through `leaf_any_hit`), where the whole closure was called out of line for each
        // leaf (~40 instructions a call); transparent objects in `through_transparent`.
        self.scene.for_each_candidate_recip(
            lanes,
            ray,
            &r,
            dist,
            #[inline(always)]
            |c| {
                let obj = c.obj;
                // The cached blocker, opaque, was just found not to block.
                if obj.no_shadow || tried.is_some_and(|t| std::ptr::eq(t, obj)) {
                    return false;
                }
                if !obj.transparent {
                    // A plain sphere's `any_hit` without the call through its table.
                    let blocks = match c.sphere() {
                        Some(s) => s.blocks(ray, dist),
                        None => opaque_blocks(obj, ray, &slabs, dist, slot, ctx),
                    };
                    if blocks {
                        att = DVec3::ZERO;
                        blocker = Some(obj);
                        return true;
                    }
                    return false;
                }
                let way = Way {
                    l: ray.dir,
                    dist,
                    slot,
                    photons_only,
                    asked,
                };
                filtered = true;
                self.through_transparent(obj, ray, &way, ctx, &mut att)
            },
        );
        if blocker.is_some() {
            ctx.blockers[slot] = blocker;
            return Shadowed::Dark;
        }
        if !filtered {
            return Shadowed::Lit;
        }
        ctx.shadow_att = att;
        Shadowed::Filtered
    }

    /// A transparent candidate `obj` of the shadow ray `way`: whether it blocks the light
    /// (then `att` is zero), else `att` filtered by its crossings. Out of line: rare, and
    /// large beside the opaque test the walk inlines.
    #[inline(never)]
    fn through_transparent(
        &self,
        obj: &'a crate::scene::object::Object,
        ray: &Ray,
        way: &Way<'a>,
        ctx: &mut TraceCtx<'a>,
        att: &mut DVec3,
    ) -> bool {
        let Way {
            l,
            dist,
            slot,
            photons_only,
            asked,
        } = *way;
        let asked = asked.filter(|a| std::ptr::eq(a.0, obj));
        let start = ctx.surface.len();
        // Taken here, not for every shadow ray: only transparent objects need it.
        let mut members = std::mem::take(&mut ctx.shadow_members);
        members.clear();
        if obj.union_members(ray, dist, ctx, &mut members) {
            // A union's crossings are its members' in member order. Any crossing that
            // blocks makes the answer zero wherever it stands in that list, so the opaque
            // members (most of a scene wrapped in a clear container, as advanced/abyss's
            // media sphere) are asked first, each alone, and the first that blocks ends
            // the ray; only when none does is the list gathered in order for the
            // product below. A member without crossings is not asked twice.
            let mut k = 0;
            for i in 0..members.len() {
                let m = members[i];
                if !m.transparent {
                    let crossed = match asked {
                        Some((_, a, crossed)) if std::ptr::eq(a, m) => crossed,
                        _ => {
                            if self.member_blocks(m, ray, l, dist, photons_only, ctx) {
                                ctx.member_blockers[slot] = Some((obj, m));
                                ctx.shadow_members = members;
                                *att = DVec3::ZERO;
                                return true;
                            }
                            let crossed = ctx.surface.len() != start;
                            ctx.surface.truncate(start);
                            crossed
                        }
                    };
                    if !crossed {
                        continue;
                    }
                }
                members[k] = m;
                k += 1;
            }
            for &m in &members[..k] {
                m.all_hits(ray, dist, ctx);
            }
        } else {
            obj.all_hits(ray, dist, ctx);
        }
        ctx.shadow_members = members;
        for i in start..ctx.surface.len() {
            let h = ctx.surface[i];
            if self.crossing_blocks(&h, ray, l, photons_only, Some(att)) {
                *att = DVec3::ZERO;
                break;
            }
        }
        // Fading interiors and media dim the light over each stretch the ray spends
        // inside them: from the last crossing (or the shaded point) to a crossing that
        // leaves (povray: absorbing media in a transparent container always shadow).
        if *att != DVec3::ZERO
            && ctx.surface[start..]
                .iter()
                .any(|h| h.obj.interior.is_some())
        {
            ctx.surface[start..].sort_by(|a, b| a.t.total_cmp(&b.t));
            let mut last = 0.0;
            for h in &ctx.surface[start..] {
                if let Some(int) = &h.obj.interior {
                    // By coordinates here and below: `Object::normal` may store x and y
                    // apart, and a pair load of them waits (place31: a quarter of this
                    // function's samples on interior/caustic2).
                    if crate::math::by_coordinates(&h.obj.normal(ray.at(h.t), h)).dot(l) > 0.0 {
                        *att *= int.fade(h.t - last);
                        if int.has_media() {
                            *att *= super::media::transmittance(&[int.media()], ray, last, h.t);
                        }
                    }
                }
                last = h.t;
            }
        }
        ctx.surface.truncate(start);
        *att == DVec3::ZERO
    }

    /// Whether a crossing of `m` (a member of a transparent union) within `dist` blocks the
    /// shadow ray, as `crossing_blocks` judges each; leaves its crossings in `ctx.surface`
    /// when none blocks, and none when one does.
    fn member_blocks(
        &self,
        m: &'a crate::scene::object::Object,
        ray: &Ray,
        l: DVec3,
        dist: f64,
        photons_only: bool,
        ctx: &mut TraceCtx<'a>,
    ) -> bool {
        let start = ctx.surface.len();
        m.all_hits(ray, dist, ctx);
        let blocks = ctx.surface[start..]
            .iter()
            .any(|h| self.crossing_blocks(h, ray, l, photons_only, None));
        if blocks {
            ctx.surface.truncate(start);
        }
        blocks
    }

    /// Whether the shadow ray's crossing `h` stops the light (an opaque layer of the texture
    /// it meets, or a photon target); otherwise `att`, when given, is filtered by each
    /// layer's transmitted colour and fake caustics. Which crossings block does not depend
    /// on `att` or on the other crossings.
    fn crossing_blocks(
        &self,
        h: &crate::scene::object::SurfaceHit<'a>,
        ray: &Ray,
        l: DVec3,
        photons_only: bool,
        mut att: Option<&mut DVec3>,
    ) -> bool {
        // Through each layer of a layered texture in turn.
        if h.obj.no_shadow {
            // A CSG member's own no_shadow (advanced/infinitybox's walls).
            return false;
        }
        let hp = ray.at(h.t);
        // A shadow ray leaving through a wall meets its inside (measured: an open
        // box's interior_texture shadows its own far wall).
        let inside = h.obj.interior_texture.is_some()
            && crate::math::by_coordinates(&h.obj.normal(hp, h)).dot(ray.dir) > 0.0;
        let top = h.obj.texture_facing(h, inside);
        let uv = if top.uses_uv() {
            h.obj.uv_point(hp, h)
        } else {
            None
        };
        if photons_only && super::photons::refracts_photons(h.obj) {
            return true;
        }
        for layer in top.layers() {
            let c = fresh_colour(&texture_map::color_at(layer, hp, uv, false));
            if c.is_opaque() {
                return true;
            }
            if let Some(a) = att.as_deref_mut() {
                *a *= c.transmitted();
            }
        }
        if let Some(a) = att {
            if let Some(int) = h.obj.interior.as_deref().filter(|i| i.caustics > 0.0) {
                let n = crate::math::by_coordinates(&h.obj.normal(hp, h));
                let n = if n.dot(l) > 0.0 { -n } else { n };
                *a *= int.caustic_gain(caustic_normal(top, hp, uv, n).dot(l));
            }
        }
        false
    }
}

/// A shadow ray's answer as its out-of-line copies (`shadow_avx`, `shadow_base`) return it:
/// a byte in a register. Returned as a `DVec3`, it went back through memory, written as an
/// x-y pair and z and read by `gather_each` as x and a y-z pair, a load the store buffer
/// cannot forward (8 % of `shade`'s samples on mirror_spheres sat right after it). Nearly
/// every answer is all of the light or none; a filtered one waits in `ctx.shadow_att`.
#[derive(Clone, Copy)]
enum Shadowed {
    /// An opaque blocker: no light (`DVec3::ZERO`).
    Dark,
    /// Nothing in the way: all of it (`DVec3::ONE`).
    Lit,
    /// Filtered by transparent crossings: `ctx.shadow_att`.
    Filtered,
}

/// Whether the opaque object `obj` crosses the shadow ray within `dist`: `Object::any_hit`,
/// a small union's members tested through the ray's `slabs` (its own took three divisions,
/// and `any_hit`'s frame for every union: cornell's walls and blocks). An indexed union is
/// walked here as `Object::any_hit` walks it, through the same `slabs` (`Slabs::known` is
/// `Slabs::new` of the reciprocal, bit for bit), without light `slot`'s cached leaf, which
/// `shadow_in` has just asked; the leaf that blocks becomes the cached one.
#[inline(always)]
fn opaque_blocks<'a>(
    obj: &'a Object,
    ray: &Ray,
    slabs: &Slabs,
    dist: f64,
    slot: usize,
    ctx: &mut TraceCtx<'a>,
) -> bool {
    if let Some(members) = obj.scanned_union() {
        return Object::scan_any_hit(members, ray, slabs, dist, ctx);
    }
    let Some((children, ix)) = obj.indexed_union() else {
        return leaf_any_hit(obj, ray, dist, ctx);
    };
    let asked = ctx.leaf_blockers[slot];
    let mut found = None;
    let blocks = ix.any(ray, dist, |i| {
        let c = ix.leaf(children, i);
        if asked.is_some_and(|a| std::ptr::eq(a, c)) {
            return false;
        }
        let blocks = slabs.hits(&c.bounds, dist) && leaf_any_hit(c, ray, dist, ctx);
        if blocks {
            found = Some(c);
        }
        blocks
    });
    if blocks {
        ctx.leaf_blockers[slot] = found;
    }
    blocks
}

/// The ray from `p` along `l`, written into `at` as an x-y pair (one 16-byte store) and z for
/// each vector: what the walks and the sphere test read (`by_coordinates`' 8-byte loads and
/// x-y pairs), each load within one store, which the store buffer forwards. Built by value,
/// LLVM wrote each vector as three doubles where it had them apart, and the pairs' loads
/// spanning two stores waited for both to reach the cache.
#[inline(always)]
fn ray_at(at: &mut std::mem::MaybeUninit<Ray>, p: DVec3, l: DVec3) -> &Ray {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{_mm_set_pd, _mm_storeu_pd};
        let r = at.as_mut_ptr();
        // SAFETY: the stores write every field of the `Ray` behind `r` (two x-y pairs of
        // doubles and two doubles, at their fields' places: `DVec3` is `repr(C)` x, y, z),
        // after which it is initialised; SSE2 is part of x86_64.
        unsafe {
            let o = std::ptr::addr_of_mut!((*r).origin);
            let d = std::ptr::addr_of_mut!((*r).dir);
            _mm_storeu_pd(o.cast::<f64>(), _mm_set_pd(p.y, p.x));
            std::ptr::addr_of_mut!((*o).z).write(p.z);
            _mm_storeu_pd(d.cast::<f64>(), _mm_set_pd(l.y, l.x));
            std::ptr::addr_of_mut!((*d).z).write(l.z);
            at.assume_init_ref()
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    at.write(Ray::new(p, l))
}

/// A shadow ray as `Tracer::through_transparent` needs it beside the ray itself: its unit
/// direction, how far it is tested, the light's number and whether refracting targets pass
/// only photons. The ray is passed as `shadow_in` wrote it (`ray_at`): a copy here was
/// written in pieces that the walk's pair loads of its direction straddled, and each such
/// load waited for the copy to reach the cache (a tenth of `union_members`' samples on
/// advanced/abyss, on its first use of the direction).
#[derive(Clone, Copy)]
struct Way<'a> {
    l: DVec3,
    dist: f64,
    slot: usize,
    photons_only: bool,
    /// The cached member a transparent union's walk need not ask again (`shadow_in`): the
    /// union, the member, and whether it crossed the ray without blocking it.
    asked: Option<(&'a Object, &'a Object, bool)>,
}

/// The normal fake caustics are computed with: the surface's, perturbed by the first normal
/// pattern of the texture at the point (through layers, texture maps and lists), the one
/// that decides refraction in `shade` (POV-Ray's `caustics` light up where bumps face the
/// light).
fn caustic_normal(
    top: &crate::scene::desc::Texture,
    p: DVec3,
    uv: Option<DVec3>,
    n: DVec3,
) -> DVec3 {
    let mut pn = None;
    for layer in top.layers() {
        texture_map::blend(layer, p, uv, false, 1.0, &mut |_, part, space, _| {
            if pn.is_none() && super::normal::perturbs(part.normal.as_deref()) {
                if let Some(nd) = part.normal.as_deref() {
                    pn = Some(super::normal::perturb_in(nd, space, p, n));
                }
            }
        });
        if pn.is_some() {
            break;
        }
    }
    // By coordinates: `perturb_in`'s answer was stored as an x-y pair and z, and read back as
    // x and a y-z pair for the dot product with the light, a load the store buffer cannot
    // forward (a fifth of `crossing_blocks`'s samples on interior/caustic2).
    match &pn {
        Some(v) => crate::math::by_coordinates(v),
        None => n,
    }
}

/// A colour a call has just returned through memory, read field by field: `is_opaque` read
/// its filter and transmit as one 16-byte load over the callee's separate stores, which the
/// store buffer cannot forward (an eighth of `crossing_blocks`'s samples on
/// interior/caustic2). The same values.
#[inline(always)]
fn fresh_colour(c: &crate::color::Rgbft) -> crate::color::Rgbft {
    // SAFETY: reads of initialised fields through a reference.
    unsafe {
        crate::color::Rgbft {
            rgb: crate::math::by_coordinates(&c.rgb),
            filter: std::ptr::read_volatile(&c.filter),
            transmit: std::ptr::read_volatile(&c.transmit),
        }
    }
}
