//! Every object, camera and light keyword of the POV-Ray 3.7 manual parses without a "not
//! supported" warning. The snippets cover the syntax blocks of the manual's sections 3.4.2
//! (camera), 3.4.4.1-2 (light sources, light groups) and 3.4.5 (objects and object modifiers):
//! every lowercase word of those blocks that is a keyword (extracted from
//! /usr/share/doc/povray/html/r3_4.html and checked to parse with povray 3.7.0). Keywords
//! lancer still warns about are listed beside their snippet, so that fixing one fails this test
//! until the list is shortened, and a new warning fails it at once.

use lancer::sdl::{ParseOptions, Parser};

/// (snippet, parts of the "not supported" warnings it still gives).
const SNIPPETS: &[(&str, &[&str])] = &[
    ("camera { perspective location <0,1,-5> look_at 0 right x*4/3 up y sky y angle 60 }", &[]),
    ("camera { orthographic location <0,1,-5> look_at 0 }", &[]),
    ("camera { fisheye angle 180 }", &[]),
    ("camera { ultra_wide_angle angle 170 }", &[]),
    ("camera { omnimax }", &[]),
    ("camera { panoramic }", &[]),
    ("camera { cylinder 1 angle 90 }", &[]),
    ("camera { cylinder 2 angle 90 }", &[]),
    ("camera { cylinder 3 angle 90 }", &[]),
    ("camera { cylinder 4 angle 90 }", &[]),
    ("camera { spherical angle 360, 180 }", &[]),
    ("camera { location <0,0,-5> direction z*2 look_at 0 aperture 0.4 blur_samples 4, 16 focal_point 0 confidence 0.9 variance 1/128 }", &[]),
    ("camera { location <0,0,-5> aperture 0.4 blur_samples 8 focal_point 0 bokeh { pigment { rgb 1 } } }", &[]),
    ("camera { location <0,0,-5> normal { bumps 0.1 } }", &[]),
    ("camera { mesh_camera { 1 3 mesh { smooth_triangle { <0,0,0>, z, <1,0,0>, z, <0,1,0>, z } } smooth } location 0 direction z }", &[]),
    ("light_source { <0,5,-5> rgb 1 }", &[]),
    ("light_source { <0,5,-5> rgb 1 spotlight point_at 0 radius 10 falloff 20 tightness 5 }", &[]),
    ("light_source { <0,5,-5> rgb 1 cylinder point_at 0 radius 1 falloff 2 tightness 1 }", &[]),
    ("light_source { <0,5,-5> rgb 1 parallel point_at 0 }", &[]),
    ("light_source { <0,5,-5> rgb 1 area_light x, y, 4, 4 adaptive 1 jitter circular orient area_illumination on }", &[]),
    ("light_source { <0,5,-5> rgb 1 shadowless }", &[]),
    ("light_source { <0,5,-5> rgb 1 looks_like { sphere { 0, 0.1 } } }", &[]),
    ("light_source { <0,5,-5> rgb 1 projected_through { sphere { 0, 0.1 } } }", &[]),
    ("light_source { <0,5,-5> rgb 1 fade_distance 2 fade_power 2 media_interaction off media_attenuation on }", &[]),
    ("light_group { light_source { <0,5,-5> rgb 1 } sphere { 0, 1 } global_lights off }", &[]),
    ("blob { threshold 0.5 sphere { 0, 1, 1 } cylinder { 0, x, 1, 1 } component 1, 1, <0,1,0> sturm hierarchy off }", &[]),
    ("box { -1, 1 }", &[]),
    ("cone { 0, 1, y, 0.5 open }", &[]),
    ("cylinder { 0, y, 1 open }", &[]),
    ("height_field { function 16, 16 { x*y } smooth water_level 0.1 hierarchy off }", &[]),
    ("isosurface { function { x*x+y*y+z*z-1 } contained_by { box { -2, 2 } } threshold 0 accuracy 0.001 max_gradient 4 evaluate 5, 1.2, 0.95 max_trace 2 open }", &[]),
    ("isosurface { function { x*x+y*y+z*z-1 } contained_by { sphere { 0, 2 } } all_intersections }", &[]),
    ("julia_fractal { <-0.083,0,-0.83,-0.025> quaternion sqr max_iteration 8 precision 15 slice <0,0,0,1>, 0 }", &[]),
    ("julia_fractal { <-0.083,0,-0.83,-0.025> quaternion cube }", &[]),
    ("julia_fractal { <-0.083,0,-0.83,-0.025> hypercomplex pwr(2, 0.5) }", &[]),
    ("lathe { linear_spline 3, <0,0>, <1,1>, <0,2> sturm }", &[]),
    ("lathe { quadratic_spline 4, <0,0>, <1,1>, <0.5,2>, <0,3> }", &[]),
    ("lathe { cubic_spline 5, <0,0>, <1,1>, <0.5,2>, <0.3,3>, <0,4> }", &[]),
    ("lathe { bezier_spline 4, <0,0>, <1,1>, <0.5,2>, <0,3> }", &[]),
    ("ovus { 1, 0.5 }", &[]),
    ("parametric { function { u } function { v } function { 0 } <0,0>, <1,1> contained_by { box { -2, 2 } } max_gradient 2 accuracy 0.001 precompute 10 x, y, z }", &[]),
    ("prism { linear_sweep linear_spline 0, 1, 4, <0,0>, <1,0>, <0,1>, <0,0> open sturm }", &[]),
    ("prism { conic_sweep quadratic_spline 0.5, 1, 6, <0,1>, <0,0>, <1,0>, <1,1>, <0,1>, <0,0> }", &[]),
    ("prism { cubic_spline 0, 1, 7, <0,1>, <0,0>, <1,0>, <1,1>, <0,1>, <0,0>, <1,0> }", &[]),
    ("prism { bezier_spline 0, 1, 4, <0,0>, <1,0>, <1,1>, <0,0> }", &[]),
    ("sphere { 0, 1 }", &[]),
    ("sphere_sweep { linear_spline 2, <0,0,0>, 0.5, <1,0,0>, 0.5 tolerance 1e-6 }", &[]),
    ("sphere_sweep { b_spline 4, <0,0,0>, 0.5, <1,0,0>, 0.5, <1,1,0>, 0.5, <0,1,0>, 0.5 }", &[]),
    ("sphere_sweep { cubic_spline 4, <0,0,0>, 0.5, <1,0,0>, 0.5, <1,1,0>, 0.5, <0,1,0>, 0.5 }", &[]),
    ("superellipsoid { <0.5, 0.5> }", &[]),
    ("sor { 4, <0,0>, <1,1>, <0.5,2>, <0,3> open sturm }", &[]),
    ("text { ttf \"timrom.ttf\" \"Hi\" 1, 0 }", &[]),
    ("torus { 1, 0.25 sturm }", &[]),
    ("bicubic_patch { type 1 flatness 0.01 u_steps 3 v_steps 3 <0,0,0>, <1,0,0>, <2,0,0>, <3,0,0>, <0,0,1>, <1,1,1>, <2,1,1>, <3,0,1>, <0,0,2>, <1,1,2>, <2,1,2>, <3,0,2>, <0,0,3>, <1,0,3>, <2,0,3>, <3,0,3> }", &[]),
    ("disc { 0, y, 1, 0.5 }", &[]),
    ("mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } smooth_triangle { <0,0,0>, y, <1,0,0>, y, <0,0,1>, y } inside_vector y hierarchy on }", &[]),
    ("mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } normal_vectors { 1, z } uv_vectors { 3, <0,0>, <1,0>, <0,1> } texture_list { 1, texture { pigment { rgb 1 } } } face_indices { 1, <0,1,2>, 0 } normal_indices { 1, <0,0,0> } uv_indices { 1, <0,1,2> } }", &[]),
    ("polygon { 4, <0,0>, <1,0>, <0,1>, <0,0> }", &[]),
    ("triangle { <0,0,0>, <1,0,0>, <0,1,0> }", &[]),
    ("smooth_triangle { <0,0,0>, y, <1,0,0>, y, <0,0,1>, y }", &[]),
    ("plane { y, 0 }", &[]),
    ("poly { 2, <1,0,0,0,1,0,0,1,0,-1> sturm }", &[]),
    ("cubic { <1,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,-1> }", &[]),
    ("quartic { <1,0,0,0,2,0,0,2,0,-2.5,0,0,0,0,0,0,0,0,0,0,1,0,0,2,0,0.5,0,1,0,-1.5,0,0,0,0,-0.5> }", &[]),
    ("polynomial { 2, xyz(2,0,0):1, xyz(0,2,0):1, xyz(0,0,2):1, xyz(0,0,0):-1 }", &[]),
    ("quadric { <1,1,1>, <0,0,0>, <0,0,0>, -1 }", &[]),
    ("union { sphere { 0, 1 } box { 0, 2 } split_union off }", &[]),
    ("intersection { sphere { 0, 1 } box { 0, 2 } }", &[]),
    ("difference { sphere { 0, 1 } box { 0, 2 } }", &[]),
    ("merge { sphere { 0, 1 } box { 0, 2 } }", &[]),
    ("object { sphere { 0, 1 } clipped_by { plane { y, 0 } } bounded_by { box { -1, 1 } } hollow inverse no_shadow no_image no_reflection double_illuminate no_radiosity material { texture { pigment { rgb 1 } } interior { ior 1.5 } } interior_texture { pigment { rgb 1 } } photons { target } radiosity { importance 0.5 } }", &[]),
];

#[test]
fn manual_keywords_parse_without_unsupported_warnings() {
    let mut failures = Vec::new();
    for (snippet, left) in SNIPPETS {
        let src = format!(
            "#version 3.7;\nglobal_settings {{ assumed_gamma 1 }}\nsphere {{ 0, 1 }}\n{snippet}\n"
        );
        let mut p = Parser::new(ParseOptions::default());
        if let Err(e) = p.parse_str("snippet.pov", &src) {
            failures.push(format!("{snippet}: {}", e.one_line(&p.sources)));
            continue;
        }
        let unsupported: Vec<&str> = p
            .warnings
            .iter()
            .map(|w| w.message.as_str())
            .filter(|m| m.contains("not supported"))
            .collect();
        for w in &unsupported {
            if !left.iter().any(|k| w.contains(k)) {
                failures.push(format!("{snippet}: unexpected warning {w}"));
            }
        }
        for k in left.iter() {
            if !unsupported.iter().any(|w| w.contains(k)) {
                failures.push(format!(
                    "{snippet}: '{k}' no longer warns; remove it from the list"
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
