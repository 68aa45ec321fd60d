//! Meshes for collision: resolving a URDF's mesh URIs to files and reading STL, Collada and OBJ
//! into the model's triangle meshes. The model reads no files; this crate is the one place that
//! does it for every front end (derive, build API, CLI, runtime).
//!
//! Two steps, usable apart or together:
//! - **resolve** ([`Resolver`]): `package://NAME/...`, `file://...` or a path to a file, looking
//!   through the user's [`Packages`], `ROS_PACKAGE_PATH`, `AMENT_PREFIX_PATH` and the folders
//!   above the description; an [`Unresolved`] lists every place looked;
//! - **read** ([`read_mesh`]): STL (ASCII or binary), Collada or OBJ through mesh-loader, every
//!   sub-mesh merged into one [`TriangleMesh`](kinematics_model::collision::TriangleMesh) in the
//!   file's units; a [`MeshFileError`] names the file. A Collada file's unit and node transforms
//!   are applied here (mesh-loader's own placement is not relied on: see `src/collada.rs`).
//!
//! [`load`] does both for one URI; [`load_tree_meshes`] for every mesh of a
//! [`KinematicTree`](kinematics_model::KinematicTree), returning the files read.
//!
//! ```no_run
//! use std::path::Path;
//! use kinematics_meshes::{Packages, Resolver, load_tree_meshes};
//!
//! let path = Path::new("robots/arm/urdf/arm.urdf");
//! let mut tree = kinematics_model::parse_source("arm.urdf", &std::fs::read_to_string(path)?)?;
//! let packages = Packages::new().with("arm_description", "robots/arm");
//! let files = load_tree_meshes(&mut tree, &Resolver::new(path, &packages))?;
//! for file in files {
//!     println!("cargo:rerun-if-changed={}", file.display());
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! Architecture invariant: no panic on any input. mesh-loader may panic on a malformed file;
//! [`read_mesh`] catches it and returns an error naming the file.

mod affine;
mod collada;
mod load;
mod merge;
mod packages;
mod read;
mod resolve;
mod ros;
mod stl;
mod unresolved;

pub use load::{MeshError, load, load_tree_meshes};
pub use packages::Packages;
pub use read::{MeshFileError, read_mesh};
pub use resolve::Resolver;
pub use unresolved::{Unresolved, UnresolvedKind};
