//! The runtime geometric Jacobian against central finite differences of the runtime FK, for bases
//! above, below and beside the tip, in both frames, and against hand-worked cases.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use common::reference;
use kinematics::ReferenceFk;
use kinematics::model::JacobianFrame;
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

/// Both frames against differences, and each of `base -> tip` and `tip -> base`.
fn check(fk: &ReferenceFk, q: &[f64], base: &str, tip: &str) {
    for (base, tip) in [(base, tip), (tip, base)] {
        let numeric = finite_difference(fk, q, base, tip);
        let analytic = fk.jacobian(q, base, tip).unwrap();
        assert!(analytic.iter().all(|v| v.is_finite()), "{base} -> {tip}: not finite");
        let err = (&analytic - &numeric).amax();
        assert!(err < FD_TOLERANCE, "{base} -> {tip} at {q:?}: differs by {err:e}\n{analytic}\n{numeric}");
        // LOCAL: both 3-vectors of every column in the tip's axes.
        let r = fk.relative_pose(q, base, tip).unwrap().rotation.inverse();
        let local = fk.jacobian_in(q, base, tip, JacobianFrame::Local).unwrap();
        for c in 0..numeric.ncols() {
            let linear = r * Vector3::new(numeric[(0, c)], numeric[(1, c)], numeric[(2, c)]);
            let angular = r * Vector3::new(numeric[(3, c)], numeric[(4, c)], numeric[(5, c)]);
            for k in 0..3 {
                let (dl, da) = ((local[(k, c)] - linear[k]).abs(), (local[(k + 3, c)] - angular[k]).abs());
                assert!(dl < FD_TOLERANCE && da < FD_TOLERANCE, "LOCAL {base} -> {tip} column {c}: {local}");
            }
        }
    }
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
        // Beside: the side link's branch and the finger's.
        check(&fk, &q, "side", "finger");
        check(&fk, &q, "finger", "finger");
    }

    #[test]
    fn bases_below_and_beside_the_tip_on_real_robots(q in q(17)) {
        let dual = reference("dual_arm_torso.urdf");
        let n = dual.tree().dof();
        check(&dual, &q[..n], "tool_l", "tool_r");
        check(&dual, &q[..n], "tool_l", "yumi_body");
        let ur5 = reference("ur5.urdf");
        check(&ur5, &q[..6], "base", "tool0");
        check(&ur5, &q[..6], "wrist_3_link", "upper_arm_link");
    }
}

/// A planar 2R arm (links 1 and 1), worked by hand: the tip at `(c1 + c12, s1 + s12)` moves with
/// `J = [-s1 - s12, -s12; c1 + c12, c12]` and turns at 1 rad/s per joint; seen from the tip, the
/// base turns the other way: at q = (0, pi/2) the tip is at (1, 1) and the base, in the tip's
/// frame, at (-1, 1).
#[test]
fn planar_2r_by_hand() {
    let fk = reference("planar_2r.toml");
    let q = [0.0, std::f64::consts::FRAC_PI_2];
    let j = fk.jacobian(&q, "base", "link2").unwrap();
    let expected = [[-1.0, -1.0], [1.0, 0.0], [0.0, 0.0], [0.0, 0.0], [0.0, 0.0], [1.0, 1.0]];
    for (r, row) in expected.iter().enumerate() {
        for (c, e) in row.iter().enumerate() {
            assert!((j[(r, c)] - e).abs() < 1e-15, "J[{r}][{c}] = {} (expected {e})\n{j}", j[(r, c)]);
        }
    }
    // The base seen from link2, in link2's axes (the base's turned by pi/2): joint 1's axis passes
    // through the base's origin, so its linear column is zero; joint 2's axis is at (-1, 0) in
    // link2's frame and the base's origin at (-1, 1): turning the base about it at -1 rad/s moves
    // that origin by -z x ((-1, 1) - (-1, 0)) = -z x (0, 1) = (1, 0).
    let back = fk.jacobian(&q, "link2", "base").unwrap();
    let expected = [[0.0, 1.0], [0.0, 0.0], [0.0, 0.0], [0.0, 0.0], [0.0, 0.0], [-1.0, -1.0]];
    for (r, row) in expected.iter().enumerate() {
        for (c, e) in row.iter().enumerate() {
            assert!((back[(r, c)] - e).abs() < 1e-15, "back J[{r}][{c}] = {} (expected {e})\n{back}", back[(r, c)]);
        }
    }
    // LOCAL of the forward Jacobian: link2's axes are the base's turned by pi/2.
    let local = fk.jacobian_in(&q, "base", "link2", JacobianFrame::Local).unwrap();
    let expected = [[1.0, 0.0], [1.0, 1.0], [0.0, 0.0], [0.0, 0.0], [0.0, 0.0], [1.0, 1.0]];
    for (r, row) in expected.iter().enumerate() {
        for (c, e) in row.iter().enumerate() {
            assert!((local[(r, c)] - e).abs() < 1e-15, "LOCAL J[{r}][{c}] = {} (expected {e})\n{local}", local[(r, c)]);
        }
    }
}

#[test]
fn columns_off_the_chain_are_zero() {
    let fk = ReferenceFk::new(kinematics::model::parse_source("mixed.urdf", MIXED).unwrap());
    let j = fk.jacobian(&[0.1, 0.2, 0.3], "base", "side").unwrap();
    assert_eq!(fk.tree().dof_names(), ["slide", "turn", "branch"]);
    assert!(j.column(0).iter().chain(j.column(1).iter()).all(|&v| v == 0.0));
    // Any base: the side link's branch does not move the finger, the finger's does.
    let beside = fk.jacobian(&[0.1, 0.2, 0.3], "side", "finger").unwrap();
    assert!(beside.column(0).iter().any(|&v| v != 0.0) && beside.column(2).iter().any(|&v| v != 0.0));
    assert!(fk.jacobian(&[0.0; 3], "side", "nowhere").is_err());
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
