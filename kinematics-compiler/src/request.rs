//! What to compile (base, tips, outputs) and the compiled result.

use std::collections::BTreeSet;

use kinematics_model::{KinematicTree, LinkId};

use crate::error::CompileError;
use crate::simplify::{
    DERIVATION_COST, EXPR_PASSES, Options, TOOL_FIRST_PASSES, angle_terms, run_chain_passes, run_expr_passes,
    simplify_with, split_tail,
};
use crate::stats::{OpCount, Reached, SIN_COS_WEIGHT};
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
    /// Compute positions only (no rotations).
    pub position_only: bool,
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
}

/// One compiled frame: a link's pose in the base frame (any link: when the base is not an ancestor
/// of the tip, the path goes up to their common ancestor and down again).
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    /// The link.
    pub link: String,
    /// Its pose as expressions in the graph.
    pub transform: SymTransform,
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
    /// Whether only positions are outputs.
    pub position_only: bool,
    /// Whether every link but the base was asked for (the emitted function then returns an array
    /// of frames, however many links there are).
    pub(crate) all_links: bool,
    pub(crate) graph: ExprGraph,
    pub(crate) frames: Vec<Frame>,
}

/// Compiles the poses `request` asks for.
///
/// One tip is accumulated both from the tool back to the base and from the base out (tool-to-base
/// usually wins: the rotations it multiplies first are sparse); several tips are accumulated from
/// the base outwards, so links share their common partial products. Each is tried with every
/// [`Options`] of the simplifier, and the cheapest by [`OpCount::weighted`] is kept.
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
    let cost = |(g, frames): &(ExprGraph, Vec<SymTransform>)| {
        let outputs =
            frames.iter().flat_map(|t| if request.position_only { t.p.to_vec() } else { t.entries().to_vec() });
        OpCount::of(g, outputs).weighted()
    };
    let mut best: Option<(usize, (ExprGraph, Vec<SymTransform>))> = None;
    let mut consider = |candidate: (ExprGraph, Vec<SymTransform>)| {
        let cost = cost(&candidate);

        if best.as_ref().is_none_or(|(c, _)| cost < *c) {
            best = Some((cost, candidate));
        }
    };
    for &order in orders {
        for options in Options::ALL {
            consider(fold_tips(tree, base, &tip_ids, order, options, request.position_only));
        }
    }
    if tip_ids.len() > 1 {
        consider(extend_tips(tree, base, &tip_ids, request.position_only));
    }
    #[allow(clippy::expect_used, reason = "an invariant of the search, named in the message")]
    let (_, (graph, frames)) = best.expect("the search tries at least one fold order with at least one option");
    let frames: Vec<Frame> =
        tips.iter().zip(frames).map(|(link, transform)| Frame { link: link.clone(), transform }).collect();
    check_finite(tree, &graph, &frames)?;
    Ok(Compiled {
        robot: tree.name().to_owned(),
        base: base_name,
        dof_names: tree.dof_names().into_iter().map(str::to_owned).collect(),
        position_only: request.position_only,
        all_links: request.tips.is_empty(),
        graph,
        frames,
    })
}

/// Every constant a frame's pose is computed from is a finite number, or the error naming the first
/// frame with one that is not. The model keeps every number of a description finite, but finite
/// numbers can compose into infinity (`1e308 + 1e308`); emitted code would compute with it, and
/// `proc_macro2` cannot even write it as a literal.
fn check_finite(tree: &KinematicTree, graph: &ExprGraph, frames: &[Frame]) -> Result<(), CompileError> {
    for frame in frames {
        let non_finite = crate::stats::reachable(graph, frame.transform.entries())
            .into_iter()
            .filter_map(|id| graph.as_const(id))
            .find(|value| !value.is_finite());
        if let Some(value) = non_finite {
            return Err(CompileError::NonFiniteConstant {
                robot: tree.name().to_owned(),
                link: frame.link.clone(),
                value,
            });
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

/// Lowers, simplifies and folds the pose of every tip in one graph.
fn fold_tips(
    tree: &KinematicTree,
    base: LinkId,
    tips: &[LinkId],
    order: Order,
    options: Options,
    position_only: bool,
) -> (ExprGraph, Vec<SymTransform>) {
    let mut graph = ExprGraph::new();
    let mut frames = Vec::with_capacity(tips.len());
    for &tip in tips {
        let steps = path_steps(&mut graph, tree, base, tip);
        let steps = simplify_with(&mut graph, steps, options);
        let transform = match order {
            Order::FromTool => {
                let steps = run_chain_passes(&mut graph, steps, TOOL_FIRST_PASSES, options);
                let (main, tail) = split_tail(&steps);
                let main = fold_from_tool(&mut graph, main);
                fold_from_base(&mut graph, main, tail)
            }
            Order::FromBase => {
                let identity = SymTransform::identity(&mut graph);
                fold_from_base(&mut graph, identity, &steps)
            }
        };
        frames.push(transform);
    }
    // A rotation column as a cross product, shared factors out of sums.
    run_expr_passes(&mut graph, &mut frames, EXPR_PASSES, position_only);
    (graph, frames)
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
                let mut known = known_terms.clone();
                let angle_cost: usize = angles
                    .iter()
                    .map(|&a| {
                        let derivable = angle_terms(&graph, a).is_some_and(|terms| !known.insert(terms));
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
        reached.add(&graph, outputs(&pose));
        known_terms = reached.angles().iter().filter_map(|&a| angle_terms(&graph, a)).collect();
        built[tip.0] = Some(pose);
        frames.push(pose);
    }
    run_expr_passes(&mut graph, &mut frames, EXPR_PASSES, position_only);
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

    /// Whether the emitted function returns an array of frames (every link was asked for, or
    /// several tips) rather than one frame (one tip). An all-links request returns an array even
    /// when the robot has one link below the base, or none.
    pub fn returns_array(&self) -> bool {
        self.all_links || self.frames.len() != 1
    }

    /// Number of degrees of freedom.
    pub fn dof(&self) -> usize {
        self.dof_names.len()
    }

    /// The output expressions of a frame: 12 for a pose (rotation row-major, then translation),
    /// or the 3 of the translation for positions only.
    pub fn frame_outputs(&self, index: usize) -> Vec<ExprId> {
        let t = &self.frames[index].transform;
        if self.position_only { t.p.to_vec() } else { t.entries().to_vec() }
    }

    /// Every output expression, frame by frame.
    pub fn outputs(&self) -> Vec<ExprId> {
        (0..self.frames.len()).flat_map(|i| self.frame_outputs(i)).collect()
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
        let mut values = Vec::new();
        self.frames.iter().map(|f| f.transform.entries().map(|id| self.graph.eval(id, q, &mut values))).collect()
    }

    /// The 12 pose entries of frame `index` as text (`c1 + c12`), rotation row-major then translation.
    ///
    /// Each entry is written out in full, so shared subexpressions are repeated: the text of a long
    /// chain grows exponentially with its length. For large robots use [`crate::emit::text_listing`],
    /// which prints shared subexpressions once as temporaries (what `kinematics expr` prints).
    pub fn frame_text(&self, index: usize) -> Vec<String> {
        let names = crate::emit::Names::new(&self.graph, &self.outputs());
        self.frames[index].transform.entries().iter().map(|&id| crate::emit::text(&self.graph, &names, id)).collect()
    }

    /// The 12 pose entries of frame `index` as LaTeX, written out in full as [`Compiled::frame_text`]
    /// (see its cost; [`crate::emit::latex_listing`] is linear).
    pub fn frame_latex(&self, index: usize) -> Vec<String> {
        let names = crate::emit::Names::new(&self.graph, &self.outputs());
        self.frames[index].transform.entries().iter().map(|&id| crate::emit::latex(&self.graph, &names, id)).collect()
    }
}
