//! Generates the UR5's and the Panda's forward kinematics into `OUT_DIR` (and, for the lints,
//! inverse kinematics, collision and dynamics), for `src/lib.rs` to `include!`. A fault in a description fails the build with its message (the file, the element
//! and what is wrong).

use kinematics_build::{BuildError, Robot};

fn main() -> Result<(), BuildError> {
    Robot::urdf("../../robots/ur5.urdf")
        .base("base")
        .tip("tool0")
        .positions()
        .struct_name("Ur5")
        .write_to_out_dir("ur5.rs")?;
    Robot::urdf("../../robots/panda.urdf")
        .base("panda_link0")
        .tips(["panda_hand_tcp", "panda_leftfinger", "panda_rightfinger"])
        .positions()
        .f32()
        .struct_name("Panda")
        .write_to_out_dir("panda.rs")?;
    // The other kinds of generated item, so that the workspace's clippy (which does not lint what
    // a derive expands to) lints the code a build script writes into a user's crate: inverse
    // kinematics compiled to branch lanes (the UR5) and measured at `q` (a planar arm), each with
    // the numeric solver; Jacobians; collision checks and distances; the dynamics, in both scalars.
    Robot::urdf("../../robots/ur5.urdf")
        .tip("tool0")
        .jacobians()
        .ik()
        .struct_name("Ur5Ik")
        .write_to_out_dir("ur5_ik.rs")?;
    Robot::dh("../../robots/planar_3r.toml")
        .tip("link3")
        .ik()
        .struct_name("Planar3")
        .write_to_out_dir("planar_3r.rs")?;
    Robot::urdf("../../robots/ur5_spherized.urdf")
        .collision()
        .struct_name("Ur5Spheres")
        .write_to_out_dir("ur5_spheres.rs")?;
    Robot::urdf("../../robots/ur5.urdf")
        .dynamics()
        .gravity([0.5, 0.0, -9.81])
        .f32()
        .struct_name("Ur5Dynamics")
        .write_to_out_dir("ur5_dynamics.rs")?;
    Ok(())
}
