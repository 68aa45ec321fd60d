//! The unvalidated description: what a URDF document or DH table says, before any rule is checked.
//!
//! The URDF, MJCF and DH readers all produce one: names as text, nothing checked.
//! `Description::with_floating_base` adds a free-flying root.

use crate::collision::Collision;
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
    /// Links' collision geometry, in file order.
    pub collisions: Vec<CollisionDescription>,
    /// Pairs of links the description rules out of collision checking for good (an MJCF
    /// `<contact><exclude>`, or geoms whose `contype` and `conaffinity` never meet); the tree
    /// keeps them ([`crate::KinematicTree::excluded_pairs`]) and the pair rule leaves them out.
    pub excluded_pairs: Vec<ExcludedPair>,
    /// Links' mass and inertia (`<inertial>`), in file order, at most one a link.
    pub inertials: Vec<InertialDescription>,
    /// Links whose mass the description leaves to be inferred from their geometry (an MJCF body
    /// with geoms and no `<inertial>`, whose inertia MuJoCo computes from them): dynamics refuse
    /// them, naming them, rather than take them as massless.
    pub inertia_from_geometry: Vec<String>,
    /// What the file says that is not applied, each with its element and line (an MJCF
    /// `<equality>` other than a linear joint coupling); the tree keeps the list
    /// ([`crate::KinematicTree::ignored`]).
    pub ignored: Vec<String>,
}

/// One `<collision>` element as the description states it.
#[derive(Debug, Clone, PartialEq)]
pub struct CollisionDescription {
    /// The link it belongs to.
    pub link: String,
    /// The element's line in its file, when read from one (for messages).
    pub line: Option<usize>,
    /// The geometry.
    pub collision: Collision,
}

/// One `<inertial>` element as the description states it.
#[derive(Debug, Clone, PartialEq)]
pub struct InertialDescription {
    /// The link it belongs to.
    pub link: String,
    /// The element's line in its file, when read from one (for messages).
    pub line: Option<usize>,
    /// The mass and inertia.
    pub inertial: crate::inertia::Inertial,
}

/// A pair of links the description rules out of collision checking, and why.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ExcludedPair {
    /// One link.
    pub link1: String,
    /// The other.
    pub link2: String,
    /// Why, naming the element and line that say so (for `inspect` and messages).
    pub why: String,
}

/// The name of the floating joint [`Description::with_floating_base`] adds (Pinocchio's name for
/// a model's free-flyer).
pub const FLOATING_BASE_JOINT: &str = "root_joint";

impl Description {
    /// The robot with a free-flying root: a new link `link` becomes the root, joined to the
    /// description's root by a floating joint [`FLOATING_BASE_JOINT`], so the first seven entries
    /// of `q` are the old root's pose in `link` (position, then quaternion `qx, qy, qz, qw`), as
    /// legged robots and humanoids are modelled. A description with no single root is returned
    /// with the link and no joint, for validation to report what is wrong with it; the caller
    /// checks that `link` and the joint's name are new (validation reports a duplicate otherwise).
    ///
    /// ```
    /// use kinematics_model::{Description, KinematicTree, urdf::parse_urdf};
    /// let urdf = r#"<robot name="r"><link name="trunk"/><link name="leg"/>
    ///   <joint name="hip" type="revolute"><parent link="trunk"/><child link="leg"/>
    ///   <limit lower="-1" upper="1" effort="1" velocity="1"/></joint></robot>"#;
    /// let floating = parse_urdf(urdf)?.with_floating_base("world");
    /// let tree = KinematicTree::from_description(&floating).unwrap();
    /// assert_eq!(tree.link(tree.root()).name, "world");
    /// assert_eq!((tree.dof(), tree.velocity_dof()), (8, 7));
    /// assert_eq!(tree.dof_names()[6], "root_joint.qw");
    /// # Ok::<(), kinematics_model::LoadErrorKind>(())
    /// ```
    pub fn with_floating_base(&self, link: &str) -> Description {
        let mut d = self.clone();
        let children: std::collections::BTreeSet<&str> = self.joints.iter().map(|j| j.child.as_str()).collect();
        let roots: Vec<&String> = self.links.iter().filter(|l| !children.contains(l.as_str())).collect();
        d.links.insert(0, link.to_owned());
        if let [root] = roots[..] {
            d.joints.insert(
                0,
                JointDescription {
                    name: FLOATING_BASE_JOINT.to_owned(),
                    element: Element::Joint(FLOATING_BASE_JOINT.to_owned()),
                    kind: JointTypeDescription::Floating,
                    parent: link.to_owned(),
                    child: root.clone(),
                    origin: FixedTransform::identity(),
                    after_motion: FixedTransform::identity(),
                    axis: [0.0, 0.0, 1.0],
                    limits: None,
                    mimic: None,
                },
            );
        }
        d
    }
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
    /// Free 6-DoF motion.
    Floating,
    /// Planar 3-DoF motion.
    Planar,
    /// URDF `spherical` (not part of the URDF specification, which gives it no entries of `q`;
    /// refused).
    Spherical,
    /// A ball joint (MJCF `ball`): a spherical joint, its rotation a quaternion
    /// ([`crate::JointKind::Spherical`]).
    Ball,
}

impl JointTypeDescription {
    /// The name used in URDF (MJCF's for a ball joint, which URDF does not have).
    pub fn name(self) -> &'static str {
        match self {
            Self::Revolute => "revolute",
            Self::Continuous => "continuous",
            Self::Prismatic => "prismatic",
            Self::Fixed => "fixed",
            Self::Floating => "floating",
            Self::Planar => "planar",
            Self::Spherical => "spherical",
            Self::Ball => "ball",
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
