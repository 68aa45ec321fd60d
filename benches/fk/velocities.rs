//! Velocities of the tip (the URDF robots, derived with `jacobians`): the generated geometric
//! Jacobian alone and with the pose, against the runtime reference's Jacobian and the `k` crate's
//! (its serial chain to the tip), and the generated twist against the generated Jacobian times
//! the rates. A controller needs the Jacobian every cycle, so the targets bound its cost
//! against the pose alone and against the runtime. Check mode holds every Jacobian timed to the
//! reference's within the agreement tolerance (linear rows times the reach), and the twist to the
//! product it replaces.

use kinematics::{AGREEMENT_TOLERANCE, Pose, ReferenceFk};

use crate::check::{joint_values, verify};
use crate::inputs::{INPUTS, arrays, inputs};
use crate::mode::Mode;

/// A pose and its geometric Jacobian.
type PoseAndJacobian<const N: usize> = (Pose<f64>, [[f64; N]; 6]);

/// The generated functions of one robot's tip velocity, for [`velocities`].
pub struct Velocity<const N: usize> {
    /// `tip_pose`.
    pub pose: fn(&[f64; N]) -> Pose<f64>,
    /// `tip_jacobian`.
    pub jacobian: fn(&[f64; N]) -> [[f64; N]; 6],
    /// `tip_pose_and_jacobian`.
    pub pose_and_jacobian: fn(&[f64; N]) -> PoseAndJacobian<N>,
    /// `tip_twist`.
    pub twist: fn(&[f64; N], &[f64; N]) -> [f64; 6],
}

/// The tip's velocity (the URDF robots; the targets name the UR5, the iiwa 14 and the Panda): the
/// generated Jacobian alone and with the pose, against the runtime reference's Jacobian and the
/// `k` crate's (its serial chain to the tip), and the generated twist against the generated
/// Jacobian times the rates. Check mode holds every Jacobian timed to the
/// reference's within the agreement tolerance (linear rows times the reach).
pub fn velocities<const N: usize>(
    mode: &mut Mode,
    file: &str,
    tip: &str,
    limits: &[kinematics::JointLimits],
    v: &Velocity<N>,
) {
    let path = format!("{}/robots/{file}", env!("CARGO_MANIFEST_DIR"));
    let reference = ReferenceFk::new(kinematics::load(&path).expect("robot loads"));
    let tree = reference.tree();
    let root = tree.link(tree.root()).name.clone();
    let qs = inputs(limits, INPUTS);
    let q64: Vec<[f64; N]> = arrays(&qs);
    let rates: Vec<[f64; N]> = arrays(&inputs(limits, INPUTS).into_iter().rev().collect::<Vec<_>>());
    let chain = k::Chain::<f64>::from_urdf_file(&path).expect("k reads the robot");
    let serial = k::SerialChain::from_end(chain.find_link(tip).expect("k has the tip"));
    let names: Vec<String> = serial.iter_joints().map(|j| j.name.clone()).collect();
    let kq = joint_values(tree, &names, &qs);
    // k's columns are its serial chain's joints: ours, by name.
    let k_columns: Vec<usize> = names
        .iter()
        .map(|name| {
            tree.joint_id(name).and_then(|j| tree.velocity_start(j)).expect("k's joint is an independent joint of ours")
        })
        .collect();
    let times = |j: &[[f64; N]; 6], qd: &[f64; N]| -> [f64; 6] {
        std::array::from_fn(|r| (0..N).map(|c| j[r][c] * qd[c]).sum())
    };
    if let Mode::Check = mode {
        let reach = tree.reach();
        let close = |what: &str, i: usize, got: f64, expected: f64, row: usize| {
            let scale = if row < 3 { reach } else { 1.0 };
            assert!(
                got.is_finite() && (got - expected).abs() <= AGREEMENT_TOLERANCE * scale,
                "{file} {what} row {row} at configuration {i}: {got} vs {expected}"
            );
        };
        for (i, q) in qs.iter().enumerate() {
            let expected = reference.jacobian(q, &root, tip).expect("the tip exists");
            let (pose, both) = (v.pose_and_jacobian)(&q64[i]);
            let jacobian = (v.jacobian)(&q64[i]);
            verify(
                "generated_pose_and_jacobian_f64",
                tip,
                i,
                &pose,
                &reference.link_pose(q, tip).expect("tip"),
                reach,
                AGREEMENT_TOLERANCE,
            );
            serial.set_joint_positions_unchecked(&kq[i]);
            let k_jacobian = k::jacobian(&serial);
            let twist = (v.twist)(&q64[i], &rates[i]);
            let product = times(&jacobian, &rates[i]);
            for row in 0..6 {
                for c in 0..N {
                    close("generated_jacobian_f64", i, jacobian[row][c], expected[(row, c)], row);
                    close("generated_pose_and_jacobian_f64", i, both[row][c], expected[(row, c)], row);
                }
                for (kc, &c) in k_columns.iter().enumerate() {
                    close("k_jacobian_f64", i, k_jacobian[(row, kc)], expected[(row, c)], row);
                }
                // A twist is a sum of N products: N roundings more than the Jacobian's entries.
                close("generated_twist_f64", i, twist[row] / N as f64, product[row] / N as f64, row);
            }
        }
        return;
    }
    let mut jacobian = |i: usize| (v.jacobian)(&q64[i]);
    let mut both = |i: usize| (v.pose_and_jacobian)(&q64[i]);
    let mut pose = |i: usize| (v.pose)(&q64[i]);
    let mut runtime = |i: usize| reference.jacobian(&qs[i], &root, tip);
    let mut k_jacobian = |i: usize| {
        serial.set_joint_positions_unchecked(&kq[i]);
        k::jacobian(&serial)
    };
    let mut twist = |i: usize| (v.twist)(&q64[i], &rates[i]);
    let mut formed = |i: usize| times(&(v.jacobian)(&q64[i]), &rates[i]);
    mode.run("generated_jacobian_f64", &mut jacobian);
    mode.run("generated_pose_and_jacobian_f64", &mut both);
    mode.run("runtime_jacobian_f64", &mut runtime);
    mode.run("k_jacobian_f64", &mut k_jacobian);
    mode.run("generated_twist_f64", &mut twist);
    mode.pair("generated_pose_and_jacobian_f64/generated_pose_f64", &mut both, &mut pose);
    mode.pair("generated_jacobian_f64/generated_pose_f64", &mut jacobian, &mut pose);
    mode.pair("runtime_jacobian_f64/generated_pose_and_jacobian_f64", &mut runtime, &mut both);
    mode.pair("runtime_jacobian_f64/generated_jacobian_f64", &mut runtime, &mut jacobian);
    mode.pair("k_jacobian_f64/generated_pose_and_jacobian_f64", &mut k_jacobian, &mut both);
    mode.pair("jacobian_times_qd_f64/generated_twist_f64", &mut formed, &mut twist);
}
