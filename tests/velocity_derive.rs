//! The velocity functions `#[derive(Kinematics)]` emits with `jacobians`, from a user's point of
//! view: what the struct gets, and that its forms agree with the runtime reference and with each
//! other. (Every robot and the random trees are checked against three witnesses in `checks`.)
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use kinematics::{F64x4, Kinematics};

#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5.urdf", base = "base", tip = "tool0", positions, jacobians, scalars(f64, f32))]
/// The UR5 with its Jacobians.
pub struct Ur5;

/// Two tips of a planar arm, with Jacobians.
#[derive(Kinematics)]
#[kinematics(
    dh(
        convention = "standard",
        row("shoulder", 1.0, 0.0, 0.0, 0.0),
        row("elbow", 1.0, 0.0, 0.0, 0.0),
        row("wrist", 0.5, 0.0, 0.0, 0.0)
    ),
    tips("link2", "link3"),
    jacobians
)]
pub struct Planar;

const CONFIGURATIONS: [[f64; 6]; 3] =
    [[0.3, -1.2, 1.0, 0.4, -0.7, 2.0], [0.0; 6], [-2.9, 0.1, -0.4, 3.0, std::f64::consts::FRAC_PI_2, -1.0]];

fn reach() -> f64 {
    Ur5::reference().unwrap().tree().reach()
}

#[test]
fn ur5_jacobian_matches_the_runtime_reference() {
    let reference = Ur5::reference().unwrap();
    let tol = 1e-12 * reach().max(1.0);
    for q in CONFIGURATIONS {
        let j = Ur5::tip_jacobian(&q);
        let r = reference.jacobian(&q, "base", "tool0").unwrap();
        for row in 0..6 {
            for col in 0..6 {
                let (g, e) = (j[row][col], r[(row, col)]);
                assert!(g.is_finite() && (g - e).abs() < tol, "J[{row}][{col}] at {q:?}: {g} vs {e}");
            }
        }
    }
}

#[test]
fn ur5_forms_agree_with_each_other() {
    let tol = 1e-12 * reach().max(1.0);
    let qd = [0.5, -0.25, 1.0, 2.0, -1.5, 0.75];
    for q in CONFIGURATIONS {
        let j = Ur5::tip_jacobian(&q);
        let pose = Ur5::tip_pose(&q);
        let (pose2, j2) = Ur5::tip_pose_and_jacobian(&q);
        assert_eq!(pose2.translation.map(f64::to_bits).len(), 3);
        for k in 0..3 {
            assert!((pose2.translation[k] - pose.translation[k]).abs() < tol);
            for m in 0..3 {
                assert!((pose2.rotation[k][m] - pose.rotation[k][m]).abs() < tol);
            }
        }
        let local = Ur5::tip_jacobian_local(&q);
        let linear = Ur5::tip_position_jacobian(&q);
        let twist = Ur5::tip_twist(&q, &qd);
        let twist_local = Ur5::tip_twist_local(&q, &qd);
        let r = pose.rotation;
        for row in 0..6 {
            let jqd: f64 = (0..6).map(|c| j[row][c] * qd[c]).sum();
            assert!((twist[row] - jqd).abs() < tol, "twist row {row}");
            let block = row / 3 * 3;
            let local_jqd: f64 = (0..6).map(|c| local[row][c] * qd[c]).sum();
            assert!((twist_local[row] - local_jqd).abs() < tol, "local twist row {row}");
            for col in 0..6 {
                assert!((j2[row][col] - j[row][col]).abs() < tol);
                if row < 3 {
                    assert!((linear[row][col] - j[row][col]).abs() < tol);
                }
                // LOCAL = R^T LOCAL_WORLD_ALIGNED, per 3-vector.
                let a = row % 3;
                let expected: f64 = (0..3).map(|k| r[k][a] * j[block + k][col]).sum();
                assert!((local[row][col] - expected).abs() < tol, "LOCAL[{row}][{col}]");
            }
        }
    }
}

#[test]
fn ur5_jacobian_runs_on_lanes_f32_and_batches() {
    let qs: Vec<[f64; 6]> = CONFIGURATIONS.iter().copied().chain([[1.0; 6]]).collect();
    let lanes: [F64x4; 6] = std::array::from_fn(|i| F64x4([qs[0][i], qs[1][i], qs[2][i], qs[3][i]]));
    let packed = Ur5::tip_jacobian_generic(&lanes);
    let mut batch = vec![[[0.0; 6]; 6]; qs.len()];
    Ur5::tip_jacobian_batch(&qs, &mut batch).unwrap();
    let mut pairs = vec![(Ur5::tip_pose(&qs[0]), [[0.0; 6]; 6]); qs.len()];
    Ur5::tip_pose_and_jacobian_batch(&qs, &mut pairs).unwrap();
    for (k, q) in qs.iter().enumerate() {
        let j = Ur5::tip_jacobian(q);
        assert_eq!(batch[k], j, "batch {k}");
        assert_eq!(pairs[k], Ur5::tip_pose_and_jacobian(q), "pose and Jacobian batch {k}");
        for row in 0..6 {
            for col in 0..6 {
                assert_eq!(packed[row][col].0[k], j[row][col], "lane {k}");
            }
        }
        let q32 = q.map(|x| x as f32);
        let j32 = Ur5::tip_jacobian_f32(&q32);
        for row in 0..6 {
            for col in 0..6 {
                assert!((f64::from(j32[row][col]) - j[row][col]).abs() < 1e-5 * reach().max(1.0));
            }
        }
    }
}

#[test]
fn several_tips_give_arrays_of_jacobians() {
    let q = [0.4, -0.3, 1.1];
    let reference = Planar::reference().unwrap();
    let jacobians = Planar::tip_jacobians(&q);
    for (k, tip) in Planar::TIPS.iter().enumerate() {
        let r = reference.jacobian(&q, Planar::BASE, tip).unwrap();
        for row in 0..6 {
            for col in 0..3 {
                assert!((jacobians[k][row][col] - r[(row, col)]).abs() < 1e-12 * 2.5, "{tip} J[{row}][{col}]");
            }
        }
    }
    // The link2 tip does not move with the wrist.
    assert!(jacobians[0].iter().all(|row| row[2] == 0.0));
    let twists = Planar::tip_twists(&q, &[1.0, 0.0, 0.0]);
    assert!((twists[1][5] - 1.0).abs() < 1e-15);
    let _: [(kinematics::Pose<f64>, [[f64; 3]; 6]); 2] = Planar::tip_poses_and_jacobians(&q);
    assert_eq!(<Planar as Kinematics>::TIPS.len(), 2);
}

/// `count` pseudo-random rows of `N` values in [-2, 2).
fn rows<const N: usize>(count: usize, seed: f64) -> Vec<[f64; N]> {
    let mut x = seed;
    (0..count)
        .map(|_| {
            std::array::from_fn(|_| {
                x = (x * 7919.0 + 0.377).fract();
                4.0 * x - 2.0
            })
        })
        .collect()
}

/// The twists' batches are the twists, bit for bit (`to_bits`: `==` would take -0.0 for 0.0), in
/// both frames, `f64` and `f32`, over 101 configurations (the last pack of four or eight padded).
#[test]
fn twist_batches_are_the_twists_bit_for_bit() {
    let (qs, qds) = (rows::<6>(101, 0.123), rows::<6>(101, 0.456));
    let bits = |t: &[f64; 6]| t.map(f64::to_bits);
    let bits32 = |t: &[f32; 6]| t.map(f32::to_bits);
    let mut out = vec![[0.0; 6]; qs.len()];
    Ur5::tip_twist_batch(&qs, &qds, &mut out).unwrap();
    for i in 0..qs.len() {
        assert_eq!(bits(&out[i]), bits(&Ur5::tip_twist(&qs[i], &qds[i])), "tip_twist_batch {i}");
    }
    Ur5::tip_twist_local_batch(&qs, &qds, &mut out).unwrap();
    for i in 0..qs.len() {
        assert_eq!(bits(&out[i]), bits(&Ur5::tip_twist_local(&qs[i], &qds[i])), "tip_twist_local_batch {i}");
    }
    let narrow = |rows: &[[f64; 6]]| -> Vec<[f32; 6]> { rows.iter().map(|r| r.map(|x| x as f32)).collect() };
    let (qs32, qds32) = (narrow(&qs), narrow(&qds));
    let mut out32 = vec![[0.0f32; 6]; qs.len()];
    Ur5::tip_twist_batch_f32(&qs32, &qds32, &mut out32).unwrap();
    for i in 0..qs.len() {
        assert_eq!(bits32(&out32[i]), bits32(&Ur5::tip_twist_f32(&qs32[i], &qds32[i])), "tip_twist_batch_f32 {i}");
    }
    Ur5::tip_twist_local_batch_f32(&qs32, &qds32, &mut out32).unwrap();
    for i in 0..qs.len() {
        let one = Ur5::tip_twist_local_f32(&qs32[i], &qds32[i]);
        assert_eq!(bits32(&out32[i]), bits32(&one), "tip_twist_local_batch_f32 {i}");
    }
}

/// Several tips: one array of twists per configuration.
#[test]
fn several_tips_give_batches_of_twists() {
    let (qs, qds) = (rows::<3>(13, 0.321), rows::<3>(13, 0.654));
    let mut out = vec![[[0.0; 6]; 2]; qs.len()];
    Planar::tip_twists_batch(&qs, &qds, &mut out).unwrap();
    Planar::tip_twists_local_batch(&qs, &qds, &mut out[..0]).expect_err("an output of another length");
    for i in 0..qs.len() {
        let want = Planar::tip_twists(&qs[i], &qds[i]);
        assert_eq!(out[i].map(|t| t.map(f64::to_bits)), want.map(|t| t.map(f64::to_bits)), "tip_twists_batch {i}");
    }
}

/// A `qs` or `qds` of another length than `out` is refused by name, and nothing is written.
#[test]
fn twist_batches_refuse_inputs_of_another_length() {
    let (qs, qds) = (rows::<6>(9, 0.1), rows::<6>(9, 0.2));
    let mut out = vec![[7.0; 6]; 9];
    let error = Ur5::tip_twist_batch(&qs, &qds[..8], &mut out).unwrap_err();
    assert_eq!(
        error,
        kinematics::KinematicsError::WrongInputLength { robot: "ur5", input: "qds", expected: 9, got: 8 }
    );
    assert!(error.to_string().contains("`qds` holds 8 values, but the output holds 9"), "{error}");
    let error = Ur5::tip_twist_local_batch(&qs[..2], &qds, &mut out).unwrap_err();
    assert_eq!(error, kinematics::KinematicsError::WrongInputLength { robot: "ur5", input: "qs", expected: 9, got: 2 });
    Ur5::tip_twist_batch(&qs, &qds, &mut out[..4]).expect_err("an output of another length");
    assert!(out.iter().all(|t| *t == [7.0; 6]), "nothing is written");
}
