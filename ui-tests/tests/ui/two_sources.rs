use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", dh = "../../../../robots/ur5.toml")]
struct Robot;

fn main() {}
