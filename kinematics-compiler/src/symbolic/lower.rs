//! Lowering: the joints on a path of the model become a product of [`Step`]s.

use kinematics_model::{Axis, Elementary, FixedTransform, JointId, JointKind, JointMotion, KinematicTree};

use super::angle::LinearAngle;
use super::graph::ExprGraph;
use super::step::Step;
use super::transform::const_vec;

/// The steps of `T_parent^child` for each joint of `path`, in order:
/// `origin`, the motion (a rotation or a translation in the joint variable), `after_motion`.
pub fn lower_path(g: &mut ExprGraph, tree: &KinematicTree, path: &[JointId]) -> Vec<Step> {
    let mut steps = Vec::new();
    for &id in path {
        let joint = tree.joint(id);
        lower_fixed(g, &joint.origin, &mut steps);
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

fn lower_fixed(g: &mut ExprGraph, t: &FixedTransform, steps: &mut Vec<Step>) {
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
