// A description that cannot be read, and code calling the functions whose lengths only the
// description knows (issue 21): only the file's error, no "type annotations needed" where the
// links' count is not written down. Every length only the description knows is an error to rustc
// (see `missing_file_every_call.rs`), so nothing more is reported where it is used.
use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(urdf = "robots/no_such_robot.urdf", tip = "tool0", positions, jacobians, ik, scalars(f64, f32))]
struct Robot;

fn main() {
    let q = [0.0; 6];
    let poses = Robot::link_poses(&q);
    let first = poses[0].translation;
    let count = poses.len();
    for pose in Robot::link_poses(&q) {
        let _ = pose.rotation;
    }
    let positions = Robot::link_positions(&q);
    let near: Vec<f64> = positions.iter().map(|p| p[2]).collect();
    let same = Robot::link_poses_f32(&[0.0f32; 6]) == Robot::link_poses_f32(&[0.0f32; 6]);
    let lanes = Robot::link_poses_generic(&[0.0f64; 6]);
    let pose = Robot::tip_pose(&q);
    let jacobian = Robot::tip_jacobian(&q);
    let twist = Robot::tip_twist(&q, &q);
    let solutions = Robot::tip_ik(&pose).unwrap();
    let best = solutions.iter().map(|s| s.q).find(|s| *s == q);
    let numeric = Robot::tip_ik_numeric(&pose, &q).unwrap();
    let mut out = vec![[pose; 9]; 2];
    let _ = Robot::link_poses_batch(&[q, q], &mut out);
    let _ = (first, count, near, same, lanes.len(), jacobian[0][0], twist[0], best, numeric);
    let _ = <Robot as Kinematics>::DOF;
}
