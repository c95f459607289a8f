//! The build hands an object the description's own texture when readying it changes nothing,
//! and a readied copy otherwise: patterns of pigments and normals that name no noise
//! generator take the scene's (`global_settings { noise_generator }`).

use lancer::scene::desc::NormalKind;

#[test]
fn normal_patterns_take_the_scenes_noise_generator() {
    let dir = std::env::temp_dir().join(format!("lancer-readying-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("gen.pov");
    std::fs::write(
        &path,
        "global_settings { noise_generator 1 }
         #declare T = texture { pigment { rgb 1 } normal { bumps 0.5 } }
         sphere { 0, 1 texture { T } }
         sphere { x, 1 texture { T } }",
    )
    .unwrap();
    let parsed = lancer::api::parse_file(&path, Default::default());
    let _ = std::fs::remove_dir_all(&dir);
    assert!(parsed.error.is_none());
    let built = lancer::scene::build::build(&parsed.parser.scene, 8, 8);
    assert_eq!(built.scene.objects.len(), 2);
    for o in &built.scene.objects {
        let n = o.texture.normal.as_deref().expect("a normal");
        let NormalKind::Pattern { pattern, .. } = &n.kind else {
            panic!("bumps is a pattern normal");
        };
        assert_eq!(pattern.noise_generator, 1);
    }
}
