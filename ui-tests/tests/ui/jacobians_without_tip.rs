use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", jacobians)]
struct Ur5;

#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", tip = "tool9", jacobians, positions)]
struct Misspelt;

fn main() {
    // The stub beside the error keeps the velocity functions: no cascade.
    let q = [0.0; 6];
    let _ = Misspelt::tip_jacobian(&q);
    let _ = Misspelt::tip_jacobian_local(&q);
    let _ = Misspelt::tip_pose_and_jacobian(&q);
    let _ = Misspelt::tip_position_jacobian(&q);
    let _ = Misspelt::tip_twist(&q, &q);
    let _ = Misspelt::tip_twist_local_generic(&[kinematics::F64x4::splat(0.0); 6], &[kinematics::F64x4::splat(0.0); 6]);
    let mut out = [[[0.0; 6]; 6]];
    let _ = Misspelt::tip_jacobian_batch(&[q], &mut out);
    let _ = Ur5::link_poses(&q);
}
