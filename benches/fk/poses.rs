//! Poses, one configuration per call: the tip's pose (f64 and f32) and position, and every link's
//! pose, each beside its trigonometry floor and beside the same robot derived with `trig = "std"`.
//! This is the compiler's main product; the floors show how much of its time is sin/cos the
//! code cannot avoid, and the std derive how much our sin/cos and one `sin_cos_many` call per
//! function save. Check mode holds every pose and position computed to the runtime reference's.

use std::hint::black_box;

use kinematics::{AGREEMENT_TOLERANCE, AGREEMENT_TOLERANCE_F32};

use crate::check::{position_pose, reference_poses, verify, widen};
use crate::floors::{floor_fast, floor_std};
use crate::mode::Mode;
use crate::robots::{Generated, Setup, StdGenerated};

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
            verify("generated_pose_f32", tip, i, &widen(&R::tip_pose_f32(&q32[i])), &expected_f32(tip), reach, f32_tol);
            let position = position_pose(R::tip_position(&q64[i]), &expected(tip));
            verify("generated_position_f64", tip, i, &position, &expected(tip), reach, f64_tol);
        }
    }
    let (n, _) = fk.sin_cos;
    let mut generated_pose = |i: usize| R::tip_pose(&q64[i]);
    mode.run("generated_pose_f64", &mut generated_pose);
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
            for (pose, link) in R::link_poses_f32(&q32[i]).as_ref().iter().zip(R::LINK_NAMES) {
                verify("generated_all_f32", link, i, &widen(pose), &expected_f32(link), reach, AGREEMENT_TOLERANCE_F32);
            }
        }
    }
    let (_, n_all) = fk.sin_cos;
    mode.run("generated_all_f64", &mut generated_all);
    mode.run("floor_all_f64", floor_all);
    mode.pair("generated_all_f64/floor_all_f64", &mut generated_all, floor_all);
    mode.run("floor_std_all_f64", |i| floor_std(&q64[i], n_all));
    mode.pair("floor_std_all_f64/floor_all_f64", |i| floor_std(&q64[i], n_all), floor_all);
    let mut std_all64 = S::link_poses(&q64[0]);
    let mut std_all = |i: usize| {
        std_all64 = S::link_poses(&q64[i]);
        black_box(&mut std_all64);
    };
    mode.run("std_all_f64", &mut std_all);
    mode.pair("std_all_f64/generated_all_f64", &mut std_all, &mut generated_all);
    let mut all32 = R::link_poses_f32(&q32[0]);
    mode.run("generated_all_f32", |i| {
        all32 = R::link_poses_f32(&q32[i]);
        black_box(&mut all32);
    });
}
