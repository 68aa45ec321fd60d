//! Helpers shared by the agreement tests: robot paths, reach, configurations, pose distances; for
//! the dynamics tests, random robots (`dynamics_robots`) and the links' motions and energies from
//! the reference's forward kinematics (`link_motions`).
#![allow(dead_code, unused_imports)] // each test uses some of the helpers

pub mod dynamics_robots;
pub mod link_motions;

use kinematics::Pose;
use kinematics::model::KinematicTree;
use nalgebra::{Isometry3, Matrix3};
use proptest::prelude::*;

/// f64 agreement, relative to the robot's reach (metres) and absolute for rotation entries: the
/// project's one tolerance.
pub use kinematics::AGREEMENT_TOLERANCE as F64_TOLERANCE;
/// f32 agreement, the same way.
pub use kinematics::AGREEMENT_TOLERANCE_F32 as F32_TOLERANCE;
pub const CASES: u32 = 10_000;

pub fn robot_path(file: &str) -> String {
    format!("{}/../robots/{file}", env!("CARGO_MANIFEST_DIR"))
}

/// Per joint: a special angle, a value within the limits, or one up to 1 beyond them. A floating or
/// spherical joint's quaternion drawn with no length to normalise (all four entries 0, about one
/// draw in 160,000 per quaternion) is the identity instead, as the runtime's `Configurations`
/// make it: the reference refuses it (`tests/floating_base.rs` and `tests/mjcf.rs` test that).
pub fn configuration(tree: &KinematicTree) -> impl Strategy<Value = Vec<f64>> {
    use std::f64::consts::{FRAC_PI_2, PI};
    let per_joint: Vec<BoxedStrategy<f64>> = tree
        .dof_joints()
        .iter()
        .map(|&j| {
            let joint = tree.joint(j);
            let (lo, hi) = joint.limits.map_or((-PI, PI), |l| (l.lower, l.upper));
            let (lo, hi) = if hi > lo { (lo, hi) } else { (lo - 1.0, hi + 1.0) };
            prop_oneof![
                2 => lo..hi,
                1 => (lo - 1.0)..(hi + 1.0),
                1 => prop::sample::select(vec![0.0, FRAC_PI_2, -FRAC_PI_2, PI, -PI]),
            ]
            .boxed()
        })
        .collect();
    let quaternions = tree.quaternion_entries();
    per_joint.prop_map(move |mut q| {
        for &start in &quaternions {
            let quaternion = &mut q[start..start + 4];
            if !quaternion.iter().map(|v| v * v).sum::<f64>().is_normal() {
                quaternion.copy_from_slice(&[0.0, 0.0, 0.0, 1.0]);
            }
        }
        q
    })
}

/// Largest difference: translation relative to `reach`, rotation entries absolute.
pub fn distance(generated: &Pose<f64>, reference: &Isometry3<f64>, reach: f64) -> f64 {
    generated.deviation(reference, reach)
}

pub fn orthonormality_error(pose: &Pose<f64>) -> f64 {
    let r = pose.rotation;
    let m = Matrix3::new(r[0][0], r[0][1], r[0][2], r[1][0], r[1][1], r[1][2], r[2][0], r[2][1], r[2][2]);
    (m.transpose() * m - Matrix3::identity()).amax()
}

pub fn to_f64(p: Pose<f32>) -> Pose<f64> {
    Pose { rotation: p.rotation.map(|row| row.map(f64::from)), translation: p.translation.map(f64::from) }
}
