//! The robots timed, each derived twice: with our sin/cos (`positions`, f64 and f32, and for the
//! URDF robots the Jacobians) and with `trig = "std"` (std's `sin_cos`, one call per angle), the
//! difference the pose comparisons measure. [`Generated`] and [`StdGenerated`] name the generated
//! functions the areas time, so each area is one generic function rather than a macro: the trait
//! methods forward to the derive's inherent functions, always inlined, so the bodies timed are the
//! same calls a user makes. [`Setup`] holds what every area of one robot shares: its file, tip,
//! configurations, runtime reference and sin/cos counts.

use kinematics::{Kinematics, KinematicsError, Pose, Real, ReferenceFk};

use crate::floors::sin_cos;
use crate::inputs::{INPUTS, arrays, arrays_f32, inputs};
use crate::mode::Mode;

/// The generated functions of a robot derived with our sin/cos, `positions` and `scalars(f64, f32)`.
pub trait Generated<const N: usize>: Kinematics {
    /// `tip_pose`.
    fn tip_pose(q: &[f64; N]) -> Pose<f64>;
    /// `tip_pose_f32`.
    fn tip_pose_f32(q: &[f32; N]) -> Pose<f32>;
    /// `tip_position`.
    fn tip_position(q: &[f64; N]) -> [f64; 3];
    /// `tip_pose_generic` on the lane types.
    fn tip_pose_generic<T: Real>(q: &[T; N]) -> Pose<T>;
    /// `link_poses`: one pose per name of `LINK_NAMES`.
    fn link_poses(q: &[f64; N]) -> impl AsRef<[Pose<f64>]>;
    /// `link_poses_f32`.
    fn link_poses_f32(q: &[f32; N]) -> impl AsRef<[Pose<f32>]>;
    /// `link_poses_generic::<f64>`: the same body, not dispatched (the build's own instruction set).
    fn link_poses_baseline(q: &[f64; N]) -> impl AsRef<[Pose<f64>]>;
    /// `tip_pose_batch`.
    fn tip_pose_batch(qs: &[[f64; N]], out: &mut [Pose<f64>]) -> Result<(), KinematicsError>;
    /// `tip_pose_batch_f32`.
    fn tip_pose_batch_f32(qs: &[[f32; N]], out: &mut [Pose<f32>]) -> Result<(), KinematicsError>;
    /// `tip_pose_batch_columns`.
    fn tip_pose_batch_columns(columns: [&[f64]; N], out: &mut [Pose<f64>]) -> Result<(), KinematicsError>;
    /// `tip_pose_batch_columns_f32`.
    fn tip_pose_batch_columns_f32(columns: [&[f32]; N], out: &mut [Pose<f32>]) -> Result<(), KinematicsError>;
    /// galaw's generated code for the same URDF against ours ([`crate::peers::galaw_contender`]); nothing
    /// for a robot galaw has no code for (the DH robots: galaw reads URDF only).
    fn galaw(_mode: &mut Mode, _fk: &Setup<N>, _generated_all: impl FnMut(usize)) {}
}

/// The generated functions of the same robot derived with `trig = "std"`.
pub trait StdGenerated<const N: usize>: Kinematics {
    /// `tip_pose`.
    fn tip_pose(q: &[f64; N]) -> Pose<f64>;
    /// `link_poses`: one pose per name of `LINK_NAMES`.
    fn link_poses(q: &[f64; N]) -> impl AsRef<[Pose<f64>]>;
}

/// Implements [`Generated`] and [`StdGenerated`] for a robot's two derives by forwarding to their
/// inherent functions, and [`Generated::galaw`] with the named module of `crate::peers::galaw`.
macro_rules! generated {
    ($ty:ty, $std:ty, $n:literal $(, $galaw:ident)?) => {
        impl Generated<$n> for $ty {
            #[inline(always)]
            fn tip_pose(q: &[f64; $n]) -> Pose<f64> {
                <$ty>::tip_pose(q)
            }
            #[inline(always)]
            fn tip_pose_f32(q: &[f32; $n]) -> Pose<f32> {
                <$ty>::tip_pose_f32(q)
            }
            #[inline(always)]
            fn tip_position(q: &[f64; $n]) -> [f64; 3] {
                <$ty>::tip_position(q)
            }
            #[inline(always)]
            fn tip_pose_generic<T: Real>(q: &[T; $n]) -> Pose<T> {
                <$ty>::tip_pose_generic::<T>(q)
            }
            #[inline(always)]
            fn link_poses(q: &[f64; $n]) -> impl AsRef<[Pose<f64>]> {
                <$ty>::link_poses(q)
            }
            #[inline(always)]
            fn link_poses_f32(q: &[f32; $n]) -> impl AsRef<[Pose<f32>]> {
                <$ty>::link_poses_f32(q)
            }
            #[inline(always)]
            fn link_poses_baseline(q: &[f64; $n]) -> impl AsRef<[Pose<f64>]> {
                <$ty>::link_poses_generic::<f64>(q)
            }
            #[inline(always)]
            fn tip_pose_batch(qs: &[[f64; $n]], out: &mut [Pose<f64>]) -> Result<(), KinematicsError> {
                <$ty>::tip_pose_batch(qs, out)
            }
            #[inline(always)]
            fn tip_pose_batch_f32(qs: &[[f32; $n]], out: &mut [Pose<f32>]) -> Result<(), KinematicsError> {
                <$ty>::tip_pose_batch_f32(qs, out)
            }
            #[inline(always)]
            fn tip_pose_batch_columns(columns: [&[f64]; $n], out: &mut [Pose<f64>]) -> Result<(), KinematicsError> {
                <$ty>::tip_pose_batch_columns(columns, out)
            }
            #[inline(always)]
            fn tip_pose_batch_columns_f32(columns: [&[f32]; $n], out: &mut [Pose<f32>]) -> Result<(), KinematicsError> {
                <$ty>::tip_pose_batch_columns_f32(columns, out)
            }
            $(
                fn galaw(mode: &mut Mode, fk: &Setup<$n>, generated_all: impl FnMut(usize)) {
                    use crate::peers::galaw::$galaw as g;
                    crate::peers::galaw_contender(mode, fk, g::JOINT_CHILDREN, g::LINKS, g::fk_f64, g::fk_f32, generated_all);
                }
            )?
        }
        impl StdGenerated<$n> for $std {
            #[inline(always)]
            fn tip_pose(q: &[f64; $n]) -> Pose<f64> {
                <$std>::tip_pose(q)
            }
            #[inline(always)]
            fn link_poses(q: &[f64; $n]) -> impl AsRef<[Pose<f64>]> {
                <$std>::link_poses(q)
            }
        }
    };
}

#[derive(Kinematics)]
#[kinematics(dh = "robots/puma560.toml", tip = "link6", positions, scalars(f64, f32))]
pub struct Puma560;
#[derive(Kinematics)]
#[kinematics(dh = "robots/puma560.toml", tip = "link6", trig = "std")]
pub struct Puma560Std;
#[derive(Kinematics)]
#[kinematics(dh = "robots/stanford_arm.toml", tip = "link6", positions, scalars(f64, f32))]
pub struct Stanford;
#[derive(Kinematics)]
#[kinematics(dh = "robots/stanford_arm.toml", tip = "link6", trig = "std")]
pub struct StanfordStd;
// The smallest robot: where the cost of dispatch, per call, shows most.
#[derive(Kinematics)]
#[kinematics(dh = "robots/planar_2r.toml", tip = "link2", positions, scalars(f64, f32))]
pub struct Planar2r;
#[derive(Kinematics)]
#[kinematics(dh = "robots/planar_2r.toml", tip = "link2", trig = "std")]
pub struct Planar2rStd;
#[derive(Kinematics)]
#[kinematics(dh = "robots/scara.toml", tip = "link4", positions, scalars(f64, f32))]
pub struct Scara;
#[derive(Kinematics)]
#[kinematics(dh = "robots/scara.toml", tip = "link4", trig = "std")]
pub struct ScaraStd;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5.urdf", tip = "tool0", positions, scalars(f64, f32), jacobians)]
pub struct Ur5;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5.urdf", tip = "tool0", trig = "std")]
pub struct Ur5Std;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur10e.urdf", tip = "tool0", positions, scalars(f64, f32), jacobians)]
pub struct Ur10e;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur10e.urdf", tip = "tool0", trig = "std")]
pub struct Ur10eStd;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/iiwa14.urdf", tip = "iiwa_link_ee", positions, scalars(f64, f32), jacobians)]
pub struct Iiwa14;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/iiwa14.urdf", tip = "iiwa_link_ee", trig = "std")]
pub struct Iiwa14Std;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/panda.urdf", tip = "panda_hand", positions, scalars(f64, f32), jacobians)]
pub struct Panda;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/panda.urdf", tip = "panda_hand", trig = "std")]
pub struct PandaStd;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/gen3.urdf", tip = "end_effector_link", positions, scalars(f64, f32), jacobians)]
pub struct Gen3;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/gen3.urdf", tip = "end_effector_link", trig = "std")]
pub struct Gen3Std;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/irb120.urdf", tip = "tool0", positions, scalars(f64, f32), jacobians)]
pub struct Irb120;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/irb120.urdf", tip = "tool0", trig = "std")]
pub struct Irb120Std;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/dual_arm_torso.urdf", tip = "tool_l", positions, scalars(f64, f32), jacobians)]
pub struct DualArm;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/dual_arm_torso.urdf", tip = "tool_l", trig = "std")]
pub struct DualArmStd;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/quadruped.urdf", tip = "RL_foot", positions, scalars(f64, f32), jacobians)]
pub struct Quadruped;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/quadruped.urdf", tip = "RL_foot", trig = "std")]
pub struct QuadrupedStd;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/humanoid.urdf", tip = "r_gripper", positions, scalars(f64, f32), jacobians)]
pub struct Humanoid;
#[derive(Kinematics)]
#[kinematics(urdf = "robots/humanoid.urdf", tip = "r_gripper", trig = "std")]
pub struct HumanoidStd;

generated!(Puma560, Puma560Std, 6);
generated!(Stanford, StanfordStd, 6);
generated!(Planar2r, Planar2rStd, 2);
generated!(Scara, ScaraStd, 4);
generated!(Ur5, Ur5Std, 6, ur5);
generated!(Ur10e, Ur10eStd, 6, ur10e);
generated!(Iiwa14, Iiwa14Std, 7, iiwa14);
generated!(Panda, PandaStd, 8, panda);
generated!(Gen3, Gen3Std, 7, gen3);
generated!(Irb120, Irb120Std, 6, irb120);
generated!(DualArm, DualArmStd, 17, dual_arm_torso);
generated!(Quadruped, QuadrupedStd, 12, quadruped);
generated!(Humanoid, HumanoidStd, 25, humanoid);

/// What every area of one robot shares, made before any timing.
pub struct Setup<const N: usize> {
    /// The description's path (`robots/<file>`).
    pub path: String,
    /// The tip the tip bodies compute.
    pub tip: &'static str,
    /// [`INPUTS`] configurations within the limits, as the runtime and the peers take them.
    pub qs: Vec<Vec<f64>>,
    /// The same as arrays, f64.
    pub q64: Vec<[f64; N]>,
    /// The same rounded to f32.
    pub q32: Vec<[f32; N]>,
    /// The runtime reference: the oracle of check mode and a contender.
    pub reference: ReferenceFk,
    /// The robot's reach, which scales the positional part of a pose's deviation.
    pub reach: f64,
    /// The `sin_cos` pairs of the tip pose and of all link poses (the floors' counts).
    pub sin_cos: (usize, usize),
    /// The joint limits, for the areas that make more configurations (the batches).
    pub limits: &'static [kinematics::JointLimits],
}

impl<const N: usize> Setup<N> {
    /// The robot of `robots/<file>` as derived by `R`, with `tip`.
    pub fn new<R: Kinematics>(file: &str, tip: &'static str) -> Self {
        let path = format!("{}/robots/{file}", env!("CARGO_MANIFEST_DIR"));
        let qs = inputs(R::JOINT_LIMITS, INPUTS);
        let reference = ReferenceFk::new(kinematics::load(&path).expect("robot loads"));
        let reach = reference.tree().reach();
        Setup {
            q64: arrays(&qs),
            q32: arrays_f32(&qs),
            qs,
            reference,
            reach,
            sin_cos: sin_cos(file, tip),
            limits: R::JOINT_LIMITS,
            path,
            tip,
        }
    }

    /// Whether the robot is a URDF, which `k` and galaw read (DH tables they do not).
    pub fn is_urdf(&self) -> bool {
        self.path.ends_with(".urdf")
    }
}
