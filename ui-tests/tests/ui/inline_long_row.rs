use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(dh(convention = "standard", row("shoulder", 1.0, 0.0, 0.0, 0.0, -1.0), row("elbow", 1.0, 0.0, 0.0, 0.0)))]
struct Robot;

fn main() {}
