use kinematics::Kinematics;

// The fixture's root is already `world`: a free-flying root needs a new name for its link.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../ui-tests/tests/ui/fixtures/floating.urdf", floating_base, tip = "body", jacobians)]
struct Robot;

fn main() {
    // The stub beside the error keeps the velocity functions: no cascade.
    let q = [0.0; 7];
    let _ = Robot::tip_jacobian(&q);
    let _ = Robot::VELOCITY_DOF;
}
