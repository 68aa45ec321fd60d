//! Conversions between [`Pose`] and nalgebra's types, and the pose distance every agreement check
//! uses (feature `nalgebra`, on through the facade's default `std` feature).
//!
//! `Pose` to `Isometry3` and `Matrix4`, and `Pose::deviation`.

use nalgebra::{Isometry3, Matrix3, Matrix4, RealField, Rotation3, Translation3, UnitQuaternion};

use crate::Pose;

impl<T: RealField + Copy> Pose<T> {
    /// The rotation as a nalgebra matrix.
    ///
    /// ```
    /// use kinematics_core::Pose;
    /// let pose = Pose { rotation: [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]], translation: [1.0, 2.0, 3.0] };
    /// let iso = pose.to_isometry();
    /// assert!((iso * nalgebra::Point3::new(1.0, 0.0, 0.0) - nalgebra::Point3::new(1.0, 3.0, 3.0)).norm() < 1e-15);
    /// assert_eq!(pose.to_matrix4()[(1, 3)], 2.0);
    /// assert_eq!(pose.rotation_matrix()[(0, 1)], -1.0);
    /// ```
    pub fn rotation_matrix(&self) -> Matrix3<T> {
        let r = &self.rotation;
        Matrix3::new(r[0][0], r[0][1], r[0][2], r[1][0], r[1][1], r[1][2], r[2][0], r[2][1], r[2][2])
    }

    /// The homogeneous 4x4 matrix.
    pub fn to_matrix4(&self) -> Matrix4<T> {
        let mut m = Matrix4::identity();
        m.fixed_view_mut::<3, 3>(0, 0).copy_from(&self.rotation_matrix());
        for i in 0..3 {
            m[(i, 3)] = self.translation[i];
        }
        m
    }

    /// The rotation as nalgebra's unit quaternion (re-orthonormalised).
    ///
    /// ```
    /// use kinematics_core::Pose;
    /// let pose = Pose::from_rpy([0.0, 0.0, std::f64::consts::FRAC_PI_2], [0.0; 3]);
    /// let q = pose.unit_quaternion();
    /// assert!((q.angle() - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
    /// assert!((pose.rotation3().matrix() - pose.rotation_matrix()).amax() < 1e-15);
    /// ```
    pub fn unit_quaternion(&self) -> UnitQuaternion<T> {
        UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(self.rotation_matrix()))
    }

    /// The rotation as nalgebra's rotation matrix (the entries as they are).
    pub fn rotation3(&self) -> Rotation3<T> {
        Rotation3::from_matrix_unchecked(self.rotation_matrix())
    }

    /// The isometry (the rotation is re-orthonormalised into a unit quaternion).
    pub fn to_isometry(&self) -> Isometry3<T> {
        let rotation = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(self.rotation_matrix()));
        let [x, y, z] = self.translation;
        Isometry3::from_parts(Translation3::new(x, y, z), rotation)
    }
}

impl Pose<f64> {
    /// How far this pose is from `reference`: the largest translation difference divided by
    /// `reach` (the robot's size), or the largest difference of a rotation-matrix entry, whichever
    /// is larger. Generated code is held to this against the runtime reference
    /// ([`AGREEMENT_TOLERANCE`](crate::AGREEMENT_TOLERANCE)).
    ///
    /// A NaN or infinite entry on either side (or a reach that is not finite and positive) is
    /// infinitely far: no check built on this can pass on a pose that is not a number.
    ///
    /// ```
    /// use kinematics_core::Pose;
    /// let pose = Pose { rotation: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], translation: [2.0, 0.0, 0.0] };
    /// let reference = nalgebra::Isometry3::translation(2.0, 0.0, 1e-9);
    /// assert!((pose.deviation(&reference, 2.0) - 0.5e-9).abs() < 1e-18);
    /// let broken = Pose { translation: [f64::NAN, 0.0, 0.0], ..pose };
    /// assert_eq!(broken.deviation(&reference, 2.0), f64::INFINITY);
    /// ```
    pub fn deviation(&self, reference: &Isometry3<f64>, reach: f64) -> f64 {
        if !(reach.is_finite() && reach > 0.0) {
            return f64::INFINITY;
        }
        let r = reference.rotation.to_rotation_matrix();
        let mut worst: f64 = 0.0;
        for i in 0..3 {
            let mut differences = [(self.translation[i] - reference.translation.vector[i]).abs() / reach; 4];
            for j in 0..3 {
                differences[j + 1] = (self.rotation[i][j] - r[(i, j)]).abs();
            }
            for d in differences {
                // `f64::max` would drop a NaN: a difference that is not a finite number is the
                // largest there is.
                if !d.is_finite() {
                    return f64::INFINITY;
                }
                worst = worst.max(d);
            }
        }
        worst
    }
}

impl<T: RealField + Copy> From<Pose<T>> for Isometry3<T> {
    fn from(pose: Pose<T>) -> Self {
        pose.to_isometry()
    }
}

impl<T: RealField + Copy> From<Pose<T>> for Matrix4<T> {
    fn from(pose: Pose<T>) -> Self {
        pose.to_matrix4()
    }
}

/// A pose from an isometry: its rotation matrix and translation.
///
/// ```
/// use kinematics_core::Pose;
/// let iso = nalgebra::Isometry3::new(nalgebra::Vector3::new(1.0, 2.0, 3.0), nalgebra::Vector3::new(0.0, 0.0, 0.5f64));
/// let pose = Pose::from(iso);
/// assert!((pose.to_isometry().rotation.angle() - 0.5).abs() < 1e-15 && pose.translation == [1.0, 2.0, 3.0]);
/// ```
impl<T: RealField + Copy> From<Isometry3<T>> for Pose<T> {
    fn from(iso: Isometry3<T>) -> Self {
        let m = iso.rotation.to_rotation_matrix().into_inner();
        let v = iso.translation.vector;
        Pose {
            rotation: [
                [m[(0, 0)], m[(0, 1)], m[(0, 2)]],
                [m[(1, 0)], m[(1, 1)], m[(1, 2)]],
                [m[(2, 0)], m[(2, 1)], m[(2, 2)]],
            ],
            translation: [v[0], v[1], v[2]],
        }
    }
}
