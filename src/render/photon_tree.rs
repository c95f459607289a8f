//! A balanced k-d tree over stored photons, built once after shooting: photons are reordered
//! so that each range's middle element splits it on the axis of its widest extent. Queries
//! find the photons nearest a point within a radius, at most `max` of them, into a buffer the
//! caller keeps (no allocation per query).
//!
//! Hand-written rather than a crate: kiddo 5, the usual choice, pulls in about thirty crates
//! (tracing-subscriber, generator with cc, fixed) and returns a new Vec from every query; the
//! photon map needs this one query on a static set.

/// One stored photon: where it landed, the way it was going and the light it carries.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Photon {
    pub pos: [f32; 3],
    pub dir: [f32; 3],
    pub power: [f32; 3],
}

pub struct PhotonTree {
    photons: Vec<Photon>,
    /// The split axis of the node at each index (the middle of its range).
    axes: Vec<u8>,
}

impl PhotonTree {
    pub fn new(mut photons: Vec<Photon>) -> PhotonTree {
        let mut axes = vec![0u8; photons.len()];
        build(&mut photons, &mut axes, 0);
        PhotonTree { photons, axes }
    }

    pub fn len(&self) -> usize {
        self.photons.len()
    }

    pub fn is_empty(&self) -> bool {
        self.photons.is_empty()
    }

    pub fn photons(&self) -> &[Photon] {
        &self.photons
    }

    /// The nearest photons to `q` closer than `radius`, at most `max`, into `found` as
    /// (squared distance, index), unordered; returns the squared radius that holds them all
    /// (`radius`² unless `max` were found, then the farthest kept).
    pub fn nearest(
        &self,
        q: [f32; 3],
        radius: f32,
        max: usize,
        found: &mut Vec<(f32, u32)>,
    ) -> f32 {
        found.clear();
        let mut r2 = radius * radius;
        if max == 0 || self.photons.is_empty() {
            return r2;
        }
        self.search(0, self.photons.len(), q, &mut r2, max, found);
        if found.len() >= max {
            found.iter().fold(0.0f32, |m, f| m.max(f.0))
        } else {
            radius * radius
        }
    }

    fn search(
        &self,
        lo: usize,
        hi: usize,
        q: [f32; 3],
        r2: &mut f32,
        max: usize,
        found: &mut Vec<(f32, u32)>,
    ) {
        if lo >= hi {
            return;
        }
        let mid = (lo + hi) / 2;
        let p = &self.photons[mid];
        let axis = self.axes[mid] as usize;
        let d = q[axis] - p.pos[axis];
        let (near, far) = if d < 0.0 {
            ((lo, mid), (mid + 1, hi))
        } else {
            ((mid + 1, hi), (lo, mid))
        };
        self.search(near.0, near.1, q, r2, max, found);
        let dist2 = dist2(q, p.pos);
        if dist2 < *r2 {
            push_bounded(found, (dist2, mid as u32), max, r2);
        }
        if d * d < *r2 {
            self.search(far.0, far.1, q, r2, max, found);
        }
    }
}

/// Keeps the `max` nearest: when full, the farthest is dropped and the search radius shrinks
/// to the farthest kept.
fn push_bounded(found: &mut Vec<(f32, u32)>, item: (f32, u32), max: usize, r2: &mut f32) {
    if found.len() < max {
        found.push(item);
        if found.len() == max {
            *r2 = found.iter().fold(0.0f32, |m, f| m.max(f.0));
        }
        return;
    }
    // Replace the farthest (a linear scan: max is ~100, and a full buffer is the rare case of a
    // dense caustic).
    let (i, _) =
        found.iter().enumerate().fold(
            (0, f32::MIN),
            |best, (i, f)| if f.0 > best.1 { (i, f.0) } else { best },
        );
    found[i] = item;
    *r2 = found.iter().fold(0.0f32, |m, f| m.max(f.0));
}

fn dist2(a: [f32; 3], b: [f32; 3]) -> f32 {
    let d = [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    d[0] * d[0] + d[1] * d[1] + d[2] * d[2]
}

fn build(ph: &mut [Photon], axes: &mut [u8], offset: usize) {
    if ph.len() <= 1 {
        return;
    }
    let mut lo = [f32::MAX; 3];
    let mut hi = [f32::MIN; 3];
    for p in ph.iter() {
        for a in 0..3 {
            lo[a] = lo[a].min(p.pos[a]);
            hi[a] = hi[a].max(p.pos[a]);
        }
    }
    let axis = (0..3)
        .max_by(|&a, &b| (hi[a] - lo[a]).total_cmp(&(hi[b] - lo[b])))
        .unwrap_or(0);
    let mid = ph.len() / 2;
    ph.select_nth_unstable_by(mid, |a, b| a.pos[axis].total_cmp(&b.pos[axis]));
    axes[offset + mid] = axis as u8;
    let (left, right) = ph.split_at_mut(mid);
    build(left, axes, offset);
    build(&mut right[1..], axes, offset + mid + 1);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(x: f32, y: f32, z: f32) -> Photon {
        Photon {
            pos: [x, y, z],
            dir: [0.0, -1.0, 0.0],
            power: [1.0; 3],
        }
    }

    #[test]
    fn finds_the_same_as_brute_force() {
        let mut pts = Vec::new();
        let mut s = 12345u32;
        let mut rnd = || {
            s ^= s << 13;
            s ^= s >> 17;
            s ^= s << 5;
            (s % 10000) as f32 / 1000.0
        };
        for _ in 0..2000 {
            pts.push(at(rnd(), rnd(), rnd()));
        }
        let tree = PhotonTree::new(pts.clone());
        let mut found = Vec::new();
        for q in [[5.0, 5.0, 5.0], [0.1, 9.0, 3.0], [20.0, 0.0, 0.0]] {
            for (radius, max) in [(1.0, 1000), (2.0, 10)] {
                tree.nearest(q, radius, max, &mut found);
                let mut brute: Vec<f32> = pts
                    .iter()
                    .map(|p| dist2(q, p.pos))
                    .filter(|&d| d < radius * radius)
                    .collect();
                brute.sort_by(f32::total_cmp);
                brute.truncate(max);
                let mut got: Vec<f32> = found.iter().map(|f| f.0).collect();
                got.sort_by(f32::total_cmp);
                assert_eq!(got, brute);
            }
        }
    }
}
