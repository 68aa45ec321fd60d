//! The runtime geometric Jacobian against central finite differences of the runtime FK.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use common::reference;
use kinematics::ReferenceFk;
use nalgebra::{Matrix6xX, Vector3};
use proptest::prelude::*;

/// Central differences with step `H` are accurate to about `H^2` times the third derivative.
const H: f64 = 1e-6;
const FD_TOLERANCE: f64 = 1e-7;

/// The Jacobian of `tip` relative to `base`, by central differences of the pose.
fn finite_difference(fk: &ReferenceFk, q: &[f64], base: &str, tip: &str) -> Matrix6xX<f64> {
    let mut jac = Matrix6xX::zeros(q.len());
    for k in 0..q.len() {
        let mut plus = q.to_vec();
        let mut minus = q.to_vec();
        plus[k] += H;
        minus[k] -= H;
        let p = fk.relative_pose(&plus, base, tip).unwrap();
        let m = fk.relative_pose(&minus, base, tip).unwrap();
        let linear = (p.translation.vector - m.translation.vector) / (2.0 * H);
        // R(q+h) R(q-h)^T = exp(2h [w]x): the rotation vector over 2h is w, in the base frame.
        let angular: Vector3<f64> = (p.rotation * m.rotation.inverse()).scaled_axis() / (2.0 * H);
        for r in 0..3 {
            jac[(r, k)] = linear[r];
            jac[(r + 3, k)] = angular[r];
        }
    }
    jac
}

fn check(fk: &ReferenceFk, q: &[f64], base: &str, tip: &str) {
    let analytic = fk.jacobian(q, base, tip).unwrap();
    let numeric = finite_difference(fk, q, base, tip);
    let err = (&analytic - &numeric).amax();
    assert!(err < FD_TOLERANCE, "{base} -> {tip} at {q:?}: differs by {err:e}\n{analytic}\n{numeric}");
}

/// Prismatic joints, a mimic joint with a multiplier and a branch: every kind of column.
const MIXED: &str = r#"<robot name="mixed">
  <link name="base"/><link name="slider"/><link name="arm"/><link name="finger"/><link name="side"/>
  <joint name="slide" type="prismatic"><parent link="base"/><child link="slider"/>
    <origin xyz="0.1 0.2 0.3" rpy="0.3 -0.2 0.1"/><axis xyz="1 1 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="turn" type="revolute"><parent link="slider"/><child link="arm"/>
    <origin xyz="0 0.4 0" rpy="0 1.2 0"/><axis xyz="0 0.6 0.8"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="follow" type="revolute"><parent link="arm"/><child link="finger"/>
    <origin xyz="0.3 0 0.1"/><axis xyz="1 0 0"/><mimic joint="turn" multiplier="-0.5" offset="0.2"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="branch" type="continuous"><parent link="base"/><child link="side"/>
    <origin xyz="0 -1 0"/><axis xyz="0 0 1"/></joint>
</robot>"#;

fn q(n: usize) -> impl Strategy<Value = Vec<f64>> {
    proptest::collection::vec(-3.0..3.0f64, n)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn ur5_dh(q in q(6)) {
        check(&reference("ur5.toml"), &q, "base", "wrist_3_link");
        check(&reference("ur5.toml"), &q, "upper_arm_link", "wrist_2_link");
    }

    #[test]
    fn ur5_urdf(q in q(6)) {
        check(&reference("ur5.urdf"), &q, "base_link", "tool0");
    }

    #[test]
    fn seed_tree(q in q(3)) {
        check(&reference("seed_tree.urdf"), &q, "link1", "link4");
        check(&reference("seed_tree.urdf"), &q, "link1", "link2");
    }

    #[test]
    fn prismatic_mimic_and_branches(q in q(3)) {
        let fk = ReferenceFk::new(kinematics::model::parse_source("mixed.urdf", MIXED).unwrap());
        check(&fk, &q, "base", "finger");
        check(&fk, &q, "slider", "finger");
        check(&fk, &q, "base", "side");
    }
}

#[test]
fn columns_off_the_chain_are_zero() {
    let fk = ReferenceFk::new(kinematics::model::parse_source("mixed.urdf", MIXED).unwrap());
    let j = fk.jacobian(&[0.1, 0.2, 0.3], "base", "side").unwrap();
    assert_eq!(fk.tree().dof_names(), ["slide", "turn", "branch"]);
    assert!(j.column(0).iter().chain(j.column(1).iter()).all(|&v| v == 0.0));
    assert!(fk.jacobian(&[0.0; 3], "side", "finger").is_err());
}

#[test]
fn wrong_q_length_is_a_typed_error() {
    let fk = reference("ur5.toml");
    let err = fk.link_poses(&[0.0; 5]).unwrap_err();
    let message = err.to_string();
    assert!(matches!(err, kinematics::RuntimeError::WrongDof { expected: 6, got: 5, .. }));
    assert!(message.contains("6 degrees of freedom") && message.contains("shoulder_pan_joint"), "{message}");
    assert!(fk.link_pose(&[0.0; 6], "flange").unwrap_err().to_string().contains("link `flange` does not exist"));
}
