//! Symbolic rigid transforms (3x3 rotation and translation; the constant bottom row is implicit)
//! and the folds that evaluate a chain of steps into one.
//!
//! There are two folds: from the tool back, and from the base out.

use super::graph::{ExprGraph, ExprId};
use super::step::{SignedPerm, Step, axis_aligned};

/// A 3x3 matrix of expressions, row-major.
pub type Mat3 = [[ExprId; 3]; 3];

/// A symbolic rigid transform `[r p; 0 1]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SymTransform {
    /// Rotation, row-major.
    pub r: Mat3,
    /// Translation.
    pub p: [ExprId; 3],
}

impl SymTransform {
    /// The identity.
    pub fn identity(g: &mut ExprGraph) -> Self {
        let (zero, one) = (g.constant(0.0), g.constant(1.0));
        let r = std::array::from_fn(|i| std::array::from_fn(|j| if i == j { one } else { zero }));
        SymTransform { r, p: [zero; 3] }
    }

    /// The twelve entries: rotation row-major, then translation.
    pub fn entries(&self) -> [ExprId; 12] {
        let r = self.r;
        [
            r[0][0], r[0][1], r[0][2], r[1][0], r[1][1], r[1][2], r[2][0], r[2][1], r[2][2], self.p[0], self.p[1],
            self.p[2],
        ]
    }
}

/// Dot product of expressions, skipping zero terms (the smart constructors fold the rest).
fn dot(g: &mut ExprGraph, a: [ExprId; 3], b: [ExprId; 3]) -> ExprId {
    let mut sum = g.constant(0.0);
    for k in 0..3 {
        let term = g.mul(a[k], b[k]);
        sum = g.add(sum, term);
    }
    sum
}

/// `a * b`.
pub fn mat_mul(g: &mut ExprGraph, a: &Mat3, b: &Mat3) -> Mat3 {
    std::array::from_fn(|i| std::array::from_fn(|j| dot(g, a[i], [b[0][j], b[1][j], b[2][j]])))
}

/// `a * v`.
pub fn mat_vec(g: &mut ExprGraph, a: &Mat3, v: [ExprId; 3]) -> [ExprId; 3] {
    std::array::from_fn(|i| dot(g, a[i], v))
}

/// `a + b`.
pub fn vec_add(g: &mut ExprGraph, a: [ExprId; 3], b: [ExprId; 3]) -> [ExprId; 3] {
    std::array::from_fn(|i| g.add(a[i], b[i]))
}

/// A numeric matrix as constant nodes.
pub fn const_mat(g: &mut ExprGraph, m: [[f64; 3]; 3]) -> Mat3 {
    std::array::from_fn(|i| std::array::from_fn(|j| g.constant(m[i][j])))
}

/// A numeric vector as constant nodes.
pub fn const_vec(g: &mut ExprGraph, v: [f64; 3]) -> [ExprId; 3] {
    std::array::from_fn(|i| g.constant(v[i]))
}

/// The rotation matrix of a rotation step: the plain axis rotation for a coordinate axis, Rodrigues'
/// formula `c I + s [u]x + (1 - c) u u^T` with folded constants otherwise.
pub fn rotation_matrix(g: &mut ExprGraph, axis: [f64; 3], s: ExprId, c: ExprId) -> Mat3 {
    let (zero, one) = (g.constant(0.0), g.constant(1.0));
    let ns = g.neg(s);
    if let Some(i) = axis_aligned(axis) {
        // Axes are normalised to +1 before this point, but a -1 axis is the inverse rotation.
        let (s, ns) = if axis[i] > 0.0 { (s, ns) } else { (ns, s) };
        return match i {
            0 => [[one, zero, zero], [zero, c, ns], [zero, s, c]],
            1 => [[c, zero, s], [zero, one, zero], [ns, zero, c]],
            _ => [[c, ns, zero], [s, c, zero], [zero, zero, one]],
        };
    }
    let omc = g.sub(one, c);
    let u = axis;
    let mut m = [[zero; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            let k = g.constant(u[i] * u[j]);
            let outer = g.mul(k, omc);
            m[i][j] = if i == j {
                g.add(c, outer)
            } else {
                // [u]x: (i, j) = -u_k for (0,1), (1,2), (2,0) with k the third index; +u_k otherwise.
                let kk = 3 - i - j;
                let sign = if (i + 1) % 3 == j { -1.0 } else { 1.0 };
                let coeff = g.constant(sign * u[kk]);
                let skew = g.mul(coeff, s);
                g.add(outer, skew)
            };
        }
    }
    m
}

fn permute_rows(g: &mut ExprGraph, p: SignedPerm, m: &Mat3) -> Mat3 {
    let cols: [[ExprId; 3]; 3] = std::array::from_fn(|j| p.apply_expr(g, [m[0][j], m[1][j], m[2][j]]));
    std::array::from_fn(|i| std::array::from_fn(|j| cols[j][i]))
}

fn permute_cols(g: &mut ExprGraph, m: &Mat3, p: SignedPerm) -> Mat3 {
    // (m P)_ij = sum_k m_ik P_kj; rows of m times P = (P^T m^T)^T
    let pt = p.inverse();
    std::array::from_fn(|i| pt.apply_expr(g, m[i]))
}

/// `step * t`: applies a step on the left (accumulating from the tool back to the base).
pub fn apply_left(g: &mut ExprGraph, step: &Step, t: &SymTransform) -> SymTransform {
    match step {
        Step::Rotate { axis, angle } => {
            let (s, c) = angle.sin_cos(g);
            let rot = rotation_matrix(g, *axis, s, c);
            SymTransform { r: mat_mul(g, &rot, &t.r), p: mat_vec(g, &rot, t.p) }
        }
        Step::Translate(v) => SymTransform { r: t.r, p: vec_add(g, *v, t.p) },
        Step::Permute(p) => SymTransform { r: permute_rows(g, *p, &t.r), p: p.apply_expr(g, t.p) },
        Step::ConstRotate(m) => {
            let m = const_mat(g, *m);
            SymTransform { r: mat_mul(g, &m, &t.r), p: mat_vec(g, &m, t.p) }
        }
        Step::Free { rotation, .. } => SymTransform { r: mat_mul(g, rotation, &t.r), p: mat_vec(g, rotation, t.p) },
    }
}

/// `t * step`: applies a step on the right (accumulating from the base out to the tool).
pub fn apply_right(g: &mut ExprGraph, t: &SymTransform, step: &Step) -> SymTransform {
    match step {
        Step::Rotate { axis, angle } => {
            let (s, c) = angle.sin_cos(g);
            let rot = rotation_matrix(g, *axis, s, c);
            SymTransform { r: mat_mul(g, &t.r, &rot), p: t.p }
        }
        Step::Translate(v) => {
            let rv = mat_vec(g, &t.r, *v);
            SymTransform { r: t.r, p: vec_add(g, t.p, rv) }
        }
        Step::Permute(p) => SymTransform { r: permute_cols(g, &t.r, *p), p: t.p },
        Step::ConstRotate(m) => {
            let m = const_mat(g, *m);
            SymTransform { r: mat_mul(g, &t.r, &m), p: t.p }
        }
        Step::Free { rotation, .. } => SymTransform { r: mat_mul(g, &t.r, rotation), p: t.p },
    }
}

/// The product of `steps`, accumulated from the last step back to the first.
pub fn fold_from_tool(g: &mut ExprGraph, steps: &[Step]) -> SymTransform {
    let identity = SymTransform::identity(g);
    steps.iter().rev().fold(identity, |t, step| apply_left(g, step, &t))
}

/// The product of `steps`, accumulated from the first step out to the last, starting at `start`.
pub fn fold_from_base(g: &mut ExprGraph, start: SymTransform, steps: &[Step]) -> SymTransform {
    steps.iter().fold(start, |t, step| apply_right(g, &t, step))
}
