use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", tip = "tool0", trig = "libm")]
struct Ur5;

// A misspelt word: the choices, and the one meant.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", tip = "tool0", trig = "sdt")]
struct Misspelt;

// Not a word at all.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", tip = "tool0", trig = 1)]
struct NotAWord;

fn main() {
    // The stub beside the error keeps the batch and generic functions: no cascade.
    let q = [0.0; 6];
    let _ = Ur5::tip_pose(&q);
    let _ = Ur5::tip_pose_generic(&[kinematics::F64x4::splat(0.0); 6]);
    let mut out = [Ur5::tip_pose(&q)];
    let _ = Ur5::tip_pose_batch(&[q], &mut out);
}
