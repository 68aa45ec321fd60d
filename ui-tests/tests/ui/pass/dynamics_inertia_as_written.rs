// An inertia whose principal moments break the triangle inequality (`dynamics_faults.rs` has it
// refused) compiles when taken as written, and its dynamics agree with the runtime reference
// built the same way.

use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(urdf = "../../../../ui-tests/tests/ui/fixtures/dynamics_triangle.urdf", dynamics(inertia_as_written))]
struct Arm;

fn main() {
    let q = [0.4, -0.9];
    let tree = Arm::reference().expect("the description loads").tree().clone();
    let reference =
        kinematics::runtime::ReferenceDynamics::new(tree, [0.0, 0.0, -9.81], true).expect("taken as written");
    let want = reference.gravity_torques(&q).expect("finite");
    for (got, want) in Arm::gravity_torques(&q).iter().zip(&want) {
        assert!((got - want).abs() < 1e-12, "{got} against {want}");
    }
    let m = Arm::mass_matrix(&q);
    assert_eq!(m[0][1], m[1][0]);
    let tau = Arm::inverse_dynamics(&q, &[0.1, 0.2], &[1.0, -1.0]);
    let qdd = Arm::forward_dynamics(&q, &[0.1, 0.2], &tau).expect("a regular mass matrix");
    assert!((qdd[0] - 1.0).abs() < 1e-9 && (qdd[1] + 1.0).abs() < 1e-9, "{qdd:?}");
}
