//! `#[derive(Kinematics)]` from a user's point of view: file and inline sources, what the struct
//! gets, and the trait for generic code.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use kinematics::{Kinematics, Pose};

#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5.urdf", base = "base", tip = "tool0", positions)]
/// The UR5, from its URDF.
pub struct Ur5;

/// A planar arm written in the attribute, with fields of the user's own.
#[derive(Kinematics)]
#[kinematics(
    dh(
        convention = "standard",
        joint(name = "shoulder", a = 1.0),
        joint(name = "elbow", a = 1.0, lower = -2.5, upper = 2.5),
        joint(name = "wrist", a = 0.5, alpha = "-pi/2"),
    ),
    tips("link2", "link3"),
    scalars(f64, f32)
)]
#[allow(dead_code)]
struct Planar {
    label: String,
}

#[test]
fn ur5_from_urdf() {
    assert_eq!(Ur5::DOF, 6);
    assert_eq!(Ur5::JOINT_NAMES[1], "shoulder_lift_joint");
    assert_eq!(Ur5::BASE, "base");
    let q = [0.3, -1.2, 1.0, 0.4, -0.7, 2.0];
    let pose = Ur5::tip_pose(&q);
    let reference = Ur5::reference().unwrap().relative_pose(&q, "base", "tool0").unwrap();
    assert!((pose.to_isometry().translation.vector - reference.translation.vector).norm() < 1e-12);
    let position = Ur5::tip_position(&q);
    assert_eq!(position, pose.translation);
    let links = Ur5::link_poses(&q);
    assert_eq!(links.len(), Ur5::LINK_NAMES.len());
}

#[test]
fn planar_from_inline_table() {
    let q = [0.1, 0.2, 0.3];
    let [elbow, hand] = Planar::tip_poses(&q);
    let [elbow32, _] = Planar::tip_poses_f32(&[0.1, 0.2, 0.3]);
    assert!((elbow.translation[0] - (0.1f64.cos() + 0.3f64.cos())).abs() < 1e-12);
    assert!((f64::from(elbow32.translation[0]) - elbow.translation[0]).abs() < 1e-6);
    assert_eq!(Planar::JOINT_LIMITS[1].lower, -2.5);
    assert!(Planar::JOINT_LIMITS[0].upper.is_infinite());
    let _ = hand;
}

fn tips_of<R: Kinematics>(q: &[f64]) -> Vec<Pose<f64>> {
    let mut out = vec![Pose { rotation: [[0.0; 3]; 3], translation: [0.0; 3] }; R::TIPS.len()];
    R::tip_poses_into(q, &mut out).unwrap();
    out
}

#[test]
fn generic_code_takes_any_compiled_robot() {
    assert_eq!(tips_of::<Ur5>(&[0.0; 6]).len(), 1);
    assert_eq!(tips_of::<Planar>(&[0.0; 3]).len(), 2);
    let mut out = vec![Pose { rotation: [[0.0; 3]; 3], translation: [0.0; 3] }; 1];
    let err = <Ur5 as Kinematics>::tip_poses_into(&[0.0; 5], &mut out).unwrap_err();
    assert!(err.to_string().contains("6 degrees of freedom"), "{err}");
}

/// The same planar arm as a textbook table: one positional row per joint.
#[derive(Kinematics)]
#[kinematics(
    dh(
        convention = "standard",
        //   joint       a     alpha    d    theta  lower  upper
        row("shoulder", 1.0,   0.0,    0.0,  0.0),
        row("elbow",    1.0,   0.0,    0.0,  0.0,   -2.5,  2.5),
        row("wrist",    0.5, "-pi/2",  0.0,  0.0),
        row("lift", "prismatic", 0.0, 0.0, 0.1, 0.0, 0.0, 0.4),
    ),
    tip = "link4"
)]
struct PlanarTable;

#[test]
fn positional_rows_read_like_the_textbook_table() {
    assert_eq!(PlanarTable::JOINT_NAMES, ["shoulder", "elbow", "wrist", "lift"]);
    assert_eq!(PlanarTable::JOINT_LIMITS[1].upper, 2.5);
    let q = [0.1, 0.2, 0.3, 0.2];
    let reference = PlanarTable::reference().unwrap().link_pose(&q, "link4").unwrap();
    let pose = PlanarTable::tip_pose(&q);
    assert!((pose.to_isometry().translation.vector - reference.translation.vector).norm() < 1e-12);
    // The prismatic joint slides along the wrist's z, which the -pi/2 twist turned into -y.
    let [x, _, _] = PlanarTable::tip_pose(&[0.0, 0.0, 0.0, 0.0]).translation;
    assert!((x - 2.5).abs() < 1e-12);
}

/// Issue 21: the generated bodies' locals (`q1`, `s1`, `c23`, `t0`, `qd1`, ...) beside constants
/// and unit structs of those names in the deriving module. A `let` named like a constant or unit
/// struct in scope is a pattern, not a binding, so these broke the derive ("expected type
/// parameter `T`, found `q1`") until the bodies moved into a module of their own.
mod locals_named_like_user_items {
    #![allow(non_upper_case_globals, non_camel_case_types, dead_code)]

    use kinematics::Kinematics;

    const q1: f64 = 0.0;
    const c23: f64 = 0.0;
    const t0: f64 = 0.0;
    const qd1: f64 = 0.0;
    struct s1;
    struct c1;

    #[derive(Kinematics)]
    #[kinematics(urdf = "robots/ur5.urdf", tip = "tool0", positions, jacobians, ik, scalars(f64, f32))]
    pub struct Ur5Here;

    #[test]
    fn every_function_computes_what_it_does_elsewhere() {
        let q = [0.3, -1.2, 1.0, 0.4, -0.7, 2.0];
        let pose = Ur5Here::tip_pose(&q);
        let reference = Ur5Here::reference().unwrap();
        let expected = reference.relative_pose(&q, Ur5Here::BASE, "tool0").unwrap();
        assert!((pose.to_isometry().translation.vector - expected.translation.vector).norm() < 1e-12);
        assert!(pose.to_isometry().rotation.angle_to(&expected.rotation) < 1e-12);
        assert_eq!(Ur5Here::tip_position(&q), pose.translation);
        for (link, link_pose) in Ur5Here::LINK_NAMES.iter().zip(Ur5Here::link_poses(&q)) {
            let expected = reference.relative_pose(&q, Ur5Here::BASE, link).unwrap();
            assert!((link_pose.to_isometry().translation.vector - expected.translation.vector).norm() < 1e-12);
        }
        let (with_jacobian, jacobian) = Ur5Here::tip_pose_and_jacobian(&q);
        // Computed together with the Jacobian, so rounded differently: equal to within rounding.
        assert!(with_jacobian.to_isometry().rotation.angle_to(&pose.to_isometry().rotation) < 1e-12);
        assert_eq!(with_jacobian.translation, pose.translation);
        assert_eq!(jacobian, Ur5Here::tip_jacobian(&q));
        let qd = [0.1, 0.2, -0.3, 0.4, 0.5, -0.6];
        let twist = Ur5Here::tip_twist(&q, &qd);
        for (row, value) in jacobian.iter().zip(twist) {
            let product: f64 = row.iter().zip(qd).map(|(j, v)| j * v).sum();
            assert!((product - value).abs() < 1e-12, "twist {value} against J * qd {product}");
        }
        let solutions = Ur5Here::tip_ik(&pose).unwrap();
        let found = Ur5Here::tip_ik_nearest(&pose, &q).unwrap().expect("a solution near q");
        assert!(!solutions.is_empty());
        for (a, b) in found.q.iter().zip(q) {
            assert!((a - b).abs() < 1e-9, "nearest solution {:?} against q {q:?}", found.q);
        }
        let pose_f32 = Ur5Here::tip_pose_f32(&q.map(|v| v as f32));
        assert!((f64::from(pose_f32.translation[0]) - pose.translation[0]).abs() < 1e-5);
    }
}
