use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(dh(convention = "standard", joint(name = "shoulder", a = "1.0"), joint(name = "elbow", a = 1.0)))]
struct Robot;

fn main() {}
