//! Dispersion (`interior { dispersion D dispersion_samples N }`): light entering such an
//! object splits into N colours, each refracting with its own ior; the colours add up to
//! white. Measured with povray 3.7 (scripts/dispersion_spectrum.sh, fitted by
//! scripts/dispersion_fit.py): a white line seen through a tilted slab shows N images at iors
//! ior · D^((i + ½)/N − ½), i = 0 (red) to N − 1 (violet), so D is the ratio between the
//! spectrum's violet and red ends; image i has the colour of bin i of one spectrum whatever N
//! (2 bins: rgb 0.956 0.730 0.012 and 0.039 0.270 0.982 in linear light; 3 bins: 0.791 0.262 0,
//! 0.159 0.737 0.301, 0.039 0.002 0.693). lancer's spectrum is a piecewise-linear fit of the 2-,
//! 3- and 10-bin colours (within 0.005 of the 2- and 3-bin ones).

use crate::math::DVec3;
use crate::scene::object::Object;

/// The spectrum's red, green and blue at 11 evenly spaced points from red (0) to violet (1),
/// each channel averaging 1 over the spectrum (scripts/dispersion_fit.py).
const SPECTRUM: [[f64; 3]; 11] = [
    [1.52, 0.137, 0.008],
    [2.284, 0.007, 0.012],
    [2.888, 0.418, 0.013],
    [2.541, 2.857, 0.0],
    [1.119, 2.658, 0.0],
    [0.002, 3.865, 0.221],
    [0.0, 1.059, 2.309],
    [0.017, 0.0, 3.245],
    [0.033, 0.0, 1.825],
    [0.133, 0.0, 1.896],
    [0.463, 0.0, 1.471],
];

/// The object's (dispersion, samples) when light entering it splits.
pub fn of(obj: &Object) -> Option<(f64, u32)> {
    let int = obj.interior.as_deref()?;
    (int.dispersion != 1.0 && int.dispersion > 0.0).then_some((
        int.dispersion as f64,
        (int.dispersion_samples as u32).max(2),
    ))
}

/// The ior of `obj` for a ray carrying spectrum position `wave` (None: undispersed light).
pub fn ior(obj: &Object, wave: Option<f32>) -> f64 {
    match (wave, of(obj)) {
        (Some(t), Some((d, _))) => obj.ior * d.powf(t as f64 - 0.5),
        _ => obj.ior,
    }
}

/// The N colours: (spectrum position of the bin's centre, the bin's colour). The colours add
/// up to white.
pub fn samples(n: u32) -> impl Iterator<Item = (f32, DVec3)> {
    let nf = n as f64;
    (0..n).map(move |i| {
        let (a, b) = (i as f64 / nf, (i + 1) as f64 / nf);
        ((((i as f64) + 0.5) / nf) as f32, integral(a, b))
    })
}

/// ∫ of the spectrum over [a, b] (each channel's whole integral is 1).
fn integral(a: f64, b: f64) -> DVec3 {
    let at = |t: f64| {
        let x = (t * 10.0).clamp(0.0, 10.0);
        let k = (x.floor() as usize).min(9);
        let f = x - k as f64;
        let (p, q) = (SPECTRUM[k], SPECTRUM[k + 1]);
        DVec3::new(
            p[0] + (q[0] - p[0]) * f,
            p[1] + (q[1] - p[1]) * f,
            p[2] + (q[2] - p[2]) * f,
        )
    };
    // Exact for a piecewise-linear function: trapezoids between the knots inside [a, b].
    let mut pts = vec![a];
    for k in 1..10 {
        let t = k as f64 / 10.0;
        if t > a && t < b {
            pts.push(t);
        }
    }
    pts.push(b);
    let sum: DVec3 = pts
        .windows(2)
        .map(|w| (at(w[0]) + at(w[1])) * (0.5 * (w[1] - w[0])))
        .sum();
    sum / total()
}

/// The integral over the whole spectrum, per channel (the table's averages are 1 to three
/// decimals; this makes the colours add up to white exactly).
fn total() -> DVec3 {
    let mut s = DVec3::ZERO;
    for k in 0..10 {
        let (p, q) = (SPECTRUM[k], SPECTRUM[k + 1]);
        s += DVec3::new(p[0] + q[0], p[1] + q[1], p[2] + q[2]) * 0.05;
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colours_add_to_white_and_match_the_measured_bins() {
        for n in [2, 3, 7, 20] {
            let sum: DVec3 = samples(n).map(|(_, c)| c).sum();
            assert!((sum - DVec3::ONE).abs().max_element() < 1e-9, "{n}: {sum}");
        }
        let two: Vec<DVec3> = samples(2).map(|(_, c)| c).collect();
        assert!(
            (two[0] - DVec3::new(0.956, 0.730, 0.012))
                .abs()
                .max_element()
                < 0.01
        );
        assert!(
            (two[1] - DVec3::new(0.039, 0.270, 0.982))
                .abs()
                .max_element()
                < 0.01
        );
        let three: Vec<DVec3> = samples(3).map(|(_, c)| c).collect();
        assert!(
            (three[1] - DVec3::new(0.159, 0.737, 0.301))
                .abs()
                .max_element()
                < 0.01
        );
    }
}
