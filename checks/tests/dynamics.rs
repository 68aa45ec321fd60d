//! The compiled dynamics against the runtime reference (`ReferenceDynamics`, Featherstone's
//! algorithms on nalgebra, sharing nothing with the compiler), for every robot in `robots/` whose
//! links carry inertias: gravity, inverse dynamics, nonlinear effects, the mass matrix and forward
//! dynamics, evaluated with the compiled graph at random configurations, rates and accelerations.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use common::robot_path;
use kinematics::model::KinematicTree;
use kinematics::runtime::ReferenceDynamics;
use kinematics_compiler::dynamics::{CompiledDynamics, DynamicsFunction, DynamicsRequest, compile_dynamics};

/// A small deterministic generator (xorshift64*).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }

    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Agreement relative to the scale of the values compared.
const RELATIVE: f64 = 1e-12;

fn close(got: &[f64], want: &[f64], what: &str) {
    assert_eq!(got.len(), want.len(), "{what}");
    let scale = want.iter().fold(1.0f64, |s, x| s.max(x.abs()));
    for (k, (g, w)) in got.iter().zip(want).enumerate() {
        assert!(g.is_finite() && (g - w).abs() <= RELATIVE * scale, "{what}[{k}]: {g} against {w} (scale {scale})");
    }
}

fn random_state(tree: &KinematicTree, rng: &mut Rng) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let mut q: Vec<f64> = (0..tree.dof()).map(|_| rng.range(-3.0, 3.0)).collect();
    for start in tree.quaternion_entries() {
        let norm = q[start..start + 4].iter().map(|x| x * x).sum::<f64>().sqrt();
        q[start..start + 4].iter_mut().for_each(|x| *x /= norm);
    }
    let v = (0..tree.velocity_dof()).map(|_| rng.range(-2.0, 2.0)).collect();
    let a = (0..tree.velocity_dof()).map(|_| rng.range(-2.0, 2.0)).collect();
    (q, v, a)
}

/// Checks the compiled functions against the reference at `cases` random states; `false` when
/// the reference refuses the robot's inertias (the compiler must then refuse them too).
fn check_tree(tree: &KinematicTree, cases: usize) -> bool {
    let request = DynamicsRequest { gravity: [0.1, -0.3, -9.81], inertia_as_written: false };
    let reference = match ReferenceDynamics::new(tree.clone(), request.gravity, false) {
        Ok(reference) => reference,
        Err(refused) => {
            let error = compile_dynamics(tree, &request, DynamicsFunction::Gravity).unwrap_err();
            println!("{}: refused: {error}", tree.name());
            assert_eq!(error.to_string(), refused.to_string());
            return false;
        }
    };
    let compiled: Vec<CompiledDynamics> =
        DynamicsFunction::ALL.iter().map(|&f| compile_dynamics(tree, &request, f).unwrap()).collect();
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let name = tree.name();
    for _ in 0..cases {
        let (q, v, a) = random_state(tree, &mut rng);
        let nv = v.len();
        close(&compiled[0].eval(&q, &v, &[]), &reference.gravity_torques(&q).unwrap(), &format!("{name} gravity"));
        let tau = reference.inverse_dynamics(&q, &v, &a).unwrap();
        close(&compiled[1].eval(&q, &v, &a), &tau, &format!("{name} inverse dynamics"));
        close(&compiled[2].eval(&q, &v, &[]), &reference.nonlinear_effects(&q, &v).unwrap(), &format!("{name} h"));
        let m = reference.mass_matrix(&q).unwrap();
        let m: Vec<f64> = (0..nv).flat_map(|i| (0..nv).map(move |j| (i, j))).map(|(i, j)| m[(i, j)]).collect();
        close(&compiled[3].eval(&q, &v, &[]), &m, &format!("{name} mass matrix"));
        if let Ok(want) = reference.forward_dynamics(&q, &v, &tau) {
            let got = compiled[4].eval(&q, &v, &tau);
            close(&got[..nv], &want, &format!("{name} forward dynamics"));
            close(&got[..nv], &a, &format!("{name} forward dynamics of inverse dynamics"));
        }
    }
    true
}

#[test]
fn every_robot_with_inertias_agrees_with_the_reference() {
    let mut files: Vec<_> = std::fs::read_dir(robot_path("")).unwrap().map(|e| e.unwrap().path()).collect();
    files.sort();
    let mut checked = 0;
    for path in files {
        let Ok(tree) = kinematics::load(&path) else { continue };
        if tree.links().iter().all(|l| l.inertial.is_none()) || !tree.inertia_from_geometry().is_empty() {
            continue;
        }
        if check_tree(&tree, 50) {
            println!("{}: agrees", path.display());
            checked += 1;
        }
    }
    assert!(checked >= 5, "{checked} robots with inertias");
}
