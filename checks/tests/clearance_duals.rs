//! The clearance's and the proximity cost's gradients (taken through the generated Jacobians of
//! the links with spheres) against a witness that shares none of that code: the same scans run
//! on dual numbers, through the generated *poses* (`clearance_generic` and
//! `proximity_cost_generic` on [`Dual`]), whose derivatives are the distance's own. A dual run
//! takes the branches the `f64` run takes, so the two measure the same nearest pair and agree
//! wherever the clearance is differentiable, kinks included (each is the derivative of the pair
//! it found). Scenes of boxes, capsules and cylinders from `scenes/` with spheres added; both
//! signs of the clearance are met.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use kinematics::collision::{Environment, SphereObstacle};
use kinematics::{Configurations, Kinematics};
use kinematics_checks::dual::Dual;

#[derive(Kinematics)]
#[kinematics(urdf = "../robots/panda_spherized.urdf", collision(srdf = "../robots/panda.srdf"))]
struct Panda;

#[derive(Kinematics)]
#[kinematics(urdf = "../robots/ur5_spherized.urdf", collision)]
struct Ur5;

/// The proximity cost's margin (m).
const MARGIN: f64 = 0.05;

/// Derivatives agree to this, relative to `1 + |derivative|`: both are exact derivatives of one
/// distance, computed along different roads (the Jacobians' columns against the chain rule
/// through the poses), so they differ in rounding only.
const TOLERANCE: f64 = 1e-9;

/// A robot's distances, per configuration and on duals seeded with one direction per joint.
trait Distances<const N: usize> {
    const LIMITS: &'static [kinematics::JointLimits];
    fn clearance_gradient(q: &[f64; N], env: &Environment<'_>) -> (f64, [f64; N]);
    fn cost_gradient(q: &[f64; N], env: &Environment<'_>) -> (f64, [f64; N]);
    fn clearance_dual(q: &[Dual<N>; N], env: &Environment<'_>) -> Dual<N>;
    fn cost_dual(q: &[Dual<N>; N], env: &Environment<'_>) -> Dual<N>;
}

macro_rules! distances {
    ($robot:ty, $n:literal) => {
        impl Distances<$n> for $robot {
            const LIMITS: &'static [kinematics::JointLimits] = &<$robot>::JOINT_LIMITS;
            fn clearance_gradient(q: &[f64; $n], env: &Environment<'_>) -> (f64, [f64; $n]) {
                <$robot>::clearance_gradient(q, env)
            }
            fn cost_gradient(q: &[f64; $n], env: &Environment<'_>) -> (f64, [f64; $n]) {
                <$robot>::proximity_cost_gradient(q, env, MARGIN).unwrap()
            }
            fn clearance_dual(q: &[Dual<$n>; $n], env: &Environment<'_>) -> Dual<$n> {
                <$robot>::clearance_generic(q, env)
            }
            fn cost_dual(q: &[Dual<$n>; $n], env: &Environment<'_>) -> Dual<$n> {
                <$robot>::proximity_cost_generic(q, env, MARGIN).unwrap()
            }
        }
    };
}

distances!(Panda, 7);
distances!(Ur5, 6);

/// `value` and `gradient` against the dual `witness`; the witness's largest derivative.
fn compare<const N: usize>(what: &str, q: &[f64; N], value: f64, gradient: &[f64; N], witness: &Dual<N>) -> f64 {
    assert!(value.is_finite() && witness.value.is_finite(), "{what} at {q:?}: {value} and {}", witness.value);
    assert!((value - witness.value).abs() <= 1e-12, "{what} at {q:?}: {value} against the duals' {}", witness.value);
    let mut largest = 0.0f64;
    for (j, (g, d)) in gradient.iter().zip(&witness.grad).enumerate() {
        let error = (g - d).abs() / (1.0 + d.abs());
        assert!(error <= TOLERANCE, "{what}'s derivative {j} at {q:?}: {g} against the duals' {d}");
        largest = largest.max(d.abs());
    }
    largest
}

/// Every configuration's clearance and cost gradients against the duals' in `scene`; how many
/// configurations had a negative clearance, and how many had a cost above zero.
fn agree<R: Distances<N>, const N: usize>(scene: &str) -> (usize, usize) {
    let file = format!("{}/../scenes/{scene}", env!("CARGO_MANIFEST_DIR"));
    let obstacles = kinematics::load_scene(&file).unwrap();
    let balls = [
        SphereObstacle { center: [0.45, -0.2, 0.5], radius: 0.08 },
        SphereObstacle { center: [-0.3, 0.35, 0.3], radius: 0.12 },
    ];
    let env = Environment::new(&balls, &obstacles.capsules, &obstacles.cylinders, &obstacles.boxes).unwrap();
    let (mut overlapping, mut costly, mut moving) = (0, 0, 0);
    for q in Configurations::within(R::LIMITS).take(300) {
        let q: [f64; N] = q.try_into().unwrap();
        let duals: [Dual<N>; N] = std::array::from_fn(|j| {
            let mut grad = [0.0; N];
            grad[j] = 1.0;
            Dual { value: q[j], grad }
        });
        let (clearance, gradient) = R::clearance_gradient(&q, &env);
        let largest = compare("clearance", &q, clearance, &gradient, &R::clearance_dual(&duals, &env));
        moving += usize::from(largest > 1e-3);
        let (cost, gradient) = R::cost_gradient(&q, &env);
        let largest = compare("proximity cost", &q, cost, &gradient, &R::cost_dual(&duals, &env));
        assert!(cost == 0.0 || largest > 0.0, "proximity cost {cost} at {q:?}: the duals' derivatives are all zero");
        overlapping += usize::from(clearance < 0.0);
        costly += usize::from(cost > 0.0);
    }
    // The clearance moves with the joints in most configurations (a witness of zeros does not
    // pass). Not in all: where the nearest pair is the base's spheres and the table under it
    // (about a third of the Panda's in the tabletop scene), no joint changes it.
    assert!(moving > 150, "{scene}: the clearance moved with the joints at only {moving} of 300 configurations");
    (overlapping, costly)
}

#[test]
fn clearance_gradients_agree_with_dual_numbers() {
    for scene in ["tabletop.toml", "shelf.toml"] {
        let (overlapping, costly) = agree::<Panda, 7>(scene);
        assert!(overlapping > 10 && overlapping < 290, "Panda in {scene}: {overlapping} of 300 overlapping");
        assert!(
            costly > overlapping,
            "Panda in {scene}: no free configuration within the margin ({costly} with a cost, {overlapping} overlapping)"
        );
        let (overlapping, _) = agree::<Ur5, 6>(scene);
        assert!(overlapping > 10 && overlapping < 290, "UR5 in {scene}: {overlapping} of 300 overlapping");
    }
}
