use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(dhh = "robots/ur5.toml")]
struct Robot;

fn main() {}
