use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(mjcf = "../../../../tests/ui/fixtures/mjcf/unnamed_body.xml")]
struct Robot;

fn main() {}
