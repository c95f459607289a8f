//! The functions a `julia_fractal` iterates (`JuliaFn`): each one's complex form on a half of
//! a hypercomplex number and its derivative there (quaternions use only sqr and cube, in
//! julia.rs's own products).

use num_complex::Complex64 as C;

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum JuliaFn {
    Sqr,
    Cube,
    Exp,
    Reciprocal,
    Sin,
    Asin,
    Sinh,
    Asinh,
    Cos,
    Acos,
    Cosh,
    Acosh,
    Tan,
    Atan,
    Tanh,
    Atanh,
    Ln,
    Pwr(f64, f64),
}

/// POV-Ray's complex arc cosine (not the principal one: acos(−0.5) = −2.094, measured).
fn acos_pov(z: C) -> C {
    -C::i() * (z + (z * z - 1.0).sqrt()).ln()
}

impl JuliaFn {
    /// Functions whose hypercomplex form reads the 3-D point as (x, y, y).
    pub(super) fn transcendental(self) -> bool {
        !matches!(self, JuliaFn::Sqr | JuliaFn::Cube | JuliaFn::Reciprocal)
    }

    /// The complex function on one half of a hypercomplex number (cube is the square).
    pub(super) fn apply(self, z: C) -> C {
        match self {
            JuliaFn::Sqr | JuliaFn::Cube => z * z,
            JuliaFn::Exp => z.exp(),
            JuliaFn::Reciprocal => z.inv(),
            JuliaFn::Sin => z.sin(),
            JuliaFn::Asin => z.asin(),
            JuliaFn::Sinh => z.sinh(),
            JuliaFn::Asinh => z.asinh(),
            JuliaFn::Cos => z.cos(),
            JuliaFn::Acos => acos_pov(z),
            JuliaFn::Cosh => z.cosh(),
            JuliaFn::Acosh => C::i() * acos_pov(z),
            JuliaFn::Tan => z.tan(),
            JuliaFn::Atan => z.atan(),
            JuliaFn::Tanh => z.tanh(),
            JuliaFn::Atanh => z.atanh(),
            JuliaFn::Ln => z.ln(),
            JuliaFn::Pwr(x, y) => {
                if z == C::new(0.0, 0.0) {
                    z
                } else {
                    (C::new(x, y) * z.ln()).exp()
                }
            }
        }
    }

    /// The derivative of `apply` at z, given its value `f` there.
    pub(super) fn derivative(self, z: C, f: C) -> C {
        let one = C::new(1.0, 0.0);
        match self {
            JuliaFn::Sqr | JuliaFn::Cube => 2.0 * z,
            JuliaFn::Exp => f,
            JuliaFn::Reciprocal => -(f * f),
            JuliaFn::Sin => z.cos(),
            JuliaFn::Asin => (one - z * z).sqrt().inv(),
            JuliaFn::Sinh => z.cosh(),
            JuliaFn::Asinh => (one + z * z).sqrt().inv(),
            JuliaFn::Cos => -z.sin(),
            JuliaFn::Acos => -C::i() * (z * z - 1.0).sqrt().inv(),
            JuliaFn::Cosh => z.sinh(),
            JuliaFn::Acosh => (z * z - 1.0).sqrt().inv(),
            JuliaFn::Tan => (z.cos() * z.cos()).inv(),
            JuliaFn::Atan => (one + z * z).inv(),
            JuliaFn::Tanh => (z.cosh() * z.cosh()).inv(),
            JuliaFn::Atanh => (one - z * z).inv(),
            JuliaFn::Ln => z.inv(),
            JuliaFn::Pwr(x, y) => {
                if z == C::new(0.0, 0.0) {
                    z
                } else {
                    C::new(x, y) * f / z
                }
            }
        }
    }
}
