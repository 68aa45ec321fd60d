//! Inverse kinematics speed: the closed forms (UR5, IRB 120, PUMA 560, compiled to straight-line
//! bodies: every solution of a pose, the solution nearest a seed, the run time's family function
//! they were compiled from, and the compiled body alone on eight lanes, on four and on one; the
//! IRB 120 written with inexact half turns, whose solutions `tip_ik` refines on the arm as
//! written; and
//! one arm of each family whose first step is a quartic, which `tip_ik` solves with the run
//! time's family function) and the numeric solver on the seven-joint arms (Panda, iiwa 14) and
//! the UR5 against the `k` crate's Jacobian IK solver on the same targets and seeds, with both
//! success rates. `ik-geo`, the run-time IK-Geo, builds nlopt with cmake, so its side of the comparison
//! lives in `benches/ik-geo/` (its own crate, run by its script), not here.
//!
//! `cargo bench --bench ik` measures; under `cargo test` every body runs once and is checked
//! instead: each closed-form answer holds the configuration its target was made from, and each
//! converged numeric answer reaches its target by the runtime reference.
//!
//! The robots are taken as traits, so each robot's bodies inline into `dispatch`. The comparisons
//! are also paired (`target/criterion/kinematics-ik-paired.tsv`).
//!
//! Beside the compiled bodies, the tip's pose on lanes is timed too: what measuring the solutions
//! would cost with `sin_cos`.

#![allow(clippy::expect_used, clippy::panic)] // a benchmark fails loudly on a robot that does not load

mod common;

use std::hint::black_box;
use std::time::Duration;

use criterion::Criterion;
use kinematics::ik::{IkBranch, IkError, IkReal, IkSolution, IkSolutions, NumericSolution};
use kinematics::{F64x4, F64x8, JointLimits, Kinematics, Pose, ReferenceModel};

#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5.urdf", base = "base_link", tip = "tool0", ik)]
struct Ur5;

#[derive(Kinematics)]
#[kinematics(urdf = "robots/irb120.urdf", tip = "tool0", ik)]
struct Irb120;

#[derive(Kinematics)]
#[kinematics(dh = "robots/puma560.toml", tip = "link6", ik)]
struct Puma560;

// The IRB 120 with its joint frames turned by half turns written 3.14159265359, read as written
// (`tests/arms/`): its family solves it with the axes made exact, and `tip_ik` refines every
// solution on the arm as written. What that costs, beside `Irb120`.
#[derive(Kinematics)]
#[kinematics(urdf = "tests/arms/irb120_half_turns.urdf", tip = "tool0", ik, exact_angles = false)]
struct Irb120HalfTurns;

// The two families whose first step is a quartic, on the made-up arms of `tests/arms/` that
// `tests/ik.rs` checks them on (no maker's arm in `robots/` is of either family): axes 1, 2, 3 skew with a spherical wrist,
// and a UR whose last two axes are 0.06 m apart.
#[derive(Kinematics)]
#[kinematics(dh = "tests/arms/skew_spherical.toml", tip = "link6", ik)]
struct SkewSpherical;

#[derive(Kinematics)]
#[kinematics(dh = "tests/arms/offset_wrist_ur.toml", tip = "link6", ik)]
struct OffsetWristUr;

#[derive(Kinematics)]
#[kinematics(urdf = "robots/panda.urdf", tip = "panda_hand", ik = "numeric")]
struct Panda;

#[derive(Kinematics)]
#[kinematics(urdf = "robots/iiwa14.urdf", tip = "iiwa_link_ee", ik = "numeric")]
struct Iiwa14;

/// Targets (and seeds) cycled through in the timed loops.
const INPUTS: usize = 256;
/// Targets of the numeric comparison (each solved once per solver for the success rates).
const NUMERIC_TARGETS: usize = 500;

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
    fn within<const N: usize>(&mut self, limits: &[JointLimits; N]) -> [f64; N] {
        limits.map(|l| {
            let (lo, hi) = if l.lower.is_finite() { (l.lower, l.upper) } else { (-3.1, 3.1) };
            lo + (hi - lo) * self.next()
        })
    }
}

fn wrapped(x: f64) -> f64 {
    let tau = std::f64::consts::TAU;
    x - tau * (x / tau).round()
}

/// One closed-form robot's functions, as a trait so that each robot's benchmark is compiled for
/// it and the bodies inline into `kinematics::dispatch` (through a function pointer the baseline
/// body would run).
trait Closed {
    const NAME: &'static str;
    const LIMITS: [JointLimits; 6];
    fn pose(q: &[f64; 6]) -> Pose<f64>;
    fn all(target: &Pose<f64>) -> Result<IkSolutions<6, 8>, IkError>;
    fn nearest(target: &Pose<f64>, seed: &[f64; 6]) -> Result<Option<IkSolution<6>>, IkError>;
    /// The run time's family function with the robot's geometry, dispatched as generated code
    /// runs it (what `tip_ik` calls for a family with a quartic first step; for the others the
    /// same branch as the compiled body, on numbers in `F64x8` lanes, the arm's geometry not
    /// folded into it).
    fn solver(target: &Pose<f64>) -> IkSolutions<6, 8>;
}

/// A robot whose closed form is compiled to a straight-line body.
trait Compiled: Closed {
    /// The compiled body: one branch per lane (`tip_ik_branch_generic`).
    fn branches<T: IkReal>(target: &Pose<T>, signs: &[T; 3]) -> IkBranch<T, 6>;
    /// The pose at `q` on lanes: what measuring the solutions would cost with `sin_cos` (the
    /// measure `tip_ik` runs takes each angle's cosine and sine from the solver instead).
    fn pose8(q: &[F64x8; 6]) -> Pose<F64x8>;
}

macro_rules! closed {
    ($robot:ident, $name:literal, $family:ident) => {
        impl Closed for $robot {
            const NAME: &'static str = $name;
            const LIMITS: [JointLimits; 6] = $robot::JOINT_LIMITS;
            fn pose(q: &[f64; 6]) -> Pose<f64> {
                $robot::tip_pose(q)
            }
            fn all(target: &Pose<f64>) -> Result<IkSolutions<6, 8>, IkError> {
                $robot::tip_ik(target)
            }
            fn nearest(target: &Pose<f64>, seed: &[f64; 6]) -> Result<Option<IkSolution<6>>, IkError> {
                $robot::tip_ik_nearest(target, seed)
            }
            fn solver(target: &Pose<f64>) -> IkSolutions<6, 8> {
                kinematics::dispatch(
                    #[inline(always)]
                    || kinematics::ik::$family(&$robot::IK_ARM, target),
                )
            }
        }
    };
}

macro_rules! compiled {
    ($robot:ident) => {
        impl Compiled for $robot {
            #[inline(always)]
            fn branches<T: IkReal>(target: &Pose<T>, signs: &[T; 3]) -> IkBranch<T, 6> {
                $robot::tip_ik_branch_generic(target, signs)
            }
            #[inline(always)]
            fn pose8(q: &[F64x8; 6]) -> Pose<F64x8> {
                $robot::tip_pose_generic(q)
            }
        }
    };
}

closed!(Ur5, "ur5", three_parallel_two_intersecting);
closed!(Irb120, "irb120", spherical_two_parallel);
closed!(Puma560, "puma560", spherical_two_parallel);
closed!(Irb120HalfTurns, "irb120-half-turns", spherical_two_parallel);
closed!(SkewSpherical, "skew-spherical", spherical);
closed!(OffsetWristUr, "offset-wrist-ur", three_parallel);
compiled!(Ur5);
compiled!(Irb120);
compiled!(Puma560);

/// The targets, seeds and configurations a closed-form robot is timed on.
struct Inputs {
    qs: Vec<[f64; 6]>,
    targets: Vec<Pose<f64>>,
    seeds: Vec<[f64; 6]>,
}

fn inputs<R: Closed>() -> Inputs {
    let mut rng = Uniform(11);
    let qs: Vec<[f64; 6]> = (0..INPUTS).map(|_| rng.within(&R::LIMITS)).collect();
    let targets = qs.iter().map(R::pose).collect();
    // Seeds near each configuration, as a controller's last command is near its next answer.
    let seeds = qs.iter().map(|q| q.map(|x| x + 0.01)).collect();
    Inputs { qs, targets, seeds }
}

/// Every solution, the nearest, and the run time's family function: for every closed form.
fn closed<R: Closed>(c: Option<&mut Criterion>) {
    let Inputs { qs, targets, seeds } = inputs::<R>();
    let Some(c) = c else {
        for ((q, target), seed) in qs.iter().zip(&targets).zip(&seeds) {
            let all = R::all(target).expect("a pose");
            let near = |s: &[f64; 6]| s.iter().zip(q).all(|(a, b)| wrapped(a - b).abs() < 1e-6);
            assert!(all.exact().any(|s| near(&s.q)), "{}: {q:?} not among {all:?}", R::NAME);
            let nearest = R::nearest(target, seed).expect("a pose").expect("solutions");
            assert!(near(&nearest.q), "{}: nearest {nearest:?} to {q:?}", R::NAME);
            assert_eq!(R::solver(target).len(), all.len());
        }
        return;
    };
    let mut group = c.benchmark_group(format!("ik-{}", R::NAME));
    let mut i = 0;
    group.bench_function("all", |b| {
        b.iter(|| {
            i = (i + 1) % INPUTS;
            black_box(R::all(black_box(&targets[i])))
        })
    });
    group.bench_function("nearest", |b| {
        b.iter(|| {
            i = (i + 1) % INPUTS;
            black_box(R::nearest(black_box(&targets[i]), black_box(&seeds[i])))
        })
    });
    group.bench_function("solver", |b| {
        b.iter(|| {
            i = (i + 1) % INPUTS;
            black_box(R::solver(black_box(&targets[i])))
        })
    });
    group.finish();
    record_pair(
        R::NAME,
        "nearest/all",
        101,
        2000,
        INPUTS,
        |i| R::nearest(&targets[i], &seeds[i]),
        |i| R::all(&targets[i]),
    );
}

/// The compiled body alone, on eight lanes, four and one, and the pose on lanes.
fn compiled<R: Compiled>(c: Option<&mut Criterion>) {
    use kinematics::ik::{BRANCH_SIGNS_8, branch_signs, branch_signs_4, splat_pose};
    let Inputs { qs, targets, .. } = inputs::<R>();
    let lanes8: Vec<Pose<F64x8>> = targets.iter().map(splat_pose).collect();
    let lanes4: Vec<Pose<F64x4>> = targets.iter().map(splat_pose).collect();
    let Some(c) = c else {
        for (k, target) in targets.iter().enumerate() {
            let all = R::all(target).expect("a pose");
            // The compiled body gives tip_ik's branches in every lane width, bit for bit.
            let eight = R::branches(&lanes8[k], &BRANCH_SIGNS_8).q;
            for (branch, solution) in all.iter().enumerate() {
                let scalar = R::branches(target, &branch_signs(branch)).q;
                let four = R::branches(&lanes4[k], &branch_signs_4(branch / 4)).q;
                for j in 0..6 {
                    assert_eq!(scalar[j].to_bits(), solution.q[j].to_bits(), "{}: branch {branch}", R::NAME);
                    assert_eq!(eight[j].lane(branch).to_bits(), scalar[j].to_bits(), "{}: branch {branch}", R::NAME);
                    assert_eq!(four[j].lane(branch % 4).to_bits(), scalar[j].to_bits(), "{}: branch {branch}", R::NAME);
                }
            }
        }
        return;
    };
    let mut group = c.benchmark_group(format!("ik-{}", R::NAME));
    let mut i = 0;
    // The compiled body alone (no measure), dispatched as `tip_ik` is: every branch in one call
    // of eight lanes, in two calls of four, and in a loop of eight scalar calls.
    group.bench_function("branches-f64x8", |b| {
        b.iter(|| {
            i = (i + 1) % INPUTS;
            kinematics::dispatch(
                #[inline(always)]
                || black_box(R::branches(black_box(&lanes8[i]), &BRANCH_SIGNS_8)),
            )
        })
    });
    group.bench_function("branches-f64x4", |b| {
        b.iter(|| {
            i = (i + 1) % INPUTS;
            kinematics::dispatch(
                #[inline(always)]
                || {
                    for half in 0..2 {
                        black_box(R::branches(black_box(&lanes4[i]), &branch_signs_4(half)));
                    }
                },
            )
        })
    });
    group.bench_function("branches-scalar", |b| {
        b.iter(|| {
            i = (i + 1) % INPUTS;
            kinematics::dispatch(
                #[inline(always)]
                || {
                    for branch in 0..8 {
                        black_box(R::branches(black_box(&targets[i]), &branch_signs(branch)));
                    }
                },
            )
        })
    });
    // The pose at q, eight configurations in the lanes of `F64x8`: what measuring the solutions
    // would cost computing their sines and cosines again.
    let qs8: Vec<[F64x8; 6]> = qs.iter().map(|q| q.map(F64x8::splat)).collect();
    group.bench_function("pose-f64x8", |b| {
        b.iter(|| {
            i = (i + 1) % INPUTS;
            kinematics::dispatch(
                #[inline(always)]
                || black_box(R::pose8(black_box(&qs8[i]))),
            )
        })
    });
    group.finish();
    // The lanes against the scalar loop, and the compiled tip_ik against the run-time family
    // function it was compiled from (which measures nothing), in alternation.
    let scalar = |i: usize| {
        kinematics::dispatch(
            #[inline(always)]
            || {
                for branch in 0..8 {
                    black_box(R::branches(&targets[i], &branch_signs(branch)));
                }
            },
        )
    };
    let eight = |i: usize| {
        kinematics::dispatch(
            #[inline(always)]
            || black_box(R::branches(&lanes8[i], &BRANCH_SIGNS_8)),
        )
    };
    let four = |i: usize| {
        kinematics::dispatch(
            #[inline(always)]
            || {
                for half in 0..2 {
                    black_box(R::branches(&lanes4[i], &branch_signs_4(half)));
                }
            },
        )
    };
    record_pair(R::NAME, "branches-scalar/branches-f64x8", 101, 2000, INPUTS, scalar, eight);
    record_pair(R::NAME, "branches-f64x4/branches-f64x8", 101, 2000, INPUTS, four, eight);
    record_pair(R::NAME, "solver/all", 101, 2000, INPUTS, |i| R::solver(&targets[i]), |i| R::all(&targets[i]));
}

/// One robot's numeric solver and its `k` chain.
struct Numeric<const N: usize> {
    name: &'static str,
    file: &'static str,
    tip: &'static str,
    limits: [JointLimits; N],
    pose: fn(&[f64; N]) -> Pose<f64>,
    solve: fn(&Pose<f64>, &[f64; N]) -> Result<NumericSolution<N>, IkError>,
    reference: fn() -> Result<kinematics::ReferenceFk, kinematics::LoadError>,
}

fn numeric<const N: usize>(c: Option<&mut Criterion>, robot: &Numeric<N>) {
    let mut rng = Uniform(23);
    let count = if c.is_some() { NUMERIC_TARGETS } else { 20 };
    let targets: Vec<Pose<f64>> = (0..count).map(|_| (robot.pose)(&rng.within(&robot.limits))).collect();
    let seeds: Vec<[f64; N]> = (0..count).map(|_| rng.within(&robot.limits)).collect();
    let reference = (robot.reference)().expect("loads");
    // k's chain from the tip up, and its solver held to the same tolerance as ours.
    let path = format!("{}/robots/{}", env!("CARGO_MANIFEST_DIR"), robot.file);
    let chain = k::Chain::<f64>::from_urdf_file(&path).expect("k reads the robot");
    let serial = k::SerialChain::from_end(chain.find_link(robot.tip).expect("k has the tip"));
    let k_solver = k::JacobianIkSolver::new(1e-10, 1e-10, 0.5, 100);
    // Our q may hold joints off the chain (the Panda's fingers): k's seed is the chain's own.
    let chain_dofs: Vec<usize> = {
        let tree = reference.tree();
        let ours = tree.dof_names();
        serial.iter_joints().map(|j| ours.iter().position(|n| *n == j.name).expect("k's joint is ours")).collect()
    };
    let k_solve = |i: usize| {
        let seed: Vec<f64> = chain_dofs.iter().map(|&d| seeds[i][d]).collect();
        serial.set_joint_positions_clamped(&seed);
        let target = k_isometry(&targets[i]);
        k::InverseKinematicsSolver::solve(&k_solver, &serial, &target).is_ok()
    };
    let mut ours = 0;
    let mut theirs = 0;
    for i in 0..count {
        let found = (robot.solve)(&targets[i], &seeds[i]).expect("a pose");
        if found.converged {
            ours += 1;
            let reached = Pose::from(reference.link_pose(&found.q, robot.tip).expect("finite"));
            let (position, rotation) = kinematics::ik::pose_errors(&reached, &targets[i]);
            assert!(position <= 1e-10 && rotation <= 1e-10, "{}: {position:e} {rotation:e}", robot.name);
        }
        theirs += usize::from(k_solve(i));
    }
    let Some(c) = c else { return };
    record_success(robot.name, ours, theirs, count);
    println!(
        "ik-{}: converged to 1e-10 from random seeds: ours {ours} of {count} ({:.1}%), k {theirs} of {count} ({:.1}%)",
        robot.name,
        100.0 * ours as f64 / count as f64,
        100.0 * theirs as f64 / count as f64
    );
    let mut group = c.benchmark_group(format!("ik-{}", robot.name));
    let mut i = 0;
    group.bench_function("numeric", |b| {
        b.iter(|| {
            i = (i + 1) % count;
            black_box((robot.solve)(black_box(&targets[i]), black_box(&seeds[i])))
        })
    });
    group.bench_function("k-jacobian-ik", |b| {
        b.iter(|| {
            i = (i + 1) % count;
            black_box(k_solve(i))
        })
    });
    group.finish();
    // k's solve over ours, in alternation on the same targets and seeds (20 of each a round).
    record_pair(robot.name, "k-jacobian-ik/numeric", 51, 20, count, k_solve, |i| (robot.solve)(&targets[i], &seeds[i]));
}

/// What refining costs: the IRB 120 read with its half turns as written (every solution refined)
/// against the IRB 120 written exactly (none), `tip_ik` on the same targets, paired.
fn refinement_cost(timed: bool) {
    if !timed {
        return;
    }
    let Inputs { targets, .. } = inputs::<Irb120HalfTurns>();
    record_pair(
        Irb120HalfTurns::NAME,
        "all/exactly-written-all",
        101,
        2000,
        INPUTS,
        |i| Irb120HalfTurns::all(&targets[i]),
        |i| Irb120::all(&targets[i]),
    );
}

/// Times `numerator` against `denominator` in alternation (`common::paired_ratio`), prints the
/// ratio and records it in `target/criterion/kinematics-ik-paired.tsv` for `bench-report`
/// (`robot, pair, ratio`), replacing the robot's last figure for that pair.
fn record_pair<A, B>(
    robot: &str,
    pair: &str,
    rounds: usize,
    calls: usize,
    inputs: usize,
    numerator: impl FnMut(usize) -> A,
    denominator: impl FnMut(usize) -> B,
) {
    if !common::selected(&format!("ik-{robot}/{pair}")) {
        return; // a filtered run times the pairs of the groups it selects only
    }
    let ratio = common::paired_ratio(rounds, calls, inputs, numerator, denominator);
    println!("ik-{robot}/{pair}: paired ratio {ratio:.3} (median of {rounds} alternating rounds)");
    replace_record("kinematics-ik-paired.tsv", &format!("{robot}\t{pair}\t"), &format!("{ratio}\n"));
}

/// Writes `prefix` + `rest` as a line of `file` in criterion's directory, in place of the line
/// that starts with `prefix`, if any.
fn replace_record(file: &str, prefix: &str, rest: &str) {
    let dir = common::criterion_dir();
    let path = dir.join(file);
    let kept: String = std::fs::read_to_string(&path)
        .unwrap_or_default()
        .lines()
        .filter(|l| !l.starts_with(prefix))
        .map(|l| format!("{l}\n"))
        .collect();
    let written = std::fs::create_dir_all(&dir).and_then(|()| std::fs::write(&path, format!("{kept}{prefix}{rest}")));
    if let Err(e) = written {
        eprintln!("cannot write {file} for bench-report: {e}");
    }
}

/// Appends a numeric robot's success counts to `target/criterion/kinematics-ik.tsv` for
/// `bench-report` (`robot, ours, k, targets`), replacing the robot's last line.
fn record_success(robot: &str, ours: usize, theirs: usize, count: usize) {
    replace_record("kinematics-ik.tsv", &format!("{robot}\t"), &format!("{ours}\t{theirs}\t{count}\n"));
}

/// A pose as the isometry of `k`'s own nalgebra version.
fn k_isometry(pose: &Pose<f64>) -> k::nalgebra::Isometry3<f64> {
    let r = &pose.rotation;
    let m = k::nalgebra::Matrix3::new(r[0][0], r[0][1], r[0][2], r[1][0], r[1][1], r[1][2], r[2][0], r[2][1], r[2][2]);
    let rotation = k::nalgebra::UnitQuaternion::from_matrix(&m);
    let [x, y, z] = pose.translation;
    k::nalgebra::Isometry3::from_parts(k::nalgebra::Translation3::new(x, y, z), rotation)
}

fn all(mut c: Option<&mut Criterion>) {
    closed::<Ur5>(c.as_deref_mut());
    compiled::<Ur5>(c.as_deref_mut());
    closed::<Irb120>(c.as_deref_mut());
    compiled::<Irb120>(c.as_deref_mut());
    closed::<Puma560>(c.as_deref_mut());
    compiled::<Puma560>(c.as_deref_mut());
    closed::<Irb120HalfTurns>(c.as_deref_mut());
    refinement_cost(c.is_some());
    closed::<SkewSpherical>(c.as_deref_mut());
    closed::<OffsetWristUr>(c.as_deref_mut());
    numeric(
        c.as_deref_mut(),
        &Numeric {
            name: "panda",
            file: "panda.urdf",
            tip: "panda_hand",
            limits: Panda::JOINT_LIMITS,
            pose: Panda::tip_pose,
            solve: Panda::tip_ik_numeric,
            reference: <Panda as ReferenceModel>::reference,
        },
    );
    numeric(
        c.as_deref_mut(),
        &Numeric {
            name: "iiwa14",
            file: "iiwa14.urdf",
            tip: "iiwa_link_ee",
            limits: Iiwa14::JOINT_LIMITS,
            pose: Iiwa14::tip_pose,
            solve: Iiwa14::tip_ik_numeric,
            reference: <Iiwa14 as ReferenceModel>::reference,
        },
    );
    // The closed-form arm's numeric solver too: OptIK's protocol times it on the UR5.
    numeric(
        c,
        &Numeric {
            name: "ur5",
            file: "ur5.urdf",
            tip: "tool0",
            limits: Ur5::JOINT_LIMITS,
            pose: Ur5::tip_pose,
            solve: Ur5::tip_ik_numeric,
            reference: <Ur5 as ReferenceModel>::reference,
        },
    );
}

fn main() {
    if common::measuring() {
        let mut c = common::criterion(Duration::from_millis(300), Duration::from_secs(1));
        all(Some(&mut c));
        c.final_summary();
    } else {
        all(None);
        println!("ik benchmarks: every body ran once and its answers were checked");
    }
}
