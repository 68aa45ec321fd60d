//! What to compile (base, tips, outputs) and the compiled result.
//!
//! `Request` is what to compile: base, tips, positions only, and a `Velocity` (Jacobian or twist,
//! frame, with or without the pose). Compiling searches fold orders and simplifier options for the
//! cheapest code; a velocity's entries are outputs too and go through the expression passes with
//! the poses, so both use the same sines and cosines. A pose whose constants compose into infinity
//! or NaN is a `CompileError` naming the link. For several poses it also builds each on an
//! ancestor's pose already built (`extend_tips`, up to three joints up, the cheapest by what the
//! pose adds to those before it), so a tree's links share their parents' work. `Compiled::points`
//! builds points of links (the collision spheres' centres) in the same graph.

use std::collections::BTreeSet;

use kinematics_model::{JacobianFrame, KinematicTree, LinkId};

use crate::error::CompileError;
use crate::simplify::{
    DERIVATION_COST, EXPR_PASSES, Options, TOOL_FIRST_PASSES, angle_terms, run_chain_passes, run_expr_passes,
    simplify_with, split_tail,
};
use crate::stats::{OpCount, Reached, SIN_COS_WEIGHT};
use crate::symbolic::differential::{Column, Differential};
use crate::symbolic::graph::{ExprGraph, ExprId};
use crate::symbolic::lower::lower_path;
use crate::symbolic::step::{Step, invert};
use crate::symbolic::transform::{SymTransform, fold_from_base, fold_from_tool};

/// Which poses to compile.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Request {
    /// The frame poses are expressed in (default: the root link).
    pub base: Option<String>,
    /// The links whose poses are wanted; empty means every link but the base.
    pub tips: Vec<String>,
    /// Compute positions only (no rotations); with `velocity`, the linear rows only.
    pub position_only: bool,
    /// Velocities of the tips (a Jacobian or a twist), beside or instead of their poses.
    pub velocity: Option<Velocity>,
}

/// Which velocity of the tips to compute.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Velocity {
    /// The axes the velocities are written in.
    pub frame: JacobianFrame,
    /// The geometric Jacobian, or the twist `J * qdot`.
    pub form: VelocityForm,
    /// Whether the poses are outputs too (the Jacobian then shares their work).
    pub with_pose: bool,
}

/// The geometric Jacobian, or the twist it maps joint rates to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum VelocityForm {
    /// The 6 x dof geometric Jacobian (3 x dof of linear rows for positions only), rows linear
    /// then angular, one column per degree of freedom in `q` order.
    #[default]
    Jacobian,
    /// The twist `J * qdot` (linear velocity, then angular velocity), built without forming `J`;
    /// the joint rates are inputs beside the positions.
    Twist,
}

impl Request {
    /// The pose of one link in the root frame.
    pub fn tip(link: &str) -> Self {
        Self { tips: vec![link.to_owned()], ..Self::default() }
    }

    /// The poses of every link in the root frame.
    pub fn all_links() -> Self {
        Self::default()
    }

    /// Poses relative to `base` instead of the root.
    pub fn with_base(mut self, base: &str) -> Self {
        self.base = Some(base.to_owned());
        self
    }

    /// Positions only.
    pub fn positions_only(mut self) -> Self {
        self.position_only = true;
        self
    }

    /// The geometric Jacobian in `frame` instead of the pose.
    pub fn jacobian(mut self, frame: JacobianFrame) -> Self {
        self.velocity = Some(Velocity { frame, form: VelocityForm::Jacobian, with_pose: false });
        self
    }

    /// The pose and the geometric Jacobian in `frame`.
    pub fn pose_and_jacobian(mut self, frame: JacobianFrame) -> Self {
        self.velocity = Some(Velocity { frame, form: VelocityForm::Jacobian, with_pose: true });
        self
    }

    /// The twist `J * qdot` in `frame` instead of the pose.
    pub fn twist(mut self, frame: JacobianFrame) -> Self {
        self.velocity = Some(Velocity { frame, form: VelocityForm::Twist, with_pose: false });
        self
    }

    /// Whether the poses (or positions) are outputs.
    pub fn has_pose(&self) -> bool {
        self.velocity.is_none_or(|v| v.with_pose)
    }
}

/// One compiled frame: a link's pose in the base frame (any link: when the base is not an ancestor
/// of the tip, the path goes up to their common ancestor and down again).
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    /// The link.
    pub link: String,
    /// Its pose as expressions in the graph (computed whether or not it is an output: the
    /// velocities are computed from it).
    pub transform: SymTransform,
    /// Its velocity, when one was asked for.
    pub velocity: Option<FrameVelocity>,
}

/// A frame's velocity as expressions in the graph, in the frame the request named.
#[derive(Debug, Clone, PartialEq)]
pub enum FrameVelocity {
    /// The geometric Jacobian: one column (linear, then angular) per degree of freedom.
    Jacobian(Vec<Column>),
    /// The twist `J * qdot` (linear, then angular), the joint rates being the graph's variables
    /// after the positions.
    Twist(Column),
}

impl FrameVelocity {
    /// The entries, row-major: the Jacobian's rows (all six, or the three linear ones) each over
    /// the columns, or the twist's entries.
    pub fn entries(&self, linear_only: bool) -> Vec<ExprId> {
        let rows = if linear_only { 3 } else { 6 };
        match self {
            FrameVelocity::Jacobian(columns) => {
                (0..rows).flat_map(|r| columns.iter().map(move |column| column[r])).collect()
            }
            FrameVelocity::Twist(twist) => twist[..rows].to_vec(),
        }
    }

    /// Every entry, column by column (the order of [`FrameVelocity::entries_mut`]).
    fn flat(&self) -> Vec<ExprId> {
        match self {
            FrameVelocity::Jacobian(columns) => columns.iter().flatten().copied().collect(),
            FrameVelocity::Twist(twist) => twist.to_vec(),
        }
    }

    fn entries_mut(&mut self) -> Vec<&mut ExprId> {
        match self {
            FrameVelocity::Jacobian(columns) => columns.iter_mut().flat_map(|c| c.iter_mut()).collect(),
            FrameVelocity::Twist(twist) => twist.iter_mut().collect(),
        }
    }
}

/// The result of [`compile`]: the expression graph and the frames computed from it.
#[derive(Debug, Clone)]
pub struct Compiled {
    /// Robot name.
    pub robot: String,
    /// The base link.
    pub base: String,
    /// Joint names in degree-of-freedom order (the entries of `q`).
    pub dof_names: Vec<String>,
    /// Velocity names (a Jacobian's columns, the entries of `qd`) in order.
    pub velocity_names: Vec<String>,
    /// Where each floating or spherical joint's quaternion starts in `q`, in tree order
    /// ([`KinematicTree::quaternion_entries`]): the generated code turns each into its rotation's
    /// nine variables (after `q` and `qd`) first.
    pub quaternions: Vec<usize>,
    /// Whether only positions are outputs (and, with a velocity, its linear rows).
    pub position_only: bool,
    /// The velocity computed, if any.
    pub velocity: Option<Velocity>,
    /// Whether the emitted function returns an array of frames however many there are: every link
    /// but the base was asked for, or a list of links ([`Compiled::into_link_list`]).
    pub(crate) all_links: bool,
    pub(crate) graph: ExprGraph,
    pub(crate) frames: Vec<Frame>,
}

/// The most tips [`compile`] folds each from the base on its own (see there); every robot in
/// `robots/` has fewer links.
const FOLD_EACH_TIP_UP_TO: usize = 256;

/// Compiles the poses `request` asks for.
///
/// One tip is accumulated both from the tool back to the base and from the base out (tool-to-base
/// usually wins: the rotations it multiplies first are sparse); several tips are accumulated from
/// the base outwards, so links share their common partial products. Each is tried with every
/// [`Options`] of the simplifier, and the cheapest by [`OpCount::weighted`] is kept. Several tips
/// without velocities are also built each on its nearest ancestor's pose, and past 256 tips only
/// so: folding each from the base costs the square of a long chain's length.
pub fn compile(tree: &KinematicTree, request: &Request) -> Result<Compiled, CompileError> {
    let error = |source| CompileError::Model { robot: tree.name().to_owned(), source };
    let base_name = request.base.clone().unwrap_or_else(|| tree.link(tree.root()).name.clone());
    let base =
        tree.link_id(&base_name).ok_or_else(|| error(kinematics_model::ModelError::NoSuchLink(base_name.clone())))?;
    let tips: Vec<String> = if request.tips.is_empty() {
        tree.links().iter().filter(|l| l.name != base_name).map(|l| l.name.clone()).collect()
    } else {
        request.tips.clone()
    };
    let tip_ids = tips
        .iter()
        .map(|tip| tree.link_id(tip).ok_or_else(|| error(kinematics_model::ModelError::NoSuchLink(tip.clone()))))
        .collect::<Result<Vec<_>, _>>()?;
    // One pose may be accumulated from the tool back or from the base out; several share their
    // prefixes from the base out. Every simplifier option is tried and the cheapest code kept (the
    // first of equals, so the choice is deterministic).
    let orders: &[Order] = if tip_ids.len() == 1 { &[Order::FromTool, Order::FromBase] } else { &[Order::FromBase] };
    let cost = |(g, frames): &(ExprGraph, Vec<Frame>)| {
        let outputs = frames.iter().flat_map(|f| frame_outputs(f, request.position_only, request.has_pose()));
        OpCount::of(g, outputs).weighted()
    };
    let mut best: Option<(usize, (ExprGraph, Vec<Frame>))> = None;
    let mut consider = |candidate: (ExprGraph, Vec<Frame>)| {
        let cost = cost(&candidate);

        if best.as_ref().is_none_or(|(c, _)| cost < *c) {
            best = Some((cost, candidate));
        }
    };
    let name_frames = |(graph, poses): (ExprGraph, Vec<(SymTransform, Option<FrameVelocity>)>)| {
        let frames = tips
            .iter()
            .zip(poses)
            .map(|(link, (transform, velocity))| Frame { link: link.clone(), transform, velocity })
            .collect();
        (graph, frames)
    };
    // Folding each tip from the base on its own costs its depth, so a long chain's every link costs
    // the square of its length (measured: 2,000 links 36 s, 5,000 over five minutes in `check`);
    // past FOLD_EACH_TIP_UP_TO tips without velocities only the build on each ancestor's pose
    // below is tried, which is linear.
    if tip_ids.len() <= FOLD_EACH_TIP_UP_TO || request.velocity.is_some() {
        for &order in orders {
            for options in Options::ALL {
                consider(name_frames(fold_tips(tree, base, &tip_ids, order, options, request)));
            }
        }
    }
    // Building on an ancestor's pose leaves out the joints above it, which a velocity needs.
    if tip_ids.len() > 1 && request.velocity.is_none() {
        let (graph, poses) = extend_tips(tree, base, &tip_ids, request.position_only);
        consider(name_frames((graph, poses.into_iter().map(|t| (t, None)).collect())));
    }
    #[allow(clippy::expect_used, reason = "an invariant of the search, named in the message")]
    let (_, (graph, frames)) = best.expect("the search tries at least one fold order with at least one option");
    check_finite(tree, &graph, &frames, request)?;
    Ok(Compiled {
        robot: tree.name().to_owned(),
        base: base_name,
        dof_names: tree.dof_names(),
        velocity_names: tree.velocity_names(),
        quaternions: tree.quaternion_entries(),
        position_only: request.position_only,
        velocity: request.velocity,
        all_links: request.tips.is_empty(),
        graph,
        frames,
    })
}

/// A frame's outputs: its pose (12 entries, or the 3 of its translation) when the pose is an
/// output, then its velocity's entries ([`FrameVelocity::entries`]).
fn frame_outputs(frame: &Frame, position_only: bool, with_pose: bool) -> Vec<ExprId> {
    let t = &frame.transform;
    let mut outputs = match (with_pose, position_only) {
        (false, _) => Vec::new(),
        (true, true) => t.p.to_vec(),
        (true, false) => t.entries().to_vec(),
    };
    if let Some(velocity) = &frame.velocity {
        outputs.extend(velocity.entries(position_only));
    }
    outputs
}

/// Evaluates a compiled robot's poses at one configuration after another ([`Compiled::evaluator`]).
pub struct FrameEvaluator<'a> {
    compiled: &'a Compiled,
    /// The nodes the poses need, each after its operands.
    order: Vec<ExprId>,
    /// One slot per node of the graph.
    values: Vec<f64>,
}

impl FrameEvaluator<'_> {
    /// Every frame's 12 pose entries at `q` (as [`Compiled::eval`]).
    ///
    /// # Panics
    ///
    /// If `q` is shorter than the robot's degrees of freedom (a caller's bug).
    pub fn eval(&mut self, q: &[f64]) -> Vec<[f64; 12]> {
        let q = self.compiled.variables(q);
        self.compiled.graph.eval_in_order(&self.order, &q, &[], &mut self.values);
        self.compiled.frames.iter().map(|f| f.transform.entries().map(|id| self.values[id.index()])).collect()
    }
}

/// Every constant a frame's pose is computed from is a finite number, or the error naming the first
/// frame with one that is not. The model keeps every number of a description finite, but finite
/// numbers can compose into infinity (`1e308 + 1e308`); emitted code would compute with it, and
/// `proc_macro2` cannot even write it as a literal.
fn check_finite(
    tree: &KinematicTree,
    graph: &ExprGraph,
    frames: &[Frame],
    request: &Request,
) -> Result<(), CompileError> {
    // One walk over the graph for all frames, in their order: a node an earlier frame reached was
    // checked there, so each frame walks only what it adds, and the first frame to reach a
    // constant is the one named (a walk per frame made a long chain's check quadratic).
    let mut seen = vec![false; graph.len()];
    for frame in frames {
        let outputs = frame_outputs(frame, request.position_only, request.has_pose());
        let mut stack: Vec<ExprId> = outputs.into_iter().chain(frame.transform.entries()).collect();
        while let Some(id) = stack.pop() {
            if std::mem::replace(&mut seen[id.index()], true) {
                continue;
            }
            if let Some(value) = graph.as_const(id).filter(|value| !value.is_finite()) {
                return Err(CompileError::NonFiniteConstant {
                    robot: tree.name().to_owned(),
                    link: frame.link.clone(),
                    value,
                });
            }
            stack.extend(graph.node(id).operands());
        }
    }
    Ok(())
}

/// What the pose of `tip` in `base` costs as a plain sequential product of its transforms (zeros
/// and ones folded, nothing else): the baseline the compiler's simplifications are measured against.
pub fn plain_product_count(tree: &KinematicTree, base: &str, tip: &str) -> Result<OpCount, CompileError> {
    let error = |source| CompileError::Model { robot: tree.name().to_owned(), source };
    let link =
        |name: &str| tree.link_id(name).ok_or_else(|| error(kinematics_model::ModelError::NoSuchLink(name.to_owned())));
    let mut g = ExprGraph::new();
    let steps = path_steps(&mut g, tree, link(base)?, link(tip)?);
    let identity = SymTransform::identity(&mut g);
    let t = fold_from_base(&mut g, identity, &steps);
    Ok(OpCount::of(&g, t.entries()))
}

/// Which way a pose is accumulated.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Order {
    /// From the tool back to the base (`A1 (A2 (A3 ...))`), trailing translations added last.
    FromTool,
    /// From the base out (`((A1 A2) A3) ...`): frames share their common prefixes.
    FromBase,
}

/// Lowers, simplifies and folds the pose of every tip in one graph, and the velocity the request
/// asks for: always from the base out over the same simplified steps (each joint's axis and
/// origin are the partial products), to the tip's origin as the pose computes it.
fn fold_tips(
    tree: &KinematicTree,
    base: LinkId,
    tips: &[LinkId],
    order: Order,
    options: Options,
    request: &Request,
) -> (ExprGraph, Vec<(SymTransform, Option<FrameVelocity>)>) {
    let mut graph = ExprGraph::new();
    let g = &mut graph;
    let mut frames = Vec::with_capacity(tips.len());
    let mut velocities = Vec::with_capacity(tips.len());
    let dof = tree.dof();
    let columns = tree.velocity_of_entry();
    let columns_count = tree.velocity_dof();
    for &tip in tips {
        let steps = path_steps(g, tree, base, tip);
        let steps = simplify_with(g, steps, options);
        let identity = SymTransform::identity(g);
        // Base axes: fold the chain from the base out. The tip's axes: fold the inverted chain
        // from the tip, so each joint's axis and origin come out in the tip's axes.
        let differential = request.velocity.map(|velocity| match velocity.frame {
            JacobianFrame::LocalWorldAligned => Differential::fold(g, identity, &steps, &columns),
            JacobianFrame::Local => {
                let inverted = invert(g, &steps);
                Differential::fold(g, identity, &inverted, &columns)
            }
        });
        let transform = match (order, &differential) {
            (Order::FromBase, Some(differential))
                if request.velocity.is_some_and(|v| v.frame == JacobianFrame::LocalWorldAligned) =>
            {
                differential.pose
            }
            (Order::FromBase, _) => fold_from_base(g, identity, &steps),
            (Order::FromTool, _) => {
                let steps = run_chain_passes(g, steps, TOOL_FIRST_PASSES, options);
                let (main, tail) = split_tail(&steps);
                let main = fold_from_tool(g, main);
                fold_from_base(g, main, tail)
            }
        };
        let velocity =
            request.velocity.zip(differential).map(|(velocity, differential)| match (velocity.form, velocity.frame) {
                (VelocityForm::Jacobian, JacobianFrame::LocalWorldAligned) => {
                    FrameVelocity::Jacobian(differential.jacobian(g, transform.p, columns_count))
                }
                (VelocityForm::Jacobian, JacobianFrame::Local) => {
                    FrameVelocity::Jacobian(differential.local_jacobian(g, columns_count))
                }
                (VelocityForm::Twist, JacobianFrame::LocalWorldAligned) => {
                    FrameVelocity::Twist(differential.twist(g, transform.p, dof))
                }
                (VelocityForm::Twist, JacobianFrame::Local) => FrameVelocity::Twist(differential.local_twist(g, dof)),
            });
        frames.push(transform);
        velocities.push(velocity);
    }
    // The velocities' entries go through the expression passes with the poses, so both use the
    // same rewritten sines and cosines.
    let mut extra: Vec<ExprId> = velocities.iter().flatten().flat_map(FrameVelocity::flat).collect();
    // A rotation column as a cross product, shared factors out of sums.
    run_expr_passes(g, &mut frames, &mut extra, EXPR_PASSES, request.position_only || !request.has_pose());
    let mut rewritten = extra.into_iter();
    for velocity in velocities.iter_mut().flatten() {
        for entry in velocity.entries_mut() {
            #[allow(clippy::expect_used, reason = "an invariant: the passes return as many outputs as they get")]
            {
                *entry = rewritten.next().expect("one rewritten entry per velocity entry");
            }
        }
    }
    (graph, frames.into_iter().zip(velocities).collect())
}

/// How many joints up from a tip [`extend_tips`] looks for an ancestor whose pose to extend.
/// Bounded, so that the search stays linear in the number of links; beyond a few joints the pose
/// from the base is the other candidate.
const EXTEND_REACH: usize = 3;

/// Builds the pose of every tip, in order, as the cheapest of: its path from the base simplified
/// and folded on its own, or the pose of an ancestor already built (up to [`EXTEND_REACH`] joints
/// up) times the simplified steps from that ancestor, each with every [`Options`]. Cheapest means
/// what the pose adds to the poses before it ([`Reached::cost_of`]), so a link extends its
/// parent's pose where recomputing its path from the base would repeat work the parent already
/// did (a constant rotation on a finger's base multiplied again for every finger link), and
/// keeps its own path where that shares more (an angle sum such as `q2 + q3`).
fn extend_tips(
    tree: &KinematicTree,
    base: LinkId,
    tips: &[LinkId],
    position_only: bool,
) -> (ExprGraph, Vec<SymTransform>) {
    let mut graph = ExprGraph::new();
    let mut built: Vec<Option<SymTransform>> = vec![None; tree.links().len()];
    let mut reached = Reached::new();
    // The joint terms of the angles computed so far.
    let mut known_terms: BTreeSet<Vec<(u32, u64)>> = BTreeSet::new();
    let mut frames = Vec::with_capacity(tips.len());
    let outputs = |t: &SymTransform| if position_only { t.p.to_vec() } else { t.entries().to_vec() };
    for &tip in tips {
        // The starting poses: the base (identity, the whole path), then each built ancestor within
        // reach, with the joints from it down to the tip.
        let mut starts: Vec<(Option<LinkId>, Vec<kinematics_model::JointId>)> = vec![(None, Vec::new())];
        let mut joints = Vec::new();
        let mut at = tip;
        while joints.len() < EXTEND_REACH
            && at != base
            && let Some(joint) = tree.link(at).parent_joint
        {
            joints.insert(0, joint);
            at = tree.joint(joint).parent;
            if built[at.0].is_some() {
                starts.push((Some(at), joints.clone()));
            }
        }
        // Past FOLD_EACH_TIP_UP_TO tips, the whole path from the base only where no ancestor
        // was built (as in `compile`: each tip's whole path makes a long chain quadratic).
        if tips.len() > FOLD_EACH_TIP_UP_TO && starts.len() > 1 {
            starts.remove(0);
        }
        let mut best: Option<(usize, SymTransform)> = None;
        for (start, joints) in &starts {
            for options in Options::ALL {
                let (origin, steps) = match start {
                    None => (SymTransform::identity(&mut graph), path_steps(&mut graph, tree, base, tip)),
                    Some(link) => (
                        built[link.0].unwrap_or_else(|| SymTransform::identity(&mut graph)),
                        lower_path(&mut graph, tree, joints),
                    ),
                };
                let steps = simplify_with(&mut graph, steps, options);
                let pose = fold_from_base(&mut graph, origin, &steps);
                let (count, angles) = reached.cost_of(&graph, outputs(&pose));
                // A new angle whose joint terms an angle already computed has (`m*q - m` beside
                // `m*q`) comes from it by `derived-angles`, for a few multiplications.
                // The terms this candidate's own angles add, beside those already known (a set
                // of its own rather than a copy of the known ones: that copy made a long chain
                // quadratic).
                let mut added = BTreeSet::new();
                let angle_cost: usize = angles
                    .iter()
                    .map(|&a| {
                        let derivable = angle_terms(&graph, a)
                            .is_some_and(|terms| known_terms.contains(&terms) || !added.insert(terms));
                        if derivable { DERIVATION_COST } else { SIN_COS_WEIGHT }
                    })
                    .sum();
                let cost = count.mul + count.add + angle_cost;
                if best.as_ref().is_none_or(|(c, _)| cost < *c) {
                    best = Some((cost, pose));
                }
            }
        }
        let pose = best.map_or_else(|| SymTransform::identity(&mut graph), |(_, pose)| pose);
        let (_, new_angles) = reached.add_angles(&graph, outputs(&pose));
        known_terms.extend(new_angles.into_iter().filter_map(|a| angle_terms(&graph, a)));
        built[tip.0] = Some(pose);
        frames.push(pose);
    }
    run_expr_passes(&mut graph, &mut frames, &mut [], EXPR_PASSES, position_only);
    (graph, frames)
}

/// The steps of `T_base^tip`: up from `base` to the nearest common ancestor (inverted), then down
/// to `tip`. When `base` is an ancestor of `tip`, only the downward part remains.
fn path_steps(g: &mut ExprGraph, tree: &KinematicTree, base: LinkId, tip: LinkId) -> Vec<Step> {
    let to_base = tree.path_from_root(base);
    let to_tip = tree.path_from_root(tip);
    let common = to_base.iter().zip(&to_tip).take_while(|(a, b)| a == b).count();
    let up = lower_path(g, tree, &to_base[common..]);
    let mut steps = invert(g, &up);
    steps.extend(lower_path(g, tree, &to_tip[common..]));
    steps
}

impl Compiled {
    /// The expression graph.
    pub fn graph(&self) -> &ExprGraph {
        &self.graph
    }

    /// The compiled frames, in request order.
    pub fn frames(&self) -> &[Frame] {
        &self.frames
    }

    /// Whether the emitted function returns an array of frames (every link was asked for, a list
    /// of links, or several tips) rather than one frame (one tip). An all-links request returns an
    /// array even when the robot has one link below the base, or none.
    pub fn returns_array(&self) -> bool {
        self.all_links || self.frames.len() != 1
    }

    /// The same frames as a list of links (`link_poses` of a `links = [...]` subset): an array
    /// even when the list has one link, as `link_poses` always returns.
    pub(crate) fn into_link_list(mut self) -> Self {
        self.all_links = true;
        self
    }

    /// Number of degrees of freedom.
    pub fn dof(&self) -> usize {
        self.dof_names.len()
    }

    /// Number of velocities: a Jacobian's columns, the length of `qd`.
    pub fn velocity_dof(&self) -> usize {
        self.velocity_names.len()
    }

    /// Every variable of the graph from the joint positions and, when given, the rates after them:
    /// `q`, `qd` (zeros when not given), and each floating or spherical joint's rotation (its
    /// quaternion normalised, row-major), as the generated code computes them.
    ///
    /// # Panics
    ///
    /// If `values` has fewer than [`Compiled::dof`] values.
    pub fn variables(&self, values: &[f64]) -> Vec<f64> {
        variables(self.dof(), self.velocity_dof(), &self.quaternions, values)
    }

    /// Whether the poses (or positions) are outputs.
    pub fn has_pose(&self) -> bool {
        self.velocity.is_none_or(|v| v.with_pose)
    }

    /// The output expressions of a frame: 12 for a pose (rotation row-major, then translation),
    /// or the 3 of the translation for positions only, when the pose is an output; then the
    /// velocity's entries, if one was asked for ([`FrameVelocity::entries`]: a Jacobian row by
    /// row, six rows or the three linear ones).
    pub fn frame_outputs(&self, index: usize) -> Vec<ExprId> {
        frame_outputs(&self.frames[index], self.position_only, self.has_pose())
    }

    /// Evaluates every frame's outputs ([`Compiled::frame_outputs`]) with the simplified graph:
    /// `q` holds the joint positions, then (for a twist) the joint rates.
    ///
    /// # Panics
    ///
    /// If `q` has fewer values than the outputs need.
    pub fn eval_outputs(&self, q: &[f64]) -> Vec<Vec<f64>> {
        let q = &self.variables(q);
        let mut values = Vec::new();
        (0..self.frames.len())
            .map(|i| self.frame_outputs(i).into_iter().map(|id| self.graph.eval(id, q, &mut values)).collect())
            .collect()
    }

    /// Every output expression, frame by frame.
    pub fn outputs(&self) -> Vec<ExprId> {
        (0..self.frames.len()).flat_map(|i| self.frame_outputs(i)).collect()
    }

    /// Points fixed in the links of the frames, in the base frame: for each `(frame, p)`, the
    /// expressions of `R p + t` with that frame's rotation `R` and translation `t`, built in the
    /// graph (constants fold, so a zero coordinate of `p` needs no column of `R`).
    pub fn points(&mut self, points: &[(usize, [f64; 3])]) -> Vec<[ExprId; 3]> {
        points
            .iter()
            .map(|&(frame, p)| {
                let t = self.frames[frame].transform;
                [0, 1, 2].map(|i| {
                    let mut sum = t.p[i];
                    for (k, &coordinate) in p.iter().enumerate() {
                        let c = self.graph.constant(coordinate);
                        let term = self.graph.mul(t.r[i][k], c);
                        sum = self.graph.add(sum, term);
                    }
                    sum
                })
            })
            .collect()
    }

    /// Operation counts of everything computed.
    pub fn op_count(&self) -> OpCount {
        OpCount::of(&self.graph, self.outputs())
    }

    /// What each frame adds to the frames before it, in frame order: the multiplications, additions
    /// and `sin_cos` pairs its outputs need that no earlier frame's outputs already computed (see
    /// [`crate::stats::marginal_counts`]). They add up to [`Compiled::op_count`].
    pub fn marginal_op_counts(&self) -> Vec<OpCount> {
        crate::stats::marginal_counts(&self.graph, (0..self.frames.len()).map(|i| self.frame_outputs(i)))
    }

    /// Operation counts of one frame alone.
    pub fn frame_op_count(&self, index: usize) -> OpCount {
        OpCount::of(&self.graph, self.frame_outputs(index))
    }

    /// Evaluates every frame at `q` with the simplified graph (no Rust compiled): per frame, the
    /// 12 pose entries (rotation row-major, translation), whatever `position_only` says.
    ///
    /// # Panics
    ///
    /// If `q` has fewer than [`Compiled::dof`] values.
    pub fn eval(&self, q: &[f64]) -> Vec<[f64; 12]> {
        self.evaluator().eval(q)
    }

    /// An evaluator of every frame's pose, for many configurations: the nodes the poses need
    /// listed once, then each [`FrameEvaluator::eval`] one pass over them (`kinematics check`
    /// evaluates a 5,000-link chain's poses at thousands of configurations).
    pub fn evaluator(&self) -> FrameEvaluator<'_> {
        let order = crate::stats::reachable(&self.graph, self.frames.iter().flat_map(|f| f.transform.entries()));
        FrameEvaluator { compiled: self, order, values: vec![0.0; self.graph.len()] }
    }

    /// The 12 pose entries of frame `index` as text (`c1 + c12`), rotation row-major then translation.
    ///
    /// Each entry is written out in full, so shared subexpressions are repeated: the text of a long
    /// chain grows exponentially with its length. For large robots use [`crate::emit::text_listing`],
    /// which prints shared subexpressions once as temporaries (what `kinematics expr` prints).
    pub fn frame_text(&self, index: usize) -> Vec<String> {
        let names = crate::emit::Names::new(&self.graph, &self.outputs()).with_sizes(self.dof(), self.velocity_dof());
        self.frames[index].transform.entries().iter().map(|&id| crate::emit::text(&self.graph, &names, id)).collect()
    }

    /// The 12 pose entries of frame `index` as LaTeX, written out in full as [`Compiled::frame_text`]
    /// (see its cost; [`crate::emit::latex_listing`] is linear).
    pub fn frame_latex(&self, index: usize) -> Vec<String> {
        let names = crate::emit::Names::new(&self.graph, &self.outputs()).with_sizes(self.dof(), self.velocity_dof());
        self.frames[index].transform.entries().iter().map(|&id| crate::emit::latex(&self.graph, &names, id)).collect()
    }
}

/// Every variable of a graph from the joint positions (`n` of them) and, when given, the `nv`
/// rates after them: `q`, `qd` (zeros when not given), and each floating or spherical joint's
/// rotation (its quaternion, starting at each of `quaternions`, normalised, row-major), as the
/// generated code computes them.
///
/// # Panics
///
/// If `values` has fewer than `n` values.
pub(crate) fn variables(n: usize, nv: usize, quaternions: &[usize], values: &[f64]) -> Vec<f64> {
    let mut vars: Vec<f64> = values[..n].to_vec();
    vars.extend((0..nv).map(|i| values.get(n + i).copied().unwrap_or(0.0)));
    for &start in quaternions {
        let [x, y, z, w] = [values[start], values[start + 1], values[start + 2], values[start + 3]];
        let s = 2.0 / (x * x + y * y + z * z + w * w);
        vars.extend([
            1.0 - s * (y * y + z * z),
            s * (x * y - z * w),
            s * (x * z + y * w),
            s * (x * y + z * w),
            1.0 - s * (x * x + z * z),
            s * (y * z - x * w),
            s * (x * z - y * w),
            s * (y * z + x * w),
            1.0 - s * (x * x + y * y),
        ]);
    }
    vars
}
