//! A closed form as straight-line code: the family's subproblems composed over the expression
//! graph ([`IkBody`]), with the chain's geometry as constants that fold as the expressions are
//! built, every shared subexpression once, and one branch of the solution per evaluation, picked
//! by three signs that are inputs of the body. Emitted as a function generic over
//! `kinematics_core::ik::IkReal` and called with `F64x8` and `BRANCH_SIGNS_8`, the body computes
//! the eight branches side by side, one per SIMD lane, with no branch in the code: where an
//! equation has no real solution in a lane, selects take its least-squares answer there and flag
//! it.
//!
//! The families whose every step has at most two roots are built here (each family's entry in
//! `ik::families` holds its branch): the UR family, and the spherical wrist with axes 2, 3
//! parallel, axes 1, 2 or axes 2, 3 meeting, or a prismatic third joint. The general spherical wrist and the three-parallel arm, whose first step is a quartic
//! (its real roots found by an iteration), the planar arms and the six of a seven-joint arm (its
//! geometry turned by the free joint at run time) keep the run time's family functions.
//!
//! The families and their subproblems are written once, in `kinematics_core::ik::branch`, over an
//! algebra; `algebra` makes the expression graph one (the run time's numbers are the other). Steps
//! carry labels, for `expr --ik`'s per-subproblem counts.

mod algebra;

pub(crate) use algebra::Builder;

use kinematics_core::Pose;
use kinematics_core::ik::branch::{Algebra, Problem};

use super::classify::{IkGeometry, IkPlan};
use super::families::SixFamily;
use crate::stats::{OpCount, marginal_counts};
use crate::symbolic::graph::{ExprGraph, ExprId};

/// The body's inputs, in order: the target's rotation row-major (`0..9`), its translation
/// (`9..12`), the three branch signs (`12..15`).
pub const INPUTS: usize = 15;

/// The index of the first branch sign among the inputs.
pub const FIRST_SIGN: usize = 12;

/// One branch of a closed form evaluated ([`IkBody::eval`]).
#[derive(Debug, Clone, PartialEq)]
pub struct BranchValue {
    /// The joint values.
    pub q: Vec<f64>,
    /// Their cosines, as the solver computed them.
    pub cos: Vec<f64>,
    /// Their sines.
    pub sin: Vec<f64>,
    /// Every equation had a real solution.
    pub exact: bool,
    /// Some joint was free.
    pub singular: bool,
}

/// One branch of a closed form, as expressions of the target and the branch signs.
#[derive(Debug, Clone)]
pub struct IkBody {
    graph: ExprGraph,
    /// The joint values, in the order of `q` (revolute angles in `(-pi, pi]`).
    q: Vec<ExprId>,
    /// Each joint's cosine and sine (`1` and `0` for a prismatic joint).
    cos: Vec<ExprId>,
    sin: Vec<ExprId>,
    /// `1` where every equation of the branch had a real solution, else `0`.
    exact: ExprId,
    /// `1` where some joint was free (a singularity), else `0`.
    singular: ExprId,
    /// The subproblems in order, with the nodes each produced.
    steps: Vec<(String, Vec<ExprId>)>,
}

impl IkBody {
    /// The body of `plan`'s family, or `None` where the family keeps the run time's solver (see
    /// the module doc).
    pub fn of(plan: &IkPlan) -> Option<IkBody> {
        Self::build(plan, true)
    }

    /// The body without its pass at the wrist's singularity (the UR family's: where `q6 = 0`
    /// leaves the elbow out of reach, the sum of the parallel joints moves), or `None` where the
    /// family has no such pass or keeps the run time's solver. It is [`IkBody::of`] on every
    /// branch but those at that singularity whose elbow misses, which it returns singular and not
    /// exact: the generated `tip_ik` runs it, and the full body only when a lane comes back so
    /// (the pass costs about a third of the body, for targets a random pose almost never is).
    pub fn regular(plan: &IkPlan) -> Option<IkBody> {
        if plan.family() != SixFamily::ThreeParallelTwoIntersecting.into() {
            return None;
        }
        Self::build(plan, false)
    }

    fn build(plan: &IkPlan, singular_pass: bool) -> Option<IkBody> {
        let IkGeometry::Six { family, arm: six, free: None } = &plan.geometry else { return None };
        let compose = family.facts().branch?;
        let mut b = Builder::default();
        let inputs: Vec<ExprId> = (0..INPUTS).map(|i| b.g.input(i)).collect();
        let rotation = [0, 1, 2].map(|i| [0, 1, 2].map(|j| inputs[3 * i + j]));
        let translation = [inputs[9], inputs[10], inputs[11]];
        let signs = [inputs[FIRST_SIGN], inputs[FIRST_SIGN + 1], inputs[FIRST_SIGN + 2]];
        let arm = six.arm();
        let problem = Problem { arm: &arm, rotation, translation, signs, singular_pass };
        let branch = compose(&mut b, &problem);
        let (q, cos, sin) = (branch.q.to_vec(), branch.cos.to_vec(), branch.sin.to_vec());
        b.step(
            "the joint values, wrapped into (-pi, pi], and the flags",
            q.iter().copied().chain(branch.quality.nodes()),
        );
        Some(IkBody {
            graph: b.g,
            q,
            cos,
            sin,
            exact: branch.quality.exact,
            singular: branch.quality.singular,
            steps: b.steps,
        })
    }

    /// The graph.
    pub fn graph(&self) -> &ExprGraph {
        &self.graph
    }

    /// The outputs: the joint values, their cosines, their sines, then the flags `exact` and
    /// `singular`.
    pub fn outputs(&self) -> Vec<ExprId> {
        self.q.iter().chain(&self.cos).chain(&self.sin).copied().chain([self.exact, self.singular]).collect()
    }

    /// How many joint values.
    pub fn dof(&self) -> usize {
        self.q.len()
    }

    /// What one branch costs (every lane of a SIMD type computes one, side by side).
    pub fn op_count(&self) -> OpCount {
        OpCount::of(&self.graph, self.outputs())
    }

    /// What each subproblem adds to those before it, labelled (`kinematics expr --ik`); the
    /// counts add up to [`IkBody::op_count`].
    pub fn step_counts(&self) -> Vec<(String, OpCount)> {
        // A step's node no output needs (the cosine of a last angle) is not emitted: not counted.
        let mut needed = vec![false; self.graph.len()];
        for id in crate::stats::reachable(&self.graph, self.outputs()) {
            needed[id.index()] = true;
        }
        let groups = self.steps.iter().map(|(_, nodes)| nodes.iter().copied().filter(|id| needed[id.index()]));
        let counts = marginal_counts(&self.graph, groups);
        self.steps.iter().map(|(label, _)| label.clone()).zip(counts).collect()
    }

    /// Evaluates branch `index` (`0..8`, the run time's order) for `target`, as the generated
    /// `f64` code would.
    pub fn eval(&self, target: &Pose<f64>, index: usize) -> BranchValue {
        let mut inputs = [0.0; INPUTS];
        inputs[..12].copy_from_slice(&target.entries());
        inputs[FIRST_SIGN..].copy_from_slice(&kinematics_core::ik::branch_signs(index));
        let mut values = Vec::new();
        let mut at = |id: ExprId| self.graph.eval_with_inputs(id, &[], &inputs, &mut values);
        BranchValue {
            q: self.q.iter().map(|&id| at(id)).collect(),
            cos: self.cos.iter().map(|&id| at(id)).collect(),
            sin: self.sin.iter().map(|&id| at(id)).collect(),
            exact: at(self.exact) == 1.0,
            singular: at(self.singular) == 1.0,
        }
    }
}
