//! What the generated solvers take as a target: a [`Pose`], or (feature `nalgebra`) an
//! `nalgebra::Isometry3`, so a caller holding either passes it as it is.

use crate::pose::Pose;

/// A target pose of the tip, in the base frame, as the generated `tip_ik`, `tip_ik_nearest`,
/// `tip_ik_within_limits` and `tip_ik_numeric` take it: [`Pose<f64>`] and, with the feature
/// `nalgebra`, `nalgebra::Isometry3<f64>`. Whatever the type, the solvers check the pose it gives
/// ([`check_target`](super::check_target)): a non-finite entry or a rotation that is not one is an
/// [`IkError`](super::IkError), never a wrong answer.
///
/// ```
/// use kinematics_core::Pose;
/// use kinematics_core::ik::IkTarget;
/// let pose = Pose { rotation: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], translation: [0.5, 0.0, 0.2] };
/// assert_eq!(pose.target_pose(), pose);
/// ```
pub trait IkTarget {
    /// The target as the rotation rows and translation the solvers read.
    fn target_pose(&self) -> Pose<f64>;
}

impl IkTarget for Pose<f64> {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn target_pose(&self) -> Pose<f64> {
        *self
    }
}

/// An isometry's rotation (its unit quaternion as a matrix) and translation.
///
/// ```
/// use kinematics_core::ik::IkTarget;
/// use nalgebra::{Isometry3, Vector3};
/// let iso = Isometry3::new(Vector3::new(0.4, -0.1, 0.3), Vector3::new(0.0, 0.0, 0.5));
/// let pose = iso.target_pose();
/// assert_eq!(pose.translation, [0.4, -0.1, 0.3]);
/// assert!((pose.rotation[0][0] - 0.5f64.cos()).abs() < 1e-15);
/// ```
#[cfg(feature = "nalgebra")]
#[cfg_attr(docsrs, doc(cfg(feature = "nalgebra")))]
impl IkTarget for ::nalgebra::Isometry3<f64> {
    #[inline]
    fn target_pose(&self) -> Pose<f64> {
        Pose::from(*self)
    }
}
