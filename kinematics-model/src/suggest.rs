//! "Did you mean" for names a user typed, and the size of a robot: small helpers every front end
//! (derive, build API, command line) needs to say the same thing.
//!
//! `find_link` finds a link by name (with "did you mean"); the reach is the robot's size.

use crate::error::UnknownLink;
use crate::tree::{KinematicTree, LinkId};

impl KinematicTree {
    /// The link named `name`, asked for as `role` (`base`, `tip`, ...); if there is none, the
    /// error names the role and the closest existing link when the name looks like a typo. The
    /// derive, the build API and the command line check the names users give with this.
    ///
    /// ```
    /// let tree = kinematics_model::synthetic::dh_chain(3);
    /// assert_eq!(tree.find_link("tip", "link2").map(|l| tree.link(l).name.as_str()), Ok("link2"));
    /// let error = tree.find_link("tip", "lnk2").unwrap_err();
    /// assert_eq!(error.to_string(), "tip link `lnk2` does not exist; did you mean `link2`?");
    /// assert_eq!(tree.find_link("base", "gripper").unwrap_err().to_string(), "base link `gripper` does not exist");
    /// ```
    pub fn find_link(&self, role: &'static str, name: &str) -> Result<LinkId, UnknownLink> {
        self.link_id(name).ok_or_else(|| UnknownLink {
            role,
            link: name.to_owned(),
            suggestion: self.suggest_link(name).map(str::to_owned),
        })
    }

    /// The link name closest to `wrong`, when it is close enough to be a likely typo.
    ///
    /// ```
    /// let tree = kinematics_model::synthetic::dh_chain(3);
    /// assert_eq!(tree.suggest_link("lnk2"), Some("link2"));
    /// assert_eq!(tree.suggest_link("gripper"), None);
    /// ```
    pub fn suggest_link(&self, wrong: &str) -> Option<&str> {
        closest(wrong, self.links().iter().map(|l| l.name.as_str()))
    }

    /// An upper bound on how far any link gets from any other, in metres: every fixed offset plus
    /// every prismatic stroke, laid end to end (at least 1, so that tolerances scaled by it never
    /// get tighter than absolute ones).
    pub fn reach(&self) -> f64 {
        // One joint at a time, in the tree's order: validation sums it the same way and names the
        // joint at which it would overflow, so this is always finite.
        (0..self.joints().len()).map(|i| self.joint_reach(crate::tree::JointId(i))).sum::<f64>().max(1.0)
    }
}

/// Names longer than this (in characters) get no suggestion: the edit distance costs the product of the two
/// lengths, and a name this long is no typo of a link name.
const LONGEST_SUGGESTED: usize = 256;

/// The name in `candidates` closest to `wrong`, if it is close enough to be a likely typo (at most
/// two edits, or a quarter of the name's length for long names): the "did you mean" of every
/// unknown name, link or option word alike.
///
/// ```
/// assert_eq!(kinematics_model::closest("lnk2", ["link1", "link2"]), Some("link2"));
/// assert_eq!(kinematics_model::closest("gripper", ["link1", "link2"]), None);
/// ```
pub fn closest<'a>(wrong: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let chars = |s: &str| s.chars().count();
    let wrong_chars = chars(wrong);
    if wrong_chars > LONGEST_SUGGESTED {
        return None;
    }
    let allowed = |c: &str| 2.max(c.len() / 4);
    candidates
        .into_iter()
        // The distance is at least the difference of the lengths: skip what cannot be close.
        .filter(|c| c.len() <= 4 * LONGEST_SUGGESTED && chars(c).abs_diff(wrong_chars) <= allowed(c))
        .map(|c| (distance(wrong, c), c))
        .filter(|&(d, c)| d <= allowed(c))
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
    #[test]
    fn long_names_cost_nothing_and_get_no_suggestion() {
        let long = "l".repeat(100_000);
        let longer = format!("{long}x");
        assert_eq!(super::closest(&longer, [long.as_str(), "link1"]), None);
        assert_eq!(super::closest("link", [long.as_str(), "link1"]), Some("link1"));
    }

    #[test]
    fn suggests_near_misses_only() {
        let links = ["base_link", "tool0", "wrist_3_link"];
        assert_eq!(super::closest("tool9", links), Some("tool0"));
        assert_eq!(super::closest("wrist3_link", links), Some("wrist_3_link"));
        assert_eq!(super::closest("gripper", links), None);
    }
}
