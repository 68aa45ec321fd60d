//! The scalar trait generated code is written against, and the pose type it returns.

use std::ops::{Add, Mul, Neg, Sub};

use nalgebra::{Isometry3, Matrix3, Matrix4, RealField, Rotation3, Translation3, UnitQuaternion};

/// The arithmetic generated forward kinematics needs: `+ - *`, negation, constants and `sin_cos`.
///
/// Implemented for `f64` and `f32`; generated functions are generic over it.
///
/// ```
/// use kinematics_runtime::Real;
/// fn double<T: Real>(x: T) -> T { T::from_f64(2.0) * x }
/// assert_eq!(double(1.5f32), 3.0);
/// assert_eq!(1.0f64.sin_cos(), (1.0f64.sin(), 1.0f64.cos()));
/// ```
pub trait Real:
    Copy + PartialOrd + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Neg<Output = Self> + 'static
{
    /// A constant of the robot (rounded to nearest for `f32`).
    fn from_f64(x: f64) -> Self;
    /// `(sin x, cos x)`.
    fn sin_cos(self) -> (Self, Self);
    /// The value as `f64`.
    fn to_f64(self) -> f64;
}

impl Real for f64 {
    #[inline(always)]
    fn from_f64(x: f64) -> Self {
        x
    }
    #[inline(always)]
    fn sin_cos(self) -> (Self, Self) {
        f64::sin_cos(self)
    }
    #[inline(always)]
    fn to_f64(self) -> f64 {
        self
    }
}

impl Real for f32 {
    #[inline(always)]
    fn from_f64(x: f64) -> Self {
        x as f32
    }
    #[inline(always)]
    fn sin_cos(self) -> (Self, Self) {
        f32::sin_cos(self)
    }
    #[inline(always)]
    fn to_f64(self) -> f64 {
        f64::from(self)
    }
}

/// A rigid pose as generated code returns it: a rotation matrix (row-major) and a translation.
///
/// ```
/// use kinematics_runtime::Pose;
/// let pose = Pose { rotation: [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]], translation: [1.0, 2.0, 3.0] };
/// let iso = pose.to_isometry();
/// assert!((iso * nalgebra::Point3::new(1.0, 0.0, 0.0) - nalgebra::Point3::new(1.0, 3.0, 3.0)).norm() < 1e-15);
/// assert_eq!(pose.to_matrix4()[(1, 3)], 2.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose<T> {
    /// Rotation matrix, row-major: `rotation[i][j]` is row `i`, column `j`.
    pub rotation: [[T; 3]; 3],
    /// Translation.
    pub translation: [T; 3],
}

impl<T: Real + RealField> Pose<T> {
    /// The rotation as a nalgebra matrix.
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

    /// The isometry (the rotation is re-orthonormalised into a unit quaternion).
    pub fn to_isometry(&self) -> Isometry3<T> {
        let rotation = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(self.rotation_matrix()));
        let [x, y, z] = self.translation;
        Isometry3::from_parts(Translation3::new(x, y, z), rotation)
    }
}

impl Pose<f64> {
    /// A pose from its twelve entries: the rotation row-major, then the translation (the layout
    /// of the compiler's evaluator).
    pub fn from_entries(e: &[f64; 12]) -> Self {
        Pose {
            rotation: [[e[0], e[1], e[2]], [e[3], e[4], e[5]], [e[6], e[7], e[8]]],
            translation: [e[9], e[10], e[11]],
        }
    }

    /// How far this pose is from `reference`: the largest translation difference divided by
    /// `reach` (the robot's size), or the largest difference of a rotation-matrix entry, whichever
    /// is larger. Generated code is held to this against the runtime reference
    /// ([`AGREEMENT_TOLERANCE`]).
    ///
    /// A NaN or infinite entry on either side (or a reach that is not finite and positive) is
    /// infinitely far: no check built on this can pass on a pose that is not a number.
    ///
    /// ```
    /// use kinematics_runtime::Pose;
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

/// Agreement required of generated `f64` code against the runtime reference, as a
/// [`Pose::deviation`]: translations within this times the reach, rotation entries within this.
/// Every agreement check (tests, `kinematics check`, the examples, the benchmark's check mode)
/// uses this one value.
pub const AGREEMENT_TOLERANCE: f64 = 1e-12;

/// Agreement required of generated `f32` code, as a [`Pose::deviation`] of its poses widened to
/// `f64` (single precision carries about 7 significant digits, and errors grow along a chain).
pub const AGREEMENT_TOLERANCE_F32: f64 = 1e-5;

impl<T: Real + RealField> From<Pose<T>> for Isometry3<T> {
    fn from(pose: Pose<T>) -> Self {
        pose.to_isometry()
    }
}

impl<T: Real + RealField> From<Pose<T>> for Matrix4<T> {
    fn from(pose: Pose<T>) -> Self {
        pose.to_matrix4()
    }
}
