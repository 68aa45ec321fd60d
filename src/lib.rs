//! Forward kinematics for robots, from a URDF file or a Denavit-Hartenberg table.
//!
//! One dependency for users: this crate re-exports the model ([`model`]: descriptions and the
//! validated [`KinematicTree`]) and the runtime reference ([`runtime`]: [`ReferenceFk`], poses and
//! Jacobians on nalgebra), and adds [`load`], which reads a description file.
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
pub use kinematics_model::{KinematicTree, LoadError, LoadErrorKind};
pub use kinematics_runtime as runtime;
pub use kinematics_runtime::{JointLimits, Kinematics, Pose, Real, ReferenceFk, RuntimeError};

/// Reads and validates a robot description file: `.urdf`/`.xml` (URDF), `.toml` or `.json` (DH table).
///
/// Errors name the file as given, the element (joint, link, DH row) and the fault.
pub fn load(path: impl AsRef<std::path::Path>) -> Result<KinematicTree, LoadError> {
    let path = path.as_ref();
    let label = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| LoadError::new(label.clone(), LoadErrorKind::Io(e)))?;
    kinematics_model::parse_source(&label, &text)
}
