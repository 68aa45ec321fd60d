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

/// The Panda with external forces on its hand (below a fixed joint, lumped onto link 7) and its
/// fourth link.
#[derive(Kinematics)]
#[kinematics(urdf = "robots/panda.urdf", dynamics(forces("panda_hand", "panda_link4")), scalars(f64, f32))]
struct PandaForces;

#[test]
fn forces_on_the_pandas_links_agree_with_the_reference() {
    assert_eq!(PandaForces::FORCE_LINKS, ["panda_hand", "panda_link4"]);
    let reference =
        ReferenceDynamics::new(PandaForces::reference().unwrap().tree().clone(), [0.0, 0.0, -9.81], false).unwrap();
    for (k, (q, v, a)) in states(PandaForces::DOF, PandaForces::VELOCITY_DOF, 100).into_iter().enumerate() {
        let (qa, va, aa): ([f64; 8], [f64; 8], [f64; 8]) =
            (q.clone().try_into().unwrap(), v.clone().try_into().unwrap(), a.clone().try_into().unwrap());
        // A push of some newtons and a twist of some newton metres on each link, varied per state.
        let forces: [[f64; 6]; 2] =
            std::array::from_fn(|l| std::array::from_fn(|c| ((k + 3 * l + c) % 7) as f64 - 3.0));
        let named = [("panda_hand", forces[0]), ("panda_link4", forces[1])];
        let tau = reference.inverse_dynamics_with_forces(&q, &v, &a, &named).unwrap();
        close(&PandaForces::inverse_dynamics_with_forces(&qa, &va, &aa, &forces), &tau, 1e-12, "inverse dynamics");
        let taua: [f64; 8] = tau.clone().try_into().unwrap();
        let back = PandaForces::forward_dynamics_with_forces(&qa, &va, &taua, &forces).unwrap();
        close(&back, &a, 1e-9, "forward dynamics of inverse dynamics");
        // Without forces, the plain function (to rounding: the sums are ordered otherwise).
        let none = [[0.0; 6]; 2];
        let plain = PandaForces::inverse_dynamics(&qa, &va, &aa);
        close(&PandaForces::inverse_dynamics_with_forces(&qa, &va, &aa, &none), &plain, 1e-13, "no forces");
        let tau32 = PandaForces::inverse_dynamics_with_forces_f32(
            &qa.map(|x| x as f32),
            &va.map(|x| x as f32),
            &aa.map(|x| x as f32),
            &forces.map(|f| f.map(|x| x as f32)),
        );
        close(&tau32.map(f64::from), &tau, 1e-4, "inverse dynamics f32");
        let lanes = PandaForces::inverse_dynamics_with_forces_generic(
            &qa.map(F64x4::splat),
            &va.map(F64x4::splat),
            &aa.map(F64x4::splat),
            &forces.map(|f| f.map(F64x4::splat)),
        );
        close(&lanes.map(|l| l.to_array()[2]), &tau, 1e-12, "inverse dynamics in lanes");
    }
}

/// The batches with forces are the per-configuration functions, bit for bit, and refuse a slice
/// of forces of another length.
#[test]
fn the_batches_with_forces_are_the_functions() {
    let states = arrays::<8, 8>(37);
    let forces: Vec<[[f64; 6]; 2]> = (0..states.len())
        .map(|k| std::array::from_fn(|l| std::array::from_fn(|c| ((k + l + c) % 5) as f64 - 2.0)))
        .collect();
    let qs: Vec<[f64; 8]> = states.iter().map(|s| s.0).collect();
    let qds: Vec<[f64; 8]> = states.iter().map(|s| s.1).collect();
    let qdds: Vec<[f64; 8]> = states.iter().map(|s| s.2).collect();
    let mut out = vec![[0.0; 8]; states.len()];
    PandaForces::inverse_dynamics_with_forces_batch(&qs, &qds, &qdds, &forces, &mut out).unwrap();
    let taus: Vec<[f64; 8]> = (0..states.len())
        .map(|k| PandaForces::inverse_dynamics_with_forces(&qs[k], &qds[k], &qdds[k], &forces[k]))
        .collect();
    for k in 0..states.len() {
        assert_eq!(bits(&out[k]), bits(&taus[k]), "inverse dynamics with forces, configuration {k}");
    }
    PandaForces::forward_dynamics_with_forces_batch(&qs, &qds, &taus, &forces, &mut out).unwrap();
    for k in 0..states.len() {
        let one = PandaForces::forward_dynamics_with_forces(&qs[k], &qds[k], &taus[k], &forces[k]).unwrap();
        assert_eq!(bits(&out[k]), bits(&one), "forward dynamics with forces, configuration {k}");
    }
    let before = out.clone();
    let short = PandaForces::inverse_dynamics_with_forces_batch(&qs, &qds, &qdds, &forces[1..], &mut out);
    assert!(matches!(short, Err(KinematicsError::WrongInputLength { input: "forces", .. })), "{short:?}");
    assert_eq!(out, before, "nothing written");
}

/// Bit patterns, so that a batch equal "bit for bit" is not merely `==` (which takes -0.0 for 0.0).
fn bits<const V: usize>(values: &[f64; V]) -> [u64; V] {
    values.map(f64::to_bits)
}

fn bits32<const V: usize>(values: &[f32; V]) -> [u32; V] {
    values.map(f32::to_bits)
}

/// `count` states of `N` joints and `V` velocities as arrays (`q`, `qd`, `qdd` or `tau`).
fn arrays<const N: usize, const V: usize>(count: usize) -> Vec<([f64; N], [f64; V], [f64; V])> {
    states(N, V, count)
        .into_iter()
        .map(|(q, v, a)| (q.try_into().unwrap(), v.try_into().unwrap(), a.try_into().unwrap()))
        .collect()
}

/// What `forward_dynamics_batch` must give against the function on one configuration: each
/// accepted configuration's accelerations bit for bit, a refused one's NaN, and the first refusal
/// as the batch's error with its index.
fn check_forward_batch<T: Copy + PartialEq + std::fmt::Debug, const V: usize>(
    one: impl Fn(usize) -> Result<[T; V], KinematicsError>,
    out: &[[T; V]],
    batch: Result<(), KinematicsError>,
    same: impl Fn(&[T; V], &[T; V]) -> bool,
    is_nan: impl Fn(T) -> bool,
) {
    let mut first = None;
    for (i, got) in out.iter().enumerate() {
        match one(i) {
            Ok(want) => assert!(same(got, &want), "configuration {i}: {got:?} against {want:?}"),
            Err(error) => {
                assert!(got.iter().all(|&a| is_nan(a)), "refused configuration {i} holds {got:?}");
                first.get_or_insert((i, error));
            }
        }
    }
    let expected = match first {
        None => Ok(()),
        Some((configuration, KinematicsError::SingularMassMatrix { robot, velocity })) => {
            Err(KinematicsError::SingularMassMatrixInBatch { robot, configuration, velocity })
        }
        Some((configuration, KinematicsError::NotFinite { robot, quantity })) => {
            Err(KinematicsError::NotFiniteInBatch { robot, configuration, quantity })
        }
        Some((_, other)) => panic!("forward dynamics refused with {other}"),
    };
    assert_eq!(batch, expected);
}

/// 203 configurations: no multiple of four or eight, so the last pack is padded.
const BATCH: usize = 203;

/// The batches of the functions that take rates are the functions on one configuration, bit for
/// bit, in `f64` and `f32`, the last (padded) pack included; one configuration holding a NaN is
/// refused by forward dynamics' batch by its index, the others still computed.
#[test]
fn the_panda_rate_batches_are_the_functions_bit_for_bit() {
    let states = arrays::<8, 8>(BATCH);
    let qs: Vec<[f64; 8]> = states.iter().map(|s| s.0).collect();
    let qds: Vec<[f64; 8]> = states.iter().map(|s| s.1).collect();
    let qdds: Vec<[f64; 8]> = states.iter().map(|s| s.2).collect();
    // Torques that give those accelerations: a well-posed forward dynamics.
    let taus: Vec<[f64; 8]> = states.iter().map(|(q, v, a)| Panda::inverse_dynamics(q, v, a)).collect();
    let mut out = vec![[0.0; 8]; BATCH];
    Panda::inverse_dynamics_batch(&qs, &qds, &qdds, &mut out).unwrap();
    for i in 0..BATCH {
        assert_eq!(bits(&out[i]), bits(&Panda::inverse_dynamics(&qs[i], &qds[i], &qdds[i])), "inverse dynamics {i}");
    }
    Panda::nonlinear_effects_batch(&qs, &qds, &mut out).unwrap();
    for i in 0..BATCH {
        assert_eq!(bits(&out[i]), bits(&Panda::nonlinear_effects(&qs[i], &qds[i])), "nonlinear effects {i}");
    }
    let result = Panda::forward_dynamics_batch(&qs, &qds, &taus, &mut out);
    assert_eq!(result, Ok(()));
    let one = |i: usize| Panda::forward_dynamics(&qs[i], &qds[i], &taus[i]);
    check_forward_batch(one, &out, result, |a, b| bits(a) == bits(b), f64::is_nan);
    // A NaN in configuration 37's `q`: refused by index, the rest still written.
    let mut broken = qs.clone();
    broken[37][2] = f64::NAN;
    let result = Panda::forward_dynamics_batch(&broken, &qds, &taus, &mut out);
    assert_eq!(
        result,
        Err(KinematicsError::NotFiniteInBatch { robot: "panda", configuration: 37, quantity: "mass matrix" })
    );
    assert!(result.unwrap_err().to_string().contains("configuration 37"), "{}", result.unwrap_err());
    let one = |i: usize| Panda::forward_dynamics(&broken[i], &qds[i], &taus[i]);
    check_forward_batch(one, &out, result, |a, b| bits(a) == bits(b), f64::is_nan);
    assert!(out.iter().enumerate().all(|(i, a)| i == 37 || a.iter().all(|x| x.is_finite())));

    // f32, on the same states.
    let narrow = |rows: &[[f64; 8]]| -> Vec<[f32; 8]> { rows.iter().map(|r| r.map(|x| x as f32)).collect() };
    let (qs32, qds32, qdds32, taus32) = (narrow(&qs), narrow(&qds), narrow(&qdds), narrow(&taus));
    let mut out32 = vec![[0.0f32; 8]; BATCH];
    Panda::inverse_dynamics_batch_f32(&qs32, &qds32, &qdds32, &mut out32).unwrap();
    for i in 0..BATCH {
        let one = Panda::inverse_dynamics_f32(&qs32[i], &qds32[i], &qdds32[i]);
        assert_eq!(bits32(&out32[i]), bits32(&one), "inverse dynamics f32 {i}");
    }
    Panda::nonlinear_effects_batch_f32(&qs32, &qds32, &mut out32).unwrap();
    for i in 0..BATCH {
        assert_eq!(bits32(&out32[i]), bits32(&Panda::nonlinear_effects_f32(&qs32[i], &qds32[i])), "h f32 {i}");
    }
    let result = Panda::forward_dynamics_batch_f32(&qs32, &qds32, &taus32, &mut out32);
    let one = |i: usize| Panda::forward_dynamics_f32(&qs32[i], &qds32[i], &taus32[i]);
    check_forward_batch(one, &out32, result, |a, b| bits32(a) == bits32(b), f32::is_nan);
}

#[test]
fn the_ur5_rate_batches_take_its_gravity() {
    let states = arrays::<6, 6>(BATCH - 2);
    let qs: Vec<[f64; 6]> = states.iter().map(|s| s.0).collect();
    let qds: Vec<[f64; 6]> = states.iter().map(|s| s.1).collect();
    let qdds: Vec<[f64; 6]> = states.iter().map(|s| s.2).collect();
    let mut out = vec![[0.0; 6]; qs.len()];
    Ur5::inverse_dynamics_batch(&qs, &qds, &qdds, &mut out).unwrap();
    for i in 0..qs.len() {
        assert_eq!(bits(&out[i]), bits(&Ur5::inverse_dynamics(&qs[i], &qds[i], &qdds[i])), "inverse dynamics {i}");
    }
    Ur5::nonlinear_effects_batch(&qs, &qds, &mut out).unwrap();
    for i in 0..qs.len() {
        assert_eq!(bits(&out[i]), bits(&Ur5::nonlinear_effects(&qs[i], &qds[i])), "nonlinear effects {i}");
    }
    let result = Ur5::forward_dynamics_batch(&qs, &qds, &qdds, &mut out);
    let one = |i: usize| Ur5::forward_dynamics(&qs[i], &qds[i], &qdds[i]);
    check_forward_batch(one, &out, result, |a, b| bits(a) == bits(b), f64::is_nan);
}

/// A slice of another length than `out` is refused by name before anything is computed: `out`
/// keeps what it held.
#[test]
fn rate_batches_refuse_inputs_of_another_length() {
    let states = arrays::<8, 8>(19);
    let qs: Vec<[f64; 8]> = states.iter().map(|s| s.0).collect();
    let qds: Vec<[f64; 8]> = states.iter().map(|s| s.1).collect();
    let untouched = [7.0; 8];
    let mut out = vec![untouched; 19];
    let wrong = |input, got| Err(KinematicsError::WrongInputLength { robot: "panda", input, expected: 19, got });
    assert_eq!(Panda::inverse_dynamics_batch(&qs, &qds, &qds[..18], &mut out), wrong("qdds", 18));
    assert_eq!(Panda::inverse_dynamics_batch(&qs, &qds[..3], &qds, &mut out), wrong("qds", 3));
    assert_eq!(Panda::inverse_dynamics_batch(&qs[..18], &qds, &qds, &mut out), wrong("qs", 18));
    assert_eq!(Panda::nonlinear_effects_batch(&qs, &qds[1..], &mut out), wrong("qds", 18));
    assert_eq!(Panda::forward_dynamics_batch(&qs, &qds, &qds[..0], &mut out), wrong("taus", 0));
    assert_eq!(Panda::forward_dynamics_batch(&qs, &qds, &qds, &mut out[..18]), {
        Err(KinematicsError::WrongInputLength { robot: "panda", input: "qs", expected: 18, got: 19 })
    });
    assert!(out.iter().all(|o| *o == untouched), "nothing is written");
    let message = Panda::forward_dynamics_batch(&qs, &qds, &qds[..5], &mut out).unwrap_err().to_string();
    assert!(message.contains("`taus` holds 5 values") && message.contains("panda"), "{message}");
    let qs32: Vec<[f32; 8]> = qs.iter().map(|q| q.map(|x| x as f32)).collect();
    let mut out32 = vec![[7.0f32; 8]; 19];
    let error = Panda::forward_dynamics_batch_f32(&qs32, &qs32[..2], &qs32, &mut out32).unwrap_err();
    assert_eq!(error, KinematicsError::WrongInputLength { robot: "panda", input: "qds", expected: 19, got: 2 });
    assert!(out32.iter().all(|o| *o == [7.0f32; 8]), "nothing is written");
}

/// The massless hand's mass matrix is singular everywhere: its batch names the first
/// configuration and the wrist, and writes NaN, never the infinities a zero pivot gives.
#[test]
fn forward_dynamics_batch_names_the_configuration_that_moves_no_mass() {
    let qs: Vec<[f64; 2]> = (0..11).map(|i| [0.1 * i as f64, -0.2]).collect();
    let (qds, taus) = (vec![[0.5; 2]; 11], vec![[1.0, 0.0]; 11]);
    let mut out = vec![[0.0; 2]; 11];
    let error = MasslessHand::forward_dynamics_batch(&qs, &qds, &taus, &mut out).unwrap_err();
    assert_eq!(
        error,
        KinematicsError::SingularMassMatrixInBatch { robot: "massless_hand", configuration: 0, velocity: "wrist" }
    );
    let message = error.to_string();
    assert!(message.contains("configuration 0") && message.contains("`wrist`"), "{message}");
    assert!(out.iter().all(|a| a.iter().all(|x| x.is_nan())), "{out:?}");
    let one = |i: usize| MasslessHand::forward_dynamics(&qs[i], &qds[i], &taus[i]);
    check_forward_batch(one, &out, Err(error), |a, b| bits(a) == bits(b), f64::is_nan);
}

/// A floating base's batches take `q` of 13 entries and the rates of 12.
#[test]
fn a_floating_base_has_rate_batches_of_its_two_lengths() {
    let states: Vec<([f64; 13], [f64; 12], [f64; 12])> = arrays::<13, 12>(37)
        .into_iter()
        .map(|(mut q, v, a)| {
            let norm = q[3..7].iter().map(|x| x * x).sum::<f64>().sqrt();
            q[3..7].iter_mut().for_each(|x| *x /= norm);
            (q, v, a)
        })
        .collect();
    let qs: Vec<[f64; 13]> = states.iter().map(|s| s.0).collect();
    let qds: Vec<[f64; 12]> = states.iter().map(|s| s.1).collect();
    let qdds: Vec<[f64; 12]> = states.iter().map(|s| s.2).collect();
    let (mut taus, mut accelerations) = (vec![[0.0; 12]; 37], vec![[0.0; 12]; 37]);
    FlyingUr5::inverse_dynamics_batch(&qs, &qds, &qdds, &mut taus).unwrap();
    let result = FlyingUr5::forward_dynamics_batch(&qs, &qds, &taus, &mut accelerations);
    for i in 0..37 {
        assert_eq!(bits(&taus[i]), bits(&FlyingUr5::inverse_dynamics(&qs[i], &qds[i], &qdds[i])), "tau {i}");
    }
    let one = |i: usize| FlyingUr5::forward_dynamics(&qs[i], &qds[i], &taus[i]);
    check_forward_batch(one, &accelerations, result, |a, b| bits(a) == bits(b), f64::is_nan);
    assert_eq!(result, Ok(()));
}
