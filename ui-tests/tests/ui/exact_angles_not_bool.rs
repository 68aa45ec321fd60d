use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(dh(convention = "standard", row("shoulder", 1.0, 0.0, 0.0, 0.0)), exact_angles = "off")]
struct Robot;

fn main() {}
