//! The orientation of a [`Pose`] in every common form, and poses built from them: unit quaternions
//! (both component orders), roll-pitch-yaw (URDF's `rpy`), ZYZ Euler angles, axis-angle and the
//! rotation vector, for `Pose<f64>` and `Pose<f32>` (`libm` does the square roots and arc
//! tangents, so this stays `no_std`).
//!
//! Conventions, and what each form does where it is singular:
//!
//! - **Quaternion** `w + x i + y j + z k` with `w >= 0` (`q` and `-q` are the same rotation; at
//!   `w == 0`, a half turn, the first non-zero of `x, y, z` is positive). Extracted by Shepperd's
//!   method (from the largest of the trace and the diagonal, so no division by a small number).
//! - **Roll-pitch-yaw**, as URDF's `rpy`: `R = Rz(yaw) Ry(pitch) Rx(roll)` (rotations about the
//!   fixed axes x, then y, then z); `pitch` in `[-pi/2, pi/2]`, `roll` and `yaw` in `[-pi, pi]`. At
//!   gimbal lock (`pitch = +-pi/2`: roll and yaw turn about the same axis) `roll` is 0 and the whole
//!   turn is in `yaw`.
//! - **ZYZ Euler angles** `[a, b, c]`: `R = Rz(a) Ry(b) Rz(c)`, `b` in `[0, pi]`, `a` and `c` in
//!   `[-pi, pi]`. At `b = 0` or `b = pi` (`a` and `c` turn about the same axis) `c` is 0.
//! - **Axis-angle** `(axis, angle)`: a unit axis and `angle` in `[0, pi]`, from the quaternion
//!   (`angle = 2 atan2(|xyz|, w)`, accurate near a half turn too); the identity has angle 0 and axis
//!   `[1, 0, 0]`; a half turn's axis follows the quaternion's sign rule. The **rotation vector** is
//!   `axis * angle` (zero for the identity).
//!
//! Constructors take any rotation the forms above give back (the round trips hold to rounding),
//! and refuse what is no rotation: a quaternion or axis of zero length, or a number that is not
//! finite, is an [`OrientationError`]. A quaternion of another length than 1 is normalised.
//!
//! ```
//! use kinematics_core::Pose;
//! let pose = Pose::<f64>::from_rpy([0.1, -0.4, 2.0], [1.0, 2.0, 3.0]);
//! let [roll, pitch, yaw] = pose.rpy();
//! assert!((roll - 0.1).abs() < 1e-15 && (pitch + 0.4).abs() < 1e-15 && (yaw - 2.0).abs() < 1e-15);
//! let [w, x, y, z] = pose.quaternion_wxyz();
//! assert_eq!(pose.quaternion_xyzw(), [x, y, z, w]);
//! let again = Pose::from_quaternion_wxyz([2.0 * w, 2.0 * x, 2.0 * y, 2.0 * z], [1.0, 2.0, 3.0])?;
//! assert!(again.rotation.iter().flatten().zip(pose.rotation.iter().flatten()).all(|(a, b)| (a - b).abs() < 1e-15));
//! # Ok::<(), kinematics_core::OrientationError>(())
//! ```

use core::fmt;

use crate::{Pose, Real};

/// A quaternion or axis that is no rotation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum OrientationError {
    /// A component is NaN or infinite.
    NotFinite,
    /// The quaternion or axis has zero length (or its squared length underflows), so it has no
    /// direction to normalise.
    ZeroLength,
}

impl fmt::Display for OrientationError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            OrientationError::NotFinite => "a component of the quaternion or axis is not a finite number",
            OrientationError::ZeroLength => "the quaternion or axis has zero length: it is no rotation",
        })
    }
}

impl core::error::Error for OrientationError {}

/// The floating-point types the orientation forms are computed in (`f64`, `f32`): what they need
/// beyond [`Real`], from `libm`. Sealed: implemented here for both, and for nothing else.
pub trait Float: Real + PartialOrd + sealed::Sealed {
    /// Below this the cosine of a middle angle counts as zero (gimbal lock): a few units in the
    /// last place, closer than which the two outer angles are not told apart by the entries.
    const SINGULAR: Self;
    /// Square root.
    fn sqrt(self) -> Self;
    /// `atan2(self, x)`.
    fn atan2(self, x: Self) -> Self;
    /// `sqrt(self^2 + y^2)` without overflow.
    fn hypot(self, y: Self) -> Self;
    /// `(sin, cos)`, by `libm`.
    fn sin_cos_of(self) -> (Self, Self);
    /// Neither NaN nor infinite.
    fn is_finite(self) -> bool;
    /// Neither zero, subnormal, NaN nor infinite.
    fn is_normal(self) -> bool;
}

mod sealed {
    pub trait Sealed {}
    impl Sealed for f64 {}
    impl Sealed for f32 {}
}

macro_rules! float {
    ($t:ident, $sqrt:path, $atan2:path, $hypot:path, $sin_cos:path) => {
        impl Float for $t {
            const SINGULAR: $t = 4.0 * $t::EPSILON;
            fn sqrt(self) -> $t {
                $sqrt(self)
            }
            fn atan2(self, x: $t) -> $t {
                $atan2(self, x)
            }
            fn hypot(self, y: $t) -> $t {
                $hypot(self, y)
            }
            fn sin_cos_of(self) -> ($t, $t) {
                $sin_cos(self)
            }
            fn is_finite(self) -> bool {
                $t::is_finite(self)
            }
            fn is_normal(self) -> bool {
                $t::is_normal(self)
            }
        }
    };
}

float!(f64, crate::real::square_root, libm::atan2, libm::hypot, libm::sincos);
float!(f32, crate::real::square_root_f32, libm::atan2f, libm::hypotf, libm::sincosf);

/// A constant in `T`.
fn c<T: Float>(x: f64) -> T {
    T::from_f64(x)
}

impl<T: Float> Pose<T> {
    /// The rotation as a unit quaternion `[w, x, y, z]` (`w >= 0`; see the module doc).
    pub fn quaternion_wxyz(&self) -> [T; 4] {
        let r = &self.rotation;
        let trace = r[0][0] + r[1][1] + r[2][2];
        // Shepperd: divide by the largest of 4w, 4x, 4y, 4z.
        let (w, x, y, z);
        if trace >= r[0][0] && trace >= r[1][1] && trace >= r[2][2] {
            let s = c::<T>(2.0) * T::sqrt(c::<T>(1.0) + trace);
            (w, x, y, z) =
                (c::<T>(0.25) * s, (r[2][1] - r[1][2]) / s, (r[0][2] - r[2][0]) / s, (r[1][0] - r[0][1]) / s);
        } else if r[0][0] >= r[1][1] && r[0][0] >= r[2][2] {
            let s = c::<T>(2.0) * T::sqrt(c::<T>(1.0) + r[0][0] - r[1][1] - r[2][2]);
            (w, x, y, z) =
                ((r[2][1] - r[1][2]) / s, c::<T>(0.25) * s, (r[0][1] + r[1][0]) / s, (r[0][2] + r[2][0]) / s);
        } else if r[1][1] >= r[2][2] {
            let s = c::<T>(2.0) * T::sqrt(c::<T>(1.0) + r[1][1] - r[0][0] - r[2][2]);
            (w, x, y, z) =
                ((r[0][2] - r[2][0]) / s, (r[0][1] + r[1][0]) / s, c::<T>(0.25) * s, (r[1][2] + r[2][1]) / s);
        } else {
            let s = c::<T>(2.0) * T::sqrt(c::<T>(1.0) + r[2][2] - r[0][0] - r[1][1]);
            (w, x, y, z) =
                ((r[1][0] - r[0][1]) / s, (r[0][2] + r[2][0]) / s, (r[1][2] + r[2][1]) / s, c::<T>(0.25) * s);
        }
        let q = [w, x, y, z];
        // One of q and -q: w >= 0, and at w == 0 the first non-zero component positive.
        let first = q.iter().copied().find(|&v| v != c::<T>(0.0)).unwrap_or(c::<T>(1.0));
        if first < c::<T>(0.0) { q.map(|v| -v) } else { q }
    }

    /// The rotation as a unit quaternion `[x, y, z, w]` (ROS's and Pinocchio's order).
    pub fn quaternion_xyzw(&self) -> [T; 4] {
        let [w, x, y, z] = self.quaternion_wxyz();
        [x, y, z, w]
    }

    /// Roll, pitch and yaw as URDF's `rpy` means them (`R = Rz(yaw) Ry(pitch) Rx(roll)`;
    /// at gimbal lock `roll` is 0, see the module doc).
    pub fn rpy(&self) -> [T; 3] {
        let r = &self.rotation;
        let cos_pitch = T::hypot(r[0][0], r[1][0]);
        let pitch = T::atan2(-r[2][0], cos_pitch);
        if cos_pitch <= T::SINGULAR {
            // Roll and yaw turn about one axis: all of it is yaw.
            return [c::<T>(0.0), pitch, T::atan2(-r[0][1], r[1][1])];
        }
        [T::atan2(r[2][1], r[2][2]), pitch, T::atan2(r[1][0], r[0][0])]
    }

    /// ZYZ Euler angles `[a, b, c]`, `R = Rz(a) Ry(b) Rz(c)` (at `b = 0` or `pi`, `c` is 0).
    pub fn euler_zyz(&self) -> [T; 3] {
        let r = &self.rotation;
        let sin_b = T::hypot(r[0][2], r[1][2]);
        let b = T::atan2(sin_b, r[2][2]);
        if sin_b <= T::SINGULAR {
            // a and c turn about one axis: all of it is a.
            return [T::atan2(-r[0][1], r[1][1]), b, c::<T>(0.0)];
        }
        [T::atan2(r[1][2], r[0][2]), b, T::atan2(r[2][1], -r[2][0])]
    }

    /// The rotation's unit axis and angle in `[0, pi]` (the identity: `[1, 0, 0]`, 0).
    pub fn axis_angle(&self) -> ([T; 3], T) {
        let [w, x, y, z] = self.quaternion_wxyz();
        let sin_half = T::sqrt(x * x + y * y + z * z);
        if sin_half == c::<T>(0.0) {
            return ([c::<T>(1.0), c::<T>(0.0), c::<T>(0.0)], c::<T>(0.0));
        }
        ([x / sin_half, y / sin_half, z / sin_half], c::<T>(2.0) * T::atan2(sin_half, w))
    }

    /// The rotation vector: the axis times the angle (zero for the identity).
    pub fn rotation_vector(&self) -> [T; 3] {
        let (axis, angle) = self.axis_angle();
        axis.map(|a| a * angle)
    }

    /// The pose with the rotation of the quaternion `[w, x, y, z]` normalised, and
    /// `translation`; an error for a quaternion of zero length or with a component that is
    /// not finite.
    pub fn from_quaternion_wxyz(q: [T; 4], translation: [T; 3]) -> Result<Self, OrientationError> {
        if !q.iter().all(|v| v.is_finite()) {
            return Err(OrientationError::NotFinite);
        }
        let norm2 = q.iter().fold(c::<T>(0.0), |sum, &v| sum + v * v);
        if !norm2.is_normal() {
            return Err(OrientationError::ZeroLength);
        }
        let [w, x, y, z] = q;
        let s = c::<T>(2.0) / norm2;
        let rotation = [
            [c::<T>(1.0) - s * (y * y + z * z), s * (x * y - z * w), s * (x * z + y * w)],
            [s * (x * y + z * w), c::<T>(1.0) - s * (x * x + z * z), s * (y * z - x * w)],
            [s * (x * z - y * w), s * (y * z + x * w), c::<T>(1.0) - s * (x * x + y * y)],
        ];
        Ok(Pose { rotation, translation })
    }

    /// [`Pose::from_quaternion_wxyz`] with the quaternion as `[x, y, z, w]`.
    pub fn from_quaternion_xyzw(q: [T; 4], translation: [T; 3]) -> Result<Self, OrientationError> {
        let [x, y, z, w] = q;
        Self::from_quaternion_wxyz([w, x, y, z], translation)
    }

    /// The pose with the rotation `Rz(yaw) Ry(pitch) Rx(roll)` (URDF's `rpy`).
    pub fn from_rpy([roll, pitch, yaw]: [T; 3], translation: [T; 3]) -> Self {
        let ((sr, cr), (sp, cp), (sy, cy)) = (T::sin_cos_of(roll), T::sin_cos_of(pitch), T::sin_cos_of(yaw));
        let rotation = [
            [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr],
        ];
        Pose { rotation, translation }
    }

    /// The pose with the rotation `Rz(a) Ry(b) Rz(c)`.
    pub fn from_euler_zyz([a, b, c]: [T; 3], translation: [T; 3]) -> Self {
        let ((sa, ca), (sb, cb), (sc, cc)) = (T::sin_cos_of(a), T::sin_cos_of(b), T::sin_cos_of(c));
        let rotation = [
            [ca * cb * cc - sa * sc, -ca * cb * sc - sa * cc, ca * sb],
            [sa * cb * cc + ca * sc, -sa * cb * sc + ca * cc, sa * sb],
            [-sb * cc, sb * sc, cb],
        ];
        Pose { rotation, translation }
    }

    /// The pose with the rotation by `angle` about `axis` (normalised); an error for an
    /// axis of zero length or a component that is not finite.
    pub fn from_axis_angle(axis: [T; 3], angle: T, translation: [T; 3]) -> Result<Self, OrientationError> {
        if !(axis.iter().all(|v| v.is_finite()) && angle.is_finite()) {
            return Err(OrientationError::NotFinite);
        }
        let norm = T::sqrt(axis.iter().fold(c::<T>(0.0), |sum, &v| sum + v * v));
        if !norm.is_normal() {
            return Err(OrientationError::ZeroLength);
        }
        let (s, c) = T::sin_cos_of(angle / c::<T>(2.0));
        let [x, y, z] = axis.map(|v| v / norm * s);
        Self::from_quaternion_wxyz([c, x, y, z], translation)
    }

    /// The pose with the rotation by `|v|` about `v` (the identity for `v = 0`); an error
    /// for a component that is not finite.
    pub fn from_rotation_vector(v: [T; 3], translation: [T; 3]) -> Result<Self, OrientationError> {
        let angle = T::sqrt(v.iter().fold(c::<T>(0.0), |sum, &x| sum + x * x));
        if !angle.is_finite() {
            return Err(OrientationError::NotFinite);
        }
        if angle == c::<T>(0.0) {
            let rotation = [
                [c::<T>(1.0), c::<T>(0.0), c::<T>(0.0)],
                [c::<T>(0.0), c::<T>(1.0), c::<T>(0.0)],
                [c::<T>(0.0), c::<T>(0.0), c::<T>(1.0)],
            ];
            return Ok(Pose { rotation, translation });
        }
        Self::from_axis_angle(v, angle, translation)
    }
}
