//! The simplify stage: directed rewrites of a chain of [`Step`]s, in a fixed pass order.
//!
//! Each pass is one named rule applied everywhere it matches; every rewrite is an exact identity
//! of rigid transforms, so no pass can change the kinematics (the agreement tests hold it to that).
//!
//! 1. `axis-sign`: a rotation about `-u` is a rotation about `u` by the negated angle.
//! 2. `merge-rotations`: rotations about one axis, separated at most by translations along that
//!    axis (which commute with them), become one rotation by the sum of the angles. This folds
//!    constant rotations into joint angles too (`Rz(0.3) Rz(q)` is `Rz(q + 0.3)`).
//! 3. `quarter-turn`: a constant rotation by a whole number of quarter turns (exact, or within
//!    1e-12 rad) is a signed permutation; any other constant rotation becomes a numeric matrix.
//! 4. `push-quarter-turns`: signed permutations move to the end of the chain, conjugating what they
//!    pass (`P R(u, a) = R(P u, a) P`, `P T(v) = T(P v) P`); they cost nothing there.
//! 5. `merge-rotations` again, on what the permutations exposed; then `combine-translations`.
//! 6. `angle-sum`: rotations about parallel axes separated only by translations merge into one
//!    rotation by the sum, the translations moving before it (`R(a) T(v) R(b) = T(R(a) v) R(a + b)`),
//!    so the code needs `sin`/`cos` of `q2 + q3`, not of `q3` alone.
//! 7. `combine-translations`: adjacent translations add up.
//!
//! For a single pose, [`translations_to_tail`] then moves translations along a joint axis past
//! that joint (rule `translation-to-tail`), and the trailing translations are applied last.
//! Once the poses are folded into expressions, [`factor_common`] (rule `common-factor`) pulls
//! shared factors out of sums.

mod angle_sum;
mod factor;
mod merge;
mod quarter_turn;
mod tail;

use crate::symbolic::graph::ExprGraph;
use crate::symbolic::step::Step;

pub use angle_sum::angle_sums;
pub use factor::factor_common;
pub use merge::{combine_translations, merge_rotations, normalize_axes};
pub use quarter_turn::{push_quarter_turns, quarter_turns};
pub use tail::{split_tail, translations_to_tail};

/// Choices the passes leave open, because which is cheaper depends on the robot: the compiler tries
/// each and keeps the cheapest result.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Options {
    /// Keep a numeric constant rotation apart from a joint rotation about the same axis instead of
    /// folding it into the joint's angle: folding saves a constant matrix product but makes a new
    /// angle, which costs a `sin_cos` when the joint's own angle is needed elsewhere.
    pub keep_constant_rotations: bool,
    /// Skip `angle-sum` when the second angle adds no new joint variable (a mimic of a joint
    /// already in the first): `sin_cos(q)` shared by both beats `sin_cos(q)` and `sin_cos(2q)`.
    pub skip_repeated_angle_sums: bool,
}

impl Options {
    /// Every combination, the default first.
    pub const ALL: [Options; 4] = [
        Options { keep_constant_rotations: false, skip_repeated_angle_sums: false },
        Options { keep_constant_rotations: true, skip_repeated_angle_sums: false },
        Options { keep_constant_rotations: false, skip_repeated_angle_sums: true },
        Options { keep_constant_rotations: true, skip_repeated_angle_sums: true },
    ];
}

/// Runs every pass in order, with the default options.
pub fn simplify(g: &mut ExprGraph, steps: Vec<Step>) -> Vec<Step> {
    simplify_with(g, steps, Options::default())
}

/// Runs every pass in order.
pub fn simplify_with(g: &mut ExprGraph, steps: Vec<Step>, options: Options) -> Vec<Step> {
    let steps = normalize_axes(steps);
    let steps = merge_rotations(g, steps, options);
    let steps = quarter_turns(steps);
    let steps = push_quarter_turns(g, steps);
    let steps = normalize_axes(steps);
    let steps = merge_rotations(g, steps, options);
    let steps = combine_translations(g, steps);
    let steps = angle_sums(g, steps, options);
    combine_translations(g, steps)
}
