//! Size bounds on the per-object types: a scene of a million spheres holds a million of each,
//! so a field that grows them by a few hundred bytes costs hundreds of megabytes (measured
//! with scripts/scale_bench.sh, docs/performance.md "Scale and memory"). The bounds are the
//! sizes on x86-64 with a little room; raise one only knowingly.

use std::mem::size_of;

use lancer::scene::desc::{ObjectDesc, Pigment, ShapeDesc, Texture};
use lancer::scene::object::Object;

#[test]
fn per_object_types_stay_small() {
    // Inline transforms (256 bytes each), textures and light sources made these 1392, 224,
    // 824, 352 and 464 bytes (inline mesh and blob data another 48 on the last).
    // ObjectDesc 192 -> 200 knowingly: an object's `photons { }` flags and target spacing
    // (3 bytes, but the struct had no padding left); 8 MB per million object descriptions.
    // 200 -> 208 knowingly: the interior's `dispersion` (f32) and `dispersion_samples` (u16),
    // held inline like the rest of the interior; another 8 MB per million.
    // 208 -> 216 knowingly: the interior's `caustics` (f32); the interior had two bytes of
    // padding left. 8 MB per million object descriptions, which are freed before the BVH is
    // built.
    assert!(
        size_of::<ObjectDesc>() <= 216,
        "{}",
        size_of::<ObjectDesc>()
    );
    assert!(size_of::<ShapeDesc>() <= 80, "{}", size_of::<ShapeDesc>());
    // Texture 320 -> 336 and Pigment 104 -> 112 knowingly: `crand` in the finish and the
    // `uv_mapping` flags of texture and pigment. Objects given a declared texture share it
    // (test below), so few objects hold a copy of their own. 336 -> 344 knowingly: the finish's
    // `irid` pointer (boxed, so the 24 bytes of its parameters stay out of every texture).
    assert!(size_of::<Texture>() <= 344, "{}", size_of::<Texture>());
    assert!(size_of::<Pigment>() <= 112, "{}", size_of::<Pigment>());
    // Object 176 -> 192 knowingly: the `interior_texture` pointer and the `hollow` flag (fog
    // stops inside solid objects), which did not fit beside the other flags; 16 MB per million
    // objects.
    assert!(size_of::<Object>() <= 192, "{}", size_of::<Object>());
}

/// `texture { T }` shares the declared texture between objects; anything that changes it
/// afterwards (a transform of the object, a pigment) works on the object's own copy.
#[test]
fn declared_textures_are_shared_until_changed() {
    let dir = std::env::temp_dir().join(format!("lancer-layout-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("shared.pov");
    std::fs::write(
        &path,
        "#declare T = texture { pigment { rgb 1 } }
         sphere { 0, 1 texture { T } }
         sphere { x, 1 texture { T } }
         sphere { y, 1 texture { T } translate x }
         sphere { z, 1 texture { T } pigment { rgb 0.5 } }",
    )
    .unwrap();
    let parsed = lancer::api::parse_file(&path, Default::default());
    let _ = std::fs::remove_dir_all(&dir);
    assert!(parsed.error.is_none());
    let tex: Vec<_> = parsed
        .parser
        .scene
        .objects
        .iter()
        .map(|o| o.texture.clone().unwrap())
        .collect();
    assert!(std::sync::Arc::ptr_eq(&tex[0], &tex[1]));
    assert!(!std::sync::Arc::ptr_eq(&tex[0], &tex[2]));
    assert!(!tex[2].pigment.transform.is_identity() && tex[0].pigment.transform.is_identity());
    assert!(!std::sync::Arc::ptr_eq(&tex[0], &tex[3]));
}
