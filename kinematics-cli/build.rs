//! Generates the UR5's forward kinematics (`robots/ur5.urdf`, root to `tool0`) with the build
//! API, with its Jacobians and inverse kinematics, for `kinematics demo` to time against the runtime reference: the command cannot compile
//! Rust at run time, so the one robot it times is compiled in here.

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
