//! Three-vectors and 3x3 matrices of graph nodes: what the recursive algorithms compute with.
//!
//! Every operation builds nodes through the graph's smart constructors, so a zero entry (an axis
//! along `z`, a link with no mass, a velocity that is not an input) drops its terms as it is built,
//! and constant operands fold to constants.

use crate::symbolic::graph::{ExprGraph, ExprId};
use crate::symbolic::transform::Mat3;

/// A vector of three nodes.
pub(super) type Vec3 = [ExprId; 3];

/// The zero vector.
pub(super) fn zero(g: &mut ExprGraph) -> Vec3 {
    [g.constant(0.0); 3]
}

/// A constant vector.
pub(super) fn constant(g: &mut ExprGraph, v: [f64; 3]) -> Vec3 {
    v.map(|x| g.constant(x))
}

/// `a + b`.
pub(super) fn add(g: &mut ExprGraph, a: Vec3, b: Vec3) -> Vec3 {
    std::array::from_fn(|i| g.add(a[i], b[i]))
}

/// `k a` for a node `k`.
pub(super) fn scale(g: &mut ExprGraph, k: ExprId, a: Vec3) -> Vec3 {
    a.map(|x| g.mul(k, x))
}

/// `a . b`.
pub(super) fn dot(g: &mut ExprGraph, a: Vec3, b: Vec3) -> ExprId {
    let mut sum = g.constant(0.0);
    for i in 0..3 {
        let term = g.mul(a[i], b[i]);
        sum = g.add(sum, term);
    }
    sum
}

/// `a x b`.
pub(super) fn cross(g: &mut ExprGraph, a: Vec3, b: Vec3) -> Vec3 {
    std::array::from_fn(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        let (x, y) = (g.mul(a[j], b[k]), g.mul(a[k], b[j]));
        g.sub(x, y)
    })
}

/// `m v`.
pub(super) fn mat_vec(g: &mut ExprGraph, m: &Mat3, v: Vec3) -> Vec3 {
    std::array::from_fn(|i| dot(g, m[i], v))
}

/// `m^T v`.
pub(super) fn mat_t_vec(g: &mut ExprGraph, m: &Mat3, v: Vec3) -> Vec3 {
    std::array::from_fn(|i| dot(g, [m[0][i], m[1][i], m[2][i]], v))
}

/// `s v` for a symmetric matrix held as its six entries `[xx, xy, xz, yy, yz, zz]`.
pub(super) fn sym_vec(g: &mut ExprGraph, s: &Sym3, v: Vec3) -> Vec3 {
    std::array::from_fn(|i| dot(g, sym_row(s, i), v))
}

/// A symmetric 3x3 matrix as its six entries `[xx, xy, xz, yy, yz, zz]`.
pub(super) type Sym3 = [ExprId; 6];

/// Row `i` of a symmetric matrix.
fn sym_row(s: &Sym3, i: usize) -> Vec3 {
    match i {
        0 => [s[0], s[1], s[2]],
        1 => [s[1], s[3], s[4]],
        _ => [s[2], s[4], s[5]],
    }
}

/// The index in [`Sym3`] of entry `(i, j)`.
pub(super) fn sym_index(i: usize, j: usize) -> usize {
    let (i, j) = (i.min(j), i.max(j));
    [[0, 1, 2], [1, 3, 4], [2, 4, 5]][i][j]
}

/// `r s r^T` for a rotation `r` and a symmetric `s`: the six entries of the upper triangle only
/// (`(s r^T)` once, then a row of `r` against each of its columns).
pub(super) fn rotate_sym(g: &mut ExprGraph, r: &Mat3, s: &Sym3) -> Sym3 {
    // Column j of s r^T is s times row j of r.
    let columns: [Vec3; 3] = std::array::from_fn(|j| sym_vec(g, s, r[j]));
    let mut out = [g.constant(0.0); 6];
    for i in 0..3 {
        for j in i..3 {
            out[sym_index(i, j)] = dot(g, r[i], columns[j]);
        }
    }
    out
}
