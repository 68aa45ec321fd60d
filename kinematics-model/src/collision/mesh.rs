//! A triangle mesh as the cover reads it: vertices and triangles in the file's own units, checked
//! (finite, at least one triangle of non-zero area, indices in range), and the geometric queries
//! the cover's overshoot bound and report need: the distance from a point to the surface, whether
//! a point lies inside (the generalised winding number, which holds for meshes that are not quite
//! closed), and the enclosed volume.
//!
//! Reading the file is the caller's (the model does no IO): `kinematics-meshes` resolves the URI
//! and parses STL, Collada and OBJ into a [`TriangleMesh`] through [`TriangleMesh::new`].

use super::vec3::{add, cross, dot, norm, scale, sub};

/// A mesh's vertices and triangles (indices into the vertices), as checked by [`TriangleMesh::new`].
#[derive(Debug, Clone, PartialEq)]
pub struct TriangleMesh {
    vertices: Vec<[f64; 3]>,
    triangles: Vec<[u32; 3]>,
}

/// What is wrong with a mesh's data.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum MeshFault {
    /// No triangle of non-zero area.
    #[error("it has no triangles of non-zero area ({triangles} triangles, {vertices} vertices)")]
    Empty {
        /// Triangles read.
        triangles: usize,
        /// Vertices read.
        vertices: usize,
    },
    /// A vertex coordinate that is NaN or infinite.
    #[error("vertex {index} is not finite")]
    NotFinite {
        /// Its index.
        index: usize,
    },
    /// A triangle naming a vertex that is not there.
    #[error("triangle {index} names vertex {vertex}, and there are {vertices}")]
    BadIndex {
        /// The triangle.
        index: usize,
        /// The vertex it names.
        vertex: u32,
        /// How many vertices there are.
        vertices: usize,
    },
}

impl TriangleMesh {
    /// The mesh of `vertices` and `triangles`, refused when a vertex is not finite, an index is out
    /// of range, or no triangle has non-zero area. Triangles of zero area are dropped (they add no
    /// surface).
    pub fn new(vertices: Vec<[f64; 3]>, triangles: Vec<[u32; 3]>) -> Result<Self, MeshFault> {
        if let Some(index) = vertices.iter().position(|v| v.iter().any(|x| !x.is_finite())) {
            return Err(MeshFault::NotFinite { index });
        }
        for (index, t) in triangles.iter().enumerate() {
            if let Some(&vertex) = t.iter().find(|&&i| i as usize >= vertices.len()) {
                return Err(MeshFault::BadIndex { index, vertex, vertices: vertices.len() });
            }
        }
        let read = triangles.len();
        let triangles: Vec<[u32; 3]> = triangles
            .into_iter()
            .filter(|t| {
                let [a, b, c] = t.map(|i| vertices[i as usize]);
                norm(cross(sub(b, a), sub(c, a))) > 0.0
            })
            .collect();
        if triangles.is_empty() {
            return Err(MeshFault::Empty { triangles: read, vertices: vertices.len() });
        }
        Ok(TriangleMesh { vertices, triangles })
    }

    /// The vertices.
    pub fn vertices(&self) -> &[[f64; 3]] {
        &self.vertices
    }

    /// The triangles, as indices into [`vertices`](Self::vertices).
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// Each triangle's corners.
    pub fn corners(&self) -> impl Iterator<Item = [[f64; 3]; 3]> + '_ {
        self.triangles.iter().map(|t| t.map(|i| self.vertices[i as usize]))
    }
}

/// Triangles placed in some frame (a link's), with the queries the cover needs. The distance goes
/// through a bounding-volume tree (boxes about triangles sorted along their longest spread), so
/// a query visits the few boxes that can hold a nearer point; the inside test, which needs every
/// triangle, is asked only where no recent answer settles it (see [`PlacedTriangles::depth`]).
#[derive(Debug)]
pub struct PlacedTriangles {
    triangles: Vec<[[f64; 3]; 3]>,
    nodes: Vec<Node>,
    /// Recent points with their depth: a point nearer one of them than its depth's magnitude is
    /// on the same side of the surface (the ball of that radius touches no surface).
    recent: std::cell::RefCell<Vec<([f64; 3], f64)>>,
}

/// A node of the tree: a box and either two children or a run of triangles.
#[derive(Debug, Clone, Copy)]
struct Node {
    lo: [f64; 3],
    hi: [f64; 3],
    /// Children (`Some(left)`, right = left + 1 is not assumed: both stored) or a leaf's range.
    kind: NodeKind,
}

#[derive(Debug, Clone, Copy)]
enum NodeKind {
    Inner(usize, usize),
    Leaf(usize, usize),
}

/// Triangles per leaf of the tree.
const LEAF: usize = 8;

/// Recent answers kept for the inside test.
const RECENT: usize = 16;

impl PlacedTriangles {
    /// The triangles, with their tree built.
    pub fn new(mut triangles: Vec<[[f64; 3]; 3]>) -> Self {
        let mut nodes = Vec::new();
        let n = triangles.len();
        build(&mut triangles, 0, n, &mut nodes);
        PlacedTriangles { triangles, nodes, recent: std::cell::RefCell::new(Vec::new()) }
    }

    /// The triangles (in the tree's order).
    pub fn triangles(&self) -> &[[[f64; 3]; 3]] {
        &self.triangles
    }

    /// The distance from `p` to the nearest point of any triangle.
    pub fn distance(&self, p: [f64; 3]) -> f64 {
        let mut best = f64::INFINITY;
        let mut stack = vec![0usize];
        while let Some(i) = stack.pop() {
            let node = self.nodes[i];
            if box_distance(p, node.lo, node.hi) >= best {
                continue;
            }
            match node.kind {
                NodeKind::Leaf(start, end) => {
                    for t in &self.triangles[start..end] {
                        best = best.min(norm(sub(p, closest_on_triangle(p, t))));
                    }
                }
                NodeKind::Inner(a, b) => {
                    // The nearer child last, so it is taken first.
                    let (da, db) = (
                        box_distance(p, self.nodes[a].lo, self.nodes[a].hi),
                        box_distance(p, self.nodes[b].lo, self.nodes[b].hi),
                    );
                    if da < db {
                        stack.extend([b, a]);
                    } else {
                        stack.extend([a, b]);
                    }
                }
            }
        }
        best
    }

    /// The generalised winding number of the triangles about `p`: 1 inside a closed outward
    /// mesh, 0 outside, in between near the gaps of one that is not closed (Jacobson et al.,
    /// "Robust Inside-Outside Segmentation using Generalized Winding Numbers", 2013: the sum of
    /// the triangles' signed solid angles over 4 pi; the solid angle from Van Oosterom and
    /// Strackee, 1983). Its sign is the orientation's: a mesh wound inwards gives -1 inside.
    pub fn winding(&self, p: [f64; 3]) -> f64 {
        let total: f64 = self
            .triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|v| sub(v, p));
                let (la, lb, lc) = (norm(a), norm(b), norm(c));
                let numerator = dot(a, cross(b, c));
                let denominator = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
                2.0 * numerator.atan2(denominator)
            })
            .sum();
        total / (4.0 * std::f64::consts::PI)
    }

    /// How far `p` lies inside: the distance to the surface, positive where the winding number's
    /// magnitude is at least one half (inside), negative elsewhere. The winding number is
    /// computed only where no recent point settles the side: a point nearer a recent one than
    /// that one's distance to the surface lies on its side.
    pub fn depth(&self, p: [f64; 3]) -> f64 {
        let d = self.distance(p);
        let known = self.recent.borrow().iter().find(|(q, dq)| norm(sub(p, *q)) < dq.abs()).map(|&(_, dq)| dq);
        let inside = match known {
            Some(dq) => dq > 0.0,
            None => {
                let inside = self.winding(p).abs() >= 0.5;
                let mut recent = self.recent.borrow_mut();
                if recent.len() == RECENT {
                    recent.remove(0);
                }
                recent.push((p, if inside { d } else { -d }));
                inside
            }
        };
        if inside { d } else { -d }
    }

    /// The enclosed volume (the divergence theorem's sum of signed tetrahedra; its magnitude, so
    /// the winding's direction does not matter). Meaningful for a closed mesh only.
    pub fn volume(&self) -> f64 {
        (self.triangles.iter().map(|[a, b, c]| dot(*a, cross(*b, *c))).sum::<f64>() / 6.0).abs()
    }

    /// The total area.
    pub fn area(&self) -> f64 {
        self.triangles.iter().map(|[a, b, c]| norm(cross(sub(*b, *a), sub(*c, *a))) / 2.0).sum()
    }
}

/// Builds the node of `triangles[start..end]` (sorting them along the longest spread of their
/// centroids, halved at the median) and returns its index.
fn build(triangles: &mut [[[f64; 3]; 3]], start: usize, end: usize, nodes: &mut Vec<Node>) -> usize {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for t in &triangles[start..end] {
        for v in t {
            for a in 0..3 {
                lo[a] = lo[a].min(v[a]);
                hi[a] = hi[a].max(v[a]);
            }
        }
    }
    let index = nodes.len();
    nodes.push(Node { lo, hi, kind: NodeKind::Leaf(start, end) });
    if end - start > LEAF {
        let axis = (0..3).fold(0, |best, a| if hi[a] - lo[a] > hi[best] - lo[best] { a } else { best });
        let key = |t: &[[f64; 3]; 3]| t[0][axis] + t[1][axis] + t[2][axis];
        triangles[start..end].sort_by(|x, y| key(x).total_cmp(&key(y)));
        let mid = start + (end - start) / 2;
        let a = build(triangles, start, mid, nodes);
        let b = build(triangles, mid, end, nodes);
        nodes[index].kind = NodeKind::Inner(a, b);
    }
    index
}

/// The distance from `p` to the box `[lo, hi]` (zero inside).
fn box_distance(p: [f64; 3], lo: [f64; 3], hi: [f64; 3]) -> f64 {
    norm([0, 1, 2].map(|a| (lo[a] - p[a]).max(p[a] - hi[a]).max(0.0)))
}

/// The point of triangle `t` nearest `p` (Ericson, Real-Time Collision Detection, 2005, 5.1.5:
/// which Voronoi region of the triangle `p` falls in).
pub fn closest_on_triangle(p: [f64; 3], t: &[[f64; 3]; 3]) -> [f64; 3] {
    let [a, b, c] = *t;
    let (ab, ac, ap) = (sub(b, a), sub(c, a), sub(p, a));
    let (d1, d2) = (dot(ab, ap), dot(ac, ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return a;
    }
    let bp = sub(p, b);
    let (d3, d4) = (dot(ab, bp), dot(ac, bp));
    if d3 >= 0.0 && d4 <= d3 {
        return b;
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return add(a, scale(ab, d1 / (d1 - d3)));
    }
    let cp = sub(p, c);
    let (d5, d6) = (dot(ab, cp), dot(ac, cp));
    if d6 >= 0.0 && d5 <= d6 {
        return c;
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return add(a, scale(ac, d2 / (d2 - d6)));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        return add(b, scale(sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6))));
    }
    let denom = 1.0 / (va + vb + vc);
    add(a, add(scale(ab, vb * denom), scale(ac, vc * denom)))
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// The closed box `[-h, h]` as twelve outward triangles.
    pub(crate) fn box_mesh(h: [f64; 3]) -> TriangleMesh {
        let v: Vec<[f64; 3]> =
            (0..8).map(|i| [0, 1, 2].map(|k| if (i >> k) & 1 == 1 { h[k] } else { -h[k] })).collect();
        // Faces as corner quads (outward), split into two triangles each.
        let quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
        let t = quads.iter().flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]).collect();
        TriangleMesh::new(v, t).unwrap()
    }

    #[test]
    fn a_closed_box_has_its_volume_winding_and_depth() {
        let mesh = box_mesh([0.1, 0.2, 0.3]);
        let placed = PlacedTriangles::new(mesh.corners().collect());
        assert!((placed.volume() - 0.2 * 0.4 * 0.6).abs() < 1e-15);
        assert!((placed.winding([0.0; 3]).abs() - 1.0).abs() < 1e-12);
        assert!(placed.winding([1.0, 0.0, 0.0]).abs() < 1e-12);
        assert!((placed.depth([0.0; 3]) - 0.1).abs() < 1e-15);
        assert!((placed.depth([0.3, 0.0, 0.0]) + 0.2).abs() < 1e-15);
        assert!((placed.area() - 2.0 * (0.08 + 0.12 + 0.24)).abs() < 1e-15);
    }

    #[test]
    fn bad_meshes_are_refused() {
        assert_eq!(
            TriangleMesh::new(vec![[0.0; 3]; 3], vec![[0, 1, 2]]),
            Err(MeshFault::Empty { triangles: 1, vertices: 3 })
        );
        assert_eq!(TriangleMesh::new(vec![], vec![]), Err(MeshFault::Empty { triangles: 0, vertices: 0 }));
        assert_eq!(TriangleMesh::new(vec![[0.0, f64::NAN, 0.0]], vec![]), Err(MeshFault::NotFinite { index: 0 }));
        assert_eq!(
            TriangleMesh::new(vec![[0.0; 3]], vec![[0, 0, 3]]),
            Err(MeshFault::BadIndex { index: 0, vertex: 3, vertices: 1 })
        );
    }

    #[test]
    fn the_closest_point_is_in_the_right_region() {
        let t = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
        assert_eq!(closest_on_triangle([-1.0, -1.0, 0.0], &t), [0.0, 0.0, 0.0]);
        assert_eq!(closest_on_triangle([0.25, 0.25, 1.0], &t), [0.25, 0.25, 0.0]);
        assert_eq!(closest_on_triangle([0.5, -1.0, 0.0], &t), [0.5, 0.0, 0.0]);
        let p = closest_on_triangle([1.0, 1.0, 0.0], &t);
        assert!((p[0] - 0.5).abs() < 1e-15 && (p[1] - 0.5).abs() < 1e-15);
    }
}
