//! URDF front end: the kinematic subset of a URDF document into a [`Description`].
//!
//! Read with `roxmltree`, following urdfdom (the ROS reference parser) where URDF leaves a choice:
//!
//! - the root element is `<robot name>`; its `<link name>` and `<joint>` children are read, every
//!   other element (materials, `<transmission>`, `<gazebo>`, xacro leftovers) is ignored, as is a
//!   link's `<visual>`;
//! - a link's `<collision>` elements are read: an `<origin xyz rpy>` and a `<geometry>` with one
//!   `<box size>`, `<cylinder radius length>`, `<sphere radius>`, `<capsule radius length>` or
//!   `<mesh filename scale>` (the mesh named, never opened);
//! - a link's `<inertial>` (at most one) is read as urdfdom reads it: an `<origin xyz rpy>`
//!   (zeros by default), `<mass value>` and `<inertia ixx ixy ixz iyy iyz izz>`, each of these
//!   elements and attributes required. The values are kept as written
//!   ([`crate::inertia::Inertial`]): the rules of a rigid body are checked where dynamics are
//!   asked for, not here, so a NaN or a negative mass loads;
//! - a joint needs `name`, `type` (`revolute`, `continuous`, `prismatic`, `fixed`, `floating`,
//!   `planar`), `<parent link>` and `<child link>`;
//! - `<origin xyz rpy>` defaults to zeros, `<axis xyz>` to `1 0 0`; a joint origin's
//!   `quat_xyzw` (URDF 1.1) is refused (write `rpy`), never ignored;
//! - revolute and prismatic joints need `<limit>`, and every `<limit>` needs `effort` and
//!   `velocity`; `lower` and `upper` default to 0;
//! - `<mimic joint multiplier offset>`: `multiplier` defaults to 1, `offset` to 0.
//!
//! A number is whatever `f64::from_str` accepts once surrounding spaces are trimmed (`inf` and
//! `nan` included: validation rejects them naming the field); anything else is an error naming the
//! attribute. An element given twice where URDF allows one (two `<origin>`s) is an error rather
//! than a silent choice. Every error names the joint (or link) and the line.
//!
//! A robot urdf-rs has already read (`k` and openrr hand around `urdf_rs::Robot`) comes in through
//! `Description::from_urdf_rs` and `KinematicTree::from_urdf_rs` (feature `urdf-rs`), which build
//! each joint with this reader's `UrdfJoint` and validate as [`crate::Source::load`] does.

use roxmltree::{Document, Node};

use crate::angle::Angle;
use crate::collision::{Collision, Shape};
use crate::description::{
    CollisionDescription, Description, InertialDescription, JointDescription, JointTypeDescription, LimitsDescription,
    MimicDescription,
};
use crate::error::{Element, LoadErrorKind};
use crate::inertia::Inertial;
use crate::transform::FixedTransform;

/// Parses URDF text into a description (no model rule is checked yet).
pub fn parse_urdf(text: &str) -> Result<Description, LoadErrorKind> {
    let options = roxmltree::ParsingOptions { allow_dtd: true, ..roxmltree::ParsingOptions::default() };
    let doc = Document::parse_with_options(text, options).map_err(|e| xml_error(text, &e))?;
    let robot = doc.root_element();
    let namespace = robot.tag_name().namespace();
    let at = At { doc: &doc, element: None };
    if robot.tag_name().name() != "robot" {
        return Err(
            at.error(robot.range().start, format!("the root element is <{}>, not <robot>", robot.tag_name().name()))
        );
    }
    let name = at.required(robot, "name")?.to_owned();
    let mut links = Vec::new();
    let mut joints = Vec::new();
    let mut collisions = Vec::new();
    let mut inertials = Vec::new();
    for child in robot.children().filter(|c| c.is_element() && c.tag_name().namespace() == namespace) {
        match child.tag_name().name() {
            "link" => {
                let link = at.required(child, "name")?.to_owned();
                collisions.extend(link_collisions(&doc, child, &link)?);
                inertials.extend(link_inertial(&doc, child, &link)?);
                links.push(link);
            }
            "joint" => joints.push(joint(&doc, child)?),
            _ => {}
        }
    }
    Ok(Description {
        name,
        links,
        joints,
        collisions,
        ignored: Vec::new(),
        excluded_pairs: Vec::new(),
        inertials,
        inertia_from_geometry: Vec::new(),
    })
}

/// A `<link>`'s `<collision>` elements: each an `<origin>` (zeros by default) and a `<geometry>`
/// holding one shape (`box`, `cylinder`, `sphere`, `capsule`, `mesh`). Sizes are checked by
/// validation, which names the link and the line.
fn link_collisions(
    doc: &Document<'_>,
    node: Node<'_, '_>,
    link: &str,
) -> Result<Vec<CollisionDescription>, LoadErrorKind> {
    let at = At { doc, element: Some(Element::Link(link.to_owned())) };
    let namespace = node.tag_name().namespace();
    let mut out = Vec::new();
    for element in node
        .children()
        .filter(|c| c.is_element() && c.tag_name().namespace() == namespace && c.tag_name().name() == "collision")
    {
        let start = element.range().start;
        let origin = at.origin(element)?;
        let Some(geometry) = at.single(element, "geometry")? else {
            return Err(at.error(start, "<collision> needs a <geometry> element".to_owned()));
        };
        let mut shapes = geometry.children().filter(|c| c.is_element() && c.tag_name().namespace() == namespace);
        let (Some(shape), None) = (shapes.next(), shapes.next()) else {
            return Err(at.error(
                geometry.range().start,
                "<geometry> needs exactly one of <box>, <cylinder>, <sphere>, <capsule>, <mesh>".to_owned(),
            ));
        };
        let shape = match shape.tag_name().name() {
            "sphere" => Shape::Sphere { radius: at.required_number(shape, "radius")? },
            "box" => Shape::Box { size: at.vector(shape, "size")?.ok_or_else(|| at.missing(shape, "size"))? },
            "cylinder" => Shape::Cylinder {
                radius: at.required_number(shape, "radius")?,
                length: at.required_number(shape, "length")?,
            },
            "capsule" => Shape::Capsule {
                radius: at.required_number(shape, "radius")?,
                length: at.required_number(shape, "length")?,
            },
            "mesh" => Shape::Mesh {
                filename: at.required(shape, "filename")?.to_owned(),
                scale: at.vector(shape, "scale")?.unwrap_or([1.0; 3]),
                loaded: None,
            },
            other => {
                return Err(at.error(
                    shape.range().start,
                    format!("unknown geometry <{other}> (expected box, cylinder, sphere, capsule or mesh)"),
                ));
            }
        };
        let line = row(doc.text_pos_at(start));
        out.push(CollisionDescription {
            link: link.to_owned(),
            line: Some(line),
            collision: Collision { origin, shape },
        });
    }
    Ok(out)
}

/// A `<link>`'s `<inertial>`, if it has one (a second is an error): its `<origin>` (zeros by
/// default), `<mass value>` and `<inertia>` with all six entries, each required as urdfdom
/// requires it. The values are taken as written: a rigid body's rules are checked where dynamics
/// are asked for ([`Inertial::fault`]).
fn link_inertial(
    doc: &Document<'_>,
    node: Node<'_, '_>,
    link: &str,
) -> Result<Option<InertialDescription>, LoadErrorKind> {
    let at = At { doc, element: Some(Element::Link(link.to_owned())) };
    let Some(element) = at.single(node, "inertial")? else { return Ok(None) };
    let start = element.range().start;
    let origin = at.origin(element)?;
    let Some(mass) = at.single(element, "mass")? else {
        return Err(at.error(start, "<inertial> needs a <mass value=\"...\"> element".to_owned()));
    };
    let mass = at.required_number(mass, "value")?;
    let Some(tensor) = at.single(element, "inertia")? else {
        return Err(at.error(start, "<inertial> needs an <inertia ixx ixy ixz iyy iyz izz> element".to_owned()));
    };
    let mut inertia = [0.0; 6];
    for (slot, name) in inertia.iter_mut().zip(["ixx", "ixy", "ixz", "iyy", "iyz", "izz"]) {
        *slot = at.required_number(tensor, name)?;
    }
    Ok(Some(InertialDescription {
        link: link.to_owned(),
        line: Some(row(doc.text_pos_at(start))),
        inertial: Inertial { mass, origin, inertia },
    }))
}

/// One `<joint>`.
fn joint(doc: &Document<'_>, node: Node<'_, '_>) -> Result<JointDescription, LoadErrorKind> {
    let name = At { doc, element: None }.required(node, "name")?.to_owned();
    let at = At { doc, element: Some(Element::Joint(name.clone())) };
    let start = node.range().start;
    let kind = match at.required(node, "type")? {
        "revolute" => JointTypeDescription::Revolute,
        "continuous" => JointTypeDescription::Continuous,
        "prismatic" => JointTypeDescription::Prismatic,
        "fixed" => JointTypeDescription::Fixed,
        "floating" => JointTypeDescription::Floating,
        "planar" => JointTypeDescription::Planar,
        "spherical" => JointTypeDescription::Spherical,
        other => {
            return Err(at.error(
                attribute_start(node, "type").unwrap_or(start),
                format!(
                    "unknown joint type `{other}` (expected revolute, continuous, prismatic, fixed, floating or planar)"
                ),
            ));
        }
    };
    let link = |tag: &str| -> Result<String, LoadErrorKind> {
        match at.single(node, tag)? {
            Some(element) => Ok(at.required(element, "link")?.to_owned()),
            None => Err(at.error(start, format!("needs a <{tag} link=\"...\"> element"))),
        }
    };
    let parent = link("parent")?;
    let child = link("child")?;
    let (xyz, rpy) = match at.single(node, "origin")? {
        Some(origin) => {
            // URDF 1.1's quaternion: refused rather than ignored (urdfdom ignores it in 1.0 files),
            // so the rotation it holds is never silently dropped.
            if let Some(byte) = attribute_start(origin, "quat_xyzw") {
                return Err(
                    at.error(byte, "<origin quat_xyzw> (URDF 1.1) is not read: write the rotation as `rpy`".to_owned())
                );
            }
            (at.vector(origin, "xyz")?.unwrap_or([0.0; 3]), at.vector(origin, "rpy")?.unwrap_or([0.0; 3]))
        }
        None => ([0.0; 3], [0.0; 3]),
    };
    let axis = match at.single(node, "axis")? {
        Some(axis) => at.vector(axis, "xyz")?.unwrap_or([1.0, 0.0, 0.0]),
        None => [1.0, 0.0, 0.0],
    };
    let limit = match at.single(node, "limit")? {
        Some(limit) => Some(LimitsDescription {
            lower: at.number(limit, "lower")?.unwrap_or(0.0),
            upper: at.number(limit, "upper")?.unwrap_or(0.0),
            effort: Some(at.required_number(limit, "effort")?),
            velocity: Some(at.required_number(limit, "velocity")?),
        }),
        None => None,
    };
    if needs_limit(kind) && limit.is_none() {
        return Err(
            at.error(start, format!("a {} joint needs a <limit> element (with `effort` and `velocity`)", kind.name()))
        );
    }
    let mimic = match at.single(node, "mimic")? {
        Some(mimic) => Some(MimicDescription {
            joint: at.required(mimic, "joint")?.to_owned(),
            multiplier: at.number(mimic, "multiplier")?.unwrap_or(1.0),
            offset: at.number(mimic, "offset")?.unwrap_or(0.0),
        }),
        None => None,
    };
    Ok(UrdfJoint { name, kind, parent, child, xyz, rpy, axis, limit, mimic }.description())
}

/// Whether URDF requires a `<limit>` of a joint of this type (revolute and prismatic joints).
pub(crate) fn needs_limit(kind: JointTypeDescription) -> bool {
    matches!(kind, JointTypeDescription::Revolute | JointTypeDescription::Prismatic)
}

/// A URDF joint's fields once read, by whichever reader (this one, or the urdf-rs conversion):
/// the one place they become a [`JointDescription`], so both describe a joint alike.
pub(crate) struct UrdfJoint {
    pub(crate) name: String,
    pub(crate) kind: JointTypeDescription,
    pub(crate) parent: String,
    pub(crate) child: String,
    pub(crate) xyz: [f64; 3],
    pub(crate) rpy: [f64; 3],
    pub(crate) axis: [f64; 3],
    pub(crate) limit: Option<LimitsDescription>,
    pub(crate) mimic: Option<MimicDescription>,
}

impl UrdfJoint {
    /// The description: the origin as `xyz` then yaw, pitch, roll (angles as written, for the
    /// exactness policy to judge), position limits for the types that take them.
    pub(crate) fn description(self) -> JointDescription {
        let UrdfJoint { name, kind, parent, child, xyz, rpy, axis, limit, mimic } = self;
        JointDescription {
            element: Element::Joint(name.clone()),
            name,
            kind,
            parent,
            child,
            origin: FixedTransform::from_xyz_rpy(xyz, rpy.map(Angle::Radians)),
            after_motion: FixedTransform::identity(),
            axis,
            // Continuous, fixed and the refused types have no position limits, whatever they write.
            limits: if needs_limit(kind) { limit } else { None },
            mimic,
        }
    }
}

/// Where errors are reported: the document (for lines) and the element being read.
pub(crate) struct At<'d, 'input> {
    pub(crate) doc: &'d Document<'input>,
    pub(crate) element: Option<Element>,
}

impl<'input> At<'_, 'input> {
    pub(crate) fn error(&self, byte: usize, message: String) -> LoadErrorKind {
        let line = row(self.doc.text_pos_at(byte));
        LoadErrorKind::Located { element: self.element.clone(), line, message }
    }

    /// The one child element `<tag>` of `node`, if any; a second one is an error.
    fn single<'a>(&self, node: Node<'a, 'input>, tag: &str) -> Result<Option<Node<'a, 'input>>, LoadErrorKind> {
        let namespace = node.tag_name().namespace();
        let mut found = node
            .children()
            .filter(|c| c.is_element() && c.tag_name().namespace() == namespace && c.tag_name().name() == tag);
        let first = found.next();
        match found.next() {
            Some(second) => Err(self.error(second.range().start, format!("more than one <{tag}>"))),
            None => Ok(first),
        }
    }

    /// The transform of `node`'s `<origin xyz rpy>` (zeros by default; one at most), for a
    /// link's `<collision>` or `<inertial>`; URDF 1.1's `quat_xyzw` is refused, as a joint's is.
    fn origin(&self, node: Node<'_, 'input>) -> Result<FixedTransform, LoadErrorKind> {
        let Some(origin) = self.single(node, "origin")? else { return Ok(FixedTransform::identity()) };
        if let Some(byte) = attribute_start(origin, "quat_xyzw") {
            return Err(
                self.error(byte, "<origin quat_xyzw> (URDF 1.1) is not read: write the rotation as `rpy`".to_owned())
            );
        }
        let (xyz, rpy) =
            (self.vector(origin, "xyz")?.unwrap_or([0.0; 3]), self.vector(origin, "rpy")?.unwrap_or([0.0; 3]));
        Ok(FixedTransform::from_xyz_rpy(xyz, rpy.map(Angle::Radians)))
    }

    /// The attribute `name` of `node`, which URDF requires.
    pub(crate) fn required<'a>(&self, node: Node<'a, 'input>, name: &str) -> Result<&'a str, LoadErrorKind> {
        node.attribute(name).ok_or_else(|| self.missing(node, name))
    }

    fn missing(&self, node: Node<'_, '_>, name: &str) -> LoadErrorKind {
        self.error(node.range().start, format!("<{}> needs a `{name}` attribute", node.tag_name().name()))
    }

    /// The number in attribute `name` of `node`, if the attribute is there.
    fn number(&self, node: Node<'_, '_>, name: &str) -> Result<Option<f64>, LoadErrorKind> {
        let Some(text) = node.attribute(name) else { return Ok(None) };
        text.trim().parse().map(Some).map_err(|_| {
            let tag = node.tag_name().name();
            self.error(
                attribute_start(node, name).unwrap_or(node.range().start),
                format!("<{tag} {name}=\"{text}\"> is not a number"),
            )
        })
    }

    /// The number in attribute `name` of `node`, which URDF requires.
    fn required_number(&self, node: Node<'_, 'input>, name: &str) -> Result<f64, LoadErrorKind> {
        match self.number(node, name)? {
            Some(number) => Ok(number),
            None => Err(self.missing(node, name)),
        }
    }

    /// The three numbers in attribute `name` of `node`, if the attribute is there.
    fn vector(&self, node: Node<'_, '_>, name: &str) -> Result<Option<[f64; 3]>, LoadErrorKind> {
        let Some(text) = node.attribute(name) else { return Ok(None) };
        let tag = node.tag_name().name();
        let byte = attribute_start(node, name).unwrap_or(node.range().start);
        let words: Vec<&str> = text.split_whitespace().collect();
        let [x, y, z] = words[..] else {
            return Err(self.error(byte, format!("<{tag} {name}=\"{text}\"> needs 3 numbers, found {}", words.len())));
        };
        let mut numbers = [0.0; 3];
        for (slot, word) in numbers.iter_mut().zip([x, y, z]) {
            *slot = word
                .parse()
                .map_err(|_| self.error(byte, format!("<{tag} {name}=\"{text}\">: `{word}` is not a number")))?;
        }
        Ok(Some(numbers))
    }
}

/// Where attribute `name` of `node` starts in the text.
fn attribute_start(node: Node<'_, '_>, name: &str) -> Option<usize> {
    node.attributes().find(|a| a.namespace().is_none() && a.name() == name).map(|a| a.range().start)
}

/// Malformed XML: the parser's message, at the parser's line (the last line when the text ends
/// too early, where the parser has no position to give).
pub(crate) fn xml_error(text: &str, error: &roxmltree::Error) -> LoadErrorKind {
    let last_line = text.lines().count().max(1);
    let (line, message) = match error {
        roxmltree::Error::NoRootNode if text.trim().is_empty() => (None, "the file is empty".to_owned()),
        roxmltree::Error::NoRootNode => (Some(last_line), "no root element (truncated?)".to_owned()),
        roxmltree::Error::UnclosedRootNode => {
            (Some(last_line), "the file ends before the root element is closed (truncated?)".to_owned())
        }
        roxmltree::Error::UnexpectedEndOfStream => {
            (Some(last_line), "the file ends in the middle of a tag (truncated?)".to_owned())
        }
        roxmltree::Error::UnexpectedCloseTag(expected, found, pos) => {
            (Some(row(*pos)), format!("</{found}> where </{expected}> should close <{expected}>"))
        }
        roxmltree::Error::UnknownToken(pos) if starts_element(text, *pos) => {
            (Some(row(*pos)), "a second root element: a URDF file holds one <robot>".to_owned())
        }
        other => {
            let pos = other.pos();
            let message = other.to_string().replacen(&format!(" at {pos}"), "", 1);
            (Some(row(pos)), message)
        }
    };
    LoadErrorKind::Syntax { line, message }
}

/// Whether an element's start tag (`<name`) begins at `pos`: where the parser finds no token
/// there, it follows the root element, as a second root.
fn starts_element(text: &str, pos: roxmltree::TextPos) -> bool {
    let line_index = row(pos).saturating_sub(1);
    let col = (pos.col as usize).saturating_sub(1);
    let Some(line) = text.split('\n').nth(line_index) else { return false };
    let mut rest = line.chars().skip(col);
    rest.next() == Some('<') && rest.next().is_some_and(|c| c.is_alphabetic() || c == '_')
}

/// The 1-based line of a parser position (`u32` to `usize` loses nothing where `std` runs).
pub(crate) fn row(pos: roxmltree::TextPos) -> usize {
    pos.row as usize
}
