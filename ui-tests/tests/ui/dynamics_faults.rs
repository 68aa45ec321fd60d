use kinematics::Kinematics;

// A negative mass: the error names the link and the line of its <inertial>.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../ui-tests/tests/ui/fixtures/dynamics_negative_mass.urdf", dynamics)]
struct NegativeMass;

// Principal moments breaking the triangle inequality (`pass/dynamics_inertia_as_written.rs` takes
// them as written).
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../ui-tests/tests/ui/fixtures/dynamics_triangle.urdf", dynamics)]
struct Triangle;

// A NaN entry of the tensor.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../ui-tests/tests/ui/fixtures/dynamics_nan_inertia.urdf", dynamics)]
struct NanInertia;

// A negative principal moment, refused even as written.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../ui-tests/tests/ui/fixtures/dynamics_not_positive.urdf", dynamics(inertia_as_written))]
struct NotPositive;

// No link has an <inertial>: no mass at all.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/planar_3r.urdf", dynamics)]
struct NoMass;

// The fault of the whole key points at its name, not at the first entry of its list.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/planar_3r.urdf", dynamics(gravity = [0.0, 0.0, -9.81]))]
struct NoMassListed;

// An MJCF body with a geom and no <inertial>, whose mass MuJoCo would infer.
#[derive(Kinematics)]
#[kinematics(mjcf = "../../../../ui-tests/tests/ui/fixtures/mjcf/mass_from_geoms.xml", dynamics)]
struct MassFromGeoms;

// Gravity of two numbers.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", dynamics(gravity = [0, 0]))]
struct TwoNumbers;

// Gravity as a word.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", dynamics(gravity = "down"))]
struct GravityWord;

// Gravity that overflows to infinity.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", dynamics(inertia_as_written, gravity = [0.0, 0.0, -1e400]))]
struct InfiniteGravity;

// `dynamics` given a value.
#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", dynamics = true)]
struct DynamicsValue;

fn main() {
    // The stub keeps the dynamics' functions, of the robot's lengths: no cascade.
    let _ = NegativeMass::gravity_torques(&[0.0; 2]);
    let _: [[f64; 2]; 2] = Triangle::mass_matrix(&[0.0; 2]);
    let _ = NoMass::forward_dynamics(&[0.0; 3], &[0.0; 3], &[0.0; 3]);
    let _ = GravityWord::inverse_dynamics(&[0.0; 6], &[0.0; 6], &[0.0; 6]);
    let _ = InfiniteGravity::nonlinear_effects(&[0.0; 6], &[0.0; 6]);
}
