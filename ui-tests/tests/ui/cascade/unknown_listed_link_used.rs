// One fault (a misspelt entry of `links`) and code that uses the struct: only the fault is
// reported, and `link_poses` still returns as many poses as `links` lists.
use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", links = ["tool0", "wrist3_link"], positions)]
struct Robot;

fn main() {
    let q = [0.0; 6];
    let poses: [kinematics::Pose<f64>; 2] = Robot::link_poses(&q);
    let positions: [[f64; 3]; 2] = Robot::link_positions(&q);
    let _ = (poses, positions, Robot::LINK_NAMES.len());
}
