//! The runtime side of a compiled robot: its reference model.
//!
//! `ReferenceModel` is the trait of a compiled robot whose reference can be built (`reference()`),
//! which generated code implements with the `std` feature.

use crate::fk::ReferenceFk;
use kinematics_core::Kinematics;

/// A compiled robot whose runtime reference model can be built: the same description, read the
/// same way, evaluated by [`ReferenceFk`]. Generated code implements it (with the facade's `std`
/// feature), beside the inherent `reference()` it calls.
///
/// ```
/// use kinematics_runtime::{Kinematics, ReferenceModel};
/// /// How far the first tip of any compiled robot is from its reference at `q`.
/// fn tip_error<R: ReferenceModel>(q: &[f64]) -> Result<f64, Box<dyn std::error::Error>> {
///     let mut out = vec![kinematics_runtime::Pose { rotation: [[0.0; 3]; 3], translation: [0.0; 3] }; R::TIPS.len()];
///     R::tip_poses_into(q, &mut out)?;
///     let reference = R::reference()?;
///     let expected = reference.relative_pose(q, R::BASE, R::TIPS[0])?;
///     Ok(out[0].deviation(&expected, reference.tree().reach()))
/// }
/// ```
pub trait ReferenceModel: Kinematics {
    /// The runtime reference model of the same robot, for checking and for tools.
    fn reference() -> Result<ReferenceFk, kinematics_model::LoadError>;
}
