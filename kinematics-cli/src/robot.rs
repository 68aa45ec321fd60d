//! Loading a description and choosing links: by name (checked, with "did you mean") or by depth.
//!
//! Files are loaded with the global `--exact-angles` policy and `--format` (the files an MJCF file
//! names read relative to it); links are picked by name, or the deepest; `--q` is read for `fk` and
//! `draw` (zeros when omitted).

use std::sync::atomic::{AtomicBool, AtomicU8, Ordering};

use kinematics::model::{KinematicTree, LinkId, Source, SourceKind};
use kinematics::{ExactAngles, LoadError, LoadErrorKind};

use crate::error::CliError;

/// The global `--exact-angles <on|off>` option (on unless `main` says otherwise), which every
/// subcommand's loading honours.
static EXACT_ANGLES: AtomicBool = AtomicBool::new(true);

/// Sets the exactness policy of every description this run loads (`main`, from the options).
pub fn set_exact_angles(on: bool) {
    EXACT_ANGLES.store(on, Ordering::Relaxed);
}

/// Whether `--exact-angles` is on.
pub fn exact_angles_on() -> bool {
    EXACT_ANGLES.load(Ordering::Relaxed)
}

/// The pairs the SRDF at `path` disables on `tree` (an unknown link refused with a suggestion).
pub fn load_srdf(
    path: &str,
    tree: &KinematicTree,
) -> Result<std::collections::BTreeSet<(kinematics::model::LinkId, kinematics::model::LinkId)>, CliError> {
    let error = |kind| CliError::Load(kinematics::LoadError::new(path, kind));
    let text = std::fs::read_to_string(path).map_err(|e| error(kinematics::LoadErrorKind::Io(e)))?;
    let srdf = kinematics::model::srdf::parse_srdf(&text).map_err(error)?;
    srdf.disabled_pairs(tree).map_err(error)
}

/// Reads and validates the description `file` (the path as the user typed it names it in errors),
/// with the exactness policy of `--exact-angles`.
/// The files an MJCF file names (`<include>`, `<model file>`) are read relative to its directory.
pub fn load(file: &str) -> Result<KinematicTree, CliError> {
    let bytes = std::fs::read(file).map_err(|e| LoadError::new(file, LoadErrorKind::Io(e)))?;
    let source = Source::from_bytes(file, format().kind(), bytes)?;
    let dir = std::path::Path::new(file).parent().map(std::path::Path::to_path_buf).unwrap_or_default();
    let read = move |path: &str| std::fs::read_to_string(dir.join(path)).map_err(|e| e.to_string());
    Ok(source.load_reading(ExactAngles::on(exact_angles_on()), None, &read)?)
}

/// The global `--format` option.
#[derive(Clone, Copy, PartialEq, Eq, Debug, clap::ValueEnum)]
pub enum Format {
    /// By the extension (and a `.xml` file's root element).
    Auto,
    /// URDF, whatever the extension.
    Urdf,
    /// MJCF (MuJoCo's XML), whatever the extension.
    Mjcf,
    /// A DH table: JSON if the name ends in `.json`, TOML otherwise.
    Dh,
}

impl Format {
    /// The model's kind of source.
    pub fn kind(self) -> SourceKind {
        match self {
            Format::Auto => SourceKind::ByExtension,
            Format::Urdf => SourceKind::Urdf,
            Format::Mjcf => SourceKind::Mjcf,
            Format::Dh => SourceKind::Dh,
        }
    }
}

/// `--format`, as `main` set it (the order of [`Format`]'s variants).
static FORMAT: AtomicU8 = AtomicU8::new(0);

/// Sets the format every description this run loads is read in (`main`, from the options).
pub fn set_format(format: Format) {
    FORMAT.store(format as u8, Ordering::Relaxed);
}

/// `--format`.
pub fn format() -> Format {
    match FORMAT.load(Ordering::Relaxed) {
        1 => Format::Urdf,
        2 => Format::Mjcf,
        3 => Format::Dh,
        _ => Format::Auto,
    }
}

/// The link named by an option (`role` says which: `base`, `tip`, ...), or the error naming it.
pub fn link(tree: &KinematicTree, file: &str, role: &'static str, name: &str) -> Result<LinkId, CliError> {
    tree.find_link(role, name).map_err(|source| CliError::UnknownLink { file: file.to_owned(), source })
}

/// `--q` and `--degrees`: a configuration on the command line (`fk`, `draw`).
#[derive(clap::Args)]
pub struct ConfigurationArgs {
    /// Joint values in DoF order, comma-separated (radians, metres); zeros if omitted (each
    /// quaternion of a floating or ball joint the identity).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    q: Option<Vec<f64>>,
    /// Read `--q` in degrees (prismatic values stay in metres).
    #[arg(long)]
    degrees: bool,
}

impl ConfigurationArgs {
    /// The configuration from `--q` (zeros when it is omitted, each floating or spherical joint's
    /// quaternion the identity `0, 0, 0, 1`: the documented default of `fk` and `draw`), with
    /// rotational joints' values read as degrees under `--degrees` (prismatic values
    /// stay metres). Its length and finiteness are checked by the runtime reference that uses it, so
    /// a wrong count or a NaN is refused there with the joint named, never padded or replaced.
    pub fn resolve(&self, tree: &KinematicTree) -> Vec<f64> {
        let (q, degrees) = (self.q.as_deref(), self.degrees);
        let mut q = q.map_or_else(
            || {
                let mut zeros = vec![0.0; tree.dof()];
                for start in tree.quaternion_entries() {
                    zeros[start + 3] = 1.0;
                }
                zeros
            },
            <[f64]>::to_vec,
        );
        if degrees {
            for (value, &joint) in q.iter_mut().zip(tree.dof_joints()) {
                if tree.joint(joint).kind.is_rotational() {
                    *value = value.to_radians();
                }
            }
        }
        q
    }
}

/// The end effector when none is named: the deepest link (most joints from the root), the last
/// of equals in the tree's depth-first order.
pub fn deepest_link(tree: &KinematicTree) -> LinkId {
    // Ties go to the last in depth-first order; the root is the answer for a robot of one link.
    (0..tree.links().len()).map(LinkId).max_by_key(|&l| (tree.depth(l), l)).unwrap_or(tree.root())
}

/// The base and tip names from the options: the base defaults to the root, the tip to the
/// deepest link; both are checked.
pub fn base_and_tip(
    tree: &KinematicTree,
    file: &str,
    base: Option<&str>,
    tip: Option<&str>,
) -> Result<(String, String), CliError> {
    let base = match base {
        Some(name) => link(tree, file, "base", name)?,
        None => tree.root(),
    };
    let tip = match tip {
        Some(name) => link(tree, file, "tip", name)?,
        None => deepest_link(tree),
    };
    Ok((tree.link(base).name.clone(), tree.link(tip).name.clone()))
}
