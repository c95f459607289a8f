//! `crand` is random in POV-Ray (its pixels change with the thread count), so no picture can
//! match povray's pixel for pixel; what can be matched is the distribution. Each light's
//! diffuse term is scaled by 1 - crand·u with u uniform and independent per light, ambient
//! untouched: measured by scripts/measure_crand.sh on 100×100 povray renders of a flat, evenly
//! lit plane (the quantiles below are its output).
//!
//! Tolerance 0.01 on each quantile: with 10,000 samples a quantile's own sampling spread is
//! about 0.003 (in u), times crand·light = 0.5 here, so 0.01 is several times that and still
//! far below the 0.2 by which a wrong rule (one u for all lights, or a subtraction) moves them.

use std::path::Path;

use lancer::render::RenderSettings;

fn quantiles(lights: &str) -> [f64; 3] {
    let dir = std::env::temp_dir().join(format!("lancer-crand-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join(format!("crand{}.pov", lights.len()));
    std::fs::write(
        &scene,
        format!(
            "#version 3.7; global_settings {{ assumed_gamma 1.0 }}
             camera {{ orthographic location <0,0,-1> look_at 0 right x up y }}
             {lights}
             plane {{ z, 0 pigment {{ rgb 1 }} finish {{ ambient 0 diffuse 1 crand 0.5 }} }}"
        ),
    )
    .unwrap();
    let settings = RenderSettings {
        width: 100,
        height: 100,
        antialias: None,
        ..RenderSettings::default()
    };
    let film = lancer::api::render_file(Path::new(&scene), &[], &settings).unwrap();
    let mut v: Vec<f64> = film.pixels.iter().map(|p| p.x).collect();
    v.sort_by(f64::total_cmp);
    let n = v.len();
    [v[n / 10], v[n / 2], v[9 * n / 10]]
}

fn assert_close(ours: [f64; 3], povray: [f64; 3]) {
    for (a, b) in ours.iter().zip(povray) {
        assert!(
            (a - b).abs() < 0.01,
            "quantiles {ours:?}, povray's {povray:?}"
        );
    }
}

#[test]
fn one_light_darkens_uniformly() {
    assert_close(
        quantiles("light_source { <0,0,-1000> rgb 1 }"),
        [0.5494, 0.7482, 0.9470],
    );
}

#[test]
fn each_light_draws_its_own_share() {
    assert_close(
        quantiles("light_source { <0,0,-1000> rgb 0.5 } light_source { <0,1,-1000> rgb 0.5 }"),
        [0.6120, 0.7502, 0.8845],
    );
}
