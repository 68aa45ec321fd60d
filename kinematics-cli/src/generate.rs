//! `kinematics generate FILE`: the Rust module the build API writes, to stdout or a file.
//!
//! It calls `kinematics_build::Robot::generate` or `write_to`, so its output is the build API's
//! byte for byte.

use std::io::Write;

use kinematics_build::{BuildError, CallFault, Robot, Trig};
use kinematics_compiler::options::OptionKey;

use crate::error::{CliError, FlagFault};

/// `--ik`'s kinds.
#[derive(Clone, Copy, clap::ValueEnum)]
enum IkKind {
    ClosedForm,
    Numeric,
}

/// Arguments of `generate`.
#[derive(clap::Args)]
pub struct Args {
    /// A URDF file (.urdf, .xml), MJCF file (.xml, .mjcf) or DH table (.toml, .json).
    file: String,
    /// The frame poses are expressed in (default: the root link).
    #[arg(long)]
    base: Option<String>,
    /// A tip link (repeat for several): `tip_pose` / `tip_poses` (default: none, only `link_poses`).
    #[arg(long)]
    tip: Vec<String>,
    /// Only these links in `link_poses` (and `link_positions`, `LINK_NAMES`), in this order,
    /// comma-separated (`--links l_sole,r_sole`; default: every link but the base).
    #[arg(long, value_delimiter = ',')]
    links: Vec<String>,
    /// The struct's name (default: the robot's name in UpperCamelCase).
    #[arg(long)]
    name: Option<String>,
    /// Also generate position-only functions.
    #[arg(long)]
    positions: bool,
    /// Also generate the tips' velocity functions (Jacobians, pose and Jacobian, twists).
    #[arg(long)]
    jacobians: bool,
    /// Also generate the tip's inverse kinematics: `closed-form` (every solution of its family,
    /// and the numeric solver) or `numeric` (the numeric solver only). Needs one tip.
    #[arg(long, value_enum, num_args = 0..=1, default_missing_value = "closed-form")]
    ik: Option<IkKind>,
    /// With `--ik`, the joint of a seven-joint arm whose value `tip_ik` takes as an input.
    #[arg(long, requires = "ik")]
    free: Option<String>,
    /// Also generate `f32` functions.
    #[arg(long)]
    f32: bool,
    /// Also generate collision checking from the links' `<collision>` geometry, as spheres.
    #[arg(long)]
    collision: bool,
    /// With `--collision`: how the geometry becomes spheres, and where meshes are.
    #[command(flatten)]
    cover: crate::cover::CoverArgs,
    /// With `--collision`, MoveIt's SRDF whose disabled pairs `self_collides` leaves out.
    #[arg(long, requires = "collision")]
    srdf: Option<String>,
    /// Also generate the dynamics from the links' `<inertial>`s: `gravity_torques`,
    /// `inverse_dynamics`, `nonlinear_effects`, `mass_matrix` and `forward_dynamics`.
    #[arg(long)]
    dynamics: bool,
    /// With `--dynamics`: the gravity and how inertias are read.
    #[command(flatten)]
    dynamics_options: crate::dynamics::DynamicsArgs,
    /// Which sine and cosine the code calls: `fast` (ours, every angle in one call) or `std` (the
    /// platform's, one call per angle).
    #[arg(long, value_enum, default_value_t = TrigArg::Fast)]
    trig: TrigArg,
    /// Write to this file (atomically) instead of standard output.
    #[arg(short, long)]
    output: Option<std::path::PathBuf>,
}

/// `--trig`.
#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum TrigArg {
    /// Ours (the default).
    Fast,
    /// The platform's.
    Std,
}

/// The builder for these arguments: the file relative to the current directory; `--free` with
/// `--ik numeric` is a usage error (the free joint is a closed form's).
pub fn builder(args: &Args) -> Result<Robot, CliError> {
    let file = &args.file;
    let robot = match crate::robot::format() {
        crate::robot::Format::Auto => Robot::file(file),
        crate::robot::Format::Urdf => Robot::urdf(file),
        crate::robot::Format::Mjcf => Robot::mjcf(file),
        crate::robot::Format::Dh => Robot::dh(file),
    };
    let mut robot =
        robot.manifest_dir(".").tips(&args.tip).exact_angles(crate::robot::exact_angles_on()).trig(match args.trig {
            TrigArg::Fast => Trig::Fast,
            TrigArg::Std => Trig::Std,
        });
    if let Some(base) = &args.base {
        robot = robot.base(base);
    }
    if !args.links.is_empty() {
        robot = robot.links(&args.links);
    }
    if let Some(name) = &args.name {
        robot = robot.struct_name(name);
    }
    if args.positions {
        robot = robot.positions();
    }
    if args.jacobians {
        robot = robot.jacobians();
    }
    match (args.ik, &args.free) {
        (Some(IkKind::ClosedForm), Some(joint)) => robot = robot.ik_free(joint),
        (Some(IkKind::ClosedForm), None) => robot = robot.ik(),
        (Some(IkKind::Numeric), Some(_)) => {
            return Err(CliError::Usage(format!(
                "{}: --free names the joint a closed form takes as an input: not with --ik numeric",
                args.file
            )));
        }
        (Some(IkKind::Numeric), None) => robot = robot.ik_numeric(),
        (None, _) => {}
    }
    if args.f32 {
        robot = robot.f32();
    }
    if args.collision {
        robot = robot.collision();
    }
    let cover = &args.cover;
    let cover_given =
        cover.spheres.is_some() || cover.cover.is_some() || cover.skip_meshes || !cover.packages.is_empty();
    if cover_given && !args.collision {
        return Err(CliError::Usage(
            "`--spheres`, `--cover`, `--package` and `--skip-meshes` need `--collision`".into(),
        ));
    }
    if let Some(n) = cover.spheres {
        robot = robot.spheres(n);
    }
    if let Some(metres) = cover.cover {
        robot = robot.sphere_cover(metres);
    }
    if cover.skip_meshes {
        robot = robot.skip_meshes();
    }
    for (name, path) in &cover.packages {
        robot = robot.package(name.clone(), path.clone());
    }
    if let Some(srdf) = &args.srdf {
        robot = robot.srdf(srdf);
    }
    if args.dynamics {
        robot = robot.dynamics();
        if let Some(gravity) = args.dynamics_options.gravity {
            robot = robot.gravity(gravity);
        }
        if args.dynamics_options.inertia_as_written {
            robot = robot.inertia_as_written();
        }
        if !args.dynamics_options.forces.is_empty() {
            robot = robot.forces(args.dynamics_options.forces.iter().cloned());
        }
    }
    Ok(robot)
}

/// Generates, then prints or writes.
pub fn run(args: &Args, out: &mut dyn Write) -> Result<(), CliError> {
    let robot = builder(args)?;
    // The build API compiles inside one call, with no progress of its own: a spinner says what
    // runs (on a terminal only).
    let spinner = crate::progress::spinner("generating code");
    let generated = match &args.output {
        Some(path) => robot.write_to(path).map(|()| None),
        None => robot.generate().map(Some),
    };
    spinner.finish_and_clear();
    if let Some(code) = generated.map_err(flags)? {
        write!(out, "{code}")?;
    }
    Ok(())
}

/// A build error naming the builder's calls as the command's error naming its flags.
fn flags(error: BuildError) -> CliError {
    let BuildError::Options { file, faults } = error else { return CliError::from(error) };
    let faults = faults.into_iter().map(|CallFault { fault, .. }| FlagFault { flag: flag(fault.key), fault }).collect();
    CliError::Options { file, faults }
}

/// The flag that sets an option (`generate`'s; `check` and `expr` name `--dynamics` and
/// `--gravity` the same).
pub fn flag(key: OptionKey) -> &'static str {
    match key {
        OptionKey::Base => "--base",
        OptionKey::Tip(_) => "--tip",
        OptionKey::Link(_) | OptionKey::Links => "--links",
        OptionKey::Positions => "--positions",
        OptionKey::Jacobians => "--jacobians",
        OptionKey::Ik => "--ik",
        // `generate` has no flag for a free-flying root; the key is mapped all the same.
        OptionKey::FloatingBase => "floating_base",
        OptionKey::Scalars => "--f32",
        OptionKey::Trig => "--trig",
        OptionKey::ExactAngles => "--exact-angles",
        OptionKey::Collision => "--collision",
        OptionKey::SphereCover => "--cover",
        OptionKey::Spheres => "--spheres",
        OptionKey::Srdf => "--srdf",
        OptionKey::Dynamics => "--dynamics",
        OptionKey::Gravity => "--gravity",
        OptionKey::ForceLink(_) => "--forces",
    }
}
