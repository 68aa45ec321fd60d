use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(dh(convention = "standard", row("j", "1.0", 0.0, "0.5", 0.0)))]
struct Robot;

fn main() {}
