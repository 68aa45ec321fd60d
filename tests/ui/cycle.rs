use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(urdf = "../../../../tests/ui/fixtures/cycle.urdf")]
struct Robot;

fn main() {}
