//! Rule `angle-sum`: parallel revolute axes separated only by translations.

use crate::symbolic::angle::LinearAngle;
use crate::symbolic::graph::ExprGraph;
use crate::symbolic::step::{Step, parallel};
use crate::symbolic::transform::{mat_vec, rotation_matrix};

use super::ChainPass;

/// Pass `angle-sum`: `R(u, a) T(v1) ... T(vk) R(+-u, b) = T(R(u, a) v1) ... T(R(u, a) vk) R(u, a +- b)`
/// for a joint angle `a`.
pub const ANGLE_SUM: ChainPass = ChainPass { name: "angle-sum", run: angle_sums };

/// Every joint variable of `b` already appears in `a`.
fn adds_no_variable(a: &LinearAngle, b: &LinearAngle) -> bool {
    b.terms().iter().all(|(dof, _)| a.terms().iter().any(|(d, _)| d == dof))
}

/// `R(u, a) T(v1) ... T(vk) R(+-u, b) = T(R(u, a) v1) ... T(R(u, a) vk) R(u, a +- b)`, applied left
/// to right so runs of parallel joints collapse into one rotation by the total angle.
fn angle_sums(g: &mut ExprGraph, steps: Vec<Step>, options: super::Options) -> Vec<Step> {
    let mut out: Vec<Step> = Vec::with_capacity(steps.len());
    for step in steps {
        if let Step::Rotate { axis, angle } = &step {
            let mut k = out.len();
            while k > 0 && matches!(out[k - 1], Step::Translate(_)) {
                k -= 1;
            }
            if k > 0
                && k < out.len()
                && let Step::Rotate { axis: prev, angle: prev_angle } = &out[k - 1]
                && !prev_angle.is_constant()
                && let Some(sign) = parallel(*prev, *axis)
                && !(options.skip_repeated_angle_sums && adds_no_variable(prev_angle, angle))
            {
                let (prev, prev_angle) = (*prev, prev_angle.clone());
                let (s, c) = prev_angle.sin_cos(g);
                let rot = rotation_matrix(g, prev, s, c);
                let moved: Vec<Step> = out
                    .drain(k..)
                    .map(|t| match t {
                        Step::Translate(v) => Step::Translate(mat_vec(g, &rot, v)),
                        other => other,
                    })
                    .collect();
                out.pop();
                out.extend(moved);
                let merged = if sign > 0.0 { prev_angle.plus(angle) } else { prev_angle.plus(&angle.negated()) };
                out.push(Step::Rotate { axis: prev, angle: merged });
                continue;
            }
        }
        out.push(step);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::super::testing::{check, check_with};
    use super::*;
    use crate::simplify::Options;

    #[test]
    fn angle_sum() {
        let check = |input, expected| check(&ANGLE_SUM, input, expected);
        // R(a) T(v) R(b) = T(R(a) v) R(a + b)
        check("Rz(q1) T(1, 0, 0) Rz(q2)", "T(cos(q1), sin(q1), 0) Rz(q1 + q2)");
        check("Rz(q1) T(1, 0, 0) T(0, 2, 0) Rz(q2)", "T(cos(q1), sin(q1), 0) T(-2*sin(q1), 2*cos(q1), 0) Rz(q1 + q2)");
        check(
            "Rz(q1) T(1, 0, 0) Rz(q2) T(1, 0, 0) Rz(q3) T(0.5, 0, 0)",
            "T(cos(q1), sin(q1), 0) T(cos(q1 + q2), sin(q1 + q2), 0) Rz(q1 + q2 + q3) T(0.5, 0, 0)",
        );
        check("Ry(q1) T(0, 0, 1) Ry(q2)", "T(sin(q1), 0, cos(q1)) Ry(q1 + q2)");
        // Opposite axes subtract.
        check("Rz(q1) T(1, 0, 0) R-z(q2)", "T(cos(q1), sin(q1), 0) Rz(q1 - q2)");
        // Not parallel, nothing between (that is `merge-rotations`), or a constant first rotation.
        check("Rz(q1) T(1, 0, 0) Rx(q2)", "Rz(q1) T(1, 0, 0) Rx(q2)");
        check("Rz(q1) Rz(q2)", "Rz(q1) Rz(q2)");
        check("Rz(0.3) T(1, 0, 0) Rz(q2)", "Rz(0.3) T(1, 0, 0) Rz(q2)");
        check("Rz(q1) T(1, 0, 0) P(y, -x, z) Rz(q2)", "Rz(q1) T(1, 0, 0) P(y, -x, z) Rz(q2)");
        // An exact quarter turn in the first angle is taken out of its sine and cosine; a decimal
        // near one is an angle of its own.
        check("Rz(q1 + pi/2) T(1, 0, 0) Rz(q2)", "T(-sin(q1), cos(q1), 0) Rz(q1 + q2 + pi/2)");
        check(
            "Rz(q1 + 1.5707963267948966) T(1, 0, 0) Rz(q2)",
            "T(cos(q1 + 1.5707963267948966), sin(q1 + 1.5707963267948966), 0) Rz(q1 + q2 + 1.5707963267948966)",
        );
        // Prismatic joints between: along the axis the translation is unchanged, across it turns.
        check("Rz(q1) T(0, 0, q2) Rz(q3)", "T(0, 0, q2) Rz(q1 + q3)");
        check("Rz(q1) T(q2, 0, 0) Rz(q3)", "T(q2*cos(q1), q2*sin(q1), 0) Rz(q1 + q3)");
        // A mimic of the first joint.
        check("Rz(q1) T(1, 0, 0) Rz(2*q1 + 0.1)", "T(cos(q1), sin(q1), 0) Rz(3*q1 + 0.1)");
    }

    #[test]
    fn angle_sum_can_skip_angles_that_add_no_joint() {
        let skip = Options { skip_repeated_angle_sums: true, ..Options::default() };
        let check = |input, expected| check_with(&ANGLE_SUM, skip, input, expected);
        check("Rz(q1) T(1, 0, 0) Rz(2*q1)", "Rz(q1) T(1, 0, 0) Rz(2*q1)");
        check("Rz(q1 + q2) T(1, 0, 0) Rz(-q1 + 0.5)", "Rz(q1 + q2) T(1, 0, 0) Rz(-q1 + 0.5)");
        check("Rz(q1) T(1, 0, 0) Rz(q1 + q2)", "T(cos(q1), sin(q1), 0) Rz(2*q1 + q2)");
        check("Rz(q1) T(1, 0, 0) Rz(q2)", "T(cos(q1), sin(q1), 0) Rz(q1 + q2)");
    }
}
