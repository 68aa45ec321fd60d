//! Check mode's measure: every pose a body computes against the runtime reference's pose of the
//! same link at the same configuration, by `Pose::deviation` within the agreement tolerance (f64)
//! or its single-precision counterpart (f32), the measure every agreement check of the project
//! uses; and the conversions that put the peers' poses (nalgebra's, `k`'s own nalgebra version,
//! f32) and their joint orders into that one form.

use kinematics::{Pose, Real, ReferenceFk};

/// Check mode: `pose` (computed by the body `what` at configuration `i`) against the reference's
/// pose of `link`, by `Pose::deviation` within `tolerance` (`AGREEMENT_TOLERANCE`, or
/// `AGREEMENT_TOLERANCE_F32` for single precision), the measure every agreement check uses.
pub fn verify(
    what: &str,
    link: &str,
    i: usize,
    pose: &Pose<f64>,
    expected: &nalgebra::Isometry3<f64>,
    reach: f64,
    tolerance: f64,
) {
    let d = pose.deviation(expected, reach);
    // NaN fails too.
    if d.is_nan() || d > tolerance {
        panic!("{what}: `{link}` off by {d:e} (tolerance {tolerance:e}) at configuration {i}");
    }
}

/// A position as a pose with the expected rotation, so the deviation measures the position alone.
pub fn position_pose(position: [f64; 3], expected: &nalgebra::Isometry3<f64>) -> Pose<f64> {
    Pose { translation: position, ..pose_of(expected) }
}

/// An nalgebra pose (the reference's, galaw's) as a [`Pose`].
pub fn pose_of(iso: &nalgebra::Isometry3<f64>) -> Pose<f64> {
    let r = iso.rotation.to_rotation_matrix();
    let t = iso.translation.vector;
    Pose { rotation: std::array::from_fn(|i| std::array::from_fn(|j| r[(i, j)])), translation: [t[0], t[1], t[2]] }
}

/// A pose computed by `k` (which links its own nalgebra).
pub fn pose_of_k(iso: &k::nalgebra::Isometry3<f64>) -> Pose<f64> {
    let m = iso.to_homogeneous();
    Pose {
        rotation: std::array::from_fn(|i| std::array::from_fn(|j| m[(i, j)])),
        translation: [m[(0, 3)], m[(1, 3)], m[(2, 3)]],
    }
}

/// A single-precision pose widened to f64 (exactly), to be measured against the reference.
pub fn widen(p: &Pose<f32>) -> Pose<f64> {
    Pose { rotation: p.rotation.map(|row| row.map(f64::from)), translation: p.translation.map(f64::from) }
}

/// A single-precision nalgebra pose (galaw's f32 code) widened to f64.
pub fn widen_iso(p: &nalgebra::Isometry3<f32>) -> nalgebra::Isometry3<f64> {
    p.cast::<f64>()
}

/// The reference's pose of every link at `q`, by name.
pub fn reference_poses(reference: &ReferenceFk, q: &[f64]) -> impl Fn(&str) -> nalgebra::Isometry3<f64> {
    let poses = reference.link_poses(q).expect("q fits the robot");
    let ids: std::collections::HashMap<String, usize> =
        reference.tree().links().iter().enumerate().map(|(i, l)| (l.name.clone(), i)).collect();
    move |link: &str| poses[*ids.get(link).unwrap_or_else(|| panic!("no link `{link}` in the reference"))]
}

/// Each of `joints` (names, in another implementation's order) gets the value our model gives it
/// at each configuration (mimic joints included), so that implementation computes the same poses.
pub fn joint_values(tree: &kinematics::KinematicTree, joints: &[String], qs: &[Vec<f64>]) -> Vec<Vec<f64>> {
    let motions: Vec<_> = joints
        .iter()
        .map(|name| tree.joints().iter().find(|j| j.name == *name).expect("the joint is ours").motion)
        .collect();
    qs.iter().map(|q| motions.iter().map(|m| m.value(q).expect("a moving joint")).collect()).collect()
}

/// A pose of NaNs: what a batch's output holds before the batch, so a slot it fails to write fails
/// the check.
pub fn nan_pose<T: Real>() -> Pose<T> {
    let nan = T::from_f64(f64::NAN);
    Pose { rotation: [[nan; 3]; 3], translation: [nan; 3] }
}
