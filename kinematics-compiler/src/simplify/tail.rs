//! Rule `translation-to-tail`, for a single pose accumulated from the tool back.

use crate::symbolic::graph::ExprGraph;
use crate::symbolic::step::Step;

use super::ChainPass;
use super::merge::along;

/// Pass `translation-to-tail`: `T(v) R(u, a) = R(u, a) T(v)` for `v` along the coordinate axis `u`.
pub const TRANSLATION_TO_TAIL: ChainPass =
    ChainPass { name: "translation-to-tail", run: |g, steps, _| translations_to_tail(g, steps) };

/// `T(v) R(u, a) = R(u, a) T(v)` when `v` lies along `u`: moves translations towards the tool, so
/// that the tool's offset is added last as `R v`, reusing the entries of the pose's rotation
/// instead of being carried through every joint.
fn translations_to_tail(g: &ExprGraph, mut steps: Vec<Step>) -> Vec<Step> {
    let mut changed = true;
    while changed {
        changed = false;
        for i in 0..steps.len().saturating_sub(1) {
            if let (Step::Translate(v), Step::Rotate { axis, .. }) = (&steps[i], &steps[i + 1])
                && along(g, v, *axis)
            {
                steps.swap(i, i + 1);
                changed = true;
            }
        }
    }
    steps
}

/// Splits off the trailing translations and quarter turns: they are applied last, on the right.
pub fn split_tail(steps: &[Step]) -> (&[Step], &[Step]) {
    let keep = steps.iter().rposition(|s| !matches!(s, Step::Translate(_) | Step::Permute(_))).map_or(0, |i| i + 1);
    steps.split_at(keep)
}

#[cfg(test)]
mod tests {
    use super::super::testing::{check, parse_steps};
    use super::*;
    use crate::symbolic::step::steps_text;

    #[test]
    fn translation_to_tail() {
        let check = |input, expected| check(&TRANSLATION_TO_TAIL, input, expected);
        check("T(0, 0, 0.5) Rz(q1)", "Rz(q1) T(0, 0, 0.5)");
        check("T(0, 0, 0.5) R-z(q1)", "R-z(q1) T(0, 0, 0.5)");
        check("T(0, 0, q2) Rz(q1)", "Rz(q1) T(0, 0, q2)");
        check("T(0, 0, 1) Rz(q1) Rz(q2)", "Rz(q1) Rz(q2) T(0, 0, 1)");
        check("T(0, 0, 1) Rz(q1) Rx(q2)", "Rz(q1) T(0, 0, 1) Rx(q2)");
        check("T(1, 0, 0) Rx(q1) T(0, 1, 0) Ry(q2)", "Rx(q1) T(1, 0, 0) Ry(q2) T(0, 1, 0)");
        // Across the axis, past a permutation or a constant rotation, or along an axis off the
        // coordinate axes (not recognised): stays.
        check("T(0.5, 0, 0) Rz(q1)", "T(0.5, 0, 0) Rz(q1)");
        check("T(0, 0, 1) P(y, -x, z)", "T(0, 0, 1) P(y, -x, z)");
        check("T(0, 0, 1) C(0.8, -0.6, 0; 0.6, 0.8, 0; 0, 0, 1)", "T(0, 0, 1) C(0.8, -0.6, 0; 0.6, 0.8, 0; 0, 0, 1)");
        check("T(0.6, 0, 0.8) R[0.6, 0, 0.8](q1)", "T(0.6, 0, 0.8) R[0.6, 0, 0.8](q1)");
    }

    #[test]
    fn the_tail_is_the_trailing_translations_and_permutations() {
        let split = |text: &str| {
            let mut g = ExprGraph::new();
            let steps = parse_steps(&mut g, text);
            let (main, tail) = split_tail(&steps);
            (steps_text(&g, main), steps_text(&g, tail))
        };
        let pair = |a: &str, b: &str| (a.to_owned(), b.to_owned());
        assert_eq!(
            split("Rz(q1) T(1, 0, 0) P(y, -x, z) T(0, 0, q2)"),
            pair("Rz(q1)", "T(1, 0, 0) P(y, -x, z) T(0, 0, q2)")
        );
        assert_eq!(split("T(1, 0, 0) Rz(q1)"), pair("T(1, 0, 0) Rz(q1)", "I"));
        assert_eq!(
            split("T(1, 0, 0) C(0.8, -0.6, 0; 0.6, 0.8, 0; 0, 0, 1)"),
            pair("T(1, 0, 0) C(0.8, -0.6, 0; 0.6, 0.8, 0; 0, 0, 1)", "I")
        );
        assert_eq!(split("T(1, 0, 0)"), pair("I", "T(1, 0, 0)"));
        assert_eq!(split("I"), pair("I", "I"));
    }
}
