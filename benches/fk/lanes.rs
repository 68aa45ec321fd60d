//! SIMD lanes: the tip pose of four configurations in one `tip_pose_generic::<F64x4>` call (and
//! eight in one `F32x8` call) against as many scalar calls on the same configurations, and
//! against the lane type's own trigonometry floor. This is what the generated code gains from
//! being generic over its scalar: one body, evaluated across a vector register. Check mode holds
//! every lane of every pack to the reference's pose of that lane's configuration. The lane calls
//! (and their floors) run inside `kinematics::dispatch`, as a user's own loop over lanes would, so
//! a plain build times them with the CPU's widest instruction set.

use kinematics::{AGREEMENT_TOLERANCE, AGREEMENT_TOLERANCE_F32, F32x8, F64x4, LaneValue, Pose, dispatch};

use crate::check::{reference_poses, verify, widen};
use crate::floors::floor_fast;
use crate::inputs::{INPUTS, packs};
use crate::mode::Mode;
use crate::robots::{Generated, Setup};

/// Lanes of f64 and of f32 against scalar calls and their floors, then f64 lanes against f32.
pub fn lanes<R: Generated<N>, const N: usize>(mode: &mut Mode, fk: &Setup<N>) {
    let Setup { q64, q32, tip, reach, .. } = fk;
    let (tip, reach) = (*tip, *reach);
    // Four (eight) configurations per pack, INPUTS packs: every configuration in four of them.
    let pack64: Vec<[F64x4; N]> = packs(q64, INPUTS);
    let pack32: Vec<[F32x8; N]> = packs(q32, INPUTS);
    if let Mode::Check = mode {
        // Every lane of every pack, against its own configuration (the f32 lanes at their own,
        // rounded, configuration).
        let tip_of = |q: &[f64]| reference_poses(&fk.reference, q)(tip);
        let tips: Vec<_> = fk.qs.iter().map(|q| tip_of(q)).collect();
        let tips_f32: Vec<_> = q32.iter().map(|q| tip_of(&q.map(f64::from))).collect();
        for i in 0..INPUTS {
            let pose64 = R::tip_pose_generic::<F64x4>(&pack64[i]);
            for l in 0..4 {
                let j = (4 * i + l) % INPUTS;
                let pose = LaneValue::<F64x4>::lane(&pose64, l);
                verify("lanes_pose_f64x4", tip, j, &pose, &tips[j], reach, AGREEMENT_TOLERANCE);
            }
            let pose32 = R::tip_pose_generic::<F32x8>(&pack32[i]);
            for l in 0..8 {
                let j = (8 * i + l) % INPUTS;
                let pose = widen(&LaneValue::<F32x8>::lane(&pose32, l));
                verify("lanes_pose_f32x8", tip, j, &pose, &tips_f32[j], reach, AGREEMENT_TOLERANCE_F32);
            }
        }
    }
    let (n, _) = fk.sin_cos;
    // Four configurations per call against four calls on the same configurations (and eight for
    // f32); the pack's own floor is our sin/cos on the lane type.
    let mut scalar4 = |i: usize| -> [Pose<f64>; 4] { std::array::from_fn(|l| R::tip_pose(&q64[(4 * i + l) % INPUTS])) };
    let mut lanes4 = |i: usize| {
        dispatch(
            #[inline(always)]
            || R::tip_pose_generic::<F64x4>(&pack64[i]),
        )
    };
    mode.run("lanes_pose_f64x4", &mut lanes4);
    mode.run("scalar4_pose_f64", &mut scalar4);
    mode.pair("scalar4_pose_f64/lanes_pose_f64x4", &mut scalar4, &mut lanes4);
    mode.run("floor_f64x4", |i| floor_fast(&pack64[i], n));
    mode.pair("lanes_pose_f64x4/floor_f64x4", &mut lanes4, |i| floor_fast(&pack64[i], n));
    let mut scalar8 =
        |i: usize| -> [Pose<f32>; 8] { std::array::from_fn(|l| R::tip_pose_f32(&q32[(8 * i + l) % INPUTS])) };
    let mut lanes8 = |i: usize| {
        dispatch(
            #[inline(always)]
            || R::tip_pose_generic::<F32x8>(&pack32[i]),
        )
    };
    mode.run("lanes_pose_f32x8", &mut lanes8);
    mode.run("scalar8_pose_f32", &mut scalar8);
    mode.pair("scalar8_pose_f32/lanes_pose_f32x8", &mut scalar8, &mut lanes8);
    mode.run("floor_f32x8", |i| floor_fast(&pack32[i], n));
    mode.pair("lanes_pose_f32x8/floor_f32x8", &mut lanes8, |i| floor_fast(&pack32[i], n));
    // Per configuration, f64 lanes against f32 lanes: two f64 packs, eight configurations.
    mode.pair(
        "lanes_pose_f64x4/lanes_pose_f32x8",
        |i| {
            dispatch(
                #[inline(always)]
                || (R::tip_pose_generic::<F64x4>(&pack64[i]), R::tip_pose_generic::<F64x4>(&pack64[(i + 1) % INPUTS])),
            )
        },
        &mut lanes8,
    );
}
