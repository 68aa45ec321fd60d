//! The bodies the recursive algorithms run over: one per elementary motion of the tree, each with
//! its transform from its parent body, the directions it moves in and the mass it carries.
//!
//! A revolute, continuous or prismatic joint (a mimic one too) is one body; a planar joint is
//! three (its two slides, then its turn), the first two massless; a floating or spherical joint is
//! one body moving in six or three directions. A body's frame is its joint's frame right after
//! the motion, where the motion's directions are constant: a rotation about `u` is `[u; 0]`, a
//! slide along `u` is `[0; u]`, a floating joint's six velocities are the unit vectors (linear then
//! angular, in the body's own axes, as the runtime reference and Pinocchio have them).
//!
//! Fixed joints are lumped at compile time: the links below a fixed joint ride on the nearest body
//! above (or on the fixed root, where their mass moves nothing), their inertias turned into its
//! frame with constants, and the fixed transforms between bodies fold into the next body's
//! transform through the chain passes, so quarter turns stay exact.

use kinematics_model::{JointKind, JointMotion, KinematicTree, LinkId};

use super::algebra::{Sym3, Vec3, constant};
use crate::simplify::simplify;
use crate::symbolic::angle::LinearAngle;
use crate::symbolic::graph::{ExprGraph, ExprId};
use crate::symbolic::lower::{lower_fixed, rotation_variables};
use crate::symbolic::step::Step;
use crate::symbolic::transform::{SymTransform, fold_from_base};

/// One direction a body moves in, per unit rate of one velocity: angular then linear part, in the
/// body's axes.
#[derive(Debug, Clone, Copy)]
pub(super) struct Motion {
    /// Angular part.
    pub(super) angular: [f64; 3],
    /// Linear part (of the body's origin).
    pub(super) linear: [f64; 3],
    /// The velocity (entry of `qd`) it moves with.
    pub(super) column: usize,
    /// Its rate per unit of that velocity (a mimic joint's multiplier; `1` otherwise).
    pub(super) rate: f64,
}

/// A rigid body's mass and inertia about the body's origin, in its axes.
#[derive(Debug, Clone, Copy)]
pub(super) struct Inertia {
    /// Mass.
    pub(super) mass: ExprId,
    /// First moment of mass `m c` (`c` the centre of mass).
    pub(super) first_moment: Vec3,
    /// Rotational inertia about the origin.
    pub(super) rotational: Sym3,
}

/// One body of the recursion.
#[derive(Debug, Clone)]
pub(super) struct Body {
    /// The parent body (`None`: the fixed root).
    pub(super) parent: Option<usize>,
    /// This body's frame in its parent's (the root's) frame.
    pub(super) transform: SymTransform,
    /// The directions it moves in.
    pub(super) motions: Vec<Motion>,
    /// The mass it carries (its own link's and the links lumped onto it), if any.
    pub(super) inertia: Option<Inertia>,
    /// The steps of its motion alone (for [`opaque`]).
    motion_steps: Vec<Step>,
    /// The steps from its parent body's frame (the root's) to its own, unsimplified
    /// ([`pose_in_root`]).
    from_parent: Vec<Step>,
}

/// Body `index`'s frame in the root's: the steps of its whole path from the root simplified as a
/// pose's (the angles of parallel axes summed, quarter turns exact) and folded. Its cost is the
/// path's length: the caller asks for it on robots of few bodies.
pub(super) fn pose_in_root(g: &mut ExprGraph, bodies: &[Body], index: usize) -> SymTransform {
    let mut chain = vec![index];
    while let Some(parent) = bodies[chain[chain.len() - 1]].parent {
        chain.push(parent);
    }
    let steps: Vec<Step> = chain.iter().rev().flat_map(|&b| bodies[b].from_parent.iter().cloned()).collect();
    let steps = simplify(g, steps);
    let identity = SymTransform::identity(g);
    fold_from_base(g, identity, &steps)
}

/// Numeric mass properties while lumping: mass, first moment and inertia about the origin.
#[derive(Debug, Clone, Copy, Default)]
struct Lumped {
    mass: f64,
    first_moment: [f64; 3],
    rotational: [[f64; 3]; 3],
}

/// Where a link sits: on which body (`None`: the root), by which fixed steps from its frame.
#[derive(Debug, Clone)]
struct Place {
    body: Option<usize>,
    steps: Vec<Step>,
}

/// The bodies of `tree`, parents before children, with the inertias read from its links.
pub(super) fn bodies(g: &mut ExprGraph, tree: &KinematicTree) -> Vec<Body> {
    bodies_and_places(g, tree).0
}

/// The bodies of `tree` ([`bodies`]) and where each of `links` rides: its body and its frame in
/// the body's (constants), or `None` for a link fixed to the root.
pub(super) fn bodies_and_link_frames(
    g: &mut ExprGraph,
    tree: &KinematicTree,
    links: &[LinkId],
) -> (Vec<Body>, Vec<Option<(usize, SymTransform)>>) {
    let (bodies, places) = bodies_and_places(g, tree);
    let frames = links
        .iter()
        .map(|link| {
            #[allow(clippy::expect_used, reason = "an invariant of the tree: every link is below its root")]
            let place = places[link.0].as_ref().expect("every link of the tree is placed");
            let body = place.body?;
            let identity = SymTransform::identity(g);
            Some((body, fold_from_base(g, identity, &place.steps)))
        })
        .collect();
    (bodies, frames)
}

/// The bodies and where every link rides.
fn bodies_and_places(g: &mut ExprGraph, tree: &KinematicTree) -> (Vec<Body>, Vec<Option<Place>>) {
    let of_entry = tree.velocity_of_entry();
    let mut places: Vec<Option<Place>> = vec![None; tree.links().len()];
    places[tree.root().0] = Some(Place { body: None, steps: Vec::new() });
    let mut bodies: Vec<Body> = Vec::new();
    let mut lumped: Vec<Lumped> = Vec::new();
    for (index, joint) in tree.joints().iter().enumerate() {
        #[allow(clippy::expect_used, reason = "an invariant of the tree: joints come in depth-first order")]
        let parent = places[joint.parent.0].clone().expect("a joint's parent link is placed before the joint");
        let mut steps = parent.steps.clone();
        lower_fixed(g, &joint.origin, &mut steps);
        let mut body = parent.body;
        let id = kinematics_model::JointId(index);
        for (motion_steps, motions) in motions_of(g, tree, id, &of_entry) {
            steps.extend(motion_steps.iter().cloned());
            let from_parent = std::mem::take(&mut steps);
            let steps_now = simplify(g, from_parent.clone());
            let identity = SymTransform::identity(g);
            let transform = fold_from_base(g, identity, &steps_now);
            bodies.push(Body { parent: body, transform, motions, inertia: None, motion_steps, from_parent });
            lumped.push(Lumped::default());
            body = Some(bodies.len() - 1);
        }
        lower_fixed(g, &joint.after_motion, &mut steps);
        places[joint.child.0] = Some(Place { body, steps });
    }
    for (link, place) in tree.links().iter().zip(&places) {
        let (Some(inertial), Some(Place { body: Some(body), steps, .. })) = (&link.inertial, place) else { continue };
        let mut steps = steps.clone();
        lower_fixed(g, &inertial.origin, &mut steps);
        let identity = SymTransform::identity(g);
        let com = fold_from_base(g, identity, &steps);
        let value = |id: ExprId| {
            #[allow(clippy::expect_used, reason = "an invariant: fixed steps fold to constants")]
            g.as_const(id).expect("a fixed transform folds to constant nodes")
        };
        let r = com.r.map(|row| row.map(value));
        let c = com.p.map(value);
        add_body(&mut lumped[*body], inertial.mass, c, r, inertial.matrix());
    }
    for (body, lumped) in bodies.iter_mut().zip(lumped) {
        if lumped.mass != 0.0 || lumped.rotational.iter().flatten().any(|&x| x != 0.0) {
            let rotational = [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)].map(|(i, j)| lumped.rotational[i][j]);
            body.inertia = Some(Inertia {
                mass: g.constant(lumped.mass),
                first_moment: constant(g, lumped.first_moment),
                rotational: rotational.map(|x| g.constant(x)),
            });
        }
    }
    (bodies, places)
}

/// Adds a body of `mass` whose centre of mass is at `c` with axes `r` (in the lumped body's
/// frame) and rotational inertia `tensor` about its centre in those axes.
fn add_body(to: &mut Lumped, mass: f64, c: [f64; 3], r: [[f64; 3]; 3], tensor: [[f64; 3]; 3]) {
    // r tensor r^T: the tensor in the body's axes.
    let mut turned = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            turned[i][j] = (0..3).map(|k| (0..3).map(|l| r[i][k] * tensor[k][l] * r[j][l]).sum::<f64>()).sum();
        }
    }
    // Parallel axes: about the origin, m (|c|^2 1 - c c^T) more.
    let c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    for i in 0..3 {
        for j in 0..3 {
            let identity = if i == j { c2 } else { 0.0 };
            to.rotational[i][j] += turned[i][j] + mass * (identity - c[i] * c[j]);
        }
        to.first_moment[i] += mass * c[i];
    }
    to.mass += mass;
}

/// A joint's motion as bodies: each the steps of its motion and the directions it moves in.
fn motions_of(
    g: &mut ExprGraph,
    tree: &KinematicTree,
    id: kinematics_model::JointId,
    of_entry: &[Option<usize>],
) -> Vec<(Vec<Step>, Vec<Motion>)> {
    let joint = tree.joint(id);
    let zero = [0.0; 3];
    let (entry, multiplier, offset) = match joint.motion {
        JointMotion::Fixed => return Vec::new(),
        JointMotion::Dof(entry) => (entry, 1.0, 0.0),
        JointMotion::Mimic { dof, multiplier, offset, .. } => (dof, multiplier, offset),
    };
    let column = |entry: usize| {
        #[allow(clippy::expect_used, reason = "an invariant of the model: a joint of one entry has one velocity")]
        of_entry[entry].expect("an entry of a revolute, prismatic or planar joint has a velocity")
    };
    let unit = |i: usize| std::array::from_fn(|k| if k == i { 1.0 } else { 0.0 });
    match joint.kind {
        JointKind::Fixed => Vec::new(),
        JointKind::Revolute | JointKind::Continuous => {
            let angle = LinearAngle::joint(entry, multiplier, offset);
            let motion = Motion { angular: joint.axis, linear: zero, column: column(entry), rate: multiplier };
            vec![(vec![Step::Rotate { axis: joint.axis, angle }], vec![motion])]
        }
        JointKind::Prismatic => {
            let (k, q, b) = (g.constant(multiplier), g.var(entry), g.constant(offset));
            let kq = g.mul(k, q);
            let d = g.add(kq, b);
            let v = joint.axis.map(|a| {
                let a = g.constant(a);
                g.mul(a, d)
            });
            let motion = Motion { angular: zero, linear: joint.axis, column: column(entry), rate: multiplier };
            vec![(vec![Step::Translate(v)], vec![motion])]
        }
        JointKind::Planar => {
            let (e1, e2) = joint.plane_axes();
            let slide = |g: &mut ExprGraph, e: [f64; 3], entry: usize| {
                let q = g.var(entry);
                let v = e.map(|a| {
                    let a = g.constant(a);
                    g.mul(a, q)
                });
                let motion = Motion { angular: zero, linear: e, column: column(entry), rate: 1.0 };
                (vec![Step::Translate(v)], vec![motion])
            };
            let turn = Motion { angular: joint.axis, linear: zero, column: column(entry + 2), rate: 1.0 };
            let angle = LinearAngle::joint(entry + 2, 1.0, 0.0);
            vec![
                slide(g, e1, entry),
                slide(g, e2, entry + 1),
                (vec![Step::Rotate { axis: joint.axis, angle }], vec![turn]),
            ]
        }
        JointKind::Floating | JointKind::Spherical => {
            #[allow(clippy::expect_used, reason = "an invariant of the model: an independent joint has velocities")]
            let first = tree.velocity_start(id).expect("an independent quaternion joint has a first velocity");
            let translates = joint.kind == JointKind::Floating;
            let start = rotation_variables(tree, id);
            let rotation = std::array::from_fn(|i| std::array::from_fn(|j| g.var(start + 3 * i + j)));
            let mut steps = Vec::new();
            let mut motions = Vec::new();
            if translates {
                steps.push(Step::Translate([g.var(entry), g.var(entry + 1), g.var(entry + 2)]));
                motions.extend((0..3).map(|i| Motion { angular: zero, linear: unit(i), column: first + i, rate: 1.0 }));
            }
            let angular = first + if translates { 3 } else { 0 };
            motions.extend((0..3).map(|i| Motion { angular: unit(i), linear: zero, column: angular + i, rate: 1.0 }));
            steps.push(Step::Free { rotation, column: first, translates, inverted: false });
            vec![(steps, motions)]
        }
    }
}

/// The same bodies with every number of the robot unknown until run time: each body's fixed
/// placement a full transform of inputs, then its motion (its joint's kind and axis known, as a
/// run-time library's joint types know them), and every inertia six inputs, a mass and a first
/// moment. The recursive algorithms over these count what they cost where nothing folds: the
/// plain recursive algorithm the compiled one is measured against.
/// The inputs are numbered from `first` on.
pub(super) fn opaque(g: &mut ExprGraph, bodies: &[Body], first: usize) -> Vec<Body> {
    let mut next = first;
    let mut input = |g: &mut ExprGraph| {
        next += 1;
        g.input(next - 1)
    };
    bodies
        .iter()
        .map(|body| {
            let placement = SymTransform {
                r: std::array::from_fn(|_| std::array::from_fn(|_| input(g))),
                p: std::array::from_fn(|_| input(g)),
            };
            let transform = fold_from_base(g, placement, &body.motion_steps);
            let inertia = body.inertia.map(|_| Inertia {
                mass: input(g),
                first_moment: std::array::from_fn(|_| input(g)),
                rotational: std::array::from_fn(|_| input(g)),
            });
            Body { transform, inertia, ..body.clone() }
        })
        .collect()
}
