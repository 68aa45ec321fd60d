//! Generates the UR5's forward kinematics (`robots/ur5.urdf`, root to `tool0`) with the build
//! API, with its Jacobians and inverse kinematics, for `kinematics demo` to time against the runtime reference: the command cannot compile
//! Rust at run time, so the one robot it times is compiled in here.
//!
//! The description is `kinematics-cli/robots/ur5.urdf`, the crate's own copy of the workspace's
//! `robots/ur5.urdf`, so the published package builds alone; `tests/package.rs` keeps them equal.
//! The code is generated into `ur5.rs`.

fn main() -> Result<(), kinematics_build::BuildError> {
    // The crate's own copy of the workspace's `robots/ur5.urdf` (a test keeps them equal): a
    // published package cannot reach files outside its directory.
    kinematics_build::Robot::urdf("robots/ur5.urdf")
        .tip("tool0")
        .jacobians()
        .ik()
        .struct_name("Ur5")
        .write_to_out_dir("ur5.rs")?;
    Ok(())
}
