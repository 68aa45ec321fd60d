use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(mjcf = "../../../../ui-tests/tests/ui/fixtures/mjcf/unnamed_body.xml")]
struct Robot;

fn main() {}
