//! Rules `quarter-turn` and `push-quarter-turns`.

use crate::symbolic::angle::LinearAngle;
use crate::symbolic::graph::ExprGraph;
use crate::symbolic::step::{SignedPerm, Step};

use super::ChainPass;

/// Pass `quarter-turn`: constant rotations by whole quarter turns of an exact angle become signed
/// permutations (the identity vanishes); any other constant rotation stays a rotation, so that
/// `merge-rotations` can still fold it into a parallel joint once the permutations have turned
/// the axes (`constant-rotations` makes it a matrix afterwards).
pub const QUARTER_TURN: ChainPass = ChainPass { name: "quarter-turn", run: |_, steps, _| quarter_turns(steps) };

/// Pass `push-quarter-turns`: `P R(u, a) = R(P u, a) P`, `P T(v) = T(P v) P`, `P C = (P C P^T) P`,
/// so every signed permutation ends up at the end of the chain.
pub const PUSH_QUARTER_TURNS: ChainPass =
    ChainPass { name: "push-quarter-turns", run: |g, steps, _| push_quarter_turns(g, steps) };

/// The numeric matrix of a constant rotation by `angle` about the unit `axis` (Rodrigues), with
/// exact entries for exact quarter turns.
pub(super) fn constant_rotation(axis: [f64; 3], angle: &LinearAngle) -> [[f64; 3]; 3] {
    let (s, c) = angle.constant_sin_cos();
    let u = axis;
    let omc = 1.0 - c;
    let skew = [[0.0, -u[2], u[1]], [u[2], 0.0, -u[0]], [-u[1], u[0], 0.0]];
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let identity = if i == j { c } else { 0.0 };
            // Keep exact zeros exact: (1 - c) u_i u_j vanishes when either factor is zero.
            let outer = if omc == 0.0 || u[i] == 0.0 || u[j] == 0.0 { 0.0 } else { omc * u[i] * u[j] };
            let skew = if s == 0.0 || skew[i][j] == 0.0 { 0.0 } else { s * skew[i][j] };
            identity + outer + skew
        })
    })
}

/// Rule `quarter-turn`: constant rotations by whole quarter turns become signed permutations.
fn quarter_turns(steps: Vec<Step>) -> Vec<Step> {
    steps
        .into_iter()
        .filter_map(|step| match step {
            Step::Rotate { axis, angle } if angle.is_constant() => {
                match SignedPerm::from_matrix(constant_rotation(axis, &angle)) {
                    Some(p) if p == SignedPerm::IDENTITY => None,
                    Some(p) => Some(Step::Permute(p)),
                    None => Some(Step::Rotate { axis, angle }),
                }
            }
            other => Some(other),
        })
        .collect()
}

pub(super) fn mat_mul(a: [[f64; 3]; 3], b: [[f64; 3]; 3]) -> [[f64; 3]; 3] {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
}

/// Rule `push-quarter-turns`: moves every signed permutation to the end, conjugating the steps
/// it passes: `P R(u, a) = R(P u, a) P`, `P T(v) = T(P v) P`, `P C = (P C P^T) P`; it stops before a
/// floating or spherical joint's rotation.
fn push_quarter_turns(g: &mut ExprGraph, steps: Vec<Step>) -> Vec<Step> {
    let mut carried = SignedPerm::IDENTITY;
    let mut out = Vec::with_capacity(steps.len());
    for step in steps {
        match step {
            Step::Permute(p) => carried = carried.then(p),
            Step::Rotate { axis, angle } => out.push(Step::Rotate { axis: carried.apply(axis), angle }),
            Step::Translate(v) => out.push(Step::Translate(carried.apply_expr(g, v))),
            Step::ConstRotate(m) => {
                // Entries of P are 0 and +-1, so these products are exact.
                let conj = mat_mul(mat_mul(carried.matrix(), m), carried.inverse().matrix());
                out.push(Step::ConstRotate(conj));
            }
            // A floating or spherical joint's rotation is variables: the permutation stops before it.
            free @ Step::Free { .. } => {
                if carried != SignedPerm::IDENTITY {
                    out.push(Step::Permute(carried));
                    carried = SignedPerm::IDENTITY;
                }
                out.push(free);
            }
        }
    }
    if carried != SignedPerm::IDENTITY {
        out.push(Step::Permute(carried));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::super::testing::check;
    use super::*;

    #[test]
    fn quarter_turns_become_permutations() {
        let check = |input, expected| check(&QUARTER_TURN, input, expected);
        check("Rx(pi/2)", "P(x, -z, y)");
        check("Rx(-pi/2)", "P(x, z, -y)");
        check("Rx(3*pi/2)", "P(x, z, -y)");
        check("Ry(pi/2)", "P(z, y, -x)");
        check("Rz(pi)", "P(-x, -y, z)");
        check("Rz(-pi/2)", "P(y, -x, z)");
        // About a negative axis (before `axis-sign` has run).
        check("R-z(pi/2)", "P(y, -x, z)");
        // Whole turns and zero angles vanish.
        check("Rx(2*pi)", "I");
        check("Rz(q1) Rz(0) Rz(q2)", "Rz(q1) Rz(q2)");
        check("Ry(-4*pi) T(1, 0, 0)", "T(1, 0, 0)");
        // Joint rotations stay, whatever their constant part.
        check("Rz(q1 + pi/2) T(1, 0, 0)", "Rz(q1 + pi/2) T(1, 0, 0)");
    }

    #[test]
    fn other_constant_rotations_stay_rotations() {
        let check = |input, expected| check(&QUARTER_TURN, input, expected);
        // The nearest f64 to pi/2, and pi/2 as URDF files spell it, are numbers, never rounded to a
        // permutation (`constant-rotations` makes them matrices).
        check("Rx(1.5707963267948966)", "Rx(1.5707963267948966)");
        check("Rz(0.3) Rx(pi/2)", "Rz(0.3) P(x, -z, y)");
        check("Rz(pi/3)", "Rz(pi/3)");
        check("R[0.6, 0, 0.8](pi)", "R[0.6, 0, 0.8](pi)");
    }

    #[test]
    fn push_quarter_turns() {
        let check = |input, expected| check(&PUSH_QUARTER_TURNS, input, expected);
        // P R(u, a) = R(P u, a) P
        check("P(x, -z, y) Rz(q1)", "R-y(q1) P(x, -z, y)");
        check("P(-y, x, z) Rz(q1) P(-y, x, z) Rx(q2)", "Rz(q1) R-x(q2) P(-x, -y, z)");
        // P T(v) = T(P v) P, for numbers and expressions (a negation is free).
        check("P(x, -z, y) T(1, 2, 3)", "T(1, -3, 2) P(x, -z, y)");
        check("P(-y, x, z) T(q1, 0, 0)", "T(0, q1, 0) P(-y, x, z)");
        check("P(-y, x, z) T(0, q1 + 0.5, 0)", "T(-(q1 + 0.5), 0, 0) P(-y, x, z)");
        // Permutations compose; inverse ones cancel.
        check("P(x, -z, y) P(x, -z, y)", "P(x, -y, -z)");
        check("P(x, -z, y) T(1, 0, 0) P(x, z, -y)", "T(1, 0, 0)");
        // P C = (P C P^T) P: a rotation about x turned a quarter about z is one about y.
        check("P(-y, x, z) C(1, 0, 0; 0, 0.8, -0.6; 0, 0.6, 0.8)", "C(0.8, 0, 0.6; 0, 1, 0; -0.6, 0, 0.8) P(-y, x, z)");
        // An axis off the coordinate axes turns too.
        check("P(-y, x, z) R[0.6, 0, 0.8](q1)", "R[-0, 0.6, 0.8](q1) P(-y, x, z)");
        // A numeric constant rotation turns as a joint's does.
        check("P(x, -z, y) Rz(0.3)", "R-y(0.3) P(x, -z, y)");
        // Nothing to push.
        check("Rz(q1) T(1, 0, 0) P(y, -x, z)", "Rz(q1) T(1, 0, 0) P(y, -x, z)");
        check("Rz(q1) T(1, 0, 0)", "Rz(q1) T(1, 0, 0)");
    }
}
