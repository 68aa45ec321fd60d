//! Poses, one configuration per call: the tip's pose (f64 and f32) and position, and every link's
//! pose, each beside its trigonometry floor and beside the same robot derived with `trig = "std"`.
//! This is the compiler's main product; the floors show how much of its time is sin/cos the
//! code cannot avoid, and the std derive how much our sin/cos and one `sin_cos_many` call per
//! function save. Check mode holds every pose and position computed to the runtime reference's.

use std::hint::black_box;

use kinematics::{AGREEMENT_TOLERANCE, AGREEMENT_TOLERANCE_F32};

use crate::check::{position_pose, reference_poses, verify, widen};
use crate::floors::{floor_fast, floor_std};
use crate::inputs::INPUTS;
use crate::mode::Mode;
use crate::robots::{Generated, Setup, StdGenerated};

/// Calls per round of the dispatch-cost pair.
const DISPATCH_CALLS: usize = 64;

/// The tip: pose f64 (generated, std-trig) and f32, position, and their floors.
pub fn tip<R: Generated<N>, S: StdGenerated<N>, const N: usize>(mode: &mut Mode, fk: &Setup<N>) {
    let Setup { q64, q32, tip, reach, .. } = fk;
    let (tip, reach) = (*tip, *reach);
    if let Mode::Check = mode {
        // Every body timed below, on every configuration it is timed on: the f32 bodies at their
        // own (rounded) configuration. The floors compute no pose.
        for (i, q) in fk.qs.iter().enumerate() {
            let expected = reference_poses(&fk.reference, q);
            let q32_64: Vec<f64> = q32[i].iter().map(|&x| f64::from(x)).collect();
            let expected_f32 = reference_poses(&fk.reference, &q32_64);
            let (f64_tol, f32_tol) = (AGREEMENT_TOLERANCE, AGREEMENT_TOLERANCE_F32);
            verify("generated_pose_f64", tip, i, &R::tip_pose(&q64[i]), &expected(tip), reach, f64_tol);
            verify("std_pose_f64", tip, i, &S::tip_pose(&q64[i]), &expected(tip), reach, f64_tol);
            let baseline = R::tip_pose_generic::<f64>(&q64[i]);
            verify("baseline_pose_f64", tip, i, &baseline, &expected(tip), reach, f64_tol);
            verify("generated_pose_f32", tip, i, &widen(&R::tip_pose_f32(&q32[i])), &expected_f32(tip), reach, f32_tol);
            let position = position_pose(R::tip_position(&q64[i]), &expected(tip));
            verify("generated_position_f64", tip, i, &position, &expected(tip), reach, f64_tol);
        }
    }
    let (n, _) = fk.sin_cos;
    let mut generated_pose = |i: usize| R::tip_pose(&q64[i]);
    mode.run("generated_pose_f64", &mut generated_pose);
    // The same body, not dispatched: the build's own instruction set (baseline x86-64 in a plain
    // build, so the pair is what dispatch gains; in a native build both are the same code and
    // the pair is what dispatch costs there, nothing).
    let mut baseline_pose = |i: usize| R::tip_pose_generic::<f64>(&q64[i]);
    mode.run("baseline_pose_f64", &mut baseline_pose);
    mode.pair("baseline_pose_f64/generated_pose_f64", &mut baseline_pose, &mut generated_pose);
    // What the choice itself costs per call: 64 dispatched calls against one dispatch around 64
    // calls of the same body.
    let each = |i: usize| {
        for k in 0..DISPATCH_CALLS {
            black_box(R::tip_pose(&q64[(i + k) % INPUTS]));
        }
    };
    let once = |i: usize| {
        kinematics::dispatch(
            #[inline(always)]
            || {
                for k in 0..DISPATCH_CALLS {
                    black_box(R::tip_pose_generic::<f64>(&q64[(i + k) % INPUTS]));
                }
            },
        );
    };
    mode.pair_calls("dispatch_each_pose_f64/dispatch_once_pose_f64", 32, each, once);
    // The new floor (our sin/cos, one call for the function's angles) and the old one (std's).
    mode.run("floor_f64", |i| floor_fast(&q64[i], n));
    mode.pair("generated_pose_f64/floor_f64", &mut generated_pose, |i| floor_fast(&q64[i], n));
    mode.run("floor_std_f64", |i| floor_std(&q64[i], n));
    mode.pair("floor_std_f64/floor_f64", |i| floor_std(&q64[i], n), |i| floor_fast(&q64[i], n));
    // The same robot with std's sin_cos, one call per angle.
    mode.run("std_pose_f64", |i| S::tip_pose(&q64[i]));
    mode.pair("std_pose_f64/generated_pose_f64", |i| S::tip_pose(&q64[i]), &mut generated_pose);
    mode.pair("std_pose_f64/floor_std_f64", |i| S::tip_pose(&q64[i]), |i| floor_std(&q64[i], n));
    mode.run("generated_pose_f32", |i| R::tip_pose_f32(&q32[i]));
    mode.run("floor_f32", |i| floor_fast(&q32[i], n));
    mode.pair("generated_pose_f32/floor_f32", |i| R::tip_pose_f32(&q32[i]), |i| floor_fast(&q32[i], n));
    mode.run("generated_position_f64", |i| R::tip_position(&q64[i]));
    mode.pair("generated_position_f64/generated_pose_f64", |i| R::tip_position(&q64[i]), &mut generated_pose);
}

/// The floor of all link poses: the sin_cos pairs of every moving joint. No code that computes
/// them with this routine can be faster, so a peer's all-links time over this floor bounds the
/// speed-up over that peer that any such code can show.
pub fn floor_all<const N: usize>(fk: &Setup<N>) -> impl Fn(usize) -> f64 + Copy + '_ {
    let (_, n_all) = fk.sin_cos;
    move |i: usize| floor_fast(&fk.q64[i], n_all)
}

/// Every link: generated f64 (against its floor and the std-trig derive) and f32.
pub fn all_links<R: Generated<N>, S: StdGenerated<N>, const N: usize>(
    mode: &mut Mode,
    fk: &Setup<N>,
    mut generated_all: impl FnMut(usize),
    floor_all: impl Fn(usize) -> f64 + Copy,
) {
    let Setup { q64, q32, reach, .. } = fk;
    let reach = *reach;
    if let Mode::Check = mode {
        for (i, q) in fk.qs.iter().enumerate() {
            let expected = reference_poses(&fk.reference, q);
            let q32_64: Vec<f64> = q32[i].iter().map(|&x| f64::from(x)).collect();
            let expected_f32 = reference_poses(&fk.reference, &q32_64);
            for (pose, link) in R::link_poses(&q64[i]).as_ref().iter().zip(R::LINK_NAMES) {
                verify("generated_all_f64", link, i, pose, &expected(link), reach, AGREEMENT_TOLERANCE);
            }
            for (pose, link) in S::link_poses(&q64[i]).as_ref().iter().zip(S::LINK_NAMES) {
                verify("std_all_f64", link, i, pose, &expected(link), reach, AGREEMENT_TOLERANCE);
            }
            for (pose, link) in R::link_poses_baseline(&q64[i]).as_ref().iter().zip(R::LINK_NAMES) {
                verify("baseline_all_f64", link, i, pose, &expected(link), reach, AGREEMENT_TOLERANCE);
            }
            for (pose, link) in R::link_poses_f32(&q32[i]).as_ref().iter().zip(R::LINK_NAMES) {
                verify("generated_all_f32", link, i, &widen(pose), &expected_f32(link), reach, AGREEMENT_TOLERANCE_F32);
            }
        }
    }
    let (_, n_all) = fk.sin_cos;
    mode.run("generated_all_f64", &mut generated_all);
    // Not dispatched (see `tip`): what dispatch gains on all links in a plain build.
    let mut baseline_all = |i: usize| {
        let poses = R::link_poses_baseline(&q64[i]);
        black_box(&poses);
    };
    mode.run("baseline_all_f64", &mut baseline_all);
    mode.pair("baseline_all_f64/generated_all_f64", &mut baseline_all, &mut generated_all);
    mode.run("floor_all_f64", floor_all);
    mode.pair("generated_all_f64/floor_all_f64", &mut generated_all, floor_all);
    mode.run("floor_std_all_f64", |i| floor_std(&q64[i], n_all));
    mode.pair("floor_std_all_f64/floor_all_f64", |i| floor_std(&q64[i], n_all), floor_all);
    let mut std_all = |i: usize| {
        let poses = S::link_poses(&q64[i]);
        black_box(&poses);
    };
    mode.run("std_all_f64", &mut std_all);
    mode.pair("std_all_f64/generated_all_f64", &mut std_all, &mut generated_all);
    mode.run("generated_all_f32", |i| {
        let poses = R::link_poses_f32(&q32[i]);
        black_box(&poses);
    });
}
