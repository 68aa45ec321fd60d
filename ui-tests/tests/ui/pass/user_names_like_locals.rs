// Constants and unit structs named like the generated code's locals (`q1`, `s1`, `c23`, `t0`)
// in the deriving module: a `let` with such a name would be a pattern, not a binding. The
// generated bodies live in a module of their own, so these compile and compute the same pose.
#![allow(non_upper_case_globals, non_camel_case_types, dead_code)]

use kinematics::Kinematics;

const q1: f64 = 0.0;
const c23: f64 = 0.0;
const t0: f64 = 0.0;
struct s1;

#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", tip = "tool0", positions, jacobians, ik)]
struct Ur5;

fn main() {
    let q = [0.3, -1.2, 1.0, 0.4, -0.7, 2.0];
    let pose = Ur5::tip_pose(&q);
    let reference = Ur5::reference().expect("the description loads");
    let expected = reference.relative_pose(&q, Ur5::BASE, "tool0").expect("finite");
    assert!((pose.to_isometry().translation.vector - expected.translation.vector).norm() < 1e-12);
    let solutions = Ur5::tip_ik(&pose).expect("a pose");
    assert!(solutions.exact().count() > 0);
}
