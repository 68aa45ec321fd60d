//! The chain IR: a rigid transform as a product of steps, which the simplifier rewrites.
//!
//! The steps are `Rotate`, `Translate`, `Permute` and `ConstRotate`. This module also prints chains
//! and expressions as text (`steps_text`, `expr_text`) for the passes' tests.

use std::fmt;

use super::angle::{LinearAngle, number_text};
use super::graph::{ExprGraph, ExprId, Node};

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

/// The image of a vector: `P(y, -x, z)` maps `(x, y, z)` to `(y, -x, z)` (a quarter turn about
/// `-z`).
impl fmt::Display for SignedPerm {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let entries: Vec<String> = (0..3)
            .map(|i| format!("{}{}", if self.sign[i] < 0 { "-" } else { "" }, ["x", "y", "z"][self.col[i]]))
            .collect();
        write!(f, "P({})", entries.join(", "))
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
    /// A floating or spherical joint's rotation: the matrix of its quaternion, whose nine entries
    /// are variables the generated code computes first (`quaternion_matrix`). The passes leave it
    /// where it is; the velocities read the joint's columns (from `column` on: a floating joint's
    /// six, a spherical joint's three angular ones) off the frame after it, or for an inverted
    /// step (the base's side of the tree) before it.
    Free {
        /// The rotation's entries, row-major (variables of the graph).
        rotation: [[ExprId; 3]; 3],
        /// The joint's first velocity (Jacobian column).
        column: usize,
        /// Whether the joint also translates (a floating joint, whose three linear velocities
        /// come before its angular ones; its translation is the [`Step::Translate`] before this
        /// step); a spherical joint only turns.
        translates: bool,
        /// Whether this is the inverse of the joint's rotation.
        inverted: bool,
    },
}

impl Step {
    /// The inverse step: `R(u, -a)`, `T(-v)`, `P^T`, `C^T`.
    pub fn inverse(&self, g: &mut ExprGraph) -> Step {
        match self {
            Step::Rotate { axis, angle } => Step::Rotate { axis: *axis, angle: angle.negated() },
            Step::Translate(v) => Step::Translate(v.map(|x| g.neg(x))),
            Step::Permute(p) => Step::Permute(p.inverse()),
            Step::ConstRotate(m) => Step::ConstRotate(std::array::from_fn(|i| std::array::from_fn(|j| m[j][i]))),
            Step::Free { rotation, column, translates, inverted } => Step::Free {
                rotation: std::array::from_fn(|i| std::array::from_fn(|j| rotation[j][i])),
                column: *column,
                translates: *translates,
                inverted: !inverted,
            },
        }
    }
}

impl Step {
    /// The step as text (see [`steps_text`]).
    pub fn text(&self, g: &ExprGraph) -> String {
        match self {
            Step::Rotate { axis, angle } => {
                let axis = match axis_aligned(*axis) {
                    Some(i) => format!("{}{}", if axis[i] < 0.0 { "-" } else { "" }, ["x", "y", "z"][i]),
                    None => format!("[{}]", axis.map(number_text).join(", ")),
                };
                format!("R{axis}({angle})")
            }
            Step::Translate(v) => format!("T({})", v.map(|x| expr_text(g, x)).join(", ")),
            Step::Permute(p) => p.to_string(),
            Step::ConstRotate(m) => {
                format!("C({})", m.map(|row| row.map(number_text).join(", ")).join("; "))
            }
            Step::Free { rotation, inverted, .. } => {
                let entries = rotation.map(|row| row.map(|x| expr_text(g, x)).join(", ")).join("; ");
                format!("F{}({entries})", if *inverted { "'" } else { "" })
            }
        }
    }
}

/// A chain of steps as text, the steps separated by spaces, for tests and traces:
/// `Rz(q1) T(0.5, 0, 0) Rz(q2 + pi/2) P(y, -x, z) C(1, 0, 0; 0, 0.8, -0.6; 0, 0.6, 0.8)`.
///
/// `Rz(a)` is a rotation by `a` about `+z` (`R-z(a)` about `-z`, `R[0.6, 0, 0.8](a)` about any other
/// unit axis), the angle as [`LinearAngle`] displays it; `T(x, y, z)` a translation, each entry as
/// [`expr_text`] writes it; `P(..)` a signed permutation ([`SignedPerm`]'s display); `C(..)` a
/// numeric rotation matrix, row by row. The empty chain (the identity) is `I`.
pub fn steps_text(g: &ExprGraph, steps: &[Step]) -> String {
    if steps.is_empty() {
        return "I".to_owned();
    }
    steps.iter().map(|s| s.text(g)).collect::<Vec<_>>().join(" ")
}

/// An expression of the graph as text with plain function names, the whole tree written out:
/// `q2*cos(q1) + 0.5*sin(q1 + q2) - q3`. Constant factors come first; otherwise operands appear in
/// the graph's order (older first), and a right operand that is itself a sum (of a sum) or a product
/// (of a product) is parenthesised, so the text shows how the expression is built.
pub fn expr_text(g: &ExprGraph, id: ExprId) -> String {
    match g.node(id) {
        Node::Const(c) => number_text(c.value()),
        Node::Var(i) => format!("q{}", u64::from(i) + 1),
        Node::Sin(a) => format!("sin({})", expr_text(g, a)),
        Node::Cos(a) => format!("cos({})", expr_text(g, a)),
        Node::Neg(a) => format!("-{}", operand(g, a, false)),
        Node::Add(a, b) => match (subtrahend(g, a), subtrahend(g, b)) {
            (_, Some(b)) => format!("{} - {b}", expr_text(g, a)),
            (Some(a), None) => format!("{} - {a}", expr_text(g, b)),
            (None, None) => {
                let b =
                    if matches!(g.node(b), Node::Add(..)) { format!("({})", expr_text(g, b)) } else { expr_text(g, b) };
                format!("{} + {b}", expr_text(g, a))
            }
        },
        Node::Mul(a, b) => {
            let (a, b) = if g.as_const(b).is_some() && g.as_const(a).is_none() { (b, a) } else { (a, b) };
            format!("{}*{}", operand(g, a, false), operand(g, b, true))
        }
        Node::Input(i) => format!("in{i}"),
        Node::Div(a, b) => format!("{}/{}", operand(g, a, false), operand(g, b, true)),
        Node::Sqrt(a) => format!("sqrt({})", expr_text(g, a)),
        Node::Atan2(y, x) => format!("atan2({}, {})", expr_text(g, y), expr_text(g, x)),
        Node::IfPositive(c, a, b) => {
            format!("if_positive({}, {}, {})", expr_text(g, c), expr_text(g, a), expr_text(g, b))
        }
    }
}

/// The magnitude of a negated term or negative constant, ready to follow ` - `.
fn subtrahend(g: &ExprGraph, id: ExprId) -> Option<String> {
    match g.node(id) {
        Node::Neg(inner) => {
            let text = expr_text(g, inner);
            Some(if matches!(g.node(inner), Node::Add(..)) { format!("({text})") } else { text })
        }
        Node::Const(c) if c.value() < 0.0 => Some(number_text(-c.value())),
        _ => None,
    }
}

/// An operand of a product or negation: sums, negations and negative numbers get parentheses, and
/// a product too when it is the right operand.
fn operand(g: &ExprGraph, id: ExprId, right: bool) -> String {
    let text = expr_text(g, id);
    let wrap = match g.node(id) {
        Node::Add(..) | Node::Neg(..) => true,
        Node::Mul(..) | Node::Div(..) => right,
        Node::Const(c) => c.value() < 0.0,
        _ => false,
    };
    if wrap { format!("({text})") } else { text }
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

#[cfg(test)]
mod tests {
    use super::*;
    use kinematics_model::{Angle, PiRational};

    #[test]
    fn steps_read_as_text() {
        let mut g = ExprGraph::new();
        let (q1, q2) = (g.var(0), g.var(1));
        let (half, zero) = (g.constant(0.5), g.constant(0.0));
        let quarter = LinearAngle::constant(Angle::Exact(PiRational::new(1, 2).unwrap()));
        let rz = |dof, offset: LinearAngle| Step::Rotate {
            axis: [0.0, 0.0, 1.0],
            angle: LinearAngle::joint(dof, 1.0, 0.0).plus(&offset),
        };
        let rz_minus_quarter = SignedPerm::from_matrix([[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]).unwrap();
        let steps = [
            rz(0, LinearAngle::constant(Angle::ZERO)),
            Step::Translate([half, zero, zero]),
            rz(1, quarter.clone()),
            Step::Permute(rz_minus_quarter),
            Step::ConstRotate([[1.0, 0.0, 0.0], [0.0, 0.8, -0.6], [0.0, 0.6, 0.8]]),
        ];
        assert_eq!(
            steps_text(&g, &steps),
            "Rz(q1) T(0.5, 0, 0) Rz(q2 + pi/2) P(y, -x, z) C(1, 0, 0; 0, 0.8, -0.6; 0, 0.6, 0.8)"
        );
        let other_axes = [
            Step::Rotate { axis: [-1.0, 0.0, 0.0], angle: quarter.clone() },
            Step::Rotate { axis: [0.6, 0.0, -0.8], angle: LinearAngle::joint(1, 2.0, -0.25) },
            Step::Translate([q1, q2, zero]),
        ];
        assert_eq!(steps_text(&g, &other_axes), "R-x(pi/2) R[0.6, 0, -0.8](2*q2 - 0.25) T(q1, q2, 0)");
        assert_eq!(steps_text(&g, &[]), "I");
        assert_eq!(SignedPerm::IDENTITY.to_string(), "P(x, y, z)");
    }

    #[test]
    fn expressions_read_as_text() {
        let mut g = ExprGraph::new();
        let (q1, q2, q3) = (g.var(0), g.var(1), g.var(2));
        let (half, minus_half) = (g.constant(0.5), g.constant(-0.5));
        let (s1, c1) = (g.sin(q1), g.cos(q1));
        let q12 = g.add(q1, q2);
        let s12 = g.sin(q12);
        let q2c1 = g.mul(q2, c1);
        let hs12 = g.mul(s12, half);
        let sum = g.add(q2c1, hs12);
        let text = |g: &ExprGraph, id| expr_text(g, id);
        assert_eq!(text(&g, sum), "q2*cos(q1) + 0.5*sin(q1 + q2)");
        let difference = g.sub(sum, q3);
        assert_eq!(text(&g, difference), "q2*cos(q1) + 0.5*sin(q1 + q2) - q3");
        let first_negated = g.sub(q3, sum);
        assert_eq!(text(&g, first_negated), "q3 - (q2*cos(q1) + 0.5*sin(q1 + q2))");
        let shifted = g.add(q1, minus_half);
        assert_eq!(text(&g, shifted), "q1 - 0.5");
        let nested = g.add(q3, q12);
        assert_eq!(text(&g, nested), "q3 + (q1 + q2)");
        let product = g.mul(s1, c1);
        let product = g.mul(q3, product);
        assert_eq!(text(&g, product), "q3*(sin(q1)*cos(q1))");
        let negated = g.neg(product);
        assert_eq!(text(&g, negated), "-q3*(sin(q1)*cos(q1))");
        let scaled = g.mul(half, q12);
        assert_eq!(text(&g, scaled), "0.5*(q1 + q2)");
        let neg_cos = g.neg(c1);
        let neg_sum = g.neg(q12);
        assert_eq!(text(&g, neg_sum), "-(q1 + q2)");
        let both = g.add(neg_cos, minus_half);
        assert_eq!(text(&g, both), "-0.5 - cos(q1)");
    }
}
