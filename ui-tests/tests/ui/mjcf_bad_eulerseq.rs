use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(mjcf = "../../../../ui-tests/tests/ui/fixtures/mjcf/bad_eulerseq.xml")]
struct Robot;

fn main() {}
