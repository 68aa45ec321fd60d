use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(urdf = 5, dhh = "robots/ur5.toml", positions = "yes", scalars(f16))]
struct Robot;

fn main() {}
