use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(dh(convention = "craigs", joint(name = "shoulder", a = 1.0)))]
struct Robot;

fn main() {}
