//! What generated forward dynamics needs at run time: the refusal of a singular mass matrix.
//!
//! Generated `forward_dynamics` solves `M qdd = tau - h` by the `L^T D L` factorisation of the
//! mass matrix and returns its pivots `D` beside the accelerations; [`accelerations_checked`]
//! turns them into the accelerations or the error naming the velocity whose pivot vanished,
//! never the infinities or NaN a division by a zero pivot gives.

use crate::error::KinematicsError;

/// How small a pivot of the mass matrix's factorisation may be, relative to the largest, before
/// the matrix is taken as singular: the runtime reference's ratio for its eigenvalues
/// (`ReferenceDynamics::SINGULAR_RATIO`), far below any real robot's (a wrist's pivot is about a
/// thousandth of the shoulder's) and far above rounding's (about `n * f64::EPSILON`).
pub const SINGULAR_RATIO: f64 = 1e-12;

/// The accelerations; or [`KinematicsError::NotFinite`] when a pivot is not finite (the mass
/// matrix overflowed, or `q` held a NaN); or [`KinematicsError::SingularMassMatrix`] naming the
/// first velocity (in `names`' order) whose pivot is not above [`SINGULAR_RATIO`] of the largest;
/// or [`KinematicsError::NotFinite`] when an acceleration is not finite.
///
/// ```
/// use kinematics_core::{KinematicsError, dynamics::accelerations_checked};
/// const NAMES: [&str; 2] = ["shoulder", "wrist"];
/// let names = &NAMES;
/// assert_eq!(accelerations_checked("arm", names, [1.0, 2.0], [0.5, 0.01]), Ok([1.0, 2.0]));
/// assert_eq!(
///     accelerations_checked("arm", names, [1.0, f64::NAN], [0.5, 0.0]),
///     Err(KinematicsError::SingularMassMatrix { robot: "arm", velocity: "wrist" })
/// );
/// assert!(matches!(
///     accelerations_checked("arm", names, [1.0, 2.0], [f64::NAN, 1.0]),
///     Err(KinematicsError::NotFinite { .. })
/// ));
/// ```
pub fn accelerations_checked<T: Copy + Into<f64>, const N: usize>(
    robot: &'static str,
    names: &'static [&'static str; N],
    accelerations: [T; N],
    pivots: [T; N],
) -> Result<[T; N], KinematicsError> {
    let pivots: [f64; N] = pivots.map(Into::into);
    if pivots.iter().any(|p| !p.is_finite()) {
        return Err(KinematicsError::NotFinite { robot, quantity: "mass matrix" });
    }
    let largest = pivots.iter().fold(0.0f64, |m, p| m.max(p.abs()));
    if let Some(k) = pivots.iter().position(|&p| p <= SINGULAR_RATIO * largest) {
        return Err(KinematicsError::SingularMassMatrix { robot, velocity: names[k] });
    }
    if accelerations.iter().any(|&a| !Into::<f64>::into(a).is_finite()) {
        return Err(KinematicsError::NotFinite { robot, quantity: "forward dynamics' accelerations" });
    }
    Ok(accelerations)
}
