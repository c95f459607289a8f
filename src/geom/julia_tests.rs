//! Unit tests of `geom::julia` against values the povray binary computed: `inside()`,
//! `trace()` hit points and normals, and one iteration of each hypercomplex function
//! recovered from `inside()` (the scripts are in tests/data/julia/).

// The values are povray's printed digits, kept as written.
#![allow(clippy::excessive_precision)]

use super::*;

pub(super) fn julia(c: [f64; 4], algebra: Algebra, func: JuliaFn, n: u32, prec: f64) -> Julia {
    Julia::new(c, algebra, func, n, prec, ([0.0, 0.0, 0.0, 1.0], 0.0))
}

pub(super) const FRACTAL3: [f64; 4] = [0.49, 0.5, -0.34, 0.1];

/// The scales either side of `j`'s surface along `p` from the origin, 40 halvings from
/// `(0, 1)`: `p * lo` inside (or the origin), `p * hi` outside (or `p`).
pub(super) fn to_the_edge(j: &Julia, p: DVec3) -> (f64, f64) {
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..40 {
        let m = 0.5 * (lo + hi);
        if j.is_in(p * m) {
            lo = m;
        } else {
            hi = m;
        }
    }
    (lo, hi)
}

/// `inside()` of objects/fractal3's quaternion (max_iteration 7); povray's answers.
#[test]
fn quaternion_inside_matches_povray() {
    let j = julia(FRACTAL3, Algebra::Quaternion, JuliaFn::Sqr, 7, 1.0);
    for (p, want) in [
        (
            [
                0.50360217325007617,
                -0.69058202479281028,
                0.67328697509907331,
            ],
            true,
        ),
        (
            [
                0.26367567080624288,
                -0.29452400312165827,
                0.70034535194289549,
            ],
            true,
        ),
        (
            [
                0.30294282271129602,
                0.35222618462336874,
                0.28050293738034182,
            ],
            true,
        ),
        (
            [
                0.033308546206287433,
                -0.020265543791527341,
                0.59108844687954742,
            ],
            true,
        ),
        (
            [1.6341583703258442, 0.3976786094246616, -1.1993323114233401],
            false,
        ),
        (
            [
                -1.6744785030080189,
                0.86164767729622471,
                -0.42128720614623449,
            ],
            false,
        ),
    ] {
        assert_eq!(j.inside(DVec3::from(p)), want, "{p:?}");
    }
    // The bailout is min(2, 1 + |c|): with c = 0 the object is the unit ball.
    let ball = julia([0.0; 4], Algebra::Quaternion, JuliaFn::Sqr, 5, 20.0);
    assert!(ball.inside(DVec3::new(0.0, 0.999, 0.0)));
    assert!(!ball.inside(DVec3::new(0.0, 1.001, 0.0)));
}

/// `trace()` of fractal3's quaternion at precision 10 (max_iteration 7): hit points within
/// povray's bisection tolerance (~1e-7), including rays whose thin
/// first band povray's march steps over (the 7th and 9th) and rays it misses. Normals to
/// 1e-5: the gradient after 7 squarings turns by ~1e-5 per 1e-7 of hit point.
#[test]
fn quaternion_trace_matches_povray() {
    type Case = ([f64; 3], [f64; 3], Option<([f64; 3], [f64; 3])>);
    let cases: [Case; 11] = [
        (
            [0.96898953953501543, -0.77946048050174965, -5.0],
            [-0.056478106627817749, 0.14179896237137704, 1.0],
            Some((
                [
                    0.65217052016288457,
                    0.015973553831798451,
                    0.60958995066744737,
                ],
                [
                    0.17860341380302358,
                    -0.31281749570717171,
                    -0.93286978456663483,
                ],
            )),
        ),
        (
            [0.33360863426551424, -0.54302264937270039, -5.0],
            [-0.125906784128376, 0.057272483479993537, 1.0],
            Some((
                [
                    -0.1803062516730683,
                    -0.3092530235435646,
                    -0.91829074583789583,
                ],
                [
                    0.94430800762716649,
                    0.0366424862492776,
                    -0.32701638327870147,
                ],
            )),
        ),
        (
            [0.58611607413881384, 0.0066877316000608601, -5.0],
            [-0.1496709087397137, -0.0067234386123538499, 1.0],
            Some((
                [
                    -0.031733659862016608,
                    -0.021066992368629089,
                    -0.87194506131243821,
                ],
                [
                    -0.17473088998916858,
                    -0.0054929635005728696,
                    -0.98460090566461222,
                ],
            )),
        ),
        (
            [-0.75994721503461404, 0.63423754487518158, -5.0],
            [-0.026775934192532661, 0.037315644763250742, 1.0],
            Some((
                [
                    -0.88285781573322331,
                    0.80552898443160803,
                    -0.4096615335689473,
                ],
                [
                    -0.13781343055082187,
                    0.86501544698038646,
                    -0.48244764984932448,
                ],
            )),
        ),
        (
            [-0.33592700651751994, 0.3156805878541622, -5.0],
            [-0.10127193148976003, 0.051859178836890313, 1.0],
            Some((
                [
                    -0.741634287931771,
                    0.52343456423030765,
                    -0.99388225892310933,
                ],
                [
                    -0.89972763087722063,
                    0.067789738713668862,
                    -0.43115512470710143,
                ],
            )),
        ),
        (
            [-0.28248950438166265, -0.87858310443781851, -5.0],
            [-0.026929728984117909, 0.14297322872862525, 1.0],
            Some((
                [
                    -0.38707016060315125,
                    -0.32335159463083735,
                    -1.1165351391703164,
                ],
                [
                    -0.32995816523655452,
                    -0.30317715818167795,
                    -0.89398614080454775,
                ],
            )),
        ),
        (
            [0.39425285204645544, 1.3397378283179688, -5.0],
            [-0.085284099666235055, -0.11455922524085249, 1.0],
            Some((
                [
                    -0.00273436807161962,
                    0.80647842187257368,
                    -0.34512034867330754,
                ],
                [
                    -0.30717784566847461,
                    0.87483153930981805,
                    -0.3745818321265586,
                ],
            )),
        ),
        (
            [-1.4335321029493426, 1.34355172557839, -5.0],
            [0.13638629188909807, -0.14768574961872905, 1.0],
            None,
        ),
        (
            [-0.14546787055336585, -0.40561022048481044, -5.0],
            [0.11748548077128024, 0.08168505586955814, 1.0],
            Some((
                [
                    0.31469844599053975,
                    -0.085666759987295046,
                    -1.0832069331209226,
                ],
                [
                    0.56820337850319313,
                    0.022842679008336621,
                    -0.82257105022805121,
                ],
            )),
        ),
        (
            [0.42567865222824697, 0.57808900556482623, -5.0],
            [0.10024682480149129, -0.1277128397202382, 1.0],
            None,
        ),
        (
            [0.46576980640314769, 0.53891023272623073, -5.0],
            [0.13145984506268515, 0.0070660809653499204, 1.0],
            None,
        ),
    ];
    let j = julia(FRACTAL3, Algebra::Quaternion, JuliaFn::Sqr, 7, 10.0);
    for (o, d, want) in cases {
        let ray = Ray::new(DVec3::from(o), DVec3::from(d));
        let got = j.intersect_first(&ray, f64::INFINITY, &mut Vec::new());
        match (got, want) {
            (None, None) => {}
            (Some(h), Some((p, n))) => {
                let at = ray.origin + ray.dir * h.t;
                assert!(at.distance(DVec3::from(p)) < 1e-6, "{o:?}: {at} vs {p:?}");
                let nn = j.normal(at, &h).normalize();
                assert!(nn.distance(DVec3::from(n)) < 1e-5, "{o:?}: {nn} vs {n:?}");
            }
            (g, w) => panic!("{o:?}: lancer {g:?}, povray {w:?}"),
        }
    }
}

/// h0 and one hypercomplex iteration (c = 0) as povray computes them: `inside()` at
/// max_iteration 2 holds iff |f(h0) + c| <= 4, so f(h0) is recovered by bisecting on c.
#[test]
fn hypercomplex_functions_match_povray() {
    let one = |func: JuliaFn, p: [f64; 3]| -> Q {
        let j = julia([0.0; 4], Algebra::Hypercomplex, func, 2, 10.0);
        let (h, _) = j.lift(DVec3::from(p));
        let (z1, z2) = split(&h);
        let (w1, w2) = (func.apply(z1), func.apply(z2));
        [
            (w1.re + w2.re) / 2.0,
            (w1.im + w2.im) / 2.0,
            (w1.im - w2.im) / 2.0,
            (w2.re - w1.re) / 2.0,
        ]
    };
    let cases: [(JuliaFn, [f64; 3], Q); 6] = [
        (JuliaFn::Sqr, [0.3, 0.5, 0.7], [-0.65, 0.3, 0.42, 0.7]),
        // cube is the square.
        (JuliaFn::Cube, [0.3, 0.5, 0.7], [-0.65, 0.3, 0.42, 0.7]),
        // Transcendental functions read (x, y, y).
        (
            JuliaFn::Exp,
            [0.3, 0.5, 0.7],
            [
                1.039595316952867,
                0.567933510081296,
                0.567933510081296,
                0.310263490623136,
            ],
        ),
        (
            JuliaFn::Acos,
            [-0.4, 0.2, -0.9],
            [
                -1.964690762317991,
                0.208912438681830,
                0.208912438681830,
                -0.017622410544394,
            ],
        ),
        (
            JuliaFn::Acos,
            [-0.5, 0.0, 0.0],
            [-2.094395102393196, 0.0, 0.0, 0.0],
        ),
        (
            JuliaFn::Pwr(1.5, 0.3),
            [0.3, 0.5, 0.7],
            [
                -0.051538444113978,
                0.310902914251114,
                0.368970721867955,
                0.205252886241495,
            ],
        ),
    ];
    for (func, p, want) in cases {
        let got = one(func, p);
        for i in 0..4 {
            assert!(
                (got[i] - want[i]).abs() < 1e-12,
                "{func:?} {p:?}: {got:?} vs {want:?}"
            );
        }
    }
}

/// The slice lifts (x, y, z) to w = (d − n·xyz) / n_w with n normalised (measured with
/// slice <0.3, 0.2, 0.5, 1>, 0.4 and the square).
#[test]
fn slice_lift_solves_for_w() {
    let j = Julia::new(
        [0.0; 4],
        Algebra::Hypercomplex,
        JuliaFn::Sqr,
        2,
        10.0,
        ([0.0, 0.0, 0.0, 2.0], 0.6),
    );
    let (h, _) = j.lift(DVec3::new(0.3, 0.5, 0.7));
    assert!((h[3] - 0.3).abs() < 1e-15);
}

/// With p = 0 the hypercomplex square escapes |h| > 4 after max_iteration − 1 squarings.
#[test]
fn hypercomplex_zero_parameter_radii() {
    for (n, r) in [(2, 2.0), (3, 2f64.sqrt()), (4, 2f64.powf(0.25))] {
        let j = julia([0.0; 4], Algebra::Hypercomplex, JuliaFn::Sqr, n, 100.0);
        assert!(j.inside(DVec3::new(r - 1e-6, 0.0, 0.0)), "N={n}");
        assert!(!j.inside(DVec3::new(r + 1e-6, 0.0, 0.0)), "N={n}");
    }
}

/// p = 0 quaternion: the unit ball, entered one step (1/precision) past the sphere entry:
/// povray hits it for impact parameters below 0.86615 at precision 1 (a chord of 1) and
/// misses it beyond, wherever the ray starts outside.
#[test]
fn zero_parameter_ball_is_found_one_step_in() {
    let j = julia([0.0; 4], Algebra::Quaternion, JuliaFn::Sqr, 2, 1.0);
    let hit = |b: f64| {
        let r = Ray::new(DVec3::new(b, 0.0, -3.0), DVec3::Z);
        j.intersect_first(&r, f64::INFINITY, &mut Vec::new())
            .map(|h| h.t - 3.0)
    };
    let z = hit(0.6).unwrap();
    assert!((z + 0.8).abs() < 1e-6, "{z}");
    assert!(hit(0.865).is_some());
    assert!(hit(0.867).is_none());
}

/// The inside test compares squared norms with `sqrt_threshold(bailout)` instead of taking
/// square roots: the two comparisons must agree on every value (exactly, no tolerance: the
/// pictures must not move).
#[test]
fn sqrt_threshold_decides_as_the_square_root() {
    let mut seed = 0x9e37_79b9_7f4a_7c15u64;
    let mut rnd = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed
    };
    let mut bails = vec![2.0, 4.0, 1.0, 1.5, 0.0, 1e-300, 1e300];
    for _ in 0..200 {
        bails.push(1.0 + (rnd() >> 11) as f64 / (1u64 << 53) as f64);
    }
    for b in bails {
        let t = sqrt_threshold(b);
        assert!(t.sqrt() <= b, "{b}");
        assert!(f64::from_bits(t.to_bits() + 1).sqrt() > b, "{b}");
        let b2 = b * b;
        for k in 0..2000u64 {
            let s = if k < 1000 {
                // Around b² to the last bits.
                f64::from_bits(b2.to_bits().wrapping_add(k).wrapping_sub(500))
            } else {
                b2 * (rnd() >> 11) as f64 / (1u64 << 52) as f64
            };
            assert_eq!(s.sqrt() > b, s > t, "b {b} s {s}");
        }
        let nan = f64::from_bits(f64::NAN.to_bits() | std::hint::black_box(1));
        assert_eq!(nan > t, nan.sqrt() > b);
        assert!(f64::INFINITY > t);
    }
}

/// The march's step skips the logarithm when `r - 1` already bounds the estimate below the
/// least step: the step must be the estimate's to the bit (`max(ln r / dr, min_step)`).
#[test]
fn march_step_is_the_estimate_to_the_bit() {
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let mut unit = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    for _ in 0..200_000 {
        let r = 1.0 + 20.0 * unit().powi(3);
        let dr = 10f64.powf(12.0 * unit() - 4.0);
        let min_step = 1.0 / (1.0 + 40.0 * unit());
        let de = r.ln() / dr;
        let want = if de.is_finite() {
            de.max(min_step)
        } else {
            min_step
        };
        let got = march_step(&Orbit::Outside { r, dr }, min_step);
        assert_eq!(
            got.to_bits(),
            want.to_bits(),
            "r {r} dr {dr} min {min_step}"
        );
    }
}

/// `intersect_first` ends its march at the first crossing beyond `tmax`, and `any_hit` at
/// the first crossing sure to come before it: both must answer as the whole march does (the
/// nearest crossing of `intersect_all` beyond EPSILON, then `tmax`), to the bit.
#[test]
fn early_stops_answer_as_the_whole_march() {
    let mut rng = crate::geom::test_rng::Lcg(5);
    let shapes = [
        julia(
            [-0.083, 0.0, -0.83, -0.025],
            Algebra::Quaternion,
            JuliaFn::Sqr,
            8,
            15.0,
        ),
        julia(
            [-0.03, 0.5, -0.2, -0.5],
            Algebra::Quaternion,
            JuliaFn::Cube,
            8,
            15.0,
        ),
        julia(
            [0.4, 0.2, 0.1, 0.0],
            Algebra::Hypercomplex,
            JuliaFn::Sqr,
            6,
            20.0,
        ),
    ];
    let mut hits = 0;
    for (k, j) in shapes.iter().enumerate() {
        for i in 0..300 {
            // From outside towards the set, and from points near it (shadow rays start on it).
            let o = if i % 2 == 0 {
                rng.vec(8.0)
            } else {
                rng.vec(1.5)
            };
            let ray = Ray::new(o, rng.vec(2.0) - o * (i % 3) as f64 * 0.3);
            let mut all = Vec::new();
            j.intersect_all(&ray, &mut all);
            let nearest = all
                .iter()
                .map(|h| h.t)
                .filter(|&t| t > EPSILON)
                .min_by(f64::total_cmp);
            for tmax in [f64::INFINITY, 0.5, 1.0, 2.0, 4.0, rng.next() * 3.0] {
                let first = j.intersect_first(&ray, tmax, &mut Vec::new());
                let want = nearest.filter(|&t| t < tmax);
                assert_eq!(
                    first.map(|h| h.t.to_bits()),
                    want.map(f64::to_bits),
                    "{k} {ray:?}"
                );
                assert_eq!(j.any_hit(&ray, tmax, &mut Vec::new()), want.is_some());
                hits += want.is_some() as usize;
            }
        }
    }
    assert!(hits > 300, "{hits}");
}

/// Orbits that leave out their last iterations (`keep_radii`) answer as the full orbit: the
/// same inside-ness, and outside the same `r` and `dr`, to the bit, on points near the
/// surface (where the orbits run longest) of the sample scenes' quaternion sets.
#[test]
fn kept_orbits_answer_as_full_orbits() {
    let mut rng = crate::geom::test_rng::Lcg(9);
    for (c, func, n) in [
        ([-0.083, 0.0, -0.83, -0.025], JuliaFn::Sqr, 8),
        ([-0.03, 0.5, -0.2, -0.5], JuliaFn::Cube, 8),
        (FRACTAL3, JuliaFn::Sqr, 7),
        ([0.2, 0.1, -0.3, 0.0], JuliaFn::Sqr, 12),
    ] {
        let fast = julia(c, Algebra::Quaternion, func, n, 20.0);
        assert!(fast.keep[1] > 0.0, "{c:?}: no radius to test");
        let mut full = fast.clone();
        full.keep = [-1.0; KEEP];
        full.keep_sq = [-1.0; KEEP];
        let mut kept = 0;
        for _ in 0..20_000 {
            let p = rng.vec(3.0);
            let (a, b) = (fast.orbit(p), full.orbit(p));
            match (a, b) {
                (Orbit::Inside, Orbit::Inside) => kept += 1,
                (Orbit::Outside { r: r1, dr: d1 }, Orbit::Outside { r: r2, dr: d2 }) => {
                    assert_eq!((r1.to_bits(), d1.to_bits()), (r2.to_bits(), d2.to_bits()))
                }
                _ => panic!("{c:?} at {p:?}: inside-ness differs"),
            }
            assert_eq!(fast.is_in(p), full.is_in(p), "{c:?} at {p:?}");
        }
        assert!(kept > 0, "{c:?}: no inside point");
    }
}

/// The default slice's lift skips w's arithmetic (`flat_slice`): the same 4-D point to the
/// bit as the general formula, for points of either sign, zeros and non-finite ones.
#[test]
fn flat_slice_lifts_as_the_formula() {
    let mut rng = crate::geom::test_rng::Lcg(11);
    for func in [JuliaFn::Sqr, JuliaFn::Sin] {
        let fast = julia(FRACTAL3, Algebra::Hypercomplex, func, 7, 20.0);
        assert!(fast.flat_slice);
        let mut full = fast.clone();
        full.flat_slice = false;
        let specials = [0.0, -0.0, f64::INFINITY, f64::NAN, 1e300];
        for i in 0..2000 {
            let mut p = rng.vec(4.0);
            if i < 125 {
                p = DVec3::new(specials[i % 5], specials[i / 5 % 5], specials[i / 25 % 5]);
            }
            let (a, b) = (fast.lift(p).0, full.lift(p).0);
            assert_eq!(a.map(f64::to_bits), b.map(f64::to_bits), "{p:?}");
        }
    }
}

/// Two orbits side by side (`is_in_n`, `orbit_n`) answer lane by lane as the lone ones, to the
/// bit, near the surface (long orbits, late escapes) and away from it, for quaternion sqr
/// and cube and for a hypercomplex set (run one by one).
#[test]
fn paired_orbits_answer_as_lone_ones() {
    let mut rng = crate::geom::test_rng::Lcg(13);
    for (c, algebra, func, n) in [
        (
            [-0.083, 0.0, -0.83, -0.025],
            Algebra::Quaternion,
            JuliaFn::Sqr,
            8,
        ),
        (
            [-0.03, 0.5, -0.2, -0.5],
            Algebra::Quaternion,
            JuliaFn::Cube,
            8,
        ),
        (FRACTAL3, Algebra::Quaternion, JuliaFn::Sqr, 7),
        ([0.2, 0.1, -0.3, 0.0], Algebra::Quaternion, JuliaFn::Sqr, 12),
        ([0.4, 0.2, 0.1, 0.0], Algebra::Hypercomplex, JuliaFn::Sqr, 6),
    ] {
        let j = julia(c, algebra, func, n, 20.0);
        let bits = |o: &Orbit| match *o {
            Orbit::Inside => None,
            Orbit::Outside { r, dr } => Some((r.to_bits(), dr.to_bits())),
        };
        let mut inside = 0;
        for i in 0..20_000 {
            let mut p = [rng.vec(2.5), rng.vec(2.5)];
            // Pull most pairs onto the surface: bisect along the line to the origin.
            if i % 4 != 0 {
                for q in p.iter_mut() {
                    let (mut lo, mut hi) = (0.0, 1.0);
                    for _ in 0..40 {
                        let m = 0.5 * (lo + hi);
                        if j.is_in(*q * m) {
                            lo = m;
                        } else {
                            hi = m;
                        }
                    }
                    *q *= if i % 2 == 0 { lo } else { hi };
                }
            }
            let pair = j.is_in_n(p);
            let four = j.is_in_n([p[0], p[1], p[1], p[0]]);
            assert_eq!(four, [pair[0], pair[1], pair[1], pair[0]]);
            assert_eq!(pair, [j.is_in(p[0]), j.is_in(p[1])], "{c:?} at {p:?}");
            let [a, b] = j.orbit_n(p);
            let [c4, ..] = j.orbit_n([p[1], p[0], p[1], p[0]]);
            assert_eq!(bits(&c4), bits(&b));
            assert_eq!(bits(&a), bits(&j.orbit(p[0])), "{c:?} at {p:?}");
            assert_eq!(bits(&b), bits(&j.orbit(p[1])), "{c:?} at {p:?}");
            inside += pair[0] as usize;
        }
        assert!(inside > 1000, "{c:?}: {inside}");
    }
}

/// The AVX lanes (`avx::tangents`, `avx::inside4`, `avx::orbits4`) give the scalar code's bits:
/// the tangents of the normal, and four distinct orbits side by side.
#[cfg(target_arch = "x86_64")]
#[test]
fn avx_lanes_are_the_scalar_code() {
    if !crate::math::has_avx() {
        return;
    }
    let mut rng = crate::geom::test_rng::Lcg(17);
    for (c, func) in [
        ([-0.083, 0.0, -0.83, -0.025], JuliaFn::Sqr),
        ([-0.03, 0.5, -0.2, -0.5], JuliaFn::Cube),
        (FRACTAL3, JuliaFn::Sqr),
    ] {
        let j = julia(c, Algebra::Quaternion, func, 8, 20.0);
        for _ in 0..5000 {
            let p: [DVec3; 4] = std::array::from_fn(|_| rng.vec(2.5));
            let h = p.map(|p| j.lift(p).0);
            let (axes, n) = (j.lift(p[0]).1, 1 + (rng.next() * 10.0) as u32);
            let want = j.tangents(h[0], axes, n);
            // SAFETY: the CPU has AVX (checked above).
            let got = unsafe {
                if func == JuliaFn::Cube {
                    super::avx::tangents::<true>(&j, h[0], axes, n)
                } else {
                    super::avx::tangents::<false>(&j, h[0], axes, n)
                }
            };
            // Any NaN as one (escaped orbits overflow; the normal then falls back to p).
            let b = |x: f64| if x.is_nan() { 1 } else { x.to_bits() };
            let bits = |(h, t): (Q, [Q; 3])| (h.map(b), t.map(|q| q.map(b)));
            assert_eq!(bits(got), bits(want), "{c:?} at {p:?}");
            assert_eq!(j.is_in_n(p), p.map(|p| j.is_in(p)), "{c:?} at {p:?}");
            // `is_in4`'s numbers lie on the side of the bailout its answers say (or are NaN).
            let (ins, g) = j.is_in4(p);
            assert_eq!(ins, j.is_in_n(p));
            assert!(ins
                .iter()
                .zip(g)
                .all(|(&i, g)| g.is_nan() || (g > 0.0) != i));
            let lone = p.map(|p| j.orbit(p));
            let four = j.orbit_n(p);
            for (a, b) in four.iter().zip(&lone) {
                let key = |o: &Orbit| match *o {
                    Orbit::Inside => None,
                    Orbit::Outside { r, dr } => Some((r.to_bits(), dr.to_bits())),
                };
                assert_eq!(key(a), key(b), "{c:?} at {p:?}");
            }
        }
    }
}

/// The orbit's branches on squared norms against `bail_sq` and `keep_thr` answer as the
/// comparisons of the norms themselves (the code before them), to the bit, for points on
/// and beside the surface.
#[test]
fn squared_norm_branches_are_the_norm_ones() {
    let mut rng = crate::geom::test_rng::Lcg(31);
    for (c, func, n) in [
        ([-0.083, 0.0, -0.83, -0.025], JuliaFn::Sqr, 8),
        ([-0.03, 0.5, -0.2, -0.5], JuliaFn::Cube, 8),
        (FRACTAL3, JuliaFn::Sqr, 7),
        ([0.2, 0.1, -0.3, 0.0], JuliaFn::Sqr, 12),
    ] {
        let j = julia(c, Algebra::Quaternion, func, n, 20.0);
        let by_norms = |p: DVec3| {
            let (mut h, _) = j.lift(p);
            let mut r = qnorm(&h);
            let mut dr = 1.0;
            if r > j.bailout {
                return Some((r.to_bits(), 1f64.to_bits()));
            }
            let steps = j.max_iteration - 1;
            for k in 0..steps {
                let cube = func == JuliaFn::Cube;
                h = j.quaternion_step(&h);
                dr *= if cube { 3.0 * r * r } else { 2.0 * r };
                r = qnorm(&h);
                if r > j.bailout {
                    return Some((r.to_bits(), dr.to_bits()));
                }
                let left = (steps - 1 - k) as usize;
                if left < KEEP && r <= j.keep[left] {
                    return None;
                }
            }
            None
        };
        for i in 0..40_000 {
            let mut p = rng.vec(2.5);
            if i % 2 == 0 {
                let (lo, hi) = to_the_edge(&j, p);
                p *= if i % 4 == 0 { lo } else { hi };
            }
            let got = match j.orbit(p) {
                Orbit::Inside => None,
                Orbit::Outside { r, dr } => Some((r.to_bits(), dr.to_bits())),
            };
            assert_eq!(got, by_norms(p), "{c:?} at {p:?}");
        }
    }
}

/// `qsquare` (the orbit's scalar square) against `qmul(h, h)`, bit for bit: random
/// quaternions over many scales, signed zeros, infinities and NaN.
#[test]
fn qsquare_is_qmul_to_the_bit() {
    let mut seed = 0x1234_5678_9abc_def1u64;
    let mut unit = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let edge = [
        0.0,
        -0.0,
        1.0,
        -1.0,
        f64::MIN_POSITIVE,
        1e-310,
        1e300,
        f64::INFINITY,
    ];
    let mut cases = Vec::new();
    for _ in 0..200_000 {
        let scale = 10f64.powf(8.0 * unit() - 4.0);
        cases.push([0; 4].map(|_| scale * (2.0 * unit() - 1.0)));
    }
    for k in 0..4096usize {
        cases.push(std::array::from_fn(|i| edge[(k >> (3 * i)) % edge.len()]));
    }
    cases.push([f64::NAN, 1.0, -2.0, 0.5]);
    for h in cases {
        let want = qmul(&h, &h);
        let got = qsquare(&h);
        for i in 0..4 {
            assert!(
                got[i].to_bits() == want[i].to_bits() || (got[i].is_nan() && want[i].is_nan()),
                "{h:?} component {i}: {} against {}",
                got[i],
                want[i]
            );
        }
    }
}

/// The hypercomplex orbit with the square inlined (`SQR`) against the one through
/// `JuliaFn::apply`, bit for bit, with and without the estimate: points near the surface, far
/// out and at edge values (signed zeros, subnormals, overflowing squares, NaN).
#[test]
fn hypercomplex_square_inlined_is_apply() {
    let mut rng = crate::geom::test_rng::Lcg(29);
    let bits = |o: Orbit| match o {
        Orbit::Inside => None,
        Orbit::Outside { r, dr } => Some((r.to_bits(), dr.to_bits())),
    };
    let edge = [0.0, -0.0, 1e-310, -1.0, 0.5, 2.0, 1e160, -1e300, f64::NAN];
    for (c, func, n) in [
        ([-0.745, 0.0, 0.113, 0.05], JuliaFn::Sqr, 9),
        ([0.2, 0.1, 0.59, -0.2], JuliaFn::Sqr, 7),
        ([0.4, 0.2, 0.1, 0.0], JuliaFn::Cube, 6),
    ] {
        let j = julia(c, Algebra::Hypercomplex, func, n, 20.0);
        let mut points: Vec<[f64; 4]> = (0..50_000)
            .map(|i| {
                let p = rng.vec(if i % 2 == 0 { 1.5 } else { 4.0 });
                [p.x, p.y, p.z, 0.1 * p.x]
            })
            .collect();
        for k in 0..edge.len().pow(3) {
            points.push(std::array::from_fn(|i| {
                edge[(k / edge.len().pow(i.min(2) as u32)) % edge.len()]
            }));
        }
        for h in points {
            assert_eq!(
                bits(j.hypercomplex_orbit::<true, true>(h)),
                bits(j.hypercomplex_orbit::<false, true>(h)),
                "{c:?} at {h:?}"
            );
            assert_eq!(
                bits(j.hypercomplex_orbit::<true, false>(h)),
                bits(j.hypercomplex_orbit::<false, false>(h)),
                "{c:?} at {h:?}"
            );
        }
    }
}
