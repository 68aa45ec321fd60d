//! Reading the description relative to the crate's `Cargo.toml`, and loading it through the
//! model's one loader (`kinematics_model::Source::load`).
//!
//! The path is resolved against `CARGO_MANIFEST_DIR` (or a given directory), and the bytes read are
//! given to `Source::load`.

use std::path::{Path, PathBuf};

use kinematics_model::{ExactAngles, KinematicTree, LoadError, LoadErrorKind, Source, SourceKind};

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
    /// The files the description names (an MJCF `<include>` or `<model file>`), each as (path
    /// as written, text), embedded beside it.
    pub files: Vec<(String, String)>,
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

/// Reads the description at `absolute` and loads it with `exact_angles` (and a free-flying root
/// named `floating_base`, if given); `label` names it in
/// errors and, with `kind`, picks the format.
pub(crate) fn load(
    label: &str,
    absolute: PathBuf,
    kind: SourceKind,
    exact_angles: ExactAngles,
    floating_base: Option<&str>,
) -> Result<Loaded, LoadError> {
    let bytes = std::fs::read(&absolute).map_err(|e| LoadError::new(label, LoadErrorKind::Io(e)))?;
    let source = Source::from_bytes(label, kind, bytes)?;
    // MJCF's `<include>` and `<model file>` paths are relative to the main file's directory;
    // each file read is kept, for the generated code to embed.
    let dir = absolute.parent().map(Path::to_path_buf).unwrap_or_default();
    let files = std::cell::RefCell::new(Vec::new());
    let read = |file: &str| {
        let text = std::fs::read_to_string(dir.join(file)).map_err(|e| e.to_string())?;
        files.borrow_mut().push((file.to_owned(), text.clone()));
        Ok(text)
    };
    let tree = source.load_reading(exact_angles, floating_base, &read)?;
    let (reference_label, text, files) = (source.file_name(), source.text, files.into_inner());
    Ok(Loaded { tree, label: label.to_owned(), reference_label, text, files })
}
