//! Photon mapping (manual 3.4.4.4): before the picture, photons are shot from each light at
//! each `target` object, followed through the surfaces that refract or reflect them, and
//! stored where they land on other surfaces; shading then adds the light of the photons found
//! around the shaded point, as a light from straight above the surface (no highlights).
//!
//! Measured with povray 3.7 (tests/probes_stochastic, docs/photons.md):
//! - a light without a `photons` block shoots photons that refract and reflect; in the block,
//!   what is not named stays on;
//! - light through a slab of ior 1 made a refracting target comes back at the direct light's
//!   strength wherever it lands (0.99 to 1.01 of it, at any distance from the light and at
//!   oblique incidence): a photon carries the light of its solid angle at the distance it
//!   travelled, lights having no distance falloff;
//! - photons are shot in rings around the line from the light to the centre of the target's
//!   bounding sphere, `spacing` apart at that centre's distance (the number shot matches
//!   π·(θmax/dθ)² with dθ = spacing / distance);
//! - a shadow edge through the ior-1 slab falls to half at the edge and back to full over
//!   about 5 photon spacings: the estimate is the photons' light over the area of a disc of
//!   that radius (the manual's own advice: a radius 5 times the spacing);
//! - a refracting target no longer lets lights that shoot refraction photons through in
//!   shadow tests (render/shadow.rs): its light arrives as photons only.
//!
//! Deterministic: rings are shot in parallel but kept in ring order, each photon's jitter
//! comes from a hash of its light, target, ring and place in the ring.

use rayon::prelude::*;

use crate::math::{DVec3, Ray};
use crate::scene::build::Scene;
use crate::scene::light::Light;
use crate::scene::object::{ObjKind, Object, Scratch};
use crate::scene::photon::{flags, PhotonSettings};

use super::photon_tree::{Photon, PhotonTree};
use super::texture_map;
use super::trace::LitBy;

/// The estimate's radius in photon spacings on the surface, measured (see above).
const RADIUS_SPACINGS: f64 = 5.0;

/// How much wider the second search is when the first finds fewer than `gather` minimum
/// (tried 1.5, 2 and 3 against povray's glass-sphere caustic: 2 is closest).
const EXPAND: f32 = 2.0;

/// Rings shot in parallel between two autostop checks.
const RING_BATCH: usize = 64;

pub struct PhotonMap {
    tree: PhotonTree,
    radius: f32,
    gather_min: usize,
    gather_max: usize,
    /// Photons shot, for the statistics.
    pub shot: u64,
}

/// What a photon path needs to know as it goes.
struct Shooter<'s> {
    scene: &'s Scene,
    light: &'s Light,
    max_level: u32,
    bailout: f64,
}

impl PhotonMap {
    /// Shoots the scene's photons; None without `photons { }` in global_settings.
    pub fn shoot(scene: &Scene) -> Option<PhotonMap> {
        let set = scene.photons.as_ref()?;
        let loaded = set.load_file.as_ref().and_then(|f| {
            match std::fs::read(f).map_err(|e| e.to_string()).and_then(|b| super::photon_file::decode(&b)) {
                Ok(map) => Some(map),
                Err(e) => {
                    eprintln!("lancer: warning: cannot load the photon map {f} ({e}); shooting photons instead");
                    None
                }
            }
        });
        let (photons, auto_radius, shot) = match loaded {
            Some((photons, radius)) => (photons, radius as f64, 0),
            None => shoot_all(scene, set),
        };
        if let Some(f) = &set.save_file {
            if let Err(e) =
                std::fs::write(f, super::photon_file::encode(&photons, auto_radius as f32))
            {
                eprintln!("lancer: warning: cannot save the photon map {f} ({e})");
            }
        }
        if std::env::var_os("LANCER_PHOTON_STATS").is_some() {
            eprintln!(
                "photons: {shot} shot, {} stored, estimated radius {auto_radius}",
                photons.len()
            );
        }
        let radius = set.radius.unwrap_or(auto_radius) * set.radius_mult;
        Some(PhotonMap {
            tree: PhotonTree::new(photons),
            radius: radius as f32,
            gather_min: set.gather_min as usize,
            gather_max: set.gather_max.max(1) as usize,
            shot,
        })
    }

    /// The photons' light at a shaded point of `obj`, as a light straight above the surface
    /// that makes no highlights; None where there is none or `obj` does not collect photons.
    pub fn caustic(
        &self,
        p: DVec3,
        nf: DVec3,
        obj: &Object,
        found: &mut Vec<(f32, u32)>,
    ) -> Option<LitBy> {
        if obj.photons & flags::NO_COLLECT != 0 {
            return None;
        }
        let e = self.irradiance(p, nf, found);
        (e != DVec3::ZERO).then_some(LitBy {
            color: e,
            l: nf,
            cos_n: 1.0,
            shadowless: true,
            back: false,
            slot: u32::MAX,
        })
    }

    pub fn stored(&self) -> usize {
        self.tree.len()
    }

    /// The photons' light arriving at `p` on a surface facing `n` (towards the viewer): their
    /// power over the area of the disc they were gathered in. `found` is scratch space.
    pub fn irradiance(&self, p: DVec3, n: DVec3, found: &mut Vec<(f32, u32)>) -> DVec3 {
        if self.tree.is_empty() {
            return DVec3::ZERO;
        }
        let q = [p.x as f32, p.y as f32, p.z as f32];
        let (sum, count, r2) = self.gather(q, n, self.radius, found);
        // The adaptive search (manual 3.4.4.4.9.2): too few photons widen the disc. The
        // manual's thresholds would then often keep the narrow search; povray's pictures keep
        // the wide one (measured: the glow beside a glass sphere's caustic, where the narrow
        // disc finds nothing, matches only with the widened search taken, SSIM 0.991 against
        // 0.988 with the thresholds and 0.985 without widening).
        let (sum, r2) = if count < self.gather_min {
            let (wsum, _, wr2) = self.gather(q, n, self.radius * EXPAND, found);
            (wsum, wr2)
        } else {
            (sum, r2)
        };
        if sum == DVec3::ZERO {
            return DVec3::ZERO;
        }
        sum / (std::f64::consts::PI * r2.max(1e-12) as f64)
    }

    /// The power of the photons near `q` that reached the side facing `n` and lie near its
    /// tangent plane: (sum, how many, squared radius of the disc).
    fn gather(
        &self,
        q: [f32; 3],
        n: DVec3,
        radius: f32,
        found: &mut Vec<(f32, u32)>,
    ) -> (DVec3, usize, f32) {
        let r2 = self.tree.nearest(q, radius, self.gather_max, found);
        let ph = self.tree.photons();
        let r = r2.sqrt();
        let mut sum = DVec3::ZERO;
        let mut count = 0;
        for &(_, i) in found.iter() {
            let f = &ph[i as usize];
            let dir = DVec3::new(f.dir[0] as f64, f.dir[1] as f64, f.dir[2] as f64);
            if dir.dot(n) >= 0.0 {
                continue;
            }
            // Photons on another surface close by (the far side of a thin object, a floor
            // under a wall) are not this surface's.
            let off = DVec3::new(
                (f.pos[0] - q[0]) as f64,
                (f.pos[1] - q[1]) as f64,
                (f.pos[2] - q[2]) as f64,
            );
            if off.dot(n).abs() > 0.25 * r as f64 {
                continue;
            }
            sum += DVec3::new(f.power[0] as f64, f.power[1] as f64, f.power[2] as f64);
            count += 1;
        }
        (sum, count, r2)
    }
}

/// Shoots every light's photons at every target: the photons stored, the gather radius
/// estimated for them, and how many were shot.
fn shoot_all(scene: &Scene, set: &PhotonSettings) -> (Vec<Photon>, f64, u64) {
    let targets = targets(&scene.objects);
    let spacing = match (set.spacing, set.count) {
        (Some(s), _) => s,
        (None, Some(n)) => spacing_for_count(scene, &targets, n),
        (None, None) => 0.1,
    }
    .max(1e-6);
    let mut photons = Vec::new();
    let mut shot = 0u64;
    let mut ratios = Vec::new();
    for (li, light) in scene.lights.iter().enumerate() {
        if !(light.photons.refraction || light.photons.reflection) {
            continue;
        }
        let shooter = Shooter {
            scene,
            light,
            max_level: set.max_trace_level.unwrap_or(scene.max_trace_level),
            bailout: set.adc_bailout.unwrap_or(scene.adc_bailout),
        };
        for (ti, t) in targets.iter().enumerate() {
            let s = spacing * t.photon_mult as f64;
            let (p, n, ratio) = shooter.shoot_target(t, s, set, (li as u64) << 32 | ti as u64);
            photons.extend(p);
            shot += n;
            ratios.push((ratio, s));
        }
    }
    // The radius: about 5 photon spacings where the photons land. A photon's spacing there
    // is the shooting spacing scaled by how far it went against the target's distance.
    let surface_spacing = ratios
        .iter()
        .map(|(r, s)| r * s)
        .fold(0.0f64, f64::max)
        .max(spacing);
    (photons, surface_spacing * RADIUS_SPACINGS, shot)
}

/// Whether shadow rays of lights that shoot refraction photons stop at `obj`: a refracting
/// target (measured: povray's glass sphere target casts a dark shadow filled by its caustic
/// only while the light shoots refraction photons; a target that only reflects, or a
/// refracting object that is not a target, lets light through as without photons).
pub fn refracts_photons(obj: &Object) -> bool {
    let both = flags::TARGET | flags::REFRACTION;
    obj.photons & both == both
}

/// Objects photons are shot at: those with `target`, a CSG as a whole.
fn targets(objects: &[Object]) -> Vec<&Object> {
    let mut out = Vec::new();
    fn walk<'a>(o: &'a Object, out: &mut Vec<&'a Object>) {
        if o.photons & flags::TARGET != 0 {
            out.push(o);
            return;
        }
        if let ObjKind::Csg { children, .. } = &o.kind {
            for c in children {
                walk(c, out);
            }
        }
    }
    for o in objects {
        walk(o, &mut out);
    }
    out
}

/// A target's bounding sphere.
fn sphere(o: &Object) -> (DVec3, f64) {
    let b = &o.bounds;
    let (lo, hi) = (b.min, b.max);
    ((lo + hi) * 0.5, (hi - lo).length() * 0.5)
}

/// The spacing that shoots about `count` photons in all: each light and target pair takes
/// π·(θmax·d / spacing)² photons.
fn spacing_for_count(scene: &Scene, targets: &[&Object], count: f64) -> f64 {
    let mut area = 0.0;
    for light in &scene.lights {
        if !(light.photons.refraction || light.photons.reflection) {
            continue;
        }
        for t in targets {
            let (c, r) = sphere(t);
            let m = t.photon_mult as f64;
            area += match light.parallel {
                Some(_) => std::f64::consts::PI * r * r / (m * m),
                None => {
                    let d = (c - light.position).length();
                    let theta = if d <= r {
                        std::f64::consts::PI
                    } else {
                        (r / d).asin()
                    };
                    std::f64::consts::PI * (theta * d).powi(2) / (m * m)
                }
            };
        }
    }
    (area / count.max(1.0)).sqrt()
}

impl Shooter<'_> {
    /// Shoots one target: the photons stored, how many were shot, and the largest ratio of a
    /// stored photon's path length to the target's distance (how much the spacing grows
    /// where photons land).
    fn shoot_target(
        &self,
        t: &Object,
        spacing: f64,
        set: &PhotonSettings,
        key: u64,
    ) -> (Vec<Photon>, u64, f64) {
        let (c, r) = sphere(t);
        if !r.is_finite() || r <= 0.0 {
            return (Vec::new(), 0, 1.0);
        }
        if let Some(dir) = self.light.parallel {
            return self.shoot_parallel(c, r, dir, spacing, set, key);
        }
        let to = c - self.light.position;
        let d = to.length();
        let w = to.normalize_or(DVec3::Z);
        let theta_max = if d <= r {
            std::f64::consts::PI
        } else {
            (r / d).asin()
        };
        let dtheta = (spacing / d.max(1e-9)).min(theta_max.max(1e-6));
        let rings = (theta_max / dtheta).ceil() as usize + 1;
        let (u, v) = frame(w);
        let mut out = Vec::new();
        let mut shot = 0u64;
        let mut any_hit = false;
        let mut start = 0;
        while start < rings {
            let end = (start + RING_BATCH).min(rings);
            let batch: Vec<(Vec<Photon>, u64, bool)> = (start..end)
                .into_par_iter()
                .map_init(Scratch::default, |ctx, i| {
                    let mut ring = Vec::new();
                    let theta = i as f64 * dtheta;
                    let n = if i == 0 {
                        1
                    } else {
                        ((std::f64::consts::TAU * theta.sin() / dtheta).round() as usize).max(1)
                    };
                    let lo = (theta - 0.5 * dtheta).max(0.0);
                    let hi = (theta + 0.5 * dtheta).min(std::f64::consts::PI);
                    let omega = std::f64::consts::TAU * (lo.cos() - hi.cos()) / n as f64;
                    let mut hit = false;
                    for j in 0..n {
                        let h = hash(key, i as u64, j as u64);
                        let jt = if i == 0 {
                            0.0
                        } else {
                            set.jitter * (unit(h) - 0.5)
                        };
                        let jp = set.jitter * (unit(h >> 21) - 0.5);
                        let th = (theta + jt * dtheta).clamp(0.0, std::f64::consts::PI);
                        let phi = (j as f64 + 0.5 + jp) * std::f64::consts::TAU / n as f64;
                        let dir = w * th.cos() + (u * phi.cos() + v * phi.sin()) * th.sin();
                        let beam = self.light.beam(self.light.position + dir);
                        if beam <= 0.0 {
                            continue;
                        }
                        let power = self.light.color * (beam * omega);
                        let ray = Ray::new(self.light.position, dir);
                        hit |=
                            self.trace(&ray, power, 1.0, 0.0, 1, false, true, None, ctx, &mut ring);
                    }
                    (ring, n as u64, hit)
                })
                .collect();
            for (i, (ring, n, hit)) in batch.into_iter().enumerate() {
                out.extend(ring);
                shot += n;
                any_hit |= hit;
                // Autostop: a whole ring missing the target once past the autostop share of
                // the target, after something was hit, ends the shooting.
                let ring_i = start + i;
                let past = ring_i as f64 * dtheta >= set.autostop * theta_max;
                if any_hit && !hit && past && ring_i > 0 {
                    let ratio = median_ratio(&out, self.light.position, d);
                    return (out, shot, ratio);
                }
            }
            start = end;
        }
        let ratio = median_ratio(&out, self.light.position, d);
        (out, shot, ratio)
    }

    /// A parallel light: photons on a square grid `spacing` apart across the target's
    /// bounding sphere, each carrying the light of its square.
    fn shoot_parallel(
        &self,
        c: DVec3,
        r: f64,
        dir: DVec3,
        spacing: f64,
        set: &PhotonSettings,
        key: u64,
    ) -> (Vec<Photon>, u64, f64) {
        let (u, v) = frame(dir);
        let n = (r / spacing).ceil() as i64;
        // From the plane through the light's location, perpendicular to the beam.
        let back = (c - self.light.position).dot(dir);
        let centre = c - dir * back;
        let rows: Vec<(Vec<Photon>, u64)> = (-n..=n)
            .into_par_iter()
            .map_init(Scratch::default, |ctx, i| {
                let mut row = Vec::new();
                let mut shot = 0;
                for j in -n..=n {
                    let h = hash(key, i as u64, j as u64);
                    let a = (i as f64 + set.jitter * (unit(h) - 0.5)) * spacing;
                    let b = (j as f64 + set.jitter * (unit(h >> 21) - 0.5)) * spacing;
                    if a * a + b * b > r * r {
                        continue;
                    }
                    shot += 1;
                    let o = centre + u * a + v * b;
                    let power = self.light.color * (self.light.beam(o) * spacing * spacing);
                    self.trace(
                        &Ray::new(o, dir),
                        power,
                        1.0,
                        0.0,
                        1,
                        false,
                        false,
                        None,
                        ctx,
                        &mut row,
                    );
                }
                (row, shot)
            })
            .collect();
        let mut out = Vec::new();
        let mut shot = 0;
        for (row, s) in rows {
            out.extend(row);
            shot += s;
        }
        (out, shot, 1.0)
    }

    /// Follows one photon: `power` is its light (per unit of squared path length for point
    /// lights, `spread`), `weight` its share of what was shot (for adc_bailout), `len` the
    /// distance travelled so far. Returns whether its first surface was a target.
    #[allow(clippy::too_many_arguments)]
    fn trace<'a>(
        &'a self,
        ray: &Ray,
        power: DVec3,
        weight: f64,
        len: f64,
        level: u32,
        bounced: bool,
        spread: bool,
        wave: Option<f32>,
        ctx: &mut Scratch<'a>,
        out: &mut Vec<Photon>,
    ) -> bool {
        if level > self.max_level || weight < self.bailout {
            return false;
        }
        let Some(h) = self.scene.first_hit(ray, f64::INFINITY, ctx) else {
            return false;
        };
        let obj = h.obj;
        let f = obj.photons;
        let p = ray.at(h.t);
        let len = len + h.t * ray.dir.length();
        let interacts = f & (flags::REFRACTION | flags::REFLECTION) != 0;
        if !bounced && f & flags::PASS_THROUGH != 0 {
            // On its way to a target a photon passes through `pass_through` objects unchanged
            // (measured: a `no_shadow` target, pass_through by default, makes no caustic).
            let on = Ray::new(p, ray.dir);
            return self.trace(
                &on, power, weight, len, level, bounced, spread, wave, ctx, out,
            );
        }
        // Measured: a refracting sphere stores one photon per photon through it (the floor's),
        // none where photons leave the glass.
        if bounced && !interacts && f & flags::NO_COLLECT == 0 {
            let k = if spread { len * len } else { 1.0 } * self.light.fade(len);
            let e = power * k;
            let d = ray.dir.normalize_or_zero();
            out.push(Photon {
                pos: [p.x as f32, p.y as f32, p.z as f32],
                dir: [d.x as f32, d.y as f32, d.z as f32],
                power: [e.x as f32, e.y as f32, e.z as f32],
            });
        }
        if !interacts {
            return false;
        }
        let dir = ray.dir.normalize_or_zero();
        // By coordinates, as in `shade`: `Object::normal` may store x and y apart.
        let n = crate::math::by_coordinates(&obj.normal(p, &h));
        let entering = n.dot(dir) < 0.0;
        let nf = if entering { n } else { -n };
        let cos_i = (-dir.dot(nf)).clamp(0.0, 1.0);
        let ior = super::dispersion::ior(obj, wave);
        let (n1, n2) = if entering { (1.0, ior) } else { (ior, 1.0) };
        // The surface's colours and finishes, as shading sees them.
        let top = obj.texture_facing(&h, !entering);
        let uv = if top.uses_uv() {
            obj.uv_point(p, &h)
        } else {
            None
        };
        let mut through = DVec3::ONE;
        let mut refl = DVec3::ZERO;
        let mut conserve = false;
        for tex in top.layers() {
            let mut layer_t = DVec3::ZERO;
            texture_map::blend(tex, p, uv, false, 1.0, &mut |c, part, _, w| {
                let fin = &part.finish;
                let r = &fin.reflection;
                if !r.is_zero() {
                    let k = if r.min == r.max {
                        0.0
                    } else if r.fresnel {
                        super::trace::fresnel(cos_i, n1, n2)
                    } else {
                        (1.0 - cos_i).powf(r.falloff)
                    };
                    let amount = (r.min + (r.max - r.min) * k) * w;
                    refl += through * amount * super::metallic::tint(c.rgb, r.metallic, cos_i);
                }
                conserve |= fin.conserve_energy;
                layer_t += c.transmitted() * w;
            });
            through *= layer_t;
        }
        if conserve {
            through *= (DVec3::ONE - refl).max(DVec3::ZERO);
        }
        // Light travelling inside a fading interior is dimmed when it leaves.
        if !entering {
            if let Some(int) = &obj.interior {
                through *= int.fade(h.t * ray.dir.length());
            }
        }
        let mirror = super::trace::reflect(dir, nf);
        if f & flags::REFRACTION != 0 && self.light.photons.refraction && through != DVec3::ZERO {
            let bend = |n2: f64| super::trace::refract(dir, nf, cos_i, n1, n2).unwrap_or(mirror);
            let w = weight * through.max_element();
            let split = match wave {
                None if entering => super::dispersion::of(obj),
                _ => None,
            };
            match split {
                None => {
                    let ray = Ray::new(p, bend(n2));
                    let power = power * through;
                    self.trace(&ray, power, w, len, level + 1, true, spread, wave, ctx, out);
                }
                Some((_, count)) => {
                    // Photons entering a dispersing object go on as `count` colours.
                    for (t, c) in super::dispersion::samples(count) {
                        let ray = Ray::new(p, bend(super::dispersion::ior(obj, Some(t))));
                        let power = power * through * c;
                        let w = w * c.max_element();
                        self.trace(
                            &ray,
                            power,
                            w,
                            len,
                            level + 1,
                            true,
                            spread,
                            Some(t),
                            ctx,
                            out,
                        );
                    }
                }
            }
        }
        if f & flags::REFLECTION != 0 && self.light.photons.reflection && refl != DVec3::ZERO {
            let w = weight * refl.max_element();
            self.trace(
                &Ray::new(p, mirror),
                power * refl,
                w,
                len,
                level + 1,
                true,
                spread,
                wave,
                ctx,
                out,
            );
        }
        f & flags::TARGET != 0
    }
}

fn median_ratio(photons: &[Photon], from: DVec3, d: f64) -> f64 {
    // The median over stored photons of (distance from the light / target distance): a
    // robust stand-in for how much the spacing has grown where photons land.
    let mut r: Vec<f64> = photons
        .iter()
        .map(|p| {
            let q = DVec3::new(p.pos[0] as f64, p.pos[1] as f64, p.pos[2] as f64);
            (q - from).length() / d.max(1e-9)
        })
        .collect();
    if r.is_empty() {
        return 1.0;
    }
    let mid = r.len() / 2;
    r.select_nth_unstable_by(mid, f64::total_cmp);
    r[mid]
}

/// Two unit vectors perpendicular to `w` and to each other.
fn frame(w: DVec3) -> (DVec3, DVec3) {
    let a = if w.x.abs() < 0.9 { DVec3::X } else { DVec3::Y };
    let u = w.cross(a).normalize();
    (u, w.cross(u))
}

fn hash(key: u64, i: u64, j: u64) -> u64 {
    let mut h = key.wrapping_mul(0x9E37_79B9_7F4A_7C15)
        ^ i.wrapping_mul(0xC2B2_AE3D_27D4_EB4F)
        ^ j.wrapping_mul(0x1656_67B1_9E37_79F9);
    h ^= h >> 33;
    h = h.wrapping_mul(0xFF51_AFD7_ED55_8CCD);
    h ^= h >> 33;
    h
}

fn unit(h: u64) -> f64 {
    (h & 0x1F_FFFF) as f64 / (1u64 << 21) as f64
}
