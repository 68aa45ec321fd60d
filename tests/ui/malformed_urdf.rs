use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(urdf = "../../../../tests/ui/fixtures/malformed.urdf")]
struct Robot;

fn main() {}
