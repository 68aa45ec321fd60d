//! Rules `axis-sign`, `merge-rotations` and `combine-translations`.

use crate::symbolic::angle::LinearAngle;
use crate::symbolic::graph::{ExprGraph, ExprId};
use crate::symbolic::step::{Step, axis_aligned, parallel};
use crate::symbolic::transform::vec_add;

use super::ChainPass;

/// Pass `axis-sign` ([`normalize_axes`]).
pub const AXIS_SIGN: ChainPass = ChainPass { name: "axis-sign", run: |_, steps, _| normalize_axes(steps) };

/// Pass `merge-rotations` ([`merge_rotations`]).
pub const MERGE_ROTATIONS: ChainPass = ChainPass { name: "merge-rotations", run: |g, steps, options| merge_rotations(g, steps, options) };

/// Pass `combine-translations` ([`combine_translations`]).
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
