//! Robot descriptions and the validated kinematic tree.
//!
//! This crate owns the first two stages of the pipeline: *description* (reading a URDF document, an
//! MJCF document or a Denavit-Hartenberg table from text into a [`Description`]) and *model* (checking that description
//! against every rule and building a [`KinematicTree`] that is valid by construction: one root, no
//! cycles, unit axes, finite numbers, mimic joints resolved to their independent source). It does no
//! file IO (an MJCF file's includes come through the caller's [`mjcf::ReadFile`]) and no numeric
//! transform math beyond writing MJCF's orientations as elementary rotations: the runtime reference (`kinematics-runtime`) and the
//! compiler both start from the tree built here, and neither shares the other's math.
//!
//! ```
//! use kinematics_model::{parse_source, KinematicTree};
//!
//! let urdf = r#"<robot name="pendulum">
//!   <link name="base"/> <link name="bob"/>
//!   <joint name="swing" type="continuous">
//!     <parent link="base"/> <child link="bob"/> <axis xyz="0 0 2"/>
//!   </joint>
//! </robot>"#;
//! let tree: KinematicTree = parse_source("pendulum.urdf", urdf)?;
//! assert_eq!(tree.dof(), 1);
//! assert_eq!(tree.joint_by_name("swing").map(|j| j.axis), Some([0.0, 0.0, 1.0]));
//! # Ok::<(), kinematics_model::LoadError>(())
//! ```
// docs.rs builds with `--cfg docsrs` on nightly (`package.metadata.docs.rs` in Cargo.toml); there
// `doc_cfg` badges each feature-gated item with the feature it needs (nightly folded the former
// `doc_auto_cfg` into `doc_cfg`, rust-lang/rust#138907).
#![cfg_attr(docsrs, feature(doc_cfg))]

mod angle;
pub mod collision;
mod description;
pub mod dh;
mod error;
pub mod exactness;
mod frame;
pub mod inertia;
mod joint;
pub mod mjcf;
pub mod scene;
mod source;
pub mod srdf;
mod suggest;
pub mod synthetic;
mod transform;
mod tree;
pub mod urdf;
#[cfg(feature = "urdf-rs")]
mod urdf_rs_interop;
mod validate;

pub use angle::{Angle, PiRational};
pub use description::{
    CollisionDescription, Description, ExcludedPair, FLOATING_BASE_JOINT, InertialDescription, JointDescription,
    JointTypeDescription, LimitsDescription, MimicDescription,
};
pub use error::{Element, LoadError, LoadErrorKind, ModelError, ModelErrors, SeveralValues, UnknownLink};
pub use exactness::{ExactAngles, RecognisedAngle};
pub use frame::JacobianFrame;
pub use joint::{Joint, JointKind, JointMotion, Limits, Link};
pub use source::{
    Source, SourceFormat, SourceKind, parse_source, parse_source_files, parse_source_floating, parse_source_with,
};
pub use suggest::closest;
pub use transform::{Axis, Elementary, FixedTransform};
pub use tree::{Chain, JointId, KinematicTree, LinkId, MeshLoadError};
/// The urdf-rs this crate converts from (feature `urdf-rs`: [`Description::from_urdf_rs`],
/// [`KinematicTree::from_urdf_rs`]), for callers without a dependency of their own.
#[cfg(feature = "urdf-rs")]
#[cfg_attr(docsrs, doc(cfg(feature = "urdf-rs")))]
pub use urdf_rs;
