use kinematics::Kinematics;

// Seven joints and no free joint named: no closed form.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/iiwa14.urdf", tip = "iiwa_link_ee", ik)]
struct Iiwa;

// The elbow free: the rest is a degenerate arm.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/iiwa14.urdf", tip = "iiwa_link_ee", ik(free = "iiwa_joint_4"))]
struct IiwaElbow;

fn main() {
    // The stub beside the error keeps the inverse kinematics functions: no cascade.
    let target = Iiwa::tip_pose(&[0.0; 7]);
    let _ = Iiwa::tip_ik(&target);
    let _ = Iiwa::tip_ik_nearest(&target, &[0.0; 7]);
    let _ = Iiwa::tip_ik_numeric(&target, &[0.0; 7]);
    let _ = IiwaElbow::tip_ik(&target, 0.5);
}
