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
    assert!(
        size_of::<ObjectDesc>() <= 192,
        "{}",
        size_of::<ObjectDesc>()
    );
    assert!(size_of::<ShapeDesc>() <= 80, "{}", size_of::<ShapeDesc>());
    assert!(size_of::<Texture>() <= 320, "{}", size_of::<Texture>());
    assert!(size_of::<Pigment>() <= 104, "{}", size_of::<Pigment>());
    assert!(size_of::<Object>() <= 176, "{}", size_of::<Object>());
}
