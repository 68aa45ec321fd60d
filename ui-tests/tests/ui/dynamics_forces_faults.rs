use kinematics::Kinematics;

// A link the robot does not have (with the name it likely meant), a link named twice, the root
// and a link fixed to it (no joint moves them): each fault on its own string.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", dynamics(forces("wrist_3_lnk", "tool0", "tool0", "base_link", "base")))]
struct Ur5Forces;

// Not a list of link names.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", dynamics(forces = "tool0"))]
struct ForcesValue;

// A bare word.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", dynamics(forces))]
struct ForcesWord;

fn main() {
    // The stub keeps the functions with forces, one force per link named: no cascade.
    let _ = Ur5Forces::inverse_dynamics_with_forces(&[0.0; 6], &[0.0; 6], &[0.0; 6], &[[0.0; 6]; 5]);
    let _ = Ur5Forces::forward_dynamics_with_forces(&[0.0; 6], &[0.0; 6], &[0.0; 6], &[[0.0; 6]; 5]);
    let _: [&str; 5] = Ur5Forces::FORCE_LINKS;
}
