//! The exactness policy (issue 13, "one robot, one meaning"): the model decides once which written
//! angles are exact quarter turns, and the compiled code and the runtime reference always compute
//! that same robot, whatever the policy.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use kinematics::model::{ExactAngles, KinematicTree, parse_source_with};
use kinematics::{AGREEMENT_TOLERANCE, Configurations, Pose, ReferenceFk};
use kinematics_compiler::{Request, compile};

fn load_with(file: &str, policy: ExactAngles) -> KinematicTree {
    let text = std::fs::read_to_string(common::robot_path(file)).unwrap();
    parse_source_with(file, &text, policy).unwrap_or_else(|e| panic!("{e}"))
}

/// The largest deviation (as `Pose::deviation`, NaN-aware) of every compiled link pose from the
/// reference over `samples` configurations.
fn worst_deviation(tree: &KinematicTree, samples: usize) -> f64 {
    let compiled = compile(tree, &Request::all_links()).unwrap();
    let fk = ReferenceFk::new(tree.clone());
    let reach = tree.reach();
    let ids: Vec<usize> = compiled.frames().iter().map(|f| tree.link_id(&f.link).unwrap().0).collect();
    let mut worst = 0.0f64;
    for q in Configurations::new(tree).take(samples) {
        let reference = fk.link_poses(&q).unwrap();
        for (entries, &id) in compiled.eval(&q).iter().zip(&ids) {
            let d = Pose::from_entries(entries).deviation(&reference[id], reach);
            assert!(!d.is_nan());
            worst = if d > worst { d } else { worst };
        }
    }
    worst
}

fn urdf_robots() -> Vec<String> {
    let mut files: Vec<String> = std::fs::read_dir(common::robot_path(""))
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|f| f.ends_with(".urdf"))
        .collect();
    files.sort();
    files
}

#[test]
fn with_recognition_off_every_real_urdf_is_computed_as_written_to_1e_14() {
    for file in urdf_robots() {
        let tree = load_with(&file, ExactAngles::Off);
        assert!(tree.recognised_angles().is_empty(), "{file}");
        let worst = worst_deviation(&tree, 300);
        assert!(worst <= 1e-14, "{file}: compiled code off by {worst:e} x reach with exact angles off");
    }
}

#[test]
fn with_recognition_on_every_robot_agrees_with_its_reference() {
    for file in urdf_robots() {
        let tree = load_with(&file, ExactAngles::default());
        let worst = worst_deviation(&tree, 300);
        assert!(worst <= AGREEMENT_TOLERANCE, "{file}: off by {worst:e} x reach");
    }
}

#[test]
#[allow(clippy::approx_constant, reason = "the decimals ROS files write for pi/2 and pi, on purpose")]
fn the_ros_spelled_ur5_costs_what_the_exact_ur5_costs() {
    let cost = |file: &str, policy| compile(&load_with(file, policy), &Request::tip("tool0")).unwrap().op_count();
    let exact = cost("ur5.urdf", ExactAngles::default());
    let ros = cost("ur5_ros.urdf", ExactAngles::default());
    assert_eq!(ros, exact, "ROS spellings of pi/2 and pi are quarter turns");
    let literal = cost("ur5_ros.urdf", ExactAngles::Off);
    assert!(literal.mul > exact.mul && literal.add > exact.add, "{literal} vs {exact}");
    // Same code, not just the same count.
    let text = |file: &str| {
        let compiled = compile(&load_with(file, ExactAngles::default()), &Request::tip("tool0")).unwrap();
        compiled.frame_text(0)
    };
    assert_eq!(text("ur5_ros.urdf"), text("ur5.urdf"));
    // Every angle the policy changed is listed, with the change.
    let tree = load_with("ur5_ros.urdf", ExactAngles::default());
    let changed: Vec<(&str, f64)> = tree.recognised_angles().iter().map(|a| (a.joint.as_str(), a.written)).collect();
    assert_eq!(changed.len(), 5, "{changed:?}");
    assert!(changed.contains(&("shoulder_lift_joint", 1.57079632679)), "{changed:?}");
    assert!(changed.contains(&("base_link-base_fixed_joint", 3.14159265359)), "{changed:?}");
    for a in tree.recognised_angles() {
        assert!(a.change().abs() < 1e-11 && a.change() != 0.0, "{a:?}");
    }
}

/// `n` revolute joints, each behind a fixed half turn about x written as ROS writes pi.
fn half_turn_chain(n: usize, rpy: &str) -> String {
    let mut text = String::from("<robot name=\"halfturns\"><link name=\"l0\"/>");
    for i in 1..=n {
        text.push_str(&format!(
            "<link name=\"l{i}\"/><joint name=\"j{i}\" type=\"continuous\"><parent link=\"l{}\"/>\
             <child link=\"l{i}\"/><origin xyz=\"0.1 0 0.2\" rpy=\"{rpy}\"/><axis xyz=\"0 0 1\"/></joint>",
            i - 1
        ));
    }
    text.push_str("</robot>");
    text
}

#[test]
fn chains_of_near_quarter_turns_agree_under_either_policy() {
    for rpy in ["3.14159265359 0 0", "1.57079632679 0 0", "0 -1.57079632679 3.14159265359", "1.5708 0 0"] {
        let text = half_turn_chain(10, rpy);
        for policy in [ExactAngles::default(), ExactAngles::Off] {
            let tree = parse_source_with("chain.urdf", &text, policy).unwrap();
            let worst = worst_deviation(&tree, 500);
            assert!(worst <= AGREEMENT_TOLERANCE, "rpy {rpy} under {policy:?}: off by {worst:e} x reach");
        }
    }
}

#[test]
fn angles_beyond_the_range_are_used_as_written() {
    // 1e16 rad lies within 1e-12 of *some* multiple of pi/2 in f64 arithmetic; it is no quarter
    // turn. 202.63... is 64.5 pi, just past the range.
    for angle in ["1e16", "-3e17", "1e300", "202.63272615654165"] {
        let text = half_turn_chain(3, &format!("{angle} 0 0"));
        let tree = parse_source_with("chain.urdf", &text, ExactAngles::default()).unwrap();
        assert!(tree.recognised_angles().is_empty(), "{angle}");
        let worst = worst_deviation(&tree, 200);
        assert!(worst <= AGREEMENT_TOLERANCE, "rpy {angle}: off by {worst:e} x reach");
    }
}
