//! SRDF, MoveIt's semantic robot description, as far as collision checking uses it: the
//! `<disable_collisions link1 link2 reason>` pairs, whose links are never checked against each
//! other. Every other element (groups, group states, end effectors, virtual and passive joints,
//! sphere approximations) is listed in [`Srdf::ignored`] and not applied.
//!
//! Unknown links are refused with a suggestion.

use std::collections::{BTreeMap, BTreeSet};

use roxmltree::Document;

use crate::error::LoadErrorKind;
use crate::tree::{KinematicTree, LinkId};
use crate::urdf::{At, row, xml_error};

/// What an SRDF document says about collisions.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Srdf {
    /// The file as the user named it (set by whoever read it; empty when parsed from text).
    pub file: String,
    /// The robot it describes (`<robot name>`).
    pub robot: String,
    /// The disabled pairs, in file order.
    pub disabled: Vec<DisabledPair>,
    /// Elements not used, each with how many there are, by name.
    pub ignored: BTreeMap<String, usize>,
}

/// One `<disable_collisions>`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DisabledPair {
    /// `link1`.
    pub link1: String,
    /// `link2`.
    pub link2: String,
    /// `reason` (`Adjacent`, `Never`, ...), if given.
    pub reason: Option<String>,
    /// The element's line.
    pub line: usize,
}

/// Parses SRDF text (no link is looked up yet: [`Srdf::disabled_pairs`] does).
///
/// ```
/// let srdf = kinematics_model::srdf::parse_srdf(r#"<robot name="arm">
///   <group name="arm"><chain base_link="a" tip_link="b"/></group>
///   <disable_collisions link1="a" link2="b" reason="Adjacent"/>
/// </robot>"#)?;
/// assert_eq!((srdf.disabled[0].link1.as_str(), srdf.disabled[0].line), ("a", 3));
/// assert_eq!(srdf.ignored.get("group"), Some(&1));
/// # Ok::<(), kinematics_model::LoadErrorKind>(())
/// ```
pub fn parse_srdf(text: &str) -> Result<Srdf, LoadErrorKind> {
    let options = roxmltree::ParsingOptions { allow_dtd: true, ..roxmltree::ParsingOptions::default() };
    let doc = Document::parse_with_options(text, options).map_err(|e| xml_error(text, &e))?;
    let robot = doc.root_element();
    let at = At { doc: &doc, element: None };
    if robot.tag_name().name() != "robot" {
        return Err(
            at.error(robot.range().start, format!("the root element is <{}>, not <robot>", robot.tag_name().name()))
        );
    }
    let mut srdf = Srdf { robot: robot.attribute("name").unwrap_or_default().to_owned(), ..Srdf::default() };
    for child in robot.children().filter(roxmltree::Node::is_element) {
        match child.tag_name().name() {
            "disable_collisions" => srdf.disabled.push(DisabledPair {
                link1: at.required(child, "link1")?.to_owned(),
                link2: at.required(child, "link2")?.to_owned(),
                reason: child.attribute("reason").map(str::to_owned),
                line: row(doc.text_pos_at(child.range().start)),
            }),
            other => *srdf.ignored.entry(other.to_owned()).or_default() += 1,
        }
    }
    Ok(srdf)
}

impl Srdf {
    /// The disabled pairs as links of `tree`, each `(a, b)` with `a` before `b` in tree order. A
    /// link the robot does not have is an error naming the line and the closest link name.
    pub fn disabled_pairs(&self, tree: &KinematicTree) -> Result<BTreeSet<(LinkId, LinkId)>, LoadErrorKind> {
        let mut pairs = BTreeSet::new();
        for pair in &self.disabled {
            let find = |attribute: &str, name: &str| {
                tree.link_id(name).ok_or_else(|| LoadErrorKind::Located {
                    element: None,
                    line: pair.line,
                    message: format!(
                        "<disable_collisions {attribute}=\"{name}\">: link `{name}` does not exist{}",
                        tree.suggest_link(name).map(|s| format!("; did you mean `{s}`?")).unwrap_or_default()
                    ),
                })
            };
            let (a, b) = (find("link1", &pair.link1)?, find("link2", &pair.link2)?);
            pairs.insert((a.min(b), a.max(b)));
        }
        Ok(pairs)
    }
}
