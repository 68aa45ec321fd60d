//! Compiled inverse kinematics, derived: the reference vectors of `REFERENCE.md`, round trips on
//! every robot of `robots/` a closed-form family covers (checked by the generated forward
//! kinematics and by the runtime reference), and the documented answers for singular,
//! unreachable and malformed targets; and the numeric solver on seven-joint arms and as the
//! closed form's witness.
#![allow(clippy::expect_used)] // test helpers fail loudly

use kinematics::ik::{IkError, IkSolutions, NumericSolution};
use kinematics::{JointLimits, Kinematics, Pose, ReferenceModel};

#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5.urdf", base = "base_link", tip = "tool0", ik, jacobians)]
struct Ur5;

#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5_ros.urdf", base = "base_link", tip = "tool0", ik, jacobians)]
struct Ur5Ros;

#[derive(Kinematics)]
#[kinematics(dh = "robots/ur5.toml", tip = "wrist_3_link", ik, jacobians)]
struct Ur5Dh;

#[derive(Kinematics)]
#[kinematics(dh = "robots/ur5_modified.toml", tip = "tool0", ik, jacobians)]
struct Ur5Modified;

#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur10e.urdf", base = "base_link", tip = "tool0", ik, jacobians)]
struct Ur10e;

#[derive(Kinematics)]
#[kinematics(dh = "robots/ur10e.toml", tip = "wrist_3_link", ik, jacobians)]
struct Ur10eDh;

#[derive(Kinematics)]
#[kinematics(urdf = "robots/irb120.urdf", tip = "tool0", ik, jacobians)]
struct Irb120;

#[derive(Kinematics)]
#[kinematics(dh = "robots/puma560.toml", tip = "link6", ik, jacobians)]
struct Puma560;

// A general spherical-wrist arm: axes 1, 2, 3 skew (offsets along both common normals, a twist
// that is no quarter turn), a spherical wrist. Made up for the family (`tests/arms/`); no maker's
// arm.
#[derive(Kinematics)]
#[kinematics(dh = "tests/arms/skew_spherical.toml", tip = "link6", ik, jacobians)]
struct SkewSpherical;

// Axes 2, 3, 4 parallel and axes 5 and 6 apart (a UR whose wrist has a common normal of 0.06 m
// between its last two axes). Made up for the family (`tests/arms/`).
#[derive(Kinematics)]
#[kinematics(dh = "tests/arms/offset_wrist_ur.toml", tip = "link6", ik, jacobians)]
struct OffsetWristUr;

// The IRB 120 again, its joint frames turned by half turns written 3.14159265359 (as xacro
// writes them) and read as written (`tests/arms/`): axes 2 and 3 parallel, and 4, 5 and 6
// meeting, only to about 2e-13 rad, so its closed form solves a slightly different arm and each
// solution is refined on the arm as written.
#[derive(Kinematics)]
#[kinematics(urdf = "tests/arms/irb120_half_turns.urdf", tip = "tool0", ik, jacobians, exact_angles = false)]
struct Irb120HalfTurns;

/// The functions of one derived robot the checks call.
struct Arm {
    name: &'static str,
    family: &'static str,
    tip: &'static str,
    limits: [JointLimits; 6],
    pose: fn(&[f64; 6]) -> Pose<f64>,
    jacobian: fn(&[f64; 6]) -> [[f64; 6]; 6],
    ik: fn(&Pose<f64>) -> Result<IkSolutions<6, 8>, IkError>,
    numeric: fn(&Pose<f64>, &[f64; 6]) -> Result<NumericSolution<6>, IkError>,
    reference: fn() -> Result<kinematics::ReferenceFk, kinematics::LoadError>,
}

macro_rules! arm {
    ($robot:ident, $tip:literal) => {
        Arm {
            name: stringify!($robot),
            family: $robot::IK_FAMILY,
            tip: $tip,
            limits: $robot::JOINT_LIMITS,
            pose: $robot::tip_pose,
            jacobian: $robot::tip_jacobian,
            ik: $robot::tip_ik,
            numeric: $robot::tip_ik_numeric,
            reference: <$robot as ReferenceModel>::reference,
        }
    };
}

fn arms() -> [Arm; 11] {
    [
        arm!(Ur5, "tool0"),
        arm!(Irb120HalfTurns, "tool0"),
        arm!(Ur5Ros, "tool0"),
        arm!(Ur5Dh, "wrist_3_link"),
        arm!(Ur5Modified, "tool0"),
        arm!(Ur10e, "tool0"),
        arm!(Ur10eDh, "wrist_3_link"),
        arm!(Irb120, "tool0"),
        arm!(Puma560, "link6"),
        arm!(SkewSpherical, "link6"),
        arm!(OffsetWristUr, "link6"),
    ]
}

/// Families whose first step is a quartic (subproblems 5 and 6): their number of solutions
/// depends on the target (two to eight, in pairs); the others always give eight.
fn quartic(family: &str) -> bool {
    family == "spherical wrist" || family == "axes 2, 3, 4 parallel"
}

/// splitmix64, uniform in [0, 1).
struct Uniform(u64);

impl Uniform {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        (z ^ (z >> 31)) as f64 / 2f64.powi(64)
    }

    /// A configuration within the limits (continuous joints within one turn).
    fn within(&mut self, limits: &[JointLimits; 6]) -> [f64; 6] {
        limits.map(|l| {
            let (lo, hi) =
                if l.lower.is_finite() { (l.lower, l.upper) } else { (-std::f64::consts::PI, std::f64::consts::PI) };
            lo + (hi - lo) * self.next()
        })
    }
}

fn wrapped(x: f64) -> f64 {
    let tau = std::f64::consts::TAU;
    x - tau * (x / tau).round()
}

/// The largest difference of two configurations' angles, modulo 2 pi.
fn angle_distance(a: &[f64; 6], b: &[f64; 6]) -> f64 {
    a.iter().zip(b).map(|(x, y)| wrapped(x - y).abs()).fold(0.0, |m, d| if d > m || d.is_nan() { d } else { m })
}

/// How far `q` is from a singularity: the smallest singular value of the tip's Jacobian.
fn smallest_singular_value(j: &[[f64; 6]; 6]) -> f64 {
    nalgebra::Matrix6::from_fn(|r, c| j[r][c]).singular_values().min()
}

/// Samples whose Jacobian's smallest singular value is below this are within the stated distance
/// of a singularity, where the solutions' angles are ill-conditioned (about 1 in 60 samples of
/// these arms): the round trip skips them, and the singular-target tests cover the singularities
/// themselves.
const NEAR_SINGULAR: f64 = 1e-3;

/// The pose errors allowed of exact solutions within [`NEAR_SINGULAR`] of a singularity (times
/// the reach for translations).
const NEAR_SINGULAR_TOLERANCE: f64 = 1e-10;

/// The round trip: for random `q` within limits, `tip_ik(tip_pose(q))` holds `q` (modulo 2 pi,
/// within 1e-9 rad) among its exact solutions, and every exact solution reaches the target
/// within `AGREEMENT_TOLERANCE` (times the reach for translations), by the errors the generated
/// forward kinematics measured and by the runtime reference; samples within [`NEAR_SINGULAR`] of
/// a singularity, within [`NEAR_SINGULAR_TOLERANCE`].
#[test]
fn every_covered_robot_round_trips() {
    let tolerance = kinematics::AGREEMENT_TOLERANCE;
    for arm in arms() {
        let reference = (arm.reference)().expect("the description loads");
        let reach = reference.tree().reach();
        let mut rng = Uniform(20);
        let (mut checked, mut skipped) = (0, 0);
        for _ in 0..1500 {
            let q = rng.within(&arm.limits);
            let target = (arm.pose)(&q);
            let solutions = (arm.ik)(&target).expect("a pose is a valid target");
            if quartic(arm.family) {
                assert!(solutions.len() >= 2 && solutions.len().is_multiple_of(2), "{}: {solutions:#?}", arm.name);
            } else {
                assert_eq!(solutions.len(), 8, "{}", arm.name);
            }
            // Within the stated distance of a singularity the angles lose digits (a double root's
            // are as good as the square root of rounding, or the distance's reciprocal times it):
            // those samples are held to a looser bound, the rest to the agreement tolerance.
            let near_singular = smallest_singular_value(&(arm.jacobian)(&q)) < NEAR_SINGULAR;
            let bound = if near_singular { NEAR_SINGULAR_TOLERANCE } else { tolerance };
            for s in solutions.exact() {
                assert!(
                    s.position_error <= bound * reach && s.rotation_error <= bound,
                    "{}: q {q:?}: solution {s:?}",
                    arm.name
                );
                let reached = reference.link_pose(&s.q, arm.tip).expect("six finite values");
                let generated = Pose::from(reached);
                let (position, rotation) = kinematics::ik::pose_errors(&generated, &target);
                assert!(
                    position <= bound * reach && rotation <= bound,
                    "{}: the reference puts solution {:?} {position:e} m, {rotation:e} rad from the target",
                    arm.name,
                    s.q
                );
            }
            if near_singular {
                skipped += 1;
                continue;
            }
            checked += 1;
            let nearest = solutions.exact().map(|s| angle_distance(&s.q, &q)).fold(f64::INFINITY, f64::min);
            assert!(nearest <= 1e-9, "{} ({}): q {q:?} is not among {solutions:#?}", arm.name, arm.family);
        }
        assert!(skipped * 20 < checked, "{}: {skipped} of {} samples near a singularity", arm.name, checked + skipped);
    }
}

/// Every solution of both UR5 poses in `REFERENCE.md` (computed independently), and no other.
#[test]
fn the_ur5_reference_vectors() {
    let pose_a = Pose {
        rotation: [
            [0.39136499247410217, 0.3990685619662358, -0.8292030665138347],
            [0.40168612883076793, 0.7366182672130785, 0.5440972177037421],
            [0.8279382202620542, -0.5460199733143489, 0.1279862968098539],
        ],
        translation: [0.39592120537499864, 0.30261508038088697, 0.48097362717521147],
    };
    let solutions_a = [
        [0.300000000000, -1.268570665726, 1.572046004858, 3.038117314458, 0.700000000000, -1.141592653590],
        [0.300000000000, 0.223271306490, -1.572046004858, -1.592817955222, 0.700000000000, -1.141592653590],
        [0.300000000000, -1.200000000000, 1.000000000000, 0.400000000000, -0.700000000000, 2.000000000000],
        [0.300000000000, -0.243777422086, -1.000000000000, 1.443777422086, -0.700000000000, 2.000000000000],
        [-2.427505464848, -2.895481585285, 0.937950114714, 1.515277316954, 2.837896873566, 1.729410998351],
        [-2.427505464848, -1.998134461626, -0.937950114714, 2.493830422723, 2.837896873566, 1.729410998351],
        [-2.427505464848, 2.925200732383, 1.623209879803, -1.849072112213, -2.837896873566, -1.412181655239],
        [-2.427505464848, -1.819186218052, -1.623209879803, -0.141450709351, -2.837896873566, -1.412181655239],
    ];
    let pose_b = Pose {
        rotation: [
            [0.9572194653517239, 0.19126038926368147, -0.2171413333533367],
            [-0.12125487559869388, -0.41622480571247433, -0.9011404808647531],
            [-0.26273208843859386, 0.8889186546632476, -0.3752272312830943],
        ],
        translation: [0.05268569775616097, -0.16972769527887926, 0.4398056622610034],
    };
    let solutions_b = [
        [-2.100000000000, -2.288041157984, 1.900000000000, 0.788041157984, 1.300000000000, -0.400000000000],
        [-2.100000000000, -0.500000000000, -1.900000000000, 2.800000000000, 1.300000000000, -0.400000000000],
        [-2.100000000000, -2.637003794990, 2.408417374504, -2.513006233104, -1.300000000000, 2.741592653590],
        [-2.100000000000, -0.436580222009, -2.408417374504, 0.103404942923, -1.300000000000, 2.741592653590],
        [-2.911221021390, -2.459720440353, 1.971333874750, 1.220901820518, 0.595707230132, -0.927371391280],
        [-2.911221021390, -0.609211260530, -1.971333874750, -2.970124916986, 0.595707230132, -0.927371391280],
        [-2.911221021390, -2.976970422258, 2.313699974340, -1.745806950757, -0.595707230132, 2.214221262310],
        [-2.911221021390, -0.845196240036, -2.313699974340, 0.749818815701, -0.595707230132, 2.214221262310],
    ];
    for (target, expected) in [(pose_a, solutions_a), (pose_b, solutions_b)] {
        let solutions = Ur5::tip_ik(&target).expect("a pose");
        assert_eq!(solutions.exact().count(), 8);
        // The vectors are rounded to 12 decimals.
        for e in &expected {
            assert!(solutions.iter().any(|s| angle_distance(&s.q, e) < 1e-11), "{e:?} missing from {solutions:#?}");
        }
        for s in solutions.iter() {
            assert!(expected.iter().any(|e| angle_distance(&s.q, e) < 1e-11), "{:?} is no reference solution", s.q);
        }
    }
}

/// At a wrist singularity (the fifth joint at zero or a half turn: axes 4 and 6 in line) the
/// branches through it are representatives of a continuum, flagged singular, and the target is
/// still reached: from many configurations of every arm with a wrist (the UR's representative
/// with `q6 = 0` leaves the elbow out of reach for about one in twenty-five of them, where the
/// solver moves it), some exact singular solution reaches the target by its own errors and by
/// the runtime reference, and every exact singular one has errors within `1e-12`.
#[test]
fn wrist_singularities_give_flagged_representatives() {
    let mut rng = Uniform(5);
    for arm in [
        arm!(Ur5, "tool0"),
        arm!(Ur10e, "tool0"),
        arm!(Ur5Dh, "wrist_3_link"),
        arm!(Irb120, "tool0"),
        arm!(Puma560, "link6"),
    ] {
        let (name, pose, ik) = (arm.name, arm.pose, arm.ik);
        let reference = (arm.reference)().expect("the reference loads");
        let reach = reference.tree().reach();
        let fixed = [[0.3, -1.2, 1.0, 0.4, 0.0, 2.0], [-0.5, 0.2, 0.6, -1.0, 0.0, 0.0], [0.0; 6]];
        let random = (0..300).map(|i| {
            let mut q = rng.within(&arm.limits);
            q[4] = if i % 2 == 0 { 0.0 } else { std::f64::consts::PI };
            q
        });
        for q in fixed.into_iter().chain(random) {
            let target = pose(&q);
            let solutions = ik(&target).expect("a pose");
            let mut reached = false;
            for s in solutions.iter().filter(|s| s.singular && s.exact) {
                assert!(s.q.iter().all(|x| x.is_finite()));
                assert!(s.position_error < 1e-12 * reach && s.rotation_error < 1e-12, "{name}: {q:?}: {s:?}");
                let by_reference = Pose::from(reference.link_pose(&s.q, arm.tip).expect("six finite values"));
                let (position, rotation) = kinematics::ik::pose_errors(&by_reference, &target);
                assert!(position < 1e-12 * reach && rotation < 1e-12, "{name}: {q:?}: {s:?} by the reference");
                reached = true;
            }
            assert!(reached, "{name}: {q:?}: no exact singular solution: {solutions:#?}");
        }
    }
}

/// A target out of reach gets every branch as the least-squares best, flagged, never NaN.
#[test]
fn unreachable_targets_are_flagged_least_squares() {
    let mut target = Ur5::tip_pose(&[0.3, -1.2, 1.0, 0.4, -0.7, 2.0]);
    for translation in [[3.0, 0.0, 0.5], [0.0, 0.0, 10.0], [1e6, -1e6, 1e6]] {
        target.translation = translation;
        for solutions in [Ur5::tip_ik(&target), Irb120::tip_ik(&target), Puma560::tip_ik(&target)] {
            let solutions = solutions.expect("a pose");
            assert_eq!(solutions.len(), 8);
            for s in solutions.iter() {
                assert!(!s.exact, "{translation:?}: {s:?}");
                assert!(s.q.iter().all(|x| x.is_finite()), "{s:?}");
                assert!(s.position_error.is_finite() && s.position_error > 0.1, "{s:?}");
            }
        }
    }
}

/// A target that is no pose is an error, not an answer.
#[test]
fn malformed_targets_are_errors() {
    let good = Ur5::tip_pose(&[0.1; 6]);
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let mut target = good;
        target.translation[1] = bad;
        assert_eq!(Ur5::tip_ik(&target), Err(IkError::NonFinite));
        let mut target = good;
        target.rotation[2][0] = bad;
        assert_eq!(Irb120::tip_ik(&target), Err(IkError::NonFinite));
    }
    let mut scaled = good;
    scaled.rotation[0] = scaled.rotation[0].map(|x| 1.01 * x);
    assert!(matches!(Ur5::tip_ik(&scaled), Err(IkError::NotARotation { deviation }) if deviation > 0.01));
    let mut mirrored = good;
    mirrored.rotation[1] = mirrored.rotation[1].map(|x| -x);
    assert!(matches!(Puma560::tip_ik(&mirrored), Err(IkError::NotARotation { .. })));
    // Within the stated tolerance a rounded rotation is taken (and its error reported).
    let mut rounded = good;
    rounded.rotation[0][0] += 1e-8;
    let solutions = Ur5::tip_ik(&rounded).expect("within ROTATION_TOLERANCE");
    assert!(solutions.exact().all(|s| s.rotation_error < 1e-7));
}

/// The nearest solution to a seed is the configuration the seed was near; limits keep only what
/// fits, moved by whole turns.
#[test]
fn nearest_and_within_limits() {
    let q = [0.3, -1.2, 1.0, 0.4, -0.7, 2.0];
    let target = Ur5::tip_pose(&q);
    let seed = q.map(|x| x + 0.05);
    let nearest = Ur5::tip_ik_nearest(&target, &seed).expect("a pose").expect("solutions");
    assert!(angle_distance(&nearest.q, &q) < 1e-12 && nearest.q.iter().zip(&q).all(|(a, b)| (a - b).abs() < 1e-12));
    // A seed a whole turn away gets the solution a whole turn away.
    let turned = seed.map(|x| x + std::f64::consts::TAU);
    let far = Ur5::tip_ik_nearest(&target, &turned).expect("a pose").expect("solutions");
    assert!(far.q.iter().zip(&q).all(|(a, b)| (a - b - std::f64::consts::TAU).abs() < 1e-12), "{far:?}");

    let mut rng = Uniform(3);
    for _ in 0..200 {
        let q = rng.within(&Irb120::JOINT_LIMITS);
        let within = Irb120::tip_ik_within_limits(&Irb120::tip_pose(&q)).expect("a pose");
        assert!(within.exact().any(|s| angle_distance(&s.q, &q) < 1e-6), "{q:?}");
        for s in within.iter() {
            for (value, limits) in s.q.iter().zip(&Irb120::JOINT_LIMITS) {
                assert!(limits.lower <= *value && *value <= limits.upper, "{s:?}");
            }
        }
    }
}

/// Every solver takes nalgebra's isometries as they are (`kinematics::ik::IkTarget`), and answers
/// them as it answers the same pose; an isometry holding NaN is refused like a pose holding it.
#[test]
fn isometry_targets() {
    let q = [0.3, -1.2, 1.0, 0.4, -0.7, 2.0];
    let iso: nalgebra::Isometry3<f64> = Ur5::tip_pose(&q).into();
    let solutions = Ur5::tip_ik(&iso).expect("a pose");
    assert!(solutions.exact().any(|s| angle_distance(&s.q, &q) < 1e-9));
    let from_pose = Ur5::tip_ik(&Pose::from(iso)).expect("a pose");
    assert_eq!(solutions.as_slice(), from_pose.as_slice());
    let seed = [0.31, -1.19, 1.0, 0.4, -0.7, 2.0];
    let nearest = Ur5::tip_ik_nearest(&iso, &seed).expect("a pose").expect("solutions");
    assert!(angle_distance(&nearest.q, &q) < 1e-9, "{nearest:?}");
    assert_eq!(Ur5::tip_ik_within_limits(&iso).expect("a pose").len(), solutions.len());
    let iiwa_q = [0.3, -0.5, 0.2, 1.1, -0.4, 0.6, 0.1];
    let iiwa_target: nalgebra::Isometry3<f64> = Iiwa14::tip_pose(&iiwa_q).into();
    let numeric = Iiwa14::tip_ik_numeric(&iiwa_target, &[0.0; 7]).expect("a pose");
    assert!(numeric.converged, "{numeric:?}");
    let mut broken = iso;
    broken.translation.vector.x = f64::NAN;
    assert_eq!(Ur5::tip_ik(&broken).err(), Some(IkError::NonFinite));
    assert_eq!(Ur5::IK_FAMILY, "axes 2, 3, 4 parallel, axes 5 and 6 meet");
    assert_eq!(Irb120::IK_FAMILY, "spherical wrist, axes 2 and 3 parallel");
    assert_eq!(SkewSpherical::IK_FAMILY, "spherical wrist");
    assert_eq!(OffsetWristUr::IK_FAMILY, "axes 2, 3, 4 parallel");
}

#[derive(Kinematics)]
#[kinematics(dh = "robots/panda.toml", tip = "flange", ik = "numeric")]
struct Panda;

#[derive(Kinematics)]
#[kinematics(urdf = "robots/iiwa14.urdf", tip = "iiwa_link_ee", ik = "numeric")]
struct Iiwa14;

/// The numeric solver on the seven-joint arms: random reachable targets (the pose at a random
/// configuration within limits), random seeds within limits; at least 99.5% converge to 1e-10,
/// and each converged answer's pose is the target's by the errors it reports and by the runtime
/// reference.
#[test]
fn numeric_ik_converges_on_seven_joint_arms() {
    struct Arm7 {
        name: &'static str,
        tip: &'static str,
        limits: [JointLimits; 7],
        pose: fn(&[f64; 7]) -> Pose<f64>,
        solve: fn(&Pose<f64>, &[f64; 7]) -> Result<NumericSolution<7>, IkError>,
        reference: kinematics::ReferenceFk,
    }
    let arms = [
        Arm7 {
            name: "panda",
            tip: "flange",
            limits: Panda::JOINT_LIMITS,
            pose: Panda::tip_pose,
            solve: Panda::tip_ik_numeric,
            reference: Panda::reference().expect("loads"),
        },
        Arm7 {
            name: "iiwa14",
            tip: "iiwa_link_ee",
            limits: Iiwa14::JOINT_LIMITS,
            pose: Iiwa14::tip_pose,
            solve: Iiwa14::tip_ik_numeric,
            reference: Iiwa14::reference().expect("loads"),
        },
    ];
    for Arm7 { name, tip, limits, pose, solve, reference } in arms {
        let mut rng = Uniform(5);
        let within = |rng: &mut Uniform| limits.map(|l| l.lower + (l.upper - l.lower) * rng.next());
        let samples = 2000;
        let mut converged = 0;
        for _ in 0..samples {
            let target = pose(&within(&mut rng));
            let seed = within(&mut rng);
            let found = solve(&target, &seed).expect("a pose and a finite seed");
            assert!(found.q.iter().zip(&limits).all(|(q, l)| l.lower <= *q && *q <= l.upper), "{name}: {found:?}");
            if found.converged {
                converged += 1;
                assert!(found.position_error <= 1e-10 && found.rotation_error <= 1e-10, "{name}: {found:?}");
                let reached = Pose::from(reference.link_pose(&found.q, tip).expect("finite q"));
                let (position, rotation) = kinematics::ik::pose_errors(&reached, &target);
                assert!(position <= 1e-10 && rotation <= 1e-10, "{name}: the reference: {position:e}, {rotation:e}");
            }
        }
        assert!(converged * 1000 >= samples * 995, "{name}: {converged} of {samples} converged");
    }
}

// A tree: a torso (one waist joint) with two seven-joint arms and their grippers, 17 degrees of
// freedom; the tip is the left arm's tool, whose chain holds eight of them.
#[derive(Kinematics)]
#[kinematics(urdf = "robots/dual_arm_torso.urdf", tip = "tool_l", ik = "numeric")]
struct DualArmLeft;

/// The numeric solver on a tree's tip: the whole configuration in, the joints off the tip's chain
/// (the other arm, both grippers) left at the seed's values, the chain's moved within limits;
/// random reachable targets from random seeds converge (at least 99% of them), each converged
/// answer reaching its target by its own errors and by the runtime reference.
#[test]
fn numeric_ik_serves_a_tree_tip() {
    let reference = DualArmLeft::reference().expect("loads");
    let tree = reference.tree();
    let chain: Vec<bool> = {
        let on = tree.chain_dofs(&tree.chain("world", "tool_l").expect("a chain"));
        (0..DualArmLeft::DOF).map(|i| on.contains(&i)).collect()
    };
    assert_eq!(chain.iter().filter(|&&c| c).count(), 8, "waist and seven arm joints");
    let limits = DualArmLeft::JOINT_LIMITS;
    let mut rng = Uniform(21);
    let within = |rng: &mut Uniform| {
        limits.map(|l| {
            let (lo, hi) = if l.lower.is_finite() { (l.lower, l.upper) } else { (-3.1, 3.1) };
            lo + (hi - lo) * rng.next()
        })
    };
    let samples = 300;
    let mut converged = 0;
    for _ in 0..samples {
        let target = DualArmLeft::tip_pose(&within(&mut rng));
        let seed = within(&mut rng);
        let found = DualArmLeft::tip_ik_numeric(&target, &seed).expect("a pose and a finite seed");
        for (i, (q, s)) in found.q.iter().zip(&seed).enumerate() {
            if !chain[i] {
                assert_eq!(q.to_bits(), s.to_bits(), "joint {i} is off the chain: {found:?}");
            }
        }
        assert!(found.q.iter().zip(&limits).all(|(q, l)| l.lower <= *q && *q <= l.upper), "{found:?}");
        if found.converged {
            converged += 1;
            let reached = Pose::from(reference.link_pose(&found.q, "tool_l").expect("finite q"));
            let (position, rotation) = kinematics::ik::pose_errors(&reached, &target);
            assert!(position <= 1e-10 && rotation <= 1e-10, "the reference: {position:e}, {rotation:e}");
        }
    }
    assert!(converged * 100 >= samples * 99, "{converged} of {samples} converged");
}

/// The numeric solver is the closed form's witness: from many seeds it finds no solution the
/// closed form misses (each converged answer is one of the closed form's, modulo 2 pi).
#[test]
fn the_numeric_solver_finds_no_solution_the_closed_form_misses() {
    for arm in [arm!(Ur5, "tool0"), arm!(Irb120, "tool0"), arm!(SkewSpherical, "link6"), arm!(OffsetWristUr, "link6")] {
        let mut rng = Uniform(9);
        for _ in 0..12 {
            let target = (arm.pose)(&rng.within(&arm.limits));
            let closed = (arm.ik)(&target).expect("a pose");
            for _ in 0..25 {
                let seed = rng.within(&arm.limits);
                let found = (arm.numeric)(&target, &seed).expect("a pose and a finite seed");
                if found.converged {
                    let nearest = closed.exact().map(|s| angle_distance(&s.q, &found.q)).fold(f64::INFINITY, f64::min);
                    assert!(
                        nearest < 1e-4,
                        "{}: numeric {:?} is no closed-form solution: {closed:#?}",
                        arm.name,
                        found.q
                    );
                }
            }
        }
    }
}

#[test]
fn non_finite_seeds_are_errors() {
    let target = Ur5::tip_pose(&[0.1; 6]);
    for bad in [f64::NAN, f64::INFINITY] {
        let mut seed = [0.0; 6];
        seed[2] = bad;
        assert_eq!(Ur5::tip_ik_numeric(&target, &seed), Err(IkError::NonFiniteSeed));
        assert_eq!(Ur5::tip_ik_nearest(&target, &seed), Err(IkError::NonFiniteSeed));
    }
}

#[derive(Kinematics)]
#[kinematics(urdf = "robots/iiwa14.urdf", tip = "iiwa_link_ee", ik(free = "iiwa_joint_3"))]
struct Iiwa14Free;

/// The iiwa 14 with its third joint given: the other six form a spherical wrist with the first
/// two axes meeting, solved in closed form for any value of the third. Round trip from random
/// configurations within limits, the third joint's value passed as it was.
#[test]
fn a_seven_joint_arm_with_a_free_joint_round_trips() {
    assert_eq!(Iiwa14Free::IK_FAMILY, "spherical wrist, axes 1 and 2 meet");
    let reach = Iiwa14Free::reference().expect("loads").tree().reach();
    let mut rng = Uniform(77);
    let (mut checked, mut near_singular) = (0, 0);
    for _ in 0..1500 {
        let q: [f64; 7] = Iiwa14Free::JOINT_LIMITS.map(|l| l.lower + (l.upper - l.lower) * rng.next());
        let target = Iiwa14Free::tip_pose(&q);
        let solutions = Iiwa14Free::tip_ik(&target, q[2]).expect("a pose");
        assert_eq!(solutions.len(), 8);
        for s in solutions.exact() {
            assert_eq!(s.q[2], q[2]);
            assert!(s.position_error <= 1e-12 * reach && s.rotation_error <= 1e-12, "{q:?}: {s:?}");
        }
        let nearest = solutions
            .exact()
            .map(|s| s.q.iter().zip(&q).map(|(a, b)| wrapped(a - b).abs()).fold(0.0, f64::max))
            .fold(f64::INFINITY, f64::min);
        // Near a singularity of the six the angles are ill-conditioned (see NEAR_SINGULAR); the
        // pose errors above still hold.
        if nearest > 1e-9 {
            near_singular += 1;
            assert!(nearest < 1e-4, "{q:?} is not among {solutions:#?}");
            continue;
        }
        checked += 1;
        // The seed's third joint is the free joint's value; the others are near q.
        let mut seed = q.map(|x| x + 1e-3);
        seed[2] = q[2];
        let found = Iiwa14Free::tip_ik_nearest(&target, &seed).expect("a pose").expect("solutions");
        assert!(found.q.iter().zip(&q).all(|(a, b)| (a - b).abs() < 1e-9), "{found:?} vs {q:?}");
    }
    assert!(near_singular * 50 < checked, "{near_singular} near a singularity, {checked} checked");
    assert_eq!(Iiwa14Free::tip_ik(&Iiwa14Free::tip_pose(&[0.1; 7]), f64::NAN), Err(IkError::NonFiniteFree));
}

#[derive(Kinematics)]
#[kinematics(dh = "robots/planar_2r.toml", tip = "link2", ik)]
struct Planar2r;

#[derive(Kinematics)]
#[kinematics(urdf = "robots/planar_3r.urdf", tip = "tool", ik)]
struct Planar3r;

#[derive(Kinematics)]
#[kinematics(dh = "robots/planar_3r_modified.toml", tip = "tool", ik)]
struct Planar3rModified;

#[derive(Kinematics)]
#[kinematics(dh = "robots/scara.toml", tip = "link4", ik)]
struct Scara;

/// The planar family on the planar arms and the SCARA: both elbow branches, the configuration
/// among the exact ones (the prismatic joint's stroke as given), every exact solution on the
/// target (position only for two joints, whose rotation follows), by its own errors and the
/// runtime reference.
#[test]
fn planar_arms_and_the_scara_round_trip() {
    macro_rules! round_trip {
        ($robot:ident, $tip:literal, $n:literal, $rotation:expr) => {{
            assert_eq!($robot::IK_FAMILY, "planar: revolute axes parallel, a prismatic joint along them at most");
            let reference = $robot::reference().expect("loads");
            let reach = reference.tree().reach();
            let mut rng = Uniform(99);
            let mut far = 0;
            for _ in 0..1000 {
                let q: [f64; $n] = $robot::JOINT_LIMITS.map(|l| {
                    let (lo, hi) = if l.lower.is_finite() { (l.lower, l.upper) } else { (-3.1, 3.1) };
                    lo + (hi - lo) * rng.next()
                });
                let target = $robot::tip_pose(&q);
                let solutions = $robot::tip_ik(&target).expect("a pose");
                assert_eq!(solutions.len(), 2);
                for s in solutions.exact() {
                    assert!(s.position_error <= 1e-12 * reach, "{}: {q:?}: {s:?}", stringify!($robot));
                    if $rotation {
                        assert!(s.rotation_error <= 1e-12, "{}: {q:?}: {s:?}", stringify!($robot));
                    }
                    let reached = Pose::from(reference.link_pose(&s.q, $tip).expect("finite"));
                    let (position, _) = kinematics::ik::pose_errors(&reached, &target);
                    assert!(position <= 1e-12 * reach, "{}: the reference: {position:e}", stringify!($robot));
                }
                let nearest = solutions
                    .exact()
                    .map(|s| s.q.iter().zip(&q).map(|(a, b)| wrapped(a - b).abs()).fold(0.0, f64::max))
                    .fold(f64::INFINITY, f64::min);
                // The elbow straight is the planar arms' singularity: near it the angles are
                // ill-conditioned (counted, kept few).
                if nearest > 1e-9 {
                    far += 1;
                }
                assert!(nearest < 1e-5, "{}: {q:?} not among {solutions:#?}", stringify!($robot));
            }
            assert!(far < 10, "{}: {far} of 1000 near the straight elbow", stringify!($robot));
        }};
    }
    round_trip!(Planar2r, "link2", 2, false);
    round_trip!(Planar3r, "tool", 3, true);
    round_trip!(Planar3rModified, "tool", 3, true);
    round_trip!(Scara, "link4", 4, true);
    // Off the plane: least squares, flagged.
    let mut target = Planar3r::tip_pose(&[0.3, -0.5, 1.0]);
    target.translation[2] += 0.1;
    assert!(Planar3r::tip_ik(&target).expect("a pose").iter().all(|s| !s.exact));
}

#[derive(Kinematics)]
#[kinematics(dh = "robots/stanford_arm.toml", tip = "link6", ik, jacobians)]
struct Stanford;

/// The Stanford arm (joint 3 prismatic): the slide from the wrist centre's distance, then the
/// shoulder and the wrist; a round trip from configurations within limits, the slide compared
/// as a length.
#[test]
fn the_stanford_arm_round_trips() {
    assert_eq!(Stanford::IK_FAMILY, "spherical wrist, axes 1 and 2 meet, joint 3 prismatic");
    let reference = Stanford::reference().expect("loads");
    let reach = reference.tree().reach();
    let mut rng = Uniform(61);
    let (mut checked, mut skipped) = (0, 0);
    for _ in 0..1500 {
        let q = rng.within(&Stanford::JOINT_LIMITS);
        let target = Stanford::tip_pose(&q);
        let solutions = Stanford::tip_ik(&target).expect("a pose");
        assert_eq!(solutions.len(), 8);
        for s in solutions.exact() {
            assert!(s.position_error <= 1e-12 * reach && s.rotation_error <= 1e-12, "{q:?}: {s:?}");
            let reached = Pose::from(reference.link_pose(&s.q, "link6").expect("finite"));
            let (position, rotation) = kinematics::ik::pose_errors(&reached, &target);
            assert!(position <= 1e-12 * reach && rotation <= 1e-12, "the reference: {position:e} {rotation:e}");
        }
        if smallest_singular_value(&Stanford::tip_jacobian(&q)) < NEAR_SINGULAR {
            skipped += 1;
            continue;
        }
        checked += 1;
        let matches = |s: &kinematics::ik::IkSolution<6>| {
            (s.q[2] - q[2]).abs() < 1e-9
                && s.q.iter().zip(&q).enumerate().all(|(i, (a, b))| i == 2 || wrapped(a - b).abs() < 1e-9)
        };
        assert!(solutions.exact().any(matches), "{q:?} not among {solutions:#?}");
        // The slide's value is a length: within limits it is kept as it is.
        let within = Stanford::tip_ik_within_limits(&target).expect("a pose");
        assert!(within.iter().all(|s| s.q[2] >= 0.3048 && s.q[2] <= 1.27), "{within:#?}");
    }
    assert!(skipped * 20 < checked, "{skipped} near a singularity, {checked} checked");
}

/// IK to the last digit: the IRB 120 written with inexact half turns is solved by its family with
/// its axes made exact, 2e-13 rad off, which left most solutions 1e-13 to 4e-13 x reach from their
/// targets; refined on the arm as written, every exact solution of 200 random targets is within
/// 1e-13 x reach by its own errors and by the runtime reference, and each is still its branch:
/// within 1e-9 rad of the same branch's solution of the IRB 120 written exactly (`Irb120`, whose
/// solutions need no refinement and whose errors stay at rounding).
#[test]
fn the_closed_form_is_refined_to_the_arm_as_written() {
    assert_eq!(Irb120HalfTurns::IK_FAMILY, Irb120::IK_FAMILY);
    let reference = Irb120HalfTurns::reference().expect("the description loads");
    let reach = reference.tree().reach();
    let mut rng = Uniform(41);
    let (mut exact, mut worst, mut worst_exact_arm) = (0, 0.0_f64, 0.0_f64);
    for _ in 0..200 {
        let q = rng.within(&Irb120HalfTurns::JOINT_LIMITS);
        let target = Irb120HalfTurns::tip_pose(&q);
        let refined = Irb120HalfTurns::tip_ik(&target).expect("a pose");
        let written_exactly = Irb120::tip_ik(&target).expect("a pose");
        assert_eq!(refined.len(), written_exactly.len());
        for (s, t) in refined.iter().zip(written_exactly.iter()) {
            assert_eq!(s.exact, t.exact, "{s:?} against {t:?}");
            if !s.exact {
                continue;
            }
            exact += 1;
            let reached = Pose::from(reference.link_pose(&s.q, "tool0").expect("finite"));
            let (position, rotation) = kinematics::ik::pose_errors(&reached, &target);
            // Each error on its own (a NaN fails every comparison, where `max` would drop it).
            for error in [s.position_error / reach, s.rotation_error, position / reach, rotation] {
                assert!(error <= 1e-13, "{s:?}: {position:e} m, {rotation:e} rad by the reference");
                worst = worst.max(error);
            }
            assert!(angle_distance(&s.q, &t.q) < 1e-9, "{s:?} left its branch {t:?}");
            for error in [t.position_error / reach, t.rotation_error] {
                assert!(error < kinematics::ik::REFINE_ABOVE, "the exactly written arm: {t:?}");
                worst_exact_arm = worst_exact_arm.max(error);
            }
        }
    }
    assert!(exact >= 1500, "{exact} exact solutions");
    println!(
        "{exact} exact solutions, the farthest {worst:.1e} x reach (the arm written exactly: {worst_exact_arm:.1e})"
    );
}
