//! Every robot in `robots/`, compiled to Rust at build time by `kinematics-compiler`, and a registry
//! of the generated functions for the agreement tests (`tests/`) to iterate over; and the same for
//! a fixed-seed set of random robots ([`random::RANDOM`]), compiled through `emit_robot` as the derive does.
//!
//! Being a workspace member, this crate also puts the generated code through the workspace's
//! `cargo clippy -D warnings`: the emitted code must be clippy-clean in a user's crate.

pub mod differences;
pub mod dual;

pub use kinematics::Pose;

/// `check` on every item, the items shared out over the machine's cores as they free up; the
/// results in the items' order. The robots' checks are independent, and one thread per test left a
/// core idle through most of a cold `cargo test`. A panic in a check is the caller's panic.
pub fn on_every_core<T: Sync, R: Send>(items: &[T], check: impl Fn(&T) -> R + Sync) -> Vec<R> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    let workers = std::thread::available_parallelism().map_or(1, usize::from).min(items.len().max(1));
    let next = AtomicUsize::new(0);
    let mut done: Vec<(usize, R)> = std::thread::scope(|scope| {
        let threads: Vec<_> = (0..workers)
            .map(|_| {
                scope.spawn(|| {
                    let mut done = Vec::new();
                    loop {
                        let i = next.fetch_add(1, Ordering::Relaxed);
                        let Some(item) = items.get(i) else { return done };
                        done.push((i, check(item)));
                    }
                })
            })
            .collect();
        threads
            .into_iter()
            .flat_map(|thread| thread.join().unwrap_or_else(|panic| std::panic::resume_unwind(panic)))
            .collect()
    });
    done.sort_by_key(|(i, _)| *i);
    done.into_iter().map(|(_, result)| result).collect()
}

/// One generated leaf-link function set.
pub struct Tip {
    /// The link.
    pub link: &'static str,
    /// Its pose, `f64`.
    pub pose: fn(&[f64]) -> Pose<f64>,
    /// Its pose, `f32`.
    pub pose_f32: fn(&[f32]) -> Pose<f32>,
    /// Its position, `f64`.
    pub position: fn(&[f64]) -> [f64; 3],
    /// Its generated geometric Jacobian (`LOCAL_WORLD_ALIGNED`), one column per velocity.
    pub jacobian: fn(&[f64]) -> Vec<[f64; 6]>,
    /// The same in the tip's axes (`LOCAL`).
    pub jacobian_local: fn(&[f64]) -> Vec<[f64; 6]>,
    /// The Jacobian of the generated pose run on dual numbers, seeded with the directions given
    /// ([`dual::directions`]).
    pub jacobian_by_duals: DualJacobianFn,
}

/// A Jacobian by dual numbers at a configuration, along the directions given.
pub type DualJacobianFn = fn(&[f64], &[Vec<f64>]) -> Vec<[f64; 6]>;

/// A generated Jacobian's columns (`[row][column]` in, one `[linear; angular]` per column out).
pub fn columns<const V: usize>(jacobian: [[f64; V]; 6]) -> Vec<[f64; 6]> {
    (0..V).map(|c| std::array::from_fn(|r| jacobian[r][c])).collect()
}

/// The generated functions of one robot file.
pub struct GeneratedRobot {
    /// File name in `robots/`.
    pub file: &'static str,
    /// Degrees of freedom.
    pub dof: usize,
    /// Leaf links.
    pub tips: &'static [Tip],
    /// Links in the order `all_poses` returns them.
    pub all_links: &'static [&'static str],
    /// Poses of every link below the root.
    pub all_poses: fn(&[f64]) -> Vec<Pose<f64>>,
}

/// A slice as a fixed-size array reference; the registry only passes slices of the right length.
fn arr<T, const N: usize>(q: &[T]) -> &[T; N] {
    match q.try_into() {
        Ok(a) => a,
        Err(_) => unreachable_len(q.len(), N),
    }
}

#[cold]
fn unreachable_len(got: usize, expected: usize) -> ! {
    // The tests build q from `dof`; a mismatch is a bug in the test itself.
    #[allow(clippy::panic)]
    {
        panic!("q has {got} values, the generated function takes {expected}")
    }
}

/// `Kinematics::tip_poses_into` and `link_poses_into`.
pub type PosesInto = fn(&[f64], &mut [Pose<f64>]) -> Result<(), kinematics::KinematicsError>;

/// One robot compiled by `#[derive(Kinematics)]`, reached through the `Kinematics` trait.
pub struct DerivedRobot {
    /// File name in `robots/`.
    pub file: &'static str,
    /// `file` (the attribute names the file) or `inline` (the table is written in the attribute).
    pub how: &'static str,
    /// The tips.
    pub tips: &'static [&'static str],
    /// The links `link_poses_into` computes.
    pub links: &'static [&'static str],
    /// `Kinematics::tip_poses_into`.
    pub tip_poses_into: PosesInto,
    /// `Kinematics::link_poses_into`.
    pub link_poses_into: PosesInto,
    /// The tips' poses through the `f32` functions.
    pub tip_poses_f32: fn(&[f32]) -> Vec<Pose<f32>>,
    /// `Kinematics::reference`.
    pub reference: fn() -> Result<kinematics::ReferenceFk, kinematics::LoadError>,
}

/// A generated pose function, through a slice.
pub type PosesFn<T> = fn(&[T]) -> Vec<Pose<T>>;
/// A generated position function, through a slice.
pub type PositionsFn<T> = fn(&[T]) -> Vec<[T; 3]>;

/// The typed functions one scalar type got, through slices (`None`: not generated).
pub struct Typed<T: 'static> {
    /// `link_poses` (or `link_poses_f32`).
    pub link_poses: PosesFn<T>,
    /// `link_positions`.
    pub link_positions: Option<PositionsFn<T>>,
    /// `tip_pose` (as a one-element vector) or `tip_poses`.
    pub tip_poses: Option<PosesFn<T>>,
    /// `tip_position` or `tip_positions`.
    pub tip_positions: Option<PositionsFn<T>>,
    /// `link_poses_batch` over the configurations given (any number).
    pub link_poses_batch: BatchFn<T>,
    /// `tip_pose(s)_batch`.
    pub tip_poses_batch: Option<BatchFn<T>>,
    /// `link_poses_generic` on the lane type (`F64x4`, `F32x8`): exactly one lane's worth of
    /// configurations.
    pub link_poses_lanes: LanesFn<T>,
    /// `tip_pose(s)_generic` on the lane type.
    pub tip_poses_lanes: Option<LanesFn<T>>,
}

/// A batch function's results, per configuration.
pub type BatchFn<T> = fn(&[Vec<T>]) -> Result<Vec<Vec<Pose<T>>>, kinematics::KinematicsError>;
/// A generic function's results on one lane's worth of configurations, per configuration.
pub type LanesFn<T> = fn(&[Vec<T>]) -> Vec<Vec<Pose<T>>>;

/// A generated batch function run over configurations given as vectors.
pub fn batch<T: Copy, O: Copy + Zero, const N: usize>(
    qs: &[Vec<T>],
    f: impl Fn(&[[T; N]], &mut [O]) -> Result<(), kinematics::KinematicsError>,
) -> Result<Vec<O>, kinematics::KinematicsError> {
    let arrays: Vec<[T; N]> = qs.iter().map(|q| *arr(q)).collect();
    let mut out = vec![O::ZERO; qs.len()];
    f(&arrays, &mut out)?;
    Ok(out)
}

/// A value to fill an output slice with before a batch writes it.
pub trait Zero {
    /// The value.
    const ZERO: Self;
}

impl<T: Zero + Copy> Zero for Pose<T> {
    const ZERO: Self = Pose { rotation: [[T::ZERO; 3]; 3], translation: [T::ZERO; 3] };
}

impl<V: Zero + Copy, const M: usize> Zero for [V; M] {
    const ZERO: Self = [V::ZERO; M];
}

impl Zero for f64 {
    const ZERO: Self = 0.0;
}

impl Zero for f32 {
    const ZERO: Self = 0.0;
}

/// A generic function run on one lane's worth of configurations (`L::LANES` of them), packed into
/// the lane type, its poses unpacked per configuration.
pub fn lanes<L, const N: usize, const M: usize>(
    qs: &[Vec<L::Scalar>],
    f: impl Fn(&[L; N]) -> [Pose<L>; M],
) -> Vec<Vec<Pose<L::Scalar>>>
where
    L: kinematics::Lanes,
{
    assert_eq!(qs.len(), L::LANES, "one configuration per lane");
    let packed: [L; N] = std::array::from_fn(|j| L::from_fn(|i| qs[i][j]));
    let poses = f(&packed);
    (0..L::LANES).map(|i| poses.iter().map(|p| kinematics::LaneValue::lane(p, i)).collect()).collect()
}

/// The constants of one compiled type: read through the trait, or the inherent ones.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TraitConsts {
    /// `Kinematics::ROBOT`.
    pub robot: &'static str,
    /// `Kinematics::BASE`.
    pub base: &'static str,
    /// `Kinematics::DOF`.
    pub dof: usize,
    /// `Kinematics::JOINT_NAMES`.
    pub joint_names: &'static [&'static str],
    /// `Kinematics::JOINT_LIMITS`.
    pub joint_limits: &'static [kinematics::JointLimits],
    /// `Kinematics::LINK_NAMES`.
    pub links: &'static [&'static str],
    /// `Kinematics::TIPS`.
    pub tips: &'static [&'static str],
}

/// The trait's constants of `K`.
pub fn trait_consts<K: kinematics::Kinematics>() -> TraitConsts {
    TraitConsts {
        robot: K::ROBOT,
        base: K::BASE,
        dof: K::DOF,
        joint_names: K::JOINT_NAMES,
        joint_limits: K::JOINT_LIMITS,
        links: K::LINK_NAMES,
        tips: K::TIPS,
    }
}

/// One random robot compiled through `emit_robot`: every function and constant it generated.
pub struct RandomRobot {
    /// Its name in the generated set (`random_07_mimic_chain`).
    pub name: &'static str,
    /// `"Fast"` or `"Std"`: the sine and cosine it was generated with.
    pub trig: &'static str,
    /// The description's file name (its label).
    pub file: &'static str,
    /// The description's text, as compiled.
    pub text: &'static str,
    /// The inherent constants (`Robot::ROBOT`, ...), in the trait's shape.
    pub consts: TraitConsts,
    /// The `f64` functions.
    pub f64: Option<Typed<f64>>,
    /// The `f32` functions.
    pub f32: Option<Typed<f32>>,
    /// `Kinematics::tip_poses_into`.
    pub tip_poses_into: PosesInto,
    /// `Kinematics::link_poses_into`.
    pub link_poses_into: PosesInto,
    /// The inherent `reference()`.
    pub reference: fn() -> Result<kinematics::ReferenceFk, kinematics::LoadError>,
    /// `Kinematics::reference`.
    pub trait_reference: fn() -> Result<kinematics::ReferenceFk, kinematics::LoadError>,
    /// The trait's constants.
    pub trait_consts: fn() -> TraitConsts,
    /// The tips' velocity functions (`f64`; robots with tips and `f64` functions).
    pub velocities: Option<Velocities>,
}

/// Jacobians by dual numbers, per tip.
pub type DualJacobiansFn = fn(&[f64], &[Vec<f64>]) -> Vec<Vec<[f64; 6]>>;

/// Poses with their Jacobians (as columns), per tip.
pub type PosesAndJacobiansFn = fn(&[f64]) -> Vec<(Pose<f64>, Vec<[f64; 6]>)>;

/// A random robot's velocity functions, per tip, through slices; Jacobians as columns.
pub struct Velocities {
    /// `tip_jacobian(s)` (`LOCAL_WORLD_ALIGNED`).
    pub jacobians: fn(&[f64]) -> Vec<Vec<[f64; 6]>>,
    /// `tip_jacobian(s)_local`.
    pub jacobians_local: fn(&[f64]) -> Vec<Vec<[f64; 6]>>,
    /// `tip_pose(s)_and_jacobian(s)`.
    pub poses_and_jacobians: PosesAndJacobiansFn,
    /// `tip_twist(s)` at the rates given.
    pub twists: fn(&[f64], &[f64]) -> Vec<[f64; 6]>,
    /// `tip_twist(s)_local`.
    pub twists_local: fn(&[f64], &[f64]) -> Vec<[f64; 6]>,
    /// `tip_pose(s)_generic` on dual numbers seeded with the directions given.
    pub by_duals: DualJacobiansFn,
}

/// The random robots, compiled (`build/random_robots.rs` generates them).
pub mod random {
    use super::{RandomRobot, TraitConsts, Typed, Velocities, arr, batch, columns, dual, lanes, trait_consts};

    include!(concat!(env!("OUT_DIR"), "/random_robots.rs"));
}

include!(concat!(env!("OUT_DIR"), "/robots.rs"));
include!(concat!(env!("OUT_DIR"), "/derived.rs"));

/// Every robot in `robots/` derived with every option it takes (its tips with positions and
/// Jacobians; its deepest link's inverse kinematics; its collision checks), and one case for
/// each function those derives wrote (`build/stack_cases.rs`).
#[allow(clippy::expect_used, reason = "a case whose call fails is a failed test, which names it")]
pub mod stack {
    /// One generated function, called on inputs of the robot's lengths.
    pub struct StackCase {
        /// File name in `robots/`.
        pub robot: &'static str,
        /// `Struct::function`.
        pub function: &'static str,
        /// The bytes of the value the function holds in its widest lanes: its own value, one
        /// pack of a batch's outputs (`F64x8` for `f64`, `F32x8` for `f32`), a generic function's
        /// value in `F64x8` (the inverse kinematics and collision checks: none counted).
        pub value: usize,
        /// Makes the inputs and calls the function: a frame of its own.
        pub run: fn(),
    }

    include!(concat!(env!("OUT_DIR"), "/stack.rs"));
}
