//! `kinematics ik FILE --pose ...` (or `--from-q ...`): every closed-form inverse kinematics
//! solution of the tip, solved by the same core function the derive's `ik` key calls, with the
//! geometry the compiler classified, each solution's errors measured by the runtime reference.
//!
//! The classified plan is solved as the derived code solves it: for a composed family, the compiled
//! body's expressions evaluated branch by branch, else the core's family function; each solution's
//! errors by `ReferenceFk`.

use std::io::Write;

use kinematics::Pose;
use kinematics::ReferenceFk;
use kinematics::ik::{IkSolutions, PlanarArm, PlanarJoint};
use kinematics_compiler::ik::{IkGeometry, IkPlan};

use crate::error::CliError;
use crate::inspect::short;

/// Arguments of `ik`.
#[derive(clap::Args)]
pub struct Args {
    /// A URDF file (.urdf, .xml), MJCF file (.xml, .mjcf) or DH table (.toml, .json).
    file: String,
    /// The base link (default: the root).
    #[arg(long)]
    base: Option<String>,
    /// The tip link (default: the deepest link).
    #[arg(long)]
    tip: Option<String>,
    /// The target: position then orientation as a unit quaternion, "x y z qw qx qy qz" (metres;
    /// the quaternion is normalised, and one of length zero is an error).
    #[arg(long, allow_hyphen_values = true, conflicts_with = "from_q", required_unless_present = "from_q")]
    pose: Option<String>,
    /// The target as the tip's pose at these joint values (comma-separated, DoF order): a round
    /// trip, which also says which solution they are.
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    from_q: Option<Vec<f64>>,
    /// Read `--from-q` and print solutions in degrees.
    #[arg(long)]
    degrees: bool,
}

/// Solves and prints.
pub fn run(args: &Args, out: &mut dyn Write) -> Result<(), CliError> {
    let file = &args.file;
    let tree = crate::robot::load(file)?;
    let (base, tip) = crate::robot::base_and_tip(&tree, file, args.base.as_deref(), args.tip.as_deref())?;
    let plan =
        kinematics_compiler::ik::classify(&tree, &base, &tip).map_err(|source| CliError::compile(file, source))?;
    let fk = ReferenceFk::new(tree);
    let runtime = |source| CliError::Runtime { file: file.clone(), source };
    let scale = if args.degrees { 180.0 / std::f64::consts::PI } else { 1.0 };
    let (target, given) = match (&args.pose, &args.from_q) {
        (Some(text), _) => (parse_pose(file, text)?, None),
        (None, Some(q)) => {
            let q: Vec<f64> = q.iter().map(|x| x / scale).collect();
            (Pose::from(fk.relative_pose(&q, &base, &tip).map_err(runtime)?), Some(q))
        }
        (None, None) => unreachable!("clap requires --pose or --from-q"),
    };
    kinematics::ik::check_target(&target).map_err(|source| CliError::Ik { file: file.clone(), source })?;
    let nan = Pose { rotation: [[f64::NAN; 3]; 3], translation: [f64::NAN; 3] };
    // Finite values always pose (the solvers never return NaN); a refusal would show as an
    // infinite error, never as a small one.
    let forward = |q: &[f64]| fk.relative_pose(q, &base, &tip).map(Pose::from).unwrap_or(nan);
    let solutions = solve(&plan, &target, &forward);
    writeln!(out, "robot `{}`: `{tip}` in `{base}`, closed form: {}", fk.tree().name(), plan.family().name())?;
    let [x, y, z] = target.translation.map(short);
    let rows: Vec<String> = target.rotation.iter().map(|r| r.map(short).join(", ")).collect();
    writeln!(out, "target: position ({x}, {y}, {z}), rotation rows ({})", rows.join("; "))?;
    writeln!(
        out,
        "{} solutions, {} exact (errors measured by the runtime reference; angles in {}):",
        solutions.len(),
        solutions.iter().filter(|s| s.exact).count(),
        if args.degrees { "degrees" } else { "radians" }
    )?;
    writeln!(out, "  #  {:<66}  {:<16}  {:<6}  {:>10}  {:>10}", "q", "flags", "limits", "position", "rotation")?;
    let within = within_limits(fk.tree());
    for (i, s) in solutions.iter().enumerate() {
        let q: Vec<String> = s.q.iter().map(|v| format!("{:>9.5}", v * scale)).collect();
        let flags = match (s.exact, s.singular) {
            (true, false) => "exact",
            (true, true) => "exact, singular",
            (false, false) => "least squares",
            (false, true) => "l. sq., singular",
        };
        let limits = if within(&s.q) { "within" } else { "beyond" };
        writeln!(
            out,
            "  {}  ({})  {flags:<16}  {limits:<6}  {:>10.2e}  {:>10.2e}",
            i + 1,
            q.join(", "),
            s.position_error,
            s.rotation_error
        )?;
    }
    if let Some(q) = given {
        // Which solution the given configuration is: the nearest modulo 2 pi.
        let distance = |s: &[f64]| {
            s.iter()
                .zip(&q)
                .map(|(a, b)| wrap(a - b).abs())
                .fold(0.0, |m: f64, d| if d > m || d.is_nan() { d } else { m })
        };
        let nearest = solutions.iter().enumerate().map(|(i, s)| (distance(&s.q), i)).min_by(|a, b| a.0.total_cmp(&b.0));
        let Some((d, i)) = nearest else { return Ok(()) };
        if d <= ROUND_TRIP_TOLERANCE {
            writeln!(
                out,
                "round trip: --from-q is solution {} (largest joint difference modulo 2 pi: {d:.1e} rad)",
                i + 1
            )?;
        } else if solutions.iter().any(|s| s.exact && s.singular) {
            // At a singularity the solutions are representatives of a continuum, which need not
            // hold the given angles: that they reach the pose is what counts (their errors above).
            writeln!(
                out,
                "round trip: --from-q is at a singularity, where the solutions are representatives of a continuum \
                 (those flagged singular, each with its errors above); the nearest, solution {}, differs by {d:.1e} \
                 rad",
                i + 1
            )?;
        } else {
            return Err(CliError::RoundTrip { file: file.clone(), nearest: i + 1, difference: d });
        }
    }
    Ok(())
}

/// Whether a solution fits the joints' limits: each angle moved by whole turns where that brings
/// it within them (as the derive's `tip_ik_within_limits` does), a slide as it is; joints without
/// limits fit.
fn within_limits(tree: &kinematics::KinematicTree) -> impl Fn(&[f64]) -> bool + '_ {
    let limits = tree.dof_limits();
    let revolute: Vec<bool> =
        tree.dof_joints().iter().map(|&j| tree.joint(j).kind != kinematics::model::JointKind::Prismatic).collect();
    move |q: &[f64]| {
        q.iter().zip(&limits).zip(&revolute).all(|((&x, limits), &revolute)| {
            let Some(l) = limits else { return true };
            if !revolute {
                return l.lower <= x && x <= l.upper;
            }
            // The smallest value of x + 2 pi k at or above the lower limit, then whether it is
            // below the upper.
            let tau = std::f64::consts::TAU;
            let lifted = x + tau * ((l.lower - x) / tau).ceil();
            lifted <= l.upper
        })
    }
}

/// Within this (rad, every joint, modulo 2 pi) a solution is the configuration `--from-q` gave.
const ROUND_TRIP_TOLERANCE: f64 = 1e-9;

/// One solution, whatever the arm's number of joints.
pub struct Solution {
    /// Joint values in the order of `q`.
    pub q: Vec<f64>,
    /// Every equation solvable.
    pub exact: bool,
    /// One of a continuum.
    pub singular: bool,
    /// Metres from the target.
    pub position_error: f64,
    /// Radians from the target.
    pub rotation_error: f64,
}

fn rows<const N: usize, const M: usize>(
    mut solutions: IkSolutions<N, M>,
    target: &Pose<f64>,
    forward: &dyn Fn(&[f64]) -> Pose<f64>,
) -> Vec<Solution> {
    solutions.measure(target, |q| forward(q));
    solutions
        .iter()
        .map(|s| Solution {
            q: s.q.to_vec(),
            exact: s.exact,
            singular: s.singular,
            position_error: s.position_error,
            rotation_error: s.rotation_error,
        })
        .collect()
}

/// The plan's solutions, as the derived code computes them: for a family the compiler composes,
/// its body (the expressions `tip_ik` runs, evaluated branch by branch as the generated `f64` code
/// computes them), else the family's core solver on the plan's geometry; each solution measured
/// by `forward`.
pub fn solve(plan: &IkPlan, target: &Pose<f64>, forward: &dyn Fn(&[f64]) -> Pose<f64>) -> Vec<Solution> {
    if let Some(body) = kinematics_compiler::ik::IkBody::of(plan) {
        return (0..plan.family().max_solutions())
            .map(|branch| {
                let value = body.eval(target, branch);
                let (position_error, rotation_error) = kinematics::ik::pose_errors(&forward(&value.q), target);
                Solution { q: value.q, exact: value.exact, singular: value.singular, position_error, rotation_error }
            })
            .collect();
    }
    match &plan.geometry {
        IkGeometry::Six { family, arm: six, .. } => {
            let arm = six.arm();
            let solutions = (family.facts().solver.function)(&arm, target);
            rows(solutions, target, forward)
        }
        IkGeometry::Planar(planar) => {
            let joint = |(sign, point): &(f64, Option<[f64; 3]>)| match point {
                Some(point) => PlanarJoint::Revolute { sign: *sign, point: *point },
                None => PlanarJoint::Prismatic { sign: *sign },
            };
            macro_rules! planar {
                ($n:literal) => {{
                    let joints: [PlanarJoint; $n] = std::array::from_fn(|i| joint(&planar.joints[i]));
                    let arm = PlanarArm {
                        axis: planar.axis,
                        joints,
                        tip_point: planar.tip_point,
                        tool_rotation: planar.tool_rotation,
                    };
                    rows(arm.solve(target), target, forward)
                }};
            }
            match planar.joints.len() {
                2 => planar!(2),
                3 => planar!(3),
                4 => planar!(4),
                other => unreachable!("the planar family takes two to four joints, not {other}"),
            }
        }
    }
}

/// `x` moved by whole turns into `(-pi, pi]`.
fn wrap(x: f64) -> f64 {
    let tau = std::f64::consts::TAU;
    let wrapped = x - tau * (x / tau).round();
    if wrapped <= -std::f64::consts::PI { wrapped + tau } else { wrapped }
}

/// "x y z qw qx qy qz" (spaces or commas) as a pose.
fn parse_pose(file: &str, text: &str) -> Result<Pose<f64>, CliError> {
    let bad = |why: String| CliError::Usage(format!("{file}: --pose \"{text}\": {why}"));
    let values: Vec<f64> = text
        .split(|c: char| c.is_whitespace() || c == ',')
        .filter(|t| !t.is_empty())
        .map(|t| t.parse::<f64>().map_err(|_| bad(format!("`{t}` is not a number"))))
        .collect::<Result<_, _>>()?;
    let [x, y, z, w, qx, qy, qz] = values[..] else {
        return Err(bad(format!("{} values given; it takes seven: x y z qw qx qy qz", values.len())));
    };
    if !values.iter().all(|v| v.is_finite()) {
        return Err(bad("every value must be a finite number".to_owned()));
    }
    let quaternion = nalgebra::Quaternion::new(w, qx, qy, qz);
    if quaternion.norm() == 0.0 {
        return Err(bad("the quaternion has length zero: it is no rotation".to_owned()));
    }
    let rotation = nalgebra::UnitQuaternion::from_quaternion(quaternion).to_rotation_matrix();
    let r = |i: usize, j: usize| rotation[(i, j)];
    Ok(Pose {
        rotation: [[r(0, 0), r(0, 1), r(0, 2)], [r(1, 0), r(1, 1), r(1, 2)], [r(2, 0), r(2, 1), r(2, 2)]],
        translation: [x, y, z],
    })
}
