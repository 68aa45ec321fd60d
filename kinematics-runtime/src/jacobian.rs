//! The geometric Jacobian of a chain (reference notes, Velocity).

use kinematics_model::{JointKind, JointMotion};
use nalgebra::{Matrix6xX, Vector3};

use crate::error::RuntimeError;
use crate::fk::ReferenceFk;

impl ReferenceFk {
    /// The geometric Jacobian of the chain from link `base` to link `tip`, at `q`.
    ///
    /// A 6 x dof matrix, one column per degree of freedom of the whole tree (columns of joints off
    /// the chain are zero): rows 0..3 the linear velocity of the tip origin, rows 3..6 the angular
    /// velocity, both relative to and expressed in the `base` frame. A revolute joint contributes
    /// `[z x (p - o); z]`, a prismatic one `[z; 0]` (z, o: the joint axis and origin); a mimic joint
    /// adds its multiplier times that to its source's column.
    ///
    /// ```
    /// use kinematics_runtime::ReferenceFk;
    /// let dh = "convention = \"standard\"\n[[joints]]\nname = \"j1\"\na = 2.0\n";
    /// let fk = ReferenceFk::new(kinematics_model::parse_source("arm.toml", dh)?);
    /// let j = fk.jacobian(&[0.0], "base", "link1")?;
    /// // Rotating about z moves the tip at (2, 0, 0) along +y at 2 m/rad.
    /// assert!((j[(1, 0)] - 2.0).abs() < 1e-12 && (j[(5, 0)] - 1.0).abs() < 1e-12);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn jacobian(&self, q: &[f64], base: &str, tip: &str) -> Result<Matrix6xX<f64>, RuntimeError> {
        let chain = self.tree().chain(base, tip).map_err(|e| self.model_error(e))?;
        let poses = self.link_poses(q)?;
        let base_rotation_inv = poses[chain.base.0].rotation.inverse();
        let p = poses[chain.tip.0].translation.vector;
        let tree = self.tree();
        let velocity_of_entry = tree.velocity_of_entry();
        let mut jac = Matrix6xX::zeros(tree.velocity_dof());
        let mut add = |column: usize, linear: Vector3<f64>, angular: Vector3<f64>| {
            let (linear, angular) = (base_rotation_inv * linear, base_rotation_inv * angular);
            for r in 0..3 {
                jac[(r, column)] += linear[r];
                jac[(r + 3, column)] += angular[r];
            }
        };
        for &joint_id in &chain.joints {
            let joint = tree.joint(joint_id);
            let (column, rate) = match joint.motion {
                JointMotion::Fixed => continue,
                JointMotion::Dof(_) => match tree.velocity_start(joint_id) {
                    Some(column) => (column, 1.0),
                    None => continue,
                },
                JointMotion::Mimic { dof, multiplier, .. } => match velocity_of_entry[dof] {
                    Some(column) => (column, multiplier),
                    None => continue,
                },
            };
            let frame = self.joint_frame(&poses, joint_id.0);
            let moved = self.moved_frame(&poses, joint_id.0);
            let vector = |v: [f64; 3]| Vector3::new(v[0], v[1], v[2]);
            let z = frame.rotation * vector(joint.axis);
            // Turning about `axis` through `origin` moves the tip origin by `axis x (p - origin)`.
            let turn = |axis: Vector3<f64>, origin: Vector3<f64>| (axis.cross(&(p - origin)), axis);
            match joint.kind {
                JointKind::Fixed => continue,
                JointKind::Prismatic => add(column, z * rate, Vector3::zeros()),
                JointKind::Revolute | JointKind::Continuous => {
                    let (linear, angular) = turn(z, frame.translation.vector);
                    add(column, linear * rate, angular * rate);
                }
                JointKind::Planar => {
                    let (e1, e2) = joint.plane_axes();
                    add(column, frame.rotation * vector(e1), Vector3::zeros());
                    add(column + 1, frame.rotation * vector(e2), Vector3::zeros());
                    // The rotation turns about the normal through the translated origin.
                    let (linear, angular) = turn(z, moved.translation.vector);
                    add(column + 2, linear, angular);
                }
                JointKind::Floating => {
                    // Pinocchio's free-flyer: the velocities are the child's, in its own axes.
                    for k in 0..3 {
                        let e = moved.rotation * Vector3::ith(k, 1.0);
                        add(column + k, e, Vector3::zeros());
                        let (linear, angular) = turn(e, moved.translation.vector);
                        add(column + 3 + k, linear, angular);
                    }
                }
            }
        }
        Ok(jac)
    }
}
