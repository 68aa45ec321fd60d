//! The reference dynamics (`ReferenceDynamics`, in `kinematics-runtime`) held to identities that
//! need no second implementation, on the random robots the compiled dynamics are checked on
//! (`tests/dynamics.rs`): fixed, mimic, planar, spherical and floating joints, solids, point masses
//! and massless links. The mass matrix is symmetric and positive definite, `M a + h` is inverse
//! dynamics, forward dynamics inverts it, `v^T M v / 2` is the links' kinetic energy, gravity
//! torques are the potential's gradient and inverse dynamics is d'Alembert's principle on the
//! links' momenta, each link's motion taken from the forward kinematics and its Jacobians alone.
//! Its hand-worked cases and errors are `kinematics-runtime/tests/dynamics.rs`.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use common::dynamics_robots::{
    G, Rng, assert_close, assert_close_at, random_cases, random_q, random_robot, random_vector,
};
use common::link_motions::{advance, kinetic_energy, link_motions, potential};
use kinematics::model::{JointMotion, KinematicTree};
use kinematics::runtime::ReferenceDynamics;
use nalgebra::{DVector, Vector3};

/// The generalized forces by d'Alembert's principle: each link's Newton-Euler wrench about its
/// centre of mass (`d/dt(m v_c) - m g`, `d/dt(I w)`), the derivatives by central differences along
/// the motion, mapped through the transposed Jacobians.
fn dalembert(dynamics: &ReferenceDynamics, q: &[f64], v: &[f64], a: &[f64], dt: f64) -> Vec<f64> {
    let tree = dynamics.tree();
    let g = Vector3::from(dynamics.gravity());
    let momenta = |t: f64| {
        let (qt, vt) =
            (advance(tree, q, v, a, t), DVector::from_iterator(v.len(), v.iter().zip(a).map(|(v, a)| v + a * t)));
        link_motions(dynamics, &qt)
            .iter()
            .map(|l| (l.mass * (&l.linear * &vt), l.tensor * (&l.angular * &vt)))
            .collect::<Vec<_>>()
    };
    let (after, before) = (momenta(dt), momenta(-dt));
    let mut tau = DVector::zeros(v.len());
    for (l, ((p1, h1), (p0, h0))) in link_motions(dynamics, q).iter().zip(after.iter().zip(&before)) {
        let force = (p1 - p0) / (2.0 * dt) - l.mass * g;
        let moment = (h1 - h0) / (2.0 * dt);
        tau += l.linear.transpose() * force + l.angular.transpose() * moment;
    }
    tau.iter().copied().collect()
}

#[test]
fn random_robots_cover_every_joint_kind_and_body() {
    let (mut kinds, mut mimics, mut afters, mut bodies) = (std::collections::BTreeSet::new(), 0, 0, [0; 3]);
    for (seed, variant) in random_cases() {
        let tree = KinematicTree::from_description(&random_robot(seed, variant)).unwrap();
        for joint in tree.joints() {
            kinds.insert(joint.kind.name());
            mimics += usize::from(matches!(joint.motion, JointMotion::Mimic { .. }));
            afters += usize::from(!joint.after_motion.is_identity());
        }
        for link in tree.links() {
            bodies[match &link.inertial {
                None => 0,
                Some(i) if i.inertia == [0.0; 6] => 1,
                Some(_) => 2,
            }] += 1;
        }
    }
    let every = ["revolute", "prismatic", "fixed", "floating", "planar", "spherical"];
    assert!(every.iter().all(|k| kinds.contains(k)), "{kinds:?}");
    assert!(mimics >= 50 && afters >= 50, "{mimics} mimics, {afters} transforms after the motion");
    assert!(bodies.iter().all(|&b| b >= 20), "massless, point masses, solids: {bodies:?}");
}

#[test]
fn random_robots_keep_the_identities() {
    for (seed, variant) in random_cases() {
        let tree = KinematicTree::from_description(&random_robot(seed, variant)).unwrap();
        let dynamics = ReferenceDynamics::new(tree, [0.3, -0.2, -G], false).unwrap();
        let tree = dynamics.tree();
        let n = tree.velocity_dof();
        let mut rng = Rng(1000 + seed);
        for _ in 0..3 {
            let q = random_q(tree, &mut rng);
            let (v, a, tau) = (random_vector(n, &mut rng), random_vector(n, &mut rng), random_vector(n, &mut rng));
            let context = format!("seed {seed} ({variant:?}), q {q:?}");
            let m = dynamics.mass_matrix(&q).unwrap();
            assert_eq!(m, m.transpose(), "{context}: M symmetric");
            if n > 0 {
                let eigen = m.clone().symmetric_eigen().eigenvalues;
                assert!(eigen.iter().all(|&e| e > 1e-9 * eigen.amax()), "{context}: M positive definite, {eigen}");
            }
            // M a + h = inverse dynamics.
            let h = dynamics.nonlinear_effects(&q, &v).unwrap();
            let id = dynamics.inverse_dynamics(&q, &v, &a).unwrap();
            let ma_h: Vec<f64> = (&m * DVector::from_column_slice(&a)).iter().zip(&h).map(|(x, y)| x + y).collect();
            assert_close(&ma_h, &id, 1e-12, &format!("{context}: M a + h"));
            // Forward dynamics inverts inverse dynamics (to rounding of `tau - h`).
            let acceleration = dynamics.forward_dynamics(&q, &v, &tau).unwrap();
            let back = dynamics.inverse_dynamics(&q, &v, &acceleration).unwrap();
            let h_scale = h.iter().fold(0.0_f64, |s, x| s.max(x.abs()));
            assert_close_at(&back, &tau, 1e-12, h_scale, &format!("{context}: ID(FD(tau))"));
            // The kinetic energy of the mass matrix is the links' energies.
            let energy = 0.5 * DVector::from_column_slice(&v).dot(&(&m * DVector::from_column_slice(&v)));
            assert_close(&[energy], &[kinetic_energy(&dynamics, &q, &v)], 1e-12, &format!("{context}: energy"));
            // The gravity torques are the potential's gradient along each velocity.
            let eps = 1e-4;
            let gradient: Vec<f64> = (0..n)
                .map(|k| {
                    let unit: Vec<f64> = (0..n).map(|i| if i == k { 1.0 } else { 0.0 }).collect();
                    let zero = vec![0.0; n];
                    let up = potential(&dynamics, &advance(tree, &q, &unit, &zero, eps));
                    let down = potential(&dynamics, &advance(tree, &q, &unit, &zero, -eps));
                    (up - down) / (2.0 * eps)
                })
                .collect();
            // Differences err by about eps^2 of the third derivative: relative to the robot's
            // weight on a lever of 1 m where the torques are smaller.
            let weight = G * link_motions(&dynamics, &q).iter().map(|l| l.mass).sum::<f64>();
            let gravity = dynamics.gravity_torques(&q).unwrap();
            assert_close_at(&gravity, &gradient, 1e-7, weight, &format!("{context}: gravity"));
            // Inverse dynamics is d'Alembert's principle on the links' momenta.
            let dalembert = dalembert(&dynamics, &q, &v, &a, 1e-4);
            assert_close_at(&id, &dalembert, 1e-7, weight, &format!("{context}: d'Alembert"));
        }
    }
}
