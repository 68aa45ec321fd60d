//! Rules `axis-sign`, `merge-rotations` and `combine-translations`.

use crate::symbolic::angle::LinearAngle;
use crate::symbolic::graph::{ExprGraph, ExprId};
use crate::symbolic::step::{Step, axis_aligned, parallel};
use crate::symbolic::transform::vec_add;

use super::ChainPass;

/// Pass `axis-sign`: `R(-e, a) = R(e, -a)` for a coordinate axis `e`.
pub const AXIS_SIGN: ChainPass = ChainPass { name: "axis-sign", run: |_, steps, _| normalize_axes(steps) };

/// Pass `merge-rotations`: `R(u, a) T(v along u)* R(+-u, b) = T(v)* R(u, a +- b)`.
pub const MERGE_ROTATIONS: ChainPass =
    ChainPass { name: "merge-rotations", run: |g, steps, options| merge_rotations(g, steps, options) };

/// Pass `combine-translations`: `T(a) T(b) = T(a + b)`.
pub const COMBINE_TRANSLATIONS: ChainPass =
    ChainPass { name: "combine-translations", run: |g, steps, _| combine_translations(g, steps) };

/// Rule `axis-sign`: `R(-e, a) = R(e, -a)` for a coordinate axis `e`.
fn normalize_axes(steps: Vec<Step>) -> Vec<Step> {
    steps
        .into_iter()
        .map(|step| match step {
            Step::Rotate { axis, angle } if axis_aligned(axis).is_some_and(|i| axis[i] < 0.0) => {
                Step::Rotate { axis: axis.map(|x| if x == 0.0 { 0.0 } else { -x }), angle: angle.negated() }
            }
            other => other,
        })
        .collect()
}

/// Whether the translation `v` lies along the coordinate axis `axis` (then it commutes with
/// rotations about that axis).
pub(crate) fn along(g: &ExprGraph, v: &[ExprId; 3], axis: [f64; 3]) -> bool {
    match axis_aligned(axis) {
        Some(i) => (0..3).filter(|&k| k != i).all(|k| g.is_const(v[k], 0.0)),
        None => false,
    }
}

/// Rule `merge-rotations`: `R(u, a) T(v along u)* R(+-u, b) = T(v)* R(u, a +- b)`.
fn merge_rotations(g: &ExprGraph, steps: Vec<Step>, options: super::Options) -> Vec<Step> {
    let mut out: Vec<Step> = Vec::with_capacity(steps.len());
    for step in steps {
        if let Step::Rotate { axis, angle } = &step {
            // Look back past translations along this axis for a rotation about a parallel axis.
            let mut k = out.len();
            while k > 0 && matches!(&out[k - 1], Step::Translate(v) if along(g, v, *axis)) {
                k -= 1;
            }
            if k > 0
                && let Step::Rotate { axis: prev, angle: prev_angle } = &out[k - 1]
                && let Some(sign) = parallel(*prev, *axis)
                && !(options.keep_constant_rotations && mixes_numeric_constant(prev_angle, angle))
            {
                let merged = if sign > 0.0 { prev_angle.plus(angle) } else { prev_angle.plus(&angle.negated()) };
                let prev = *prev;
                out.remove(k - 1);
                out.push(Step::Rotate { axis: prev, angle: merged });
                continue;
            }
        }
        out.push(step);
    }
    out
}

/// One angle is a constant that is not a whole number of quarter turns, the other moves.
fn mixes_numeric_constant(a: &LinearAngle, b: &LinearAngle) -> bool {
    let numeric = |x: &LinearAngle| x.is_constant() && !x.is_quarter_turns();
    (numeric(a) && !b.is_constant()) || (numeric(b) && !a.is_constant())
}

/// Rule `combine-translations`: `T(a) T(b) = T(a + b)`.
fn combine_translations(g: &mut ExprGraph, steps: Vec<Step>) -> Vec<Step> {
    let mut out: Vec<Step> = Vec::with_capacity(steps.len());
    for step in steps {
        if let Step::Translate(v) = &step
            && let Some(Step::Translate(prev)) = out.last()
        {
            let sum = vec_add(g, *prev, *v);
            out.pop();
            out.push(Step::Translate(sum));
            continue;
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
    fn axis_sign() {
        let check = |input, expected| check(&AXIS_SIGN, input, expected);
        check("R-z(q1)", "Rz(-q1)");
        check("Rz(q1)", "Rz(q1)");
        check("R-x(pi/2 + 0.3)", "Rx(-pi/2 - 0.3)");
        check("R-y(-2*q1 + 0.5)", "Ry(2*q1 - 0.5)");
        check("T(0, 0, -1) R-z(q2) Ry(q3)", "T(0, 0, -1) Rz(-q2) Ry(q3)");
        // Only coordinate axes: any other axis keeps its sign.
        check("R[0, -0.6, -0.8](q1)", "R[0, -0.6, -0.8](q1)");
        check("I", "I");
    }

    #[test]
    fn merge_rotations() {
        let check = |input, expected| check(&MERGE_ROTATIONS, input, expected);
        check("Rz(q1) Rz(q2)", "Rz(q1 + q2)");
        check("Rz(q1) Rz(q2) Rz(q3)", "Rz(q1 + q2 + q3)");
        check("Rz(q1) Rx(q2)", "Rz(q1) Rx(q2)");
        // Opposite axes subtract.
        check("Rz(q1) R-z(q2)", "Rz(q1 - q2)");
        check("R-z(q1) Rz(q2)", "R-z(q1 - q2)");
        // A translation along the axis commutes with the rotation and moves before it; one across
        // the axis does not.
        check("Rz(q1) T(0, 0, 0.5) Rz(q2)", "T(0, 0, 0.5) Rz(q1 + q2)");
        check("Rz(q1) T(0, 0, 0.5) T(0, 0, q3) Rz(q2)", "T(0, 0, 0.5) T(0, 0, q3) Rz(q1 + q2)");
        check("Rz(q1) T(0.5, 0, 0) Rz(q2)", "Rz(q1) T(0.5, 0, 0) Rz(q2)");
        check("Rz(q1) T(0, 0, 0.5) T(0.5, 0, 0) Rz(q2)", "Rz(q1) T(0, 0, 0.5) T(0.5, 0, 0) Rz(q2)");
        // A prismatic joint along the axis.
        check("Rz(q1) T(0, 0, q2) Rz(q3)", "T(0, 0, q2) Rz(q1 + q3)");
        // Constants fold into joint angles, exact parts stay exact, numbers are added as they are.
        check("Rz(0.3) Rz(q1)", "Rz(q1 + 0.3)");
        check("Rx(pi/2) Rx(q1) Rx(pi/2)", "Rx(q1 + pi)");
        check("Rx(1.5707963267948966) Rx(1.5707963267948966)", "Rx(3.141592653589793)");
        check("Rx(pi/2) Rx(1.5707963267948966)", "Rx(pi/2 + 1.5707963267948966)");
        // Mimic multipliers add up; a joint and its inverse cancel to the zero angle.
        check("Rz(q1) Rz(2*q1 + 0.1)", "Rz(3*q1 + 0.1)");
        check("Rz(q1) Rz(-q1)", "Rz(0)");
        // Parallel but not equal axes off the coordinate axes merge only when adjacent.
        check("R[0.6, 0, 0.8](q1) R[-0.6, 0, -0.8](q2)", "R[0.6, 0, 0.8](q1 - q2)");
        check(
            "R[0.6, 0, 0.8](q1) T(0.6, 0, 0.8) R[0.6, 0, 0.8](q2)",
            "R[0.6, 0, 0.8](q1) T(0.6, 0, 0.8) R[0.6, 0, 0.8](q2)",
        );
    }

    #[test]
    fn merge_rotations_can_keep_numeric_constants_apart() {
        let keep = Options { keep_constant_rotations: true, ..Options::default() };
        let check = |input, expected| check_with(&MERGE_ROTATIONS, keep, input, expected);
        check("Rz(0.3) Rz(q1)", "Rz(0.3) Rz(q1)");
        check("Rz(q1) Rz(pi/2 + 0.3)", "Rz(q1) Rz(pi/2 + 0.3)");
        check("Rz(1.5707963267948966) Rz(q1)", "Rz(1.5707963267948966) Rz(q1)");
        // Quarter turns, and constants with constants, still merge.
        check("Rz(pi/2) Rz(q1)", "Rz(q1 + pi/2)");
        check("Rz(0.3) Rz(0.2)", "Rz(0.5)");
        check("Rz(q1) Rz(q2)", "Rz(q1 + q2)");
    }

    #[test]
    fn combine_translations() {
        let check = |input, expected| check(&COMBINE_TRANSLATIONS, input, expected);
        check("T(1, 0, 0) T(0, 2, 0)", "T(1, 2, 0)");
        check("T(1, 0, 0) T(1, 0, 0) T(1, 0, 0)", "T(3, 0, 0)");
        check("T(0, 0, q1) T(0, 0, 0.5)", "T(0, 0, q1 + 0.5)");
        check("T(q1, 0, 0) T(-q1, 0, 0)", "T(0, 0, 0)");
        check("T(1, 0, 0) Rz(q1) T(1, 0, 0)", "T(1, 0, 0) Rz(q1) T(1, 0, 0)");
        check("T(1, 0, 0) P(y, -x, z) T(1, 0, 0)", "T(1, 0, 0) P(y, -x, z) T(1, 0, 0)");
        check("Rz(q1)", "Rz(q1)");
    }
}
