//! Loading a description and choosing links: by name (checked, with "did you mean") or by depth.

use kinematics::model::{KinematicTree, LinkId};

use crate::error::CliError;

/// Reads and validates the description `file` (the path as the user typed it names it in errors).
pub fn load(file: &str) -> Result<KinematicTree, CliError> {
    Ok(kinematics::load(file)?)
}

/// The link named by an option (`role` says which: `base`, `tip`, ...), or the error naming it.
pub fn link(tree: &KinematicTree, file: &str, role: &'static str, name: &str) -> Result<LinkId, CliError> {
    Ok(kinematics_build::find_link(tree, file, role, name)?)
}

/// The end effector when none is named: the deepest link (most joints from the root), the last
/// of equals in the tree's depth-first order.
pub fn deepest_link(tree: &KinematicTree) -> LinkId {
    (0..tree.links().len()).map(LinkId).max_by_key(|&l| (tree.path_from_root(l).len(), l)).unwrap_or(tree.root())
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
