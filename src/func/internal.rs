//! POV-Ray's built-in functions that `functions.inc` binds as `function { internal(N) }`.
//!
//! The numbers are those `functions.inc` uses. The formulas were written from the parameter
//! descriptions in `functions.inc` and the manual, then checked against the `povray` binary by
//! printing each function at several points (see the tests below for the values captured).
//! Numbers lancer does not implement yet (the rarer surfaces and curves) are
//! reported as unsupported when such a function is called, not when it is declared.

use super::internal_noise as noisy;
use super::internal_surfaces as surf;

/// One internal function, by what it computes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Internal {
    Ellipsoid,
    /// `f_helix1`, `f_helix2`, `f_spiral`, `f_poly4`: see [`super::internal_surfaces`].
    Helix1,
    Helix2,
    Spiral,
    Poly4,
    /// A polynomial times a field strength: see [`super::internal_polynomials`].
    Polynomial(u32),
    /// A plane curve's polynomial, extruded or revolved: see [`super::internal_curves`].
    Curve(u32),
    /// `f_noise3d`: the default noise generator's value in [0, 1].
    Noise3d,
    /// `f_noise_generator(x, y, z, generator)`.
    NoiseGenerator,
    /// `f_ridged_mf(x, y, z, H, lacunarity, octaves, offset, gain, generator)`: Musgrave's
    /// ridged multifractal over signed noise.
    RidgedMf,
    /// `f_hetero_mf(x, y, z, H, lacunarity, octaves, offset, T, generator)`.
    HeteroMf,
    /// `f_ridge(x, y, z, lambda, octaves, omega, offset, ridge, generator)`.
    Ridge,
    Paraboloid,
    Ph,
    R,
    RoundedBox,
    Sphere,
    Superellipsoid,
    Th,
    Torus,
    Torus2,
    /// `f_hex_x`, `f_hex_y`: see [`super::internal_surfaces`].
    HexX,
    HexY,
    /// `f_cross_ellipsoids`, `f_isect_ellipsoids`.
    CrossEllipsoids,
    IsectEllipsoids,
    Quantum,
    /// An internal number lancer does not implement.
    Unknown(u32),
}

/// Some POV-Ray field functions keep their value within ±10 so an isosurface's gradient
/// estimate stays bounded; measured with `f_paraboloid` and `f_torus2`.
fn clamp10(v: f64) -> f64 {
    v.clamp(-10.0, 10.0)
}

/// The names `functions.inc` gives the internal numbers, for error messages.
const NAMES: &[&str] = &[
    "f_algbr_cyl1",
    "f_algbr_cyl2",
    "f_algbr_cyl3",
    "f_algbr_cyl4",
    "f_bicorn",
    "f_bifolia",
    "f_blob",
    "f_blob2",
    "f_boy_surface",
    "f_comma",
    "f_cross_ellipsoids",
    "f_crossed_trough",
    "f_cubic_saddle",
    "f_cushion",
    "f_devils_curve",
    "f_devils_curve_2d",
    "f_dupin_cyclid",
    "f_ellipsoid",
    "f_enneper",
    "f_flange_cover",
    "f_folium_surface",
    "f_folium_surface_2d",
    "f_glob",
    "f_heart",
    "f_helical_torus",
    "f_helix1",
    "f_helix2",
    "f_hex_x",
    "f_hex_y",
    "f_hetero_mf",
    "f_hunt_surface",
    "f_hyperbolic_torus",
    "f_isect_ellipsoids",
    "f_kampyle_of_eudoxus",
    "f_kampyle_of_eudoxus_2d",
    "f_klein_bottle",
    "f_kummer_surface_v1",
    "f_kummer_surface_v2",
    "f_lemniscate_of_gerono",
    "f_lemniscate_of_gerono_2d",
    "f_mesh1",
    "f_mitre",
    "f_nodal_cubic",
    "f_odd",
    "f_ovals_of_cassini",
    "f_paraboloid",
    "f_parabolic_torus",
    "f_ph",
    "f_pillow",
    "f_piriform",
    "f_piriform_2d",
    "f_poly4",
    "f_polytubes",
    "f_quantum",
    "f_quartic_paraboloid",
    "f_quartic_saddle",
    "f_quartic_cylinder",
    "f_r",
    "f_ridge",
    "f_ridged_mf",
    "f_rounded_box",
    "f_sphere",
    "f_spikes",
    "f_spikes_2d",
    "f_spiral",
    "f_steiners_roman",
    "f_strophoid",
    "f_strophoid_2d",
    "f_superellipsoid",
    "f_th",
    "f_torus",
    "f_torus2",
    "f_torus_gumdrop",
    "f_umbrella",
    "f_witch_of_agnesi",
    "f_witch_of_agnesi_2d",
    "f_noise3d",
    "(internal 77)",
    "f_noise_generator",
];

impl Internal {
    pub fn from_id(id: u32) -> Internal {
        match id {
            17 => Internal::Ellipsoid,
            25 => Internal::Helix1,
            26 => Internal::Helix2,
            64 => Internal::Spiral,
            51 => Internal::Poly4,
            45 => Internal::Paraboloid,
            47 => Internal::Ph,
            57 => Internal::R,
            60 => Internal::RoundedBox,
            61 => Internal::Sphere,
            68 => Internal::Superellipsoid,
            69 => Internal::Th,
            70 => Internal::Torus,
            71 => Internal::Torus2,
            76 => Internal::Noise3d,
            78 => Internal::NoiseGenerator,
            59 => Internal::RidgedMf,
            29 => Internal::HeteroMf,
            27 => Internal::HexX,
            10 => Internal::CrossEllipsoids,
            53 => Internal::Quantum,
            32 => Internal::IsectEllipsoids,
            28 => Internal::HexY,
            58 => Internal::Ridge,
            n if super::internal_polynomials::terms(n).is_some() => Internal::Polynomial(n),
            n if super::internal_curves::terms(n).is_some() => Internal::Curve(n),
            n => Internal::Unknown(n),
        }
    }

    /// Number of arguments: x, y, z and the extra parameters.
    pub fn arity(self) -> Option<usize> {
        Some(match self {
            Internal::Ph | Internal::R | Internal::Th | Internal::Noise3d => 3,
            Internal::Sphere
            | Internal::Paraboloid
            | Internal::NoiseGenerator
            | Internal::HexX
            | Internal::HexY
            | Internal::Quantum => 4,
            Internal::Polynomial(id) => 4 + super::internal_polynomials::terms(id)?.1,
            Internal::Curve(id) => 7 + super::internal_curves::terms(id)?.1,
            Internal::Torus | Internal::Superellipsoid => 5,
            Internal::Ellipsoid | Internal::Torus2 => 6,
            Internal::Poly4 => 8,
            Internal::RoundedBox | Internal::CrossEllipsoids | Internal::IsectEllipsoids => 7,
            Internal::RidgedMf | Internal::HeteroMf | Internal::Ridge | Internal::Spiral => 9,
            Internal::Helix1 | Internal::Helix2 => 10,
            Internal::Unknown(_) => return None,
        })
    }

    pub fn unsupported_reason(self) -> Option<String> {
        match self {
            Internal::Unknown(n) => Some(match NAMES.get(n as usize) {
                Some(name) => format!(
                    "'{name}' is not supported by lancer yet (internal function {n} of functions.inc)"
                ),
                None => format!("POV-Ray 3.7 has no internal function {n}"),
            }),
            _ => None,
        }
    }

    /// `a` holds at least [`Internal::arity`] values (missing ones read as zero).
    pub fn eval(self, a: &[f64]) -> f64 {
        let g = |i: usize| a.get(i).copied().unwrap_or(0.0);
        let (x, y, z) = (g(0), g(1), g(2));
        match self {
            Internal::Sphere => (x * x + y * y + z * z).sqrt() - g(3),
            Internal::R => (x * x + y * y + z * z).sqrt(),
            Internal::Th => atan2_or_zero(x, z),
            Internal::Ph => {
                let r = (x * x + y * y + z * z).sqrt();
                if r == 0.0 {
                    0.0
                } else {
                    (y / r).clamp(-1.0, 1.0).acos()
                }
            }
            Internal::Torus => {
                let d = (x * x + z * z).sqrt() - g(3);
                (d * d + y * y).sqrt() - g(4)
            }
            Internal::Torus2 => {
                let (big, small) = (g(4) * g(4), g(5) * g(5));
                let s = x * x + y * y + z * z + big - small;
                clamp10(-g(3) * (s * s - 4.0 * big * (x * x + z * z)))
            }
            Internal::Ellipsoid => {
                ((x * g(3)).powi(2) + (y * g(4)).powi(2) + (z * g(5)).powi(2)).sqrt()
            }
            Internal::Paraboloid => clamp10(g(3) * (y - x * x - z * z)),
            Internal::RoundedBox => {
                let r = g(3);
                let q = |p: f64, half: f64| (p.abs() - half + r).max(0.0);
                let (qx, qy, qz) = (q(x, g(4)), q(y, g(5)), q(z, g(6)));
                // The extra millionth is POV-Ray's: the surface sits just outside the box.
                (qx * qx + qy * qy + qz * qz).sqrt() - r - 1e-6
            }
            Internal::Superellipsoid => {
                let (e, n) = (g(3), g(4));
                let xy = x.abs().powf(2.0 / e) + y.abs().powf(2.0 / e);
                1.0 - (xy.powf(e / n) + z.abs().powf(2.0 / n)).powf(n / 2.0)
            }
            Internal::Noise3d => crate::render::noise::noise(crate::math::DVec3::new(x, y, z), 2),
            Internal::NoiseGenerator => crate::render::noise::noise(
                crate::math::DVec3::new(x, y, z),
                (g(3) as i64).clamp(1, 3) as u8,
            ),
            Internal::RidgedMf => noisy::ridged_mf(
                crate::math::DVec3::new(x, y, z),
                [g(3), g(4), g(5), g(6), g(7)],
                (g(8) as i64).clamp(1, 3) as u8,
            ),
            Internal::HeteroMf => noisy::hetero_mf(
                crate::math::DVec3::new(x, y, z),
                [g(3), g(4), g(5), g(6), g(7)],
                (g(8) as i64).clamp(1, 3) as u8,
            ),
            Internal::Ridge => noisy::ridge(
                crate::math::DVec3::new(x, y, z),
                [g(3), g(4), g(5), g(6), g(7)],
                (g(8) as i64).clamp(1, 3) as u8,
            ),
            Internal::Helix1 => surf::helix1(x, y, z, std::array::from_fn(|i| g(i + 3))),
            Internal::Helix2 => surf::helix2(x, y, z, std::array::from_fn(|i| g(i + 3))),
            Internal::Spiral => surf::spiral(x, y, z, std::array::from_fn(|i| g(i + 3))),
            Internal::HexX => surf::hex_x(x, y),
            Internal::HexY => surf::hex_y(x, y),
            Internal::Quantum => surf::quantum(x, y, z),
            Internal::CrossEllipsoids => {
                surf::crossed_ellipsoids(x, y, z, [g(3), g(4), g(5), g(6)], true)
            }
            Internal::IsectEllipsoids => {
                surf::crossed_ellipsoids(x, y, z, [g(3), g(4), g(5), g(6)], false)
            }
            Internal::Poly4 => surf::poly4(x, y, z, std::array::from_fn(|i| g(i + 3))),
            Internal::Polynomial(id) => match super::internal_polynomials::terms(id) {
                Some((t, _)) => super::internal_polynomials::eval(t, a),
                None => f64::NAN,
            },
            Internal::Curve(id) => match super::internal_curves::terms(id) {
                Some((t, k)) => super::internal_curves::eval(t, k, a),
                None => f64::NAN,
            },
            Internal::Unknown(_) => f64::NAN,
        }
    }
}

fn atan2_or_zero(a: f64, b: f64) -> f64 {
    if a == 0.0 && b == 0.0 {
        0.0
    } else {
        a.atan2(b)
    }
}

/// The points at which POV-Ray's printed values of internal functions are tabled in the
/// tests (scripts/measure_internal_functions.py's default points).
#[cfg(test)]
pub(crate) const PRINTED_AT: [[f64; 3]; 6] = [
    [1.0, 2.0, 3.0],
    [-0.5, 0.3, 0.2],
    [0.2, -1.5, 0.7],
    [0.0, 0.0, 0.4],
    [0.7, 0.1, -0.3],
    [-1.1, 0.45, -0.6],
];

/// Asserts that `f` with parameters `extra` takes the arity it should and gives POV-Ray's
/// printed values `want` at the first `want.len()` of `PRINTED_AT`, within 1e-12 (printed with
/// 15 decimals).
#[cfg(test)]
pub(crate) fn check_printed(f: Internal, extra: &[f64], want: &[f64]) {
    for (p, w) in PRINTED_AT.iter().zip(want) {
        let args = [&p[..], extra].concat();
        assert_eq!(f.arity(), Some(args.len()), "{f:?}");
        let got = f.eval(&args);
        assert!(
            (got - w).abs() < 1e-12,
            "{f:?} {extra:?} at {p:?}: {got} vs {w}"
        );
    }
}

#[cfg(test)]
// The expected values are kept exactly as POV-Ray printed them.
#[allow(clippy::excessive_precision)]
mod tests {
    use super::*;

    /// Values printed by POV-Ray 3.7 for `f_...(X,Y,Z,...)` at these points.
    #[test]
    fn matches_povray_at_sample_points() {
        #[rustfmt::skip]
        let cases: &[(Internal, &[f64], [f64; 4])] = &[
            (Internal::Sphere, &[0.8], [2.941657386773941, -0.183558599703102, 0.867333200053306, -0.4]),
            (Internal::Torus, &[1.2, 0.3], [2.501880371392735, 0.426333564065243, 1.272505525132639, 0.5]),
            (Internal::R, &[], [3.741657386773941, 0.616441400296898, 1.667333200053307, 0.4]),
            (Internal::Th, &[], [0.321750554396642, -1.190289949682532, 0.278299659005111, 0.0]),
            (Internal::Ph, &[], [1.006853685434268, 1.062529080623613, 2.689741142411326, std::f64::consts::FRAC_PI_2]),
            (Internal::RoundedBox, &[0.1, 0.5, 0.6, 0.7], [2.793094228297886, -0.000001, 0.904986562112089, -0.100001]),
            (Internal::RoundedBox, &[0.0, 2.0, 2.5, 3.5], [-0.000001; 4]),
            (Internal::Ellipsoid, &[0.5, 2.0, 3.0], [9.861541461658010, 0.884590300647707, 3.663331816802840, 1.2]),
            (Internal::Superellipsoid, &[0.5, 2.0], [-4.030543184868931, 0.284532634290270, -1.200118504474468, 0.6]),
            (Internal::Superellipsoid, &[1.0, 1.0], [-2.741657386773941, 0.383558599703102, -0.667333200053307, 0.6]),
            (Internal::Paraboloid, &[2.0], [-10.0, 0.02, -4.06, -0.32]),
            (Internal::Torus2, &[2.0, 1.2, 0.3], [-10.0, -2.644999999999999, -10.0, -2.716999999999999]),
            // povray's first f_ridged_mf call of its run (see ridged_mf), generator 1 and 2.
            (Internal::RidgedMf, &[0.07, 2.2, 7.0, 0.6, 0.9, 1.0], [0.048016074648238, 0.002640418425742, 0.238491689069120, 0.342913651060993]),
            // Fractional octaves, T 2 and 1, generators 2 and 3.
            (Internal::HeteroMf, &[0.5, 2.0, 3.7, 0.3, 2.0, 2.0], [0.163751919025990, 0.012995625247854, 0.331596875334881, 0.373987374055675]),
            (Internal::HeteroMf, &[0.8, 2.2, 6.0, -0.2, 1.0, 3.0], [-0.210436405577135, -0.098259394224290, -0.490169840430962, 0.146317492945162]),
            (Internal::HexX, &[0.0], [0.5, 0.509807621135332, 0.666025403784439, 0.0]),
            (Internal::HexY, &[0.0], [0.133974596215561, 0.283012701892219, 0.0, 0.0]),
            (Internal::CrossEllipsoids, &[2.0, 0.7, 1.5, 0.3], [0.299997488260186, -0.749658746601916, 0.152146726447691, -1.041066386250536]),
            (Internal::IsectEllipsoids, &[0.5, -0.3, 1.2, -0.2], [-11.585283003630231, -1.478032207077566, -2.031841155159748, -1.429148381468746]),
            (Internal::Quantum, &[0.0], [1.156394782809103, 1.191489614654903, -1.530336625039595, 1.175970970720714]),
            (Internal::Curve(21), &[1.0, 0.8, 0.6, 0.0, 0.0, 0.0], [4.800000000000001, -0.607, -1.144, 0.0]),
            // Revolved about y (switch 1), offset 0.4, turned 30 degrees.
            (Internal::Curve(39), &[-0.7, 1.2, 0.9, 1.0, 0.4, 30.0], [7.331905267614897, 0.075062648479237, 0.677053370410730, 0.0]),
            // A ridge below 0.5 (folds scaled) and a negative one, fractional octaves.
            (Internal::Ridge, &[2.1, 3.5, 0.6, 0.3, 0.4, 2.0], [-0.326484689433890, -0.298163106449626, -0.129975892950166, -0.142530703793675]),
            (Internal::Ridge, &[1.7, 5.0, 0.8, 0.6, -1.0, 1.0], [0.274838017242055, 0.035857079179415, 0.252099538318762, 0.236131660963319]),
        ];
        for (f, extra, want) in cases {
            check_printed(*f, extra, want);
        }
        assert_eq!(Internal::Paraboloid.eval(&[0.0, 20.0, 0.0, 2.0]), 10.0);
        assert_eq!(Internal::Ph.eval(&[0.0, 0.0, 0.0]), 0.0);
        assert_eq!(Internal::Th.eval(&[0.0, 0.0, 0.0]), 0.0);
    }

    #[test]
    fn unknown_numbers_are_named_in_the_reason() {
        let r = Internal::from_id(0).unsupported_reason().unwrap();
        assert!(r.contains("f_algbr_cyl1"), "{r}");
        assert!(Internal::from_id(61).unsupported_reason().is_none());
        assert!(Internal::from_id(500)
            .unsupported_reason()
            .unwrap()
            .contains("no internal function 500"));
    }
}
