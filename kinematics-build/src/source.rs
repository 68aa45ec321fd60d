//! Reading the description relative to the crate's `Cargo.toml`, and validating it.

use std::path::{Path, PathBuf};

use kinematics_model::{KinematicTree, LoadError, LoadErrorKind, SourceFormat};

/// A description, read and validated.
#[derive(Debug)]
pub(crate) struct Loaded {
    /// The validated tree.
    pub tree: KinematicTree,
    /// The file as the caller wrote it, for messages.
    pub label: String,
    /// The label `reference()` parses under: the caller's, with an extension naming the format
    /// appended when it does not already (`reference()` picks the format by extension).
    pub reference_label: String,
    /// The description's text, as read (the generated code embeds it for `reference()`).
    pub text: String,
}

/// Where a relative path is read from: `dir` if given, else `CARGO_MANIFEST_DIR` (set for build
/// scripts), else the current directory.
pub(crate) fn resolve(path: &Path, dir: Option<&Path>) -> PathBuf {
    let root = match dir {
        Some(dir) => dir.to_path_buf(),
        None => std::env::var_os("CARGO_MANIFEST_DIR").map(PathBuf::from).unwrap_or_default(),
    };
    let joined = root.join(path);
    // A clean absolute path (no `..`) where the file exists; the joined one otherwise.
    std::fs::canonicalize(&joined).unwrap_or_else(|_| std::path::absolute(&joined).unwrap_or(joined))
}

/// Reads and validates the description at `absolute`; `label` names it in errors. `format` is
/// the front end (`None`: by the label's extension).
pub(crate) fn load(label: &str, absolute: PathBuf, format: Option<SourceFormat>) -> Result<Loaded, LoadError> {
    let error = |kind| LoadError::new(label, kind);
    let format = match format {
        Some(format) => format,
        None => SourceFormat::from_file_name(label).ok_or_else(|| error(LoadErrorKind::UnknownFormat))?,
    };
    let text = std::fs::read_to_string(&absolute).map_err(|e| error(LoadErrorKind::Io(e)))?;
    let description = format.parse(&text).map_err(error)?;
    let tree = KinematicTree::from_description(&description).map_err(|e| error(LoadErrorKind::Model(e)))?;
    let reference_label = match SourceFormat::from_file_name(label) {
        Some(f) if f == format => label.to_owned(),
        _ => format!(
            "{label}.{}",
            match format {
                SourceFormat::Urdf => "urdf",
                SourceFormat::DhJson => "json",
                SourceFormat::DhToml => "toml",
            }
        ),
    };
    Ok(Loaded { tree, label: label.to_owned(), reference_label, text })
}
