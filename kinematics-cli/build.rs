//! Generates the code `kinematics demo` times against the runtime reference, with the build API:
//! the command cannot compile Rust at run time, so the robots it times are compiled in here.
//!
//! - `ur5.rs`: the UR5's forward kinematics (`robots/ur5.urdf`, root to `tool0`), with its
//!   Jacobians, inverse kinematics and dynamics;
//! - `panda.rs`: VAMP's spherized Panda (`robots/panda_spherized.urdf`) with collision checking,
//!   its self-collision pairs less those `robots/panda.srdf` disables, in `f64` and `f32`.
//!
//! The files under `robots/` are the crate's own copies of the workspace's, so the published
//! package builds alone; `tests/package.rs` keeps them equal.

// Boxed: the build error is large, and `?` boxes it.
fn main() -> Result<(), Box<kinematics_build::BuildError>> {
    // The crate's own copies of the workspace's robots (a test keeps them equal): a published
    // package cannot reach files outside its directory.
    kinematics_build::Robot::urdf("robots/ur5.urdf")
        .tip("tool0")
        .jacobians()
        .ik()
        .dynamics()
        .struct_name("Ur5")
        .write_to_out_dir("ur5.rs")?;
    kinematics_build::Robot::urdf("robots/panda_spherized.urdf")
        .collision()
        .srdf("robots/panda.srdf")
        .f32()
        .struct_name("Panda")
        .write_to_out_dir("panda.rs")?;
    Ok(())
}
