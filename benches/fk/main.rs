//! Forward kinematics speed, per robot, f64 and f32: the generated code (derive, our own sin/cos,
//! every angle of a function in one `sin_cos_many` call) against the same robot derived with
//! `trig = "std"` (std's `sin_cos`, one call per angle), the runtime reference, the `k` crate
//! (whole-tree `update_transforms` and a serial chain's `end_transform`), galaw's ahead-of-time
//! generated code (all link poses; `benches/galaw/`), position only; SIMD lanes (`tip_pose_generic`
//! on `F64x4` and `F32x8`) against as many scalar calls; batches of 1,024 configurations
//! (`tip_pose_batch`, `tip_pose_batch_f32`) against the scalar loop; `parallel::batch` (rayon)
//! against one thread on 16,384 configurations; and the trigonometry floors: our sin/cos alone
//! (`sin_cos_many` over as many angles as the generated function has) and std's (`sin_cos` once per
//! angle), of the pose and of all links. The comparisons that matter are also timed in alternation
//! (`Mode::pair`), which a drifting shared machine cannot skew.
//!
//! One module per area, each saying what it measures and why: `poses` (tip and all links),
//! `lanes`, `batches` (and rayon), `peers` (runtime, `k`, galaw), `velocities` (Jacobians and
//! twists); beside them `robots` (the derives and the traits the areas take them by), `inputs`,
//! `floors`, `mode` (criterion or check mode, and the pairs), `check` (check mode's measure) and
//! `records` (the files `bench-report` reads). This file only runs the areas, robot by robot.
//!
//! `cargo bench --bench fk` measures (plain x86-64 build; about 10 minutes on 2 cores, build
//! excluded); the same with `RUSTFLAGS="-C target-cpu=native" CARGO_TARGET_DIR=target/native` is the
//! native run, kept apart. `cargo run -p bench-report` turns both runs' results into
//! `benches/SUMMARY.md` and `benches/ratios.svg`. Under `cargo test` (no `--bench` argument) every
//! benchmark body runs once and everything the bodies compute is checked against the runtime
//! reference instead, on every configuration they are timed on (`Pose::deviation` within
//! `AGREEMENT_TOLERANCE`, f32 within `AGREEMENT_TOLERANCE_F32`): every lane of the lane bodies and
//! every configuration of the batches, also on batches whose length is no multiple of 4 or 8 (the
//! tail), so CI knows the suite builds and times code that computes the right thing.
//!
//! The areas run robot by robot, in a fixed order.

#![allow(clippy::expect_used, clippy::panic)] // a benchmark fails loudly on a robot that does not load

#[path = "../common/mod.rs"]
mod common;

mod batches;
mod check;
mod floors;
mod inputs;
mod lanes;
mod mode;
mod peers;
mod poses;
mod records;
mod robots;
mod velocities;

use std::time::Duration;

use criterion::Criterion;

use mode::Mode;
use robots::*;
use velocities::{Velocity, velocities};

/// Every area of one robot, in the order they have always run: each contender runs next to the
/// one it is compared with (pose and floor, all links and galaw and the runtime), as the machine
/// is shared and its speed drifts over minutes.
fn robot<R: Generated<N>, S: StdGenerated<N>, const N: usize>(mode: &mut Mode, file: &str, tip: &'static str) {
    let fk = Setup::<N>::new::<R>(file, tip);
    poses::tip::<R, S, N>(mode, &fk);
    lanes::lanes::<R, N>(mode, &fk);
    // The generated all-links body every comparison of all link poses times: every link's pose
    // into a fixed-size array in the caller's frame (`let poses = link_poses(q)`, the function's
    // own return slot), black-boxed so no store can be skipped. One closure, lent to criterion
    // and to every pair (poses, galaw, runtime, `k`), so all of them time the same body.
    // Assigning into an array kept from call to call (`kept = link_poses(q)`) costs one copy of
    // the result more: the dispatched body is a call LLVM cannot see through, whose result it
    // builds aside (measured on the UR5's nine poses: about 20 ns).
    let mut generated_all = |i: usize| {
        let poses = R::link_poses(&fk.q64[i]);
        std::hint::black_box(&poses);
    };
    let floor_all = poses::floor_all(&fk);
    poses::all_links::<R, S, N>(mode, &fk, &mut generated_all, floor_all);
    R::galaw(mode, &fk, &mut generated_all);
    peers::runtime(mode, &fk, &mut generated_all, floor_all);
    batches::batches::<R, N>(mode, &fk);
    batches::parallel::<R, N>(mode, &fk);
    if fk.is_urdf() {
        peers::k_crate(mode, &fk, &mut generated_all, floor_all);
    }
}

fn all(c: Option<&mut Criterion>) {
    let mut c = c;
    macro_rules! each {
        ($(($name:literal, $ty:ty, $std:ty, $n:literal, $file:literal, $tip:literal)),* $(,)?) => {
            if c.is_some() {
                // The robot list, for `bench-report` to find the results by.
                records::write_robots(&[$(concat!($name, "\t", $file, "\t", $tip, "\n")),*].concat());
            }
            $({
                match c.as_deref_mut() {
                    Some(c) => {
                        let mut group = c.benchmark_group($name);
                        robot::<$ty, $std, $n>(&mut Mode::Measure(&mut group, $name), $file, $tip);
                        group.finish();
                    }
                    None => robot::<$ty, $std, $n>(&mut Mode::Check, $file, $tip),
                }
            })*
        };
    }
    each!(
        ("puma560", Puma560, Puma560Std, 6, "puma560.toml", "link6"),
        ("stanford", Stanford, StanfordStd, 6, "stanford_arm.toml", "link6"),
        ("planar_2r", Planar2r, Planar2rStd, 2, "planar_2r.toml", "link2"),
        ("scara", Scara, ScaraStd, 4, "scara.toml", "link4"),
        ("ur5", Ur5, Ur5Std, 6, "ur5.urdf", "tool0"),
        ("ur10e", Ur10e, Ur10eStd, 6, "ur10e.urdf", "tool0"),
        ("iiwa14", Iiwa14, Iiwa14Std, 7, "iiwa14.urdf", "iiwa_link_ee"),
        ("panda", Panda, PandaStd, 8, "panda.urdf", "panda_hand"),
        ("gen3", Gen3, Gen3Std, 7, "gen3.urdf", "end_effector_link"),
        ("irb120", Irb120, Irb120Std, 6, "irb120.urdf", "tool0"),
        ("dual_arm", DualArm, DualArmStd, 17, "dual_arm_torso.urdf", "tool_l"),
        ("quadruped", Quadruped, QuadrupedStd, 12, "quadruped.urdf", "RL_foot"),
        ("humanoid", Humanoid, HumanoidStd, 25, "humanoid.urdf", "r_gripper"),
    );
    // The tip velocities of every URDF robot (`jacobians` on their derives): `k` reads URDF only.
    macro_rules! velocity {
        ($(($name:literal, $ty:ty, $file:literal, $tip:literal)),* $(,)?) => {
            $({
                let v = Velocity { pose: <$ty>::tip_pose, jacobian: <$ty>::tip_jacobian, pose_and_jacobian: <$ty>::tip_pose_and_jacobian, twist: <$ty>::tip_twist };
                match c.as_deref_mut() {
                    Some(c) => {
                        let mut group = c.benchmark_group($name);
                        velocities(&mut Mode::Measure(&mut group, $name), $file, $tip, &<$ty>::JOINT_LIMITS, &v);
                        group.finish();
                    }
                    None => velocities(&mut Mode::Check, $file, $tip, &<$ty>::JOINT_LIMITS, &v),
                }
            })*
        };
    }
    velocity!(
        ("ur5", Ur5, "ur5.urdf", "tool0"),
        ("ur10e", Ur10e, "ur10e.urdf", "tool0"),
        ("iiwa14", Iiwa14, "iiwa14.urdf", "iiwa_link_ee"),
        ("panda", Panda, "panda.urdf", "panda_hand"),
        ("gen3", Gen3, "gen3.urdf", "end_effector_link"),
        ("irb120", Irb120, "irb120.urdf", "tool0"),
        ("dual_arm", DualArm, "dual_arm_torso.urdf", "tool_l"),
        ("quadruped", Quadruped, "quadruped.urdf", "RL_foot"),
        ("humanoid", Humanoid, "humanoid.urdf", "r_gripper"),
    );
}

fn main() {
    if common::measuring() {
        let mut c = common::criterion(Duration::from_millis(200), Duration::from_millis(800));
        all(Some(&mut c));
        c.final_summary();
        records::write_paired();
    } else {
        all(None);
        println!("fk benchmarks: every body ran once and agreed with the runtime reference");
    }
}
