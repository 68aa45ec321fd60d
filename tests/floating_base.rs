//! Floating and planar joints, and the derive's free-flying root (`floating_base`): generated poses,
//! Jacobians and twists against the runtime reference, the runtime's Jacobian against central
//! differences along each velocity, and what a quaternion that is not of unit length does.
//!
//! Conventions under test: a floating joint takes seven entries of `q` (the child's position in
//! the joint frame, then its quaternion `qx, qy, qz, qw`), and six velocities, the child's linear
//! and angular velocity in its own axes (Pinocchio's free-flyer); a planar joint takes three (the
//! translations along the plane's axes, then the rotation about the normal).
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use kinematics::model::{JointMotion, KinematicTree};
use kinematics::{Kinematics, ReferenceFk, RuntimeError};

#[derive(Kinematics)]
#[kinematics(
    urdf = "robots/quadruped.urdf",
    floating_base,
    tips("FR_foot", "FL_foot", "RR_foot", "RL_foot"),
    jacobians
)]
/// The quadruped with a free-flying trunk, its four feet.
pub struct Quadruped;

#[derive(Kinematics)]
#[kinematics(urdf = "robots/humanoid.urdf", floating_base = "odom", tips("l_wrist", "r_wrist"), jacobians)]
/// The humanoid with a free-flying torso (the new root named `odom`), its wrists.
pub struct Humanoid;

#[derive(Kinematics)]
#[kinematics(urdf = "tests/fixtures/planar_base.urdf", tip = "hand", jacobians, positions)]
/// An arm on a cart moving in a tilted plane.
pub struct PlanarBase;

/// Deterministic values in [-1, 1].
fn values(count: usize, seed: u64) -> Vec<f64> {
    let mut state = seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1;
    (0..count)
        .map(|_| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 52) as f64 - 1.0
        })
        .collect()
}

/// A configuration: joint values in [-1, 1], each floating joint's quaternion of some length
/// between 0.5 and 3 (never unit on purpose).
fn configuration(tree: &KinematicTree, seed: u64) -> Vec<f64> {
    let mut q = values(tree.dof(), seed);
    for joint in tree.floating_joints() {
        if let JointMotion::Dof(start) = tree.joint(joint).motion {
            let scale = 0.5 + 1.25 * (q[start] + 1.0);
            let norm = q[start + 3..start + 7].iter().map(|v| v * v).sum::<f64>().sqrt().max(1e-3);
            for v in &mut q[start + 3..start + 7] {
                *v *= scale / norm;
            }
        }
    }
    q
}

fn close(what: &str, got: f64, expected: f64, tolerance: f64) {
    assert!(got.is_finite() && (got - expected).abs() <= tolerance, "{what}: {got} vs {expected}");
}

/// Every tip's generated pose and Jacobian against the runtime reference, and the twist against
/// the Jacobian times the rates.
fn agree<const N: usize, const V: usize, const K: usize>(
    reference: &ReferenceFk,
    tips: &[&str],
    poses: fn(&[f64; N]) -> [kinematics::Pose<f64>; K],
    jacobians: fn(&[f64; N]) -> [[[f64; V]; 6]; K],
    twists: fn(&[f64; N], &[f64; V]) -> [[f64; 6]; K],
) {
    let tree = reference.tree();
    let base = tree.link(tree.root()).name.clone();
    let reach = tree.reach().max(1.0);
    for seed in 1..=20 {
        let q: [f64; N] = configuration(tree, seed).try_into().unwrap();
        let qd: [f64; V] = values(V, seed + 100).try_into().unwrap();
        let (pose, jacobian, twist) = (poses(&q), jacobians(&q), twists(&q, &qd));
        for (k, tip) in tips.iter().enumerate() {
            let expected = reference.relative_pose(&q, &base, tip).unwrap();
            let deviation = pose[k].deviation(&expected, reach);
            assert!(deviation <= 1e-12, "{tip}: pose deviates by {deviation:e}");
            let j = reference.jacobian(&q, &base, tip).unwrap();
            assert_eq!(j.ncols(), V);
            for row in 0..6 {
                let scale = if row < 3 { reach } else { 1.0 };
                for col in 0..V {
                    close(&format!("{tip} J[{row}][{col}]"), jacobian[k][row][col], j[(row, col)], 1e-12 * scale);
                }
                let jqd: f64 = (0..V).map(|c| j[(row, c)] * qd[c]).sum();
                close(&format!("{tip} twist[{row}]"), twist[k][row], jqd, 1e-11 * scale);
            }
        }
    }
}

#[test]
fn quadruped_with_a_free_flying_trunk() {
    assert_eq!((Quadruped::DOF, Quadruped::VELOCITY_DOF), (19, 18));
    assert_eq!(
        Quadruped::JOINT_NAMES[..7],
        [
            "root_joint.x",
            "root_joint.y",
            "root_joint.z",
            "root_joint.qx",
            "root_joint.qy",
            "root_joint.qz",
            "root_joint.qw"
        ]
    );
    assert_eq!(Quadruped::VELOCITY_NAMES[3], "root_joint.wx");
    assert_eq!(Quadruped::BASE, "world");
    let reference = Quadruped::reference().unwrap();
    agree(&reference, &Quadruped::TIPS, Quadruped::tip_poses, Quadruped::tip_jacobians, Quadruped::tip_twists);
}

#[test]
fn humanoid_with_a_free_flying_torso() {
    assert_eq!(Humanoid::BASE, "odom");
    assert_eq!(Humanoid::VELOCITY_DOF + 1, Humanoid::DOF);
    let reference = Humanoid::reference().unwrap();
    agree(&reference, &Humanoid::TIPS, Humanoid::tip_poses, Humanoid::tip_jacobians, Humanoid::tip_twists);
}

#[test]
fn planar_joint() {
    assert_eq!(PlanarBase::JOINT_NAMES, ["slide.x", "slide.y", "slide.theta", "shoulder"]);
    let reference = PlanarBase::reference().unwrap();
    agree(
        &reference,
        &PlanarBase::TIPS,
        |q| [PlanarBase::tip_pose(q)],
        |q| [PlanarBase::tip_jacobian(q)],
        |q, qd| [PlanarBase::tip_twist(q, qd)],
    );
    // The cart's translations move the hand along the plane, whatever the arm does: the linear
    // rows of the first two columns are the plane's axes in the ground frame, orthonormal and
    // normal to the plane's normal.
    let q = [0.3, -0.2, 0.7, 1.1];
    let j = PlanarBase::tip_position_jacobian(&q);
    let (e1, e2) = ([j[0][0], j[1][0], j[2][0]], [j[0][1], j[1][1], j[2][1]]);
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    close("|e1|", dot(e1, e1), 1.0, 1e-15);
    close("|e2|", dot(e2, e2), 1.0, 1e-15);
    close("e1.e2", dot(e1, e2), 0.0, 1e-15);
    // The third column turns the hand about the normal (rows 3..6: the normal in the ground frame).
    let normal = [
        j[1][0] * j[2][1] - j[2][0] * j[1][1],
        j[2][0] * j[0][1] - j[0][0] * j[2][1],
        j[0][0] * j[1][1] - j[1][0] * j[0][1],
    ];
    let full = PlanarBase::tip_jacobian(&q);
    for (r, n) in normal.iter().enumerate() {
        close("normal", full[r + 3][2], *n, 1e-15);
    }
}

/// A quaternion is normalised, never taken as given: any length gives the same pose; a zero
/// quaternion has no rotation, so the generated code gives NaN and the reference an error.
#[test]
fn quaternions_of_any_length_and_none() {
    let tree = Quadruped::reference().unwrap();
    let q: [f64; 19] = configuration(tree.tree(), 7).try_into().unwrap();
    let mut scaled = q;
    for v in &mut scaled[3..7] {
        *v *= 1e3;
    }
    let (a, b) = (Quadruped::tip_poses(&q), Quadruped::tip_poses(&scaled));
    for k in 0..4 {
        assert!(a[k].deviation(&b[k].to_isometry(), 1.0) < 1e-14, "{:?} vs {:?}", a[k], b[k]);
    }
    let mut zero = q;
    zero[3..7].copy_from_slice(&[0.0; 4]);
    assert!(Quadruped::tip_poses(&zero)[0].rotation[0][0].is_nan());
    let error = tree.link_poses(&zero).unwrap_err();
    assert!(matches!(error, RuntimeError::DegenerateQuaternion { index: 3, .. }), "{error}");
    assert_eq!(
        error.to_string(),
        "robot `quadruped`: the quaternion of floating joint `root_joint` (q[3..7]) has no length to normalise"
    );
}

/// The runtime reference's Jacobian against central differences of its own poses along each
/// velocity: a floating joint's linear velocities move the child along its own axes, its angular
/// ones turn it about them (the quaternion times `exp(h e / 2)` on the right). Differences of step
/// `1e-6` are good to about `1e-8`: this checks the convention, the agreement tests the digits.
#[test]
fn runtime_jacobian_of_floating_and_planar_joints_against_differences() {
    for reference in [Quadruped::reference().unwrap(), PlanarBase::reference().unwrap()] {
        let tree = reference.tree();
        let root = tree.link(tree.root()).name.clone();
        for leaf in tree.leaves() {
            let tip = tree.link(leaf).name.clone();
            for seed in 1..=3 {
                let q = configuration(tree, seed);
                let j = reference.jacobian(&q, &root, &tip).unwrap();
                let pose = reference.relative_pose(&q, &root, &tip).unwrap();
                for v in 0..tree.velocity_dof() {
                    let h = 1e-6;
                    let plus = reference.relative_pose(&moved(tree, &q, v, h), &root, &tip).unwrap();
                    let minus = reference.relative_pose(&moved(tree, &q, v, -h), &root, &tip).unwrap();
                    let linear = (plus.translation.vector - minus.translation.vector) / (2.0 * h);
                    let turn = (plus.rotation * minus.rotation.inverse()).scaled_axis() / (2.0 * h);
                    for r in 0..3 {
                        close(&format!("{tip} J[{r}][{v}]"), j[(r, v)], linear[r], 1e-7);
                        close(&format!("{tip} J[{}][{v}]", r + 3), j[(r + 3, v)], turn[r], 1e-7);
                    }
                }
                assert!(pose.translation.vector.iter().all(|x| x.is_finite()));
            }
        }
    }
}

/// `q` moved by `h` along velocity `v` (see the test above).
fn moved(tree: &KinematicTree, q: &[f64], v: usize, h: f64) -> Vec<f64> {
    let mut q = q.to_vec();
    if let Some(entry) = tree.velocity_of_entry().iter().position(|&c| c == Some(v)) {
        q[entry] += h;
        return q;
    }
    let joint =
        tree.floating_joints().find(|&j| tree.velocity_start(j).is_some_and(|s| (s..s + 6).contains(&v))).unwrap();
    let (JointMotion::Dof(s), Some(first)) = (tree.joint(joint).motion, tree.velocity_start(joint)) else {
        unreachable!()
    };
    let rotation =
        nalgebra::UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(q[s + 6], q[s + 3], q[s + 4], q[s + 5]));
    let k = v - first;
    if k < 3 {
        let axis = rotation * nalgebra::Vector3::ith(k, 1.0);
        for a in 0..3 {
            q[s + a] += h * axis[a];
        }
    } else {
        let turned = rotation * nalgebra::UnitQuaternion::from_scaled_axis(nalgebra::Vector3::ith(k - 3, h));
        let c = turned.coords; // (x, y, z, w)
        q[s + 3..s + 7].copy_from_slice(&[c[0], c[1], c[2], c[3]]);
    }
    q
}
