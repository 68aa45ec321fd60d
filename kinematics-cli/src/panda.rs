//! VAMP's spherized Panda with collision checking (`robots/panda_spherized.urdf`; its
//! self-collision pairs less those `robots/panda.srdf` disables; `f64` and `f32`), generated at
//! build time by `build.rs` with the build API, and the tabletop scene `scenes/tabletop.toml`:
//! what `kinematics demo` times collision checks on. The SRDF and the scene are compiled in as
//! text too (the crate's copies of the workspace's files), so the demo needs no file at hand.
#![allow(dead_code)] // the generated API is complete; the demo uses part of it

use kinematics::model::KinematicTree;
use kinematics::model::scene::{SceneFormat, parse_scene};
use kinematics::model::srdf::parse_srdf;
use kinematics::{LoadError, LoadErrorKind, SceneObstacles};

use crate::collision::Setup;
use crate::error::CliError;

include!(concat!(env!("OUT_DIR"), "/panda.rs"));

/// The description the code was generated from, as the demo names it.
pub const FILE: &str = "robots/panda_spherized.urdf";
/// The semantic description whose disabled pairs `self_collides` leaves out.
pub const SRDF: &str = "robots/panda.srdf";
/// The scene the demo checks `collides` in.
pub const SCENE: &str = "scenes/tabletop.toml";

/// The built-in Panda's tree (its generated `reference()`'s), with the SRDF's disabled pairs
/// and the scene's obstacles as a collision check's [`Setup`].
pub fn setup() -> Result<(KinematicTree, Setup<'static>), CliError> {
    let tree = Panda::reference()?.tree().clone();
    let load = |file: &'static str| move |kind: LoadErrorKind| CliError::Load(LoadError::new(file, kind));
    let disabled = parse_srdf(include_str!("../robots/panda.srdf"))
        .and_then(|srdf| srdf.disabled_pairs(&tree))
        .map_err(load(SRDF))?;
    let scene = parse_scene(include_str!("../scenes/tabletop.toml"), SceneFormat::Toml).map_err(load(SCENE))?;
    let setup = Setup {
        cover: kinematics::model::collision::Cover::default(),
        meshes: kinematics::model::collision::Meshes::Read,
        srdf: Some((SRDF, disabled)),
        scene: Some((SCENE, SceneObstacles::from_scene(&scene))),
    };
    Ok((tree, setup))
}
