//! A firmware-style user of `kinematics`: `#![no_std]`, no allocator, the facade's default
//! features off. It derives the UR5 from `robots/ur5.urdf` and computes the tool pose, the tool
//! position, a batch of poses and every inverse kinematics solution of a pose, with our own
//! sin/cos (and `libm`'s inverse trigonometry) and nothing else at run time.
//!
//! `tests/no_std.rs` builds this crate on its own (so its features are not unified with the rest
//! of the workspace's) and checks, with `cargo tree`, that it depends on no crate that needs
//! `std`, and that the binary `src/main.rs` contains no XML, TOML, JSON or nalgebra code.
#![no_std]

use kinematics::ik::{IkError, IkSolutions};
use kinematics::{Kinematics, Pose};

/// The UR5, base to tool flange.
#[derive(Kinematics)]
#[kinematics(urdf = "../../robots/ur5.urdf", base = "base_link", tip = "tool0", positions, ik)]
pub struct Ur5;

/// The tool pose at `q`.
pub fn tool_pose(q: &[f64; 6]) -> Pose<f64> {
    Ur5::tip_pose(q)
}

/// The tool position at `q`.
pub fn tool_position(q: &[f64; 6]) -> [f64; 3] {
    Ur5::tip_position(q)
}

/// Tool poses of a batch of configurations into `out` (no allocation: the caller owns both).
pub fn tool_poses(qs: &[[f64; 6]], out: &mut [Pose<f64>]) -> Result<(), kinematics::KinematicsError> {
    Ur5::tip_pose_batch(qs, out)
}

/// Every joint configuration that puts the tool at `target` (eight branches, no heap).
pub fn tool_ik(target: &Pose<f64>) -> Result<IkSolutions<6, 8>, IkError> {
    Ur5::tip_ik(target)
}
