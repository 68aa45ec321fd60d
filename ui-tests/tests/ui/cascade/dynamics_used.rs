// Derives whose dynamics fail (a rule's fault, and a key darling cannot read), and a user calling
// every function of the dynamics in every form: only the derives' errors. The lengths are the
// robot's (the description loaded in both).
use kinematics::{F64x4, Kinematics};

#[derive(Kinematics)]
#[kinematics(urdf = "../../../../ui-tests/tests/ui/fixtures/dynamics_negative_mass.urdf", dynamics, scalars(f64, f32))]
struct Refused;

#[derive(Kinematics)]
#[kinematics(urdf = "../../../../robots/ur5.urdf", dynamics(gravity = "down"))]
struct Unreadable;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let (q, qd) = ([0.1; 2], [0.2; 2]);
    let hold: [f64; 2] = Refused::gravity_torques(&q);
    let hold32 = Refused::gravity_torques_f32(&[0.1f32; 2]);
    let mut out = vec![[0.0; 2]; 2];
    Refused::gravity_torques_batch(&[q, q], &mut out)?;
    Refused::gravity_torques_batch_columns([&[0.1][..]; 2], &mut out[..1])?;
    let mut matrices = vec![[[0.0f32; 2]; 2]; 3];
    Refused::mass_matrix_batch_f32(&[[0.1f32; 2]; 3], &mut matrices)?;
    let m: [[f64; 2]; 2] = Refused::mass_matrix(&q);
    let tau = Refused::inverse_dynamics(&q, &qd, &[1.0; 2]);
    let h = Refused::nonlinear_effects_f32(&[0.1f32; 2], &[0.2f32; 2]);
    let qdd: [f64; 2] = Refused::forward_dynamics(&q, &qd, &tau)?;
    let mut rates = vec![[0.0; 2]; 2];
    Refused::inverse_dynamics_batch(&[q, q], &[qd, qd], &[qdd, qdd], &mut rates)?;
    Refused::nonlinear_effects_batch_f32(&[[0.1f32; 2]], &[[0.2f32; 2]], &mut [[0.0f32; 2]])?;
    Refused::forward_dynamics_batch(&[q, q], &[qd, qd], &[tau, tau], &mut rates)?;
    let lanes: [F64x4; 2] = [F64x4::splat(0.1); 2];
    let (accelerations, pivots) = Refused::forward_dynamics_generic(&lanes, &lanes, &lanes);
    let generic = Refused::mass_matrix_generic(&lanes);
    let _ = (hold, hold32, m, h, qdd, accelerations, pivots, generic);
    let six = [0.0; 6];
    let g: [f64; 6] = Unreadable::gravity_torques(&six);
    let m6: [[f64; 6]; 6] = Unreadable::mass_matrix(&six);
    let a6: [f64; 6] = Unreadable::forward_dynamics(&six, &six, &g)?;
    let mut a6s = vec![a6; 3];
    Unreadable::forward_dynamics_batch(&[six; 3], &[six; 3], &[g; 3], &mut a6s)?;
    Unreadable::inverse_dynamics_batch(&[six; 3], &[six; 3], &[g; 3], &mut a6s)?;
    let _ = (m6, a6, Unreadable::inverse_dynamics(&six, &six, &six), Unreadable::nonlinear_effects(&six, &six));
    Ok(())
}
