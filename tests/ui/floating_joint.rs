use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(urdf = "../../../../tests/ui/fixtures/floating.urdf")]
struct Robot;

fn main() {}
