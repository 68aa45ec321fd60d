//! The rotation of a floating or spherical joint, from the quaternion in `q`.
//!
//! `quaternion_matrix` gives the rotation of the joint's quaternion, normalised by dividing by its
//! squared length; generated code calls it first.

use crate::real::Real;

/// The rotation matrix (row-major) of the quaternion `x i + y j + z k + w` normalised: generated
/// code calls it for each floating or spherical joint, with the joint's entries `qx, qy, qz, qw`
/// of `q`.
///
/// The quaternion need not have unit length: dividing by its squared length gives the rotation
/// of the unit quaternion along it, exactly as normalising first would (up to rounding). A zero
/// quaternion has no rotation: its entries come out NaN (the runtime reference refuses it with an
/// error), never a made-up rotation.
///
/// ```
/// use kinematics_core::quaternion_matrix;
/// // A quarter turn about z, the quaternion scaled by 3: x maps to y.
/// let h = 3.0 * std::f64::consts::FRAC_1_SQRT_2;
/// let r = quaternion_matrix(0.0, 0.0, h, h);
/// assert!((r[1][0] - 1.0).abs() < 1e-15 && r[0][0].abs() < 1e-15);
/// assert!(quaternion_matrix(0.0f64, 0.0, 0.0, 0.0)[0][0].is_nan());
/// ```
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn quaternion_matrix<T: Real>(x: T, y: T, z: T, w: T) -> [[T; 3]; 3] {
    let s = T::from_f64(2.0) / (x * x + y * y + z * z + w * w);
    let one = T::from_f64(1.0);
    let (xs, ys, zs) = (x * s, y * s, z * s);
    let (xx, yy, zz) = (x * xs, y * ys, z * zs);
    let (xy, xz, yz) = (x * ys, x * zs, y * zs);
    let (wx, wy, wz) = (w * xs, w * ys, w * zs);
    [[one - (yy + zz), xy - wz, xz + wy], [xy + wz, one - (xx + zz), yz - wx], [xz - wy, yz + wx, one - (xx + yy)]]
}
