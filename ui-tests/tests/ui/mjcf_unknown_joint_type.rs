use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(mjcf = "../../../../ui-tests/tests/ui/fixtures/mjcf/unknown_joint_type.xml")]
struct Robot;

fn main() {}
