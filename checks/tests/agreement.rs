//! Generated code against the runtime reference, for every robot in `robots/`: every leaf link's
//! pose (f64 and f32) and position, and every link's pose, on 10,000 configurations per robot drawn
//! within the limits, beyond them, and from the special angles 0, +-pi/2, +-pi.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use std::cell::Cell;

use common::*;
use kinematics::{Pose, ReferenceFk};
use kinematics_checks::{GeneratedRobot, ROBOTS, on_every_core};
use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};

fn check_robot(robot: &GeneratedRobot) -> (f64, f64) {
    let tree = kinematics::load(robot_path(robot.file)).unwrap();
    assert_eq!(tree.dof(), robot.dof, "{}", robot.file);
    let fk = ReferenceFk::new(tree.clone());
    let reach = tree.reach();
    let (worst, worst_f32) = (Cell::new(0.0f64), Cell::new(0.0f64));
    let mut runner = TestRunner::new(Config { cases: CASES, failure_persistence: None, ..Config::default() });
    runner
        .run(&configuration(&tree), |q| {
            let reference = fk.link_poses(&q).unwrap();
            let check = |pose: &Pose<f64>, link: &str, tol: f64| -> Result<f64, TestCaseError> {
                let d = distance(pose, &reference[fk.link_id(link).unwrap().0], reach);
                prop_assert!(d <= tol, "{} link {link}: off by {d:e} (x reach {reach}) at q = {q:?}", robot.file);
                Ok(d)
            };
            for tip in robot.tips {
                let pose = (tip.pose)(&q);
                worst.set(worst.get().max(check(&pose, tip.link, F64_TOLERANCE)?));
                let ortho = orthonormality_error(&pose);
                prop_assert!(ortho < F64_TOLERANCE, "{} {}: |R^T R - I| = {ortho:e}", robot.file, tip.link);
                let position = Pose { rotation: pose.rotation, translation: (tip.position)(&q) };
                check(&position, tip.link, F64_TOLERANCE)?;
                let q32: Vec<f32> = q.iter().map(|&x| x as f32).collect();
                worst_f32.set(worst_f32.get().max(check(&to_f64((tip.pose_f32)(&q32)), tip.link, F32_TOLERANCE)?));
            }
            for (pose, link) in (robot.all_poses)(&q).iter().zip(robot.all_links) {
                worst.set(worst.get().max(check(pose, link, F64_TOLERANCE)?));
            }
            Ok(())
        })
        .unwrap_or_else(|e| panic!("{e}"));
    (worst.get(), worst_f32.get())
}

#[test]
fn every_robot_agrees_with_the_runtime_reference() {
    assert!(ROBOTS.len() >= 8, "robots/ should hold every robot: found {}", ROBOTS.len());
    for (robot, (worst, worst_f32)) in ROBOTS.iter().zip(on_every_core(ROBOTS, check_robot)) {
        println!("{:<28} {CASES} configurations: largest error {worst:.2e} (f64), {worst_f32:.2e} (f32)", robot.file);
    }
}

#[test]
fn all_links_cover_every_link_but_the_root() {
    for robot in ROBOTS {
        let tree = kinematics::load(robot_path(robot.file)).unwrap();
        assert_eq!(robot.all_links.len(), tree.links().len() - 1, "{}", robot.file);
    }
}
