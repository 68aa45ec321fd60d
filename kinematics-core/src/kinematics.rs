//! The trait every compiled robot implements, so generic code can take any of them.
//!
//! The `Kinematics` trait, with `q_array` and `check_output`.

use crate::error::KinematicsError;
use crate::pose::Pose;

/// Position limits of one degree of freedom; infinite for a continuous joint.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JointLimits {
    /// Lower bound (radians or metres).
    pub lower: f64,
    /// Upper bound (radians or metres).
    pub upper: f64,
}

/// A robot whose forward kinematics was compiled (by `#[derive(Kinematics)]` or the build API).
///
/// The inherent functions the derive adds (`tip_pose`, `link_poses`, ...) take fixed-size arrays and
/// are what hot loops call; this trait offers the same computations through slices, checked, for
/// code that works with any robot. (The runtime reference of a robot, `reference()`, is the
/// facade's `ReferenceModel` trait, with the `std` feature.)
///
/// ```
/// use kinematics_core::{Kinematics, KinematicsError, Pose};
/// /// The reach of any compiled robot at a configuration: the farthest link from the base.
/// fn farthest<R: Kinematics>(q: &[f64]) -> Result<f64, KinematicsError> {
///     let mut poses = [Pose { rotation: [[0.0; 3]; 3], translation: [0.0; 3] }; 64];
///     let poses = &mut poses[..R::LINK_NAMES.len()];
///     R::link_poses_into(q, poses)?;
///     Ok(poses.iter().map(|p| p.translation.iter().map(|x| x * x).sum::<f64>()).fold(0.0, f64::max))
/// }
/// ```
pub trait Kinematics {
    /// Robot name.
    const ROBOT: &'static str;
    /// The link all poses are expressed in.
    const BASE: &'static str;
    /// Degrees of freedom: the length of `q`.
    const DOF: usize;
    /// Joint names in degree-of-freedom order.
    const JOINT_NAMES: &'static [&'static str];
    /// Position limits in degree-of-freedom order.
    const JOINT_LIMITS: &'static [JointLimits];
    /// The links `link_poses_into` computes, in order (every link but the base).
    const LINK_NAMES: &'static [&'static str];
    /// The links `tip_poses_into` computes, in order.
    const TIPS: &'static [&'static str];

    /// Poses of [`Kinematics::TIPS`] at `q`, into `out` (one per tip).
    fn tip_poses_into(q: &[f64], out: &mut [Pose<f64>]) -> Result<(), KinematicsError>;

    /// Poses of [`Kinematics::LINK_NAMES`] at `q`, into `out` (one per link).
    fn link_poses_into(q: &[f64], out: &mut [Pose<f64>]) -> Result<(), KinematicsError>;
}

/// `q` as an array of the robot's DoF, or the error naming the joints (used by generated code).
pub fn q_array<'a, const N: usize>(
    robot: &'static str,
    joints: &'static [&'static str],
    q: &'a [f64],
) -> Result<&'a [f64; N], KinematicsError> {
    q.try_into().map_err(|_| KinematicsError::WrongDof { robot, expected: N, got: q.len(), joints })
}

/// Checks that an output slice holds one value per computed frame (or per configuration of a
/// batch); used by generated code.
pub fn check_output(robot: &'static str, expected: usize, got: usize) -> Result<(), KinematicsError> {
    if expected == got {
        return Ok(());
    }
    Err(KinematicsError::WrongOutputLength { robot, expected, got })
}
