//! The resolution error: a URI naming no file, with every place looked and, for a package, how to
//! say where it is.

use std::fmt::Write as _;
use std::path::PathBuf;

/// A mesh URI that names no file [`Resolver::resolve`](crate::Resolver::resolve) can find.
///
/// Its message names the URI, lists every file tried in order and, for a `package://` URI, says
/// how to give the package's folder in each front end.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{}", describe(.uri, .kind, .looked))]
pub struct Unresolved {
    /// The URI as written.
    pub uri: String,
    /// Why it names no file.
    pub kind: UnresolvedKind,
    /// Every file tried, in order (empty when the URI could not be read as one).
    pub looked: Vec<PathBuf>,
}

/// Why a URI names no file.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum UnresolvedKind {
    /// `package://NAME/...`: none of the package's candidate folders holds the file.
    Package {
        /// The package's name.
        name: String,
        /// Whether `ROS_PACKAGE_PATH` or `AMENT_PREFIX_PATH` listed any folder.
        environment: bool,
    },
    /// A path or `file://` URI naming no file.
    NoFile,
    /// A scheme this crate does not fetch (`http://`, Gazebo's `model://`).
    Scheme {
        /// The scheme, without `://`.
        scheme: String,
    },
    /// Not a URI of the expected shape.
    Malformed {
        /// What was expected.
        expected: &'static str,
    },
}

fn describe(uri: &str, kind: &UnresolvedKind, looked: &[PathBuf]) -> String {
    let mut out = match kind {
        UnresolvedKind::Package { name, .. } => format!("cannot find `{uri}`: no folder of package `{name}` holds it"),
        UnresolvedKind::NoFile => format!("cannot find `{uri}`: there is no such file"),
        UnresolvedKind::Scheme { scheme } => {
            format!("cannot read `{uri}`: `{scheme}://` is not supported (only `package://`, `file://` and paths are)")
        }
        UnresolvedKind::Malformed { expected } => format!("cannot read `{uri}`: it is not {expected}"),
    };
    if !looked.is_empty() {
        out.push_str("; looked, in order, at:");
        for path in looked {
            // Writing to a String cannot fail.
            let _ = write!(out, "\n    {}", path.display());
        }
    }
    if let UnresolvedKind::Package { name, environment } = kind {
        if !environment {
            out.push_str("\n  (ROS_PACKAGE_PATH and AMENT_PREFIX_PATH are not set)");
        }
        let _ = write!(
            out,
            "\n  give the package's folder: `packages({name} = \"PATH\")` in the derive, \
             `.package(\"{name}\", \"PATH\")` in the build API, `--package {name}=PATH` on the command line"
        );
    }
    out
}
