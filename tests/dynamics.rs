//! `#[kinematics(dynamics)]`: the generated dynamics against the runtime reference, in `f64`,
//! `f32`, lanes and batches; forward dynamics' refusal of a singular mass matrix.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)] // tests fail loudly

use kinematics::runtime::ReferenceDynamics;
use kinematics::{F64x4, Kinematics, KinematicsError};

#[derive(Kinematics)]
#[kinematics(urdf = "robots/panda.urdf", dynamics, scalars(f64, f32))]
struct Panda;

#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5.urdf", dynamics(gravity = [0.5, 0, -9.81]))]
struct Ur5;

/// A two-joint arm whose hand carries no mass: its wrist moves nothing.
#[derive(Kinematics)]
#[kinematics(urdf = "tests/fixtures/dynamics/massless_hand.urdf", dynamics)]
struct MasslessHand;

fn close(got: &[f64], want: &[f64], relative: f64, what: &str) {
    let scale = want.iter().fold(1.0f64, |s, x| s.max(x.abs()));
    for (k, (g, w)) in got.iter().zip(want).enumerate() {
        assert!(g.is_finite() && (g - w).abs() <= relative * scale, "{what}[{k}]: {g} against {w}");
    }
}

fn states(n: usize, nv: usize, count: usize) -> Vec<(Vec<f64>, Vec<f64>, Vec<f64>)> {
    let mut x = 0.123_f64;
    let mut next = move || {
        x = (x * 7919.0 + 0.377).fract();
        4.0 * x - 2.0
    };
    (0..count)
        .map(|_| {
            ((0..n).map(|_| next()).collect(), (0..nv).map(|_| next()).collect(), (0..nv).map(|_| next()).collect())
        })
        .collect()
}

#[test]
fn the_panda_agrees_with_the_reference() {
    let reference =
        ReferenceDynamics::new(Panda::reference().unwrap().tree().clone(), [0.0, 0.0, -9.81], false).unwrap();
    for (q, v, a) in states(Panda::DOF, Panda::VELOCITY_DOF, 200) {
        let (qa, va, aa): ([f64; 8], [f64; 8], [f64; 8]) =
            (q.clone().try_into().unwrap(), v.clone().try_into().unwrap(), a.clone().try_into().unwrap());
        let tau = reference.inverse_dynamics(&q, &v, &a).unwrap();
        close(&Panda::inverse_dynamics(&qa, &va, &aa), &tau, 1e-12, "inverse dynamics");
        close(&Panda::gravity_torques(&qa), &reference.gravity_torques(&q).unwrap(), 1e-12, "gravity");
        close(&Panda::nonlinear_effects(&qa, &va), &reference.nonlinear_effects(&q, &v).unwrap(), 1e-12, "h");
        let m = reference.mass_matrix(&q).unwrap();
        for (i, row) in Panda::mass_matrix(&qa).iter().enumerate() {
            close(row, &m.row(i).iter().copied().collect::<Vec<_>>(), 1e-12, "mass matrix");
        }
        let taua: [f64; 8] = tau.clone().try_into().unwrap();
        close(&Panda::forward_dynamics(&qa, &va, &taua).unwrap(), &a, 1e-9, "forward dynamics");
        let q32 = qa.map(|x| x as f32);
        let g32 = Panda::gravity_torques_f32(&q32).map(f64::from);
        close(&g32, &reference.gravity_torques(&q).unwrap(), 1e-4, "gravity f32");
        // Lanes: the same configuration in each of four lanes.
        let lanes = Panda::gravity_torques_generic(&qa.map(F64x4::splat));
        close(&lanes.map(|l| l.to_array()[3]), &Panda::gravity_torques(&qa), 0.0, "gravity in lanes");
    }
}

#[test]
fn the_ur5_takes_its_gravity() {
    let reference = ReferenceDynamics::new(Ur5::reference().unwrap().tree().clone(), [0.5, 0.0, -9.81], false).unwrap();
    for (q, _, _) in states(6, 6, 50) {
        let qa: [f64; 6] = q.clone().try_into().unwrap();
        close(&Ur5::gravity_torques(&qa), &reference.gravity_torques(&q).unwrap(), 1e-12, "gravity");
        let mut out = [[0.0; 6]; 3];
        Ur5::gravity_torques_batch(&[qa; 3], &mut out).unwrap();
        assert_eq!(out[2], Ur5::gravity_torques(&qa));
    }
}

/// The UR5 on a free-flying base: 13 entries of `q` (position, quaternion, joints), 12 velocities
/// (the base's linear and angular velocity in its own axes, then the joints).
#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5.urdf", floating_base, dynamics)]
struct FlyingUr5;

#[test]
fn a_floating_base_agrees_with_the_reference() {
    let reference =
        ReferenceDynamics::new(FlyingUr5::reference().unwrap().tree().clone(), [0.0, 0.0, -9.81], false).unwrap();
    assert_eq!((FlyingUr5::DOF, FlyingUr5::VELOCITY_DOF), (13, 12));
    for (mut q, v, a) in states(13, 12, 100) {
        // A unit quaternion (the generated code normalises it as the reference does).
        let norm = q[3..7].iter().map(|x| x * x).sum::<f64>().sqrt();
        q[3..7].iter_mut().for_each(|x| *x /= norm);
        let (qa, va, aa): ([f64; 13], [f64; 12], [f64; 12]) =
            (q.clone().try_into().unwrap(), v.clone().try_into().unwrap(), a.clone().try_into().unwrap());
        let tau = reference.inverse_dynamics(&q, &v, &a).unwrap();
        close(&FlyingUr5::inverse_dynamics(&qa, &va, &aa), &tau, 1e-12, "inverse dynamics");
        close(&FlyingUr5::gravity_torques(&qa), &reference.gravity_torques(&q).unwrap(), 1e-12, "gravity");
        let m = reference.mass_matrix(&q).unwrap();
        for (i, row) in FlyingUr5::mass_matrix(&qa).iter().enumerate() {
            close(row, &m.row(i).iter().copied().collect::<Vec<_>>(), 1e-12, "mass matrix");
        }
        // Forward dynamics undoes inverse dynamics, in torque units (the floating base's mass
        // matrix is well conditioned enough for 1e-9 in accelerations too).
        let taua: [f64; 12] = tau.try_into().unwrap();
        close(&FlyingUr5::forward_dynamics(&qa, &va, &taua).unwrap(), &a, 1e-9, "forward dynamics");
    }
}

/// The humanoid (the NAO with its published inertias) on a free-flying torso: 32 entries of `q`,
/// 31 velocities; its 17 mimic joints (the right hip, the fingers) fold into their sources.
#[derive(Kinematics)]
#[kinematics(urdf = "robots/humanoid.urdf", floating_base, dynamics)]
struct FlyingHumanoid;

#[test]
fn a_free_flying_humanoid_agrees_with_the_reference() {
    let reference =
        ReferenceDynamics::new(FlyingHumanoid::reference().unwrap().tree().clone(), [0.0, 0.0, -9.81], false).unwrap();
    assert_eq!((FlyingHumanoid::DOF, FlyingHumanoid::VELOCITY_DOF), (32, 31));
    for (mut q, v, a) in states(32, 31, 100) {
        let norm = q[3..7].iter().map(|x| x * x).sum::<f64>().sqrt();
        q[3..7].iter_mut().for_each(|x| *x /= norm);
        let (qa, va, aa): ([f64; 32], [f64; 31], [f64; 31]) =
            (q.clone().try_into().unwrap(), v.clone().try_into().unwrap(), a.clone().try_into().unwrap());
        let tau = reference.inverse_dynamics(&q, &v, &a).unwrap();
        close(&FlyingHumanoid::inverse_dynamics(&qa, &va, &aa), &tau, 1e-12, "inverse dynamics");
        close(&FlyingHumanoid::gravity_torques(&qa), &reference.gravity_torques(&q).unwrap(), 1e-12, "gravity");
        let h = reference.nonlinear_effects(&q, &v).unwrap();
        close(&FlyingHumanoid::nonlinear_effects(&qa, &va), &h, 1e-12, "h");
        let m = reference.mass_matrix(&q).unwrap();
        for (i, row) in FlyingHumanoid::mass_matrix(&qa).iter().enumerate() {
            close(row, &m.row(i).iter().copied().collect::<Vec<_>>(), 1e-12, "mass matrix");
        }
        let taua: [f64; 31] = tau.try_into().unwrap();
        close(&FlyingHumanoid::forward_dynamics(&qa, &va, &taua).unwrap(), &a, 1e-9, "forward dynamics");
    }
}

#[test]
fn forward_dynamics_names_the_joint_that_moves_no_mass() {
    let err = MasslessHand::forward_dynamics(&[0.1, 0.2], &[0.0; 2], &[1.0, 0.0]).unwrap_err();
    assert_eq!(err, KinematicsError::SingularMassMatrix { robot: "massless_hand", velocity: "wrist" });
    assert!(err.to_string().contains("`wrist`"), "{err}");
}
