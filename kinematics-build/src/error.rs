//! Everything that can go wrong between a build script's call and the written file.

use kinematics_compiler::CompileError;
use kinematics_compiler::options::OptionFault;
use kinematics_model::LoadError;

/// Why a robot could not be generated or written. Messages name the description file as the
/// caller wrote it, the element (link, joint, DH row, option) and the fault, lower-case.
///
/// `Debug` prints the message too, so a build script whose `main` returns
/// `Result<(), BuildError>` (or a boxed error) shows it as it is.
#[derive(thiserror::Error)]
#[non_exhaustive]
pub enum BuildError {
    /// The description could not be read, has an unknown extension, is malformed, or breaks a
    /// model rule (every broken rule is listed).
    #[error(transparent)]
    Load(#[from] LoadError),
    /// Options that break the compiler's rules against this robot (every fault, each naming the
    /// call that set the option): a link the robot does not have (with "did you mean"), a link
    /// listed twice, `jacobians` without a tip, `ik` of a chain no family covers, a floating base
    /// whose names clash.
    #[error("{file}: {}", faults.iter().map(ToString::to_string).collect::<Vec<_>>().join("; "))]
    Options {
        /// The description file.
        file: String,
        /// Every fault, in the order the rules run (never empty).
        faults: Vec<CallFault>,
    },
    /// A mesh of the collision geometry that could not be found or read (the link, the URI, every
    /// place looked or what is wrong with the file).
    #[error("{file}: {source}")]
    Mesh {
        /// The description file.
        file: String,
        /// The mesh's link, file and reason.
        source: kinematics_model::MeshLoadError,
    },
    /// A struct name that is not a Rust identifier.
    #[error("{file}: struct name `{name}` is not a Rust identifier")]
    StructName {
        /// The description file.
        file: String,
        /// The name given.
        name: String,
    },
    /// A crate path that is not a Rust path.
    #[error("{file}: crate path `{path}` is not a Rust path")]
    CratePath {
        /// The description file.
        file: String,
        /// The path given.
        path: String,
    },
    /// The compiler refused the request.
    #[error("{file}: {source}")]
    Compile {
        /// The description file.
        file: String,
        /// What the compiler said.
        #[source]
        source: CompileError,
    },
    /// The emitted tokens did not parse as a Rust file (a bug in the compiler, reported rather
    /// than written).
    #[error("{file}: the generated code does not parse ({message}); please report this")]
    Unparsable {
        /// The description file.
        file: String,
        /// The parser's message.
        message: String,
    },
    /// `write_to_out_dir` outside a build script.
    #[error("OUT_DIR is not set: `write_to_out_dir` is for build scripts (use `write_to` elsewhere)")]
    NoOutDir,
    /// The output file could not be written (nothing is left behind).
    #[error("{file}: cannot write `{path}`: {source}")]
    Write {
        /// The description file.
        file: String,
        /// The output path.
        path: String,
        /// The IO error.
        #[source]
        source: std::io::Error,
    },
}

impl std::fmt::Debug for BuildError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Display::fmt(self, f)
    }
}

/// An option's fault, and the builder call that set the option.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("`{method}`: {fault}")]
pub struct CallFault {
    /// The builder call (`.links(..)`).
    pub method: &'static str,
    /// What is wrong.
    pub fault: OptionFault,
}
