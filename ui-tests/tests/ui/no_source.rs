use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(tip = "tool0")]
struct Robot;

fn main() {}
