use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(dh(convention = "standard", row("shoulder", 0.0, 0.0, "0.089159", 0.0), row("elbow", -0.425, 0.0, 0.0, 0.0)))]
struct Robot;

fn main() {}
