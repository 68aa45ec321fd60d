//! Links and joints of a validated tree.

use crate::transform::FixedTransform;
use crate::tree::{JointId, LinkId};

/// A link: a rigid body with its own frame.
#[derive(Debug, Clone, PartialEq)]
pub struct Link {
    /// Link name (unique in the tree).
    pub name: String,
    /// The joint whose child this link is; `None` for the root.
    pub parent_joint: Option<JointId>,
    /// Joints whose parent this link is, in description order.
    pub child_joints: Vec<JointId>,
}

/// How a joint moves.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum JointKind {
    /// Rotation about the axis, within position limits.
    Revolute,
    /// Rotation about the axis, no position limits.
    Continuous,
    /// Translation along the axis.
    Prismatic,
    /// No motion.
    Fixed,
}

impl JointKind {
    /// Whether the joint rotates (revolute or continuous).
    pub fn is_rotational(self) -> bool {
        matches!(self, JointKind::Revolute | JointKind::Continuous)
    }

    /// The URDF name of the kind.
    pub fn name(self) -> &'static str {
        match self {
            JointKind::Revolute => "revolute",
            JointKind::Continuous => "continuous",
            JointKind::Prismatic => "prismatic",
            JointKind::Fixed => "fixed",
        }
    }
}

/// Where a joint's value comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum JointMotion {
    /// A fixed joint: no value.
    Fixed,
    /// An independent degree of freedom: the value is `q[index]`.
    Dof(usize),
    /// A mimic joint: the value is `multiplier * q[dof] + offset`, where `dof` is the index of the
    /// independent joint `source` (chains of mimics are resolved to the end).
    Mimic {
        /// The independent joint followed.
        source: JointId,
        /// Its degree-of-freedom index.
        dof: usize,
        /// Multiplier.
        multiplier: f64,
        /// Offset.
        offset: f64,
    },
}

impl JointMotion {
    /// The joint value for the configuration `q` (`None` for a fixed joint).
    ///
    /// `q` must have the tree's DoF length; the caller checks that.
    pub fn value(self, q: &[f64]) -> Option<f64> {
        match self {
            JointMotion::Fixed => None,
            JointMotion::Dof(i) => q.get(i).copied(),
            JointMotion::Mimic { dof, multiplier, offset, .. } => q.get(dof).map(|v| multiplier * v + offset),
        }
    }
}

/// Position limits, `lower <= upper`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    /// Lower bound (radians or metres).
    pub lower: f64,
    /// Upper bound (radians or metres).
    pub upper: f64,
}

/// A validated joint: `T_child = T_parent * origin * M(value) * after_motion`.
///
/// `M` is the rotation by the value about `axis` (revolute, continuous), the translation by
/// `value * axis` (prismatic), or the identity (fixed). URDF joints have an identity `after_motion`;
/// standard DH rows place their constants there.
#[derive(Debug, Clone, PartialEq)]
pub struct Joint {
    /// Joint name (unique in the tree).
    pub name: String,
    /// How it moves.
    pub kind: JointKind,
    /// Parent link.
    pub parent: LinkId,
    /// Child link.
    pub child: LinkId,
    /// Fixed transform from the parent frame to the joint frame.
    pub origin: FixedTransform,
    /// Fixed transform after the motion.
    pub after_motion: FixedTransform,
    /// Unit axis in the joint frame (exactly `[0, 0, 1]` etc. when written axis-aligned).
    pub axis: [f64; 3],
    /// Position limits, if any (continuous joints have none).
    pub limits: Option<Limits>,
    /// Velocity limit, if given.
    pub velocity_limit: Option<f64>,
    /// Effort limit, if given.
    pub effort_limit: Option<f64>,
    /// Where the joint's value comes from.
    pub motion: JointMotion,
}
