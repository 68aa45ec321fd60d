//! The compiled closed forms (`IkBody`: the subproblems composed over the expression graph, the
//! geometry folded in as constants) against the run time's family functions, which solve the same
//! plan from the geometry as data: on random arms of every family the body composes, and on the
//! robots in `robots/` it covers, every branch of the body (evaluated as the generated `f64` code
//! computes it) is the run time's branch of the same index, joint for joint and flag for flag.
//! Targets in reach and out of it; singular ones (a wrist with `q5 = 0`) too.
#![allow(clippy::expect_used, clippy::panic)] // test helpers fail loudly

mod common;

use common::arms::{Uniform, random_arm, solve, wrapped};
use kinematics_compiler::ik::{IkBody, IkPlan, SixFamily, classify};
use kinematics_compiler::{Request, compile};
use kinematics_core::Pose;

/// The families the body composes (the rest keep the run time's solver).
const COMPOSED: [SixFamily; 4] = [
    SixFamily::ThreeParallelTwoIntersecting,
    SixFamily::SphericalTwoParallel,
    SixFamily::SphericalFirstTwoIntersecting,
    SixFamily::SphericalLastTwoIntersecting,
];

/// Every branch of `body` against the run time's for `target`: joint values within `1e-10` rad
/// (modulo 2 pi; the folded constants round differently), `1e-6` at a singularity (where the
/// angles are ill-conditioned), exact or least-squares alike; the same `exact` flag; no NaN.
fn agree(plan: &IkPlan, body: &IkBody, target: &Pose<f64>, what: &str) {
    let run_time = solve(plan, target);
    assert_eq!(run_time.len(), 8, "{what}");
    for (index, expected) in run_time.iter().enumerate() {
        let branch = body.eval(target, index);
        let (q, exact, singular) = (&branch.q, branch.exact, branch.singular);
        // The cosines and sines are those of the angles (a prismatic joint's are 1 and 0).
        for (j, (&c, &s)) in branch.cos.iter().zip(&branch.sin).enumerate() {
            let (expected_c, expected_s) = if plan.family() == SixFamily::SphericalPrismaticThird.into() && j == 2 {
                (1.0, 0.0)
            } else {
                (q[j].cos(), q[j].sin())
            };
            assert!(
                (c - expected_c).abs() < 1e-14 && (s - expected_s).abs() < 1e-14,
                "{what}: branch {index} joint {j}"
            );
        }
        assert!(q.iter().all(|x| x.is_finite()), "{what}: branch {index} {q:?}");
        let worst = q.iter().zip(&expected.q).map(|(a, b)| wrapped(a - b).abs()).fold(0.0, f64::max);
        let tolerance = if expected.singular || singular { 1e-6 } else { 1e-10 };
        assert!(worst <= tolerance, "{what}: branch {index}: {q:?} against {:?} ({worst:e})", expected.q);
        assert_eq!(exact, expected.exact, "{what}: branch {index}: {q:?} against {expected:?}");
    }
}

#[test]
fn random_arms_agree_with_the_run_time() {
    let mut rng = Uniform(77);
    for family in COMPOSED {
        for arm in 0..20 {
            let text = random_arm(&mut rng, family);
            let tree = kinematics_model::parse_source("random.toml", &text).expect("a valid table");
            let plan = classify(&tree, "base", "link6").unwrap_or_else(|e| panic!("{e}\n{text}"));
            let body = IkBody::of(&plan).expect("a composed family");
            let compiled = compile(&tree, &Request::tip("link6")).expect("compiles");
            for sample in 0..40 {
                let q = [0; 6].map(|_| std::f64::consts::PI * (2.0 * rng.next() - 1.0));
                let mut target = Pose::from_entries(&compiled.eval(&q)[0]);
                // Every fourth target pushed out of reach (its translation doubled).
                if sample % 4 == 3 {
                    target.translation = target.translation.map(|x| 2.0 * x);
                }
                agree(&plan, &body, &target, &format!("{family:?} arm {arm} sample {sample}\n{text}"));
            }
        }
    }
}

#[test]
fn robots_agree_with_the_run_time_including_singular_wrists() {
    let mut rng = Uniform(78);
    for (file, tip) in [
        ("ur5.urdf", "tool0"),
        ("ur5_ros.urdf", "tool0"),
        ("ur5.toml", "wrist_3_link"),
        ("ur5_modified.toml", "tool0"),
        ("ur10e.urdf", "tool0"),
        ("ur10e.toml", "wrist_3_link"),
        ("irb120.urdf", "tool0"),
        ("puma560.toml", "link6"),
        ("stanford_arm.toml", "link6"),
    ] {
        let tree = common::robot(file);
        let base = tree.link(tree.root()).name.clone();
        let plan = classify(&tree, &base, tip).unwrap_or_else(|e| panic!("{file}: {e}"));
        let body = IkBody::of(&plan).unwrap_or_else(|| panic!("{file}: {:?} is composed", plan.family()));
        let compiled = compile(&tree, &Request::tip(tip)).expect("compiles");
        for sample in 0..200 {
            let mut q = [0; 6].map(|_| 3.0 * (2.0 * rng.next() - 1.0));
            // Every fifth sample at the wrist's singularity.
            if sample % 5 == 0 {
                q[4] = 0.0;
            }
            let target = Pose::from_entries(&compiled.eval(&q)[0]);
            agree(&plan, &body, &target, &format!("{file} sample {sample}: {q:?}"));
        }
    }
}

/// At the UR family's wrist singularity (`q5 = 0` or `pi`: axis 6 in line with axes 2, 3, 4) the
/// representative with `q6 = 0` leaves the elbow out of reach for some targets the arm reaches
/// (about one in twenty-five on the UR5); there the body moves the sum of the parallel joints and
/// `q6` with it. On many such targets of every UR description, every branch agrees with the run
/// time, some exact branch reaches the target, by the compiled forward kinematics, and the body
/// without the pass is the body bit for bit but where the pass moved a branch.
#[test]
fn singular_ur_targets_are_reached() {
    let mut rng = Uniform(80);
    for (file, tip) in
        [("ur5.urdf", "tool0"), ("ur5_ros.urdf", "tool0"), ("ur5.toml", "wrist_3_link"), ("ur10e.urdf", "tool0")]
    {
        let tree = common::robot(file);
        let base = tree.link(tree.root()).name.clone();
        let plan = classify(&tree, &base, tip).unwrap_or_else(|e| panic!("{file}: {e}"));
        let body = IkBody::of(&plan).expect("composed");
        let compiled = compile(&tree, &Request::tip(tip)).expect("compiles");
        let reach = tree.reach();
        let mut moved = 0;
        for sample in 0..400 {
            let mut q = [0; 6].map(|_| std::f64::consts::PI * (2.0 * rng.next() - 1.0));
            q[4] = if sample % 2 == 0 { 0.0 } else { std::f64::consts::PI };
            let target = Pose::from_entries(&compiled.eval(&q)[0]);
            let what = format!("{file} sample {sample}: {q:?}");
            agree(&plan, &body, &target, &what);
            // The body without the pass (what `tip_ik` runs first) gives the same bits on every
            // branch but those the pass is for, which it returns singular and not exact.
            let regular = IkBody::regular(&plan).expect("the UR family has a pass");
            for index in 0..8 {
                let (full, first) = (body.eval(&target, index), regular.eval(&target, index));
                if first.singular && !first.exact {
                    moved += usize::from(full.exact);
                } else {
                    let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
                    assert_eq!(bits(&full.q), bits(&first.q), "{what}: branch {index}");
                    assert_eq!((full.exact, full.singular), (first.exact, first.singular), "{what}: branch {index}");
                }
            }
            let reached = (0..8).map(|index| body.eval(&target, index)).filter(|b| b.exact).any(|b| {
                let q: [f64; 6] = b.q.try_into().expect("six joints");
                let (position, rotation) =
                    kinematics_core::ik::pose_errors(&Pose::from_entries(&compiled.eval(&q)[0]), &target);
                position <= 1e-12 * reach && rotation <= 1e-12
            });
            assert!(reached, "{what}: no exact branch reaches the target");
        }
        // The pass was needed (a branch the body without it missed, solved with it).
        assert!(moved > 0, "{file}: no target needed the singular pass");
    }
}

#[test]
fn families_with_a_quartic_keep_the_run_times_solver() {
    let mut rng = Uniform(79);
    for family in [SixFamily::Spherical, SixFamily::ThreeParallel] {
        let text = random_arm(&mut rng, family);
        let tree = kinematics_model::parse_source("random.toml", &text).expect("a valid table");
        let plan = classify(&tree, "base", "link6").expect("classified");
        assert!(IkBody::of(&plan).is_none(), "{family:?}");
    }
}

#[test]
fn step_counts_add_up_and_constants_fold() {
    let tree = common::robot("ur5.urdf");
    let plan = classify(&tree, "base_link", "tool0").expect("the UR family");
    let body = IkBody::of(&plan).expect("composed");
    let total = body.op_count();
    let steps = body.step_counts();
    let sum = steps.iter().fold(kinematics_compiler::OpCount::default(), |a, (_, c)| a + *c);
    assert_eq!(sum, total);
    assert!(steps.iter().any(|(label, _)| label == "q3 by SP3"), "{steps:?}");
    // One atan2 per solved angle (q1, q5, q6, the sum, q3, q2), none for q4 (by difference),
    // and one for the sum moved at the wrist's singularity (q6 then by difference).
    assert_eq!(total.atan2, 7, "{total}");
    assert_eq!(total.sin_cos, 0, "{total}");
}
