use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(urdf = 5)]
struct Robot;

fn main() {}
