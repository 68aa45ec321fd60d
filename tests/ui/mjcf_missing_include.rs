use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(mjcf = "../../../../tests/ui/fixtures/mjcf/missing_include.xml")]
struct Robot;

fn main() {}
