use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(dh(convention = "standard", joint(name = "shoulder", a = 1.0, lower = -1.0, upper = 1.0, velocity = "2.5", effort = 150)))]
struct Robot;

fn main() {}
