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
//! `cargo bench --bench fk` measures (plain x86-64 build; about 10 minutes on 2 cores, build
//! excluded); the same with `RUSTFLAGS="-C target-cpu=native" CARGO_TARGET_DIR=target/native` is the
//! native run, kept apart. `cargo run -p bench-report` turns both runs' results into
//! `benches/SUMMARY.md` and `benches/ratios.svg`. Under `cargo test` (no `--bench` argument) every
//! benchmark body runs once and everything the bodies compute is checked against the runtime
//! reference instead, on every configuration they are timed on (`Pose::deviation` within
//! `AGREEMENT_TOLERANCE`, f32 within `AGREEMENT_TOLERANCE_F32`): every lane of the lane bodies and
//! every configuration of the batches, also on batches whose length is no multiple of 4 or 8 (the
//! tail), so CI knows the suite builds and times code that computes the right thing.

#![allow(clippy::expect_used, clippy::panic)] // a benchmark fails loudly on a robot that does not load

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{BenchmarkGroup, Criterion, measurement::WallTime};
use kinematics::{
    AGREEMENT_TOLERANCE, AGREEMENT_TOLERANCE_F32, F32x8, F64x4, Kinematics, LaneValue, Pose, Real, ReferenceFk, StdTrig,
};

/// Inputs cycled through in the timed loops (computed before timing).
const INPUTS: usize = 256;
/// The batch size of the batch benchmarks.
const BATCH: usize = 1024;
/// The batch size of the rayon benchmark: well above `parallel::PARALLEL_THRESHOLD` (4,096).
const LARGE_BATCH: usize = 16_384;
/// Check mode also runs each batch on its first `len - TAIL_CUT` configurations, a length that is
/// no multiple of 4 or 8, so the last, partly filled pack of lanes is checked too.
const TAIL_CUT: usize = 3;

/// Configurations within the limits (or +-pi for continuous joints), from a fixed seed.
fn inputs(limits: &[kinematics::JointLimits], count: usize) -> Vec<Vec<f64>> {
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    let mut uniform = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..count)
        .map(|_| {
            limits
                .iter()
                .map(|l| {
                    let (lo, hi) =
                        if l.lower.is_finite() && l.upper.is_finite() { (l.lower, l.upper) } else { (-3.1, 3.1) };
                    lo + (hi - lo) * uniform()
                })
                .collect()
        })
        .collect()
}

fn arrays<const N: usize>(qs: &[Vec<f64>]) -> Vec<[f64; N]> {
    qs.iter().map(|q| std::array::from_fn(|i| q[i])).collect()
}

fn arrays_f32<const N: usize>(qs: &[Vec<f64>]) -> Vec<[f32; N]> {
    qs.iter().map(|q| std::array::from_fn(|i| q[i] as f32)).collect()
}

/// The trigonometry floor with std's `sin_cos`: `n` calls, one per angle, as code derived with
/// `trig = "std"` makes them (each pair folded into one sum so none is optimised away; that costs a
/// multiply-add per pair). The angles are the joint values, cycled: the routine's time does not
/// depend on which angles they are.
#[inline(always)]
fn floor_std<T: StdTrig, const N: usize>(q: &[T; N], n: usize) -> T {
    let mut acc = T::from_f64(0.0);
    for i in 0..n {
        let (s, c) = q[i % N].sin_cos_std();
        acc = acc + s * c;
    }
    acc
}

/// The trigonometry floor with our sin/cos, as the generated code calls it: all `n` angles of the
/// function in one `T::sin_cos_many` call (folded like [`floor_std`]). `n` is a run-time count
/// (the compiler's), `sin_cos_many` takes it as a constant: one arm per count, chosen by a branch
/// that always goes the same way.
#[inline(always)]
fn floor_fast<T: Real, const N: usize>(q: &[T; N], n: usize) -> T {
    #[inline(always)]
    fn many<T: Real, const N: usize, const K: usize>(q: &[T; N]) -> T {
        let (s, c) = T::sin_cos_many::<K>(std::array::from_fn(|i| q[i % N]));
        let mut acc = T::from_f64(0.0);
        for i in 0..K {
            acc = acc + s[i] * c[i];
        }
        acc
    }
    macro_rules! by_count {
        ($($k:literal)*) => {
            match n {
                $($k => many::<T, N, $k>(q),)*
                _ => panic!("no floor for {n} angles: add the count to `floor_fast`"),
            }
        };
    }
    by_count!(0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29 30 31 32)
}

/// `count` packs of lanes from `qs` (cycled): pack `i` holds configurations `(L * i + l) % len`.
fn packs<T: Copy, L: kinematics::Lanes<Scalar = T>, const N: usize>(qs: &[[T; N]], count: usize) -> Vec<[L; N]> {
    (0..count).map(|i| std::array::from_fn(|j| L::from_fn(|l| qs[(L::LANES * i + l) % qs.len()][j]))).collect()
}

/// How one benchmark is run: measured by criterion, or once and checked (`cargo test`).
enum Mode<'a, 'c> {
    /// Criterion's group, and the robot's name for the paired ratios.
    Measure(&'a mut BenchmarkGroup<'c, WallTime>, &'static str),
    Check,
}

impl Mode<'_, '_> {
    fn run<R>(&mut self, name: &str, mut f: impl FnMut(usize) -> R) {
        match self {
            Mode::Measure(group, _) => {
                let mut i = 0usize;
                group.bench_function(name, |b| {
                    b.iter(|| {
                        i = (i + 1) % INPUTS;
                        black_box(f(black_box(i)))
                    })
                });
            }
            Mode::Check => {
                black_box(f(0));
            }
        }
    }

    /// The time of `numerator` over the time of `denominator`, measured in alternation: 201 rounds,
    /// each timing both on the same 2,000 inputs back to back (which goes first alternates), and
    /// the median of the rounds' ratios. Criterion's medians come from different seconds of a
    /// shared machine whose speed drifts; these ratios do not. Recorded for `bench-report`.
    fn pair<A, B>(&mut self, name: &str, numerator: impl FnMut(usize) -> A, denominator: impl FnMut(usize) -> B) {
        self.pair_calls(name, 2000, numerator, denominator);
    }

    /// [`Mode::pair`] with `calls` calls of each per round: fewer for bodies that take a batch per
    /// call, so a round stays about a millisecond.
    fn pair_calls<A, B>(
        &mut self,
        name: &str,
        calls: usize,
        mut numerator: impl FnMut(usize) -> A,
        mut denominator: impl FnMut(usize) -> B,
    ) {
        let Mode::Measure(_, robot) = self else { return };
        if !selected(&format!("{robot}/{name}")) {
            return; // a filtered run times the pairs of the robots it selects only
        }
        const ROUNDS: usize = 201;
        let time = |f: &mut dyn FnMut(usize)| {
            let start = Instant::now();
            for k in 0..calls {
                f(black_box(k % INPUTS));
            }
            start.elapsed().as_secs_f64()
        };
        let mut ratios: Vec<f64> = (0..ROUNDS)
            .map(|round| {
                let mut num = |i: usize| {
                    black_box(numerator(i));
                };
                let mut den = |i: usize| {
                    black_box(denominator(i));
                };
                if round % 2 == 0 {
                    let n = time(&mut num);
                    n / time(&mut den)
                } else {
                    let d = time(&mut den);
                    time(&mut num) / d
                }
            })
            .collect();
        ratios.sort_by(f64::total_cmp);
        let median = ratios[ROUNDS / 2];
        println!("{robot}/{name}: paired ratio {median:.3} (median of {ROUNDS} alternating rounds)");
        PAIRED.lock().map(|mut p| p.push(format!("{robot}\t{name}\t{median}\n"))).ok();
    }
}

/// Criterion's filter, if it was given one: the first argument that is neither a flag nor the
/// value of a flag that takes one.
static FILTER: std::sync::LazyLock<Option<String>> = std::sync::LazyLock::new(|| {
    const TAKES_VALUE: [&str; 16] = [
        "--save-baseline",
        "--baseline",
        "--baseline-lenient",
        "--load-baseline",
        "--sample-size",
        "--warm-up-time",
        "--measurement-time",
        "--nresamples",
        "--noise-threshold",
        "--confidence-level",
        "--significance-level",
        "--profile-time",
        "--plotting-backend",
        "--output-format",
        "--color",
        "--format",
    ];
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        if TAKES_VALUE.contains(&arg.as_str()) {
            args.next();
        } else if !arg.starts_with('-') {
            return Some(arg);
        }
    }
    None
});

/// Whether a pair named `id` (`robot/numerator/denominator`) is timed in this run: always without
/// a filter, else when the filter is part of its name (criterion's filters are regular
/// expressions; a plain robot name such as `ur5` selects the same robots both ways).
fn selected(id: &str) -> bool {
    FILTER.as_deref().is_none_or(|filter| id.contains(filter))
}

/// Paired ratios of this run, written next to criterion's results for `bench-report`.
static PAIRED: std::sync::Mutex<Vec<String>> = std::sync::Mutex::new(Vec::new());

/// galaw 0.3.0's generated forward kinematics for our URDF robots, written by
/// `benches/galaw/regenerate.sh` (its output is kept as generated: no lints apply).
#[allow(clippy::all, clippy::pedantic, unused_imports, non_snake_case)]
mod galaw {
    pub mod ur5 {
        include!("galaw/ur5.rs");
    }
    pub mod ur10e {
        include!("galaw/ur10e.rs");
    }
    pub mod iiwa14 {
        include!("galaw/iiwa14.rs");
    }
    pub mod panda {
        include!("galaw/panda.rs");
    }
    pub mod gen3 {
        include!("galaw/gen3.rs");
    }
    pub mod irb120 {
        include!("galaw/irb120.rs");
    }
    pub mod dual_arm_torso {
        include!("galaw/dual_arm_torso.rs");
    }
    pub mod quadruped {
        include!("galaw/quadruped.rs");
    }
    pub mod humanoid {
        include!("galaw/humanoid.rs");
    }
}

/// galaw's all-link forward kinematics, f64 and f32, on the same configurations. galaw has one
/// command per moving joint (it does not follow mimic joints), so each command gets the value
/// our model gives that joint, mimic joints included: the poses then agree, which check mode
/// asserts at the tip.
#[allow(clippy::too_many_arguments)]
fn galaw_contender<const N: usize, const M: usize>(
    mode: &mut Mode,
    reference: &ReferenceFk,
    qs: &[Vec<f64>],
    tip: &str,
    children: [&str; N],
    links: [&str; M],
    fk_f64: impl Fn(&[f64; N], &mut [nalgebra::Isometry3<f64>; M]),
    fk_f32: impl Fn(&[f32; N], &mut [nalgebra::Isometry3<f32>; M]),
    generated: impl FnMut(usize),
) {
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
        assert!(links.contains(&tip), "galaw computes the tip");
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

/// Check mode: `pose` (computed by the body `what` at configuration `i`) against the reference's
/// pose of `link`, by `Pose::deviation` within `tolerance` (`AGREEMENT_TOLERANCE`, or
/// `AGREEMENT_TOLERANCE_F32` for single precision), the measure every agreement check uses.
fn verify(
    what: &str,
    link: &str,
    i: usize,
    pose: &Pose<f64>,
    expected: &nalgebra::Isometry3<f64>,
    reach: f64,
    tolerance: f64,
) {
    let d = pose.deviation(expected, reach);
    // NaN fails too.
    if d.is_nan() || d > tolerance {
        panic!("{what}: `{link}` off by {d:e} (tolerance {tolerance:e}) at configuration {i}");
    }
}

/// A position as a pose with the expected rotation, so the deviation measures the position alone.
fn position_pose(position: [f64; 3], expected: &nalgebra::Isometry3<f64>) -> Pose<f64> {
    Pose { translation: position, ..pose_of(expected) }
}

fn pose_of(iso: &nalgebra::Isometry3<f64>) -> Pose<f64> {
    let r = iso.rotation.to_rotation_matrix();
    let t = iso.translation.vector;
    Pose { rotation: std::array::from_fn(|i| std::array::from_fn(|j| r[(i, j)])), translation: [t[0], t[1], t[2]] }
}

/// A pose computed by `k` (which links its own nalgebra).
fn pose_of_k(iso: &k::nalgebra::Isometry3<f64>) -> Pose<f64> {
    let m = iso.to_homogeneous();
    Pose {
        rotation: std::array::from_fn(|i| std::array::from_fn(|j| m[(i, j)])),
        translation: [m[(0, 3)], m[(1, 3)], m[(2, 3)]],
    }
}

fn widen(p: &Pose<f32>) -> Pose<f64> {
    Pose { rotation: p.rotation.map(|row| row.map(f64::from)), translation: p.translation.map(f64::from) }
}

fn widen_iso(p: &nalgebra::Isometry3<f32>) -> nalgebra::Isometry3<f64> {
    p.cast::<f64>()
}

/// The reference's pose of every link at `q`, by name.
fn reference_poses(reference: &ReferenceFk, q: &[f64]) -> impl Fn(&str) -> nalgebra::Isometry3<f64> {
    let poses = reference.link_poses(q).expect("q fits the robot");
    let ids: std::collections::HashMap<String, usize> =
        reference.tree().links().iter().enumerate().map(|(i, l)| (l.name.clone(), i)).collect();
    move |link: &str| poses[*ids.get(link).unwrap_or_else(|| panic!("no link `{link}` in the reference"))]
}

/// Each of `joints` (names, in another implementation's order) gets the value our model gives it
/// at each configuration (mimic joints included), so that implementation computes the same poses.
fn joint_values(tree: &kinematics::KinematicTree, joints: &[String], qs: &[Vec<f64>]) -> Vec<Vec<f64>> {
    let motions: Vec<_> = joints
        .iter()
        .map(|name| tree.joints().iter().find(|j| j.name == *name).expect("the joint is ours").motion)
        .collect();
    qs.iter().map(|q| motions.iter().map(|m| m.value(q).expect("a moving joint")).collect()).collect()
}

macro_rules! robot {
    ($mode:expr, $ty:ty, $std:ty, $n:literal, $file:literal, $tip:literal, $sin_cos:expr $(, $galaw:ident)?) => {{
        let mode: &mut Mode = $mode;
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/robots/", $file);
        let qs = inputs(&<$ty>::JOINT_LIMITS, INPUTS);
        let q64: Vec<[f64; $n]> = arrays(&qs);
        let q32: Vec<[f32; $n]> = arrays_f32(&qs);
        // Four (eight) configurations per pack, INPUTS packs: every configuration in four of them.
        let pack64: Vec<[F64x4; $n]> = packs(&q64, INPUTS);
        let pack32: Vec<[F32x8; $n]> = packs(&q32, INPUTS);
        let reference = ReferenceFk::new(kinematics::load(path).expect("robot loads"));
        let reach = reference.tree().reach();
        if let Mode::Check = mode {
            // Every body timed below that computes poses, on every configuration it is timed on:
            // the f32 bodies at their own (rounded) configuration. The runtime bodies are the
            // reference itself, and the floors compute no pose.
            let (tip, f64_tol, f32_tol) = ($tip, AGREEMENT_TOLERANCE, AGREEMENT_TOLERANCE_F32);
            let mut tips = Vec::new();
            let mut tips_f32 = Vec::new();
            for (i, q) in qs.iter().enumerate() {
                let expected = reference_poses(&reference, q);
                let q32_64: Vec<f64> = q32[i].iter().map(|&x| f64::from(x)).collect();
                let expected_f32 = reference_poses(&reference, &q32_64);
                verify("generated_pose_f64", tip, i, &<$ty>::tip_pose(&q64[i]), &expected(tip), reach, f64_tol);
                verify("std_pose_f64", tip, i, &<$std>::tip_pose(&q64[i]), &expected(tip), reach, f64_tol);
                verify("generated_pose_f32", tip, i, &widen(&<$ty>::tip_pose_f32(&q32[i])), &expected_f32(tip), reach, f32_tol);
                let position = position_pose(<$ty>::tip_position(&q64[i]), &expected(tip));
                verify("generated_position_f64", tip, i, &position, &expected(tip), reach, f64_tol);
                for (pose, link) in <$ty>::link_poses(&q64[i]).iter().zip(<$ty>::LINK_NAMES) {
                    verify("generated_all_f64", link, i, pose, &expected(link), reach, f64_tol);
                }
                for (pose, link) in <$std>::link_poses(&q64[i]).iter().zip(<$std>::LINK_NAMES) {
                    verify("std_all_f64", link, i, pose, &expected(link), reach, f64_tol);
                }
                for (pose, link) in <$ty>::link_poses_f32(&q32[i]).iter().zip(<$ty>::LINK_NAMES) {
                    verify("generated_all_f32", link, i, &widen(pose), &expected_f32(link), reach, f32_tol);
                }
                tips.push(expected(tip));
                tips_f32.push(expected_f32(tip));
            }
            // Every lane of every pack, against its own configuration.
            for i in 0..INPUTS {
                let pose64 = <$ty>::tip_pose_generic::<F64x4>(&pack64[i]);
                for l in 0..4 {
                    let j = (4 * i + l) % INPUTS;
                    verify("lanes_pose_f64x4", tip, j, &LaneValue::<F64x4>::lane(&pose64, l), &tips[j], reach, f64_tol);
                }
                let pose32 = <$ty>::tip_pose_generic::<F32x8>(&pack32[i]);
                for l in 0..8 {
                    let j = (8 * i + l) % INPUTS;
                    let pose = widen(&LaneValue::<F32x8>::lane(&pose32, l));
                    verify("lanes_pose_f32x8", tip, j, &pose, &tips_f32[j], reach, f32_tol);
                }
            }
        }
        // Each contender runs next to the one it is compared with (pose and floor, all links and
        // galaw and the runtime): the machine is shared and its speed drifts over minutes.
        let (n, n_all): (usize, usize) = $sin_cos;
        let mut generated_pose = |i: usize| <$ty>::tip_pose(&q64[i]);
        mode.run("generated_pose_f64", &mut generated_pose);
        // The new floor (our sin/cos, one call for the function's angles) and the old one (std's).
        mode.run("floor_f64", |i| floor_fast(&q64[i], n));
        mode.pair("generated_pose_f64/floor_f64", &mut generated_pose, |i| floor_fast(&q64[i], n));
        mode.run("floor_std_f64", |i| floor_std(&q64[i], n));
        mode.pair("floor_std_f64/floor_f64", |i| floor_std(&q64[i], n), |i| floor_fast(&q64[i], n));
        // The same robot with std's sin_cos, one call per angle.
        mode.run("std_pose_f64", |i| <$std>::tip_pose(&q64[i]));
        mode.pair("std_pose_f64/generated_pose_f64", |i| <$std>::tip_pose(&q64[i]), &mut generated_pose);
        mode.pair("std_pose_f64/floor_std_f64", |i| <$std>::tip_pose(&q64[i]), |i| floor_std(&q64[i], n));
        mode.run("generated_pose_f32", |i| <$ty>::tip_pose_f32(&q32[i]));
        mode.run("floor_f32", |i| floor_fast(&q32[i], n));
        mode.pair("generated_pose_f32/floor_f32", |i| <$ty>::tip_pose_f32(&q32[i]), |i| floor_fast(&q32[i], n));
        mode.run("generated_position_f64", |i| <$ty>::tip_position(&q64[i]));
        mode.pair("generated_position_f64/generated_pose_f64", |i| <$ty>::tip_position(&q64[i]), &mut generated_pose);
        // Lanes: four configurations per call against four calls on the same configurations (and
        // eight for f32); the pack's own floor is our sin/cos on the lane type.
        let mut scalar4 = |i: usize| -> [Pose<f64>; 4] { std::array::from_fn(|l| <$ty>::tip_pose(&q64[(4 * i + l) % INPUTS])) };
        let mut lanes4 = |i: usize| <$ty>::tip_pose_generic::<F64x4>(&pack64[i]);
        mode.run("lanes_pose_f64x4", &mut lanes4);
        mode.run("scalar4_pose_f64", &mut scalar4);
        mode.pair("scalar4_pose_f64/lanes_pose_f64x4", &mut scalar4, &mut lanes4);
        mode.run("floor_f64x4", |i| floor_fast(&pack64[i], n));
        mode.pair("lanes_pose_f64x4/floor_f64x4", &mut lanes4, |i| floor_fast(&pack64[i], n));
        let mut scalar8 = |i: usize| -> [Pose<f32>; 8] { std::array::from_fn(|l| <$ty>::tip_pose_f32(&q32[(8 * i + l) % INPUTS])) };
        let mut lanes8 = |i: usize| <$ty>::tip_pose_generic::<F32x8>(&pack32[i]);
        mode.run("lanes_pose_f32x8", &mut lanes8);
        mode.run("scalar8_pose_f32", &mut scalar8);
        mode.pair("scalar8_pose_f32/lanes_pose_f32x8", &mut scalar8, &mut lanes8);
        mode.run("floor_f32x8", |i| floor_fast(&pack32[i], n));
        mode.pair("lanes_pose_f32x8/floor_f32x8", &mut lanes8, |i| floor_fast(&pack32[i], n));
        // Per configuration, f64 lanes against f32 lanes: two f64 packs, eight configurations.
        mode.pair(
            "lanes_pose_f64x4/lanes_pose_f32x8",
            |i| (<$ty>::tip_pose_generic::<F64x4>(&pack64[i]), <$ty>::tip_pose_generic::<F64x4>(&pack64[(i + 1) % INPUTS])),
            &mut lanes8,
        );
        // Every link's pose into a fixed-size array the caller keeps (as a planner would, and as
        // `k` and the reference keep theirs), black-boxed so no store can be skipped.
        // One closure, lent to criterion and to both pairs, so all three time the same body.
        let mut all64 = <$ty>::link_poses(&q64[0]);
        let mut generated_all = |i: usize| {
            all64 = <$ty>::link_poses(&q64[i]);
            black_box(&mut all64);
        };
        mode.run("generated_all_f64", &mut generated_all);
        // The floor of all link poses: the sin_cos pairs of every moving joint. No code that
        // computes them with this routine can be faster, so runtime all / floor all bounds the
        // speed-up over the runtime that any such code can show.
        let floor_all = |i: usize| floor_fast(&q64[i], n_all);
        mode.run("floor_all_f64", floor_all);
        mode.pair("generated_all_f64/floor_all_f64", &mut generated_all, floor_all);
        mode.run("floor_std_all_f64", |i| floor_std(&q64[i], n_all));
        mode.pair("floor_std_all_f64/floor_all_f64", |i| floor_std(&q64[i], n_all), floor_all);
        let mut std_all64 = <$std>::link_poses(&q64[0]);
        let mut std_all = |i: usize| {
            std_all64 = <$std>::link_poses(&q64[i]);
            black_box(&mut std_all64);
        };
        mode.run("std_all_f64", &mut std_all);
        mode.pair("std_all_f64/generated_all_f64", &mut std_all, &mut generated_all);
        let mut all32 = <$ty>::link_poses_f32(&q32[0]);
        mode.run("generated_all_f32", |i| {
            all32 = <$ty>::link_poses_f32(&q32[i]);
            black_box(&mut all32);
        });
        $({
            use galaw::$galaw as g;
            galaw_contender(mode, &reference, &qs, $tip, g::JOINT_CHILDREN, g::LINKS, g::fk_f64, g::fk_f32, &mut generated_all);
        })?
        mode.run("runtime_all_f64", |i| reference.link_poses(&qs[i]));
        mode.pair("runtime_all_f64/generated_all_f64", |i| reference.link_poses(&qs[i]), &mut generated_all);
        mode.pair("runtime_all_f64/floor_all_f64", |i| reference.link_poses(&qs[i]), floor_all);
        mode.run("runtime_pose_f64", |i| reference.link_pose(&qs[i], $tip));
        // Batches: the generated `*_batch` (lanes inside) against the scalar loop over the same
        // configurations; criterion's figures are per batch, bench-report divides them.
        let batch = inputs(&<$ty>::JOINT_LIMITS, BATCH);
        let batch64: Vec<[f64; $n]> = arrays(&batch);
        let batch32: Vec<[f32; $n]> = arrays_f32(&batch);
        let mut out64 = vec![<$ty>::tip_pose(&batch64[0]); BATCH];
        let mut out32 = vec![<$ty>::tip_pose_f32(&batch32[0]); BATCH];
        if let Mode::Check = mode {
            let expected: Vec<_> = batch.iter().map(|q| reference.link_pose(q, $tip).expect("tip exists")).collect();
            let expected_f32: Vec<_> = batch32
                .iter()
                .map(|q| reference.link_pose(&q.map(f64::from), $tip).expect("tip exists"))
                .collect();
            for len in [BATCH, BATCH - TAIL_CUT] {
                let mut out = vec![nan_pose(); len];
                <$ty>::tip_pose_batch(&batch64[..len], &mut out).expect("one output per configuration");
                for (i, pose) in out.iter().enumerate() {
                    verify("batch1024_f64", $tip, i, pose, &expected[i], reach, AGREEMENT_TOLERANCE);
                }
                let mut out = vec![nan_pose::<f32>(); len];
                <$ty>::tip_pose_batch_f32(&batch32[..len], &mut out).expect("one output per configuration");
                for (i, pose) in out.iter().enumerate() {
                    verify("batch1024_f32", $tip, i, &widen(pose), &expected_f32[i], reach, AGREEMENT_TOLERANCE_F32);
                }
            }
        }
        let mut scalar_batch64 = |_: usize| {
            for (o, q) in out64.iter_mut().zip(&batch64) {
                *o = <$ty>::tip_pose(q);
            }
            black_box(&mut out64);
        };
        let mut out_lanes64 = vec![<$ty>::tip_pose(&batch64[0]); BATCH];
        let mut batch_f64 = |_: usize| {
            <$ty>::tip_pose_batch(&batch64, &mut out_lanes64).expect("one output per configuration");
            black_box(&mut out_lanes64);
        };
        mode.run("generated_batch1024_f64", &mut scalar_batch64);
        mode.run("batch1024_f64", &mut batch_f64);
        mode.pair_calls("generated_batch1024_f64/batch1024_f64", 8, &mut scalar_batch64, &mut batch_f64);
        let mut scalar_batch32 = |_: usize| {
            for (o, q) in out32.iter_mut().zip(&batch32) {
                *o = <$ty>::tip_pose_f32(q);
            }
            black_box(&mut out32);
        };
        let mut out_lanes32 = vec![<$ty>::tip_pose_f32(&batch32[0]); BATCH];
        let mut batch_f32 = |_: usize| {
            <$ty>::tip_pose_batch_f32(&batch32, &mut out_lanes32).expect("one output per configuration");
            black_box(&mut out_lanes32);
        };
        mode.run("generated_batch1024_f32", &mut scalar_batch32);
        mode.run("batch1024_f32", &mut batch_f32);
        mode.pair_calls("generated_batch1024_f32/batch1024_f32", 8, &mut scalar_batch32, &mut batch_f32);
        mode.pair_calls("batch1024_f64/batch1024_f32", 8, &mut batch_f64, &mut batch_f32);
        if let Mode::Check = mode {
            for (i, (pose, q)) in out64.iter().zip(&batch).enumerate() {
                let expected = reference.link_pose(q, $tip).expect("tip exists");
                verify("generated_batch1024_f64", $tip, i, pose, &expected, reach, AGREEMENT_TOLERANCE);
            }
            for (i, (pose, q)) in out32.iter().zip(&batch32).enumerate() {
                let expected = reference.link_pose(&q.map(f64::from), $tip).expect("tip exists");
                verify("generated_batch1024_f32", $tip, i, &widen(pose), &expected, reach, AGREEMENT_TOLERANCE_F32);
            }
        }
        // Rayon: the same batch function split across the pool's threads, against one thread.
        let large: Vec<[f64; $n]> = arrays(&inputs(&<$ty>::JOINT_LIMITS, LARGE_BATCH));
        let mut out_large = vec![<$ty>::tip_pose(&large[0]); LARGE_BATCH];
        if let Mode::Check = mode {
            for len in [LARGE_BATCH, LARGE_BATCH - TAIL_CUT] {
                let mut out = vec![nan_pose(); len];
                kinematics::parallel::batch(&large[..len], &mut out, <$ty>::tip_pose_batch)
                    .expect("one output per configuration");
                for (i, (pose, q)) in out.iter().zip(&large).enumerate() {
                    let expected = reference.link_pose(q, $tip).expect("tip exists");
                    verify("parallel_batch16384_f64", $tip, i, pose, &expected, reach, AGREEMENT_TOLERANCE);
                }
            }
        }
        let mut one_thread = |_: usize| {
            <$ty>::tip_pose_batch(&large, &mut out_large).expect("one output per configuration");
            black_box(&mut out_large);
        };
        mode.run("batch16384_f64", &mut one_thread);
        let mut out_parallel = vec![<$ty>::tip_pose(&large[0]); LARGE_BATCH];
        let mut parallel = |_: usize| {
            kinematics::parallel::batch(&large, &mut out_parallel, <$ty>::tip_pose_batch)
                .expect("one output per configuration");
            black_box(&mut out_parallel);
        };
        mode.run("parallel_batch16384_f64", &mut parallel);
        mode.pair_calls("batch16384_f64/parallel_batch16384_f64", 2, &mut one_thread, &mut parallel);
        if $file.ends_with(".urdf") {
            k_crate(mode, path, $tip, &qs, &mut generated_all, floor_all);
        }
    }};
}

/// A pose of NaNs: what a batch's output holds before the batch, so a slot it fails to write fails
/// the check.
fn nan_pose<T: Real>() -> Pose<T> {
    let nan = T::from_f64(f64::NAN);
    Pose { rotation: [[nan; 3]; 3], translation: [nan; 3] }
}

/// The `k` crate on the same URDF: its whole-tree update and its serial chain to the tip.
fn k_crate(
    mode: &mut Mode,
    path: &str,
    tip: &str,
    qs: &[Vec<f64>],
    generated_all: impl FnMut(usize),
    floor_all: impl FnMut(usize) -> f64,
) {
    let Ok(chain) = k::Chain::<f64>::from_urdf_file(path) else { return };
    // k orders its degrees of freedom its own way (and sets mimic joints like any other): each of
    // its joints gets the value our model gives it.
    let reference = ReferenceFk::new(kinematics::load(path).expect("robot loads"));
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
            let expected = reference_poses(&reference, q);
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

#[derive(Kinematics)]
#[kinematics(dh = "robots/puma560.toml", tip = "link6", positions, scalars(f64, f32))]
struct Puma560;
#[derive(Kinematics)]
#[kinematics(dh = "robots/puma560.toml", tip = "link6", trig = "std")]
struct Puma560Std;
#[derive(Kinematics)]
#[kinematics(dh = "robots/stanford_arm.toml", tip = "link6", positions, scalars(f64, f32))]
struct Stanford;
#[derive(Kinematics)]
#[kinematics(dh = "robots/stanford_arm.toml", tip = "link6", trig = "std")]
struct StanfordStd;
#[derive(Kinematics)]
#[kinematics(dh = "robots/scara.toml", tip = "link4", positions, scalars(f64, f32))]
struct Scara;
#[derive(Kinematics)]
#[kinematics(dh = "robots/scara.toml", tip = "link4", trig = "std")]
struct ScaraStd;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5.urdf", tip = "tool0", positions, scalars(f64, f32), jacobians)]
struct Ur5;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5.urdf", tip = "tool0", trig = "std")]
struct Ur5Std;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur10e.urdf", tip = "tool0", positions, scalars(f64, f32), jacobians)]
struct Ur10e;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur10e.urdf", tip = "tool0", trig = "std")]
struct Ur10eStd;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/iiwa14.urdf", tip = "iiwa_link_ee", positions, scalars(f64, f32), jacobians)]
struct Iiwa14;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/iiwa14.urdf", tip = "iiwa_link_ee", trig = "std")]
struct Iiwa14Std;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/panda.urdf", tip = "panda_hand", positions, scalars(f64, f32), jacobians)]
struct Panda;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/panda.urdf", tip = "panda_hand", trig = "std")]
struct PandaStd;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/gen3.urdf", tip = "end_effector_link", positions, scalars(f64, f32), jacobians)]
struct Gen3;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/gen3.urdf", tip = "end_effector_link", trig = "std")]
struct Gen3Std;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/irb120.urdf", tip = "tool0", positions, scalars(f64, f32), jacobians)]
struct Irb120;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/irb120.urdf", tip = "tool0", trig = "std")]
struct Irb120Std;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/dual_arm_torso.urdf", tip = "tool_l", positions, scalars(f64, f32), jacobians)]
struct DualArm;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/dual_arm_torso.urdf", tip = "tool_l", trig = "std")]
struct DualArmStd;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/quadruped.urdf", tip = "RL_foot", positions, scalars(f64, f32), jacobians)]
struct Quadruped;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/quadruped.urdf", tip = "RL_foot", trig = "std")]
struct QuadrupedStd;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/humanoid.urdf", tip = "r_gripper", positions, scalars(f64, f32), jacobians)]
struct Humanoid;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/humanoid.urdf", tip = "r_gripper", trig = "std")]
struct HumanoidStd;

/// A pose and its geometric Jacobian.
type PoseAndJacobian<const N: usize> = (Pose<f64>, [[f64; N]; 6]);

/// The generated functions of one robot's tip velocity, for [`velocities`].
struct Velocity<const N: usize> {
    pose: fn(&[f64; N]) -> Pose<f64>,
    jacobian: fn(&[f64; N]) -> [[f64; N]; 6],
    pose_and_jacobian: fn(&[f64; N]) -> PoseAndJacobian<N>,
    twist: fn(&[f64; N], &[f64; N]) -> [f64; 6],
}

/// The tip's velocity (the URDF robots; the targets name the UR5, the iiwa 14 and the Panda): the generated Jacobian alone and with the pose, against the runtime
/// reference's Jacobian and the `k` crate's (its serial chain to the tip), and the generated twist
/// against the generated Jacobian times the rates. Check mode holds every Jacobian timed to the
/// reference's within the agreement tolerance (linear rows times the reach).
fn velocities<const N: usize>(
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

/// How this benchmark was compiled, for `bench-report`: a label (`KINEMATICS_BENCH_BUILD` when the
/// command sets it, `native` or `baseline`; else `native` when the code may use AVX2, which a plain
/// x86-64 build may not) and the vector features the compiler was allowed to use.
fn build_record() -> String {
    let features = [
        ("avx", cfg!(target_feature = "avx")),
        ("avx2", cfg!(target_feature = "avx2")),
        ("fma", cfg!(target_feature = "fma")),
        ("avx512f", cfg!(target_feature = "avx512f")),
    ];
    let on: Vec<&str> = features.iter().filter(|(_, on)| *on).map(|(name, _)| *name).collect();
    let inferred = if cfg!(target_feature = "avx2") { "native" } else { "baseline" };
    let label = std::env::var("KINEMATICS_BENCH_BUILD").unwrap_or_else(|_| inferred.to_owned());
    let on = if on.is_empty() { "sse2 only".to_owned() } else { on.join(",") };
    format!("build\t{label}\nfeatures\t{on}\n")
}

/// The `sin_cos` pairs of a robot's tip pose and of all its link poses, as the compiler counts them.
fn sin_cos(file: &str, tip: &str) -> (usize, usize) {
    use kinematics_compiler::{Request, compile};
    let path = format!("{}/robots/{file}", env!("CARGO_MANIFEST_DIR"));
    let tree = kinematics::load(path).expect("robot loads");
    let count = |request: &Request| compile(&tree, request).map_or(0, |c| c.op_count().sin_cos);
    (count(&Request::tip(tip)), count(&Request::all_links()))
}

fn all(c: Option<&mut Criterion>) {
    let mut c = c;
    macro_rules! each {
        ($(($name:literal, $ty:ty, $std:ty, $n:literal, $file:literal, $tip:literal $(, $galaw:ident)?)),* $(,)?) => {
            if c.is_some() {
                // The robot list, for `bench-report` to find the results by.
                let manifest: String = [$(concat!($name, "\t", $file, "\t", $tip, "\n")),*].concat();
                let dir = std::env::var("CARGO_TARGET_DIR")
                    .map(std::path::PathBuf::from)
                    .unwrap_or_else(|_| std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target"))
                    .join("criterion");
                let written = std::fs::create_dir_all(&dir)
                    .and_then(|()| std::fs::write(dir.join("kinematics-robots.tsv"), manifest))
                    .and_then(|()| std::fs::write(dir.join("kinematics-build.tsv"), build_record()));
                if let Err(e) = written {
                    eprintln!("cannot write the robot list for bench-report: {e}");
                }
            }
            $({
                let n = sin_cos($file, $tip);
                match c.as_deref_mut() {
                    Some(c) => {
                        let mut group = c.benchmark_group($name);
                        robot!(&mut Mode::Measure(&mut group, $name), $ty, $std, $n, $file, $tip, n $(, $galaw)?);
                        group.finish();
                    }
                    None => robot!(&mut Mode::Check, $ty, $std, $n, $file, $tip, n $(, $galaw)?),
                }
            })*
        };
    }
    each!(
        ("puma560", Puma560, Puma560Std, 6, "puma560.toml", "link6"),
        ("stanford", Stanford, StanfordStd, 6, "stanford_arm.toml", "link6"),
        ("scara", Scara, ScaraStd, 4, "scara.toml", "link4"),
        ("ur5", Ur5, Ur5Std, 6, "ur5.urdf", "tool0", ur5),
        ("ur10e", Ur10e, Ur10eStd, 6, "ur10e.urdf", "tool0", ur10e),
        ("iiwa14", Iiwa14, Iiwa14Std, 7, "iiwa14.urdf", "iiwa_link_ee", iiwa14),
        ("panda", Panda, PandaStd, 8, "panda.urdf", "panda_hand", panda),
        ("gen3", Gen3, Gen3Std, 7, "gen3.urdf", "end_effector_link", gen3),
        ("irb120", Irb120, Irb120Std, 6, "irb120.urdf", "tool0", irb120),
        ("dual_arm", DualArm, DualArmStd, 17, "dual_arm_torso.urdf", "tool_l", dual_arm_torso),
        ("quadruped", Quadruped, QuadrupedStd, 12, "quadruped.urdf", "RL_foot", quadruped),
        ("humanoid", Humanoid, HumanoidStd, 25, "humanoid.urdf", "r_gripper", humanoid),
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
    if std::env::args().any(|a| a == "--bench") {
        let mut c = Criterion::default()
            .warm_up_time(Duration::from_millis(200))
            .measurement_time(Duration::from_millis(800))
            .sample_size(30)
            .configure_from_args();
        all(Some(&mut c));
        c.final_summary();
        let paired = PAIRED.lock().map(|p| p.concat()).unwrap_or_default();
        let dir = std::env::var("CARGO_TARGET_DIR")
            .map(std::path::PathBuf::from)
            .unwrap_or_else(|_| std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target"))
            .join("criterion");
        // A filtered run replaces the pairs it timed and keeps the last run's others.
        let path = dir.join("kinematics-paired.tsv");
        let id = |line: &str| line.rsplit_once('\t').map(|(id, _)| id.to_owned());
        let timed: std::collections::BTreeSet<String> = paired.lines().filter_map(id).collect();
        let kept: String = match FILTER.as_deref() {
            Some(_) => std::fs::read_to_string(&path)
                .unwrap_or_default()
                .lines()
                .filter(|l| id(l).is_none_or(|id| !timed.contains(&id)))
                .map(|l| format!("{l}\n"))
                .collect(),
            None => String::new(),
        };
        if let Err(e) = std::fs::write(&path, kept + &paired) {
            eprintln!("cannot write the paired ratios for bench-report: {e}");
        }
    } else {
        all(None);
        println!("fk benchmarks: every body ran once and agreed with the runtime reference");
    }
}
