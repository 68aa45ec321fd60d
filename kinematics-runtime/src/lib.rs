//! Reference forward kinematics and geometric Jacobians, written directly from the conventions in
//! the project's reference notes with nalgebra's own types.
//!
//! This crate is the independent witness that judges the compiler: it shares the validated model
//! ([`kinematics_model::KinematicTree`]) with it and nothing else. Every rotation here comes from
//! nalgebra (`UnitQuaternion::from_axis_angle`), every composition is an `Isometry3` product; no
//! symbolic or hand-expanded transform code lives here.
//!
//! ```
//! use kinematics_model::parse_source;
//! use kinematics_runtime::ReferenceFk;
//!
//! let dh = r#"
//! convention = "standard"
//! [[joints]]
//! name = "shoulder"
//! a = 1.0
//! [[joints]]
//! name = "elbow"
//! a = 1.0
//! "#;
//! let fk = ReferenceFk::new(parse_source("planar_2r.toml", dh)?);
//! let tip = fk.link_pose(&[std::f64::consts::FRAC_PI_2, 0.0], "link2")?;
//! assert!((tip.translation.vector - nalgebra::Vector3::new(0.0, 2.0, 0.0)).norm() < 1e-12);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! `ReferenceFk` is the reference forward kinematics over the tree (`fk.rs`) and the geometric
//! Jacobian (`jacobian.rs`), all with nalgebra's `Isometry3`, `UnitQuaternion` and `Translation3`.
//! The crate re-exports the core's `Pose`, `Real`, `Kinematics` and tolerances.

mod collision;
mod compiled;
mod dynamics;
mod error;
mod fk;
mod jacobian;
mod sample;
mod scene;

pub use collision::ReferenceObstacles;
pub use compiled::ReferenceModel;
pub use dynamics::{DynamicsError, ReferenceDynamics};
pub use error::RuntimeError;
pub use fk::{ReferenceFk, fixed_isometry};
pub use kinematics_core::{
    AGREEMENT_TOLERANCE, AGREEMENT_TOLERANCE_F32, JointLimits, Kinematics, KinematicsError, Pose, Real, check_output,
    q_array,
};
pub use kinematics_model;
pub use sample::{Configurations, SPECIAL_ANGLES};
pub use scene::SceneObstacles;
