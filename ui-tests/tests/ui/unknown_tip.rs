use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", tip = "tool9")]
struct Robot;

fn main() {}
