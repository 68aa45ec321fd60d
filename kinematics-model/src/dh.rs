//! DH front end: a Denavit-Hartenberg table (TOML or JSON) into a [`Description`].
//!
//! ```toml
//! name = "planar_2r"
//! convention = "standard"      # or "modified" (Craig)
//! angle_unit = "radians"       # or "degrees"; exact strings like "pi/2" are always radians
//!
//! [[joints]]
//! name = "shoulder"
//! a = 1.0
//! alpha = 0.0
//!
//! [[joints]]
//! name = "elbow"
//! a = 1.0
//! lower = "-pi"
//! upper = "pi"
//! ```
//!
//! Each row becomes one joint whose child link is the row's frame, so the link poses are exactly
//! the DH frames: standard rows `Rz(theta) Tz(d) Tx(a) Rx(alpha)`, modified rows
//! `Rx(alpha) Tx(a) Rz(theta) Tz(d)` (REFERENCE.md). A revolute joint's variable adds to `theta`,
//! a prismatic joint's to `d`; `offset` (the joint's zero offset, as in Corke's toolbox) adds to the
//! same column. An optional `[base]` transform comes before row 1 and an optional `[tool]` frame
//! after the last row, as a fixed joint.
//!
//! The table is read with serde. This module owns the column rules (`number`, `check_angle`) that
//! the derive's inline table uses too.

use serde::{Deserialize, Serialize};

use crate::angle::Angle;
use crate::description::{Description, JointDescription, JointTypeDescription, LimitsDescription};
use crate::error::{Element, LoadErrorKind};
use crate::transform::{Axis, FixedTransform};

/// A DH table as written in the file.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct DhTable {
    /// Robot name.
    #[serde(default = "default_name")]
    pub name: String,
    /// Standard (distal) or modified (proximal, Craig).
    pub convention: DhConvention,
    /// Unit of the numeric angles.
    #[serde(default)]
    pub angle_unit: AngleUnit,
    /// Name of the base link (frame 0).
    #[serde(default = "default_base_link")]
    pub base_link: String,
    /// Fixed transform before row 1.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub base: Option<DhFixed>,
    /// Fixed tool frame after the last row.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tool: Option<DhFixed>,
    /// The rows, in order.
    pub joints: Vec<DhRow>,
}

fn default_name() -> String {
    "robot".to_owned()
}

fn default_base_link() -> String {
    "base".to_owned()
}

fn default_tool_name() -> String {
    "tool".to_owned()
}

/// DH convention.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum DhConvention {
    /// Standard (distal): `A_i = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i)`.
    #[serde(alias = "distal")]
    Standard,
    /// Modified (proximal, Craig): `A_i = Rx(alpha_{i-1}) Tx(a_{i-1}) Rz(theta_i) Tz(d_i)`; each row
    /// holds the `a` and `alpha` applied before its own joint.
    #[serde(alias = "craig", alias = "proximal")]
    Modified,
}

/// Unit of numeric angles in the table.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum AngleUnit {
    /// Radians (the default).
    #[default]
    Radians,
    /// Degrees; whole degrees are exact multiples of pi.
    Degrees,
}

/// A number, or an exact angle written as text (`"pi/2"`).
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(untagged)]
pub enum Value {
    /// A plain number, in the table's angle unit where it is an angle.
    Number(f64),
    /// An exact multiple of pi, in radians whatever the table's unit.
    Text(String),
}

impl Default for Value {
    fn default() -> Self {
        Value::Number(0.0)
    }
}

/// A fixed base or tool transform, URDF-style.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct DhFixed {
    /// Link name of the tool frame (ignored for the base).
    #[serde(default = "default_tool_name")]
    pub name: String,
    /// Translation.
    #[serde(default)]
    pub xyz: [f64; 3],
    /// Roll, pitch, yaw (fixed axes x, y, z), as in URDF.
    #[serde(default)]
    pub rpy: [Value; 3],
}

/// Joint type of a DH row.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum DhJointType {
    /// The variable adds to `theta`.
    #[default]
    Revolute,
    /// The variable adds to `d`.
    Prismatic,
}

/// One row of the table.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct DhRow {
    /// Joint name.
    pub name: String,
    /// Name of the link whose frame this row defines (default `link<i>`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub link: Option<String>,
    /// Joint type.
    #[serde(default, rename = "type")]
    pub kind: DhJointType,
    /// Link length `a`.
    #[serde(default)]
    pub a: f64,
    /// Link twist `alpha`.
    #[serde(default)]
    pub alpha: Value,
    /// Link offset `d`.
    #[serde(default)]
    pub d: f64,
    /// Joint angle `theta` (constant part).
    #[serde(default)]
    pub theta: Value,
    /// Joint zero offset, added to the joint variable.
    #[serde(default)]
    pub offset: Value,
    /// Lower position limit.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lower: Option<Value>,
    /// Upper position limit.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub upper: Option<Value>,
    /// Velocity limit.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub velocity: Option<f64>,
    /// Effort limit.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub effort: Option<f64>,
}

impl DhTable {
    /// The table as TOML text (what [`parse_dh_toml`] reads back).
    pub fn to_toml(&self) -> Result<String, LoadErrorKind> {
        toml::to_string(self).map_err(|e| LoadErrorKind::Syntax { line: None, message: e.to_string() })
    }
}

/// Parses a DH table from TOML.
pub fn parse_dh_toml(text: &str) -> Result<DhTable, LoadErrorKind> {
    toml::from_str(text).map_err(|e| LoadErrorKind::Syntax {
        line: e.span().map(|s| line_of(text, s.start)),
        message: e.message().trim().to_owned(),
    })
}

/// Parses a DH table from JSON.
pub fn parse_dh_json(text: &str) -> Result<DhTable, LoadErrorKind> {
    serde_json::from_str(text).map_err(|e| LoadErrorKind::Syntax {
        line: (e.line() > 0).then_some(e.line()),
        message: strip_json_position(&e.to_string()),
    })
}

fn line_of(text: &str, byte: usize) -> usize {
    text.as_bytes().iter().take(byte).filter(|&&b| b == b'\n').count() + 1
}

/// serde_json appends " at line L column C"; the line is reported separately.
fn strip_json_position(message: &str) -> String {
    match message.rfind(" at line ") {
        Some(at) => message[..at].to_owned(),
        None => message.to_owned(),
    }
}

impl DhTable {
    /// The joints, links and fixed transforms this table describes.
    pub fn to_description(&self) -> Result<Description, LoadErrorKind> {
        let mut links = vec![self.base_link.clone()];
        let mut joints = Vec::new();
        let base = match &self.base {
            Some(b) => self.fixed(b, Element::DhSection("base"))?,
            None => FixedTransform::identity(),
        };
        for (i, row) in self.joints.iter().enumerate() {
            let element = Element::DhRow { row: i + 1, joint: row.name.clone() };
            let link = row.link.clone().unwrap_or_else(|| format!("link{}", i + 1));
            // `links` starts with the base link and grows by one per row.
            let parent = links[links.len() - 1].clone();
            let first = if i == 0 { base.clone() } else { FixedTransform::identity() };
            let (origin, after_motion) = self.row_transforms(row, &element, first)?;
            joints.push(JointDescription {
                name: row.name.clone(),
                kind: match row.kind {
                    DhJointType::Revolute => JointTypeDescription::Revolute,
                    DhJointType::Prismatic => JointTypeDescription::Prismatic,
                },
                parent,
                child: link.clone(),
                origin,
                after_motion,
                axis: [0.0, 0.0, 1.0],
                limits: self.limits(row, &element)?,
                mimic: None,
                element,
            });
            links.push(link);
        }
        if let Some(tool) = &self.tool {
            let origin = self.fixed(tool, Element::DhSection("tool"))?;
            let origin = if self.joints.is_empty() { base.then(&origin) } else { origin };
            joints.push(JointDescription {
                name: format!("{}_joint", tool.name),
                element: Element::DhSection("tool"),
                kind: JointTypeDescription::Fixed,
                parent: links[links.len() - 1].clone(),
                child: tool.name.clone(),
                origin,
                after_motion: FixedTransform::identity(),
                axis: [0.0, 0.0, 1.0],
                limits: None,
                mimic: None,
            });
            links.push(tool.name.clone());
        }
        Ok(Description {
            name: self.name.clone(),
            links,
            joints,
            collisions: Vec::new(),
            ignored: Vec::new(),
            excluded_pairs: Vec::new(),
            inertials: Vec::new(),
            inertia_from_geometry: Vec::new(),
        })
    }

    /// The row's fixed parts before and after the joint motion (`Rz(q)` or `Tz(q)`).
    fn row_transforms(
        &self,
        row: &DhRow,
        element: &Element,
        first: FixedTransform,
    ) -> Result<(FixedTransform, FixedTransform), LoadErrorKind> {
        let alpha = self.angle(&row.alpha, element, "alpha")?;
        let theta = self.angle(&row.theta, element, "theta")?;
        let (theta, d) = match row.kind {
            DhJointType::Revolute => (theta + self.angle(&row.offset, element, "offset")?, row.d),
            DhJointType::Prismatic => (theta, row.d + number(&row.offset, element, "offset")?),
        };
        let identity = FixedTransform::identity();
        Ok(match (self.convention, row.kind) {
            // Rz(q + theta) Tz(d) Tx(a) Rx(alpha): Rz(theta) commutes with the motion Rz(q).
            (DhConvention::Standard, DhJointType::Revolute) => (
                first.rotate(Axis::Z, theta),
                identity.translate([0.0, 0.0, d]).translate([row.a, 0.0, 0.0]).rotate(Axis::X, alpha),
            ),
            // Rz(theta) Tz(d) Tz(q) Tx(a) Rx(alpha).
            (DhConvention::Standard, DhJointType::Prismatic) => (
                first.rotate(Axis::Z, theta).translate([0.0, 0.0, d]),
                identity.translate([row.a, 0.0, 0.0]).rotate(Axis::X, alpha),
            ),
            // Rx(alpha) Tx(a) Rz(theta) Tz(d), then the motion (Rz(q) or Tz(q)) commutes to the end.
            (DhConvention::Modified, _) => (
                first
                    .rotate(Axis::X, alpha)
                    .translate([row.a, 0.0, 0.0])
                    .rotate(Axis::Z, theta)
                    .translate([0.0, 0.0, d]),
                identity,
            ),
        })
    }

    fn limits(&self, row: &DhRow, element: &Element) -> Result<Option<LimitsDescription>, LoadErrorKind> {
        let bound = |v: &Value, field| match row.kind {
            DhJointType::Revolute => self.angle(v, element, field).map(Angle::radians),
            DhJointType::Prismatic => number(v, element, field),
        };
        match (&row.lower, &row.upper) {
            (None, None) => Ok(None),
            (Some(lower), Some(upper)) => Ok(Some(LimitsDescription {
                lower: bound(lower, "lower")?,
                upper: bound(upper, "upper")?,
                velocity: row.velocity,
                effort: row.effort,
            })),
            _ => Err(LoadErrorKind::Value {
                element: element.clone(),
                message: "give both `lower` and `upper` limits, or neither".to_owned(),
            }),
        }
    }

    fn fixed(&self, f: &DhFixed, element: Element) -> Result<FixedTransform, LoadErrorKind> {
        let rpy = [
            self.angle(&f.rpy[0], &element, "roll")?,
            self.angle(&f.rpy[1], &element, "pitch")?,
            self.angle(&f.rpy[2], &element, "yaw")?,
        ];
        Ok(FixedTransform::from_xyz_rpy(f.xyz, rpy))
    }

    fn angle(&self, v: &Value, element: &Element, field: &str) -> Result<Angle, LoadErrorKind> {
        match v {
            Value::Number(x) => Ok(match self.angle_unit {
                AngleUnit::Radians => Angle::Radians(*x),
                AngleUnit::Degrees => Angle::from_degrees(*x),
            }),
            Value::Text(t) => exact_angle(t, element, field),
        }
    }
}

/// An angle written as text: it must be exact, like `"pi/2"`, `"-3pi/4"` or `"0"`.
fn exact_angle(text: &str, element: &Element, field: &str) -> Result<Angle, LoadErrorKind> {
    Angle::parse_exact(text).ok_or_else(|| LoadErrorKind::Value {
        element: element.clone(),
        message: format!("`{field}` = \"{text}\" is neither a number nor an exact angle like \"pi/2\""),
    })
}

/// Checks a cell of an angle column (`alpha`, `theta`, a revolute joint's `offset`, `lower` and
/// `upper`, a fixed transform's `rpy`) as [`DhTable::to_description`] will read it: a number, or
/// text that is an exact angle. Front ends that build a [`DhTable`] from another syntax (the
/// derive's inline table) check each cell with this, to point at the offending one.
///
/// ```
/// use kinematics_model::Element;
/// use kinematics_model::dh::{Value, check_angle};
/// let row = Element::DhRow { row: 2, joint: "elbow".to_owned() };
/// assert!(check_angle(&Value::Text("-pi/2".to_owned()), &row, "alpha").is_ok());
/// let error = check_angle(&Value::Text("pie/2".to_owned()), &row, "alpha").unwrap_err();
/// assert_eq!(error.to_string(), "DH row 2 (joint `elbow`): `alpha` = \"pie/2\" is neither a number nor an exact angle like \"pi/2\"");
/// ```
pub fn check_angle(value: &Value, element: &Element, field: &str) -> Result<(), LoadErrorKind> {
    match value {
        Value::Number(_) => Ok(()),
        Value::Text(t) => exact_angle(t, element, field).map(|_| ()),
    }
}

/// The number in a cell of a column that holds no angle (`a`, `d`, `velocity`, `effort`, a
/// prismatic joint's `offset`, `lower` and `upper`, a fixed transform's `xyz`): text is refused,
/// naming the element, the column and the value, as a DH file refuses it.
///
/// ```
/// use kinematics_model::Element;
/// use kinematics_model::dh::{Value, number};
/// let row = Element::DhRow { row: 1, joint: "j".to_owned() };
/// assert_eq!(number(&Value::Number(-0.5), &row, "a").ok(), Some(-0.5));
/// let error = number(&Value::Text("1.0".to_owned()), &row, "a").unwrap_err();
/// assert_eq!(error.to_string(), "DH row 1 (joint `j`): `a` = \"1.0\" must be a number, not text");
/// ```
pub fn number(value: &Value, element: &Element, field: &str) -> Result<f64, LoadErrorKind> {
    match value {
        Value::Number(x) => Ok(*x),
        Value::Text(t) => Err(LoadErrorKind::Value {
            element: element.clone(),
            message: format!("`{field}` = \"{t}\" must be a number, not text"),
        }),
    }
}
