//! The hierarchy of a mesh laid out as a grid (tessellated bicubic patches, parametric
//! surfaces), built from the layout: each node halves its cells across the longer side.
//!
//! The walk's nodes are written directly, in the order `Bvh::from_binary` would write them
//! from the builders' layout: that layout was a second 56-byte node per triangle (7 MB of
//! fresh pages for objects/bezier's 131,072 triangles) written once and read once.

use crate::math::Aabb;

use super::build::union_no_nan;
use super::slabs::Pair;
use super::{Bvh, Node, Ref};

/// The cells `[i0, i1) × [j0, j1)` of a grid mesh.
#[derive(Clone, Copy)]
struct Cells {
    i0: usize,
    i1: usize,
    j0: usize,
    j1: usize,
}

impl Cells {
    fn count(&self) -> usize {
        (self.i1 - self.i0) * (self.j1 - self.j0)
    }

    /// The two halves across the side with more cells.
    fn halves(&self) -> (Cells, Cells) {
        if self.i1 - self.i0 >= self.j1 - self.j0 {
            let m = self.i0 + (self.i1 - self.i0) / 2;
            (Cells { i1: m, ..*self }, Cells { i0: m, ..*self })
        } else {
            let m = self.j0 + (self.j1 - self.j0) / 2;
            (Cells { j1: m, ..*self }, Cells { j0: m, ..*self })
        }
    }
}

/// Cells per leaf of a grid hierarchy: two cells are four triangles, `MAX_LEAF`.
const GRID_LEAF_CELLS: usize = 2;

/// `Bvh::build_grid`'s state: the triangles' boxes and the arrays being filled.
struct GridBuilder<F> {
    bounds: F,
    nu: usize,
    nodes: Vec<Node>,
    prims: Vec<u32>,
    /// Every box kept so far (leaves' and interior nodes') is finite.
    finite: bool,
}

impl<F: FnMut(usize) -> Aabb> GridBuilder<F> {
    /// Appends the subtree over `cells` (its interior nodes in depth-first order, a node's
    /// slot taken before its children's) and returns its box and how its parent refers to
    /// it, or `None` (appending nothing) when all its triangles are degenerate.
    fn node(&mut self, cells: Cells) -> Option<(Aabb, Ref)> {
        if cells.count() <= GRID_LEAF_CELLS {
            let first = self.prims.len();
            let mut b = Aabb::EMPTY;
            for j in cells.j0..cells.j1 {
                for i in cells.i0..cells.i1 {
                    for p in [2 * (j * self.nu + i), 2 * (j * self.nu + i) + 1] {
                        let pb = (self.bounds)(p);
                        if !pb.is_empty() {
                            b = union_no_nan(&b, &pb);
                            self.prims.push(p as u32);
                        }
                    }
                }
            }
            let count = self.prims.len() - first;
            if count == 0 {
                return None;
            }
            self.finite &= b.is_finite();
            let leaf = Ref {
                index: first as u32,
                count: count as u32,
            };
            return Some((b, leaf));
        }
        let (a, c) = cells.halves();
        let slot = self.nodes.len();
        self.nodes.push(Node {
            boxes: Pair::of(&Aabb::EMPTY, &Aabb::EMPTY),
            child: [Ref::default(); 2],
        });
        let ha = self.node(a);
        let hc = self.node(c);
        match (ha, hc) {
            (Some((ba, ra)), Some((bc, rc))) => {
                self.nodes[slot] = Node {
                    boxes: Pair::of(&ba, &bc),
                    child: [ra, rc],
                };
                let b = union_no_nan(&ba, &bc);
                self.finite &= b.is_finite();
                Some((
                    b,
                    Ref {
                        index: slot as u32,
                        count: 0,
                    },
                ))
            }
            (None, None) => {
                self.nodes.pop();
                None
            }
            // One half holds nothing: the other takes the parent's place, its interior
            // nodes moving down one slot with the references to them.
            (Some((b, r)), None) | (None, Some((b, r))) => {
                self.nodes.remove(slot);
                let down = |r: &mut Ref| {
                    if r.count == 0 {
                        r.index -= 1;
                    }
                };
                for n in &mut self.nodes[slot..] {
                    n.child.iter_mut().for_each(down);
                }
                let mut r = r;
                down(&mut r);
                Some((b, r))
            }
        }
    }
}

impl Bvh {
    /// The hierarchy of a mesh laid out as a grid of `nu` × `nv` cells, two triangles each
    /// (cell (i, j) holds primitives `2 (j nu + i)` and the one after; `bounds(p)` is
    /// primitive p's box, asked once each, in no particular order, and holding no NaN: an
    /// empty box for a primitive to leave out): each node halves its cells across the longer
    /// side. A tessellated bicubic patch or parametric surface is such a grid, and this takes
    /// a few milliseconds where the surface-area heuristic took most of the scene's time
    /// (objects/bezier: 131,072 triangles); on a smooth grid its nodes are as tight as the
    /// heuristic's.
    pub fn build_grid(nu: usize, nv: usize, bounds: impl FnMut(usize) -> Aabb) -> Bvh {
        let n = nu * nv;
        let mut g = GridBuilder {
            bounds,
            nu,
            // At most one interior node per leaf, a leaf per cell at least.
            nodes: Vec::with_capacity(n),
            prims: Vec::with_capacity(2 * n),
            finite: true,
        };
        if n == 0 {
            return Bvh::default();
        }
        let Some((root_box, root)) = g.node(Cells {
            i0: 0,
            i1: nu,
            j0: 0,
            j1: nv,
        }) else {
            return Bvh::default();
        };
        Bvh {
            paired: !g.nodes.is_empty() && g.finite,
            nodes: g.nodes,
            prims: g.prims,
            root_box,
            root,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::BinNode;
    use super::*;
    use crate::math::DVec3;

    /// The builders' layout of the same tree, as the grid build made it before it wrote the
    /// walk's nodes itself; `Bvh::from_binary` turns it into the walk's.
    struct BinGrid<F> {
        bounds: F,
        nu: usize,
        nodes: Vec<BinNode>,
        prims: Vec<u32>,
    }

    impl<F: Fn(usize) -> Aabb> BinGrid<F> {
        fn node(&mut self, cells: Cells) -> Option<Aabb> {
            if cells.count() <= GRID_LEAF_CELLS {
                let first = self.prims.len();
                let mut b = Aabb::EMPTY;
                for j in cells.j0..cells.j1 {
                    for i in cells.i0..cells.i1 {
                        for p in [2 * (j * self.nu + i), 2 * (j * self.nu + i) + 1] {
                            let pb = (self.bounds)(p);
                            if !pb.is_empty() {
                                b = b.union(&pb);
                                self.prims.push(p as u32);
                            }
                        }
                    }
                }
                let count = self.prims.len() - first;
                if count == 0 {
                    return None;
                }
                self.nodes.push(BinNode {
                    bounds: b,
                    index: first as u32,
                    count: count as u32,
                });
                return Some(b);
            }
            let (a, c) = cells.halves();
            let idx = self.nodes.len();
            self.nodes.push(BinNode {
                bounds: Aabb::EMPTY,
                index: 0,
                count: 0,
            });
            let ba = self.node(a);
            let second = self.nodes.len();
            let bc = self.node(c);
            match (ba, bc) {
                (Some(ba), Some(bc)) => {
                    let b = ba.union(&bc);
                    self.nodes[idx] = BinNode {
                        bounds: b,
                        index: second as u32,
                        count: 0,
                    };
                    Some(b)
                }
                (None, None) => {
                    self.nodes.pop();
                    None
                }
                (Some(b), None) | (None, Some(b)) => {
                    self.nodes.remove(idx);
                    for n in &mut self.nodes[idx..] {
                        if n.count == 0 {
                            n.index -= 1;
                        }
                    }
                    Some(b)
                }
            }
        }
    }

    fn bin_build(nu: usize, nv: usize, bounds: impl Fn(usize) -> Aabb) -> Bvh {
        let mut g = BinGrid {
            bounds,
            nu,
            nodes: Vec::new(),
            prims: Vec::new(),
        };
        if nu == 0
            || nv == 0
            || g.node(Cells {
                i0: 0,
                i1: nu,
                j0: 0,
                j1: nv,
            })
            .is_none()
        {
            return Bvh::default();
        }
        Bvh::from_binary(&g.nodes, g.prims)
    }

    /// The direct build gives the nodes, primitives, root and flags the builders' layout
    /// gave through `from_binary`, bit for bit, on grids of every shape with degenerate
    /// triangles scattered, in runs, in whole halves, everywhere, and with non-finite boxes.
    #[test]
    fn direct_grid_build_is_the_binary_layouts() {
        let mut rng = crate::geom::test_rng::Lcg(5);
        let sizes = [
            (1, 1),
            (2, 1),
            (1, 3),
            (3, 5),
            (8, 8),
            (16, 4),
            (7, 13),
            (32, 32),
        ];
        for (nu, nv) in sizes {
            for kind in 0..6 {
                let n = 2 * nu * nv;
                let boxes: Vec<Aabb> = (0..n)
                    .map(|p| {
                        let c = rng.vec(10.0);
                        let b = Aabb::new(c, c + DVec3::splat(rng.next()));
                        let gone = match kind {
                            0 => false,
                            1 => rng.next() < 0.3,
                            2 => p < n / 2,
                            3 => (p / 7) % 3 == 0,
                            4 => true,
                            _ => p == n / 3,
                        };
                        if gone {
                            Aabb::EMPTY
                        } else if kind == 3 && p % 4 == 1 {
                            let z = if p % 8 == 1 { -0.0 } else { 0.0 };
                            Aabb::new(DVec3::new(z, b.min.y, z), DVec3::new(b.max.x, z, 0.0))
                        } else if kind == 5 && p % 5 == 1 {
                            Aabb::new(b.min, DVec3::new(f64::INFINITY, b.max.y, b.max.z))
                        } else {
                            b
                        }
                    })
                    .collect();
                let direct = Bvh::build_grid(nu, nv, |p| boxes[p]);
                let bin = bin_build(nu, nv, |p| boxes[p]);
                assert_eq!(
                    format!("{direct:?}"),
                    format!("{bin:?}"),
                    "{nu}x{nv} {kind}"
                );
            }
        }
    }
}
