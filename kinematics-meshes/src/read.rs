//! Reading one mesh file (STL, Collada, OBJ) into the model's [`TriangleMesh`], and what can be
//! wrong with it.

use std::io;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};

use kinematics_model::collision::{MeshFault, TriangleMesh};

use crate::merge::Merged;
use crate::{collada, stl};

/// A mesh file that could not be read. Every message names the file.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum MeshFileError {
    /// The file could not be read at all.
    #[error("cannot read `{}`: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// Why.
        #[source]
        source: io::Error,
    },
    /// Neither its extension nor its first bytes say STL, Collada or OBJ.
    #[error(
        "cannot read `{}`: not a mesh format read here (the extension is not .stl, .dae or .obj, \
         and the content is neither ASCII STL nor Collada)",
        path.display()
    )]
    UnknownFormat {
        /// The file.
        path: PathBuf,
    },
    /// The file is not a valid file of its format.
    #[error("`{}` is not a valid {format} file: {message}", path.display())]
    Corrupt {
        /// The file.
        path: PathBuf,
        /// `STL`, `Collada` or `OBJ`.
        format: &'static str,
        /// What the reader found wrong.
        message: String,
    },
    /// The mesh reader panicked on the file (mesh-loader does on some malformed input); the panic
    /// was caught.
    #[error("`{}` is not a valid {format} file: the mesh reader failed on it ({message})", path.display())]
    ReaderFailed {
        /// The file.
        path: PathBuf,
        /// `STL`, `Collada` or `OBJ`.
        format: &'static str,
        /// The reader's panic message.
        message: String,
    },
    /// The file holds no triangle of non-zero area.
    #[error("`{}` has no triangles{}", path.display(), zero_area(*triangles))]
    NoTriangles {
        /// The file.
        path: PathBuf,
        /// The triangles read, every one of zero area.
        triangles: usize,
    },
    /// The triangles read break the model's rule for a mesh (a vertex not finite).
    #[error("`{}`: {fault}", path.display())]
    Invalid {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        fault: MeshFault,
    },
}

impl MeshFileError {
    /// The file the error is about.
    pub fn path(&self) -> &Path {
        match self {
            MeshFileError::Io { path, .. }
            | MeshFileError::UnknownFormat { path }
            | MeshFileError::Corrupt { path, .. }
            | MeshFileError::ReaderFailed { path, .. }
            | MeshFileError::NoTriangles { path, .. }
            | MeshFileError::Invalid { path, .. } => path,
        }
    }
}

fn zero_area(triangles: usize) -> String {
    if triangles == 0 { String::new() } else { format!(" of non-zero area ({triangles} read, all degenerate)") }
}

/// The formats read, as told by extension or content.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Format {
    Stl,
    Collada,
    Obj,
}

impl Format {
    /// By extension (any case), else by content: text starting `solid` is STL, a `<COLLADA`
    /// among the first kilobyte is Collada (mesh-loader's own sniffing, `src/loader.rs`). OBJ
    /// and binary STL have no signature.
    fn of(path: &Path, bytes: &[u8]) -> Option<Format> {
        let extension = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
        match extension.as_deref() {
            Some("stl") => return Some(Format::Stl),
            Some("dae") => return Some(Format::Collada),
            Some("obj") => return Some(Format::Obj),
            _ => {}
        }
        let head = &bytes[..bytes.len().min(1024)];
        if head.trim_ascii_start().starts_with(b"solid") {
            Some(Format::Stl)
        } else if head.windows(8).any(|w| w == b"<COLLADA") {
            Some(Format::Collada)
        } else {
            None
        }
    }

    fn name(self) -> &'static str {
        match self {
            Format::Stl => "STL",
            Format::Collada => "Collada",
            Format::Obj => "OBJ",
        }
    }

    fn read(self, bytes: &[u8], merged: &mut Merged) -> Result<(), String> {
        match self {
            Format::Stl => stl::read(bytes, merged),
            Format::Collada => collada::read(bytes, merged),
            Format::Obj => {
                // No path, so `mtllib` is not followed: materials are no collision matter, and
                // every file read should be one `load_tree_meshes` reports.
                let no_materials = |_: &Path| -> io::Result<Vec<u8>> { Err(io::ErrorKind::Unsupported.into()) };
                let scene = mesh_loader::obj::from_slice(bytes, None, no_materials).map_err(|e| e.to_string())?;
                scene.meshes.iter().try_for_each(|m| merged.add(&m.vertices, &m.faces, None))
            }
        }
    }
}

/// Reads the mesh file at `path`: STL (binary or ASCII), Collada (`.dae`) or OBJ, told by the
/// extension or else the content, every sub-mesh merged into one [`TriangleMesh`] in the file's
/// units (`f32` widened to `f64`; a Collada file's `<unit>` and node transforms applied, see the
/// crate's README). Never panics: a reader panic on a malformed file is caught and returned as
/// [`MeshFileError::ReaderFailed`] (the panic hook still prints it, as for any panic).
pub fn read_mesh(path: &Path) -> Result<TriangleMesh, MeshFileError> {
    let bytes = std::fs::read(path).map_err(|source| MeshFileError::Io { path: path.to_owned(), source })?;
    let format = Format::of(path, &bytes).ok_or_else(|| MeshFileError::UnknownFormat { path: path.to_owned() })?;
    let mut merged = Merged::default();
    // mesh-loader indexes and unwraps freely on malformed input (`src/collada/iter.rs`,
    // `src/collada/instance.rs`): a bad mesh must be an error naming the file, not a crash of the
    // build or the derive. `merged` is only read on success, so a half-filled one is never seen.
    let outcome = catch_unwind(AssertUnwindSafe(|| format.read(&bytes, &mut merged)));
    match outcome {
        Ok(Ok(())) => {}
        Ok(Err(message)) => {
            return Err(MeshFileError::Corrupt { path: path.to_owned(), format: format.name(), message });
        }
        Err(panic) => {
            let message = panic
                .downcast_ref::<&str>()
                .map(|s| (*s).to_owned())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "no message".to_owned());
            return Err(MeshFileError::ReaderFailed { path: path.to_owned(), format: format.name(), message });
        }
    }
    let triangles = merged.triangle_count();
    let (vertices, faces) = merged.finish();
    TriangleMesh::new(vertices, faces).map_err(|fault| match fault {
        MeshFault::Empty { .. } => MeshFileError::NoTriangles { path: path.to_owned(), triangles },
        fault => MeshFileError::Invalid { path: path.to_owned(), fault },
    })
}
