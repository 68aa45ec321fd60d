//! Checking link names the caller asked for, with "did you mean" for typos.

use kinematics_model::{KinematicTree, LinkId};

use crate::error::BuildError;

/// The link named `name`, or [`BuildError::UnknownLink`] naming `file`, the `role` (`base`,
/// `tip`, ...) and the closest existing link when the name looks like a typo: the model's
/// [`KinematicTree::find_link`] with the file named.
///
/// The builder checks its base and tips with this; the `kinematics` command checks `--base`,
/// `--tip` and `--link` with it too, so both say what the derive says.
pub fn find_link(tree: &KinematicTree, file: &str, role: &'static str, name: &str) -> Result<LinkId, BuildError> {
    tree.find_link(role, name).map_err(|e| BuildError::UnknownLink {
        file: file.to_owned(),
        role: e.role,
        link: e.link,
        suggestion: e.suggestion,
    })
}

#[cfg(test)]
mod tests {
    fn check(wrong: &str, expected: &str) {
        let urdf = r#"<robot name="r"><link name="base_link"/><link name="wrist_3_link"/><link name="tool0"/>
            <joint name="a" type="fixed"><parent link="base_link"/><child link="wrist_3_link"/></joint>
            <joint name="b" type="fixed"><parent link="wrist_3_link"/><child link="tool0"/></joint></robot>"#;
        let tree = kinematics_model::parse_source("r.urdf", urdf).unwrap();
        assert_eq!(super::find_link(&tree, "r.urdf", "tip", wrong).unwrap_err().to_string(), expected, "{wrong}");
    }

    #[test]
    fn suggests_near_misses_only() {
        check("tool9", "r.urdf: tip link `tool9` does not exist; did you mean `tool0`?");
        check("wrist3_link", "r.urdf: tip link `wrist3_link` does not exist; did you mean `wrist_3_link`?");
        check("base_lnk", "r.urdf: tip link `base_lnk` does not exist; did you mean `base_link`?");
        check("gripper", "r.urdf: tip link `gripper` does not exist");
    }
}
