//! Warps (`warp { turbulence | repeat | black_hole | planar ... }`): each moves the evaluation point in
//! the space the pattern had when the warp was written.

use crate::math::DVec3;
use crate::scene::pattern::{Warp, WarpKind};

use super::noise;
use super::pattern_wrap::rem_euclid;

pub fn apply(w: &Warp, q: DVec3, generator: u8) -> DVec3 {
    let identity = w.space.is_identity();
    let p = if identity { q } else { w.space.point(q) };
    let moved = match &w.kind {
        WarpKind::Turbulence(t) => {
            p + t.amount * noise::turbulence_vec(p, t.octaves, t.omega, t.lambda, generator)
        }
        WarpKind::Repeat { dir, offset, flip } => repeat(p, *dir, *offset, *flip),
        WarpKind::Planar { e1, e2, e3, d } => *e1 * p.x + *e2 * p.y + *e3 * *d,
        WarpKind::Wrap {
            spherical,
            orientation,
            dist_exp,
        } => wrap(p, *spherical, *orientation, *dist_exp),
        WarpKind::BlackHole {
            center,
            radius,
            strength,
            falloff,
            inverse,
            repeat,
            turbulence,
        } => {
            let mut c = *center;
            if *repeat != DVec3::ZERO {
                // The hole repeats in blocks of `repeat`; find this point's block.
                let cell = DVec3::new(
                    cell_of(p.x, repeat.x),
                    cell_of(p.y, repeat.y),
                    cell_of(p.z, repeat.z),
                );
                c += cell * *repeat;
                if *turbulence != DVec3::ZERO {
                    let (x, y, z) = (cell.x as i64, cell.y as i64, cell.z as i64);
                    let jitter = DVec3::new(
                        noise::unit(noise::hash3(x, y, z, 31)),
                        noise::unit(noise::hash3(x, y, z, 32)),
                        noise::unit(noise::hash3(x, y, z, 33)),
                    );
                    c += *turbulence * jitter;
                }
            }
            let d = p - c;
            let len = d.length();
            if *radius <= 0.0 || len >= *radius || len == 0.0 {
                p
            } else {
                let closeness = 1.0 - len / radius;
                let force = (closeness.powf(*falloff) * strength).min(1.0);
                // Sucking in shows the pattern from farther out; inverse pushes it away.
                if *inverse {
                    p - d * force
                } else {
                    p + d * force
                }
            }
        }
    };
    if identity {
        moved
    } else {
        w.space.inv_point(moved)
    }
}

fn cell_of(v: f64, size: f64) -> f64 {
    if size == 0.0 {
        0.0
    } else {
        (v / size).floor()
    }
}

/// `repeat <d> offset <o> flip <f>`: the slab from 0 to |d| along d's axis is copied along it,
/// each copy moved by `offset` once more and every other copy mirrored on the flipped axes.
fn repeat(p: DVec3, dir: DVec3, offset: DVec3, flip: DVec3) -> DVec3 {
    let axis = if dir.x != 0.0 {
        0
    } else if dir.y != 0.0 {
        1
    } else if dir.z != 0.0 {
        2
    } else {
        return p;
    };
    let width = dir[axis];
    let n = (p[axis] / width).floor();
    let mut q = p;
    q[axis] -= n * width;
    if rem_euclid(n, 2.0) == 1.0 {
        for k in 0..3 {
            if flip[k] != 0.0 {
                q[k] = if k == axis { width - q[k] } else { -q[k] };
            }
        }
    }
    q + offset * n
}

/// The cylindrical and spherical warps, measured with scripts/measure_pattern.py (function
/// patterns of x, y, z read through the warp): u = atan2(z, x)/2π in [0, 1); v = y for a
/// cylinder, asin(y/r)/π + 1/2 for a sphere; d = the distance from the y axis (cylinder) or
/// the origin (sphere); u (and a sphere's v) times d^dist_exp. The triple (u, v, d) is
/// (x, y, z) for orientation z, (u, −d, v) for y, (d, v, −u) for x.
fn wrap(p: DVec3, spherical: bool, orientation: u8, dist_exp: f64) -> DVec3 {
    let mut u = p.z.atan2(p.x) / std::f64::consts::TAU;
    if u < 0.0 {
        u += 1.0;
    }
    let (mut v, d) = if spherical {
        let r = p.length();
        let lat = if r > 0.0 {
            (p.y / r).clamp(-1.0, 1.0).asin() / std::f64::consts::PI + 0.5
        } else {
            0.5
        };
        (lat, r)
    } else {
        (p.y, (p.x * p.x + p.z * p.z).sqrt())
    };
    if dist_exp != 0.0 {
        let s = d.powf(dist_exp);
        u *= s;
        if spherical {
            v *= s;
        }
    }
    match orientation {
        0 => DVec3::new(d, v, -u),
        1 => DVec3::new(u, -d, v),
        _ => DVec3::new(u, v, d),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Transform;

    /// povray's values of function { x*0.1 } (or y, z) through each warp, printed by
    /// scripts/measure_pattern.py (a function pattern wraps negative values into [0, 1)).
    #[test]
    fn cylindrical_and_spherical_match_povray() {
        let cases = [
            (false, 2, 1.0, [0.3, 0.9, -0.5], 0, 0.048747366),
            (false, 2, 1.0, [-0.4, 1.5, -0.2], 0, 0.025660750),
            (true, 2, 0.0, [0.3, 0.9, -0.5], 1, 0.081700812),
            (true, 2, 0.0, [0.5, 0.5, 0.5], 1, 0.069591328),
            (false, 0, 0.0, [-0.7, -0.2, 0.4], 2, 0.958262467),
        ];
        for (sph, orient, exp, p, axis, want) in cases {
            let q = wrap(DVec3::from_array(p), sph, orient, exp);
            let v = rem_euclid(q[axis] * 0.1, 1.0);
            assert!((v - want).abs() < 1e-9, "{p:?}: {v} vs {want}");
        }
    }

    #[test]
    fn repeat_copies_the_first_slab() {
        let w = Warp {
            space: Transform::IDENTITY,
            kind: WarpKind::Repeat {
                dir: DVec3::new(2.0, 0.0, 0.0),
                offset: DVec3::new(0.0, 0.0, 0.5),
                flip: DVec3::ZERO,
            },
        };
        let q = apply(&w, DVec3::new(5.0, 1.0, 0.0), 2);
        assert!((q - DVec3::new(1.0, 1.0, 1.0)).length() < 1e-12);
    }
}
