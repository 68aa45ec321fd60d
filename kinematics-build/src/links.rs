//! Checking link names the caller asked for, with "did you mean" for typos.

use kinematics_model::{KinematicTree, LinkId};

use crate::error::BuildError;

/// The link named `name`, or [`BuildError::UnknownLink`] naming `file`, the `role` (`base`,
/// `tip`, ...) and the closest existing link when the name looks like a typo.
///
/// The builder checks its base and tips with this; the `kinematics` command checks `--base`,
/// `--tip` and `--link` with it too, so both say the same thing.
pub fn find_link(tree: &KinematicTree, file: &str, role: &'static str, name: &str) -> Result<LinkId, BuildError> {
    tree.link_id(name).ok_or_else(|| BuildError::UnknownLink {
        file: file.to_owned(),
        role,
        link: name.to_owned(),
        suggestion: tree.suggest_link(name).map(str::to_owned),
    })
}

#[cfg(test)]
mod tests {
    fn check(wrong: &str, expected: Option<&str>) {
        let urdf = r#"<robot name="r"><link name="base_link"/><link name="wrist_3_link"/><link name="tool0"/>
            <joint name="a" type="fixed"><parent link="base_link"/><child link="wrist_3_link"/></joint>
            <joint name="b" type="fixed"><parent link="wrist_3_link"/><child link="tool0"/></joint></robot>"#;
        let tree = kinematics_model::parse_source("r.urdf", urdf).unwrap();
        assert_eq!(tree.suggest_link(wrong), expected, "{wrong}");
    }

    #[test]
    fn suggests_near_misses_only() {
        check("tool9", Some("tool0"));
        check("wrist3_link", Some("wrist_3_link"));
        check("base_lnk", Some("base_link"));
        check("gripper", None);
    }
}
