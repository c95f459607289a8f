//! The triangles of a mesh, stored by field: corner indices always, and the normal, uv and
//! texture indices only once some triangle has them.
//!
//! A generated mesh of a million flat triangles kept 52 bytes a triangle as
//! `MeshTriangle` structs (the three optional index sets inline), 40 MB of which said
//! "none": with the optional parts in their own arrays, allocated only when used, it keeps
//! the 12 bytes of corner indices. Generated grids (bicubic patches, parametric surfaces)
//! index their normals and uvs by the corner indices themselves: while every triangle does,
//! those arrays are not stored at all (3.1 MB of copies on objects/bezier).

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

/// An optional index set of every triangle.
#[derive(Clone, Debug, Default)]
enum Corners {
    /// No triangle has one (so far).
    #[default]
    Absent,
    /// Every triangle has one, equal to its corner indices.
    SameAsV,
    /// An entry per triangle, `u32::MAX` meaning none.
    Own(Vec<[u32; 3]>),
}

impl Corners {
    /// Appends triangle `len`'s set `x`, its corners being `v` and the earlier ones `vs`.
    fn push(&mut self, vs: &[[u32; 3]], v: [u32; 3], x: Option<[u32; 3]>) {
        let x = x.filter(|&x| x != NONE3);
        match self {
            Corners::Absent if x.is_none() => {}
            Corners::Absent if vs.is_empty() && x == Some(v) => *self = Corners::SameAsV,
            Corners::SameAsV if x == Some(v) => {}
            Corners::Own(arr) => arr.push(x.unwrap_or(NONE3)),
            _ => {
                let mut arr = match self {
                    Corners::SameAsV => vs.to_vec(),
                    _ => vec![NONE3; vs.len()],
                };
                arr.push(x.unwrap_or(NONE3));
                *self = Corners::Own(arr);
            }
        }
    }

    fn get(&self, vs: &[[u32; 3]], i: usize) -> Option<[u32; 3]> {
        match self {
            Corners::Absent => None,
            Corners::SameAsV => vs.get(i).copied(),
            Corners::Own(arr) => get_opt(arr, i, NONE3),
        }
    }
}

/// The triangles of a `MeshData`. The texture array is empty until a triangle has one;
/// then it holds an entry per triangle, `u32::MAX` meaning none.
#[derive(Clone, Debug, Default)]
pub struct Triangles {
    v: Vec<[u32; 3]>,
    n: Corners,
    uv: Corners,
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

    /// Triangles whose normal and uv indices are their corner indices, as every triangle of
    /// a generated grid without poles has them: what pushing each with `n` and `uv` equal
    /// to `v` gives, without the per-triangle bookkeeping (1.5 ms of objects/bezier's
    /// 131,072 triangles).
    pub fn same_as_corners(v: Vec<[u32; 3]>) -> Triangles {
        let same = if v.is_empty() {
            Corners::Absent
        } else {
            Corners::SameAsV
        };
        Triangles {
            v,
            n: same.clone(),
            uv: same,
            texture: Vec::new(),
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
        self.n.push(&self.v, t.v, t.n);
        self.uv.push(&self.v, t.v, t.uv);
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
            n: self.n.get(&self.v, i),
            texture: get_opt(&self.texture, i, NONE),
            uv: self.uv.get(&self.v, i),
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
        assert!(matches!(&t.n, Corners::Own(n) if n.len() == 3));
        assert!(matches!(t.uv, Corners::Absent));
        assert_eq!(t.get(0), Some(plain(0)));
        assert_eq!(t.get(1).unwrap().n, Some([3, 4, 5]));
        assert_eq!(t.get(1).unwrap().texture, Some(7));
        assert_eq!(t.get(2), Some(plain(2)));
        assert_eq!(t.get(3), None);
        assert_eq!(t.iter().count(), 3);
    }

    #[test]
    fn sets_equal_to_the_corners_are_not_stored_until_one_differs() {
        let grid = |k: u32| MeshTriangle {
            v: [k, k + 1, k + 2],
            n: Some([k, k + 1, k + 2]),
            texture: None,
            uv: Some([k, k + 1, k + 2]),
        };
        let mut t: Triangles = (0..3).map(grid).collect();
        assert!(matches!(t.n, Corners::SameAsV) && matches!(t.uv, Corners::SameAsV));
        assert_eq!(t.get(2), Some(grid(2)));
        // A flat triangle (no normals) among smooth ones: the normals get their own array.
        t.push(MeshTriangle { n: None, ..grid(3) });
        t.push(grid(4));
        assert!(matches!(&t.n, Corners::Own(n) if n.len() == 5));
        assert!(matches!(t.uv, Corners::SameAsV));
        let got: Vec<_> = t.iter().collect();
        let want: Vec<_> = (0..5)
            .map(|k| {
                if k == 3 {
                    MeshTriangle { n: None, ..grid(3) }
                } else {
                    grid(k)
                }
            })
            .collect();
        assert_eq!(got, want);
        // A first triangle without normals, then one whose normals are its corners.
        let mut t = Triangles::default();
        t.push(MeshTriangle { n: None, ..grid(0) });
        t.push(grid(1));
        assert_eq!(t.get(0).unwrap().n, None);
        assert_eq!(t.get(1).unwrap().n, Some([1, 2, 3]));
    }

    #[test]
    fn same_as_corners_is_pushing_each() {
        for k in [0u32, 1, 5] {
            let v: Vec<[u32; 3]> = (0..k).map(|i| [i, i + 2, i + 1]).collect();
            let pushed: Triangles = v
                .iter()
                .map(|&v| MeshTriangle {
                    v,
                    n: Some(v),
                    texture: None,
                    uv: Some(v),
                })
                .collect();
            let built = Triangles::same_as_corners(v);
            assert_eq!(built.len(), pushed.len());
            assert_eq!(
                built.iter().collect::<Vec<_>>(),
                pushed.iter().collect::<Vec<_>>()
            );
            assert_eq!(format!("{built:?}"), format!("{pushed:?}"));
        }
    }
}
