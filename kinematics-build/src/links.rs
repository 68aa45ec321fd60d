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
        suggestion: closest(name, tree.links().iter().map(|l| l.name.as_str())).map(str::to_owned),
    })
}

/// The name in `candidates` closest to `wrong`, if it is close enough to be a likely typo.
fn closest<'a>(wrong: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    candidates
        .into_iter()
        .map(|c| (distance(wrong, c), c))
        .filter(|&(d, c)| d <= 2.max(c.len() / 4))
        .min_by_key(|&(d, _)| d)
        .map(|(_, c)| c)
}

/// Levenshtein distance.
fn distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let next = (prev + usize::from(ca != cb)).min(row[j] + 1).min(row[j + 1] + 1);
            prev = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}

#[cfg(test)]
mod tests {
    use super::closest;

    fn check(wrong: &str, expected: Option<&str>) {
        assert_eq!(closest(wrong, ["base_link", "tool0", "wrist_3_link"]), expected, "{wrong}");
    }

    #[test]
    fn suggests_near_misses_only() {
        check("tool9", Some("tool0"));
        check("wrist3_link", Some("wrist_3_link"));
        check("base_lnk", Some("base_link"));
        check("gripper", None);
    }
}
