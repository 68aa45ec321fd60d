//! Resolving and reading together: one URI ([`load`]) and every mesh of a tree
//! ([`load_tree_meshes`]).

use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::Arc;

use kinematics_model::collision::TriangleMesh;
use kinematics_model::{KinematicTree, MeshLoadError};

use crate::read::{MeshFileError, read_mesh};
use crate::resolve::Resolver;
use crate::unresolved::Unresolved;

/// A mesh URI that could not be loaded: not found (with every place looked) or found and not
/// readable (naming the file and what is wrong).
#[derive(Debug, thiserror::Error)]
pub enum MeshError {
    /// No file found.
    #[error(transparent)]
    Unresolved(#[from] Unresolved),
    /// The file found could not be read.
    #[error(transparent)]
    File(#[from] MeshFileError),
}

/// Resolves `uri` and reads the file it names: the file and its triangles.
pub fn load(resolver: &Resolver, uri: &str) -> Result<(PathBuf, TriangleMesh), MeshError> {
    let path = resolver.resolve(uri)?;
    let mesh = read_mesh(&path)?;
    Ok((path, mesh))
}

/// Loads every mesh of `tree`'s collision geometry ([`KinematicTree::load_meshes`]), each distinct
/// file read once, and returns the files read in the order first read: what a build script prints
/// as `cargo:rerun-if-changed` and a derive tracks to rebuild when a mesh changes.
///
/// A mesh that cannot be loaded is an error naming the first link that uses it and the URI, its
/// reason the whole [`MeshError`] message (the places looked, or the file and what is wrong).
pub fn load_tree_meshes(tree: &mut KinematicTree, resolver: &Resolver) -> Result<Vec<PathBuf>, MeshLoadError> {
    let mut files = Vec::new();
    // By file, not by URI: `meshes/a.stl` and `package://robot/meshes/a.stl` may be one file.
    let mut read: HashMap<PathBuf, Arc<TriangleMesh>> = HashMap::new();
    tree.load_meshes(&mut |uri| {
        let path = resolver.resolve(uri).map_err(|e| MeshError::from(e).to_string())?;
        if let Some(mesh) = read.get(&path) {
            return Ok(Arc::clone(mesh));
        }
        let mesh = Arc::new(read_mesh(&path).map_err(|e| MeshError::from(e).to_string())?);
        read.insert(path.clone(), Arc::clone(&mesh));
        files.push(path);
        Ok(mesh)
    })?;
    Ok(files)
}
