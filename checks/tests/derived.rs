//! `#[derive(Kinematics)]` output against the runtime reference, for every robot in `robots/`,
//! from its file and (DH tables) from the same table written inline: every tip and every link, on
//! 10,000 configurations each, f64 and f32, through the `Kinematics` trait.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use std::cell::Cell;

use common::*;
use kinematics::{Pose, ReferenceFk};
use kinematics_checks::{DERIVED, DerivedRobot, on_every_core};
use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};

fn zero_poses(n: usize) -> Vec<Pose<f64>> {
    vec![Pose { rotation: [[0.0; 3]; 3], translation: [0.0; 3] }; n]
}

fn check(robot: &DerivedRobot) -> (f64, f64) {
    // The witness is built from the file by the runtime, not from anything the derive produced.
    let tree = kinematics::load(robot_path(robot.file)).unwrap();
    let fk = ReferenceFk::new(tree.clone());
    let reach = tree.reach();
    let (worst, worst_f32) = (Cell::new(0.0f64), Cell::new(0.0f64));
    let mut runner = TestRunner::new(Config { cases: CASES, failure_persistence: None, ..Config::default() });
    runner
        .run(&configuration(&tree), |q| {
            let reference = fk.link_poses(&q).unwrap();
            let expected = |link: &str| reference[fk.link_id(link).unwrap().0];
            let mut tips = zero_poses(robot.tips.len());
            (robot.tip_poses_into)(&q, &mut tips).unwrap();
            let mut links = zero_poses(robot.links.len());
            (robot.link_poses_into)(&q, &mut links).unwrap();
            let q32: Vec<f32> = q.iter().map(|&x| x as f32).collect();
            let tips32 = (robot.tip_poses_f32)(&q32);
            for (pose, link) in tips.iter().chain(&links).zip(robot.tips.iter().chain(robot.links)) {
                let d = distance(pose, &expected(link), reach);
                prop_assert!(d <= F64_TOLERANCE, "{} ({}) {link}: off by {d:e} at q = {q:?}", robot.file, robot.how);
                worst.set(worst.get().max(d));
            }
            for (pose, link) in tips32.iter().zip(robot.tips) {
                let pose = Pose {
                    rotation: pose.rotation.map(|r| r.map(f64::from)),
                    translation: pose.translation.map(f64::from),
                };
                let d = distance(&pose, &expected(link), reach);
                prop_assert!(
                    d <= F32_TOLERANCE,
                    "{} ({}) {link} f32: off by {d:e} at q = {q:?}",
                    robot.file,
                    robot.how
                );
                worst_f32.set(worst_f32.get().max(d));
            }
            Ok(())
        })
        .unwrap_or_else(|e| panic!("{e}"));
    (worst.get(), worst_f32.get())
}

#[test]
fn every_derived_robot_agrees_with_the_runtime_reference() {
    assert!(DERIVED.len() >= 8, "robots/ should hold every robot: found {}", DERIVED.len());
    for (robot, (worst, worst_f32)) in DERIVED.iter().zip(on_every_core(DERIVED, check)) {
        println!("{:<28} {:<7} largest error {worst:.2e} (f64), {worst_f32:.2e} (f32)", robot.file, robot.how);
    }
}

#[test]
fn the_reference_of_a_derived_robot_is_the_same_robot() {
    for robot in DERIVED {
        let from_derive = (robot.reference)().unwrap();
        let from_file = kinematics::load(robot_path(robot.file)).unwrap();
        assert_eq!(from_derive.tree().dof_names(), from_file.dof_names(), "{}", robot.file);
        assert_eq!(from_derive.tree().links().len(), from_file.links().len(), "{}", robot.file);
    }
}
