//! The flags every collision command shares: how the geometry becomes spheres (`--spheres`,
//! `--cover`), where meshes are (`--package NAME=PATH`), or meshes left out (`--skip-meshes`);
//! and reading a description's meshes by them.

use std::path::{Path, PathBuf};

use kinematics::model::KinematicTree;
use kinematics::model::collision::{Cover, Meshes};

use crate::error::CliError;

/// The cover's flags, as the derive's `collision(spheres, sphere_cover, meshes, packages)`.
#[derive(clap::Args, Clone, Debug, Default)]
pub struct CoverArgs {
    /// At most N spheres per link (with `--cover` too, whichever is reached first; neither: at
    /// most 10, stopping early at 1 cm).
    #[arg(long, value_name = "N")]
    pub spheres: Option<usize>,
    /// The cover's largest overshoot in metres: the fewest spheres found with no point farther
    /// than this beyond the geometry.
    #[arg(long = "cover", visible_alias = "sphere-cover", value_name = "METRES")]
    pub cover: Option<f64>,
    /// Where `package://NAME/...` meshes are (repeatable), looked at before `ROS_PACKAGE_PATH`,
    /// `AMENT_PREFIX_PATH` and a folder NAME above the description.
    #[arg(long = "package", value_name = "NAME=PATH", value_parser = kinematics_meshes::Packages::parse_pair)]
    pub packages: Vec<(String, PathBuf)>,
    /// Leave meshes out (only the primitives and spheres are covered).
    #[arg(long)]
    pub skip_meshes: bool,
}

impl CoverArgs {
    /// The cover asked for, its fault a usage error naming the flag.
    pub fn cover(&self) -> Result<Cover, CliError> {
        let cover = match (self.spheres, self.cover) {
            (None, None) => Cover::default(),
            (spheres, overshoot) => Cover { spheres, overshoot },
        };
        match cover.fault() {
            Some(fault) => {
                Err(CliError::Usage(fault.replace("`spheres`", "`--spheres`").replace("`sphere_cover`", "`--cover`")))
            }
            None => Ok(cover),
        }
    }

    /// Whether meshes are read or left out.
    pub fn meshes(&self) -> Meshes {
        if self.skip_meshes { Meshes::Skip } else { Meshes::Read }
    }

    /// Reads the triangles of `tree`'s meshes (the description at `file`), unless they are left
    /// out; a mesh not found or not read is an error naming the file, the link and the URI.
    pub fn read_meshes(&self, tree: &mut KinematicTree, file: &str) -> Result<(), CliError> {
        if self.skip_meshes {
            return Ok(());
        }
        let mut packages = kinematics_meshes::Packages::new();
        for (name, path) in &self.packages {
            packages.insert(name.clone(), path.clone());
        }
        let resolver = kinematics_meshes::Resolver::new(Path::new(file), &packages);
        kinematics_meshes::load_tree_meshes(tree, &resolver)
            .map(drop)
            .map_err(|source| CliError::Mesh { file: file.to_owned(), source })
    }

    /// The cover in words, for headers: `at most 10 spheres per link, stopping at 0.01 m`.
    pub fn describe(cover: &Cover) -> String {
        match (cover.spheres, cover.overshoot) {
            (Some(n), Some(d)) => format!("at most {n} spheres per link, stopping at an overshoot of {d} m"),
            (Some(n), None) => format!("{n} spheres per link"),
            (None, Some(d)) => format!("an overshoot of at most {d} m"),
            (None, None) => "no cover".to_owned(),
        }
    }
}
