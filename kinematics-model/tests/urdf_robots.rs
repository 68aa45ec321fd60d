//! Numbers the URDF reader must read from the robots in `robots/` (it replaced a reader on
//! urdf-rs, and gave every robot there the very same tree; these pins keep it so).
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use kinematics_model::{Angle, Elementary, JointKind, JointMotion, KinematicTree, parse_source};

fn load(file: &str) -> KinematicTree {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../robots").join(file);
    parse_source(file, &std::fs::read_to_string(path).unwrap()).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn ur5_elbow() {
    let tree = load("ur5.urdf");
    assert_eq!((tree.name(), tree.links().len(), tree.joints().len(), tree.dof()), ("ur5", 10, 9, 6));
    let elbow = tree.joint_by_name("elbow_joint").unwrap();
    assert_eq!(elbow.kind, JointKind::Revolute);
    assert_eq!(elbow.axis, [0.0, 1.0, 0.0]);
    assert_eq!(elbow.origin.steps(), [Elementary::Translation([0.0, -0.1197, 0.425])]);
    let limits = elbow.limits.unwrap();
    assert_eq!((limits.lower, limits.upper), (-std::f64::consts::TAU, std::f64::consts::TAU));
}

#[test]
fn humanoid_finger_mimic() {
    let tree = load("humanoid.urdf");
    let finger = tree.joint_by_name("LFinger11").unwrap();
    let JointMotion::Mimic { multiplier, offset, .. } = finger.motion else { panic!("{:?}", finger.motion) };
    assert_eq!((multiplier, offset), (0.999899, 0.0));
    assert_eq!(
        finger.origin.steps(),
        [
            Elementary::Translation([0.06907, 0.01157, -0.00304]),
            Elementary::Rotation(kinematics_model::Axis::Z, Angle::Radians(0.264067)),
            Elementary::Rotation(kinematics_model::Axis::Y, Angle::Radians(0.976662)),
            Elementary::Rotation(kinematics_model::Axis::X, Angle::Radians(1.8862)),
        ]
    );
}
