//! `kinematics generate FILE`: the Rust module the build API writes, to stdout or a file.

use std::io::Write;

use kinematics_build::{Robot, Trig};

use crate::error::CliError;

/// Arguments of `generate`.
#[derive(clap::Args)]
pub struct Args {
    /// A URDF file (.urdf, .xml) or DH table (.toml, .json).
    file: String,
    /// The frame poses are expressed in (default: the root link).
    #[arg(long)]
    base: Option<String>,
    /// A tip link (repeat for several): `tip_pose` / `tip_poses` (default: none, only `link_poses`).
    #[arg(long)]
    tip: Vec<String>,
    /// The struct's name (default: the robot's name in UpperCamelCase).
    #[arg(long)]
    name: Option<String>,
    /// Also generate position-only functions.
    #[arg(long)]
    positions: bool,
    /// Also generate the tips' velocity functions (Jacobians, pose and Jacobian, twists).
    #[arg(long)]
    jacobians: bool,
    /// Also generate `f32` functions.
    #[arg(long)]
    f32: bool,
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

/// The builder for these arguments: the file relative to the current directory.
pub fn builder(args: &Args) -> Robot {
    let mut robot =
        Robot::file(&args.file).manifest_dir(".").tips(&args.tip).exact_angles(crate::robot::exact_angles_on()).trig(
            match args.trig {
                TrigArg::Fast => Trig::Fast,
                TrigArg::Std => Trig::Std,
            },
        );
    if let Some(base) = &args.base {
        robot = robot.base(base);
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
    if args.f32 {
        robot = robot.f32();
    }
    robot
}

/// Generates, then prints or writes.
pub fn run(args: &Args, out: &mut dyn Write) -> Result<(), CliError> {
    let robot = builder(args);
    match &args.output {
        Some(path) => robot.write_to(path)?,
        None => write!(out, "{}", robot.generate()?)?,
    }
    Ok(())
}
