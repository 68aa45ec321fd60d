use kinematics::Kinematics;

// Inverse kinematics of a robot with a spherical joint (an MJCF ball joint: a quaternion in `q`)
// is refused, closed form and numeric alike.
#[derive(Kinematics)]
#[kinematics(mjcf = "../../../../ui-tests/tests/ui/fixtures/mjcf/ball_joint.xml", tip = "link1", ik)]
struct ClosedForm;

#[derive(Kinematics)]
#[kinematics(mjcf = "../../../../ui-tests/tests/ui/fixtures/mjcf/ball_joint.xml", tip = "link1", ik = "numeric")]
struct Numeric;

fn main() {}
