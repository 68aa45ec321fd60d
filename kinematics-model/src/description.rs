//! The unvalidated description: what a URDF document or DH table says, before any rule is checked.

use crate::error::Element;
use crate::transform::FixedTransform;

/// A robot as its description file states it: names as text, nothing checked yet.
///
/// Both front ends (URDF and DH) produce this; [`crate::KinematicTree::from_description`] checks
/// every rule and builds the tree.
#[derive(Debug, Clone, Default)]
pub struct Description {
    /// Robot name.
    pub name: String,
    /// Link names, in file order.
    pub links: Vec<String>,
    /// Joints, in file order.
    pub joints: Vec<JointDescription>,
}

/// A joint type as written in the description, including the ones the model refuses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum JointTypeDescription {
    /// Rotation about the axis, with position limits.
    Revolute,
    /// Rotation about the axis, unlimited.
    Continuous,
    /// Translation along the axis.
    Prismatic,
    /// No motion.
    Fixed,
    /// Free 6-DoF motion (refused for now).
    Floating,
    /// Planar 3-DoF motion (refused for now).
    Planar,
    /// Ball joint (not part of the URDF specification; refused).
    Spherical,
}

impl JointTypeDescription {
    /// The name used in URDF.
    pub fn name(self) -> &'static str {
        match self {
            Self::Revolute => "revolute",
            Self::Continuous => "continuous",
            Self::Prismatic => "prismatic",
            Self::Fixed => "fixed",
            Self::Floating => "floating",
            Self::Planar => "planar",
            Self::Spherical => "spherical",
        }
    }
}

/// Position, velocity and effort limits as written; infinite position limits mean "none".
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LimitsDescription {
    /// Lower position limit.
    pub lower: f64,
    /// Upper position limit.
    pub upper: f64,
    /// Velocity limit, if given.
    pub velocity: Option<f64>,
    /// Effort limit, if given.
    pub effort: Option<f64>,
}

/// `<mimic joint multiplier offset>` as written.
#[derive(Debug, Clone, PartialEq)]
pub struct MimicDescription {
    /// The joint this one follows.
    pub joint: String,
    /// Multiplier (URDF default 1).
    pub multiplier: f64,
    /// Offset (URDF default 0).
    pub offset: f64,
}

/// One joint as written.
#[derive(Debug, Clone)]
pub struct JointDescription {
    /// Joint name.
    pub name: String,
    /// How the element is named in messages (a URDF joint, or a DH row).
    pub element: Element,
    /// Joint type.
    pub kind: JointTypeDescription,
    /// Parent link name.
    pub parent: String,
    /// Child link name.
    pub child: String,
    /// Fixed transform from the parent frame to the joint frame (URDF `<origin>`).
    pub origin: FixedTransform,
    /// Fixed transform applied after the joint motion (standard DH puts its constants here).
    pub after_motion: FixedTransform,
    /// Joint axis in the joint frame, as written (not yet normalised).
    pub axis: [f64; 3],
    /// Limits, if the description has them.
    pub limits: Option<LimitsDescription>,
    /// Mimic relation, if any.
    pub mimic: Option<MimicDescription>,
}
