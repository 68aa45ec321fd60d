//! Spatial vector algebra (Featherstone, Rigid Body Dynamics Algorithms, 2008, ch. 2) on nalgebra.
//!
//! A spatial vector is a `Vector6` in Plücker coordinates, angular part first (Featherstone's
//! order): a motion vector `[w; v_O]` (angular velocity, and the velocity of the body-fixed point
//! at the coordinate frame's origin `O`), a force vector `[n_O; f]` (moment about `O`, and force).
//! A spatial inertia is a symmetric `Matrix6` in the same coordinates.

use nalgebra::{Isometry3, Matrix3, Matrix6, Vector3, Vector6};

/// A motion or force vector, angular part first.
pub(super) type Spatial = Vector6<f64>;

/// The spatial vector `[angular; linear]`.
pub(super) fn spatial(angular: Vector3<f64>, linear: Vector3<f64>) -> Spatial {
    Vector6::new(angular.x, angular.y, angular.z, linear.x, linear.y, linear.z)
}

fn angular(v: &Spatial) -> Vector3<f64> {
    v.fixed_rows::<3>(0).into_owned()
}

fn linear(v: &Spatial) -> Vector3<f64> {
    v.fixed_rows::<3>(3).into_owned()
}

/// `v x m`, the cross product of motion vectors (§2.9, `crm`).
pub(super) fn cross_motion(v: &Spatial, m: &Spatial) -> Spatial {
    let (w, v0) = (angular(v), linear(v));
    spatial(w.cross(&angular(m)), w.cross(&linear(m)) + v0.cross(&angular(m)))
}

/// `v x* f`, the cross product of a motion vector with a force vector (§2.9, `crf`).
pub(super) fn cross_force(v: &Spatial, f: &Spatial) -> Spatial {
    let (w, v0) = (angular(v), linear(v));
    spatial(w.cross(&angular(f)) + v0.cross(&linear(f)), w.cross(&linear(f)))
}

/// The Plücker transform `B_X_A` of motion vectors from frame A's coordinates to frame B's
/// (§2.8, `rot(E) xlt(r)`): `E` turns A's coordinates into B's, `r` is B's origin in A's
/// coordinates.
#[derive(Debug, Clone, Copy)]
pub(super) struct Plucker {
    e: Matrix3<f64>,
    r: Vector3<f64>,
}

impl Plucker {
    /// The transform from A's coordinates to B's, for `pose` the pose of frame B in frame A
    /// (`p_A = R p_B + t`, so `E = R^T`, `r = t`).
    pub(super) fn from_pose(pose: &Isometry3<f64>) -> Self {
        Plucker { e: pose.rotation.to_rotation_matrix().into_inner().transpose(), r: pose.translation.vector }
    }

    /// `X m`: a motion vector in A's coordinates to B's, `[E w; E (v - r x w)]`.
    pub(super) fn motion(&self, m: &Spatial) -> Spatial {
        let w = angular(m);
        spatial(self.e * w, self.e * (linear(m) - self.r.cross(&w)))
    }

    /// `X^T f`: a force vector in B's coordinates to A's (`A_X*_B = (B_X_A)^T`, §2.8),
    /// `[E^T n + r x E^T f; E^T f]`.
    pub(super) fn force_to_parent(&self, f: &Spatial) -> Spatial {
        let (n, f) = (self.e.transpose() * angular(f), self.e.transpose() * linear(f));
        spatial(n + self.r.cross(&f), f)
    }

    /// The 6x6 matrix `[E 0; -E r^x E]`.
    fn matrix(&self) -> Matrix6<f64> {
        let mut x = Matrix6::zeros();
        x.fixed_view_mut::<3, 3>(0, 0).copy_from(&self.e);
        x.fixed_view_mut::<3, 3>(3, 3).copy_from(&self.e);
        x.fixed_view_mut::<3, 3>(3, 0).copy_from(&(-self.e * self.r.cross_matrix()));
        x
    }

    /// A spatial inertia in B's coordinates expressed in A's: `X^T I X` (§2.13).
    pub(super) fn inertia_to_parent(&self, inertia: &Matrix6<f64>) -> Matrix6<f64> {
        let x = self.matrix();
        x.transpose() * inertia * x
    }
}

/// The spatial inertia of a rigid body about a frame's origin, in its axes, from its mass, the
/// position `c` of its centre of mass and its rotational inertia `i_c` about the centre of mass
/// in the frame's axes (§2.13): `[i_c + m c^x c^xT, m c^x; m c^xT, m 1]`.
pub(super) fn rigid_body_inertia(mass: f64, c: Vector3<f64>, i_c: Matrix3<f64>) -> Matrix6<f64> {
    let cx = c.cross_matrix();
    let mut inertia = Matrix6::zeros();
    inertia.fixed_view_mut::<3, 3>(0, 0).copy_from(&(i_c + cx * cx.transpose() * mass));
    inertia.fixed_view_mut::<3, 3>(0, 3).copy_from(&(cx * mass));
    inertia.fixed_view_mut::<3, 3>(3, 0).copy_from(&(cx.transpose() * mass));
    inertia.fixed_view_mut::<3, 3>(3, 3).copy_from(&(Matrix3::identity() * mass));
    inertia
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Translation3, UnitQuaternion};

    fn pose() -> Isometry3<f64> {
        Isometry3::from_parts(Translation3::new(0.3, -1.2, 0.7), UnitQuaternion::from_euler_angles(0.4, -0.9, 2.1))
    }

    #[test]
    fn transforms_keep_power_and_match_the_matrix() {
        let x = Plucker::from_pose(&pose());
        let m = Spatial::new(0.1, -0.5, 0.9, 1.3, 0.2, -0.7);
        let f = Spatial::new(-0.4, 0.8, 0.3, 0.6, -1.1, 0.5);
        // A force in B's coordinates does the same work on a motion in A's as on its image in B's.
        assert!((x.force_to_parent(&f).dot(&m) - f.dot(&x.motion(&m))).abs() < 1e-14);
        assert!((x.matrix() * m - x.motion(&m)).norm() < 1e-14);
        assert!((x.matrix().transpose() * f - x.force_to_parent(&f)).norm() < 1e-14);
        // v x* f = -(v x)^T f.
        let crm = Matrix6::from_columns(&std::array::from_fn::<_, 6, _>(|k| cross_motion(&m, &Spatial::ith(k, 1.0))));
        assert!((cross_force(&m, &f) + crm.transpose() * f).norm() < 1e-14);
    }

    #[test]
    fn a_point_mass_off_the_origin() {
        // Mass 2 at (0, 0, 1): turning about x at 1 rad/s moves it at -1 m/s along y, angular
        // momentum about the origin 2 kg m^2/s about x.
        let inertia = rigid_body_inertia(2.0, Vector3::new(0.0, 0.0, 1.0), Matrix3::zeros());
        let h = inertia * spatial(Vector3::x(), Vector3::zeros());
        assert!((h - Spatial::new(2.0, 0.0, 0.0, 0.0, -2.0, 0.0)).norm() < 1e-15, "{h}");
    }
}
