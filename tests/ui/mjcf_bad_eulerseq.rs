use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(mjcf = "../../../../tests/ui/fixtures/mjcf/bad_eulerseq.xml")]
struct Robot;

fn main() {}
