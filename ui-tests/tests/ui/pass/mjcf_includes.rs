// An MJCF file that includes others: the derive reads them relative to the file, and the
// generated `reference()` reads them from the text it embeds, so both see the same robot.

use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(mjcf = "../../../../ui-tests/tests/ui/fixtures/mjcf/with_include.xml", tip = "tcp")]
struct Arm;

fn main() {
    let q = [0.5];
    let pose = Arm::tip_pose(&q);
    let reference = Arm::reference().expect("the description and its includes load");
    let expected = reference.relative_pose(&q, Arm::BASE, "tcp").expect("finite");
    assert!((pose.to_isometry().translation.vector - expected.translation.vector).norm() < 1e-12);
    // The included default: a hinge about y limited to 90 degrees either way.
    assert_eq!(<Arm as kinematics::Kinematics>::JOINT_LIMITS[0].upper, std::f64::consts::FRAC_PI_2);
}
