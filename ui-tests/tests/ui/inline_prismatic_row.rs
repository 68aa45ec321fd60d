use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(dh(convention = "standard", row("lift", 0.0, 0.0, 0.0, 0.0), row("slide", "prismatic", 0.0, "pi/2", 0.1, 0.0, "-pi", 0.5)))]
struct Robot;

fn main() {}
