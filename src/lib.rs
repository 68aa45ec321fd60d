//! Forward kinematics for robots, from a URDF file or a Denavit-Hartenberg table, compiled to
//! closed-form Rust.
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

pub use kinematics_derive::Kinematics;
pub use kinematics_model as model;
pub use kinematics_model::{ExactAngles, KinematicTree, LoadError, LoadErrorKind};
pub use kinematics_runtime as runtime;
pub use kinematics_runtime::{
    AGREEMENT_TOLERANCE, AGREEMENT_TOLERANCE_F32, Configurations, JointLimits, Kinematics, Pose, Real, ReferenceFk,
    RuntimeError,
};

/// Reads and validates a robot description file: `.urdf`/`.xml` (URDF), `.toml` or `.json` (DH table).
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
pub fn load_with(path: impl AsRef<std::path::Path>, exact_angles: ExactAngles) -> Result<KinematicTree, LoadError> {
    let path = path.as_ref();
    let label = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|e| LoadError::new(label.clone(), LoadErrorKind::Io(e)))?;
    kinematics_model::Source::from_bytes(label, kinematics_model::SourceKind::ByExtension, bytes)?.load(exact_angles)
}
