//! Dispatched and baseline bodies give the same results, bit for bit.
//!
//! Every typed function of a derive (`tip_pose`, `link_poses`, Jacobians, twists, f32, batches)
//! runs the body compiled for the widest instruction set the CPU has (`kinematics::dispatch`);
//! `*_generic` runs the same body with the build's own (baseline x86-64 in `cargo test`). Rust
//! never fuses a multiply and an add on its own, so the two must agree to the last bit: this file
//! holds them to it on random configurations, and, through pulp directly, the AVX2 (x86-64-v3) and
//! AVX-512 (x86-64-v4) bodies where the CPU has them, whichever one dispatch picks here.
//!
//! Bits are compared through `Debug`, which prints every finite `f64`/`f32` by its shortest
//! round-trip form (so equal text is equal bits, `-0.0` included); a NaN anywhere fails.

#![cfg(target_arch = "x86_64")]
#![allow(clippy::expect_used, clippy::panic)]

use std::fmt::Debug;

use kinematics::{Kinematics, Pose};

#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5.urdf", tip = "tool0", positions, jacobians, scalars(f64, f32))]
struct Ur5;

#[derive(Kinematics)]
#[kinematics(urdf = "robots/panda.urdf", tip = "panda_hand", positions, jacobians, scalars(f64, f32))]
struct Panda;

#[derive(Kinematics)]
#[kinematics(urdf = "robots/humanoid.urdf", tips("l_wrist", "r_gripper"), scalars(f64, f32))]
struct Humanoid;

#[derive(Kinematics)]
#[kinematics(dh = "robots/planar_2r.toml", tip = "link2", jacobians, scalars(f64, f32))]
struct Planar2r;

/// Configurations in [-4, 4] per joint (beyond the limits on purpose: the bodies do not care),
/// from a fixed-seed xorshift, a few of them exactly zero.
fn configurations<const N: usize>(count: usize) -> Vec<[f64; N]> {
    let mut state = 0x2545_F491_4F6C_DD1Du64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..count).map(|i| if i % 50 == 0 { [0.0; N] } else { std::array::from_fn(|_| 8.0 * next() - 4.0) }).collect()
}

/// `a` and `b` are the same bits (see the module doc), and neither holds a NaN.
fn same<T: Debug>(a: &T, b: &T, what: &str, i: usize) {
    let (a, b) = (format!("{a:?}"), format!("{b:?}"));
    assert!(!a.contains("NaN") && !b.contains("NaN"), "{what}, configuration {i}: NaN\n{a}\n{b}");
    assert_eq!(a, b, "{what}, configuration {i}: dispatched and baseline bodies differ");
}

/// Runs `f` under each instruction set pulp finds on this CPU (and the baseline), for `same`.
/// `f` must be an `#[inline(always)]` closure, as the generated code passes its bodies: only then
/// is the body compiled inside pulp's `#[target_feature]` function rather than called from it.
fn each_level<R>(f: impl Fn() -> R + Copy) -> Vec<(&'static str, R)> {
    let mut out = vec![("baseline", f())];
    if let Some(v3) = pulp::x86::V3::try_new() {
        out.push(("x86-64-v3", v3.vectorize(f)));
    }
    if let Some(v4) = pulp::x86::V4::try_new() {
        out.push(("x86-64-v4", v4.vectorize(f)));
    }
    out
}

/// One robot's typed functions against its generic bodies: poses, positions, all links,
/// Jacobians and twists (where derived), f32, and the batches (row- and column-wise, with a tail).
macro_rules! check_robot {
    ($ty:ty, $n:literal, { $($extra:tt)* }) => {{
        let qs = configurations::<$n>(203);
        for (i, q) in qs.iter().enumerate() {
            same(&<$ty>::link_poses(q), &<$ty>::link_poses_generic::<f64>(q), "link_poses", i);
            let q32 = q.map(|x| x as f32);
            same(&<$ty>::link_poses_f32(&q32), &<$ty>::link_poses_generic::<f32>(&q32), "link_poses_f32", i);
            for (level, poses) in each_level(#[inline(always)] || <$ty>::link_poses_generic::<f64>(q)) {
                same(&poses, &<$ty>::link_poses_generic::<f64>(q), level, i);
            }
            $( check_robot!(@extra $ty, q, i, $extra); )*
        }
        // Batches: every configuration, and a length no lane count divides (the tail).
        for len in [qs.len(), qs.len() - 3] {
            let qs = &qs[..len];
            let mut rows = vec![<$ty>::link_poses(&qs[0]); len];
            <$ty>::link_poses_batch(qs, &mut rows).expect("one output per configuration");
            let columns: Vec<Vec<f64>> = (0..$n).map(|j| qs.iter().map(|q| q[j]).collect()).collect();
            let columns: [&[f64]; $n] = std::array::from_fn(|j| columns[j].as_slice());
            let mut by_columns = rows.clone();
            <$ty>::link_poses_batch_columns(columns, &mut by_columns).expect("one output per configuration");
            for (i, q) in qs.iter().enumerate() {
                same(&rows[i], &<$ty>::link_poses_generic::<f64>(q), "link_poses_batch", i);
                same(&by_columns[i], &rows[i], "link_poses_batch_columns", i);
            }
            let qs32: Vec<[f32; $n]> = qs.iter().map(|q| q.map(|x| x as f32)).collect();
            let mut rows32 = vec![<$ty>::link_poses_f32(&qs32[0]); len];
            <$ty>::link_poses_batch_f32(&qs32, &mut rows32).expect("one output per configuration");
            for (i, q) in qs32.iter().enumerate() {
                same(&rows32[i], &<$ty>::link_poses_generic::<f32>(q), "link_poses_batch_f32", i);
            }
        }
    }};
    (@extra $ty:ty, $q:ident, $i:ident, tip) => {
        same(&<$ty>::tip_pose($q), &<$ty>::tip_pose_generic::<f64>($q), "tip_pose", $i);
    };
    (@extra $ty:ty, $q:ident, $i:ident, tips) => {
        same(&<$ty>::tip_poses($q), &<$ty>::tip_poses_generic::<f64>($q), "tip_poses", $i);
    };
    (@extra $ty:ty, $q:ident, $i:ident, positions) => {
        same(&<$ty>::tip_position($q), &<$ty>::tip_position_generic::<f64>($q), "tip_position", $i);
    };
    (@extra $ty:ty, $q:ident, $i:ident, jacobians) => {
        same(&<$ty>::tip_jacobian($q), &<$ty>::tip_jacobian_generic::<f64>($q), "tip_jacobian", $i);
        same(&<$ty>::tip_jacobian_local($q), &<$ty>::tip_jacobian_local_generic::<f64>($q), "tip_jacobian_local", $i);
        same(
            &<$ty>::tip_pose_and_jacobian($q),
            &<$ty>::tip_pose_and_jacobian_generic::<f64>($q),
            "tip_pose_and_jacobian",
            $i,
        );
        let qd = $q.map(|x| 0.5 - x);
        same(&<$ty>::tip_twist($q, &qd), &<$ty>::tip_twist_generic::<f64>($q, &qd), "tip_twist", $i);
    };
}

#[test]
fn ur5_dispatched_bodies_equal_baseline() {
    check_robot!(Ur5, 6, { tip positions jacobians });
}

#[test]
fn panda_dispatched_bodies_equal_baseline() {
    check_robot!(Panda, 8, { tip positions jacobians });
}

#[test]
fn humanoid_dispatched_bodies_equal_baseline() {
    check_robot!(Humanoid, 25, { tips });
}

#[test]
fn planar_2r_dispatched_bodies_equal_baseline() {
    check_robot!(Planar2r, 2, { tip jacobians });
}

/// The column-wise batch names the joint whose column is short, and writes nothing.
#[test]
fn short_column_is_an_error_naming_the_joint() {
    let qs = configurations::<6>(9);
    let columns: Vec<Vec<f64>> = (0..6).map(|j| qs.iter().map(|q| q[j]).collect()).collect();
    let mut columns: [&[f64]; 6] = std::array::from_fn(|j| columns[j].as_slice());
    columns[2] = &columns[2][..8];
    let untouched = Pose { rotation: [[7.0; 3]; 3], translation: [7.0; 3] };
    let mut out = vec![untouched; 9];
    let error = Ur5::tip_pose_batch_columns(columns, &mut out).expect_err("a short column");
    let message = error.to_string();
    assert!(message.contains(Ur5::JOINT_NAMES[2]) && message.contains("holds 8 values"), "{message}");
    assert!(out.iter().all(|p| *p == untouched), "nothing is written");
}

/// The level dispatch reports is one pulp finds here.
#[test]
fn dispatched_level_is_what_the_cpu_has() {
    let level = kinematics::dispatched_level();
    let expected = if pulp::x86::V4::try_new().is_some() {
        "x86-64-v4 (AVX-512)"
    } else if pulp::x86::V3::try_new().is_some() {
        "x86-64-v3 (AVX2, FMA)"
    } else {
        "baseline"
    };
    assert_eq!(level, expected);
}
