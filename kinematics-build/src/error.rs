//! Everything that can go wrong between a build script's call and the written file.

use kinematics_compiler::CompileError;
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
    /// A base, tip or listed link (`links`) that the robot does not have.
    #[error("{file}: {role} link `{link}` does not exist{}", suggestion.as_ref().map(|s| format!("; did you mean `{s}`?")).unwrap_or_default())]
    UnknownLink {
        /// The description file.
        file: String,
        /// `base`, `tip` or `listed` (an entry of `links`).
        role: &'static str,
        /// The link asked for.
        link: String,
        /// The closest link name, when it looks like a typo.
        suggestion: Option<String>,
    },
    /// [`crate::Robot::links`] called with no link at all (leave it out for every link).
    #[error("{file}: `links` lists no link (leave it out to have every link)")]
    EmptyLinks {
        /// The description file.
        file: String,
    },
    /// A link listed twice in [`crate::Robot::links`].
    #[error("{file}: link `{link}` is listed twice in `links`")]
    DuplicateLink {
        /// The description file.
        file: String,
        /// The link listed twice.
        link: String,
    },
    /// A free-flying root whose link or joint name the description already has.
    #[error(
        "{file}: `floating_base` adds a root link `{link}` and a floating joint `root_joint`, but the description already has a {clash} (give the new root link another name)"
    )]
    FloatingBaseClash {
        /// The description file.
        file: String,
        /// The new root link asked for.
        link: String,
        /// What clashes (`link `world``).
        clash: String,
    },
    /// `jacobians` asked for with no tip.
    #[error("{file}: `jacobians` needs a tip: the Jacobians are the tips' (call `.tip(\"link\")`)")]
    JacobiansWithoutTip {
        /// The description file.
        file: String,
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
