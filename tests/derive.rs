//! `#[derive(Kinematics)]` from a user's point of view: file and inline sources, what the struct
//! gets, and the trait for generic code.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use kinematics::{Kinematics, Pose};

#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5.urdf", base = "base", tip = "tool0", positions)]
/// The UR5, from its URDF.
pub struct Ur5;

/// A planar arm written in the attribute, with fields of the user's own.
#[derive(Kinematics)]
#[kinematics(
    dh(
        convention = "standard",
        joint(name = "shoulder", a = 1.0),
        joint(name = "elbow", a = 1.0, lower = -2.5, upper = 2.5),
        joint(name = "wrist", a = 0.5, alpha = "-pi/2"),
    ),
    tips("link2", "link3"),
    scalars(f64, f32)
)]
#[allow(dead_code)]
struct Planar {
    label: String,
}

#[test]
fn ur5_from_urdf() {
    assert_eq!(Ur5::DOF, 6);
    assert_eq!(Ur5::JOINT_NAMES[1], "shoulder_lift_joint");
    assert_eq!(Ur5::BASE, "base");
    let q = [0.3, -1.2, 1.0, 0.4, -0.7, 2.0];
    let pose = Ur5::tip_pose(&q);
    let reference = Ur5::reference().unwrap().relative_pose(&q, "base", "tool0").unwrap();
    assert!((pose.to_isometry().translation.vector - reference.translation.vector).norm() < 1e-12);
    let position = Ur5::tip_position(&q);
    assert_eq!(position, pose.translation);
    let links = Ur5::link_poses(&q);
    assert_eq!(links.len(), Ur5::LINK_NAMES.len());
}

#[test]
fn planar_from_inline_table() {
    let q = [0.1, 0.2, 0.3];
    let [elbow, hand] = Planar::tip_poses(&q);
    let [elbow32, _] = Planar::tip_poses_f32(&[0.1, 0.2, 0.3]);
    assert!((elbow.translation[0] - (0.1f64.cos() + 0.3f64.cos())).abs() < 1e-12);
    assert!((f64::from(elbow32.translation[0]) - elbow.translation[0]).abs() < 1e-6);
    assert_eq!(Planar::JOINT_LIMITS[1].lower, -2.5);
    assert!(Planar::JOINT_LIMITS[0].upper.is_infinite());
    let _ = hand;
}

fn tips_of<R: Kinematics>(q: &[f64]) -> Vec<Pose<f64>> {
    let mut out = vec![Pose { rotation: [[0.0; 3]; 3], translation: [0.0; 3] }; R::TIPS.len()];
    R::tip_poses_into(q, &mut out).unwrap();
    out
}

#[test]
fn generic_code_takes_any_compiled_robot() {
    assert_eq!(tips_of::<Ur5>(&[0.0; 6]).len(), 1);
    assert_eq!(tips_of::<Planar>(&[0.0; 3]).len(), 2);
    let mut out = vec![Pose { rotation: [[0.0; 3]; 3], translation: [0.0; 3] }; 1];
    let err = <Ur5 as Kinematics>::tip_poses_into(&[0.0; 5], &mut out).unwrap_err();
    assert!(err.to_string().contains("6 degrees of freedom"), "{err}");
}

/// The same planar arm as a textbook table: one positional row per joint.
#[derive(Kinematics)]
#[kinematics(
    dh(
        convention = "standard",
        //   joint       a     alpha    d    theta  lower  upper
        row("shoulder", 1.0,   0.0,    0.0,  0.0),
        row("elbow",    1.0,   0.0,    0.0,  0.0,   -2.5,  2.5),
        row("wrist",    0.5, "-pi/2",  0.0,  0.0),
        row("lift", "prismatic", 0.0, 0.0, 0.1, 0.0, 0.0, 0.4),
    ),
    tip = "link4"
)]
struct PlanarTable;

#[test]
fn positional_rows_read_like_the_textbook_table() {
    assert_eq!(PlanarTable::JOINT_NAMES, ["shoulder", "elbow", "wrist", "lift"]);
    assert_eq!(PlanarTable::JOINT_LIMITS[1].upper, 2.5);
    let q = [0.1, 0.2, 0.3, 0.2];
    let reference = PlanarTable::reference().unwrap().link_pose(&q, "link4").unwrap();
    let pose = PlanarTable::tip_pose(&q);
    assert!((pose.to_isometry().translation.vector - reference.translation.vector).norm() < 1e-12);
    // The prismatic joint slides along the wrist's z, which the -pi/2 twist turned into -y.
    let [x, _, _] = PlanarTable::tip_pose(&[0.0, 0.0, 0.0, 0.0]).translation;
    assert!((x - 2.5).abs() < 1e-12);
}
