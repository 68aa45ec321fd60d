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
        let mut jac = Matrix6xX::zeros(self.tree().dof());
        for &joint_id in &chain.joints {
            let joint = self.tree().joint(joint_id);
            let (dof, rate) = match joint.motion {
                JointMotion::Fixed => continue,
                JointMotion::Dof(i) => (i, 1.0),
                JointMotion::Mimic { dof, multiplier, .. } => (dof, multiplier),
            };
            let frame = self.joint_frame(&poses, joint_id.0);
            let z = frame.rotation * Vector3::new(joint.axis[0], joint.axis[1], joint.axis[2]);
            let o = frame.translation.vector;
            let (linear, angular) = match joint.kind {
                JointKind::Prismatic => (z, Vector3::zeros()),
                JointKind::Revolute | JointKind::Continuous => (z.cross(&(p - o)), z),
                JointKind::Fixed => continue,
            };
            let linear = base_rotation_inv * linear * rate;
            let angular = base_rotation_inv * angular * rate;
            for r in 0..3 {
                jac[(r, dof)] += linear[r];
                jac[(r + 3, dof)] += angular[r];
            }
        }
        Ok(jac)
    }
}
