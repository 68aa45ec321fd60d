//! The robot library in `robots/`: published robots load, have the structure their makers publish,
//! and where one robot has both a DH table and a URDF, the two attach frames to the same bodies, so
//! each pair of same-body frames differs by a fixed transform at every configuration.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use common::pair::{Pair, related_at_zero};
use common::{AGREEMENT_TOLERANCE, assert_pose_eq, load, reference, robot_path};
use kinematics::ReferenceFk;
use kinematics::model::{JointKind, JointMotion, KinematicTree, SourceFormat};
use nalgebra::{Isometry3, Matrix3, Rotation3, Translation3, UnitQuaternion, Vector3};
use proptest::prelude::*;
use std::f64::consts::PI;
use std::sync::LazyLock;

const UR_LINKS: [&str; 6] =
    ["shoulder_link", "upper_arm_link", "forearm_link", "wrist_1_link", "wrist_2_link", "wrist_3_link"];

/// UR10e: Universal Robots' standard DH table against the ur_description-style URDF. Both base
/// links `base` are the controller's Base frame (DH frame 0).
fn ur10e_dh_vs_urdf() -> Pair {
    let mut links: Vec<(&str, &str)> = UR_LINKS.iter().map(|&l| (l, l)).collect();
    links.extend([("wrist_3_link", "flange"), ("wrist_3_link", "tool0")]);
    related_at_zero(reference("ur10e.toml"), "base", reference("ur10e.urdf"), "base", &links)
}

const IIWA_LINKS: [&str; 7] =
    ["iiwa_link_1", "iiwa_link_2", "iiwa_link_3", "iiwa_link_4", "iiwa_link_5", "iiwa_link_6", "iiwa_link_7"];

/// LBR iiwa 14: KUKA's modified DH table against iiwa_stack's URDF, both from the base plate
/// `iiwa_link_0`.
fn iiwa14_dh_vs_urdf() -> Pair {
    let mut links: Vec<(&str, &str)> = IIWA_LINKS.iter().map(|&l| (l, l)).collect();
    links.extend([("iiwa_link_7", "iiwa_link_ee_kuka"), ("iiwa_link_ee", "iiwa_link_ee"), ("iiwa_link_0", "world")]);
    related_at_zero(reference("iiwa14.toml"), "iiwa_link_0", reference("iiwa14.urdf"), "iiwa_link_0", &links)
}

/// Franka Panda: Franka's modified DH table (with the flange) against franka_description's URDF
/// (arm, hand and mimic fingers). Each DH frame i is `panda_link<i>` itself and the flange is
/// `panda_link8`; the URDF's extra degree of freedom (the finger) moves neither.
struct PandaPair {
    dh: ReferenceFk,
    urdf: ReferenceFk,
}

impl PandaPair {
    fn check(&self, q: &[f64], finger: f64) {
        let mut q_urdf = q.to_vec();
        q_urdf.push(finger);
        let pairs = (1..=7)
            .map(|i| (format!("panda_link{i}"), format!("panda_link{i}")))
            .chain([("flange".to_owned(), "panda_link8".to_owned())]);
        for (a, b) in pairs {
            let pa = self.dh.relative_pose(q, "panda_link0", &a).unwrap();
            let pb = self.urdf.relative_pose(&q_urdf, "panda_link0", &b).unwrap();
            assert_pose_eq(&pa, &pb, AGREEMENT_TOLERANCE, &format!("{a} vs {b} at q = {q:?}"));
        }
    }
}

// Loaded once; the property tests run 1,000 cases each.
static PANDA: LazyLock<PandaPair> =
    LazyLock::new(|| PandaPair { dh: reference("panda.toml"), urdf: reference("panda.urdf") });
static UR10E: LazyLock<Pair> = LazyLock::new(ur10e_dh_vs_urdf);
static IIWA14: LazyLock<Pair> = LazyLock::new(iiwa14_dh_vs_urdf);
static DUAL_ARM: LazyLock<ReferenceFk> = LazyLock::new(|| reference("dual_arm_torso.urdf"));
static QUADRUPED: LazyLock<ReferenceFk> = LazyLock::new(|| reference("quadruped.urdf"));

fn q(n: usize) -> impl Strategy<Value = Vec<f64>> {
    proptest::collection::vec(-2.0 * PI..2.0 * PI, n)
}

fn rz(angle: f64) -> Isometry3<f64> {
    Isometry3::from_parts(Translation3::identity(), UnitQuaternion::from_axis_angle(&Vector3::z_axis(), angle))
}

fn dof_index(tree: &KinematicTree, joint: &str) -> usize {
    tree.dof_names().iter().position(|n| n == joint).unwrap_or_else(|| panic!("no degree of freedom {joint}"))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    #[test]
    fn ur10e_standard_dh_matches_urdf(q in q(6)) {
        UR10E.check(&q);
    }

    #[test]
    fn iiwa14_modified_dh_matches_urdf(q in q(7)) {
        IIWA14.check(&q);
    }

    #[test]
    fn panda_modified_dh_matches_urdf(q in q(7), finger in 0.0..0.04f64) {
        PANDA.check(&q, finger);
    }

    /// The dual-arm robot's waist turns everything above it about the vertical axis through the root.
    #[test]
    fn dual_arm_waist_turns_both_arms(q in q(17), turn in -PI..PI) {
        let fk = &*DUAL_ARM;
        let waist = dof_index(fk.tree(), "waist_joint");
        let mut turned = q.clone();
        turned[waist] += turn;
        for link in ["yumi_body", "yumi_link_4_r", "tool_r", "gripper_l_finger_l", "tool_l"] {
            let before = fk.link_pose(&q, link).unwrap();
            let after = fk.link_pose(&turned, link).unwrap();
            assert_pose_eq(&(rz(turn) * before), &after, AGREEMENT_TOLERANCE, link);
        }
    }

    /// The quadruped's left legs mirror its right legs in the sagittal (x-z) plane when the hip
    /// abduction angle changes sign.
    #[test]
    fn quadruped_left_legs_mirror_right_legs(abduction in -0.8..0.8f64, hip in -1.0..4.1f64, knee in -2.6..-0.95f64) {
        let fk = &*QUADRUPED;
        for (right, left) in [("FR", "FL"), ("RR", "RL")] {
            let mut q = vec![0.0; 12];
            for (side, sign) in [(right, 1.0), (left, -1.0)] {
                q[dof_index(fk.tree(), &format!("{side}_hip_joint"))] = sign * abduction;
                q[dof_index(fk.tree(), &format!("{side}_thigh_joint"))] = hip;
                q[dof_index(fk.tree(), &format!("{side}_calf_joint"))] = knee;
            }
            let r = fk.link_pose(&q, &format!("{right}_foot")).unwrap().translation.vector;
            let l = fk.link_pose(&q, &format!("{left}_foot")).unwrap().translation.vector;
            prop_assert!((Vector3::new(r.x, -r.y, r.z) - l).norm() < AGREEMENT_TOLERANCE, "{right} {r:?} vs {left} {l:?}");
        }
    }
}

#[test]
fn ur10e_frames_relate_as_published() {
    // ROS-Industrial's `tool0` is the DH flange frame 6 itself, and `base` is a half turn about z
    // from the REP-103 `base_link`.
    let pair = ur10e_dh_vs_urdf();
    assert_pose_eq(
        &pair.relation("wrist_3_link", "tool0"),
        &Isometry3::identity(),
        AGREEMENT_TOLERANCE,
        "DH 6 vs tool0",
    );
    let base = pair.b.relative_pose(&[0.0; 6], "base_link", "base").unwrap();
    assert_pose_eq(&base, &rz(PI), AGREEMENT_TOLERANCE, "base vs base_link");
    // At q = 0 the flange sits at (a2 + a3, -(d4 + d6), d1 - d5) in the Base frame.
    let tool = pair.a.relative_pose(&[0.0; 6], "base", "wrist_3_link").unwrap();
    let expected = Vector3::new(-0.6127 - 0.57155, -(0.17415 + 0.11655), 0.1807 - 0.11985);
    assert!((tool.translation.vector - expected).norm() < AGREEMENT_TOLERANCE, "{tool}");
}

#[test]
fn iiwa14_frames_relate_as_published() {
    // DH frame 7 is KUKA's flange frame (iiwa_link_ee_kuka), the DH tool is the ROS tool frame, and
    // DH frame 1 sits on joint 1's axis 0.2025 m above the URDF's link 1 (0.36 - 0.1575).
    let pair = iiwa14_dh_vs_urdf();
    let id = Isometry3::identity();
    assert_pose_eq(&pair.relation("iiwa_link_7", "iiwa_link_ee_kuka"), &id, AGREEMENT_TOLERANCE, "DH 7 vs flange");
    assert_pose_eq(&pair.relation("iiwa_link_ee", "iiwa_link_ee"), &id, AGREEMENT_TOLERANCE, "tool frames");
    let link1 = Isometry3::translation(0.0, 0.0, -0.2025);
    assert_pose_eq(&pair.relation("iiwa_link_1", "iiwa_link_1"), &link1, AGREEMENT_TOLERANCE, "link 1");
    // Upright at q = 0: the flange is 0.36 + 0.42 + 0.4 + 0.126 = 1.306 m above the base plate.
    let flange = pair.b.relative_pose(&[0.0; 7], "iiwa_link_0", "iiwa_link_ee_kuka").unwrap();
    assert_pose_eq(&flange, &Isometry3::translation(0.0, 0.0, 1.306), AGREEMENT_TOLERANCE, "flange at q = 0");
}

/// Every description file in `robots/`.
fn robot_files() -> Vec<String> {
    let mut files: Vec<String> = std::fs::read_dir(robot_path(""))
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|f| SourceFormat::from_file_name(f).is_some())
        .collect();
    files.sort();
    files
}

#[test]
fn every_robot_file_loads_and_urdf_limits_are_complete() {
    let files = robot_files();
    for mine in [
        "ur10e.toml",
        "ur10e.urdf",
        "iiwa14.toml",
        "iiwa14.urdf",
        "panda.urdf",
        "gen3.urdf",
        "irb120.urdf",
        "stanford_arm.toml",
        "scara.toml",
        "dual_arm_torso.urdf",
        "quadruped.urdf",
        "humanoid.urdf",
    ] {
        assert!(files.iter().any(|f| f == mine), "robots/{mine} is missing");
    }
    for file in &files {
        let tree = load(file);
        assert!(tree.dof() > 0, "{file}");
        if file.ends_with(".urdf") {
            // URDF requires position limits on revolute and prismatic joints.
            for joint in tree.joints() {
                if matches!(joint.kind, JointKind::Revolute | JointKind::Prismatic) {
                    assert!(joint.limits.is_some(), "{file}: {} has no limits", joint.name);
                }
            }
        }
    }
}

fn moving_joints(tree: &KinematicTree) -> usize {
    tree.joints().iter().filter(|j| j.kind != JointKind::Fixed).count()
}

fn kind_count(tree: &KinematicTree, kind: JointKind) -> usize {
    tree.joints().iter().filter(|j| j.kind == kind).count()
}

/// The independent joint a mimic joint follows, with multiplier and offset.
fn mimic_of<'a>(tree: &'a KinematicTree, joint: &str) -> (&'a str, f64, f64) {
    match tree.joint_by_name(joint).unwrap().motion {
        JointMotion::Mimic { source, multiplier, offset, .. } => (&tree.joint(source).name, multiplier, offset),
        other => panic!("{joint} is not a mimic joint: {other:?}"),
    }
}

#[test]
fn degrees_of_freedom_as_published() {
    let expected = [
        ("ur10e.toml", 6),
        ("ur10e.urdf", 6),
        ("iiwa14.toml", 7),
        ("iiwa14.urdf", 7),
        ("panda.urdf", 8), // 7 arm joints + panda_finger_joint1 (joint2 mimics it)
        ("gen3.urdf", 7),
        ("irb120.urdf", 6),
        ("stanford_arm.toml", 6),
        ("scara.toml", 4),
        ("dual_arm_torso.urdf", 17), // waist + 2 x 7 arm joints + 2 grippers
        ("quadruped.urdf", 12),
        ("humanoid.urdf", 25), // NAO H25
    ];
    for (file, dof) in expected {
        assert_eq!(load(file).dof(), dof, "{file}");
    }
}

#[test]
fn panda_hand_and_zero_pose() {
    let tree = load("panda.urdf");
    assert_eq!(tree.link(tree.root()).name, "world");
    let finger = tree.joint_by_name("panda_finger_joint2").unwrap();
    assert_eq!(finger.kind, JointKind::Prismatic);
    assert_eq!(mimic_of(&tree, "panda_finger_joint2"), ("panda_finger_joint1", 1.0, 0.0));
    let limits = finger.limits.unwrap();
    assert_eq!((limits.lower, limits.upper), (0.0, 0.04));
    // Franka's zero pose: the flange (panda_link8) at (0.088, 0, 0.333 + 0.316 + 0.384 - 0.107).
    let fk = ReferenceFk::new(tree);
    let q = [0.0; 8];
    let flange = fk.relative_pose(&q, "panda_link0", "panda_link8").unwrap();
    assert!((flange.translation.vector - Vector3::new(0.088, 0.0, 0.926)).norm() < AGREEMENT_TOLERANCE, "{flange}");
    // Opening the hand moves the fingers apart symmetrically along the hand's y axis.
    let mut open = q;
    open[dof_index(fk.tree(), "panda_finger_joint1")] = 0.04;
    let left = fk.relative_pose(&open, "panda_hand", "panda_leftfinger").unwrap().translation.vector;
    let right = fk.relative_pose(&open, "panda_hand", "panda_rightfinger").unwrap().translation.vector;
    assert!((left - Vector3::new(0.0, 0.04, 0.0584)).norm() < AGREEMENT_TOLERANCE, "{left:?}");
    assert!((right - Vector3::new(0.0, -0.04, 0.0584)).norm() < AGREEMENT_TOLERANCE, "{right:?}");
}

#[test]
fn gen3_joint_types_and_zero_pose() {
    let tree = load("gen3.urdf");
    for (joint, kind) in [
        ("joint_1", JointKind::Continuous),
        ("joint_2", JointKind::Revolute),
        ("joint_3", JointKind::Continuous),
        ("joint_4", JointKind::Revolute),
        ("joint_5", JointKind::Continuous),
        ("joint_6", JointKind::Revolute),
        ("joint_7", JointKind::Continuous),
    ] {
        let j = tree.joint_by_name(joint).unwrap();
        assert_eq!(j.kind, kind, "{joint}");
        assert_eq!(j.limits.is_some(), kind == JointKind::Revolute, "{joint}");
    }
    // At q = 0 the arm stands straight up; the end effector frame is aligned with the base, the
    // z offsets add to 1.187385 m and the y offsets (signs flipped by the alternating quarter
    // turns) to -(0.005375 + 3 * 0.006375 + 2 * 0.00017505) = -0.0248501 m.
    let fk = ReferenceFk::new(tree);
    let ee = fk.relative_pose(&[0.0; 7], "base_link", "end_effector_link").unwrap();
    let expected = Isometry3::translation(0.0, -0.0248501, 1.187385);
    assert_pose_eq(&ee, &expected, AGREEMENT_TOLERANCE, "end effector at q = 0");
}

#[test]
fn irb120_zero_pose() {
    // ABB's zero pose: the wrist centre 0.302 m ahead of axis 4, the flange 0.072 m further, at the
    // height of 0.29 + 0.27 + 0.07; tool0 has z along the flange normal (world x).
    let fk = reference("irb120.urdf");
    let tool0 = fk.relative_pose(&[0.0; 6], "base", "tool0").unwrap();
    let rotation = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), PI / 2.0);
    let expected = Isometry3::from_parts(Translation3::new(0.374, 0.0, 0.63), rotation);
    assert_pose_eq(&tool0, &expected, AGREEMENT_TOLERANCE, "tool0 at q = 0");
}

#[test]
fn stanford_arm_prismatic_joint() {
    let tree = load("stanford_arm.toml");
    let kinds: Vec<JointKind> = tree.dof_joints().iter().map(|&j| tree.joint(j).kind).collect();
    assert_eq!(kinds.iter().filter(|&&k| k == JointKind::Prismatic).count(), 1);
    assert_eq!(kinds[2], JointKind::Prismatic);
    let fk = ReferenceFk::new(tree);
    // With the revolute joints at zero the wrist centre lies d1 + q3 above the base and
    // d2 - a3 to the side (theta3 = -pi/2 turns a3 onto -y).
    for stroke in [0.3048, 0.5, 1.27] {
        let wrist = fk.link_pose(&[0.0, 0.0, stroke, 0.0, 0.0, 0.0], "link6").unwrap();
        let expected = Vector3::new(0.0, 0.154 - 0.0203, 0.412 + stroke);
        assert!((wrist.translation.vector - expected).norm() < AGREEMENT_TOLERANCE, "{wrist}");
    }
}

#[test]
fn scara_points_down_and_plunges() {
    let fk = reference("scara.toml");
    assert_eq!(fk.tree().joint_by_name("joint3").unwrap().kind, JointKind::Prismatic);
    let down = Rotation3::from_matrix_unchecked(Matrix3::from_diagonal(&Vector3::new(1.0, -1.0, -1.0)));
    for (q, at) in [
        ([0.0, 0.0, 0.0, 0.0], Vector3::new(0.6, 0.0, 0.387)),
        ([0.0, 0.0, 0.21, 0.0], Vector3::new(0.6, 0.0, 0.177)),
        ([PI / 2.0, 0.0, 0.1, 0.0], Vector3::new(0.0, 0.6, 0.287)),
    ] {
        let tip = fk.link_pose(&q, "link4").unwrap();
        // The arm turns the downward tool frame about the vertical by q1 + q2.
        let turn = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), q[0] + q[1]);
        let expected = Isometry3::from_parts(at.into(), turn * UnitQuaternion::from_rotation_matrix(&down));
        assert_pose_eq(&tip, &expected, AGREEMENT_TOLERANCE, &format!("link4 at {q:?}"));
    }
}

#[test]
fn quadruped_legs() {
    let tree = load("quadruped.urdf");
    assert_eq!(moving_joints(&tree), 12);
    for leg in ["FR", "FL", "RR", "RL"] {
        assert_eq!(tree.joint_by_name(&format!("{leg}_hip_joint")).unwrap().axis, [1.0, 0.0, 0.0], "{leg}");
        for joint in ["thigh", "calf"] {
            assert_eq!(tree.joint_by_name(&format!("{leg}_{joint}_joint")).unwrap().axis, [0.0, 1.0, 0.0]);
        }
    }
    // Legs straight down at q = 0: the front right foot is 0.4 m below its hip, 0.0838 m outboard.
    let fk = ReferenceFk::new(tree);
    let foot = fk.link_pose(&[0.0; 12], "FR_foot").unwrap();
    assert!((foot.translation.vector - Vector3::new(0.1805, -0.1308, -0.4)).norm() < AGREEMENT_TOLERANCE, "{foot}");
}

#[test]
fn dual_arm_torso_structure() {
    let tree = load("dual_arm_torso.urdf");
    assert_eq!(tree.dof_names()[0], "waist_joint");
    for side in ["r", "l"] {
        let arm = tree.chain("yumi_body", &format!("yumi_link_7_{side}")).unwrap();
        assert_eq!(arm.joints.len(), 7, "{side} arm");
        assert!(arm.joints.iter().all(|&j| tree.joint(j).kind == JointKind::Revolute));
        let gripper = format!("gripper_{side}_joint");
        assert_eq!(mimic_of(&tree, &format!("{gripper}_m")), (gripper.as_str(), 1.0, 0.0));
    }
}

#[test]
fn humanoid_tree() {
    let tree = load("humanoid.urdf");
    assert!(moving_joints(&tree) >= 30, "{} moving joints", moving_joints(&tree));
    assert_eq!(moving_joints(&tree), 42);
    assert!(kind_count(&tree, JointKind::Fixed) >= 10, "sensor and tool frames");
    let mimics: Vec<&str> = tree
        .joints()
        .iter()
        .filter(|j| matches!(j.motion, JointMotion::Mimic { .. }))
        .map(|j| j.name.as_str())
        .collect();
    assert_eq!(mimics.len(), 17, "{mimics:?}");
    assert_eq!(mimic_of(&tree, "RHipYawPitch"), ("LHipYawPitch", 1.0, 0.0));
    for (hand, side) in [("LHand", "L"), ("RHand", "R")] {
        for finger in ["Finger11", "Finger12", "Finger13", "Finger21", "Finger22", "Finger23", "Thumb1", "Thumb2"] {
            let joint = format!("{side}{finger}");
            assert_eq!(mimic_of(&tree, &joint), (hand, 0.999899, 0.0), "{joint}");
            assert_eq!(tree.joint_by_name(&joint).unwrap().kind, JointKind::Continuous);
        }
    }
    // The hip yaw-pitch axes are published as (0, 0.707106, -+0.707106): normalised on loading.
    let axis = tree.joint_by_name("LHipYawPitch").unwrap().axis;
    assert!((Vector3::from(axis) - Vector3::new(0.0, 1.0, -1.0).normalize()).norm() < 1e-15);
    // Standing straight at q = 0, the left sole is below the hip by thigh + tibia + foot height.
    let fk = ReferenceFk::new(tree);
    let sole = fk.link_pose(&[0.0; 25], "l_sole").unwrap();
    let expected = Vector3::new(0.0, 0.05, -0.085 - 0.1 - 0.1029 - 0.04511);
    assert!((sole.translation.vector - expected).norm() < AGREEMENT_TOLERANCE, "{sole}");
    // One motor drives both hip yaw-pitch joints: moving it moves both feet.
    let mut q = vec![0.0; 25];
    q[dof_index(fk.tree(), "LHipYawPitch")] = 0.5;
    for foot in ["l_sole", "r_sole"] {
        let moved = fk.link_pose(&q, foot).unwrap().translation.vector;
        let still = fk.link_pose(&[0.0; 25], foot).unwrap().translation.vector;
        assert!((moved - still).norm() > 1e-3, "{foot} did not move");
    }
}
