//! Generated code against the runtime reference, for every robot in `robots/`: every leaf link's
//! pose (f64 and f32) and position, and every link's pose, on 10,000 configurations per robot drawn
//! within the limits, beyond them, and from the special angles 0, +-pi/2, +-pi.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use std::cell::Cell;

use kinematics::model::{Elementary, JointKind, KinematicTree};
use kinematics::{Pose, ReferenceFk};
use kinematics_checks::{GeneratedRobot, ROBOTS};
use nalgebra::{Isometry3, Matrix3};
use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};

/// f64 agreement, relative to the robot's reach (metres) and absolute for rotation entries.
const F64_TOLERANCE: f64 = 1e-12;
/// f32 agreement, the same way.
const F32_TOLERANCE: f64 = 1e-5;
const CASES: u32 = 10_000;

fn robot_path(file: &str) -> String {
    format!("{}/../robots/{file}", env!("CARGO_MANIFEST_DIR"))
}

/// An upper bound on how far any link gets from the base: every fixed offset plus every prismatic
/// stroke, laid end to end (at least 1 m, so tiny robots are held to the absolute tolerance).
fn reach(tree: &KinematicTree) -> f64 {
    let offsets: f64 = tree
        .joints()
        .iter()
        .flat_map(|j| j.origin.steps().iter().chain(j.after_motion.steps()))
        .map(|s| match s {
            Elementary::Translation(v) => (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt(),
            Elementary::Rotation(..) => 0.0,
        })
        .sum();
    let strokes: f64 = tree
        .joints()
        .iter()
        .filter(|j| j.kind == JointKind::Prismatic)
        .map(|j| j.limits.map_or(1.0, |l| l.lower.abs().max(l.upper.abs()) + 1.0))
        .sum();
    (offsets + strokes).max(1.0)
}

/// Per joint: a special angle, a value within the limits, or one up to 1 beyond them.
fn configuration(tree: &KinematicTree) -> impl Strategy<Value = Vec<f64>> {
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
    per_joint
}

/// Largest difference: translation relative to `reach`, rotation entries absolute.
fn distance(generated: &Pose<f64>, reference: &Isometry3<f64>, reach: f64) -> f64 {
    let r = reference.rotation.to_rotation_matrix();
    let mut worst: f64 = 0.0;
    for i in 0..3 {
        worst = worst.max((generated.translation[i] - reference.translation.vector[i]).abs() / reach);
        for j in 0..3 {
            worst = worst.max((generated.rotation[i][j] - r[(i, j)]).abs());
        }
    }
    worst
}

fn orthonormality_error(pose: &Pose<f64>) -> f64 {
    let r = pose.rotation;
    let m = Matrix3::new(r[0][0], r[0][1], r[0][2], r[1][0], r[1][1], r[1][2], r[2][0], r[2][1], r[2][2]);
    (m.transpose() * m - Matrix3::identity()).amax()
}

fn to_f64(p: Pose<f32>) -> Pose<f64> {
    Pose { rotation: p.rotation.map(|row| row.map(f64::from)), translation: p.translation.map(f64::from) }
}

fn check_robot(robot: &GeneratedRobot) -> (f64, f64) {
    let tree = kinematics::load(robot_path(robot.file)).unwrap();
    assert_eq!(tree.dof(), robot.dof, "{}", robot.file);
    let fk = ReferenceFk::new(tree.clone());
    let reach = reach(&tree);
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
    for robot in ROBOTS {
        let (worst, worst_f32) = check_robot(robot);
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
