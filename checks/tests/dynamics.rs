//! The compiled dynamics against the runtime reference (`ReferenceDynamics`, Featherstone's
//! algorithms on nalgebra, sharing nothing with the compiler), for every robot in `robots/` whose
//! links carry inertias and for the random robots of `common::dynamics_robots` (fixed, mimic,
//! planar, spherical and floating joints; solids, point masses and massless links): gravity,
//! inverse dynamics, nonlinear effects, the mass matrix and forward dynamics, evaluated with the
//! compiled graph at random configurations, rates and accelerations.
//!
//! And the compiled functions held to identities among themselves and to the links' energies,
//! which need no second implementation of the dynamics: inverse dynamics undoes forward dynamics,
//! `M a + h` is inverse dynamics, the mass matrix is exactly symmetric and positive definite,
//! `v^T M v / 2` is the links' kinetic energy and the gravity torques are the gradient of the
//! potential energy (the energies from the reference's forward kinematics alone).
//!
//! With external forces on links: the compiled `inverse_dynamics_with_forces` and
//! `forward_dynamics_with_forces` against the reference's, and against inverse dynamics less
//! `J^T f` of each link's Jacobian in its own axes, from the reference's forward kinematics
//! (`ReferenceFk::jacobian_in`, which shares nothing with either dynamics).
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use common::dynamics_robots::{Rng, assert_close_at, random_cases, random_q, random_robot, random_vector};
use common::link_motions::{advance, kinetic_energy, link_motions, potential};
use common::robot_path;
use kinematics::model::{JacobianFrame, JointMotion, KinematicTree, LinkId};
use kinematics::runtime::ReferenceDynamics;
use kinematics_compiler::dynamics::{CompiledDynamics, DynamicsFunction, DynamicsRequest, compile_dynamics};
use nalgebra::{DMatrix, DVector};

/// Agreement relative to the scale of the values compared.
const RELATIVE: f64 = 1e-12;

const REQUEST: DynamicsRequest =
    DynamicsRequest { gravity: [0.1, -0.3, -9.81], inertia_as_written: false, forces: Vec::new() };

/// `got` within [`RELATIVE`] of `want`, relative to the largest of `scale`, `want`'s entries and
/// 1 (N, N m, kg m^2, m/s^2 or J); NaN and infinities fail.
#[track_caller]
fn close_at(got: &[f64], want: &[f64], scale: f64, what: &str) {
    assert_close_at(got, want, RELATIVE, scale.max(1.0), what);
}

#[track_caller]
fn close(got: &[f64], want: &[f64], what: &str) {
    close_at(got, want, 1.0, what);
}

fn largest(values: &[f64]) -> f64 {
    values.iter().fold(0.0, |s, x| s.max(x.abs()))
}

/// A configuration (unit quaternions for floating and spherical joints), rates and accelerations.
fn random_state(tree: &KinematicTree, rng: &mut Rng) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let nv = tree.velocity_dof();
    (random_q(tree, rng), random_vector(nv, rng), random_vector(nv, rng))
}

/// The robots of `robots/` whose links carry inertias (none left to geometry), by file name.
fn robots_with_inertias() -> Vec<(String, KinematicTree)> {
    let mut files: Vec<_> = std::fs::read_dir(robot_path("")).unwrap().map(|e| e.unwrap().path()).collect();
    files.sort();
    files
        .into_iter()
        .filter_map(|path| Some((path.display().to_string(), kinematics::load(&path).ok()?)))
        .filter(|(_, tree)| {
            tree.links().iter().any(|l| l.inertial.is_some()) && tree.inertia_from_geometry().is_empty()
        })
        .collect()
}

fn random_trees() -> impl Iterator<Item = KinematicTree> {
    random_cases().map(|(seed, variant)| KinematicTree::from_description(&random_robot(seed, variant)).unwrap())
}

/// The reference and every compiled function (in [`DynamicsFunction::ALL`]'s order), or `None`
/// when the reference refuses the robot's inertias (the compiler must then refuse them too, with
/// the same message).
fn compile_all(tree: &KinematicTree) -> Option<(ReferenceDynamics, Vec<CompiledDynamics>)> {
    let reference = match ReferenceDynamics::new(tree.clone(), REQUEST.gravity, false) {
        Ok(reference) => reference,
        Err(refused) => {
            let error = compile_dynamics(tree, &REQUEST, DynamicsFunction::Gravity).unwrap_err();
            println!("{}: refused: {error}", tree.name());
            assert_eq!(error.to_string(), refused.to_string());
            return None;
        }
    };
    let compiled = DynamicsFunction::ALL.iter().map(|&f| compile_dynamics(tree, &REQUEST, f).unwrap()).collect();
    Some((reference, compiled))
}

/// Checks the compiled functions against the reference at `cases` random states; `false` when
/// the reference refuses the robot's inertias.
fn check_tree(tree: &KinematicTree, cases: usize) -> bool {
    let Some((reference, compiled)) = compile_all(tree) else { return false };
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let name = tree.name();
    for case in 0..cases {
        let (q, v, a) = random_state(tree, &mut rng);
        let name = format!("{name} case {case} (q {q:?}, v {v:?}, a {a:?})");
        let nv = v.len();
        close(&compiled[0].eval(&q, &v, &[]), &reference.gravity_torques(&q).unwrap(), &format!("{name} gravity"));
        let tau = reference.inverse_dynamics(&q, &v, &a).unwrap();
        close(&compiled[1].eval(&q, &v, &a), &tau, &format!("{name} inverse dynamics"));
        close(&compiled[2].eval(&q, &v, &[]), &reference.nonlinear_effects(&q, &v).unwrap(), &format!("{name} h"));
        let m = reference.mass_matrix(&q).unwrap();
        let m: Vec<f64> = (0..nv).flat_map(|i| (0..nv).map(move |j| (i, j))).map(|(i, j)| m[(i, j)]).collect();
        close(&compiled[3].eval(&q, &v, &[]), &m, &format!("{name} mass matrix"));
        // Forward dynamics in torque units: the reference's mass matrix times the difference of
        // the accelerations, against the torques' scale. Accelerations themselves carry the mass
        // matrix's conditioning (a random robot's reaches 6e3, and two correct solves of one
        // system then differ by 1e-12 in their accelerations while their torques agree to 1e-15).
        if let Ok(want) = reference.forward_dynamics(&q, &v, &tau) {
            let got = compiled[4].eval(&q, &v, &tau);
            let h = reference.nonlinear_effects(&q, &v).unwrap();
            let scale = largest(&tau).max(largest(&h));
            let in_torques = |accelerations: &[f64]| -> Vec<f64> {
                (0..nv).map(|i| (0..nv).map(|j| m[i * nv + j] * (got[j] - accelerations[j])).sum()).collect()
            };
            let zero = vec![0.0; nv];
            close_at(&in_torques(&want), &zero, scale, &format!("{name} forward dynamics, M (qdd - qdd_ref)"));
            close_at(&in_torques(&a), &zero, scale, &format!("{name} forward dynamics of inverse dynamics"));
        }
    }
    true
}

/// The step of the central differences of the potential (in radians, metres or, for a quaternion
/// joint, the angle of its turn).
const STEP: f64 = 1e-6;

/// A bound on how fast a unit velocity turns or slides any link (rad/s, m/s): 1 for a joint's own,
/// and a joint's mimics move with it (up to 1.5 times as fast in the random robots, several in
/// series in a hand's fingers).
const RATE: f64 = 10.0;

/// How far the central difference `(V(q + h e_k) - V(q - h e_k)) / 2h` may stray from `dV/dq_k`
/// (and so from the gravity torque, whose own rounding is some `1e-15` of it), for a robot of
/// weight `w` (`|g|` times its mass), every centre of mass and link origin within `reach` of the
/// root's origin, at most `depth` joints from the root to a link, and `|q|` at most `q_max`:
///
/// - truncation: `h^2 / 6 |V'''|`. Along one velocity each centre of mass turns at most [`RATE`]
///   about axes at most `2 reach` from it, or slides (no third derivative), so
///   `|V'''| <= w 2 reach RATE^3`: `3.4e-10 w reach` at `h = 1e-6`. Negligible next to
/// - rounding of the potential: each centre of mass comes out of the forward kinematics' products
///   (a joint's origin, motion and transform after it, then the inertial's origin: `3 depth + 1`
///   isometries, each rounding to a few `eps` of the `reach` it carries; `4 eps` each, and as much
///   again for the sum `sum m g.c`), so each `V` is within `4 eps (3 depth + 2) w reach`, and the
///   difference of two divided by `2 h` within that over `h`: `2.0e-8 w reach` for a depth of 7;
/// - rounding of the step: `q +- h` is rounded to `eps |q|`, the quotient's step so off by
///   `eps q_max / h` of it, the torque (at most `w 2 reach RATE`) with it: `1.1e-8 w reach` at
///   `q_max = 2.5`.
///
/// The finite difference is the potential's own, from the reference's link poses: nothing here
/// comes from the compiled code.
fn gradient_tolerance(w: f64, reach: f64, depth: usize, q_max: f64) -> f64 {
    let eps = f64::EPSILON;
    let truncation = STEP * STEP / 6.0 * 2.0 * RATE.powi(3) * w * reach;
    let rounding = 4.0 * eps * (3.0 * depth as f64 + 2.0) * w * reach / STEP;
    let step = eps * q_max.max(1.0) / STEP * 2.0 * RATE * w * reach;
    truncation + rounding + step
}

/// Holds the compiled functions of `tree` to the identities, at `cases` random states; `false`
/// when the reference refuses the robot's inertias (it gives the energies).
fn check_identities(tree: &KinematicTree, cases: usize) -> bool {
    let Some((reference, compiled)) = compile_all(tree) else { return false };
    let [gravity, inverse, nonlinear, mass, forward] = &compiled[..] else { unreachable!() };
    let depth = (0..tree.links().len()).map(|l| tree.depth(LinkId(l))).max().unwrap_or(0);
    let mut rng = Rng(0x2545_f491_4f6c_dd1d);
    let mut worst_gradient = 0.0f64;
    for case in 0..cases {
        let (q, v, a) = random_state(tree, &mut rng);
        let nv = v.len();
        let tau = random_vector(nv, &mut rng);
        let name = format!("{} case {case} (q {q:?}, v {v:?}, a {a:?}, tau {tau:?})", tree.name());

        // The mass matrix: finite, exactly symmetric, positive definite (Cholesky succeeds).
        let m = mass.eval(&q, &v, &[]);
        assert_eq!(m.len(), nv * nv, "{name}: mass matrix");
        assert!(m.iter().all(|x| x.is_finite()), "{name}: mass matrix not finite: {m:?}");
        for i in 0..nv {
            for j in 0..i {
                assert!(
                    m[i * nv + j] == m[j * nv + i],
                    "{name}: M[{i}][{j}] {} != M[{j}][{i}] {}",
                    m[i * nv + j],
                    m[j * nv + i]
                );
            }
        }
        let m = DMatrix::from_row_slice(nv, nv, &m);
        assert!(nv == 0 || m.clone().cholesky().is_some(), "{name}: mass matrix not positive definite: {m}");

        // Forward dynamics: accelerations then the factorisation's pivots, all positive; inverse
        // dynamics undoes it, to rounding of `tau - h`.
        let h = nonlinear.eval(&q, &v, &[]);
        let fd = forward.eval(&q, &v, &tau);
        assert_eq!(fd.len(), 2 * nv, "{name}: forward dynamics");
        let (acceleration, pivots) = fd.split_at(nv);
        assert!(pivots.iter().all(|&p| p > 0.0 && p.is_finite()), "{name}: pivots {pivots:?}");
        let back = inverse.eval(&q, &v, acceleration);
        let scale = largest(&tau).max(largest(&h));
        close_at(&back, &tau, scale, &format!("{name}: inverse dynamics of forward dynamics"));

        // M a + h is inverse dynamics, to rounding of the terms summed.
        let ma = &m * DVector::from_column_slice(&a);
        let ma_h: Vec<f64> = ma.iter().zip(&h).map(|(x, y)| x + y).collect();
        let scale = largest(ma.as_slice()).max(largest(&h));
        close_at(&inverse.eval(&q, &v, &a), &ma_h, scale, &format!("{name}: M a + h"));

        // v^T M v / 2 is the links' kinetic energy, to rounding of the terms |M_ij v_i v_j|.
        let vv = DVector::from_column_slice(&v);
        let energy = 0.5 * vv.dot(&(&m * &vv));
        let scale = 0.5 * vv.abs().dot(&(m.abs() * vv.abs()));
        close_at(&[energy], &[kinetic_energy(&reference, &q, &v)], scale, &format!("{name}: kinetic energy"));

        // The gravity torques are the gradient of the potential along each velocity.
        let links = link_motions(&reference, &q);
        let origins = reference.fk().link_poses(&q).unwrap();
        let reach = links
            .iter()
            .map(|l| l.com.norm())
            .chain(origins.iter().map(|p| p.translation.vector.norm()))
            .fold(0.0, f64::max);
        let weight = nalgebra::Vector3::from(REQUEST.gravity).norm() * links.iter().map(|l| l.mass).sum::<f64>();
        let tolerance = gradient_tolerance(weight, reach, depth, largest(&q));
        let zero = vec![0.0; nv];
        let got = gravity.eval(&q, &v, &[]);
        assert_eq!(got.len(), nv, "{name}: gravity");
        for (k, &torque) in got.iter().enumerate() {
            let unit: Vec<f64> = (0..nv).map(|i| if i == k { 1.0 } else { 0.0 }).collect();
            let up = potential(&reference, &advance(tree, &q, &unit, &zero, STEP));
            let down = potential(&reference, &advance(tree, &q, &unit, &zero, -STEP));
            let gradient = (up - down) / (2.0 * STEP);
            let error = (torque - gradient).abs();
            assert!(
                error <= tolerance,
                "{name}: gravity[{k}] {torque} against the potential's gradient {gradient} (error {error:.3e}, \
                 tolerance {tolerance:.3e})"
            );
            worst_gradient = worst_gradient.max(error / tolerance);
        }
    }
    println!("{}: identities hold (gradient error at most {worst_gradient:.1e} of its tolerance)", tree.name());
    true
}

#[test]
fn every_robot_with_inertias_agrees_with_the_reference() {
    let mut checked = 0;
    for (path, tree) in robots_with_inertias() {
        if check_tree(&tree, 50) {
            println!("{path}: agrees");
            checked += 1;
        }
    }
    assert!(checked >= 5, "{checked} robots with inertias");
}

/// The random robots, every function of each compiled, at 10 random states.
#[test]
fn random_robots_agree_with_the_reference() {
    for tree in random_trees() {
        assert!(check_tree(&tree, 10), "{}: refused", tree.name());
    }
}

#[test]
fn compiled_dynamics_keep_the_identities_on_every_robot_with_inertias() {
    let mut checked = 0;
    for (_, tree) in robots_with_inertias() {
        checked += usize::from(check_identities(&tree, 10));
    }
    assert!(checked >= 5, "{checked} robots with inertias");
}

#[test]
fn compiled_dynamics_keep_the_identities_on_random_robots() {
    for tree in random_trees() {
        assert!(check_identities(&tree, 10), "{}: refused", tree.name());
    }
}

/// Up to `count` links below a moving joint, spread over the tree (the last link, then every
/// so many before it).
fn force_links(tree: &KinematicTree, count: usize) -> Vec<String> {
    let moving: Vec<&str> = tree
        .links()
        .iter()
        .enumerate()
        .filter(|(i, _)| {
            tree.path_from_root(LinkId(*i)).into_iter().any(|j| !matches!(tree.joint(j).motion, JointMotion::Fixed))
        })
        .map(|(_, link)| link.name.as_str())
        .collect();
    let step = moving.len().div_ceil(count).max(1);
    moving.iter().rev().step_by(step).take(count).map(|&name| name.to_owned()).collect()
}

/// Forces on up to three links of `tree`, at `cases` random states: the compiled functions with
/// forces against the reference's, and inverse dynamics with forces against inverse dynamics less
/// `J^T f` (each link's Jacobian in its own axes, from the reference's forward kinematics); forward
/// dynamics with the forces undoes inverse dynamics with them. `false` when the reference refuses
/// the robot's inertias.
fn check_forces(tree: &KinematicTree, cases: usize) -> bool {
    let Ok(reference) = ReferenceDynamics::new(tree.clone(), REQUEST.gravity, false) else { return false };
    let links = force_links(tree, 3);
    assert!(!links.is_empty(), "{}: no link below a moving joint", tree.name());
    let request = DynamicsRequest { forces: links.clone(), ..REQUEST };
    let [inverse, forward] = DynamicsFunction::WITH_FORCES.map(|f| compile_dynamics(tree, &request, f).unwrap());
    let mut rng = Rng(0x2545_f491_4f6c_dd1d);
    let root = &tree.link(tree.root()).name;
    for case in 0..cases {
        let (q, v, a) = random_state(tree, &mut rng);
        let nv = v.len();
        let forces: Vec<[f64; 6]> = links.iter().map(|_| std::array::from_fn(|_| 4.0 * rng.range(-1.5, 1.5))).collect();
        let named: Vec<(&str, [f64; 6])> = links.iter().map(String::as_str).zip(forces.iter().copied()).collect();
        let flat: Vec<f64> = forces.iter().flatten().copied().collect();
        let name = format!("{} case {case} (forces on {links:?}: {forces:?}, q {q:?})", tree.name());
        let want = reference.inverse_dynamics_with_forces(&q, &v, &a, &named).unwrap();
        let input: Vec<f64> = a.iter().chain(&flat).copied().collect();
        let got = inverse.eval(&q, &v, &input);
        close(&got, &want, &format!("{name}: inverse dynamics with forces"));
        // Inverse dynamics less each force's generalized force `J^T f`.
        let mut by_jacobians = reference.inverse_dynamics(&q, &v, &a).unwrap();
        for (link, f) in &named {
            let j = reference.fk().jacobian_in(&q, root, link, JacobianFrame::Local).unwrap();
            let f = DVector::from_column_slice(f);
            let generalized = j.transpose() * f;
            for (tau, g) in by_jacobians.iter_mut().zip(generalized.iter()) {
                *tau -= g;
            }
        }
        close(&got, &by_jacobians, &format!("{name}: inverse dynamics with forces against J^T f"));
        // Forward dynamics with the same forces gives the accelerations back (in torque units).
        let input: Vec<f64> = want.iter().chain(&flat).copied().collect();
        let values = forward.eval(&q, &v, &input);
        let (accelerations, pivots) = values.split_at(nv);
        if pivots.iter().all(|&p| p > 1e-9) {
            let m = reference.mass_matrix(&q).unwrap();
            let difference = DVector::from_iterator(nv, accelerations.iter().zip(&a).map(|(x, y)| x - y));
            let torques = m * difference;
            let h = reference.nonlinear_effects(&q, &v).unwrap();
            let scale = largest(&want).max(largest(&h));
            close_at(torques.as_slice(), &vec![0.0; nv], scale, &format!("{name}: forward of inverse with forces"));
        }
    }
    true
}

#[test]
fn forces_on_links_agree_on_every_robot_with_inertias() {
    let mut checked = 0;
    for (_, tree) in robots_with_inertias() {
        checked += usize::from(check_forces(&tree, 20));
    }
    assert!(checked >= 5, "{checked} robots with inertias");
}

#[test]
fn forces_on_links_agree_on_random_robots() {
    for tree in random_trees() {
        assert!(check_forces(&tree, 5), "{}: refused", tree.name());
    }
}
