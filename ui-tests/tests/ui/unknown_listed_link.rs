use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", links = ["wrist_3_link", "tool9"])]
struct Robot;

fn main() {}
