use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(urdf = "../../../../ui-tests/tests/ui/fixtures/cycle.urdf")]
struct Robot;

fn main() {}
