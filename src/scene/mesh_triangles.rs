//! The triangles of a mesh, stored by field: corner indices always, and the normal, uv and
//! texture indices only once some triangle has them.
//!
//! A generated mesh of a million flat triangles kept 52 bytes a triangle as
//! `MeshTriangle` structs (the three optional index sets inline), 40 MB of which said
//! "none": with the optional parts in their own arrays, allocated only when used, it keeps
//! the 12 bytes of corner indices.

/// One triangle's indices, as readers see them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MeshTriangle {
    pub v: [u32; 3],
    /// Indices into `MeshData::normals` for a smooth triangle.
    pub n: Option<[u32; 3]>,
    pub texture: Option<u32>,
    /// Indices into `MeshData::uvs`, when the triangle has texture coordinates.
    pub uv: Option<[u32; 3]>,
}

const NONE: u32 = u32::MAX;
const NONE3: [u32; 3] = [NONE; 3];

/// The triangles of a `MeshData`. An optional field's array is empty until a triangle has
/// one; then it holds an entry per triangle, `u32::MAX` meaning none.
#[derive(Clone, Debug, Default)]
pub struct Triangles {
    v: Vec<[u32; 3]>,
    n: Vec<[u32; 3]>,
    uv: Vec<[u32; 3]>,
    texture: Vec<u32>,
}

/// Appends `x` (or the none marker) to an optional array, creating it when first needed.
fn push_opt<T: Copy + PartialEq>(arr: &mut Vec<T>, len: usize, x: Option<T>, none: T) {
    match x {
        Some(x) if x != none => {
            if arr.is_empty() {
                arr.resize(len, none);
            }
            arr.push(x);
        }
        _ if !arr.is_empty() => arr.push(none),
        _ => {}
    }
}

fn get_opt<T: Copy + PartialEq>(arr: &[T], i: usize, none: T) -> Option<T> {
    arr.get(i).copied().filter(|&x| x != none)
}

impl Triangles {
    pub fn with_capacity(n: usize) -> Triangles {
        Triangles {
            v: Vec::with_capacity(n),
            ..Default::default()
        }
    }

    pub fn len(&self) -> usize {
        self.v.len()
    }

    pub fn is_empty(&self) -> bool {
        self.v.is_empty()
    }

    pub fn push(&mut self, t: MeshTriangle) {
        let len = self.v.len();
        push_opt(&mut self.n, len, t.n, NONE3);
        push_opt(&mut self.uv, len, t.uv, NONE3);
        push_opt(&mut self.texture, len, t.texture, NONE);
        self.v.push(t.v);
    }

    /// The corner indices of triangle `i` (panics out of range, as indexing does).
    #[inline]
    pub fn corners(&self, i: usize) -> [u32; 3] {
        self.v[i]
    }

    pub fn get(&self, i: usize) -> Option<MeshTriangle> {
        Some(MeshTriangle {
            v: *self.v.get(i)?,
            n: get_opt(&self.n, i, NONE3),
            texture: get_opt(&self.texture, i, NONE),
            uv: get_opt(&self.uv, i, NONE3),
        })
    }

    pub fn iter(&self) -> impl Iterator<Item = MeshTriangle> + '_ {
        (0..self.len()).filter_map(|i| self.get(i))
    }
}

impl FromIterator<MeshTriangle> for Triangles {
    fn from_iter<I: IntoIterator<Item = MeshTriangle>>(iter: I) -> Triangles {
        let mut t = Triangles::default();
        for x in iter {
            t.push(x);
        }
        t
    }
}

impl From<Vec<MeshTriangle>> for Triangles {
    fn from(v: Vec<MeshTriangle>) -> Triangles {
        let mut t = Triangles::with_capacity(v.len());
        for x in v {
            t.push(x);
        }
        t
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn optional_parts_round_trip() {
        let plain = |k: u32| MeshTriangle {
            v: [k, k + 1, k + 2],
            n: None,
            texture: None,
            uv: None,
        };
        let mut t = Triangles::default();
        t.push(plain(0));
        t.push(MeshTriangle {
            n: Some([3, 4, 5]),
            texture: Some(7),
            ..plain(1)
        });
        t.push(plain(2));
        assert!(t.n.len() == 3 && t.uv.is_empty());
        assert_eq!(t.get(0), Some(plain(0)));
        assert_eq!(t.get(1).unwrap().n, Some([3, 4, 5]));
        assert_eq!(t.get(1).unwrap().texture, Some(7));
        assert_eq!(t.get(2), Some(plain(2)));
        assert_eq!(t.get(3), None);
        assert_eq!(t.iter().count(), 3);
    }
}
