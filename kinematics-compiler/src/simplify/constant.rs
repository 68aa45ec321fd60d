//! Rule `constant-rotations`.

use crate::symbolic::step::Step;

use super::ChainPass;
use super::quarter_turn::{constant_rotation, mat_mul};

/// Pass `constant-rotations`: the constant rotations left after the quarter turns have gone and
/// the parallel rotations have merged become numeric matrices, and a run of adjacent matrices
/// becomes their product when multiplying a pose by the product costs fewer operations than by
/// each in turn (`C(Rz(a)) C(Ry(b)) C(Rx(c))`, an `rpy` origin: 27 multiplications, not 36).
pub const CONSTANT_ROTATIONS: ChainPass =
    ChainPass { name: "constant-rotations", run: |_, steps, _| constant_rotations(steps) };

/// What multiplying a general rotation by `m` on the right costs, in multiplications plus
/// additions: each row of the result takes, per column of `m`, one product per entry that is
/// neither `0` nor `+-1` and one addition fewer than the column's non-zero entries.
fn product_cost(m: &[[f64; 3]; 3]) -> usize {
    let per_row: usize = (0..3)
        .map(|j| {
            let nonzero = (0..3).filter(|&i| m[i][j] != 0.0).count();
            let products = (0..3).filter(|&i| m[i][j] != 0.0 && m[i][j].abs() != 1.0).count();
            products + nonzero.saturating_sub(1)
        })
        .sum();
    3 * per_row
}

/// Rule `constant-rotations`: constant rotations become matrices; each run of adjacent matrices
/// becomes one when that is cheaper.
fn constant_rotations(steps: Vec<Step>) -> Vec<Step> {
    let mut out: Vec<Step> = Vec::with_capacity(steps.len());
    let mut run: Vec<[[f64; 3]; 3]> = Vec::new();
    let flush = |run: &mut Vec<[[f64; 3]; 3]>, out: &mut Vec<Step>| {
        if let Some((&first, rest)) = run.split_first() {
            let product = rest.iter().fold(first, |acc, m| mat_mul(acc, *m));
            let separate: usize = run.iter().map(product_cost).sum();
            if run.len() > 1 && product_cost(&product) < separate {
                out.push(Step::ConstRotate(product));
            } else {
                out.extend(run.iter().map(|m| Step::ConstRotate(*m)));
            }
        }
        run.clear();
    };
    for step in steps {
        match step {
            Step::Rotate { axis, angle } if angle.is_constant() => run.push(constant_rotation(axis, &angle)),
            Step::ConstRotate(m) => run.push(m),
            other => {
                flush(&mut run, &mut out);
                out.push(other);
            }
        }
    }
    flush(&mut run, &mut out);
    out
}

#[cfg(test)]
mod tests {
    use super::super::testing::check;
    use super::*;

    #[test]
    fn constant_rotations_become_matrices() {
        let check = |input, expected| check(&CONSTANT_ROTATIONS, input, expected);
        // The nearest f64 to pi/2, and pi/2 as URDF files spell it, are numbers: numeric rotations.
        check("Rx(1.5707963267948966)", "C(1, 0, 0; 0, 6.123233995736766e-17, -1; 0, 1, 6.123233995736766e-17)");
        check("Rx(1.57079632679)", "C(1, 0, 0; 0, 4.8965888601467475e-12, -1; 0, 1, 4.8965888601467475e-12)");
        check(
            "Rz(0.3)",
            "C(0.955336489125606, -0.29552020666133955, 0; 0.29552020666133955, 0.955336489125606, 0; 0, 0, 1)",
        );
        // A quarter-turn exact part is taken out exactly: sin(pi/2 + x) = cos x, cos(pi/2 + x) = -sin x.
        check(
            "Rz(pi/2 + 0.3)",
            "C(-0.29552020666133955, -0.955336489125606, 0; 0.955336489125606, -0.29552020666133955, 0; 0, 0, 1)",
        );
        // Exact, but not a quarter turn: the sine and cosine f64 computes.
        check(
            "Rz(pi/3)",
            "C(0.5000000000000001, -0.8660254037844386, 0; 0.8660254037844386, 0.5000000000000001, 0; 0, 0, 1)",
        );
        // A half turn about an axis off the coordinate axes: `2 u u^T - I`, its zeros exact.
        check("R[0.6, 0, 0.8](pi)", "C(-0.28, 0, 0.96; 0, -1, 0; 0.96, 0, 0.28000000000000025)");
        // Joint rotations stay.
        check("Rz(q1 + 0.3) T(1, 0, 0)", "Rz(q1 + 0.3) T(1, 0, 0)");
    }

    #[test]
    fn runs_of_matrices_multiply_when_that_is_cheaper() {
        let check = |input, expected| check(&CONSTANT_ROTATIONS, input, expected);
        // Three rotations about the three axes (an rpy origin): one full matrix, 27 products
        // instead of 36 (the product checked against Python's floats, multiplied in that order).
        check(
            "Rz(0.5) Ry(0.5) Rx(0.5) Rz(q1)",
            "C(0.7701511529340699, -0.2190241523482808, 0.5990789783679945; 0.42073549240394825, 0.8803465602362085, \
             -0.2190241523482808; -0.479425538604203, 0.42073549240394825, 0.7701511529340699) Rz(q1)",
        );
        // Two about different axes: the product has eight entries to multiply by, the pair the
        // same number of products but fewer additions, so they stay apart.
        check(
            "Rz(0.5) Ry(0.5)",
            "C(0.8775825618903728, -0.479425538604203, 0; 0.479425538604203, 0.8775825618903728, 0; 0, 0, 1) \
             C(0.8775825618903728, 0, 0.479425538604203; 0, 1, 0; -0.479425538604203, 0, 0.8775825618903728)",
        );
        // Matrices already made join a run; anything else ends it.
        check(
            "C(0.8, -0.6, 0; 0.6, 0.8, 0; 0, 0, 1) T(1, 0, 0) C(0.8, 0, 0.6; 0, 1, 0; -0.6, 0, 0.8)",
            "C(0.8, -0.6, 0; 0.6, 0.8, 0; 0, 0, 1) T(1, 0, 0) C(0.8, 0, 0.6; 0, 1, 0; -0.6, 0, 0.8)",
        );
        check(
            "C(0.8, -0.6, 0; 0.6, 0.8, 0; 0, 0, 1) C(0.8, 0.6, 0; -0.6, 0.8, 0; 0, 0, 1)",
            "C(1, 0, 0; 0, 1, 0; 0, 0, 1)",
        );
    }
}
