//! Height fields' tests: the diagonal's side, orientation, smooth normals, water level and
//! the pyramid walk against a plain cell-by-cell search.

use super::*;
use std::sync::Arc;

/// A W×H grid from a function of the vertex (i, j), as 16-bit heights.
fn grid(w: usize, h: usize, f: impl Fn(usize, usize) -> f64, water: f64) -> HeightField {
    let mut heights = Vec::new();
    for j in 0..h {
        for i in 0..w {
            heights.push((f(i, j) * 65536.0) as u16);
        }
    }
    HeightField::new(Arc::new(HeightData {
        width: w,
        depth: h,
        heights,
        smooth: false,
        water_level: water,
        pyramid: Default::default(),
        normals: Default::default(),
    }))
}

fn down(hf: &HeightField, x: f64, z: f64) -> Option<(f64, DVec3)> {
    let r = Ray::new(DVec3::new(x, 5.0, z), DVec3::NEG_Y);
    let h = hf.intersect_first(&r, f64::INFINITY, &mut Vec::new())?;
    Some((5.0 - h.t, hf.normal(r.at(h.t), &h).normalize()))
}

#[test]
fn diagonal_and_orientation() {
    // One cell, corner (0, 1) raised: the diagonal from (0, 1) to (1, 0) splits it into
    // h = z below it and h = 1 - x above it.
    let hf = grid(2, 2, |i, j| if (i, j) == (0, 1) { 0.5 } else { 0.0 }, 0.0);
    let (y, n) = down(&hf, 0.3, 0.3).unwrap();
    assert!((y - 0.15).abs() < 1e-9, "{y}");
    assert!(
        (n - DVec3::new(0.0, 2.0, -1.0).normalize()).length() < 1e-9,
        "{n}"
    );
    let (y, n) = down(&hf, 0.75, 0.5).unwrap();
    assert!((y - 0.125).abs() < 1e-9, "{y}");
    assert!(
        (n - DVec3::new(1.0, 2.0, 0.0).normalize()).length() < 1e-9,
        "{n}"
    );
    // On the diagonal itself the second triangle answers, as in povray.
    let (_, n) = down(&hf, 0.5, 0.5).unwrap();
    assert!(n.x > 0.0 && n.z.abs() < 1e-9, "{n}");
    assert!(hf.inside(DVec3::new(0.3, 0.1, 0.3)) && !hf.inside(DVec3::new(0.3, 0.2, 0.3)));
    // However deep below, and only over the square.
    assert!(hf.inside(DVec3::new(0.3, -50.0, 0.3)) && !hf.inside(DVec3::new(1.3, 0.0, 0.3)));
}

#[test]
fn large_grid_matches_brute_force() {
    let f = |i: usize, j: usize| 0.5 + 0.3 * ((i as f64 * 0.37).sin() * (j as f64 * 0.23).cos());
    let hf = grid(97, 61, f, 0.0);
    let mut rng = crate::geom::test_rng::Lcg(7);
    let mut rnd = move || rng.next();
    for _ in 0..400 {
        let o = DVec3::new(rnd() * 3.0 - 1.0, 1.0 + rnd(), rnd() * 3.0 - 1.0);
        let target = DVec3::new(rnd(), rnd() * 0.8, rnd());
        let ray = Ray::new(o, target - o);
        let first = hf.intersect_first(&ray, f64::INFINITY, &mut Vec::new());
        let mut all = Vec::new();
        hf.intersect_all(&ray, &mut all);
        // March along the ray for the first sign change of y - h.
        let h_at = |p: DVec3| {
            let (gx, gz) = (p.x * 96.0, p.z * 60.0);
            if !(0.0..=96.0).contains(&gx) || !(0.0..=60.0).contains(&gz) {
                return None;
            }
            let (i, j) = ((gx as usize).min(95), (gz as usize).min(59));
            let (u, v) = (gx - i as f64, gz - j as f64);
            let g = |a, b| (f(a, b) * 65536.0) as u16 as f64 / 65536.0;
            Some(if u + v <= 1.0 {
                g(i, j) + (g(i + 1, j) - g(i, j)) * u + (g(i, j + 1) - g(i, j)) * v
            } else {
                g(i + 1, j + 1)
                    + (g(i, j + 1) - g(i + 1, j + 1)) * (1.0 - u)
                    + (g(i + 1, j) - g(i + 1, j + 1)) * (1.0 - v)
            })
        };
        // The first step across the surface, either way (there are no side walls).
        let mut want = None;
        let steps = 20000;
        let mut last: Option<bool> = None;
        for k in 1..=steps {
            let t = k as f64 / steps as f64 * 1.5;
            let p = ray.at(t);
            let now = h_at(p).map(|h| p.y < h);
            if now.is_some() && last.is_some() && now != last {
                want = Some(t);
                break;
            }
            last = now;
        }
        match (first, want) {
            (Some(h), Some(t)) => assert!((h.t - t).abs() < 2e-4, "{} vs {t}", h.t),
            (None, None) => {}
            (got, want) => panic!("{got:?} vs {want:?} for {ray:?}"),
        }
        assert_eq!(!all.is_empty(), first.is_some());
        if let Some(h) = first {
            let min = all.iter().map(|h| h.t).fold(f64::INFINITY, f64::min);
            assert_eq!(min, h.t);
        }
    }
}

#[test]
fn water_level_and_degenerate_grids() {
    let hf = grid(11, 11, |i, _| i as f64 / 10.0 * 0.99, 0.5);
    assert!(down(&hf, 0.3, 0.5).is_none());
    let (y, _) = down(&hf, 0.8, 0.5).unwrap();
    assert!((y - 0.8 * 0.99).abs() < 1e-4);
    let flat = HeightField::new(Arc::new(HeightData {
        width: 1,
        depth: 5,
        heights: vec![0; 5],
        smooth: true,
        water_level: 0.0,
        pyramid: Default::default(),
        normals: Default::default(),
    }));
    assert!(flat.bounds().is_empty() && down(&flat, 0.5, 0.5).is_none());
    assert!(!flat.inside(DVec3::splat(0.5)));
    let hf = grid(3, 3, |_, _| 0.5, 0.0);
    let mut v = Vec::new();
    hf.intersect_all(&Ray::new(DVec3::splat(f64::NAN), DVec3::Y), &mut v);
    hf.intersect_all(&Ray::new(DVec3::ZERO, DVec3::ZERO), &mut v);
    assert!(v.is_empty());
}

/// The cached corner normals are `vertex_normal`'s, kept exactly.
#[test]
fn cached_vertex_normals_are_exact() {
    let f = |i: usize, j: usize| 0.5 + 0.45 * ((i as f64 * 1.7).sin() * (j as f64 * 0.9).cos());
    let mut hf = grid(23, 17, f, 0.0);
    Arc::get_mut(&mut hf.data).unwrap().smooth = true;
    let r = Ray::new(DVec3::new(0.4, 5.0, 0.6), DVec3::NEG_Y);
    let h = hf
        .intersect_first(&r, f64::INFINITY, &mut Vec::new())
        .unwrap();
    hf.normal(r.at(h.t), &h);
    let CornerNormals::Unit(cache) = hf.data.normals.get().unwrap() else {
        panic!("a small grid keeps its normals in object units");
    };
    for j in 0..17 {
        for i in 0..23 {
            let n = hf.vertex_normal(i, j).to_array();
            // Whole numbers within ±32767: `i16` keeps them exactly.
            let grid = n.map(|c| c as i16);
            assert_eq!(grid.map(f64::from), n, "{i} {j}");
            let unit = hf.corner_unit(grid).to_array().map(f64::to_bits);
            assert_eq!(
                cache[j * 23 + i].to_array().map(f64::to_bits),
                unit,
                "{i} {j}"
            );
        }
    }
    // A large grid's 16-bit normals, taken to object units per hit, give the same bits.
    let mut data = (*hf.data).clone();
    data.normals = std::sync::OnceLock::from(CornerNormals::Grid(
        (0..17 * 23)
            .map(|k| {
                hf.vertex_normal(k % 23, k / 23)
                    .to_array()
                    .map(|c| c as i16)
            })
            .collect(),
    ));
    let big = HeightField::new(Arc::new(data));
    let mut rng = crate::geom::test_rng::Lcg(7);
    for _ in 0..2000 {
        let o = DVec3::new(rng.next(), 5.0, rng.next());
        let r = Ray::new(o, DVec3::new(rng.next() - 0.5, -1.0, rng.next() - 0.5));
        let (a, b) = (&mut Vec::new(), &mut Vec::new());
        let (Some(h), Some(g)) = (
            hf.intersect_first(&r, f64::INFINITY, a),
            big.intersect_first(&r, f64::INFINITY, b),
        ) else {
            continue;
        };
        let (n, m) = (hf.normal(r.at(h.t), &h), big.normal(r.at(g.t), &g));
        assert_eq!(
            n.to_array().map(f64::to_bits),
            m.to_array().map(f64::to_bits),
            "{r:?}"
        );
    }
}

#[test]
fn smooth_normals_follow_the_slopes() {
    let mut heights = Vec::new();
    for _ in 0..5 {
        for i in 0..5 {
            let x = i as f64 / 4.0;
            heights.push((0.5 * x * x * 65536.0) as u16);
        }
    }
    let hf = HeightField::new(Arc::new(HeightData {
        width: 5,
        depth: 5,
        heights,
        smooth: true,
        water_level: 0.0,
        pyramid: Default::default(),
        normals: Default::default(),
    }));
    // At the middle vertex the central difference is the true slope of 0.5 x² at 0.5.
    let (_, n) = down(&hf, 0.5 + 1e-9, 0.5).unwrap();
    assert!((-n.x / n.y - 0.5).abs() < 1e-3, "{n}");
    // Between vertices the normal turns smoothly.
    let (_, a) = down(&hf, 0.55, 0.5).unwrap();
    let (_, b) = down(&hf, 0.7, 0.5).unwrap();
    assert!(-a.x / a.y > 0.5 && -b.x / b.y > -a.x / a.y);
}

/// `intersect_all_within` gives `intersect_all`'s crossings within its window, bit for bit
/// and in the same order (a clipped field's running minimum takes the earliest of equal `t`):
/// rays of every slope, along the axes and nearly so (where a cell's crossing found just
/// outside it lies far along the ray), windows at crossings, inside and past the field, with
/// NaN and infinite ends, on flat steps (edge ties) and with water.
#[test]
fn window_keeps_the_crossings_within_it() {
    use super::walk::tests::bits;
    let mut rng = crate::geom::test_rng::Lcg(31);
    let mut rnd = move || rng.next();
    let (mut checked, mut left_out) = (0, 0);
    for (w, h, water) in [(2, 3, 0.0), (9, 6, 0.4), (37, 23, 0.0), (64, 65, 0.25)] {
        let f = |i: usize, j: usize| {
            let v = 0.5 + 0.45 * ((i as f64 * 0.8).sin() * (j as f64 * 0.4).cos());
            (v * 7.0).floor() / 7.0
        };
        let hf = grid(w, h, f, water);
        for k in 0..8000 {
            let o = DVec3::new(rnd() * 1.6 - 0.3, rnd() * 2.0 - 0.2, rnd() * 1.6 - 0.3);
            let mut d = DVec3::new(rnd(), rnd(), rnd()) - o;
            match k % 7 {
                // Along an axis (the pyramid's own walk) or nearly.
                0 => d[k % 3] = 0.0,
                1 => d[k % 3] = (rnd() - 0.5) * 1e-9,
                _ => {}
            }
            let ray = Ray::new(o, d);
            let mut all = Vec::new();
            hf.intersect_all(&ray, &mut all);
            let mut end = |e: usize| match (k / 5 + e) % 5 {
                0 => f64::NAN,
                1 => f64::INFINITY * if e == 0 { -1.0 } else { 1.0 },
                // At a crossing: the window's end on the surface.
                2 if !all.is_empty() => all[(k / 3 + e) % all.len()].t,
                _ => rnd() * 2.0 - 0.2,
            };
            let (a, b) = (end(0), end(1));
            let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
            let mut within = Vec::new();
            hf.intersect_all_within(&ray, lo, hi, &mut within);
            let kept = |v: &[Hit]| {
                let inside = |t: f64| (lo.is_nan() || t >= lo) && (hi.is_nan() || t <= hi);
                let kept: Vec<Hit> = v.iter().filter(|c| inside(c.t)).copied().collect();
                bits(&kept)
            };
            assert_eq!(kept(&within), kept(&all), "{ray:?} {lo} {hi}");
            checked += kept(&all).len();
            left_out += all.len() - within.len();
        }
    }
    // The windows did leave crossings out.
    assert!(checked > 1000 && left_out > 1000, "{checked} {left_out}");
}
