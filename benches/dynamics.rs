//! Compiled dynamics (issue 61), per call, on the Panda (`robots/panda.urdf`, franka_ros's
//! identified inertias; 8 velocities: the 7 arm joints and `panda_finger_joint1`, whose mimic
//! `panda_finger_joint2` folds into it), the UR5 (`robots/ur5.urdf`, 6 velocities) and the
//! humanoid (`robots/humanoid.urdf`, the NAO with its published inertias, its torso free-flying
//! as in Pinocchio's humanoid benchmarks: 32 entries of `q`, the base's position and quaternion
//! then 25 joints, and 31 velocities, the base's six then the joints'; its 17 mimic joints, the
//! right hip's and the fingers', fold into their sources), gravity along -z at 9.81 m/s^2:
//!
//! - the five functions, each a group `dynamics/{robot}/{function}`: `gravity`
//!   (`gravity_torques`), `rnea` (`inverse_dynamics`), `nonlinear_effects`, `crba`
//!   (`mass_matrix`) and `forward_dynamics`;
//! - in each group: `generated` (the `f64` function, dispatched at run time as every typed
//!   function is), `generated_f32`, `f64x4` and `f64x8` (the `_generic` body on four and eight
//!   configurations at a time, the loop over all 256 states dispatched once and timed whole; they
//!   report their throughput, configurations per second, whose inverse is the time per
//!   configuration), `reference` (`kinematics::runtime::ReferenceDynamics`, Featherstone's
//!   algorithms on nalgebra with heap vectors) and `featherstone` (the `featherstone` crate, 0.1.0).
//!   The humanoid has `generated` and `reference` only: no `generated_f32` (it is derived for
//!   `f64` alone), no `featherstone` (that crate has no mimic joints, and the NAO has 17: its
//!   fingers follow their hand, its right hip its left, so a model of it there would be another
//!   robot), and no lanes: with its `_generic` bodies in `F64x4` and `F64x8` inlined into
//!   `dispatch`, this benchmark's optimised build took 16 min 47 s against 32 s without the
//!   humanoid (2026-12-06), past the ten minutes a benchmark run may take here.
//!
//! The states: 256 configurations drawn uniformly within the joint limits, joint rates and
//! accelerations uniform in [-2, 2] (rad/s, rad/s^2; m/s and m/s^2 for the finger and the
//! humanoid's base), and for forward dynamics the torques `inverse_dynamics` gives for them, so
//! `forward_dynamics` returns accelerations of that size. The humanoid's base position and
//! quaternion entries are drawn in [-pi, pi] as the limits of a floating joint give them, the
//! quaternion then scaled to unit length. The timed loops cycle through them.
//!
//! **featherstone 0.1.0.** `f32` only (its state and spatial algebra are `f32`), so its figures
//! sit beside `generated_f32` as much as `generated`. It has ABA, RNEA and CRBA (no mimic joints,
//! no generic scalar, no lanes): all five functions are timed. Its URDF reader
//! (`urdf_convert::articulated_body_from_urdf`, left off here) builds a different robot from the
//! same file: it takes a joint origin's rotation `R` and offset `p` as the Plücker transform's
//! rotation and translation, where its own `SpatialTransform::apply_motion` needs `R^T` and
//! `R^T p`, so every joint whose origin turns (both arms have them) is placed wrong (checked once,
//! outside this benchmark: the UR5's gravity torques at q = (0.3, -0.7, 1.1, -0.4, 0.9, 0.2) came
//! out 34.5 and 1.2 N m at the shoulder and elbow, where ours and the reference's are -47.7 and
//! -14.4, with its `q` negated or not). The models are therefore built here by hand from the URDF
//! numbers ([`UR5`], [`PANDA`]), in its convention; fixed joints are lumped into their parent body
//! as our compiler lumps them (the fixed root's own mass is left out: it never moves). Its
//! revolute joint also turns the child by the active rotation `R(axis, q)` where its motion
//! subspace (`+axis`) needs `R(axis, -q)`: its `q` for a revolute joint is minus ours, and the
//! states are given to it so. With no mimic joints, its Panda has 9 velocities (both fingers, as
//! Pinocchio's figures below count them): the finger's entries of our states are given to both,
//! and its results are checked against the reference on the Panda with the `<mimic>` removed
//! (the forward dynamics of the two robots differ: one finger or two independent ones).
//! `gravity_compensation` and `bias_forces_rnea` clone the whole body before running RNEA; here
//! its RNEA runs on a body whose rates (and accelerations) are zero instead, the cheapest way
//! through its API to the same numbers. Every call still allocates (its per-body vectors, the
//! result, and ABA's `DMatrix` per joint).
//!
//! Setup checks every state before anything is timed (measuring or not): the generated `f64`
//! functions against the reference (relative 1e-12, forward dynamics 1e-9), `f32` where derived
//! against it (1e-4; forward dynamics 1e-3), every lane of `F64x4` and `F64x8` equal to the `f64`
//! function bit for bit, and featherstone where there is a model against the reference (relative
//! 1e-4, forward dynamics 1e-3: its `f32`). A model built wrong cannot be timed.
//!
//! Measuring also prints each generated function's operation count (its doc's "Cost:" line, from
//! `kinematics_compiler::dynamics::compile_dynamics`).
//!
//! For scale (issue 61): Pinocchio 4.1 (C++, -O3, a 2-core AMD EPYC as ours), ns per call, Panda
//! with both fingers (9 joints): RNEA 1,227, gravity 689, nonlinear effects 1,147, CRBA 630, ABA
//! 2,578; UR5: RNEA 828, gravity 485, CRBA 419, ABA 1,746.
//!
//! `cargo bench --bench dynamics` measures (filter by group: `-- dynamics/panda/rnea`, a robot:
//! `-- humanoid`, or a variant: `-- featherstone`); under `cargo test` every check above runs, and
//! nothing is timed.
#![allow(missing_docs, clippy::unwrap_used, clippy::expect_used, clippy::panic)]

#[allow(dead_code)] // the helpers the fk and ik benchmarks use and this one does not
mod common;

use std::hint::black_box;
use std::time::Duration;

use criterion::measurement::WallTime;
use criterion::{BenchmarkGroup, Criterion, Throughput};
use featherstone::prelude::{
    ArticulatedBody, GenJoint, SpatialInertia, SpatialTransform, aba_forward_dynamics, crba_mass_matrix,
    rnea_inverse_dynamics,
};
use kinematics::runtime::ReferenceDynamics;
use kinematics::{Configurations, F64x4, F64x8, JointLimits, Kinematics, Lanes, Real, dispatch};
use kinematics_compiler::dynamics::{DynamicsFunction, DynamicsRequest, compile_dynamics};
use nalgebra_featherstone::{Matrix3, Vector3};

#[derive(Kinematics)]
#[kinematics(urdf = "robots/panda.urdf", dynamics, scalars(f64, f32))]
struct Panda;

#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5.urdf", dynamics, scalars(f64, f32))]
struct Ur5;

#[derive(Kinematics)]
#[kinematics(urdf = "robots/humanoid.urdf", floating_base, dynamics)]
struct Humanoid;

/// Gravity (m/s^2, root frame): the derive's default.
const GRAVITY: [f64; 3] = [0.0, 0.0, -9.81];

/// States cycled through (a multiple of 8: whole packs of lanes).
const STATES: usize = 256;

/// A robot's generated dynamics, so that one generic function times every robot and the
/// `_generic` bodies inline into `dispatch`: `N` entries of `q`, `V` velocities (equal but for a
/// floating base, whose quaternion is four entries for three velocities).
trait Compiled<const N: usize, const V: usize> {
    const NAME: &'static str;
    const LIMITS: [JointLimits; N];
    /// Whether the derive wrote the `_f32` functions (`scalars(f64, f32)`): the `*_f32` methods
    /// are called only then.
    const F32: bool = false;
    fn gravity(q: &[f64; N]) -> [f64; V];
    fn rnea(q: &[f64; N], qd: &[f64; V], qdd: &[f64; V]) -> [f64; V];
    fn nonlinear(q: &[f64; N], qd: &[f64; V]) -> [f64; V];
    fn crba(q: &[f64; N]) -> [[f64; V]; V];
    fn aba(q: &[f64; N], qd: &[f64; V], tau: &[f64; V]) -> [f64; V];
    fn gravity_f32(_: &[f32; N]) -> [f32; V] {
        unreachable!("{} has no f32 functions", Self::NAME)
    }
    fn rnea_f32(_: &[f32; N], _: &[f32; V], _: &[f32; V]) -> [f32; V] {
        unreachable!("{} has no f32 functions", Self::NAME)
    }
    fn nonlinear_f32(_: &[f32; N], _: &[f32; V]) -> [f32; V] {
        unreachable!("{} has no f32 functions", Self::NAME)
    }
    fn crba_f32(_: &[f32; N]) -> [[f32; V]; V] {
        unreachable!("{} has no f32 functions", Self::NAME)
    }
    fn aba_f32(_: &[f32; N], _: &[f32; V], _: &[f32; V]) -> [f32; V] {
        unreachable!("{} has no f32 functions", Self::NAME)
    }
    /// Whether the `_generic` bodies are timed in lanes: the `*_generic` methods are called only
    /// then (a robot without them never builds its bodies in lanes here).
    const LANES: bool = false;
    fn gravity_generic<T: Real>(_: &[T; N]) -> [T; V] {
        unreachable!("{} is not timed in lanes", Self::NAME)
    }
    fn rnea_generic<T: Real>(_: &[T; N], _: &[T; V], _: &[T; V]) -> [T; V] {
        unreachable!("{} is not timed in lanes", Self::NAME)
    }
    fn nonlinear_generic<T: Real>(_: &[T; N], _: &[T; V]) -> [T; V] {
        unreachable!("{} is not timed in lanes", Self::NAME)
    }
    fn crba_generic<T: Real>(_: &[T; N]) -> [[T; V]; V] {
        unreachable!("{} is not timed in lanes", Self::NAME)
    }
    /// The accelerations and the pivots of the mass matrix's factorisation.
    fn aba_generic<T: Real>(_: &[T; N], _: &[T; V], _: &[T; V]) -> ([T; V], [T; V]) {
        unreachable!("{} is not timed in lanes", Self::NAME)
    }
}

/// `impl Compiled<N, V>` for a derived robot; with `f32`, its `_f32` functions and its lanes too.
macro_rules! compiled {
    ($robot:ident, $name:literal, $n:literal, $v:literal, f32) => {
        compiled!($robot, $name, $n, $v, {
            const F32: bool = true;
            #[inline(always)]
            fn gravity_f32(q: &[f32; $n]) -> [f32; $v] {
                $robot::gravity_torques_f32(q)
            }
            #[inline(always)]
            fn rnea_f32(q: &[f32; $n], qd: &[f32; $v], qdd: &[f32; $v]) -> [f32; $v] {
                $robot::inverse_dynamics_f32(q, qd, qdd)
            }
            #[inline(always)]
            fn nonlinear_f32(q: &[f32; $n], qd: &[f32; $v]) -> [f32; $v] {
                $robot::nonlinear_effects_f32(q, qd)
            }
            #[inline(always)]
            fn crba_f32(q: &[f32; $n]) -> [[f32; $v]; $v] {
                $robot::mass_matrix_f32(q)
            }
            #[inline(always)]
            fn aba_f32(q: &[f32; $n], qd: &[f32; $v], tau: &[f32; $v]) -> [f32; $v] {
                $robot::forward_dynamics_f32(q, qd, tau).unwrap()
            }
            const LANES: bool = true;
            #[inline(always)]
            fn gravity_generic<T: Real>(q: &[T; $n]) -> [T; $v] {
                $robot::gravity_torques_generic(q)
            }
            #[inline(always)]
            fn rnea_generic<T: Real>(q: &[T; $n], qd: &[T; $v], qdd: &[T; $v]) -> [T; $v] {
                $robot::inverse_dynamics_generic(q, qd, qdd)
            }
            #[inline(always)]
            fn nonlinear_generic<T: Real>(q: &[T; $n], qd: &[T; $v]) -> [T; $v] {
                $robot::nonlinear_effects_generic(q, qd)
            }
            #[inline(always)]
            fn crba_generic<T: Real>(q: &[T; $n]) -> [[T; $v]; $v] {
                $robot::mass_matrix_generic(q)
            }
            #[inline(always)]
            fn aba_generic<T: Real>(q: &[T; $n], qd: &[T; $v], tau: &[T; $v]) -> ([T; $v], [T; $v]) {
                $robot::forward_dynamics_generic(q, qd, tau)
            }
        });
    };
    ($robot:ident, $name:literal, $n:literal, $v:literal) => {
        compiled!($robot, $name, $n, $v, {});
    };
    ($robot:ident, $name:literal, $n:literal, $v:literal, { $($f32:tt)* }) => {
        impl Compiled<$n, $v> for $robot {
            const NAME: &'static str = $name;
            const LIMITS: [JointLimits; $n] = $robot::JOINT_LIMITS;
            #[inline(always)]
            fn gravity(q: &[f64; $n]) -> [f64; $v] {
                $robot::gravity_torques(q)
            }
            #[inline(always)]
            fn rnea(q: &[f64; $n], qd: &[f64; $v], qdd: &[f64; $v]) -> [f64; $v] {
                $robot::inverse_dynamics(q, qd, qdd)
            }
            #[inline(always)]
            fn nonlinear(q: &[f64; $n], qd: &[f64; $v]) -> [f64; $v] {
                $robot::nonlinear_effects(q, qd)
            }
            #[inline(always)]
            fn crba(q: &[f64; $n]) -> [[f64; $v]; $v] {
                $robot::mass_matrix(q)
            }
            #[inline(always)]
            fn aba(q: &[f64; $n], qd: &[f64; $v], tau: &[f64; $v]) -> [f64; $v] {
                $robot::forward_dynamics(q, qd, tau).unwrap()
            }
            $($f32)*
        }
    };
}

compiled!(Panda, "panda", 8, 8, f32);
compiled!(Ur5, "ur5", 6, 6, f32);
compiled!(Humanoid, "humanoid", 32, 31);

/// A joint of the hand-built featherstone models (axes in the child link's frame, as URDF's).
#[derive(Clone, Copy)]
enum Joint {
    Fixed,
    Revolute([f64; 3]),
    Prismatic([f64; 3]),
}

/// One link of a hand-built model and the joint to it, copied from the URDF: the link's name, its
/// parent's (none for the fixed root), the joint, the joint origin's `xyz` and `rpy`, and the
/// link's inertial: mass, centre of mass and the tensor about it (`ixx ixy ixz iyy iyz izz`; every
/// inertial origin of both files has `rpy="0 0 0"`). Massless links have none.
struct Part {
    name: &'static str,
    parent: Option<&'static str>,
    joint: Joint,
    xyz: [f64; 3],
    rpy: [f64; 3],
    inertial: Option<(f64, [f64; 3], [f64; 6])>,
}

const QUARTER: f64 = std::f64::consts::FRAC_PI_2;
const EIGHTH: f64 = std::f64::consts::FRAC_PI_4;

/// `robots/ur5.urdf` from `base_link` (the fixed root; its child `base` by a fixed joint, a half
/// turn, and `ee_link` and `tool0` after `wrist_3_link` are massless, and left out).
const UR5: &[Part] = &[
    Part { name: "base_link", parent: None, joint: Joint::Fixed, xyz: [0.0; 3], rpy: [0.0; 3], inertial: None },
    Part {
        name: "shoulder_link",
        parent: Some("base_link"),
        joint: Joint::Revolute([0.0, 0.0, 1.0]),
        xyz: [0.0, 0.0, 0.089159],
        rpy: [0.0; 3],
        inertial: Some((3.7, [0.0; 3], [0.010267495893, 0.0, 0.0, 0.010267495893, 0.0, 0.00666])),
    },
    Part {
        name: "upper_arm_link",
        parent: Some("shoulder_link"),
        joint: Joint::Revolute([0.0, 1.0, 0.0]),
        xyz: [0.0, 0.13585, 0.0],
        rpy: [0.0, QUARTER, 0.0],
        inertial: Some((8.393, [0.0, 0.0, 0.28], [0.22689067591, 0.0, 0.0, 0.22689067591, 0.0, 0.0151074])),
    },
    Part {
        name: "forearm_link",
        parent: Some("upper_arm_link"),
        joint: Joint::Revolute([0.0, 1.0, 0.0]),
        xyz: [0.0, -0.1197, 0.425],
        rpy: [0.0; 3],
        inertial: Some((2.275, [0.0, 0.0, 0.25], [0.049443313556, 0.0, 0.0, 0.049443313556, 0.0, 0.004095])),
    },
    Part {
        name: "wrist_1_link",
        parent: Some("forearm_link"),
        joint: Joint::Revolute([0.0, 1.0, 0.0]),
        xyz: [0.0, 0.0, 0.39225],
        rpy: [0.0, QUARTER, 0.0],
        inertial: Some((1.219, [0.0; 3], [0.111172755531, 0.0, 0.0, 0.111172755531, 0.0, 0.21942])),
    },
    Part {
        name: "wrist_2_link",
        parent: Some("wrist_1_link"),
        joint: Joint::Revolute([0.0, 0.0, 1.0]),
        xyz: [0.0, 0.093, 0.0],
        rpy: [0.0; 3],
        inertial: Some((1.219, [0.0; 3], [0.111172755531, 0.0, 0.0, 0.111172755531, 0.0, 0.21942])),
    },
    Part {
        name: "wrist_3_link",
        parent: Some("wrist_2_link"),
        joint: Joint::Revolute([0.0, 1.0, 0.0]),
        xyz: [0.0, 0.0, 0.09465],
        rpy: [0.0; 3],
        inertial: Some((0.1879, [0.0; 3], [0.0171364731454, 0.0, 0.0, 0.0171364731454, 0.0, 0.033822])),
    },
];

/// `robots/panda.urdf` from `panda_link0` (the fixed root, at `world` by an identity fixed
/// joint; `panda_hand_tcp` is massless and left out). `panda_link8` and `panda_hand` lump into
/// `panda_link7`'s body; `panda_finger_joint2`, a mimic in the file, is a joint of its own here.
const PANDA: &[Part] = &[
    Part { name: "panda_link0", parent: None, joint: Joint::Fixed, xyz: [0.0; 3], rpy: [0.0; 3], inertial: None },
    Part {
        name: "panda_link1",
        parent: Some("panda_link0"),
        joint: Joint::Revolute([0.0, 0.0, 1.0]),
        xyz: [0.0, 0.0, 0.333],
        rpy: [0.0; 3],
        inertial: Some((
            4.970684,
            [0.003875, 0.002081, -0.04762],
            [0.70337, -0.000139, 0.006772, 0.70661, 0.019169, 0.009117],
        )),
    },
    Part {
        name: "panda_link2",
        parent: Some("panda_link1"),
        joint: Joint::Revolute([0.0, 0.0, 1.0]),
        xyz: [0.0; 3],
        rpy: [-QUARTER, 0.0, 0.0],
        inertial: Some((
            0.646926,
            [-0.003141, -0.02872, 0.003495],
            [0.007962, -0.003925, 0.010254, 0.02811, 0.000704, 0.025995],
        )),
    },
    Part {
        name: "panda_link3",
        parent: Some("panda_link2"),
        joint: Joint::Revolute([0.0, 0.0, 1.0]),
        xyz: [0.0, -0.316, 0.0],
        rpy: [QUARTER, 0.0, 0.0],
        inertial: Some((
            3.228604,
            [0.027518, 0.039252, -0.066502],
            [0.037242, -0.004761, -0.011396, 0.036155, -0.012805, 0.01083],
        )),
    },
    Part {
        name: "panda_link4",
        parent: Some("panda_link3"),
        joint: Joint::Revolute([0.0, 0.0, 1.0]),
        xyz: [0.0825, 0.0, 0.0],
        rpy: [QUARTER, 0.0, 0.0],
        inertial: Some((
            3.587895,
            [-0.05317, 0.104419, 0.027454],
            [0.025853, 0.007796, -0.001332, 0.019552, 0.008641, 0.028323],
        )),
    },
    Part {
        name: "panda_link5",
        parent: Some("panda_link4"),
        joint: Joint::Revolute([0.0, 0.0, 1.0]),
        xyz: [-0.0825, 0.384, 0.0],
        rpy: [-QUARTER, 0.0, 0.0],
        inertial: Some((
            1.225946,
            [-0.011953, 0.041065, -0.038437],
            [0.035549, -0.002117, -0.004037, 0.029474, 0.000229, 0.008627],
        )),
    },
    Part {
        name: "panda_link6",
        parent: Some("panda_link5"),
        joint: Joint::Revolute([0.0, 0.0, 1.0]),
        xyz: [0.0; 3],
        rpy: [QUARTER, 0.0, 0.0],
        inertial: Some((
            1.666555,
            [0.060149, -0.014117, -0.010517],
            [0.001964, 0.000109, -0.001158, 0.004354, 0.000341, 0.005433],
        )),
    },
    Part {
        name: "panda_link7",
        parent: Some("panda_link6"),
        joint: Joint::Revolute([0.0, 0.0, 1.0]),
        xyz: [0.088, 0.0, 0.0],
        rpy: [QUARTER, 0.0, 0.0],
        inertial: Some((
            0.735522,
            [0.010517, -0.004252, 0.061597],
            [0.012516, -0.000428, -0.001196, 0.010027, -0.000741, 0.004815],
        )),
    },
    Part {
        name: "panda_link8",
        parent: Some("panda_link7"),
        joint: Joint::Fixed,
        xyz: [0.0, 0.0, 0.107],
        rpy: [0.0; 3],
        inertial: None,
    },
    Part {
        name: "panda_hand",
        parent: Some("panda_link8"),
        joint: Joint::Fixed,
        xyz: [0.0; 3],
        rpy: [0.0, 0.0, -EIGHTH],
        inertial: Some((0.73, [-0.01, 0.0, 0.03], [0.001, 0.0, 0.0, 0.0025, 0.0, 0.0017])),
    },
    Part {
        name: "panda_leftfinger",
        parent: Some("panda_hand"),
        joint: Joint::Prismatic([0.0, 1.0, 0.0]),
        xyz: [0.0, 0.0, 0.0584],
        rpy: [0.0; 3],
        inertial: Some((0.015, [0.0; 3], [2.375e-06, 0.0, 0.0, 2.375e-06, 0.0, 7.5e-07])),
    },
    Part {
        name: "panda_rightfinger",
        parent: Some("panda_hand"),
        joint: Joint::Prismatic([0.0, -1.0, 0.0]),
        xyz: [0.0, 0.0, 0.0584],
        rpy: [0.0; 3],
        inertial: Some((0.015, [0.0; 3], [2.375e-06, 0.0, 0.0, 2.375e-06, 0.0, 7.5e-07])),
    },
];

fn vector(x: [f64; 3]) -> Vector3<f32> {
    Vector3::new(x[0] as f32, x[1] as f32, x[2] as f32)
}

/// URDF's fixed-axis roll, pitch, yaw: `Rz(yaw) Ry(pitch) Rx(roll)`.
fn rpy_matrix([r, p, y]: [f64; 3]) -> [[f64; 3]; 3] {
    let (sr, cr) = r.sin_cos();
    let (sp, cp) = p.sin_cos();
    let (sy, cy) = y.sin_cos();
    [
        [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
        [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
        [-sp, cp * sr, cp * cr],
    ]
}

/// featherstone's transform from a parent's coordinates into those of a frame at `xyz` turned by
/// `rpy` (URDF's origin): rotation `E = R^T`, translation `E p` (what its `apply_motion` reads).
fn origin(xyz: [f64; 3], rpy: [f64; 3]) -> SpatialTransform {
    let r = rpy_matrix(rpy);
    let e = Matrix3::from_fn(|i, j| r[j][i]);
    let t: [f64; 3] = std::array::from_fn(|i| (0..3).map(|k| r[k][i] * xyz[k]).sum());
    SpatialTransform::from_rotation_translation(e.map(|x| x as f32), vector(t))
}

fn spatial_inertia(inertial: Option<(f64, [f64; 3], [f64; 6])>) -> SpatialInertia {
    let Some((mass, com, [xx, xy, xz, yy, yz, zz])) = inertial else { return SpatialInertia::zero() };
    let tensor = Matrix3::new(xx, xy, xz, xy, yy, yz, xz, yz, zz).map(|x| x as f32);
    SpatialInertia::from_mass_inertia(mass as f32, vector(com), tensor)
}

/// The featherstone model of `parts` (fixed joints lumped into their parent's body), and whether
/// each velocity's joint is revolute (its `q` is minus ours; see the module doc).
fn featherstone_model(parts: &[Part]) -> (ArticulatedBody, Vec<bool>) {
    let mut body = ArticulatedBody::new();
    body.set_gravity(vector(GRAVITY));
    let mut revolute = Vec::new();
    // Each link placed: its body (none: the root's) and the transform from that body's frame.
    let mut placed: Vec<(&str, Option<usize>, SpatialTransform)> = Vec::new();
    for part in parts {
        let Some(parent) = part.parent else {
            placed.push((part.name, None, SpatialTransform::identity()));
            continue;
        };
        let (_, parent_body, in_parent) = placed.iter().find(|p| p.0 == parent).expect("parents come first");
        let (parent_body, x) = (*parent_body, origin(part.xyz, part.rpy).compose(in_parent));
        let joint = match part.joint {
            Joint::Fixed => {
                if let Some(b) = parent_body {
                    let lumped = x.inverse().apply_inertia(&spatial_inertia(part.inertial));
                    body.bodies[b].inertia = body.bodies[b].inertia.add(&lumped);
                }
                placed.push((part.name, parent_body, x));
                continue;
            }
            Joint::Revolute(axis) => GenJoint::Revolute { axis: vector(axis) },
            Joint::Prismatic(axis) => GenJoint::Prismatic { axis: vector(axis) },
        };
        revolute.push(matches!(part.joint, Joint::Revolute(_)));
        let parent_index = parent_body.map_or(-1, |b| b as i32);
        let b = body.add_body(part.name, parent_index, joint, spatial_inertia(part.inertial), x);
        placed.push((part.name, Some(b), SpatialTransform::identity()));
    }
    (body, revolute)
}

/// One state of the robot: positions, rates, accelerations, and the torques that give them.
#[derive(Clone, Copy)]
struct State<T, const N: usize, const V: usize> {
    q: [T; N],
    qd: [T; V],
    qdd: [T; V],
    tau: [T; V],
}

/// The states, each configuration passed through `finish` (a floating base's quaternion made
/// unit) before its torques are computed.
fn draw_states<R: Compiled<N, V>, const N: usize, const V: usize>(
    finish: impl Fn(&mut [f64; N]),
) -> Vec<State<f64, N, V>> {
    let rates = [JointLimits { lower: -2.0, upper: 2.0 }; V];
    let mut q = Configurations::within(&R::LIMITS).uniform();
    let mut qd = Configurations::within(&rates).uniform().seeded(1);
    let mut qdd = Configurations::within(&rates).uniform().seeded(2);
    (0..STATES)
        .map(|_| {
            let (mut q, qd, qdd) = (q.next_array().unwrap(), qd.next_array().unwrap(), qdd.next_array().unwrap());
            finish(&mut q);
            State { q, qd, qdd, tau: R::rnea(&q, &qd, &qdd) }
        })
        .collect()
}

/// The states `lanes` at a time: pack `i`'s lane `l` is state `lanes * i + l`.
fn packs<L: Lanes<Scalar = f64>, const N: usize, const V: usize>(states: &[State<f64, N, V>]) -> Vec<State<L, N, V>> {
    let lanes = L::LANES;
    (0..states.len() / lanes)
        .map(|i| {
            fn pack<L: Lanes<Scalar = f64>, const M: usize>(of: impl Fn(usize) -> [f64; M]) -> [L; M] {
                std::array::from_fn(|j| L::from_fn(|l| of(l)[j]))
            }
            let s = |l: usize| &states[lanes * i + l];
            State { q: pack(|l| s(l).q), qd: pack(|l| s(l).qd), qdd: pack(|l| s(l).qdd), tau: pack(|l| s(l).tau) }
        })
        .collect()
}

/// `got` within `relative` of `want`'s largest entry (at least 1) of `want`.
fn close(got: &[f64], want: &[f64], relative: f64, what: &str) {
    assert_eq!(got.len(), want.len(), "{what}");
    let scale = want.iter().fold(1.0f64, |s, x| s.max(x.abs()));
    for (k, (g, w)) in got.iter().zip(want).enumerate() {
        assert!(g.is_finite() && (g - w).abs() <= relative * scale, "{what}[{k}]: {g} against {w}");
    }
}

fn rows<T: Copy + Into<f64>, const N: usize>(m: &[[T; N]; N]) -> Vec<f64> {
    m.iter().flatten().map(|&x| x.into()).collect()
}

fn narrow<const N: usize>(x: &[f64; N]) -> [f32; N] {
    x.map(|x| x as f32)
}

fn widen<const N: usize>(x: &[f32; N]) -> Vec<f64> {
    x.iter().map(|&x| f64::from(x)).collect()
}

/// The featherstone side of one robot: its model, and each state in its coordinates (revolute
/// positions negated, the Panda's finger entry given to both fingers) with the torques the
/// reference gives on its robot.
struct Peer {
    body: ArticulatedBody,
    q: Vec<Vec<f32>>,
    qd: Vec<Vec<f32>>,
    qdd: Vec<Vec<f32>>,
    tau: Vec<Vec<f32>>,
    zeros: Vec<f32>,
}

impl Peer {
    /// `parts` built, checked against `reference` (the same robot, with as many velocities) on
    /// every state (`expand` takes a state's vector to the peer's velocities).
    fn new<const N: usize>(
        parts: &[Part],
        reference: &ReferenceDynamics,
        states: &[State<f64, N, N>],
        expand: impl Fn(&[f64; N]) -> Vec<f64>,
        name: &str,
    ) -> Peer {
        let (mut body, revolute) = featherstone_model(parts);
        let nv = body.dof_count();
        assert_eq!((nv, body.nq()), (reference.tree().velocity_dof(), reference.tree().dof()), "{name}");
        let to32 = |v: &[f64]| v.iter().map(|&x| x as f32).collect::<Vec<f32>>();
        let mut peer =
            Peer { body: body.clone(), q: vec![], qd: vec![], qdd: vec![], tau: vec![], zeros: vec![0.0; nv] };
        for s in states {
            let (q, qd, qdd) = (expand(&s.q), expand(&s.qd), expand(&s.qdd));
            let tau = reference.inverse_dynamics(&q, &qd, &qdd).unwrap();
            let theirs: Vec<f64> = q.iter().zip(&revolute).map(|(&x, &r)| if r { -x } else { x }).collect();
            peer.q.push(to32(&theirs));
            peer.qd.push(to32(&qd));
            peer.qdd.push(to32(&qdd));
            peer.tau.push(to32(&tau));
            let k = peer.q.len() - 1;
            let as64 = |v: &[f32]| v.iter().map(|&x| f64::from(x)).collect::<Vec<f64>>();
            // The peer's own positions, read back: the reference at the rounded state.
            let q = as64(&peer.q[k]).iter().zip(&revolute).map(|(&x, &r)| if r { -x } else { x }).collect::<Vec<_>>();
            let (qd, qdd) = (as64(&peer.qd[k]), as64(&peer.qdd[k]));
            let what = |f: &str| format!("featherstone {name} {f} at state {k}");
            peer.set(&mut body, k, [true, false, false, false]);
            close(
                &as64(rnea_inverse_dynamics(&body).0.as_slice()),
                &reference.gravity_torques(&q).unwrap(),
                1e-4,
                &what("gravity"),
            );
            peer.set(&mut body, k, [true, true, true, false]);
            let want = reference.inverse_dynamics(&q, &qd, &qdd).unwrap();
            close(&as64(rnea_inverse_dynamics(&body).0.as_slice()), &want, 1e-4, &what("rnea"));
            peer.set(&mut body, k, [true, true, false, false]);
            let want = reference.nonlinear_effects(&q, &qd).unwrap();
            close(&as64(rnea_inverse_dynamics(&body).0.as_slice()), &want, 1e-4, &what("nonlinear effects"));
            let m = crba_mass_matrix(&body);
            let want = reference.mass_matrix(&q).unwrap();
            close(&as64(m.as_slice()), want.as_slice(), 1e-4, &what("crba"));
            peer.set(&mut body, k, [true, true, false, true]);
            let tau = as64(&peer.tau[k]);
            let want = reference.forward_dynamics(&q, &qd, &tau).unwrap();
            close(&as64(aba_forward_dynamics(&mut body).as_slice()), &want, 1e-3, &what("forward dynamics"));
        }
        peer
    }

    /// Gives `body` state `k`'s positions, rates, accelerations and torques where `which` says so
    /// (zeros elsewhere).
    #[inline(always)]
    fn set<'a>(&'a self, body: &mut ArticulatedBody, k: usize, which: [bool; 4]) {
        let [q, qd, qdd, tau] = which.map(|on| if on { k } else { usize::MAX });
        let pick = |v: &'a [Vec<f32>], k: usize| -> &'a [f32] { v.get(k).unwrap_or(&self.zeros) };
        body.q.as_mut_slice().copy_from_slice(pick(&self.q, q));
        body.qd.as_mut_slice().copy_from_slice(pick(&self.qd, qd));
        body.qdd.as_mut_slice().copy_from_slice(pick(&self.qdd, qdd));
        body.tau.as_mut_slice().copy_from_slice(pick(&self.tau, tau));
    }
}

/// Times `f` on state after state, one call per iteration. The result is kept where the call
/// left it (`black_box(&out)`, as the fk benchmark's `link_poses`): moved into `black_box`, a
/// matrix is copied by `memcpy`, whose wide loads wait on the call's scalar stores (a third of the
/// UR5's `crba` time, measured).
fn per_call<O>(group: &mut BenchmarkGroup<'_, WallTime>, id: &str, mut f: impl FnMut(usize) -> O) {
    let mut k = 0;
    group.bench_function(id, |b| {
        b.iter(|| {
            k = (k + 1) % STATES;
            let out = f(black_box(k));
            black_box(&out);
        })
    });
}

/// Times `f` on every pack of `lanes` states in one dispatched loop, per configuration.
fn per_pack<O>(group: &mut BenchmarkGroup<'_, WallTime>, id: &str, lanes: usize, mut f: impl FnMut(usize) -> O) {
    group.throughput(Throughput::Elements(STATES as u64));
    group.bench_function(id, |b| {
        b.iter(|| {
            dispatch(
                #[inline(always)]
                || {
                    for i in 0..STATES / lanes {
                        let out = f(black_box(i));
                        black_box(&out);
                    }
                },
            )
        })
    });
    group.throughput(Throughput::Elements(1));
}

/// One robot: its checks, then (measuring) its groups; `peer`, the featherstone model, where there
/// is one.
fn robot<R: Compiled<N, V>, const N: usize, const V: usize>(
    criterion: Option<&mut Criterion>,
    tree: kinematics::model::KinematicTree,
    peer: Option<Peer>,
    states: &[State<f64, N, V>],
) {
    let name = R::NAME;
    let reference = ReferenceDynamics::new(tree.clone(), GRAVITY, false).unwrap();
    let s32: Vec<State<f32, N, V>> = states
        .iter()
        .map(|s| State { q: narrow(&s.q), qd: narrow(&s.qd), qdd: narrow(&s.qdd), tau: narrow(&s.tau) })
        .collect();
    let (p4, p8): (Vec<State<F64x4, N, V>>, Vec<State<F64x8, N, V>>) = (packs(states), packs(states));
    // The generated functions against the reference, in f64 and f32, and every lane against f64.
    for (k, s) in states.iter().enumerate() {
        let what = |f: &str| format!("{name} {f} at state {k}");
        let (q, qd, qdd, tau) = (&s.q[..], &s.qd[..], &s.qdd[..], &s.tau[..]);
        let m = reference.mass_matrix(q).unwrap();
        let m: Vec<f64> = (0..V).flat_map(|i| (0..V).map(move |j| (i, j))).map(|(i, j)| m[(i, j)]).collect();
        let wanted = [
            reference.gravity_torques(q).unwrap(),
            reference.inverse_dynamics(q, qd, qdd).unwrap(),
            reference.nonlinear_effects(q, qd).unwrap(),
            m,
            reference.forward_dynamics(q, qd, tau).unwrap(),
        ];
        let ours = [
            R::gravity(&s.q).to_vec(),
            R::rnea(&s.q, &s.qd, &s.qdd).to_vec(),
            R::nonlinear(&s.q, &s.qd).to_vec(),
            rows(&R::crba(&s.q)),
            R::aba(&s.q, &s.qd, &s.tau).to_vec(),
        ];
        for (i, f) in ["gravity", "rnea", "nonlinear effects", "crba", "forward dynamics"].into_iter().enumerate() {
            close(&ours[i], &wanted[i], if i == 4 { 1e-9 } else { 1e-12 }, &what(f));
        }
        if R::F32 {
            let t = &s32[k];
            let ours32 = [
                widen(&R::gravity_f32(&t.q)),
                widen(&R::rnea_f32(&t.q, &t.qd, &t.qdd)),
                widen(&R::nonlinear_f32(&t.q, &t.qd)),
                rows(&R::crba_f32(&t.q)),
                widen(&R::aba_f32(&t.q, &t.qd, &t.tau)),
            ];
            for (i, f) in ["gravity", "rnea", "nonlinear effects", "crba", "forward dynamics"].into_iter().enumerate() {
                close(&ours32[i], &wanted[i], if i == 4 { 1e-3 } else { 1e-4 }, &what(&format!("{f} f32")));
            }
        }
        if !R::LANES {
            continue;
        }
        let (i4, l4, i8, l8) = (k / 4, k % 4, k / 8, k % 8);
        let (a, b) = (&p4[i4], &p8[i8]);
        let lanes4 = [
            R::gravity_generic(&a.q).map(|x| x.to_array()[l4]).to_vec(),
            R::rnea_generic(&a.q, &a.qd, &a.qdd).map(|x| x.to_array()[l4]).to_vec(),
            R::nonlinear_generic(&a.q, &a.qd).map(|x| x.to_array()[l4]).to_vec(),
            R::crba_generic(&a.q).iter().flatten().map(|x| x.to_array()[l4]).collect(),
            R::aba_generic(&a.q, &a.qd, &a.tau).0.map(|x| x.to_array()[l4]).to_vec(),
        ];
        let lanes8 = [
            R::gravity_generic(&b.q).map(|x| x.to_array()[l8]).to_vec(),
            R::rnea_generic(&b.q, &b.qd, &b.qdd).map(|x| x.to_array()[l8]).to_vec(),
            R::nonlinear_generic(&b.q, &b.qd).map(|x| x.to_array()[l8]).to_vec(),
            R::crba_generic(&b.q).iter().flatten().map(|x| x.to_array()[l8]).collect(),
            R::aba_generic(&b.q, &b.qd, &b.tau).0.map(|x| x.to_array()[l8]).to_vec(),
        ];
        assert_eq!(lanes4, ours, "{name}: F64x4 lanes at state {k}");
        assert_eq!(lanes8, ours, "{name}: F64x8 lanes at state {k}");
    }
    let Some(c) = criterion else { return };
    let request = DynamicsRequest { gravity: GRAVITY, ..DynamicsRequest::default() };
    let functions = [
        (DynamicsFunction::Gravity, "gravity"),
        (DynamicsFunction::InverseDynamics, "rnea"),
        (DynamicsFunction::NonlinearEffects, "nonlinear_effects"),
        (DynamicsFunction::MassMatrix, "crba"),
        (DynamicsFunction::ForwardDynamics, "forward_dynamics"),
    ];
    for (function, short) in functions {
        let cost = compile_dynamics(&tree, &request, function).unwrap().op_count();
        println!("dynamics/{name}/{short}: {} Cost: {cost}.", function.name());
    }
    let mut peer = peer.map(|p| (p.body.clone(), p));
    let (st, s32) = (states, &s32[..]);

    let mut g = c.benchmark_group(format!("dynamics/{name}/gravity"));
    per_call(&mut g, "generated", |k| R::gravity(&st[k].q));
    if R::F32 {
        per_call(&mut g, "generated_f32", |k| R::gravity_f32(&s32[k].q));
    }
    if R::LANES {
        per_pack(
            &mut g,
            "f64x4",
            4,
            #[inline(always)]
            |i| R::gravity_generic(&p4[i].q),
        );
        per_pack(
            &mut g,
            "f64x8",
            8,
            #[inline(always)]
            |i| R::gravity_generic(&p8[i].q),
        );
    }
    per_call(&mut g, "reference", |k| reference.gravity_torques(&st[k].q).unwrap());
    if let Some((body, peer)) = &mut peer {
        peer.set(body, 0, [true, false, false, false]);
        per_call(&mut g, "featherstone", |k| {
            body.q.as_mut_slice().copy_from_slice(&peer.q[k]);
            rnea_inverse_dynamics(body).0
        });
    }
    g.finish();

    let mut g = c.benchmark_group(format!("dynamics/{name}/rnea"));
    per_call(&mut g, "generated", |k| R::rnea(&st[k].q, &st[k].qd, &st[k].qdd));
    if R::F32 {
        per_call(&mut g, "generated_f32", |k| R::rnea_f32(&s32[k].q, &s32[k].qd, &s32[k].qdd));
    }
    if R::LANES {
        per_pack(
            &mut g,
            "f64x4",
            4,
            #[inline(always)]
            |i| R::rnea_generic(&p4[i].q, &p4[i].qd, &p4[i].qdd),
        );
        per_pack(
            &mut g,
            "f64x8",
            8,
            #[inline(always)]
            |i| R::rnea_generic(&p8[i].q, &p8[i].qd, &p8[i].qdd),
        );
    }
    per_call(&mut g, "reference", |k| reference.inverse_dynamics(&st[k].q, &st[k].qd, &st[k].qdd).unwrap());
    if let Some((body, peer)) = &mut peer {
        per_call(&mut g, "featherstone", |k| {
            peer.set(body, k, [true, true, true, false]);
            rnea_inverse_dynamics(body).0
        });
    }
    g.finish();

    let mut g = c.benchmark_group(format!("dynamics/{name}/nonlinear_effects"));
    per_call(&mut g, "generated", |k| R::nonlinear(&st[k].q, &st[k].qd));
    if R::F32 {
        per_call(&mut g, "generated_f32", |k| R::nonlinear_f32(&s32[k].q, &s32[k].qd));
    }
    if R::LANES {
        per_pack(
            &mut g,
            "f64x4",
            4,
            #[inline(always)]
            |i| R::nonlinear_generic(&p4[i].q, &p4[i].qd),
        );
        per_pack(
            &mut g,
            "f64x8",
            8,
            #[inline(always)]
            |i| R::nonlinear_generic(&p8[i].q, &p8[i].qd),
        );
    }
    per_call(&mut g, "reference", |k| reference.nonlinear_effects(&st[k].q, &st[k].qd).unwrap());
    if let Some((body, peer)) = &mut peer {
        peer.set(body, 0, [true, true, false, false]);
        per_call(&mut g, "featherstone", |k| {
            body.q.as_mut_slice().copy_from_slice(&peer.q[k]);
            body.qd.as_mut_slice().copy_from_slice(&peer.qd[k]);
            rnea_inverse_dynamics(body).0
        });
    }
    g.finish();

    let mut g = c.benchmark_group(format!("dynamics/{name}/crba"));
    per_call(&mut g, "generated", |k| R::crba(&st[k].q));
    if R::F32 {
        per_call(&mut g, "generated_f32", |k| R::crba_f32(&s32[k].q));
    }
    if R::LANES {
        per_pack(
            &mut g,
            "f64x4",
            4,
            #[inline(always)]
            |i| R::crba_generic(&p4[i].q),
        );
        per_pack(
            &mut g,
            "f64x8",
            8,
            #[inline(always)]
            |i| R::crba_generic(&p8[i].q),
        );
    }
    per_call(&mut g, "reference", |k| reference.mass_matrix(&st[k].q).unwrap());
    if let Some((body, peer)) = &mut peer {
        per_call(&mut g, "featherstone", |k| {
            body.q.as_mut_slice().copy_from_slice(&peer.q[k]);
            crba_mass_matrix(body)
        });
    }
    g.finish();

    let mut g = c.benchmark_group(format!("dynamics/{name}/forward_dynamics"));
    per_call(&mut g, "generated", |k| R::aba(&st[k].q, &st[k].qd, &st[k].tau));
    if R::F32 {
        per_call(&mut g, "generated_f32", |k| R::aba_f32(&s32[k].q, &s32[k].qd, &s32[k].tau));
    }
    if R::LANES {
        per_pack(
            &mut g,
            "f64x4",
            4,
            #[inline(always)]
            |i| R::aba_generic(&p4[i].q, &p4[i].qd, &p4[i].tau),
        );
        per_pack(
            &mut g,
            "f64x8",
            8,
            #[inline(always)]
            |i| R::aba_generic(&p8[i].q, &p8[i].qd, &p8[i].tau),
        );
    }
    per_call(&mut g, "reference", |k| reference.forward_dynamics(&st[k].q, &st[k].qd, &st[k].tau).unwrap());
    if let Some((body, peer)) = &mut peer {
        per_call(&mut g, "featherstone", |k| {
            peer.set(body, k, [true, true, false, true]);
            aba_forward_dynamics(body)[0]
        });
    }
    g.finish();
}

fn run(mut criterion: Option<&mut Criterion>) {
    // The Panda: featherstone's has both fingers, checked against the reference on the Panda with
    // the `<mimic>` removed.
    let states = draw_states::<Panda, 8, 8>(|_| ());
    let urdf = std::fs::read_to_string(format!("{}/robots/panda.urdf", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let mimic = r#"<mimic joint="panda_finger_joint1" multiplier="1" offset="0"/>"#;
    assert!(urdf.contains(mimic));
    let both = kinematics::model::parse_source("panda_both_fingers.urdf", &urdf.replace(mimic, "")).unwrap();
    let both = ReferenceDynamics::new(both, GRAVITY, false).unwrap();
    let expand = |v: &[f64; 8]| -> Vec<f64> { v.iter().copied().chain([v[7]]).collect() };
    let peer = Peer::new(PANDA, &both, &states, expand, "panda");
    robot::<Panda, 8, 8>(criterion.as_deref_mut(), Panda::reference().unwrap().tree().clone(), Some(peer), &states);

    let states = draw_states::<Ur5, 6, 6>(|_| ());
    let tree = Ur5::reference().unwrap().tree().clone();
    let reference = ReferenceDynamics::new(tree.clone(), GRAVITY, false).unwrap();
    let peer = Peer::new(UR5, &reference, &states, |v: &[f64; 6]| v.to_vec(), "ur5");
    robot::<Ur5, 6, 6>(criterion.as_deref_mut(), tree, Some(peer), &states);

    // The humanoid on its free-flying torso: `q[3..7]` is the base's quaternion, made unit. No
    // featherstone model (see the module doc).
    assert_eq!(Humanoid::JOINT_NAMES[3..7], ["root_joint.qx", "root_joint.qy", "root_joint.qz", "root_joint.qw"]);
    let states = draw_states::<Humanoid, 32, 31>(|q| {
        let norm = q[3..7].iter().map(|x| x * x).sum::<f64>().sqrt();
        q[3..7].iter_mut().for_each(|x| *x /= norm);
    });
    robot::<Humanoid, 32, 31>(criterion, Humanoid::reference().unwrap().tree().clone(), None, &states);
}

fn main() {
    if common::measuring() {
        let mut c = common::criterion(Duration::from_millis(500), Duration::from_secs(2));
        run(Some(&mut c));
        c.final_summary();
    } else {
        run(None);
        println!("dynamics benchmarks: every function checked on every state");
    }
}
