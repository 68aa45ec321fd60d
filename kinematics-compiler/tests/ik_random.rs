//! Random arms built to each closed-form family (random lengths, offsets and axis signs, written
//! as DH tables): the classification finds the family, and the plan it makes, solved by the
//! family's core function, round-trips against the compiler's own evaluation of the forward
//! kinematics (which shares nothing with the solvers' product of exponentials).
#![allow(clippy::expect_used, clippy::panic)] // test helpers fail loudly

mod common;

use common::arms::{Uniform, random_arm, solve, wrapped};
use kinematics_compiler::ik::{SixFamily, classify};
use kinematics_compiler::{Request, compile};
use kinematics_core::Pose;

#[test]
fn random_arms_of_every_family_are_classified_and_round_trip() {
    let mut rng = Uniform(2026);
    for family in SixFamily::REVOLUTE {
        let (mut worst_error, mut far) = (0.0f64, 0);
        for arm in 0..30 {
            let text = random_arm(&mut rng, family);
            let tree = kinematics_model::parse_source("random.toml", &text).expect("a valid table");
            let plan = classify(&tree, "base", "link6").unwrap_or_else(|e| panic!("{e}\n{text}"));
            assert_eq!(plan.family(), family.into(), "{text}");
            let compiled = compile(&tree, &Request::tip("link6")).expect("compiles");
            let forward = |q: &[f64; 6]| Pose::from_entries(&compiled.eval(q)[0]);
            for _ in 0..60 {
                let q = [0; 6].map(|_| std::f64::consts::PI * (2.0 * rng.next() - 1.0));
                let target = forward(&q);
                let mut solutions = solve(&plan, &target);
                solutions.measure(&target, forward);
                let errors: Vec<f64> =
                    solutions.exact().map(|s| (s.position_error / plan.reach).max(s.rotation_error)).collect();
                assert!(errors.iter().all(|e| *e < 1e-9), "{family:?} arm {arm}: {q:?}: {solutions:#?}");
                let nearest = solutions
                    .exact()
                    .map(|s| s.q.iter().zip(&q).map(|(a, b)| wrapped(a - b).abs()).fold(0.0, f64::max))
                    .fold(f64::INFINITY, f64::min);
                // Within 1e-9 rad, or near a singularity (two branches nearly one, where the
                // angles are ill-conditioned) within 1e-4 rad: that still tells a missed branch,
                // which is far; such samples are counted and kept few.
                if nearest > 1e-9 {
                    far += 1;
                } else {
                    // A sample whose own branch is well conditioned: every branch to 1e-12.
                    worst_error = errors.iter().fold(worst_error, |w, e| w.max(*e));
                }
                assert!(nearest < 1e-4, "{family:?} arm {arm}: {q:?} not among {solutions:#?}\n{text}");
            }
        }
        assert!(worst_error < 1e-12, "{family:?}: worst pose error {worst_error:e}");
        assert!(far < 30, "{family:?}: {far} of 1800 samples matched only to 1e-4");
    }
}
