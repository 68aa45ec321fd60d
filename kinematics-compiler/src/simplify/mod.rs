//! The simplify stage: every rewrite the compiler applies, each a named pass, run from three lists
//! in a fixed order.
//!
//! Each pass is one named rule applied everywhere it matches; every rewrite is an exact identity
//! of rigid transforms (or, over expressions, of real arithmetic), so no pass can change the
//! kinematics (the agreement tests hold it to that). Nothing calls a pass by hand: the compiler
//! runs [`CHAIN_PASSES`] on every chain, [`TOOL_FIRST_PASSES`] after them when a pose is
//! accumulated from the tool back, and [`EXPR_PASSES`] on the folded expressions. The numbered
//! names below are the lists' names in order (a unit test keeps them equal).
//!
//! # Chain passes ([`CHAIN_PASSES`])
//!
//! Over a chain of [`Step`]s, in order:
//!
//! 1. `axis-sign`: a rotation about `-u` is a rotation about `u` by the negated angle.
//! 2. `merge-rotations`: rotations about one axis, separated at most by translations along that
//!    axis (which commute with them), become one rotation by the sum of the angles. This folds
//!    constant rotations into joint angles too (`Rz(0.3) Rz(q1)` is `Rz(q1 + 0.3)`).
//! 3. `quarter-turn`: a constant rotation by a whole number of quarter turns of its exact part
//!    (the model decided which angles are exact; the compiler never rounds a number) is a signed
//!    permutation; any other constant rotation stays a rotation for now.
//! 4. `push-quarter-turns`: signed permutations move to the end of the chain, conjugating what they
//!    pass (`P R(u, a) = R(P u, a) P`, `P T(v) = T(P v) P`); they cost nothing there.
//! 5. `axis-sign` again, on the axes the permutations turned round.
//! 6. `merge-rotations` again, on what the permutations exposed (a constant rotation of an `rpy`
//!    origin that the permutation turned parallel to the joint's axis).
//! 7. `constant-rotations`: the constant rotations left become numeric matrices, and a run of
//!    adjacent matrices their product when that is cheaper to multiply by (an `rpy` origin about
//!    three axes: one full matrix).
//! 8. `combine-translations`: adjacent translations add up.
//! 9. `angle-sum`: rotations about parallel axes separated only by translations merge into one
//!    rotation by the sum, the translations moving before it (`R(a) T(v) R(b) = T(R(a) v) R(a + b)`),
//!    so the code needs `sin`/`cos` of `q2 + q3`, not of `q3` alone.
//! 10. `combine-translations` again, on the translations `angle-sum` moved together.
//!
//! # Tool-first passes ([`TOOL_FIRST_PASSES`])
//!
//! For a single pose accumulated from the tool back, after the chain passes:
//!
//! 1. `translation-to-tail`: a translation along a joint axis moves past that joint, towards the
//!    tool; the trailing translations and permutations ([`split_tail`]) are then applied last.
//!
//! # Expression passes ([`EXPR_PASSES`])
//!
//! Over the folded poses, in order:
//!
//! 1. `derived-angles`: the sine and cosine of an angle that is a computed angle plus a constant
//!    (`m*q - m` beside `m*q`), or a sum of two computed angles, come from theirs by the sum
//!    formulas (four multiplications) instead of a `sin_cos` call.
//! 2. `cross-column`: for a single pose, a rotation column becomes the cross product of the other
//!    two when that is cheaper.
//! 3. `common-factor`: `k*a + k*b = k*(a + b)` for products used only in that sum.
//!
//! # Not passes
//!
//! The graph's smart constructors ([`ExprGraph::add`], [`ExprGraph::mul`], [`ExprGraph::neg`],
//! [`ExprGraph::sin`], [`ExprGraph::cos`]) fold constants, drop `0` and `1`, pull negations out of
//! products, order operands and turn `sin^2 x + cos^2 x` into `1` as each node is built. That is
//! canonicalisation at construction, which every node gets whichever pass (or fold) builds it, not a
//! rewrite run over finished expressions, so it is not listed here.
//!
//! Every pass has text-in, text-out unit tests beside it, written in the text of
//! [`steps_text`](crate::symbolic::step::steps_text) and
//! [`expr_text`](crate::symbolic::step::expr_text).
//!
//! The passes are `ChainPass`es and `ExprPass`es.

mod angle_sum;
mod constant;
mod cross_column;
mod derived_angles;
mod factor;
mod merge;
mod quarter_turn;
mod tail;
#[cfg(test)]
mod testing;

use crate::symbolic::graph::{ExprGraph, ExprId};
use crate::symbolic::step::Step;
use crate::symbolic::transform::SymTransform;

pub use angle_sum::ANGLE_SUM;
pub use constant::CONSTANT_ROTATIONS;
pub use cross_column::CROSS_COLUMN;
pub use derived_angles::DERIVED_ANGLES;
pub(crate) use derived_angles::{DERIVATION_COST, angle_terms, linear_form, sum_formula};
pub use factor::COMMON_FACTOR;
pub use merge::{AXIS_SIGN, COMBINE_TRANSLATIONS, MERGE_ROTATIONS};
pub use quarter_turn::{PUSH_QUARTER_TURNS, QUARTER_TURN};
pub use tail::{TRANSLATION_TO_TAIL, split_tail};

/// A named rewrite of a chain of steps.
#[derive(Debug, Clone, Copy)]
pub struct ChainPass {
    /// The rule's stable kebab-case name (`merge-rotations`).
    pub name: &'static str,
    /// Rewrites a chain into an equal one; new expressions go into the graph.
    pub run: fn(&mut ExprGraph, Vec<Step>, Options) -> Vec<Step>,
}

/// A named rewrite of the folded poses (all of them at once, so that it sees what they share).
#[derive(Debug, Clone, Copy)]
pub struct ExprPass {
    /// The rule's stable kebab-case name (`common-factor`).
    pub name: &'static str,
    /// Rewrites the poses, and the further outputs computed from them (Jacobian entries, twists),
    /// in place (new nodes in the graph; the old ones stay, unreachable). The flag says whether
    /// only the translations of the poses are outputs (then the rotations must not be used).
    pub run: fn(&mut ExprGraph, &mut [SymTransform], &mut [ExprId], bool),
}

/// The chain passes, in the order they run (a pass listed twice runs twice).
pub const CHAIN_PASSES: &[ChainPass] = &[
    AXIS_SIGN,
    MERGE_ROTATIONS,
    QUARTER_TURN,
    PUSH_QUARTER_TURNS,
    AXIS_SIGN,
    MERGE_ROTATIONS,
    CONSTANT_ROTATIONS,
    COMBINE_TRANSLATIONS,
    ANGLE_SUM,
    COMBINE_TRANSLATIONS,
];

/// The passes run after [`CHAIN_PASSES`] on a pose accumulated from the tool back.
pub const TOOL_FIRST_PASSES: &[ChainPass] = &[TRANSLATION_TO_TAIL];

/// The passes over the folded poses, in the order they run.
pub const EXPR_PASSES: &[ExprPass] = &[DERIVED_ANGLES, CROSS_COLUMN, COMMON_FACTOR];

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

/// Runs [`CHAIN_PASSES`], with the default options.
pub fn simplify(g: &mut ExprGraph, steps: Vec<Step>) -> Vec<Step> {
    simplify_with(g, steps, Options::default())
}

/// Runs [`CHAIN_PASSES`].
pub fn simplify_with(g: &mut ExprGraph, steps: Vec<Step>, options: Options) -> Vec<Step> {
    run_chain_passes(g, steps, CHAIN_PASSES, options)
}

/// Runs `passes` over a chain, in order.
pub fn run_chain_passes(g: &mut ExprGraph, steps: Vec<Step>, passes: &[ChainPass], options: Options) -> Vec<Step> {
    passes.iter().fold(steps, |steps, pass| (pass.run)(g, steps, options))
}

/// Runs `passes` over the folded poses and the further outputs `extra`, in order.
pub fn run_expr_passes(
    g: &mut ExprGraph,
    frames: &mut [SymTransform],
    extra: &mut [ExprId],
    passes: &[ExprPass],
    position_only: bool,
) {
    for pass in passes {
        (pass.run)(g, frames, extra, position_only);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::symbolic::step::steps_text;
    use testing::parse_steps;

    /// The numbered names of each `# ... ([`LIST`])` section of this module's doc.
    fn documented_lists() -> Vec<(String, Vec<String>)> {
        let mut sections: Vec<(String, Vec<String>)> = Vec::new();
        for line in include_str!("mod.rs").lines().filter_map(|l| l.strip_prefix("//!")).map(str::trim) {
            if let Some(heading) = line.strip_prefix("# ") {
                let list = heading.split("([`").nth(1).and_then(|rest| rest.split('`').next()).unwrap_or("");
                sections.push((list.to_owned(), Vec::new()));
            } else if let Some((number, rest)) = line.split_once(". `")
                && number.parse::<usize>().is_ok()
                && let Some((name, _)) = rest.split_once('`')
            {
                let (_, names) = sections.last_mut().expect("a numbered pass sits under a heading");
                assert_eq!(number.parse::<usize>().unwrap(), names.len() + 1, "numbering of `{name}`");
                names.push(name.to_owned());
            }
        }
        sections
    }

    #[test]
    fn the_doc_lists_the_passes_in_order() {
        let names = |passes: &[&'static str]| passes.iter().map(|s| (*s).to_owned()).collect::<Vec<_>>();
        let chain: Vec<_> = CHAIN_PASSES.iter().map(|p| p.name).collect();
        let tool: Vec<_> = TOOL_FIRST_PASSES.iter().map(|p| p.name).collect();
        let expr: Vec<_> = EXPR_PASSES.iter().map(|p| p.name).collect();
        assert_eq!(
            documented_lists(),
            vec![
                ("CHAIN_PASSES".to_owned(), names(&chain)),
                ("TOOL_FIRST_PASSES".to_owned(), names(&tool)),
                ("EXPR_PASSES".to_owned(), names(&expr)),
                (String::new(), Vec::new()),
            ]
        );
    }

    #[test]
    fn pass_names_are_kebab_case_and_no_list_reuses_another_lists_name() {
        let chain: Vec<&str> = CHAIN_PASSES.iter().map(|p| p.name).collect();
        let tool: Vec<&str> = TOOL_FIRST_PASSES.iter().map(|p| p.name).collect();
        let expr: Vec<&str> = EXPR_PASSES.iter().map(|p| p.name).collect();
        for name in chain.iter().chain(&tool).chain(&expr) {
            assert!(!name.is_empty() && name.chars().all(|c| c.is_ascii_lowercase() || c == '-'), "{name}");
        }
        for name in &tool {
            assert!(!chain.contains(name) && !expr.contains(name), "{name}");
        }
        for name in &expr {
            assert!(!chain.contains(name), "{name}");
        }
    }

    /// The whole chain list on a planar 3R arm: the joints' angles add up, the link lengths move
    /// before the total rotation.
    #[test]
    fn chain_passes_on_a_planar_arm() {
        let mut g = ExprGraph::new();
        let steps = parse_steps(&mut g, "Rz(q1) T(1, 0, 0) Rz(q2) T(1, 0, 0) Rz(q3) T(0.5, 0, 0)");
        let steps = simplify(&mut g, steps);
        assert_eq!(
            steps_text(&g, &steps),
            "T(cos(q1) + cos(q1 + q2), sin(q1) + sin(q1 + q2), 0) Rz(q1 + q2 + q3) T(0.5, 0, 0)"
        );
    }

    /// The whole chain list on the first three rows of the UR5's DH table: the exact twist becomes a
    /// permutation at the end (turning the shoulder and elbow axes to `-y`, then `y`), and the
    /// parallel shoulder and elbow become one rotation by `-q2 - q3`, the upper arm's length moving
    /// before it and adding to the shoulder's height.
    #[test]
    fn chain_passes_on_dh_rows_with_exact_twists() {
        let mut g = ExprGraph::new();
        let steps =
            parse_steps(&mut g, "Rz(q1) T(0, 0, 0.089159) Rx(pi/2) Rz(q2) T(-0.425, 0, 0) Rz(q3) T(-0.39225, 0, 0)");
        let steps = simplify(&mut g, steps);
        assert_eq!(
            steps_text(&g, &steps),
            "Rz(q1) T(-0.425*cos(q2), 0, 0.089159 - 0.425*sin(q2)) Ry(-q2 - q3) T(-0.39225, 0, 0) P(x, -z, y)"
        );
    }
}
