//! The peers, on the same robot and configurations, against the generated code's all-links body
//! and the trigonometry floor of all links: the runtime reference (nalgebra, walking the tree),
//! the `k` crate (whole-tree `update_transforms`, and a serial chain's `end_transform` to the
//! tip), and galaw's ahead-of-time generated code (all link poses; `benches/galaw/`). These are
//! the alternatives a user has, and the targets are stated as speed-ups over them. `k`
//! and galaw read URDF only, and order or name joints their own way: each of their joints gets the
//! value our model gives it (mimic joints included), so they compute the same poses, which check
//! mode asserts link by link.
//!
//! galaw's code in `benches/galaw/` is its own generator's output for our URDFs, rebuilt by
//! `benches/galaw/regenerate.sh`.

use std::hint::black_box;

use kinematics::{AGREEMENT_TOLERANCE, AGREEMENT_TOLERANCE_F32};

use crate::check::{joint_values, pose_of, pose_of_k, reference_poses, verify, widen_iso};
use crate::mode::Mode;
use crate::robots::Setup;

/// galaw 0.3.0's generated forward kinematics for our URDF robots, written by
/// `benches/galaw/regenerate.sh` (its output is kept as generated: no lints apply).
#[allow(clippy::all, clippy::pedantic, unused_imports, non_snake_case)]
pub mod galaw {
    pub mod ur5 {
        include!("../galaw/ur5.rs");
    }
    pub mod ur10e {
        include!("../galaw/ur10e.rs");
    }
    pub mod iiwa14 {
        include!("../galaw/iiwa14.rs");
    }
    pub mod panda {
        include!("../galaw/panda.rs");
    }
    pub mod gen3 {
        include!("../galaw/gen3.rs");
    }
    pub mod irb120 {
        include!("../galaw/irb120.rs");
    }
    pub mod dual_arm_torso {
        include!("../galaw/dual_arm_torso.rs");
    }
    pub mod quadruped {
        include!("../galaw/quadruped.rs");
    }
    pub mod humanoid {
        include!("../galaw/humanoid.rs");
    }
}

/// galaw's all-link forward kinematics, f64 and f32, on the same configurations. galaw has one
/// command per moving joint (it does not follow mimic joints), so each command gets the value
/// our model gives that joint, mimic joints included: the poses then agree, which check mode
/// asserts at every link galaw computes.
pub fn galaw_contender<const DOF: usize, const N: usize, const M: usize>(
    mode: &mut Mode,
    fk: &Setup<DOF>,
    children: [&str; N],
    links: [&str; M],
    fk_f64: impl Fn(&[f64; N], &mut [nalgebra::Isometry3<f64>; M]),
    fk_f32: impl Fn(&[f32; N], &mut [nalgebra::Isometry3<f32>; M]),
    generated: impl FnMut(usize),
) {
    let Setup { reference, qs, tip, .. } = fk;
    let tree = reference.tree();
    let motions: Vec<_> = children
        .iter()
        .map(|child| {
            let link = tree.link_id(child).expect("galaw's link is ours");
            tree.joints().iter().find(|j| j.child == link).expect("a joint moves it").motion
        })
        .collect();
    let commands: Vec<[f64; N]> =
        qs.iter().map(|q| std::array::from_fn(|i| motions[i].value(q).expect("a moving joint"))).collect();
    let commands_f32: Vec<[f32; N]> = commands.iter().map(|c| c.map(|v| v as f32)).collect();
    let mut poses = [nalgebra::Isometry3::identity(); M];
    let mut poses_f32 = [nalgebra::Isometry3::identity(); M];
    if let Mode::Check = mode {
        // Every link galaw computes, f64 and f32, on every configuration timed.
        assert!(links.contains(tip), "galaw computes the tip");
        let reach = tree.reach();
        for (i, q) in qs.iter().enumerate() {
            let expected = reference_poses(reference, q);
            fk_f64(&commands[i], &mut poses);
            fk_f32(&commands_f32[i], &mut poses_f32);
            for (k, link) in links.iter().enumerate() {
                verify("galaw_all_f64", link, i, &pose_of(&poses[k]), &expected(link), reach, AGREEMENT_TOLERANCE);
                let pose = pose_of(&widen_iso(&poses_f32[k]));
                verify("galaw_all_f32", link, i, &pose, &expected(link), reach, AGREEMENT_TOLERANCE_F32);
            }
        }
    }
    mode.run("galaw_all_f64", |i| {
        fk_f64(&commands[i], &mut poses);
        black_box(&mut poses);
    });
    mode.run("galaw_all_f32", |i| {
        fk_f32(&commands_f32[i], &mut poses_f32);
        black_box(&mut poses_f32);
    });
    mode.pair(
        "galaw_all_f64/generated_all_f64",
        |i| {
            fk_f64(&commands[i], &mut poses);
            black_box(&mut poses);
        },
        generated,
    );
}

/// The runtime reference: all link poses (against the generated code and the floor of all
/// links) and the tip's pose. It is the oracle check mode measures against, so nothing to check.
pub fn runtime<const N: usize>(
    mode: &mut Mode,
    fk: &Setup<N>,
    generated_all: impl FnMut(usize),
    floor_all: impl FnMut(usize) -> f64,
) {
    let Setup { reference, qs, tip, .. } = fk;
    mode.run("runtime_all_f64", |i| reference.link_poses(&qs[i]));
    mode.pair("runtime_all_f64/generated_all_f64", |i| reference.link_poses(&qs[i]), generated_all);
    mode.pair("runtime_all_f64/floor_all_f64", |i| reference.link_poses(&qs[i]), floor_all);
    mode.run("runtime_pose_f64", |i| reference.link_pose(&qs[i], tip));
}

/// The `k` crate on the same URDF: its whole-tree update and its serial chain to the tip.
pub fn k_crate<const N: usize>(
    mode: &mut Mode,
    fk: &Setup<N>,
    generated_all: impl FnMut(usize),
    floor_all: impl FnMut(usize) -> f64,
) {
    let Setup { path, tip, qs, .. } = fk;
    let tip = *tip;
    let Ok(chain) = k::Chain::<f64>::from_urdf_file(path) else { return };
    // k orders its degrees of freedom its own way (and sets mimic joints like any other): each of
    // its joints gets the value our model gives it.
    let reference = &fk.reference;
    let tree = reference.tree();
    let names: Vec<String> = chain.iter_joints().map(|j| j.name.clone()).collect();
    let kq = joint_values(tree, &names, qs);
    let mut k_all = |i: usize| {
        chain.set_joint_positions_unchecked(&kq[i]);
        chain.update_transforms().len()
    };
    if let Mode::Check = mode {
        // Each k node's transform is the pose of its joint's child link; k's own root node
        // (`k::urdf::ROOT_JOINT_NAME`) is the root link.
        let children: Vec<String> = chain
            .iter()
            .map(|node| {
                let name = node.joint().name.clone();
                match tree.joints().iter().find(|j| j.name == name) {
                    Some(joint) => tree.link(joint.child).name.clone(),
                    None if name == k::urdf::ROOT_JOINT_NAME => tree.link(tree.root()).name.clone(),
                    None => panic!("k's joint `{name}` is not ours"),
                }
            })
            .collect();
        let reach = tree.reach();
        for (i, q) in qs.iter().enumerate() {
            chain.set_joint_positions_unchecked(&kq[i]);
            let expected = reference_poses(reference, q);
            for (pose, link) in chain.update_transforms().iter().zip(&children) {
                verify("k_all_f64", link, i, &pose_of_k(pose), &expected(link), reach, AGREEMENT_TOLERANCE);
            }
        }
    }
    mode.run("k_all_f64", &mut k_all);
    mode.pair("k_all_f64/generated_all_f64", &mut k_all, generated_all);
    mode.pair("k_all_f64/floor_all_f64", &mut k_all, floor_all);
    let Some(end) = chain.find_link(tip) else { return };
    let serial = k::SerialChain::from_end(end);
    let names: Vec<String> = serial.iter_joints().map(|j| j.name.clone()).collect();
    let sq = joint_values(tree, &names, qs);
    if let Mode::Check = mode {
        let reach = tree.reach();
        for (i, q) in qs.iter().enumerate() {
            serial.set_joint_positions_unchecked(&sq[i]);
            let expected = reference.link_pose(q, tip).expect("tip exists");
            verify("k_pose_f64", tip, i, &pose_of_k(&serial.end_transform()), &expected, reach, AGREEMENT_TOLERANCE);
        }
    }
    mode.run("k_pose_f64", |i| {
        serial.set_joint_positions_unchecked(&sq[i]);
        serial.end_transform()
    });
}
