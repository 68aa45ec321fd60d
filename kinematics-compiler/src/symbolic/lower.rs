//! Lowering: the joints on a path of the model become a product of [`Step`]s.

use kinematics_model::{Axis, Elementary, FixedTransform, JointId, JointKind, JointMotion, KinematicTree};

use super::angle::LinearAngle;
use super::graph::ExprGraph;
use super::step::Step;
use super::transform::const_vec;

/// The first graph variable of quaternion joint `joint`'s rotation (a floating or spherical
/// joint's; its nine entries, row-major): after the positions (`q`, `dof` of them) and the rates
/// (`qd`, `velocity_dof`), nine per quaternion joint in tree order
/// ([`KinematicTree::quaternion_joints`]).
pub fn rotation_variables(tree: &KinematicTree, joint: JointId) -> usize {
    let before = tree.quaternion_joints().take_while(|&j| j != joint).count();
    tree.dof() + tree.velocity_dof() + 9 * before
}

/// The steps of `T_parent^child` for each joint of `path`, in order:
/// `origin`, the motion (a rotation or a translation in the joint variable; for a planar joint the
/// translation in the plane then the rotation about its normal; for a floating joint the
/// translation by its position then its rotation, [`Step::Free`]; for a spherical joint that
/// rotation alone), `after_motion`.
pub fn lower_path(g: &mut ExprGraph, tree: &KinematicTree, path: &[JointId]) -> Vec<Step> {
    let mut steps = Vec::new();
    for &id in path {
        let joint = tree.joint(id);
        lower_fixed(g, &joint.origin, &mut steps);
        if let (JointKind::Planar | JointKind::Floating | JointKind::Spherical, JointMotion::Dof(start)) =
            (joint.kind, joint.motion)
        {
            lower_several(g, tree, id, start, &mut steps);
            lower_fixed(g, &joint.after_motion, &mut steps);
            continue;
        }
        let value = match joint.motion {
            JointMotion::Fixed => None,
            JointMotion::Dof(dof) => Some(LinearAngle::joint(dof, 1.0, 0.0)),
            JointMotion::Mimic { dof, multiplier, offset, .. } => Some(LinearAngle::joint(dof, multiplier, offset)),
        };
        match (joint.kind, value) {
            (JointKind::Revolute | JointKind::Continuous, Some(angle)) => {
                steps.push(Step::Rotate { axis: joint.axis, angle });
            }
            (JointKind::Prismatic, Some(value)) => {
                // A linear form in one variable: its "angle" expression is the displacement.
                let d = displacement(g, &value);
                let v = std::array::from_fn(|i| {
                    let k = g.constant(joint.axis[i]);
                    g.mul(k, d)
                });
                steps.push(Step::Translate(v));
            }
            _ => {}
        }
        lower_fixed(g, &joint.after_motion, &mut steps);
    }
    steps
}

/// The motion of a planar, floating or spherical joint whose entries of `q` start at `start`.
fn lower_several(g: &mut ExprGraph, tree: &KinematicTree, id: JointId, start: usize, steps: &mut Vec<Step>) {
    let joint = tree.joint(id);
    if joint.kind == JointKind::Planar {
        let (e1, e2) = joint.plane_axes();
        let (x, y) = (g.var(start), g.var(start + 1));
        let v = std::array::from_fn(|i| {
            let (k1, k2) = (g.constant(e1[i]), g.constant(e2[i]));
            let (a, b) = (g.mul(k1, x), g.mul(k2, y));
            g.add(a, b)
        });
        steps.push(Step::Translate(v));
        steps.push(Step::Rotate { axis: joint.axis, angle: LinearAngle::joint(start + 2, 1.0, 0.0) });
        return;
    }
    let translates = joint.kind == JointKind::Floating;
    if translates {
        steps.push(Step::Translate([g.var(start), g.var(start + 1), g.var(start + 2)]));
    }
    let first = rotation_variables(tree, id);
    let rotation = std::array::from_fn(|i| std::array::from_fn(|j| g.var(first + 3 * i + j)));
    #[allow(clippy::expect_used, reason = "an invariant of the model: an independent joint has velocities")]
    let column = tree.velocity_start(id).expect("an independent quaternion joint has a first velocity");
    steps.push(Step::Free { rotation, column, translates, inverted: false });
}

fn displacement(g: &mut ExprGraph, value: &LinearAngle) -> super::graph::ExprId {
    let mut sum = g.constant(value.constant_radians());
    for &(dof, k) in value.terms() {
        let q = g.var(dof);
        let k = g.constant(k);
        let kq = g.mul(k, q);
        sum = g.add(kq, sum);
    }
    sum
}

/// The steps of a fixed transform (its translations and rotations by constant angles, exact ones
/// kept exact), appended to `steps`.
pub(crate) fn lower_fixed(g: &mut ExprGraph, t: &FixedTransform, steps: &mut Vec<Step>) {
    for step in t.steps() {
        match *step {
            Elementary::Translation(v) => steps.push(Step::Translate(const_vec(g, v))),
            Elementary::Rotation(axis, angle) => {
                let axis = match axis {
                    Axis::X => [1.0, 0.0, 0.0],
                    Axis::Y => [0.0, 1.0, 0.0],
                    Axis::Z => [0.0, 0.0, 1.0],
                };
                steps.push(Step::Rotate { axis, angle: LinearAngle::constant(angle) });
            }
        }
    }
}
