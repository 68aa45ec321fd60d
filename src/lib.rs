//! Robot kinematics compiled to closed-form Rust at build time, from a URDF file, an MJCF file or a
//! Denavit-Hartenberg table: the poses of the links (forward kinematics), their Jacobians and
//! velocities, inverse kinematics (closed forms for the arm families it recognises, and a numeric
//! solver), and collision checking on spheres (against obstacles, point clouds and the robot
//! itself, along straight motions, holding an object, with the clearance and its gradient). Each
//! comes for one configuration, in SIMD lanes and in batches, and is checked against a runtime
//! reference that shares none of the compiler's transform math. The guide (module `guide`, with
//! the `std` feature) starts with a short tutorial (`guide::tutorial`) and has a page per topic:
//! `guide::velocities`, `guide::inverse_kinematics`, `guide::collision` and more.
//!
//! Most users meet it as a derive:
//!
//! ```
//! use kinematics::Kinematics;
//!
//! #[derive(Kinematics)]
//! #[kinematics(urdf = "robots/ur5.urdf", base = "base", tip = "tool0", positions)]
//! pub struct Ur5;
//!
//! let q = [0.3, -1.2, 1.0, 0.4, -0.7, 2.0];
//! let pose = Ur5::tip_pose(&q);
//! assert_eq!(Ur5::tip_position(&q), pose.translation);
//! // Checked against the runtime reference built from the same file:
//! let reference = Ur5::reference()?.relative_pose(&q, "base", "tool0")?;
//! let iso: nalgebra::Isometry3<f64> = pose.into();
//! assert!((iso.translation.vector - reference.translation.vector).norm() < 1e-12);
//! assert_eq!(Ur5::link_poses(&q).len(), Ur5::LINK_NAMES.len());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! This crate is the one dependency users add: it re-exports the derive and its trait
//! ([`Kinematics`]), the model ([`model`]: descriptions and the validated [`KinematicTree`]) and
//! the runtime reference ([`runtime`]: [`ReferenceFk`], poses and Jacobians on nalgebra), and adds
//! [`load`] (and [`load_with`], with an exactness policy), which reads a description file.
//!
//! ```
//! let fk = kinematics::ReferenceFk::new(kinematics::load(concat!(env!("CARGO_MANIFEST_DIR"), "/robots/planar_3r.toml"))?);
//! let q = [30f64.to_radians(), -60f64.to_radians(), 20f64.to_radians()];
//! let tip = fk.link_pose(&q, "link3")?;
//! assert!((tip.translation.x - 2.224455).abs() < 1e-6 && (tip.translation.y + 0.086824).abs() < 1e-6);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Lanes and batches
//!
//! Every computation also comes as a batch over slices of configurations (four `f64` or eight
//! `f32` configurations per call inside, in SIMD lanes) and as a generic function the lane types
//! [`F64x4`] and [`F32x8`] run directly:
//!
//! ```
//! use kinematics::{F64x4, Kinematics, Pose};
//!
//! #[derive(Kinematics)]
//! #[kinematics(urdf = "robots/ur5.urdf", base = "base", tip = "tool0", scalars(f64, f32))]
//! pub struct Ur5;
//!
//! // A batch: array of structs in, array of structs out, no allocation inside.
//! let qs: Vec<[f64; 6]> = (0..1000).map(|i| [0.001 * i as f64, -1.2, 1.0, 0.4, -0.7, 2.0]).collect();
//! let mut poses = vec![Pose { rotation: [[0.0; 3]; 3], translation: [0.0; 3] }; qs.len()];
//! Ur5::tip_pose_batch(&qs, &mut poses)?;
//! assert_eq!(poses[999], Ur5::tip_pose(&qs[999]));
//!
//! // Lanes: four configurations in one call of the same generated code.
//! let q: [F64x4; 6] = std::array::from_fn(|j| F64x4::new([qs[0][j], qs[1][j], qs[2][j], qs[3][j]]));
//! let four = Ur5::tip_pose_generic(&q);
//! assert_eq!(four.translation[0].lane(2), Ur5::tip_pose(&qs[2]).translation[0]);
//! # Ok::<(), kinematics::KinematicsError>(())
//! ```
//!
//! # Features
//!
//! - `std` (default): the runtime reference, the model, file loading, nalgebra conversions of
//!   [`Pose`], `trig = "std"`, and batches that choose AVX2 at run time when the CPU has it (a
//!   plain build targets baseline x86-64). Without it the crate is `#![no_std]` and a derived robot needs
//!   nothing but [`kinematics_core`] (no allocation, no XML, TOML, JSON or nalgebra code).
//! - `rayon`: `parallel::batch`, batches split across cores.
//! - `urdf-rs`: `from_urdf_rs`, the model of a robot urdf-rs has read (as `k` and openrr hold
//!   it), by the same rules and exactness policy as [`load`].
//!
//! Generated code reaches what it needs through one path, `kinematics::__private` (hidden from
//! the docs, not for users: it may change with the code generator).
#![cfg_attr(
    feature = "std",
    doc = "\n# Guide\n\nNew here? The [`guide::tutorial`] goes from `cargo add` to a pose, its Jacobian, its \
           inverse and a collision check in a few small steps. The [`guide`] has the rest, one page per \
           topic: the derive's keys, velocities, \
           inverse kinematics, floating bases, exactness, trigonometry, lanes, `no_std`, errors, the \
           command line, build scripts, what the compiler emits, how it is checked, and every measured \
           figure with the command that measured it."
)]
#![cfg_attr(not(feature = "std"), no_std)]
// docs.rs builds with `--cfg docsrs` on nightly (`package.metadata.docs.rs` in Cargo.toml); there
// `doc_cfg` badges each feature-gated item with the feature it needs (nightly folded the former
// `doc_auto_cfg` into `doc_cfg`, rust-lang/rust#138907).
#![cfg_attr(docsrs, feature(doc_cfg))]

pub use kinematics_core::{
    AGREEMENT_TOLERANCE, AGREEMENT_TOLERANCE_F32, F32x8, F32x16, F64x4, F64x8, JointLimits, Kinematics,
    KinematicsError, LaneValue, Lanes, OrientationError, Pose, Real, collision, dispatch, dispatched_level, ik,
    quaternion_matrix, trig,
};
pub use kinematics_derive::Kinematics;

#[cfg(feature = "std")]
pub use kinematics_core::StdTrig;
#[cfg(feature = "std")]
pub use kinematics_model as model;
#[cfg(feature = "std")]
pub use kinematics_model::{ExactAngles, KinematicTree, LoadError, LoadErrorKind};
#[cfg(feature = "std")]
pub use kinematics_runtime as runtime;
#[cfg(feature = "std")]
pub use kinematics_runtime::{Configurations, ReferenceFk, ReferenceModel, RuntimeError};

#[cfg(feature = "rayon")]
#[cfg_attr(docsrs, doc(cfg(feature = "rayon")))]
pub mod parallel;

// Documentation only, as clap ships `_derive` and `_tutorial`: docs.rs renders the pages and
// `cargo test --doc` runs their examples, most of which need `std` (the reference, file loading).
#[cfg(feature = "std")]
#[cfg_attr(docsrs, doc(cfg(feature = "std")))]
pub mod guide;

/// What generated code calls: the core crate, and with `std` the loader and the reference.
/// Not for users; it changes with the code generator.
#[doc(hidden)]
pub mod __private {
    pub use crate::__kinematics_with_std as with_std;
    pub use kinematics_core::*;
    #[cfg(feature = "std")]
    pub use kinematics_model::{
        ExactAngles, LoadError, LoadErrorKind, parse_source_files, parse_source_floating, parse_source_with,
    };
    #[cfg(feature = "std")]
    pub use kinematics_runtime::{ReferenceFk, ReferenceModel};
}

/// Its input with the `std` feature, nothing without: generated code wraps `reference()` in it.
#[cfg(feature = "std")]
#[doc(hidden)]
#[macro_export]
macro_rules! __kinematics_with_std {
    ($($code:tt)*) => { $($code)* };
}

/// Its input with the `std` feature, nothing without: generated code wraps `reference()` in it.
#[cfg(not(feature = "std"))]
#[doc(hidden)]
#[macro_export]
macro_rules! __kinematics_with_std {
    ($($code:tt)*) => {};
}

#[cfg(feature = "std")]
#[cfg_attr(docsrs, doc(cfg(feature = "std")))]
pub use kinematics_runtime::SceneObstacles;

#[cfg(feature = "std")]
#[cfg_attr(docsrs, doc(cfg(feature = "std")))]
/// Reads a scene file (`.toml` or `.json`: obstacles with poses and sizes, the format on the
/// guide's collision page) into the obstacles a compiled robot's `collides` is checked against.
///
/// Errors name the file, the obstacle (its number, its name, in TOML its line) and the fault.
///
/// ```
/// let file = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/tabletop.toml");
/// let scene = kinematics::load_scene(file)?;
/// assert_eq!((scene.boxes.len(), scene.names[0].as_str()), (12, "table"));
/// let environment = scene.environment()?;
/// assert!(environment.hits([0.6, 0.0, 0.0], 0.01)); // on the table
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn load_scene(path: impl AsRef<std::path::Path>) -> Result<SceneObstacles, LoadError> {
    Ok(SceneObstacles::from_scene(&read_scene(path)?))
}

#[cfg(feature = "std")]
#[cfg_attr(docsrs, doc(cfg(feature = "std")))]
/// Reads a scene file as written (each obstacle's name, shape, `xyz` and `rpy`), its format by its
/// extension; [`load_scene`] turns it into obstacles.
pub fn read_scene(path: impl AsRef<std::path::Path>) -> Result<model::scene::Scene, LoadError> {
    use kinematics_model::scene::{SceneFormat, parse_scene};
    let path = path.as_ref();
    let file = path.display().to_string();
    let Some(format) = SceneFormat::from_file_name(&file) else {
        let message = "a scene file is .toml or .json".to_owned();
        return Err(LoadError::new(file, LoadErrorKind::Syntax { line: None, message }));
    };
    let text = std::fs::read_to_string(path).map_err(|e| LoadError::new(&file, LoadErrorKind::Io(e)))?;
    parse_scene(&text, format).map_err(|kind| LoadError::new(file, kind))
}

#[cfg(feature = "std")]
#[cfg_attr(docsrs, doc(cfg(feature = "std")))]
/// Reads and validates a robot description file: `.urdf` (URDF), `.xml` (URDF or MJCF, as its root
/// element says), `.mjcf`, `.toml` or `.json` (DH table). The files an MJCF file names (`<include>`,
/// `<model file>`) are read relative to its directory.
///
/// Errors name the file as given, the element (joint, link, DH row) and the fault. Decimal angles
/// are read by the default exactness policy ([`ExactAngles::default`]); [`load_with`] takes
/// another.
pub fn load(path: impl AsRef<std::path::Path>) -> Result<KinematicTree, LoadError> {
    load_with(path, ExactAngles::default())
}

/// [`load`] with the exactness policy `exact_angles` (`ExactAngles::Off` reads every angle as
/// written): the file's bytes through the model's one loader, [`model::Source::load`].
///
/// ```
/// use kinematics::ExactAngles;
/// let file = concat!(env!("CARGO_MANIFEST_DIR"), "/robots/ur5.urdf");
/// let on = kinematics::load_with(file, ExactAngles::default())?;
/// let off = kinematics::load_with(file, ExactAngles::Off)?;
/// assert_eq!(on.dof(), off.dof());
/// assert!(off.recognised_angles().is_empty());
/// # Ok::<(), kinematics::LoadError>(())
/// ```
#[cfg(feature = "std")]
#[cfg_attr(docsrs, doc(cfg(feature = "std")))]
pub fn load_with(path: impl AsRef<std::path::Path>, exact_angles: ExactAngles) -> Result<KinematicTree, LoadError> {
    let path = path.as_ref();
    let label = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|e| LoadError::new(label.clone(), LoadErrorKind::Io(e)))?;
    let source = kinematics_model::Source::from_bytes(label, kinematics_model::SourceKind::ByExtension, bytes)?;
    // MJCF's `<include>` and `<model file>` paths are relative to the main file's directory.
    let dir = path.parent().map(std::path::Path::to_path_buf).unwrap_or_default();
    let read = move |file: &str| std::fs::read_to_string(dir.join(file)).map_err(|e| e.to_string());
    source.load_reading(exact_angles, None, &read)
}

/// The validated tree of a robot urdf-rs has read (`urdf_rs::read_file`, or the robot `k` and
/// openrr hand around), by the rules and the exactness policy [`load`] applies to a file
/// ([`KinematicTree::from_urdf_rs`]; [`from_urdf_rs_with`] takes another policy). Errors name the
/// joint or link; urdf-rs keeps no lines. The same file gives the same tree either way, so the
/// runtime reference and the compiler see the same robot:
///
/// ```
/// use kinematics::model::urdf_rs;
/// let file = concat!(env!("CARGO_MANIFEST_DIR"), "/robots/ur5.urdf");
/// let robot = urdf_rs::read_file(file)?; // what a user of `k` already holds
/// let tree = kinematics::from_urdf_rs(&robot)?;
/// let q = [0.3, -1.2, 1.0, 0.4, -0.7, 2.0];
/// let pose = kinematics::ReferenceFk::new(tree.clone()).link_pose(&q, "tool0")?;
/// let built_in = kinematics::ReferenceFk::new(kinematics::load(file)?).link_pose(&q, "tool0")?;
/// assert_eq!(pose, built_in);
/// // The compiler takes the tree too (`kinematics-compiler`, beside the derive).
/// let compiled = kinematics_compiler::compile(&tree, &kinematics_compiler::Request::tip("tool0"))?;
/// let entries = compiled.eval(&q)[0];
/// assert!((0..3).all(|i| (entries[9 + i] - pose.translation.vector[i]).abs() < 1e-12));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[cfg(feature = "urdf-rs")]
#[cfg_attr(docsrs, doc(cfg(feature = "urdf-rs")))]
pub fn from_urdf_rs(robot: &kinematics_model::urdf_rs::Robot) -> Result<KinematicTree, LoadErrorKind> {
    from_urdf_rs_with(robot, ExactAngles::default())
}

/// [`from_urdf_rs`] with the exactness policy `exact_angles`.
#[cfg(feature = "urdf-rs")]
#[cfg_attr(docsrs, doc(cfg(feature = "urdf-rs")))]
pub fn from_urdf_rs_with(
    robot: &kinematics_model::urdf_rs::Robot,
    exact_angles: ExactAngles,
) -> Result<KinematicTree, LoadErrorKind> {
    KinematicTree::from_urdf_rs(robot, exact_angles)
}

/// Every Rust example in the README, run as a doctest (`cargo test --doc`), so the README's code
/// stays code that compiles and passes (examples that need a build script are marked `ignore`).
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
