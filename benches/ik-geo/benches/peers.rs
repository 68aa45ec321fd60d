//! Our compiled closed-form inverse kinematics against `ik-geo` 0.1.2, the run-time Rust IK-Geo
//! (the same subproblem decompositions, arXiv 2211.05737), on UR5, IRB 120 and PUMA 560, and on
//! one arm of each family whose first step is a quartic (`spherical`, `three_parallel`).
//!
//! Both sides solve the very same kinematics: ik-geo's `h` and `p` are built from `IK_ARM`, the
//! geometry our solver is compiled from, so a disagreement is a solver's and not a model's.
//!
//! A check pass first (not timed): on every pose ik-geo finds as many exact solutions as we do,
//! each of its solutions is one of ours, and ours hold the configuration the pose was made from.
//! Then paired timing: a shared machine's load drifts, so each round times the two sides back to
//! back on the same poses, the side that goes first alternating, and the table reports the median
//! of the per-round ratios (the drift cancels within a round) beside each side's median time.
//!
//! `bash benches/ik-geo/run.sh` from the repository root; the table also goes to `RESULTS.md`.

use std::fmt::Write as _;
use std::hint::black_box;
use std::time::{Duration, Instant, SystemTime, UNIX_EPOCH};

use ik_geo::inverse_kinematics::auxiliary::Matrix3x7;
use ik_geo::nalgebra::{Matrix3, Matrix3x6, Vector3};
use ik_geo::robot::{IKSolver, Robot};
use kinematics::ik::{Arm6, BRANCH_SIGNS_8, IkError, IkSolutions, splat_pose};
use kinematics::{F64x8, JointLimits, Kinematics, Pose};

#[derive(Kinematics)]
#[kinematics(urdf = "../../robots/ur5.urdf", base = "base_link", tip = "tool0", ik)]
struct Ur5;

#[derive(Kinematics)]
#[kinematics(urdf = "../../robots/irb120.urdf", tip = "tool0", ik)]
struct Irb120;

#[derive(Kinematics)]
#[kinematics(dh = "../../robots/puma560.toml", tip = "link6", ik)]
struct Puma560;

// The two families whose first step is a quartic, on the made-up arms of `tests/arms/` that
// `tests/ik.rs` checks them on (no maker's arm in `robots/` is of either family): axes 1, 2, 3 skew with a spherical wrist,
// and a UR whose last two axes are 0.06 m apart.
#[derive(Kinematics)]
#[kinematics(dh = "../../tests/arms/skew_spherical.toml", tip = "link6", ik)]
struct SkewSpherical;

#[derive(Kinematics)]
#[kinematics(dh = "../../tests/arms/offset_wrist_ur.toml", tip = "link6", ik)]
struct OffsetWristUr;

/// Random configurations (and so poses) per robot.
const POSES: usize = 256;
/// Timed rounds per pair; odd, so the median is one round's.
const ROUNDS: usize = 201;
/// Calls per side per round (cycling through the poses): long enough (about a millisecond) for
/// the clock's resolution not to matter, short enough for a round to see one machine load.
const CALLS: usize = 2_000;
/// How far (radians, modulo 2 pi) an ik-geo solution may be from ours to count as the same.
const SAME: f64 = 1e-9;
/// The same for a least-squares answer: where an equation just misses its reach (a double root
/// about to appear), the residual is flat to second order around its minimum, so two solvers'
/// minimisers differ by up to the square root of rounding (seen: 7.7e-9 rad on the quartic UR).
const SAME_LEAST_SQUARES: f64 = 1e-6;

/// splitmix64, uniform in [0, 1): fixed-seed and dependency-free, so every run times the same poses.
struct Uniform(u64);

impl Uniform {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        // The top 53 bits: every value exactly representable, 1.0 never reached.
        (z >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A configuration within the limits (a continuous joint, without limits, within one turn).
    fn within(&mut self, limits: &[JointLimits; 6]) -> [f64; 6] {
        limits.map(|l| {
            let (lo, hi) = if l.lower.is_finite() && l.upper.is_finite() { (l.lower, l.upper) } else { (-3.1, 3.1) };
            lo + (hi - lo) * self.next()
        })
    }
}

/// `x` moved by a multiple of 2 pi into `[-pi, pi]`.
fn wrapped(x: f64) -> f64 {
    let tau = std::f64::consts::TAU;
    x - tau * (x / tau).round()
}

/// The largest joint difference between two configurations, modulo 2 pi.
fn distance(a: &[f64; 6], b: &[f64; 6]) -> f64 {
    a.iter().zip(b).map(|(x, y)| wrapped(x - y).abs()).fold(0.0, f64::max)
}

fn median(mut xs: Vec<f64>) -> f64 {
    xs.sort_by(f64::total_cmp);
    xs[xs.len() / 2]
}

/// ik-geo's robot for our arm: its product-of-exponentials form is `Arm6`'s, column for column.
fn ik_geo_robot(arm: &Arm6, family: fn(Matrix3x6<f64>, Matrix3x7<f64>) -> Robot) -> Robot {
    let h = Matrix3x6::from_columns(&arm.axes.map(Vector3::from));
    let p = Matrix3x7::from_columns(&arm.offsets.map(Vector3::from));
    family(h, p)
}

/// ik-geo's target for a pose. Its model has no tool rotation, so it takes the sixth frame's
/// rotation `R R6T^T`. Done once per pose, outside the timed calls: ik-geo is timed on its `ik`
/// alone, which spares it this one 3x3 product per call that our solvers do inside.
fn ik_geo_target(arm: &Arm6, pose: &Pose<f64>) -> (Matrix3<f64>, Vector3<f64>) {
    let rotation = Matrix3::from_fn(|i, j| pose.rotation[i][j]);
    let tool = Matrix3::from_fn(|i, j| arm.tool_rotation[i][j]);
    (rotation * tool.transpose(), Vector3::from(pose.translation))
}

/// A robot as both sides see it. Generic rather than function pointers, so each side's call is
/// as direct as a user's would be.
struct Case<P, A, S> {
    name: &'static str,
    limits: [JointLimits; 6],
    arm: Arm6,
    /// Our `tip_pose`: the poses are ours.
    pose: P,
    /// Our `tip_ik`: every branch, errors measured by forward kinematics.
    all: A,
    /// Our solver alone, without the errors' measure: the compiled body with the eight branches
    /// in the lanes of `F64x8`, dispatched as `tip_ik` runs it (for a family with a quartic first
    /// step, the run time's family function `tip_ik` calls).
    solver: S,
    /// ik-geo's constructor for the same family.
    family: fn(Matrix3x6<f64>, Matrix3x7<f64>) -> Robot,
}

/// One row of the table.
struct Row {
    name: &'static str,
    ik_geo_ns: f64,
    tip_ik_ns: f64,
    solver_ns: f64,
    over_tip_ik: f64,
    over_solver: f64,
    /// Poses on which both sides found the same number of exact solutions (all, or the check
    /// pass would have stopped the run).
    equal: usize,
    /// Exact solutions over all poses (ours, equal to ik-geo's).
    exact: usize,
    /// The largest distance from an ik-geo solution to the nearest of ours.
    worst_ik_geo: f64,
    /// The largest distance from a pose's configuration to the nearest of our exact solutions.
    worst_original: f64,
    /// ik-geo's answers farther than `SAME` from ours (least-squares ones, or exact ones near a
    /// singularity that reach the pose less closely than ours).
    ill_conditioned: usize,
}

/// The distance from `q` to the nearest of `ours` (of the exact ones only if `exact_only`).
fn nearest(ours: &IkSolutions<6, 8>, q: &[f64; 6], exact_only: bool) -> f64 {
    ours.iter().filter(|s| s.exact || !exact_only).map(|s| distance(&s.q, q)).fold(f64::INFINITY, f64::min)
}

/// Times `CALLS` calls of `f` (given the call's index).
fn time(f: &mut impl FnMut(usize)) -> Duration {
    let start = Instant::now();
    for i in 0..CALLS {
        f(i);
    }
    start.elapsed()
}

/// Paired rounds of `a` against `b`: the median of the per-round ratios `a / b` and each side's
/// round times (nanoseconds per call).
fn paired(mut a: impl FnMut(usize), mut b: impl FnMut(usize)) -> (f64, Vec<f64>, Vec<f64>) {
    // One untimed round each: caches, branch predictors and the allocator warmed for both.
    time(&mut a);
    time(&mut b);
    let per_call = |d: Duration| d.as_nanos() as f64 / CALLS as f64;
    let (mut ratios, mut ta, mut tb) = (Vec::new(), Vec::new(), Vec::new());
    for round in 0..ROUNDS {
        let (da, db) = if round % 2 == 0 {
            let da = time(&mut a);
            (da, time(&mut b))
        } else {
            let db = time(&mut b);
            (time(&mut a), db)
        };
        ratios.push(da.as_secs_f64() / db.as_secs_f64());
        ta.push(per_call(da));
        tb.push(per_call(db));
    }
    (median(ratios), ta, tb)
}

fn run<P, A, S>(case: &Case<P, A, S>) -> Row
where
    P: Fn(&[f64; 6]) -> Pose<f64>,
    A: Fn(&Pose<f64>) -> Result<IkSolutions<6, 8>, IkError>,
    S: Fn(&Pose<f64>),
{
    let name = case.name;
    let robot = ik_geo_robot(&case.arm, case.family);
    let mut rng = Uniform(11);
    let qs: Vec<[f64; 6]> = (0..POSES).map(|_| rng.within(&case.limits)).collect();
    let targets: Vec<Pose<f64>> = qs.iter().map(|q| (case.pose)(q)).collect();
    let theirs: Vec<(Matrix3<f64>, Vector3<f64>)> = targets.iter().map(|t| ik_geo_target(&case.arm, t)).collect();

    // The check pass: the timings below compare equals only if both sides answer alike.
    let (mut equal, mut exact, mut worst_ik_geo, mut worst_original) = (0, 0, 0.0f64, 0.0f64);
    let mut ill_conditioned = 0;
    for (k, (q, target)) in qs.iter().zip(&targets).enumerate() {
        let ours = (case.all)(target).expect("our poses are rotations");
        let (rotation, translation) = theirs[k];
        let answers = robot.ik(rotation, translation);
        let ours_exact = ours.exact().count();
        let theirs_exact = answers.iter().filter(|(_, ls)| !ls).count();
        assert_eq!(
            theirs_exact, ours_exact,
            "{name}, pose {k} (q = {q:?}): ik-geo finds {theirs_exact} exact solutions, we find {ours_exact}\n\
             ik-geo: {answers:?}\nours: {ours:#?}"
        );
        equal += 1;
        exact += ours_exact;
        for (solution, ls) in &answers {
            let solution: [f64; 6] = (*solution).into();
            // An exact answer of ik-geo's must be an exact one of ours; a least-squares one, any.
            let d = nearest(&ours, &solution, !ls);
            // Near a singularity the angles are ill-conditioned and the two sides' roundings part
            // further: there an exact answer may be up to 1e-6 rad away if ours reaches the pose
            // at least as closely as ik-geo's (both measured with our forward kinematics).
            let (theirs_error, _) = kinematics::ik::pose_errors(&(case.pose)(&solution), target);
            let ours_error = ours.exact().map(|s| s.position_error).fold(0.0, f64::max);
            let conditioned = !ls && d <= SAME_LEAST_SQUARES && ours_error <= theirs_error;
            assert!(
                d <= if *ls { SAME_LEAST_SQUARES } else { SAME } || conditioned,
                "{name}, pose {k} (q = {q:?}): ik-geo's {solution:?} (least squares: {ls}, reaching the target \
                 within {theirs_error:e} m) is {d:e} rad from the nearest of ours\nours: {ours:#?}"
            );
            if d > SAME {
                ill_conditioned += 1;
            }
            worst_ik_geo = worst_ik_geo.max(d);
        }
        let d = nearest(&ours, q, true);
        assert!(
            d <= SAME,
            "{name}, pose {k}: the configuration {q:?} is {d:e} rad from the nearest of ours: {ours:#?}"
        );
        worst_original = worst_original.max(d);
    }

    let n = targets.len();
    let ik_geo = |i: usize| {
        let (rotation, translation) = theirs[i % n];
        black_box(robot.ik(black_box(rotation), black_box(translation)));
    };
    let tip_ik = |i: usize| {
        let _ = black_box((case.all)(black_box(&targets[i % n])));
    };
    let solver = |i: usize| (case.solver)(black_box(&targets[i % n]));
    let (over_tip_ik, mut ik_geo_times, tip_ik_times) = paired(ik_geo, tip_ik);
    let (over_solver, more_ik_geo_times, solver_times) = paired(ik_geo, solver);
    // ik-geo ran in both pairs: its time is the median over all its rounds.
    ik_geo_times.extend(more_ik_geo_times);
    Row {
        name,
        ik_geo_ns: median(ik_geo_times),
        tip_ik_ns: median(tip_ik_times),
        solver_ns: median(solver_times),
        over_tip_ik,
        over_solver,
        equal,
        exact,
        worst_ik_geo,
        worst_original,
        ill_conditioned,
    }
}

/// `YYYY-MM-DD HH:MM:SS UTC` for seconds since the Unix epoch (the civil-from-days algorithm of
/// H. Hinnant's date library), so the header needs no date crate.
fn utc(seconds: u64) -> String {
    let (days, rest) = ((seconds / 86_400) as i64, seconds % 86_400);
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1_460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!("{year:04}-{month:02}-{day:02} {:02}:{:02}:{:02} UTC", rest / 3_600, rest / 60 % 60, rest % 60)
}

fn table(rows: &[Row]) -> String {
    let mut out = String::from(
        "| robot | ik-geo ns | ours tip_ik ns | ours solver ns | ik-geo / tip_ik | ik-geo / solver | exact solutions equal on N poses |\n\
         |---|---:|---:|---:|---:|---:|---:|\n",
    );
    for r in rows {
        let _ = writeln!(
            out,
            "| {} | {:.0} | {:.0} | {:.0} | {:.2} | {:.2} | {} / {POSES} |",
            r.name, r.ik_geo_ns, r.tip_ik_ns, r.solver_ns, r.over_tip_ik, r.over_solver, r.equal
        );
    }
    out.push('\n');
    for r in rows {
        let _ = writeln!(
            out,
            "- {}: {} exact solutions on both sides; every ik-geo solution within {:.1e} rad of one of ours \
             ({} farther than {SAME:e}: least-squares answers, or exact ones near a singularity reaching the \
             pose less closely than ours), every configuration within {:.1e} rad of one of our exact solutions.",
            r.name, r.exact, r.worst_ik_geo, r.ill_conditioned, r.worst_original
        );
    }
    out
}

/// The compiled body of a robot's closed form, all eight branches in one call on `F64x8`,
/// dispatched (the solve `tip_ik` does before measuring), its answer kept from the optimiser.
macro_rules! compiled {
    ($robot:ident) => {
        |t: &Pose<f64>| {
            let lanes = splat_pose::<F64x8>(t);
            kinematics::dispatch(
                #[inline(always)]
                || {
                    black_box($robot::tip_ik_branch_generic(black_box(&lanes), &BRANCH_SIGNS_8));
                },
            )
        }
    };
}

fn main() {
    let rows = [
        run(&Case {
            name: "UR5",
            limits: Ur5::JOINT_LIMITS,
            arm: Ur5::IK_ARM,
            pose: Ur5::tip_pose,
            all: Ur5::tip_ik,
            solver: compiled!(Ur5),
            family: ik_geo::robot::three_parallel_two_intersecting,
        }),
        run(&Case {
            name: "IRB 120",
            limits: Irb120::JOINT_LIMITS,
            arm: Irb120::IK_ARM,
            pose: Irb120::tip_pose,
            all: Irb120::tip_ik,
            solver: compiled!(Irb120),
            family: ik_geo::robot::spherical_two_parallel,
        }),
        run(&Case {
            name: "PUMA 560",
            limits: Puma560::JOINT_LIMITS,
            arm: Puma560::IK_ARM,
            pose: Puma560::tip_pose,
            all: Puma560::tip_ik,
            solver: compiled!(Puma560),
            family: ik_geo::robot::spherical_two_parallel,
        }),
        run(&Case {
            name: "skew spherical wrist (quartic)",
            limits: SkewSpherical::JOINT_LIMITS,
            arm: SkewSpherical::IK_ARM,
            pose: SkewSpherical::tip_pose,
            all: SkewSpherical::tip_ik,
            solver: |t: &Pose<f64>| {
                black_box(kinematics::ik::spherical(&SkewSpherical::IK_ARM, t));
            },
            family: ik_geo::robot::spherical,
        }),
        run(&Case {
            name: "UR, wrist offset (quartic)",
            limits: OffsetWristUr::JOINT_LIMITS,
            arm: OffsetWristUr::IK_ARM,
            pose: OffsetWristUr::tip_pose,
            all: OffsetWristUr::tip_ik,
            solver: |t: &Pose<f64>| {
                black_box(kinematics::ik::three_parallel(&OffsetWristUr::IK_ARM, t));
            },
            family: ik_geo::robot::three_parallel,
        }),
    ];
    let table = table(&rows);
    println!("{table}");

    let now = SystemTime::now().duration_since(UNIX_EPOCH).map(|d| d.as_secs()).expect("the system clock is past 1970");
    let report = format!(
        "# ik-geo 0.1.2 against our compiled IK\n\n\
         Produced by `bash benches/ik-geo/run.sh` (`cargo bench --manifest-path benches/ik-geo/Cargo.toml`) on {}: \
         a plain `cargo bench` build (no target-cpu flags, no LTO). Nanoseconds per call are medians over {ROUNDS} \
         rounds of {CALLS} calls cycling through {POSES} poses (ik-geo's over the rounds of both pairs); a ratio is \
         the median of the per-round ratios of back-to-back runs, the first side alternating. ik-geo's time is of \
         its `ik` alone (a `Vec` per call); ours of `tip_ik` (every branch, errors measured by forward kinematics) \
         and of the solver alone (the compiled body, eight branches in the lanes of `F64x8`; for a family with a \
         quartic first step, the run time's family function).\n\n{table}",
        utc(now)
    );
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/RESULTS.md");
    std::fs::write(path, report).expect("RESULTS.md is writable");
    println!("written to {path}");
    let record = write_record(&rows);
    println!("and the record for bench-report to {}", record.display());
}

/// The record `bench-report` reads (`kinematics-ik-geo.tsv` in the root workspace's criterion
/// directory, beside the other benchmarks' records): one line per robot, tab-separated, the
/// figures unrounded: robot, ik-geo ns, `tip_ik` ns, solver ns, the two paired ratios, poses with
/// equal exact solutions, poses.
fn write_record(rows: &[Row]) -> std::path::PathBuf {
    let target = std::env::var_os("CARGO_TARGET_DIR").map_or_else(
        || std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../target"),
        std::path::PathBuf::from,
    );
    let dir = target.join("criterion");
    let mut record = String::new();
    for r in rows {
        let _ = writeln!(
            record,
            "{}\t{}\t{}\t{}\t{}\t{}\t{}\t{POSES}",
            r.name, r.ik_geo_ns, r.tip_ik_ns, r.solver_ns, r.over_tip_ik, r.over_solver, r.equal
        );
    }
    let path = dir.join("kinematics-ik-geo.tsv");
    std::fs::create_dir_all(&dir)
        .and_then(|()| std::fs::write(&path, record))
        .expect("the criterion directory is writable");
    path
}
