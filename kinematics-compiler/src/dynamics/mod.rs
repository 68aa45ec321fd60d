//! The dynamics stage: a robot's rigid-body dynamics from its links' inertias, as expressions in
//! the same graph, passes and emitter as its poses.
//!
//! What it owns: [`compile_dynamics`], which checks the inertias (the model's rules, mass left to
//! geometry, a finite gravity), builds the bodies (`bodies`: one per elementary motion, fixed joints
//! lumped at compile time) and writes one of the [`DynamicsFunction`]s over them symbolically
//! (`recursive`: Newton-Euler, composite first moments for gravity, composite rigid bodies for the
//! mass matrix; `solve`: forward dynamics by the mass matrix's `L^T D L` factorisation, which keeps
//! the tree's sparsity; `articulated`: forward dynamics by the articulated-body algorithm, the
//! cheaper of the two kept); and [`CompiledDynamics`], the result, with its operation counts and a
//! numeric evaluator. Zeros fold as the nodes are built (an axis along `z` leaves one entry of a
//! rotation's projection; a massless link carries nothing), constants fold, and common
//! subexpressions are shared, so the code is what a careful hand would write for this robot.
//!
//! Conventions are the runtime reference's (`kinematics_runtime::ReferenceDynamics`): velocities,
//! accelerations and forces have one entry per velocity (a floating base's six in its own axes,
//! linear first), a mimic joint's torque is folded into its source's, gravity is a vector in the
//! root's frame, and `gravity_torques` are the torques that hold the robot still.

mod algebra;
mod articulated;
mod bodies;
mod recursive;
mod solve;

use kinematics_model::{JointMotion, KinematicTree, LinkId};

use crate::error::CompileError;
use crate::simplify::{EXPR_PASSES, run_expr_passes};
use crate::stats::OpCount;
use crate::symbolic::graph::{ExprGraph, ExprId};
use crate::symbolic::transform::SymTransform;
use recursive::{External, NewtonEuler};

/// Gravity along `-z` at the Earth's standard value (m/s^2), the default.
pub const STANDARD_GRAVITY: [f64; 3] = [0.0, 0.0, -9.81];

/// The most joints for which gravity is also written in the root's axes (each body's whole path
/// folded: quadratic in a chain's length, as each tip's path from the base is for the poses);
/// every robot in `robots/` has fewer.
const ROOT_WAY_UP_TO: usize = 256;

/// One function of the dynamics.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum DynamicsFunction {
    /// `gravity_torques(q)`: the generalized forces that hold the robot still.
    Gravity,
    /// `inverse_dynamics(q, qd, qdd)`: the generalized forces that give accelerations `qdd`.
    InverseDynamics,
    /// `nonlinear_effects(q, qd)`: Coriolis, centrifugal and gravity forces (inverse dynamics at
    /// zero acceleration).
    NonlinearEffects,
    /// `mass_matrix(q)`: the joint-space inertia matrix, symmetric.
    MassMatrix,
    /// `forward_dynamics(q, qd, tau)`: the accelerations the generalized forces `tau` give.
    ForwardDynamics,
    /// `inverse_dynamics_with_forces(q, qd, qdd, forces)`: inverse dynamics with external forces
    /// on the links [`DynamicsRequest::forces`] names.
    InverseDynamicsWithForces,
    /// `forward_dynamics_with_forces(q, qd, tau, forces)`: forward dynamics with external forces
    /// on the links [`DynamicsRequest::forces`] names.
    ForwardDynamicsWithForces,
}

impl DynamicsFunction {
    /// Every function, in the order emitted.
    pub const ALL: [DynamicsFunction; 5] = [
        DynamicsFunction::Gravity,
        DynamicsFunction::InverseDynamics,
        DynamicsFunction::NonlinearEffects,
        DynamicsFunction::MassMatrix,
        DynamicsFunction::ForwardDynamics,
    ];

    /// The functions that take external forces, emitted when [`DynamicsRequest::forces`] names
    /// links.
    pub const WITH_FORCES: [DynamicsFunction; 2] =
        [DynamicsFunction::InverseDynamicsWithForces, DynamicsFunction::ForwardDynamicsWithForces];

    /// Its name on the type.
    pub fn name(self) -> &'static str {
        match self {
            DynamicsFunction::Gravity => "gravity_torques",
            DynamicsFunction::InverseDynamics => "inverse_dynamics",
            DynamicsFunction::NonlinearEffects => "nonlinear_effects",
            DynamicsFunction::MassMatrix => "mass_matrix",
            DynamicsFunction::ForwardDynamics => "forward_dynamics",
            DynamicsFunction::InverseDynamicsWithForces => "inverse_dynamics_with_forces",
            DynamicsFunction::ForwardDynamicsWithForces => "forward_dynamics_with_forces",
        }
    }

    /// Whether it takes the joint rates `qd`.
    pub fn takes_rates(self) -> bool {
        !matches!(self, DynamicsFunction::Gravity | DynamicsFunction::MassMatrix)
    }

    /// The name of its third argument, one value per velocity (`qdd` or `tau`), if it takes one.
    pub fn input(self) -> Option<&'static str> {
        match self {
            DynamicsFunction::InverseDynamics | DynamicsFunction::InverseDynamicsWithForces => Some("qdd"),
            DynamicsFunction::ForwardDynamics | DynamicsFunction::ForwardDynamicsWithForces => Some("tau"),
            _ => None,
        }
    }

    /// Whether it takes external forces (a fourth argument `forces`, one spatial force per link
    /// of [`DynamicsRequest::forces`]).
    pub fn takes_forces(self) -> bool {
        matches!(self, DynamicsFunction::InverseDynamicsWithForces | DynamicsFunction::ForwardDynamicsWithForces)
    }

    /// Whether it solves for accelerations (returning them and the factorisation's pivots).
    pub fn is_forward(self) -> bool {
        matches!(self, DynamicsFunction::ForwardDynamics | DynamicsFunction::ForwardDynamicsWithForces)
    }
}

/// How to compile the dynamics: gravity, whether inertia tensors that break the triangle
/// inequality are taken as written, and the links external forces act on.
#[derive(Debug, Clone, PartialEq)]
pub struct DynamicsRequest {
    /// Gravity in the root link's frame (m/s^2).
    pub gravity: [f64; 3],
    /// Take tensors that break the triangle inequality as written (they must still be positive
    /// semi-definite).
    pub inertia_as_written: bool,
    /// The links external forces act on, in the order of the `forces` argument of the
    /// [`DynamicsFunction::WITH_FORCES`] functions (none: those are not emitted). Each force is
    /// six numbers `[fx, fy, fz, nx, ny, nz]`, the force and the moment about the link's origin,
    /// both in the link's own axes (Pinocchio's `fext` of `rnea` and `aba`, there per joint), acting
    /// on the link (a contact pushing on it, a payload's weight, a sensed wrench).
    pub forces: Vec<String>,
}

impl Default for DynamicsRequest {
    fn default() -> Self {
        DynamicsRequest { gravity: STANDARD_GRAVITY, inertia_as_written: false, forces: Vec::new() }
    }
}

/// Why a link named in [`DynamicsRequest::forces`] cannot take an external force.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ForceLinkFault {
    /// The robot has no such link.
    #[error(transparent)]
    Unknown(kinematics_model::UnknownLink),
    /// Named twice (the second time is the fault).
    #[error("link `{0}` is named twice in `forces`")]
    Twice(String),
    /// The root link: a force on it moves nothing.
    #[error("link `{0}` is the root: a force on it moves nothing")]
    Root(String),
    /// Only fixed joints between it and the root: a force on it moves nothing.
    #[error("link `{link}` is fixed to the root `{root}` (no joint between them moves): a force on it moves nothing")]
    Fixed {
        /// The link.
        link: String,
        /// The root link.
        root: String,
    },
}

/// Every link of `request.forces` that cannot take an external force, with its index in the
/// list.
pub fn force_link_faults(tree: &KinematicTree, request: &DynamicsRequest) -> Vec<(usize, ForceLinkFault)> {
    let links = &request.forces;
    links
        .iter()
        .enumerate()
        .filter_map(|(i, name)| {
            let link = match tree.find_link("force", name) {
                Ok(link) => link,
                Err(unknown) => return Some((i, ForceLinkFault::Unknown(unknown))),
            };
            if links[..i].contains(name) {
                return Some((i, ForceLinkFault::Twice(name.clone())));
            }
            let moves =
                tree.path_from_root(link).into_iter().any(|j| !matches!(tree.joint(j).motion, JointMotion::Fixed));
            let root = &tree.link(tree.root()).name;
            let fault = if name == root {
                ForceLinkFault::Root(name.clone())
            } else {
                ForceLinkFault::Fixed { link: name.clone(), root: root.clone() }
            };
            (!moves).then_some((i, fault))
        })
        .collect()
}

/// One compiled function of the dynamics: the graph and its outputs.
///
/// The graph's variables are `q` then `qd` (the joint rates) then each floating or spherical
/// joint's rotation, as a twist's; its inputs are the third argument (`qdd` or `tau`), then for
/// the [`DynamicsFunction::WITH_FORCES`] functions six per link of [`CompiledDynamics::forces`]
/// (the force, then its moment about the link's origin, in the link's axes). The outputs are one per velocity (forces, or for [`DynamicsFunction::ForwardDynamics`] the
/// accelerations and then the pivots of the factorisation), or the mass matrix row by row.
#[derive(Debug, Clone)]
pub struct CompiledDynamics {
    /// Robot name.
    pub robot: String,
    /// What it computes.
    pub function: DynamicsFunction,
    /// Joint names in degree-of-freedom order (the entries of `q`).
    pub dof_names: Vec<String>,
    /// Velocity names (the entries of `qd`, `qdd`, `tau` and the results).
    pub velocity_names: Vec<String>,
    /// Where each floating or spherical joint's quaternion starts in `q`.
    pub quaternions: Vec<usize>,
    /// The gravity it was compiled for.
    pub gravity: [f64; 3],
    /// The links its external forces act on (none unless it takes forces).
    pub forces: Vec<String>,
    pub(crate) graph: ExprGraph,
    pub(crate) outputs: Vec<ExprId>,
}

/// Compiles `function` of `tree`'s dynamics.
///
/// Fails on a gravity that is not finite, and on the first link in tree order whose mass is left
/// to its geometry (an MJCF body MuJoCo would infer) or whose inertia breaks a rigid body's rules
/// ([`kinematics_model::inertia::Inertial::fault`]), naming it and the line of its `<inertial>`.
///
/// ```
/// use kinematics_compiler::dynamics::{DynamicsFunction, DynamicsRequest, compile_dynamics};
/// let urdf = r#"<robot name="pendulum"><link name="base"/>
///   <link name="bob"><inertial><origin xyz="0 0 -0.5"/><mass value="2"/>
///     <inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial></link>
///   <joint name="hinge" type="continuous"><parent link="base"/><child link="bob"/><axis xyz="0 1 0"/></joint>
/// </robot>"#;
/// let tree = kinematics_model::parse_source("pendulum.urdf", urdf)?;
/// let gravity = compile_dynamics(&tree, &DynamicsRequest::default(), DynamicsFunction::Gravity)?;
/// // m g l sin q holds it, and the mass matrix is m l^2.
/// let q = [0.3];
/// let hold = gravity.eval(&q, &[0.0], &[])[0];
/// assert!((hold - 2.0 * 9.81 * 0.5 * 0.3f64.sin()).abs() < 1e-14);
/// let m = compile_dynamics(&tree, &DynamicsRequest::default(), DynamicsFunction::MassMatrix)?;
/// assert_eq!(m.eval(&q, &[0.0], &[]), vec![0.5]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn compile_dynamics(
    tree: &KinematicTree,
    request: &DynamicsRequest,
    function: DynamicsFunction,
) -> Result<CompiledDynamics, CompileError> {
    check(tree, request)?;
    // Gravity is written two ways (each body in its own axes, or in the root's) and forward
    // dynamics two (the mass matrix's factorisation, or the articulated-body algorithm where it
    // applies), and the cheaper kept, the first of equals; the other functions one way. The root's
    // way folds each body's whole path, the square of a long chain's length: past `ROOT_WAY_UP_TO`
    // joints it is not tried.
    let few = tree.joints().len() <= ROOT_WAY_UP_TO;
    let ways: &[Way] = match function {
        DynamicsFunction::Gravity if few => &[Way::Recursive, Way::FromRoot],
        _ if function.is_forward() => &[Way::Recursive, Way::Articulated],
        _ => &[Way::Recursive],
    };
    let mut best: Option<(usize, ExprGraph, Vec<ExprId>)> = None;
    for &way in ways {
        let Some((g, outputs)) = written(tree, request, function, way) else { continue };
        let cost = OpCount::of(&g, outputs.iter().copied()).weighted();
        if best.as_ref().is_none_or(|(c, ..)| cost < *c) {
            best = Some((cost, g, outputs));
        }
    }
    #[allow(clippy::expect_used, reason = "an invariant: the function is written at least one way")]
    let (_, g, outputs) = best.expect("every function is written at least one way");
    Ok(compiled(tree, request, function, g, outputs))
}

/// `function` written `way` (`None` where that way does not apply), its expressions simplified.
fn written(
    tree: &KinematicTree,
    request: &DynamicsRequest,
    function: DynamicsFunction,
    way: Way,
) -> Option<(ExprGraph, Vec<ExprId>)> {
    // The links the forces act on (checked: each exists, once, below a moving joint).
    let links: Vec<LinkId> = if function.takes_forces() {
        request.forces.iter().filter_map(|name| tree.link_id(name)).collect()
    } else {
        Vec::new()
    };
    let mut g = ExprGraph::new();
    let (bodies, frames) = bodies::bodies_and_link_frames(&mut g, tree, &links);
    let mut outputs = match way {
        Way::Recursive => write(&mut g, tree, &bodies, &frames, request.gravity, function),
        Way::FromRoot => recursive::gravity_from_root(&mut g, &bodies, tree.velocity_dof(), request.gravity),
        Way::Articulated => {
            let (n, nv) = (tree.dof(), tree.velocity_dof());
            let rates = |g: &mut ExprGraph, i: usize| Some(g.var(n + i));
            let tau = |g: &mut ExprGraph, i: usize| g.input(i);
            let external = externals(&mut g, &frames, nv);
            let (accelerations, pivots) =
                articulated::forward_dynamics(&mut g, &bodies, nv, request.gravity, &rates, &tau, &external)?;
            accelerations.into_iter().chain(pivots).collect()
        }
    };
    run_expr_passes(&mut g, &mut [], &mut outputs, EXPR_PASSES, false);
    Some((g, outputs))
}

/// The compiled function of `tree` from its graph and outputs.
fn compiled(
    tree: &KinematicTree,
    request: &DynamicsRequest,
    function: DynamicsFunction,
    graph: ExprGraph,
    outputs: Vec<ExprId>,
) -> CompiledDynamics {
    CompiledDynamics {
        robot: tree.name().to_owned(),
        function,
        dof_names: tree.dof_names(),
        velocity_names: tree.velocity_names(),
        quaternions: tree.quaternion_entries(),
        gravity: request.gravity,
        forces: if function.takes_forces() { request.forces.clone() } else { Vec::new() },
        graph,
        outputs,
    }
}

/// `function`'s outputs over `bodies`, built in `g`; `frames` are where the links the external
/// forces act on ride (their body, and their frame in its), in the order of the forces.
fn write(
    g: &mut ExprGraph,
    tree: &KinematicTree,
    bodies: &[bodies::Body],
    frames: &[Option<(usize, SymTransform)>],
    gravity: [f64; 3],
    function: DynamicsFunction,
) -> Vec<ExprId> {
    let (n, nv) = (tree.dof(), tree.velocity_dof());
    let rates = |g: &mut ExprGraph, i: usize| Some(g.var(n + i));
    let none = |_: &mut ExprGraph, _: usize| None;
    let inputs = |g: &mut ExprGraph, i: usize| Some(g.input(i));
    let external = externals(g, frames, nv);
    match function {
        DynamicsFunction::Gravity => recursive::gravity(g, bodies, nv, gravity),
        DynamicsFunction::InverseDynamics | DynamicsFunction::InverseDynamicsWithForces => {
            let input = NewtonEuler { rates: &rates, accelerations: &inputs, gravity, external: &external };
            recursive::newton_euler(g, bodies, nv, &input)
        }
        DynamicsFunction::NonlinearEffects => {
            let input = NewtonEuler { rates: &rates, accelerations: &none, gravity, external: &[] };
            recursive::newton_euler(g, bodies, nv, &input)
        }
        DynamicsFunction::MassMatrix => {
            let upper = recursive::mass_matrix(g, bodies, nv);
            (0..nv).flat_map(|i| (0..nv).map(move |j| (i, j))).map(|(i, j)| upper[i.min(j)][i.max(j)]).collect()
        }
        DynamicsFunction::ForwardDynamics | DynamicsFunction::ForwardDynamicsWithForces => {
            // `M qdd = tau - h`, where `h` (inverse dynamics at zero acceleration) holds the
            // external forces too.
            let input = NewtonEuler { rates: &rates, accelerations: &none, gravity, external: &external };
            let h = recursive::newton_euler(g, bodies, nv, &input);
            let upper = recursive::mass_matrix(g, bodies, nv);
            let rhs: Vec<ExprId> = (0..nv)
                .map(|i| {
                    let tau = g.input(i);
                    g.sub(tau, h[i])
                })
                .collect();
            let (accelerations, pivots) = solve::solve(g, upper, rhs);
            accelerations.into_iter().chain(pivots).collect()
        }
    }
}

/// The external forces on the links riding where `frames` say: inputs after the `nv` of `qdd` or
/// `tau`, six per link, the force then its moment.
fn externals(g: &mut ExprGraph, frames: &[Option<(usize, SymTransform)>], nv: usize) -> Vec<External> {
    frames
        .iter()
        .enumerate()
        .filter_map(|(k, frame)| {
            let (body, frame) = (*frame)?;
            let at = nv + 6 * k;
            let force = std::array::from_fn(|c| g.input(at + c));
            let moment = std::array::from_fn(|c| g.input(at + 3 + c));
            Some(External { body, frame, force, moment })
        })
        .collect()
}

/// One way of writing a function.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Way {
    /// The recursive algorithms in each body's axes (forward dynamics: the mass matrix factorised).
    Recursive,
    /// Gravity with the first moments in the root's axes.
    FromRoot,
    /// Forward dynamics by the articulated-body algorithm.
    Articulated,
}

/// What `function` costs as the plain recursive algorithm: the same recursion over the same
/// bodies, with every number of the robot (each fixed placement, each inertia) unknown until run
/// time, as a library that reads the robot at run time has it; only each joint's kind and axis
/// are known (a run-time library's joint types), and exact zeros of the algorithm itself fold.
/// The compiled function's count ([`CompiledDynamics::op_count`]) set beside it is what the
/// robot's own numbers save.
pub fn plain_op_count(
    tree: &KinematicTree,
    request: &DynamicsRequest,
    function: DynamicsFunction,
) -> Result<OpCount, CompileError> {
    check(tree, request)?;
    let mut g = ExprGraph::new();
    let bodies = bodies::bodies(&mut g, tree);
    // The robot's numbers are inputs after the function's own (`qdd`, `tau`).
    let opaque = bodies::opaque(&mut g, &bodies, tree.velocity_dof());
    let outputs = write(&mut g, tree, &opaque, &[], request.gravity, function);
    Ok(OpCount::of(&g, outputs))
}

/// The dynamics' refusals: a gravity that is not finite, a link forces cannot act on
/// ([`force_link_faults`]), then the first link at fault ([`link_faults`]).
pub(crate) fn check(tree: &KinematicTree, request: &DynamicsRequest) -> Result<(), CompileError> {
    if request.gravity.iter().any(|x| !x.is_finite()) {
        return Err(CompileError::NonFiniteGravity { robot: tree.name().to_owned(), gravity: request.gravity });
    }
    if let Some((_, fault)) = force_link_faults(tree, request).into_iter().next() {
        return Err(CompileError::ForceLink { robot: tree.name().to_owned(), fault });
    }
    match link_faults(tree, request).into_iter().next() {
        Some(fault) => Err(fault),
        None => Ok(()),
    }
}

/// Every link the dynamics refuse ([`KinematicTree::inertia_refusals`]), as errors.
pub(crate) fn link_faults(tree: &KinematicTree, request: &DynamicsRequest) -> Vec<CompileError> {
    let robot = tree.name();
    tree.inertia_refusals(request.inertia_as_written)
        .into_iter()
        .map(|refusal| CompileError::Inertia { robot: robot.to_owned(), refusal: Box::new(refusal) })
        .collect()
}

impl CompiledDynamics {
    /// The expression graph.
    pub fn graph(&self) -> &ExprGraph {
        &self.graph
    }

    /// The output expressions (see the type's doc for their order).
    pub fn outputs(&self) -> &[ExprId] {
        &self.outputs
    }

    /// Number of entries of `q`.
    pub fn dof(&self) -> usize {
        self.dof_names.len()
    }

    /// Number of velocities.
    pub fn velocity_dof(&self) -> usize {
        self.velocity_names.len()
    }

    /// Operation counts of everything computed.
    pub fn op_count(&self) -> OpCount {
        OpCount::of(&self.graph, self.outputs.iter().copied())
    }

    /// Evaluates the outputs with the graph (no Rust compiled) at `q`, the rates `qd` and the
    /// inputs `input`: the third argument (`qdd` or `tau`; ignored by functions that take none),
    /// then each link's force and moment (six numbers per link of [`Self::forces`]).
    ///
    /// # Panics
    ///
    /// If `q` or `qd` is shorter than the robot needs, or `input` shorter than the function reads.
    pub fn eval(&self, q: &[f64], qd: &[f64], input: &[f64]) -> Vec<f64> {
        let mut values: Vec<f64> = q[..self.dof()].to_vec();
        values.extend_from_slice(&qd[..self.velocity_dof()]);
        let variables = crate::request::variables(self.dof(), self.velocity_dof(), &self.quaternions, &values);
        let mut cache = Vec::new();
        self.outputs.iter().map(|&id| self.graph.eval_with_inputs(id, &variables, input, &mut cache)).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::symbolic::graph::Node;
    use crate::symbolic::step::expr_text;

    /// A two-link arm in the vertical x-z plane, hinges about `y`, point masses `m1 = 2` and
    /// `m2 = 3` at the ends of links of lengths `l1 = 0.5` and `l2 = 0.25`, and gravity `-z`.
    fn planar_arm() -> KinematicTree {
        let urdf = r#"<robot name="arm"><link name="base"/>
          <link name="upper"><inertial><origin xyz="0.5 0 0"/><mass value="2"/>
            <inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial></link>
          <link name="fore"><inertial><origin xyz="0.25 0 0"/><mass value="3"/>
            <inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial></link>
          <joint name="shoulder" type="continuous"><parent link="base"/><child link="upper"/><axis xyz="0 -1 0"/></joint>
          <joint name="elbow" type="continuous"><parent link="upper"/><child link="fore"/>
            <origin xyz="0.5 0 0"/><axis xyz="0 -1 0"/></joint></robot>"#;
        kinematics_model::parse_source("arm.urdf", urdf).unwrap()
    }

    fn texts(compiled: &CompiledDynamics) -> Vec<String> {
        compiled.outputs.iter().map(|&id| expr_text(&compiled.graph, id)).collect()
    }

    /// The textbook's gravity torques of the planar arm (Spong, Hutchinson and Vidyasagar, *Robot
    /// Modeling and Control*, §7.4 with point masses): `tau2 = m2 g l2 cos(q1 + q2)` and
    /// `tau1 = (m1 l1 + m2 l1) g cos q1 + tau2`, here `g = 9.81` (an axis `-y` turns `x` up
    /// towards `z`).
    #[test]
    fn a_planar_arms_gravity_reads_as_the_textbooks() {
        let tree = planar_arm();
        let gravity = compile_dynamics(&tree, &DynamicsRequest::default(), DynamicsFunction::Gravity).unwrap();
        let at = |q: [f64; 2]| gravity.eval(&q, &[0.0; 2], &[]);
        for q in [[0.3, -0.7], [1.2, 2.0], [-2.5, 0.1]] {
            let tau = at(q);
            let want2 = 3.0 * 9.81 * 0.25 * (q[0] + q[1]).cos();
            let want1 = (2.0 + 3.0) * 9.81 * 0.5 * q[0].cos() + want2;
            assert!((tau[1] - want2).abs() < 1e-13 && (tau[0] - want1).abs() < 1e-13, "{tau:?} at {q:?}");
        }
        // As the textbook writes them, the shoulder's `m1 l1 + m2 l1 = 2.5` and the elbow's
        // `m2 l2 = 0.75` times `g`: the first moments in the root's axes, whose angles sum.
        assert_eq!(texts(&gravity), ["9.81*(0.75*cos(q1 + q2) + 2.5*cos(q1))", "7.3575*cos(q1 + q2)"]);
        assert_eq!(gravity.op_count().sin_cos, 2);
    }

    /// The mass matrix of the planar arm: `m22 = m2 l2^2`, `m12 = m2 (l2^2 + l1 l2 cos q2)`,
    /// `m11 = m1 l1^2 + m2 (l1^2 + l2^2 + 2 l1 l2 cos q2)`, exactly symmetric.
    #[test]
    fn a_planar_arms_mass_matrix_is_the_textbooks() {
        let tree = planar_arm();
        let m = compile_dynamics(&tree, &DynamicsRequest::default(), DynamicsFunction::MassMatrix).unwrap();
        assert_eq!(m.outputs[1], m.outputs[2], "one node for both sides of the diagonal");
        for q2 in [0.0, 0.4, -2.0] {
            let v = m.eval(&[0.7, q2], &[0.0; 2], &[]);
            let (l1, l2) = (0.5, 0.25);
            let want = [
                2.0 * l1 * l1 + 3.0 * (l1 * l1 + l2 * l2 + 2.0 * l1 * l2 * q2.cos()),
                3.0 * (l2 * l2 + l1 * l2 * q2.cos()),
                3.0 * l2 * l2,
            ];
            for (got, want) in [v[0], v[1], v[3]].into_iter().zip(want) {
                assert!((got - want).abs() < 1e-15, "{v:?} against {want:?}");
            }
        }
        // Nothing reads the shoulder's angle.
        let reads_q1 = crate::stats::reachable(&m.graph, m.outputs.iter().copied())
            .into_iter()
            .any(|id| m.graph.node(id) == Node::Var(0));
        assert!(!reads_q1, "{:?}", texts(&m));
    }

    /// The Panda's first joint turns about gravity: none of its dynamics reads `q1`.
    #[test]
    fn the_pandas_dynamics_do_not_read_its_first_joint() {
        let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../robots/panda.urdf")).unwrap();
        let tree = kinematics_model::parse_source("panda.urdf", &text).unwrap();
        for function in DynamicsFunction::ALL {
            let compiled = compile_dynamics(&tree, &DynamicsRequest::default(), function).unwrap();
            let reached = crate::stats::reachable(&compiled.graph, compiled.outputs.iter().copied());
            assert!(!reached.iter().any(|&id| compiled.graph.node(id) == Node::Var(0)), "{function:?}");
        }
    }

    /// Forward dynamics both ways, the factorisation and the articulated-body algorithm, agree
    /// (in torque units: the mass matrix times the difference) on the UR5 and the planar arm, with
    /// a force on a link; the cheaper is the one compiled; a robot with a mimic joint has no
    /// articulated way.
    #[test]
    fn forward_dynamics_both_ways_agree() {
        let read = |file: &str| {
            let path = format!("{}/../robots/{file}", env!("CARGO_MANIFEST_DIR"));
            kinematics_model::parse_source(file, &std::fs::read_to_string(path).unwrap()).unwrap()
        };
        let cases = [(read("ur5.urdf"), "wrist_2_link"), (planar_arm(), "fore"), (long_chain(24), "l17")];
        for (tree, link) in &cases {
            let request = DynamicsRequest { forces: vec![(*link).to_owned()], ..DynamicsRequest::default() };
            let function = DynamicsFunction::ForwardDynamicsWithForces;
            let mass = compile_dynamics(tree, &request, DynamicsFunction::MassMatrix).unwrap();
            let [factorised, articulated] = [Way::Recursive, Way::Articulated].map(|way| {
                let (g, outputs) = written(tree, &request, function, way).unwrap();
                compiled(tree, &request, function, g, outputs)
            });
            let nv = tree.velocity_dof();
            let mut x = 0.37_f64;
            for _ in 0..20 {
                let mut next = || {
                    x = (x * 7919.0 + 0.123).fract();
                    3.0 * x - 1.5
                };
                let q: Vec<f64> = (0..nv).map(|_| next()).collect();
                let qd: Vec<f64> = (0..nv).map(|_| next()).collect();
                let input: Vec<f64> = (0..nv + 6).map(|_| 10.0 * next()).collect();
                let (a, b) = (factorised.eval(&q, &qd, &input), articulated.eval(&q, &qd, &input));
                let m = mass.eval(&q, &qd, &[]);
                for i in 0..nv {
                    let torque: f64 = (0..nv).map(|j| m[i * nv + j] * (a[j] - b[j])).sum();
                    assert!(torque.abs() < 1e-10, "{}: {torque} at {i}: {a:?} against {b:?}", tree.name());
                    // The pivots agree too (both are the articulated inertia about each joint).
                    assert!((a[nv + i] - b[nv + i]).abs() < 1e-12 * a[nv + i].abs().max(1.0), "{a:?} against {b:?}");
                }
            }
            let chosen = compile_dynamics(tree, &request, function).unwrap().op_count().weighted();
            let cheaper = factorised.op_count().weighted().min(articulated.op_count().weighted());
            assert_eq!(chosen, cheaper, "{}", tree.name());
            if tree.name() == "ur5" {
                // The guide quotes these (`src/guide/dynamics.md`, forward dynamics).
                assert_eq!((factorised.op_count().mul, articulated.op_count().mul), (469, 791));
            }
        }
        let panda = read("panda.urdf");
        let request = DynamicsRequest::default();
        assert!(written(&panda, &request, DynamicsFunction::ForwardDynamics, Way::Articulated).is_none());
    }

    /// A serial chain of `n` hinges, each turned and offset from the last, its axes in turn along
    /// x, y and z, every link a solid of its own.
    fn long_chain(n: usize) -> KinematicTree {
        let mut urdf = format!(r#"<robot name="chain{n}"><link name="l0"/>"#);
        for i in 1..=n {
            let (m, a) = (0.5 + 0.1 * i as f64, 0.01 + 0.001 * i as f64);
            urdf += &format!(
                r#"<link name="l{i}"><inertial><origin xyz="0.05 -0.02 0.03" rpy="0.1 0.2 0.3"/><mass value="{m}"/>
                   <inertia ixx="{a}" ixy="0.001" ixz="0" iyy="{b}" iyz="0.002" izz="{c}"/></inertial></link>
                   <joint name="j{i}" type="continuous"><parent link="l{p}"/><child link="l{i}"/>
                   <origin xyz="0.1 0.02 0.2" rpy="0.3 -0.2 0.1"/><axis xyz="{axis}"/></joint>"#,
                b = a * 1.1,
                c = a * 0.9,
                p = i - 1,
                axis = ["1 0 0", "0 1 0", "0 0 1"][i % 3],
            );
        }
        kinematics_model::parse_source("chain.urdf", &(urdf + "</robot>")).unwrap()
    }

    /// On a short chain the factorisation is the cheaper way to forward dynamics; on a long one
    /// the articulated-body algorithm, whose work grows with the chain's length where the
    /// factorisation's grows faster: 24 hinges take 10,382 multiplications that way against
    /// 14,092, 6 hinges 1,990 against 1,306.
    #[test]
    fn a_long_chain_takes_the_articulated_way() {
        let request = DynamicsRequest::default();
        let function = DynamicsFunction::ForwardDynamics;
        for (n, articulated_wins) in [(6, false), (24, true)] {
            let tree = long_chain(n);
            let costs = [Way::Recursive, Way::Articulated].map(|way| {
                let (g, outputs) = written(&tree, &request, function, way).unwrap();
                OpCount::of(&g, outputs.iter().copied())
            });
            assert_eq!(costs[1].weighted() < costs[0].weighted(), articulated_wins, "{n} hinges: {costs:?}");
            let chosen = compile_dynamics(&tree, &request, function).unwrap().op_count();
            assert_eq!(chosen, if articulated_wins { costs[1] } else { costs[0] }, "{n} hinges");
            if n == 24 {
                // The guide quotes these (`src/guide/dynamics.md`, forward dynamics).
                assert_eq!((costs[0].mul, costs[1].mul), (14_092, 10_382));
            }
        }
    }

    /// A massless link below a fixed joint is nothing; a massive one is lumped onto its parent: the
    /// same torques as the link's mass written on the parent at the child's place.
    #[test]
    fn fixed_joints_are_lumped() {
        let arm = |extra: &str, joint: &str| {
            let urdf = format!(
                r#"<robot name="lumped"><link name="base"/>
                  <link name="upper">{extra}</link><link name="tool"><inertial><origin xyz="0 0 0.1"/><mass value="1.5"/>
                    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.02" iyz="0" izz="0.015"/></inertial></link>
                  <joint name="shoulder" type="continuous"><parent link="base"/><child link="upper"/><axis xyz="0 1 0"/></joint>
                  {joint}</robot>"#
            );
            kinematics_model::parse_source("lumped.urdf", &urdf).unwrap()
        };
        let fixed = arm(
            "",
            r#"<joint name="flange" type="fixed"><parent link="upper"/><child link="tool"/><origin xyz="0.4 0 0" rpy="0 1.5707963267948966 0"/></joint>"#,
        );
        let compiled = compile_dynamics(&fixed, &DynamicsRequest::default(), DynamicsFunction::MassMatrix).unwrap();
        // The tool's centre at (0.4 + 0.1, 0, 0) after the quarter turn about y, its tensor turned:
        // about the hinge (y), m r^2 + iyy.
        let m = compiled.eval(&[0.3], &[0.0], &[]);
        assert!((m[0] - (1.5 * 0.5 * 0.5 + 0.02)).abs() < 1e-15, "{m:?}");
        assert!(compiled.op_count().mul == 0 && compiled.op_count().sin_cos == 0, "{}", compiled.op_count());
    }
}
