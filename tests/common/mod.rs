//! Helpers shared by the integration tests: robot files, loading, comparison of poses.
#![allow(dead_code)]

use kinematics::{KinematicTree, ReferenceFk};
use nalgebra::Isometry3;

pub mod pair;

/// Poses computed two ways must agree this closely (metres and radians) on robots of about 1 m
/// reach: the one agreement tolerance of the project.
pub use kinematics::AGREEMENT_TOLERANCE;

/// Absolute path of a file in `robots/`.
pub fn robot_path(file: &str) -> String {
    format!("{}/robots/{file}", env!("CARGO_MANIFEST_DIR"))
}

/// Loads a robot from `robots/`.
pub fn load(file: &str) -> KinematicTree {
    kinematics::load(robot_path(file)).unwrap_or_else(|e| panic!("{e}"))
}

/// Reference FK of a robot from `robots/`.
pub fn reference(file: &str) -> ReferenceFk {
    ReferenceFk::new(load(file))
}

/// Largest difference between two poses: translation distance, and the Frobenius norm of the
/// rotation matrices' difference; infinite when either is not a number (`f64::max` would drop a
/// NaN, and a check built on it would pass).
pub fn pose_distance(a: &Isometry3<f64>, b: &Isometry3<f64>) -> f64 {
    let dt = (a.translation.vector - b.translation.vector).norm();
    let dr = (a.rotation.to_rotation_matrix().matrix() - b.rotation.to_rotation_matrix().matrix()).norm();
    if dt.is_finite() && dr.is_finite() { dt.max(dr) } else { f64::INFINITY }
}

/// Asserts two poses agree to `tol`, with a message naming what was compared.
pub fn assert_pose_eq(a: &Isometry3<f64>, b: &Isometry3<f64>, tol: f64, what: &str) {
    let d = pose_distance(a, b);
    assert!(d <= tol, "{what}: poses differ by {d:e} (tolerance {tol:e})\n{a}\n{b}");
}
