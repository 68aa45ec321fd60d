//! Everything a subcommand can fail with; each message names the file, the element and the fault.
//!
//! `CliError` is printed by `main` as `error: <file>: <element>: <fault>`; option faults
//! (`generate`'s, and `--dynamics`' of `check` and `expr`) name their flag.

use kinematics::{LoadError, RuntimeError};
use kinematics_build::BuildError;
use kinematics_compiler::CompileError;

/// A failed subcommand. `main` prints it as `error: <message>` and exits non-zero.
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    /// The description could not be read, parsed or validated.
    #[error(transparent)]
    Load(#[from] LoadError),
    /// Generating or writing code failed, or a link name given on the command line is unknown
    /// (boxed, as the large errors below: `CliError` stays small to move).
    #[error(transparent)]
    Build(Box<BuildError>),
    /// A mesh of the collision geometry that could not be found or read.
    #[error("{file}: {source}")]
    Mesh {
        /// The description file.
        file: String,
        /// The mesh's link, URI and why.
        #[source]
        source: kinematics::model::MeshLoadError,
    },
    /// A link named by an option that the robot does not have (with "did you mean").
    #[error("{file}: {source}")]
    UnknownLink {
        /// The description file.
        file: String,
        /// Which link, and the closest name.
        #[source]
        source: kinematics::model::UnknownLink,
    },
    /// `generate` (and `--dynamics` of `check` and `expr`): options that break the compiler's
    /// rules against this robot, each naming its flag.
    #[error("{file}: {}", faults.iter().map(ToString::to_string).collect::<Vec<_>>().join("; "))]
    Options {
        /// The description file.
        file: String,
        /// Every fault, in the order the rules run.
        faults: Vec<FlagFault>,
    },
    /// The runtime reference refused the query (a wrong number of joint values).
    #[error("{file}: {source}")]
    Runtime {
        /// The description file.
        file: String,
        /// What the runtime said.
        #[source]
        source: RuntimeError,
    },
    /// The compiler refused the request.
    #[error("{file}: {source}")]
    Compile {
        /// The description file.
        file: String,
        /// What the compiler said.
        #[source]
        source: Box<CompileError>,
    },
    /// `check`: the compiled expressions disagree with the runtime reference.
    #[error("{file}: link `{link}`: the compiled pose is off by {error:.2e} x reach (tolerance {tolerance:e})")]
    Disagrees {
        /// The description file.
        file: String,
        /// The link with the largest error.
        link: String,
        /// Its error, relative to the robot's reach.
        error: f64,
        /// The tolerance.
        tolerance: f64,
    },
    /// The runtime reference's dynamics refused the robot or a state.
    #[error("{file}: {source}")]
    Dynamics {
        /// The description file.
        file: String,
        /// What the reference said.
        #[source]
        source: Box<kinematics::runtime::DynamicsError>,
    },
    /// `check --dynamics`: a compiled dynamics function disagrees with the runtime reference.
    #[error(
        "{file}: `{function}`: the compiled dynamics are off by {error:.2e} x the values' scale (tolerance {tolerance:e})"
    )]
    DynamicsDisagrees {
        /// The description file.
        file: String,
        /// The function with the largest error (`gravity_torques`, ...).
        function: &'static str,
        /// Its error, relative to the scale of the values compared.
        error: f64,
        /// The tolerance.
        tolerance: f64,
    },
    /// `check --dynamics`: forward dynamics refused a singular mass matrix on one side only.
    #[error(
        "{file}: `forward_dynamics` at q = {q:?}: {}",
        match reference {
            Some(velocities) => format!(
                "the reference finds the mass matrix singular (velocities {}), but the compiled factorisation's pivots are all positive",
                velocities.iter().map(|v| format!("`{v}`")).collect::<Vec<_>>().join(", ")
            ),
            None => format!(
                "the compiled factorisation refuses the mass matrix as singular (the pivot of {}), but the reference's is regular",
                subject.iter().map(|v| format!("`{v}`")).collect::<Vec<_>>().join(", ")
            ),
        }
    )]
    SingularDisagrees {
        /// The description file.
        file: String,
        /// The configuration.
        q: Vec<f64>,
        /// The velocities the compiled code refused at (empty when it did not refuse).
        subject: Vec<String>,
        /// The velocities the reference refused along, when it refused.
        reference: Option<Vec<String>>,
    },
    /// `expr --dynamics --joint`: a name that is none of the robot's velocities.
    #[error(
        "{file}: `--joint`: `{name}` is none of the velocities ({}){}",
        velocities.iter().map(|v| format!("`{v}`")).collect::<Vec<_>>().join(", "),
        suggestion.as_ref().map(|s| format!("; did you mean `{s}`?")).unwrap_or_default()
    )]
    UnknownVelocity {
        /// The description file.
        file: String,
        /// The name given.
        name: String,
        /// The robot's velocities.
        velocities: Vec<String>,
        /// The closest, when it looks like a typo.
        suggestion: Option<String>,
    },
    /// `check`: a collision verdict that is not the reference's, outside the band about contact.
    #[error(
        "{file}: `{check}` says {} at q = {q:?}, but the reference's distance is {distance:e} m",
        if *verdict { "colliding" } else { "free" }
    )]
    CollisionDisagrees {
        /// The description file.
        file: String,
        /// `collides` or `self_collides`.
        check: String,
        /// The configuration.
        q: Vec<f64>,
        /// The reference's signed distance.
        distance: f64,
        /// The check's verdict.
        verdict: bool,
    },
    /// `check`: the robot has no link besides the root, so no pose can be compared.
    #[error("{file}: nothing to check: the robot has no link besides its root")]
    NothingToCheck {
        /// The description file.
        file: String,
    },
    /// `ik`: the target is no pose.
    #[error("{file}: {source}")]
    Ik {
        /// The description file.
        file: String,
        /// What the solver refused.
        #[source]
        source: kinematics::ik::IkError,
    },
    /// `ik --from-q`: the configuration given is none of the solutions of its own pose, and the
    /// pose is at no singularity: the solver missed a solution.
    #[error(
        "{file}: round trip failed: --from-q is none of the solutions of its own pose (the nearest, solution \
         {nearest}, differs by {difference:.1e} rad), and no solution is singular: the solver missed one"
    )]
    RoundTrip {
        /// The description file.
        file: String,
        /// The nearest solution's number (from 1).
        nearest: usize,
        /// Its largest joint difference, modulo 2 pi (rad).
        difference: f64,
    },
    /// `convert`: a joint URDF has no type for (a spherical joint, an MJCF `ball`).
    #[error(
        "{file}: joint `{joint}`: a {kind} joint cannot be written as URDF (URDF has no joint whose position is a \
         quaternion; its `spherical` type is not in the specification), so nothing is written"
    )]
    NotUrdf {
        /// The description file.
        file: String,
        /// The joint, the first such in the tree's order.
        joint: String,
        /// Its kind (`spherical`).
        kind: &'static str,
    },
    /// An option's value that cannot be used (the message names the option and why).
    #[error("{0}")]
    Usage(String),
    /// `draw --path`: a path file that is not configurations of the robot, one a line.
    #[error("{path}: {}{fault}", line.map(|l| format!("line {l}: ")).unwrap_or_default())]
    BadPath {
        /// The path file, as given.
        path: String,
        /// The line at fault (from 1), if one is.
        line: Option<usize>,
        /// What is wrong there.
        fault: String,
    },
    /// An output file could not be written (it was written atomically, so nothing is left behind).
    #[error("{file}: cannot write `{path}`: {source}")]
    Write {
        /// The description file.
        file: String,
        /// The output path, as given.
        path: String,
        /// The IO error.
        #[source]
        source: std::io::Error,
    },
    /// Standard output could not be written.
    #[error("cannot write to standard output: {0}")]
    Output(#[source] std::io::Error),
}

impl From<BuildError> for CliError {
    fn from(error: BuildError) -> Self {
        CliError::Build(Box::new(error))
    }
}

impl CliError {
    /// The compiler's refusal of something asked of `file`.
    pub fn compile(file: &str, source: CompileError) -> Self {
        CliError::Compile { file: file.to_owned(), source: Box::new(source) }
    }
}

impl From<std::io::Error> for CliError {
    fn from(error: std::io::Error) -> Self {
        CliError::Output(error)
    }
}

/// An option's fault, and the flag that set the option.
#[derive(Debug, thiserror::Error)]
#[error("`{flag}`: {fault}")]
pub struct FlagFault {
    /// The flag (`--links`).
    pub flag: &'static str,
    /// What is wrong.
    pub fault: kinematics_compiler::options::OptionFault,
}

/// `text` written to `output` atomically (a file is whole or not there), or printed to `out`
/// without one; `file` is the description it was made from, for the error.
pub fn deliver(
    text: &str,
    output: Option<&std::path::Path>,
    file: &str,
    out: &mut dyn std::io::Write,
) -> Result<(), CliError> {
    match output {
        Some(path) => kinematics_build::write_atomic(path, text).map_err(|source| CliError::Write {
            file: file.to_owned(),
            path: path.display().to_string(),
            source,
        }),
        None => Ok(write!(out, "{text}")?),
    }
}
