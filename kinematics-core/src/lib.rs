//! What generated forward kinematics needs at run time, and nothing else: `#![no_std]`, no
//! allocation, no dependency but `libm` (itself `no_std`, for arguments beyond our sin/cos's fast
//! range).
//!
//! It holds the pose type ([`Pose`]), the scalar trait generated code is generic over ([`Real`]),
//! the trait every compiled robot implements ([`Kinematics`]) with its error ([`KinematicsError`]),
//! our own sin/cos ([`trig`]), the SIMD lane types ([`F64x4`], [`F32x8`]), the batch driver
//! ([`batch`]) and inverse kinematics at run time ([`ik`]: subproblems, closed-form families,
//! the numeric solver). Generated code reaches it through one path, `kinematics::__private` (the facade
//! re-exports this crate there), so a user's crate needs only the `kinematics` dependency.
//!
//! Features: `std` adds [`StdTrig`] (the platform's `sin_cos`, for code generated with
//! `trig = "std"`); `nalgebra` adds conversions of [`Pose`] to nalgebra's types and the pose
//! distance the agreement checks use. The facade's default `std` feature turns both on.
//!
//! Without features it depends on `libm` only; nalgebra comes with the `nalgebra` feature and pulp
//! with `dispatch`, both of which need `std`. Depended on by: the facade (always), the runtime, and through the
//! facade every generated function. It depends on nothing else of ours.
#![no_std]
// docs.rs builds with `--cfg docsrs` on nightly (`package.metadata.docs.rs` in Cargo.toml); there
// `doc_cfg` badges each feature-gated item with the feature it needs (nightly folded the former
// `doc_auto_cfg` into `doc_cfg`, rust-lang/rust#138907).
#![cfg_attr(docsrs, feature(doc_cfg))]

// The unit tests use `std` (vectors, cells) whatever the features: a test build links it anyway.
#[cfg(any(feature = "std", test))]
extern crate std;

mod batch;
pub mod collision;
mod dispatch;
pub mod dynamics;
mod error;
mod floating;
pub mod ik;
mod kinematics;
mod lanes;
#[cfg(feature = "nalgebra")]
mod nalgebra;
mod orientation;
mod pose;
mod real;
mod splitmix;
pub mod trig;

pub use batch::{Input, Inputs, Packable, any_wide, batch, batch_columns, batch_inputs, batch_wide};
pub use dispatch::{dispatch, dispatched_level};
pub use error::KinematicsError;
pub use floating::quaternion_matrix;
pub use kinematics::{JointLimits, Kinematics, check_output, q_array};
pub use lanes::{F32x8, F32x16, F64x4, F64x8, LaneValue, Lanes};
pub use orientation::OrientationError;
pub use pose::{AGREEMENT_TOLERANCE, AGREEMENT_TOLERANCE_F32, Pose};
#[cfg(feature = "std")]
pub use real::StdTrig;
pub use real::{BLOCK_MARK_OPS, Real, chunk};
