//! Generates the UR5's and the Panda's forward kinematics into `OUT_DIR`, for `src/lib.rs` to
//! `include!`. A fault in a description fails the build with its message (the file, the element
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
    Ok(())
}
