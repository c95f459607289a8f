//! Tests of radiosity's tracer (radiosity.rs): the direction pool, the pretrace blocks, a
//! gathering point's own lights, kept crossings, and one plain layer shaded with radiosity.

use super::*;

#[test]
fn pool_is_cosine_weighted() {
    let pool = direction_pool(4000);
    // E[cos θ] over a cosine-weighted hemisphere is 2/3.
    let mean: f64 = pool
        .iter()
        .map(|(x, y)| (1.0 - x * x - y * y).max(0.0).sqrt())
        .sum::<f64>()
        / pool.len() as f64;
    assert!((mean - 2.0 / 3.0).abs() < 1e-3, "{mean}");
}

#[test]
fn pretrace_blocks_halve_to_the_end() {
    let set = RadiositySettings::default();
    assert_eq!(pretrace_blocks(&set, 160, 120), vec![12.8, 6.4]);
}

/// A scene from its text, built for a 24x18 picture, and its camera.
fn scene_24x18(text: &str) -> (Scene, crate::render::camera::Camera) {
    let mut parser = crate::sdl::Parser::new(crate::sdl::ParseOptions::default());
    parser.parse_str("test.pov", text).expect("parses");
    let scene = crate::scene::build::build(&parser.scene, 24, 18).scene;
    let camera = crate::render::camera::Camera::of_scene(&scene);
    (scene, camera)
}

/// A point whose lookup misses gathers a sample, and the gathering rays shade hits of their
/// own: the point is still lit by its own lights. (They replaced its list: a point that
/// gathered was lit as the last gathering ray's hit saw the lights.) With `brightness 0`
/// and no ambient, every pixel is then what the scene gives without radiosity, to the bit.
#[test]
fn a_point_that_gathers_keeps_its_own_lights() {
    let text = "#version 3.7;
        global_settings { assumed_gamma 1 radiosity { count 20 brightness 0 } }
        camera { location <0, 2, -4> look_at <0, 0, 0> }
        light_source { <3, 20, -2> rgb 1 }
        sphere { 0, 1000 hollow no_shadow pigment { rgb <0.3, 0.5, 1> }
                 finish { ambient 0 diffuse 0 emission 1 } }
        plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 0.8 } }
        box { <-1, 1, -1>, <1, 1.2, 1> pigment { rgb <1, 0.5, 0.2> }
              finish { ambient 0 diffuse 0.8 } }";
    let (scene, camera) = scene_24x18(text);
    let plain = Tracer::new(
        &scene,
        &camera,
        false,
        crate::render::trace::Quality::level(9),
    );
    let set = scene.radiosity.as_ref().expect("radiosity");
    // An empty cache: every lookup misses, so every lit point gathers.
    let mut cache = Cache::with_pool(direction_pool(set.count), 2);
    cache.file_new(set.error_bound, set.error_bound);
    let gathering = final_tracer(&plain, set, &cache);
    let mut ctx = Scratch::default();
    for y in 0..18 {
        for x in 0..24 {
            let (px, py) = (x as f64 + 0.5, y as f64 + 0.5);
            let want = plain.trace_camera_at(px, py, &mut ctx).rgb;
            let got = gathering.trace_camera_at(px, py, &mut ctx).rgb;
            assert_eq!(got.to_array(), want.to_array(), "pixel ({x}, {y})");
        }
    }
}

/// A camera ray traced from the crossing the completion passes keep (`camera_hit`, found
/// with another scratch) sees what it sees traced whole, to the bit, gathering the same
/// samples.
#[test]
fn a_kept_crossing_traces_as_the_ray() {
    let text = "#version 3.7;
        global_settings { assumed_gamma 1 radiosity { count 20 } }
        camera { location <0, 2, -4> look_at <0, 0, 0> }
        light_source { <3, 20, -2> rgb 1 }
        fog { fog_type 2 fog_alt 1 fog_offset 0 color rgb 0.8 distance 30 }
        plane { y, 0 pigment { rgb 1 } finish { diffuse 0.8 reflection 0.2 } }
        box { <-1, 0.5, -1>, <1, 1.2, 1> pigment { rgb <1, 0.5, 0.2> } }";
    let (scene, camera) = scene_24x18(text);
    let plain = Tracer::new(
        &scene,
        &camera,
        false,
        crate::render::trace::Quality::level(9),
    );
    let set = scene.radiosity.as_ref().expect("radiosity");
    let mut cache = Cache::with_pool(direction_pool(set.count), 2);
    cache.file_new(set.error_bound, set.error_bound);
    let tracer = final_tracer(&plain, set, &cache);
    let (mut ctx, mut own) = (Scratch::default(), Scratch::default());
    for y in 0..18 {
        for x in 0..24 {
            let ray = camera.ray(x as f64 + 0.5, y as f64 + 0.5).expect("a ray");
            ctx.rad_local.clear();
            let want = tracer.trace_pretrace(Some(ray), &mut ctx);
            let samples = ctx.rad_local.len();
            ctx.rad_local.clear();
            let hit = plain.camera_hit(&ray, &mut own);
            let got = tracer.trace_pretrace_hit(&ray, hit, &mut ctx);
            assert_eq!(got.rgb.to_array(), want.rgb.to_array(), "pixel ({x}, {y})");
            assert_eq!(got.clear.to_bits(), want.clear.to_bits());
            assert_eq!(ctx.rad_local.len(), samples);
        }
    }
}

/// With radiosity, a hit on one plain layer is shaded by `shade_single` as the layer loop
/// shades it, to the bit: the irradiance asked at the same normal, at the same point of the
/// sums. Two tracers, each with its own empty cache and scratch, shade the same hits one
/// each way; the samples each gathers then match too, so the caches stay alike hit by hit.
/// Camera-level and gathering-level hits, `normal on` and off, `#version 3.6`'s kept
/// ambient, a `diffuse 0` texture, reflections, filter and transmit.
#[test]
fn one_plain_layer_with_radiosity_is_the_layer_loop() {
    use crate::geom::test_rng::Lcg;
    use crate::math::Ray;
    use crate::render::layers::{single_plain, HitView, LayerSum};
    use crate::render::normal;
    use crate::render::trace::reflect;
    let body = "camera { location <0, 2, -4> look_at <0, 0, 0> }
        light_source { <3, 20, -2> rgb 1 }
        sphere { 0, 1000 hollow no_shadow pigment { rgb <0.3, 0.5, 1> }
                 finish { ambient 0 diffuse 0 emission 1 } }
        plane { y, 0 pigment { checker rgb 1 rgb 0.2 } finish { diffuse 0.8 reflection 0.1 } }
        sphere { <-1, 0.6, 0>, 0.6 pigment { rgbf <0.9, 0.9, 1, 0.6> }
                 finish { reflection { 0.1, 0.9 fresnel on } phong 0.6 } interior { ior 1.5 } }
        box { <0, 0, -1>, <1.5, 1.2, 1> pigment { rgbt <1, 0.5, 0.2, 0.2> }
              finish { ambient 0.3 diffuse 0.7 specular 0.4 } }";
    let texts = [
        format!("#version 3.7; global_settings {{ radiosity {{ count 20 }} }} {body}"),
        format!(
            "#version 3.7; global_settings {{ radiosity {{ count 12 normal on recursion_limit 3 }} }} {body}"
        ),
        format!("#version 3.6; global_settings {{ radiosity {{ count 16 }} }} {body}"),
    ];
    for text in &texts {
        let (scene, camera) = scene_24x18(text);
        let plain = Tracer::new(
            &scene,
            &camera,
            false,
            crate::render::trace::Quality::level(9),
        );
        let set = scene.radiosity.as_ref().expect("radiosity");
        let caches = [0, 1].map(|_| {
            let mut cache = Cache::with_pool(direction_pool(set.count), 2);
            cache.file_new(set.error_bound, set.error_bound);
            cache
        });
        let [one_way, loop_way] = [&caches[0], &caches[1]].map(|c| final_tracer(&plain, set, c));
        let (mut ctx1, mut ctx2) = (Scratch::default(), Scratch::default());
        let mut rng = Lcg(11);
        let mut checked = 0;
        for case in 0..600 {
            let origin = if case % 3 == 0 {
                rng.vec(1.5) + DVec3::new(0.0, 1.5, 0.0)
            } else {
                DVec3::new(0.0, 2.0, -4.0) + rng.vec(0.5)
            };
            let ray = Ray::new(origin, rng.vec(1.0) + DVec3::new(0.0, -0.4, 0.8));
            let Some(h) = scene.first_hit(&ray, f64::INFINITY, &mut ctx1) else {
                continue;
            };
            let p = ray.at(h.t);
            let dir = ray.dir.normalize();
            let n = h.obj.normal(p, &h);
            let entering = n.dot(dir) < 0.0;
            let nf = if entering { n } else { -n };
            let top = h.obj.texture_facing(&h, !entering);
            let mirror = reflect(dir, nf);
            let bumpy = normal::texture_perturbs(top);
            if !single_plain(top, bumpy, mirror) || top.uses_uv() {
                continue;
            }
            let (n1, n2) = if entering {
                (1.0, h.obj.ior)
            } else {
                (h.obj.ior, 1.0)
            };
            // A camera ray's hit, or a gathering ray's (of a sample of level 1).
            let path = if case % 2 == 0 {
                Path::CAMERA
            } else {
                Path::CAMERA.gathering(1)
            };
            let hv = HitView {
                p,
                dir,
                nf,
                mirror,
                cos_i: (-dir.dot(nf)).clamp(0.0, 1.0),
                n1,
                n2,
                entering,
                obj: h.obj,
                uv: &None,
                path,
            };
            let deeper = path.rad_level > 0;
            one_way.gather_lights(p, nf, bumpy, h.obj, deeper, &mut ctx1);
            let one = one_way.shade_single(top, &hv, None, &mut ctx1);
            loop_way.gather_lights(p, nf, bumpy, h.obj, deeper, &mut ctx2);
            let mut sum = LayerSum::new();
            loop_way.shade_layers(top, &hv, &mut sum, &mut ctx2);
            assert!(sum.bent.is_empty(), "case {case}");
            let all = sum.out;
            let bits = |v: DVec3| v.to_array().map(f64::to_bits);
            for (a, b) in [
                (one.col, all.col),
                (one.through, all.through),
                (one.refl_amount, all.refl_amount),
                (one.refl_tinted, all.refl_tinted),
                (one.refl_all_tinted, all.refl_all_tinted),
            ] {
                assert_eq!(bits(a), bits(b), "case {case}");
            }
            let last = |c: crate::color::Rgbft| c.to_array().map(f64::to_bits);
            assert_eq!(last(one.last), last(all.last), "case {case}");
            assert_eq!(one.conserve, all.conserve);
            assert_eq!(
                one.refl_power.map(f64::to_bits),
                all.refl_power.map(f64::to_bits)
            );
            assert_eq!(ctx1.rad_local.len(), ctx2.rad_local.len(), "case {case}");
            checked += 1;
        }
        assert!(checked > 200, "{checked} hits checked");
        assert!(!ctx1.rad_local.is_empty(), "no hit gathered");
    }
}
