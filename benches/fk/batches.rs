//! Batches: the generated `tip_pose_batch` and `tip_pose_batch_f32` (lanes inside, the tail
//! handled) on 1,024 configurations against the scalar loop over the same ones, and
//! `parallel::batch` (rayon) on 16,384 against one thread. This is the throughput a user with many
//! configurations gets without writing lane code; criterion's figures are per batch, and
//! `bench-report` divides them. Check mode holds every output to the reference, also on batches
//! whose length is no multiple of 4 or 8, so the last, partly filled pack is checked too. The
//! column-wise batches (`tip_pose_batch_columns`, one slice per joint) are timed against the
//! row-wise ones and must give the very same poses, and every batch is timed against its lane
//! floor: the sin/cos of its configurations in the lanes it runs on this CPU.

use std::hint::black_box;

use kinematics::{AGREEMENT_TOLERANCE, AGREEMENT_TOLERANCE_F32, F32x8, F64x4, F64x8};

use crate::check::{nan_pose, verify, widen};
use crate::floors::floor_fast;
use crate::inputs::{arrays, arrays_f32, inputs, packs};
use crate::mode::Mode;
use crate::robots::{Generated, Setup};

/// The batch size of the batch benchmarks.
const BATCH: usize = 1024;
/// The batch size of the rayon benchmark: well above `parallel::PARALLEL_THRESHOLD` (4,096).
const LARGE_BATCH: usize = 16_384;
/// Check mode also runs each batch on its first `len - TAIL_CUT` configurations, a length that is
/// no multiple of 4 or 8, so the last, partly filled pack of lanes is checked too.
const TAIL_CUT: usize = 3;

/// 1,024 configurations, f64 and f32, batch against scalar loop, and f64 against f32.
pub fn batches<R: Generated<N>, const N: usize>(mode: &mut Mode, fk: &Setup<N>) {
    let (tip, reach) = (fk.tip, fk.reach);
    let reference = &fk.reference;
    let batch = inputs(fk.limits, BATCH);
    let batch64: Vec<[f64; N]> = arrays(&batch);
    let batch32: Vec<[f32; N]> = arrays_f32(&batch);
    let mut out64 = vec![R::tip_pose(&batch64[0]); BATCH];
    let mut out32 = vec![R::tip_pose_f32(&batch32[0]); BATCH];
    if let Mode::Check = mode {
        let expected: Vec<_> = batch.iter().map(|q| reference.link_pose(q, tip).expect("tip exists")).collect();
        let expected_f32: Vec<_> =
            batch32.iter().map(|q| reference.link_pose(&q.map(f64::from), tip).expect("tip exists")).collect();
        for len in [BATCH, BATCH - TAIL_CUT] {
            let mut out = vec![nan_pose(); len];
            R::tip_pose_batch(&batch64[..len], &mut out).expect("one output per configuration");
            for (i, pose) in out.iter().enumerate() {
                verify("batch1024_f64", tip, i, pose, &expected[i], reach, AGREEMENT_TOLERANCE);
            }
            let mut out = vec![nan_pose::<f32>(); len];
            R::tip_pose_batch_f32(&batch32[..len], &mut out).expect("one output per configuration");
            for (i, pose) in out.iter().enumerate() {
                verify("batch1024_f32", tip, i, &widen(pose), &expected_f32[i], reach, AGREEMENT_TOLERANCE_F32);
            }
        }
    }
    let mut scalar_batch64 = |_: usize| {
        for (o, q) in out64.iter_mut().zip(&batch64) {
            *o = R::tip_pose(q);
        }
        black_box(&mut out64);
    };
    let mut out_lanes64 = vec![R::tip_pose(&batch64[0]); BATCH];
    let mut batch_f64 = |_: usize| {
        R::tip_pose_batch(&batch64, &mut out_lanes64).expect("one output per configuration");
        black_box(&mut out_lanes64);
    };
    mode.run("generated_batch1024_f64", &mut scalar_batch64);
    mode.run("batch1024_f64", &mut batch_f64);
    mode.pair_calls("generated_batch1024_f64/batch1024_f64", 8, &mut scalar_batch64, &mut batch_f64);
    let mut scalar_batch32 = |_: usize| {
        for (o, q) in out32.iter_mut().zip(&batch32) {
            *o = R::tip_pose_f32(q);
        }
        black_box(&mut out32);
    };
    let mut out_lanes32 = vec![R::tip_pose_f32(&batch32[0]); BATCH];
    let mut batch_f32 = |_: usize| {
        R::tip_pose_batch_f32(&batch32, &mut out_lanes32).expect("one output per configuration");
        black_box(&mut out_lanes32);
    };
    mode.run("generated_batch1024_f32", &mut scalar_batch32);
    mode.run("batch1024_f32", &mut batch_f32);
    mode.pair_calls("generated_batch1024_f32/batch1024_f32", 8, &mut scalar_batch32, &mut batch_f32);
    mode.pair_calls("batch1024_f64/batch1024_f32", 8, &mut batch_f64, &mut batch_f32);
    // Column-wise input (one slice per joint), against the same batch row-wise.
    let columns64: Vec<Vec<f64>> = (0..N).map(|j| batch64.iter().map(|q| q[j]).collect()).collect();
    let columns32: Vec<Vec<f32>> = (0..N).map(|j| batch32.iter().map(|q| q[j]).collect()).collect();
    let cols64: [&[f64]; N] = std::array::from_fn(|j| columns64[j].as_slice());
    let cols32: [&[f32]; N] = std::array::from_fn(|j| columns32[j].as_slice());
    if let Mode::Check = mode {
        for len in [BATCH, BATCH - TAIL_CUT] {
            let mut out = vec![nan_pose(); len];
            R::tip_pose_batch_columns(cols64.map(|c| &c[..len]), &mut out).expect("one output per configuration");
            let mut rows = vec![nan_pose(); len];
            R::tip_pose_batch(&batch64[..len], &mut rows).expect("one output per configuration");
            assert_eq!(out, rows, "{tip}: the column-wise batch differs from the row-wise one");
            let mut out = vec![nan_pose::<f32>(); len];
            R::tip_pose_batch_columns_f32(cols32.map(|c| &c[..len]), &mut out).expect("one output per configuration");
            let mut rows = vec![nan_pose::<f32>(); len];
            R::tip_pose_batch_f32(&batch32[..len], &mut rows).expect("one output per configuration");
            assert_eq!(out, rows, "{tip}: the column-wise f32 batch differs from the row-wise one");
        }
    }
    let mut out_columns64 = vec![R::tip_pose(&batch64[0]); BATCH];
    let mut columns_f64 = |_: usize| {
        R::tip_pose_batch_columns(cols64, &mut out_columns64).expect("one output per configuration");
        black_box(&mut out_columns64);
    };
    mode.run("batch_columns1024_f64", &mut columns_f64);
    mode.pair_calls("batch1024_f64/batch_columns1024_f64", 8, &mut batch_f64, &mut columns_f64);
    let mut out_columns32 = vec![R::tip_pose_f32(&batch32[0]); BATCH];
    let mut columns_f32 = |_: usize| {
        R::tip_pose_batch_columns_f32(cols32, &mut out_columns32).expect("one output per configuration");
        black_box(&mut out_columns32);
    };
    mode.run("batch_columns1024_f32", &mut columns_f32);
    mode.pair_calls("batch1024_f32/batch_columns1024_f32", 8, &mut batch_f32, &mut columns_f32);
    // The batches' lane floor: the sin/cos of 1,024 configurations in the lanes the batch runs on
    // this CPU (eight f64 with AVX-512, else four; eight f32 on every CPU), dispatched.
    let (n, _) = fk.sin_cos;
    let wide = kinematics::dispatched_level().contains("AVX-512");
    let floor64: Box<dyn FnMut(usize) -> f64> = if wide {
        let packs: Vec<[F64x8; N]> = packs(&batch64, BATCH / 8);
        Box::new(move |_| packs.iter().map(|p| floor_fast(p, n).lane(0)).sum())
    } else {
        let packs: Vec<[F64x4; N]> = packs(&batch64, BATCH / 4);
        Box::new(move |_| packs.iter().map(|p| floor_fast(p, n).lane(0)).sum())
    };
    let mut floor64 = floor64;
    mode.run("floor_batch1024_f64", &mut floor64);
    mode.pair_calls("batch1024_f64/floor_batch1024_f64", 8, &mut batch_f64, &mut floor64);
    let floor32: Box<dyn FnMut(usize) -> f32> = {
        let packs: Vec<[F32x8; N]> = packs(&batch32, BATCH / 8);
        Box::new(move |_| packs.iter().map(|p| floor_fast(p, n).lane(0)).sum())
    };
    let mut floor32 = floor32;
    mode.run("floor_batch1024_f32", &mut floor32);
    mode.pair_calls("batch1024_f32/floor_batch1024_f32", 8, &mut batch_f32, &mut floor32);
    if let Mode::Check = mode {
        // The scalar loops' outputs, as the single run above left them.
        for (i, (pose, q)) in out64.iter().zip(&batch).enumerate() {
            let expected = reference.link_pose(q, tip).expect("tip exists");
            verify("generated_batch1024_f64", tip, i, pose, &expected, reach, AGREEMENT_TOLERANCE);
        }
        for (i, (pose, q)) in out32.iter().zip(&batch32).enumerate() {
            let expected = reference.link_pose(&q.map(f64::from), tip).expect("tip exists");
            verify("generated_batch1024_f32", tip, i, &widen(pose), &expected, reach, AGREEMENT_TOLERANCE_F32);
        }
    }
}

/// Rayon: the same batch function split across the pool's threads, against one thread.
pub fn parallel<R: Generated<N>, const N: usize>(mode: &mut Mode, fk: &Setup<N>) {
    let (tip, reach) = (fk.tip, fk.reach);
    let large: Vec<[f64; N]> = arrays(&inputs(fk.limits, LARGE_BATCH));
    let mut out_large = vec![R::tip_pose(&large[0]); LARGE_BATCH];
    if let Mode::Check = mode {
        for len in [LARGE_BATCH, LARGE_BATCH - TAIL_CUT] {
            let mut out = vec![nan_pose(); len];
            kinematics::parallel::batch(&large[..len], &mut out, R::tip_pose_batch)
                .expect("one output per configuration");
            for (i, (pose, q)) in out.iter().zip(&large).enumerate() {
                let expected = fk.reference.link_pose(q, tip).expect("tip exists");
                verify("parallel_batch16384_f64", tip, i, pose, &expected, reach, AGREEMENT_TOLERANCE);
            }
        }
    }
    let mut one_thread = |_: usize| {
        R::tip_pose_batch(&large, &mut out_large).expect("one output per configuration");
        black_box(&mut out_large);
    };
    mode.run("batch16384_f64", &mut one_thread);
    let mut out_parallel = vec![R::tip_pose(&large[0]); LARGE_BATCH];
    let mut parallel = |_: usize| {
        kinematics::parallel::batch(&large, &mut out_parallel, R::tip_pose_batch)
            .expect("one output per configuration");
        black_box(&mut out_parallel);
    };
    mode.run("parallel_batch16384_f64", &mut parallel);
    mode.pair_calls("batch16384_f64/parallel_batch16384_f64", 2, &mut one_thread, &mut parallel);
}
