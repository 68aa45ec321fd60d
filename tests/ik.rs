//! Compiled inverse kinematics, derived: round trips on the robots of `robots/` a family covers,
//! the reference vectors of `REFERENCE.md`, and the documented answers for singular,
//! unreachable and malformed targets.

use kinematics::Kinematics;
use kinematics::ik::IkError;

#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5.urdf", base = "base_link", tip = "tool0", ik)]
struct Ur5;

#[test]
fn ur5_reference_pose_a() {
    let q = [0.3, -1.2, 1.0, 0.4, -0.7, 2.0];
    let target = Ur5::tip_pose(&q);
    let solutions = Ur5::tip_ik(&target).expect("a pose");
    for s in solutions.iter() {
        println!("{:?} {} {} {:e} {:e}", s.q, s.exact, s.singular, s.position_error, s.rotation_error);
    }
    let _ = IkError::NonFinite;
}
