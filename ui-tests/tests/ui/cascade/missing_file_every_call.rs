// A description that cannot be read, and a user calling every family of functions the derive
// would have written (poses, positions, Jacobians, twists, batches, lanes, the closed-form and
// numeric inverse, collision): only the file's error. Lengths no one could know are an error to
// rustc, so nothing is inferred from them and nothing more is reported: a seed built by
// `std::array::from_fn`, links destructured or written down at any length. (One use still speaks:
// a pattern with a rest, `let [first, .., last] = ...`, is "cannot pattern-match on an array
// without a fixed length", as rustc does not look at why the length is unknown.)
use kinematics::collision::{Environment, SphereObstacle};
use kinematics::ik::NumericOptions;
use kinematics::{F64x4, Kinematics};

#[derive(Kinematics)]
#[kinematics(
    urdf = "robots/no_such_robot.urdf",
    tip = "tool0",
    positions,
    jacobians,
    ik,
    collision,
    scalars(f64, f32)
)]
struct Robot;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let q = [0.1; 6];
    let seed = std::array::from_fn(|j| 0.1 * j as f64);
    let pose = Robot::tip_pose(&seed);
    let links: [kinematics::Pose<f64>; 9] = Robot::link_poses(&q);
    let [first, second, _, _, _, _, _, _, last] = Robot::link_poses(&q);
    let positions = Robot::link_positions(&q);
    let position = Robot::tip_position_f32(&std::array::from_fn(|_| 0.5));
    let jacobian = Robot::tip_jacobian(&q);
    let twist = Robot::tip_twist(&q, &std::array::from_fn(|_| 1.0));
    let lanes: [F64x4; 6] = std::array::from_fn(|_| F64x4::splat(0.2));
    let generic = Robot::link_poses_generic(&lanes);
    let mut out = vec![[pose; 9]; 2];
    Robot::link_poses_batch(&[q, seed], &mut out)?;
    Robot::link_poses_batch_columns([&[0.1][..]; 6], &mut out[..1])?;
    let mut twists = vec![twist; 2];
    Robot::tip_twist_batch(&[q, seed], &[[1.0; 6]; 2], &mut twists)?;
    Robot::tip_twist_local_batch_f32(&[[0.1; 6]], &[[1.0; 6]], &mut [[0.0f32; 6]])?;
    let solutions = Robot::tip_ik(&pose)?;
    let best = solutions.iter().map(|s| s.q).find(|s| *s == seed);
    let limited = Robot::tip_ik_within_limits(&pose)?;
    let nearest = Robot::tip_ik_nearest(&pose, &std::array::from_fn(|_| 0.0))?;
    let numeric = Robot::tip_ik_numeric(&pose, &seed)?;
    let tuned = Robot::tip_ik_numeric_with(&pose, &seed, &NumericOptions::default())?;
    let arm = Robot::IK_ARM;
    let ball = [SphereObstacle { center: [0.5, 0.0, 0.5], radius: 0.1 }];
    let environment = Environment::new(&ball, &[], &[], &[])?;
    let hit = Robot::collides(&seed, &environment) || Robot::self_collides_f32(&[0.0; 6]);
    let mut verdicts = [false; 2];
    Robot::collides_batch(&[q, seed], &environment, &mut verdicts)?;
    let mask = Robot::self_collides_generic(&lanes);
    let motion = Robot::motion_collides(&q, &seed, &environment, 0.05)?;
    let held = Robot::hold("tool0", &ball, &[])?;
    let holding = Robot::collides(&q, &environment.holding(&held));
    let clearance = Robot::clearance(&q, &environment);
    let (_, gradient) = Robot::clearance_gradient(&q, &environment);
    let cost = Robot::proximity_cost_gradient(&q, &environment, 0.05)?;
    let radii = (Robot::SPHERE_RADII.len(), Robot::SPHERE_LINKS[0], Robot::sphere_centers(&q)[3]);
    let names: [&str; 6] = Robot::JOINT_NAMES;
    let _ = (links, first, second, last, positions, position, jacobian, twist, generic, best, limited, nearest);
    let _ = (numeric, tuned, arm, hit, mask, motion, holding, clearance, gradient, cost, radii, names);
    let _ = (<Robot as Kinematics>::DOF, Robot::reference()?.tree().dof());
    Ok(())
}
