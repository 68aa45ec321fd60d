//! `kinematics demo [FILE]`: the whole pipeline on one robot, in a few screens.

use std::hint::black_box;
use std::io::Write;
use std::path::Path;
use std::time::Instant;

use kinematics::ReferenceFk;
use kinematics::model::KinematicTree;
use kinematics_compiler::{Request, compile};

use crate::agreement::{Configurations, TOLERANCE, check_graph, distance, entries, worst_of};
use crate::error::CliError;
use crate::ur5::Ur5;

mod collision;
mod dynamics;

/// The robot shown when no file is given.
const DEFAULT_FILE: &str = "robots/ur5.urdf";

/// Arguments of `demo`.
#[derive(clap::Args)]
pub struct Args {
    /// A URDF file, MJCF file or DH table (default: `robots/ur5.urdf`, or the copy built into this binary).
    file: Option<String>,
    /// Configurations checked against the runtime reference (at least 1).
    #[arg(long, default_value_t = 10_000, value_parser = crate::agreement::sample_count)]
    samples: usize,
    /// Evaluations timed per implementation.
    #[arg(long, default_value_t = 1_000_000)]
    evaluations: usize,
}

/// Runs the demo.
pub fn run(args: &Args, out: &mut dyn Write) -> Result<(), CliError> {
    let (file, tree) = match &args.file {
        Some(file) => (file.clone(), crate::robot::load(file)?),
        None if Path::new(DEFAULT_FILE).exists() => (DEFAULT_FILE.to_owned(), crate::robot::load(DEFAULT_FILE)?),
        None => ("ur5.urdf (the copy built into this binary)".to_owned(), Ur5::reference()?.tree().clone()),
    };
    let base = tree.link(tree.root()).name.clone();
    let tip = tree.link(crate::robot::deepest_link(&tree)).name.clone();
    // The generated code this binary holds is for the UR5 from the root to `tool0`.
    let built_in = tip == "tool0" && Ur5::reference().is_ok_and(|r| r.tree() == &tree);

    writeln!(out, "kinematics demo: {file}, the pose of `{tip}` (the deepest link) in `{base}`\n")?;
    writeln!(out, "1. The description, validated into a kinematic tree (`kinematics inspect`)\n")?;
    write!(out, "{}", crate::inspect::describe(&tree))?;

    writeln!(out, "\n2. The pose, multiplied out symbolically and simplified (`kinematics expr`)\n")?;
    write!(out, "{}", crate::expr::pose_text(&tree, &file, &base, &tip, false)?)?;

    writeln!(out, "\n3. What the generated code computes, against the plain product of the chain's transforms\n")?;
    let mut rows = crate::expr::op_counts(&tree, &file, &base, &tip)?;
    let all = compile(&tree, &Request::all_links()).map_err(|source| CliError::compile(&file, source))?;
    rows.push((format!("every link's pose ({} links), generated", all.frames().len()), all.op_count()));
    write!(out, "{}", crate::expr::op_table(&rows))?;

    writeln!(
        out,
        "\n4. Agreement with the runtime reference (nalgebra), {} configurations (`kinematics check`)\n",
        thousands(args.samples)
    )?;
    let errors = check_graph(&tree, &file, args.samples)?;
    if let Some(worst) = errors.iter().max_by(|a, b| a.error.total_cmp(&b.error)) {
        writeln!(
            out,
            "  compiled expressions, every link:        largest error {:.2e} x reach (link `{}`)",
            worst.error, worst.link
        )?;
    }
    if built_in {
        let worst = generated_agreement(&tree, &file, args.samples)?;
        writeln!(out, "  generated Rust in this binary (Ur5):     largest error {worst:.2e} x reach")?;
    }
    writeln!(out, "  (reach {:.3} m; tolerance {TOLERANCE:e})", tree.reach())?;

    writeln!(
        out,
        "\n5. Timing: {} evaluations of the pose of `{tip}`, inputs precomputed, results through black_box\n",
        thousands(args.evaluations)
    )?;
    out.flush()?;
    let fk = ReferenceFk::new(tree.clone());
    let inputs: Vec<Vec<f64>> = Configurations::new(&tree).take(1024).collect();
    let n = inputs.len();
    let reference = per_call(args.evaluations, |i| {
        let _ = black_box(fk.link_pose(black_box(&inputs[i % n]), &tip));
    });
    writeln!(out, "  runtime reference, ReferenceFk::link_pose:   {reference:>9.1} ns per pose")?;
    if built_in {
        let arrays: Vec<[f64; Ur5::DOF]> = inputs.iter().filter_map(|q| q.as_slice().try_into().ok()).collect();
        let generated = per_call(args.evaluations, |i| {
            black_box(Ur5::tip_pose(black_box(&arrays[i % n])));
        });
        writeln!(
            out,
            "  generated code, Ur5::tip_pose:               {generated:>9.1} ns per pose ({:.0}x faster)",
            reference / generated.max(1e-3)
        )?;
        if cfg!(debug_assertions) {
            writeln!(out, "  (a debug build: run with `cargo run --release` for representative numbers)")?;
        }
    } else {
        writeln!(
            out,
            "  generated code: not timed. This binary cannot compile Rust at run time; it holds generated\n  \
             code for the UR5 only (built by kinematics-cli/build.rs). For this robot, use\n  \
             `kinematics generate {file}` or the build API in your crate, and time it there."
        )?;
    }
    velocities(args, out, &tree, &file, (&base, &tip), built_in, &inputs)?;
    inverse(args, out, &tree, &file, built_in, &inputs)?;
    dynamics::run(args, out, &tree, &file, built_in)?;
    collision::run(args, out, &tree, &file)
}

/// The configuration whose pose the demo's inverse kinematics solves.
const IK_Q: [f64; 6] = [0.3, -1.2, 1.0, 0.4, -0.7, 2.0];

/// Step 7: inverse kinematics. For the built-in UR5, every solution of one pose with its errors
/// (by the generated pose, and by the runtime reference's), and the closed form timed against the
/// numeric solver; for another robot, the family its chain falls in (`kinematics ik`).
fn inverse(
    args: &Args,
    out: &mut dyn Write,
    tree: &KinematicTree,
    file: &str,
    built_in: bool,
    inputs: &[Vec<f64>],
) -> Result<(), CliError> {
    writeln!(out, "\n7. Inverse kinematics (`kinematics ik`)\n")?;
    if !built_in {
        writeln!(
            out,
            "  not timed: this binary holds generated code for the UR5 only. For this robot, `kinematics ik {file} \
             --from-q ...` solves a pose with the run time's solvers, and the derive's `ik` key gives the \
             compiled ones."
        )?;
        return Ok(());
    }
    let fk = ReferenceFk::new(tree.clone());
    let runtime = |source| CliError::Runtime { file: file.to_owned(), source };
    let ik = |source| CliError::Ik { file: file.to_owned(), source };
    let target = Ur5::tip_pose(&IK_Q);
    let reference_target = fk.link_pose(&IK_Q, "tool0").map_err(runtime)?;
    let solutions = Ur5::tip_ik(&target).map_err(ik)?;
    writeln!(
        out,
        "  the pose of tool0 at q = {IK_Q:?}: {} solutions, {} exact ({})\n",
        solutions.len(),
        solutions.exact().count(),
        Ur5::IK_FAMILY
    )?;
    writeln!(out, "  {:<62}  position   rotation   reference", "q (rad)")?;
    for s in solutions.iter() {
        let q = s.q.map(|x| format!("{x:>8.4}")).join(" ");
        let by_reference = kinematics::Pose::from(fk.link_pose(&s.q, "tool0").map_err(runtime)?);
        let reference_error = by_reference.deviation(&reference_target, 1.0);
        let kind = if s.exact { "" } else { "  (not exact: the best of an unreachable branch)" };
        writeln!(out, "  [{q}]  {:.2e} m  {:.2e}  {reference_error:.2e}{kind}", s.position_error, s.rotation_error)?;
    }
    writeln!(
        out,
        "  (errors by the generated pose; `reference`: the runtime reference's pose at q against the target)\n"
    )?;
    out.flush()?;
    let arrays: Vec<[f64; Ur5::DOF]> = inputs.iter().filter_map(|q| q.as_slice().try_into().ok()).collect();
    let targets: Vec<kinematics::Pose<f64>> = arrays.iter().map(Ur5::tip_pose).collect();
    let n = targets.len();
    let closed = per_call(args.evaluations / 4, |i| {
        let _ = black_box(Ur5::tip_ik(black_box(&targets[i % n])));
    });
    // The numeric solver from another configuration of the set, as a planner's seed would be.
    let solves = (args.evaluations / 100).max(1);
    let mut converged = 0usize;
    let numeric = per_call(solves, |i| {
        let solution = Ur5::tip_ik_numeric(black_box(&targets[i % n]), &arrays[(i + n / 2) % n]);
        converged += usize::from(solution.is_ok_and(|s| s.converged));
    });
    writeln!(out, "  closed form, Ur5::tip_ik (every solution):   {closed:>9.1} ns per pose")?;
    writeln!(
        out,
        "  numeric, Ur5::tip_ik_numeric (one solution):  {numeric:>9.1} ns per pose ({}/{} converged; the closed \
         form {:.0}x faster)",
        thousands(converged),
        thousands(solves),
        numeric / closed.max(1e-3)
    )?;
    Ok(())
}

/// Step 6: the tip's geometric Jacobian, what its functions cost, and for the built-in UR5 its
/// agreement with the runtime reference and a timing.
fn velocities(
    args: &Args,
    out: &mut dyn Write,
    tree: &KinematicTree,
    file: &str,
    (base, tip): (&str, &str),
    built_in: bool,
    inputs: &[Vec<f64>],
) -> Result<(), CliError> {
    let frame = kinematics::model::JacobianFrame::LocalWorldAligned;
    writeln!(
        out,
        "\n6. Velocities: the geometric Jacobian of `{tip}` (`kinematics expr --jacobian`; {})\n",
        frame.name()
    )?;
    write!(out, "{}", crate::expr::op_table(&crate::expr::velocity_op_counts(tree, file, base, tip, frame)?))?;
    if !built_in {
        return Ok(());
    }
    let fk = ReferenceFk::new(tree.clone());
    let runtime = |source| CliError::Runtime { file: file.to_owned(), source };
    let arrays: Vec<[f64; Ur5::DOF]> = inputs.iter().filter_map(|q| q.as_slice().try_into().ok()).collect();
    let n = arrays.len();
    // Linear rows relative to the reach, angular rows as they are: the agreement tests' measure.
    let reach = tree.reach().max(f64::MIN_POSITIVE);
    let mut worst = 0.0f64;
    for q in arrays.iter().take(args.samples.max(1)) {
        let generated = Ur5::tip_jacobian(q);
        let reference = fk.jacobian(q, base, tip).map_err(runtime)?;
        for (row, entries) in generated.iter().enumerate() {
            for (col, &value) in entries.iter().enumerate() {
                let scale = if row < 3 { reach } else { 1.0 };
                let error = (value - reference[(row, col)]).abs() / scale;
                // NaN counts as the largest error.
                worst = if error.is_nan() { f64::INFINITY } else { worst.max(error) };
            }
        }
    }
    writeln!(
        out,
        "\n  Ur5::tip_jacobian against ReferenceFk::jacobian, {} configurations: largest error {worst:.2e}\n  \
         (linear rows x reach, angular rows as they are)\n",
        thousands(args.samples.max(1).min(n))
    )?;
    out.flush()?;
    let reference = per_call(args.evaluations / 4, |i| {
        let _ = black_box(fk.jacobian(black_box(&inputs[i % n]), base, tip));
    });
    let jacobian = per_call(args.evaluations, |i| {
        black_box(Ur5::tip_jacobian(black_box(&arrays[i % n])));
    });
    let both = per_call(args.evaluations, |i| {
        black_box(Ur5::tip_pose_and_jacobian(black_box(&arrays[i % n])));
    });
    writeln!(out, "  runtime reference, ReferenceFk::jacobian:    {reference:>9.1} ns per Jacobian")?;
    writeln!(
        out,
        "  generated code, Ur5::tip_jacobian:           {jacobian:>9.1} ns per Jacobian ({:.0}x faster)",
        reference / jacobian.max(1e-3)
    )?;
    writeln!(out, "  generated code, Ur5::tip_pose_and_jacobian:  {both:>9.1} ns per pose and Jacobian")?;
    Ok(())
}

/// `1000000` as `1,000,000`.
fn thousands(n: usize) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}

/// Nanoseconds per call of `f(i)`, over `evaluations` calls.
fn per_call(evaluations: usize, mut f: impl FnMut(usize)) -> f64 {
    let start = Instant::now();
    for i in 0..evaluations {
        f(i);
    }
    start.elapsed().as_secs_f64() * 1e9 / evaluations.max(1) as f64
}

/// The largest error of the built-in generated UR5 code (tip pose and every link's pose) against
/// the runtime reference.
fn generated_agreement(tree: &KinematicTree, file: &str, samples: usize) -> Result<f64, CliError> {
    let fk = ReferenceFk::new(tree.clone());
    let reach = tree.reach();
    let tool0 = crate::robot::link(tree, file, "tip", "tool0")?.0;
    let runtime = |source| CliError::Runtime { file: file.to_owned(), source };
    let ids: Vec<usize> = Ur5::LINK_NAMES
        .iter()
        .map(|name| fk.link_id(name).map(|id| id.0))
        .collect::<Result<_, _>>()
        .map_err(runtime)?;
    let mut worst: f64 = 0.0;
    for q in Configurations::new(tree).take(samples) {
        #[allow(clippy::expect_used, reason = "invariant: the caller checked that `tree` is the built-in UR5")]
        let q = <[f64; Ur5::DOF]>::try_from(q.as_slice()).expect("the built-in UR5's configurations have its DoF");
        let reference = fk.link_poses(&q).map_err(runtime)?;
        worst = worst_of(worst, distance(&entries(&Ur5::tip_pose(&q)), &reference[tool0], reach));
        for (pose, &id) in Ur5::link_poses(&q).iter().zip(&ids) {
            worst = worst_of(worst, distance(&entries(pose), &reference[id], reach));
        }
    }
    Ok(worst)
}

#[cfg(test)]
mod tests {
    #[test]
    fn thousands_are_separated() {
        for (n, expected) in [(0, "0"), (999, "999"), (1000, "1,000"), (10_000, "10,000"), (1_000_000, "1,000,000")] {
            assert_eq!(super::thousands(n), expected);
        }
    }
}
