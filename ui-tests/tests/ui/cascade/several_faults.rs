// Several faults of different kinds at once (an unknown base, an unknown tip, a bad scalar type):
// every one is reported, and none cascades.
use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", base = "bsae", tips("tool9", "wrist_3_link"), scalars(f16, f32))]
struct Robot;

fn main() {
    let q = [0.0f32; 6];
    let [a, b] = Robot::tip_poses_f32(&q);
    let _ = (a.translation, b.rotation, <Robot as Kinematics>::TIPS);
}
