use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(urdf = "../../../../ui-tests/tests/ui/fixtures/malformed.urdf")]
struct Robot;

fn main() {}
