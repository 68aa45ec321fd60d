//! A user binary built with the facade's default features off: it prints one tool position.
//! `tests/no_std.rs` looks through this binary for code of the crates it must not contain.

fn main() {
    let q = [0.3, -1.2, 1.0, 0.4, -0.7, 2.0];
    let [x, y, z] = kinematics_no_std_example::tool_position(&q);
    println!("UR5 tool0 at q = {q:?}: ({x:.6}, {y:.6}, {z:.6}) m");
    let target = kinematics_no_std_example::tool_pose(&q);
    match kinematics_no_std_example::tool_ik(&target) {
        Ok(solutions) => println!("{} exact inverse kinematics solutions of that pose", solutions.exact().count()),
        Err(e) => println!("inverse kinematics refused the pose: {e}"),
    }
}
