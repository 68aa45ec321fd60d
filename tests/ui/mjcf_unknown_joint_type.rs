use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(mjcf = "../../../../tests/ui/fixtures/mjcf/unknown_joint_type.xml")]
struct Robot;

fn main() {}
