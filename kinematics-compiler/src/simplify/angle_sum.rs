//! Rule `angle-sum`: parallel revolute axes separated only by translations.

use crate::symbolic::angle::LinearAngle;
use crate::symbolic::graph::ExprGraph;
use crate::symbolic::step::{Step, parallel};
use crate::symbolic::transform::{mat_vec, rotation_matrix};

use super::ChainPass;

/// Pass `angle-sum` ([`angle_sums`]).
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
