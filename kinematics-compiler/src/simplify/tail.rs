//! Rule `translation-to-tail`, for a single pose accumulated from the tool back.

use crate::symbolic::graph::ExprGraph;
use crate::symbolic::step::Step;

use super::ChainPass;
use super::merge::along;

/// Pass `translation-to-tail` ([`translations_to_tail`]).
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
