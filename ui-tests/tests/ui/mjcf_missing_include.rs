use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(mjcf = "../../../../ui-tests/tests/ui/fixtures/mjcf/missing_include.xml")]
struct Robot;

fn main() {}
