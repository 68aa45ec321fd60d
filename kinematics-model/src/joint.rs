//! Links and joints of a validated tree.
//!
//! It also defines what a planar, a spherical and a floating joint take (`JointKind::positions`,
//! `velocities`, the entry names, `quaternion_offset`: where a spherical or floating joint's
//! quaternion starts, which the tree's `quaternion_joints` and `quaternion_entries` list for every
//! stage that normalises or moves one) and a planar joint's in-plane axes (`Joint::plane_axes`),
//! the one piece of geometry both the runtime and the compiler need.

use crate::collision::Collision;
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
    /// Its collision geometry (`<collision>` elements), in description order.
    pub collisions: Vec<Collision>,
    /// Its mass and inertia as written (`<inertial>`); `None` where the description gives none
    /// or gives a zero mass with a zero tensor (a massless link either way).
    pub inertial: Option<crate::inertia::Inertial>,
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
    /// Free motion (URDF `floating`): seven entries of `q`, the child's origin in the joint frame
    /// (`x, y, z`) then its orientation as a quaternion `(qx, qy, qz, qw)` (Pinocchio's order),
    /// whose rotation is that of the quaternion normalised; six velocities (the columns of a
    /// Jacobian): the child's linear and angular velocity in its own axes (Pinocchio's free-flyer).
    Floating,
    /// Motion in the plane normal to the axis (URDF `planar`): three entries of `q`, the
    /// translations along the plane's axes ([`Joint::plane_axes`]) then the rotation about the
    /// normal; three velocities, their rates.
    Planar,
    /// Free rotation about a point (MJCF `ball`): four entries of `q`, the child's orientation in
    /// the joint frame as a quaternion `(qx, qy, qz, qw)` (the order and normalisation of a
    /// floating joint's rotation); three velocities: the child's angular velocity in its own axes
    /// (the angular part of a floating joint's, Pinocchio's spherical joint).
    Spherical,
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
            JointKind::Floating => "floating",
            JointKind::Planar => "planar",
            JointKind::Spherical => "spherical",
        }
    }

    /// How many entries of `q` an independent joint of this kind takes (0 for a fixed joint).
    pub fn positions(self) -> usize {
        match self {
            JointKind::Fixed => 0,
            JointKind::Revolute | JointKind::Continuous | JointKind::Prismatic => 1,
            JointKind::Planar => 3,
            JointKind::Spherical => 4,
            JointKind::Floating => 7,
        }
    }

    /// How many velocities (columns of a Jacobian, entries of `qd`) it takes: a joint with a
    /// quaternion has one fewer than its entries of `q` (three rates of rotation for the
    /// quaternion's four entries).
    pub fn velocities(self) -> usize {
        if self.takes_quaternion() { self.positions() - 1 } else { self.positions() }
    }

    /// Where its quaternion `(qx, qy, qz, qw)` starts among its entries of `q`: 3 for a floating
    /// joint (after its position), 0 for a spherical joint; `None` for the kinds without one. The
    /// same offset among its velocities is where its angular velocity starts (a floating joint's
    /// three linear velocities come first).
    ///
    /// ```
    /// use kinematics_model::JointKind;
    /// assert_eq!(JointKind::Floating.quaternion_offset(), Some(3));
    /// assert_eq!(JointKind::Spherical.quaternion_offset(), Some(0));
    /// assert_eq!(JointKind::Planar.quaternion_offset(), None);
    /// assert_eq!((JointKind::Spherical.positions(), JointKind::Spherical.velocities()), (4, 3));
    /// ```
    pub fn quaternion_offset(self) -> Option<usize> {
        match self {
            JointKind::Floating => Some(3),
            JointKind::Spherical => Some(0),
            _ => None,
        }
    }

    /// Whether its entries of `q` hold a quaternion (a floating or spherical joint), normalised
    /// before use, so that it has fewer velocities than entries of `q`.
    pub fn takes_quaternion(self) -> bool {
        self.quaternion_offset().is_some()
    }

    /// The names of its entries of `q`, after the joint's name (`.x`, ...); empty for a joint of
    /// one entry, whose entry is the joint's name.
    pub fn position_suffixes(self) -> &'static [&'static str] {
        match self {
            JointKind::Planar => &[".x", ".y", ".theta"],
            JointKind::Floating => &[".x", ".y", ".z", ".qx", ".qy", ".qz", ".qw"],
            JointKind::Spherical => &[".qx", ".qy", ".qz", ".qw"],
            _ => &[],
        }
    }

    /// The names of its velocities, after the joint's name.
    pub fn velocity_suffixes(self) -> &'static [&'static str] {
        match self {
            JointKind::Floating => &[".vx", ".vy", ".vz", ".wx", ".wy", ".wz"],
            JointKind::Spherical => &[".wx", ".wy", ".wz"],
            other => other.position_suffixes(),
        }
    }
}

/// Where a joint's value comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum JointMotion {
    /// A fixed joint: no value.
    Fixed,
    /// An independent joint: the value is `q[index]` (a planar joint's three values, a
    /// spherical joint's four and a floating joint's seven start there).
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
/// `value * axis` (prismatic), the motion of a planar, floating or spherical joint's several
/// values ([`JointKind`]), or the identity (fixed). URDF joints have an identity `after_motion`;
/// standard DH rows place their constants there, and an MJCF hinge or ball joint off its body's
/// origin the translation back from its `pos`.
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
    /// Unit axis in the joint frame (exactly `[0, 0, 1]` etc. when written axis-aligned); unused,
    /// and kept as written, for fixed, floating and spherical joints.
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

/// The largest absolute component of `v` (0 for the zero vector).
fn largest(v: [f64; 3]) -> f64 {
    v.iter().fold(0.0, |m: f64, x| if x.abs() > m { x.abs() } else { m })
}

/// The Euclidean norm computed directly, when no square can overflow or lose precision to
/// underflow (components between 1e-150 and 1e150, the ones real descriptions have); the scaled
/// forms below give the same value to rounding, and this keeps the tree's numbers as they were.
fn plain_norm(v: [f64; 3]) -> Option<f64> {
    let scale = largest(v);
    (1e-150..=1e150).contains(&scale).then(|| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt())
}

/// The length of a finite vector, scaled by its largest component first so that it overflows
/// only when the length itself is past `f64::MAX` (`[1e200, 1e200, 0]` is `1.41e200`, not
/// infinity) and small vectors do not underflow to zero.
pub(crate) fn length(v: [f64; 3]) -> f64 {
    if let Some(n) = plain_norm(v) {
        return n;
    }
    let scale = largest(v);
    if scale == 0.0 || !scale.is_finite() {
        return scale;
    }
    let [x, y, z] = v.map(|c| c / scale);
    scale * (x * x + y * y + z * z).sqrt()
}

/// The unit vector along a finite axis, scaled by its largest component before it is squared, so
/// that `0 0 1e200` is `0 0 1` and `1e-300 0 0` is `1 0 0`; `None` for the zero vector (or a
/// vector that is not finite).
impl Joint {
    /// The in-plane axes `(e1, e2)` of a planar joint, in the joint frame: `e1` is the coordinate
    /// axis least aligned with the normal (`axis`; the first of equals) made orthogonal to it and
    /// of unit length, `e2 = axis x e1`. For the normal `z` they are `x` and `y`, exactly; for `x`,
    /// `y` and `z`; for `y`, `x` and `-z`. `q`'s first two entries of the joint move the child along
    /// them.
    ///
    /// ```
    /// use kinematics_model::parse_source;
    /// let urdf = r#"<robot name="r"><link name="a"/><link name="b"/>
    ///   <joint name="slide" type="planar"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/></joint></robot>"#;
    /// let tree = parse_source("r.urdf", urdf)?;
    /// assert_eq!(tree.joint_by_name("slide").unwrap().plane_axes(), ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0]));
    /// # Ok::<(), kinematics_model::LoadError>(())
    /// ```
    pub fn plane_axes(&self) -> ([f64; 3], [f64; 3]) {
        let n = self.axis;
        let least = (0..3).fold(0, |best, i| if n[i].abs() < n[best].abs() { i } else { best });
        let mut e1 = [0.0; 3];
        e1[least] = 1.0;
        let along = n[least];
        let e1 = [e1[0] - along * n[0], e1[1] - along * n[1], e1[2] - along * n[2]];
        let norm = (e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]).sqrt();
        let e1 = if along == 0.0 { e1 } else { [e1[0] / norm, e1[1] / norm, e1[2] / norm] };
        let e2 = [n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2], n[0] * e1[1] - n[1] * e1[0]];
        (e1, e2)
    }
}

pub(crate) fn unit_axis(v: [f64; 3]) -> Option<[f64; 3]> {
    if let Some(n) = plain_norm(v) {
        return Some(v.map(|c| c / n));
    }
    let scale = largest(v);
    if scale == 0.0 || !scale.is_finite() {
        return None;
    }
    let scaled = v.map(|c| c / scale);
    // The largest scaled component is exactly +-1, so the norm is in [1, sqrt 3].
    let n = (scaled[0] * scaled[0] + scaled[1] * scaled[1] + scaled[2] * scaled[2]).sqrt();
    Some(scaled.map(|c| c / n))
}

/// How far a joint's value ranges in the configurations agreement is checked on
/// (`kinematics_runtime::Configurations`): up to 1 beyond finite limits, and up to pi + 1 either
/// way when a side is unlimited (the sampler draws unlimited joints from [-pi, pi], up to 1
/// beyond).
pub(crate) fn stroke(limits: Option<Limits>) -> f64 {
    match limits {
        Some(l) if l.lower.is_finite() && l.upper.is_finite() => l.lower.abs().max(l.upper.abs()) + 1.0,
        _ => std::f64::consts::PI + 1.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axes_are_normalised_without_overflow_or_underflow() {
        let check = |v: [f64; 3], expected: Option<[f64; 3]>| assert_eq!(unit_axis(v), expected, "{v:?}");
        check([0.0, 0.0, 1e200], Some([0.0, 0.0, 1.0]));
        check([0.0, 0.0, -1e300], Some([0.0, 0.0, -1.0]));
        check([1e-300, 0.0, 0.0], Some([1.0, 0.0, 0.0]));
        check([5e-324, 0.0, 0.0], Some([1.0, 0.0, 0.0]));
        check([0.0, 2.0, 0.0], Some([0.0, 1.0, 0.0]));
        check([0.0, 0.0, 0.0], None);
        check([0.0, f64::INFINITY, 0.0], None);
        let diagonal = unit_axis([1e308, 1e308, 0.0]).unwrap();
        assert!((diagonal[0] - std::f64::consts::FRAC_1_SQRT_2).abs() < 2e-16 && diagonal[0] == diagonal[1]);
    }

    #[test]
    fn lengths_do_not_overflow_before_the_length_does() {
        assert_eq!(length([3.0, 4.0, 0.0]), 5.0);
        assert!((length([1e200, 1e200, 0.0]) / 1e200 - std::f64::consts::SQRT_2).abs() < 1e-15);
        assert_eq!(length([1.5e308, 1.5e308, 0.0]), f64::INFINITY);
        assert!(length([1e308, 1e308, 1e308]).is_finite());
        assert_eq!(length([1e-300, 0.0, 0.0]), 1e-300);
        assert_eq!(length([0.0; 3]), 0.0);
    }

    #[test]
    fn strokes_follow_the_sampled_range() {
        let limits = |lower, upper| Some(Limits { lower, upper });
        assert_eq!(stroke(limits(-0.5, 2.0)), 3.0);
        assert_eq!(stroke(None), std::f64::consts::PI + 1.0);
        assert_eq!(stroke(limits(f64::NEG_INFINITY, 2.0)), std::f64::consts::PI + 1.0);
    }
}
