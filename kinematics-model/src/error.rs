//! Errors of the description and model stages.

use std::fmt;

/// The element of a description an error is about, as a user would name it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Element {
    /// The robot as a whole.
    Robot,
    /// A URDF link.
    Link(String),
    /// A URDF joint.
    Joint(String),
    /// A DH table row (1-based) and its joint name.
    DhRow {
        /// 1-based row number.
        row: usize,
        /// Joint name of the row.
        joint: String,
    },
    /// The fixed base or tool transform of a DH table.
    DhSection(&'static str),
    /// An MJCF `<body>`.
    Body(String),
    /// An MJCF `<site>`.
    Site(String),
    /// An MJCF `<frame>`.
    Frame(String),
    /// An obstacle of a scene file: its 1-based place in the file and, if it has one, its name,
    /// as shown (`3`, or ``3 (`table`)``). One `String`, so the enum (held by every model
    /// error) stays the size it was.
    Obstacle(String),
}

impl fmt::Display for Element {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Element::Robot => write!(f, "robot"),
            Element::Link(name) => write!(f, "link `{name}`"),
            Element::Joint(name) => write!(f, "joint `{name}`"),
            Element::DhRow { row, joint } => write!(f, "DH row {row} (joint `{joint}`)"),
            Element::DhSection(section) => write!(f, "DH `{section}` transform"),
            Element::Body(name) => write!(f, "body `{name}`"),
            Element::Site(name) => write!(f, "site `{name}`"),
            Element::Frame(name) => write!(f, "frame `{name}`"),
            Element::Obstacle(label) => write!(f, "obstacle {label}"),
        }
    }
}

/// One rule a description broke. Every message names the element.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ModelError {
    /// The description has no links.
    #[error("the robot has no links")]
    NoLinks,
    /// Two links share a name.
    #[error("link `{0}` is defined more than once")]
    DuplicateLink(String),
    /// Two joints share a name.
    #[error("joint `{0}` is defined more than once")]
    DuplicateJoint(String),
    /// A joint names a link that does not exist.
    #[error("{element}: {role} link `{link}` does not exist")]
    UnknownLink {
        /// The joint.
        element: Element,
        /// `parent` or `child`.
        role: &'static str,
        /// The missing link.
        link: String,
    },
    /// A link is the child of more than one joint.
    #[error("link `{link}` has more than one parent joint: {}", quoted(.joints))]
    MultipleParents {
        /// The link.
        link: String,
        /// The joints that name it as child.
        joints: Vec<String>,
    },
    /// More than one link is no joint's child.
    #[error("more than one root link (links that are no joint's child): {}", quoted(.links))]
    MultipleRoots {
        /// The root candidates.
        links: Vec<String>,
    },
    /// Links that cannot be reached from the root: they form a cycle.
    #[error("the joints form a cycle through {}", quoted(.links))]
    Cycle {
        /// Links on or behind the cycle.
        links: Vec<String>,
    },
    /// A joint type the model does not support.
    #[error(
        "{element}: joint type `{kind}` is not supported (revolute, continuous, prismatic, fixed, floating, planar are)"
    )]
    UnsupportedJoint {
        /// The joint.
        element: Element,
        /// The type as written.
        kind: &'static str,
    },
    /// A moving joint with a zero axis.
    #[error("{element}: axis is zero")]
    ZeroAxis {
        /// The joint.
        element: Element,
    },
    /// Collision geometry whose sizes break its shape's rule (a negative or non-finite radius, a
    /// zero box).
    #[error("link `{link}`{}: <collision>: {fault}", line.map(|l| format!(" (line {l})")).unwrap_or_default())]
    Geometry {
        /// The link.
        link: String,
        /// The element's line, when read from a file.
        line: Option<usize>,
        /// What is wrong.
        fault: String,
    },
    /// An `<inertial>` that belongs nowhere, or a second one of a link.
    #[error("link `{link}`{}: <inertial>: {fault}", line.map(|l| format!(" (line {l})")).unwrap_or_default())]
    Inertial {
        /// The link.
        link: String,
        /// The element's line, when read from a file.
        line: Option<usize>,
        /// What is wrong.
        fault: String,
    },
    /// A NaN or infinity where a finite number is needed.
    #[error("{element}: {field} is not a finite number")]
    NonFinite {
        /// The element.
        element: Element,
        /// Which number (`origin`, `axis`, `lower limit`, ...).
        field: &'static str,
    },
    /// Lower position limit above the upper.
    #[error("{element}: lower limit {lower} is greater than upper limit {upper}")]
    LimitOrder {
        /// The joint.
        element: Element,
        /// Lower limit.
        lower: f64,
        /// Upper limit.
        upper: f64,
    },
    /// A mimic of a joint that does not exist.
    #[error("{element}: mimics joint `{source_joint}`, which does not exist")]
    MimicUnknown {
        /// The mimic joint.
        element: Element,
        /// The missing source.
        source_joint: String,
    },
    /// A mimic of a fixed joint.
    #[error("{element}: mimics joint `{source_joint}`, which is fixed")]
    MimicOfFixed {
        /// The mimic joint.
        element: Element,
        /// The fixed source.
        source_joint: String,
    },
    /// A mimic of a planar or floating joint, or a planar or floating joint that mimics.
    #[error(
        "{element}: mimics joint `{source_joint}`, but a {kind} joint takes several values (a mimic follows one with one)"
    )]
    MimicOfSeveral {
        /// The mimic joint.
        element: Element,
        /// The source.
        source_joint: String,
        /// The type that takes several values.
        kind: SeveralValues,
    },
    /// A fixed joint that claims to mimic another.
    #[error("{element}: a fixed joint cannot mimic another joint")]
    FixedMimic {
        /// The fixed joint.
        element: Element,
    },
    /// Mimic relations that loop.
    #[error("mimic joints form a loop: {}", quoted(.joints))]
    MimicLoop {
        /// The joints on the loop, in order.
        joints: Vec<String>,
    },
    /// A mimic chain whose composed multiplier or offset is not a finite number.
    #[error(
        "{element}: following its mimic chain to joint `{source_joint}`, the composed mimic {} is not a finite number",
        if *.offset { "offset" } else { "multiplier" }
    )]
    MimicOverflow {
        /// The mimic joint at which the composition overflows.
        element: Element,
        /// The independent joint the chain ends at.
        source_joint: String,
        /// Whether it is the offset that overflows (the multiplier being finite).
        offset: bool,
    },
    /// The robot's reach (every fixed offset and prismatic stroke laid end to end) overflows.
    #[error(
        "{element}: the robot's reach (every fixed offset and prismatic stroke laid end to end) is not a finite number from this joint on"
    )]
    ReachOverflow {
        /// The joint at which the running sum overflows.
        element: Element,
    },
    /// A link name that is not in the tree (chain selection, lookups).
    #[error("link `{0}` does not exist")]
    NoSuchLink(String),
    /// A chain whose base is not an ancestor of its tip.
    #[error("link `{base}` is not an ancestor of link `{tip}`, so there is no chain from one to the other")]
    NotAChain {
        /// Requested base.
        base: String,
        /// Requested tip.
        tip: String,
    },
}

fn located(element: Option<&Element>, line: usize) -> String {
    match element {
        Some(element) => format!("{element} (line {line}): "),
        None => format!("line {line}: "),
    }
}

fn quoted(names: &[String]) -> String {
    names.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", ")
}

/// A link name given by the user (a base, a tip, a link to print) that the robot does not have,
/// with the closest existing name when it looks like a typo.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{role} link `{link}` does not exist{}", .suggestion.as_ref().map(|s| format!("; did you mean `{s}`?")).unwrap_or_default())]
pub struct UnknownLink {
    /// What the link was asked for as (`base`, `tip`, ...).
    pub role: &'static str,
    /// The name given.
    pub link: String,
    /// The closest link name, when it looks like a typo.
    pub suggestion: Option<String>,
}

/// Every rule a description broke (never empty).
#[derive(Debug, Clone, PartialEq)]
pub struct ModelErrors(Vec<ModelError>);

impl ModelErrors {
    /// Wraps a non-empty list; `None` if empty.
    pub fn from_vec(errors: Vec<ModelError>) -> Option<Self> {
        (!errors.is_empty()).then_some(Self(errors))
    }

    /// The errors, in the order the rules ran.
    pub fn errors(&self) -> &[ModelError] {
        &self.0
    }
}

impl From<ModelError> for ModelErrors {
    fn from(error: ModelError) -> Self {
        Self(vec![error])
    }
}

impl fmt::Display for ModelErrors {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, e) in self.0.iter().enumerate() {
            if i > 0 {
                write!(f, "; ")?;
            }
            write!(f, "{e}")?;
        }
        Ok(())
    }
}

impl std::error::Error for ModelErrors {}

/// What went wrong while loading a robot description.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum LoadErrorKind {
    /// The file could not be read.
    #[error("cannot read the file: {0}")]
    Io(#[source] std::io::Error),
    /// The file extension names no format we read.
    #[error("unknown description format (expected .urdf, .xml, .mjcf, .toml or .json)")]
    UnknownFormat,
    /// The text is not well-formed for its format.
    #[error("{}{message}", line.map(|l| format!("line {l}: ")).unwrap_or_default())]
    Syntax {
        /// 1-based line, where the parser gives one.
        line: Option<usize>,
        /// The parser's message.
        message: String,
    },
    /// A URDF element that is well-formed XML but not what URDF allows: a missing attribute or
    /// element, a wrong count of numbers, a word where a number belongs. Displayed as
    /// ``joint `elbow` (line 42): <origin xyz="1 2"> needs 3 numbers, found 2``, or as
    /// `line 7: <joint> needs a `name` attribute` when the element has no name to give.
    #[error("{}{message}", located(.element.as_ref(), *.line))]
    Located {
        /// The joint or link, when it has a name.
        element: Option<Element>,
        /// 1-based line of the offending element or attribute.
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// A value is well-formed but wrong (a bad angle, half a limit pair).
    #[error("{element}: {message}")]
    Value {
        /// Where.
        element: Element,
        /// What is wrong.
        message: String,
    },
    /// The description breaks model rules.
    #[error("{0}")]
    Model(ModelErrors),
    /// An error in a file the description names (an MJCF `<include>` or `<model>`), displayed as
    /// ``in `parts.xml`: joint `elbow` (line 3): ...``.
    #[error("in `{file}`: {error}")]
    Included {
        /// The file, as the including element names it.
        file: String,
        /// What is wrong there.
        error: Box<LoadErrorKind>,
    },
}

/// A description that could not be loaded, with the file as the user named it.
#[derive(Debug, thiserror::Error)]
#[error("{file}: {kind}")]
pub struct LoadError {
    /// The file, as the caller named it.
    pub file: String,
    /// What went wrong.
    #[source]
    pub kind: LoadErrorKind,
}

impl LoadError {
    /// A load error for `file`.
    pub fn new(file: impl Into<String>, kind: LoadErrorKind) -> Self {
        Self { file: file.into(), kind }
    }

    /// The model errors, if that is what went wrong.
    pub fn model_errors(&self) -> Option<&ModelErrors> {
        match &self.kind {
            LoadErrorKind::Model(e) => Some(e),
            _ => None,
        }
    }
}

/// A joint type that takes several values of `q` (named in [`ModelError::MimicOfSeveral`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SeveralValues {
    /// A planar joint (three values).
    Planar,
    /// A floating joint (seven values).
    Floating,
    /// A spherical joint (MJCF `ball`: four values).
    Spherical,
}

impl fmt::Display for SeveralValues {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            SeveralValues::Planar => "planar",
            SeveralValues::Floating => "floating",
            SeveralValues::Spherical => "spherical",
        })
    }
}
