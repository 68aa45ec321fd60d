//! The code `build.rs` generated, against the runtime reference (`kinematics::load` +
//! `ReferenceFk`) on a few thousand random configurations, and against `#[derive(Kinematics)]`
//! structs of the same robots with the same options, which must give the very same numbers.
//!
//! 3,000 configurations, within `AGREEMENT_TOLERANCE` of the reference.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use kinematics::{AGREEMENT_TOLERANCE, Configurations, Kinematics, Pose, ReferenceFk};
use kinematics_build_example::{Panda, Ur5, Ur5Dynamics};
use nalgebra::Isometry3;

const CASES: usize = 3_000;

#[derive(Kinematics)]
#[kinematics(urdf = "../../robots/ur5.urdf", base = "base", tip = "tool0", positions)]
struct DerivedUr5;

#[derive(Kinematics)]
#[kinematics(
    urdf = "../../robots/panda.urdf",
    base = "panda_link0",
    tips("panda_hand_tcp", "panda_leftfinger", "panda_rightfinger"),
    positions,
    scalars(f64, f32)
)]
struct DerivedPanda;

#[derive(Kinematics)]
#[kinematics(urdf = "../../robots/ur5.urdf", dynamics(gravity = [0.5, 0.0, -9.81]), scalars(f64, f32))]
struct DerivedUr5Dynamics;

fn load(file: &str) -> ReferenceFk {
    ReferenceFk::new(kinematics::load(format!("{}/../../robots/{file}", env!("CARGO_MANIFEST_DIR"))).unwrap())
}

/// The project's one agreement measure (`Pose::deviation`: translation relative to `reach`,
/// rotation entries absolute, NaN infinitely far) against its one tolerance.
fn assert_close(what: &str, generated: &Pose<f64>, reference: &Isometry3<f64>, reach: f64, q: &[f64]) -> f64 {
    let d = generated.deviation(reference, reach);
    assert!(d <= AGREEMENT_TOLERANCE, "{what}: off by {d:e} x reach at q = {q:?}");
    d
}

#[test]
fn ur5_agrees_with_the_runtime_reference() {
    let fk = load("ur5.urdf");
    let reach = fk.tree().reach();
    let base = fk.link_id(Ur5::BASE).unwrap().0;
    let mut configurations = Configurations::within(&Ur5::JOINT_LIMITS);
    let mut worst: f64 = 0.0;
    for _ in 0..CASES {
        let q = configurations.next_array::<6>().unwrap();
        let poses = fk.link_poses(&q).unwrap();
        let relative = |link: &str| poses[base].inverse() * poses[fk.link_id(link).unwrap().0];
        let tip = Ur5::tip_pose(&q);
        worst = worst.max(assert_close("tool0", &tip, &relative("tool0"), reach, &q));
        let position = Pose { rotation: tip.rotation, translation: Ur5::tip_position(&q) };
        assert_close("tool0 position", &position, &relative("tool0"), reach, &q);
        for ((pose, position), link) in Ur5::link_poses(&q).iter().zip(Ur5::link_positions(&q)).zip(Ur5::LINK_NAMES) {
            worst = worst.max(assert_close(link, pose, &relative(link), reach, &q));
            assert_close(link, &Pose { rotation: pose.rotation, translation: position }, &relative(link), reach, &q);
        }
    }
    println!("ur5.urdf: {CASES} configurations, largest error {worst:.2e} x reach");
}

#[test]
fn panda_agrees_with_the_runtime_reference() {
    let fk = load("panda.urdf");
    let reach = fk.tree().reach();
    let base = fk.link_id(Panda::BASE).unwrap().0;
    let mut configurations = Configurations::within(&Panda::JOINT_LIMITS);
    let mut worst: f64 = 0.0;
    for _ in 0..CASES {
        let q = configurations.next_array::<8>().unwrap();
        let poses = fk.link_poses(&q).unwrap();
        let relative = |link: &str| poses[base].inverse() * poses[fk.link_id(link).unwrap().0];
        for (pose, tip) in Panda::tip_poses(&q).iter().zip(Panda::TIPS) {
            worst = worst.max(assert_close(tip, pose, &relative(tip), reach, &q));
        }
        for (pose, link) in Panda::link_poses(&q).iter().zip(Panda::LINK_NAMES) {
            worst = worst.max(assert_close(link, pose, &relative(link), reach, &q));
        }
    }
    println!("panda.urdf: {CASES} configurations, largest error {worst:.2e} x reach");
}

#[test]
fn the_build_api_and_the_derive_give_the_same_numbers() {
    assert_eq!(Ur5::LINK_NAMES, DerivedUr5::LINK_NAMES);
    assert_eq!(Ur5::JOINT_NAMES, DerivedUr5::JOINT_NAMES);
    assert_eq!(Ur5::JOINT_LIMITS, DerivedUr5::JOINT_LIMITS);
    assert_eq!((Panda::TIPS, Panda::BASE, Panda::DOF), (DerivedPanda::TIPS, DerivedPanda::BASE, DerivedPanda::DOF));
    let mut ur5 = Configurations::within(&Ur5::JOINT_LIMITS);
    let mut panda = Configurations::within(&Panda::JOINT_LIMITS);
    for _ in 0..CASES {
        let q = ur5.next_array::<6>().unwrap();
        assert_eq!(Ur5::tip_pose(&q), DerivedUr5::tip_pose(&q), "q = {q:?}");
        assert_eq!(Ur5::tip_position(&q), DerivedUr5::tip_position(&q), "q = {q:?}");
        assert_eq!(Ur5::link_poses(&q), DerivedUr5::link_poses(&q), "q = {q:?}");
        let q = panda.next_array::<8>().unwrap();
        assert_eq!(Panda::tip_poses(&q), DerivedPanda::tip_poses(&q), "q = {q:?}");
        assert_eq!(Panda::link_positions(&q), DerivedPanda::link_positions(&q), "q = {q:?}");
        let q32 = q.map(|x| x as f32);
        assert_eq!(Panda::tip_poses_f32(&q32), DerivedPanda::tip_poses_f32(&q32), "q = {q:?}");
    }
}

#[test]
fn the_trait_and_the_reference_match_the_derive() {
    let q = [0.3, -1.2, 1.0, 0.4, -0.7, 2.0];
    let mut built = [Ur5::tip_pose(&q); 1];
    let mut derived = built;
    <Ur5 as Kinematics>::tip_poses_into(&q, &mut built).unwrap();
    <DerivedUr5 as Kinematics>::tip_poses_into(&q, &mut derived).unwrap();
    assert_eq!(built, derived);
    assert!(<Ur5 as Kinematics>::tip_poses_into(&q[..5], &mut built).is_err());
    assert_eq!(Ur5::reference().unwrap().tree(), DerivedUr5::reference().unwrap().tree());
    assert_eq!(Panda::reference().unwrap().tree(), load("panda.urdf").tree());
}

/// `.dynamics().gravity(..)` writes what `dynamics(gravity = ..)` derives: the same numbers from
/// every function of the dynamics, in both scalars, and gravity torques that hold the reference's.
#[test]
fn the_build_api_and_the_derive_give_the_same_dynamics() {
    let reference =
        kinematics::runtime::ReferenceDynamics::new(load("ur5.urdf").tree().clone(), [0.5, 0.0, -9.81], false).unwrap();
    let mut configurations = Configurations::within(&Ur5Dynamics::JOINT_LIMITS);
    for k in 0..100 {
        let q = configurations.next_array::<6>().unwrap();
        let (qd, qdd) = (q.map(|x| 0.5 * x - 0.1), q.map(|x| 0.3 - x));
        assert_eq!(Ur5Dynamics::gravity_torques(&q), DerivedUr5Dynamics::gravity_torques(&q), "q = {q:?}");
        assert_eq!(Ur5Dynamics::mass_matrix(&q), DerivedUr5Dynamics::mass_matrix(&q), "q = {q:?}");
        let tau = Ur5Dynamics::inverse_dynamics(&q, &qd, &qdd);
        assert_eq!(tau, DerivedUr5Dynamics::inverse_dynamics(&q, &qd, &qdd), "q = {q:?}");
        assert_eq!(Ur5Dynamics::nonlinear_effects(&q, &qd), DerivedUr5Dynamics::nonlinear_effects(&q, &qd));
        assert_eq!(Ur5Dynamics::forward_dynamics(&q, &qd, &tau), DerivedUr5Dynamics::forward_dynamics(&q, &qd, &tau));
        let q32 = q.map(|x| x as f32);
        assert_eq!(Ur5Dynamics::mass_matrix_f32(&q32), DerivedUr5Dynamics::mass_matrix_f32(&q32), "q = {q:?}");
        if k < 10 {
            let want = reference.gravity_torques(&q).unwrap();
            for (got, want) in Ur5Dynamics::gravity_torques(&q).iter().zip(&want) {
                assert!((got - want).abs() <= 1e-12 * want.abs().max(1.0), "{got} against {want} at q = {q:?}");
            }
        }
    }
}
