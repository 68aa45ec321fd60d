//! URDF front end: a URDF document (via `urdf-rs`) into a [`Description`].
//!
//! Only the kinematic part is read: links by name, and each joint's type, parent, child, origin,
//! axis, limits and mimic. Meshes, materials, inertials, `<transmission>` and `<gazebo>` elements
//! are ignored, so real-world files load.

use crate::angle::Angle;
use crate::description::{Description, JointDescription, JointTypeDescription, LimitsDescription, MimicDescription};
use crate::error::{Element, LoadErrorKind};
use crate::transform::FixedTransform;

/// Parses URDF text into a description (no rule is checked yet).
pub fn parse_urdf(text: &str) -> Result<Description, LoadErrorKind> {
    let robot = urdf_rs::read_from_string(text).map_err(|e| syntax_error(text, &e.to_string()))?;
    Ok(Description {
        name: robot.name.clone(),
        links: robot.links.iter().map(|l| l.name.clone()).collect(),
        joints: robot.joints.iter().map(joint).collect(),
    })
}

fn joint(j: &urdf_rs::Joint) -> JointDescription {
    let kind = match j.joint_type {
        urdf_rs::JointType::Revolute => JointTypeDescription::Revolute,
        urdf_rs::JointType::Continuous => JointTypeDescription::Continuous,
        urdf_rs::JointType::Prismatic => JointTypeDescription::Prismatic,
        urdf_rs::JointType::Fixed => JointTypeDescription::Fixed,
        urdf_rs::JointType::Floating => JointTypeDescription::Floating,
        urdf_rs::JointType::Planar => JointTypeDescription::Planar,
        urdf_rs::JointType::Spherical => JointTypeDescription::Spherical,
    };
    let rpy = j.origin.rpy.0.map(Angle::Radians);
    let limited = matches!(kind, JointTypeDescription::Revolute | JointTypeDescription::Prismatic);
    JointDescription {
        name: j.name.clone(),
        element: Element::Joint(j.name.clone()),
        kind,
        parent: j.parent.link.clone(),
        child: j.child.link.clone(),
        origin: FixedTransform::from_xyz_rpy(j.origin.xyz.0, rpy),
        after_motion: FixedTransform::identity(),
        axis: j.axis.xyz.0,
        limits: limited.then_some(LimitsDescription {
            lower: j.limit.lower,
            upper: j.limit.upper,
            velocity: Some(j.limit.velocity),
            effort: Some(j.limit.effort),
        }),
        mimic: j.mimic.as_ref().map(|m| MimicDescription {
            joint: m.joint.clone(),
            multiplier: m.multiplier.unwrap_or(1.0),
            offset: m.offset.unwrap_or(0.0),
        }),
    }
}

/// Turns a parser message into a syntax error, with the line when the message carries one.
fn syntax_error(_text: &str, message: &str) -> LoadErrorKind {
    LoadErrorKind::Syntax { line: line_in_message(message), message: message.trim().to_owned() }
}

/// The XML parsers behind urdf-rs report positions as `line N` or `N:M`; take the first.
fn line_in_message(message: &str) -> Option<usize> {
    let lower = message.to_ascii_lowercase();
    if let Some(at) = lower.find("line ") {
        let digits: String = lower[at + 5..].chars().take_while(char::is_ascii_digit).collect();
        return digits.parse().ok();
    }
    None
}
