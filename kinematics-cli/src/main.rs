//! The `kinematics` command-line tool: a clap front end over the library calls, one module per
//! subcommand.
//!
//! `inspect` prints the kinematic tree, `fk` the runtime reference pose of every link (or one, or
//! as JSON), `expr` the simplified symbolic pose with its operation counts, `generate` the Rust a
//! build script would write (the build API's own text), `check` the compiled expressions against
//! the runtime reference, `graph` the tree as Graphviz DOT, `draw` the robot at a configuration as
//! SVG (three orthographic views of the runtime reference's link origins and joint axes), and
//! `demo` all of it on one robot with a timing of the generated code built into this binary
//! (`ur5.rs`, from `build.rs`, dynamics included), then collision checks timed on the built-in
//! spherized Panda (`panda.rs`; `hand_loop.rs` is the naive check it is timed against). Errors go
//! to stderr as `error: <file>: <element>: <fault>`, with a non-zero exit status; files are
//! written atomically, so a failed run leaves none behind. Long work shows progress on stderr when
//! stderr is a terminal, and nothing when it is not: a spinner while the compiler runs (`check`,
//! `demo`, `generate`, `expr --all`, `--dynamics`), then a bar over the configurations (and
//! states) `check` and `demo` compare.
//!
//! `--dynamics` (`dynamics.rs`) adds the rigid-body dynamics from the links' inertias to `generate`
//! (the functions), `check` (each compiled function against the runtime reference's) and `expr`
//! (the gravity torques as text).
//!
//! Also `ik` (closed-form solutions), `convert` (URDF text) and `collision-pairs` (an SRDF of
//! disabled pairs). Every padded column is padded by hand and capped, so names of any length print.

mod agreement;
mod check;
mod collision;
mod collision_pairs;
mod convert;
mod cover;
mod demo;
mod draw;
mod dynamics;
mod error;
mod expr;
mod fk;
mod generate;
mod graph;
mod hand_loop;
mod ik;
mod inspect;
mod panda;
mod progress;
mod robot;
mod spherize;
mod ur5;

use std::io::Write;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

use crate::error::CliError;

/// Forward kinematics of robots described by URDF files, MJCF files or DH tables: inspect,
/// evaluate, print symbolically, check, generate Rust and convert to URDF.
#[derive(Parser)]
#[command(name = "kinematics", version, about)]
struct Cli {
    /// Read decimal angles within 1e-8 rad of a multiple of pi/2 (such as 3.14159265359) as that
    /// exact multiple (`on`), or every angle as written (`off`).
    #[arg(long, global = true, value_enum, value_name = "on|off", default_value = "on")]
    exact_angles: Switch,
    /// The description's format: by its extension (`auto`: .urdf, .mjcf, .toml, .json, and .xml
    /// as its root element says, `<robot>` or `<mujoco>`), or as named.
    #[arg(long, global = true, value_enum, default_value = "auto")]
    format: robot::Format,
    #[command(subcommand)]
    command: Command,
}

/// A global on/off option.
#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum Switch {
    On,
    Off,
}

#[derive(Subcommand)]
enum Command {
    /// Print the kinematic tree: links, joints, types, axes, limits, mimic relations, DoF order,
    /// and the chain from the root to each leaf.
    Inspect(inspect::Args),
    /// Print the pose of every link (or one) at a configuration, by the runtime reference.
    Fk(fk::Args),
    /// Print the simplified symbolic pose of a link, with its operation counts against the plain
    /// product of the chain's transforms (or its Jacobian, or with `--dynamics` the gravity
    /// torques).
    Expr(expr::Args),
    /// Print (or write atomically) the Rust a build script would generate for the robot (with
    /// `--dynamics`, its dynamics too).
    Generate(generate::Args),
    /// Check the compiled expressions of every link against the runtime reference on many
    /// configurations; fails past 1e-12 x reach. With `--dynamics`, the compiled dynamics too
    /// (past 1e-12 x the values' scale).
    Check(check::Args),
    /// Print the kinematic tree as Graphviz DOT (links as boxes, joints as labelled edges).
    Graph(graph::Args),
    /// Draw the robot at a configuration as SVG: front, side and top views on one scale, links
    /// as segments between origins, joint axes as arrows.
    Draw(draw::Args),
    /// Every closed-form inverse kinematics solution of the tip for a pose (or for the pose at
    /// given joint values), each with its flags and its errors by the runtime reference.
    Ik(ik::Args),
    /// Write an SRDF of the link pairs a self-collision check can leave out (adjacent bodies,
    /// pairs touching at the default configuration, always or never over random samples), as
    /// MoveIt's setup assistant does.
    CollisionPairs(collision_pairs::Args),
    /// Write the robot's kinematics as URDF (links, joints, origins, axes, limits, mimic
    /// relations; geometry left out), e.g. from an MJCF file.
    Convert(convert::Args),
    /// Write the URDF again with each link's collision geometry replaced by its sphere cover (a
    /// `<collision>` with a `<sphere>` per sphere, as VAMP and cuRobo read), all else as written.
    Spherize(spherize::Args),
    /// The whole pipeline on one robot: tree, symbolic pose, operation counts, agreement with the
    /// runtime reference, and timing; velocities, inverse kinematics and dynamics; then collision
    /// checks on the built-in spherized Panda.
    Demo(demo::Args),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    robot::set_exact_angles(cli.exact_angles == Switch::On);
    robot::set_format(cli.format);
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    let result = match cli.command {
        Command::Inspect(args) => inspect::run(&args, &mut out),
        Command::Fk(args) => fk::run(&args, &mut out),
        Command::Ik(args) => ik::run(&args, &mut out),
        Command::Expr(args) => expr::run(&args, &mut out),
        Command::Generate(args) => generate::run(&args, &mut out),
        Command::Check(args) => check::run(&args, &mut out),
        Command::Graph(args) => graph::run(&args, &mut out),
        Command::Draw(args) => draw::run(&args, &mut out),
        Command::Convert(args) => convert::run(&args, &mut out),
        Command::CollisionPairs(args) => collision_pairs::run(&args, &mut out),
        Command::Spherize(args) => spherize::run(&args, &mut out),
        Command::Demo(args) => demo::run(&args, &mut out),
    };
    let result = result.and_then(|()| out.flush().map_err(CliError::Output));
    match result {
        Ok(()) => ExitCode::SUCCESS,
        // The reader went away (`kinematics generate ... | head`): not our fault.
        Err(CliError::Output(e)) if e.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("error: {error}");
            ExitCode::FAILURE
        }
    }
}
