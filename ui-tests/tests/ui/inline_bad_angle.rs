use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(dh(convention = "standard", joint(name = "shoulder", a = 1.0), joint(name = "elbow", alpha = "pie/2")))]
struct Robot;

fn main() {}
