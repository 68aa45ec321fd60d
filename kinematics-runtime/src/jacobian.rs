//! The geometric Jacobian of one link's pose relative to any other (reference notes, Velocity),
//! in Pinocchio's `LOCAL_WORLD_ALIGNED` or `LOCAL` axes.

use kinematics_model::{JacobianFrame, JointKind, JointMotion};
use nalgebra::{Matrix6xX, Vector3};

use crate::error::RuntimeError;
use crate::fk::ReferenceFk;

impl ReferenceFk {
    /// The geometric Jacobian of the pose of link `tip` relative to link `base`, at `q`, in the
    /// base's axes (Pinocchio's `LOCAL_WORLD_ALIGNED`): [`ReferenceFk::jacobian_in`].
    ///
    /// ```
    /// use kinematics_runtime::ReferenceFk;
    /// let dh = "convention = \"standard\"\n[[joints]]\nname = \"j1\"\na = 2.0\n";
    /// let fk = ReferenceFk::new(kinematics_model::parse_source("arm.toml", dh)?);
    /// let j = fk.jacobian(&[0.0], "base", "link1")?;
    /// // Rotating about z moves the tip at (2, 0, 0) along +y at 2 m/rad.
    /// assert!((j[(1, 0)] - 2.0).abs() < 1e-12 && (j[(5, 0)] - 1.0).abs() < 1e-12);
    /// // Seen from the tip, the base turns the other way about the same axis, which passes
    /// // through the base's origin: that origin does not move.
    /// let back = fk.jacobian(&[0.0], "link1", "base")?;
    /// assert!(back.fixed_rows::<3>(0).iter().all(|v| v.abs() < 1e-12) && (back[(5, 0)] + 1.0).abs() < 1e-12);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn jacobian(&self, q: &[f64], base: &str, tip: &str) -> Result<Matrix6xX<f64>, RuntimeError> {
        self.jacobian_in(q, base, tip, JacobianFrame::LocalWorldAligned)
    }

    /// The geometric Jacobian of the pose of link `tip` relative to link `base` (any two links), at
    /// `q`, its rows in `frame`'s axes.
    ///
    /// A 6 x `velocity_dof` matrix, one column per velocity of the tree (columns of joints off the
    /// path from `base` to `tip` are zero): rows 0..3 the velocity of the tip's origin relative to
    /// the base, rows 3..6 the angular velocity, in the base's axes (`LocalWorldAligned`: the
    /// derivative of the relative pose's translation, and `w` with `dR/dt = [w]x R`) or the tip's
    /// (`Local`: `R^T` times each). A revolute or continuous joint with axis `z` through `o`
    /// contributes `[z x (p - o); z]`, a prismatic one `[z; 0]` (`p`: the tip's origin), a planar
    /// joint its two translations and its rotation, a floating joint the child's six (Pinocchio's
    /// free-flyer: linear then angular velocity in the child's axes), a spherical joint the
    /// child's three angular ones (in its axes, about the joint's origin), and a mimic joint its
    /// multiplier times that, added to its source's column. The path goes up from the base to the
    /// two links' nearest common ancestor and down to the tip: a joint on the way up moves the base,
    /// not the tip, and contributes with the opposite sign; joints above the common ancestor move
    /// both and contribute nothing.
    pub fn jacobian_in(
        &self,
        q: &[f64],
        base: &str,
        tip: &str,
        frame: JacobianFrame,
    ) -> Result<Matrix6xX<f64>, RuntimeError> {
        let (base_id, tip_id) = (self.link_id(base)?, self.link_id(tip)?);
        let poses = self.link_poses(q)?;
        let tree = self.tree();
        let (to_base, to_tip) = (tree.path_from_root(base_id), tree.path_from_root(tip_id));
        let common = to_base.iter().zip(&to_tip).take_while(|(a, b)| a == b).count();
        let sided = to_tip[common..].iter().map(|&j| (j, 1.0)).chain(to_base[common..].iter().map(|&j| (j, -1.0)));
        let axes = match frame {
            JacobianFrame::LocalWorldAligned => poses[base_id.0].rotation,
            JacobianFrame::Local => poses[tip_id.0].rotation,
        }
        .inverse();
        let p = poses[tip_id.0].translation.vector;
        let velocity_of_entry = tree.velocity_of_entry();
        let mut jac = Matrix6xX::zeros(tree.velocity_dof());
        let mut add = |column: usize, linear: Vector3<f64>, angular: Vector3<f64>| {
            let (linear, angular) = (axes * linear, axes * angular);
            for r in 0..3 {
                jac[(r, column)] += linear[r];
                jac[(r + 3, column)] += angular[r];
            }
        };
        for (joint_id, side) in sided {
            let joint = tree.joint(joint_id);
            let (column, rate) = match joint.motion {
                JointMotion::Fixed => continue,
                JointMotion::Dof(_) => match tree.velocity_start(joint_id) {
                    Some(column) => (column, side),
                    None => continue,
                },
                JointMotion::Mimic { dof, multiplier, .. } => match velocity_of_entry[dof] {
                    Some(column) => (column, side * multiplier),
                    None => continue,
                },
            };
            let frame = self.joint_frame(&poses, joint_id.0);
            let moved = self.moved_frame(&poses, joint_id.0);
            let vector = |v: [f64; 3]| Vector3::new(v[0], v[1], v[2]);
            let z = frame.rotation * vector(joint.axis);
            // Turning about `axis` through `origin` moves the tip's origin by `axis x (p - origin)`.
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
                    add(column, frame.rotation * vector(e1) * rate, Vector3::zeros());
                    add(column + 1, frame.rotation * vector(e2) * rate, Vector3::zeros());
                    // The rotation turns about the normal through the translated origin.
                    let (linear, angular) = turn(z, moved.translation.vector);
                    add(column + 2, linear * rate, angular * rate);
                }
                JointKind::Floating => {
                    // Pinocchio's free-flyer: the velocities are the child's, in its own axes.
                    for k in 0..3 {
                        let e = moved.rotation * Vector3::ith(k, 1.0);
                        add(column + k, e * rate, Vector3::zeros());
                        let (linear, angular) = turn(e, moved.translation.vector);
                        add(column + 3 + k, linear * rate, angular * rate);
                    }
                }
                JointKind::Spherical => {
                    // Pinocchio's spherical joint: the child's angular velocity in its own axes,
                    // about the joint's origin (which the rotation leaves where it is).
                    for k in 0..3 {
                        let e = moved.rotation * Vector3::ith(k, 1.0);
                        let (linear, angular) = turn(e, moved.translation.vector);
                        add(column + k, linear * rate, angular * rate);
                    }
                }
            }
        }
        Ok(jac)
    }
}
