// One fault (an unknown tip) and code that uses the struct: only the fault is reported, not
// "no function `tip_pose`" or "trait `Kinematics` not implemented" wherever the struct is used.
use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", tip = "tool9", positions)]
struct Robot;

fn reach<R: Kinematics>() -> usize {
    R::LINK_NAMES.len()
}

fn main() {
    let q = [0.0; 6];
    let pose = Robot::tip_pose(&q);
    let position: [f64; 3] = Robot::tip_position(&q);
    let _ = (pose.translation, position, Robot::DOF, Robot::JOINT_NAMES, reach::<Robot>());
    let _ = Robot::reference().map(|r| r.tree().dof());
}
