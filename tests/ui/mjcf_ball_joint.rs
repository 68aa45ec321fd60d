use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(mjcf = "../../../../tests/ui/fixtures/mjcf/ball_joint.xml")]
struct Robot;

fn main() {}
