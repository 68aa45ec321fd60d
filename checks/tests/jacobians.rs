//! Every generated Jacobian of every robot in `robots/` (each leaf, relative to the root, in both
//! frames) against three witnesses that share none of its code: the runtime reference's
//! Jacobian, the generated *pose* run on dual numbers, and Richardson-extrapolated central
//! differences of the generated pose. Tolerance: `1e-12` times the robot's reach for the linear
//! rows, `1e-12` for the angular rows (NaN and infinity fail).
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use common::*;
use kinematics::ReferenceFk;
use kinematics::model::JacobianFrame;
use kinematics_checks::{ROBOTS, differences, dual, on_every_core};
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::TestRunner;

/// Jacobian agreement: the poses' tolerance, linear rows relative to the reach, angular rows
/// absolute.
const TOLERANCE: f64 = F64_TOLERANCE;

fn reference(file: &str) -> ReferenceFk {
    ReferenceFk::new(kinematics::load(robot_path(file)).unwrap())
}

/// The largest difference of two Jacobians (columns of `[linear; angular]`), linear rows divided
/// by `reach`; infinite if either has a value that is not finite.
fn deviation(a: &[[f64; 6]], b: &[[f64; 6]], reach: f64) -> f64 {
    assert_eq!(a.len(), b.len(), "columns");
    let mut worst = 0.0f64;
    for (x, y) in a.iter().zip(b) {
        for r in 0..6 {
            if !(x[r].is_finite() && y[r].is_finite()) {
                return f64::INFINITY;
            }
            let scale = if r < 3 { reach } else { 1.0 };
            worst = worst.max((x[r] - y[r]).abs() / scale);
        }
    }
    worst
}

/// A runtime Jacobian as columns.
fn columns(j: &nalgebra::Matrix6xX<f64>) -> Vec<[f64; 6]> {
    (0..j.ncols()).map(|c| std::array::from_fn(|r| j[(r, c)])).collect()
}

/// Configurations of `tree` (the agreement tests' mix of values within, beyond and at special
/// angles), deterministic.
fn configurations(tree: &kinematics::KinematicTree, count: usize) -> Vec<Vec<f64>> {
    let mut runner = TestRunner::deterministic();
    let strategy = configuration(tree);
    (0..count).map(|_| strategy.new_tree(&mut runner).unwrap().current()).collect()
}

#[test]
fn every_generated_jacobian_against_the_runtime_and_dual_numbers() {
    let report = on_every_core(ROBOTS, |robot| {
        let fk = reference(robot.file);
        let tree = fk.tree();
        let (root, reach) = (tree.link(tree.root()).name.clone(), tree.reach());
        let (mut runtime, mut duals, mut local) = (0.0f64, 0.0f64, 0.0f64);
        for q in configurations(tree, 2_000) {
            let directions = dual::directions(tree, &q);
            for tip in robot.tips {
                let generated = (tip.jacobian)(&q);
                let expected = columns(&fk.jacobian(&q, &root, tip.link).unwrap());
                runtime = runtime.max(deviation(&generated, &expected, reach));
                duals = duals.max(deviation(&generated, &(tip.jacobian_by_duals)(&q, &directions), reach));
                let expected_local = columns(&fk.jacobian_in(&q, &root, tip.link, JacobianFrame::Local).unwrap());
                local = local.max(deviation(&(tip.jacobian_local)(&q), &expected_local, reach));
            }
        }
        assert!(runtime <= TOLERANCE, "{}: generated vs runtime {runtime:e}", robot.file);
        assert!(duals <= TOLERANCE, "{}: generated vs dual numbers {duals:e}", robot.file);
        assert!(local <= TOLERANCE, "{}: LOCAL vs runtime {local:e}", robot.file);
        format!("{}: runtime {runtime:.1e}, duals {duals:.1e}, LOCAL {local:.1e}", robot.file)
    });
    println!("largest deviation per robot (linear rows x reach):\n{}", report.join("\n"));
}

/// Richardson-extrapolated differences of the generated pose: slower (ten poses per column), so
/// fewer configurations.
#[test]
fn every_generated_jacobian_against_extrapolated_differences() {
    let report = on_every_core(ROBOTS, |robot| {
        let fk = reference(robot.file);
        let tree = fk.tree();
        let reach = tree.reach();
        let mut worst = 0.0f64;
        for q in configurations(tree, 40) {
            for tip in robot.tips {
                let differences = differences::jacobian(tree, tip.pose, &q);
                worst = worst.max(deviation(&(tip.jacobian)(&q), &differences, reach));
            }
        }
        assert!(worst <= TOLERANCE, "{}: generated vs differences {worst:e}", robot.file);
        format!("{}: {worst:.1e}", robot.file)
    });
    println!("largest deviation from extrapolated differences (linear rows x reach):\n{}", report.join("\n"));
}
