//! Forward kinematics over the tree: `T_world^child = T_world^parent * origin * M(q) * after`.

use kinematics_model::{Elementary, FixedTransform, Joint, JointKind, JointMotion, KinematicTree, LinkId};
use nalgebra::{Isometry3, Quaternion, Translation3, Unit, UnitQuaternion, Vector3};

use crate::error::RuntimeError;

/// The reference forward kinematics of one robot.
///
/// Built once from a validated tree; the fixed transforms are converted to isometries up front, and
/// every query walks the links in the tree's depth-first order (parents before children).
#[derive(Debug, Clone)]
pub struct ReferenceFk {
    tree: KinematicTree,
    origins: Vec<Isometry3<f64>>,
    afters: Vec<Isometry3<f64>>,
    axes: Vec<Unit<Vector3<f64>>>,
}

/// The isometry of a fixed transform: the product of its steps, left to right.
///
/// ```
/// use kinematics_model::{Angle, FixedTransform};
/// let urdf_origin = FixedTransform::from_xyz_rpy([1.0, 2.0, 3.0], [Angle::Radians(0.1), Angle::Radians(0.2), Angle::Radians(0.3)]);
/// let iso = kinematics_runtime::fixed_isometry(&urdf_origin);
/// let expected = nalgebra::Isometry3::from_parts(
///     nalgebra::Translation3::new(1.0, 2.0, 3.0),
///     nalgebra::UnitQuaternion::from_euler_angles(0.1, 0.2, 0.3),
/// );
/// approx::assert_relative_eq!(iso, expected, epsilon = 1e-15);
/// ```
pub fn fixed_isometry(t: &FixedTransform) -> Isometry3<f64> {
    t.steps().iter().fold(Isometry3::identity(), |acc, step| acc * elementary(step))
}

fn elementary(step: &Elementary) -> Isometry3<f64> {
    match *step {
        Elementary::Translation(v) => {
            Isometry3::from_parts(Translation3::new(v[0], v[1], v[2]), UnitQuaternion::identity())
        }
        Elementary::Rotation(axis, angle) => {
            let axis = match axis {
                kinematics_model::Axis::X => Vector3::x_axis(),
                kinematics_model::Axis::Y => Vector3::y_axis(),
                kinematics_model::Axis::Z => Vector3::z_axis(),
            };
            Isometry3::from_parts(Translation3::identity(), UnitQuaternion::from_axis_angle(&axis, angle.radians()))
        }
    }
}

impl ReferenceFk {
    /// Prepares the reference FK of a tree.
    pub fn new(tree: KinematicTree) -> Self {
        let origins = tree.joints().iter().map(|j| fixed_isometry(&j.origin)).collect();
        let afters = tree.joints().iter().map(|j| fixed_isometry(&j.after_motion)).collect();
        let axes =
            tree.joints().iter().map(|j| Unit::new_normalize(Vector3::new(j.axis[0], j.axis[1], j.axis[2]))).collect();
        Self { tree, origins, afters, axes }
    }

    /// The tree this evaluates.
    pub fn tree(&self) -> &KinematicTree {
        &self.tree
    }

    /// Fails unless `q` has one value per degree of freedom, each a finite number (the error
    /// names the first joint whose value is NaN or infinite).
    ///
    /// ```
    /// use kinematics_runtime::{ReferenceFk, RuntimeError};
    /// let dh = "convention = \"standard\"\n[[joints]]\nname = \"j1\"\na = 2.0\n";
    /// let fk = ReferenceFk::new(kinematics_model::parse_source("arm.toml", dh)?);
    /// assert!(fk.check_q(&[0.5]).is_ok());
    /// let err = fk.link_poses(&[f64::NAN]).unwrap_err();
    /// assert_eq!(err.to_string(), "robot `robot`: the value of joint `j1` (q[0]) is NaN, not a finite number");
    /// assert!(matches!(fk.jacobian(&[f64::INFINITY], "base", "link1"), Err(RuntimeError::NonFiniteValue { .. })));
    /// assert!(matches!(fk.relative_pose(&[-f64::INFINITY], "link1", "base"), Err(RuntimeError::NonFiniteValue { .. })));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn check_q(&self, q: &[f64]) -> Result<(), RuntimeError> {
        if q.len() != self.tree.dof() {
            return Err(RuntimeError::WrongDof {
                robot: self.tree.name().to_owned(),
                expected: self.tree.dof(),
                got: q.len(),
                joints: self.tree.dof_names().join(", "),
            });
        }
        if let Some(index) = q.iter().position(|v| !v.is_finite()) {
            return Err(RuntimeError::NonFiniteValue {
                robot: self.tree.name().to_owned(),
                joint: self.tree.joint(self.tree.dof_joints()[index]).name.clone(),
                index,
                value: q[index],
            });
        }
        // A floating or spherical joint's quaternion is normalised, so it must have a length to
        // normalise.
        for (joint, start) in self.tree.quaternion_joints().zip(self.tree.quaternion_entries()) {
            let squared: f64 = q[start..start + 4].iter().map(|v| v * v).sum();
            if !(squared.is_normal()) {
                return Err(RuntimeError::DegenerateQuaternion {
                    robot: self.tree.name().to_owned(),
                    joint: self.tree.joint(joint).name.clone(),
                    kind: self.tree.joint(joint).kind.name(),
                    index: start,
                });
            }
        }
        Ok(())
    }

    /// The id of a link, or an error naming it.
    pub fn link_id(&self, name: &str) -> Result<LinkId, RuntimeError> {
        self.tree
            .link_id(name)
            .ok_or_else(|| self.model_error(kinematics_model::ModelError::NoSuchLink(name.to_owned())))
    }

    pub(crate) fn model_error(&self, source: kinematics_model::ModelError) -> RuntimeError {
        RuntimeError::Model { robot: self.tree.name().to_owned(), source }
    }

    /// The motion `M(values)` of a joint: its entries of `q` (one, or a planar joint's three, a
    /// spherical joint's four, a floating joint's seven).
    pub(crate) fn motion(&self, index: usize, joint: &Joint, values: &[f64]) -> Isometry3<f64> {
        let axis = self.axes[index];
        let value = values[0];
        match joint.kind {
            JointKind::Planar => {
                let (e1, e2) = joint.plane_axes();
                let along = |e: [f64; 3], v: f64| Vector3::new(e[0], e[1], e[2]) * v;
                Isometry3::from_parts(
                    Translation3::from(along(e1, values[0]) + along(e2, values[1])),
                    UnitQuaternion::from_axis_angle(&axis, values[2]),
                )
            }
            JointKind::Floating => Isometry3::from_parts(
                Translation3::new(values[0], values[1], values[2]),
                // Pinocchio's order in `q`: x, y, z, w; nalgebra's constructor takes w first.
                UnitQuaternion::from_quaternion(Quaternion::new(values[6], values[3], values[4], values[5])),
            ),
            // The same order and normalisation, without the position.
            JointKind::Spherical => Isometry3::from_parts(
                Translation3::identity(),
                UnitQuaternion::from_quaternion(Quaternion::new(values[3], values[0], values[1], values[2])),
            ),
            JointKind::Revolute | JointKind::Continuous => {
                Isometry3::from_parts(Translation3::identity(), UnitQuaternion::from_axis_angle(&axis, value))
            }
            JointKind::Prismatic => {
                Isometry3::from_parts(Translation3::from(axis.into_inner() * value), UnitQuaternion::identity())
            }
            JointKind::Fixed => Isometry3::identity(),
        }
    }

    /// The frame of joint `index` before its motion: `T_world^parent * origin`.
    pub(crate) fn joint_frame(&self, poses: &[Isometry3<f64>], index: usize) -> Isometry3<f64> {
        poses[self.tree.joints()[index].parent.0] * self.origins[index]
    }

    /// The frame of joint `index` after its motion: `T_world^parent * origin * M(q)`, from the
    /// child link's pose.
    pub(crate) fn moved_frame(&self, poses: &[Isometry3<f64>], index: usize) -> Isometry3<f64> {
        poses[self.tree.joints()[index].child.0] * self.afters[index].inverse()
    }

    /// World pose of every link, indexed by [`LinkId`] (the tree's link order).
    pub fn link_poses(&self, q: &[f64]) -> Result<Vec<Isometry3<f64>>, RuntimeError> {
        self.check_q(q)?;
        let mut poses = vec![Isometry3::identity(); self.tree.links().len()];
        for (i, joint) in self.tree.joints().iter().enumerate() {
            // `check_q` gave `q` one value per degree of freedom, so every moving joint has one.
            let motion = match joint.motion {
                JointMotion::Fixed => Isometry3::identity(),
                JointMotion::Dof(dof) => self.motion(i, joint, &q[dof..dof + joint.kind.positions()]),
                JointMotion::Mimic { dof, multiplier, offset, .. } => {
                    self.motion(i, joint, &[multiplier * q[dof] + offset])
                }
            };
            poses[joint.child.0] = self.joint_frame(&poses, i) * motion * self.afters[i];
        }
        Ok(poses)
    }

    /// World pose of the link named `link`.
    pub fn link_pose(&self, q: &[f64], link: &str) -> Result<Isometry3<f64>, RuntimeError> {
        let id = self.link_id(link)?;
        Ok(self.link_poses(q)?[id.0])
    }

    /// Pose of link `tip` in the frame of link `base` (`base` need not be an ancestor).
    pub fn relative_pose(&self, q: &[f64], base: &str, tip: &str) -> Result<Isometry3<f64>, RuntimeError> {
        let (b, t) = (self.link_id(base)?, self.link_id(tip)?);
        let poses = self.link_poses(q)?;
        Ok(poses[b.0].inverse() * poses[t.0])
    }
}
