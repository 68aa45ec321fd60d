//! The chain IR: a rigid transform as a product of steps, which the simplifier rewrites.

use super::angle::LinearAngle;
use super::graph::{ExprGraph, ExprId};

/// A rotation by whole quarter turns: a signed permutation matrix, free to apply.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SignedPerm {
    /// Row `i` has `sign[i]` in column `col[i]`.
    col: [usize; 3],
    sign: [i8; 3],
}

impl SignedPerm {
    /// The identity.
    pub const IDENTITY: SignedPerm = SignedPerm { col: [0, 1, 2], sign: [1, 1, 1] };

    /// From an exact rotation matrix with entries in {-1, 0, 1}; `None` otherwise.
    pub fn from_matrix(m: [[f64; 3]; 3]) -> Option<Self> {
        let mut col = [0; 3];
        let mut sign = [0; 3];
        for i in 0..3 {
            let nonzero: Vec<usize> = (0..3).filter(|&j| m[i][j] != 0.0).collect();
            let [j] = nonzero[..] else { return None };
            if m[i][j].abs() != 1.0 {
                return None;
            }
            col[i] = j;
            sign[i] = if m[i][j] > 0.0 { 1 } else { -1 };
        }
        Some(SignedPerm { col, sign })
    }

    /// The matrix.
    pub fn matrix(self) -> [[f64; 3]; 3] {
        let mut m = [[0.0; 3]; 3];
        for i in 0..3 {
            m[i][self.col[i]] = f64::from(self.sign[i]);
        }
        m
    }

    /// `self * v` for a numeric vector.
    pub fn apply(self, v: [f64; 3]) -> [f64; 3] {
        std::array::from_fn(|i| f64::from(self.sign[i]) * v[self.col[i]])
    }

    /// `self * v` for a symbolic vector (only negations: free).
    pub fn apply_expr(self, g: &mut ExprGraph, v: [ExprId; 3]) -> [ExprId; 3] {
        std::array::from_fn(|i| if self.sign[i] < 0 { g.neg(v[self.col[i]]) } else { v[self.col[i]] })
    }

    /// `self * other`.
    pub fn then(self, other: SignedPerm) -> SignedPerm {
        // (A B)_ij = A_i,col_a[i] * B_col_a[i], j
        let col = std::array::from_fn(|i| other.col[self.col[i]]);
        let sign = std::array::from_fn(|i| self.sign[i] * other.sign[self.col[i]]);
        SignedPerm { col, sign }
    }

    /// The inverse (transpose).
    pub fn inverse(self) -> SignedPerm {
        let mut col = [0; 3];
        let mut sign = [0; 3];
        for i in 0..3 {
            col[self.col[i]] = i;
            sign[self.col[i]] = self.sign[i];
        }
        SignedPerm { col, sign }
    }
}

/// One factor of a chain's transform.
#[derive(Debug, Clone, PartialEq)]
pub enum Step {
    /// Rotation about a unit axis by an angle (a joint's motion, or a constant rotation).
    Rotate {
        /// Unit axis; axis-aligned axes are exactly `[0, 0, 1]` etc.
        axis: [f64; 3],
        /// The angle.
        angle: LinearAngle,
    },
    /// Translation by a vector (constant, or symbolic after a prismatic joint or an angle sum).
    Translate([ExprId; 3]),
    /// Rotation by quarter turns.
    Permute(SignedPerm),
    /// A constant rotation that is not a quarter turn.
    ConstRotate([[f64; 3]; 3]),
}

impl Step {
    /// The inverse step: `R(u, -a)`, `T(-v)`, `P^T`, `C^T`.
    pub fn inverse(&self, g: &mut ExprGraph) -> Step {
        match self {
            Step::Rotate { axis, angle } => Step::Rotate { axis: *axis, angle: angle.negated() },
            Step::Translate(v) => Step::Translate(v.map(|x| g.neg(x))),
            Step::Permute(p) => Step::Permute(p.inverse()),
            Step::ConstRotate(m) => Step::ConstRotate(std::array::from_fn(|i| std::array::from_fn(|j| m[j][i]))),
        }
    }
}

/// The inverse of the product of `steps`: the inverted steps in reverse order.
pub fn invert(g: &mut ExprGraph, steps: &[Step]) -> Vec<Step> {
    steps.iter().rev().map(|s| s.inverse(g)).collect()
}

/// Whether a unit axis is a coordinate axis (exactly one non-zero entry).
pub fn axis_aligned(axis: [f64; 3]) -> Option<usize> {
    let nonzero: Vec<usize> = (0..3).filter(|&i| axis[i] != 0.0).collect();
    match nonzero[..] {
        [i] => Some(i),
        _ => None,
    }
}

/// `a` and `b` are the same line: `Some(1.0)` if equal, `Some(-1.0)` if opposite.
pub fn parallel(a: [f64; 3], b: [f64; 3]) -> Option<f64> {
    if a == b {
        Some(1.0)
    } else if a.iter().zip(&b).all(|(x, y)| *x == -*y) {
        Some(-1.0)
    } else {
        None
    }
}
