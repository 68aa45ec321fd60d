//! A derived 200-joint chain compiles in a debug build (issue 13: rustc overflowed its stack on a
//! derived 500-joint chain, whose expressions nested as deep as the chain is long; see
//! `kinematics-compiler/tests/expression_depth.rs` for the bound on nesting, which is what fails
//! without it: the rustc we build with compiled even the unbounded 500-joint planar chain, in 20 s,
//! too slow for this suite). The planar chain is the deep case: its rotations merge into angle
//! sums `q1 + ... + qk`.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use kinematics::{AGREEMENT_TOLERANCE, Kinematics};

#[derive(Kinematics)]
#[kinematics(dh = "tests/emitted/planar_200.toml", tip = "link200")]
struct Planar200;

#[test]
fn a_200_joint_chain_compiles_and_agrees() {
    let q: Vec<f64> = (0..200).map(|i| 0.01 * f64::from(i % 17) - 0.05).collect();
    let q: [f64; 200] = q.try_into().unwrap();
    let pose = Planar200::tip_pose(&q);
    let reference = Planar200::reference().unwrap().relative_pose(&q, "base", "link200").unwrap();
    // The reach: the sum of the link lengths (0.101 + ... + 0.300 m).
    let reach: f64 = (1..=200).map(|i| 0.1 + 0.001 * f64::from(i)).sum();
    let deviation = pose.deviation(&reference, reach);
    assert!(deviation <= AGREEMENT_TOLERANCE, "off by {deviation:e}");
    let mut out = vec![pose; Planar200::LINK_NAMES.len()];
    Planar200::link_poses_into(&q, &mut out).unwrap();
}
