//! Each joint at a configuration (Featherstone ch. 4, the joint models of §4.4): the transform
//! from its parent link's coordinates to its child's, and its motion subspace's columns in the
//! child's coordinates, each with the velocity it multiplies.

use kinematics_model::{JointKind, JointMotion};
use nalgebra::{Unit, UnitQuaternion, Vector3};

use super::ReferenceDynamics;
use super::spatial::{Plucker, Spatial, spatial};

/// One joint at `q`.
pub(super) struct JointAt {
    /// Parent link's coordinates to the child link's (`origin * M(q) * after`).
    pub(super) x: Plucker,
    /// The columns of the motion subspace `S` in the child's coordinates, each with the index of
    /// the velocity that multiplies it: a mimic joint's one column is its multiplier times its
    /// own, on its source's velocity.
    pub(super) columns: Vec<(usize, Spatial)>,
    /// The derivative of the columns along the joint's own positions, `(k, l, dS_k/dq_l)` in the
    /// child's coordinates (velocities `k` and `l`): the velocity-product term `c_J = S' qd` is
    /// the sum of `dS_k/dq_l v_l v_k`. Only a planar joint's subspace depends on its position.
    pub(super) curvature: Vec<(usize, usize, Spatial)>,
}

impl JointAt {
    /// `S v`: the joint's velocity (or, given accelerations, `S a`).
    pub(super) fn times(&self, v: &[f64]) -> Spatial {
        self.columns.iter().map(|(k, s)| s * v[*k]).sum()
    }

    /// `c_J = S' v`, the apparent derivative of `S` in the child's coordinates times `v`.
    pub(super) fn velocity_product(&self, v: &[f64]) -> Spatial {
        self.curvature.iter().map(|(k, l, ds)| ds * (v[*k] * v[*l])).sum()
    }
}

impl ReferenceDynamics {
    /// Joint `index` of the tree at `q` (checked).
    pub(super) fn joint_at(&self, index: usize, q: &[f64]) -> JointAt {
        let joint = &self.fk.tree().joints()[index];
        let (values, velocity, multiplier) = match joint.motion {
            JointMotion::Fixed => (Vec::new(), 0, 0.0),
            JointMotion::Dof(dof) => (q[dof..dof + joint.kind.positions()].to_vec(), self.velocity[index], 1.0),
            JointMotion::Mimic { dof, multiplier, offset, .. } => {
                (vec![multiplier * q[dof] + offset], self.velocity[index], multiplier)
            }
        };
        let motion =
            if values.is_empty() { nalgebra::Isometry3::identity() } else { self.fk.motion(index, joint, &values) };
        let x = Plucker::from_pose(&(self.origins[index] * motion * self.afters[index]));
        // The subspace is written in the moved joint frame (after `M(q)`, before `after`), the
        // child's coordinates one constant transform away.
        let after = Plucker::from_pose(&self.afters[index]);
        let axis = Unit::new_normalize(Vector3::from(joint.axis)).into_inner();
        let zero = Vector3::zeros();
        let unit = |k: usize| Vector3::ith(k, 1.0);
        let (moved, curvature): (Vec<Spatial>, Vec<(usize, usize, Spatial)>) = match joint.kind {
            JointKind::Fixed => (Vec::new(), Vec::new()),
            JointKind::Revolute | JointKind::Continuous => (vec![spatial(axis, zero)], Vec::new()),
            JointKind::Prismatic => (vec![spatial(zero, axis)], Vec::new()),
            JointKind::Planar => {
                // The child's origin slides along e1 and e2 of the joint frame (fixed in the
                // parent) and turns by theta about the normal: in the moved frame the slides are
                // `R^T e1`, `R^T e2`, whose derivative along theta is `-n x R^T e`.
                let (e1, e2) = joint.plane_axes();
                let turn = UnitQuaternion::from_axis_angle(&Unit::new_unchecked(axis), values[2]).inverse();
                let (e1, e2) = (turn * Vector3::from(e1), turn * Vector3::from(e2));
                let moved = vec![spatial(zero, e1), spatial(zero, e2), spatial(axis, zero)];
                let curvature = vec![(0, 2, spatial(zero, -axis.cross(&e1))), (1, 2, spatial(zero, -axis.cross(&e2)))];
                (moved, curvature)
            }
            // Pinocchio's free-flyer: the moved frame's linear then angular velocity, in its own
            // axes; constant there, so no velocity-product term.
            JointKind::Floating => (
                (0..3).map(|k| spatial(zero, unit(k))).chain((0..3).map(|k| spatial(unit(k), zero))).collect(),
                Vec::new(),
            ),
            JointKind::Spherical => ((0..3).map(|k| spatial(unit(k), zero)).collect(), Vec::new()),
        };
        let columns = moved.iter().enumerate().map(|(k, s)| (velocity + k, after.motion(s) * multiplier)).collect();
        let curvature = curvature
            .into_iter()
            .map(|(k, l, ds)| (velocity + k, velocity + l, after.motion(&ds) * multiplier))
            .collect();
        JointAt { x, columns, curvature }
    }
}
