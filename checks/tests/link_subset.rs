//! `links = [...]` (issue 22): `link_poses`, `link_positions` and `LINK_NAMES` of a derive that
//! lists its links hold those links only, in the order given, and agree with the runtime reference
//! for each of them on random configurations (f64, and f32 within the f32 tolerance), whether the
//! list skips the links between (a finger without its hand, a sole without its leg), names a base's
//! ancestor-free leaf first, or holds one link.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use common::*;
use kinematics::{Kinematics, Pose, ReferenceFk};
use proptest::test_runner::{Config, TestRunner};

#[derive(Kinematics)]
#[kinematics(
    urdf = "../robots/humanoid.urdf",
    links = ["RFinger13_link", "l_sole", "torso", "CameraBottom_optical_frame", "RThumb2_link", "r_sole"],
    positions,
    scalars(f64, f32)
)]
struct HumanoidFeetAndFingers;

#[derive(Kinematics)]
#[kinematics(urdf = "../robots/quadruped.urdf", links = ["RL_foot", "FR_foot"], positions)]
struct QuadrupedFeet;

#[derive(Kinematics)]
#[kinematics(urdf = "../robots/dual_arm_torso.urdf", links = ["tool_l"])]
struct DualArmLeftTool;

#[derive(Kinematics)]
#[kinematics(dh = "../robots/panda.toml", base = "panda_link2", links = ["flange", "panda_link1"])]
struct PandaFromLink2;

/// A struct's `link_positions`, taking `q` as a slice.
type Positions = fn(&[f64]) -> Vec<[f64; 3]>;

/// Every listed link's pose and position against the reference, on a tenth of [`CASES`]
/// configurations.
fn check<R: Kinematics>(
    file: &str,
    base: Option<&str>,
    link_poses: fn(&[f64]) -> Vec<Pose<f64>>,
    link_positions: Option<Positions>,
) {
    let tree = kinematics::load(robot_path(file)).unwrap();
    let fk = ReferenceFk::new(tree.clone());
    let reach = tree.reach();
    let base = base.unwrap_or_else(|| tree.link(tree.root()).name.as_str()).to_owned();
    let mut runner = TestRunner::new(Config { cases: CASES / 10, failure_persistence: None, ..Config::default() });
    runner
        .run(&configuration(&tree), |q| {
            let poses = link_poses(&q);
            assert_eq!(poses.len(), R::LINK_NAMES.len());
            let mut out = vec![Pose { rotation: [[0.0; 3]; 3], translation: [0.0; 3] }; R::LINK_NAMES.len()];
            R::link_poses_into(&q, &mut out).unwrap();
            let positions = link_positions.map(|f| f(&q));
            for (i, link) in R::LINK_NAMES.iter().enumerate() {
                let expected = fk.relative_pose(&q, &base, link).unwrap();
                let d = distance(&poses[i], &expected, reach);
                proptest::prop_assert!(d <= F64_TOLERANCE, "{file} {link}: off by {d:e} at q = {q:?}");
                proptest::prop_assert_eq!(out[i], poses[i]);
                if let Some(positions) = &positions {
                    // Compiled on their own (no rotations), so rounded their own way: to the reference.
                    let position = Pose { rotation: poses[i].rotation, translation: positions[i] };
                    let d = distance(&position, &expected, reach);
                    proptest::prop_assert!(d <= F64_TOLERANCE, "{file} {link} position: off by {d:e} at q = {q:?}");
                }
            }
            Ok(())
        })
        .unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn listed_links_come_in_the_order_given() {
    assert_eq!(
        HumanoidFeetAndFingers::LINK_NAMES,
        ["RFinger13_link", "l_sole", "torso", "CameraBottom_optical_frame", "RThumb2_link", "r_sole"]
    );
    assert_eq!(<HumanoidFeetAndFingers as Kinematics>::LINK_NAMES.len(), 6);
    assert_eq!(QuadrupedFeet::LINK_NAMES, ["RL_foot", "FR_foot"]);
    assert_eq!(DualArmLeftTool::LINK_NAMES, ["tool_l"]);
    assert_eq!(PandaFromLink2::LINK_NAMES, ["flange", "panda_link1"]);
    // One listed link is still an array of one.
    let [_]: [Pose<f64>; 1] = DualArmLeftTool::link_poses(&[0.0; DualArmLeftTool::DOF]);
}

#[test]
fn listed_links_agree_with_the_reference() {
    check::<HumanoidFeetAndFingers>(
        "humanoid.urdf",
        None,
        |q| HumanoidFeetAndFingers::link_poses(q.try_into().unwrap()).to_vec(),
        Some(|q| HumanoidFeetAndFingers::link_positions(q.try_into().unwrap()).to_vec()),
    );
    check::<QuadrupedFeet>(
        "quadruped.urdf",
        None,
        |q| QuadrupedFeet::link_poses(q.try_into().unwrap()).to_vec(),
        Some(|q| QuadrupedFeet::link_positions(q.try_into().unwrap()).to_vec()),
    );
    check::<DualArmLeftTool>(
        "dual_arm_torso.urdf",
        None,
        |q| DualArmLeftTool::link_poses(q.try_into().unwrap()).to_vec(),
        None,
    );
    check::<PandaFromLink2>(
        "panda.toml",
        Some("panda_link2"),
        |q| PandaFromLink2::link_poses(q.try_into().unwrap()).to_vec(),
        None,
    );
}

/// The f32 functions of a list agree within the f32 tolerance.
#[test]
fn listed_links_in_f32() {
    let tree = kinematics::load(robot_path("humanoid.urdf")).unwrap();
    let fk = ReferenceFk::new(tree.clone());
    let reach = tree.reach();
    let mut runner = TestRunner::new(Config { cases: CASES / 10, failure_persistence: None, ..Config::default() });
    runner
        .run(&configuration(&tree), |q| {
            let q32: Vec<f32> = q.iter().map(|&x| x as f32).collect();
            let poses = HumanoidFeetAndFingers::link_poses_f32(q32.as_slice().try_into().unwrap());
            let q_rounded: Vec<f64> = q32.iter().map(|&x| f64::from(x)).collect();
            for (pose, link) in poses.into_iter().zip(HumanoidFeetAndFingers::LINK_NAMES) {
                let expected = fk.relative_pose(&q_rounded, "base_link", link).unwrap();
                let d = distance(&to_f64(pose), &expected, reach);
                proptest::prop_assert!(d <= F32_TOLERANCE, "{link} f32: off by {d:e} at q = {q:?}");
            }
            Ok(())
        })
        .unwrap_or_else(|e| panic!("{e}"));
}
