//! Unit tests of `geom::algebraic`: quadric bounds within slabs, POV-Ray's term order, the
//! unrolled expansion against the loops, a sphere as a quadric, and the Cauchy bound.

use super::*;

#[test]
fn quadric_slab_bounds() {
    // (x-1)² + 4y² <= 4, any z: x in [-1, 3], y in [-1, 1].
    let q = Algebraic::new(
        2,
        &[
            ([2, 0, 0], 1.0),
            ([0, 2, 0], 4.0),
            ([1, 0, 0], -2.0),
            ([0, 0, 0], -3.0),
        ],
        false,
    );
    let b = q.slab_bounds();
    assert!((b.min.x + 1.0).abs() < 1e-5 && (b.max.x - 3.0).abs() < 1e-5);
    assert!((b.max.y - 1.0).abs() < 1e-5 && b.min.y < -1.0);
    assert!(b.min.z == f64::NEG_INFINITY && b.max.z == f64::INFINITY);
    for p in [DVec3::new(3.0, 0.0, 7.0), DVec3::new(1.0, 1.0, -9.0)] {
        assert!(b.contains(p));
    }
    // A hyperboloid (negative square term) and a cross term give nothing.
    let h = Algebraic::new(2, &[([2, 0, 0], 1.0), ([0, 2, 0], -1.0)], false);
    assert!(!h.slab_bounds().is_finite() && h.slab_bounds().min.x.is_infinite());
    let c = Algebraic::new(2, &[([2, 0, 0], 1.0), ([1, 1, 0], 1.0)], false);
    assert_eq!(c.slab_bounds().max.x, f64::INFINITY);
}

#[test]
fn hyperboloid_within_a_slab() {
    // shapes.inc's Hyperboloid_Y, x² - y² + z² <= 1, for y in [-2, 1]: x² + z² <= 5.
    let h = Algebraic::new(
        2,
        &[
            ([2, 0, 0], 1.0),
            ([0, 2, 0], -1.0),
            ([0, 0, 2], 1.0),
            ([0, 0, 0], -1.0),
        ],
        false,
    );
    let slab = Aabb::new(
        DVec3::new(f64::NEG_INFINITY, -2.0, f64::NEG_INFINITY),
        DVec3::new(f64::INFINITY, 1.0, f64::INFINITY),
    );
    let b = h.slab_bounds_within(&slab);
    let r = 5f64.sqrt();
    assert!(b.max.x >= r && b.max.x < r + 1e-4 && b.min.z <= -r && b.min.z > -r - 1e-4);
    assert_eq!((b.min.y, b.max.y), (-2.0, 1.0));
    // Every point of the solid in the slab is in the box.
    for i in 0..2000 {
        let t = i as f64 * 0.37;
        let y = -2.0 + 3.0 * ((t * 0.13).sin() * 0.5 + 0.5);
        let rr = (1.0 + y * y).sqrt() * ((t * 0.7).cos() * 0.5 + 0.5);
        let p = DVec3::new(rr * t.cos(), y, rr * t.sin());
        assert!(!h.inside(p) || b.contains(p));
    }
    // Open on y, nothing closes x or z.
    assert_eq!(h.slab_bounds_within(&Aabb::INFINITE).max.x, f64::INFINITY);
    // A translated cylinder (x-3)² + z² <= 4 inside x <= 2 keeps its own z bounds.
    let c = Algebraic::new(
        2,
        &[
            ([2, 0, 0], 1.0),
            ([0, 0, 2], 1.0),
            ([1, 0, 0], -6.0),
            ([0, 0, 0], 5.0),
        ],
        false,
    );
    let half = Aabb::new(
        DVec3::splat(f64::NEG_INFINITY),
        DVec3::new(2.0, f64::INFINITY, f64::INFINITY),
    );
    let b = c.slab_bounds_within(&half);
    assert!(b.min.x < 1.0 && b.min.x > 0.99 && b.max.x == 2.0);
    // x = 2 leaves z² <= 3.
    assert!(b.max.z >= 3f64.sqrt() && b.max.z < 3f64.sqrt() + 1e-4);
}

#[test]
fn quartic_term_order_matches_the_manuals_torus() {
    let order = pov_term_order(4);
    assert_eq!(order.len(), 35);
    assert_eq!(order[0], [4, 0, 0]);
    assert_eq!(order[4], [2, 2, 0]);
    assert_eq!(order[9], [2, 0, 0]);
    assert_eq!(order[20], [0, 4, 0]);
    assert_eq!(order[25], [0, 2, 0]);
    assert_eq!(order[34], [0, 0, 0]);
    assert_eq!(pov_term_order(2).len(), 10);
    assert_eq!(pov_term_order(3).len(), 20);
}

/// A polynomial of `order` with every term of POV-Ray's order and coefficients from `rnd`;
/// `sparse`: the negative ones left out (zero), for the expansions' zero-term paths.
fn random_poly(order: usize, sparse: bool, rnd: &mut impl FnMut() -> f64) -> Algebraic {
    let terms: Vec<([u8; 3], f64)> = pov_term_order(order)
        .into_iter()
        .map(|p| (p, rnd()))
        .map(|(p, c)| (p, if sparse && c < 0.0 { 0.0 } else { c }))
        .collect();
    Algebraic::new(order, &terms, false)
}

/// The unrolled expansions and the power tables give the bits of the loops they replace.
#[test]
fn unrolled_expansion_matches_the_loops() {
    let mut unit = crate::math::xorshift_unit(0x9e37_79b9_7f4a_7c15u64);
    let mut rnd = move || unit() * 8.0 - 4.0;
    for order in [2usize, 3, 4] {
        for case in 0..400 {
            // Every other case a sparse polynomial (zero terms left out).
            let a = random_poly(order, case % 2 == 1, &mut rnd);
            let (o, d) = if case % 4 < 2 {
                (
                    DVec3::new(rnd(), rnd(), -0.0),
                    DVec3::new(rnd(), 0.0, rnd()),
                )
            } else {
                (
                    DVec3::new(0.0, rnd(), rnd()),
                    DVec3::new(-0.0, rnd(), -rnd().abs()),
                )
            };
            let mut x = [0.0; MAX_ORDER + 1];
            a.along(o, d, &mut x);
            let y = a.along_in::<{ MAX_ORDER + 1 }>(o, d);
            assert_eq!(x.map(f64::to_bits), y.map(f64::to_bits));
            let p = DVec3::new(rnd(), rnd(), rnd());
            let direct: f64 = a
                .terms
                .iter()
                .map(|([i, j, k], c)| {
                    c * p.x.powi(*i as i32) * p.y.powi(*j as i32) * p.z.powi(*k as i32)
                })
                .sum();
            assert_eq!(a.value(p).to_bits(), direct.to_bits());
        }
    }
    for x in [0.3, -1.7, 1e-200, -0.0, 3.5e100, 1.0000001, f64::NAN] {
        let t = powi_table::<{ MAX_ORDER + 1 }>(x, MAX_ORDER);
        for (e, v) in t.iter().enumerate() {
            assert_eq!(v.to_bits(), x.powi(e as i32).to_bits(), "{x}^{e}");
        }
        let t = powi_table::<5>(x, 4);
        for (e, v) in t.iter().enumerate() {
            assert_eq!(v.to_bits(), x.powi(e as i32).to_bits(), "{x}^{e}");
        }
        let t = powi_table::<3>(x, 2);
        for (e, v) in t.iter().enumerate() {
            assert_eq!(v.to_bits(), x.powi(e as i32).to_bits(), "{x}^{e}");
        }
    }
}

/// The normal from power tables gives the bits of the `powi` calls it replaced: random
/// polynomials of each table size (orders 1 to 7), at random points and at points with
/// zeros of either sign, tiny and huge coordinates, infinities and NaN.
#[test]
fn gradient_from_tables_matches_powi() {
    let mut unit = crate::math::xorshift_unit(0x51ed_2701_a3c4_9b17u64);
    let mut rnd = move || unit() * 8.0 - 4.0;
    let edges = [
        0.0,
        -0.0,
        1e-200,
        -3.5e100,
        1.0000001,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
    ];
    let mut checked = 0;
    for order in 1usize..=7 {
        for case in 0..200 {
            let a = random_poly(order, case % 2 == 1, &mut rnd);
            for k in 0..12 {
                let mut p = DVec3::new(rnd(), rnd(), rnd());
                if k >= 4 {
                    p[k % 3] = edges[(case + k) % edges.len()];
                }
                let (got, want) = (a.normal(p, &Hit::new(1.0)), a.gradient_powi(p));
                for axis in 0..3 {
                    assert_eq!(
                        got[axis].to_bits(),
                        want[axis].to_bits(),
                        "order {order} at {p:?}"
                    );
                }
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 7 * 200 * 12);
}

#[test]
fn unit_sphere_as_a_quadric() {
    let s = Algebraic::new(
        2,
        &[
            ([2, 0, 0], 1.0),
            ([0, 2, 0], 1.0),
            ([0, 0, 2], 1.0),
            ([0, 0, 0], -1.0),
        ],
        false,
    );
    let mut hits = Vec::new();
    s.intersect_all(
        &Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z * 2.0),
        &mut hits,
    );
    let mut t: Vec<f64> = hits.iter().map(|h| h.t).collect();
    t.sort_by(f64::total_cmp);
    assert_eq!(t.len(), 2);
    assert!((t[0] - 2.0).abs() < 1e-9 && (t[1] - 3.0).abs() < 1e-9);
    assert!(s.inside(DVec3::ZERO) && !s.inside(DVec3::X * 2.0));
    let n = s.normal(DVec3::X, &hits[0]);
    assert!((n.normalize() - DVec3::X).length() < 1e-12);
}

/// One division gives the per-coefficient divisions' bound bit for bit: random
/// coefficients with zeros, signed zeros, subnormal, huge, infinite and NaN values.
#[test]
fn cauchy_by_one_division_is_per_coefficient() {
    let mut rng = crate::geom::test_rng::Lcg(26);
    let special = [
        0.0,
        -0.0,
        1e300,
        -1e-300,
        5e-324,
        -1e-310,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
    ];
    for case in 0..100_000 {
        let lead = 1 + case % 6;
        let mut c: Vec<f64> = (0..=lead)
            .map(|_| (rng.next() * 8.0 - 4.0) * 10f64.powi((rng.next() * 40.0) as i32 - 20))
            .collect();
        for _ in 0..case % 4 {
            let k = (rng.next() * (lead + 1) as f64) as usize;
            c[k.min(lead)] = special[(rng.next() * special.len() as f64) as usize];
        }
        if c[lead] == 0.0 {
            c[lead] = 1.0;
        }
        assert_eq!(
            cauchy(&c, lead).to_bits(),
            cauchy_per_coefficient(&c, lead).to_bits(),
            "{c:?}"
        );
    }
}

/// `intersect_first` before the walk stopped at `tmax`: the walk to the first kept root,
/// each root polished, that root's `t` kept below `tmax` (the reference).
fn first_unstopped(a: &Algebraic, ray: &Ray, tmax: f64) -> Option<f64> {
    let mut c = [0.0; MAX_ORDER + 1];
    let (hi, len) = a.along_ray(ray, &mut c)?;
    if a.surely_misses(&c, EPSILON * len, hi) {
        return None;
    }
    let keep = |x: f64| x / len > EPSILON;
    let c = &c[..=a.order];
    let first = if a.order == 4 && c[4] != 0.0 {
        crate::geom::poly::first_root_in_unchecked(c, EPSILON * len, hi, keep)
    } else {
        crate::geom::poly::first_root_in(c, EPSILON * len, hi, keep)
    };
    first.map(|x| x / len).filter(|&t| t < tmax)
}

/// The walk stopped at a piece starting at or past `tmax`, and `any_hit`'s brackets that
/// settle its answer unpolished, give the answers of the full walk: random cubics, quartics
/// and quintics (some sparse), rays from near and far with directions of any length, and
/// `tmax` anywhere, at every crossing, a hair either side of it, zero, tiny and infinite.
#[test]
fn stopped_walks_answer_as_the_full_walk() {
    let mut unit = crate::math::xorshift_unit(0x2545_f491_4f6c_dd1du64);
    let mut rnd = move || unit() * 8.0 - 4.0;
    let (mut hits, mut cases) = (0, 0);
    for order in [3usize, 4, 5] {
        for case in 0..600 {
            let a = random_poly(order, case % 3 == 1, &mut rnd);
            let far = if case % 2 == 0 { 1.0 } else { 6.0 };
            let origin = DVec3::new(rnd(), rnd(), rnd()) * far;
            let scale = [1.0, 0.25, 3.0][case % 3];
            let dir = DVec3::new(rnd(), rnd(), rnd()) * scale;
            let ray = Ray::new(origin, dir);
            let mut all = Vec::new();
            a.intersect_all(&ray, &mut all);
            let mut tmaxes = vec![0.0, 1e-9, EPSILON, 0.5, 2.0, 40.0, f64::INFINITY];
            for h in &all {
                let t = h.t;
                tmaxes.extend([t, t.next_up(), t.next_down(), t * 1.01, t * 0.99]);
            }
            tmaxes.push(rnd().abs() * 10.0);
            let mut scratch = Vec::new();
            for &tmax in &tmaxes {
                cases += 1;
                let want = first_unstopped(&a, &ray, tmax);
                let got = a.intersect_first(&ray, tmax, &mut scratch).map(|h| h.t);
                assert_eq!(
                    got.map(f64::to_bits),
                    want.map(f64::to_bits),
                    "{a:?} {ray:?} {tmax}"
                );
                assert_eq!(a.any_hit(&ray, tmax, &mut scratch), want.is_some());
                hits += want.is_some() as usize;
            }
        }
    }
    assert!(hits > 2_000 && cases > 20_000, "{hits} of {cases}");
}
