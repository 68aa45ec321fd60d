//! `kinematics check FILE`: the compiled expressions against the runtime reference, with
//! `--collision` the collision checks against the reference's distances, and with `--dynamics`
//! the compiled dynamics against the reference's (`dynamics`).
//!
//! Every link's compiled pose is evaluated by `Compiled::evaluator` (the nodes the poses need
//! listed once, then one pass per configuration) against `ReferenceFk`, the configurations split
//! across the cores (`agreement`); with `--collision`, the `collision` module's checks, which
//! `demo` runs too.

use std::io::Write;

use kinematics_compiler::dynamics::DynamicsFunction;

use crate::agreement::{TOLERANCE, check_graph, verdict};
use crate::error::CliError;

/// Arguments of `check`.
#[derive(clap::Args)]
pub struct Args {
    /// A URDF file (.urdf, .xml), MJCF file (.xml, .mjcf) or DH table (.toml, .json).
    file: String,
    /// How many configurations (the first five put every joint at 0, pi/2, -pi/2, pi, -pi).
    #[arg(long, default_value_t = 10_000, value_parser = crate::agreement::sample_count)]
    samples: usize,
    /// Check the collision checks too (`self_collides`, and with `--scene` `collides`), on the
    /// robot's `<collision>` geometry against the reference's distances.
    #[arg(long)]
    collision: bool,
    /// How many configurations the collision checks are run on.
    #[arg(long, default_value_t = 1_000, value_parser = crate::agreement::sample_count)]
    collision_samples: usize,
    /// How the geometry becomes spheres, and where meshes are.
    #[command(flatten)]
    cover: crate::cover::CoverArgs,
    /// An SRDF whose disabled pairs the self-collision check leaves out (implies `--collision`).
    #[arg(long, value_name = "FILE")]
    srdf: Option<String>,
    /// A scene file whose obstacles `collides` is checked against (implies `--collision`).
    #[arg(long, value_name = "FILE")]
    scene: Option<String>,
    /// Check the compiled dynamics too (gravity torques, inverse dynamics, nonlinear effects,
    /// mass matrix, forward dynamics) against the runtime reference's, from the links' inertias;
    /// fails past 1e-12 x the values' scale.
    #[arg(long)]
    dynamics: bool,
    /// With `--dynamics`, how many states (configurations as above; rates and accelerations
    /// random in [-2, 2]).
    #[arg(long, default_value_t = 1_000, value_parser = crate::agreement::sample_count, requires = "dynamics")]
    dynamics_samples: usize,
    /// With `--dynamics`: the gravity and how inertias are read.
    #[command(flatten)]
    dynamics_options: crate::dynamics::DynamicsArgs,
}

/// Prints the largest error of every link; fails past the tolerance.
pub fn run(args: &Args, out: &mut dyn Write) -> Result<(), CliError> {
    let mut tree = crate::robot::load(&args.file)?;
    // The collision inputs are read first: a bad SRDF or scene fails before anything is printed.
    let collision = if args.collision || args.srdf.is_some() || args.scene.is_some() {
        args.cover.read_meshes(&mut tree, &args.file)?;
        Some(crate::collision::setup(&tree, &args.cover, args.srdf.as_deref(), args.scene.as_deref())?)
    } else {
        None
    };
    // The dynamics' request is checked first too: a refused inertia fails before anything is printed.
    let dynamics = if args.dynamics {
        let request = args.dynamics_options.request();
        let with_forces = if request.forces.is_empty() { &[][..] } else { &DynamicsFunction::WITH_FORCES[..] };
        let functions: Vec<DynamicsFunction> = DynamicsFunction::ALL.iter().chain(with_forces).copied().collect();
        let compiled = crate::dynamics::compile(&tree, &args.file, &request, &functions)?;
        Some((crate::dynamics::reference(&tree, &args.file, &request)?, compiled, request.forces))
    } else {
        None
    };
    let errors = check_graph(&tree, &args.file, args.samples)?;
    writeln!(
        out,
        "robot `{}`: the compiled pose of every link in `{}` against the runtime reference",
        tree.name(),
        tree.link(tree.root()).name
    )?;
    writeln!(
        out,
        "{} configurations (fixed seed; 0, +-pi/2, +-pi and beyond the limits included), reach {:.3} m",
        args.samples,
        tree.reach()
    )?;
    let width = crate::inspect::column_width(errors.iter().map(|e| e.link.as_str())).max(4);
    writeln!(out, "{}  largest error (x reach)", crate::inspect::pad("link", width))?;
    for e in &errors {
        writeln!(out, "{}  {:.2e}", crate::inspect::pad(&e.link, width), e.error)?;
    }
    if let Some(worst) = errors.iter().max_by(|a, b| a.error.total_cmp(&b.error)) {
        let ok = if worst.error <= TOLERANCE { "within" } else { "past" };
        // (A NaN error cannot occur: `check_graph` counts it as infinite.)
        writeln!(
            out,
            "largest: {:.2e} x reach (link `{}`), {ok} the tolerance {TOLERANCE:e}",
            worst.error, worst.link
        )?;
    }
    verdict(&args.file, &errors)?;
    if let Some(setup) = &collision {
        match crate::collision::check(&tree, &args.file, args.collision_samples, setup)? {
            Some(report) => write!(out, "{}", crate::collision::text(&report, args.collision_samples))?,
            None => writeln!(out, "collision: no <collision> geometry the cover reads")?,
        }
    }
    if let Some((reference, compiled, forces)) = &dynamics {
        let graphs = crate::dynamics::Graphs(compiled);
        let report = crate::dynamics::compare(&tree, &args.file, reference, &graphs, forces, args.dynamics_samples)?;
        write!(out, "{}", crate::dynamics::report_text(&tree, &report))?;
        crate::dynamics::verdict(&args.file, &report)?;
    }
    Ok(())
}
