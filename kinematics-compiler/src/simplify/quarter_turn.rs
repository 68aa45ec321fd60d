//! Rules `quarter-turn` and `push-quarter-turns`.

use crate::symbolic::angle::LinearAngle;
use crate::symbolic::graph::ExprGraph;
use crate::symbolic::step::{SignedPerm, Step};

use super::ChainPass;

/// Pass `quarter-turn` ([`quarter_turns`]).
pub const QUARTER_TURN: ChainPass = ChainPass { name: "quarter-turn", run: |_, steps, _| quarter_turns(steps) };

/// Pass `push-quarter-turns` ([`push_quarter_turns`]).
pub const PUSH_QUARTER_TURNS: ChainPass =
    ChainPass { name: "push-quarter-turns", run: |g, steps, _| push_quarter_turns(g, steps) };

/// The numeric matrix of a constant rotation by `angle` about the unit `axis` (Rodrigues), with
/// exact entries for exact quarter turns.
fn constant_rotation(axis: [f64; 3], angle: &LinearAngle) -> [[f64; 3]; 3] {
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

/// Rule `quarter-turn`: constant rotations become signed permutations or numeric matrices.
fn quarter_turns(steps: Vec<Step>) -> Vec<Step> {
    steps
        .into_iter()
        .filter_map(|step| match step {
            Step::Rotate { axis, angle } if angle.is_constant() => {
                let m = constant_rotation(axis, &angle);
                match SignedPerm::from_matrix(m) {
                    Some(p) if p == SignedPerm::IDENTITY => None,
                    Some(p) => Some(Step::Permute(p)),
                    None => Some(Step::ConstRotate(m)),
                }
            }
            other => Some(other),
        })
        .collect()
}

fn mat_mul(a: [[f64; 3]; 3], b: [[f64; 3]; 3]) -> [[f64; 3]; 3] {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
}

/// Rule `push-quarter-turns`: moves every signed permutation to the end, conjugating the steps
/// it passes: `P R(u, a) = R(P u, a) P`, `P T(v) = T(P v) P`, `P C = (P C P^T) P`.
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
        }
    }
    if carried != SignedPerm::IDENTITY {
        out.push(Step::Permute(carried));
    }
    out
}
