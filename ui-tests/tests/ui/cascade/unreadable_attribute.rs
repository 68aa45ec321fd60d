// An attribute darling cannot read (a value of the wrong type) beside a missing file: the stub
// still has the functions the attribute names, so the calls below add no error.
use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(urdf = "robots/no_such_robot.urdf", tips("a", "b"), positions = "yes", scalars(f64, f32))]
struct Robot;

fn main() {
    let q = [0.0; 2];
    let [a, b] = Robot::tip_poses(&q);
    let [p, _] = Robot::tip_positions_f32(&[0.0f32; 2]);
    // The links' count is the description's, which was not read: any length written down checks.
    let links: [[f64; 3]; 4] = Robot::link_positions(&q);
    let _ = (a.translation, b.rotation, p, links.len());
}
