//! Warps (`warp { turbulence | repeat | black_hole | planar ... }`): each moves the evaluation point in
//! the space the pattern had when the warp was written.

use crate::math::DVec3;
use crate::scene::pattern::{Warp, WarpKind};

use super::noise;

pub fn apply(w: &Warp, q: DVec3, generator: u8) -> DVec3 {
    let identity = w.space.is_identity();
    let p = if identity { q } else { w.space.point(q) };
    let moved = match &w.kind {
        WarpKind::Turbulence(t) => {
            p + t.amount * noise::turbulence_vec(p, t.octaves, t.omega, t.lambda, generator)
        }
        WarpKind::Repeat { dir, offset, flip } => repeat(p, *dir, *offset, *flip),
        WarpKind::Planar { e1, e2, e3, d } => *e1 * p.x + *e2 * p.y + *e3 * *d,
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
    if n.rem_euclid(2.0) == 1.0 {
        for k in 0..3 {
            if flip[k] != 0.0 {
                q[k] = if k == axis { width - q[k] } else { -q[k] };
            }
        }
    }
    q + offset * n
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Transform;

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
