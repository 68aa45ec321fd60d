//! Forward kinematics generated at build time by `kinematics-build` (see `build.rs`), the
//! alternative to `#[derive(Kinematics)]` for code you want to read as a file or keep out of
//! macro expansion. The structs below are exactly what the derive would generate for the same
//! options; `tests/agreement.rs` checks them against the runtime reference and the derive.
//!
//! ```
//! use kinematics_build_example::Ur5;
//! let q = [0.3, -1.2, 1.0, 0.4, -0.7, 2.0];
//! let flange = Ur5::tip_pose(&q); // pose of `tool0` in `base`
//! assert_eq!(Ur5::tip_position(&q), flange.translation);
//! assert_eq!(Ur5::TIPS, ["tool0"]);
//! ```
//!
//! `build.rs` generates the UR5 and the Panda with the build API; this file `include!`s them. Being
//! a workspace member, its generated code goes through the workspace's clippy run.

include!(concat!(env!("OUT_DIR"), "/ur5.rs"));
include!(concat!(env!("OUT_DIR"), "/panda.rs"));
include!(concat!(env!("OUT_DIR"), "/ur5_ik.rs"));
include!(concat!(env!("OUT_DIR"), "/planar_3r.rs"));
include!(concat!(env!("OUT_DIR"), "/ur5_spheres.rs"));
include!(concat!(env!("OUT_DIR"), "/ur5_dynamics.rs"));
