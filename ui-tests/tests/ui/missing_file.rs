use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(urdf = "robots/no_such_robot.urdf")]
struct Robot;

fn main() {}
